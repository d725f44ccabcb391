//! The contact step: Newmark's average acceleration with the contact forces implicit, the
//! levels in contact solved together. Its buffers live in a [`Scratch`] kept for the whole run,
//! and the compliance of the points over a whole grid step (the same at every such step) is
//! computed once. A pair with one contact level takes, inside its contacts, the same step
//! written out for that level (`contact/single.rs`), bit for bit this one's.

use super::yielding::MAX_PASSES;
use super::*;
use crate::model::building::slab::Prediction;
use std::cmp::Reverse;
use std::collections::BinaryHeap;

mod single;

/// A contact step computed but not taken.
#[derive(Default)]
pub(super) struct Trial {
    hh: f64,
    ground: f64,
    /// The modal displacements' increments.
    dq: [Vec<f64>; 2],
    forces: Vec<f64>,
    deltas: Vec<f64>,
    rates: Vec<f64>,
    /// The level whose Kelvin-Voigt link let go at the end of this (shortened) step.
    released: Option<usize>,
    /// Each mode's load from the forces at the step's end, per side: the next step's
    /// `load_now`, summed as [`Stepper::contact_loads`] sums it (made again by it where the
    /// committed forces are not the trial's).
    load: [Vec<f64>; 2],
}

/// The contact step's buffers.
#[derive(Default)]
pub(super) struct Scratch {
    k_hat: [Vec<f64>; 2],
    step: [Vec<f64>; 2],
    /// Each point's overlap at the step's end without new forces.
    predicted: Vec<f64>,
    /// The compliance G (points x points, row-major) of the step being tried.
    g: Vec<f64>,
    /// G over a whole grid step, once computed, and whether the step tried reads it.
    g_full: Option<Vec<f64>>,
    use_full: bool,
    /// The slabs' instantaneous compliance, per point.
    compliance: Vec<f64>,
    /// Per point: out of reach this step (its slabs' ringing not read), the bound on that
    /// ringing, and whether it was found within reach after all (then read exactly).
    far: Vec<bool>,
    far_bound: Vec<f64>,
    near_forced: Vec<bool>,
    /// Whether any entry of `near_forced` is set (a step clears them only then).
    any_near_forced: bool,
    /// The ground acceleration where the step starts.
    ground0: f64,
    /// Each mode's load from the contact forces where the step starts, per side.
    load_now: [Vec<f64>; 2],
    /// Per point: shown out of reach since the contact phase began without reading it (its
    /// closing is not evaluated, it takes no part in the step).
    asleep: Vec<bool>,
    /// The sleeping levels, each under its proven lower bound on its gap less its closing and
    /// its slabs' ringing.
    sleep: Sleepers,
    /// The points the step reads: in contact or within reach, in ascending order.
    awake: Vec<usize>,
    trial: Trial,
    /// Each side's modal displacements and velocities where the step started.
    modal_before: [[Vec<f64>; 2]; 2],
    /// Each awake point's closing where the step started (its work's displacement).
    u_before: Vec<f64>,
    /// The step count at whose end each point's closing went into `u_before` (the closing
    /// where the next step starts, if no other step came between).
    closing_step: Vec<usize>,
    /// Yielding storeys: each side's load of their corrections at the trial's end, per mode.
    pseudo1: [Vec<f64>; 2],
    /// The trial leaves every yielding storey inside its elastic range
    /// ([`Storeys::quiet`](super::yielding::Storeys::quiet)): the laws are not followed and
    /// the corrections stay.
    quiet: bool,
    /// The trial's storeys were followed to its end ([`Stepper::contact_end_loads`]) with the
    /// modes it moved: its commit takes their ends as they are.
    followed: bool,
    /// Each side's dq of the trial whose storeys were last followed.
    followed_dq: [Vec<f64>; 2],
    /// Per point, its slabs' predictions for the step, made by the trial, read by the commit
    /// (a live slab's, of every point the step reads: a point far out of reach has no live
    /// slab).
    slab_predictions: Vec<[Prediction; 2]>,
}

/// The levels asleep in a contact phase, looked at only when the steps could have moved one
/// out of its margin: a step moves a level's closing by at most its projections' sizes times
/// the sizes of each side's dq (Cauchy-Schwarz), so the steps' sizes summed per side since a
/// level's margin was found bound what they took of it. A heap orders the levels by the sum
/// (of both sides', against the larger of its two sizes) at which their margin could be gone.
#[derive(Default)]
struct Sleepers {
    /// Each side's dq sizes summed over the phase's steps taken.
    moved: [f64; 2],
    /// Per level: its margin, and `moved` where it was found.
    base: Vec<(f64, [f64; 2])>,
    /// The levels asleep, by the sum of both sides' `moved` at which each must be looked at
    /// (the bits of a non-negative float order as it does).
    due: BinaryHeap<Reverse<(u64, usize)>>,
    /// The levels the trial looked at: each with its key in `due`, and its margin at the
    /// trial's end (NaN for one that woke).
    looked: Vec<(u64, usize, f64)>,
    /// The sizes of the trial's dq per side.
    trial: [f64; 2],
}

impl Sleepers {
    /// The margin of a level whose projections' sizes are `norm` once the sides' dq sizes have
    /// summed to `moved`: less a hair over the Cauchy-Schwarz bound, which covers the round-off
    /// of the sums.
    fn left(&self, i: usize, norm: [f64; 2], moved: [f64; 2]) -> f64 {
        let (margin, at) = self.base[i];
        margin - (norm[0] * (moved[0] - at[0]) + norm[1] * (moved[1] - at[1])) * (1.0 + 1e-9)
    }

    /// Level i asleep with `margin` where the sides' dq sizes sum to `moved`.
    fn keep(&mut self, i: usize, norm: [f64; 2], margin: f64, moved: [f64; 2]) {
        self.base[i] = (margin, moved);
        // The sum at which the margin could be gone, a hair early: below the rounding of the
        // sums it is compared with (a level due at once is looked at every step, as before).
        let key = ((moved[0] + moved[1]) + margin / (norm[0].max(norm[1]) * (1.0 + 2e-9)))
            * (1.0 - 1e-12);
        self.due.push(Reverse((key.max(0.0).to_bits(), i)));
    }

    /// The levels the last trial looked at back in the heap as they were (the step is made
    /// again).
    fn put_back(&mut self) {
        if self.looked.is_empty() {
            return;
        }
        for (key, i, _) in self.looked.drain(..) {
            self.due.push(Reverse((key, i)));
        }
    }
}

