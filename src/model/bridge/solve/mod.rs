//! The bridge run: every frame's two modes propagated exactly over each step (forcing linear in
//! time: its ground's acceleration and the joint forces on its girder), the joint forces at the
//! step's end solved together, the girders' waves (Sears) stepped with them.
//!
//! At the step's end each girder end's displacement is a known part plus the new joint forces
//! times the step's compliances: the frame's (the girder row of its modal step) and, under
//! Sears, the end's own wave compliance. A joint's overlap is thus
//!   delta_j = K_j - S_j F_j + p_(j-1) F_(j-1) + p_j F_(j+1),
//! each joint's element law closing it: a scalar implicit equation per joint (the elements'
//! `solve_step`), swept joint by joint until the forces agree (the coupling p / S is of the
//! order of h^2 k / m, tiny where the step resolves the contact).

mod stretch;

use super::girder::GirderWaves;
use super::ground::{Ground, GroundState};
use super::result::{BridgeEnergy, BridgeResult, BridgeStats, Unseating};
use super::scenario::{BridgeScenario, Joint, Member};
use crate::model::building::ContactModel;
use crate::model::building::elements::Element;
use crate::model::building::modal::{Propagator, evaluate, propagator};
use crate::model::building::result::{RawContact, group_impacts};
use crate::model::control::Control;
use crate::model::error::SolveError;
use crate::model::motion::GroundMotion;

/// Samples a history keeps at most (the step is strided to it).
const MAX_SAMPLES: usize = 20_000;
/// Sweeps over the joints before the forces are taken as they are.
const MAX_SWEEPS: usize = 100;

/// One frame: its modes and state, relative to its own ground.
#[derive(Debug, Clone)]
struct Frame {
    omega: [f64; 2],
    zeta: [f64; 2],
    /// Mode shapes at the pier top and at the girder.
    pier: [f64; 2],
    girder: [f64; 2],
    gamma: [f64; 2],
    step: [Propagator; 2],
    q: [f64; 2],
    v: [f64; 2],
    /// The modal forcing now.
    g: [f64; 2],
    delay_s: f64,
    /// The girder's compliance to its net joint force over a step [m/N].
    compliance: f64,
    /// The girder's inverse effective mass, sum of phi^2 [1/kg].
    inverse_mass: f64,
    /// The girder's displacement at the step's end without the new joint forces.
    u_star: f64,
    /// The ground acceleration the forcing `g` holds, and the one the step ends with.
    a_now: f64,
    a_next: f64,
    /// The net joint force `g` holds.
    f_now: f64,
    /// Where the ground's acceleration breaks inside the step being taken.
    jump: Option<Jump>,
    /// The index of the record sample the last step looked for (a ceiling kept).
    sample: f64,
    /// Each mode's state at the step's end without joint forces, as the prediction found it
    /// (what a step that stays free commits).
    free_end: [(f64, f64); 2],
}

/// A break in the ground's acceleration inside a step: a record sample (a kink), or where the
/// wave arrives (a jump from zero to the record's first sample) or the record ends (from its
/// last sample back to zero).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Jump {
    /// Time from the step's start [s].
    at: f64,
    before: f64,
    after: f64,
}

impl Frame {
    fn new(sc: &BridgeScenario, i: usize, h: f64) -> Self {
        let modes = sc.frame_modes(i);
        let m = sc.frame_masses(i);
        let two = |f: &dyn Fn(usize) -> f64| [f(0), f(1)];
        let omega = two(&|k| modes.omega_rad_s[k]);
        let zeta = two(&|k| modes.damping[k]);
        let step = [
            propagator(omega[0], zeta[0], h),
            propagator(omega[1], zeta[1], h),
        ];
        let girder = two(&|k| modes.shapes[k][1]);
        let compliance = (0..2)
            .map(|k| girder[k] * girder[k] * step[k].q[3] / h)
            .sum();
        let v0 = sc.initial_velocity(i);
        // An initial velocity of the girder alone: q' = Phi^T M v.
        let v = two(&|k| modes.shapes[k][1] * m[1] * v0);
        Frame {
            omega,
            zeta,
            pier: two(&|k| modes.shapes[k][0]),
            girder,
            gamma: two(&|k| modes.participation[k]),
            step,
            q: [0.0; 2],
            v,
            g: [0.0; 2],
            delay_s: sc.delay_s(sc.frame_position_m(i)),
            compliance,
            inverse_mass: girder[0] * girder[0] + girder[1] * girder[1],
            u_star: 0.0,
            a_now: 0.0,
            a_next: 0.0,
            f_now: 0.0,
            jump: None,
            sample: f64::NAN,
            free_end: [(0.0, 0.0); 2],
        }
    }

    fn girder_u(&self) -> f64 {
        self.girder[0] * self.q[0] + self.girder[1] * self.q[1]
    }
    fn girder_v(&self) -> f64 {
        self.girder[0] * self.v[0] + self.girder[1] * self.v[1]
    }
    fn pier_u(&self) -> f64 {
        self.pier[0] * self.q[0] + self.pier[1] * self.q[1]
    }
    fn energy(&self) -> f64 {
        (0..2)
            .map(|k| 0.5 * (self.v[k] * self.v[k] + (self.omega[k] * self.q[k]).powi(2)))
            .sum()
    }
    /// The power its damping takes, and the power its ground puts in.
    fn powers(&self, accel: f64) -> (f64, f64) {
        let mut damping = 0.0;
        let mut input = 0.0;
        for k in 0..2 {
            damping += 2.0 * self.zeta[k] * self.omega[k] * self.v[k] * self.v[k];
            input -= accel * self.gamma[k] * self.v[k];
        }
        (damping, input)
    }

