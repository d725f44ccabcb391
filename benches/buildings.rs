//! Criterion benchmarks of the building runs on 8 s of the shipped El Centro 1940 record: each
//! contact element at the default tolerance (the paper's one-storey pair), the 3- against
//! 5-storey pair, the whole run `pounding buildings` makes (the run, its error estimate and the
//! run without contact), the gap that avoids pounding over 20 records, and yielding storeys
//! against elastic ones.

use criterion::{Criterion, criterion_group, criterion_main};
use pounding::io::building_settings::BuildingSetup;
use pounding::io::preset;
use pounding::model::building::{
    BuildingScenario, Checked, ContactModel, estimate_error, solve, solve_checked,
    solve_checked_summary,
};
use pounding::model::motion::GroundMotion;
use pounding::model::motion::synthetic::SyntheticSpec;
use pounding::study::Control;
use pounding::study::gaps::record_gaps;
use std::hint::black_box;

fn record() -> GroundMotion {
    pounding::io::motion::built_in("elcentro-1940")
        .expect("built in")
        .truncated(8.0)
}

/// The three- against five-storey pair as shipped.
fn mdof_3_5() -> BuildingScenario {
    preset::load_for::<BuildingSetup>("mdof-3-5", "buildings")
        .expect("shipped")
        .scenario
}

