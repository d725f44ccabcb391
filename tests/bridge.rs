//! Bridges against independent truth: frames alone against an independent integrator, two
//! frames against the two-building solver, the travelling wave's limit, the corrected ground
//! against its closed form, a girder thrown at an abutment against wave theory, and the
//! energy ledger.

use pounding::model::bridge::ground::Ground;
use pounding::model::bridge::{BridgeScenario, solve};
use pounding::model::building::{BuildingScenario, ContactModel, SlabReading};
use pounding::model::motion::GroundMotion;

mod common;
use common::{
    girder_thrown_at_the_left_abutment, ground_at_rest, middle_girder_struck_at_both_ends,
};

fn el_centro(seconds: f64) -> GroundMotion {
    pounding::io::motion::built_in("elcentro-1940")
        .unwrap()
        .truncated(seconds)
}

fn rel(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        (a - b).abs()
    } else {
        ((a - b) / b).abs()
    }
}

/// A two-degree-of-freedom shear frame integrated by the classical Runge-Kutta method on a
/// fine step, written for this test: M u'' + C u' + K u = -M 1 a(t), C modal with `zeta` in
/// both modes (C = M Phi diag(2 zeta w) Phi^T M, built from the frame's own eigenproblem
/// solved here in closed form). Returns the girder's and the pier top's displacement at every
/// `every`-th step.
fn rk4_frame(
    m: [f64; 2],
    k: [f64; 2],
    zeta: f64,
    accel: impl Fn(f64, bool) -> f64,
    h: f64,
    steps: usize,
    every: usize,
) -> Vec<(f64, f64)> {
    // K = [[k0 + k1, -k1], [-k1, k1]]; M^-1 K's eigenpairs by the 2x2 closed form.
    let kk = [[k[0] + k[1], -k[1]], [-k[1], k[1]]];
    let a = [
        [kk[0][0] / m[0], kk[0][1] / m[0]],
        [kk[1][0] / m[1], kk[1][1] / m[1]],
    ];
    let tr = a[0][0] + a[1][1];
    let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    let disc = (tr * tr / 4.0 - det).sqrt();
    let lambdas = [tr / 2.0 - disc, tr / 2.0 + disc];
    let mut c = [[0.0; 2]; 2];
    for lam in lambdas {
        // (A - lam) phi = 0: phi = [a01, lam - a00], mass-normalised.
        let mut phi = [a[0][1], lam - a[0][0]];
        let norm = (m[0] * phi[0] * phi[0] + m[1] * phi[1] * phi[1]).sqrt();
        phi = [phi[0] / norm, phi[1] / norm];
        let mphi = [m[0] * phi[0], m[1] * phi[1]];
        let coef = 2.0 * zeta * lam.sqrt();
        for i in 0..2 {
            for j in 0..2 {
                c[i][j] += coef * mphi[i] * mphi[j];
            }
        }
    }
    // `late`: the acceleration's left limit (the step's last stage), else its right limit, so
    // that a jump at a step's boundary belongs to the step after it.
    let deriv = |t: f64, late: bool, y: [f64; 4]| -> [f64; 4] {
        let (u, v) = ([y[0], y[1]], [y[2], y[3]]);
        let ag = accel(t, late);
        let mut acc = [0.0; 2];
        for i in 0..2 {
            let f = -(kk[i][0] * u[0] + kk[i][1] * u[1]) - (c[i][0] * v[0] + c[i][1] * v[1]);
            acc[i] = f / m[i] - ag;
        }
        [v[0], v[1], acc[0], acc[1]]
    };
    let mut y = [0.0; 4];
    let mut out = vec![(y[1], y[0])];
    for n in 0..steps {
        let t = n as f64 * h;
        let add = |y: [f64; 4], k: [f64; 4], s: f64| std::array::from_fn(|i| y[i] + s * k[i]);
        let k1 = deriv(t, false, y);
        let k2 = deriv(t + h / 2.0, false, add(y, k1, h / 2.0));
        let k3 = deriv(t + h / 2.0, false, add(y, k2, h / 2.0));
        let k4 = deriv(t + h, true, add(y, k3, h));
        y = std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        if (n + 1) % every == 0 {
            out.push((y[1], y[0]));
        }
    }
    out
}