    /// The girder's displacement at the step's end before the joint forces, the ground's
    /// acceleration going from `accel` (its value just after the step's start) to `accel_next`
    /// (just before its end), exactly: a jump at a boundary by these limits, a record sample
    /// or a jump inside the step by splitting it there.
    fn predict(&mut self, [accel, accel_next]: [f64; 2], jump: Option<Jump>, h: f64) {
        self.a_next = accel_next;
        self.jump = jump;
        for k in 0..2 {
            // The forcing just after the start: the same joint force, the ground's right limit.
            self.g[k] += self.gamma[k] * (self.a_now - accel);
        }
        self.free_end = [self.advance(0, 0.0, h), self.advance(1, 0.0, h)];
        self.u_star = self.girder[0] * self.free_end[0].0 + self.girder[1] * self.free_end[1].0;
    }

    /// Mode k's state at the step's end with the net joint force `net_force` there.
    #[inline(always)]
    fn advance(&self, k: usize, net_force: f64, h: f64) -> (f64, f64) {
        let g1 = self.girder[k] * net_force - self.gamma[k] * self.a_next;
        let Some(j) = self.jump else {
            let y = [self.q[k], self.v[k], self.g[k], (g1 - self.g[k]) / h];
            return self.step[k].apply(&y);
        };
        // The joint force stays linear across the split; the ground goes from j.before to
        // j.after at j.at.
        let f_mid = self.f_now + (net_force - self.f_now) * j.at / h;
        let before = self.girder[k] * f_mid - self.gamma[k] * j.before;
        let after = self.girder[k] * f_mid - self.gamma[k] * j.after;
        let (w, z) = (self.omega[k], self.zeta[k]);
        let y = [self.q[k], self.v[k], self.g[k], (before - self.g[k]) / j.at];
        let (q, v) = evaluate(w, z, &y, j.at);
        let rest = h - j.at;
        evaluate(w, z, &[q, v, after, (g1 - after) / rest], rest)
    }

    /// Takes the step with the net joint force on the girder at its end.
    fn commit(&mut self, net_force: f64, h: f64) {
        for k in 0..2 {
            let (q, v) = self.advance(k, net_force, h);
            self.q[k] = q;
            self.v[k] = v;
            self.g[k] = self.girder[k] * net_force - self.gamma[k] * self.a_next;
        }
        self.a_now = self.a_next;
        self.f_now = net_force;
    }

    /// Takes the step without joint forces: the state the prediction found.
    fn commit_free(&mut self) {
        for k in 0..2 {
            (self.q[k], self.v[k]) = self.free_end[k];
            self.g[k] = self.girder[k] * 0.0 - self.gamma[k] * self.a_next;
        }
        self.a_now = self.a_next;
        self.f_now = 0.0;
    }

    /// A velocity jump of the girder by an impulse on it `since` seconds ago.
    fn kick(&mut self, impulse: f64, since: f64) {
        for k in 0..2 {
            self.v[k] += self.girder[k] * impulse;
            self.q[k] += self.girder[k] * impulse * since;
        }
    }
}

/// One side of a joint, as a step reads it: the support whose ground it stands on, and the
/// girder with the end of it at the joint (none for an abutment).
#[derive(Debug, Clone, Copy)]
struct Side {
    support: usize,
    girder: Option<(usize, usize)>,
}

/// One joint's state.
#[derive(Debug, Clone)]
struct JointState {
    joint: Joint,
    /// Its left and right members' sides.
    sides: [Side; 2],
    element: Element,
    force: f64,
    delta: f64,
    rate: f64,
    v0: f64,
    /// The contact now open: its index in the list.
    open: Option<usize>,
    max_force: f64,
    max_closing: f64,
    max_opening: f64,
    unseated: Option<f64>,
    /// Integrals for the ledger: F d(delta), F d(ground difference).
    work_delta: f64,
    work_ground: f64,
    /// The ground displacement across the joint (left member's support less right's) at the
    /// last step a force acted in, which is all its work reads (see `Run::ground_stale`).
    ground_difference: f64,
    /// The known part of the overlap at the step's end, and its compliance to the joint's own
    /// force (the same every step).
    k_star: f64,
    s: f64,
}

/// The run.
struct Run<'a> {
    sc: &'a BridgeScenario,
    ground: Ground,
    h: f64,
    frames: Vec<Frame>,
    girders: Vec<Option<GirderWaves>>,
    /// Each girder's elastic displacement at its ends now.
    waves: Vec<[f64; 2]>,
    joints: Vec<JointState>,
    /// The supports' delays: the left abutment, each frame, the right abutment.
    support_delay: Vec<f64>,
    /// For each support, the first support with the same delay (whose ground it shares): every
    /// read of `ground_now` and `ground_then` goes through it (`Run::at_support`).
    same_ground: Vec<usize>,
    /// The ground at the run's present instant, and at the reading before (a step's start,
    /// once the step has read its end), by support; only the first support of each delay is
    /// read (the others' entries stay unwritten).
    ground_now: Vec<GroundState>,
    ground_then: Vec<GroundState>,
    /// The girders' end waves known before the step's new forces.
    predicted: Vec<[f64; 2]>,
    /// Each girder's coupling p: how the force at one of its ends moves the other end over a
    /// step (the same every step).
    coupling: Vec<f64>,
    /// The step's joint overlaps and forces, solved.
    solved: Vec<(f64, f64)>,
    /// The state before the step being taken, kept for its bookkeeping.
    before: Before,
    contacts: Vec<RawContact>,
    energy: BridgeEnergy,
    contact_steps: usize,
    /// The frames' damping and input powers now.
    powers_now: (f64, f64),
    /// Whether the joints' ground differences are older than the step's start (left so by free
    /// steps).
    ground_stale: bool,
    /// Each frame's exact maps for free stretches, the grid steps a stretch's check spans at
    /// most, and the stretch's buffers.
    stretch_steps: Vec<stretch::FrameSteps>,
    check: usize,
    stretch_scratch: stretch::Scratch,
    /// The grid point of the onset the last free stretch stopped before.
    onset_next: Option<usize>,
    /// Free stretches walk every grid point for every signal (the bounds' reference).
    walk_all: bool,
}

