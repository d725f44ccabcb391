//! Storeys that yield: checked against an elastic run, an independent integration of a yielding
//! storey, the energy balance and a tenfold-refined run.

use pounding::io::building_settings::BuildingSetup;
use pounding::model::building::estimate::refined;
use pounding::model::building::{
    BuildingResult, BuildingScenario, ContactModel, estimate_error, solve,
};
use pounding::model::hysteresis::Hysteresis;
use pounding::model::motion::GroundMotion;

fn record(seconds: f64) -> GroundMotion {
    pounding::io::motion::built_in("elcentro-1940")
        .expect("El Centro is built in")
        .truncated(seconds)
}

fn run(sc: &BuildingScenario, m: &GroundMotion) -> BuildingResult {
    solve(sc, m).unwrap_or_else(|e| panic!("{}: {e}", sc.contact.name()))
}

/// The paper's pair with bilinear storeys of the preset's yield forces.
fn yielding(contact: ContactModel) -> BuildingScenario {
    let mut sc = BuildingScenario::paper();
    sc.contact = contact;
    for (b, fy) in [(&mut sc.left, 2.5e5), (&mut sc.right, 1.7e5)] {
        b.hysteresis = Hysteresis::Bilinear;
        b.yield_forces_n = Some(vec![fy]);
        b.hardening = 0.05;
    }
    sc
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(f64::MIN_POSITIVE)
}

#[test]
fn storeys_that_never_reach_their_yield_force_pound_as_elastic_ones() {
    let m = record(4.0);
    for contact in [ContactModel::Linear, ContactModel::Sears] {
        let elastic = run(
            &BuildingScenario {
                contact,
                ..BuildingScenario::paper()
            },
            &m,
        );
        let mut sc = yielding(contact);
        sc.left.yield_forces_n = Some(vec![1e15]);
        sc.right.yield_forces_n = Some(vec![1e15]);
        let y = run(&sc, &m);
        assert_eq!(y.impacts.len(), elastic.impacts.len(), "{contact:?}");
        for (a, b) in y.impacts.iter().zip(&elastic.impacts) {
            assert!((a.start_s - b.start_s).abs() < 1e-9, "{contact:?}");
        }
        let force = rel(y.max_pounding_force_n, elastic.max_pounding_force_n);
        assert!(force < 1e-9, "{contact:?}: max force off by {force:e}");
        for s in 0..2 {
            let d = rel(y.peak_displacement_m[s], elastic.peak_displacement_m[s]);
            assert!(d < 1e-9, "{contact:?} side {s}: peak off by {d:e}");
            assert_eq!(y.hysteretic_energy_j[s], vec![0.0]);
        }
    }
}

/// One storey, m u'' + c u' + F(u) = -m a_g, integrated independently of the solver: its own
/// bilinear law (return mapping on the plastic drift) and classical Runge-Kutta with the law's
/// state frozen over each tiny step. Returns (peak |u|, u at the end, dissipated energy).
/// One storey's constants for the independent integration.
#[derive(Clone, Copy)]
struct Storey {
    m: f64,
    k: f64,
    zeta: f64,
    fy: f64,
    b: f64,
}

fn independent_storey(
    storey: &Storey,
    ground: &[f64],
    dt_ground: f64,
    end: f64,
) -> (f64, f64, f64) {
    let Storey { m, k, zeta, fy, b } = *storey;
    let c = 2.0 * zeta * (k * m).sqrt();
    let a_g = |t: f64| {
        let p = t / dt_ground;
        let i = p.floor() as usize;
        if i + 1 >= ground.len() {
            return 0.0;
        }
        let x = p - i as f64;
        ground[i] * (1.0 - x) + ground[i + 1] * x
    };
    let uy = fy / k;
    let (mut u, mut v, mut up, mut dissipated, mut peak) = (0.0f64, 0.0f64, 0.0f64, 0.0, 0.0f64);
    let h = 2e-6;
    let steps = (end / h).round() as usize;
    for n in 0..steps {
        let t = n as f64 * h;
        let force = |u: f64| b * k * u + (1.0 - b) * k * (u - up);
        let acc = |t: f64, u: f64, v: f64| -a_g(t) - (c * v + force(u)) / m;
        let (k1u, k1v) = (v, acc(t, u, v));
        let (k2u, k2v) = (
            v + 0.5 * h * k1v,
            acc(t + 0.5 * h, u + 0.5 * h * k1u, v + 0.5 * h * k1v),
        );
        let (k3u, k3v) = (
            v + 0.5 * h * k2v,
            acc(t + 0.5 * h, u + 0.5 * h * k2u, v + 0.5 * h * k2v),
        );
        let (k4u, k4v) = (v + h * k3v, acc(t + h, u + h * k3u, v + h * k3v));
        u += h / 6.0 * (k1u + 2.0 * k2u + 2.0 * k3u + k4u);
        v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        let new_up = up.clamp(u - uy, u + uy);
        dissipated += (1.0 - b) * fy * (new_up - up).abs();
        up = new_up;
        peak = peak.max(u.abs());
    }
    (peak, u, dissipated)
}

