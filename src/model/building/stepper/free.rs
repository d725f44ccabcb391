//! The free stretch: the exact motion between contacts, checked at a few points and walked grid
//! point by grid point only where a bound cannot rule out an onset or a new peak.

use super::*;
use crate::model::bound::{
    ROUNDING, cubic_bound, cubic_margin, cubic_max, cubic_max_abs, mode_bounds, monotone,
    second_derivative,
};
use crate::model::building::modal::evaluate;

/// The sum of |r_k| m_k over the modes.
fn weighted(r: &[f64], m: &[f64]) -> f64 {
    r.iter().zip(m).map(|(r, m)| r.abs() * m).sum()
}

/// A part this short (in grid steps) is walked rather than halved again.
const WALK_SPAN: usize = 8;

/// The part of a stretch a check covers: grid indices (from the stretch's start) a to b.
#[derive(Clone, Copy)]
struct Part {
    a: usize,
    b: usize,
}

impl Stepper<'_> {
    /// The augmented initial states y0 = [q, q', g, g'] of every mode of a side.
    pub(super) fn initial(&self, s: usize, t: f64) -> Vec<[f64; 4]> {
        let mut y = Vec::new();
        self.initial_into(s, t, &mut y);
        y
    }

    pub(super) fn initial_into(&self, s: usize, t: f64, out: &mut Vec<[f64; 4]>) {
        self.initial_on(s, self.ground(t), out);
    }

    /// [`Stepper::initial_into`] with the ground's acceleration and its slope at t given (a
    /// step planned pass by pass reads them once).
    pub(super) fn initial_on(&self, s: usize, (a0, slope): (f64, f64), out: &mut Vec<[f64; 4]>) {
        let side = &self.sides[s];
        out.clear();
        out.extend((0..side.modes()).map(|k| {
            let (p, p_rate) = side.storeys.as_ref().map_or((0.0, 0.0), |st| st.pseudo(k));
            [
                side.q[k],
                side.v[k],
                -side.gamma[k] * a0 + p,
                -side.gamma[k] * slope + p_rate,
            ]
        }));
    }

    /// Writes a free stretch of length `len` from `y0` to the ledger and moves the state to
    /// (`q1`, `v1`): the exact integrals of the ground's power and of the damping.
    pub(super) fn commit_free(
        &mut self,
        y0: [&[[f64; 4]]; 2],
        q1: [&[f64]; 2],
        v1: [&[f64]; 2],
        len: f64,
    ) {
        self.newmark = false;
        // A whole number of fine steps reuses its integrals; another length (up to an event
        // inside a step) needs its own.
        let j = self.grid.whole_steps(len);
        for s in 0..2 {
            let side = &mut self.sides[s];
            if let Some(j) = j
                && j < self.grid.per_stretch
                && side.part[j].is_none()
            {
                side.part[j] = Some(
                    (0..side.modes())
                        .map(|k| side.integrals_over(k, j))
                        .collect(),
                );
            }
            for k in 0..side.modes() {
                let ints = match j {
                    Some(j) if j == self.grid.per_stretch => side.full[k],
                    Some(j) => side.part[j].as_ref().expect("just made")[k],
                    None => step_integrals(side.omega[k], side.zeta[k], len),
                };
                let y = &y0[s][k];
                let dq = q1[s][k] - y[0];
                let int_q: f64 = (0..4).map(|j| ints.int_q[j] * y[j]).sum();
                let int_s_v = len * q1[s][k] - int_q;
                let (p, p_rate) = side.storeys.as_ref().map_or((0.0, 0.0), |st| st.pseudo(k));
                // The storeys' corrections are loads in y; their work is theirs, not the ground's
                // (what they dissipate is their laws' own count).
                self.ledger.input_j += (y[2] - p) * dq + (y[3] - p_rate) * int_s_v;
                self.ledger.damping_j +=
                    2.0 * side.zeta[k] * side.omega[k] * ints.velocity_squared(y);
                side.q[k] = q1[s][k];
                side.v[k] = v1[s][k];
            }
        }
        if self.yields() {
            let t0 = self.time();
            self.commit_storeys(t0, t0 + len);
        }
    }

    /// Both sides' exact states and modal accelerations j fine steps into the stretch (into
    /// `w.q`, `w.v`, `w.acc`): [`Stepper::states_at`] and [`Stepper::accelerations`] in one
    /// pass ([`lanes::exact_states`]).
    fn states_and_accelerations(&self, w: &mut Scratch, j: usize) {
        for s in 0..2 {
            let side = &self.sides[s];
            let e = lanes::Exact {
                maps: side.maps(j),
                y0: &w.y0[s],
                damping: &side.damping,
                stiffness: &side.stiffness,
                s: j as f64 * self.grid.h,
            };
            lanes::exact_states(&e, &mut w.q[s], &mut w.v[s], &mut w.acc[s]);
        }
    }

    /// Both sides' exact states j fine steps after the start of the stretch from `y0`.
    pub(super) fn states_at(
        &self,
        y0: &[Vec<[f64; 4]>; 2],
        j: usize,
        q: &mut [Vec<f64>; 2],
        v: &mut [Vec<f64>; 2],
    ) {
        for s in 0..2 {
            for (k, p) in self.sides[s].maps(j).iter().enumerate() {
                let (qk, vk) = p.apply(&y0[s][k]);
                q[s][k] = qk;
                v[s][k] = vk;
            }
        }
    }

    /// One free stretch from a grid point to the next sample of the record (or the next free
    /// step's end, where a stretch is a free step: [`Grid::per_stretch`]). Its parts are checked
    /// against the bounds; a part a bound cannot clear is halved until what is left near an onset
    /// or a peak is walked grid point by grid point.
    pub(super) fn free_step(&mut self) -> Result<Free, SolveError> {
        self.newmark = false;
        let g = self.grid;
        // To the next stretch's end (a sample of the record, or a free step's end where a stretch
        // is one); the planned piece where storeys yield (their corrections are planned piece
        // by piece).
        let len = (g.per_stretch - self.n % g.per_stretch).min(g.total - self.n);
        let len = if self.single_step {
            len.min(self.piece)
        } else {
            len
        };
        self.count_step()?;
        let t0 = self.time();
        let mut w = self
            .scratch
            .take()
            .expect("the scratch is home between stages");
        self.prepare(&mut w, t0, len);
        let mut a = 0;
        while a < len {
            let part = Part {
                a,
                b: (a + g.check).min(len),
            };
            match self.refine(&mut w, 0, part, t0, false) {
                Ok(None) => {}
                Ok(Some(onset)) => {
                    // The stretch is taken up to the grid point before the onset's step: its
                    // samples before there first.
                    if let Free::Onset { j, .. } = onset {
                        self.record_inside(&mut w, j - 1);
                    }
                    self.scratch = Some(w);
                    return Ok(onset);
                }
                Err(e) => {
                    self.scratch = Some(w);
                    return Err(e);
                }
            }
            a = part.b;
        }
        self.record_inside(&mut w, len);
        // Every check ends by working out the states at its part's end (its halves and its walk
        // end there too): `w` holds the stretch's end.
        {
            let Scratch { y0, q, v, .. } = &*w;
            self.commit_free(
                [&y0[0], &y0[1]],
                [&q[0], &q[1]],
                [&v[0], &v[1]],
                len as f64 * g.h,
            );
        }
        self.scratch = Some(w);
        self.at_step(self.n + len);
        self.record_free();
        Ok(Free::Done)
    }

    /// The histories' samples a free step apart inside a stretch of `len` fine steps from now
    /// (its end is recorded once the stretch is taken): the exact states there, from its start.
    fn record_inside(&mut self, w: &mut Scratch, len: usize) {
        let every = self.grid.per_free_step;
        if !self.histories || every >= self.grid.per_stretch {
            return;
        }
        for s in 0..2 {
            let n = self.sides[s].modes();
            w.inside[0][s].resize(n, 0.0);
            w.inside[1][s].resize(n, 0.0);
        }
        let n0 = self.n;
        let mut j = every - n0 % every;
        while j < len {
            let [q, v] = &mut w.inside;
            self.states_at(&w.y0, j, q, v);
            // The sample reads the sides' states at the step's time: the stretch's own are put
            // back after it.
            self.swap_states(&mut w.inside);
            self.at_step(n0 + j);
            self.record_now();
            self.at_step(n0);
            self.swap_states(&mut w.inside);
            j += every;
        }
    }

    /// Trades the sides' modal displacements and velocities with `[q, v]` (no copies: twice
    /// makes it as it was).
    fn swap_states(&mut self, [q, v]: &mut [[Vec<f64>; 2]; 2]) {
        for s in 0..2 {
            std::mem::swap(&mut self.sides[s].q, &mut q[s]);
            std::mem::swap(&mut self.sides[s].v, &mut v[s]);
        }
    }

    /// Checks a part at depth `d` of the halving (for what its parent left open): clears it,
    /// halves it, or walks it. Returns the onset, if one was found in it.
    /// `end_read`: the part ends where its parent does (its second half), whose check read
    /// every value this one looks at there.
    fn refine(
        &mut self,
        w: &mut Scratch,
        d: usize,
        part: Part,
        t0: f64,
        end_read: bool,
    ) -> Result<Option<Free>, SolveError> {
        self.steps += 1;
        // The states at the part's end even where its values are known: a part ends with `w`
        // there (the stretch's end is committed from it).
        self.states_and_accelerations(w, part.b);
        let (any, unbounded) = self.flag(w, d, part, t0, end_read);
        if any {
            let len = part.b - part.a;
            if unbounded || len <= WALK_SPAN {
                if let Some(onset) = self.walk(w, d, part, t0)? {
                    return Ok(Some(onset));
                }
            } else {
                let mid = part.a + len / 2;
                let halves = [
                    (Part { a: part.a, b: mid }, false),
                    (Part { a: mid, b: part.b }, true),
                ];
                for (half, end_read) in halves {
                    if let Some(onset) = self.refine(w, d + 1, half, t0, end_read)? {
                        return Ok(Some(onset));
                    }
                }
            }
        }
        self.pass(w, d, part, t0);
        Ok(None)
    }

    /// The stretch's starting states and the bounds its checks use; and, from the bound on each
    /// mode's size over the whole stretch, what it must be checked for at all (the root of its
    /// halving): a point whose closing motion cannot reach the gap or its largest value, a signal
    /// that cannot reach its peak, are left alone for the whole stretch.
    // Once a stretch, out of line: inlined, it weighs on the loop every step runs through.
    #[inline(never)]
    fn prepare(&mut self, w: &mut Scratch, t0: f64, len: usize) {
        let span = len as f64 * self.grid.h;
        self.start_states(w, t0, span);
        self.accelerations(w, 0);
        // A tall building's bounds come from its tables, a few modes' row by row (the same
        // sums).
        let tall = [0, 1].map(|s| self.sides[s].modes() >= TALL);
        for s in (0..2).filter(|&s| tall[s]) {
            let m = [&w.size[s][..], &w.m4[s], &w.m5[s], &w.m2[s]];
            self.bound_rows.points[s].weigh(m, &mut w.point_bounds[s]);
            self.bound_rows.signals[s].weigh(m, &mut w.signal_bounds[s]);
        }
        self.flag_points(w, span, tall);
        self.flag_signals(w, t0, span, tall);
    }

    /// Each mode's state at the stretch's start, and its bounds over the stretch: its size, its
    /// fourth and fifth derivatives, and (a tall building's) its second.
    fn start_states(&self, w: &mut Scratch, t0: f64, span: f64) {
        for s in 0..2 {
            self.initial_into(s, t0, &mut w.y0[s]);
            let side = &self.sides[s];
            let n = side.modes();
            w.q[s].resize(n, 0.0);
            w.v[s].resize(n, 0.0);
            w.acc[s].resize(n, 0.0);
            w.m4[s].clear();
            w.m5[s].clear();
            w.m2[s].clear();
            w.size[s].clear();
            for k in 0..n {
                let y = &w.y0[s][k];
                let [size, m4, m5] = mode_bounds(side.omega[k], side.zeta[k], y, span);
                w.size[s].push(size);
                w.m4[s].push(m4);
                w.m5[s].push(m5);
                // Only a tall building's signals are tested on it (see below).
                if n >= TALL {
                    w.m2[s].push(second_derivative(side.omega[k], side.zeta[k], y));
                }
                w.q[s][k] = y[0];
                w.v[s][k] = y[1];
            }
        }
    }

    /// Which contact points the stretch may bring to their gap (onset) or to a new largest
    /// closing, from their readings now and their bounds over the stretch.
    fn flag_points(&self, w: &mut Scratch, span: f64, tall: [bool; 2]) {
        let contact = self.sc.contact != ContactModel::None;
        w.root.onset.clear();
        w.root.closing.clear();
        w.root.points.clear();
        w.prev.clear();
        w.point_m4.clear();
        w.point_m5.clear();
        for (j, p) in self.points.iter().enumerate() {
            let [c, cv, ca] = self.point_reading(
                p,
                [&w.q[0], &w.q[1]],
                [&w.v[0], &w.v[1]],
                [&w.acc[0], &w.acc[1]],
            );
            w.prev.push([c, cv, ca]);
            // Per side: the bounds on the point's size, its fourth and fifth derivatives, and
            // (both sides tall) its second.
            let mut sides = [[0.0; 4]; 2];
            for (s, out) in sides.iter_mut().enumerate() {
                *out = if tall[s] {
                    let b = &w.point_bounds[s];
                    [b[0][j], b[1][j], b[2][j], b[3][j]]
                } else {
                    let r = &p.r[s];
                    [
                        weighted(r, &w.size[s]),
                        weighted(r, &w.m4[s]),
                        weighted(r, &w.m5[s]),
                        f64::INFINITY,
                    ]
                };
            }
            let [l, r] = sides;
            w.point_m4.push(l[1] + r[1]);
            w.point_m5.push(l[2] + r[2]);
            let size = (l[0] + r[0]) * (1.0 + ROUNDING);
            let gap = self.sc.gap_m;
            let below = self.closing_bar(p);
            // The slabs' ringing is bounded (its envelope tabulated) only where the motion alone
            // cannot reach the gap: the bound is never negative.
            let ringing = |reach: f64| {
                if self.sears && reach < gap {
                    p.elastic_bound_from(self.n)
                } else {
                    0.0
                }
            };
            let mut onset = contact && (size >= gap || size + ringing(size) >= gap);
            let mut closing = size >= below;
            // As for a tall building's signals (below): from where the closing motion is, at its
            // rate, with its acceleration's bound, it may still stay below the gap and its
            // largest value over the stretch.
            let m2 = l[3] + r[3];
            if (onset || closing) && m2.is_finite() {
                let reach = c + cv.abs() * span + 0.5 * m2 * span * span;
                let reach = reach + ROUNDING * (size + reach.abs());
                onset &= reach + ringing(reach) >= gap;
                closing &= reach >= below;
            }
            if onset || closing {
                w.root.points.push(j);
            }
            w.root.onset.push(onset);
            w.root.closing.push(closing);
        }
    }

    /// Which followed signals the stretch may bring past their peak; those it leaves alone are
    /// marked stale.
    fn flag_signals(&mut self, w: &mut Scratch, t0: f64, span: f64, tall: [bool; 2]) {
        w.root.peak.clear();
        w.root.signals.clear();
        w.signal_m4.clear();
        w.signal_m5.clear();
        w.signal_acc.clear();
        for (i, sig) in self.signals.iter().enumerate() {
            // A signal the run does not follow has no bounds.
            let Some(j) = self.bound_rows.row_of[i] else {
                w.signal_m4.push(0.0);
                w.signal_m5.push(0.0);
                w.root.peak.push(false);
                self.proof[i].stale = true;
                w.signal_acc.push(0.0);
                continue;
            };
            let side = sig.side_and_coefficients().0;
            let table = tall[side].then(|| &w.signal_bounds[side]);
            let peak = self.peaks.peak(i);
            let size = match table {
                Some(b) => b[0][j],
                None => sig.bound(&w.size),
            };
            let mut open = size * (1.0 + ROUNDING) >= peak;
            let mut now = (0.0, 0.0);
            if open {
                now = self.signal(i, [&w.q[0], &w.q[1]], [&w.v[0], &w.v[1]]);
                // The sum of the modes' sizes is far above what a tall building's signal
                // reaches: from where it is, at its rate, with its acceleration's bound, it may
                // still stay below its peak over the stretch (rounding: a hair of the sizes
                // its sums are made from). A few modes' sum is close enough.
                if let Some(b) = table {
                    let (u, r) = now;
                    let reach = u.abs() + r.abs() * span + 0.5 * b[3][j] * span * span;
                    open = reach + ROUNDING * (size + reach) >= peak;
                }
            }
            // A signal the stretch leaves alone needs no bounds on its derivatives.
            let [m4, m5] = match (open, table) {
                (false, _) => [0.0; 2],
                (true, Some(b)) => [b[1][j], b[2][j]],
                (true, None) => [sig.bound(&w.m4), sig.bound(&w.m5)],
            };
            w.signal_m4.push(m4);
            w.signal_m5.push(m5);
            w.root.peak.push(open);
            if open {
                w.root.signals.push(i);
                // Its last instant is this one (a stretch that left it alone did not keep it).
                let (u, r) = now;
                self.peaks.pass(i, t0, u, r);
                self.proof[i].stale = false;
                w.signal_acc
                    .push(self.signal_value(i, [&w.acc[0], &w.acc[1]]));
            } else {
                self.proof[i].stale = true;
                w.signal_acc.push(0.0);
            }
        }
    }

    /// The modal accelerations j fine steps into the stretch, from the states in `w.q`, `w.v`
    /// (as [`lanes::exact_states`] takes them).
    fn accelerations(&self, w: &mut Scratch, j: usize) {
        let s = j as f64 * self.grid.h;
        for side in 0..2 {
            let sd = &self.sides[side];
            for k in 0..sd.modes() {
                let y = &w.y0[side][k];
                let (q, v) = (w.q[side][k], w.v[side][k]);
                w.acc[side][k] = lanes::acceleration(y, s, sd.damping[k], sd.stiffness[k], q, v);
            }
        }
    }

    /// Decides, from the states at the part's end (in `w.q`, `w.v`), what the part must still be
    /// looked into for, of what its parent left open: a point whose closing motion may reach the
    /// gap or its largest value so far, a signal that may pass its peak. A signal whose rate keeps
    /// its sign over the part (proved as its value's bound proves the rest) has its largest
    /// value at an end: that is taken at once, as a walk would take it. Returns whether anything
    /// must be looked into, and whether an onset can have no bound (a slab's waves fresh from a
    /// contact).
    /// `end_read`: the part's parent ended where it does, and its values there are taken
    /// (the same sums of the same states) rather than read again.
    fn flag(
        &mut self,
        w: &mut Scratch,
        d: usize,
        part: Part,
        t0: f64,
        end_read: bool,
    ) -> (bool, bool) {
        let (h, l) = (self.grid.h, (part.b - part.a) as f64 * self.grid.h);
        let t = t0 + part.b as f64 * h;
        let gap = self.sc.gap_m;
        let contact = self.sc.contact != ContactModel::None;
        if w.depths.len() <= d {
            w.depths.resize_with(d + 1, Depth::default);
        }
        let (parents, rest) = w.depths.split_at_mut(d);
        let parent = parents.last().unwrap_or(&w.root);
        let now = &mut rest[0];
        let (mut any, mut unbounded) = (false, false);
        let (np, ns) = (self.points.len(), self.signals.len());
        now.onset.resize(np, false);
        now.closing.resize(np, false);
        now.peak.resize(ns, false);
        now.values.resize(np + ns, [0.0; 3]);
        now.points.clear();
        now.signals.clear();
        let (q, v, acc) = (
            [&w.q[0][..], &w.q[1]],
            [&w.v[0][..], &w.v[1]],
            [&w.acc[0][..], &w.acc[1]],
        );
        let mut may_touch = false;
        for &i in &parent.points {
            let (open_onset, open_closing) = (parent.onset[i], parent.closing[i]);
            let p = &self.points[i];
            let [c, cv, ca] = if end_read {
                parent.values[i]
            } else {
                self.point_reading(p, q, v, acc)
            };
            let [c0, cv0, _] = w.prev[i];
            let margin = cubic_margin(w.point_m4[i], l)
                + cubic_margin(w.point_m4[i], h)
                + ROUNDING * (c0.abs() + c.abs() + l * (cv0.abs() + cv.abs()));
            // The cubic's largest value: at once below a quick bound, else found exactly.
            let quick = cubic_bound(c0, cv0, c, cv, l);
            let below = self.closing_bar(p);
            let elastic = |top: f64| {
                if self.sears && open_onset && contact && top + margin < gap {
                    p.elastic_bound_from(self.n + part.a)
                } else {
                    0.0
                }
            };
            let top = if quick + margin + elastic(quick) < gap && quick + margin < below {
                quick
            } else {
                cubic_max(c0, cv0, c, cv, l)
            };
            let elastic = elastic(top);
            let onset = open_onset && contact && top + margin + elastic >= gap;
            let closing = open_closing && top + margin >= below;
            any |= onset || closing;
            may_touch |= onset;
            unbounded |= onset && elastic.is_infinite();
            now.onset[i] = onset;
            now.closing[i] = closing;
            now.values[i] = [c, cv, ca];
            if onset || closing {
                now.points.push(i);
            }
        }
        // A contact may start inside the part: what the free motion does after it does not
        // count, so nothing is taken from the part's end until the onset has been ruled out.
        if !may_touch {
            any = self.close_monotone(now, &w.prev, &w.point_m5, l);
        }
        for &i in &parent.signals {
            let [u, r, a] = if end_read {
                parent.values[np + i]
            } else {
                self.signal_reading(i, q, v, acc)
            };
            let (u0, r0) = self.peaks.last(i);
            let m4 = w.signal_m4[i];
            let margin = cubic_margin(m4, l)
                + cubic_margin(m4, h)
                + ROUNDING * (u0.abs() + u.abs() + l * (r0.abs() + r.abs()));
            let bar = self.peaks.peak(i);
            let quick = cubic_bound(u0.abs(), r0.abs(), u.abs(), r.abs(), l);
            let top = if quick + margin < bar {
                quick
            } else {
                cubic_max_abs(u0, r0, u, r, l)
            };
            let mut peak = top + margin >= bar;
            if peak && !may_touch && monotone([r0, w.signal_acc[i]], [r, a], l, w.signal_m5[i]) {
                self.peaks.update(i, t, u, r);
                w.signal_acc[i] = a;
                peak = false;
            }
            any |= peak;
            now.peak[i] = peak;
            now.values[np + i] = [u, r, a];
            if peak {
                now.signals.push(i);
            }
        }
        (any, unbounded)
    }

    /// Where no point can touch, every open point is open for its closing motion alone: one
    /// whose closing is monotone over the part takes its largest value at an end (the start
    /// counted already) and is closed. Whether any point stays open.
    fn close_monotone(&mut self, now: &mut Depth, prev: &[[f64; 3]], m5: &[f64], l: f64) -> bool {
        for &i in &now.points {
            let [c, cv, ca] = now.values[i];
            let [_, cv0, ca0] = prev[i];
            if monotone([cv0, ca0], [cv, ca], l, m5[i]) {
                let p = &mut self.points[i];
                p.max_closing = p.max_closing.max(c);
                now.closing[i] = false;
            }
        }
        let closing = &now.closing;
        now.points.retain(|&i| closing[i]);
        !now.points.is_empty()
    }

    /// Walks the part grid point by grid point for what [`Stepper::flag`] left open at depth
    /// `d`: the onset at the first grid point where the overlap
    /// is positive, the largest closing motion and the peaks on the cubics between grid points.
    /// Returns the onset, if one was found (the slabs then stand at the grid point before it).
    fn walk(
        &mut self,
        w: &mut Scratch,
        d: usize,
        part: Part,
        t0: f64,
    ) -> Result<Option<Free>, SolveError> {
        let g = self.grid;
        let contact = self.sc.contact;
        let gap = self.sc.gap_m;
        let needs_approach = self.needs_approach();
        let open = std::mem::take(&mut w.depths[d]);
        let mut marks = std::mem::take(&mut w.marks);
        let mut found = None;
        for j in part.a + 1..=part.b {
            self.steps += 1;
            self.states_and_accelerations(w, j);
            if self.sears {
                marks.clear();
                for p in self.points.iter_mut() {
                    marks.push(std::array::from_fn(|s| {
                        p.slabs[s].as_mut().filter(|x| x.is_live()).map(|x| {
                            let m = x.mark();
                            x.push(0.0);
                            m
                        })
                    }));
                }
            }
            let (q, v, acc) = (
                [&w.q[0][..], &w.q[1]],
                [&w.v[0][..], &w.v[1]],
                [&w.acc[0][..], &w.acc[1]],
            );
            // At the part's end, its check read every value the walk looks at.
            let at_end = j == part.b;
            let np = self.points.len();
            let mut onset = None;
            for &i in &open.points {
                let [c, cv, ca] = if at_end {
                    open.values[i]
                } else {
                    self.point_reading(&self.points[i], q, v, acc)
                };
                let [c0, cv0, _] = w.prev[i];
                w.prev[i] = [c, cv, ca];
                // Between grid points the closing motion is the cubic through their exact
                // states: a maximum inside a step is found there, and a new largest one is
                // refined on the exact motion (the gap that avoids contact is this maximum).
                let inside = hermite_max(c0, cv0, c, cv, g.h);
                if self.follow_closing {
                    let p = &mut self.points[i];
                    p.max_closing = p.max_closing.max(c);
                    // The cubic is good to (w h)^4 / 384 of the amplitude: near the running
                    // maximum the exact motion decides.
                    if inside > p.max_closing - 1e-6 * p.max_closing.abs() {
                        let (a, b) = ((j - 1) as f64 * g.h, j as f64 * g.h);
                        let exact = self.exact_max_closing(i, &w.y0, a, b);
                        let m = &mut self.points[i].max_closing;
                        *m = m.max(exact);
                    }
                }
                let p = &self.points[i];
                if contact == ContactModel::None || onset.is_some() || !open.onset[i] {
                    continue;
                }
                let elastic = if self.sears {
                    p.elastic_at(self.n + j)
                } else {
                    0.0
                };
                let delta = c - gap - elastic;
                let approaching = !needs_approach || cv > 0.0;
                let exchanged = p.exchanged_in == Some(self.n + j - 1);
                if !exchanged
                    && ((delta > 0.0 && approaching) || (!self.sears && inside > gap && cv0 > 0.0))
                {
                    onset = Some(i);
                }
            }
            if let Some(level) = onset {
                // The slabs go back to the grid point before: the contact starts from there.
                for (p, m) in self.points.iter_mut().zip(&marks) {
                    for (slab, mark) in p.slabs.iter_mut().zip(m) {
                        if let (Some(s), Some(m)) = (slab.as_mut(), mark) {
                            s.reset(*m);
                        }
                    }
                }
                found = Some(Free::Onset { j, level });
                break;
            }
            // The motion up to here is free: its peaks count.
            let t = t0 + j as f64 * g.h;
            for &i in &open.signals {
                let [u, r, a] = if at_end {
                    open.values[np + i]
                } else {
                    self.signal_reading(i, q, v, acc)
                };
                self.peaks.update(i, t, u, r);
                w.signal_acc[i] = a;
            }
            if self.sears {
                for p in self.points.iter_mut() {
                    for slab in p.slabs.iter_mut().flatten() {
                        slab.settle();
                    }
                }
            }
        }
        w.depths[d] = open;
        w.marks = marks;
        Ok(found)
    }

    /// The part's end becomes the last point looked at for what its parent left open and it
    /// cleared (what it did not clear, its halves or its walk took there).
    fn pass(&mut self, w: &mut Scratch, d: usize, part: Part, t0: f64) {
        let np = self.points.len();
        let t = t0 + part.b as f64 * self.grid.h;
        let (parents, rest) = w.depths.split_at(d);
        let parent = parents.last().unwrap_or(&w.root);
        let now = &rest[0];
        for &i in &parent.points {
            if !(now.onset[i] || now.closing[i]) {
                w.prev[i] = now.values[i];
            }
        }
        for &i in &parent.signals {
            if !now.peak[i] {
                let [u, r, a] = now.values[np + i];
                self.peaks.pass(i, t, u, r);
                w.signal_acc[i] = a;
            }
        }
    }

    /// The largest closing motion of point i over [a, b] after the start of a free stretch from
    /// `y0`, on the exact motion: where its rate falls through zero.
    pub(super) fn exact_max_closing(
        &self,
        i: usize,
        y0: &[Vec<[f64; 4]>; 2],
        a: f64,
        b: f64,
    ) -> f64 {
        let p = &self.points[i];
        let at = |s: f64| {
            let mut c = (0.0, 0.0);
            for (side, sign) in [(0, 1.0), (1, -1.0)] {
                let sd = &self.sides[side];
                for (k, y) in y0[side].iter().enumerate() {
                    let (q, v) = evaluate(sd.omega[k], sd.zeta[k], y, s);
                    c.0 += sign * p.r[side][k] * q;
                    c.1 += sign * p.r[side][k] * v;
                }
            }
            c
        };
        let (ca, va) = if a > 0.0 { at(a) } else { self.point_now_of(p) };
        let (cb, vb) = at(b);
        if va > 0.0 && vb < 0.0 {
            let s = bracket(|s| at(s).1, a, b, 1e-15 * b.max(1e-300)).mid();
            at(s).0.max(ca).max(cb)
        } else {
            ca.max(cb)
        }
    }

    /// A point's closing motion u_left - u_right and its rate, from modal states. Inlined where
    /// it is read: the compiler leaves it out of line where a tall side's sums take a branch of
    /// their own, and the call then weighs on every check of a free stretch.
    #[inline(always)]
    pub(super) fn point_state(&self, p: &Point, q: [&[f64]; 2], v: [&[f64]; 2]) -> (f64, f64) {
        (
            self.point_value(p, q),
            dotv(&p.r[0], v[0]) - dotv(&p.r[1], v[1]),
        )
    }

    /// What a point's closing motion must reach to be looked into for its largest value: a hair
    /// under the largest so far, or out of reach where the run does not follow it.
    fn closing_bar(&self, p: &Point) -> f64 {
        if self.follow_closing {
            p.max_closing - 1e-6 * p.max_closing.abs()
        } else {
            f64::INFINITY
        }
    }

    /// A point's closing motion, its rate and its acceleration from modal displacements,
    /// velocities and accelerations: [`Stepper::point_state`] and [`Stepper::point_value`] of
    /// `acc`, the same sums, a tall side's three in one pass over its modes.
    #[inline(always)]
    pub(super) fn point_reading(
        &self,
        p: &Point,
        q: [&[f64]; 2],
        v: [&[f64]; 2],
        acc: [&[f64]; 2],
    ) -> [f64; 3] {
        if !self.tall {
            // A few modes' sums as the point's own functions take them (inlined, unrolled).
            let (c, cv) = self.point_state(p, q, v);
            return [c, cv, self.point_value(p, acc)];
        }
        let side = |s: usize| {
            let r = &p.r[s][..];
            if r.len() >= lanes::LANES_FROM {
                lanes::dot3(r, q[s], v[s], acc[s])
            } else {
                [dotv(r, q[s]), dotv(r, v[s]), dotv(r, acc[s])]
            }
        };
        let (l, r) = (side(0), side(1));
        [l[0] - r[0], l[1] - r[1], l[2] - r[2]]
    }

    /// A point's closing (left less right) from modal values `q` alone: [`Stepper::point_state`]'s
    /// first part (its acceleration, from modal accelerations), without the rate's sums.
    #[inline(always)]
    pub(super) fn point_value(&self, p: &Point, q: [&[f64]; 2]) -> f64 {
        let n = [p.r[0].len().min(q[0].len()), p.r[1].len().min(q[1].len())];
        self.point_value_of(p, q, n)
    }

    /// [`Stepper::point_value`] over each side's first n modes (a caller that knows them lets
    /// the compiler unroll the sums).
    #[inline(always)]
    fn point_value_of(&self, p: &Point, q: [&[f64]; 2], n: [usize; 2]) -> f64 {
        dotv_of(&p.r[0], q[0], n[0]) - dotv_of(&p.r[1], q[1], n[1])
    }

    /// A point's closing motion now, without its rate ([`Stepper::point_state`]'s first part),
    /// each side's modes counted (`n`).
    #[inline(always)]
    pub(super) fn point_closing_of(&self, p: &Point, n: [usize; 2]) -> f64 {
        self.point_value_of(p, [&self.sides[0].q, &self.sides[1].q], n)
    }

    /// A free stretch of arbitrary length (back onto the grid after an event, or up to a
    /// located onset), exact, checked at its end. Returns a level where a contact starts by its
    /// end, if one does.
    pub(super) fn free_partial(&mut self, len: f64) -> Result<Option<usize>, SolveError> {
        self.count_step()?;
        self.newmark = false;
        let t0 = self.time();
        let y0 = [self.initial(0, t0), self.initial(1, t0)];
        let before: Vec<(f64, f64)> = self.points.iter().map(|p| self.point_now_of(p)).collect();
        let ends: [Vec<(f64, f64)>; 2] = std::array::from_fn(|s| {
            let side = &self.sides[s];
            (0..side.modes())
                .map(|k| propagator(side.omega[k], side.zeta[k], len).apply(&y0[s][k]))
                .collect()
        });
        let q: [Vec<f64>; 2] = std::array::from_fn(|s| ends[s].iter().map(|e| e.0).collect());
        let v: [Vec<f64>; 2] = std::array::from_fn(|s| ends[s].iter().map(|e| e.1).collect());
        let mut onset = None;
        for (i, &(c0, cv0)) in before.iter().enumerate() {
            let (c, cv) = self.point_state(&self.points[i], [&q[0], &q[1]], [&v[0], &v[1]]);
            let p = &mut self.points[i];
            if self.follow_closing {
                p.max_closing = p.max_closing.max(c).max(hermite_max(c0, cv0, c, cv, len));
            }
            if self.sc.contact == ContactModel::None || self.sears {
                continue;
            }
            let approaching = !matches!(
                self.sc.contact,
                ContactModel::Kelvin | ContactModel::HertzDamp
            ) || cv > 0.0;
            let inside = hermite_max(c0, cv0, c, cv, len) > self.sc.gap_m && cv0 > 0.0;
            // Leaving a contact just released, the closing motion starts at the gap: only a
            // new approach counts; and one exchange per level per step.
            let fresh = (c0 < self.sc.gap_m || cv0 > 0.0) && p.exchanged_in != Some(self.n);
            if onset.is_none() && fresh && ((c > self.sc.gap_m && approaching) || inside) {
                onset = Some(i);
            }
        }
        if onset.is_some() {
            return Ok(onset);
        }
        self.commit_free([&y0[0], &y0[1]], [&q[0], &q[1]], [&v[0], &v[1]], len);
        self.advance(len);
        self.track_peaks_now();
        if self.offset == 0.0 {
            self.record_free();
        }
        Ok(None)
    }

    pub(super) fn advance(&mut self, len: f64) {
        // One whole fine step from the grid (the contact steps): what the general case below
        // gives, without its division.
        if self.offset == 0.0 && len == self.grid.h {
            // Whole numbers below 2^53 count exactly as floats.
            self.n += 1;
            self.n_f += 1.0;
            return;
        }
        let t = self.offset + len;
        // t >= 0: truncation is the floor, without a call to one.
        let whole = ((t / self.grid.h + 1e-9) as usize) as f64;
        self.at_step(self.n + whole as usize);
        self.offset = t - whole * self.grid.h;
        if self.offset < 1e-9 * self.grid.h {
            self.offset = 0.0;
        }
    }
}