fn el_centro_8s(c: &mut Criterion) {
    let motion = record();
    let mut g = c.benchmark_group("buildings_8s");
    for model in ContactModel::ALL {
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

/// Three storeys against five (the mdof-3-5 preset): three floor-to-floor levels.
fn three_against_five(c: &mut Criterion) {
    let motion = record();
    let base = mdof_3_5();
    let mut g = c.benchmark_group("mdof_3_5_8s");
    g.sample_size(10);
    for model in [
        ContactModel::Linear,
        ContactModel::Sears,
        ContactModel::None,
    ] {
        let sc = BuildingScenario {
            contact: model,
            ..base.clone()
        };
        g.bench_function(model.name(), |b| {
            b.iter(|| solve(black_box(&sc), black_box(&motion)).expect("solves"))
        });
    }
    g.finish();
}

/// The paper's pair with yielding storeys (the preset: bilinear, its record and settling).
fn paper_yielding() -> (BuildingScenario, GroundMotion) {
    let setup: BuildingSetup =
        preset::load_for("paper-buildings-yielding", "buildings").expect("a shipped preset");
    let motion = pounding::io::motion::load(&setup.motion).expect("its record");
    (setup.scenario, motion)
}

/// What one `pounding buildings` makes: the run with its histories, its error estimate and the
/// run without contact (the report's figures aside), for the paper's pair with Sears and with
/// the linear spring, elastic and yielding, and the 3- against 5-storey pair with Sears.
fn whole_run(c: &mut Criterion) {
    let motion = record();
    let (yielding, settled) = paper_yielding();
    let mut g = c.benchmark_group("whole_run");
    g.sample_size(10);
    for (name, base, model, motion) in [
        (
            "paper_sears",
            BuildingScenario::paper(),
            ContactModel::Sears,
            &motion,
        ),
        (
            "paper_linear",
            BuildingScenario::paper(),
            ContactModel::Linear,
            &motion,
        ),
        ("mdof_3_5_sears", mdof_3_5(), ContactModel::Sears, &motion),
        (
            "paper_yielding_sears",
            yielding.clone(),
            ContactModel::Sears,
            &settled,
        ),
        (
            "paper_yielding_linear",
            yielding.clone(),
            ContactModel::Linear,
            &settled,
        ),
    ] {
        let sc = BuildingScenario {
            contact: model,
            ..base
        };
        let none = BuildingScenario {
            contact: ContactModel::None,
            ..sc.clone()
        };
        g.bench_function(name, |b| {
            b.iter(|| {
                let r = solve(black_box(&sc), black_box(motion)).expect("solves");
                let e = estimate_error(&sc, motion, &r).expect("estimates");
                (r, e, solve(&none, motion).expect("solves"))
            })
        });
    }
    g.finish();
}

/// A run with its checks, as [`solve_checked`] makes it.
type Checker = fn(
    &BuildingScenario,
    &GroundMotion,
    &Control,
) -> Result<Checked, pounding::model::error::SolveError>;

/// The same whole runs as `pounding buildings` makes them: the estimate's companion and the
/// run without contact on a second thread beside the run (`solve_checked`). The same
/// instructions; on two cores, about the companion's time.
fn whole_run_side_by_side(c: &mut Criterion) {
    let motion = record();
    let mut g = c.benchmark_group("whole_run_side_by_side");
    g.sample_size(10);
    for (name, base, model) in [
        (
            "paper_sears",
            BuildingScenario::paper(),
            ContactModel::Sears,
        ),
        (
            "paper_linear",
            BuildingScenario::paper(),
            ContactModel::Linear,
        ),
        ("mdof_3_5_sears", mdof_3_5(), ContactModel::Sears),
    ] {
        let sc = BuildingScenario {
            contact: model,
            ..base
        };
        // With the histories a window draws, and as `pounding buildings --json` runs it,
        // without the histories it never reads.
        for (suffix, checked) in [
            ("", solve_checked as Checker),
            ("_report", solve_checked_summary),
        ] {
            g.bench_function(format!("{name}{suffix}"), |b| {
                b.iter(|| {
                    checked(black_box(&sc), black_box(&motion), &Control::new()).expect("solves")
                })
            });
        }
    }
    g.finish();
}

/// `pounding gaps` over 20 records (El Centro and 19 synthetic ones), the 3- against 5-storey
/// pair, in parallel: from the records loaded to every record's gaps.
fn gaps_20_records(c: &mut Criterion) {
    let base = mdof_3_5();
    let mut motions = vec![record()];
    motions.extend((1..20).map(|seed| {
        SyntheticSpec {
            seed,
            ..SyntheticSpec::default()
        }
        .generate()
    }));
    let mut g = c.benchmark_group("gaps");
    g.sample_size(10);
    g.bench_function("mdof_3_5_20_records", |b| {
        b.iter(|| record_gaps(black_box(&base), &motions, &Control::new()).expect("runs"))
    });
    g.finish();
}

/// The yielding preset with `settings` (as `--set`) applied, and its record.
fn yielding_setup(settings: &[&str]) -> (BuildingScenario, GroundMotion) {
    let mut setup: BuildingSetup =
        preset::load_for("paper-buildings-yielding", "buildings").expect("a shipped preset");
    for s in settings {
        setup.apply_assignment(s).expect("a shipped key");
    }
    let motion = pounding::io::motion::load(&setup.motion).expect("its record");
    (setup.scenario, motion)
}

/// What yielding storeys cost against elastic ones, the same run otherwise: the paper's pair
/// (its yielding preset's record with settling) elastic, bilinear and Bouc-Wen (at the preset's
/// yield forces and at the smallest accepted, 1e-3 N, where the law saturates at once), and a
/// 10- against 10-storey pair. Its instruction counts come from `examples/building_loop` under
/// callgrind with the same settings (docs/numerics.md, "Yielding storeys").
fn yielding_against_elastic(c: &mut Criterion) {
    let mut g = c.benchmark_group("yielding");
    g.sample_size(10);
    let laws = |law: &str| {
        [
            format!("left.hysteresis={law}"),
            format!("right.hysteresis={law}"),
        ]
    };
    let mut cases: Vec<(String, Vec<String>)> = Vec::new();
    for law in ["elastic", "bilinear", "bouc-wen"] {
        cases.push((format!("paper_{law}"), laws(law).to_vec()));
        let mut tall = laws(law).to_vec();
        tall.extend(["left.storeys=10".into(), "right.storeys=10".into()]);
        cases.push((format!("10_10_{law}"), tall));
    }
    let mut small = laws("bouc-wen").to_vec();
    small.push("left.yield_forces=1e-3".into());
    cases.push(("paper_bouc_wen_fy_1e-3_linear".into(), small));
    for (name, settings) in cases {
        let refs: Vec<&str> = settings.iter().map(String::as_str).collect();
        let (mut sc, motion) = yielding_setup(&refs);
        if name.ends_with("_linear") {
            sc.contact = ContactModel::Linear;
        }
        g.bench_function(name, |b| {
            b.iter(|| solve(black_box(&sc), black_box(&motion)).expect("solves"))
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).warm_up_time(std::time::Duration::from_secs(1)).measurement_time(std::time::Duration::from_secs(3));
    targets = el_centro_8s, three_against_five, whole_run, whole_run_side_by_side, gaps_20_records,
        yielding_against_elastic
}
criterion_main!(benches);