impl<'a> Run<'a> {
    fn new(sc: &'a BridgeScenario, motion: &GroundMotion, h: f64) -> Self {
        let frames: Vec<Frame> = (0..sc.spans).map(|i| Frame::new(sc, i, h)).collect();
        let girders = (0..sc.spans)
            .map(|i| {
                (sc.contact == ContactModel::Sears)
                    .then(|| GirderWaves::new(&sc.girder(i), sc.girder_damping, h))
            })
            .collect();
        let joints = sc
            .joints()
            .into_iter()
            .map(|joint| JointState {
                sides: [(joint.left, true), (joint.right, false)].map(|(member, on_left)| Side {
                    support: support_of(sc.spans, member, on_left),
                    girder: match member {
                        Member::Girder(i) => Some((i, usize::from(on_left))),
                        Member::Abutment => None,
                    },
                }),
                element: Element::new(
                    sc.contact,
                    sc.joint_stiffness(&joint),
                    sc.restitution,
                    sc.joint_effective_mass(&joint),
                ),
                joint,
                force: 0.0,
                delta: -joint.gap_m,
                rate: 0.0,
                v0: 0.0,
                open: None,
                max_force: 0.0,
                max_closing: f64::NEG_INFINITY,
                max_opening: f64::NEG_INFINITY,
                unseated: None,
                work_delta: 0.0,
                work_ground: 0.0,
                ground_difference: 0.0,
                k_star: 0.0,
                s: 0.0,
            })
            .collect();
        let energy = BridgeEnergy {
            initial_j: frames.iter().map(Frame::energy).sum(),
            ..Default::default()
        };
        let mut run = Run {
            sc,
            ground: Ground::new(motion),
            h,
            frames,
            girders,
            waves: vec![[0.0; 2]; sc.spans],
            joints,
            support_delay: Vec::new(),
            same_ground: Vec::new(),
            ground_now: Vec::new(),
            ground_then: Vec::new(),
            predicted: vec![[0.0; 2]; sc.spans],
            coupling: Vec::new(),
            solved: Vec::new(),
            before: Before::default(),
            contacts: Vec::new(),
            energy,
            contact_steps: 0,
            powers_now: (0.0, 0.0),
            ground_stale: false,
            stretch_steps: Vec::new(),
            check: 1,
            stretch_scratch: stretch::Scratch::default(),
            onset_next: None,
            walk_all: false,
        };
        run.compliances();
        run.supports();
        run.refresh_ground(0.0);
        run.read_joints(0.0);
        for j in 0..run.joints.len() {
            run.joints[j].ground_difference = run.ground_difference(j);
        }
        run.powers_now = run.powers();
        run
    }

    /// Every support's delay, and which supports share a ground (all of them under uniform
    /// excitation, so the record is read once an instant).
    fn supports(&mut self) {
        let sc = self.sc;
        self.support_delay = std::iter::once(0.0)
            .chain(self.frames.iter().map(|f| f.delay_s))
            .chain(std::iter::once(sc.delay_s(sc.length_m())))
            .collect();
        let d = &self.support_delay;
        self.same_ground = (0..d.len())
            .map(|s| (0..s).find(|&o| d[o] == d[s]).unwrap_or(s))
            .collect();
        self.ground_now = vec![GroundState::default(); d.len()];
        self.ground_then = self.ground_now.clone();
    }

    /// The ground at time t at the first support of each delay: what every later look at the
    /// ground reads (the reading it replaces kept as the one before).
    fn refresh_ground(&mut self, t: f64) {
        std::mem::swap(&mut self.ground_now, &mut self.ground_then);
        for s in 0..self.support_delay.len() {
            // A support sharing another's ground is read there (see `same_ground`).
            if self.same_ground[s] == s {
                self.ground_now[s] = self.ground.at(t, self.support_delay[s]);
            }
        }
    }

