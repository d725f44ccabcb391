//! Recording: the histories at the resolution a plot needs, and the peaks exactly between them.

use super::*;

/// Peaks of each floor and each storey's drift ratio per side, and each point's per side.
pub(super) type PeakSummary = ([Vec<f64>; 2], [Vec<f64>; 2], Vec<[f64; 2]>);

/// A signal whose peak is reported: a floor's displacement, a storey's drift ratio, or a contact
/// point's displacement on one side; all relative to the ground.
pub(super) struct Signal {
    side: usize,
    /// Its value per unit of each of its side's modes.
    coef: Vec<f64>,
    /// An earlier signal it is identical to (a contact point on a floor is that floor): its peak
    /// is that one's, and it is not tracked itself.
    pub(super) same_as: Option<usize>,
    /// Whether the run keeps its peak (see [`super::super::Tracked`]).
    kept: bool,
}

impl Signal {
    /// Every signal, in the order [`Stepper::peaks`] reads them: each floor (left, then right),
    /// each storey's drift ratio (left, then right), each point on each side.
    pub(super) fn all(sides: &[Side; 2], points: &[Point], tracked: Tracked) -> Vec<Signal> {
        let mut out = Vec::new();
        for (s, side) in sides.iter().enumerate() {
            for f in 0..side.heights.len() {
                out.push(Signal {
                    side: s,
                    coef: (0..side.modes()).map(|k| side.shapes[k][f]).collect(),
                    same_as: None,
                    kept: true,
                });
            }
        }
        for (s, side) in sides.iter().enumerate() {
            for f in 0..side.heights.len() {
                let below = |k: usize| if f == 0 { 0.0 } else { side.shapes[k][f - 1] };
                out.push(Signal {
                    side: s,
                    coef: (0..side.modes())
                        .map(|k| (side.shapes[k][f] - below(k)) / side.heights[f])
                        .collect(),
                    same_as: None,
                    kept: true,
                });
            }
        }
        for p in points {
            for s in 0..2 {
                out.push(Signal {
                    side: s,
                    coef: p.r[s].clone(),
                    same_as: None,
                    kept: true,
                });
            }
        }
        for i in 0..out.len() {
            out[i].same_as = (0..i).find(|&j| {
                out[j].same_as.is_none() && out[j].side == out[i].side && out[j].coef == out[i].coef
            });
        }
        let floors: usize = sides.iter().map(|s| s.heights.len()).sum();
        let first_point = 2 * floors;
        for (i, sig) in out.iter_mut().enumerate() {
            sig.kept = match tracked {
                Tracked::All => true,
                Tracked::Floors => i < floors,
                Tracked::Levels => i >= first_point,
            };
        }
        if tracked == Tracked::Levels {
            // A point on a floor is that floor: the floor's signal stands for it.
            for i in first_point..out.len() {
                if let Some(j) = out[i].same_as {
                    out[j].kept = true;
                }
            }
        }
        out
    }

    /// Whether the run follows this signal's peak itself (not through an identical one, and
    /// kept).
    pub(super) fn watched(&self) -> bool {
        self.same_as.is_none() && self.kept
    }

    /// The bound on its size (or a derivative's), from its modes' bounds.
    pub(super) fn bound(&self, m: &[Vec<f64>; 2]) -> f64 {
        self.coef
            .iter()
            .zip(&m[self.side])
            .map(|(c, m)| c.abs() * m)
            .sum()
    }

    /// Its side and its value per unit of each of the side's modes.
    pub(super) fn side_and_coefficients(&self) -> (usize, &[f64]) {
        (self.side, &self.coef)
    }
}

/// Modes from which a signal's sums are taken in four lanes.
const LANES_FROM: usize = 16;

/// The sums of c q and c v over the modes, each as [`sum_of`] takes it.
#[inline]
fn sums_of(c: &[f64], q: &[f64], v: &[f64]) -> (f64, f64) {
    if c.len() < LANES_FROM {
        let (mut u, mut r) = (0.0, 0.0);
        for ((c, q), v) in c.iter().zip(q).zip(v) {
            u += c * q;
            r += c * v;
        }
        return (u, r);
    }
    // Each sum in its own pass: taken together, the compiler pairs the two sums' lanes
    // instead of each sum's, and vectorises less.
    (in_lanes(c, q), in_lanes(c, v))
}

