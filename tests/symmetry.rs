//! Swapping the bars (mirror image: bar 2 becomes the left bar, every velocity changes sign)
//! must not change the impact.

mod common;
use common::{rel, run};
use pounding::model::impact::ModelKind;
use pounding::model::scenario::{ImpactScenario, Reading};

#[test]
fn swapping_the_bars_mirrors_the_result_in_every_model() {
    let mut sc = ImpactScenario::default();
    sc.bar2.added_mass_kg = 30.0;
    sc.bar2.section = pounding::model::bar::Section::Circular { radius_m: 0.06 };
    for model in ModelKind::ALL {
        for reading in Reading::ALL {
            if model != ModelKind::Sears && reading != Reading::Paper {
                continue;
            }
            let mut a = sc;
            a.reading = reading;
            let b = a.mirrored();
            let (ra, rb) = (run(model, &a), run(model, &b));
            let tag = format!("{} {}", model.name(), reading.name());
            assert!(
                (ra.restitution - rb.restitution).abs() < 1e-12,
                "{tag}: e {} vs {}",
                ra.restitution,
                rb.restitution
            );
            assert!(rel(rb.impulse_ns, ra.impulse_ns) < 1e-12, "{tag}: impulse");
            assert!(
                (ra.contact_duration_s - rb.contact_duration_s).abs() < 1e-15,
                "{tag}: duration"
            );
            assert_eq!(ra.force_n.len(), rb.force_n.len(), "{tag}");
            for (fa, fb) in ra.force_n.iter().zip(&rb.force_n) {
                assert!(
                    (fa - fb).abs() <= 1e-9 * ra.peak_force_n.unwrap_or(1.0).max(1.0),
                    "{tag}: force {fa} vs {fb}"
                );
            }
            // The mirror image's bar 1 is the original bar 2, moving the other way.
            assert!(
                rel(-rb.velocities_after_m_s[0], ra.velocities_after_m_s[1]) < 1e-12
                    || ra.velocities_after_m_s[1].abs() < 1e-12,
                "{tag}"
            );
        }
    }
}
