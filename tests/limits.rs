//! The limits the model states (docs/model.md), and closed forms of the peer models.

mod common;
use common::{rel, run, wave_force};
use pounding::model::bar::EndShape;
use pounding::model::contact::LawKind;
use pounding::model::impact::Warning;
use pounding::model::impact::{ModelKind, lumped};
use pounding::model::scenario::{ImpactScenario, Reading};

fn rods(l1: f64, l2: f64) -> ImpactScenario {
    let mut sc = ImpactScenario::default();
    sc.bar1.length_m = l1;
    sc.bar2.length_m = l2;
    sc
}

/// Force samples in the middle of the first contact lie within `tol` of `level`.
fn assert_plateau(r: &pounding::model::impact::ImpactResult, level: f64, tol: f64) {
    let d = r.contact_duration_s;
    let mid: Vec<f64> = r
        .time_s
        .iter()
        .zip(&r.force_n)
        .filter(|(t, _)| **t > 0.3 * d && **t < 0.7 * d)
        .map(|(_, f)| *f)
        .collect();
    assert!(mid.len() > 10);
    for f in mid {
        assert!(rel(f, level) < tol, "force {f} vs plateau {level}");
    }
    assert!(
        rel(r.peak_force_n.unwrap(), level) < tol,
        "peak {:?} vs {level}",
        r.peak_force_n
    );
}

#[test]
fn long_equal_bars_force_plateaus_at_half_impedance_times_velocity() {
    for reading in Reading::ALL {
        let mut sc = rods(10.0, 10.0);
        sc.reading = reading;
        let r = run(ModelKind::Sears, &sc);
        let z = sc.bar1.impedance_n_s_m();
        assert_plateau(&r, 0.5 * z * 1.0, 0.01);
    }
}

#[test]
fn long_bars_of_different_impedance_plateau_at_series_impedance_force() {
    let mut sc = rods(10.0, 20.0);
    sc.bar2.section = pounding::model::bar::Section::Circular { radius_m: 0.08 };
    sc.reading = Reading::End;
    let r = run(ModelKind::Sears, &sc);
    assert_plateau(&r, wave_force(&sc), 0.01);
}

#[test]
fn wave_theory_gives_restitution_one_for_equal_bars() {
    let sc = rods(2.0, 2.0);
    let r = run(ModelKind::Wave, &sc);
    assert!((r.restitution - 1.0).abs() < 1e-12, "e = {}", r.restitution);
    assert!(rel(r.contact_duration_s, sc.bar1.round_trip_s()) < 1e-12);
    assert!(rel(r.peak_force_n.unwrap(), wave_force(&sc)) < 1e-12);
    assert!(r.energy.balance_error.abs() < 1e-12);
}

#[test]
fn wave_theory_restitution_is_the_length_ratio_and_contact_lasts_one_short_round_trip() {
    for l2 in [2.0, 3.0, 7.5] {
        let sc = rods(1.0, l2);
        let r = run(ModelKind::Wave, &sc);
        assert!(
            (r.restitution - 1.0 / l2).abs() < 1e-12,
            "L2 = {l2}: e = {}",
            r.restitution
        );
        assert!(rel(r.contact_duration_s, sc.bar1.round_trip_s()) < 1e-12);
    }
}

#[test]
fn hertz_contact_leaves_equal_bars_just_below_one() {
    // docs/model.md: e about 0.988 for equal 2 m steel rods with Hertz contact.
    for reading in Reading::ALL {
        let mut sc = rods(2.0, 2.0);
        sc.reading = reading;
        let e = run(ModelKind::Sears, &sc).restitution;
        assert!(e > 0.98 && e < 1.0, "{}: e = {e}", reading.name());
        if reading == Reading::Paper {
            assert!(
                (e - 0.988).abs() < 0.001,
                "paper reading: e = {e}, reference 0.988"
            );
        }
    }
}

#[test]
fn long_bar_restitution_tends_slowly_to_the_length_ratio() {
    // docs/model.md: ratio 2 gives e = 0.68, 0.55, 0.52 for a short bar of 5, 20, 50 m.
    let mut last = 1.0;
    for (l, reference) in [(5.0, 0.68), (20.0, 0.55), (50.0, 0.52)] {
        let e = run(ModelKind::Sears, &rods(l, 2.0 * l)).restitution;
        assert!(
            (e - reference).abs() < 0.006,
            "L = {l}: e = {e}, reference {reference}"
        );
        assert!(e > 0.5 && e < last, "e must fall towards 0.5: {e}");
        last = e;
    }
}

#[test]
fn stiff_contact_on_long_bars_gives_the_length_ratio() {
    let mut sc = rods(5.0, 10.0);
    sc.contact.law = LawKind::Linear;
    sc.contact.stiffness = Some(1e12);
    sc.reading = Reading::End;
    let r = run(ModelKind::Sears, &sc);
    assert!((r.restitution - 0.5).abs() < 0.005, "e = {}", r.restitution);
}

