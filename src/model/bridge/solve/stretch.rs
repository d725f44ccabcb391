//! The free stretch: between contacts no joint force acts, every frame moves exactly (each
//! mode's forcing is linear in time between two kinks of its ground's record) and every girder
//! rings in closed form, so the run jumps from grid point to grid point without stepping.
//!
//! What a walk of every grid point would find is found all the same, at the same grid points:
//! the stretch is checked at a few points (at most `check` grid steps apart, a radian of the
//! fastest frame mode), and between two of them every signal is within a margin of the cubic
//! through its values and rates there (`model::bound`: the frames' fourth derivatives are
//! bounded, the grounds are cubics between the record's samples; the girders' waves are within
//! their envelopes, their largest values on the grid over two round trips with a margin for the
//! phases between grid points). Only a part where that margin leaves a joint able to close its
//! gap, to pass its largest closing or opening or its seat, or a frame able to pass a peak, is
//! walked grid point by grid point, and only for those signals; an onset there ends the stretch
//! at the grid point before it, where the stepped run takes over.

use super::*;
use crate::model::bound::{ROUNDING, cubic_bound, cubic_margin, cubic_max, mode_bounds, monotone};
use crate::model::building::modal::{StepIntegrals, doublings, integrals_over, step_powers};

/// The longest stretch, in grid steps: each frame's exact maps over 1 to this many steps are
/// tabulated once a run.
const MAX_STRETCH: usize = 2048;

/// A part no longer than twice this (in grid steps) is walked rather than halved again.
const WALK_SPAN: usize = 8;

/// A check spans at most this many radians of the fastest frame mode: the cubic between two
/// checks is then within (w l)^4 / 128 = 8e-3 of the amplitude (a part it cannot clear is
/// halved).
const CHECK_RADIANS: f64 = 1.0;

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
    /// The grid points after `from` up to `to` that are recorded: every stride's, and the run's
    /// last (none in a summary).
    fn samples(&self, from: usize, to: usize) -> impl Iterator<Item = usize> + use<> {
        let (stride, steps) = (self.stride, self.steps);
        let strided = (from / stride).saturating_add(1).saturating_mul(stride);
        let last =
            (to == steps && stride != usize::MAX && !steps.is_multiple_of(stride)).then_some(steps);
        (strided..=to).step_by(stride).chain(last)
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
    /// The stretch's length in grid steps.
    len: usize,
    /// Each frame's modes' augmented starting states [q, q', g, g'].
    y0: Vec<[[f64; 4]; 2]>,
    /// The ground acceleration at each frame's support at the stretch's start and end.
    accel: Vec<(f64, f64)>,
    /// Bounds on each joint's smooth closing's fourth and fifth derivatives and on its
    /// girders' waves.
    joint_m4: Vec<f64>,
    joint_m5: Vec<f64>,
    joint_env: Vec<f64>,
    /// Whether no girder at the joint has ever been struck (no waves ride on its closing).
    joint_still: Vec<bool>,
    /// Bounds on each frame signal's fourth derivative, and whether it can reach its peak at
    /// all in the stretch.
    signal_m4: Vec<[f64; 3]>,
    signal_m5: Vec<[f64; 3]>,
    signal_open: Vec<[bool; 3]>,
    /// Each frame's modal (q, q') at the check being made.
    modes_b: Vec<[(f64, f64); 2]>,
    /// The ground at every support at the check being made (the first of each delay read).
    ground: Vec<GroundState>,
    /// Each frame's modal accelerations at the check being made.
    accel_b: Vec<[f64; 2]>,
    /// Each joint's closing without the waves, its rate and acceleration, at the last check
    /// and this one.
    joint_a: Vec<[f64; 3]>,
    joint_b: Vec<[f64; 3]>,
    /// Each frame signal's value, rate and acceleration at the last check and this one.
    signal_a: Vec<[[f64; 3]; 3]>,
    signal_b: Vec<[[f64; 3]; 3]>,
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
    /// The `_b` values of the parts being halved, outermost first (and spares, reused).
    saved: Vec<Saved>,
    depth: usize,
}

/// A check's values at one grid point, kept while the part before it is halved.
#[derive(Default)]
struct Saved {
    modes: Vec<[(f64, f64); 2]>,
    ground: Vec<GroundState>,
    joint: Vec<[f64; 3]>,
    signal: Vec<[[f64; 3]; 3]>,
}

impl Scratch {
    /// The part's end becomes the next part's start.
    fn swap_ends(&mut self) {
        std::mem::swap(&mut self.joint_a, &mut self.joint_b);
        std::mem::swap(&mut self.signal_a, &mut self.signal_b);
    }