#[test]
fn with_joints_too_wide_to_close_each_frame_moves_as_its_own_fixed_base_frame() {
    let motion = el_centro(8.0);
    let ground = Ground::new(&motion);
    // At 500 m/s the supports' delays fall on the steps; at 433 m/s inside them.
    for v_app in [None, Some(500.0), Some(433.0)] {
        let sc = BridgeScenario {
            contact: ContactModel::Linear,
            joint_gaps_m: vec![10.0],
            apparent_velocity_m_s: v_app,
            ..BridgeScenario::three_span()
        };
        let r = solve(&sc, &motion).unwrap();
        assert!(r.contacts.is_empty());
        let h = r.stats.step_s;
        // The reference's steps do not fall on the delayed records' samples: at a tenth of the
        // bridge's step its error there is 1.5e-7 of the peak, at a fortieth well below.
        let every = 40;
        let fine = h / every as f64;
        for i in 0..sc.spans {
            let delay = sc.delay_s(sc.frame_position_m(i));
            let truth = rk4_frame(
                sc.frame_masses(i),
                sc.frame_stiffnesses(i),
                sc.damping_ratio,
                |t, late| {
                    if late {
                        ground.accel_before(t, delay)
                    } else {
                        ground.accel_after(t, delay)
                    }
                },
                fine,
                r.stats.steps * every,
                every,
            );
            let peak = truth.iter().map(|p| p.0.abs()).fold(0.0, f64::max);
            let mut worst: f64 = 0.0;
            for (s, t) in r.time_s.iter().enumerate() {
                let n = (t / h).round() as usize;
                worst = worst.max((r.girder_displacement_m[i][s] - truth[n].0).abs());
                worst = worst.max((r.pier_displacement_m[i][s] - truth[n].1).abs());
            }
            assert!(
                worst < 1e-7 * peak,
                "frame {i}, v_app {v_app:?}: off by {worst:e} of a peak {peak:e}"
            );
        }
    }
}

/// Two frames, abutments out of reach: two two-storey buildings (pier top and girder floors)
/// with the girders as the slabs that meet, under the same corrected record.
fn two_frames_as_buildings(contact: ContactModel) -> (BridgeScenario, BuildingScenario) {
    let bridge = BridgeScenario {
        spans: 2,
        contact,
        pier_stiffness_n_m: vec![1e9],
        bearing_stiffness_n_m: vec![1e8, 4e7],
        joint_gaps_m: vec![10.0, 0.03, 10.0],
        ..BridgeScenario::three_span()
    };
    let mut building = BuildingScenario {
        contact,
        gap_m: 0.03,
        reading: SlabReading::End,
        slab_damping: bridge.girder_damping,
        ..BuildingScenario::paper()
    };
    for (i, b) in [&mut building.left, &mut building.right]
        .into_iter()
        .enumerate()
    {
        let g = bridge.girder(i);
        b.storeys = 2;
        b.masses_kg = bridge.frame_masses(i).to_vec();
        b.stiffnesses_n_m = bridge.frame_stiffnesses(i).to_vec();
        b.heights_m = vec![8.0, 2.0];
        b.damping_ratio = bridge.damping_ratio;
        b.slab_lengths_m = vec![g.length_m];
        b.slab_widths_m = vec![g.area_m2];
        b.slab_thicknesses_m = vec![1.0];
        b.slab_youngs_pa = vec![g.youngs_pa];
    }
    (bridge, building)
}

