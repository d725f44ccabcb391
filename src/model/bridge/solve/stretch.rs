//! The free stretch: between contacts no joint force acts, every frame moves exactly (each
//! mode's forcing is linear in time between two kinks of its ground's record) and every girder
//! rings in closed form, so the run jumps from grid point to grid point without stepping.
//!
//! What a walk of every grid point would find is found all the same, at the same grid points:
//! the stretch is checked at a few points (every recorded sample, at most `check` grid steps
//! apart), and between two of them every signal is within a proven margin of the cubic through
//! its values and rates there (`model::bound`: the frames' fourth derivatives are bounded, the
//! grounds are cubics between the record's samples, the girders' waves are within their
//! envelopes). Only a part where that margin leaves a joint able to close its gap, to pass its
//! largest closing or opening or its seat, or a frame able to pass a peak, is walked grid point
//! by grid point, and only for those signals; an onset there ends the stretch at the grid point
//! before it, where the stepped run takes over.

use super::*;
use crate::model::bound::{cubic_bound, cubic_margin, cubic_max, mode_bounds};
use crate::model::building::modal::{StepIntegrals, doublings, integrals_over, step_powers};

/// The longest stretch, in grid steps: each frame's exact maps over 1 to this many steps are
/// tabulated once a run.
const MAX_STRETCH: usize = 2048;

/// What the rounding of the states at two points can move a cubic's maximum by, relative to the
/// size of its ends and slopes (as the buildings' free stretches allow).
const ROUNDING: f64 = 1e-12;

/// A check spans at most this many radians of the fastest frame mode: the cubic between two
/// checks is then within (w l)^4 / 128 = 5e-4 of the amplitude.
const CHECK_RADIANS: f64 = 0.5;

/// One frame's exact maps over 1..=count grid steps, and the ledger's integrals over a number
/// of steps (joined from doublings, kept once made).
pub(super) struct FrameSteps {
    powers: [Vec<Propagator>; 2],
    doublings: [Vec<(StepIntegrals, [[f64; 4]; 4])>; 2],
    integrals: Vec<Option<[StepIntegrals; 2]>>,
}

impl FrameSteps {
    fn new(f: &Frame, h: f64, count: usize) -> Self {
        FrameSteps {
            powers: [0, 1].map(|k| step_powers(f.omega[k], f.zeta[k], h, count)),
            doublings: [0, 1].map(|k| doublings(f.omega[k], f.zeta[k], h, count)),
            integrals: vec![None; count + 1],
        }
    }

    /// Both modes' (q, q') `j` grid steps on from the augmented states `y0`.
    #[inline]
    fn state(&self, y0: &[[f64; 4]; 2], j: usize) -> [(f64, f64); 2] {
        [
            self.powers[0][j - 1].apply(&y0[0]),
            self.powers[1][j - 1].apply(&y0[1]),
        ]
    }

    fn integrals(&mut self, steps: usize) -> [StepIntegrals; 2] {
        *self.integrals[steps]
            .get_or_insert_with(|| [0, 1].map(|k| integrals_over(&self.doublings[k], steps)))
    }
}

/// What a stretch writes outside the run: the histories and the frames' peaks, and which grid
/// points are recorded.
pub(super) struct Sink<'s> {
    pub hist: &'s mut Histories,
    pub peaks: &'s mut Peaks,
    pub stride: usize,
    pub steps: usize,
}

impl Sink<'_> {
    fn records(&self, n: usize) -> bool {
        n.is_multiple_of(self.stride) || n == self.steps
    }
}

/// A frame's three peaked signals, as combinations of its modes: girder, pier, bearing.
fn signal_shapes(f: &Frame) -> [[f64; 2]; 3] {
    [
        f.girder,
        f.pier,
        [f.girder[0] - f.pier[0], f.girder[1] - f.pier[1]],
    ]
}