    fn save_b(&mut self) {
        if self.saved.len() <= self.depth {
            self.saved.push(Saved::default());
        }
        let s = &mut self.saved[self.depth];
        s.modes.clone_from(&self.modes_b);
        s.ground.clone_from(&self.ground);
        s.joint.clone_from(&self.joint_b);
        s.signal.clone_from(&self.signal_b);
        self.depth += 1;
    }

    fn restore_b(&mut self) {
        self.depth -= 1;
        let s = &mut self.saved[self.depth];
        std::mem::swap(&mut s.modes, &mut self.modes_b);
        std::mem::swap(&mut s.ground, &mut self.ground);
        std::mem::swap(&mut s.joint, &mut self.joint_b);
        std::mem::swap(&mut s.signal, &mut self.signal_b);
    }

    fn drop_saved(&mut self) {
        self.depth -= 1;
    }
}

impl<'a> Run<'a> {
    /// The frames' exact maps, for stretches of up to a record step (at most `MAX_STRETCH`
    /// grid steps and the run's `steps`), and the span of a check.
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
        // The girders fall quiet where the stepped run lets them (whether a stretch follows or
        // not), so both read the same closed form from then on.
        self.settle_if_free();
        // The onset a stretch has just stopped before, and a joint overlapping without a force
        // (a damped link letting go, a stereomechanical exchange): the next step is a stepped
        // one, without looking for it again.
        if self.onset_next == Some(n0 + 1) || self.joints.iter().any(|js| js.delta > 0.0) {
            return 0;
        }
        let len = self.stretch_length(n0, sink.steps);
        if len == 0 {
            return 0;
        }
        let mut w = std::mem::take(&mut self.stretch_scratch);
        self.prepare(&mut w, n0, len, sink);
        let mut a = 0;
        let mut reached = len;
        while a < len {
            let b = (a + self.check).min(len);
            self.values_at(&mut w, n0, b);
            let onset = self.check_part(&mut w, n0, a, b, sink);
            // The samples the part holds, up to the grid point before an onset.
            let to = onset.map_or(b, |m| m - 1);
            for r in sink.samples(n0 + a, n0 + to) {
                self.record_at(&mut w, n0, r - n0, b, sink);
            }
            if let Some(m) = onset {
                reached = m - 1;
                self.onset_next = Some(n0 + m);
                break;
            }
            w.swap_ends();
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
        w.signal_m5.clear();
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
            mode_m4.push([[bounds[0][1], bounds[1][1]], [bounds[0][2], bounds[1][2]]]);
            let peaks = sink.peaks.at(i);
            let shapes = signal_shapes(f);
            w.signal_m4
                .push(shapes.map(|c| c[0].abs() * bounds[0][1] + c[1].abs() * bounds[1][1]));
            w.signal_m5
                .push(shapes.map(|c| c[0].abs() * bounds[0][2] + c[1].abs() * bounds[1][2]));
            // A signal whose modes' amplitudes cannot reach its peak anywhere in the stretch is
            // left alone for all of it.
            w.signal_open.push(std::array::from_fn(|s| {
                let c = shapes[s];
                let size = c[0].abs() * bounds[0][0] + c[1].abs() * bounds[1][0];
                size * (1.0 + ROUNDING) >= peaks[s]
            }));
        }
        w.joint_m4.clear();
        w.joint_m5.clear();
        w.joint_env.clear();
        w.joint_still.clear();
        for js in &self.joints {
            let (mut m4, mut m5, mut env) = (0.0, 0.0, 0.0);
            let mut still = true;
            for side in &js.sides {
                if let Some((i, end)) = side.girder {
                    let (f, [b4, b5]) = (&self.frames[i], mode_m4[i]);
                    m4 += f.girder[0].abs() * b4[0] + f.girder[1].abs() * b4[1];
                    m5 += f.girder[0].abs() * b5[0] + f.girder[1].abs() * b5[1];
                    if let Some(g) = &self.girders[i] {
                        env += g.envelope_from(n0 + 1)[end];
                        still &= g.is_still();
                    }
                }
            }
            w.joint_m4.push(m4);
            w.joint_m5.push(m5);
            w.joint_env.push(env);
            w.joint_still.push(still);
        }
        w.waves.clear();
        w.waves.resize(self.girders.len(), None);
        w.joint_look.resize(self.joints.len(), false);
        w.closings.resize(self.joints.len(), 0.0);
        w.signal_look.resize(nf, [false; 3]);
        // The first check's values: the state now.
        w.modes_b.clear();
        w.modes_b.extend(
            self.frames
                .iter()
                .map(|f| [(f.q[0], f.v[0]), (f.q[1], f.v[1])]),
        );
        w.modes_walk.clone_from(&w.modes_b);
        w.len = len;
        self.ground_in_stretch(w, n0, 0);
        self.smooth_values(w, 0);
        w.swap_ends();
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
    fn smooth_values(&self, w: &mut Scratch, j: usize) {
        // Each mode's acceleration from its equation of motion, its forcing linear in time.
        let s = j as f64 * self.h;
        w.accel_b.clear();
        for ((f, y), m) in self.frames.iter().zip(&w.y0).zip(&w.modes_b) {
            w.accel_b.push(std::array::from_fn(|k| {
                y[k][2] + y[k][3] * s
                    - 2.0 * f.zeta[k] * f.omega[k] * m[k].1
                    - f.omega[k] * f.omega[k] * m[k].0
            }));
        }
        w.joint_b.clear();
        for js in &self.joints {
            let mut out = [0.0; 3];
            for (side, sign) in js.sides.iter().zip([1.0, -1.0]) {
                let g = &w.ground[side.support];
                let mut x = [g.displacement, g.velocity, g.accel];
                if let Some((i, _)) = side.girder {
                    let (f, m, acc) = (&self.frames[i], &w.modes_b[i], &w.accel_b[i]);
                    x[0] += f.girder[0] * m[0].0 + f.girder[1] * m[1].0;
                    x[1] += f.girder[0] * m[0].1 + f.girder[1] * m[1].1;
                    x[2] += f.girder[0] * acc[0] + f.girder[1] * acc[1];
                }
                for (o, x) in out.iter_mut().zip(x) {
                    *o += sign * x;
                }
            }
            w.joint_b.push(out);
        }
        w.signal_b.clear();
        for ((f, m), acc) in self.frames.iter().zip(&w.modes_b).zip(&w.accel_b) {
            w.signal_b.push(signal_shapes(f).map(|c| {
                [
                    c[0] * m[0].0 + c[1] * m[1].0,
                    c[0] * m[0].1 + c[1] * m[1].1,
                    c[0] * acc[0] + c[1] * acc[1],
                ]
            }));
        }
    }

