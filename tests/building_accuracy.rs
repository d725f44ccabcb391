//! Every number with its error: the building runs' default accuracy against runs refined
//! tenfold in every discretisation parameter, and their own error estimates against that.

use pounding::model::building::BuildingErrorEstimate;
use pounding::model::building::estimate::{compare, refined};
use pounding::model::building::{
    BuildingResult, BuildingScenario, ContactModel, SlabReading, Warning, estimate_error, solve,
};
use pounding::model::motion::GroundMotion;

fn el_centro() -> GroundMotion {
    pounding::io::motion::built_in("elcentro-1940")
        .expect("built in")
        .truncated(8.0)
}

fn run(sc: &BuildingScenario, m: &GroundMotion) -> BuildingResult {
    solve(sc, m).unwrap_or_else(|e| panic!("{}: {e}", sc.contact.name()))
}

/// The figures an estimate bounds, each as (what, the actual error, the estimate), printed.
fn errors_and_estimates(
    label: &str,
    actual: &BuildingErrorEstimate,
    estimate: &BuildingErrorEstimate,
) -> [(&'static str, f64, f64); 3] {
    eprintln!(
        "{label:9}: actual max force {:.2e}, peaks {:.2e}, impact times {:.2e}; estimated {:.2e}, {:.2e}, {:.2e}",
        actual.max_force,
        actual.peak_displacement,
        actual.impact_time,
        estimate.max_force,
        estimate.peak_displacement,
        estimate.impact_time
    );
    [
        ("max force", actual.max_force, estimate.max_force),
        (
            "peak displacements",
            actual.peak_displacement,
            estimate.peak_displacement,
        ),
        ("impact times", actual.impact_time, estimate.impact_time),
    ]
}

/// Whether a run was held to a coarser step by its step budget (and said so).
fn held_to_budget(r: &BuildingResult) -> bool {
    r.warnings
        .iter()
        .any(|w| matches!(w, Warning::GridOverBudget { .. }))
}

#[test]
fn every_element_is_within_1e_3_of_a_tenfold_refined_run_and_its_estimate_tracks_the_error() {
    let m = el_centro();
    for model in ContactModel::ALL {
        let sc = BuildingScenario {
            contact: model,
            ..BuildingScenario::paper()
        };
        let default = run(&sc, &m);
        let fine = run(&refined(&sc, 10.0), &m);
        let actual = compare(&default, &fine);
        let estimate = estimate_error(&sc, &m, &default).unwrap();
        let figures = errors_and_estimates(model.name(), &actual, &estimate);
        assert_eq!(
            actual.impact_count_change,
            0,
            "{}: the impacts are the same",
            model.name()
        );
        for (what, a, e) in figures {
            assert!(a <= 1e-3, "{}: {what} off by {a:e}", model.name());
            // Where the error has fallen to round-off there is nothing to estimate.
            if a > 1e-9 {
                assert!(
                    e >= a / 3.0,
                    "{}: {what} estimated {e:e} against an actual {a:e}",
                    model.name()
                );
            }
        }
    }
}

#[test]
fn the_first_impact_starts_where_the_exact_free_motion_closes_the_gap() {
    // Until the first contact both buildings move freely: their exact motion under the
    // piecewise-linear record, integrated here independently (each building's oscillator by its
    // closed form, sample interval by sample interval), gives the instant the gap closes.
    let m = el_centro();
    let sc = BuildingScenario {
        contact: ContactModel::Linear,
        ..BuildingScenario::paper()
    };
    let r = run(&sc, &m);
    let oscillator = |mass: f64, k: f64, zeta: f64| {
        let w = (k / mass).sqrt();
        let wd = w * (1.0 - zeta * zeta).sqrt();
        move |u: f64, v: f64, a0: f64, a1: f64, dt: f64, t: f64| {
            // u'' + 2 z w u' + w^2 u = -(a0 + (a1 - a0) s / dt): particular p + q s.
            let slope = -(a1 - a0) / dt;
            let q = slope / (w * w);
            let p = (-a0 - 2.0 * zeta * w * q) / (w * w);
            let (c0, v0) = (u - p, v - q);
            let e = (-zeta * w * t).exp();
            let (s, c) = (wd * t).sin_cos();
            let x = e * (c0 * c + (v0 + zeta * w * c0) / wd * s);
            let xd = e * (v0 * c - (zeta * w * v0 + w * w * c0) / wd * s);
            (x + p + q * t, xd + q)
        }
    };
    let left = oscillator(36_000.0, 1.16e7, 0.05);
    let right = oscillator(45_000.0, 7.11e6, 0.05);
    let (mut ul, mut vl, mut ur, mut vr) = (0.0, 0.0, 0.0, 0.0);
    let dt = m.dt_s;
    let mut touch = None;
    'outer: for i in 0..m.accel_m_s2.len() - 1 {
        let (a0, a1) = (m.accel_m_s2[i], m.accel_m_s2[i + 1]);
        let gap = |s: f64| left(ul, vl, a0, a1, dt, s).0 - right(ur, vr, a0, a1, dt, s).0 - 1e-3;
        // Fine scan, then bisection on the closed forms.
        let n = 2000;
        for j in 1..=n {
            let (s0, s1) = (dt * (j - 1) as f64 / n as f64, dt * j as f64 / n as f64);
            if gap(s0) <= 0.0 && gap(s1) > 0.0 {
                let (mut lo, mut hi) = (s0, s1);
                for _ in 0..80 {
                    let mid = 0.5 * (lo + hi);
                    if gap(mid) > 0.0 { hi = mid } else { lo = mid }
                }
                touch = Some(i as f64 * dt + hi);
                break 'outer;
            }
        }
        (ul, vl) = left(ul, vl, a0, a1, dt, dt);
        (ur, vr) = right(ur, vr, a0, a1, dt, dt);
    }
    let exact = touch.expect("the buildings touch");
    let got = r.contacts[0].start_s;
    eprintln!("first contact at {got:.12} s, exact {exact:.12} s");
    assert!((got - exact).abs() < 1e-9, "{got} against {exact}");
}