/// The stretch's buffers, kept for the run.
#[derive(Default)]
pub(super) struct Scratch {
    /// Each frame's modes' augmented starting states [q, q', g, g'].
    y0: Vec<[[f64; 4]; 2]>,
    /// The ground acceleration at each frame's support at the stretch's start and end.
    accel: Vec<(f64, f64)>,
    /// Bounds on each joint's smooth closing's fourth derivative and on its girders' waves.
    joint_m4: Vec<f64>,
    joint_env: Vec<f64>,
    /// Bounds on each frame signal's fourth derivative, and whether it can reach its peak at
    /// all in the stretch.
    signal_m4: Vec<[f64; 3]>,
    signal_open: Vec<[bool; 3]>,
    /// Each frame's modal (q, q') at the last check and at the one being made.
    modes_a: Vec<[(f64, f64); 2]>,
    modes_b: Vec<[(f64, f64); 2]>,
    /// The ground at every support at the check being made (the first of each delay read).
    ground: Vec<GroundState>,
    /// Each joint's closing without the waves, and its rate, at the last check and this one.
    joint_a: Vec<[f64; 2]>,
    joint_b: Vec<[f64; 2]>,
    /// Each frame signal's value and rate at the last check and this one.
    signal_a: Vec<[[f64; 2]; 3]>,
    signal_b: Vec<[[f64; 2]; 3]>,
    /// What a part must be walked for: per joint, per frame signal.
    joint_look: Vec<bool>,
    signal_look: Vec<[bool; 3]>,
    /// Each girder's end waves at the grid point walked, where read.
    waves: Vec<Option<[f64; 2]>>,
    /// Each joint's closing at the grid point walked, where read.
    closings: Vec<f64>,
    /// The frames a walk reads, and its own modes and ground.
    frame_read: Vec<bool>,
    modes_walk: Vec<[(f64, f64); 2]>,
    ground_walk: Vec<GroundState>,
}

impl<'a> Run<'a> {
    /// The frames' exact maps, for stretches of up to `count` steps.
    pub(super) fn tabulate_stretches(&mut self, steps: usize) {
        let dt = self.ground.corrected.dt_s;
        let per_sample = if dt > 0.0 {
            (dt / self.h).ceil() as usize + 1
        } else {
            1
        };
        let count = per_sample.min(MAX_STRETCH).min(steps).max(1);
        self.stretch_steps = self
            .frames
            .iter()
            .map(|f| FrameSteps::new(f, self.h, count))
            .collect();
        let w_max = self.frames.iter().flat_map(|f| f.omega).fold(0.0, f64::max);
        self.check = ((CHECK_RADIANS / (w_max * self.h)) as usize).clamp(1, count);
    }

    /// Takes a free stretch from grid point `n0` if one can start there (no joint force acts):
    /// as far as the next kink of any support's record, the longest stretch, the run's end, or
    /// the grid point before an onset. Returns the grid steps it took (0: the next step is a
    /// stepped one).
    pub(super) fn free_stretch(&mut self, n0: usize, sink: &mut Sink) -> usize {
        if self.stretch_steps.is_empty() || self.joints.iter().any(|js| js.force != 0.0) {
            return 0;
        }
        let len = self.stretch_length(n0, sink.steps);
        if len == 0 {
            return 0;
        }
        self.settle_if_free();
        let mut w = std::mem::take(&mut self.stretch_scratch);
        self.prepare(&mut w, n0, len, sink);
        let mut a = 0;
        let mut reached = len;
        while a < len {
            let next_record = (n0 + a) / sink.stride * sink.stride + sink.stride;
            let b = (a + self.check).min(len).min(next_record - n0);
            if let Some(m) = self.check_part(&mut w, n0, a, b, sink) {
                reached = m - 1;
                break;
            }
            if sink.records(n0 + b) {
                self.record_at(&mut w, n0, b, sink);
            }
            std::mem::swap(&mut w.modes_a, &mut w.modes_b);
            std::mem::swap(&mut w.joint_a, &mut w.joint_b);
            std::mem::swap(&mut w.signal_a, &mut w.signal_b);
            a = b;
        }
        if reached > 0 {
            self.commit_stretch(&mut w, n0, reached, len);
            sink.peaks.read(&self.frames);
        }
        self.stretch_scratch = w;
        reached
    }

    /// Lets every girder fall quiet where no joint force acts (as a stretch does before it
    /// starts).
    pub(super) fn settle_if_free(&mut self) {
        if self.joints.iter().all(|js| js.force == 0.0) {
            for g in self.girders.iter_mut().flatten() {
                g.settle();
            }
        }
    }

