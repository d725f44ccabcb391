//! Stress and particle velocity anywhere in a bar, from its wave history.
//!
//! With the history sum H(t) = F(t) + H(t - T) of the force on the impacting end (T = 2l/c),
//! d'Alembert's solution for a free-free bar gives, at distance x from that end,
//!   axial force N(x, t) = H(t - x/c) - H(t - (2l - x)/c)   (compression positive),
//!   velocity change  dv = (H(t - x/c) + H(t - (2l - x)/c)) / Z, directed away from the contact.
//! Beyond the simulated span the force is taken as zero, so H repeats with period T.
//!
//! A damped bar (the building slabs' material damping, see `building::slab`) attenuates every
//! arrival by exp(-tau / t_d), tau its travel time: then H(t) = F(t) + r H(t - T) with
//! r = exp(-T / t_d), and each term above carries exp(-x / (c t_d)) or exp(-(2l - x) / (c t_d)).

use super::history::{Tap, sample_at, sample_at_unit};
use super::ring::{Look, Ring};

/// How a history is stored.
#[derive(Debug, Clone, PartialEq)]
pub enum History {
    /// Samples at t = n dt, n = 0, 1, ...
    Uniform {
        /// The spacing [s].
        dt_s: f64,
        /// H at each sample.
        values: Vec<f64>,
    },
    /// A step function: `values[k]` holds on [times[k], times[k+1]).
    Steps {
        /// Where each step starts [s].
        times: Vec<f64>,
        /// H on each step.
        values: Vec<f64>,
    },
    /// Stretches of samples at t = n dt, in time order, zero before the first; after each
    /// stretch no force acts until the next, so H repeats its stretch's last round trip,
    /// attenuated by r each time (a building slab between contacts).
    Segments {
        /// The spacing [s].
        dt_s: f64,
        /// The stretches, in time order.
        segments: Vec<HistorySegment>,
    },
}

/// One stretch of a [`History::Segments`]: samples at indices `first`, `first + 1`, ...
#[derive(Debug, Clone, PartialEq)]
pub struct HistorySegment {
    /// Grid index of the first sample.
    pub first: usize,
    /// H at each sample.
    pub values: Vec<f64>,
}

impl HistorySegment {
    /// H at the fractional grid index `p` (at or after `first`): cubic inside the stretch, and
    /// after it the stretch's last round trip (`round_steps` grid steps) repeated, attenuated by
    /// `r` per round trip.
    pub fn value_at(&self, p: f64, round_steps: f64, r: f64) -> f64 {
        let last = (self.first + self.values.len()) as f64 - 1.0;
        let (mut p, mut weight) = (p, 1.0);
        if p > last && round_steps > 0.0 {
            let k = ((p - last) / round_steps).ceil();
            p -= k * round_steps;
            weight = r.powi(k as i32);
        }
        let local = p - self.first as f64;
        if local < 0.0 {
            return 0.0;
        }
        weight * sample_at(&self.values, 1.0, local)
    }
}

/// The wave state of one bar, enough to evaluate its field at any point and time.
#[derive(Debug, Clone, PartialEq)]
pub struct BarWaves {
    /// Length of the elastic body the waves run in [m].
    pub body_length_m: f64,
    /// Length of a massless contact zone before the body (collocated Sears reading), else 0.
    pub zone_length_m: f64,
    /// Wave speed c [m/s].
    pub wave_speed_m_s: f64,
    /// Cross-section area [m^2].
    pub area_m2: f64,
    /// Impedance Z [N s/m].
    pub impedance_n_s_m: f64,
    /// Rigid-body velocity before impact [m/s].
    pub initial_velocity_m_s: f64,
    /// +1 when the force pushes the bar towards +x of the lab (bar 2), -1 for bar 1.
    pub push_direction: f64,
    /// H(t) over the simulated span.
    pub history: History,
    /// End of the simulated span [s].
    pub end_s: f64,
    /// Material damping 1 / t_d [1/s]: every arrival is attenuated by exp(-travel time / t_d);
    /// 0 for elastic bars.
    pub decay_per_s: f64,
}

/// What a bar's waves need besides its force history: its geometry, material and damping, and
/// which way the force pushes it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BarBody {
    /// [m]
    pub length_m: f64,
    /// Cross-section area [m^2].
    pub area_m2: f64,
    /// [m/s]
    pub wave_speed_m_s: f64,
    /// Z = rho A c [N s/m].
    pub impedance_n_s_m: f64,
    /// Material damping 1 / t_d [1/s].
    pub decay_per_s: f64,
    /// +1 when the force pushes the bar towards +x.
    pub push_direction: f64,
}