#[test]
fn two_frames_pound_as_the_two_building_solver_says() {
    let motion = el_centro(8.0);
    let corrected = Ground::new(&motion).corrected;
    for contact in [
        ContactModel::Linear,
        ContactModel::Sears,
        ContactModel::Kelvin,
    ] {
        let (bridge, building) = two_frames_as_buildings(contact);
        let r = solve(&bridge, &motion).unwrap();
        let b = pounding::model::building::solve(&building, &corrected).unwrap();
        let est = pounding::model::bridge::estimate_error(
            &bridge,
            &motion,
            &r,
            pounding::model::control::Control::never(),
        )
        .unwrap();
        let b_est = pounding::model::building::estimate_error(&building, &corrected, &b).unwrap();
        // The pier tops never meet: only the girders' level pounds.
        assert!(
            b.contacts
                .iter()
                .all(|c| b.levels[c.level].elevation_m == 10.0)
        );
        assert!(r.contacts.iter().all(|c| c.level == 1));
        assert_eq!(r.impacts.len(), b.impacts.len(), "{contact:?}");
        assert!(!r.impacts.is_empty());
        let force = rel(r.max_pounding_force_n, b.max_pounding_force_n);
        assert!(
            force <= est.max_force + b_est.max_force,
            "{contact:?}: max force {:e} against {:e}: {force:e}, bounds {:e} + {:e}",
            r.max_pounding_force_n,
            b.max_pounding_force_n,
            est.max_force,
            b_est.max_force
        );
        for side in 0..2 {
            let peak = rel(
                r.peak_girder_displacement_m[side],
                b.peak_floor_displacement_m[side][1],
            );
            assert!(
                peak <= est.peak_displacement + b_est.peak_displacement,
                "{contact:?}, girder {side}: {peak:e}"
            );
        }
        for (x, y) in r.impacts.iter().zip(&b.impacts) {
            assert!(rel(x.start_s, y.start_s) <= est.impact_time + b_est.impact_time + 1e-9);
        }
    }
}

#[test]
fn an_apparent_velocity_of_1e12_is_uniform_excitation_to_round_off() {
    let motion = el_centro(8.0);
    for contact in [ContactModel::Sears, ContactModel::Linear] {
        let uniform = BridgeScenario {
            contact,
            ..BridgeScenario::three_span()
        };
        let fast = BridgeScenario {
            apparent_velocity_m_s: Some(1e12),
            ..uniform.clone()
        };
        let (a, b) = (
            solve(&uniform, &motion).unwrap(),
            solve(&fast, &motion).unwrap(),
        );
        // The far support's delay of 1.2e-10 s adds one step to the run's end.
        assert_eq!(a.impacts.len(), b.impacts.len());
        assert!(rel(b.max_pounding_force_n, a.max_pounding_force_n) < 1e-8);
        for i in 0..3 {
            assert!(
                rel(
                    b.peak_girder_displacement_m[i],
                    a.peak_girder_displacement_m[i]
                ) < 1e-8
            );
        }
        for j in 0..4 {
            assert!(rel(b.max_opening_m[j], a.max_opening_m[j]) < 1e-8);
        }
        assert!(b.energy.differential_j.abs() < 1e-8 * b.energy.input_j);
    }
}

