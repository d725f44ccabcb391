//! A girder's elastic (wave) response to the forces at both its ends, for the Sears contact.
//!
//! The girder is a free-free bar carrying its frame's girder mass (rho~ = m / (A L)), so its
//! rigid-body response is already the frame's. What a joint needs on top of the frame's girder
//! displacement is the elastic part at each end: d'Alembert's response less the rigid-body one.
//! A force F pushing into one end (the buildings' slab kernel, with the law read at the end):
//!   at that end      e_own(t) = (1/Z) [Q(t) + r Q(t - T)] - B(t)/m,
//!   at the far end   e_far(t) = (2/Z) r_h Q(t - T/2) - B(t)/m,
//! with T = 2L/c, A(t) = int exp(-(t-s)/t_d) F(s) ds, Q(t) = A(t) + r Q(t - T),
//! B(t) = int (t-s) exp(-(t-s)/t_d) F(s) ds, r = exp(-T/t_d), r_h = exp(-T/(2 t_d)) and
//! t_d = T / (2 pi zeta) (zeta the damping of the girder's fundamental axial mode; with none,
//! Q is the history sum Psi and B the double integral of F). The far end sees the first
//! arrival after L/c and then every round trip; the own end sees the force at once and its
//! echoes every round trip. The left end's force pushes +x and the right end's -x, so
//!   w_left  = e_own[F_left] - e_far[F_right],   w_right = e_far[F_left] - e_own[F_right]:
//! the waves from the two ends meet in the girder and each end feels both.
//!
//! Over a step the force is linear in time, and A and B are integrated exactly for it; a
//! lag is read from the stored Q (a ring a round trip deep) by a [`Tap`]'s cubic through four
//! samples (the step is at most a sixteenth of a round trip, so every lag reaches samples
//! already known).
//!
//! **Between contacts the girder only rings**, and the ringing is known in closed form
//! (`model::ringing`): once both end forces are zero the girder falls quiet, keeps the last
//! samples of each end's Q, and reads its end waves at any later grid index without being
//! stepped; since 2/Z = T/m, each end's waves repeat every round trip attenuated by r, so their
//! largest values over the first two round trips bound every later one. At the next contact it
//! is revived: its rings are rebuilt from the closed form.

use super::scenario::Girder;
use crate::model::field::{BarBody, BarWaves};
use crate::model::history::Tap;
use crate::model::ring::{Look, Ring};
use crate::model::ringing::{Fold, Frozen, Ringing, read_four};

/// A quiet girder: each end's history frozen when both forces stopped, and the largest end
/// waves over the two round trips after that, once asked for.
#[derive(Debug, Clone, Default)]
struct Quiet {
    ends: [Frozen; 2],
    /// The look-ups a round trip and half a round trip back last made (each is the same for
    /// every grid index folded back as many round trips).
    folds: [std::cell::Cell<Option<Fold>>; 2],
    /// `[first round trip, second]`, each `[left end, right end]`.
    envelope: std::cell::OnceCell<[[f64; 2]; 2]>,
}

/// One end's force history: A and B now, Q on the grid.
#[derive(Debug, Clone)]
struct End {
    a: f64,
    b: f64,
    q: Ring,
    /// What the step being taken knows without its new force.
    a_star: f64,
    b_star: f64,
    q_lag: f64,
}