impl BarWaves {
    /// The waves of a bar whose end force was recorded over stretches of a grid of step `h`
    /// (each stretch: the index of its first sample, and the force at it and after; no force
    /// between stretches): H = F + r H(t - T) over each stretch, repeated round trip by round
    /// trip (attenuated by r) between them. `end_s` is the run's end.
    pub fn from_stretches(
        body: BarBody,
        h: f64,
        stretches: &[(usize, Vec<f64>)],
        end_s: f64,
    ) -> Self {
        let t = 2.0 * body.length_m / body.wave_speed_m_s;
        let round_steps = t / h;
        let tap = Look::of(Tap::new(t, h));
        let r = (-t * body.decay_per_s).exp();
        let gain = 1.0 / (1.0 - r * tap.newest);
        // Each stretch starts a round trip early (the previous stretch's ringing): folding past
        // its end reads its last round trip, which must be stored whatever the contact's length.
        let lead = round_steps.ceil() as usize + tap.reach() + 4;
        let mut segments: Vec<HistorySegment> = Vec::with_capacity(stretches.len());
        let mut ring = Ring::new(tap.reach());
        for (first, forces) in stretches {
            // The samples before the stretch: the previous stretch's ringing, or rest.
            let start = first.saturating_sub(lead);
            ring.next = start;
            // Kept as they are made: the lead is longer than the ring, which keeps only the
            // look-ups' reach (read back from it, the oldest would be later samples').
            let mut values: Vec<f64> = Vec::with_capacity(first - start + forces.len());
            for i in start..*first {
                let v = segments.last().map_or(0.0, |s: &HistorySegment| {
                    s.value_at(i as f64, round_steps, r)
                });
                ring.push(v);
                values.push(v);
            }
            for &f in forces {
                let v = (f + r * ring.known(&tap)) * gain;
                ring.push(v);
                values.push(v);
            }
            segments.push(HistorySegment {
                first: start,
                values,
            });
        }
        BarWaves {
            body_length_m: body.length_m,
            zone_length_m: 0.0,
            wave_speed_m_s: body.wave_speed_m_s,
            area_m2: body.area_m2,
            impedance_n_s_m: body.impedance_n_s_m,
            initial_velocity_m_s: 0.0,
            push_direction: body.push_direction,
            end_s,
            history: History::Segments { dt_s: h, segments },
            decay_per_s: body.decay_per_s,
        }
    }