/// The sum of c q over the modes. A tall building's is taken in four interleaved partial sums
/// (mode k in lane k mod 4, the lanes joined pairwise), which the compiler vectorises: at 100
/// modes a signal's reading (two such sums) costs about half of one taken mode after mode. A
/// few modes' sum is taken in order, the cheapest there.
#[inline]
fn sum_of(c: &[f64], q: &[f64]) -> f64 {
    if c.len() < LANES_FROM {
        let mut u = 0.0;
        for (c, q) in c.iter().zip(q) {
            u += c * q;
        }
        return u;
    }
    in_lanes(c, q)
}

/// [`sum_of`] for a tall building, in four lanes: out of line, so that the few modes' loop
/// inlined where signals are read stays small.
#[inline(never)]
fn in_lanes(c: &[f64], q: &[f64]) -> f64 {
    let q = &q[..c.len()];
    let mut u = [0.0f64; 4];
    let (cs, qs) = (c.chunks_exact(4), q.chunks_exact(4));
    let (ct, qt) = (cs.remainder(), qs.remainder());
    for (c, q) in cs.zip(qs) {
        for l in 0..4 {
            u[l] += c[l] * q[l];
        }
    }
    for l in 0..ct.len() {
        u[l] += ct[l] * qt[l];
    }
    join(u)
}

/// Four lanes joined pairwise.
fn join(l: [f64; 4]) -> f64 {
    (l[0] + l[2]) + (l[1] + l[3])
}

/// What the proofs know of a signal.
#[derive(Clone, Copy)]
pub(super) struct Proof {
    /// Inside contacts: how far below its peak it has been shown to stay.
    pub headroom: f64,
    /// Inside contacts: its rate's proven distance from zero since it was last read.
    pub sign_room: f64,
    /// Its last instant not kept (a free stretch, or contact steps, left it alone where it
    /// could not reach its peak): the next look at it starts afresh.
    pub stale: bool,
    /// Left unread as monotone since it was last read.
    pub deferred: bool,
}

impl Proof {
    pub(super) const NONE: Proof = Proof {
        headroom: f64::NEG_INFINITY,
        sign_room: 0.0,
        stale: false,
        deferred: false,
    };
}

/// A followed signal as the contact steps' proofs read it.
#[derive(Clone, Copy)]
pub(super) struct Watch {
    /// The signal's index.
    i: usize,
    side: usize,
    /// Its largest coefficient: a step that moves its side's modes by dq moves it by at most
    /// this times the sum of |dq|.
    largest: f64,
    /// The Euclidean size of its coefficients: that step moves it by at most this times the
    /// size of dq, too (the tighter of the two is used).
    norm: f64,
}

impl Watch {
    /// Every signal the run follows, in their order.
    pub(super) fn all(signals: &[Signal]) -> Vec<Watch> {
        signals
            .iter()
            .enumerate()
            .filter(|(_, s)| s.watched())
            .map(|(i, s)| Watch {
                i,
                side: s.side,
                largest: s.coef.iter().fold(0.0, |m: f64, c| m.max(c.abs())),
                norm: s.coef.iter().map(|c| c * c).sum::<f64>().sqrt(),
            })
            .collect()
    }
}

/// The sum of |x| and the Euclidean size of x.
fn sizes(x: impl Iterator<Item = f64>) -> [f64; 2] {
    x.fold(Sizes::default(), Sizes::add).done()
}

/// [`sizes`] taken value by value, where the values are made one at a time (a contact step's
/// dq and velocities, as the modes are stepped).
#[derive(Default, Clone, Copy)]
pub(super) struct Sizes([f64; 2]);

impl Sizes {
    pub(super) fn add(self, v: f64) -> Self {
        let [l1, l2] = self.0;
        Sizes([l1 + v.abs(), l2 + v * v])
    }

    /// The sum of |x| and the Euclidean size.
    pub(super) fn done(self) -> [f64; 2] {
        [self.0[0], self.0[1].sqrt()]
    }
}

/// The largest |value| of signals known with their rates at a sequence of instants: between
/// two instants a signal is the cubic through both values and rates, and its extremum there is
/// found, so a peak is not missed by the spacing of the instants (the error is that of the cubic,
/// (w h)^4 / 384 of the amplitude, against (w h)^2 / 8 for sampling).
pub(super) struct Peaks {
    /// Each signal's last instant, value and rate.
    last: Vec<(f64, f64, f64)>,
    peak: Vec<f64>,
}

