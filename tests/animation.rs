//! Animations for slides, rendered offscreen by the window's pipelines: the files decode (with
//! the gif and png crates) to the frames asked for, frames change, and the bar view's stress
//! front sits where the wave theory puts it.
//!
//! Needs a wgpu adapter (Mesa's lavapipe will do); skips without one, except under `CI=true`.
#![cfg(feature = "gui")]

use pounding::model::impact::{ImpactResult, ModelKind, solve};
use pounding::model::scenario::ImpactScenario;
use pounding::render::animate::{AnimView, ImpactAnimation};
use pounding::render::offscreen::Offscreen;
use std::path::{Path, PathBuf};

mod common;

/// Wave theory, 1 m of steel on 2 m: sharp fronts at x = c t.
fn wave_case() -> (ImpactScenario, ImpactResult) {
    let mut sc = ImpactScenario::default();
    sc.bar2.length_m = 2.0;
    let r = solve(ModelKind::Wave, &sc).expect("solves");
    (sc, r)
}

fn target(size: (u32, u32)) -> Option<Offscreen> {
    let adapter = common::adapter_or_skip()?;
    let (device, queue) = pollster::block_on(adapter.request_device(&Default::default()))
        .expect("the adapter gives a device");
    Some(Offscreen::new(device, queue, size).expect("an offscreen target"))
}

fn scratch(name: &str) -> PathBuf {
    // Under the build's own scratch folder (cargo clean empties it), not the system's: these
    // files are left for a failed test's reader.
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("pounding-animation-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// A GIF's frames composed onto its canvas (each frame stores only what changed) as palette
/// colours, and the canvas size.
fn gif_frames(path: &Path) -> (Vec<Vec<u8>>, (u32, u32)) {
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::RGBA);
    let mut decoder = options
        .read_info(std::fs::File::open(path).unwrap())
        .expect("a GIF");
    let (w, h) = (decoder.width() as usize, decoder.height() as usize);
    let mut canvas = vec![0u8; w * h * 4];
    let mut frames = vec![];
    while let Some(f) = decoder.read_next_frame().expect("a frame decodes") {
        for y in 0..f.height as usize {
            let row = (f.top as usize + y) * w + f.left as usize;
            let src = &f.buffer[y * f.width as usize * 4..(y + 1) * f.width as usize * 4];
            canvas[row * 4..row * 4 + src.len()].copy_from_slice(src);
        }
        frames.push(canvas.clone());
    }
    (frames, (w as u32, h as u32))
}

/// An APNG's frames (RGB, each the whole image) and its declared frame count.
fn apng_frames(path: &Path) -> (Vec<Vec<u8>>, (u32, u32), u32) {
    let mut reader = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()))
        .read_info()
        .expect("a PNG");
    let info = reader.info();
    let declared = info
        .animation_control
        .expect("an animation control chunk")
        .num_frames;
    let size = (info.width, info.height);
    let mut frames = vec![];
    for _ in 0..declared {
        let mut buf = vec![0; reader.output_buffer_size().unwrap()];
        let out = reader.next_frame(&mut buf).expect("a frame decodes");
        assert_eq!(
            (out.width, out.height),
            size,
            "every frame covers the image"
        );
        buf.truncate(out.buffer_size());
        frames.push(buf);
    }
    (frames, size, declared)
}

#[test]
fn gif_and_apng_decode_to_the_requested_frames_and_size_and_consecutive_frames_differ() {
    let (sc, r) = wave_case();
    let size = (400, 240);
    let Some(mut target) = target(size) else {
        return;
    };
    for view in [AnimView::Bars, AnimView::Xt, AnimView::Both] {
        let frames = 7;
        let anim = ImpactAnimation::new(&sc, &r, "test".into(), view, size, frames);
        let gif_path = scratch(&format!("{view:?}.gif"));
        let png_path = scratch(&format!("{view:?}.png"));
        let mut heard = vec![];
        anim.write(&mut target, &gif_path, 10.0, &mut |k| heard.push(k))
            .expect("the GIF is written");
        assert_eq!(
            heard,
            (1..=frames).collect::<Vec<_>>(),
            "progress per frame"
        );
        anim.write(&mut target, &png_path, 10.0, &mut |_| {})
            .expect("the APNG is written");

        let (gif, gif_size) = gif_frames(&gif_path);
        assert_eq!(gif.len(), frames, "{view:?}: GIF frames");
        assert_eq!(gif_size, size, "{view:?}: GIF size");
        let (apng, apng_size, declared) = apng_frames(&png_path);
        assert_eq!(
            (declared as usize, apng.len()),
            (frames, frames),
            "{view:?}"
        );
        assert_eq!(apng_size, size, "{view:?}: APNG size");
        for k in 1..frames {
            assert_ne!(
                gif[k - 1],
                gif[k],
                "{view:?}: GIF frames {} and {k} equal",
                k - 1
            );
            assert_ne!(
                apng[k - 1],
                apng[k],
                "{view:?}: APNG frames {} and {k} equal",
                k - 1
            );
        }
    }
}

