//! Exporting an animation for slides: seconds to render and write 120 frames at 1280 x 720 (the
//! long-bars x-t diagram with its moving time line, and the bars and the diagram together), GIF
//! and APNG, on whatever adapter wgpu finds (Mesa's lavapipe on a machine without a GPU: set
//! `WGPU_ADAPTER_NAME=llvmpipe` to insist on it).

use criterion::{Criterion, criterion_group, criterion_main};
use pounding::io::preset::load_for;
use pounding::io::settings::ImpactSetup;
use pounding::model::impact::solve;
use pounding::render::animate::{AnimView, ImpactAnimation};
use pounding::render::offscreen::{Offscreen, headless_device};

fn export_120_frames(c: &mut Criterion) {
    let (device, queue, name) = match headless_device() {
        Ok(d) => d,
        Err(e) => {
            eprintln!("the animation benchmark is skipped: {e}");
            return;
        }
    };
    eprintln!("adapter: {name}");
    let size = (1280, 720);
    let mut target = Offscreen::new(device, queue, size).expect("a 1280x720 target");
    let setup: ImpactSetup = load_for("long-bars", "impact").expect("embedded preset");
    let result = solve(setup.model, &setup.scenario).expect("solves");
    let dir = std::env::temp_dir().join(format!("pounding-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a scratch folder");
    let mut g = c.benchmark_group("animation_120_frames_1280x720");
    g.sample_size(10);
    g.measurement_time(std::time::Duration::from_secs(60));
    for (view, ext) in [
        (AnimView::Xt, "gif"),
        (AnimView::Xt, "png"),
        (AnimView::Both, "gif"),
    ] {
        let anim = ImpactAnimation::new(
            &setup.scenario,
            &result,
            "long-bars".into(),
            view,
            size,
            120,
        );
        let path = dir.join(format!("bench.{ext}"));
        g.bench_function(format!("{view:?}_{ext}"), |b| {
            b.iter(|| {
                anim.write(&mut target, &path, 30.0, &mut |_| {})
                    .expect("written")
            })
        });
    }
    g.finish();
}

criterion_group!(benches, export_120_frames);
criterion_main!(benches);