    /// Grid steps from `n0` to the first grid point at or before the next kink of any
    /// support's ground (a record sample, the wave's arrival or the record's end), within the
    /// longest stretch and the run.
    fn stretch_length(&self, n0: usize, steps: usize) -> usize {
        let h = self.h;
        let t0 = n0 as f64 * h;
        let eps = 1e-9 * h;
        let dt = self.ground.corrected.dt_s;
        let last = (self.ground.corrected.accel_m_s2.len() as f64 - 1.0).max(0.0);
        let mut len = (steps - n0).min(self.stretch_steps[0].powers[0].len());
        for (s, &d) in self.support_delay.iter().enumerate() {
            if self.same_ground[s] != s {
                continue;
            }
            let u = (t0 + eps - d) / dt;
            // The first sample strictly after t0 (within round-off), or the wave's arrival.
            let m = if u < 0.0 { 0.0 } else { u.floor() + 1.0 };
            if m > last {
                continue;
            }
            let to = ((d + m * dt - t0 + eps) / h).floor();
            len = len.min(to.max(0.0) as usize);
        }
        len
    }

    /// The stretch's starting states, its bounds and its first check's values.
    fn prepare(&mut self, w: &mut Scratch, n0: usize, len: usize, sink: &Sink) {
        let h = self.h;
        let (t0, t1) = (n0 as f64 * h, (n0 + len) as f64 * h);
        let span = len as f64 * h;
        let nf = self.frames.len();
        w.y0.clear();
        w.accel.clear();
        w.signal_m4.clear();
        w.signal_open.clear();
        let mut mode_m4 = Vec::with_capacity(nf);
        for (i, f) in self.frames.iter().enumerate() {
            let delay = self.support_delay[i + 1];
            let a0 = self.ground.accel_after(t0, delay);
            let a1 = self.ground.accel_before(t1, delay);
            w.accel.push((a0, a1));
            let slope = (a1 - a0) / span;
            let y: [[f64; 4]; 2] =
                std::array::from_fn(|k| [f.q[k], f.v[k], -f.gamma[k] * a0, -f.gamma[k] * slope]);
            let bounds = [0, 1].map(|k| mode_bounds(f.omega[k], f.zeta[k], &y[k], span));
            w.y0.push(y);
            mode_m4.push([bounds[0][1], bounds[1][1]]);
            let peaks = [
                sink.peaks.girder[i],
                sink.peaks.pier[i],
                sink.peaks.bearing[i],
            ];
            let shapes = signal_shapes(f);
            w.signal_m4
                .push(shapes.map(|c| c[0].abs() * bounds[0][1] + c[1].abs() * bounds[1][1]));
            // A signal whose modes' amplitudes cannot reach its peak anywhere in the stretch is
            // left alone for all of it.
            w.signal_open.push(std::array::from_fn(|s| {
                let c = shapes[s];
                let size = c[0].abs() * bounds[0][0] + c[1].abs() * bounds[1][0];
                size * (1.0 + ROUNDING) >= peaks[s]
            }));
        }
        w.joint_m4.clear();
        w.joint_env.clear();
        for js in &self.joints {
            let (mut m4, mut env) = (0.0, 0.0);
            for side in &js.sides {
                if let Some((i, end)) = side.girder {
                    let f = &self.frames[i];
                    m4 += f.girder[0].abs() * mode_m4[i][0] + f.girder[1].abs() * mode_m4[i][1];
                    if let Some(g) = &self.girders[i] {
                        env += g.envelope_from(n0 + 1)[end];
                    }
                }
            }
            w.joint_m4.push(m4);
            w.joint_env.push(env);
        }
        w.waves.clear();
        w.waves.resize(self.girders.len(), None);
        w.joint_look.resize(self.joints.len(), false);
        w.closings.resize(self.joints.len(), 0.0);
        w.signal_look.resize(nf, [false; 3]);
        // The first check's values: the state now.
        w.modes_a.clear();
        w.modes_a.extend(
            self.frames
                .iter()
                .map(|f| [(f.q[0], f.v[0]), (f.q[1], f.v[1])]),
        );
        w.modes_b.clone_from(&w.modes_a);
        self.ground_into(t0, &mut w.ground);
        self.smooth_values(w);
        std::mem::swap(&mut w.joint_a, &mut w.joint_b);
        std::mem::swap(&mut w.signal_a, &mut w.signal_b);
    }