impl Scratch {
    /// The buffers for sides of `modes` modes and `points` contact points, sized once for the
    /// whole run: a contact step resizes none of them.
    pub(super) fn sized(modes: [usize; 2], points: usize) -> Box<Self> {
        let per_mode = || modes.map(|n| vec![0.0; n]);
        let per_point = || vec![0.0; points];
        Box::new(Scratch {
            k_hat: per_mode(),
            step: per_mode(),
            predicted: per_point(),
            compliance: per_point(),
            far: vec![false; points],
            far_bound: per_point(),
            near_forced: vec![false; points],
            load_now: per_mode(),
            asleep: vec![false; points],
            sleep: Sleepers {
                base: vec![(0.0, [0.0; 2]); points],
                ..Sleepers::default()
            },
            trial: Trial {
                dq: per_mode(),
                forces: per_point(),
                deltas: per_point(),
                rates: per_point(),
                load: per_mode(),
                ..Trial::default()
            },
            modal_before: modes.map(|n| [vec![0.0; n], vec![0.0; n]]),
            u_before: per_point(),
            closing_step: vec![usize::MAX; points],
            slab_predictions: vec![Default::default(); points],
            ..Scratch::default()
        })
    }

    /// No point is held within reach by the last step's forces any more.
    fn clear_near_forced(&mut self) {
        if self.any_near_forced {
            self.near_forced.fill(false);
            self.any_near_forced = false;
        }
    }
}