#[test]
fn the_corrected_ground_ends_at_rest_and_follows_its_closed_form() {
    // a(t) = sin(2 pi t / T) on [0, T]: V = 0 and D = T^2 / (2 pi) at its end, so the baseline
    // is c0 = 3 / pi, c1 = -6 / (pi T), and the ground is
    // d(t) = t T/(2 pi) - (T/(2 pi))^2 sin(2 pi t/T) - c0 t^2/2 - c1 t^3/6.
    let t_end = 2.0;
    let n = 4000;
    let dt = t_end / n as f64;
    let w = 2.0 * std::f64::consts::PI / t_end;
    let motion = GroundMotion {
        name: "sine".into(),
        dt_s: dt,
        accel_m_s2: (0..=n).map(|i| (w * i as f64 * dt).sin()).collect(),
    };
    let ground = Ground::new(&motion);
    let (c0, c1) = (
        3.0 / std::f64::consts::PI,
        -6.0 / (std::f64::consts::PI * t_end),
    );
    assert!((ground.baseline.c0_m_s2 - c0).abs() < 1e-6);
    assert!((ground.baseline.c1_m_s3 - c1).abs() < 1e-6);
    let d = |t: f64| t / w - (t * w).sin() / (w * w) - c0 * t * t / 2.0 - c1 * t.powi(3) / 6.0;
    let v = |t: f64| (1.0 - (t * w).cos()) / w - c0 * t - c1 * t * t / 2.0;
    let scale = (0..100)
        .map(|i| d(i as f64 * t_end / 100.0).abs())
        .fold(0.0, f64::max);
    for delay in [0.0, 0.37] {
        for i in 0..=93 {
            let t = i as f64 * 0.0213;
            let g = ground.at(t + delay, delay);
            assert!(
                (g.displacement - d(t)).abs() < 1e-6 * scale,
                "{t}: {} against {}",
                g.displacement,
                d(t)
            );
            assert!(
                (g.velocity - v(t)).abs() < 1e-6,
                "{t}: {} against {}",
                g.velocity,
                v(t)
            );
        }
        // Before the wave arrives and after the record has passed: at rest.
        for t in [0.5 * delay, delay + t_end, delay + t_end + 3.0] {
            let g = ground.at(t, delay);
            assert!(
                g.displacement.abs() < 1e-12 && g.velocity.abs() < 1e-12,
                "{t}"
            );
        }
    }
}

#[test]
fn a_girder_thrown_at_a_rigid_abutment_rebounds_as_wave_theory_says() {
    // One free girder (bearings and pier of negligible stiffness) at 1 m/s towards the left
    // abutment, contact stiff enough that its rise time Z/k is 0.06 ms against a round trip of
    // 21.7 ms: the wave-theory limit is contact for 2 L / c and restitution 1, at a force of
    // Z v (the rigid face reflects the girder's own wave).
    let sc = girder_thrown_at_the_left_abutment();
    let still = ground_at_rest();
    let r = solve(&sc, &still).unwrap();
    let g = sc.girder(0);
    assert_eq!(r.impacts.len(), 1, "{:?}", r.contacts);
    let c = &r.contacts[0];
    let duration = c.end_s - c.start_s;
    assert!(
        rel(duration, g.round_trip_s()) < 0.01,
        "{duration} against {}",
        g.round_trip_s()
    );
    let e = c.impulse_ns / g.mass_kg - 1.0;
    assert!((e - 1.0).abs() < 0.01, "e = {e}");
    assert!(rel(c.peak_force_n, g.impedance_n_s_m()) < 0.02);
    assert!((c.start_s - 1e-3).abs() < 1e-6);
}

#[test]
fn every_element_balances_its_energy_ledger() {
    let motion = el_centro(8.0);
    for contact in ContactModel::ALL {
        for v_app in [None, Some(300.0)] {
            let sc = BridgeScenario {
                contact,
                apparent_velocity_m_s: v_app,
                ..BridgeScenario::three_span()
            };
            let r = solve(&sc, &motion).unwrap();
            let e = r.energy.balance_error();
            assert!(
                e.abs() < 2e-5,
                "{contact:?} {v_app:?}: {e:e} {:?}",
                r.energy
            );
            if !matches!(contact, ContactModel::None) {
                assert!(!r.impacts.is_empty());
            }
        }
    }
}