/// The waves of one girder.
#[derive(Debug, Clone)]
pub struct GirderWaves {
    inv_z: f64,
    inv_m: f64,
    r: f64,
    r_half: f64,
    decay: f64,
    /// Weights of F_n and F_{n+1} in A's update, and in B's.
    wa: [f64; 2],
    wb: [f64; 2],
    h: f64,
    round_trip: Look,
    half_trip: Look,
    ends: [End; 2],
    /// Steps committed: the grid index of the newest forces.
    n: usize,
    /// Whether a force has reached either end yet: until then every wave is zero and its
    /// rings hold nothing but zeros, so a step only counts itself.
    struck: bool,
    /// Each end's force over the stretches it was loaded (the grid index of the first sample,
    /// the forces), for its stress waves.
    stretches: [Vec<(usize, Vec<f64>)>; 2],
    body: BarBody,
    /// The constants of the quiet ringing, and the samples a quiet end keeps (the deepest
    /// look-up and a stencil more).
    ringing: Ringing,
    window: usize,
    /// exp(lam T) and exp(lam T / 2): A a round trip and half a round trip back, relative to
    /// A now.
    grow: [f64; 2],
    /// The forces of the last step committed (a girder falls quiet only after zeros).
    last_forces: [f64; 2],
    /// `Some` while quiet; the buffers of the last quiet spell are kept for the next.
    quiet: Option<Box<Quiet>>,
    spare: Option<Box<Quiet>>,
}

/// The known parts of the two ends' elastic displacements at the step's end, before the new
/// forces: w_left = left + (s - b) F_left + b F_right, w_right = right - b F_left - (s - b) F_right.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Predicted {
    /// Known part at the left end [m].
    pub left: f64,
    /// Known part at the right end [m].
    pub right: f64,
}

/// int_0^h u^k exp(-lam u) du for k = 0, 1, 2: by its series where lam h is small (the closed
/// form cancels there), else in closed form.
fn moments(lam: f64, h: f64) -> [f64; 3] {
    let x = lam * h;
    if x < 0.1 {
        std::array::from_fn(|k| {
            let mut term = 1.0;
            let mut sum = 0.0;
            for m in 0..14 {
                sum += term / (k + m + 1) as f64;
                term *= -x / (m + 1) as f64;
            }
            sum * h.powi(k as i32 + 1)
        })
    } else {
        let e = (-x).exp();
        [
            (1.0 - e) / lam,
            (1.0 - e * (1.0 + x)) / (lam * lam),
            (2.0 - e * (2.0 + 2.0 * x + x * x)) / (lam * lam * lam),
        ]
    }
}

impl GirderWaves {
    /// The waves of `girder` damped by `zeta`, stepped by `h` (at most a sixteenth of its round
    /// trip).
    pub fn new(girder: &Girder, zeta: f64, h: f64) -> Self {
        let t = girder.round_trip_s();
        let lam = 2.0 * std::f64::consts::PI * zeta / t;
        let [i0, i1, i2] = moments(lam, h);
        let round_trip = Look::of(Tap::new(t, h));
        let half_trip = Look::of(Tap::new(0.5 * t, h));
        let end = End {
            a: 0.0,
            b: 0.0,
            q: Ring::new(round_trip.reach()),
            a_star: 0.0,
            b_star: 0.0,
            q_lag: 0.0,
        };
        GirderWaves {
            inv_z: 1.0 / girder.impedance_n_s_m(),
            inv_m: 1.0 / girder.mass_kg,
            r: (-lam * t).exp(),
            r_half: (-0.5 * lam * t).exp(),
            decay: (-lam * h).exp(),
            // A gains int_0^h e^(-lam u) F(h - u) du, F linear from F_n to F_{n+1}.
            wa: [i1 / h, i0 - i1 / h],
            wb: [i2 / h, i1 - i2 / h],
            h,
            round_trip,
            half_trip,
            ends: [end.clone(), end],
            n: 0,
            struck: false,
            stretches: [Vec::new(), Vec::new()],
            body: BarBody {
                length_m: girder.length_m,
                area_m2: girder.area_m2,
                wave_speed_m_s: girder.wave_speed_m_s(),
                impedance_n_s_m: girder.impedance_n_s_m(),
                decay_per_s: lam,
                push_direction: 1.0,
            },
            ringing: Ringing {
                h,
                step_decay: (-lam * h).exp(),
                round_decay: (-lam * t).exp(),
                round_steps: t / h,
                decay_per_s: lam,
            },
            window: round_trip.reach().max(half_trip.reach()) + 4,
            grow: [(lam * t).exp(), (0.5 * lam * t).exp()],
            last_forces: [0.0; 2],
            quiet: None,
            spare: None,
        }
    }