#[test]
fn a_yielding_storey_under_a_sine_pulse_follows_an_independent_fine_integration() {
    let (dt, pulse) = (0.002, 0.6);
    let amp = 9.0;
    let n = (3.0 / dt) as usize;
    let ground: Vec<f64> = (0..=n)
        .map(|i| {
            let t = i as f64 * dt;
            if t < pulse {
                amp * (2.0 * std::f64::consts::PI * t / pulse).sin()
            } else {
                0.0
            }
        })
        .collect();
    let motion = GroundMotion {
        name: "sine pulse".into(),
        dt_s: dt,
        accel_m_s2: ground.clone(),
    };
    for b in [0.05, 0.3] {
        let mut sc = yielding(ContactModel::None);
        sc.left.hardening = b;
        let r = run(&sc, &motion);
        let (peak, end, dissipated) = independent_storey(
            &Storey {
                m: 36_000.0,
                k: 1.16e7,
                zeta: 0.05,
                fy: 2.5e5,
                b,
            },
            &ground,
            dt,
            n as f64 * dt,
        );
        let mu = peak / (2.5e5 / 1.16e7);
        assert!(
            mu > 1.5,
            "b = {b}: the pulse must drive the storey well past yield ({mu})"
        );
        assert!(
            (r.ductility_demand[0][0] - mu).abs() < 1e-4 * mu,
            "b = {b}: ductility {} against {mu}",
            r.ductility_demand[0][0]
        );
        assert!(
            (r.residual_drift_m[0][0] - end).abs() < 1e-4 * peak,
            "b = {b}: drift at the end {} against {end}",
            r.residual_drift_m[0][0]
        );
        assert!(
            rel(r.hysteretic_energy_j[0][0], dissipated) < 1e-4,
            "b = {b}: dissipated {} against {dissipated}",
            r.hysteretic_energy_j[0][0]
        );
    }
}

#[test]
fn the_energy_balance_closes_with_the_storeys_hysteretic_energy() {
    let m = record(8.0);
    for contact in [
        ContactModel::Linear,
        ContactModel::Sears,
        ContactModel::Kelvin,
        ContactModel::Stereo,
    ] {
        let r = run(&yielding(contact), &m);
        let e = &r.energy;
        assert!(
            e.hysteretic_j > 0.05 * e.input_j,
            "{contact:?}: the storeys must yield ({} of {} J)",
            e.hysteretic_j,
            e.input_j
        );
        // The balance without the hysteretic term is off by all of it: the term is what closes it.
        assert!(
            e.balance_error().abs() < 1e-6,
            "{contact:?}: balance error {:e}",
            e.balance_error()
        );
        assert!(r.ductility_demand.iter().flatten().any(|&mu| mu > 1.0));
    }
}

/// The run's error estimate bounds its error against the same run with every step ten times
/// finer, in the largest force and in either roof's peak displacement.
fn estimate_bounds_a_tenfold_refined_run(
    sc: &BuildingScenario,
    m: &GroundMotion,
    r: &BuildingResult,
    what: &str,
) {
    let est = estimate_error(sc, m, r).expect("estimate");
    let truth = run(&refined(sc, 10.0), m);
    let force = rel(r.max_pounding_force_n, truth.max_pounding_force_n);
    assert!(
        force <= est.max_force.max(1e-12),
        "{what}: max force error {force:e} over the bound {:e}",
        est.max_force
    );
    let peak = (0..2)
        .map(|s| rel(r.peak_displacement_m[s], truth.peak_displacement_m[s]))
        .fold(0.0, f64::max);
    assert!(
        peak <= est.peak_displacement.max(1e-12),
        "{what}: peak error {peak:e} over the bound {:e}",
        est.peak_displacement
    );
}

#[test]
fn the_error_estimate_of_a_yielding_run_bounds_a_tenfold_refined_run() {
    let m = record(3.0);
    let cases = [
        (ContactModel::Linear, Hysteresis::Bilinear),
        (ContactModel::Sears, Hysteresis::Bilinear),
        // Its max force once converged erratically (read at the steps alone) and left the bound.
        (ContactModel::Linear, Hysteresis::BoucWen),
        (ContactModel::Hertz, Hysteresis::BoucWen),
    ];
    for (contact, law) in cases {
        let mut sc = yielding(contact);
        sc.left.hysteresis = law;
        sc.right.hysteresis = law;
        let r = run(&sc, &m);
        assert!(r.hysteretic_energy_j.iter().flatten().any(|&e| e > 0.0));
        estimate_bounds_a_tenfold_refined_run(&sc, &m, &r, &format!("{contact:?} {law:?}"));
    }
}

