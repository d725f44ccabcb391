//! Animations for slides: frames (8-bit RGB rows) written as an animated GIF or an APNG, picked
//! by the file's extension. The GIF has one palette for the whole animation, learnt from a few
//! of its frames, so colours do not flicker from frame to frame, and each frame stores only the
//! rectangle that changed. The APNG is lossless.
//!
//! Video (MP4, WebM) is not written: every encoder for them in Rust either wraps a system
//! library (ffmpeg, libvpx, x264) or, like rav1e, needs a container muxer beside it and minutes
//! per clip on a CPU; a GIF or APNG goes into any slide program as it is.

use std::io::Write;
use std::path::{Path, PathBuf};

/// The frame rates an animation may have [frames per second].
pub const FPS_RANGE: std::ops::RangeInclusive<f64> = 1.0..=50.0;
/// The number of frames an animation may have.
pub const FRAMES_RANGE: std::ops::RangeInclusive<usize> = 2..=2000;
/// The pixels each side of an offscreen frame may have (a texture's limits on every adapter).
pub const SIDE_RANGE: std::ops::RangeInclusive<u32> = 16..=8192;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AnimationFormat {
    Gif,
    /// Animated PNG.
    Apng,
}

impl AnimationFormat {
    /// By the file's extension: .gif, or .png (APNG).
    pub fn of_path(path: &Path) -> Result<Self, AnimationError> {
        match super::extension(path).as_str() {
            "gif" => Ok(AnimationFormat::Gif),
            "png" | "apng" => Ok(AnimationFormat::Apng),
            _ => Err(AnimationError::Extension(path.to_path_buf())),
        }
    }
}

#[derive(Debug, thiserror::Error)]
pub enum AnimationError {
    #[error("{}: the animation's extension must be .gif or .png (APNG)", .0.display())]
    Extension(PathBuf),
    #[error("frames: {0} is outside {min} to {max}", min = FRAMES_RANGE.start(), max = FRAMES_RANGE.end())]
    Frames(usize),
    #[error("frames per second: {0} is outside {min} to {max}", min = FPS_RANGE.start(), max = FPS_RANGE.end())]
    Fps(f64),
    #[error("{}: {message}", path.display())]
    Write { path: PathBuf, message: String },
    #[error("frame {index}: {message}")]
    Frame { index: usize, message: String },
}

/// Checks a frame count and rate against their ranges.
pub fn check_timing(frames: usize, fps: f64) -> Result<(), AnimationError> {
    if !FRAMES_RANGE.contains(&frames) {
        return Err(AnimationError::Frames(frames));
    }
    if !fps.is_finite() || !FPS_RANGE.contains(&fps) {
        return Err(AnimationError::Fps(fps));
    }
    Ok(())
}

/// Writes an animation frame by frame.
pub struct AnimationWriter {
    path: PathBuf,
    size: (u32, u32),
    inner: Inner,
}

enum Inner {
    Gif {
        encoder: gif::Encoder<std::io::BufWriter<std::fs::File>>,
        palette: Palette,
        /// The previous frame's palette indices: a frame stores the rectangle that differs.
        previous: Option<Vec<u8>>,
        delay_cs: u16,
    },
    Apng(png::Writer<std::io::BufWriter<std::fs::File>>),
}

impl AnimationWriter {
    /// Creates `path` (and its folder) for `frames` frames of `size` at `fps`; `samples` (RGB
    /// frames of `size`, a few spread over the animation) teach the GIF its palette.
    pub fn create(
        path: &Path,
        size: (u32, u32),
        frames: usize,
        fps: f64,
        samples: &[Vec<u8>],
    ) -> Result<Self, AnimationError> {
        check_timing(frames, fps)?;
        let format = AnimationFormat::of_path(path)?;
        let fail = |message: String| AnimationError::Write {
            path: path.to_path_buf(),
            message,
        };
        if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
            std::fs::create_dir_all(parent)
                .map_err(|e| fail(format!("cannot create its folder: {e}")))?;
        }
        let file = std::io::BufWriter::new(
            std::fs::File::create(path).map_err(|e| fail(format!("cannot create: {e}")))?,
        );
        let (w, h) = size;
        let inner = match format {
            AnimationFormat::Gif => {
                let palette = Palette::learn(samples);
                let (gw, gh) = (
                    u16::try_from(w).map_err(|_| fail("wider than 65535 px".into()))?,
                    u16::try_from(h).map_err(|_| fail("taller than 65535 px".into()))?,
                );
                let mut encoder = gif::Encoder::new(file, gw, gh, &palette.rgb)
                    .map_err(|e| fail(e.to_string()))?;
                encoder
                    .set_repeat(gif::Repeat::Infinite)
                    .map_err(|e| fail(e.to_string()))?;
                Inner::Gif {
                    encoder,
                    palette,
                    previous: None,
                    // GIF delays are in hundredths of a second; below 2, viewers slow it to 10.
                    delay_cs: (100.0 / fps).round().max(2.0) as u16,
                }
            }
            AnimationFormat::Apng => {
                let mut encoder = png::Encoder::new(file, w, h);
                encoder.set_color(png::ColorType::Rgb);
                encoder.set_depth(png::BitDepth::Eight);
                encoder.set_compression(png::Compression::Fast);
                encoder
                    .set_animated(frames as u32, 0)
                    .map_err(|e| fail(e.to_string()))?;
                encoder
                    .set_frame_delay((1000.0 / fps).round() as u16, 1000)
                    .map_err(|e| fail(e.to_string()))?;
                Inner::Apng(encoder.write_header().map_err(|e| fail(e.to_string()))?)
            }
        };
        Ok(AnimationWriter {
            path: path.to_path_buf(),
            size,
            inner,
        })
    }

    /// Appends one frame (RGB rows, top first, of the animation's size).
    pub fn push(&mut self, rgb: &[u8]) -> Result<(), AnimationError> {
        let (w, h) = self.size;
        let fail = |message: String| AnimationError::Write {
            path: self.path.clone(),
            message,
        };
        if rgb.len() != (w * h * 3) as usize {
            return Err(fail(format!(
                "a frame of {} bytes, not {w}x{h} RGB",
                rgb.len()
            )));
        }
        match &mut self.inner {
            Inner::Gif {
                encoder,
                palette,
                previous,
                delay_cs,
            } => {
                let indices = palette.map(rgb);
                let [x0, y0, x1, y1] = match previous {
                    Some(p) => changed(p, &indices, w as usize).unwrap_or([0, 0, 1, 1]),
                    None => [0, 0, w as usize, h as usize],
                };
                let mut buffer = Vec::with_capacity((x1 - x0) * (y1 - y0));
                for row in indices.chunks(w as usize).take(y1).skip(y0) {
                    buffer.extend_from_slice(&row[x0..x1]);
                }
                let frame = gif::Frame {
                    delay: *delay_cs,
                    dispose: gif::DisposalMethod::Keep,
                    left: x0 as u16,
                    top: y0 as u16,
                    width: (x1 - x0) as u16,
                    height: (y1 - y0) as u16,
                    buffer: std::borrow::Cow::Owned(buffer),
                    ..gif::Frame::default()
                };
                encoder
                    .write_frame(&frame)
                    .map_err(|e| fail(e.to_string()))?;
                *previous = Some(indices);
            }
            Inner::Apng(writer) => {
                writer
                    .write_image_data(rgb)
                    .map_err(|e| fail(e.to_string()))?;
            }
        }
        Ok(())
    }

    /// Writes the file's end.
    pub fn finish(self) -> Result<(), AnimationError> {
        let fail = |message: String| AnimationError::Write {
            path: self.path.clone(),
            message,
        };
        match self.inner {
            Inner::Gif { encoder, .. } => {
                let mut file = encoder.into_inner().map_err(|e| fail(e.to_string()))?;
                file.flush().map_err(|e| fail(e.to_string()))
            }
            Inner::Apng(writer) => writer.finish().map_err(|e| fail(e.to_string())),
        }
    }
}