    /// The ground at every support at t, read once per delay.
    fn ground_into(&self, t: f64, out: &mut Vec<GroundState>) {
        out.clear();
        for (s, &d) in self.support_delay.iter().enumerate() {
            let g = if self.same_ground[s] == s {
                self.ground.at(t, d)
            } else {
                out[self.same_ground[s]]
            };
            out.push(g);
        }
    }

    /// Every frame's modes j grid steps into the stretch, into `w.modes_b`.
    fn modes_at(&self, w: &mut Scratch, j: usize) {
        for (i, steps) in self.stretch_steps.iter().enumerate() {
            w.modes_b[i] = steps.state(&w.y0[i], j);
        }
    }

    /// Each joint's closing without the girders' waves and each frame signal, with their rates,
    /// from `w.modes_b` and `w.ground`, into `w.joint_b` and `w.signal_b`.
    fn smooth_values(&self, w: &mut Scratch) {
        w.joint_b.clear();
        for js in &self.joints {
            let mut out = [0.0; 2];
            for (side, sign) in js.sides.iter().zip([1.0, -1.0]) {
                let g = &w.ground[side.support];
                let (mut u, mut v) = (g.displacement, g.velocity);
                if let Some((i, _)) = side.girder {
                    let (f, m) = (&self.frames[i], &w.modes_b[i]);
                    u += f.girder[0] * m[0].0 + f.girder[1] * m[1].0;
                    v += f.girder[0] * m[0].1 + f.girder[1] * m[1].1;
                }
                out[0] += sign * u;
                out[1] += sign * v;
            }
            w.joint_b.push(out);
        }
        w.signal_b.clear();
        for (f, m) in self.frames.iter().zip(&w.modes_b) {
            w.signal_b.push(
                signal_shapes(f)
                    .map(|c| [c[0] * m[0].0 + c[1] * m[1].0, c[0] * m[0].1 + c[1] * m[1].1]),
            );
        }
    }

    /// Checks the part from grid step a to b of the stretch from `n0`, walking what its bounds
    /// cannot clear. Returns the grid step of an onset found in it.
    fn check_part(
        &mut self,
        w: &mut Scratch,
        n0: usize,
        a: usize,
        b: usize,
        sink: &mut Sink,
    ) -> Option<usize> {
        let h = self.h;
        let l = (b - a) as f64 * h;
        self.modes_at(w, b);
        self.ground_into((n0 + b) as f64 * h, &mut w.ground);
        self.smooth_values(w);
        let contact = self.sc.contact != ContactModel::None;
        let seat = self.sc.seat_length_m;
        let mut any = false;
        for (j, js) in self.joints.iter().enumerate() {
            let ([c0, r0], [c1, r1]) = (w.joint_a[j], w.joint_b[j]);
            let margin = cubic_margin(w.joint_m4[j], l)
                + ROUNDING * (c0.abs() + c1.abs() + l * (r0.abs() + r1.abs()))
                + w.joint_env[j];
            let gap = js.joint.gap_m;
            let quick_hi = cubic_bound(c0, r0, c1, r1, l) + margin;
            let quick_lo = -cubic_bound(-c0, -r0, -c1, -r1, l) - margin;
            let clear = |hi: f64, lo: f64| {
                !(contact && hi >= gap)
                    && hi < js.max_closing
                    && -lo < js.max_opening
                    && (js.unseated.is_some() || -lo <= seat)
            };
            let look = !clear(quick_hi, quick_lo) && {
                let hi = cubic_max(c0, r0, c1, r1, l) + margin;
                let lo = -cubic_max(-c0, -r0, -c1, -r1, l) - margin;
                !clear(hi, lo)
            };
            w.joint_look[j] = look;
            any |= look;
        }
        for i in 0..self.frames.len() {
            let peaks = [
                sink.peaks.girder[i],
                sink.peaks.pier[i],
                sink.peaks.bearing[i],
            ];
            for (s, &peak) in peaks.iter().enumerate() {
                let look = w.signal_open[i][s] && {
                    let ([u0, r0], [u1, r1]) = (w.signal_a[i][s], w.signal_b[i][s]);
                    let margin = cubic_margin(w.signal_m4[i][s], l)
                        + ROUNDING * (u0.abs() + u1.abs() + l * (r0.abs() + r1.abs()));
                    cubic_bound(u0.abs(), r0.abs(), u1.abs(), r1.abs(), l) + margin >= peak
                        && cubic_max(u0, r0, u1, r1, l).max(cubic_max(-u0, -r0, -u1, -r1, l))
                            + margin
                            >= peak
                };
                w.signal_look[i][s] = look;
                any |= look;
            }
        }
        if any {
            self.walk(w, n0, a, b, sink)
        } else {
            None
        }
    }

