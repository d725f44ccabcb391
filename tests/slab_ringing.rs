//! A floor slab rings after a contact for as long as its damping lets it, and the building run
//! reads that ringing at the next onset. The run reads it in closed form (Q(t) = J A(t) +
//! r^J Q(t - J T), from the round trip before the force stopped), which costs nothing between
//! contacts, instead of stepping the slab's recursion on the contact grid all the way. Both
//! against d'Alembert's sum for the same force, integrated here independently by quadrature:
//! the closed form and the stepped recursion agree with each other far more closely than either
//! with it, so the closed form loses nothing.

use pounding::model::building::Slab;
use pounding::model::building::slab::SlabWaves;

/// The paper's roof slab carrying the left building's 36 t.
fn slab() -> (Slab, f64) {
    (
        Slab {
            length_m: 10.0,
            width_m: 8.0,
            thickness_m: 0.15,
            youngs_modulus_pa: 2.5e10,
        },
        36_000.0,
    )
}

/// A contact's force: rising linearly from the onset and falling linearly to the separation,
/// with kinks at both ends and at the top (the hardest shape for a cubic look-up).
fn force(t: f64) -> f64 {
    let (f0, t1) = (4.0e6, 3.0e-3);
    if (0.0..=t1).contains(&t) {
        f0 * (1.0 - (2.0 * t / t1 - 1.0).abs())
    } else {
        0.0
    }
}