#[test]
fn the_error_estimate_bounds_a_tenfold_refined_run_for_every_element() {
    let motion = el_centro(4.0);
    for contact in ContactModel::ALL {
        let sc = BridgeScenario {
            contact,
            apparent_velocity_m_s: Some(400.0),
            ..BridgeScenario::three_span()
        };
        let r = solve(&sc, &motion).unwrap();
        let est = pounding::model::bridge::estimate_error(
            &sc,
            &motion,
            &r,
            pounding::model::control::Control::never(),
        )
        .unwrap();
        let fine = solve(
            &pounding::model::bridge::estimate::refined(&sc, 10.0),
            &motion,
        )
        .unwrap();
        let actual = pounding::model::bridge::estimate::compare(&r, &fine);
        if contact != ContactModel::None {
            assert!(!r.impacts.is_empty(), "{contact:?}");
        }
        assert_eq!(actual.impact_count_change, 0, "{contact:?}");
        for (what, err, bound) in [
            ("max force", actual.max_force, est.max_force),
            ("peaks", actual.peak_displacement, est.peak_displacement),
            ("openings", actual.opening, est.opening),
            ("impact times", actual.impact_time, est.impact_time),
        ] {
            assert!(
                err <= bound + 1e-12,
                "{contact:?} {what}: error {err:e} above its bound {bound:e}"
            );
        }
    }
}

#[test]
fn extreme_values_of_every_key_end_in_a_result_or_a_named_refusal() {
    use pounding::io::bridge_settings::{BRIDGE, BridgeSetup};
    use pounding::io::settings::SettingValue;
    use pounding::model::settings::{BRIDGE_SETTINGS, Kind};
    let motion = el_centro(1.0);
    let mut runs = 0;
    for s in BRIDGE_SETTINGS {
        let values: Vec<f64> = match s.kind {
            Kind::Number { range, .. } | Kind::List { range, .. } => {
                vec![range.low_accepted(), range.high_accepted()]
            }
            Kind::Count { min, max } => vec![min as f64, max as f64],
            _ => continue,
        };
        if s.key.starts_with("motion.") && s.key != "motion.apparent_velocity" {
            continue;
        }
        for x in values.into_iter().chain([-1.0, f64::NAN, 1e300]) {
            let mut setup = BridgeSetup::default();
            setup.scenario.max_steps = 200_000;
            let applied = setup.apply(s.key, &SettingValue::Number(x));
            let outcome = applied
                .map_err(|e| e.to_string())
                .and_then(|_| solve(&setup.scenario, &motion).map_err(|e| e.to_string()));
            match outcome {
                Ok(r) => {
                    assert!(r.max_pounding_force_n.is_finite(), "{}={x}", s.key);
                    assert!(r.energy.balance_error().is_finite(), "{}={x}", s.key);
                    assert!(
                        r.peak_girder_displacement_m.iter().all(|u| u.is_finite()),
                        "{}={x}",
                        s.key
                    );
                }
                Err(e) => assert!(
                    e.contains(s.key) || e.contains("solver.max_steps") || e.contains("pier"),
                    "{}={x}: {e}",
                    s.key
                ),
            }
            runs += 1;
        }
        let _ = BRIDGE.lookup(s.key).expect("every row has an entry");
    }
    assert!(runs > 80, "only {runs}");
}