    /// Support s's ground in a reading of every support's (`ground_now`, `ground_then`).
    #[inline(always)]
    fn at_support<'r>(&self, readings: &'r [GroundState], s: usize) -> &'r GroundState {
        &readings[self.same_ground[s]]
    }

    /// The joints' own compliances S and the girders' couplings p, fixed by the step.
    fn compliances(&mut self) {
        let rigid = |g: &Option<GirderWaves>| g.as_ref().map_or(0.0, |g| g.rigid_compliance());
        let own = |g: &Option<GirderWaves>| g.as_ref().map_or(0.0, |g| g.own_compliance());
        for j in 0..self.joints.len() {
            let joint = self.joints[j].joint;
            let mut s = 0.0;
            for member in [joint.left, joint.right] {
                if let Member::Girder(i) = member {
                    s += self.frames[i].compliance + own(&self.girders[i]);
                    s -= rigid(&self.girders[i]);
                }
            }
            self.joints[j].s = s;
        }
        self.coupling = (0..self.frames.len())
            .map(|i| self.frames[i].compliance - rigid(&self.girders[i]))
            .collect();
    }

    /// A joint side's absolute displacement and rigid velocity now.
    #[inline(always)]
    fn side_now(&self, side: &Side) -> (f64, f64) {
        let g = self.at_support(&self.ground_now, side.support);
        match side.girder {
            None => (g.displacement, g.velocity),
            Some((i, end)) => {
                let f = &self.frames[i];
                (
                    g.displacement + f.girder_u() + self.waves[i][end],
                    g.velocity + f.girder_v(),
                )
            }
        }
    }

    /// Closing (left member minus right member, absolute) and rigid closing rate of joint j
    /// now.
    #[inline(always)]
    fn closing(&self, j: usize) -> (f64, f64) {
        let [left, right] = &self.joints[j].sides;
        let (xl, vl) = self.side_now(left);
        let (xr, vr) = self.side_now(right);
        (xl - xr, vl - vr)
    }

    /// Ground displacement difference across joint j now (left member's support minus right's).
    fn ground_difference(&self, j: usize) -> f64 {
        self.ground_difference_in(&self.ground_now, j)
    }

    /// The same from a reading of the ground at every support.
    fn ground_difference_in(&self, readings: &[GroundState], j: usize) -> f64 {
        let [left, right] = &self.joints[j].sides;
        self.at_support(readings, left.support).displacement
            - self.at_support(readings, right.support).displacement
    }

    /// The joints' overlaps, rates, openings and seats at time t (the ground's present).
    fn read_joints(&mut self, t: f64) {
        let seat = self.sc.seat_length_m;
        for j in 0..self.joints.len() {
            let (closing, rate) = self.closing(j);
            let js = &mut self.joints[j];
            js.delta = closing - js.joint.gap_m;
            js.rate = rate;
            js.max_closing = js.max_closing.max(closing);
            js.max_opening = js.max_opening.max(-closing);
            if js.unseated.is_none() && -closing > seat {
                js.unseated = Some(t);
            }
        }
    }

    /// The known parts of every joint's overlap at the step's end (the frames predicted, the
    /// ground already there).
    fn predict_joints(&mut self, next: usize) {
        for (i, g) in self.girders.iter_mut().enumerate() {
            if let Some(g) = g {
                // A quiet girder (no force at its ends since it fell quiet) rings in closed
                // form: its known part is its ringing at the step's end.
                self.predicted[i] = if g.is_quiet() {
                    g.waves_at(next)
                } else {
                    let forces = [self.joints[i].force, self.joints[i + 1].force];
                    let p = g.predict(forces);
                    [p.left, p.right]
                };
            }
        }
        for j in 0..self.joints.len() {
            let js = &self.joints[j];
            let mut k = -js.joint.gap_m;
            for (side, sign) in js.sides.iter().zip([1.0, -1.0]) {
                let ground = self.at_support(&self.ground_now, side.support).displacement;
                k += sign
                    * match side.girder {
                        None => ground,
                        Some((i, end)) => ground + self.frames[i].u_star + self.predicted[i][end],
                    };
            }
            self.joints[j].k_star = k;
        }
    }

    /// Every frame's girder before the joint forces, over the step from t0 to t1; the ground
    /// is read at t1 on the way (it was at t0).
    fn predict_frames(&mut self, t0: f64, t1: f64) {
        let h = self.h;
        let eps = 1e-9 * h;
        let dt = self.ground.corrected.dt_s;
        let last = (self.ground.corrected.accel_m_s2.len() as f64 - 1.0).max(0.0);
        self.refresh_ground(t1);
        for (i, f) in self.frames.iter_mut().enumerate() {
            let accel = [
                self.ground.accel_after_from(
                    t0,
                    f.delay_s,
                    &self.ground_then[self.same_ground[i + 1]],
                ),
                self.ground.accel_before_from(
                    t1,
                    f.delay_s,
                    &self.ground_now[self.same_ground[i + 1]],
                ),
            ];
            // The record's samples are its acceleration's kinks, and its first and last are
            // where it jumps from and back to rest: at most one lies inside a step (h <= dt).
            let x = (t0 + eps - f.delay_s) / dt;
            // ceil(x), from the last step's where x has not passed it (a call saved a step).
            if !(x <= f.sample && x > f.sample - 1.0) {
                f.sample = x.ceil();
            }
            let m = f.sample.max(0.0);
            let t = f.delay_s + m * dt;
            let jump = (m <= last && t > t0 + eps && t < t1 - eps).then(|| Jump {
                at: t - t0,
                before: self.ground.accel_before(t, f.delay_s),
                after: self.ground.accel_after(t, f.delay_s),
            });
            f.predict(accel, jump, h);
        }
    }

    /// Every joint's force at the step's end, swept joint by joint until they agree.
    fn solve_forces(&mut self) {
        let n = self.joints.len();
        let mut out = std::mem::take(&mut self.solved);
        out.clear();
        out.extend(self.joints.iter().map(|js| (js.k_star, 0.0)));
        let h = self.h;
        // No joint closed at the step's end without forces: every force is zero (what one
        // sweep finds, without its element calls).
        if self.joints.iter().all(|js| js.k_star <= 0.0) {
            out.iter_mut().for_each(|o| o.1 = 0.0);
            self.solved = out;
            return;
        }
        for _ in 0..MAX_SWEEPS {
            let mut change: f64 = 0.0;
            let mut largest: f64 = 0.0;
            for j in 0..n {
                let js = &self.joints[j];
                let mut rhs = js.k_star;
                if j > 0 {
                    rhs += self.coupling[j - 1] * out[j - 1].1;
                }
                if j + 1 < n {
                    rhs += self.coupling[j] * out[j + 1].1;
                }
                let e = &js.element;
                let v0 = if js.open.is_some() { js.v0 } else { js.rate };
                let delta = e.solve_step(js.s, rhs, h, js.delta, js.rate, v0);
                let rate = e.rate(h, delta, js.delta, js.rate);
                let force = e.force(delta, rate, v0);
                change = change.max((force - out[j].1).abs());
                largest = largest.max(force);
                out[j] = (delta, force);
            }
            if change <= 1e-12 * largest {
                break;
            }
        }
        self.solved = out;
    }
}

