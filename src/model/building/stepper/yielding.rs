//! Storeys that yield, in the pseudo-force form: a storey's shear force is F = k u - c, where
//! k u is the elastic spring the modes already carry and c = k u - F(history) is the correction
//! the storey's law makes of it (zero while it is elastic from rest, (1 - b) k u_p for the
//! bilinear law, (1 - b) k (u - z) for Bouc-Wen). The correction acts on the floors above and
//! below the storey as a load, +c and -c, so the modes stay those of the elastic building, their
//! damping stays the one set on the initial stiffness, and every stage of the stepper takes the
//! corrections as one more load on the modes.
//!
//! Over a step the correction is taken linear in time between its values at both ends, and the
//! value at the end comes from the storey's law along the drift path of the step: a fixed
//! point, since the end drift depends on the correction. The map is a contraction of factor
//! about (w L)^2 / 6 over a step of length L, so it settles in a few passes.
//!
//! How long a piece of free motion may be is the correction's to say, not the building's
//! highest mode: the line's error in the response is the correction's departure from it, so
//! each piece measures that departure in its middle (following the laws there) and is as long
//! as keeps it within a share of the tolerance of the storey's force. Where the storeys are
//! quiet (the correction hardly moves, as in a tall building whose top modes barely stir its
//! storeys) the pieces run to the free step's end; where one flows they shorten to what its
//! drift's curvature allows. A bilinear storey's yield is a corner of the correction and is
//! located; a turn is not (see [`first_event`]).
//!
//! In contact steps a bilinear storey that provably stays inside its elastic range over the
//! step (a bound, [`Storeys::quiet`]) is left where it stands, its correction unchanged: no
//! drift is summed for it until a step is not quiet or the free motion resumes.

use super::*;
use crate::model::bound::{Envelope, envelope};
use crate::model::hysteresis::{Hysteresis, StoreyLaw, StoreyState};

/// The most passes of the fixed point over one step.
pub(super) const MAX_PASSES: usize = 60;

/// A piece longer than a fine step whose fixed point takes more passes than this is shortened:
/// the map's contraction goes as the square of the piece, so a shorter one settles sooner and
/// costs less.
const PIECE_PASSES: usize = 12;

/// An event closer than this share of its step to either end is left inside the step: a piece
/// that short would cost a step and change nothing the law can tell.
const EVENT_PIECE: f64 = 1e-6;

/// A building's storey springs and what they remember.
#[derive(Debug, Clone)]
pub(super) struct Storeys {
    laws: Vec<StoreyLaw>,
    /// Each storey's state where the current time stands.
    pub state: Vec<StoreyState>,
    /// `drift[j][k]`: storey j's drift per unit of mode k.
    drift: Vec<Vec<f64>>,
    /// `by_mode[k][j]`: the same, mode by mode, so that a mode's load from the corrections
    /// reads consecutive memory.
    by_mode: Vec<Vec<f64>>,
    /// The corrections now [N], and their load on each mode.
    c0: Vec<f64>,
    /// The largest correction each storey has carried so far [N]: a piece's departure is
    /// measured against it where the correction is smaller now.
    c_peak: Vec<f64>,
    pub load0: Vec<f64>,
    /// How fast each mode's load moved over the last step committed [N/s].
    trend: Vec<f64>,
    /// The planned free step: each mode's load at its end, and its length.
    pub load1: Vec<f64>,
    pub len: f64,
    /// When each storey's drift first reached its yield drift F_y / k [s].
    pub first_yield_s: Vec<Option<f64>>,
    /// Each storey's drift rate where the current time stands [m/s].
    rate: Vec<f64>,
    /// The storeys' drifts and rates (`state`, `rate`) lag the modes: contact steps over which
    /// every storey provably stayed elastic left them (and the corrections, unchanged) alone.
    /// They were last moved with the modes at `synced` (displacements, velocities).
    pub stale: bool,
    synced: [Vec<f64>; 2],
    /// Each storey's drift per unit of modal displacement at most: the length of its row.
    reach: Vec<f64>,
    /// How far a mode's load from the corrections can move per unit of modal displacement at
    /// most, the largest over the modes: a correction's slope is within (1 - b) k of its drift.
    load_reach: f64,
    /// Buffers a step's planning reuses: the modes' augmented states, their ends, and the
    /// corrections at the end (a fine step is planned hundreds of thousands of times a run).
    plan: Plan,
    c1: std::cell::RefCell<Vec<f64>>,
    /// Each storey's state, drift and rate at the end of the step [`Storeys::end_loads`] last
    /// followed: what committing that step makes of them ([`Storeys::commit_ends`]).
    ends: std::cell::RefCell<Vec<(StoreyState, f64, f64)>>,
}

/// The planning's buffers.
#[derive(Debug, Clone, Default)]
struct Plan {
    y0: Vec<[f64; 4]>,
    q1: Vec<f64>,
    v1: Vec<f64>,
}