impl Stepper<'_> {
    /// One implicit step of every level in contact, to the next grid point (or a Kelvin-Voigt
    /// link's release inside it): the single level's step where it applies
    /// ([`Stepper::single_level_step`]), the general one elsewhere.
    pub(super) fn contact_step(&mut self) -> Result<(), SolveError> {
        if self.single_level_step() {
            return self.contact_step_single();
        }
        self.contact_step_of(self.grid.h - self.offset)
    }

    /// A contact step of length hh (the last one of a graded start lands on the grid).
    pub(super) fn contact_step_of(&mut self, hh: f64) -> Result<(), SolveError> {
        self.count_step()?;
        let mut cs = self
            .contact_scratch
            .take()
            .expect("the scratch is home between stages");
        if self.newmark {
            // Straight after a contact step (Newmark's steps go on until a free step), the loads
            // are the ones it committed, already summed.
            std::mem::swap(&mut cs.load_now, &mut cs.trial.load);
        } else {
            self.start_contact_phase(&mut cs);
        }
        // The levels awake where the last step ended (every level where a phase starts): a
        // level asleep stays so until `wake_reached` wakes it.
        let mut fell_asleep = false;
        for j in 0..cs.awake.len() {
            let i = cs.awake[j];
            if self.points[i].force <= 0.0 {
                self.follow_free_level(i, &mut cs);
                fell_asleep |= cs.asleep[i];
            }
        }
        if fell_asleep {
            let asleep = &cs.asleep;
            cs.awake.retain(|&i| !asleep[i]);
        }
        cs.ground0 = self.motion.at(self.time());
        cs.clear_near_forced();
        // A sleeping level the step could have brought within reach wakes, and the step is made
        // again with it.
        loop {
            self.try_step(hh, &mut cs);
            if !self.wake_reached(&mut cs) {
                break;
            }
        }
        self.commit_contact(&mut cs);

        self.contact_scratch = Some(cs);
        Ok(())
    }

    /// Where a contact phase starts: the loads of the forces now, and Newmark's accelerations
    /// from them. Out of line (once a phase), so that the steps' code keeps its registers.
    #[cold]
    #[inline(never)]
    fn start_contact_phase(&mut self, cs: &mut Scratch) {
        self.contact_loads(&mut cs.load_now);
        self.start_contact_proofs();
        self.equilibrium_accelerations(&cs.load_now);
        self.newmark = true;
        // The free stretch before moved every level: none is known to be out of reach.
        cs.asleep.fill(false);
        cs.awake.clear();
        cs.awake.extend(0..self.points.len());
        cs.sleep.due.clear();
        cs.sleep.looked.clear();
        cs.sleep.moved = [0.0; 2];
    }

    /// A level out of contact follows the motion: its overlap and rate are the kinematics now,
    /// not what they were when it last let go; or, where its quiet slabs' ringing cannot close
    /// the gap, it sleeps (its overlap unread until it wakes), and is only read again once the
    /// steps' motion could have used up its margin.
    #[inline(never)]
    fn follow_free_level(&mut self, i: usize, cs: &mut Scratch) {
        let n = self.n;
        let (c, w) = self.point_now(i);
        let p = &mut self.points[i];
        let bound = p.elastic_bound_from(n);
        if c - self.sc.gap_m + bound < 0.0 {
            cs.asleep[i] = true;
            let moved = cs.sleep.moved;
            cs.sleep.keep(i, p.norm, self.sc.gap_m - c - bound, moved);
        } else {
            p.delta = c - self.sc.gap_m - p.elastic_at(n);
            p.rate = w;
        }
    }

    /// The step of length hh into `cs.trial`, made again where a level turns out within reach or
    /// a slab starts stepping, and ended early where a Kelvin-Voigt link lets go.
    fn try_step(&mut self, hh: f64, cs: &mut Scratch) {
        self.trial(hh, cs);
        // A level left out of reach may have been reached after all (the other levels' forces
        // can pull it closer): then it is read exactly and the step made again.
        if self.sears && self.reach_back(cs) {
            self.trial(hh, cs);
        }
        // A quiet slab (its waves only ringing) starts stepping where its level is pushed.
        if self.sears && self.revive_pushed(&cs.awake, &cs.trial.forces) {
            self.trial(hh, cs);
        }
        // A Kelvin-Voigt link lets go where k delta + c delta' reaches zero, inside the step.
        let kelvin = self.sc.contact == ContactModel::Kelvin;
        let released = cs.awake.iter().copied().find(|&i| {
            kelvin
                && self.points[i].force > 0.0
                && cs.trial.forces[i] <= 0.0
                && cs.trial.deltas[i] > 0.0
        });
        if let Some(i) = released {
            let push = |x: f64, cs: &mut Scratch| {
                self.trial(x * hh, cs);
                let p = &self.points[i];
                p.element.push(cs.trial.deltas[i], cs.trial.rates[i], p.v0)
            };
            let x = bracket(|x| push(x, cs), 0.0, 1.0, 1e-12)
                .second_side
                .max(1e-9);
            self.trial(x * hh, cs);
            cs.trial.forces[i] = 0.0;
            cs.trial.released = Some(i);
        }
    }

    /// Each sleeping level's margin after the trial: less the most the steps' modal increments
    /// can have moved it since it was found, or, where that leaves none, read exactly at the
    /// trial's end. Only the levels whose margin the steps could have used up are looked at
    /// ([`Sleepers`]). A level whose exact reading finds it within reach wakes (read exactly
    /// where the step starts); whether any did, and the step must be made again.
    fn wake_reached(&mut self, cs: &mut Scratch) -> bool {
        cs.sleep.put_back();
        if cs.awake.len() == self.points.len() {
            return false;
        }
        // A tall side's sum in lanes: a bound's size, which only decides when a level is read.
        let size: [f64; 2] = std::array::from_fn(|s| dotv(&cs.trial.dq[s], &cs.trial.dq[s]).sqrt());
        cs.sleep.trial = size;
        let moved = [cs.sleep.moved[0] + size[0], cs.sleep.moved[1] + size[1]];
        let total = moved[0] + moved[1];
        let (n, gap) = (self.n, self.sc.gap_m);
        let mut any = false;
        while let Some(&Reverse((key, i))) = cs.sleep.due.peek() {
            if f64::from_bits(key) > total {
                break;
            }
            cs.sleep.due.pop();
            let p = &self.points[i];
            let left = cs.sleep.left(i, p.norm, moved);
            if left > 0.0 {
                cs.sleep.looked.push((key, i, left));
                continue;
            }
            let exact = gap - self.closing_after(p, &cs.trial.dq) - p.elastic_bound_from(n + 1);
            if exact > 0.0 {
                cs.sleep.looked.push((key, i, exact));
                continue;
            }
            cs.sleep.looked.push((key, i, f64::NAN));
            let (c, w) = self.point_now(i);
            let p = &mut self.points[i];
            p.delta = c - gap - p.elastic_at(n);
            p.rate = w;
            cs.asleep[i] = false;
            any = true;
        }
        if any {
            // The woken levels go into the step, which is made again: the others go back.
            cs.sleep.looked.retain(|l| !l.2.is_nan());
            cs.awake.clear();
            cs.awake
                .extend((0..self.points.len()).filter(|&i| !cs.asleep[i]));
        }
        any
    }

    /// Whether a level the trial left out of reach could have been reached: its overlap with
    /// the trial's forces, its ringing at its largest, is not below zero. Such a level is read
    /// exactly from now on in this step.
    fn reach_back(&self, cs: &mut Scratch) -> bool {
        let np = self.points.len();
        let mut any = false;
        for &i in &cs.awake {
            if !cs.far[i] {
                continue;
            }
            let g = if cs.use_full {
                cs.g_full.as_ref().expect("made")
            } else {
                &cs.g
            };
            let others: f64 = cs
                .awake
                .iter()
                .map(|&j| g[i * np + j] * cs.trial.forces[j])
                .sum();
            if cs.predicted[i] + cs.far_bound[i] - others >= 0.0 {
                cs.far[i] = false;
                cs.near_forced[i] = true;
                cs.any_near_forced = true;
                any = true;
            }
        }
        any
    }

    /// Revives the quiet slabs of every level the trial pushes (only the `awake` ones take part
    /// in it); whether there were any (the trial must then be made again, with their stepped
    /// waves).
    fn revive_pushed(&mut self, awake: &[usize], forces: &[f64]) -> bool {
        let n = self.n;
        let mut any = false;
        for &i in awake {
            if forces[i] > 0.0 {
                for slab in self.points[i].slabs.iter_mut().flatten() {
                    if !slab.is_live() {
                        slab.revive(n);
                        any = true;
                    }
                }
            }
        }
        any
    }

    /// Each mode's load from the points' contact forces, per side, into `loads`: point by point,
    /// each mode's sum in the points' order.
    fn contact_loads(&self, loads: &mut [Vec<f64>; 2]) {
        for (s, load) in loads.iter_mut().enumerate() {
            let sign = if s == 0 { -1.0 } else { 1.0 };
            load.clear();
            load.resize(self.sides[s].modes(), 0.0);
            for p in self.points.iter().filter(|p| p.force != 0.0) {
                for (l, r) in load.iter_mut().zip(&p.r[s]) {
                    *l += sign * r * p.force;
                }
            }
        }
    }

    /// Newmark's step needs accelerations that satisfy the equations of motion where it starts:
    /// q'' = g - 2 zeta w q' - w^2 q with the ground's and the contact forces (`load`, per side
    /// and mode) at this instant.
    fn equilibrium_accelerations(&mut self, load: &[Vec<f64>; 2]) {
        let ground = self.motion.at(self.time());
        for (side, load) in self.sides.iter_mut().zip(load) {
            for (k, contact) in load.iter().enumerate() {
                side.a[k] = -side.gamma[k] * ground + contact + side.pseudo_now(k)
                    - 2.0 * side.zeta[k] * side.omega[k] * side.v[k]
                    - side.omega[k].powi(2) * side.q[k];
            }
        }
    }

    /// A point's closing (left less right) with each side's modes at q plus `inc`.
    #[inline(always)]
    fn closing_after(&self, p: &Point, inc: &[Vec<f64>; 2]) -> f64 {
        self.closing_after_of(p, inc, [p.r[0].len(), p.r[1].len()])
    }

    /// [`Stepper::closing_after`] with each side's modes counted (`n`: a caller that knows them
    /// lets the compiler unroll the sums).
    #[inline(always)]
    fn closing_after_of(&self, p: &Point, inc: &[Vec<f64>; 2], n: [usize; 2]) -> f64 {
        let mut moved = [0.0; 2];
        for (s, out) in moved.iter_mut().enumerate() {
            let n = n[s];
            let r = &p.r[s][..n];
            let (q, inc) = (&self.sides[s].q[..n], &inc[s][..n]);
            if n >= lanes::LANES_FROM {
                *out = lanes::dot_moved(r, q, inc);
                continue;
            }
            for k in 0..n {
                *out += r[k] * (q[k] + inc[k]);
            }
        }
        moved[0] - moved[1]
    }

    /// A contact step of length hh, not yet taken, into `cs.trial`; where storeys yield, with
    /// their corrections at its end found by the fixed point.
    fn trial(&self, hh: f64, cs: &mut Scratch) {
        if !self.yields() {
            return self.trial_once(hh, cs);
        }
        for s in 0..2 {
            match &self.sides[s].storeys {
                Some(st) => st.guess_into(hh.max(0.0), &mut cs.pseudo1[s]),
                None => cs.pseudo1[s].clear(),
            }
        }
        cs.quiet = false;
        cs.followed = false;
        // A step of no length (the release search's end point) has no end state to correct.
        if hh <= 0.0 {
            return self.trial_once(hh, cs);
        }
        for pass in 0..MAX_PASSES {
            self.trial_once(hh, cs);
            if pass == 0 && self.trial_is_quiet(hh, cs) {
                cs.quiet = true;
                return;
            }
            if pass > 0 && self.trial_is_settled(cs) {
                cs.followed = true;
                break;
            }
            for (keep, dq) in cs.followed_dq.iter_mut().zip(&cs.trial.dq) {
                keep.clone_from(dq);
            }
            let mut pseudo1 = std::mem::take(&mut cs.pseudo1);
            let change = self.contact_end_loads(&cs.trial.dq, hh, &mut pseudo1);
            cs.pseudo1 = pseudo1;
            if change <= 1e-13 {
                cs.followed = true;
                break;
            }
        }
    }

    /// Whether the trial just made, with the loads the last pass's storeys left, moved the modes
    /// so little from the trial those storeys followed that following them again would change
    /// the loads by round-off ([`Storeys::settled_by`](super::yielding::Storeys::settled_by)):
    /// its commit takes that pass's ends, whose loads it was made with.
    fn trial_is_settled(&self, cs: &Scratch) -> bool {
        (0..2).all(|s| {
            let Some(st) = self.sides[s].storeys.as_ref() else {
                return true;
            };
            let moved = cs.trial.dq[s]
                .iter()
                .zip(&cs.followed_dq[s])
                .map(|(a, b)| (a - b) * (a - b))
                .sum::<f64>()
                .sqrt();
            st.settled_by(moved, &cs.pseudo1[s])
        })
    }

    /// Whether the trial just made, with the corrections as they are, leaves every yielding
    /// storey of both sides inside its elastic range.
    fn trial_is_quiet(&self, hh: f64, cs: &Scratch) -> bool {
        (0..2).all(|s| {
            let side = &self.sides[s];
            let Some(st) = side.storeys.as_ref() else {
                return true;
            };
            // A trial made with loads on the move (`Storeys::guess_into`) is not the quiet one.
            if cs.pseudo1[s] != st.load0 {
                return false;
            }
            let n = side.modes();
            let dq = &cs.trial.dq[s];
            let v1: Vec<f64> = (0..n)
                .map(|k| lanes::newmark_end(dq[k], side.v[k], side.a[k], hh).0)
                .collect();
            st.quiet(&side.q, &side.v, dq, &v1, hh)
        })
    }

    /// The contact step of length hh with the storeys' corrections at its end as in
    /// `cs.pseudo1` (none where they are elastic).
    fn trial_once(&self, hh: f64, cs: &mut Scratch) {
        let ground = self.motion.at(self.time() + hh);
        // A whole grid step: each mode's effective stiffness is the side's, computed once.
        let full = (hh - self.grid.h).abs() <= 1e-12 * hh;
        if full && self.lanes_increment {
            self.free_increment_in_lanes(hh, ground, cs);
        } else {
            self.free_increment(hh, full, ground, cs);
        }
        self.contact_compliance(full, cs);
        self.contact_forces(hh, cs);
        self.end_trial(full, hh, ground, cs);
    }

    /// The trial's end, once its forces are found: the modal loads and increments with them,
    /// and the step it is (of length hh, the ground at its end given, no link let go).
    #[inline(always)]
    fn end_trial(&self, full: bool, hh: f64, ground: f64, cs: &mut Scratch) {
        if self.tall {
            self.trial_loads_tall(full, cs);
        } else {
            self.trial_loads(full, cs, false);
        }
        let out = &mut cs.trial;
        out.hh = hh;
        out.ground = ground;
        out.released = None;
    }

    /// The trial's modal loads from the contact forces and its increments with them, side by
    /// side (`tall`: a tall side's in vector lanes).
    #[inline(always)]
    fn trial_loads(&self, full: bool, cs: &mut Scratch, tall: bool) {
        let out = &mut cs.trial;
        // Where one point pushes (as in most of a contact's steps), a tall side takes its load
        // and its increments in one pass.
        let pusher = if tall {
            pushing_one(&cs.awake, &out.forces)
        } else {
            None
        };
        for s in 0..2 {
            let sign = if s == 0 { -1.0 } else { 1.0 };
            let k_hat = self.step_k_hat(&cs.k_hat, s, full);
            // Rounding is symmetric, so the sign taken out of a mode's sum changes no bit of it:
            // each mode's end is `lanes::with_force` of its sum without the sign.
            if let [k_hat] = k_hat {
                // One mode: its sum straight from the points, in the points' order.
                let mut f = 0.0;
                for &i in &cs.awake {
                    let force = out.forces[i];
                    if force != 0.0 {
                        f += self.points[i].r[s][0] * force;
                    }
                }
                (out.dq[s][0], out.load[s][0]) = lanes::with_force(cs.step[s][0], f, *k_hat, sign);
                continue;
            }
            // A tall side's sums four modes a register (the same terms in the same order).
            let in_lanes = tall && k_hat.len() >= lanes::LANES_FROM;
            if in_lanes && let Some(i) = pusher {
                let r = &self.points[i].r[s];
                let (dq, load) = (&mut out.dq[s], &mut out.load[s]);
                lanes::with_one_force(dq, load, &cs.step[s], k_hat, r, out.forces[i], sign);
                continue;
            }
            // Each mode's sum, in the points' order, made point by point in `load`: a pass over
            // the modes for each point that pushes, which the compiler puts in vector lanes.
            let sums = &mut out.load[s][..];
            sums.fill(0.0);
            for &i in &cs.awake {
                let force = out.forces[i];
                if force == 0.0 {
                    continue;
                }
                let r = &self.points[i].r[s];
                if in_lanes {
                    lanes::add_scaled(sums, r, force);
                } else {
                    for (f, r) in sums.iter_mut().zip(r) {
                        *f += r * force;
                    }
                }
            }
            if in_lanes {
                lanes::with_forces(&mut out.dq[s], &mut out.load[s], &cs.step[s], k_hat, sign);
                continue;
            }
            let each = out.dq[s].iter_mut().zip(out.load[s].iter_mut());
            for ((dq, load), (step, k_hat)) in each.zip(cs.step[s].iter().zip(k_hat)) {
                (*dq, *load) = lanes::with_force(*step, *load, *k_hat, sign);
            }
        }
    }

    /// [`Stepper::trial_loads`] where a side is tall: out of the few modes' way, whose step
    /// keeps its registers.
    #[cold]
    #[inline(never)]
    fn trial_loads_tall(&self, full: bool, cs: &mut Scratch) {
        self.trial_loads(full, cs, true);
    }

    /// Side s's effective stiffness per mode over the step being tried: the side's own over a
    /// whole grid step (`full`), the one [`Stepper::free_increment`] `made` for a shorter one.
    fn step_k_hat<'a>(&'a self, made: &'a [Vec<f64>; 2], s: usize, full: bool) -> &'a [f64] {
        if full { &self.sides[s].k_hat } else { &made[s] }
    }

    /// Newmark's step in incremental form, k_hat dq = dp + (4/h + 2c) v + 2a, so that short
    /// steps lose nothing to cancellation: each mode's increment over hh without a change of the
    /// contact forces (the ground at the step's end given), and, for a step shorter than the
    /// grid's (`full` false), its effective stiffness.
    fn free_increment(&self, hh: f64, full: bool, ground: f64, cs: &mut Scratch) {
        let ground_change = ground - cs.ground0;
        for s in 0..2 {
            let n = self.sides[s].modes();
            self.free_increment_of(s, n, hh, full, ground_change, cs);
        }
    }

    /// [`Stepper::free_increment`] for side s of n modes, the ground's change over the step
    /// given.
    #[inline(always)]
    fn free_increment_of(
        &self,
        s: usize,
        n: usize,
        hh: f64,
        full: bool,
        ground_change: f64,
        cs: &mut Scratch,
    ) {
        {
            let side = &self.sides[s];
            // Every array sliced to the modes, so that the loop reads them unchecked.
            let (k_hat, step) = (&mut cs.k_hat[s][..n], &mut cs.step[s][..n]);
            let (omega, zeta, gamma) = (&side.omega[..n], &side.zeta[..n], &side.gamma[..n]);
            let (v, a, full_k_hat) = (&side.v[..n], &side.a[..n], &side.k_hat[..n]);
            let load_now = &cs.load_now[s][..n];
            let pseudo = side
                .storeys
                .as_ref()
                .map(|st| (&cs.pseudo1[s][..n], &st.load0[..n]));
            for k in 0..n {
                let kh = if full {
                    full_k_hat[k]
                } else {
                    newmark_k_hat(omega[k], zeta[k], hh)
                };
                let pseudo_change = match pseudo {
                    Some((end, now)) => end[k] - now[k],
                    None => 0.0,
                };
                let mode = [omega[k], zeta[k], gamma[k]];
                let load = lanes::increment_load(
                    mode,
                    ground_change,
                    load_now[k],
                    pseudo_change,
                    v[k],
                    a[k],
                    hh,
                );
                if !full {
                    k_hat[k] = kh;
                }
                step[k] = load / kh;
            }
        }
    }

    /// [`Stepper::free_increment`] over a whole grid step where a side is tall and elastic: its
    /// modes in vector lanes ([`lanes::increment`]; each mode's terms as the few modes' loop
    /// takes them, so the same bits). Out of the few modes' way, whose step keeps its registers.
    #[cold]
    #[inline(never)]
    fn free_increment_in_lanes(&self, hh: f64, ground: f64, cs: &mut Scratch) {
        let ground_change = ground - cs.ground0;
        for s in 0..2 {
            let side = &self.sides[s];
            if side.storeys.is_some() || side.modes() < lanes::LANES_FROM {
                self.free_increment_of(s, side.modes(), hh, true, ground_change, cs);
                continue;
            }
            let e = lanes::Increment {
                coefficients: [&side.omega, &side.zeta, &side.gamma],
                v: &side.v,
                a: &side.a,
                k_hat: &side.k_hat,
                load_now: &cs.load_now[s],
                hh,
                ground_change,
            };
            lanes::increment(&e, &mut cs.step[s][..side.modes()]);
        }
    }

    /// Each contact point's overlap at the step's end without new forces, less the gap (and
    /// the slabs' predicted elastic part), and the compliance G: delta_p = predicted_p -
    /// sum_q G_pq F_q.
    fn contact_compliance(&self, full: bool, cs: &mut Scratch) {
        let np = self.points.len();
        let next = self.n + 1;
        for &i in &cs.awake {
            let p = &self.points[i];
            let closing = self.closing_after(p, &cs.step) - self.sc.gap_m;
            let (mut e0, mut e1) = (0.0, 0.0);
            cs.far[i] = false;
            if self.sears {
                // A level without force whose slabs only ring, and whose ringing at its largest
                // cannot close the gap, is out of reach: its ringing is not read (the trial is
                // checked against it afterwards).
                let bound = if p.force <= 0.0 && !cs.near_forced[i] {
                    p.elastic_bound_from(next)
                } else {
                    f64::INFINITY
                };
                if closing + bound < 0.0 {
                    cs.far[i] = true;
                    cs.far_bound[i] = bound;
                    e1 = p.instant_compliance();
                } else {
                    (e0, e1) = predict_slabs(p, next, &mut cs.slab_predictions[i], false);
                }
            }
            cs.predicted[i] = closing - e0;
            cs.compliance[i] = e1;
        }
        cs.use_full = full && cs.g_full.is_some();
        if cs.use_full {
            return;
        }
        cs.g.clear();
        cs.g.resize(np * np, 0.0);
        // The whole-step G is kept for every later step, so it is made for every point; another
        // step's only for the points it reads.
        let every: Vec<usize>;
        let rows: &[usize] = if full {
            for i in (0..np).filter(|&i| cs.asleep[i]) {
                cs.compliance[i] = self.points[i].instant_compliance();
            }
            every = (0..np).collect();
            &every
        } else {
            &cs.awake
        };
        for &i in rows {
            let p = &self.points[i];
            for &j in rows {
                let o = &self.points[j];
                let mut g = 0.0;
                for s in 0..2 {
                    let k_hat = self.step_k_hat(&cs.k_hat, s, full);
                    let mut part = 0.0;
                    for (k, k_hat) in k_hat.iter().enumerate() {
                        part += p.r[s][k] * o.r[s][k] / k_hat;
                    }
                    g += part;
                }
                cs.g[i * np + j] = g;
            }
            // The slabs' instantaneous compliance minus their rigid part can be a hair below
            // zero (the storeys' springs and dampers stiffen the rigid response): clamp.
            cs.g[i * np + i] = (cs.g[i * np + i] + cs.compliance[i]).max(0.0);
        }
        if full {
            cs.g_full = Some(cs.g.clone());
            cs.use_full = true;
        }
    }

    /// The contact forces at the step's end, with each point's overlap and its rate, by
    /// nonlinear Gauss-Seidel: each level's monotone scalar equation with the others' forces
    /// fixed, swept until the forces settle (one sweep for one level; the levels couple through
    /// the storeys only, weakly over a fine step).
    fn contact_forces(&self, hh: f64, cs: &mut Scratch) {
        let np = self.points.len();
        let out = &mut cs.trial;
        for (f, p) in out.forces.iter_mut().zip(&self.points) {
            *f = p.force;
        }
        // Only the awake points' entries are written and read.
        let g = if cs.use_full {
            cs.g_full.as_ref().expect("made")
        } else {
            &cs.g
        };
        for _sweep in 0..200 {
            let mut change = 0.0f64;
            let mut scale = 0.0f64;
            for &i in &cs.awake {
                let p = &self.points[i];
                let others: f64 = cs
                    .awake
                    .iter()
                    .filter(|&&j| j != i)
                    .map(|&j| g[i * np + j] * out.forces[j])
                    .sum();
                let rhs = cs.predicted[i] - others;
                // A damped link that let go with the floors still overlapping takes hold again
                // only when they approach each other (as a free step starts a contact).
                let held =
                    p.force > 0.0 || p.delta <= 0.0 || p.rate > 0.0 || !self.needs_approach();
                let d = if held {
                    p.element
                        .solve_step(g[i * np + i], rhs, hh, p.delta, p.rate, p.v0)
                } else {
                    rhs
                };
                let rate = p.element.rate(hh, d, p.delta, p.rate);
                let f = self.trial_force(p, d, rate, held);
                change = change.max((f - out.forces[i]).abs());
                scale = scale.max(f.abs());
                out.forces[i] = f;
                out.deltas[i] = d;
                out.rates[i] = rate;
            }
            if cs.awake.len() <= 1 || change <= 1e-13 * scale {
                break;
            }
        }
    }

    /// A level's force at the trial's end from its overlap d and rate: the Sears law on the
    /// overlap, another element's own law where the link holds, none where it does not.
    #[inline(always)]
    fn trial_force(&self, p: &Point, d: f64, rate: f64, held: bool) -> f64 {
        if self.sears {
            p.element.stiffness() * d.max(0.0)
        } else if held {
            p.element.force(d, rate, p.v0)
        } else {
            0.0
        }
    }

    /// Level i's closing where the step starts, for its work (into `u_before`), kept unless
    /// the last step's end (this one's start) already put it there (`closing_step`).
    #[inline(always)]
    fn keep_closing_before(
        &self,
        i: usize,
        u_before: &mut [f64],
        closing_step: &[usize],
        n: [usize; 2],
    ) {
        if closing_step[i] != self.steps - 1 {
            u_before[i] = self.point_closing_of(&self.points[i], n);
        }
    }

    /// Level i's live slabs through the step with its force, each with the trial's prediction
    /// for it.
    #[inline(always)]
    fn push_slabs(&mut self, i: usize, force: f64, made: [Prediction; 2]) {
        for (slab, made) in self.points[i].slabs.iter_mut().zip(made) {
            if let Some(slab) = slab
                && slab.is_live()
            {
                slab.push_predicted(force, made);
            }
        }
    }

    /// A Sears level left without force: its slabs fall quiet (their ringing read in closed
    /// form from then on).
    #[inline(always)]
    fn settle_if_free(&mut self, i: usize) {
        let p = &mut self.points[i];
        if self.sears && p.force <= 0.0 {
            for slab in p.slabs.iter_mut().flatten() {
                slab.settle();
            }
        }
    }

    /// Takes the trial step: the modes, the slabs, the ledger and the contacts.
    #[inline(never)]
    fn commit_contact(&mut self, cs: &mut Scratch) {
        let hh = cs.trial.hh;
        let t0 = self.time();
        // Only the awake points' entries are read (by `account_contacts`): the others may hold
        // an earlier step's.
        let n = self.mode_counts();
        for &i in &cs.awake {
            self.keep_closing_before(i, &mut cs.u_before, &cs.closing_step, n);
        }
        if self.yields() {
            // A quiet step leaves the storeys where they stand; any other follows them from
            // where the modes stand now.
            for side in self.sides.iter_mut() {
                if let Some(st) = side.storeys.as_mut() {
                    if cs.quiet {
                        st.go_stale(&side.q, &side.v);
                    } else {
                        st.sync(&side.q, &side.v);
                    }
                }
            }
        }
        let sizes = self.commit_modes(cs, n);
        let tr = &cs.trial;
        self.advance(hh);
        if self.yields() && !cs.quiet {
            let t1 = self.time();
            if cs.followed {
                self.commit_storeys_from_trial(&cs.pseudo1, t1 - hh, t1);
            } else {
                self.commit_storeys(t1 - hh, t1);
            }
        }
        // A level asleep has no live slab: it fell asleep with its slabs quiet (a live one's
        // ringing has no bound), and only a level the step pushes revives them.
        for &i in &cs.awake {
            self.push_slabs(i, tr.forces[i], cs.slab_predictions[i]);
        }
        // A sleeping level keeps sleeping with what the trial left of its margin (those the
        // trial looked at: the others' margins are still their bases less the steps' sizes).
        if !cs.sleep.due.is_empty() || !cs.sleep.looked.is_empty() {
            let sl = &mut cs.sleep;
            sl.moved = [sl.moved[0] + sl.trial[0], sl.moved[1] + sl.trial[1]];
            let moved = sl.moved;
            for (_, i, margin) in std::mem::take(&mut sl.looked) {
                sl.keep(i, self.points[i].norm, margin, moved);
            }
        }
        // A level falls asleep only without force, and nothing pushes it while it sleeps.
        debug_assert!((0..self.points.len()).all(|i| !cs.asleep[i] || self.points[i].force == 0.0));
        let opened_or_closed = self.account_contacts(cs, t0);
        self.contact_steps += 1;
        // The trial summed the loads of the awake points' forces as it found them: a link let go
        // inside the step makes them again.
        if cs.trial.released.is_some() {
            self.contact_loads(&mut cs.trial.load);
        }
        for &i in &cs.awake {
            self.settle_if_free(i);
        }
        // Accelerations stay Newmark's inside contacts; leaving one, the free steps need none.
        self.track_peaks_in_contact(sizes, &cs.modal_before, hh);
        self.record_in_contact(opened_or_closed);
    }

    /// The modes through the trial step, its energy terms in the ledger; the state where it
    /// started kept in `cs.modal_before`. Per side, the sizes of the step's dq and of the
    /// velocities it ends with, summed as the modes are stepped: the peaks' proofs read them.
    #[inline(always)]
    fn commit_modes(&mut self, cs: &mut Scratch, n: [usize; 2]) -> [[[f64; 2]; 2]; 2] {
        let tr = &cs.trial;
        let (hh, ground0) = (tr.hh, cs.ground0);
        let mut moved = [[0.0f64; 2]; 2];
        let mut speed_after = [[0.0f64; 2]; 2];
        for s in 0..2 {
            let n = n[s];
            if n >= lanes::LANES_FROM {
                let ground = ground0 + tr.ground;
                let sums = self.commit_in_lanes(s, &mut cs.modal_before[s], &tr.dq[s], hh, ground);
                (moved[s], speed_after[s]) = (sums.moved, sums.speed);
                continue;
            }
            let side = &mut self.sides[s];
            let (mut m, mut sp) = (Sizes::default(), Sizes::default());
            // The state the step starts from is kept (the peaks' proofs read it), mode by mode
            // as the step reads it.
            let [q0s, v0s] = &mut cs.modal_before[s];
            let (q0s, v0s) = (&mut q0s[..n], &mut v0s[..n]);
            let (q, v, a) = (&mut side.q[..n], &mut side.v[..n], &mut side.a[..n]);
            let (omega, zeta, gamma) = (&side.omega[..n], &side.zeta[..n], &side.gamma[..n]);
            let dqs = &tr.dq[s][..n];
            for k in 0..n {
                let (q0, v0, a0) = (q[k], v[k], a[k]);
                (q0s[k], v0s[k]) = (q0, v0);
                let dq = dqs[k];
                let (v1, a1) = lanes::newmark_end(dq, v0, a0, hh);
                let mode = [omega[k], zeta[k], gamma[k]];
                let (input, damping) =
                    lanes::energy_terms(dq, v0, v1, mode, hh, ground0 + tr.ground);
                self.ledger.input_j += input;
                self.ledger.damping_j += damping;
                q[k] = q0 + dq;
                v[k] = v1;
                a[k] = a1;
                (m, sp) = (m.add(dq), sp.add(v1));
            }
            (moved[s], speed_after[s]) = (m.done(), sp.done());
        }
        [moved, speed_after]
    }

    /// A tall side's modes through the contact step that moves them by `dq`, its energy terms
    /// and sizes summed in lanes ([`lanes::commit`]); its state where the step starts kept in
    /// `before` (by trading buffers: a few modes' are copied, [`Stepper::commit_modes`]).
    #[cold]
    #[inline(never)]
    fn commit_in_lanes(
        &mut self,
        s: usize,
        before: &mut [Vec<f64>; 2],
        dq: &[f64],
        hh: f64,
        ground: f64,
    ) -> lanes::Committed {
        let side = &mut self.sides[s];
        let [q0, v0] = before;
        std::mem::swap(q0, &mut side.q);
        std::mem::swap(v0, &mut side.v);
        let ends = lanes::Ends {
            q0,
            v0,
            dq,
            coefficients: [&side.omega, &side.zeta, &side.gamma],
            hh,
            ground,
        };
        let sums = lanes::commit(&ends, &mut side.q, &mut side.v, &mut side.a);
        self.ledger.input_j += sums.input;
        self.ledger.damping_j += sums.damping;
        sums
    }

    /// Each level's contact after the step just taken from `t0`: the work of its force, its
    /// overlap, and its contact opened, carried on or closed (with where inside the step);
    /// whether any opened or closed.
    fn account_contacts(&mut self, cs: &mut Scratch, t0: f64) -> bool {
        let mut opened_or_closed = false;
        for j in 0..cs.awake.len() {
            opened_or_closed |= self.account_contact(cs.awake[j], cs, t0);
        }
        opened_or_closed
    }

    /// [`Stepper::account_contacts`] at level i; whether its contact opened or closed. Out of
    /// line: a level's bookkeeping reads a dozen of the run's fields, which a loop over one or
    /// two levels would keep on the stack for nothing.
    #[inline(never)]
    fn account_contact(&mut self, i: usize, cs: &mut Scratch, t0: f64) -> bool {
        self.account_contact_of(i, cs, t0, self.mode_counts())
    }

    /// [`Stepper::account_contact`] with each side's modes counted (`n`).
    #[inline(always)]
    fn account_contact_of(&mut self, i: usize, cs: &mut Scratch, t0: f64, n: [usize; 2]) -> bool {
        let tr = &cs.trial;
        let hh = tr.hh;
        let (t1, n1) = (self.time(), self.n);
        let mut opened_or_closed = false;
        // The closing now; its rate is read only where a contact opens without an approach
        // velocity.
        let closing = self.point_closing_of(&self.points[i], n);
        let opening = {
            let p = &self.points[i];
            (p.force <= 0.0 && tr.forces[i] > 0.0 && p.v0 <= 0.0).then(|| self.point_now(i).1)
        };
        let p = &mut self.points[i];
        // The point's force is still the step's first until it is set below.
        let (f0, f1) = (p.force, tr.forces[i]);
        // The contact's work on the buildings: -(F0 + F1)/2 times the closing displacement.
        self.ledger.contact_work_j -= 0.5 * (f0 + f1) * (closing - cs.u_before[i]);
        cs.u_before[i] = closing;
        cs.closing_step[i] = self.steps;
        let delta0 = p.delta;
        p.delta = if self.sears && cs.far[i] {
            // Out of reach: a lower bound on the overlap (no force is read from it).
            closing - self.sc.gap_m - cs.far_bound[i]
        } else if self.sears {
            closing - self.sc.gap_m - p.elastic_at(n1)
        } else {
            tr.deltas[i]
        };
        // An undamped element's force peaks with the overlap: between the steps, at the
        // cubic's maximum through both ends' overlaps and rates (sampling the steps alone
        // would miss it by up to (w h)^2 / 8, at a phase that changes with the step).
        let between = if !self.sears && p.element.undamped() && f0 > 0.0 && f1 > 0.0 {
            let top = hermite_max(delta0, p.rate, tr.deltas[i], tr.rates[i], hh);
            if top.is_finite() {
                p.element.force(top, 0.0, p.v0)
            } else {
                0.0
            }
        } else {
            0.0
        };
        p.rate = tr.rates[i];
        p.force = f1;
        p.max_force = p.max_force.max(f1).max(between);
        if f0 <= 0.0 && f1 > 0.0 {
            opened_or_closed = true;
            // Opened inside this step: where the overlap crossed zero.
            let start = if delta0 < 0.0 && p.delta > delta0 {
                t0 + hh * (-delta0 / (p.delta - delta0)).clamp(0.0, 1.0)
            } else {
                t0
            };
            if let Some(rate) = opening {
                p.v0 = rate.max(1e-12);
            }
            p.open = Some(self.contacts.len());
            self.contacts.push(RawContact {
                level: i,
                start_s: start,
                end_s: start,
                peak_force_n: 0.0,
                impulse_ns: 0.0,
                approach_velocity_m_s: p.v0,
            });
        }
        if let Some(c) = p.open {
            let contact = &mut self.contacts[c];
            contact.impulse_ns += 0.5 * hh * (f0 + f1);
            contact.peak_force_n = contact.peak_force_n.max(f1).max(between);
            if f1 <= 0.0 {
                opened_or_closed = true;
                contact.end_s = if tr.released == Some(i) || p.delta > 0.0 {
                    t1
                } else {
                    t0 + hh
                        * (delta0.max(0.0) / (delta0.max(0.0) - p.delta).max(f64::MIN_POSITIVE))
                            .clamp(0.0, 1.0)
                };
                p.open = None;
                p.v0 = 0.0;
                if contact.impulse_ns <= 0.0 {
                    // The touch carried no force (a grazing approach): not a contact.
                    self.contacts.pop();
                }
            } else {
                contact.end_s = t1;
            }
        }
        opened_or_closed
    }

    pub(super) fn point_now_of(&self, p: &Point) -> (f64, f64) {
        self.point_state(
            p,
            [&self.sides[0].q, &self.sides[1].q],
            [&self.sides[0].v, &self.sides[1].v],
        )
    }
}