/// Simpson's rule over [a, b] with n (even) intervals.
fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
    if b <= a {
        return 0.0;
    }
    let h = (b - a) / n as f64;
    let mut s = f(a) + f(b);
    for i in 1..n {
        s += f(a + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    s * h / 3.0
}

/// d'Alembert's elastic displacement of the plane a zone length in from the struck end, with
/// the slab's material damping (every arrival attenuated by exp(-travel / t_d)).
struct Exact {
    inv_z: f64,
    inv_m: f64,
    round: f64,
    tau: f64,
    decay_time: f64,
}

impl Exact {
    fn a(&self, t: f64) -> f64 {
        let t1 = 3.0e-3;
        simpson(
            |s| (-(t - s) / self.decay_time).exp() * force(s),
            0.0,
            t.min(t1),
            2000,
        )
    }

    fn q(&self, t: f64) -> f64 {
        let r = (-self.round / self.decay_time).exp();
        let mut sum = 0.0;
        let mut j = 0;
        while t - j as f64 * self.round > 0.0 {
            sum += r.powi(j) * self.a(t - j as f64 * self.round);
            j += 1;
        }
        sum
    }

    fn b(&self, t: f64) -> f64 {
        let t1 = 3.0e-3;
        let inside = |u: f64| {
            simpson(
                |s| (-(u - s) / self.decay_time).exp() * self.a(s),
                0.0,
                u,
                400,
            )
        };
        if t <= t1 {
            return inside(t);
        }
        (-(t - t1) / self.decay_time).exp() * (inside(t1) + self.a(t1) * (t - t1))
    }

    fn elastic(&self, t: f64) -> f64 {
        let near = (-self.tau / self.decay_time).exp() * self.q(t - self.tau);
        let far =
            (-(self.round - self.tau) / self.decay_time).exp() * self.q(t - self.round + self.tau);
        self.inv_z * (near + far) - self.inv_m * self.b(t)
    }
}

#[test]
fn a_slabs_ringing_read_in_closed_form_is_what_stepping_it_gives_and_both_are_dalembert_to_1e_5() {
    let (slab, mass) = slab();
    let zeta = 0.01;
    let zone = 1.0;
    let c = slab.wave_speed_m_s(mass);
    let round = 2.0 * slab.length_m / c;
    let h = round / 495.3;
    let exact = Exact {
        inv_z: 1.0 / slab.impedance_n_s_m(mass),
        inv_m: 1.0 / mass,
        round,
        tau: zone / c,
        decay_time: round / (2.0 * std::f64::consts::PI * zeta),
    };
    let pulse_end = (3.0e-3 / h).ceil() as usize + 1;
    let mut stepped = SlabWaves::new(&slab, mass, zone, zeta, h, 1.0, usize::MAX);
    stepped.revive(0);
    for n in 1..=pulse_end {
        stepped.push(force(n as f64 * h));
    }
    let mut folded = stepped.clone();
    folded.settle();
    assert!(
        !folded.is_live(),
        "the force has stopped: the slab falls quiet"
    );
    let mut worst = [0.0f64; 2];
    let mut apart = 0.0f64;
    let mut amplitude = 0.0f64;
    let mut n = pulse_end;
    for trips in [2usize, 5, 10, 20] {
        let target = pulse_end + (trips as f64 * round / h) as usize + 37;
        while n < target {
            n += 1;
            stepped.push(0.0);
        }
        let truth = exact.elastic(n as f64 * h);
        let errors = [
            (stepped.elastic_m() - truth).abs(),
            (folded.elastic_at(n) - truth).abs(),
        ];
        let between = (stepped.elastic_m() - folded.elastic_at(n)).abs();
        eprintln!(
            "{trips:2} round trips on: d'Alembert {truth:.6e} m, stepped off by {:.2e}, closed form off by {:.2e}, they differ by {between:.2e}",
            errors[0], errors[1]
        );
        apart = apart.max(between);
        amplitude = amplitude.max(truth.abs());
        for k in 0..2 {
            worst[k] = worst[k].max(errors[k]);
        }
    }
    // The two readings differ by far less than either's error (that of the force's
    // discretisation, which they share).
    assert!(
        apart <= 1e-3 * worst[0].min(worst[1]),
        "they differ by {apart:.2e}, each off by {:.2e} / {:.2e}",
        worst[0],
        worst[1]
    );
    // And both are d'Alembert's ringing to a part in 10^5.
    for w in worst {
        assert!(w < 1e-5 * amplitude, "{w:.2e} of {amplitude:.2e}");
    }
}

/// A drawing puts every slab's history on a grid in one pass (`history_on_grid`); the picture
/// must be the model's, so each sample is what reading H at that instant gives: on grids finer
/// and coarser than the solver's, across contacts, the ringing between them and the ringing
/// after the run. On a grid of a whole number of samples a round trip (the drawings' 400) the
/// ringing past a stretch is the sample a round trip before times r, which differs from a
/// reading by the rounding of the round trip on the grid: within 1e-10 of the largest H (the
/// drawings keep f32, good to 6e-8); every other sample is the reading to the bit.
#[test]
fn a_slab_history_put_on_a_grid_in_one_pass_is_the_history_read_instant_by_instant() {
    use pounding::io::building_settings::BuildingSetup;
    use pounding::model::field::History;
    let mut setup: BuildingSetup =
        pounding::io::preset::load_for("paper-buildings", "buildings").expect("preset");
    // Slab damping makes each round trip of ringing weaker than the last.
    setup.apply_assignment("slab.damping=0.05").expect("key");
    setup.apply_assignment("motion.duration=3").expect("key");
    let motion = pounding::io::motion::load(&setup.motion).expect("record");
    let result = pounding::model::building::solve(&setup.scenario, &motion).expect("run");
    let mut checked = 0;
    for w in result.slab_waves().iter().flat_map(|l| l.iter().flatten()) {
        let History::Segments { dt_s, segments } = &w.history else {
            panic!("a slab's history is kept in stretches");
        };
        assert!(
            segments.len() > 3,
            "several contacts and ringing between them"
        );
        assert!(w.decay_per_s > 0.0);
        let drawings = w.round_trip_s() / 400.0;
        for dt in [0.37, 1.0, 1.2, 7.9]
            .map(|scale| dt_s * scale)
            .into_iter()
            .chain([drawings])
        {
            // Past the run's end: the ringing after it.
            let n = (1.2 * w.end_s / dt) as usize;
            let grid: Vec<f64> = w.history_on_grid(dt, n).collect();
            assert_eq!(grid.len(), n);
            let read: Vec<f64> = (0..n).map(|k| w.history_at(k as f64 * dt)).collect();
            let largest = read.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let mut multiplied = 0;
            let mut worst = 0.0f64;
            for (k, (v, at)) in grid.iter().zip(&read).enumerate() {
                if dt == drawings {
                    assert!(
                        (v - at).abs() <= 1e-10 * largest,
                        "sample {k} of the drawings' grid: {v:e} against {at:e}"
                    );
                    multiplied += usize::from(v.to_bits() != at.to_bits());
                    worst = worst.max((v - at).abs() / largest);
                } else {
                    assert!(
                        v.to_bits() == at.to_bits(),
                        "sample {k} of dt = {dt:e}: {v:e} against {at:e}"
                    );
                }
            }
            if dt == drawings {
                eprintln!(
                    "the drawings' grid: {multiplied} of {n} samples multiplied, within {worst:.1e} of the largest H"
                );
                // Most of the ringing is multiplied, not read.
                assert!(multiplied > n / 4, "{multiplied} of {n}");
            }
            assert!(grid.iter().any(|v| *v != 0.0));
            checked += n;
        }
    }
    assert!(checked > 100_000, "{checked} samples");
}

/// A slab keeps its forces for drawing its waves within a share of samples: every grid point's
/// while they fit, then every second, fourth, ... one, so that the memory is set by the share,
/// not the steps. The waves drawn from those are the ones drawn from every force: H = F +
/// r H(t - T) holds at every instant, so the recursion on the coarser grid samples the same
/// history; only its look-ups of H a round trip back are interpolated more coarsely. Both against
/// the sum H(t) = sum_k r^k F(t - k T) of two contacts' forces, the second while the first still
/// rings (its history also holds the round trips before it).
#[test]
fn a_slab_over_its_share_keeps_every_fourth_force_and_draws_the_same_waves() {
    let (slab, mass) = slab();
    let (zeta, zone) = (0.05, 1.0);
    let round = 2.0 * slab.length_m / slab.wave_speed_m_s(mass);
    let h = round / 2000.3;
    let pulse_end = (3.0e-3 / h).ceil() as usize + 1;
    let ringing = (2.2 * round / h) as usize;
    let second = pulse_end + ringing;
    let stepped = |share: usize| {
        let mut s = SlabWaves::new(&slab, mass, zone, zeta, h, 1.0, share);
        // Two contacts, each with its ringing stepped for two round trips.
        for start in [0, second] {
            s.revive(start);
            for j in 1..=pulse_end {
                s.push(force(j as f64 * h));
            }
            for _ in 0..ringing {
                s.push(0.0);
            }
            s.settle();
        }
        s.waves((2 * second) as f64 * h)
    };
    // 2 x 5 270 forces in all: a share of 3 000 is outgrown twice.
    let (every, thinned) = (stepped(usize::MAX), stepped(3000));
    let samples = |w: &pounding::model::field::BarWaves| match &w.history {
        pounding::model::field::History::Segments { dt_s, segments } => (
            *dt_s,
            segments.iter().map(|s| s.values.len()).sum::<usize>(),
        ),
        _ => panic!("a slab's history is kept in stretches"),
    };
    let ((dt1, n1), (dt4, n4)) = (samples(&every), samples(&thinned));
    assert!(
        (dt4 - 4.0 * dt1).abs() <= 1e-12 * dt4,
        "{dt4} against {dt1}"
    );
    // A quarter of the samples (each stretch's history also holds the round trips before it, on
    // its own grid, whose look-ups' reach rounds differently: a few tens of samples).
    assert!(4 * n4 <= n1 + 128, "{n4} samples kept against {n1}");
    let r = (-2.0 * std::f64::consts::PI * zeta).exp();
    let truth = |t: f64| {
        (0..20)
            .map(|k| {
                let back = t - k as f64 * round;
                r.powi(k) * (force(back) + force(back - second as f64 * h))
            })
            .sum::<f64>()
    };
    let t_end = (2 * second) as f64 * h;
    let (mut e1, mut e4, mut apart, mut largest) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for i in 0..=4000 {
        let t = t_end * i as f64 / 4000.0;
        let (a, b) = (every.history_at(t), thinned.history_at(t));
        largest = largest.max(a.abs());
        apart = apart.max((a - b).abs());
        e1 = e1.max((a - truth(t)).abs());
        e4 = e4.max((b - truth(t)).abs());
    }
    eprintln!(
        "every fourth force: H differs by {apart:.2e} of {largest:.2e}; off the sum by {e1:.2e} (every force) and {e4:.2e} (every fourth)"
    );
    assert!(largest > 1e6, "the pulses are there: {largest:e}");
    // A cubic look-up across the force's kinks is off by a fraction of what the force changes
    // over one kept step: within a quarter of that, on either grid.
    let slope = 4.0e6 / 1.5e-3;
    for (e, keep) in [(e1, 1.0), (e4, 4.0)] {
        assert!(
            e <= 0.25 * slope * keep * h,
            "keeping every {keep} forces: off by {e:.2e}, against {:.2e}",
            0.25 * slope * keep * h
        );
    }
    assert!(
        apart <= 0.25 * slope * 4.0 * h,
        "{apart:.2e} of {largest:.2e}: the drawing would move"
    );
}