/// What one step's bookkeeping needs from before it (buffers kept between steps).
#[derive(Debug, Clone, Default)]
struct Before {
    forces: Vec<f64>,
    deltas: Vec<f64>,
    rates: Vec<f64>,
    waves: Vec<[f64; 2]>,
    damping_power: f64,
    input_power: f64,
}

impl Run<'_> {
    /// The frames' damping and input powers now.
    fn powers(&self) -> (f64, f64) {
        self.frames
            .iter()
            .enumerate()
            .fold((0.0, 0.0), |(d, i), (k, f)| {
                let (pd, pi) = f.powers(self.at_support(&self.ground_now, k + 1).accel);
                (d + pd, i + pi)
            })
    }

    /// Keeps the state at the step's start for its bookkeeping. It runs after the step has
    /// read the ground at its end: the powers at its start are the ones the last step left.
    fn keep_before(&mut self) {
        let b = &mut self.before;
        b.forces.clear();
        b.forces.extend(self.joints.iter().map(|j| j.force));
        b.deltas.clear();
        b.deltas.extend(self.joints.iter().map(|j| j.delta));
        b.rates.clear();
        b.rates.extend(self.joints.iter().map(|j| j.rate));
        b.waves.clear();
        b.waves.extend_from_slice(&self.waves);
        (b.damping_power, b.input_power) = self.powers_now;
    }

    /// One step from t0 = n h.
    fn step(&mut self, n: usize) {
        let h = self.h;
        let (t0, t1) = (n as f64 * h, (n + 1) as f64 * h);
        let forces_act = !matches!(self.sc.contact, ContactModel::None | ContactModel::Stereo);
        // A step from rest at every joint (no stereomechanical exchange pending) that closes
        // none stays free: what the step's force solve and bookkeeping would find, without them.
        let free_start =
            self.sc.contact != ContactModel::Stereo && self.joints.iter().all(|js| js.force == 0.0);
        self.predict_frames(t0, t1);
        if forces_act {
            self.predict_joints(n + 1);
        }
        if free_start && (!forces_act || self.joints.iter().all(|js| js.k_star <= 0.0)) {
            self.commit_free(t1);
            return;
        }
        if self.ground_stale {
            // The free steps before left the ground across each joint as it was; the step's
            // work on it starts from its start.
            for j in 0..self.joints.len() {
                self.joints[j].ground_difference = self.ground_difference_in(&self.ground_then, j);
            }
            self.ground_stale = false;
        }
        self.keep_before();
        if forces_act {
            self.solve_forces();
            // A quiet girder a force now reaches is stepped again from here: its rings are
            // rebuilt and the step solved again with its stepped prediction.
            while self.revive_pushed() {
                self.predict_joints(n + 1);
                self.solve_forces();
            }
        }
        for j in 0..self.joints.len() {
            self.joints[j].force = if forces_act { self.solved[j].1 } else { 0.0 };
        }
        for i in 0..self.frames.len() {
            let (fl, fr) = (self.joints[i].force, self.joints[i + 1].force);
            self.frames[i].commit(fl - fr, h);
            if let Some(g) = self.girders[i].as_mut() {
                self.waves[i] = girder_step(g, self.predicted[i], [fl, fr]);
            }
        }
        self.read_joints(t1);
        // The powers at the step's end are those the step arrived with: an exchange after it
        // is a jump whose loss the exchange counts itself.
        let powers = self.powers();
        self.powers_now = powers;
        if self.sc.contact == ContactModel::Stereo {
            self.exchange(t1);
            self.powers_now = self.powers();
        }
        self.account(powers, t0, t1);
    }

    /// Ends a step that no joint force acts in: the frames and girders take the states their
    /// predictions found, and of the bookkeeping only the ledger's damping and input change
    /// (every joint's work is zero, no contact starts); the ground across the joints, which
    /// only a force's work reads, is brought up to date at the next step with a force.
    fn commit_free(&mut self, t1: f64) {
        for f in &mut self.frames {
            f.commit_free();
        }
        for (i, g) in self.girders.iter_mut().enumerate() {
            if let Some(g) = g {
                self.waves[i] = girder_step(g, self.predicted[i], [0.0, 0.0]);
            }
        }
        self.read_joints(t1);
        let before = self.powers_now;
        self.powers_now = self.powers();
        let h = self.h;
        self.energy.damping_j += 0.5 * h * (before.0 + self.powers_now.0);
        self.energy.input_j += 0.5 * h * (before.1 + self.powers_now.1);
        self.ground_stale = true;
    }

    /// Stereomechanics: every joint still approaching while overlapped reverses its rigid
    /// closing rate with restitution e, at once (neighbours in turn, until none approaches).
    /// The exchange belongs where the overlap crossed zero inside the step (by its linear
    /// interpolation), so the girders are moved on by their velocity change over the time
    /// since then: without it the contact would be first order in the step.
    fn exchange(&mut self, t: f64) {
        for _ in 0..50 {
            let mut any = false;
            for j in 0..self.joints.len() {
                let d0 = self.before.deltas[j];
                let (delta, rate) = (self.joints[j].delta, self.joints[j].rate);
                if delta <= 0.0 || rate <= 0.0 {
                    continue;
                }
                any = true;
                let joint = self.joints[j].joint;
                let inverse = |m: Member| match m {
                    Member::Girder(i) => self.frames[i].inverse_mass,
                    Member::Abutment => 0.0,
                };
                let w = inverse(joint.left) + inverse(joint.right);
                let impulse = (1.0 + self.sc.restitution) * rate / w;
                let since = if d0 < 0.0 {
                    self.h * delta / (delta - d0)
                } else {
                    0.0
                };
                let energy: f64 = self.frames.iter().map(Frame::energy).sum();
                if let Member::Girder(i) = joint.left {
                    self.frames[i].kick(-impulse, since);
                }
                if let Member::Girder(i) = joint.right {
                    self.frames[i].kick(impulse, since);
                }
                self.energy.contact_j +=
                    energy - self.frames.iter().map(Frame::energy).sum::<f64>();
                self.contacts.push(RawContact {
                    level: j,
                    start_s: t - since,
                    end_s: t - since,
                    peak_force_n: 0.0,
                    impulse_ns: impulse,
                    approach_velocity_m_s: rate,
                });
                for k in 0..self.joints.len() {
                    let (closing, r) = self.closing(k);
                    let js = &mut self.joints[k];
                    js.delta = closing - js.joint.gap_m;
                    js.rate = r;
                }
            }
            if !any {
                break;
            }
        }
    }

    /// The ledger's integrals and the contacts over the step just taken.
    fn account(&mut self, (damping_power, input_power): (f64, f64), t0: f64, t1: f64) {
        let h = self.h;
        let before = std::mem::take(&mut self.before);
        self.energy.damping_j += 0.5 * h * (before.damping_power + damping_power);
        self.energy.input_j += 0.5 * h * (before.input_power + input_power);
        for i in 0..self.waves.len() {
            let (fl, fr) = (
                0.5 * (before.forces[i] + self.joints[i].force),
                0.5 * (before.forces[i + 1] + self.joints[i + 1].force),
            );
            self.energy.girder_waves_j += fl * (self.waves[i][0] - before.waves[i][0])
                - fr * (self.waves[i][1] - before.waves[i][1]);
        }
        let mut in_contact = false;
        for j in 0..self.joints.len() {
            let ground = self.ground_difference(j);
            let js = &mut self.joints[j];
            let (f0, f1) = (before.forces[j], js.force);
            let (d0, d1) = (before.deltas[j], js.delta);
            js.work_delta += 0.5 * (f0 + f1) * (d1 - d0);
            js.work_ground += 0.5 * (f0 + f1) * (ground - js.ground_difference);
            js.ground_difference = ground;
            js.max_force = js.max_force.max(f1);
            in_contact |= f1 > 0.0;
            if f0 <= 0.0 && f1 > 0.0 {
                let start = if d0 < 0.0 && d1 > 0.0 {
                    t0 + h * (-d0) / (d1 - d0)
                } else {
                    t0
                };
                js.v0 = before.rates[j];
                js.open = Some(self.contacts.len());
                self.contacts.push(RawContact {
                    level: j,
                    start_s: start,
                    end_s: t1,
                    peak_force_n: 0.0,
                    impulse_ns: 0.0,
                    approach_velocity_m_s: js.v0,
                });
            }
            if let Some(c) = js.open {
                let c = &mut self.contacts[c];
                c.peak_force_n = c.peak_force_n.max(f1);
                c.impulse_ns += 0.5 * (f0 + f1) * h;
                c.end_s = if f1 > 0.0 {
                    t1
                } else if d0 > 0.0 && d1 <= 0.0 {
                    t0 + h * d0 / (d0 - d1)
                } else {
                    t1
                };
                if f1 <= 0.0 {
                    js.open = None;
                }
            }
        }
        if in_contact {
            self.contact_steps += 1;
        }
        self.before = before;
    }
}