#[test]
fn very_short_bars_behave_as_lumped_masses() {
    // Sears' zone (0.125 m) exceeds these bars, so the paper reading is undefined: use d -> 0.
    let mut sc = rods(0.01, 0.02);
    sc.reading = Reading::End;
    let sears = run(ModelKind::Sears, &sc);
    let lumped = run(ModelKind::LumpedHertz, &sc);
    assert!(sears.restitution > 0.99, "e = {}", sears.restitution);
    assert!(rel(sears.contact_duration_s, lumped.contact_duration_s) < 0.02);
    assert!(rel(sears.peak_force_n.unwrap(), lumped.peak_force_n.unwrap()) < 0.02);
}

#[test]
fn restitution_rises_towards_one_as_bars_shorten() {
    let mut last = 0.0;
    for l in [2.0, 0.5, 0.1, 0.02] {
        let mut sc = rods(l, 2.0 * l);
        sc.reading = Reading::End;
        let e = run(ModelKind::Sears, &sc).restitution;
        assert!(e > last, "L = {l}: e = {e} should exceed {last}");
        last = e;
    }
}

#[test]
fn lumped_hertz_matches_the_closed_form_compression_and_duration() {
    let sc = ImpactScenario::default();
    let r = run(ModelKind::LumpedHertz, &sc);
    let k = sc.hertz_law().unwrap().stiffness;
    let m = sc.effective_mass_kg();
    let w = sc.approach_velocity_m_s();
    let dmax = (5.0 * m * w * w / (4.0 * k)).powf(0.4);
    let max_approach = r.approach_m.iter().cloned().fold(0.0, f64::max);
    assert!(rel(max_approach, dmax) < 1e-6, "{max_approach} vs {dmax}");
    // Duration 2 (dmax / w) * integral_0^1 (1 - x^(5/2))^(-1/2) dx = (4/5) B(2/5, 1/2) dmax / w,
    // 2.9432752 dmax / w (often rounded to 2.9432).
    assert!(rel(r.contact_duration_s, 2.943_275_184_324_705 * dmax / w) < 1e-8);
    assert!(rel(r.peak_force_n.unwrap(), k * dmax.powf(1.5)) < 1e-6);
    assert!((r.restitution - 1.0).abs() < 1e-8);
}

#[test]
fn lumped_linear_matches_the_closed_form_duration_and_peak() {
    let mut sc = ImpactScenario::default();
    sc.contact.law = LawKind::Linear;
    sc.contact.stiffness = Some(2e9);
    let r = run(ModelKind::LumpedLinear, &sc);
    let m = sc.effective_mass_kg();
    assert!(
        rel(
            r.contact_duration_s,
            std::f64::consts::PI * (m / 2e9).sqrt()
        ) < 1e-9
    );
    assert!(rel(r.peak_force_n.unwrap(), (2e9 * m).sqrt()) < 1e-7);
}

#[test]
fn kelvin_voigt_restitution_matches_its_target() {
    for target in [0.1, 0.3, 0.65, 0.9, 1.0] {
        let mut sc = ImpactScenario::default();
        sc.contact.restitution = target;
        let r = run(ModelKind::Kelvin, &sc);
        assert!(
            (r.restitution - target).abs() < 1e-6,
            "target {target}: e = {}",
            r.restitution
        );
        assert!(
            r.force_n.iter().all(|&f| f >= 0.0),
            "a Kelvin-Voigt link here never pulls"
        );
        assert!(
            r.energy.balance_error.abs() < 1e-6,
            "dissipation accounted: {}",
            r.energy.balance_error
        );
    }
    // The calibration inverts the closed form.
    for xi in [0.01, 0.2, 0.9, 3.0, 1e3, 1e5, 1e7] {
        assert!(
            rel(
                lumped::kelvin_damping_ratio(lumped::kelvin_restitution(xi)),
                xi
            ) < 1e-9
        );
    }
}

#[test]
fn stereomechanics_exchanges_momentum_with_the_given_restitution() {
    let mut sc = ImpactScenario::default();
    sc.contact.restitution = 0.4;
    let r = run(ModelKind::Stereo, &sc);
    // Newton's law with momentum, written independently of the solver's impulse: the after
    // velocities are V1 = (m1 v1 + m2 v2 - m2 e w) / (m1 + m2), V2 = V1 + e w, with the masses
    // from the bars' own geometry (the solver's after-velocities are v -/+ J/m and would
    // balance momentum for any J).
    let (m1, m2) = (sc.bar1.mass_kg(), sc.bar2.mass_kg());
    let (u1, u2) = (sc.bar1.velocity_m_s, sc.bar2.velocity_m_s);
    let w = u1 - u2;
    let want1 = (m1 * u1 + m2 * u2 - m2 * 0.4 * w) / (m1 + m2);
    let want2 = want1 + 0.4 * w;
    let [v1, v2] = r.velocities_after_m_s;
    assert!((r.restitution - 0.4).abs() < 1e-12);
    assert!(
        rel(v1, want1) < 1e-12 && rel(v2, want2) < 1e-12,
        "{v1} {v2} against {want1} {want2}"
    );
    assert!(r.peak_force_n.is_none());
}