    /// The frames' modes, the ground, the joints' smooth closings and the frame signals j grid
    /// steps into the stretch from `n0`, into the `_b` buffers.
    fn values_at(&self, w: &mut Scratch, n0: usize, j: usize) {
        self.modes_at(w, j);
        self.ground_in_stretch(w, n0, j);
        self.smooth_values(w, j);
    }

    /// The ground at every support j grid steps into the stretch, into `w.ground`, with the
    /// acceleration's one-sided limit at the stretch's ends (a wave's arrival and a record's
    /// end are jumps; the stretch's forcing takes the side inside it).
    fn ground_in_stretch(&self, w: &mut Scratch, n0: usize, j: usize) {
        let t = (n0 + j) as f64 * self.h;
        self.ground_into(t, &mut w.ground);
        if j == 0 || j == w.len {
            for (s, g) in w.ground.iter_mut().enumerate() {
                let d = self.support_delay[s];
                g.accel = if j == 0 {
                    self.ground.accel_after(t, d)
                } else {
                    self.ground.accel_before(t, d)
                };
            }
        }
    }

    /// Checks the part from grid step a to b of the stretch from `n0` (its values at a in the
    /// `_a` buffers, at b in the `_b` ones): clears it, halves it, or walks what its bounds
    /// cannot clear once it is short. Returns the grid step of an onset found in it. Leaves
    /// b's values in the `_b` buffers.
    fn check_part(
        &mut self,
        w: &mut Scratch,
        n0: usize,
        a: usize,
        b: usize,
        sink: &mut Sink,
    ) -> Option<usize> {
        if !self.flag(w, a, b, sink) {
            return None;
        }
        if b - a <= 2 * WALK_SPAN {
            return self.walk(w, n0, a, b, sink);
        }
        let mid = a + (b - a) / 2;
        w.save_b();
        self.values_at(w, n0, mid);
        let first = self.check_part(w, n0, a, mid, sink);
        if first.is_some() {
            w.drop_saved();
            return first;
        }
        w.swap_ends();
        w.restore_b();
        self.check_part(w, n0, mid, b, sink)
    }