impl Storeys {
    /// The storeys of a building with the given laws, on modes with `shapes[k][floor]`.
    pub fn new(laws: Vec<StoreyLaw>, shapes: &[Vec<f64>]) -> Self {
        let n = laws.len();
        let drift: Vec<Vec<f64>> = (0..n)
            .map(|j| {
                shapes
                    .iter()
                    .map(|shape| shape[j] - if j > 0 { shape[j - 1] } else { 0.0 })
                    .collect()
            })
            .collect();
        let modes = shapes.len();
        let by_mode: Vec<Vec<f64>> = (0..modes)
            .map(|k| drift.iter().map(|d| d[k]).collect())
            .collect();
        let reach = drift
            .iter()
            .map(|d| d.iter().map(|x| x * x).sum::<f64>().sqrt())
            .collect();
        let load_reach = by_mode
            .iter()
            .map(|d| {
                d.iter()
                    .zip(&laws)
                    .zip(&reach)
                    .map(|((x, l), r)| x.abs() * (1.0 - l.hardening) * l.stiffness_n_m * r)
                    .sum::<f64>()
            })
            .fold(0.0, f64::max);
        Storeys {
            load_reach,
            stale: false,
            synced: [Vec::new(), Vec::new()],
            reach,
            laws,
            state: vec![StoreyState::default(); n],
            drift,
            by_mode,
            c0: vec![0.0; n],
            c_peak: vec![0.0; n],
            load0: vec![0.0; modes],
            trend: vec![0.0; modes],
            load1: vec![0.0; modes],
            len: 0.0,
            first_yield_s: vec![None; n],
            rate: vec![0.0; n],
            plan: Plan {
                y0: Vec::new(),
                q1: vec![0.0; modes],
                v1: vec![0.0; modes],
            },
            c1: std::cell::RefCell::new(Vec::with_capacity(n)),
            ends: std::cell::RefCell::new(Vec::with_capacity(n)),
        }
    }

    /// Whether a contact step from the modes at `q`, `v` (where the storeys stand, or where
    /// they stood when they went stale) that moves them by `dq` to velocities `v1`, made with
    /// the loads as they are, leaves every storey inside its elastic range, turn included: then
    /// no correction moves and the laws need not be followed. Only bilinear storeys have a
    /// range. A bound, by the rows' lengths and the distance from where the storeys last
    /// stood: no drift is summed.
    pub fn quiet(&self, q: &[f64], v: &[f64], dq: &[f64], v1: &[f64], hh: f64) -> bool {
        if self.laws.first().map(|l| l.kind) != Some(Hysteresis::Bilinear) {
            return false;
        }
        let (q0, v0) = if self.stale {
            (&self.synced[0][..], &self.synced[1][..])
        } else {
            (q, v)
        };
        let (mut start, mut end, mut speed) = (0.0f64, 0.0f64, 0.0f64);
        for k in 0..q.len() {
            let off = q[k] - q0[k];
            start += off * off;
            end += (off + dq[k]) * (off + dq[k]);
            speed = speed.max((v[k] - v0[k]).abs()).max((v1[k] - v0[k]).abs());
        }
        // Velocities by their largest change (any norm bounds the sum's rows with the
        // dimension's root).
        let dim = (q.len() as f64).sqrt();
        let moved = start.max(end).sqrt();
        for (j, law) in self.laws.iter().enumerate() {
            let Some((lo, hi)) = law.elastic_range_m(&self.state[j]) else {
                return false;
            };
            let u = self.state[j].drift_m;
            let rate = self.rate[j].abs() + self.reach[j] * dim * speed;
            // The path between the step's ends is the cubic through their drifts and rates:
            // within 4/27 of the step times each end's rate of the line between them.
            let spread = self.reach[j] * moved + 0.3 * hh * rate;
            let margin = 1e-9 * (hi - lo);
            if !(u - spread > lo + margin && u + spread < hi - margin) {
                return false;
            }
        }
        true
    }

    /// The storeys left where they stand while the modes move on from `q`, `v` (a quiet
    /// contact step, [`Storeys::quiet`]).
    pub fn go_stale(&mut self, q: &[f64], v: &[f64]) {
        if !self.stale {
            self.synced[0].clear();
            self.synced[0].extend_from_slice(q);
            self.synced[1].clear();
            self.synced[1].extend_from_slice(v);
            self.stale = true;
        }
    }

    /// The storeys brought to the modes at `q`, `v` after quiet contact steps: inside its
    /// elastic range a bilinear storey's state is its drift's alone, so the steps it skipped
    /// would have left it just so.
    pub fn sync(&mut self, q: &[f64], v: &[f64]) {
        if !self.stale {
            return;
        }
        for j in 0..self.laws.len() {
            self.state[j].drift_m = self.drift_of(j, q);
            self.rate[j] = self.drift_of(j, v);
        }
        self.stale = false;
    }