    /// The own end's instantaneous compliance s = (weight of F_{n+1} in A) / Z [m/N].
    pub fn own_compliance(&self) -> f64 {
        self.wa[1] * self.inv_z
    }

    /// The rigid-body part taken out, b = (weight of F_{n+1} in B) / m [m/N].
    pub fn rigid_compliance(&self) -> f64 {
        self.wb[1] * self.inv_m
    }

    /// The known parts at the next step's end, from the forces now (`forces[0]` at the left end).
    pub fn predict(&mut self, forces: [f64; 2]) -> Predicted {
        debug_assert!(
            self.quiet.is_none(),
            "a quiet girder is revived before it is stepped"
        );
        if !self.struck {
            // What the look-ups below find in a girder at rest, forces zero (its ends' a*, b*
            // and lag are still the zeros they started with).
            return Predicted {
                left: 0.0,
                right: 0.0,
            };
        }
        let mut own = [0.0; 2];
        let mut far = [0.0; 2];
        for (i, e) in self.ends.iter_mut().enumerate() {
            e.a_star = self.decay * e.a + self.wa[0] * forces[i];
            e.b_star = self.decay * (e.b + self.h * e.a) + self.wb[0] * forces[i];
            e.q_lag = e.q.known(&self.round_trip);
            let rigid = e.b_star * self.inv_m;
            own[i] = self.inv_z * (e.a_star + 2.0 * self.r * e.q_lag) - rigid;
            far[i] = 2.0 * self.inv_z * self.r_half * e.q.known(&self.half_trip) - rigid;
        }
        Predicted {
            left: own[0] - far[1],
            right: far[0] - own[1],
        }
    }

    /// The ends' elastic displacements at the step's end from their known parts `p` (the
    /// prediction's, left then right) and the step's new end forces.
    pub fn end_waves(&self, p: [f64; 2], [fl, fr]: [f64; 2]) -> [f64; 2] {
        let (s, b) = (self.own_compliance(), self.rigid_compliance());
        [p[0] + (s - b) * fl + b * fr, p[1] - b * fl - (s - b) * fr]
    }

    /// Takes the step with its new end forces.
    pub fn commit(&mut self, forces: [f64; 2]) {
        debug_assert!(
            self.quiet.is_none(),
            "a quiet girder is revived before it is stepped"
        );
        self.last_forces = forces;
        self.struck |= forces != [0.0, 0.0];
        if !self.struck {
            // The rings would take zeros where they hold only zeros: a look-up relative to
            // the newest sample reads the same without them.
            self.n += 1;
            return;
        }
        for (i, e) in self.ends.iter_mut().enumerate() {
            e.a = e.a_star + self.wa[1] * forces[i];
            e.b = e.b_star + self.wb[1] * forces[i];
            e.q.push(e.a + self.r * e.q_lag);
        }
        self.n += 1;
        for (stretches, f) in self.stretches.iter_mut().zip(forces) {
            record(stretches, self.n, f);
        }
    }

    /// Whether its ringing is read in closed form (quiet, or never struck: then it is still).
    pub fn is_quiet(&self) -> bool {
        self.is_frozen() || self.is_still()
    }

    /// Whether it has never been struck: no waves at all.
    pub fn is_still(&self) -> bool {
        !self.struck
    }

    /// Whether it keeps a frozen history (struck, then quiet): stepping it needs a revival.
    pub fn is_frozen(&self) -> bool {
        self.quiet.is_some()
    }

    /// The grid index of its newest step.
    pub fn newest_index(&self) -> usize {
        self.n
    }