    /// H at t = k dt for k = 0, 1, ... n - 1: [`BarWaves::history_at`] at each, in one pass.
    /// A drawing puts a run's waves on such a grid after every run (a million samples for a
    /// pair of slabs over 8 s); walking the stretches in order, and working out each round
    /// trip's attenuation once, takes a fraction of the time looking each one up does. Where
    /// the grid holds a whole number of samples a round trip (the drawings' 400), a sample past
    /// a stretch's end is r times the one a round trip before it (the ringing repeats,
    /// attenuated: H(t + T) = r H(t) once the force has stopped), a multiplication instead of a
    /// look-up: it differs from `history_at` by the rounding of the round trip on the grid, a
    /// part in 10^10 of the largest H at most (the drawings keep f32, good to 6e-8). Every
    /// other sample is `history_at`'s to the bit.
    pub fn history_on_grid(&self, dt: f64, n: usize) -> impl Iterator<Item = f64> + '_ {
        let stretches = match &self.history {
            History::Segments { dt_s, segments } => Some((*dt_s, segments)),
            _ => None,
        };
        let round_steps = stretches.map_or(0.0, |(dt_s, _)| self.round_trip_s() / dt_s);
        let r = self.attenuation(self.round_trip_s());
        // The stretch under way (the last that starts at or before the sample), and the
        // attenuation of the last round-trip count folded back.
        let mut next = 0;
        let mut folds = (0.0, 1.0);
        // Where the next stretch starts (its first sample), and the last sample of the one
        // under way: kept as the stretch changes, not worked out for every sample.
        let first_of = |i: usize, segments: &[HistorySegment]| {
            segments.get(i).map_or(f64::INFINITY, |s| s.first as f64)
        };
        let mut next_first = stretches.map_or(f64::INFINITY, |(_, s)| first_of(0, s));
        let mut last = 0.0;
        // Samples a round trip on this grid, where a whole number, and the last round trip's.
        let per_trip = self.round_trip_s() / dt;
        let whole = per_trip.round();
        let period =
            if stretches.is_some() && whole >= 1.0 && (per_trip - whole).abs() <= 1e-9 * per_trip {
                whole as usize
            } else {
                0
            };
        let mut recent = vec![0.0; period];
        (0..n).map(move |k| {
            let Some((dt_s, segments)) = stretches else {
                return self.history_at(k as f64 * dt);
            };
            let p = (k as f64 * dt) / dt_s;
            while next_first <= p && next < segments.len() {
                let seg = &segments[next];
                last = (seg.first + seg.values.len()) as f64 - 1.0;
                next += 1;
                next_first = first_of(next, segments);
            }
            let Some(seg) = next.checked_sub(1).map(|i| &segments[i]) else {
                return 0.0;
            };
            if period > 0 && p > last && round_steps > 0.0 && k >= period {
                // Past the stretch's end a round trip back is in the same stretch (it stores
                // the round trip before its forces): the ringing there, attenuated once more.
                let v = r * recent[k % period];
                recent[k % period] = v;
                return v;
            }
            let (mut q, mut weight) = (p, 1.0);
            if p > last && round_steps > 0.0 {
                let trips = ceil_positive((p - last) / round_steps);
                if folds.0 != trips {
                    folds = (trips, r.powi(trips as i32));
                }
                q -= trips * round_steps;
                weight = folds.1;
            }
            let local = q - seg.first as f64;
            let v = if local < 0.0 {
                0.0
            } else {
                // sample_at with a unit step (its division by one left out: the same bits).
                weight * sample_at_unit(&seg.values, local)
            };
            if period > 0 {
                recent[k % period] = v;
            }
            v
        })
    }

    /// The body's round trip 2 L / c [s].
    pub fn round_trip_s(&self) -> f64 {
        2.0 * self.body_length_m / self.wave_speed_m_s
    }

    /// Total length, zone included [m].
    pub fn length_m(&self) -> f64 {
        self.body_length_m + self.zone_length_m
    }

    /// H(t): zero before the impact; after the simulated span (no force) each round trip
    /// repeats the last, attenuated by r.
    pub fn history_at(&self, t_s: f64) -> f64 {
        if t_s < 0.0 {
            return 0.0;
        }
        if let History::Segments { dt_s, segments } = &self.history {
            let p = t_s / dt_s;
            let k = segments.partition_point(|s| s.first as f64 <= p);
            return match k {
                0 => 0.0,
                k => segments[k - 1].value_at(
                    p,
                    self.round_trip_s() / dt_s,
                    self.attenuation(self.round_trip_s()),
                ),
            };
        }
        let mut t = t_s;
        let mut weight = 1.0;
        let period = self.round_trip_s();
        if t > self.end_s && period > 0.0 {
            let k = ((t - self.end_s) / period).ceil();
            t -= k * period;
            if t < 0.0 {
                return 0.0;
            }
            weight = self.attenuation(k * period);
        }
        weight
            * match &self.history {
                History::Uniform { dt_s, values } => sample_at(values, *dt_s, t),
                History::Steps { times, values } => {
                    let k = times.partition_point(|&x| x <= t);
                    if k == 0 { 0.0 } else { values[k - 1] }
                }
                History::Segments { .. } => unreachable!("read above"),
            }
    }

    /// exp(-travel / t_d): what damping leaves of a wave after `travel_s` [s].
    pub fn attenuation(&self, travel_s: f64) -> f64 {
        if self.decay_per_s == 0.0 {
            1.0
        } else {
            (-travel_s * self.decay_per_s).exp()
        }
    }

    /// Force on the impacting end of the body at time t [N]: F(t) = H(t) - r H(t - T).
    pub fn end_force_n(&self, t_s: f64) -> f64 {
        let t = self.round_trip_s();
        self.history_at(t_s) - self.attenuation(t) * self.history_at(t_s - t)
    }

    /// Axial stress at distance x from the impacting end [Pa], tension positive.
    pub fn stress_pa(&self, x_m: f64, t_s: f64) -> f64 {
        let x = x_m - self.zone_length_m;
        if x < 0.0 {
            return -self.end_force_n(t_s) / self.area_m2;
        }
        let x = x.min(self.body_length_m);
        let c = self.wave_speed_m_s;
        let (near, far) = (x / c, (2.0 * self.body_length_m - x) / c);
        let n = self.attenuation(near) * self.history_at(t_s - near)
            - self.attenuation(far) * self.history_at(t_s - far);
        -n / self.area_m2
    }

    /// Particle velocity at distance x from the impacting end [m/s], in the lab frame. For a
    /// damped bar (a building's slab) this is the waves' part on top of the starting velocity,
    /// each arrival attenuated like the stress; the slab's rigid motion is its floor's.
    pub fn velocity_m_s(&self, x_m: f64, t_s: f64) -> f64 {
        let x = (x_m - self.zone_length_m).clamp(0.0, self.body_length_m);
        let c = self.wave_speed_m_s;
        let (near, far) = (x / c, (2.0 * self.body_length_m - x) / c);
        let g = self.attenuation(near) * self.history_at(t_s - near)
            + self.attenuation(far) * self.history_at(t_s - far);
        self.initial_velocity_m_s + self.push_direction * g / self.impedance_n_s_m
    }

    /// Energy of the waves in the bar's own initial frame at time t [J]:
    /// (1/Z) times the integral of H^2 over the last round trip.
    pub fn wave_energy_j(&self, t_s: f64) -> f64 {
        let period = self.round_trip_s();
        let integral = match &self.history {
            History::Uniform { dt_s, values } => {
                integrate_square_uniform(values, *dt_s, t_s - period, t_s)
            }
            History::Steps { times, values } => {
                integrate_square_steps(times, values, t_s - period, t_s)
            }
            History::Segments { dt_s, .. } => {
                // The trapezoid rule on the grid the stretches are stored on.
                let (a, b) = ((t_s - period).max(0.0), t_s);
                let n = ((b - a) / dt_s).ceil().max(1.0) as usize;
                let step = (b - a) / n as f64;
                (0..=n)
                    .map(|i| {
                        let v = self.history_at(a + i as f64 * step);
                        let w = if i == 0 || i == n { 0.5 } else { 1.0 };
                        w * v * v
                    })
                    .sum::<f64>()
                    * step
            }
        };
        integral / self.impedance_n_s_m
    }
}

