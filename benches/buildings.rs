//! Criterion benchmarks of the building pounding run: 8 s of El Centro (from ../shared/data when
//! present, else the synthetic record) with the Sears contact and with a linear spring.

use criterion::{Criterion, criterion_group, criterion_main};
use pounding::io::motion::{Units, parse};
use pounding::model::building::{BuildingScenario, ContactModel, solve};
use pounding::model::motion::GroundMotion;
use std::hint::black_box;

fn record() -> GroundMotion {
    match std::fs::read_to_string("../shared/data/elcentro_1940_ns.txt") {
        Ok(text) => parse(&text, "elcentro", Units::G, None)
            .expect("the shared record parses")
            .truncated(8.0),
        Err(_) => {
            eprintln!("../shared/data is absent: benchmarking on the synthetic record");
            pounding::model::motion::synthetic::SyntheticSpec::default()
                .generate()
                .truncated(8.0)
        }
    }
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
