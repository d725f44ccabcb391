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

use super::lanes::{self, LANES_FROM};

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
    lanes::dot2(c, q, v)
}

/// The sum of c q over the modes. A tall building's is taken in four interleaved partial sums
/// (mode k in lane k mod 4, the lanes joined pairwise; [`lanes::dot`], one AVX register where
/// the processor has it). A few modes' sum is taken in order, the cheapest there.
#[inline]
fn sum_of(c: &[f64], q: &[f64]) -> f64 {
    if c.len() < LANES_FROM {
        let mut u = 0.0;
        for (c, q) in c.iter().zip(q) {
            u += c * q;
        }
        return u;
    }
    lanes::dot(c, q)
}

/// What the proofs know of a signal.
#[derive(Clone, Copy)]
pub(super) struct Proof {
    /// Inside contacts: how far below its peak it has been shown to stay.
    pub headroom: f64,
    /// Its last instant not kept (a free stretch, or contact steps, left it alone where it
    /// could not reach its peak): the next look at it starts afresh.
    pub stale: bool,
}

impl Proof {
    pub(super) const NONE: Proof = Proof {
        headroom: f64::NEG_INFINITY,
        stale: false,
    };
}

/// The contact steps since the peaks' proofs last looked at the signals
/// ([`Stepper::track_peaks_in_contact`]).
pub(super) struct Batch {
    /// Contact steps in it.
    steps: usize,
    /// Where it started, and each side's modal displacements and velocities then.
    start_s: f64,
    start: [[Vec<f64>; 2]; 2],
    /// Per side, the most its steps can have moved a signal: per unit of the signal's largest
    /// coefficient, and per unit of its coefficients' Euclidean size.
    reach: [[f64; 2]; 2],
    /// The sizes of each side's modal velocities where its last step ended.
    speeds: [[f64; 2]; 2],
}

impl Batch {
    pub(super) fn new(modes: [usize; 2]) -> Self {
        Batch {
            steps: 0,
            start_s: 0.0,
            start: modes.map(|n| [vec![0.0; n], vec![0.0; n]]),
            reach: [[0.0; 2]; 2],
            speeds: [[0.0; 2]; 2],
        }
    }
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
    /// instant. Its size there counts all the same: a piece of motion no proof looked at (the
    /// way back onto the grid after a contact ends inside a step) ends here too.
    pub(super) fn pass(&mut self, i: usize, t: f64, u: f64, v: f64) {
        self.peak[i] = self.peak[i].max(u.abs());
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

    /// Signal i's value, rate and acceleration: [`Stepper::signal`] and
    /// [`Stepper::signal_value`] of `acc`, the same sums, a tall side's three in one pass.
    #[inline]
    pub(super) fn signal_reading(
        &self,
        i: usize,
        q: [&[f64]; 2],
        v: [&[f64]; 2],
        acc: [&[f64]; 2],
    ) -> [f64; 3] {
        let sig = &self.signals[i];
        let s = sig.side;
        if sig.coef.len() < LANES_FROM {
            let (u, r) = sums_of(&sig.coef, q[s], v[s]);
            return [u, r, sum_of(&sig.coef, acc[s])];
        }
        lanes::dot3(&sig.coef, q[s], v[s], acc[s])
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
    /// steps' proofs start from (its headroom below the peak).
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
            stale: false,
        };
    }

    /// Where a contact phase starts: no headroom is known (the free stretches moved every
    /// signal), and no batch is open.
    pub(super) fn start_contact_proofs(&mut self) {
        for w in &self.watch {
            self.proof[w.i].headroom = f64::NEG_INFINITY;
        }
        self.batch.steps = 0;
    }

