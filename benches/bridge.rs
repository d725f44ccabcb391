//! Criterion benchmarks of the bridge runs on the `bridge-3-span` preset (three girders on
//! piers of unequal stiffness, the first 8 s of El Centro 1940): one run (`model::bridge::solve`)
//! with Sears (the preset's element), with the linear spring, and with Sears on ten spans; and
//! the whole work of `pounding bridge` (the run, its error estimate and the run without contact)
//! for the same three. `examples/bridge_loop.rs` runs the same scenes for callgrind.

use criterion::{Criterion, criterion_group, criterion_main};
use pounding::io::bridge_settings::BridgeSetup;
use pounding::io::preset;
use pounding::model::bridge::{BridgeScenario, estimate_error, solve};
use pounding::model::building::ContactModel;
use pounding::model::control::Control;
use pounding::model::motion::GroundMotion;
use std::hint::black_box;
use std::time::Duration;

/// The preset with the `KEY=VALUE` settings and the contact element applied, and its record.
fn bridge(contact: ContactModel, sets: &[&str]) -> (BridgeScenario, GroundMotion) {
    let mut setup: BridgeSetup = preset::load_for("bridge-3-span", "bridge").expect("shipped");
    for a in sets {
        setup.apply_assignment(a).expect("a valid setting");
    }
    setup.scenario.contact = contact;
    setup.scenario.validate().expect("a valid scene");
    let motion = pounding::io::motion::load(&setup.motion).expect("its record");
    (setup.scenario, motion)
}

/// Ten spans: the preset's three pier stiffnesses repeated, its abutment gaps at the ends and
/// its inner gap between (as `bridge_loop sears 10` makes them).
const TEN_SPANS: [&str; 3] = [
    "bridge.spans=10",
    "pier.stiffness=8e7,2e8,4e7,8e7,2e8,4e7,8e7,2e8,4e7,8e7",
    "joint.gaps=0.05,0.03,0.03,0.03,0.03,0.03,0.03,0.03,0.03,0.03,0.05",
];

/// The benchmarked scenes: name, contact element (as `--contact`), settings (as `--set`).
const CASES: [(&str, ContactModel, &[&str]); 3] = [
    ("3_span_sears", ContactModel::Sears, &[]),
    ("3_span_linear", ContactModel::Linear, &[]),
    ("10_span_sears", ContactModel::Sears, &TEN_SPANS),
];

/// One run with its histories.
fn one_solve(c: &mut Criterion) {
    let mut g = c.benchmark_group("bridge_solve");
    for (name, contact, sets) in CASES {
        let (sc, motion) = bridge(contact, sets);
        g.bench_function(name, |b| {
            b.iter(|| solve(black_box(&sc), black_box(&motion)).expect("solves"))
        });
    }
    g.finish();
}

/// What one `pounding bridge` makes (the report aside): the run, its error estimate (the run
/// with half the step) and the run without contact.
fn whole_run(c: &mut Criterion) {
    let mut g = c.benchmark_group("bridge_whole_run");
    for (name, contact, sets) in CASES {
        let (sc, motion) = bridge(contact, sets);
        let none = BridgeScenario {
            contact: ContactModel::None,
            ..sc.clone()
        };
        g.bench_function(name, |b| {
            b.iter(|| {
                let r = solve(black_box(&sc), black_box(&motion)).expect("solves");
                let e = estimate_error(&sc, &motion, &r, Control::never()).ok();
                (r, e, solve(&none, &motion).expect("solves"))
            })
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    targets = one_solve, whole_run
}
criterion_main!(benches);