#[test]
fn stress_fronts_from_both_ends_of_a_girder_meet_and_add_as_wave_theory_says() {
    // Wave theory for two equal bars meeting at w = 1 m/s: a compressive front of Z w / (2 A)
    // runs into each from the contact at c, and the particles behind it move at w / 2 towards
    // the other bar. The middle girder takes one front from each end: they meet at its middle
    // after L / (2c) and add to Z w / A there; its middle is at rest.
    let v = 1.0;
    let (sc, still) = (middle_girder_struck_at_both_ends(v), ground_at_rest());
    let r = solve(&sc, &still).unwrap();
    assert_eq!(r.girder_waves.len(), 3);
    let g = sc.girder(1);
    let (l, c) = (g.length_m, g.wave_speed_m_s());
    let front = g.impedance_n_s_m() * v / (2.0 * g.area_m2);
    let t0 = 1e-3;
    let first = r
        .contacts
        .iter()
        .map(|c| c.start_s)
        .fold(f64::MAX, f64::min);
    assert!((first - t0).abs() < 1e-6, "first contact at {first}");
    // After L / (4c) each front is a quarter of the way in.
    let t = t0 + 0.25 * l / c;
    let near_left = r.girder_stress_pa(1, 0.125 * l, t);
    let near_right = r.girder_stress_pa(1, 0.875 * l, t);
    let middle = r.girder_stress_pa(1, 0.5 * l, t);
    assert!(
        rel(near_left, -front) < 0.02,
        "{near_left} against {}",
        -front
    );
    assert!(
        rel(near_right, -front) < 0.02,
        "{near_right} against {}",
        -front
    );
    assert!(middle.abs() < 0.02 * front, "ahead of the fronts: {middle}");
    // Behind the left front the girder moves right at w/2, behind the right front left.
    let v_left = r.girder_wave_velocity_m_s(1, 0.125 * l, t);
    let v_right = r.girder_wave_velocity_m_s(1, 0.875 * l, t);
    assert!((v_left - 0.5 * v).abs() < 0.02 * v, "{v_left}");
    assert!((v_right + 0.5 * v).abs() < 0.02 * v, "{v_right}");
    // Three quarters: the fronts have passed each other in the middle and add.
    let t = t0 + 0.75 * l / c;
    let met = r.girder_stress_pa(1, 0.5 * l, t);
    assert!(
        rel(met, -2.0 * front) < 0.02,
        "{met} against {}",
        -2.0 * front
    );
    let still_middle = r.girder_wave_velocity_m_s(1, 0.5 * l, t);
    assert!(still_middle.abs() < 0.02 * v, "{still_middle}");
    // The struck end of an outer girder carries its joint's force: stress -F / A there.
    let k = r.time_s.partition_point(|&s| s < t0 + 0.5 * l / c);
    let (t, f) = (r.time_s[k], r.joint_force_n[1][k]);
    let end = r.girder_stress_pa(0, l, t);
    assert!(
        rel(end, -f / g.area_m2) < 1e-6,
        "{end} against {}",
        -f / g.area_m2
    );
}

#[test]
fn a_girder_that_rebounds_from_an_abutment_leaves_it_free_of_stress() {
    // Wave theory: a bar that hits a rigid face at v is compressed to Z v / A as the front runs
    // in, and after the round trip of contact leaves at -v with no stress left in it.
    let sc = girder_thrown_at_the_left_abutment();
    let still = ground_at_rest();
    let r = solve(&sc, &still).unwrap();
    let g = sc.girder(0);
    let (l, c) = (g.length_m, g.wave_speed_m_s());
    let full = g.impedance_n_s_m() / g.area_m2;
    let t0 = r.contacts[0].start_s;
    let t = t0 + 0.5 * l / c;
    let behind = r.girder_stress_pa(0, 0.25 * l, t);
    let ahead = r.girder_stress_pa(0, 0.75 * l, t);
    assert!(rel(behind, -full) < 0.02, "{behind} against {}", -full);
    assert!(ahead.abs() < 0.02 * full, "{ahead}");
    // A quarter round trip after the contact, at points whose arrivals left the end away from
    // its last instants (where the force falls over its rise time, a sliver of the picture).
    let after = r.contacts[0].end_s + 0.5 * l / c;
    for x in [0.15, 0.35, 0.65, 0.85] {
        let s = r.girder_stress_pa(0, x * l, after);
        assert!(s.abs() < 0.02 * full, "at {x} L after the rebound: {s}");
    }
}

