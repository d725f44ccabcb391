//! A bridge girder between contacts only rings: read in closed form (quiet), it must be what
//! stepping it gives, its envelope must bound every later end wave, and a girder revived from
//! the closed form must go on as the stepped one does.

use pounding::model::bridge::Girder;
use pounding::model::bridge::girder::GirderWaves;

/// A 40 m concrete box girder, as the bridge presets' (A 6.5 m^2, E 3.4e10 Pa, 2500 kg/m^3).
fn girder() -> Girder {
    Girder {
        length_m: 40.0,
        area_m2: 6.5,
        youngs_pa: 3.4e10,
        mass_kg: 2500.0 * 6.5 * 40.0,
    }
}

/// Half-sine pulses: at the left end from 0 to 2 ms (30 MN), at the right from 1 ms to 4 ms
/// (12 MN), so the two ends' waves overlap in the girder.
fn forces(t: f64) -> [f64; 2] {
    let pulse = |t: f64, start: f64, len: f64, peak: f64| {
        if t > start && t < start + len {
            peak * (std::f64::consts::PI * (t - start) / len).sin()
        } else {
            0.0
        }
    };
    [pulse(t, 0.0, 2e-3, 3e7), pulse(t, 1e-3, 3e-3, 1.2e7)]
}

/// D'Alembert's end waves of the girder under the end forces as the solver sees them (each
/// linear between grid samples), integrated on a grid 64 times finer than the solver's.
struct Exact {
    h: f64,
    lam: f64,
    round: f64,
    inv_z: f64,
    inv_m: f64,
}

impl Exact {
    fn new(zeta: f64, h: f64) -> Self {
        let g = girder();
        let round = g.round_trip_s();
        Exact {
            h,
            lam: 2.0 * std::f64::consts::PI * zeta / round,
            round,
            inv_z: 1.0 / g.impedance_n_s_m(),
            inv_m: 1.0 / g.mass_kg,
        }
    }

    /// End `e`'s force at t, linear between the grid samples.
    fn force(&self, e: usize, t: f64) -> f64 {
        let i = (t / self.h).floor();
        let x = t / self.h - i;
        (1.0 - x) * forces(i * self.h)[e] + x * forces((i + 1.0) * self.h)[e]
    }

    /// int_0^t (t - s)^k exp(-lam (t - s)) F_e(s) ds for k = 0 (A) and 1 (B): by Simpson's rule
    /// (16 panels a step) while the forces act, and once they have stopped (after 4.5 ms) in
    /// closed form from there: A decays, B = (B_q + A_q (t - t_q)) exp(-lam (t - t_q)).
    fn moment(&self, e: usize, t: f64, k: i32) -> f64 {
        const STOP: f64 = 4.5e-3;
        if t > STOP {
            let decay = (-self.lam * (t - STOP)).exp();
            let (a, b) = (self.moment(e, STOP, 0), self.moment(e, STOP, 1));
            return if k == 0 {
                decay * a
            } else {
                decay * (b + (t - STOP) * a)
            };
        }
        if t <= 0.0 {
            return 0.0;
        }
        let n = 2 * ((8.0 * t / self.h).ceil() as usize).max(1);
        let d = t / n as f64;
        let f = |s: f64| (t - s).powi(k) * (-self.lam * (t - s)).exp() * self.force(e, s);
        let mut sum = f(0.0) + f(t);
        for i in 1..n {
            sum += if i % 2 == 1 { 4.0 } else { 2.0 } * f(i as f64 * d);
        }
        sum * d / 3.0
    }

    /// Q(t) = sum_j r^j A(t - j T).
    fn q(&self, e: usize, t: f64) -> f64 {
        let r = (-self.lam * self.round).exp();
        let mut sum = 0.0;
        let mut j = 0;
        while t - j as f64 * self.round > 0.0 {
            sum += r.powi(j) * self.moment(e, t - j as f64 * self.round, 0);
            j += 1;
        }
        sum
    }

    fn waves(&self, t: f64) -> [f64; 2] {
        let r = (-self.lam * self.round).exp();
        let r_half = (-0.5 * self.lam * self.round).exp();
        let reading = |e: usize| {
            let b = self.moment(e, t, 1) * self.inv_m;
            let own = self.inv_z * (self.q(e, t) + r * self.q(e, t - self.round)) - b;
            let far = 2.0 * self.inv_z * r_half * self.q(e, t - 0.5 * self.round) - b;
            [own, far]
        };
        let (l, r) = (reading(0), reading(1));
        [l[0] - r[1], l[1] - r[0]]
    }
}

