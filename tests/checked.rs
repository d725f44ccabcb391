//! `pounding buildings`' run with its checks side by side: each of the three is what it is when
//! made alone, and one cancel stops them all.

use pounding::model::building::{
    BuildingResult, BuildingScenario, ContactModel, estimate_error, solve, solve_checked,
    solve_checked_summary, solve_checked_with, solve_with,
};
use pounding::model::control::Control;
use pounding::model::error::SolveError;

fn record() -> pounding::model::motion::GroundMotion {
    pounding::io::motion::built_in("elcentro-1940")
        .expect("built in")
        .truncated(8.0)
}

/// Asserts that two runs found the same, bit for bit: the max force, the floors' and drifts'
/// peaks, the impacts, the energy and the steps.
fn assert_same_findings(a: &BuildingResult, b: &BuildingResult) {
    assert_eq!(
        a.max_pounding_force_n.to_bits(),
        b.max_pounding_force_n.to_bits()
    );
    assert_eq!(
        format!("{:?}", a.peak_floor_displacement_m),
        format!("{:?}", b.peak_floor_displacement_m)
    );
    assert_eq!(
        format!("{:?}", a.peak_drift_ratio),
        format!("{:?}", b.peak_drift_ratio)
    );
    assert_eq!(format!("{:?}", a.impacts), format!("{:?}", b.impacts));
    assert_eq!(format!("{:?}", a.energy), format!("{:?}", b.energy));
    assert_eq!(a.stats.steps, b.stats.steps);
}

#[test]
fn the_run_and_its_checks_made_side_by_side_are_bit_for_bit_those_made_one_after_another() {
    let m = record();
    for contact in [ContactModel::Sears, ContactModel::Kelvin] {
        let sc = BuildingScenario {
            contact,
            ..BuildingScenario::paper()
        };
        let checked = solve_checked(&sc, &m, &Control::new()).expect("runs");
        let alone = solve(&sc, &m).expect("runs");
        let estimate = estimate_error(&sc, &m, &alone).expect("estimates");
        let baseline = solve(
            &BuildingScenario {
                contact: ContactModel::None,
                ..sc.clone()
            },
            &m,
        )
        .expect("runs");
        let r = &checked.result;
        assert_same_findings(r, &alone);
        assert_eq!(r.force_n, alone.force_n);
        assert_eq!(r.time_s, alone.time_s);
        assert_eq!(r.floor_displacement_m, alone.floor_displacement_m);
        let e = checked.estimate.expect("an estimate");
        assert_eq!(
            (e.max_force, e.peak_displacement, e.impact_time),
            (
                estimate.max_force,
                estimate.peak_displacement,
                estimate.impact_time
            )
        );
        assert_eq!(e.impact_count_change, estimate.impact_count_change);
        assert_eq!(
            checked.baseline.peak_floor_displacement_m,
            baseline.peak_floor_displacement_m
        );
        assert_eq!(
            format!("{:?}", checked.baseline.peak_drift_ratio),
            format!("{:?}", baseline.peak_drift_ratio)
        );
        // The report reads no gaps: its run without contact does not search for them.
        assert!(checked.baseline.max_closing_m.is_empty());
        assert_eq!(baseline.max_closing_m.len(), sc.levels().len());
    }
}

#[test]
fn a_report_without_histories_finds_every_number_the_full_runs_find() {
    // Recording reads the state and never moves it: the summaries' impacts, peaks, forces,
    // energy and estimate are bit for bit the full runs', on the three-storey pair whose
    // contacts open and close at three levels.
    let setup: pounding::io::building_settings::BuildingSetup =
        pounding::io::preset::load_for("mdof-3-5", "buildings").expect("preset");
    let m = pounding::io::motion::load(&setup.motion).expect("record");
    let full = solve_checked(&setup.scenario, &m, &Control::new()).unwrap();
    let summary = solve_checked_summary(&setup.scenario, &m, &Control::new()).unwrap();
    assert!(!full.result.time_s.is_empty() && !full.baseline.time_s.is_empty());
    assert!(summary.result.time_s.is_empty() && summary.baseline.time_s.is_empty());
    assert_same_findings(&full.result, &summary.result);
    assert_same_findings(&full.baseline, &summary.baseline);
    assert!(full.result.max_pounding_force_n > 0.0);
    let (e, f) = (full.estimate.unwrap(), summary.estimate.unwrap());
    assert_eq!(e.max_force.to_bits(), f.max_force.to_bits());
    assert_eq!(e.peak_displacement.to_bits(), f.peak_displacement.to_bits());
}

#[test]
fn a_cancel_during_the_run_ends_the_run_and_its_checks_as_cancelled() {
    let m = record();
    let sc = BuildingScenario::paper();
    // How many times the run alone looks at its control: a cancel at its last look stops it at
    // a point of the work fixed in advance, and must stop the checks with it.
    let counting = Control::new();
    solve_with(&sc, &m, &counting).expect("runs");
    let looks = counting.looks();
    assert!(looks >= 2, "{looks} looks");
    let control = Control::stopping_at_look(looks);
    let checks = Control::new();
    let out = solve_checked_with(&sc, &m, &control, &checks);
    assert!(matches!(out, Err(SolveError::Cancelled)), "{out:?}");
    assert!(checks.cancelled(), "the checks were told to stop");
}

#[test]
fn checks_cancelled_on_their_own_end_the_whole_as_cancelled() {
    let m = record();
    let sc = BuildingScenario::paper();
    // The checks stop at their first look: the companion gives no estimate and the run
    // without contact no result, so the whole is cancelled (as the command was when the run
    // without contact failed after the run).
    let out = solve_checked_with(&sc, &m, &Control::new(), &Control::stopping_at_look(1));
    assert!(matches!(out, Err(SolveError::Cancelled)), "{out:?}");
}
