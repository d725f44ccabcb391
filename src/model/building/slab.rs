//! A floor slab's elastic (wave) response to the pounding force, for the Sears contact.
//!
//! The slab is a free-free bar carrying its floor's mass (rho~ = m / (A L)), so its rigid-body
//! response to F is already the building's. What the contact needs on top of the floors' motion
//! is the elastic part at the plane P (x = d from the contact end): d'Alembert's response minus
//! the rigid-body one,
//!   e(t) = (1/Z) [Psi(t - tau) + Psi(t - T + tau)] - (1/m) integral of Phi,
//! (tau = d/c, T = 2L/c; tau = 0 for the end reading). Material damping makes that elastic kernel
//! decay as exp(-t/t_d), rigid motion untouched. With A(t) = integral of exp(-(t-s)/t_d) F(s) ds
//! and B' = A - B/t_d, the decaying kernel keeps an O(1) recursion:
//!   Q(t) = A(t) + r Q(t - T),  r = exp(-T/t_d),
//!   e(t) = (1/Z) [exp(-tau/t_d) Q(t - tau) + exp(-(T - tau)/t_d) Q(t - T + tau)] - B(t)/m.
//! With no damping A = Phi, Q = Psi, B = integral of Phi: the undamped d'Alembert response.
//! t_d = T / (2 pi zeta): zeta is the damping ratio of the slab's fundamental axial mode.
//!
//! **Between contacts the slab rings, and the ringing is known in closed form.** Once the force
//! is zero, A(t) decays as exp(-t/t_d) and B(t) = (B_q + A_q (t - t_q)) exp(-(t - t_q)/t_d), and
//! unrolling the recursion J round trips (r^j A(t - j T) = A(t)) gives
//!   Q(t) = J A(t) + r^J Q(t - J T),
//! with t - J T inside the last round trip before the force stopped. So the slab is stepped on
//! the contact grid only while its force acts; then it falls **quiet**: it keeps the samples of
//! Q its look-ups reach and reads e at any later instant from that closed form, so a free
//! stretch of any length costs it nothing. Since 2/Z = T/m, a round trip after the force stopped
//! the ringing repeats itself, attenuated: e(t + T) = r e(t); its largest value over one round
//! trip bounds every later one, which is what lets a free stretch be cleared of an onset without
//! looking at each grid point. At the next contact it is **revived**: the samples before the
//! contact are rebuilt from the closed form. Its memory is a round trip, whatever the run's
//! length.
//!
//! The force samples are kept while it steps, so the slab's stress waves can be drawn and
//! exported ([`SlabWaves::waves`]: the field module's damped history H = F + r H(t - T), stored
//! over each stretch of contact and repeated, attenuated, between them).

use super::Slab;
use super::stepper::lanes;
use crate::model::field::{BarBody, BarWaves};
use crate::model::history::Tap;
use crate::model::ring::{Look, Ring};
use crate::model::ringing::{Frozen, Ringing, stencil};

/// The slab's state frozen when it fell quiet: its last samples, from which every later instant
/// is read until the next contact.
#[derive(Debug, Clone, Default)]
struct Quiet {
    /// Its last samples, and A and B then.
    w: Frozen,
    /// The largest |e| over the first round trip after `n` and over the second (from which
    /// the ringing repeats, attenuated), once asked for.
    envelope: std::cell::OnceCell<[f64; 2]>,
    /// Whether it has never been struck (nothing rings).
    silent: bool,
}

