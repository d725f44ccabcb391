//! Where the energy is over an impact: the parts sum to the total at every sample, the
//! energy-consistent models keep the initial energy throughout, and the last sample is the
//! reported final state.

mod common;
use common::{rel, run};
use pounding::model::impact::ModelKind;
use pounding::model::impact::energy::energy_history;
use pounding::model::scenario::{ImpactScenario, Reading};

fn cases() -> Vec<(String, ModelKind, ImpactScenario)> {
    let mut out = vec![];
    for reading in Reading::ALL {
        for l2 in [1.0, 2.0, 10.0] {
            let mut sc = ImpactScenario {
                reading,
                ..Default::default()
            };
            sc.bar2.length_m = l2;
            out.push((
                format!("sears {} 1 m on {l2} m", reading.name()),
                ModelKind::Sears,
                sc,
            ));
        }
    }
    for model in [
        ModelKind::Wave,
        ModelKind::LumpedHertz,
        ModelKind::LumpedLinear,
        ModelKind::Kelvin,
        ModelKind::Stereo,
        ModelKind::Fe,
    ] {
        out.push((model.name().to_string(), model, ImpactScenario::default()));
    }
    out
}

#[test]
fn the_parts_sum_to_the_total_and_consistent_models_keep_the_initial_energy_throughout() {
    for (name, model, sc) in cases() {
        let r = run(model, &sc);
        let h = energy_history(&sc, &r, 400);
        assert!(h.time_s.len() >= 2, "{name}");
        let initial = r.energy.initial_j;
        let relative = {
            let [m1, m2] = r.masses_kg;
            let w = sc.approach_velocity_m_s();
            0.5 * m1 * m2 / (m1 + m2) * w * w
        };
        for k in 0..h.time_s.len() {
            let parts = [
                h.rigid_kinetic_j[k],
                h.wave_j[k],
                h.contact_j[k],
                h.dissipated_j[k],
            ];
            assert!(parts.iter().all(|p| p.is_finite()), "{name}: sample {k}");
            let sum: f64 = parts.iter().sum();
            assert_eq!(
                sum,
                h.total_j(k),
                "{name}: the total is the sum of the parts"
            );
            if let Some(by_bar) = &h.wave_by_bar_j {
                assert!(
                    rel(by_bar[0][k] + by_bar[1][k], h.wave_j[k]) < 1e-12
                        || h.wave_j[k].abs() < 1e-12 * initial
                );
            }
            // Measured against the energy an impact can move (the relative motion's).
            let drift = (h.total_j(k) - initial) / relative;
            let consistent = model != ModelKind::Sears || sc.reading != Reading::Paper;
            if consistent {
                assert!(
                    drift.abs() < 1e-3,
                    "{name}: total off by {drift:.2e} at t = {:e} s",
                    h.time_s[k]
                );
            }
        }
        // The last sample is the reported end state.
        let last = h.time_s.len() - 1;
        let [m1, m2] = r.masses_kg;
        let [u1, u2] = r.velocities_after_m_s;
        let rigid = 0.5 * m1 * u1 * u1 + 0.5 * m2 * u2 * u2;
        assert!(
            rel(h.rigid_kinetic_j[last], rigid) < 1e-12,
            "{name}: rigid {} vs {rigid}",
            h.rigid_kinetic_j[last]
        );
        assert!(
            rel(h.dissipated_j[last], r.energy.dissipated_j) < 1e-12
                || r.energy.dissipated_j == 0.0,
            "{name}"
        );
        if r.waves.is_some() {
            assert!(
                (h.wave_j[last] - r.energy.vibration_j).abs() < 1e-9 * initial,
                "{name}: waves {} vs {}",
                h.wave_j[last],
                r.energy.vibration_j
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
