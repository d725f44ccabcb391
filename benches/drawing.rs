//! What the window does after every run before it can show it: the waves put on the grid the
//! GPU reads (`GpuHistory`), for the slabs of `paper-buildings` (Sears) and the girders of
//! `bridge-3-span`, each about 880 000 samples at 400 a round trip.

use criterion::{Criterion, criterion_group, criterion_main};
use pounding::io::bridge_settings::BridgeSetup;
use pounding::io::building_settings::BuildingSetup;
use pounding::io::preset;
use pounding::render::bars::GpuHistory;
use std::hint::black_box;

fn grids(c: &mut Criterion) {
    let mut g = c.benchmark_group("drawing_grid");
    g.sample_size(20);
    let setup: BuildingSetup = preset::load_for("paper-buildings", "buildings").expect("shipped");
    let motion = pounding::io::motion::load(&setup.motion).expect("its record");
    let r = pounding::model::building::solve(&setup.scenario, &motion).expect("solves");
    let slabs: Vec<_> = r
        .slab_waves()
        .iter()
        .flat_map(|level| level.iter().flatten())
        .collect();
    g.bench_function("paper_buildings_slabs", |b| {
        b.iter(|| GpuHistory::from_bars(black_box(slabs.iter().copied())))
    });
    let setup: BridgeSetup = preset::load_for("bridge-3-span", "bridge").expect("shipped");
    let motion = pounding::io::motion::load(&setup.motion).expect("its record");
    let r = pounding::model::bridge::solve(&setup.scenario, &motion).expect("solves");
    g.bench_function("bridge_3_span_girders", |b| {
        b.iter(|| GpuHistory::from_pairs(black_box(&r.girder_waves)))
    });
    g.finish();
}

criterion_group!(benches, grids);
criterion_main!(benches);