/// A floor slab's elastic response to the contact force, stepped on the contact grid while its
/// waves are fresh and read in closed form once they only ring.
#[derive(Debug, Clone)]
pub struct SlabWaves {
    inv_z: f64,
    inv_m: f64,
    /// The constants of its ringing (the step, the decays, the round trip in steps).
    ringing: Ringing,
    near_weight: f64,
    far_weight: f64,
    recur: Look,
    near: Look,
    far: Look,
    /// Samples a quiet window keeps: the deepest look-up and a stencil more.
    window: usize,
    /// The step's constants: 1 / (1 - r w) for the recursion's newest weight w, the weight of
    /// the newest Q in the plane's look-ups, and e1 (what the newest force moves the plane by).
    gain: f64,
    top: f64,
    e1: f64,
    tau_steps: f64,
    a: f64,
    b: f64,
    f_prev: f64,
    q: Ring,
    elastic: f64,
    /// Pushes since the last nonzero force.
    zero_run: usize,
    /// `Some` while quiet.
    quiet: Option<Quiet>,
    /// The buffers of the last quiet window, kept for the next.
    spare: Quiet,
    /// The forces kept for drawing the waves.
    forces: KeptForces,
    /// The buffers of the last tabulation of its ringing, kept for the next.
    tabulation: std::cell::RefCell<Tabulation>,
    geometry: BarBody,
}

/// What a tabulation of the ringing works in: Q over the window and two round trips after it,
/// and A, B and e at each point of those.
#[derive(Debug, Clone, Default)]
struct Tabulation {
    q: Vec<f64>,
    a: Vec<f64>,
    b: Vec<f64>,
    e: Vec<f64>,
}

/// A step's prediction: (e0, e1), the plane's elastic displacement at the step's end as
/// e0 + e1 F, and the recursion's look-up.
pub type Prediction = ((f64, f64), f64);

/// A saved state to return to after one trial step.
#[derive(Debug, Clone, Copy)]
pub struct SlabMark {
    next: usize,
    a: f64,
    b: f64,
    f_prev: f64,
    elastic: f64,
    zero_run: usize,
}

impl SlabWaves {
    /// The slab `slab` carrying `mass_kg`, read at `zone_m` from its contact end, with damping
    /// ratio `damping_ratio`, on a grid of step `h`; `push_direction` is +1 when the force
    /// pushes it towards +x (the right building), -1 for the left. It keeps at most `share`
    /// forces for drawing its waves (none for 0): every one while they fit, then every second,
    /// fourth, ... grid point's. It starts at rest, quiet.
    pub fn new(
        slab: &Slab,
        mass_kg: f64,
        zone_m: f64,
        damping_ratio: f64,
        h: f64,
        push_direction: f64,
        share: usize,
    ) -> Self {
        let c = slab.wave_speed_m_s(mass_kg);
        let t = 2.0 * slab.length_m / c;
        let tau = zone_m / c;
        let decay_time = if damping_ratio > 0.0 {
            t / (2.0 * std::f64::consts::PI * damping_ratio)
        } else {
            f64::INFINITY
        };
        let decay = |s: f64| (-s / decay_time).exp();
        let (recur, near, far) = (
            Look::of(Tap::new(t, h)),
            Look::of(Tap::new(tau, h)),
            Look::of(Tap::new(t - tau, h)),
        );
        let reach = recur.reach().max(near.reach()).max(far.reach());
        let round_steps = t / h;
        let window = reach + 4;
        let gain = 1.0 / (1.0 - decay(t) * recur.newest);
        let top = decay(tau) * near.newest + decay(t - tau) * far.newest;
        let (inv_z, inv_m) = (1.0 / slab.impedance_n_s_m(mass_kg), 1.0 / mass_kg);
        let e1 = inv_z * top * 0.5 * h * gain - inv_m * 0.25 * h * h;
        SlabWaves {
            inv_z: 1.0 / slab.impedance_n_s_m(mass_kg),
            inv_m: 1.0 / mass_kg,
            ringing: Ringing {
                h,
                step_decay: decay(h),
                round_decay: decay(t),
                round_steps,
                decay_per_s: 1.0 / decay_time,
            },
            near_weight: decay(tau),
            far_weight: decay(t - tau),
            recur,
            near,
            far,
            window,
            gain,
            top,
            e1,
            tau_steps: tau / h,
            a: 0.0,
            b: 0.0,
            f_prev: 0.0,
            q: Ring::new(reach),
            elastic: 0.0,
            zero_run: 0,
            quiet: Some(Quiet {
                w: Frozen {
                    q: vec![0.0; window],
                    ..Frozen::default()
                },
                silent: true,
                ..Quiet::default()
            }),
            spare: Quiet::default(),
            forces: KeptForces::new(share),
            tabulation: Default::default(),
            geometry: BarBody {
                length_m: slab.length_m,
                area_m2: slab.area_m2(),
                wave_speed_m_s: c,
                impedance_n_s_m: slab.impedance_n_s_m(mass_kg),
                decay_per_s: 1.0 / decay_time,
                push_direction,
            },
        }
    }