#[test]
fn the_recorded_loops_stay_inside_the_bilinear_bounds_and_enclose_the_hysteretic_energy() {
    let m = record(8.0);
    let sc = yielding(ContactModel::Linear);
    let r = run(&sc, &m);
    for (s, b) in [&sc.left, &sc.right].into_iter().enumerate() {
        let law = b.storey_laws()[0];
        let (k, fy, hardening) = (law.stiffness_n_m, law.yield_force_n, law.hardening);
        let u = r.storey_drift_m(s, 0);
        let f = &r.storey_shear_n[s][0];
        assert_eq!(u.len(), r.time_s.len());
        // Kinematic hardening: |F - b k u| never passes (1 - b) F_y, and reaches it.
        let reach = u
            .iter()
            .zip(f)
            .map(|(u, f)| (f - hardening * k * u).abs() / ((1.0 - hardening) * fy))
            .fold(0.0, f64::max);
        assert!(
            reach <= 1.0 + 1e-8,
            "side {s}: the loop leaves its bounds ({reach})"
        );
        assert!(
            reach > 1.0 - 1e-6,
            "side {s}: the storey must yield ({reach})"
        );
        // The work the samples' trapezoids give, less what the spring stores at the end (its
        // elastic part after unloading to the hardening line), against the solver's own count.
        let work: f64 = (1..u.len())
            .map(|i| 0.5 * (f[i] + f[i - 1]) * (u[i] - u[i - 1]))
            .sum();
        let (ue, fe) = (u[u.len() - 1], f[f.len() - 1]);
        let elastic_part = (fe - hardening * k * ue) / ((1.0 - hardening) * k);
        let stored =
            0.5 * hardening * k * ue * ue + 0.5 * (1.0 - hardening) * k * elastic_part.powi(2);
        let area = work - stored;
        let counted = r.hysteretic_energy_j[s][0];
        assert!(
            rel(area, counted) < 0.01,
            "side {s}: the loop encloses {area} J against {counted} J dissipated"
        );
        // Before its first yield the drift stays inside the yield drift.
        let first = r.first_yield_s[s][0].expect("it yields");
        let uy = fy / k;
        let mut before = r.time_s.iter().zip(&u).filter(|(t, _)| **t < first - 1e-9);
        assert!(before.all(|(_, u)| u.abs() < uy * (1.0 + 1e-9)));
    }
    // An elastic building records no shear of its own (its shear is k times the drift).
    let elastic = run(&BuildingScenario::paper(), &record(2.0));
    assert!(elastic.storey_shear_n.iter().all(Vec::is_empty));
    assert!(elastic.first_yield_s.iter().flatten().all(Option::is_none));
}

#[test]
fn the_yielding_preset_reads_and_its_keys_round_trip() {
    let setup: BuildingSetup =
        pounding::io::preset::load("paper-buildings-yielding").expect("the preset loads");
    let sc = &setup.scenario;
    assert_eq!(sc.left.hysteresis, Hysteresis::Bilinear);
    assert_eq!(sc.left.yield_force(0), 2.5e5);
    assert_eq!(sc.right.yield_force(0), 1.7e5);
    assert_eq!(sc.right.hardening, 0.05);
    assert!(setup.motion.settle_s > 0.0);
}

#[test]
fn extreme_yield_settings_end_in_a_result_or_a_named_refusal() {
    let m = record(2.0);
    let cases: &[(&str, &str)] = &[
        ("left.yield_forces", "1e-3"),
        ("left.yield_forces", "1e15"),
        ("left.hardening", "0"),
        ("left.hardening", "0.999999"),
        ("left.bouc_wen_n", "1"),
        ("left.bouc_wen_n", "100"),
    ];
    for hysteresis in ["bilinear", "bouc-wen"] {
        for (key, value) in cases {
            let mut setup = BuildingSetup::default();
            setup
                .apply_assignment(&format!("left.hysteresis={hysteresis}"))
                .expect("a law");
            setup.scenario.contact = ContactModel::Linear;
            setup
                .apply_assignment(&format!("{key}={value}"))
                .unwrap_or_else(|e| panic!("{key}={value} is in range: {e}"));
            match solve(&setup.scenario, &m) {
                Ok(r) => {
                    assert!(r.max_pounding_force_n.is_finite(), "{key}={value}");
                    assert!(r.peak_displacement_m.iter().all(|x| x.is_finite()));
                    assert!(
                        r.hysteretic_energy_j[0]
                            .iter()
                            .all(|e| e.is_finite() && *e >= 0.0)
                    );
                }
                Err(e) => {
                    let text = e.to_string();
                    assert!(
                        text.contains("solver.") || text.contains(key),
                        "{key}={value}: {text}"
                    );
                }
            }
        }
    }
    for (key, value) in [
        ("left.yield_forces", "0"),
        ("left.yield_forces", "1,2"),
        ("left.hardening", "1"),
        ("left.hardening", "-0.1"),
        ("left.bouc_wen_n", "0.5"),
        ("left.hysteresis", "plastic"),
        ("motion.settle_s", "-1"),
    ] {
        let mut setup = BuildingSetup::default();
        let refused = setup
            .apply_assignment(&format!("{key}={value}"))
            .and_then(|_| setup.scenario.validate());
        let e = refused.expect_err(&format!("{key}={value} must be refused"));
        assert!(e.to_string().contains(key), "{key}={value}: {e}");
    }
}