    /// Falls quiet once the last step committed had no force at either end: from then on its
    /// ringing is read in closed form and it is not stepped. A girder never struck stays as it
    /// is (still, and as cheap).
    pub fn settle(&mut self) {
        if self.is_quiet() || self.last_forces != [0.0, 0.0] {
            return;
        }
        let mut q = self.spare.take().unwrap_or_default();
        for (frozen, e) in q.ends.iter_mut().zip(&self.ends) {
            frozen.n = self.n;
            frozen.a = e.a;
            frozen.b = e.b;
            e.q.newest(self.window, &mut frozen.q);
        }
        q.envelope = std::cell::OnceCell::new();
        q.folds.iter().for_each(|f| f.set(None));
        self.quiet = Some(q);
    }

    /// Moves a quiet girder on by `steps` grid steps without force (nothing to step).
    pub fn skip(&mut self, steps: usize) {
        debug_assert!(self.is_quiet());
        self.n += steps;
    }

    /// Starts stepping again at its newest index: each end's ring is rebuilt from the closed
    /// form of its ringing, and A and B brought there.
    pub fn revive(&mut self) {
        let Some(q) = self.quiet.take() else {
            return;
        };
        let n = self.n;
        let from = (n as isize - self.window as isize + 1).max(0) as usize;
        for (e, frozen) in self.ends.iter_mut().zip(&q.ends) {
            e.q.next = from;
            self.ringing.rebuild(frozen, &mut e.q, from, n);
            e.a = self.ringing.a_at(frozen, n as f64);
            e.b = self.ringing.b_at(frozen, n as f64);
        }
        self.spare = Some(q);
    }

    /// The end waves `[left, right]` at grid index `n` (at or after its newest) of a quiet
    /// girder: each end's own and far readings from the closed form of its history.
    pub fn waves_at(&self, n: usize) -> [f64; 2] {
        let Some(q) = &self.quiet else {
            // Never struck: still. A live girder is read by stepping it, never here.
            assert!(
                !self.struck,
                "a struck girder is read in closed form only when quiet"
            );
            return [0.0; 2];
        };
        let r = &self.ringing;
        let [w0, w1] = &q.ends;
        let steps = (n as i64 - w0.n as i64) as f64;
        // One exponential for both ends: A and B decay alike since both fell quiet at once.
        let base = r.decay(steps);
        let (back, half) = (self.fold_at(q, 0, n), self.fold_at(q, 1, n));
        let (a0, a1) = (w0.a * base, w1.a * base);
        let k = steps * r.h;
        let (b0, b1) = (
            base * (w0.b + k * w0.a) * self.inv_m,
            base * (w1.b + k * w1.a) * self.inv_m,
        );
        let (z, r2, rh2) = (self.inv_z, 2.0 * self.r, 2.0 * self.inv_z * self.r_half);
        // Both ends' windows end at the same index and hold as many samples: one stencil
        // start per look-up serves both.
        let len = w0.q.len();
        let (kb, kh) = (back.start(w0.n, len, n), half.start(w0.n, len, n));
        let own0 = z * (a0 + r2 * back.read_at(w0, kb, n, a0 * self.grow[0])) - b0;
        let far0 = rh2 * half.read_at(w0, kh, n, a0 * self.grow[1]) - b0;
        let own1 = z * (a1 + r2 * back.read_at(w1, kb, n, a1 * self.grow[0])) - b1;
        let far1 = rh2 * half.read_at(w1, kh, n, a1 * self.grow[1]) - b1;
        // Each end's own reading less the other end's far one (see the module's sign rule).
        [own0 - far1, far0 - own1]
    }

    /// The look-up a round trip (`l` 0) or half a round trip (1) back from grid index n of a
    /// quiet girder, made once for all the grid indices folded back as many round trips.
    #[inline]
    fn fold_at(&self, q: &Quiet, l: usize, n: usize) -> Fold {
        let r = &self.ringing;
        let lag = if l == 0 {
            r.round_steps
        } else {
            0.5 * r.round_steps
        };
        let j = r.trips_back(q.ends[0].n, n, lag);
        match q.folds[l].get() {
            Some(f) if f.j == j => f,
            _ => {
                let f = r.fold(lag, j);
                q.folds[l].set(Some(f));
                f
            }
        }
    }