/// The smallest rectangle [x0, y0, x1, y1) holding every pixel that differs; `None` when none.
fn changed(a: &[u8], b: &[u8], w: usize) -> Option<[usize; 4]> {
    let rows: Vec<usize> = (0..a.len() / w)
        .filter(|&y| a[y * w..(y + 1) * w] != b[y * w..(y + 1) * w])
        .collect();
    let (&y0, &y1) = (rows.first()?, rows.last()?);
    let (mut x0, mut x1) = (w, 0);
    for y in y0..=y1 {
        let (ra, rb) = (&a[y * w..(y + 1) * w], &b[y * w..(y + 1) * w]);
        if let Some(first) = (0..w).find(|&x| ra[x] != rb[x]) {
            x0 = x0.min(first);
            x1 = x1.max((first..w).rev().find(|&x| ra[x] != rb[x]).unwrap_or(first) + 1);
        }
    }
    Some([x0, y0, x1, y1 + 1])
}

/// A 256-colour palette for a whole animation, and a memo of each colour's nearest entry.
struct Palette {
    quant: color_quant::NeuQuant,
    rgb: Vec<u8>,
    nearest: std::collections::HashMap<[u8; 3], u8>,
}

impl Palette {
    fn learn(samples: &[Vec<u8>]) -> Self {
        // Every pixel of the samples, as RGBA: NeuQuant samples them itself (every 10th).
        let rgba: Vec<u8> = samples
            .iter()
            .flat_map(|f| f.chunks_exact(3).flat_map(|p| [p[0], p[1], p[2], 255]))
            .collect();
        let rgba = if rgba.is_empty() { vec![255; 4] } else { rgba };
        let quant = color_quant::NeuQuant::new(10, 256, &rgba);
        let rgb = quant.color_map_rgb();
        Palette {
            quant,
            rgb,
            nearest: std::collections::HashMap::new(),
        }
    }

    fn map(&mut self, rgb: &[u8]) -> Vec<u8> {
        rgb.chunks_exact(3)
            .map(|p| {
                let key = [p[0], p[1], p[2]];
                *self
                    .nearest
                    .entry(key)
                    .or_insert_with(|| self.quant.index_of(&[p[0], p[1], p[2], 255]) as u8)
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_changed_rectangle_holds_exactly_the_differing_pixels() {
        let w = 7;
        let a = vec![0u8; w * 5];
        let mut b = a.clone();
        b[w + 2] = 1;
        b[3 * w + 5] = 1;
        assert_eq!(changed(&a, &b, w), Some([2, 1, 6, 4]));
        assert_eq!(changed(&a, &a, w), None);
    }

    #[test]
    fn timing_outside_its_ranges_is_refused_naming_the_field() {
        assert!(
            check_timing(1, 10.0)
                .unwrap_err()
                .to_string()
                .contains("frames")
        );
        let e = check_timing(10, 0.0).unwrap_err().to_string();
        assert!(
            e.contains("frames per second") && e.contains("1 to 50"),
            "{e}"
        );
        assert!(check_timing(10, f64::NAN).is_err());
        assert!(check_timing(120, 30.0).is_ok());
    }

    #[test]
    fn an_unknown_extension_is_refused() {
        let e = AnimationFormat::of_path(Path::new("a.mp4")).unwrap_err();
        assert!(e.to_string().contains(".gif or .png"), "{e}");
    }
}
