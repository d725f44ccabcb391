//! Solves stop when their control is cancelled: the window cancels a running solve when newer
//! inputs arrive, and must not wait for a long one to finish.
//!
//! A solver looks at its control at least every `CHECK_EVERY` steps (microseconds of work), and
//! stops at the first look after a cancel. Both are checked by counting looks, not by timing a
//! thread that cancels: a timed test passes or fails with the machine's load. The time from a
//! cancel to the stop is a cost, measured in the benchmarks.

use pounding::model::building::{BuildingScenario, solve_with as solve_buildings};
use pounding::model::control::{CHECK_EVERY, Control};
use pounding::model::impact::{ModelKind, SolveError, solve_with};
use pounding::model::scenario::ImpactScenario;

const MODELS: [ModelKind; 3] = [ModelKind::Sears, ModelKind::LumpedHertz, ModelKind::Fe];

/// Twenty million steps of each model: seconds to minutes if nothing stopped them.
fn long_impact() -> ImpactScenario {
    let mut sc = ImpactScenario::default();
    sc.solver.dt_s = 1e-13;
    sc.solver.refine = false;
    sc.solver.max_steps = 20_000_000;
    sc
}

#[test]
fn long_impact_solves_stop_at_the_first_look_after_a_cancel() {
    // (FE at its default mesh: 4e9 node updates, just within its work budget.)
    for model in MODELS {
        let control = Control::stopping_at_look(3);
        let out = solve_with(model, &long_impact(), &control);
        assert!(
            matches!(out, Err(SolveError::Cancelled)),
            "{}: {:?}",
            model.name(),
            out.map(|r| r.stats.steps)
        );
        assert_eq!(
            control.looks(),
            3,
            "{}: no work after the cancel",
            model.name()
        );
        let f = control.fraction();
        assert!(f < 1e-2, "{}: stopped at {f} of the run", model.name());
    }
}

#[test]
fn impact_solvers_look_at_their_control_at_least_every_check_interval() {
    let mut sc = long_impact();
    sc.solver.max_steps = 2_000_000;
    sc.solver.dt_s = 2e-9;
    for model in [ModelKind::Sears, ModelKind::LumpedHertz] {
        let control = Control::new();
        let r = solve_with(model, &sc, &control).expect("a run of some 1e5 steps");
        let steps = r.stats.steps;
        assert!(steps > 20 * CHECK_EVERY, "{}: {steps} steps", model.name());
        assert!(
            control.looks() as usize >= steps / CHECK_EVERY,
            "{}: {} looks in {steps} steps",
            model.name(),
            control.looks()
        );
    }
}

#[test]
fn a_long_building_solve_stops_at_the_first_look_after_a_cancel_and_reports_progress() {
    let mut sc = BuildingScenario::paper();
    sc.tolerance = 1e-12;
    let motion = pounding::io::motion::built_in("elcentro-1940").unwrap();
    let control = Control::stopping_at_look(5);
    let out = solve_buildings(&sc, &motion, &control);
    assert!(
        matches!(out, Err(SolveError::Cancelled)),
        "{:?}",
        out.map(|r| r.stats)
    );
    assert_eq!(control.looks(), 5);
    assert!(control.fraction() > 0.0 && control.fraction() < 1.0);
}

/// The building solver looks at its control at least once every `CHECK_EVERY` steps it takes,
/// the free stretches' checks and walks and the contact steps alike (a free stretch of the exact
/// motion counts as one step however many grid points it spans).
#[test]
fn the_building_solver_looks_at_its_control_at_least_every_check_interval() {
    let sc = BuildingScenario::paper();
    let motion = pounding::io::motion::built_in("elcentro-1940").unwrap();
    let control = Control::new();
    let r = solve_buildings(&sc, &motion, &control).expect("the paper's buildings solve");
    let steps = r.stats.steps;
    assert!(steps > 10 * CHECK_EVERY, "{steps} steps");
    assert!(
        control.looks() as usize >= steps / CHECK_EVERY,
        "{} looks in {steps} steps",
        control.looks(),
    );
}