    /// Bounds on |end waves| `[left, right]` at every grid index from `n` on (zero for a girder
    /// never struck); only for a quiet girder.
    pub fn envelope_from(&self, n: usize) -> [f64; 2] {
        let Some(q) = &self.quiet else {
            // Still (never struck), or live: nothing to ring, or nothing known.
            return if self.struck {
                [f64::INFINITY; 2]
            } else {
                [0.0; 2]
            };
        };
        let [early, late] = *q.envelope.get_or_init(|| self.tabulate_envelope(q));
        let offset = n.saturating_sub(q.ends[0].n);
        std::array::from_fn(|e| self.ringing.envelope_at([early[e], late[e]], offset))
    }

    /// The largest |end waves| on the grid over the first round trip after the girder fell
    /// quiet and over the second (from the second on, w(t + T) = r w(t)): the recursion
    /// stepped with zero force from copies of its windows, as [`GirderWaves::commit`] steps it.
    fn tabulate_envelope(&self, q: &Quiet) -> [[f64; 2]; 2] {
        let steps = self.ringing.tabulated_steps();
        let len = q.ends[0].q.len();
        let mut bufs = [q.ends[0].buffer(2 * steps), q.ends[1].buffer(2 * steps)];
        let (round, half) = (self.round_trip.stored_four(), self.half_trip.stored_four());
        debug_assert!(round.0.max(half.0) <= len);
        let mut ab = [(q.ends[0].a, q.ends[0].b), (q.ends[1].a, q.ends[1].b)];
        let (e, h) = (self.decay, self.h);
        let mut most = [[0.0f64; 2]; 2];
        for i in 0..2 * steps {
            let at = len + i;
            let mut readings = [[0.0; 2]; 2];
            for ((buf, (a, b)), out) in bufs.iter_mut().zip(ab.iter_mut()).zip(&mut readings) {
                *b = e * (*b + h * *a);
                *a *= e;
                let lag = read_four(buf, at, round);
                let rigid = *b * self.inv_m;
                out[0] = self.inv_z * (*a + 2.0 * self.r * lag) - rigid;
                out[1] = 2.0 * self.inv_z * self.r_half * read_four(buf, at, half) - rigid;
                buf[at] = *a + self.r * lag;
            }
            let k = usize::from(i >= steps);
            let waves = [
                readings[0][0] - readings[1][1],
                readings[0][1] - readings[1][0],
            ];
            for (m, w) in most[k].iter_mut().zip(waves) {
                *m = m.max(w.abs());
            }
        }
        most
    }

    /// The stress waves from each end over the run (`[0]` from the left end, pushed towards
    /// +x; `[1]` from the right end, pushed towards -x); the field anywhere in the girder is
    /// their sum, the right end's read at the distance from that end. `end_s` is the run's end.
    pub fn waves(&self, end_s: f64) -> [BarWaves; 2] {
        std::array::from_fn(|i| {
            let body = BarBody {
                push_direction: if i == 0 { 1.0 } else { -1.0 },
                ..self.body
            };
            BarWaves::from_stretches(body, self.h, &self.stretches[i], end_s)
        })
    }
}

/// Keeps the force `f` at grid index `n` where it belongs: a stretch opens a sample before the
/// first nonzero force (the rest it starts from), and closes after two zero forces (the waves
/// then only ring, which the history reads without samples).
fn record(stretches: &mut Vec<(usize, Vec<f64>)>, n: usize, f: f64) {
    match stretches.last_mut() {
        Some((first, v)) if *first + v.len() == n => {
            let quiet = v.len() >= 2 && v[v.len() - 1] == 0.0 && v[v.len() - 2] == 0.0;
            if f != 0.0 || !quiet {
                v.push(f);
            }
        }
        _ if f != 0.0 => stretches.push((n - 1, vec![0.0, f])),
        _ => {}
    }
}