    /// Walks grid steps a + 1 ..= b of the stretch for the joints and frame signals its check
    /// could not clear, as stepping would read them: an onset ends the walk (returned), else
    /// every largest closing and opening, seat and peak is brought up to date. Leaves the
    /// modes and ground at b in `w` as the check found them.
    fn walk(
        &mut self,
        w: &mut Scratch,
        n0: usize,
        a: usize,
        b: usize,
        sink: &mut Sink,
    ) -> Option<usize> {
        let h = self.h;
        let contact = self.sc.contact != ContactModel::None;
        let seat = self.sc.seat_length_m;
        // The frames the walk reads: those of the joints looked at and those with a signal
        // looked at; the ground only for the joints.
        w.frame_read.clear();
        w.frame_read
            .extend(w.signal_look.iter().map(|l| l[0] || l[1] || l[2]));
        for (js, &look) in self.joints.iter().zip(&w.joint_look) {
            for side in js.sides.iter().filter(|_| look) {
                if let Some((i, _)) = side.girder {
                    w.frame_read[i] = true;
                }
            }
        }
        let any_joint = w.joint_look.iter().any(|&x| x);
        let mut modes = std::mem::take(&mut w.modes_walk);
        modes.clone_from(&w.modes_b);
        let mut ground = std::mem::take(&mut w.ground_walk);
        let mut found = None;
        for m in a + 1..=b {
            let t = (n0 + m) as f64 * h;
            for (i, steps) in self.stretch_steps.iter().enumerate() {
                if w.frame_read[i] {
                    modes[i] = steps.state(&w.y0[i], m);
                }
            }
            if any_joint {
                self.ground_into(t, &mut ground);
            }
            w.waves.iter_mut().for_each(|x| *x = None);
            // Every joint looked at, its closing at m: without its girders' waves first, and
            // with them only where their envelope leaves it able to close its gap or pass a
            // largest value. An onset at any of them leaves m to the stepped run (its readings
            // there are after the forces).
            let mut onset = false;
            for j in 0..self.joints.len() {
                w.closings[j] = f64::NAN;
                if !w.joint_look[j] {
                    continue;
                }
                let js = &self.joints[j];
                let smooth = self.smooth_closing(j, &modes, &ground);
                let env = w.joint_env[j];
                let (hi, lo) = (smooth + env, smooth - env);
                let reach = (contact && hi > js.joint.gap_m)
                    || hi > js.max_closing
                    || -lo > js.max_opening
                    || (js.unseated.is_none() && -lo > seat);
                if !reach {
                    continue;
                }
                let c = smooth + self.waves_across(j, &mut w.waves, n0 + m);
                w.closings[j] = c;
                onset |= contact && c - js.joint.gap_m > 0.0;
            }
            if onset {
                found = Some(m);
                break;
            }
            for (js, &c) in self.joints.iter_mut().zip(&w.closings) {
                // NaN where the joint was not read (it could not pass anything here).
                if c.is_nan() {
                    continue;
                }
                js.max_closing = js.max_closing.max(c);
                js.max_opening = js.max_opening.max(-c);
                if js.unseated.is_none() && -c > seat {
                    js.unseated = Some(t);
                }
            }
            for (i, f) in self.frames.iter().enumerate() {
                let look = w.signal_look[i];
                if !(look[0] || look[1] || look[2]) {
                    continue;
                }
                let md = &modes[i];
                let u = signal_shapes(f).map(|c| (c[0] * md[0].0 + c[1] * md[1].0).abs());
                let peaks = [
                    &mut sink.peaks.girder[i],
                    &mut sink.peaks.pier[i],
                    &mut sink.peaks.bearing[i],
                ];
                for ((p, u), l) in peaks.into_iter().zip(u).zip(look) {
                    if l {
                        *p = p.max(u);
                    }
                }
            }
        }
        w.modes_walk = modes;
        w.ground_walk = ground;
        found
    }