    /// Storey j's drift with the modes at `q` where the storeys lag them, its own otherwise.
    fn drift_now(&self, j: usize, q: &[f64]) -> f64 {
        if self.stale {
            self.drift_of(j, q)
        } else {
            self.state[j].drift_m
        }
    }

    /// Where the fixed point over a step of length `len` starts: the loads moved on at their
    /// last trend (a pass or two fewer where the storeys flow), into `out`.
    pub fn guess_into(&self, len: f64, out: &mut Vec<f64>) {
        out.clear();
        // Bilinear storeys inside their elastic ranges keep their corrections: their trend is
        // round-off, and the loads as they are let a contact step be found quiet.
        let inside = |(law, s): (&StoreyLaw, &StoreyState)| {
            law.elastic_range_m(s)
                .is_some_and(|(lo, hi)| s.drift_m > lo && s.drift_m < hi)
        };
        if self.stale || self.laws.iter().zip(&self.state).all(inside) {
            out.extend_from_slice(&self.load0);
        } else {
            out.extend(self.load0.iter().zip(&self.trend).map(|(l, r)| l + r * len));
        }
    }

    /// Whether the storeys' laws are smooth (Bouc-Wen): their corrections have no corners.
    pub fn smooth(&self) -> bool {
        self.laws.first().map(|l| l.kind) == Some(Hysteresis::BoucWen)
    }

    /// Whether loads `loads`, made by following the storeys over a contact step, are settled
    /// for a trial that moved the modes `moved` (in norm) from the one they were followed on:
    /// following them again would move no load by more than 1e-13 of the largest. Bouc-Wen
    /// sides only: a bilinear side's contact steps are mostly quiet, where no pass follows it.
    pub fn settled_by(&self, moved: f64, loads: &[f64]) -> bool {
        let scale = loads.iter().fold(0.0f64, |m, l| m.max(l.abs()));
        // A storey's drift moves by its row's length times `moved`; where its path turns inside
        // the step, the turn moves by at most 1 + 8/27 times that (the cubic's rate at the end
        // moves by twice the drift over the step) and counts on both legs: four times in all.
        self.smooth() && scale > 0.0 && 4.0 * self.load_reach * moved <= 1e-13 * scale
    }

    /// How many storeys.
    pub fn count(&self) -> usize {
        self.laws.len()
    }

    /// Each storey's drift rate taken from modal velocities v (the start, or a velocity jump).
    pub fn set_rates(&mut self, v: &[f64]) {
        for j in 0..self.laws.len() {
            self.rate[j] = self.drift_of(j, v);
        }
    }

    /// Moves a storey's state along its drift path over a step of length `len` that ends at
    /// drift u1 with rate r1, from where it stands with rate r0: where the rate changes sign the
    /// path turns inside the step, at the extremum of the cubic through both ends' drifts and
    /// rates, and the law follows the turn (a straight path would cut it short).
    fn follow(law: &StoreyLaw, s: &mut StoreyState, r0: f64, (u1, r1): (f64, f64), len: f64) {
        if len > 0.0 && r0 != 0.0 && r1 != 0.0 && (r0 > 0.0) != (r1 > 0.0) {
            let u0 = s.drift_m;
            let turn = if r0 > 0.0 {
                hermite_max(u0, r0, u1, r1, len)
            } else {
                -hermite_max(-u0, -r0, -u1, -r1, len)
            };
            if turn.is_finite() {
                law.advance(s, turn);
            }
        }
        law.advance(s, u1);
    }

    /// Storey j's drift with the modes at q [m].
    pub fn drift_of(&self, j: usize, q: &[f64]) -> f64 {
        dotv(&self.drift[j], q)
    }

    /// Mode k's load over the planned free step: its value now and its rate.
    pub fn pseudo(&self, k: usize) -> (f64, f64) {
        let rate = if self.len > 0.0 {
            (self.load1[k] - self.load0[k]) / self.len
        } else {
            0.0
        };
        (self.load0[k], rate)
    }

    /// The correction c = k u - F of a storey in state `s` [N].
    fn correction(law: &StoreyLaw, s: &StoreyState) -> f64 {
        law.stiffness_n_m * s.drift_m - law.force_n(s)
    }

    /// Each mode's load from corrections `c` on storeys of drift columns `by_mode`, into `out`.
    fn loads(by_mode: &[Vec<f64>], c: &[f64], out: &mut Vec<f64>) {
        out.clear();
        out.extend(by_mode.iter().map(|d| dotv(d, c)));
    }

