//! A bridge run jumps over its free stretches (no joint force, frames exact, girders ringing in
//! closed form) and checks them only at a few points against bounds: it must find what walking
//! every grid point of them finds, to the bit, and what stepping every grid point finds, to
//! rounding; for every element, under uniform and travelling excitation, where girders unseat,
//! where their waves never decay or die within a round trip, on coarse grids.

use pounding::model::bridge::{BridgeResult, BridgeScenario, solve, solve_stepped, solve_walked};
use pounding::model::building::ContactModel;
use pounding::model::building::result::RawContact;

fn el_centro(seconds: f64) -> pounding::model::motion::GroundMotion {
    pounding::io::motion::built_in("elcentro-1940")
        .unwrap()
        .truncated(seconds)
}

/// |a - b| relative to `scale`.
fn off(a: f64, b: f64, scale: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / scale.abs().max(1e-300)
    }
}

fn largest(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// The largest relative difference of every result two runs share, by what it is.
fn differences(a: &BridgeResult, b: &BridgeResult) -> Vec<(&'static str, f64)> {
    let pairs = |x: &[f64], y: &[f64]| {
        assert_eq!(x.len(), y.len());
        x.iter()
            .zip(y)
            .map(|(p, q)| off(*p, *q, *q))
            .fold(0.0, f64::max)
    };
    let histories = |x: &[Vec<f64>], y: &[Vec<f64>]| {
        x.iter()
            .zip(y)
            .map(|(p, q)| {
                let scale = largest(q);
                p.iter()
                    .zip(q)
                    .map(|(u, v)| off(*u, *v, scale))
                    .fold(0.0, f64::max)
            })
            .fold(0.0, f64::max)
    };
    // The largest of `d` over the two runs' contacts, paired in order.
    let contacts = |d: &dyn Fn(&RawContact, &RawContact) -> f64| {
        a.contacts
            .iter()
            .zip(&b.contacts)
            .map(|(p, q)| d(p, q))
            .fold(0.0, f64::max)
    };
    let impulse_scale = b.contacts.iter().map(|c| c.impulse_ns).fold(0.0, f64::max);
    let force_scale = b.max_pounding_force_n;
    vec![
        (
            "largest closings",
            pairs(&a.max_closing_m, &b.max_closing_m),
        ),
        (
            "largest openings",
            pairs(&a.max_opening_m, &b.max_opening_m),
        ),
        (
            "girder peaks",
            pairs(&a.peak_girder_displacement_m, &b.peak_girder_displacement_m),
        ),
        (
            "pier peaks",
            pairs(&a.peak_pier_displacement_m, &b.peak_pier_displacement_m),
        ),
        (
            "bearing peaks",
            pairs(
                &a.peak_bearing_displacement_m,
                &b.peak_bearing_displacement_m,
            ),
        ),
        (
            "forces by joint",
            pairs(&a.max_force_by_joint_n, &b.max_force_by_joint_n),
        ),
        (
            "contact starts [s]",
            contacts(&|p, q| (p.start_s - q.start_s).abs()),
        ),
        (
            "contact peaks",
            contacts(&|p, q| off(p.peak_force_n, q.peak_force_n, force_scale)),
        ),
        (
            "contact impulses",
            contacts(&|p, q| off(p.impulse_ns, q.impulse_ns, impulse_scale)),
        ),
        (
            "opening histories",
            histories(&a.joint_opening_m, &b.joint_opening_m),
        ),
        (
            "girder histories",
            histories(&a.girder_displacement_m, &b.girder_displacement_m),
        ),
        (
            "pier histories",
            histories(&a.pier_displacement_m, &b.pier_displacement_m),
        ),
        (
            "force histories",
            histories(&a.joint_force_n, &b.joint_force_n),
        ),
    ]
}

/// The largest of [`differences`] (the start times aside: they are seconds, not fractions).
fn most(a: &BridgeResult, b: &BridgeResult) -> (f64, &'static str) {
    differences(a, b)
        .into_iter()
        .filter(|(what, _)| !what.contains("[s]"))
        .fold(
            (0.0, ""),
            |m, (what, d)| if d > m.0 { (d, what) } else { m },
        )
}

/// The record with every sample changed by one part in 10^11: a run's own sensitivity to
/// rounding (pounding sequences amplify it; a Kelvin-Voigt one chaotically).
fn perturbed(
    motion: &pounding::model::motion::GroundMotion,
) -> pounding::model::motion::GroundMotion {
    let mut m = motion.clone();
    for a in m.accel_m_s2.iter_mut() {
        *a *= 1.0 + 1e-11;
    }
    m
}

#[test]
fn a_bridge_run_jumping_over_free_stretches_finds_what_stepping_every_grid_point_finds() {
    let motion = el_centro(8.0);
    let twin_motion = perturbed(&motion);
    let base = BridgeScenario::three_span();
    let scenes: [(&str, BridgeScenario); 4] = [
        ("uniform", base.clone()),
        (
            "passage 500 m/s",
            BridgeScenario {
                apparent_velocity_m_s: Some(500.0),
                ..base.clone()
            },
        ),
        (
            "unseating: 0.1 m seats, 200 m/s",
            BridgeScenario {
                apparent_velocity_m_s: Some(200.0),
                seat_length_m: 0.1,
                ..base.clone()
            },
        ),
        (
            "passage 350 m/s, undamped girders",
            BridgeScenario {
                apparent_velocity_m_s: Some(350.0),
                girder_damping: 0.0,
                ..base.clone()
            },
        ),
    ];
    let mut largest_ratio: f64 = 0.0;
    for (name, scene) in &scenes {
        for contact in ContactModel::ALL {
            if name.contains("undamped") && contact != ContactModel::Sears {
                continue;
            }
            let sc = BridgeScenario {
                contact,
                ..scene.clone()
            };
            let jumped = solve(&sc, &motion).unwrap();
            let stepped = solve_stepped(&sc, &motion).unwrap();
            let twin = solve_stepped(&sc, &twin_motion).unwrap();
            let case = format!("{name}, {contact:?}");
            assert_eq!(jumped.time_s, stepped.time_s, "{case}: the samples' times");
            // What rounding alone keeps, the stretches keep: the contacts, their joints, and
            // the grid point where a joint unseats.
            let events = |r: &BridgeResult| {
                (
                    r.contacts.iter().map(|c| c.level).collect::<Vec<_>>(),
                    r.unseating
                        .iter()
                        .map(|u| (u.joint, u.time_s))
                        .collect::<Vec<_>>(),
                )
            };
            if events(&twin) == events(&stepped) {
                assert_eq!(
                    events(&jumped),
                    events(&stepped),
                    "{case}: contacts and unseating"
                );
            }
            assert_eq!(
                jumped.impacts.len(),
                stepped.impacts.len(),
                "{case}: impacts"
            );
            // Every number differs from stepping's by less than rounding alone moves it.
            let ((d, what), (sensitivity, _)) = (most(&jumped, &stepped), most(&twin, &stepped));
            eprintln!(
                "{case}: {d:.2e} ({what}); rounding moves the stepped run by {sensitivity:.2e}"
            );
            assert!(
                d <= sensitivity.max(1e-13),
                "{case}: {what} {d:e} against {sensitivity:e}"
            );
            largest_ratio = largest_ratio.max(d / sensitivity.max(1e-13));
            // The stretches' ledger integrates the damping and the ground's power exactly,
            // the steps by the trapezoidal rule: both balance.
            assert!(jumped.energy.balance_error().abs() < 2e-5, "{case}");
        }
    }
    eprintln!("largest difference against rounding's: {largest_ratio:.2}");
}

/// The run with its debug text, its wall time left out: equal texts are equal runs to the bit
/// (every number printed in full).
fn text(r: &BridgeResult) -> String {
    let mut r = r.clone();
    r.stats.wall_time_s = 0.0;
    format!("{r:?}")
}

#[test]
fn a_bridge_run_finds_what_walking_every_grid_point_of_its_stretches_finds_to_the_bit() {
    let base = BridgeScenario::three_span();
    let el_centro_8 = el_centro(8.0);
    // El Centro backwards and 1.7 times as strong: other contacts, harder ones.
    let mut reversed = pounding::io::motion::built_in("elcentro-1940").unwrap();
    reversed.accel_m_s2.reverse();
    let reversed = reversed.scaled(1.7).truncated(12.0);
    let mut scenes: Vec<(
        String,
        BridgeScenario,
        &pounding::model::motion::GroundMotion,
    )> = Vec::new();
    for contact in ContactModel::ALL {
        for (name, v, seat) in [
            ("uniform", None, 0.25),
            ("passage 500 m/s", Some(500.0), 0.25),
            ("0.1 m seats, 200 m/s", Some(200.0), 0.1),
        ] {
            let sc = BridgeScenario {
                contact,
                apparent_velocity_m_s: v,
                seat_length_m: seat,
                ..base.clone()
            };
            scenes.push((format!("{name}, {contact:?}"), sc, &el_centro_8));
        }
    }
    for (v, damping, soft) in [
        (170.0, 0.05, false),
        (1300.0, 0.05, false),
        (310.0, 0.0, false),
        (310.0, 0.3, false),
        (310.0, 0.6, false),
        (310.0, 0.3, true),
    ] {
        // Soft contact at a loose tolerance: about 22 grid steps a girder's round trip.
        let sc = BridgeScenario {
            apparent_velocity_m_s: Some(v),
            girder_damping: damping,
            stiffness: soft.then_some(1e8),
            tolerance: if soft { 0.05 } else { base.tolerance },
            ..base.clone()
        };
        let name = format!("reversed x1.7, {v} m/s, girder damping {damping}, soft {soft}, Sears");
        scenes.push((name, sc, &reversed));
    }
    for (name, sc, motion) in &scenes {
        let jumped = solve(sc, motion).unwrap();
        let walked = solve_walked(sc, motion).unwrap();
        assert!(
            text(&jumped) == text(&walked),
            "{name}: the bounds left out something that mattered ({} contacts against {})",
            jumped.contacts.len(),
            walked.contacts.len()
        );
    }
}