/// The awake point that pushes (a non-zero force), where exactly one does.
fn pushing_one(awake: &[usize], forces: &[f64]) -> Option<usize> {
    let mut pushing = awake.iter().copied().filter(|&i| forces[i] != 0.0);
    match (pushing.next(), pushing.next()) {
        (Some(i), None) => Some(i),
        _ => None,
    }
}

/// A point's slabs' predictions for the step to grid index `next`, kept per slab in `kept`,
/// and their sums (e0, e1) in the slabs' order: the point's elastic displacement at the step's
/// end is e0 + e1 F. `live`: the caller knows every slab is live (the single level's step),
/// and the quiet ones' closed form is not looked for.
#[inline(always)]
fn predict_slabs(p: &Point, next: usize, kept: &mut [Prediction; 2], live: bool) -> (f64, f64) {
    let (mut e0, mut e1) = (0.0, 0.0);
    for (slab, kept) in p.slabs.iter().zip(kept) {
        if let Some(slab) = slab {
            *kept = if live {
                slab.prediction()
            } else {
                slab.predict_at(next)
            };
            let (a, b) = kept.0;
            e0 += a;
            e1 += b;
        }
    }
    (e0, e1)
}

#[cfg(test)]
mod tests {
    use super::super::fixed_values;
    use super::*;