#[test]
fn the_undamped_end_reading_converges_to_the_independent_max_force() {
    // Undamped slabs in the end reading, the hardest of the paper's cases for the estimate
    // (the slabs ring between impacts): an independent calculation gives 4.393 MN.
    let m = el_centro();
    let sc = BuildingScenario {
        contact: ContactModel::Sears,
        reading: SlabReading::End,
        slab_damping: 0.0,
        merge_gap_s: 0.01,
        ..BuildingScenario::paper()
    };
    let r = run(&sc, &m);
    let f = r.max_pounding_force_n;
    assert!((f / 4.393e6 - 1.0).abs() < 1.5e-3, "{f:e}");
    let e = estimate_error(&sc, &m, &r).unwrap();
    assert!(e.max_force < 1e-3, "{e:?}");
}

#[test]
fn a_run_held_to_its_step_budget_still_bounds_its_error() {
    // A step budget too small for the contact's time scale holds the run to a coarser step (and
    // says so). Its error estimate must still refine that step, not the one the tolerance asked
    // for: a companion held to the same budget would take the same steps and estimate no error.
    let m = el_centro();
    let held = BuildingScenario {
        max_steps: 500_000,
        ..BuildingScenario::paper()
    };
    let r = run(&held, &m);
    assert!(held_to_budget(&r), "held to the budget: {:?}", r.warnings);
    let free = run(&BuildingScenario::paper(), &m);
    assert!(
        r.stats.fine_step_s > 2.0 * free.stats.fine_step_s,
        "{} against {}",
        r.stats.fine_step_s,
        free.stats.fine_step_s
    );
    let truth = run(&refined(&BuildingScenario::paper(), 10.0), &m);
    assert!(
        truth.warnings.is_empty(),
        "the reference is not held: {:?}",
        truth.warnings
    );
    let actual = compare(&r, &truth);
    let estimate = estimate_error(&held, &m, &r).unwrap();
    let figures = errors_and_estimates("held", &actual, &estimate);
    assert_eq!(actual.impact_count_change, 0);
    assert_eq!(estimate.impact_count_change, 0);
    for (what, a, e) in figures {
        assert!(a > 1e-9, "{what}: a coarse step has an error to estimate");
        assert!(e >= a, "{what} estimated {e:e} against an actual {a:e}");
    }
}

#[test]
fn a_run_the_budget_does_not_hold_has_the_same_estimate_whatever_the_budget() {
    // Between one and two times the grid's steps the run is not held, and its companion (twice
    // the steps) gets twice the run's budget, so it is not held either: a companion held there
    // would estimate a smaller error than the run has. The budget is the estimate's concern
    // only where the run itself is held.
    let m = el_centro();
    let sc = BuildingScenario::paper();
    let roomy = run(&sc, &m);
    let tight = BuildingScenario {
        max_steps: 1_500_000,
        ..BuildingScenario::paper()
    };
    let r = run(&tight, &m);
    assert!(r.warnings.is_empty(), "not held: {:?}", r.warnings);
    assert_eq!(r.stats.fine_step_s, roomy.stats.fine_step_s);
    let [a, b] = [(&sc, &roomy), (&tight, &r)].map(|(sc, r)| estimate_error(sc, &m, r).unwrap());
    assert_eq!(
        (a.max_force, a.peak_displacement, a.impact_time),
        (b.max_force, b.peak_displacement, b.impact_time)
    );
}

#[test]
fn a_run_at_the_tightest_tolerance_still_estimates_its_error() {
    // A tolerance of 1e-12 (the tightest accepted) holds the run to its step budget; its
    // companion halves the run's own step with twice the budget, so the run still comes with
    // an estimate.
    let m = el_centro().truncated(2.0);
    let sc = BuildingScenario {
        tolerance: 1e-12,
        max_steps: 200_000,
        ..BuildingScenario::paper()
    };
    let r = run(&sc, &m);
    assert!(held_to_budget(&r));
    let e = estimate_error(&sc, &m, &r).expect("an estimate");
    assert!(e.max_force > 0.0 && e.max_force.is_finite(), "{e:?}");
}
