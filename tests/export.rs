//! Plot files as a reader of a lecture or paper gets them: a PNG of the asked pixel size whose
//! text and lines grow with the scale, and an SVG that is well-formed XML with the title, axis
//! labels (units included) and legend.

use pounding::export::plot::{LinePlot, Series};
use std::path::PathBuf;

mod common;

fn plot(scale: f64) -> LinePlot {
    LinePlot {
        size: (800, 500),
        scale,
        ..LinePlot::new(
            "Contact force",
            "time [ms]",
            "force [kN]",
            vec![Series {
                name: "force".into(),
                points: (0..200)
                    .map(|i| {
                        let t = i as f64 / 199.0;
                        (t, (std::f64::consts::PI * t).sin() * 135.0)
                    })
                    .collect(),
            }],
        )
    }
}

fn temp(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("pounding-export-{}-{name}", std::process::id()))
}

/// Pixel size, the share of pixels that are not white, and the curve's thickness: the median
/// over columns of the count of pixels in the curve's blue (the curve is one stroke per column
/// except where it is steep).
fn png_ink(path: &std::path::Path) -> ((u32, u32), f64, f64) {
    let (width, height, channels, buf) = common::read_png(path);
    let (w, h) = (width as usize, height as usize);
    let px = |x: usize, y: usize| &buf[(y * w + x) * channels..(y * w + x) * channels + 3];
    let inked = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .filter(|&(x, y)| px(x, y).iter().any(|&c| c < 200))
        .count();
    let blue = |p: &[u8]| p[2] > 120 && p[2] as i32 > p[0] as i32 + 60;
    let mut thickness: Vec<usize> = (0..w)
        .map(|x| (0..h).filter(|&y| blue(px(x, y))).count())
        .filter(|&n| n > 0)
        .collect();
    thickness.sort_unstable();
    (
        (width, height),
        inked as f64 / (w * h) as f64,
        thickness[thickness.len() / 2] as f64,
    )
}

#[test]
fn png_has_the_asked_size_and_its_lines_thicken_with_the_scale() {
    let (a, b) = (temp("s1.png"), temp("s2.png"));
    plot(1.0).write(&a).unwrap();
    plot(2.0).write(&b).unwrap();
    let (size1, ink1, curve1) = png_ink(&a);
    let (size2, ink2, curve2) = png_ink(&b);
    assert_eq!(size1, (800, 500));
    assert_eq!(size2, (800, 500));
    // Axes, text and a curve, on a mostly white page.
    assert!(ink1 > 0.005 && ink1 < 0.5, "ink {ink1}");
    // The stroke goes from 2 to 4 px: the median column of the curve is 2 px thicker (3 where
    // rounding falls the other way), and the larger text adds ink.
    assert!(
        curve2 - curve1 >= 2.0 && curve2 - curve1 <= 3.0,
        "curve {curve2} px thick at scale 2 vs {curve1}"
    );
    assert!(ink2 > ink1, "ink {ink2} at scale 2 vs {ink1}");
    let _ = (std::fs::remove_file(a), std::fs::remove_file(b));
}

#[test]
fn svg_is_well_formed_and_carries_title_axes_with_units_and_legend() {
    let path = temp("p.svg");
    plot(1.0).write(&path).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let doc = roxmltree::Document::parse(&text).expect("well-formed XML");
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    assert_eq!(root.attribute("width"), Some("800"));
    assert_eq!(root.attribute("height"), Some("500"));
    let texts: Vec<&str> = doc.descendants().filter_map(|n| n.text()).collect();
    for want in ["Contact force", "time [ms]", "force [kN]", "force"] {
        assert!(
            texts.iter().any(|t| t.contains(want)),
            "no text {want}: {texts:?}"
        );
    }
    // The curve: a polyline with the 200 points.
    let longest = doc
        .descendants()
        .filter_map(|n| n.attribute("points"))
        .map(|p| p.split_whitespace().count())
        .max()
        .unwrap_or(0);
    assert!(longest >= 150, "longest polyline has {longest} points");
    let _ = std::fs::remove_file(path);
}

