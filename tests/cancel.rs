//! Solves stop when their control is cancelled: the window cancels a running solve when newer
//! inputs arrive, and must not wait for a long one to finish.

use pounding::model::building::{BuildingScenario, solve_with as solve_buildings};
use pounding::model::control::Control;
use pounding::model::impact::{ModelKind, SolveError, solve_with};
use pounding::model::scenario::ImpactScenario;
use std::time::{Duration, Instant};

/// Runs `solve` with a control cancelled from another thread after 50 ms; the outcome and how
/// long after the cancel it came.
fn cancelled_after_50ms<T>(solve: impl FnOnce(&Control) -> T) -> (T, Duration) {
    let control = Control::new();
    std::thread::scope(|s| {
        s.spawn(|| {
            std::thread::sleep(Duration::from_millis(50));
            control.cancel();
        });
        let start = Instant::now();
        let out = solve(&control);
        (
            out,
            start.elapsed().saturating_sub(Duration::from_millis(50)),
        )
    })
}

#[test]
fn long_impact_solves_stop_within_a_frame_of_a_cancel() {
    let mut sc = ImpactScenario::default();
    // Twenty million steps of each model: seconds to minutes if nothing stopped them.
    sc.solver.dt_s = 1e-13;
    sc.solver.refine = false;
    sc.solver.max_steps = 20_000_000;
    // (FE at its default mesh: 4e9 node updates, just within its work budget.)
    for model in [ModelKind::Sears, ModelKind::LumpedHertz, ModelKind::Fe] {
        let (out, late) = cancelled_after_50ms(|c| solve_with(model, &sc, c));
        assert!(
            matches!(out, Err(SolveError::Cancelled)),
            "{}: {:?}",
            model.name(),
            out.map(|r| r.stats.steps)
        );
        assert!(
            late < Duration::from_millis(500),
            "{}: {late:?} late",
            model.name()
        );
    }
}

#[test]
fn a_long_building_solve_stops_within_a_frame_of_a_cancel_and_reports_progress() {
    let mut sc = BuildingScenario::paper();
    sc.tolerance = 1e-12;
    let motion = pounding::io::motion::built_in("elcentro-1940").unwrap();
    let control = Control::new();
    std::thread::scope(|s| {
        s.spawn(|| {
            // Progress moves before the cancel.
            let start = Instant::now();
            while control.fraction() == 0.0 && start.elapsed() < Duration::from_secs(20) {
                std::thread::sleep(Duration::from_millis(1));
            }
            std::thread::sleep(Duration::from_millis(50));
            control.cancel();
        });
        let out = solve_buildings(&sc, &motion, &control);
        assert!(
            matches!(out, Err(SolveError::Cancelled)),
            "{:?}",
            out.map(|r| r.stats)
        );
    });
    assert!(control.fraction() > 0.0 && control.fraction() < 1.0);
    let (out, late) = cancelled_after_50ms(|c| solve_buildings(&sc, &motion, c));
    assert!(matches!(out, Err(SolveError::Cancelled)));
    assert!(late < Duration::from_millis(500), "{late:?} late");
}