impl Peaks {
    pub(super) fn new(signals: usize) -> Self {
        Peaks {
            last: vec![(0.0, 0.0, 0.0); signals],
            peak: vec![0.0; signals],
        }
    }

    /// Signal i is (u, v) at t: its peak includes the cubic's extremum since its last instant.
    pub(super) fn update(&mut self, i: usize, t: f64, u: f64, v: f64) {
        let (t0, u0, v0) = self.last[i];
        let l = t - t0;
        let mut p = self.peak[i].max(u.abs());
        if l > 0.0 && (v0 > 0.0) != (v > 0.0) {
            let inside = if v0 > 0.0 {
                hermite_max(u0, v0, u, v, l)
            } else {
                -hermite_max(-u0, -v0, -u, -v, l)
            };
            if inside.is_finite() {
                p = p.max(inside.abs());
            }
        }
        self.peak[i] = p;
        self.last[i] = (t, u, v);
    }

    /// Signal i is (u, v) at t, where it has been shown to stay below its peak since its last
    /// instant.
    pub(super) fn pass(&mut self, i: usize, t: f64, u: f64, v: f64) {
        self.last[i] = (t, u, v);
    }

    /// Signal i's value and rate at its last instant.
    pub(super) fn last(&self, i: usize) -> (f64, f64) {
        (self.last[i].1, self.last[i].2)
    }

    pub(super) fn peak(&self, i: usize) -> f64 {
        self.peak[i]
    }
}

/// The histories, one column per quantity, sampled where a plot needs them: at the end of every
/// free stretch, and inside contacts every `contact_sample_s`, where a contact opens or closes,
/// and at the end.
#[derive(Clone)]
pub(in crate::model::building) struct Record {
    pub time_s: Vec<f64>,
    pub ground: Vec<f64>,
    /// `floors[side][floor][sample]`, relative to the ground.
    pub floors: [Vec<Vec<f64>>; 2],
    pub floor_v: [Vec<Vec<f64>>; 2],
    pub roof_v: [Vec<f64>; 2],
    /// Absolute roof accelerations (relative plus the ground's).
    pub roof_a: [Vec<f64>; 2],
    pub level_force: Vec<Vec<f64>>,
    pub force: Vec<f64>,
    /// `storey_shear[side][storey][sample]` [N], for a side whose storeys yield (empty for an
    /// elastic side: its shear is k times the drift the floors give).
    pub storey_shear: [Vec<Vec<f64>>; 2],
    contact_sample_s: f64,
    /// One side's floors worked out for a sample, before they go to their columns.
    scratch: Vec<f64>,
}

impl Record {
    pub(in crate::model::building) fn new(
        left: usize,
        right: usize,
        levels: usize,
        contact_sample_s: f64,
    ) -> Self {
        Record {
            time_s: Vec::new(),
            ground: Vec::new(),
            floors: [vec![Vec::new(); left], vec![Vec::new(); right]],
            floor_v: [vec![Vec::new(); left], vec![Vec::new(); right]],
            roof_v: [Vec::new(), Vec::new()],
            roof_a: [Vec::new(), Vec::new()],
            level_force: vec![Vec::new(); levels],
            force: Vec::new(),
            storey_shear: [Vec::new(), Vec::new()],
            contact_sample_s,
            scratch: Vec::new(),
        }
    }

    /// Records each storey's shear on the sides given a count of storeys (those that yield).
    pub(in crate::model::building) fn with_shears(mut self, storeys: [usize; 2]) -> Self {
        self.storey_shear = storeys.map(|n| vec![Vec::new(); n]);
        self
    }

    /// Bytes its samples take.
    pub(super) fn bytes(&self) -> f64 {
        let floors = self.floors[0].len() + self.floors[1].len();
        let shears = self.storey_shear[0].len() + self.storey_shear[1].len();
        let per_sample = 2 + 2 * floors + 4 + self.level_force.len() + 1 + shears;
        (8 * per_sample * self.time_s.len()) as f64
    }

    pub(super) fn last_time(&self) -> f64 {
        self.time_s.last().copied().unwrap_or(f64::NEG_INFINITY)
    }
}