    /// Whether it is being stepped (a contact now or within the last two round trips).
    #[inline]
    pub fn is_live(&self) -> bool {
        self.quiet.is_none()
    }

    /// The next step's prediction (while live): the elastic displacement at the plane after it
    /// as e0 + e1 F_{n+1}, and the recursion's look-up, which the step's
    /// [`SlabWaves::push_predicted`] reads.
    #[inline]
    pub fn prediction(&self) -> Prediction {
        debug_assert!(self.is_live());
        let (e, h) = (self.ringing.step_decay, self.ringing.h);
        let a0 = e * self.a + 0.5 * h * e * self.f_prev;
        let b0 = e * self.b + 0.5 * h * (e * self.a + a0);
        let recur = self.q.known(&self.recur);
        let q0 = (a0 + self.ringing.round_decay * recur) * self.gain;
        let known =
            self.near_weight * self.q.known(&self.near) + self.far_weight * self.q.known(&self.far);
        let e0 = self.inv_z * (known + self.top * q0) - self.inv_m * b0;
        ((e0, self.e1), recur)
    }

    /// The elastic displacement at grid index `next` (the next step) as e0 + e1 F_next: the
    /// stepped prediction while live; while quiet, the ringing there and the compliance the
    /// slab would have if it were pushed, with no look-up (NaN: a quiet slab is revived, and
    /// predicted again, before it is pushed).
    #[inline]
    pub fn predict_at(&self, next: usize) -> Prediction {
        match &self.quiet {
            None => {
                debug_assert_eq!(self.q.next, next);
                self.prediction()
            }
            Some(_) => ((self.elastic_at(next), self.instant_compliance()), f64::NAN),
        }
    }

    /// de/dF over one step: what the newest force moves the plane by (independent of the state).
    pub fn instant_compliance(&self) -> f64 {
        self.e1
    }

    /// Advances one step with the force F_{n+1} (while live), its prediction made here.
    pub fn push(&mut self, force: f64) {
        let made = self.prediction();
        self.push_predicted(force, made);
    }

    /// Advances one step with the force F_{n+1} (while live) and the step's prediction (made by
    /// [`SlabWaves::prediction`] since the last push).
    #[inline(always)]
    pub fn push_predicted(&mut self, force: f64, ((e0, e1), recur): Prediction) {
        debug_assert!(self.is_live());
        let (e, h) = (self.ringing.step_decay, self.ringing.h);
        let a1 = e * self.a + 0.5 * h * (e * self.f_prev + force);
        self.b = e * self.b + 0.5 * h * (e * self.a + a1);
        self.a = a1;
        let q1 = (a1 + self.ringing.round_decay * recur) * self.gain;
        self.q.push(q1);
        self.f_prev = force;
        self.elastic = e0 + e1 * force;
        // The force just pushed stands at grid index next - 1.
        self.forces.push(self.q.next - 1, force);
        self.zero_run = if force == 0.0 { self.zero_run + 1 } else { 0 };
    }

    /// Index of the newest sample.
    pub fn newest_index(&self) -> usize {
        match &self.quiet {
            Some(q) => q.w.n,
            None => self.q.next - 1,
        }
    }