#[test]
fn the_bars_views_stress_front_in_frame_k_lies_within_2_px_of_x_equals_c_t_k() {
    let (sc, r) = wave_case();
    let size = (960, 540);
    let Some(mut target) = target(size) else {
        return;
    };
    let frames = 16;
    let anim = ImpactAnimation::new(&sc, &r, "front".into(), AnimView::Bars, size, frames);
    let path = scratch("front.png");
    anim.write(&mut target, &path, 10.0, &mut |_| {})
        .expect("written");
    let (decoded, (w, _), _) = apng_frames(&path);
    let [_, top, _, height] = anim.panels().0.expect("a bar panel");
    let row = top + height / 2;
    let l = anim.layout();
    let c = r.waves.as_ref().unwrap()[1].wave_speed_m_s;
    let neutral = pounding::export::xt::diverging(0.0);
    let column_of = |metres: f64| {
        anim.bars_column(l.gap + metres * l.world_per_metre[1])
            .unwrap()
    };
    let (contact, far) = (column_of(0.0).ceil() as u32, column_of(2.0).floor() as u32);
    let (mut checked, mut worst) = (0, 0.0f64);
    for (k, rgb) in decoded.iter().enumerate() {
        let t = anim.time(k);
        // Before bar 2's front reaches its far end, and far enough out to be seen.
        if !(0.1..1.9).contains(&(c * t)) {
            continue;
        }
        let stressed = |px: u32| {
            let i = ((row * w + px) * 3) as usize;
            (0..3).any(|ch| rgb[i + ch].abs_diff(neutral[ch]) > 3)
        };
        // From the far end inwards: the first stressed column is the front's.
        let front = (contact + 2..far - 1)
            .rev()
            .find(|&px| stressed(px))
            .unwrap_or_else(|| panic!("frame {k}: no stress in bar 2"));
        let want = column_of(c * t);
        let got = front as f64 + 1.0;
        assert!(
            (got - want).abs() <= 2.0,
            "frame {k} (t = {t:e} s): front at column {got}, c t at {want:.1}"
        );
        worst = worst.max((got - want).abs());
        checked += 1;
    }
    eprintln!("{checked} frames: the front within {worst:.2} px of c t");
    assert!(checked >= 3, "only {checked} frames had a front in bar 2");
}

#[test]
fn cli_impact_animate_writes_a_gif_of_the_asked_frames_and_size() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    let path = scratch("cli-xt.gif");
    let o = common::pounding(&[
        "impact",
        "--preset",
        "long-bars",
        "--animate",
        path.to_str().unwrap(),
        "--animate-view",
        "xt",
        "--animate-frames",
        "5",
        "--animate-size",
        "320x200",
        "--json",
    ]);
    assert!(o.status.success(), "{}", common::stderr(&o));
    let (frames, size) = gif_frames(&path);
    assert_eq!((frames.len(), size), (5, (320, 200)));
    // --json keeps standard output one JSON object.
    serde_json::from_str::<serde_json::Value>(&common::stdout(&o)).expect("JSON on stdout");
}

#[test]
fn cli_buildings_animate_writes_an_apng_whose_frames_differ() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    let path = scratch("cli-buildings.png");
    let o = common::pounding(&[
        "buildings",
        "--animate",
        path.to_str().unwrap(),
        "--animate-frames",
        "4",
        "--animate-size",
        "480x270",
        "--quiet",
    ]);
    assert!(o.status.success(), "{}", common::stderr(&o));
    let (frames, size, declared) = apng_frames(&path);
    assert_eq!((frames.len(), declared, size), (4, 4, (480, 270)));
    assert!(frames.windows(2).all(|f| f[0] != f[1]), "frames repeat");
}

#[test]
fn bad_animation_flags_are_refused_naming_the_flag_and_its_range() {
    for (args, want) in [
        (
            vec!["--animate-view", "side"],
            "--animate-view: unknown view 'side': allowed bars|xt|both",
        ),
        (
            vec!["--animate-frames", "1"],
            "'--animate-frames <N>': '1': expected a whole number from 2 to 2000",
        ),
        (vec!["--animate-fps", "100"], "--animate-fps"),
        (vec!["--animate-size", "10x10"], "--animate-size"),
    ] {
        let path = scratch("refused.gif");
        let mut all = vec!["impact", "--animate", path.to_str().unwrap()];
        all.extend(args.iter().copied());
        let o = common::pounding(&all);
        assert!(!o.status.success(), "{args:?} accepted");
        let err = common::stderr(&o);
        assert!(err.contains(want), "{args:?}: {err}");
    }
    let o = common::pounding(&["impact", "--animate", "a.mp4"]);
    assert!(
        common::stderr(&o).contains(".gif or .png"),
        "{}",
        common::stderr(&o)
    );
}

#[test]
fn cli_bridge_animate_writes_a_gif_around_the_strongest_impact_whose_frames_differ() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    let path = scratch("cli-bridge.gif");
    let o = common::pounding(&[
        "bridge",
        "--animate",
        path.to_str().unwrap(),
        "--animate-frames",
        "4",
        "--animate-size",
        "480x270",
        "--animate-around",
        "strongest",
        "--quiet",
    ]);
    assert!(o.status.success(), "{}", common::stderr(&o));
    let (frames, size) = gif_frames(&path);
    assert_eq!((frames.len(), size), (4, (480, 270)));
    assert!(frames.windows(2).all(|f| f[0] != f[1]), "frames repeat");
    // An impact the run does not have is refused by number, before anything is written.
    let o = common::pounding(&[
        "bridge",
        "--animate",
        path.to_str().unwrap(),
        "--animate-around",
        "999",
        "--quiet",
    ]);
    assert!(!o.status.success());
    assert!(
        common::stderr(&o).contains("--animate-around: '999'"),
        "{}",
        common::stderr(&o)
    );
}
