//! The x-t diagram's grid against independent truth: d'Alembert's closed form for wave theory,
//! and for a Sears run the d'Alembert sum of its own force history.

mod common;
use common::run;
use pounding::model::impact::ModelKind;
use pounding::model::scenario::{ImpactScenario, Reading};
use pounding::model::xt::XtGrid;

fn rods(l1: f64, l2: f64) -> ImpactScenario {
    let mut sc = ImpactScenario::default();
    sc.bar1.length_m = l1;
    sc.bar2.length_m = l2;
    sc
}

#[test]
fn wave_theory_grid_is_dalemberts_closed_form_away_from_the_fronts() {
    // 1 m on 2 m of equal steel: the force is F0 = Z w / 2 for one round trip of bar 1, T1.
    let sc = rods(1.0, 2.0);
    let r = run(ModelKind::Wave, &sc);
    let c = sc.bar1.wave_speed_m_s();
    let (l1, l2) = (1.0, 2.0);
    let t1 = 2.0 * l1 / c;
    let f0 = 0.5 * sc.bar1.impedance_n_s_m() * sc.approach_velocity_m_s();
    let area = sc.bar1.area_m2();
    let z = sc.bar1.impedance_n_s_m();
    let t_end = 3.0 * 2.0 * l2 / c;
    let (nx, nt) = (200, 400);
    let g = XtGrid::of(&r, [area; 2], [l1, l2], nx, nt, t_end);
    // Bar 1 holds F0 between the front x/c and its reflection's return (2 L1 - x)/c, and is at
    // rest, stress-free, after. Bar 2 carries a pulse of length T1 out and back, reflected as
    // tension at its free end, and so on.
    let pulse = |s: f64| if (0.0..t1).contains(&s) { 1.0 } else { 0.0 };
    let h2 = |s: f64| {
        // H2(s) = F(s) + H2(s - T2), F = F0 on [0, T1): F0 for s mod T2 in [0, T1).
        if s < 0.0 {
            0.0
        } else {
            f0 * pulse(s % (2.0 * l2 / c))
        }
    };
    let level = f0 / area;
    let mut checked = 0;
    let mut worst: f64 = 0.0;
    let dx = [l1, l2].map(|l| l / (nx - 1) as f64);
    let dt = t_end / (nt - 1) as f64;
    for (k, &t) in g.times_s.iter().enumerate() {
        for b in 0..2 {
            let l = [l1, l2][b];
            for (i, &x) in g.bars[b].x_m.iter().enumerate() {
                let (near, far) = (t - x / c, t - (2.0 * l - x) / c);
                // Away from every front: a cell's worth in x and t from any jump.
                let jumps: Vec<f64> = if b == 0 {
                    vec![near, far]
                } else {
                    (0..4)
                        .flat_map(|m| {
                            let s = m as f64 * 2.0 * l2 / c;
                            [near - s, near - s - t1, far - s, far - s - t1]
                        })
                        .collect()
                };
                let margin = 3.0 * (dt + dx[b] / c);
                if jumps.iter().any(|j| j.abs() < margin) {
                    continue;
                }
                let (stress, velocity) = if b == 0 {
                    let n = f0 * (if near > 0.0 && far < 0.0 { 1.0 } else { 0.0 });
                    let vel = sc.bar1.velocity_m_s
                        - (f0 * (near > 0.0) as u8 as f64 + f0 * (far > 0.0) as u8 as f64) / z;
                    (-n / area, vel)
                } else {
                    let n = h2(near) - h2(far);
                    (-n / area, sc.bar2.velocity_m_s + (h2(near) + h2(far)) / z)
                };
                let (gs, gv) = (
                    g.bars[b].stress_pa[k * nx + i],
                    g.bars[b].velocity_m_s[k * nx + i],
                );
                worst = worst.max((gs - stress).abs() / level);
                worst = worst.max((gv - velocity).abs() / (f0 / z));
                checked += 1;
            }
        }
    }
    eprintln!(
        "wave theory against the closed form: {checked} points, worst {worst:.2e} of the stress level"
    );
    assert!(
        checked > 100_000,
        "only {checked} points away from the fronts"
    );
    assert!(
        worst < 1e-3,
        "worst difference {worst:.2e} of the stress level"
    );
}

#[test]
fn a_sears_grid_is_the_dalembert_sum_of_its_own_force_history() {
    for reading in [Reading::End, Reading::Paper] {
        let mut sc = rods(1.0, 3.0);
        sc.reading = reading;
        let r = run(ModelKind::Sears, &sc);
        let waves = r.waves.as_ref().expect("Sears keeps its waves");
        let c = sc.bar1.wave_speed_m_s();
        let t_end = 4.0 * 2.0 * 3.0 / c;
        let (nx, nt) = (120, 300);
        let g = XtGrid::from_waves(waves, nx, nt, 0.0, t_end);
        // F between samples, linearly; zero after the run (the bars are apart).
        let force = |s: f64| {
            if s < 0.0 || s > r.end_s {
                return 0.0;
            }
            let k = r
                .time_s
                .partition_point(|&x| x <= s)
                .min(r.time_s.len() - 1)
                .max(1);
            let (t0, t1) = (r.time_s[k - 1], r.time_s[k]);
            let (f0, f1) = (r.force_n[k - 1], r.force_n[k]);
            if t1 > t0 {
                f0 + (f1 - f0) * (s - t0) / (t1 - t0)
            } else {
                f1
            }
        };
        let level = r.peak_force_n.unwrap() / sc.bar1.area_m2();
        let mut worst: f64 = 0.0;
        for b in 0..2 {
            let bar = [sc.bar1, sc.bar2][b];
            let (l, area) = (bar.length_m, bar.area_m2());
            let trip = 2.0 * l / c;
            for (k, &t) in g.times_s.iter().enumerate() {
                for (i, &x) in g.bars[b].x_m.iter().enumerate() {
                    // Every arrival of F with weight one: incident at x/c + m T, reflected (sign
                    // changed, free end) at (2L - x)/c + m T.
                    let mut n = 0.0;
                    let mut m = 0.0;
                    while t - x / c - m * trip > -trip {
                        n += force(t - x / c - m * trip) - force(t - (2.0 * l - x) / c - m * trip);
                        m += 1.0;
                    }
                    worst = worst.max((g.bars[b].stress_pa[k * nx + i] + n / area).abs() / level);
                }
            }
        }
        eprintln!(
            "{}: worst difference {worst:.2e} of the peak stress",
            reading.name()
        );
        assert!(
            worst < 1e-3,
            "{}: worst difference {worst:.2e} of the peak stress",
            reading.name()
        );
    }
}