impl Stepper<'_> {
    /// Signal i's value and rate from modal states: its coefficients over its side's modes
    /// (a floor's mode shapes, a storey's difference of them over its height, a point's
    /// projection).
    #[inline]
    pub(super) fn signal(&self, i: usize, q: [&[f64]; 2], v: [&[f64]; 2]) -> (f64, f64) {
        let sig = &self.signals[i];
        sums_of(&sig.coef, q[sig.side], v[sig.side])
    }

    /// Signal i's value alone (its acceleration, from modal accelerations): the first of
    /// [`Stepper::signal`]'s sums, taken the same way.
    #[inline]
    pub(super) fn signal_value(&self, i: usize, q: [&[f64]; 2]) -> f64 {
        let sig = &self.signals[i];
        sum_of(&sig.coef, q[sig.side])
    }

    /// Every signal's peak brought up to the current state.
    pub(super) fn track_peaks_now(&mut self) {
        let t = self.time();
        for i in 0..self.signals.len() {
            if self.signals[i].watched() {
                self.read_signal(i, t);
            }
        }
    }

    /// Reads signal i in the current state, at t: its peak brought up, and what the contact
    /// steps' proofs start from (its headroom below the peak, its rate's distance from zero).
    fn read_signal(&mut self, i: usize, t: f64) {
        let (u, r) = self.signal(
            i,
            [&self.sides[0].q, &self.sides[1].q],
            [&self.sides[0].v, &self.sides[1].v],
        );
        if self.proof[i].stale {
            // Left alone since its last instant, where a bound kept it below its peak.
            self.peaks.pass(i, t, u, r);
        } else {
            // Read now after steps it was shown monotone over, too: its peak is at an end.
            self.peaks.update(i, t, u, r);
        }
        self.proof[i] = Proof {
            headroom: self.peaks.peak(i) - u.abs(),
            sign_room: r.abs(),
            stale: false,
            deferred: false,
        };
    }

    /// Where a contact phase starts: no headroom is known, and a signal the free stretches kept
    /// reading is known at its last instant there, its rate's distance from zero its rate's
    /// size then (not what the last contact step left).
    pub(super) fn start_contact_proofs(&mut self) {
        for w in &self.watch {
            let pr = &mut self.proof[w.i];
            // The free stretches moved it: what a contact step had shown of its headroom holds
            // no more.
            pr.headroom = f64::NEG_INFINITY;
            if !pr.stale {
                pr.sign_room = self.peaks.last(w.i).1.abs();
            }
        }
    }

    /// Every signal's peak brought up to the end of a contact step from `before` (each side's
    /// modal displacements and velocities where it started) that moved each side's modes by a
    /// dq of sizes `moved`, left its modal velocities of sizes `speed_after` and changed them by
    /// sizes `kick` (each [the sum of |x|, the Euclidean size], as [`sizes`] takes them). A
    /// signal is read only where neither of two proofs holds, each checked at the cost of a few
    /// operations:
    /// - **below its peak**: the step's bound (its coefficients against the size of dq, and the
    ///   cubic's bulge between the step's ends) cannot bring it there; its headroom shrinks by
    ///   that bound;
    /// - **monotone**: its rate cannot have changed sign since it was last read (the changes of
    ///   the modal velocities bound the rate's). A Newmark step moves it by h/2 (r0 + r1), so it
    ///   has moved one way only, and its largest size since is at one end: the peak is brought
    ///   up when the proof ends, reading it at the step before (from `before`) and now, as
    ///   reading it at every step would have.
    pub(super) fn track_peaks_in_contact(
        &mut self,
        [moved, speed_after, kick]: [[[f64; 2]; 2]; 3],
        before: &[[Vec<f64>; 2]; 2],
        hh: f64,
    ) {
        let t = self.time();
        // Straight after another contact step (the step count one on), the velocities this one
        // started from are those that one ended with, and so are their sizes.
        let speeds: [[f64; 2]; 2] = match self.speeds_after.take() {
            Some((step, sizes)) if step + 1 == self.steps => sizes,
            _ => std::array::from_fn(|s| sizes(before[s][1].iter().copied())),
        };
        self.speeds_after = Some((self.steps, speed_after));
        for w in 0..self.watch.len() {
            let Watch {
                i,
                side: s,
                largest,
                norm,
            } = self.watch[w];
            let peak = self.peaks.peak(i);
            // |sum c dq| is at most max|c| sum|dq| and |c| |dq|: the tighter of the two, for
            // the step's displacement and for the rates at both ends.
            let most = |[l1, l2]: [f64; 2]| (largest * l1).min(norm * l2);
            let pr = &mut self.proof[i];
            if !pr.deferred {
                let step = most(moved[s]);
                let (rate0, rate1) = (most(speeds[s]), most(speed_after[s]));
                let room = pr.headroom - step - 4.0 / 27.0 * hh * (rate0 + rate1);
                if room > 1e-9 * peak {
                    pr.headroom = room;
                    pr.stale = true;
                    continue;
                }
            }
            if !pr.stale {
                let keeps = pr.sign_room - most(kick[s]);
                // A tall building's bound on the kick sees the contact force at every floor:
                // its rate alone, read exactly, shows it monotone at half a reading's cost (the
                // step's ends' rates of one sign keep Newmark's cubic monotone between them).
                let room = if keeps > 1e-9 * pr.sign_room.abs().max(f64::MIN_POSITIVE) {
                    Some(keeps)
                } else {
                    self.rate_keeps_sign(i, s)
                };
                if let Some(room) = room {
                    let pr = &mut self.proof[i];
                    pr.sign_room = room;
                    pr.deferred = true;
                    self.any_deferred = true;
                    continue;
                }
            }
            let (deferred, stale) = (self.proof[i].deferred, self.proof[i].stale);
            if deferred || stale {
                let (u0, r0) = self.signal(
                    i,
                    [&before[0][0], &before[1][0]],
                    [&before[0][1], &before[1][1]],
                );
                if deferred {
                    self.peaks.update(i, t - hh, u0, r0);
                } else {
                    // Shown below its peak up to where this step started, not over the step:
                    // its last instant is the step's start, and the step is read as a step.
                    self.peaks.pass(i, t - hh, u0, r0);
                    self.proof[i].stale = false;
                }
            }
            self.read_signal(i, t);
        }
    }

    /// On a side of many modes, signal i's rate now where it has the sign it had when the
    /// signal was last read: its distance from zero.
    fn rate_keeps_sign(&self, i: usize, side: usize) -> Option<f64> {
        let coef = &self.signals[i].coef;
        if coef.len() < TALL {
            return None;
        }
        let then = self.peaks.last(i).1;
        let now = sum_of(coef, &self.sides[side].v);
        (then != 0.0 && now != 0.0 && (now > 0.0) == (then > 0.0)).then_some(now.abs())
    }

    /// Signal i's peak up to now: a signal shown monotone since it was last read has it at one
    /// end.
    fn peak_so_far(&self, i: usize) -> f64 {
        let peak = self.peaks.peak(i);
        if !self.proof[i].deferred {
            return peak;
        }
        let side = &self.sides[self.signals[i].side];
        let u = sum_of(&self.signals[i].coef, &side.q);
        peak.max(u.abs())
    }

    /// Brings the peaks of the signals left monotone up to now, before anything but a contact
    /// step moves them.
    pub(super) fn flush_deferred(&mut self) {
        if !self.any_deferred {
            return;
        }
        let t = self.time();
        for i in 0..self.signals.len() {
            if self.proof[i].deferred {
                // Never stale while deferred: read from its last instant.
                self.read_signal(i, t);
            }
        }
        self.any_deferred = false;
    }

    /// Peaks of each floor, each storey's drift ratio and each point.
    pub fn peaks(&self) -> PeakSummary {
        let n = [self.sides[0].heights.len(), self.sides[1].heights.len()];
        let p: Vec<f64> = (0..self.signals.len())
            .map(|i| {
                let i = self.signals[i].same_as.unwrap_or(i);
                if self.signals[i].kept {
                    self.peak_so_far(i)
                } else {
                    f64::NAN
                }
            })
            .collect();
        let floors = [p[..n[0]].to_vec(), p[n[0]..n[0] + n[1]].to_vec()];
        let d0 = n[0] + n[1];
        let drifts = [p[d0..d0 + n[0]].to_vec(), p[d0 + n[0]..2 * d0].to_vec()];
        let points = p[2 * d0..].chunks(2).map(|c| [c[0], c[1]]).collect();
        (floors, drifts, points)
    }

    /// The roof acceleration relative to the ground from the modal state and forcing.
    pub(super) fn roof_accelerations(&self, ground: f64, contact: bool) -> [f64; 2] {
        std::array::from_fn(|s| {
            let side = &self.sides[s];
            let roof = side.heights.len() - 1;
            (0..side.modes())
                .map(|k| {
                    let a = if contact {
                        side.a[k]
                    } else {
                        side.pseudo_now(k)
                            - side.gamma[k] * ground
                            - 2.0 * side.zeta[k] * side.omega[k] * side.v[k]
                            - side.omega[k].powi(2) * side.q[k]
                    };
                    side.shapes[k][roof] * a
                })
                .sum()
        })
    }

    /// Records the current state as a sample of the histories.
    pub(super) fn record_now(&mut self) {
        if !self.histories {
            return;
        }
        let t = self.time();
        let ground = self.motion.at(t);
        let contact = self.points.iter().any(|p| p.force > 0.0);
        let roof_a = self.roof_accelerations(ground, contact);
        let rec = &mut self.record;
        rec.time_s.push(t);
        rec.ground.push(ground);
        for (s, (side, roof_a)) in self.sides.iter().zip(roof_a).enumerate() {
            side.floors_into(&side.q, &mut rec.scratch);
            for (column, x) in rec.floors[s].iter_mut().zip(&rec.scratch) {
                column.push(*x);
            }
            side.floors_into(&side.v, &mut rec.scratch);
            for (column, x) in rec.floor_v[s].iter_mut().zip(&rec.scratch) {
                column.push(*x);
            }
            let roof = side.heights.len() - 1;
            rec.roof_v[s].push(rec.scratch[roof]);
            rec.roof_a[s].push(roof_a + ground);
            if let Some(st) = &side.storeys {
                for (j, column) in rec.storey_shear[s].iter_mut().enumerate() {
                    column.push(st.shear_n(j));
                }
            }
        }
        let mut total = 0.0;
        for (l, p) in self.points.iter().enumerate() {
            rec.level_force[l].push(p.force);
            total += p.force;
        }
        rec.force.push(total);
    }

    /// After a free step: records it, or, where storeys yield and the steps are fine, where the
    /// last sample is a whole free step old (the density of an elastic run's samples).
    pub(super) fn record_free(&mut self) {
        let spacing = self.grid.per_free_step as f64 * self.grid.h;
        if !self.single_step || self.time() >= self.record.last_time() + spacing * (1.0 - 1e-9) {
            self.record_now();
        }
    }

    /// Inside contacts: records the state where a contact opened or closed in the last step, or
    /// where the last sample is `contact_sample_s` old.
    pub(super) fn record_in_contact(&mut self, opened_or_closed: bool) {
        if !self.histories {
            return;
        }
        let every_step = self.sc.recording == crate::model::building::Recording::Steps;
        if opened_or_closed
            || every_step
            || self.time() >= self.record.last_time() + self.record.contact_sample_s
        {
            self.record_now();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{sum_of, sums_of};

    /// Fixed pseudo-random values in [-1, 1).
    fn values(seed: u64, n: usize) -> Vec<f64> {
        let mut x = seed;
        (0..n)
            .map(|_| {
                x = x
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                (x >> 11) as f64 / (1u64 << 52) as f64 - 1.0
            })
            .collect()
    }

    #[test]
    fn a_signal_summed_in_lanes_is_the_exact_sum_within_its_rounding() {
        for n in 1..=130 {
            let (c, q, v) = (values(n as u64, n), values(7 + n as u64, n), values(99, n));
            // Products of values on a 2^-52 grid, summed exactly in 128 bits of integer.
            let exact = |x: &[f64]| -> f64 {
                let scale = (1u64 << 52) as f64;
                let total: i128 = c
                    .iter()
                    .zip(x)
                    .map(|(a, b)| (a * scale) as i128 * (b * scale) as i128)
                    .sum();
                total as f64 / (scale * scale)
            };
            let size: f64 = c.iter().zip(&q).map(|(a, b)| (a * b).abs()).sum();
            let got = sum_of(&c, &q);
            assert!(
                (got - exact(&q)).abs() <= n as f64 * f64::EPSILON * size,
                "{n} modes: {got} against {}",
                exact(&q)
            );
            // The pair takes each sum exactly as the single one does.
            assert_eq!(sums_of(&c, &q, &v), (sum_of(&c, &q), sum_of(&c, &v)));
        }
    }
}
