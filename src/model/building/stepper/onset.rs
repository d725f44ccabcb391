//! Onset location: the touching instant inside its step, and the start of a contact there.

use super::*;

impl Stepper<'_> {
    /// A contact starts at `level` inside the j-th fine step of the free stretch that began at
    /// the current time: move there exactly (the slabs already stand at the grid point before
    /// it), then into contact.
    pub(super) fn onset(&mut self, j: usize, level: usize) -> Result<(), SolveError> {
        let g = self.grid;
        let t0 = self.time();
        if j > 1 {
            // Exactly to the grid point before.
            let y0 = [self.initial(0, t0), self.initial(1, t0)];
            let mut q = [0, 1].map(|s| vec![0.0; self.sides[s].modes()]);
            let mut v = q.clone();
            self.states_at(&y0, j - 1, &mut q, &mut v);
            self.commit_free(
                [&y0[0], &y0[1]],
                [&q[0], &q[1]],
                [&v[0], &v[1]],
                (j - 1) as f64 * g.h,
            );
            self.at_step(self.n + j - 1);
            // Every signal's peak up to here (those a check cleared were not walked).
            self.track_peaks_now();
            self.record_now();
        }
        self.onset_in_partial(level, g.h)
    }

    /// A contact starts at `level` within the next `len` of time from now.
    pub(super) fn onset_in_partial(&mut self, level: usize, len: f64) -> Result<(), SolveError> {
        if self.sears {
            // The slabs' waves are known on the grid only: the contact starts from this grid
            // point, its first step implicit from zero force; its start is interpolated.
            let n = self.n;
            let (c0, w) = self.point_now(level);
            let p = &mut self.points[level];
            for slab in p.slabs.iter_mut().flatten() {
                slab.revive(n);
            }
            p.delta = c0 - self.sc.gap_m - p.elastic_at(n);
            p.rate = 0.0;
            p.v0 = w;
            return self.contact_step();
        }
        // Where the closing motion reaches the gap, on the cubic through the exact states at
        // both ends (exact to round-off over a fine step).
        let t0 = self.time();
        let y0 = [self.initial(0, t0), self.initial(1, t0)];
        let (c0, v0) = self.point_now(level);
        let end: [Vec<(f64, f64)>; 2] = std::array::from_fn(|s| {
            let side = &self.sides[s];
            (0..side.modes())
                .map(|k| propagator(side.omega[k], side.zeta[k], len).apply(&y0[s][k]))
                .collect()
        });
        let q1: [Vec<f64>; 2] = std::array::from_fn(|s| end[s].iter().map(|e| e.0).collect());
        let v1: [Vec<f64>; 2] = std::array::from_fn(|s| end[s].iter().map(|e| e.1).collect());
        let (c1, cv1) = self.point_state(&self.points[level], [&q1[0], &q1[1]], [&v1[0], &v1[1]]);
        let gap = self.sc.gap_m;
        let cubic = |x: f64| hermite(c0, v0, c1, cv1, len, x) - gap;
        // The first crossing: up to the cubic's maximum where the end itself is still open.
        let upper = if cubic(len) > 0.0 {
            len
        } else {
            hermite_argmax(c0, v0, c1, cv1, len).unwrap_or(len)
        };
        let s_on = if c0 - gap >= 0.0 {
            0.0
        } else {
            bracket(cubic, 0.0, upper, 1e-14 * len).second_side
        };
        if s_on > 0.0 {
            let ends: [Vec<(f64, f64)>; 2] = std::array::from_fn(|s| {
                let side = &self.sides[s];
                (0..side.modes())
                    .map(|k| propagator(side.omega[k], side.zeta[k], s_on).apply(&y0[s][k]))
                    .collect()
            });
            let q: [Vec<f64>; 2] = std::array::from_fn(|s| ends[s].iter().map(|e| e.0).collect());
            let v: [Vec<f64>; 2] = std::array::from_fn(|s| ends[s].iter().map(|e| e.1).collect());
            self.commit_free([&y0[0], &y0[1]], [&q[0], &q[1]], [&v[0], &v[1]], s_on);
            self.advance(s_on);
        }
        let (c, w) = self.point_now(level);
        let t_on = self.time();
        if self.sc.contact == ContactModel::Stereo {
            // Floors already overlapping (after a cut sequence of exchanges) and not yet
            // approaching: nothing to exchange in this step.
            self.exchange(level, w, t_on);
            self.points[level].exchanged_in = Some(self.n);
            self.track_peaks_now();
            self.record_now();
            return Ok(());
        }
        let p = &mut self.points[level];
        p.delta = (c - gap).min(0.0);
        p.rate = w;
        p.v0 = w;
        // A Kelvin-Voigt link pushes with c delta' from the first instant.
        p.force = p.element.push(0.0, w, w).max(0.0);
        if p.force > 0.0 {
            p.open = Some(self.contacts.len());
            p.max_force = p.max_force.max(p.force);
            self.contacts.push(RawContact {
                level,
                start_s: t_on,
                end_s: t_on,
                peak_force_n: p.force,
                impulse_ns: 0.0,
                approach_velocity_m_s: w,
            });
        }
        self.track_peaks_now();
        self.record_now();
        // The force rises from the onset as a power of the time since it (t^1 linear, t^1.5
        // Hertz, t^0.25 for Jankowski's dashpot): steps graded towards the onset keep the
        // method's order where uniform ones would lose it.
        let mut rest = self.grid.h - self.offset;
        if rest < self.grid.h / 16.0 {
            // An onset at the end of a step: grade over the next step too, rather than take
            // steps far shorter than the contact's own scale.
            rest += self.grid.h;
        }
        let mut len = rest / (1u64 << ONSET_GRADING) as f64;
        self.contact_step_of(len)?;
        for _ in 0..ONSET_GRADING {
            if !self.points.iter().any(|p| p.force > 0.0) {
                break;
            }
            self.contact_step_of(len)?;
            len *= 2.0;
        }
        Ok(())
    }

    /// Whether the element's link takes hold only of approaching floors (a damped link that let
    /// go with them still overlapping).
    pub(super) fn needs_approach(&self) -> bool {
        matches!(
            self.sc.contact,
            ContactModel::Kelvin | ContactModel::HertzDamp
        )
    }

    /// The closing motion and its rate at a level now.
    pub(super) fn point_now(&self, level: usize) -> (f64, f64) {
        self.point_state(
            &self.points[level],
            [&self.sides[0].q, &self.sides[1].q],
            [&self.sides[0].v, &self.sides[1].v],
        )
    }

    /// Stereomechanics: the relative velocity at the point reverses with restitution e, at once.
    pub(super) fn exchange(&mut self, level: usize, w: f64, t: f64) {
        if w <= 0.0 {
            return;
        }
        self.points[level].exchanged_in = Some(self.n);
        let energy = self.sides[0].energy() + self.sides[1].energy();
        let p = &self.points[level];
        let inverse_mass: f64 = p.r.iter().flatten().map(|x| x * x).sum();
        let impulse = (1.0 + self.sc.restitution) * w / inverse_mass;
        for (s, sign) in [(0, -1.0), (1, 1.0)] {
            for k in 0..self.sides[s].modes() {
                self.sides[s].v[k] += sign * p.r[s][k] * impulse;
            }
        }
        self.ledger.exchanged_j += energy - (self.sides[0].energy() + self.sides[1].energy());
        // The storeys' drift rates jumped with the floors' velocities.
        for side in self.sides.iter_mut() {
            if let Some(st) = side.storeys.as_mut() {
                st.set_rates(&side.v);
            }
        }
        self.contacts.push(RawContact {
            level,
            start_s: t,
            end_s: t,
            peak_force_n: 0.0,
            impulse_ns: impulse,
            approach_velocity_m_s: w,
        });
    }
}