/// Takes a girder's step with its end forces: a quiet girder without force rings on (its
/// predicted waves are its ringing), any other is stepped. Returns its end waves.
fn girder_step(g: &mut GirderWaves, predicted: [f64; 2], forces: [f64; 2]) -> [f64; 2] {
    if g.is_quiet() && forces == [0.0, 0.0] {
        g.skip(1);
        return predicted;
    }
    g.commit(forces);
    g.end_waves(predicted, forces)
}

impl Run<'_> {
    /// Revives every quiet girder the solved forces push at either end; whether any was (its
    /// prediction then changes from the closed form to the stepped one).
    fn revive_pushed(&mut self) -> bool {
        let mut any = false;
        for (i, g) in self.girders.iter_mut().enumerate() {
            let Some(g) = g else { continue };
            let pushed = self.solved[i].1 != 0.0 || self.solved[i + 1].1 != 0.0;
            if pushed && g.is_frozen() {
                g.revive();
                any = true;
            }
        }
        any
    }
}

/// The support of a member of a bridge of `spans` spans: its frame's, or an abutment's (the
/// left one where the abutment is on a joint's left).
fn support_of(spans: usize, member: Member, on_left: bool) -> usize {
    match member {
        Member::Girder(i) => i + 1,
        Member::Abutment if on_left => 0,
        Member::Abutment => spans + 1,
    }
}

/// The histories, kept every `stride` steps.
#[derive(Clone, Default)]
struct Histories {
    time_s: Vec<f64>,
    force: Vec<Vec<f64>>,
    opening: Vec<Vec<f64>>,
    girder: Vec<Vec<f64>>,
    pier: Vec<Vec<f64>>,
    absolute: Vec<Vec<f64>>,
}

impl Histories {
    fn new(joints: usize, spans: usize) -> Self {
        Histories {
            force: vec![Vec::new(); joints],
            opening: vec![Vec::new(); joints],
            girder: vec![Vec::new(); spans],
            pier: vec![Vec::new(); spans],
            absolute: vec![Vec::new(); spans],
            ..Default::default()
        }
    }

    fn reserve(&mut self, samples: usize) {
        self.time_s.reserve(samples);
        for v in [
            &mut self.force,
            &mut self.opening,
            &mut self.girder,
            &mut self.pier,
            &mut self.absolute,
        ] {
            v.iter_mut().for_each(|x| x.reserve(samples));
        }
    }

