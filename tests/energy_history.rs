//! Where the energy is over an impact, checked against counts the history is not made from:
//! - the d'Alembert models (Sears, wave theory): each bar's energy integrated from its stress and
//!   velocity fields, bar by bar, at instants through the run;
//! - finite elements: the kinetic and strain energy of the solver's own elements, against the
//!   initial energy;
//! - the lumped models: their rigid motion, spring and dashpot against the initial energy.

mod common;
use common::{run, simpson};
use pounding::model::field::BarWaves;
use pounding::model::impact::energy::energy_history;
use pounding::model::impact::{ImpactResult, ModelKind};
use pounding::model::scenario::{ImpactScenario, Reading};

fn sears_cases() -> Vec<(String, ImpactScenario)> {
    let mut out = vec![];
    for reading in Reading::ALL {
        for l2 in [1.0, 2.0, 10.0] {
            let mut sc = ImpactScenario {
                reading,
                ..Default::default()
            };
            sc.bar2.length_m = l2;
            out.push((format!("sears {} 1 m on {l2} m", reading.name()), sc));
        }
    }
    out
}

/// The energy an impact can move: the relative motion's kinetic energy.
fn relative_j(sc: &ImpactScenario, r: &ImpactResult) -> f64 {
    let [m1, m2] = r.masses_kg;
    let w = sc.approach_velocity_m_s();
    0.5 * m1 * m2 / (m1 + m2) * w * w
}

/// Simpson points for a field: eight per distance a wave runs in one step (the field is
/// piecewise linear between force samples; fewer alias the pulse, see tests/properties.rs).
fn points(w: &BarWaves, dt_s: f64) -> usize {
    // Wave theory takes no steps: its field is piecewise constant between a few events, and a
    // fixed fine rule resolves it.
    if dt_s <= 0.0 {
        return 20_000;
    }
    ((8.0 * w.length_m() / (w.wave_speed_m_s * dt_s)).ceil() as usize)
        .max(2000)
        .next_multiple_of(2)
}

/// The energy of a bar's elastic body from its stress and velocity fields: the kinetic and strain
/// energy densities integrated over the body, leaving out a collocated reading's massless zone
/// (whose strain is the contact's stored energy).
fn body_energy(w: &BarWaves, density: f64, youngs: f64, t: f64, n: usize) -> f64 {
    let zone = w.zone_length_m;
    simpson(w.body_length_m, n, |x| {
        let (v, sigma) = (w.velocity_m_s(zone + x, t), w.stress_pa(zone + x, t));
        0.5 * density * w.area_m2 * v * v + 0.5 * w.area_m2 * sigma * sigma / youngs
    })
}

#[test]
fn each_bars_rigid_and_wave_energy_equals_its_field_energy_through_the_run() {
    let mut cases = sears_cases();
    cases.push(("wave".into(), ImpactScenario::default()));
    for (name, sc) in cases {
        let model = if name == "wave" {
            ModelKind::Wave
        } else {
            ModelKind::Sears
        };
        let r = run(model, &sc);
        let waves = r.waves.as_ref().expect("a d'Alembert model keeps waves");
        let h = energy_history(&sc, &r, 24);
        let by_bar = h.wave_by_bar_j.as_ref().expect("each bar's waves");
        let bars = [sc.bar1, sc.bar2];
        let scale = relative_j(&sc, &r);
        let initial = r.energy.initial_j;
        for (k, &t) in h.time_s.iter().enumerate() {
            let j = r.impulse_at(t);
            let u = r.rigid_velocities_at(t);
            let mut total_fields = 0.0;
            for i in 0..2 {
                let field = body_energy(
                    &waves[i],
                    bars[i].effective_density_kg_m3(),
                    bars[i].material.youngs_modulus_pa,
                    t,
                    points(&waves[i], r.stats.dt_s),
                );
                let history = 0.5 * r.masses_kg[i] * u[i] * u[i] + by_bar[i][k];
                // The field is rebuilt from the force samples by interpolation: second order in
                // the step, within 1e-4 of the movable energy at the 1 us step.
                let off = (history - field) / scale;
                assert!(
                    off.abs() < 1e-4,
                    "{name}: bar {} at t = {t:e} s: history {history} J, field {field} J ({off:.1e}; impulse {j})",
                    i + 1
                );
                total_fields += field;
            }
            // The energy-consistent models keep the initial energy: the fields, the contact's
            // stored energy and what a damped contact took, against the energy before impact.
            let consistent = model == ModelKind::Wave || sc.reading.energy_consistent();
            if consistent {
                let drift = (total_fields + h.contact_j[k] + h.dissipated_j[k] - initial) / scale;
                assert!(
                    drift.abs() < 1e-3,
                    "{name}: fields off the initial energy by {drift:.2e} at t = {t:e} s"
                );
            }
        }
    }
}