    /// The loads at the end of a step of length `len` that brings storey j to the drift and
    /// rate `end(j)` (each storey along its path, [`Storeys::follow`]), into `out`; the largest
    /// change of a load from what `out` held, relative to the largest load before or after.
    fn end_loads(
        &self,
        end: impl Fn(usize) -> (f64, f64),
        start: impl Fn(usize) -> (f64, f64),
        len: f64,
        out: &mut [f64],
    ) -> f64 {
        let mut c1 = self.c1.borrow_mut();
        c1.clear();
        let mut ends = self.ends.borrow_mut();
        ends.clear();
        let mut scale = 0.0f64;
        for (j, law) in self.laws.iter().enumerate() {
            let (u, r) = end(j);
            if !u.is_finite() || !r.is_finite() {
                // No end state to follow (a trial that failed): the loads stay as they were.
                return 0.0;
            }
            let (u0, r0) = start(j);
            let mut s = StoreyState {
                drift_m: u0,
                ..self.state[j]
            };
            Self::follow(law, &mut s, r0, (u, r), len);
            let c = Self::correction(law, &s);
            scale = scale.max(c.abs()).max(self.c0[j].abs());
            c1.push(c);
            ends.push((s, u, r));
        }
        // Where no correction moved (every storey elastic over the step), the loads are the
        // ones now, to the bit: `loads` made them from the same corrections.
        if c1.iter().zip(&self.c0).all(|(a, b)| a == b) && out.len() == self.load0.len() {
            let (mut change, mut load_scale) = (0.0f64, 0.0f64);
            for (o, l) in out.iter_mut().zip(&self.load0) {
                change = change.max((l - *o).abs());
                load_scale = load_scale.max(l.abs()).max(o.abs());
                *o = *l;
            }
            return if scale == 0.0 || load_scale == 0.0 {
                0.0
            } else {
                change / load_scale
            };
        }
        // Mode by mode, as `loads` sums, comparing as it writes.
        let (mut change, mut load_scale) = (0.0f64, 0.0f64);
        for (o, d) in out.iter_mut().zip(&self.by_mode) {
            let load = dotv(d, &c1);
            change = change.max((load - *o).abs());
            load_scale = load_scale.max(load.abs()).max(o.abs());
            *o = load;
        }
        if scale == 0.0 || load_scale == 0.0 {
            0.0
        } else {
            change / load_scale
        }
    }

    /// How far the corrections a step's plan reaches at a point `theta` of its way (a length
    /// `len` in) depart from the line between its ends, each storey's departure over
    /// `allowed` times its force scale (its correction at either end or the largest it has
    /// been, or the share of its yield force it may correct, or of its elastic force where that
    /// is less): the largest, where
    /// storey j stands at the drift and rate `at(j)` there. Infinite where a state is not
    /// finite. The ends' corrections are those [`Storeys::end_loads`] left.
    fn departure(
        &self,
        at: impl Fn(usize) -> (f64, f64),
        len: f64,
        theta: f64,
        allowed: f64,
    ) -> f64 {
        let c1 = self.c1.borrow();
        if c1.len() != self.laws.len() {
            return f64::INFINITY;
        }
        let mut worst = 0.0f64;
        for (j, law) in self.laws.iter().enumerate() {
            let (u, r) = at(j);
            if !u.is_finite() || !r.is_finite() {
                return f64::INFINITY;
            }
            let mut s = self.state[j];
            let reach = s.drift_m.abs().max(u.abs());
            Self::follow(law, &mut s, self.rate[j], (u, r), len);
            let c = Self::correction(law, &s);
            let (a, b) = (self.c0[j], c1[j]);
            let line = a + theta * (b - a);
            let own = (1.0 - law.hardening) * law.yield_force_n.min(law.stiffness_n_m * reach);
            // A correction passing through zero is measured against the largest it has been,
            // not its value there: a load's error weighs against the loads the storey carries.
            let scale = a.abs().max(b.abs()).max(own).max(self.c_peak[j]);
            let off = (c - line).abs();
            if off > 0.0 {
                worst = worst.max(off / (allowed * scale));
            }
        }
        worst
    }

    /// Storey j's shear force now [N], the modes at `q`.
    pub fn shear_n(&self, j: usize, q: &[f64]) -> f64 {
        let s = StoreyState {
            drift_m: self.drift_now(j, q),
            ..self.state[j]
        };
        self.laws[j].force_n(&s)
    }

    /// Moves every storey to the drifts of the modes at q (their rates at v), along their paths
    /// from where they stand, over the step from `t0` to `t1`.
    pub fn commit(&mut self, q: &[f64], v: &[f64], t0: f64, t1: f64) {
        let mut moved = false;
        for j in 0..self.laws.len() {
            let u = self.drift_of(j, q);
            let r = self.drift_of(j, v);
            let before = self.state[j].drift_m;
            self.note_first_yield(j, before, u, t0, t1);
            Self::follow(
                &self.laws[j],
                &mut self.state[j],
                self.rate[j],
                (u, r),
                t1 - t0,
            );
            self.rate[j] = r;
            let c = Self::correction(&self.laws[j], &self.state[j]);
            moved |= c != self.c0[j];
            self.c0[j] = c;
            self.c_peak[j] = self.c_peak[j].max(c.abs());
        }
        // Unmoved corrections keep their loads, to the bit.
        if moved || self.load0.len() != self.by_mode.len() {
            let before = std::mem::take(&mut self.load0);
            Self::loads(&self.by_mode, &self.c0, &mut self.load0);
            let len = t1 - t0;
            for ((r, now), was) in self.trend.iter_mut().zip(&self.load0).zip(&before) {
                *r = if len > 0.0 { (now - was) / len } else { 0.0 };
            }
        } else {
            self.trend.fill(0.0);
        }
    }