#[test]
fn girders_without_waves_have_none_to_draw() {
    let (sc, still) = (middle_girder_struck_at_both_ends(1.0), ground_at_rest());
    let r = solve(
        &BridgeScenario {
            contact: ContactModel::Linear,
            stiffness: Some(1e10),
            ..sc
        },
        &still,
    )
    .unwrap();
    assert!(r.impacts.len() >= 2);
    assert!(r.girder_waves.is_empty());
    assert_eq!(r.girder_stress_pa(1, 20.0, 0.01), 0.0);
}

/// The window draws a run while it solves: each partial result handed out is the whole run's
/// beginning, to the bit (its samples, its finished contacts, its girders' waves up to the
/// instant solved), and the streamed run's end is the run solved at once.
#[test]
fn a_bridge_run_streamed_while_it_solves_is_the_whole_runs_beginning_at_every_stage() {
    use pounding::model::bridge::solve_streaming;
    use pounding::model::control::Control;
    let setup: pounding::io::bridge_settings::BridgeSetup =
        pounding::io::preset::load_for("bridge-3-span-passage", "bridge").expect("preset");
    let sc = setup.scenario;
    let motion = el_centro(4.0);
    let whole = solve(&sc, &motion).expect("run");
    let mut partials = vec![];
    let streamed = solve_streaming(
        &sc,
        &motion,
        Control::never(),
        std::time::Duration::ZERO,
        &mut |p| partials.push(p),
    )
    .expect("run");
    assert!(partials.len() > 5, "{} partial results", partials.len());
    assert_eq!(streamed.solved_to_s, streamed.duration_s);
    assert_eq!(streamed.time_s, whole.time_s);
    assert_eq!(streamed.joint_force_n, whole.joint_force_n);
    assert_eq!(streamed.contacts, whole.contacts);
    assert_eq!(streamed.max_force_by_joint_n, whole.max_force_by_joint_n);
    let mut before = 0.0;
    for p in &partials {
        assert!(p.solved_to_s > before && p.solved_to_s < whole.duration_s);
        before = p.solved_to_s;
        let n = p.time_s.len();
        assert!(n < whole.time_s.len());
        assert_eq!(p.time_s[..], whole.time_s[..n]);
        assert!(p.time_s[n - 1] <= p.solved_to_s);
        for j in 0..whole.joints.len() {
            assert_eq!(p.joint_force_n[j][..], whole.joint_force_n[j][..n]);
            assert_eq!(p.joint_opening_m[j][..], whole.joint_opening_m[j][..n]);
        }
        for i in 0..sc.spans {
            assert_eq!(p.girder_absolute_m[i][..], whole.girder_absolute_m[i][..n]);
        }
        // Contacts over are the whole run's; one still under way has its start, and its end
        // so far.
        if let Some((now, over)) = p.contacts.split_last() {
            let m = over.len();
            assert_eq!(over[..], whole.contacts[..m]);
            let then = whole.contacts[m];
            assert!(now == &then || (now.start_s == then.start_s && now.end_s <= then.end_s));
            assert!(now.end_s <= p.solved_to_s);
        }
        // The waves read the same up to the instant solved (less the two samples a cubic
        // reads ahead, which the partial run has not yet taken), to round-off: where the whole
        // run's next contact opens a stretch, it keeps the round trip of ringing before it as
        // samples, where the partial run reads that ringing by folding its last stretch.
        let known = p.solved_to_s - 3.0 * whole.stats.step_s;
        for (pw, ww) in p.girder_waves.iter().zip(&whole.girder_waves) {
            for end in 0..2 {
                let at = |w: &pounding::model::field::BarWaves, k: usize| {
                    w.history_at(known * k as f64 / 400.0)
                };
                let scale = (0..=400).map(|k| at(&ww[end], k).abs()).fold(1.0, f64::max);
                for k in 0..=400 {
                    let (a, b) = (at(&pw[end], k), at(&ww[end], k));
                    assert!((a - b).abs() <= 1e-9 * scale, "{a} against {b} of {scale}");
                }
            }
        }
    }
    assert!(partials.last().unwrap().contacts.len() > 3);
}