    fn push(&mut self, run: &Run, t: f64) {
        self.time_s.push(t);
        for (j, js) in run.joints.iter().enumerate() {
            self.force[j].push(js.force);
            self.opening[j].push(-(js.delta + js.joint.gap_m));
        }
        for (i, f) in run.frames.iter().enumerate() {
            self.girder[i].push(f.girder_u());
            self.pier[i].push(f.pier_u());
            self.absolute[i]
                .push(f.girder_u() + run.at_support(&run.ground_now, i + 1).displacement);
        }
    }
}

/// Peaks of each frame over the run.
#[derive(Clone)]
struct Peaks {
    girder: Vec<f64>,
    pier: Vec<f64>,
    bearing: Vec<f64>,
}

impl Peaks {
    /// Frame i's peaks: girder, pier, bearing (the order of `stretch::signal_shapes`).
    fn at(&self, i: usize) -> [f64; 3] {
        [self.girder[i], self.pier[i], self.bearing[i]]
    }

    /// The same, to raise.
    fn of(&mut self, i: usize) -> [&mut f64; 3] {
        [&mut self.girder[i], &mut self.pier[i], &mut self.bearing[i]]
    }

    fn read(&mut self, frames: &[Frame]) {
        let peaks = self
            .girder
            .iter_mut()
            .zip(self.pier.iter_mut().zip(self.bearing.iter_mut()));
        for (f, (girder, (pier, bearing))) in frames.iter().zip(peaks) {
            let (g, p) = (f.girder_u(), f.pier_u());
            *girder = girder.max(g.abs());
            *pier = pier.max(p.abs());
            *bearing = bearing.max((g - p).abs());
        }
    }
}

/// The step of a run of `sc` on a record sampled at `dt`: the target step, shortened to a
/// whole fraction of the record's step so that uniformly excited frames meet every sample.
pub fn step_s(sc: &BridgeScenario, dt: f64) -> f64 {
    let target = sc.target_step_s();
    if dt.is_nan() || dt <= 0.0 {
        return target;
    }
    dt / (dt / target).ceil().max(1.0)
}

/// Solves the bridge under `motion`.
pub fn solve(sc: &BridgeScenario, motion: &GroundMotion) -> Result<BridgeResult, SolveError> {
    solve_with(sc, motion, Control::never())
}

/// [`solve`], reporting its progress to `control` and stopping when it is cancelled.
pub fn solve_with(
    sc: &BridgeScenario,
    motion: &GroundMotion,
    control: &Control,
) -> Result<BridgeResult, SolveError> {
    run_publishing(sc, motion, control, None, Stretches::Taken)
}

/// [`solve`] stepping every grid point between contacts too, instead of jumping over free
/// stretches (the girders still ring in closed form there): what the stretches must find, for
/// tests and comparisons; slower.
pub fn solve_stepped(
    sc: &BridgeScenario,
    motion: &GroundMotion,
) -> Result<BridgeResult, SolveError> {
    run_publishing(sc, motion, Control::never(), None, Stretches::Stepped)
}

/// [`solve_with`] for a run only compared with another (the error estimate's): the same
/// contacts, peaks, largest closings and openings and ledger, without the histories (only the
/// start's sample) and without the girders' waves for drawing (none).
pub fn solve_summary(
    sc: &BridgeScenario,
    motion: &GroundMotion,
    control: &Control,
) -> Result<BridgeResult, SolveError> {
    run_publishing(sc, motion, control, None, Stretches::Summary)
}

/// [`solve`] walking its free stretches grid point by grid point for every signal, where a
/// run checks them against its bounds: the same stretches, exact maps and closed forms, so a
/// run must find what this finds to the bit (what its bounds leave out could not have
/// mattered); for tests; slower.
pub fn solve_walked(
    sc: &BridgeScenario,
    motion: &GroundMotion,
) -> Result<BridgeResult, SolveError> {
    run_publishing(sc, motion, Control::never(), None, Stretches::Walked)
}

/// Whether a run jumps over its free stretches, walks them (every grid point read) or steps
/// them grid point by grid point, and whether it keeps its histories and girder waves.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Stretches {
    Taken,
    Walked,
    Stepped,
    Summary,
}

/// [`solve_with`], handing `publish` what the run has solved so far, at most once per `every`
/// of wall time (its histories, contacts and waves to the instant solved, marked by
/// [`BridgeResult::solved_to_s`]), so a window can draw a long run while it solves. It is
/// called where the run looks at its control (every 4096 steps); `every` zero calls it at each.
pub fn solve_streaming(
    sc: &BridgeScenario,
    motion: &GroundMotion,
    control: &Control,
    every: std::time::Duration,
    publish: &mut dyn FnMut(BridgeResult),
) -> Result<BridgeResult, SolveError> {
    run_publishing(
        sc,
        motion,
        control,
        Some((every, publish)),
        Stretches::Taken,
    )
}