    /// Elastic displacement of the plane at the newest step [m] (while live).
    pub fn elastic_m(&self) -> f64 {
        self.elastic
    }

    /// Elastic displacement of the plane at grid index `n` [m]: the newest step's while live, the
    /// closed form while quiet.
    pub fn elastic_at(&self, n: usize) -> f64 {
        match &self.quiet {
            None => {
                debug_assert_eq!(n, self.q.next - 1);
                self.elastic
            }
            Some(q) => self.quiet_elastic(q, n as f64),
        }
    }

    /// e at grid index `n` of a quiet slab: the d'Alembert sum of the closed-form Q less the
    /// rigid part B / m (one exponential: the decays at the two look-ups differ from the one at
    /// n by the look-ups' own weights).
    fn quiet_elastic(&self, q: &Quiet, n: f64) -> f64 {
        let (r, w) = (&self.ringing, &q.w);
        let base = r.decay(n - w.n as f64);
        let near = r.fold_q(w, n - self.tau_steps, w.a * base / self.near_weight);
        let far = r.fold_q(
            w,
            n - (r.round_steps - self.tau_steps),
            w.a * base / self.far_weight,
        );
        let b = base * (w.b + (n - w.n as f64) * r.h * w.a);
        self.inv_z * (self.near_weight * near + self.far_weight * far) - self.inv_m * b
    }

    /// A bound on |e| at every grid index from `n` on (infinite while live: the waves are
    /// fresh).
    pub fn envelope_from(&self, n: usize) -> f64 {
        let Some(q) = &self.quiet else {
            return f64::INFINITY;
        };
        if q.silent {
            return 0.0;
        }
        let tabulated = *q.envelope.get_or_init(|| self.tabulate_envelope(q));
        self.ringing.envelope_at(tabulated, n.saturating_sub(q.w.n))
    }

    /// The largest |e| on the grid over the first round trip after the slab fell quiet and over
    /// the second: from the second on, e(t + T) = r e(t). The grid recursion is stepped on with
    /// zero force from the quiet window (a copy of its samples), the cheapest way to every grid
    /// point of two round trips.
    ///
    /// In stages, each the same arithmetic as stepping would do, in the same order (so bit for
    /// bit the values stepping finds): A and B (a scalar recursion of their own), then Q block by
    /// block (the recursion reads a round trip back, so a block shorter than that reads only
    /// blocks done) and e at every point from the finished Q, four points a vector register
    /// ([`lanes::ringing_block`], [`lanes::elastic_rows`]), then its largest |value|.
    fn tabulate_envelope(&self, q: &Quiet) -> [f64; 2] {
        let steps = self.ringing.tabulated_steps();
        let len = q.w.q.len();
        let looks = [
            self.recur.stored_four(),
            self.near.stored_four(),
            self.far.stored_four(),
        ];
        // Every look-up reads four samples from `back` before the one being made, at most that
        // one, so they stay within the buffer from its first sample on.
        debug_assert!(looks.iter().all(|(back, _)| (3..=len).contains(back)));
        let mut guard = self.tabulation.borrow_mut();
        let t = &mut *guard;
        // The buffers keep their length from one window to the next, and every entry read is
        // written first: none is cleared.
        for v in [&mut t.a, &mut t.b, &mut t.e] {
            v.resize(2 * steps, 0.0);
        }
        t.q.resize(len + 2 * steps, 0.0);
        q.w.fill(&mut t.q[..len]);
        self.quiet_ab(q, &mut t.a, &mut t.b);
        self.tabulate_q(&mut t.q, len, &t.a, looks[0]);
        self.tabulate_elastic(&t.q, len, &t.b, [looks[1], looks[2]], &mut t.e);
        let e = &t.e;
        let most = |e: &[f64]| {
            // Two partial maxima: the largest of a set is the same whatever the order.
            let mut m = [0.0f64; 2];
            let pairs = e.chunks_exact(2);
            let rest = pairs.remainder();
            for p in pairs {
                m[0] = m[0].max(p[0].abs());
                m[1] = m[1].max(p[1].abs());
            }
            rest.iter().fold(m[0].max(m[1]), |m, x| m.max(x.abs()))
        };
        [most(&e[..steps]), most(&e[steps..])]
    }