    /// [`Storeys::commit`] for the step [`Storeys::end_loads`] last followed, from `t0` to `t1`,
    /// whose loads at the end it wrote into `load`: its ends taken as they are, without summing
    /// the drifts again (a contact step's trial ends where the step does). False, and nothing
    /// done, where that step has no ends (a state that was not finite).
    pub fn commit_ends(&mut self, load: &[f64], t0: f64, t1: f64) -> bool {
        let ends = std::mem::take(&mut *self.ends.borrow_mut());
        if ends.len() != self.laws.len() || load.len() != self.load0.len() {
            *self.ends.borrow_mut() = ends;
            return false;
        }
        let mut moved = false;
        for (j, &(s, u, r)) in ends.iter().enumerate() {
            let before = self.state[j].drift_m;
            self.note_first_yield(j, before, u, t0, t1);
            self.state[j] = s;
            self.rate[j] = r;
            let c = Self::correction(&self.laws[j], &s);
            moved |= c != self.c0[j];
            self.c0[j] = c;
            self.c_peak[j] = self.c_peak[j].max(c.abs());
        }
        if moved {
            let len = t1 - t0;
            for ((r, now), was) in self.trend.iter_mut().zip(load).zip(&self.load0) {
                *r = if len > 0.0 { (now - was) / len } else { 0.0 };
            }
            self.load0.copy_from_slice(load);
        } else {
            self.trend.fill(0.0);
        }
        *self.ends.borrow_mut() = ends;
        true
    }

    /// Records when storey j's drift first reaches its yield drift, on the straight path from
    /// `before` to `u` over the step from `t0` to `t1`.
    fn note_first_yield(&mut self, j: usize, before: f64, u: f64, t0: f64, t1: f64) {
        let uy = self.laws[j].yield_drift_m();
        if self.first_yield_s[j].is_none() && u.abs() >= uy {
            // Within the step, where the straight drift path reaches the yield drift.
            let target = uy.copysign(u);
            let share = if u != before {
                ((target - before) / (u - before)).clamp(0.0, 1.0)
            } else {
                1.0
            };
            self.first_yield_s[j] = Some(t0 + share * (t1 - t0));
        }
    }

    /// Whether every storey provably stays inside its elastic range over a stretch of length
    /// `span` whose modes have the envelopes `env`: its drift is the line of the particular
    /// responses plus at most the free vibrations' reach. Only the bilinear law has a range.
    pub fn stays_elastic(&self, env: &[Option<Envelope>], span: f64) -> bool {
        if self.laws.first().map(|l| l.kind) != Some(Hysteresis::Bilinear) {
            return false;
        }
        for (j, law) in self.laws.iter().enumerate() {
            let (mut p0, mut p1, mut reach) = (0.0, 0.0, 0.0);
            for (d, e) in self.drift[j].iter().zip(env) {
                let Some(e) = e else { return false };
                p0 += d * e.alpha;
                p1 += d * (e.alpha + e.beta * span);
                reach += d.abs() * e.free;
            }
            let Some((lo, hi)) = law.elastic_range_m(&self.state[j]) else {
                return false;
            };
            // A hair inside the range: the bound's own round-off must not let a yield through.
            let margin = 1e-9 * (hi - lo);
            if p0.min(p1) - reach <= lo + margin || p0.max(p1) + reach >= hi - margin {
                return false;
            }
        }
        true
    }

    /// The energy the storeys have dissipated [J].
    pub fn dissipated_j(&self) -> f64 {
        self.state.iter().map(|s| s.dissipated_j).sum()
    }

    /// What the storeys store by their laws less what the modes count for them (1/2 k u^2) [J],
    /// the modes at `q`: added to the modes' energy, the buildings' true energy.
    pub fn stored_less_elastic_j(&self, q: &[f64]) -> f64 {
        self.laws
            .iter()
            .zip(&self.state)
            .enumerate()
            .map(|(j, (l, s))| {
                let s = StoreyState {
                    drift_m: self.drift_now(j, q),
                    ..*s
                };
                l.stored_energy_j(&s) - 0.5 * l.stiffness_n_m * s.drift_m * s.drift_m
            })
            .sum()
    }
}

/// Whether a free step's fixed point, whose last two passes changed its loads by `last` and then
/// `change`, has settled: the free step takes the loads the last pass made, so what it leaves
/// is the next pass's change, about `change` times the contraction `change / last` the passes
/// show, and that is round-off. Only a smooth law's map contracts at the rate its passes show;
/// a bilinear storey's slope jumps where a pass moves it across its yield.
fn settled(change: f64, last: f64) -> bool {
    change <= 0.1 * last && change * change <= 1e-13 * last
}

