//! `pounding buildings`' run with its checks side by side: each of the three is what it is when
//! made alone, and one cancel stops them all.

use pounding::model::building::{
    BuildingScenario, ContactModel, estimate_error, solve, solve_checked, solve_checked_with,
    solve_with,
};
use pounding::model::control::Control;
use pounding::model::error::SolveError;

fn record() -> pounding::model::motion::GroundMotion {
    pounding::io::motion::built_in("elcentro-1940")
        .expect("built in")
        .truncated(8.0)
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
        assert_eq!(r.max_pounding_force_n, alone.max_pounding_force_n);
        assert_eq!(r.force_n, alone.force_n);
        assert_eq!(r.time_s, alone.time_s);
        assert_eq!(r.floor_displacement_m, alone.floor_displacement_m);
        assert_eq!(r.peak_floor_displacement_m, alone.peak_floor_displacement_m);
        assert_eq!(r.peak_drift_ratio, alone.peak_drift_ratio);
        assert_eq!(format!("{:?}", r.impacts), format!("{:?}", alone.impacts));
        assert_eq!(format!("{:?}", r.energy), format!("{:?}", alone.energy));
        assert_eq!(r.stats.steps, alone.stats.steps);
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
    }
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