    /// A and B at each grid point after the slab fell quiet (as many as `out_a` holds), stepped
    /// with zero force.
    fn quiet_ab(&self, q: &Quiet, out_a: &mut [f64], out_b: &mut [f64]) {
        let (e, h) = (self.ringing.step_decay, self.ringing.h);
        let (mut a, mut b) = (q.w.a, q.w.b);
        for (out_a, out_b) in out_a.iter_mut().zip(out_b) {
            let a1 = e * a;
            b = e * b + 0.5 * h * (e * a + a1);
            a = a1;
            *out_a = a;
            *out_b = b;
        }
    }

    /// Q after the window (`buf[len..]`) from A there, by the recursion Q = (A + r Q(t - T))
    /// gain, whose look-up (`back`, weights) reads `back` samples back.
    fn tabulate_q(&self, buf: &mut [f64], len: usize, a: &[f64], (back, w): (usize, [f64; 4])) {
        let (round, gain) = (self.ringing.round_decay, self.gain);
        let total = buf.len();
        if back < 4 {
            // A round trip within a step: the look-up's last weight is zero, on the point being
            // made (still zero when stepping reads it).
            for at in len..total {
                let s = &buf[at - back..at];
                let read = stencil(&w, &[s[0], s[1], s[2], 0.0]);
                buf[at] = (a[at - len] + round * read) * gain;
            }
            return;
        }
        // A block of back - 3 points reads only points before it.
        let block = back - 3;
        let mut at = len;
        while at < total {
            let end = (at + block).min(total);
            let (done, todo) = buf.split_at_mut(at);
            let todo = &mut todo[..end - at];
            let src = &done[at - back..at - back + todo.len() + 3];
            let a = &a[at - len..end - len];
            lanes::ringing_block(todo, a, src, &w, round, gain);
            at = end;
        }
    }

    /// e at each point after the window, from the finished Q and B there: the plane's two
    /// look-ups, the newest Q's share of them and the rigid part.
    fn tabulate_elastic(
        &self,
        buf: &[f64],
        len: usize,
        b: &[f64],
        [near, far]: [(usize, [f64; 4]); 2],
        out: &mut [f64],
    ) {
        let n = out.len();
        let e = lanes::Elastic {
            near: (&buf[len - near.0..len - near.0 + n + 3], &near.1),
            far: (&buf[len - far.0..len - far.0 + n + 3], &far.1),
            newest: &buf[len..len + n],
            b: &b[..n],
            constants: [
                self.near_weight,
                self.far_weight,
                self.inv_z,
                self.top,
                self.inv_m,
            ],
        };
        lanes::elastic_rows(&e, out);
    }

    /// Falls quiet once the force has stopped: from then on its ringing is read in closed form.
    pub fn settle(&mut self) {
        if self.quiet.is_some() || self.zero_run == 0 {
            return;
        }
        let mut q = std::mem::take(&mut self.spare);
        q.w.n = self.q.next - 1;
        q.w.a = self.a;
        q.w.b = self.b;
        q.envelope = std::cell::OnceCell::new();
        self.q.newest(self.window, &mut q.w.q);
        q.silent = q.w.silent();
        self.quiet = Some(q);
    }

    /// Starts stepping again at grid index `n` (at or after the quiet window's end): the samples
    /// the look-ups need are rebuilt from the closed form of the ringing.
    pub fn revive(&mut self, n: usize) {
        let Some(q) = self.quiet.take() else {
            return;
        };
        let from = (n as isize - self.window as isize + 1).max(0) as usize;
        self.q.next = from;
        self.ringing.rebuild(&q.w, &mut self.q, from, n);
        self.a = self.ringing.a_at(&q.w, n as f64);
        self.b = self.ringing.b_at(&q.w, n as f64);
        self.f_prev = 0.0;
        self.elastic = self.quiet_elastic(&q, n as f64);
        self.zero_run = 0;
        self.forces.start(n + 1);
        self.spare = q;
    }