/// Steps the girder through the pulses and two zero steps; returns it and its step count.
fn struck(zeta: f64, h: f64) -> (GirderWaves, usize) {
    let mut g = GirderWaves::new(&girder(), zeta, h);
    let mut n = 0;
    let mut prev = [0.0; 2];
    loop {
        let f = forces((n + 1) as f64 * h);
        g.predict(prev);
        g.commit(f);
        n += 1;
        if f == [0.0, 0.0] && prev == [0.0, 0.0] {
            return (g, n);
        }
        prev = f;
    }
}

/// The end waves after one stepped step with no force.
fn stepped_waves(g: &mut GirderWaves) -> [f64; 2] {
    let p = g.predict([0.0; 2]);
    g.commit([0.0; 2]);
    g.end_waves([p.left, p.right], [0.0; 2])
}

/// What a quiet girder's ringing read in closed form is, against stepping it with zero force,
/// for 10 round trips after a strike on a grid of `per_trip` steps a round trip: each reading's
/// largest distance from d'Alembert's (stepped, closed form; sampled every 13 steps), how far
/// they are apart, the largest wave, and the largest ratio of a wave to its envelope.
struct Ringing {
    off: [f64; 2],
    apart: f64,
    amplitude: f64,
    over: f64,
}

fn ringing(zeta: f64, per_trip: f64) -> Ringing {
    let round = girder().round_trip_s();
    let h = round / per_trip;
    let (mut stepped, n0) = struck(zeta, h);
    let mut quiet = stepped.clone();
    quiet.settle();
    assert!(quiet.is_quiet(), "both forces have stopped: it falls quiet");
    let exact = Exact::new(zeta, h);
    let mut out = Ringing {
        off: [0.0; 2],
        apart: 0.0,
        amplitude: 0.0,
        over: f64::NEG_INFINITY,
    };
    let steps = (10.0 * round / h) as usize;
    for n in n0 + 1..=n0 + steps {
        let w = stepped_waves(&mut stepped);
        let c = quiet.waves_at(n);
        let bound = quiet.envelope_from(n);
        if n % 13 == 0 {
            let truth = exact.waves(n as f64 * h);
            for e in 0..2 {
                out.off[0] = out.off[0].max((w[e] - truth[e]).abs());
                out.off[1] = out.off[1].max((c[e] - truth[e]).abs());
            }
        }
        for e in 0..2 {
            out.apart = out.apart.max((w[e] - c[e]).abs());
            out.amplitude = out.amplitude.max(w[e].abs());
            out.over = out.over.max(w[e].abs() / bound[e]);
        }
    }
    eprintln!(
        "zeta {zeta}, {per_trip} steps a round trip: amplitude {:.3e} m, closed form apart by {:.2e}, d'Alembert's off by {:.2e} (stepped) and {:.2e} (closed form), largest wave / envelope {:.3}",
        out.amplitude, out.apart, out.off[0], out.off[1], out.over
    );
    out
}

#[test]
fn a_quiet_girders_ringing_is_dalemberts_as_stepping_it_is_and_its_envelope_bounds_it() {
    for zeta in [0.05, 0.0] {
        let coarse = ringing(zeta, 480.37);
        let fine = ringing(zeta, 960.74);
        assert!(coarse.amplitude > 1e-4, "the pulses set it ringing");
        for r in [&coarse, &fine] {
            // The closed form (one look-up a whole number of round trips back) is as close to
            // d'Alembert as stepping (look-ups of look-ups): both err by the look-ups'
            // truncation where the pulses start with a kink.
            assert!(
                r.off[1] <= 1.5 * r.off[0],
                "closed form off by {:.2e}, stepped by {:.2e}",
                r.off[1],
                r.off[0]
            );
            assert!(
                r.over <= 1.0,
                "an end wave {:.3} times its envelope",
                r.over
            );
            // Not loose by orders of magnitude either.
            assert!(
                r.over >= 0.3,
                "the envelope is {:.1} times the waves",
                1.0 / r.over
            );
        }
        // And both converge to it with the step, at second order (a factor 4 in the limit).
        for k in 0..2 {
            assert!(
                fine.off[k] <= coarse.off[k] / 3.0,
                "reading {k}: {:.2e} -> {:.2e}",
                coarse.off[k],
                fine.off[k]
            );
        }
    }
}

