//! The paper's reading of Sears (delayed planes): what an independent reference implementation found (docs/numerics.md),
//! and where the reading creates energy.

mod common;
use common::{rel, run};
use pounding::model::contact::LawKind;
use pounding::model::impact::Warning;
use pounding::model::impact::{ModelKind, solve};
use pounding::model::scenario::ImpactScenario;

fn peak_with_zone_scale(scale: f64) -> f64 {
    let mut sc = ImpactScenario::default();
    sc.contact.zone_scale = scale;
    run(ModelKind::Sears, &sc).peak_force_n.unwrap()
}

#[test]
fn zone_length_changes_the_peak_force_as_the_reference_found() {
    // The reference (1 m / 2 m rods): x0.01 -3.5%, x2 +3.4%, x5 +22%, x10 +53%, quoted to 2 digits.
    let base = peak_with_zone_scale(1.0);
    for (scale, reference, tol) in [
        (0.01, -3.5, 0.05),
        (2.0, 3.4, 0.05),
        (5.0, 22.0, 0.5),
        (10.0, 53.0, 1.0),
    ] {
        let change = 100.0 * (peak_with_zone_scale(scale) / base - 1.0);
        assert!(
            (change - reference).abs() <= tol,
            "x{scale}: {change:.2}% vs reference {reference}%"
        );
    }
}

fn linear_rods(k: f64) -> ImpactScenario {
    let mut sc = ImpactScenario::default();
    sc.contact.law = LawKind::Linear;
    sc.contact.stiffness = Some(k);
    sc
}

#[test]
fn soft_linear_contact_rattles_with_a_negative_first_contact_restitution() {
    // The reference: kL = 1.57e10 N/m rattles, first-contact e = -0.59.
    let r = run(ModelKind::Sears, &linear_rods(1.57e10));
    assert!(
        (r.restitution_first_contact + 0.59).abs() < 0.01,
        "first-contact e = {}",
        r.restitution_first_contact
    );
    assert!(r.contacts.len() >= 2, "the bars must touch again");
    assert!(
        r.restitution >= 0.0,
        "the run goes on until the bars separate for good"
    );
}

/// An independent integration of the same model for a contact that ends before any reflection
/// returns: delta(t) = w t - (1/Z1 + 1/Z2) Phi(t - tau), tau = d / c, with the lag an exact whole
/// number of (tiny) steps, so no interpolation at all.
fn delay_equation_restitution(sc: &ImpactScenario, k: f64, steps_per_lag: usize) -> f64 {
    let (c, z) = (sc.bar1.wave_speed_m_s(), sc.bar1.impedance_n_s_m());
    let tau = sc.zone_lengths_m()[0] / c;
    let dt = tau / steps_per_lag as f64;
    let w = sc.approach_velocity_m_s();
    let (mut phi, mut force) = (vec![0.0], vec![0.0]);
    let mut n = 0;
    loop {
        n += 1;
        let lagged = if n >= steps_per_lag {
            phi[n - steps_per_lag]
        } else {
            0.0
        };
        let delta = w * n as f64 * dt - 2.0 / z * lagged;
        let f = if delta > 0.0 { k * delta } else { 0.0 };
        phi.push(phi[n - 1] + 0.5 * dt * (force[n - 1] + f));
        force.push(f);
        if delta <= 0.0 {
            break;
        }
    }
    phi[n] / (sc.effective_mass_kg() * w) - 1.0
}

#[test]
fn stiff_paper_reading_creates_energy_and_an_independent_integration_agrees() {
    let sc = linear_rods(1e12);
    let r = run(ModelKind::Sears, &sc);
    // The contact ends long before a reflection (2 (L - d) / c = 0.34 ms) comes back.
    assert!(r.contact_duration_s < 0.1e-3);
    let independent = delay_equation_restitution(&sc, 1e12, 2000);
    assert!(
        rel(r.restitution, independent) < 1e-4,
        "e = {} vs independent {independent}",
        r.restitution
    );
    // The reference quotes e = 7.66 here; this solver and the brute-force delay equation
    // above agree on 7.283 at every step size, so the difference lies in the reference's set-up.
    assert!((r.restitution - 7.283).abs() < 1e-3);
    let d = r.sears.unwrap();
    assert!(d.creates_energy && d.a_tau > std::f64::consts::FRAC_PI_2);
    assert!(r.energy.balance_error > 1.0);
    assert!(
        r.warnings
            .iter()
            .any(|w| matches!(w, Warning::PaperCreatesEnergy { .. }))
    );
}

#[test]
fn paper_reading_base_case_is_well_behaved() {
    let r = run(ModelKind::Sears, &ImpactScenario::default());
    let d = r.sears.unwrap();
    // The reference: a tau about 0.13 for Hertz steel rods at 1 m/s.
    assert!(
        d.a_tau > 0.1 && d.a_tau < 1.0 / std::f64::consts::E,
        "a tau = {}",
        d.a_tau
    );
    assert!(!d.creates_energy);
    assert!(r.energy.balance_error.abs() < 0.01);
}

#[test]
fn paper_reading_is_undefined_when_the_zone_exceeds_twice_the_bar() {
    let mut sc = ImpactScenario::default();
    sc.bar1.length_m = 0.05;
    let err = solve(ModelKind::Sears, &sc).unwrap_err().to_string();
    assert!(
        err.contains("contact.zone_scale") && err.contains("undefined"),
        "{err}"
    );
}

#[test]
fn hertz_at_high_velocity_overshoots_the_wave_force() {
    // a tau > 1/e: the paper reading overshoots Z1 Z2/(Z1 + Z2) (v1 - v2). The reference
    // quotes 7.6% at 100 m/s; this solver gives 7.32%, converged in the step (2 us to 0.25 us).
    let mut sc = ImpactScenario::default();
    sc.bar1.velocity_m_s = 100.0;
    let r = run(ModelKind::Sears, &sc);
    let over = r.peak_force_n.unwrap() / common::wave_force(&sc) - 1.0;
    assert!(over > 0.07 && over < 0.08, "overshoot {over}");
    assert!(r.sears.unwrap().a_tau > 1.0 / std::f64::consts::E);
}

#[test]
fn the_a_tau_label_never_calls_a_run_that_created_energy_well_behaved() {
    use pounding::io::preset;
    use pounding::io::settings::ImpactSetup;
    use pounding::model::impact::ENERGY_CREATION_TOL;
    let mut created = 0;
    for k in [1e8, 1e9, 1.5e9, 2e9, 5e9, 2e10] {
        let mut s: ImpactSetup = preset::load_for("stiff-linear", "impact").expect("shipped");
        s.apply_assignment(&format!("contact.stiffness={k:e}"))
            .unwrap();
        s.apply_assignment("sears.reading=paper").unwrap();
        let r = run(ModelKind::Sears, &s.scenario);
        let d = r.sears.expect("a Sears run");
        let made = r.energy.balance_error > ENERGY_CREATION_TOL;
        created += usize::from(made);
        assert_eq!(
            d.regime().contains("created energy"),
            made,
            "k = {k:e}: a tau {}, balance {:+.3e}, label '{}'",
            d.a_tau,
            r.energy.balance_error,
            d.regime()
        );
        if d.a_tau < (-1f64).exp() && made {
            // The case a lecturer saw: a tau below 1/e and energy created all the same.
            assert!(!d.regime().contains("well behaved"), "k = {k:e}");
        }
    }
    assert!(created > 0, "the ladder reaches a run that creates energy");
}