/// Storeys of a yield force far below their loads flow the whole record: their corrections
/// follow their drifts through zero, where a piece's departure is measured against the largest
/// correction the storey has carried, not the one there.
fn flowing(law: Hysteresis, contact: ContactModel) -> BuildingScenario {
    let mut sc = yielding(contact);
    sc.left.hysteresis = law;
    sc.left.yield_forces_n = Some(vec![1e-3]);
    sc
}

#[test]
fn the_error_estimate_of_a_storey_flowing_the_whole_record_bounds_a_tenfold_refined_run() {
    let m = record(3.0);
    for (law, contact) in [
        (Hysteresis::BoucWen, ContactModel::Sears),
        (Hysteresis::Bilinear, ContactModel::Linear),
    ] {
        let sc = flowing(law, contact);
        let r = run(&sc, &m);
        // It flows: its peak drift is many times its yield drift.
        assert!(
            r.ductility_demand[0][0] > 1e5,
            "{law:?}: {:?}",
            r.ductility_demand
        );
        estimate_bounds_a_tenfold_refined_run(&sc, &m, &r, &format!("{law:?}"));
    }
}

#[test]
fn a_storey_flowing_the_whole_record_takes_at_most_three_times_the_steps_of_one_that_yields_a_few_times()
 {
    let m = record(8.0);
    for law in [Hysteresis::Bilinear, Hysteresis::BoucWen] {
        let mut yields = yielding(ContactModel::Sears);
        yields.left.hysteresis = law;
        let flows = run(&flowing(law, ContactModel::Sears), &m);
        let yields = run(&yields, &m);
        // A flowing storey's pieces are held by its drift's curvature, as a yielding one's are
        // near its yields (the bilinear one's free stretches are whole elsewhere); pieces held
        // to the correction where it passes through zero would take several times as many.
        assert!(
            flows.stats.steps <= 3 * yields.stats.steps,
            "{law:?}: {} steps against {}",
            flows.stats.steps,
            yields.stats.steps
        );
    }
}

#[test]
fn the_error_estimate_of_a_multi_storey_bouc_wen_pair_bounds_a_tenfold_refined_run() {
    // Three storeys beside five, every storey Bouc-Wen at the automatic yield force: contact
    // steps that take the loads of storeys followed on the trial before, where the modes moved
    // too little since for following them again to change a load beyond round-off.
    let m = record(3.0);
    for contact in [ContactModel::Linear, ContactModel::Hertz] {
        let setup: BuildingSetup =
            pounding::io::preset::load("mdof-3-5").expect("the preset loads");
        let mut sc = setup.scenario;
        sc.contact = contact;
        for b in [&mut sc.left, &mut sc.right] {
            b.hysteresis = Hysteresis::BoucWen;
            b.yield_forces_n = None;
        }
        let r = run(&sc, &m);
        assert!(r.stats.contact_steps > 0, "{contact:?}");
        assert!(r.hysteretic_energy_j.iter().flatten().any(|&e| e > 0.0));
        let est = estimate_error(&sc, &m, &r).expect("estimate");
        let truth = run(&refined(&sc, 10.0), &m);
        let force = rel(r.max_pounding_force_n, truth.max_pounding_force_n);
        assert!(
            force <= est.max_force.max(1e-12),
            "{contact:?}: max force error {force:e} over the bound {:e}",
            est.max_force
        );
        for s in 0..2 {
            for (floor, (a, b)) in r.peak_floor_displacement_m[s]
                .iter()
                .zip(&truth.peak_floor_displacement_m[s])
                .enumerate()
            {
                let peak = rel(*a, *b);
                assert!(
                    peak <= est.peak_displacement.max(1e-12),
                    "{contact:?} side {s} floor {floor}: peak error {peak:e} over the bound {:e}",
                    est.peak_displacement
                );
            }
        }
    }
}