#[test]
fn a_girder_revived_from_its_closed_form_goes_on_as_the_stepped_one() {
    let round = girder().round_trip_s();
    let h = round / 511.7;
    let (mut stepped, n0) = struck(0.05, h);
    let mut quiet = stepped.clone();
    quiet.settle();
    // Three and a half round trips of ringing, then a new push at the right end.
    let quiet_steps = (3.5 * round / h) as usize;
    for _ in 0..quiet_steps {
        stepped_waves(&mut stepped);
    }
    quiet.skip(quiet_steps);
    assert_eq!(quiet.newest_index(), n0 + quiet_steps);
    quiet.revive();
    assert!(!quiet.is_quiet());
    let mut prev = [0.0; 2];
    let mut apart = 0.0f64;
    let mut amplitude = 0.0f64;
    for k in 1..=(2.0 * round / h) as usize {
        let f = [0.0, 2e7 * ((k as f64 * h / 1e-3).min(1.0))];
        let f = if k as f64 * h > 2e-3 { [0.0; 2] } else { f };
        let ps = stepped.predict(prev);
        let pq = quiet.predict(prev);
        stepped.commit(f);
        quiet.commit(f);
        let ws = stepped.end_waves([ps.left, ps.right], f);
        let wq = quiet.end_waves([pq.left, pq.right], f);
        for e in 0..2 {
            apart = apart.max((ws[e] - wq[e]).abs());
            amplitude = amplitude.max(ws[e].abs());
        }
        prev = f;
    }
    eprintln!("revived: amplitude {amplitude:.3e} m, apart by {apart:.2e}");
    // As far apart as the two readings of the ringing in the test above.
    assert!(apart <= 2e-4 * amplitude, "{apart:.2e} of {amplitude:.2e}");
}

/// The envelope a free stretch reads the quiet girder's waves against must bound every later
/// end wave of the closed form the stretch reads, on coarse grids (16 to 46 steps a round trip,
/// as soft contacts and a loose tolerance give) and under heavy damping (up to 0.6, where one
/// round trip's attenuation is 0.02): pushes of random sizes at one end, the other or both
/// (fixed seed), then 60 round trips of ringing read at every grid point.
#[test]
fn a_quiet_girders_envelope_bounds_its_closed_form_on_coarse_grids_and_under_heavy_damping() {
    let mut seed: u64 = 0x2545_F491_4F6C_DD1D;
    let mut uniform = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let round = girder().round_trip_s();
    let mut worst: f64 = 0.0;
    for case in 0..400 {
        let zeta = [0.0, 0.02, 0.05, 0.3, 0.6][case % 5];
        let per_trip = 16.0 + 30.0 * uniform();
        let h = round / per_trip;
        let pushes: Vec<[f64; 2]> = (0..1 + (uniform() * 40.0) as usize)
            .map(|_| {
                let mut end = || {
                    if uniform() < 0.5 {
                        0.0
                    } else {
                        1e7 * uniform()
                    }
                };
                [end(), end()]
            })
            .collect();
        let mut g = GirderWaves::new(&girder(), zeta, h);
        let mut prev = [0.0; 2];
        for f in pushes.iter().copied().chain([[0.0; 2]; 2]) {
            g.predict(prev);
            g.commit(f);
            prev = f;
        }
        g.settle();
        if !g.is_frozen() {
            continue;
        }
        let n0 = g.newest_index();
        for n in n0 + 1..=n0 + (60.0 * per_trip) as usize {
            let (waves, bound) = (g.waves_at(n), g.envelope_from(n));
            for e in 0..2 {
                if waves[e] != 0.0 {
                    worst = worst.max(waves[e].abs() / bound[e]);
                }
            }
        }
    }
    eprintln!("largest end wave against its envelope: {worst:.3}");
    assert!(worst <= 1.0, "an end wave {worst:.3} times its envelope");
    assert!(
        worst >= 0.3,
        "the envelope is {:.1} times the waves",
        1.0 / worst
    );
}
