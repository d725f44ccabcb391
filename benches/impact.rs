//! Criterion benchmarks: every model on the paper's base case, the Sears per-step cost against
//! bar length, and FE with 1000 segments per bar.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use pounding::model::impact::{ModelKind, Workspace, solve, summary_with};
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
    // The summary path sweeps take: no histories, one workspace reused.
    let mut ws = Workspace::default();
    for reading in Reading::ALL {
        let mut sc = base;
        sc.reading = reading;
        g.bench_function(format!("sears-{}-summary", reading.name()), |b| {
            b.iter(|| summary_with(ModelKind::Sears, black_box(&sc), &mut ws).expect("solves"))
        });
    }
    g.finish();
}

/// Same number of steps (a window of 20 000 steps, longer than the longest round trip here, so
/// every look-up reads stored history) for bars from 0.1 m to 10 m: the cost per step must not
/// grow with the number of reflections (0.1 m bars see about 500 round trips, 10 m bars 2).
fn sears_step_cost_against_length(c: &mut Criterion) {
    let mut g = c.benchmark_group("sears_20000_steps_by_length");
    // Whichever length is measured first comes out about 60% slower, in any order, and not with
    // glibc's mmap threshold raised (MALLOC_MMAP_THRESHOLD_): the first benchmark pays for the
    // allocator's large-block pages. A throwaway first entry takes that cost.
    let mut prime = ImpactScenario::default();
    prime.solver.window_s = 20_000.0 * prime.solver.dt_s;
    g.bench_function("allocator-warm-up", |b| {
        b.iter(|| solve(ModelKind::Sears, black_box(&prime)).expect("solves"))
    });
    for length in [0.1, 0.3, 1.0, 3.0, 10.0] {
        let mut sc = ImpactScenario::default();
        sc.bar1.length_m = length;
        sc.bar2.length_m = 2.0 * length;
        sc.solver.window_s = 20_000.0 * sc.solver.dt_s;
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

/// 1000 Sears solves of the base case, bar 2 from 0.5 m to 10 m, in parallel: what
/// `pounding sweep --param bar2.length --from 0.5 --to 10 --count 1000` does, from validating the
/// values to the last point.
fn sweep_1000(c: &mut Criterion) {
    use pounding::io::settings::ImpactSetup;
    use pounding::study::{Control, sweep};
    let base = ImpactSetup::default();
    let mut group = c.benchmark_group("sweep");
    group.sample_size(10);
    group.bench_function("sears_1000_bar2_length", |b| {
        b.iter(|| {
            let values = sweep::values(0.5, 10.0, 1000, false);
            let setups = sweep::setups(black_box(&base), "bar2.length", &values).expect("valid");
            sweep::run(&setups, &values, &[ModelKind::Sears], &Control::new()).expect("sweeps")
        })
    });
    group.finish();
}

/// Every impact study of the paper (Figures 4-9, Sections 3.3-3.5) solved, without writing
/// files: what `pounding study` spends on solving.
fn paper_studies(c: &mut Criterion) {
    use pounding::study::{self, Context, Control};
    let mut group = c.benchmark_group("study");
    group.sample_size(10);
    for s in study::studies().into_iter().filter(|s| !s.buildings) {
        group.bench_function(s.name, |b| {
            b.iter(|| {
                let progress = Control::new();
                (s.run)(&Context::new(&progress)).expect("the study runs")
            })
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30).warm_up_time(std::time::Duration::from_millis(500)).measurement_time(std::time::Duration::from_secs(2));
    targets = base_case, sears_step_cost_against_length, fe_fine_mesh, sweep_1000, paper_studies
}
criterion_main!(benches);