    #[test]
    fn a_sleeping_level_is_looked_at_before_the_steps_could_have_used_up_its_margin() {
        let levels = 300;
        let r = fixed_values(3, 3 * levels);
        let decade = |x: f64| 10f64.powf(12.0 * x - 9.0);
        let norms: Vec<[f64; 2]> = (0..levels)
            .map(|i| {
                let n = decade(r[i]);
                match i % 7 {
                    0 => [n, 0.0],
                    1 => [n, decade(r[levels + i])],
                    _ => [n, n],
                }
            })
            .collect();
        let mut sl = Sleepers {
            base: vec![(0.0, [0.0; 2]); levels],
            ..Sleepers::default()
        };
        for i in 0..levels {
            let margin = 12.0 * r[2 * levels + i] * norms[i][0].max(norms[i][1]);
            sl.keep(i, norms[i], margin, [0.0; 2]);
        }
        let steps = fixed_values(11, 2 * 3000);
        let mut looked = vec![false; levels];
        let mut moved = [0.0f64; 2];
        for k in 0..3000 {
            moved = [
                moved[0] + 1e-3 * (0.5 + steps[2 * k]),
                moved[1] + 1e-3 * (0.5 + steps[2 * k + 1]),
            ];
            let total = moved[0] + moved[1];
            while let Some(&Reverse((key, i))) = sl.due.peek() {
                if f64::from_bits(key) > total {
                    break;
                }
                sl.due.pop();
                looked[i] = true;
            }
            for i in 0..levels {
                if sl.left(i, norms[i], moved) <= 0.0 {
                    assert!(
                        looked[i],
                        "level {i} at step {k}: margin used up, not looked at"
                    );
                }
            }
        }
        // Not vacuous: many levels ran out of margin, and many never did (never looked at).
        let used_up = (0..levels)
            .filter(|&i| sl.left(i, norms[i], moved) <= 0.0)
            .count();
        let seen = looked.iter().filter(|&&x| x).count();
        assert!(
            used_up > levels / 4 && seen < levels - levels / 4,
            "{used_up} {seen}"
        );
    }
}