/// Trapezoid rule for the integral of v^2 over [a, b] on uniform samples (zero before t = 0).
fn integrate_square_uniform(values: &[f64], dt: f64, a: f64, b: f64) -> f64 {
    let a = a.max(0.0);
    if b <= a || values.is_empty() {
        return 0.0;
    }
    let at = |t: f64| sample_at(values, dt, t);
    let i0 = (a / dt).ceil() as usize;
    let i1 = ((b / dt).floor() as usize).min(values.len() - 1);
    if i0 > i1 {
        let (fa, fb) = (at(a), at(b));
        return 0.5 * (fa * fa + fb * fb) * (b - a);
    }
    // The trapezoid sum over [i0, i1] is dt (v_i0^2 / 2 + interior v^2 + v_i1^2 / 2); the
    // interior in four lanes, so that the additions do not wait on each other.
    let mut sum = 0.0;
    if i1 > i0 {
        let mut lanes = [0.0f64; 4];
        let interior = &values[i0 + 1..i1];
        let chunks = interior.chunks_exact(4);
        let rest = chunks.remainder();
        for c in chunks {
            for (l, &v) in lanes.iter_mut().zip(c) {
                *l += v * v;
            }
        }
        let mut squares = (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]);
        for &v in rest {
            squares += v * v;
        }
        let (v0, v1) = (values[i0], values[i1]);
        sum = (0.5 * (v0 * v0 + v1 * v1) + squares) * dt;
    }
    let (fa, f0) = (at(a), values[i0]);
    sum += 0.5 * (fa * fa + f0 * f0) * (i0 as f64 * dt - a);
    let (f1, fb) = (values[i1], at(b));
    sum += 0.5 * (f1 * f1 + fb * fb) * (b - i1 as f64 * dt);
    sum
}

/// Exact integral of v^2 over [a, b] for a step function.
fn integrate_square_steps(times: &[f64], values: &[f64], a: f64, b: f64) -> f64 {
    let mut sum = 0.0;
    for k in 0..times.len() {
        let lo = times[k].max(a);
        let hi = times.get(k + 1).copied().unwrap_or(f64::INFINITY).min(b);
        if hi > lo {
            sum += values[k] * values[k] * (hi - lo);
        }
    }
    sum
}

/// ceil(x) for x > 0 (below 2^63): truncation, up by one where it cut something off; exactly
/// what `f64::ceil` gives there, without a call to libm's (a grid's every sample takes one).
#[inline]
fn ceil_positive(x: f64) -> f64 {
    let t = x as i64 as f64;
    if t < x { t + 1.0 } else { t }
}
