//! Criterion benchmarks: every model on the paper's base case, the Sears per-step cost against
//! bar length, and FE with 1000 segments per bar.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use pounding::model::impact::{ModelKind, solve};
use pounding::model::scenario::{ImpactScenario, Reading};
use std::hint::black_box;

fn base_case(c: &mut Criterion) {
    let base = ImpactScenario::default();
    let mut g = c.benchmark_group("base_case");
    for model in ModelKind::ALL {
        g.bench_function(model.name(), |b| {
            b.iter(|| solve(model, black_box(&base)).expect("solves"))
        });
    }
    for reading in [Reading::Collocated, Reading::End] {
        let mut sc = base;
        sc.reading = reading;
        g.bench_function(format!("sears-{}", reading.name()), |b| {
            b.iter(|| solve(ModelKind::Sears, black_box(&sc)).expect("solves"))
        });
    }
    g.finish();
}

/// Same number of steps (a fixed window of 2000 steps) for bars from 0.1 m to 10 m: the cost per
/// step must not grow with the number of reflections.
fn sears_step_cost_against_length(c: &mut Criterion) {
    let mut g = c.benchmark_group("sears_2000_steps_by_length");
    for length in [0.1, 0.3, 1.0, 3.0, 10.0] {
        let mut sc = ImpactScenario::default();
        sc.bar1.length_m = length;
        sc.bar2.length_m = 2.0 * length;
        sc.solver.window_s = 2000.0 * sc.solver.dt_s;
        g.bench_with_input(BenchmarkId::from_parameter(length), &sc, |b, sc| {
            b.iter(|| solve(ModelKind::Sears, black_box(sc)).expect("solves"))
        });
    }
    g.finish();
}

fn fe_fine_mesh(c: &mut Criterion) {
    let mut sc = ImpactScenario::default();
    sc.fe.segments = 1000;
    c.bench_function("fe_1000_segments_base_case", |b| {
        b.iter(|| solve(ModelKind::Fe, black_box(&sc)).expect("solves"))
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30).warm_up_time(std::time::Duration::from_millis(500)).measurement_time(std::time::Duration::from_secs(2));
    targets = base_case, sears_step_cost_against_length, fe_fine_mesh
}
criterion_main!(benches);