#[test]
fn energy_consistent_models_balance_their_energy() {
    let sc = ImpactScenario::default();
    let cases: Vec<(ModelKind, Reading, f64)> = vec![
        (ModelKind::Sears, Reading::End, 1e-5),
        (ModelKind::Sears, Reading::Collocated, 1e-5),
        (ModelKind::Wave, Reading::Paper, 1e-12),
        (ModelKind::LumpedHertz, Reading::Paper, 1e-8),
        (ModelKind::LumpedLinear, Reading::Paper, 1e-8),
        (ModelKind::Fe, Reading::Paper, 2e-2),
    ];
    for (model, reading, tol) in cases {
        let mut s = sc;
        s.reading = reading;
        let r = run(model, &s);
        assert!(
            r.energy.balance_error.abs() < tol,
            "{} {}: {}",
            model.name(),
            reading.name(),
            r.energy.balance_error
        );
    }
}

#[test]
fn bars_that_do_not_approach_give_no_impact() {
    let mut sc = ImpactScenario::default();
    sc.bar1.velocity_m_s = -0.5;
    for model in ModelKind::ALL {
        let r = run(model, &sc);
        assert!(!r.impact && r.contacts.is_empty(), "{}", model.name());
        assert_eq!(r.impulse_ns, 0.0);
        assert!(
            r.warnings
                .iter()
                .any(|w| matches!(w, Warning::NotApproaching { .. }))
        );
    }
}

#[test]
fn flat_ends_have_no_hertz_stiffness() {
    let mut sc = ImpactScenario::default();
    sc.bar1.end = EndShape::Flat;
    let err = pounding::model::impact::solve(ModelKind::Sears, &sc)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("contact.law") && err.contains("rounded"),
        "{err}"
    );
}

/// x solving (1 + x) e^-x = eps, by bisection: how many spring time constants the force of a
/// stiff spring between equal bars takes to fall to `eps` of its plateau once the short bar's
/// unloading wave is back.
fn decay_constants(eps: f64) -> f64 {
    let (mut a, mut b) = (0.0f64, 100.0f64);
    for _ in 0..200 {
        let x = 0.5 * (a + b);
        if (1.0 + x) * (-x).exp() > eps {
            a = x
        } else {
            b = x
        }
    }
    0.5 * (a + b)
}

#[test]
fn a_stiff_flat_contact_lasts_one_short_round_trip_though_the_bars_go_on_touching() {
    // 1 m on 2 m of equal steel, flat ends, a linear spring k: between equal impedances Z the
    // force obeys tau F' + F = Z v / 2 - F(t - 2 L1/c), tau = Z / (2 k), so it rises to Z v / 2
    // and, once the short bar's unloading wave is back at 2 L1/c, falls as (1 + s/tau) e^(-s/tau):
    // it reaches the loaded threshold eps = LOADED_FRACTION x tau later. The bars then touch at
    // zero force until the long bar's wave returns; that touching time is the second field.
    use pounding::model::impact::LOADED_FRACTION;
    for k in [1e12, 1e14] {
        let mut sc = rods(1.0, 2.0);
        sc.bar1.end = EndShape::Flat;
        sc.bar2.end = EndShape::Flat;
        sc.reading = Reading::End;
        sc.contact.law = LawKind::Linear;
        sc.contact.stiffness = Some(k);
        let r = run(ModelKind::Sears, &sc);
        let round_trip = sc.bar1.round_trip_s();
        let tau = 0.5 * sc.bar1.impedance_n_s_m() / k;
        let decay = decay_constants(LOADED_FRACTION) * tau;
        assert!(
            rel(r.contact_duration_s, round_trip) <= 1.05 * decay / round_trip,
            "k = {k:e}: duration {:e} s against 2 L1/c = {round_trip:e} s (decay {decay:e} s)",
            r.contact_duration_s
        );
        assert!(
            (r.contact_duration_s - round_trip - decay).abs() < 0.05 * decay,
            "k = {k:e}: duration {:e} s against 2 L1/c + decay = {:e} s",
            r.contact_duration_s,
            round_trip + decay
        );
        assert!(
            r.touching_duration_s > 1.2 * round_trip,
            "k = {k:e}: touching {:e} s",
            r.touching_duration_s
        );
    }
}