    /// Brings the peaks up through a contact step from `before` (each side's modal
    /// displacements and velocities where it started) that moved each side's modes by a dq of
    /// sizes `moved` and left its modal velocities of sizes `speed_after` (each [the sum of |x|,
    /// the Euclidean size], as [`sizes`] takes them).
    ///
    /// The steps are taken in batches of [`Grid::read_every`](super::Grid::read_every) steps,
    /// and at the end of each every signal is looked at once ([`Stepper::close_batch`]): a step
    /// moves a signal by at most its coefficients against the size of dq, and the cubic between
    /// the step's ends bulges by at most 4/27 of the step times the rates' bounds at its ends;
    /// the batch adds these up per side.
    #[inline(always)]
    pub(super) fn track_peaks_in_contact(
        &mut self,
        [moved, speed_after]: [[[f64; 2]; 2]; 2],
        before: &[[Vec<f64>; 2]; 2],
        hh: f64,
    ) {
        let t = self.time();
        let b = &mut self.batch;
        if b.steps == 0 {
            b.start_s = t - hh;
            for (kept, state) in b.start.iter_mut().zip(before) {
                for (k, x) in kept.iter_mut().zip(state) {
                    k.copy_from_slice(x);
                }
            }
            b.speeds = std::array::from_fn(|s| sizes(before[s][1].iter().copied()));
            b.reach = [[0.0; 2]; 2];
        }
        for s in 0..2 {
            for l in 0..2 {
                b.reach[s][l] +=
                    moved[s][l] + 4.0 / 27.0 * hh * (b.speeds[s][l] + speed_after[s][l]);
            }
        }
        b.speeds = speed_after;
        b.steps += 1;
        if b.steps >= self.grid.read_every {
            self.close_batch();
        }
    }

    /// Every signal's peak brought up to the end of the open batch of contact steps, if there
    /// is one: a signal is read there only where the batch's reach could have brought it to
    /// its peak (its headroom shrinks by that reach where it could not), and its peak over the
    /// batch is the cubic's through its values and rates at the batch's ends. The cubic misses
    /// a peak of the steps by about (w l)^4 / 384 of a signal of frequency w, l the batch's
    /// length: batches of up to 8 steps moved the peaks of 38 preset and element runs by
    /// 1.1e-8 of themselves at most (mdof-3-5 with Hertz's element, whose estimated error is
    /// 8e-6), and a look at every signal at every step took more than the batch's.
    pub(super) fn close_batch(&mut self) {
        if self.batch.steps == 0 {
            return;
        }
        self.batch.steps = 0;
        let t = self.time();
        let reach = self.batch.reach;
        for w in 0..self.watch.len() {
            let Watch {
                i,
                side: s,
                largest,
                norm,
            } = self.watch[w];
            let pr = &mut self.proof[i];
            // The tighter of the two bounds (neither is NaN: sizes of finite states), taken
            // without `f64::min`'s care for NaN, in the loop every batch runs over every signal
            // (the side masked to 0 or 1, which the compiler indexes without a check).
            let (by_largest, by_norm) = (largest * reach[s & 1][0], norm * reach[s & 1][1]);
            let moved = if by_norm < by_largest {
                by_norm
            } else {
                by_largest
            };
            let room = pr.headroom - moved;
            if room > 1e-9 * self.peaks.peak(i) {
                pr.headroom = room;
                pr.stale = true;
                continue;
            }
            if pr.stale {
                // Shown below its peak up to where the batch started, not over the batch: its
                // last instant is the batch's start.
                let [l, r] = &self.batch.start;
                let (u0, r0) = self.signal(i, [&l[0], &r[0]], [&l[1], &r[1]]);
                self.peaks.pass(i, self.batch.start_s, u0, r0);
                self.proof[i].stale = false;
            }
            self.read_signal(i, t);
        }
    }

    /// Signal i's peak up to now: inside a batch of contact steps, at least its size now.
    fn peak_so_far(&self, i: usize) -> f64 {
        let peak = self.peaks.peak(i);
        if self.batch.steps == 0 {
            return peak;
        }
        let side = &self.sides[self.signals[i].side];
        let u = sum_of(&self.signals[i].coef, &side.q);
        peak.max(u.abs())
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
                    column.push(st.shear_n(j, &side.q));
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
    use super::super::fixed_signed;
    use super::{sum_of, sums_of};

    #[test]
    fn a_signal_summed_in_lanes_is_the_exact_sum_within_its_rounding() {
        for n in 1..=130 {
            let (c, q, v) = (
                fixed_signed(n as u64, n),
                fixed_signed(7 + n as u64, n),
                fixed_signed(99, n),
            );
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