/// The first yield of a bilinear storey of `side` strictly inside a step of length `len` from
/// the augmented modal states `y0` (the planned loads in them), if any: the corner where its
/// correction starts to move, a jump in the correction's slope that a line across it would
/// smear over the whole step.
///
/// A turn needs no locating: the drift's rate is zero there, so the correction's slope is
/// continuous through it (only its curvature jumps, an error of the order of the line's own
/// that the piece's departure check bounds), and the law follows the turn on the cubic through
/// the step's ends ([`Storeys::follow`]).
fn first_event(
    side: &Side,
    st: &Storeys,
    plan: &mut Plan,
    len: f64,
    maps: Option<&[Propagator]>,
) -> Option<f64> {
    if st.laws.first().map(|l| l.kind) != Some(Hysteresis::Bilinear) {
        return None;
    }
    let Plan { y0, q1, v1 } = plan;
    // Whole fine steps (the usual case) have their maps made once for the run.
    for k in 0..side.modes() {
        (q1[k], v1[k]) = match maps {
            Some(m) => m[k].apply(&y0[k]),
            None => propagator(side.omega[k], side.zeta[k], len).apply(&y0[k]),
        };
    }
    // Storey j's drift tau into the step, on the exact motion.
    let at = |j: usize, tau: f64| -> f64 {
        (0..side.modes())
            .map(|k| {
                let (q, _) = propagator(side.omega[k], side.zeta[k], tau).apply(&y0[k]);
                st.drift[j][k] * q
            })
            .sum()
    };
    let tol = 1e-14 * len;
    let inside = |tau: f64| tau > EVENT_PIECE * len && tau < (1.0 - EVENT_PIECE) * len;
    let mut first: Option<f64> = None;
    for j in 0..st.laws.len() {
        let (u0, u1) = (st.drift_of(j, &side.q), st.drift_of(j, q1));
        if let Some((lo, hi)) = st.laws[j].elastic_range_m(&st.state[j])
            && u0 > lo
            && u0 < hi
            && !(lo..=hi).contains(&u1)
        {
            // Just past the edge: the law yields from the next step on.
            let edge = if u1 > hi { hi } else { lo };
            let tau = bracket(|x| at(j, x) - edge, 0.0, len, tol).second_side;
            if inside(tau) {
                first = Some(first.map_or(tau, |f: f64| f.min(tau)));
            }
        }
    }
    first
}

/// What the storeys did over a run, per side and storey (lowest first).
#[derive(Debug, Clone, Default)]
pub(in crate::model::building) struct StoreySummary {
    pub ductility_demand: [Vec<f64>; 2],
    pub residual_drift_m: [Vec<f64>; 2],
    pub hysteretic_energy_j: [Vec<f64>; 2],
    pub first_yield_s: [Vec<Option<f64>>; 2],
    pub yield_drift_m: [Vec<f64>; 2],
}