    /// Joint j's closing without its girders' waves, from the frames' modes and the ground.
    fn smooth_closing(&self, j: usize, modes: &[[(f64, f64); 2]], ground: &[GroundState]) -> f64 {
        let mut c = 0.0;
        for (side, sign) in self.joints[j].sides.iter().zip([1.0, -1.0]) {
            let mut u = ground[side.support].displacement;
            if let Some((i, _)) = side.girder {
                let (f, m) = (&self.frames[i], &modes[i]);
                u += f.girder[0] * m[0].0 + f.girder[1] * m[1].0;
            }
            c += sign * u;
        }
        c
    }

    /// The girders' waves across joint j at grid index `n` (left member's end less right's),
    /// each girder's read once per grid point into `waves`.
    fn waves_across(&self, j: usize, waves: &mut [Option<[f64; 2]>], n: usize) -> f64 {
        let mut c = 0.0;
        for (side, sign) in self.joints[j].sides.iter().zip([1.0, -1.0]) {
            if let Some((i, end)) = side.girder
                && let Some(g) = &self.girders[i]
            {
                c += sign * waves[i].get_or_insert_with(|| g.waves_at(n))[end];
            }
        }
        c
    }

    /// Records the sample at grid step b of the stretch (its modes and ground in `w`).
    fn record_at(&self, w: &mut Scratch, n0: usize, b: usize, sink: &mut Sink) {
        let n = n0 + b;
        w.waves.iter_mut().for_each(|x| *x = None);
        let hist = &mut *sink.hist;
        hist.time_s.push(n as f64 * self.h);
        for j in 0..self.joints.len() {
            let c = self.smooth_closing(j, &w.modes_b, &w.ground)
                + self.waves_across(j, &mut w.waves, n);
            hist.force[j].push(0.0);
            hist.opening[j].push(-c);
        }
        for (i, f) in self.frames.iter().enumerate() {
            let m = &w.modes_b[i];
            let girder = f.girder[0] * m[0].0 + f.girder[1] * m[1].0;
            hist.girder[i].push(girder);
            hist.pier[i].push(f.pier[0] * m[0].0 + f.pier[1] * m[1].0);
            hist.absolute[i].push(girder + w.ground[i + 1].displacement);
        }
    }

    /// Ends the stretch `reached` grid steps after `n0` (of the `len` it was planned for): the
    /// frames take their exact states there, the ledger the exact integrals of the damping and
    /// the ground's power, the girders ring on to there.
    fn commit_stretch(&mut self, w: &mut Scratch, n0: usize, reached: usize, len: usize) {
        let h = self.h;
        let span = reached as f64 * h;
        let t1 = (n0 + reached) as f64 * h;
        for i in 0..self.frames.len() {
            let ints = self.stretch_steps[i].integrals(reached);
            let (a0, a1) = w.accel[i];
            let a_end = a0 + (a1 - a0) * reached as f64 / len as f64;
            let f = &mut self.frames[i];
            let ends = self.stretch_steps[i].state(&w.y0[i], reached);
            for (k, (y, (q, v))) in w.y0[i].iter().zip(ends).enumerate() {
                let int_q: f64 = (0..4).map(|j| ints[k].int_q[j] * y[j]).sum();
                let int_s_v = span * q - int_q;
                self.energy.input_j += y[2] * (q - y[0]) + y[3] * int_s_v;
                self.energy.damping_j += 2.0 * f.zeta[k] * f.omega[k] * ints[k].velocity_squared(y);
                f.q[k] = q;
                f.v[k] = v;
                f.g[k] = -f.gamma[k] * a_end;
            }
            f.a_now = a_end;
            f.f_now = 0.0;
        }
        for (i, g) in self.girders.iter_mut().enumerate() {
            if let Some(g) = g {
                g.skip(reached);
                self.waves[i] = g.waves_at(n0 + reached);
            }
        }
        self.refresh_ground(t1);
        self.read_joints(t1);
        self.powers_now = self.powers();
        self.ground_stale = true;
    }
}