#[test]
fn finite_elements_keep_the_initial_energy_in_their_own_elements() {
    for l2 in [1.0, 2.0, 10.0] {
        let mut sc = ImpactScenario::default();
        sc.bar2.length_m = l2;
        let r = run(ModelKind::Fe, &sc);
        let samples = r
            .elastic_samples
            .as_ref()
            .expect("finite elements count their elements' energy");
        assert!(samples.index.len() > 50, "{} samples", samples.index.len());
        let h = energy_history(&sc, &r, 400);
        let scale = relative_j(&sc, &r);
        let initial = r.energy.initial_j;
        for k in 0..h.time_s.len() {
            // Elastic = rigid + waves by the history's definition; the elastic count itself is
            // the elements', so this is the elements' energy plus the link's against the start.
            let elastic = h.rigid_kinetic_j[k] + h.wave_j[k];
            let drift = (elastic + h.contact_j[k] - initial) / scale;
            // The leapfrog keeps its own energy exactly for the chains; the link, treated by the
            // average acceleration, swaps energy with them to second order in the step.
            assert!(
                drift.abs() < 1e-3,
                "1 m on {l2} m: elements and link off the initial energy by {drift:.2e} at t = {:e} s",
                h.time_s[k]
            );
            // The product-form kinetic energy and the impulse's rigid motion differ to second
            // order in the step: waves never fall below that.
            assert!(
                h.wave_j[k] >= -1e-4 * scale,
                "waves below zero: {}",
                h.wave_j[k]
            );
        }
    }
}

#[test]
fn finite_element_waves_match_the_wave_models_after_a_long_bar_is_struck() {
    // 1 m on 10 m: wave theory leaves e = 1/10 and 99% of the movable energy in the waves. The
    // finite elements count their waves from their own nodes; the Sears end reading from its
    // d'Alembert fields. Two different discretisations of the same bars agree on where the
    // energy went.
    let mut sc = ImpactScenario::default();
    sc.bar2.length_m = 10.0;
    sc.reading = Reading::End;
    let fe = run(ModelKind::Fe, &sc);
    let sears = run(ModelKind::Sears, &sc);
    let last = |r: &ImpactResult| {
        let h = energy_history(&sc, r, 50);
        h.wave_j[h.time_s.len() - 1]
    };
    let scale = relative_j(&sc, &fe);
    let (w_fe, w_sears) = (last(&fe), last(&sears));
    assert!(
        w_sears > 0.5 * scale,
        "Sears keeps {w_sears} of {scale} J in waves"
    );
    // FE's mesh (100 segments a bar) disperses the pulse, but the energy it leaves in the
    // waves is fixed by the impulse: within 2% of the movable energy.
    assert!(
        (w_fe - w_sears).abs() < 0.02 * scale,
        "waves after the impact: FE {w_fe} J, Sears {w_sears} J"
    );
}

#[test]
fn the_lumped_models_keep_the_initial_energy_in_motion_spring_and_dashpot() {
    for model in [
        ModelKind::LumpedHertz,
        ModelKind::LumpedLinear,
        ModelKind::Kelvin,
        ModelKind::Stereo,
    ] {
        let sc = ImpactScenario::default();
        let r = run(model, &sc);
        let h = energy_history(&sc, &r, 400);
        let scale = relative_j(&sc, &r);
        assert!(h.wave_j.iter().all(|w| *w == 0.0), "{model:?} has no waves");
        for k in 0..h.time_s.len() {
            let total = h.rigid_kinetic_j[k] + h.contact_j[k] + h.dissipated_j[k];
            let drift = (total - r.energy.initial_j) / scale;
            assert!(
                drift.abs() < 1e-3,
                "{}: off the initial energy by {drift:.2e} at t = {:e} s",
                model.name(),
                h.time_s[k]
            );
        }
        // A damped contact ends having taken 1 - e^2 of the movable energy, e the run's own
        // restitution (from its impulse; the dissipation is the dashpot's integral).
        if model == ModelKind::Kelvin {
            let e = r.restitution;
            let taken = h.dissipated_j[h.time_s.len() - 1] / scale;
            assert!(
                (taken - (1.0 - e * e)).abs() < 0.01,
                "kelvin took {taken} of the movable energy, 1 - e^2 = {}",
                1.0 - e * e
            );
        }
    }
}

#[test]
fn a_long_second_bar_keeps_energy_in_its_waves_after_the_contact() {
    // 1 m on 10 m: bar 1's reflection ends the contact, and the waves left in bar 2 carry away
    // what the rigid motion lost (wave theory: e = 1/10, 99% of the relative kinetic energy).
    let mut sc = ImpactScenario::default();
    sc.bar2.length_m = 10.0;
    sc.reading = Reading::End;
    let r = run(ModelKind::Sears, &sc);
    let h = energy_history(&sc, &r, 400);
    let last = h.time_s.len() - 1;
    let by_bar = h
        .wave_by_bar_j
        .as_ref()
        .expect("Sears keeps each bar's waves");
    assert!(
        by_bar[1][last] > 0.5 * h.wave_j[last],
        "bar 2 holds {} of {}",
        by_bar[1][last],
        h.wave_j[last]
    );
    assert!(h.wave_j[last] > 0.5 * (r.energy.initial_j - h.rigid_kinetic_j[last]));
    assert_eq!(h.contact_j[last], 0.0);
}