    /// Decides what the part from a to b must be looked into for (into `w.joint_look` and
    /// `w.signal_look`): whether anything must.
    fn flag(&mut self, w: &mut Scratch, a: usize, b: usize, sink: &mut Sink) -> bool {
        if self.walk_all {
            // The bounds' reference: everything is looked into, at every grid point.
            w.joint_look.fill(true);
            w.signal_look.fill([true; 3]);
            return true;
        }
        let l = (b - a) as f64 * self.h;
        let contact = self.sc.contact != ContactModel::None;
        let seat = self.sc.seat_length_m;
        // A joint that may close its gap or unseat in the part must be walked for it; the
        // others may be found at a largest value only.
        let mut events = false;
        let mut peaks_only = false;
        for (j, js) in self.joints.iter().enumerate() {
            let ([c0, r0, _], [c1, r1, _]) = (w.joint_a[j], w.joint_b[j]);
            let margin = cubic_margin(w.joint_m4[j], l)
                + ROUNDING * (c0.abs() + c1.abs() + l * (r0.abs() + r1.abs()))
                + w.joint_env[j];
            let gap = js.joint.gap_m;
            // (may close its gap or unseat, may pass its largest closing or opening)
            let reach = |hi: f64, lo: f64| {
                (
                    (contact && hi >= gap) || (js.unseated.is_none() && -lo > seat),
                    hi >= js.max_closing || -lo >= js.max_opening,
                )
            };
            let quick = reach(
                cubic_bound(c0, r0, c1, r1, l) + margin,
                -cubic_bound(-c0, -r0, -c1, -r1, l) - margin,
            );
            let (event, peak) = if quick == (false, false) {
                quick
            } else {
                reach(
                    cubic_max(c0, r0, c1, r1, l) + margin,
                    -cubic_max(-c0, -r0, -c1, -r1, l) - margin,
                )
            };
            w.joint_look[j] = event || peak;
            events |= event;
            peaks_only |= peak && !event;
        }
        // Where no onset can come first, a signal whose rate keeps its sign over the part has
        // its largest value at an end: taken at once, as a walk would take it (a joint's only
        // where no girder waves ride on it).
        if !events && peaks_only {
            for j in 0..self.joints.len() {
                let ([_, r0, a0], [c1, r1, a1]) = (w.joint_a[j], w.joint_b[j]);
                if w.joint_look[j]
                    && w.joint_still[j]
                    && monotone([r0, a0], [r1, a1], l, w.joint_m5[j])
                {
                    let js = &mut self.joints[j];
                    js.max_closing = js.max_closing.max(c1);
                    js.max_opening = js.max_opening.max(-c1);
                    w.joint_look[j] = false;
                }
            }
        }
        let mut any = w.joint_look.iter().any(|&x| x);
        for i in 0..self.frames.len() {
            for (s, peak) in sink.peaks.of(i).into_iter().enumerate() {
                let ([u0, r0, a0], [u1, r1, a1]) = (w.signal_a[i][s], w.signal_b[i][s]);
                let look = w.signal_open[i][s] && {
                    let margin = cubic_margin(w.signal_m4[i][s], l)
                        + ROUNDING * (u0.abs() + u1.abs() + l * (r0.abs() + r1.abs()));
                    cubic_bound(u0.abs(), r0.abs(), u1.abs(), r1.abs(), l) + margin >= *peak
                        && cubic_max(u0, r0, u1, r1, l).max(cubic_max(-u0, -r0, -u1, -r1, l))
                            + margin
                            >= *peak
                };
                let look = look
                    && !(!events && monotone([r0, a0], [r1, a1], l, w.signal_m5[i][s]) && {
                        *peak = peak.max(u1.abs());
                        true
                    });
                w.signal_look[i][s] = look;
                any |= look;
            }
        }
        any
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
                let reach = self.walk_all
                    || (contact && hi > js.joint.gap_m)
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
                for ((p, u), l) in sink.peaks.of(i).into_iter().zip(u).zip(look) {
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

    /// Records the sample at grid step j of the stretch, in the part ending at b (whose
    /// modes and ground `w` holds).
    fn record_at(&self, w: &mut Scratch, n0: usize, j: usize, b: usize, sink: &mut Sink) {
        let n = n0 + j;
        // The check's reading at its end, or a reading of its own.
        let (modes, ground) = if j == b {
            (&w.modes_b, &w.ground)
        } else {
            for (i, steps) in self.stretch_steps.iter().enumerate() {
                w.modes_walk[i] = steps.state(&w.y0[i], j);
            }
            self.ground_into(n as f64 * self.h, &mut w.ground_walk);
            (&w.modes_walk, &w.ground_walk)
        };
        w.waves.iter_mut().for_each(|x| *x = None);
        let hist = &mut *sink.hist;
        hist.time_s.push(n as f64 * self.h);
        for joint in 0..self.joints.len() {
            let c = self.smooth_closing(joint, modes, ground)
                + self.waves_across(joint, &mut w.waves, n);
            hist.force[joint].push(0.0);
            hist.opening[joint].push(-c);
        }
        for (i, f) in self.frames.iter().enumerate() {
            let m = &modes[i];
            let girder = f.girder[0] * m[0].0 + f.girder[1] * m[1].0;
            hist.girder[i].push(girder);
            hist.pier[i].push(f.pier[0] * m[0].0 + f.pier[1] * m[1].0);
            hist.absolute[i].push(girder + ground[i + 1].displacement);
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