#[test]
fn an_unknown_extension_is_refused_with_the_allowed_ones() {
    let e = plot(1.0).write(&temp("p.jpg")).unwrap_err().to_string();
    assert!(e.contains(".svg or .png") && e.contains("p.jpg"), "{e}");
}

/// The gaps between the inked column runs of rows `rows` of a PNG: how far apart its glyphs are.
fn glyph_gaps(path: &std::path::Path, rows: std::ops::Range<usize>) -> Vec<usize> {
    let (width, _, channels, buf) = common::read_png(path);
    let w = width as usize;
    let inked = |x: usize| {
        rows.clone().any(|y| {
            let i = (y * w + x) * channels;
            buf[i..i + 3].iter().map(|&c| u32::from(c)).sum::<u32>() < 3 * 160
        })
    };
    let mut gaps = vec![];
    let (mut seen_ink, mut run) = (false, 0);
    for x in 0..w {
        if inked(x) {
            if seen_ink && run > 0 {
                gaps.push(run);
            }
            seen_ink = true;
            run = 0;
        } else {
            run += 1;
        }
    }
    gaps
}

/// The gaps between the ink of consecutive glyphs of `text` set in the font figures use, at
/// `size` px, from the font's own metrics: each glyph's outline box at its pen position, the pen
/// moved by advances and kerning.
fn font_gaps(text: &str, size: f32) -> Vec<f32> {
    use ab_glyph::{Font, ScaleFont};
    let font = ab_glyph::FontRef::try_from_slice(epaint_default_fonts::UBUNTU_LIGHT).unwrap();
    let scaled = font.as_scaled(size);
    let (mut pen, mut prev) = (0f32, None);
    let mut boxes = vec![];
    for c in text.chars() {
        let id = scaled.glyph_id(c);
        if let Some(p) = prev {
            pen += scaled.kern(p, id);
        }
        prev = Some(id);
        let glyph = id.with_scale_and_position(size, ab_glyph::point(pen, 0.0));
        if let Some(o) = scaled.outline_glyph(glyph) {
            let b = o.px_bounds();
            boxes.push((b.min.x, b.max.x));
        }
        pen += scaled.h_advance(id);
    }
    boxes.windows(2).map(|w| w[1].0 - w[0].1).collect()
}

#[test]
fn exported_text_sets_each_glyph_where_the_font_places_it() {
    // "time [ms]" drawn without each glyph's own left offset read "tim e [m s]": letters with
    // wide side bearings crowded or parted their neighbours by pixels.
    let mut p = LinePlot::new(
        "",
        "time [ms]",
        "",
        vec![Series {
            name: "a".into(),
            points: vec![(0.0, 0.0), (1.0, 1.0)],
        }],
    );
    p.size = (960, 540);
    let path = temp("kerning.png");
    p.write(&path).unwrap();
    // The axis description's band, below the tick labels, at 16 px.
    let drawn = glyph_gaps(&path, 508..532);
    let want = font_gaps("time [ms]", 16.0);
    assert_eq!(drawn.len(), want.len(), "drawn {drawn:?}, font {want:?}");
    // The ink threshold moves every edge alike: each drawn gap differs from the font's by the
    // same offset, give or take the one pixel a glyph's position rounds to. Glyphs set without
    // their left offsets differ by up to three (drawn [2, 1, 3, 5, 1, 3, 1] against the font's
    // [0, 2, 1, 4, 0, 1, 0]).
    let offsets: Vec<f32> = drawn
        .iter()
        .zip(&want)
        .map(|(d, w)| *d as f32 - w)
        .collect();
    let spread = offsets.iter().cloned().fold(f32::MIN, f32::max)
        - offsets.iter().cloned().fold(f32::MAX, f32::min);
    assert!(
        spread <= 1.0,
        "drawn {drawn:?} against the font's {want:?}: offsets {offsets:?}"
    );
    let _ = std::fs::remove_file(&path);
}
