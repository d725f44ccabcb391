//! The stress and velocity field along the bars, from the force history (d'Alembert).

mod common;
use common::{field_energy, field_momentum, rel, run, wave_force};
use pounding::model::impact::ModelKind;
use pounding::model::scenario::{ImpactScenario, Reading};

#[test]
fn stress_front_travels_at_the_bar_wave_speed() {
    let sc = ImpactScenario::default();
    let r = run(ModelKind::Wave, &sc);
    let w2 = &r.waves.as_ref().unwrap()[1];
    let c = w2.wave_speed_m_s;
    let t = 0.3e-3;
    let front = c * t;
    let compression = -wave_force(&sc) / w2.area_m2;
    assert!(
        rel(w2.stress_pa(front - 0.01, t), compression) < 1e-12,
        "behind the front: compression"
    );
    assert_eq!(
        w2.stress_pa(front + 0.01, t),
        0.0,
        "ahead of the front: undisturbed"
    );
}

#[test]
fn compression_reflects_from_the_free_end_as_tension() {
    // Bar 2 (2 m) carries a pulse 2 m long (twice bar 1); at t = 4 m / c the part that came back
    // from its free end is tension of the same magnitude, near the contact end.
    let sc = ImpactScenario::default();
    let r = run(ModelKind::Wave, &sc);
    let w2 = &r.waves.as_ref().unwrap()[1];
    let t = 4.0 / w2.wave_speed_m_s;
    let tension = wave_force(&sc) / w2.area_m2;
    assert!(
        rel(w2.stress_pa(0.5, t), tension) < 1e-9,
        "{} vs {tension}",
        w2.stress_pa(0.5, t)
    );
}

#[test]
fn free_far_end_carries_no_stress_and_the_contact_end_carries_the_force() {
    for reading in Reading::ALL {
        let sc = ImpactScenario {
            reading,
            ..Default::default()
        };
        let r = run(ModelKind::Sears, &sc);
        for waves in r.waves.as_ref().unwrap() {
            for k in (0..r.time_s.len()).step_by(37) {
                let t = r.time_s[k];
                assert!(
                    waves.stress_pa(waves.length_m(), t).abs()
                        < 1e-6 * r.peak_force_n.unwrap() / waves.area_m2
                );
                let at_contact = -waves.stress_pa(0.0, t) * waves.area_m2;
                assert!(
                    (at_contact - r.force_n[k]).abs() < 1e-6 * r.peak_force_n.unwrap(),
                    "{}: {at_contact} vs {}",
                    reading.name(),
                    r.force_n[k]
                );
            }
        }
    }
}

#[test]
fn momentum_integrated_over_the_velocity_field_matches_the_impulse() {
    for reading in Reading::ALL {
        let sc = ImpactScenario {
            reading,
            ..Default::default()
        };
        let r = run(ModelKind::Sears, &sc);
        let bars = [sc.bar1, sc.bar2];
        for (i, waves) in r.waves.as_ref().unwrap().iter().enumerate() {
            // The collocated zone is massless: integrate over the body only.
            let density = bars[i].effective_density_kg_m3();
            let p = field_momentum(waves, density, r.end_s, 4000)
                - density * waves.area_m2 * waves.zone_length_m * waves.velocity_m_s(0.0, r.end_s);
            let expected = r.masses_kg[i] * r.velocities_after_m_s[i];
            assert!(
                (p - expected).abs() < 1e-4 * r.impulse_ns,
                "{} bar {}: {p} vs {expected}",
                reading.name(),
                i + 1
            );
        }
    }
}

#[test]
fn energy_integrated_over_the_field_matches_the_reported_split() {
    for reading in [Reading::End, Reading::Paper] {
        let sc = ImpactScenario {
            reading,
            ..Default::default()
        };
        let r = run(ModelKind::Sears, &sc);
        let bars = [sc.bar1, sc.bar2];
        let total: f64 = r
            .waves
            .as_ref()
            .unwrap()
            .iter()
            .zip(bars)
            .map(|(w, b)| {
                field_energy(
                    w,
                    b.effective_density_kg_m3(),
                    b.material.youngs_modulus_pa,
                    r.end_s,
                    4000,
                )
            })
            .sum();
        let reported = r.energy.rigid_body_j + r.energy.vibration_j;
        assert!(
            rel(total, reported) < 1e-4,
            "{}: field {total} vs reported {reported}",
            reading.name()
        );
    }
}
