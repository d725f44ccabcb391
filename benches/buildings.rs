//! Criterion benchmarks of the building pounding run: 8 s of the shipped El Centro 1940 record
//! with each contact element.

use criterion::{Criterion, criterion_group, criterion_main};
use pounding::model::building::{BuildingScenario, ContactModel, solve};
use pounding::model::motion::GroundMotion;
use std::hint::black_box;

fn record() -> GroundMotion {
    pounding::io::motion::built_in("elcentro-1940")
        .expect("built in")
        .truncated(8.0)
}

fn el_centro_8s(c: &mut Criterion) {
    let motion = record();
    let mut g = c.benchmark_group("buildings_8s");
    for model in [
        ContactModel::Sears,
        ContactModel::Linear,
        ContactModel::Kelvin,
        ContactModel::None,
    ] {
        let sc = BuildingScenario {
            contact: model,
            ..BuildingScenario::paper()
        };
        g.bench_function(model.name(), |b| {
            b.iter(|| solve(black_box(&sc), black_box(&motion)).expect("solves"))
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30).warm_up_time(std::time::Duration::from_secs(1)).measurement_time(std::time::Duration::from_secs(3));
    targets = el_centro_8s
}
criterion_main!(benches);