impl Stepper<'_> {
    /// Whether any storey yields (the run takes its corrections as loads).
    pub(super) fn yields(&self) -> bool {
        self.sides.iter().any(|s| s.storeys.is_some())
    }

    /// Plans the next free step from a grid point: where every yielding storey provably stays
    /// elastic over the whole stretch to the next free-step boundary, its corrections are
    /// constant and the stretch is taken whole, as an elastic run's; otherwise a piece
    /// ([`Stepper::plan_piece`]), with the corrections planned by the fixed point. Whether the
    /// stretch is whole.
    pub(super) fn plan_stretch(&mut self) -> bool {
        let g = self.grid;
        let len = (g.per_free_step - self.n % g.per_free_step).min(g.total - self.n);
        let span = len as f64 * g.h;
        let t0 = self.time();
        for s in 0..2 {
            if let Some(st) = self.sides[s].storeys.as_mut() {
                st.load1.clone_from(&st.load0);
                st.len = 0.0;
            }
        }
        let whole = (0..2).all(|s| {
            let Some(st) = self.sides[s].storeys.as_ref() else {
                return true;
            };
            let side = &self.sides[s];
            let y0 = self.initial(s, t0);
            let env: Vec<Option<Envelope>> = (0..side.modes())
                .map(|k| envelope(side.omega[k], side.zeta[k], &y0[k]))
                .collect();
            st.stays_elastic(&env, span)
        });
        if !whole {
            self.piece = self.plan_piece(len);
        }
        whole
    }

    /// Plans a piece of free motion of at most `most` fine steps from a grid point: the longest
    /// whose corrections stay within [`Grid::yield_departure`] of their line, found from the
    /// length the last piece suggested (the departure goes as the square of the length). Its
    /// length in fine steps.
    fn plan_piece(&mut self, most: usize) -> usize {
        let h = self.grid.h;
        let mut steps = self.piece_guess.clamp(1, most);
        loop {
            let passes = self.plan_free(steps as f64 * h);
            if steps == 1 {
                self.piece_guess = 2;
                return 1;
            }
            let ratio = if passes <= PIECE_PASSES {
                self.piece_departure(steps)
            } else {
                f64::INFINITY
            };
            let factor = if ratio > 0.0 { 0.9 / ratio.sqrt() } else { 2.0 };
            if ratio <= 1.0 {
                let next = ((steps as f64 * factor.min(2.0)) as usize).max(1);
                // A piece cut short by the free step's end says nothing against a longer one.
                self.piece_guess = if steps == most {
                    self.piece_guess.max(next)
                } else {
                    next
                };
                return steps;
            }
            steps = ((steps as f64 * factor.clamp(0.1, 0.5)) as usize).max(1);
        }
    }

    /// The planned piece's largest departure of a correction from its line, at the fine step
    /// nearest its middle, over what a piece may leave ([`Storeys::departure`]); `steps` fine
    /// steps long, at least two. The plan's end states serve as buffers (the event search makes
    /// them again).
    fn piece_departure(&mut self, steps: usize) -> f64 {
        let mid = steps / 2;
        let theta = mid as f64 / steps as f64;
        let (h, allowed) = (self.grid.h, self.grid.yield_departure);
        let mut worst = 0.0f64;
        for side in self.sides.iter_mut() {
            let Some(mut plan) = side.storeys.as_mut().map(|st| std::mem::take(&mut st.plan))
            else {
                continue;
            };
            let Plan { y0, q1, v1 } = &mut plan;
            for (k, p) in side.maps(mid).iter().enumerate() {
                (q1[k], v1[k]) = p.apply(&y0[k]);
            }
            let st = side.storeys.as_mut().expect("checked");
            st.plan = plan;
            let (q, v) = (&st.plan.q1, &st.plan.v1);
            let at = |j: usize| (st.drift_of(j, q), st.drift_of(j, v));
            worst = worst.max(st.departure(at, mid as f64 * h, theta, allowed));
        }
        worst
    }

    /// The length of the piece of free motion planned now [s].
    pub(super) fn planned_piece(&self) -> f64 {
        self.sides
            .iter()
            .find_map(|s| s.storeys.as_ref().map(|st| st.len))
            .unwrap_or(self.grid.h)
    }

    /// The fine steps' exact maps for a piece of length `len`, when it is a whole number of
    /// them within a free stretch (the maps the run made once).
    fn grid_maps(&self, s: usize, len: f64) -> Option<&[Propagator]> {
        let j = self.grid.whole_steps(len)?;
        Some(self.sides[s].maps(j))
    }

    /// Plans a free step of length `len` from now: each side's corrections at its end, by the
    /// fixed point over the exact step with the corrections linear in time. The most passes a
    /// side took, [`MAX_PASSES`] + 1 where one did not settle.
    pub(super) fn plan_free(&mut self, len: f64) -> usize {
        let ground = self.ground(self.time());
        let mut most = 0;
        for s in 0..2 {
            let Some(st) = self.sides[s].storeys.as_mut() else {
                continue;
            };
            let mut load1 = std::mem::take(&mut st.load1);
            st.guess_into(len, &mut load1);
            st.load1 = load1;
            st.len = len;
            let Plan {
                mut y0,
                mut q1,
                mut v1,
            } = std::mem::take(&mut st.plan);
            let side = &self.sides[s];
            let own: Option<Vec<Propagator>> = self.grid_maps(s, len).is_none().then(|| {
                (0..side.modes())
                    .map(|k| propagator(side.omega[k], side.zeta[k], len))
                    .collect()
            });
            let mut passes = MAX_PASSES + 1;
            let mut last = f64::INFINITY;
            for pass in 1..=MAX_PASSES {
                self.initial_on(s, ground, &mut y0);
                let props = own
                    .as_deref()
                    .or_else(|| self.grid_maps(s, len))
                    .expect("one or the other");
                for (k, p) in props.iter().enumerate() {
                    (q1[k], v1[k]) = p.apply(&y0[k]);
                }
                let st = self.sides[s].storeys.as_mut().expect("checked");
                let mut load1 = std::mem::take(&mut st.load1);
                let end = |j: usize| (st.drift_of(j, &q1), st.drift_of(j, &v1));
                let start = |j: usize| (st.state[j].drift_m, st.rate[j]);
                let change = st.end_loads(end, start, len, &mut load1);
                st.load1 = load1;
                if change <= 1e-13 || (st.smooth() && settled(change, last)) {
                    passes = pass;
                    break;
                }
                last = change;
            }
            most = most.max(passes);
            let st = self.sides[s].storeys.as_mut().expect("checked");
            st.plan = Plan { y0, q1, v1 };
        }
        most
    }

    /// Where a bilinear storey reaches the edge of its elastic range (yields) inside a planned
    /// free step of length `len`, that instant is located on the exact motion, as a contact
    /// onset is ([`first_event`]). Where the first is, or `len` where there is none; the plan
    /// stays the whole step's.
    pub(super) fn first_storey_event(&mut self, len: f64) -> f64 {
        let ground = self.ground(self.time());
        let mut first = len;
        for s in 0..2 {
            let Some(st) = self.sides[s].storeys.as_mut() else {
                continue;
            };
            let mut plan = std::mem::take(&mut st.plan);
            self.initial_on(s, ground, &mut plan.y0);
            let side = &self.sides[s];
            let st = side.storeys.as_ref().expect("checked");
            let maps = self.grid_maps(s, len);
            if let Some(tau) = first_event(side, st, &mut plan, len, maps) {
                first = first.min(tau);
            }
            self.sides[s].storeys.as_mut().expect("checked").plan = plan;
        }
        first
    }

    /// [`Stepper::first_storey_event`], with the step re-planned to end there where it is
    /// inside. The length of the step to take.
    pub(super) fn step_to_first_event(&mut self, len: f64) -> f64 {
        let first = self.first_storey_event(len);
        if first < len {
            self.plan_free(first);
        }
        first
    }

    /// Every side's storeys moved through the contact step the last trial made, from `t0` to
    /// `t1`, from its ends and its loads at the end (`load`, per side); where a side's trial
    /// left none, as [`Stepper::commit_storeys`].
    pub(super) fn commit_storeys_from_trial(&mut self, load: &[Vec<f64>; 2], t0: f64, t1: f64) {
        for (side, load) in self.sides.iter_mut().zip(load) {
            if let Some(st) = side.storeys.as_mut() {
                if !st.commit_ends(load, t0, t1) {
                    st.commit(&side.q, &side.v, t0, t1);
                }
                st.len = 0.0;
            }
        }
    }

    /// Every side's storeys brought to where the modes stand, where quiet contact steps left
    /// them behind.
    pub(super) fn sync_storeys(&mut self) {
        for side in self.sides.iter_mut() {
            if let Some(st) = side.storeys.as_mut() {
                st.sync(&side.q, &side.v);
            }
        }
    }

    /// Every side's storeys moved to where the modes stand at the end of the step just
    /// committed, from `t0` to `t1`.
    pub(super) fn commit_storeys(&mut self, t0: f64, t1: f64) {
        for side in self.sides.iter_mut() {
            if let Some(st) = side.storeys.as_mut() {
                st.commit(&side.q, &side.v, t0, t1);
                st.len = 0.0;
            }
        }
    }

    /// Inside a contact step of length `hh`: each side's corrections at the trial's end (its
    /// modes moved by `dq`) into `load1`; the largest relative change.
    pub(super) fn contact_end_loads(
        &self,
        dq: &[Vec<f64>; 2],
        hh: f64,
        load1: &mut [Vec<f64>; 2],
    ) -> f64 {
        let mut worst = 0.0f64;
        for s in 0..2 {
            let side = &self.sides[s];
            if let Some(st) = side.storeys.as_ref() {
                // Newmark's (trapezoidal) velocity: the end rate is 2 du / h less the start's.
                // Where the storeys stand where the modes do (each commit moves both), the end
                // drift is the step's change on top of theirs.
                let start = |j: usize| {
                    if st.stale {
                        (st.drift_of(j, &side.q), st.drift_of(j, &side.v))
                    } else {
                        (st.state[j].drift_m, st.rate[j])
                    }
                };
                let end = |j: usize| {
                    let (u0, r0) = start(j);
                    let u1 = u0 + st.drift_of(j, &dq[s]);
                    (u1, 2.0 * (u1 - u0) / hh - r0)
                };
                worst = worst.max(st.end_loads(end, start, hh, &mut load1[s]));
            }
        }
        worst
    }

    /// Every storey's ductility demand, drift now and dissipated energy, per side, from the
    /// peak drift ratios of the run so far.
    pub fn storey_summary(
        &self,
        buildings: [&crate::model::building::Building; 2],
        peak_drift_ratio: &[Vec<f64>; 2],
    ) -> StoreySummary {
        let mut out = StoreySummary::default();
        for (s, b) in buildings.into_iter().enumerate() {
            let side = &self.sides[s];
            for j in 0..b.storeys {
                let yield_drift = b.yield_force(j) / b.stiffness(j);
                let peak = peak_drift_ratio[s].get(j).copied().unwrap_or(0.0) * b.height(j);
                out.ductility_demand[s].push(peak / yield_drift);
                out.yield_drift_m[s].push(yield_drift);
                out.first_yield_s[s].push(
                    side.storeys
                        .as_ref()
                        .and_then(|st| st.first_yield_s.get(j).copied().flatten()),
                );
                let (drift, dissipated) = match &side.storeys {
                    Some(st) => (st.drift_of(j, &side.q), st.state[j].dissipated_j),
                    None => {
                        let below = if j > 0 {
                            side.floor(&side.q, j - 1)
                        } else {
                            0.0
                        };
                        (side.floor(&side.q, j) - below, 0.0)
                    }
                };
                out.residual_drift_m[s].push(drift);
                out.hysteretic_energy_j[s].push(dissipated);
            }
        }
        out
    }
}