fn run_publishing(
    sc: &BridgeScenario,
    motion: &GroundMotion,
    control: &Control,
    mut publish: Option<(std::time::Duration, &mut dyn FnMut(BridgeResult))>,
    stretches: Stretches,
) -> Result<BridgeResult, SolveError> {
    sc.validate()?;
    let start = std::time::Instant::now();
    let h = step_s(sc, motion.dt_s);
    let duration = motion.duration_s() + sc.delay_s(sc.length_m()).max(0.0);
    let steps = (duration / h).ceil() as usize;
    if steps > sc.max_steps {
        return Err(SolveError::StepBudget {
            max_steps: sc.max_steps,
            needed: steps,
            dt_s: h,
            why: sc.step_advice(),
        });
    }
    let mut run = Run::new(sc, motion, h);
    run.tabulate_stretches(steps);
    run.walk_all = stretches == Stretches::Walked;
    let histories = stretches != Stretches::Summary;
    // A summary records nothing: its only sample is the start's (a grid point it never
    // reaches again).
    let stride = if histories {
        steps.div_ceil(MAX_SAMPLES).max(1)
    } else {
        usize::MAX
    };
    let mut hist = Histories::new(run.joints.len(), sc.spans);
    if histories {
        hist.reserve(steps / stride + 2);
    }
    let mut peaks = Peaks {
        girder: vec![0.0; sc.spans],
        pier: vec![0.0; sc.spans],
        bearing: vec![0.0; sc.spans],
    };
    hist.push(&run, 0.0);
    peaks.read(&run.frames);
    let mut published = start;
    let mut n = 0;
    let mut look_at = 0;
    while n < steps {
        if n >= look_at {
            look_at = n + 4096;
            control.report(n as f64 / steps as f64)?;
            if let Some((every, publish)) = publish.as_mut()
                && n > 0
                && published.elapsed() >= *every
            {
                published = std::time::Instant::now();
                let so_far = (n as f64 * h).min(duration);
                publish(finish(
                    &run,
                    run.contacts.clone(),
                    hist.clone(),
                    peaks.clone(),
                    (duration, so_far),
                    n,
                    start,
                ));
            }
        }
        let mut sink = stretch::Sink {
            hist: &mut hist,
            peaks: &mut peaks,
            stride,
            steps,
        };
        let taken = match stretches {
            Stretches::Taken | Stretches::Summary | Stretches::Walked => {
                run.free_stretch(n, &mut sink)
            }
            Stretches::Stepped => {
                run.settle_if_free();
                0
            }
        };
        if taken > 0 {
            n += taken;
        } else {
            run.step(n);
            n += 1;
            peaks.read(&run.frames);
            if histories && (n.is_multiple_of(stride) || n == steps) {
                hist.push(&run, n as f64 * h);
            }
        }
        // x * 0 is zero for every finite x and NaN otherwise: one sum tells them all apart.
        let not_finite: f64 = run
            .frames
            .iter()
            .map(|f| (f.q[0] * 0.0 + f.q[1] * 0.0) + (f.v[0] * 0.0 + f.v[1] * 0.0))
            .sum();
        if not_finite != 0.0 {
            return Err(SolveError::Diverged {
                at_s: n as f64 * h,
                why: "the frames' motion is no longer finite; lower solver.max_step or the contact stiffness".into(),
            });
        }
    }
    if !histories {
        run.girders.iter_mut().for_each(|g| *g = None);
    }
    let contacts = std::mem::take(&mut run.contacts);
    Ok(finish(
        &run,
        contacts,
        hist,
        peaks,
        (duration, duration),
        steps,
        start,
    ))
}

/// The result of the run to `steps` steps, `solved_to` of its `duration` (the two equal once
/// it is whole), with its contacts so far.
fn finish(
    run: &Run,
    contacts: Vec<RawContact>,
    hist: Histories,
    peaks: Peaks,
    (duration, solved_to): (f64, f64),
    steps: usize,
    start: std::time::Instant,
) -> BridgeResult {
    let sc = run.sc;
    let mut energy = run.energy;
    energy.final_j = run.frames.iter().map(Frame::energy).sum();
    for js in &run.joints {
        let stored = if js.force > 0.0 {
            js.element.stored_energy(js.delta.max(0.0))
        } else {
            0.0
        };
        energy.stored_contact_j += stored;
        energy.contact_j += js.work_delta - stored;
        energy.differential_j += js.work_ground;
    }
    // Work on the frames by the joints = differential - waves - element work; the element
    // work was counted as contact (less what is stored), the waves as girder waves.
    let unseating: Vec<Unseating> = run
        .joints
        .iter()
        .enumerate()
        .filter_map(|(j, js)| {
            js.unseated.map(|t| Unseating {
                joint: j,
                time_s: t,
            })
        })
        .collect();
    let mut warnings: Vec<String> = unseating
        .iter()
        .map(|u| {
            format!(
                "joint {} unseated at {:.3} s: it opened further than the seat length {} m",
                u.joint,
                u.time_s,
                crate::model::settings::shown(sc.seat_length_m)
            )
        })
        .collect();
    if energy.balance_error().abs() > 1e-3 {
        warnings.push(format!(
            "the energy ledger misses {:.2e} of the input: refine solver.steps_per_scale",
            energy.balance_error()
        ));
    }
    let impacts = group_impacts(&contacts, sc.merge_gap_s);
    let max_force_by_joint_n: Vec<f64> = run.joints.iter().map(|j| j.max_force).collect();
    BridgeResult {
        contact: sc.contact,
        joints: run.joints.iter().map(|j| j.joint).collect(),
        time_s: hist.time_s,
        joint_force_n: hist.force,
        joint_opening_m: hist.opening,
        girder_displacement_m: hist.girder,
        pier_displacement_m: hist.pier,
        girder_absolute_m: hist.absolute,
        contacts,
        impacts,
        max_pounding_force_n: max_force_by_joint_n.iter().copied().fold(0.0, f64::max),
        max_force_by_joint_n,
        max_closing_m: run.joints.iter().map(|j| j.max_closing).collect(),
        max_opening_m: run.joints.iter().map(|j| j.max_opening).collect(),
        unseating,
        peak_girder_displacement_m: peaks.girder,
        peak_pier_displacement_m: peaks.pier,
        peak_bearing_displacement_m: peaks.bearing,
        girder_waves: run
            .girders
            .iter()
            .flatten()
            .map(|g| g.waves(steps as f64 * run.h))
            .collect(),
        energy,
        stats: BridgeStats {
            steps,
            contact_steps: run.contact_steps,
            step_s: run.h,
            steps_per_scale: sc.steps_per_scale(),
            wall_time_s: start.elapsed().as_secs_f64(),
        },
        duration_s: duration,
        solved_to_s: solved_to,
        warnings,
    }
}
