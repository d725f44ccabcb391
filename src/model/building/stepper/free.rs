//! The free step: the exact motion between contacts, checked for an onset at every grid point.

use super::*;

impl Stepper<'_> {
    /// The augmented initial states y0 = [q, q', g, g'] of every mode of a side.
    pub(super) fn initial(&self, s: usize, t: f64) -> Vec<[f64; 4]> {
        let (a0, slope) = self.ground(t);
        let side = &self.sides[s];
        (0..side.modes())
            .map(|k| {
                [
                    side.q[k],
                    side.v[k],
                    -side.gamma[k] * a0,
                    -side.gamma[k] * slope,
                ]
            })
            .collect()
    }

    /// Writes a free stretch of length `len` from `y0` to the ledger and moves the state there:
    /// the exact integrals of the ground's power and of the damping.
    pub(super) fn commit_free(&mut self, y0: [&[[f64; 4]]; 2], ends: [&[(f64, f64)]; 2], len: f64) {
        self.newmark = false;
        // A whole number of fine steps reuses its integrals; another length (up to an event
        // inside a step) needs its own.
        let steps = len / self.grid.h;
        let whole = steps.round();
        let j = ((steps - whole).abs() <= 1e-9 * steps.max(1.0))
            .then_some(whole as usize)
            .filter(|j| (1..=self.grid.per_free_step).contains(j));
        for s in 0..2 {
            let side = &mut self.sides[s];
            if let Some(j) = j
                && j < self.grid.per_free_step
                && side.part[j].is_none()
            {
                let l = j as f64 * self.grid.h;
                side.part[j] = Some(
                    (0..side.modes())
                        .map(|k| step_integrals(side.omega[k], side.zeta[k], l))
                        .collect(),
                );
            }
            for k in 0..side.modes() {
                let ints = match j {
                    Some(j) if j == self.grid.per_free_step => side.full[k],
                    Some(j) => side.part[j].as_ref().expect("just made")[k],
                    None => step_integrals(side.omega[k], side.zeta[k], len),
                };
                let y = &y0[s][k];
                let (q1, v1) = ends[s][k];
                let dq = q1 - y[0];
                let int_q: f64 = (0..4).map(|j| ints.int_q[j] * y[j]).sum();
                let int_s_v = len * q1 - int_q;
                self.ledger.input_j += y[2] * dq + y[3] * int_s_v;
                self.ledger.damping_j +=
                    2.0 * side.zeta[k] * side.omega[k] * ints.velocity_squared(y);
                side.q[k] = q1;
                side.v[k] = v1;
            }
        }
    }

    /// One free stretch from a grid point to the next sample of the record (or the longest free
    /// step), checked at every grid point.
    pub(super) fn free_step(&mut self) -> Result<Free, SolveError> {
        self.newmark = false;
        let g = self.grid;
        // To the next free-step boundary (record samples are boundaries too).
        let len = (g.per_free_step - self.n % g.per_free_step).min(g.total - self.n);
        self.steps += len - 1;
        self.count_step()?;
        let t0 = self.time();
        let y0 = [self.initial(0, t0), self.initial(1, t0)];
        let mut w = std::mem::take(&mut self.scratch);
        w.marks.clear();
        w.marks.extend(
            self.points
                .iter()
                .map(|p| std::array::from_fn(|i| p.slabs[i].as_ref().map(|s| s.mark()))),
        );
        w.prev.clear();
        for p in &self.points {
            w.prev.push(self.point_now_of(p));
        }
        for s in 0..2 {
            w.q[s].resize(self.sides[s].modes(), 0.0);
            w.v[s].resize(self.sides[s].modes(), 0.0);
        }
        let contact = self.sc.contact;
        let gap = self.sc.gap_m;
        let needs_approach = matches!(contact, ContactModel::Kelvin | ContactModel::HertzDamp);
        let mut onset = None;
        for j in 1..=len {
            for (s, y) in y0.iter().enumerate() {
                for (k, p) in self.sides[s].sub[j - 1].iter().enumerate() {
                    let (q, v) = p.apply(&y[k]);
                    w.q[s][k] = q;
                    w.v[s][k] = v;
                }
            }
            for i in 0..self.points.len() {
                if self.sears {
                    for slab in self.points[i].slabs.iter_mut().flatten() {
                        slab.push(0.0);
                    }
                }
                let p = &mut self.points[i];
                let c = dotv(&p.r[0], &w.q[0]) - dotv(&p.r[1], &w.q[1]);
                let cv = dotv(&p.r[0], &w.v[0]) - dotv(&p.r[1], &w.v[1]);
                let (c0, cv0) = w.prev[i];
                w.prev[i] = (c, cv);
                // Between grid points the closing motion is the cubic through their exact
                // states: a maximum inside a step is found there, and a new largest one is
                // refined on the exact motion (the gap that avoids contact is this maximum).
                let inside = hermite_max(c0, cv0, c, cv, g.h);
                p.max_closing = p.max_closing.max(c);
                // The cubic is good to (w h)^4 / 384 of the amplitude: near the running maximum
                // the exact motion decides.
                if inside > p.max_closing - 1e-6 * p.max_closing.abs() {
                    let (a, b) = ((j - 1) as f64 * g.h, j as f64 * g.h);
                    let exact = self.exact_max_closing(i, &y0, a, b);
                    let m = &mut self.points[i].max_closing;
                    *m = m.max(exact);
                }
                let p = &mut self.points[i];
                if contact == ContactModel::None || onset.is_some() {
                    continue;
                }
                let delta = c - gap - p.elastic();
                let approaching = !needs_approach || cv > 0.0;
                let exchanged = p.exchanged_in == Some(self.n + j - 1);
                if !exchanged
                    && ((delta > 0.0 && approaching) || (!self.sears && inside > gap && cv0 > 0.0))
                {
                    onset = Some(i);
                }
            }
            if let Some(level) = onset {
                // Back to the start of the stretch: the caller redoes it up to the onset.
                for (p, m) in self.points.iter_mut().zip(&w.marks) {
                    for (slab, mark) in p.slabs.iter_mut().zip(m) {
                        if let (Some(s), Some(m)) = (slab.as_mut(), mark) {
                            s.reset(*m);
                        }
                    }
                }
                self.scratch = w;
                return Ok(Free::Onset { j, level });
            }
            // The motion up to here is free: its peaks count.
            let mut now = std::mem::take(&mut w.signals);
            self.signals([&w.q[0], &w.q[1]], [&w.v[0], &w.v[1]], &mut now);
            self.peaks.update(t0 + j as f64 * g.h, &now);
            w.signals = now;
        }
        let ends: [Vec<(f64, f64)>; 2] =
            std::array::from_fn(|s| w.q[s].iter().zip(&w.v[s]).map(|(q, v)| (*q, *v)).collect());
        self.scratch = w;
        self.commit_free([&y0[0], &y0[1]], [&ends[0], &ends[1]], len as f64 * g.h);
        self.n += len;
        self.record();
        Ok(Free::Done)
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
                    let (q, v) = propagator(sd.omega[k], sd.zeta[k], s).apply(y);
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

    /// A point's closing motion u_left - u_right and its rate, from modal states.
    pub(super) fn point_state(&self, p: &Point, q: [&[f64]; 2], v: [&[f64]; 2]) -> (f64, f64) {
        (
            dotv(&p.r[0], q[0]) - dotv(&p.r[1], q[1]),
            dotv(&p.r[0], v[0]) - dotv(&p.r[1], v[1]),
        )
    }

    /// A free stretch of arbitrary length (back onto the grid after an event, or up to a
    /// located onset), exact, checked at its end. Returns a level where a contact starts by its
    /// end, if one does.
    pub(super) fn free_partial(&mut self, len: f64) -> Result<Option<usize>, SolveError> {
        self.count_step()?;
        self.newmark = false;
        let t0 = self.time();
        let y0 = [self.initial(0, t0), self.initial(1, t0)];
        let before: Vec<(f64, f64)> = self
            .points
            .iter()
            .map(|p| {
                self.point_state(
                    p,
                    [&self.sides[0].q, &self.sides[1].q],
                    [&self.sides[0].v, &self.sides[1].v],
                )
            })
            .collect();
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
            p.max_closing = p.max_closing.max(c).max(hermite_max(c0, cv0, c, cv, len));
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
        self.commit_free([&y0[0], &y0[1]], [&ends[0], &ends[1]], len);
        self.advance(len);
        if self.offset == 0.0 {
            self.record();
        } else {
            let t = self.time();
            let (q0, q1) = (self.sides[0].q.clone(), self.sides[1].q.clone());
            let (v0, v1) = (self.sides[0].v.clone(), self.sides[1].v.clone());
            self.track_peaks(t, [&q0, &q1], [&v0, &v1]);
        }
        Ok(None)
    }

    pub(super) fn advance(&mut self, len: f64) {
        let t = self.offset + len;
        let whole = (t / self.grid.h + 1e-9).floor();
        self.n += whole as usize;
        self.offset = t - whole * self.grid.h;
        if self.offset < 1e-9 * self.grid.h {
            self.offset = 0.0;
        }
    }
}