    /// The state to come back to if one trial step is taken again (while live).
    pub fn mark(&self) -> SlabMark {
        SlabMark {
            next: self.q.next,
            a: self.a,
            b: self.b,
            f_prev: self.f_prev,
            elastic: self.elastic,
            zero_run: self.zero_run,
        }
    }

    /// Back to a marked state (one step back at most: the ring keeps a few spare samples).
    pub fn reset(&mut self, mark: SlabMark) {
        self.q.next = mark.next;
        self.a = mark.a;
        self.b = mark.b;
        self.f_prev = mark.f_prev;
        self.elastic = mark.elastic;
        self.zero_run = mark.zero_run;
        self.forces.truncate_from(mark.next);
    }

    /// The slab's stress waves over the run: H = F + r H(t - T) on the grid of its kept forces
    /// (the step grid while they fit in its share) over each stretch the slab was stepped,
    /// repeated round trip by round trip (attenuated by r) between them, read as any bar's
    /// (stress from the contact end to the free end). `end_s` is the run's end.
    pub fn waves(&self, end_s: f64) -> BarWaves {
        BarWaves::from_stretches(
            self.geometry,
            self.ringing.h * self.forces.keep as f64,
            &self.forces.stretches,
            end_s,
        )
    }
}

/// A slab's forces kept for drawing its waves, within a share of samples: every grid point's
/// while they fit, and each time they outgrow it, every second one of those kept (so that the
/// memory is set by the share, not by the steps, and the drawing is as fine as the share allows).
#[derive(Debug, Clone)]
struct KeptForces {
    /// Stretches of forces: (the first's index on the grid of every `keep`-th point, the forces).
    stretches: Vec<(usize, Vec<f64>)>,
    /// Every how many grid points a force is kept (a power of two).
    keep: usize,
    /// The most forces kept (0: none).
    share: usize,
    kept: usize,
}

impl KeptForces {
    fn new(share: usize) -> Self {
        KeptForces {
            stretches: Vec::new(),
            keep: 1,
            share,
            kept: 0,
        }
    }

    /// A stretch starts at grid index `first`.
    fn start(&mut self, first: usize) {
        if self.share > 0 {
            self.stretches.push((first.div_ceil(self.keep), Vec::new()));
        }
    }

    /// The force at grid index `i` (the stretch's next).
    #[inline]
    fn push(&mut self, i: usize, force: f64) {
        // keep is a power of two: a multiple of it has no bits below it.
        if self.share == 0 || i & (self.keep - 1) != 0 {
            return;
        }
        if let Some((_, f)) = self.stretches.last_mut() {
            f.push(force);
            self.kept += 1;
            if self.kept > self.share {
                self.thin();
            }
        }
    }

    /// Every second force kept, on a grid twice as coarse.
    #[cold]
    fn thin(&mut self) {
        self.kept = 0;
        for (first, f) in self.stretches.iter_mut() {
            // The kept ones are those at even indices of the present grid.
            let skip = *first % 2;
            let mut w = 0;
            for r in (skip..f.len()).step_by(2) {
                f[w] = f[r];
                w += 1;
            }
            f.truncate(w);
            *first = first.div_ceil(2);
            self.kept += w;
        }
        self.keep *= 2;
    }

    /// Forgets the forces at grid index `i` and later (a step taken again).
    fn truncate_from(&mut self, i: usize) {
        if let Some((first, f)) = self.stretches.last_mut() {
            let len = i.div_ceil(self.keep).saturating_sub(*first).min(f.len());
            self.kept -= f.len() - len;
            f.truncate(len);
        }
    }
}
