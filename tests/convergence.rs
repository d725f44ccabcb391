//! Convergence: the Sears solver at its design order under step refinement, and the FE model
//! converging to the Sears end reading (d -> 0) as the mesh is refined. Observed orders are
//! printed (`cargo test --test convergence -- --nocapture`).

mod common;
use common::{rel, run};
use pounding::model::contact::LawKind;
use pounding::model::impact::Warning;
use pounding::model::impact::{ImpactResult, ModelKind};
use pounding::model::scenario::{ImpactScenario, Reading};

fn sears_at(reading: Reading, dt: f64) -> ImpactResult {
    let mut sc = ImpactScenario {
        reading,
        ..Default::default()
    };
    sc.solver.dt_s = dt;
    run(ModelKind::Sears, &sc)
}

fn show(v: &[f64]) -> String {
    v.iter()
        .map(|x| format!("{x:.2e}"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn orders(errors: &[f64]) -> Vec<f64> {
    errors.windows(2).map(|e| (e[0] / e[1]).log2()).collect()
}

/// Errors against a solve at dt / 64, for dt halving from 4 us to 0.5 us.
fn ladder(reading: Reading, quantity: impl Fn(&ImpactResult) -> f64) -> (Vec<f64>, Vec<f64>) {
    let reference = quantity(&sears_at(reading, 0.5e-6 / 64.0));
    let errors: Vec<f64> = [4e-6, 2e-6, 1e-6, 0.5e-6]
        .iter()
        .map(|&dt| rel(quantity(&sears_at(reading, dt)), reference))
        .collect();
    let p = orders(&errors);
    (errors, p)
}

#[test]
fn sears_converges_at_second_order_as_the_step_shrinks() {
    type Quantity = fn(&ImpactResult) -> f64;
    let quantities: [(&str, Quantity); 4] = [
        ("impulse", |r| r.impulse_ns),
        ("duration", |r| r.contact_duration_s),
        ("peak", |r| r.peak_force_n.unwrap()),
        ("e", |r| r.restitution),
    ];
    let mut failures = vec![];
    for reading in Reading::ALL {
        for (name, q) in quantities {
            let (errors, p) = ladder(reading, q);
            // Order over the whole ladder (4 us to 0.5 us), robust to the wobble that the
            // grid position of the separation instant puts on single halvings.
            let overall = (errors[0] / errors[errors.len() - 1]).log2() / (errors.len() - 1) as f64;
            eprintln!(
                "{:10} {name:8} errors [{}] orders [{}] overall {overall:.2}",
                reading.name(),
                show(&errors),
                show(&p)
            );
            if overall < 1.7 || errors[errors.len() - 1] > 1e-6 {
                failures.push(format!(
                    "{} {name}: overall order {overall:.2}, error {:.2e}",
                    reading.name(),
                    errors[errors.len() - 1]
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{failures:?}");
}

#[test]
fn sears_peak_force_reaches_one_part_per_million_at_the_papers_step() {
    for reading in Reading::ALL {
        let reference = sears_at(reading, 1e-6 / 64.0).peak_force_n.unwrap();
        let at_1us = sears_at(reading, 1e-6).peak_force_n.unwrap();
        eprintln!(
            "{:10} peak force error at 1 us: {:.2e}",
            reading.name(),
            rel(at_1us, reference)
        );
        assert!(rel(at_1us, reference) < 1e-6);
    }
}

/// L1 distance between two force histories, sampled on the first one's times and normalised by
/// the first's integral.
fn force_distance(a: &ImpactResult, b: &ImpactResult) -> f64 {
    let interp = |r: &ImpactResult, t: f64| {
        let k = r.time_s.partition_point(|&x| x <= t);
        if k == 0 || k >= r.time_s.len() {
            return 0.0;
        }
        let (t0, t1) = (r.time_s[k - 1], r.time_s[k]);
        let s = if t1 > t0 { (t - t0) / (t1 - t0) } else { 0.0 };
        r.force_n[k - 1] + s * (r.force_n[k] - r.force_n[k - 1])
    };
    let (mut num, mut den) = (0.0, 0.0);
    for w in a.time_s.windows(2) {
        let t = 0.5 * (w[0] + w[1]);
        let fa = interp(a, t);
        num += (fa - interp(b, t)).abs() * (w[1] - w[0]);
        den += fa.abs() * (w[1] - w[0]);
    }
    num / den
}

#[test]
fn finite_elements_converge_to_the_sears_end_reading_as_the_mesh_is_refined() {
    let mut sc = ImpactScenario {
        reading: Reading::End,
        ..Default::default()
    };
    sc.solver.dt_s = 0.05e-6;
    let sears = run(ModelKind::Sears, &sc);
    // FE at its own stable step (a fixed fraction of dx / c), so time and space refine together.
    sc.solver.dt_s = 1e-5;
    let mut force_errors = vec![];
    let mut e_errors = vec![];
    for n in [25, 50, 100, 200, 400, 800] {
        sc.fe.segments = n;
        let fe = run(ModelKind::Fe, &sc);
        force_errors.push(force_distance(&sears, &fe));
        e_errors.push((fe.restitution - sears.restitution).abs());
    }
    let pf = orders(&force_errors);
    let pe = orders(&e_errors);
    eprintln!(
        "FE vs Sears end: L1 force error [{}], rates [{}]",
        show(&force_errors),
        show(&pf)
    );
    eprintln!(
        "FE vs Sears end: restitution error [{}], rates [{}]",
        show(&e_errors),
        show(&pe)
    );
    for w in force_errors.windows(2) {
        assert!(
            w[1] < w[0],
            "force error must fall as the mesh is refined: {force_errors:?}"
        );
    }
    let mean = pf.iter().sum::<f64>() / pf.len() as f64;
    assert!(mean > 0.8, "observed rate {mean}");
    assert!(*force_errors.last().unwrap() < 0.01);
    assert!(*e_errors.last().unwrap() < 2e-3);
}

#[test]
fn stiff_linear_contact_stays_stable_and_accurate_at_coarse_steps() {
    // An explicit update needs dt < 2 / (kL (1/Z1 + 1/Z2)): 3 ns at 1e14 N/m. Ours runs at 1 us.
    for k in [1e12, 1e14, 1e16] {
        let mut sc = ImpactScenario::default();
        sc.contact.law = LawKind::Linear;
        sc.contact.stiffness = Some(k);
        sc.reading = Reading::End;
        sc.solver.refine = false;
        let r = run(ModelKind::Sears, &sc);
        let wave = run(ModelKind::Wave, &sc);
        assert!(r.force_n.iter().all(|f| f.is_finite() && *f >= 0.0));
        // No ringing: the force never exceeds the wave-theory plateau by more than 1%.
        let peak = r.peak_force_n.unwrap();
        assert!(
            peak < 1.01 * wave.peak_force_n.unwrap(),
            "k = {k:e}: peak {peak} vs wave {:?}",
            wave.peak_force_n
        );
        assert!(
            (r.restitution - wave.restitution).abs() < 0.01,
            "k = {k:e}: e {} vs wave {}",
            r.restitution,
            wave.restitution
        );
        assert!(
            r.energy.balance_error.abs() < 0.01,
            "k = {k:e}: balance {}",
            r.energy.balance_error
        );
        assert!(
            r.warnings
                .iter()
                .any(|w| matches!(w, Warning::StepKept { .. } | Warning::StepRefined { .. }))
        );
    }
}

#[test]
fn a_step_too_coarse_for_the_contact_is_refined_and_reported() {
    let mut sc = ImpactScenario::default();
    sc.contact.law = LawKind::Linear;
    sc.contact.stiffness = Some(1e12);
    sc.reading = Reading::End;
    let r = run(ModelKind::Sears, &sc);
    let from = r.stats.refined_from_s.expect("refined");
    assert_eq!(from, 1e-6);
    assert!(r.stats.dt_s < 0.2e-6);
    assert!(
        r.warnings
            .iter()
            .any(|w| matches!(w, Warning::StepRefined { .. }))
    );
}

#[test]
fn each_results_error_estimate_tracks_its_true_error() {
    use pounding::model::impact::estimate::estimate_error;
    for reading in Reading::ALL {
        let sc = ImpactScenario {
            reading,
            ..Default::default()
        };
        let r = run(ModelKind::Sears, &sc);
        let est = estimate_error(ModelKind::Sears, &sc, &r).unwrap();
        let reference = sears_at(reading, 1e-6 / 64.0);
        let truth = rel(r.peak_force_n.unwrap(), reference.peak_force_n.unwrap());
        let ratio = est.peak_force / truth;
        eprintln!(
            "{:10} peak force: estimated {:.2e}, true {truth:.2e}",
            reading.name(),
            est.peak_force
        );
        assert!(
            ratio > 0.3 && ratio < 3.0,
            "{}: estimate {} against {truth}",
            reading.name(),
            est.peak_force
        );
    }
}
