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
//! The force samples are kept too, so the slab's stress waves can be drawn and exported
//! ([`SlabWaves::waves`]: the field module's damped history H = F + r H(t - T)).

use super::Slab;
use crate::model::field::{BarWaves, History};
use crate::model::history::{Series, Tap};

/// A floor slab's elastic response to the contact force, stepped on the contact grid.
#[derive(Debug, Clone)]
pub struct SlabWaves {
    inv_z: f64,
    inv_m: f64,
    h: f64,
    step_decay: f64,
    round_decay: f64,
    near_weight: f64,
    far_weight: f64,
    recur: Tap,
    near: Tap,
    far: Tap,
    a: f64,
    b: f64,
    f_prev: f64,
    q: Series,
    elastic: f64,
    forces: Vec<f64>,
    geometry: Geometry,
}

/// What [`SlabWaves::waves`] needs to describe the bar.
#[derive(Debug, Clone, Copy)]
struct Geometry {
    length_m: f64,
    area_m2: f64,
    wave_speed_m_s: f64,
    impedance_n_s_m: f64,
    decay_per_s: f64,
    push_direction: f64,
}

/// A saved state to return to (after a trial step).
#[derive(Debug, Clone, Copy)]
pub struct SlabMark {
    len: usize,
    a: f64,
    b: f64,
    f_prev: f64,
    elastic: f64,
}

impl SlabWaves {
    /// The slab `slab` carrying `mass_kg`, read at `zone_m` from its contact end, with damping
    /// ratio `damping_ratio`, on a grid of step `h`; `push_direction` is +1 when the force
    /// pushes it towards +x (the right building), -1 for the left.
    pub fn new(
        slab: &Slab,
        mass_kg: f64,
        zone_m: f64,
        damping_ratio: f64,
        h: f64,
        capacity: usize,
        push_direction: f64,
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
        let mut q = Series::with_capacity(capacity);
        q.push(0.0);
        let mut forces = Vec::with_capacity(capacity);
        forces.push(0.0);
        SlabWaves {
            inv_z: 1.0 / slab.impedance_n_s_m(mass_kg),
            inv_m: 1.0 / mass_kg,
            h,
            step_decay: decay(h),
            round_decay: decay(t),
            near_weight: decay(tau),
            far_weight: decay(t - tau),
            recur: Tap::new(t, h),
            near: Tap::new(tau, h),
            far: Tap::new(t - tau, h),
            a: 0.0,
            b: 0.0,
            f_prev: 0.0,
            q,
            elastic: 0.0,
            forces,
            geometry: Geometry {
                length_m: slab.length_m,
                area_m2: slab.area_m2(),
                wave_speed_m_s: c,
                impedance_n_s_m: slab.impedance_n_s_m(mass_kg),
                decay_per_s: 1.0 / decay_time,
                push_direction,
            },
        }
    }

    /// The elastic displacement at the plane after one more step, as e0 + e1 F_{n+1}.
    #[inline]
    pub fn predict(&self) -> (f64, f64) {
        let (e, h) = (self.step_decay, self.h);
        let a0 = e * self.a + 0.5 * h * e * self.f_prev;
        let b0 = e * self.b + 0.5 * h * (e * self.a + a0);
        let gain = 1.0 / (1.0 - self.round_decay * self.recur.newest_weight());
        let q0 = (a0 + self.round_decay * self.recur.known_before_push(&self.q)) * gain;
        let q1 = 0.5 * h * gain;
        let top = self.near_weight * self.near.newest_weight()
            + self.far_weight * self.far.newest_weight();
        let known = self.near_weight * self.near.known_before_push(&self.q)
            + self.far_weight * self.far.known_before_push(&self.q);
        let e0 = self.inv_z * (known + top * q0) - self.inv_m * b0;
        let e1 = self.inv_z * top * q1 - self.inv_m * 0.25 * h * h;
        (e0, e1)
    }

    /// Advances one step with the force F_{n+1}.
    #[inline]
    pub fn push(&mut self, force: f64) {
        let (e0, e1) = self.predict();
        let (e, h) = (self.step_decay, self.h);
        let a1 = e * self.a + 0.5 * h * (e * self.f_prev + force);
        self.b = e * self.b + 0.5 * h * (e * self.a + a1);
        self.a = a1;
        let gain = 1.0 / (1.0 - self.round_decay * self.recur.newest_weight());
        let q1 = (a1 + self.round_decay * self.recur.known_before_push(&self.q)) * gain;
        self.q.push(q1);
        self.forces.push(force);
        self.f_prev = force;
        self.elastic = e0 + e1 * force;
    }

    /// Elastic displacement of the plane at the newest step [m].
    pub fn elastic_m(&self) -> f64 {
        self.elastic
    }

    /// The state to come back to if a trial step is taken again.
    pub fn mark(&self) -> SlabMark {
        SlabMark {
            len: self.q.len(),
            a: self.a,
            b: self.b,
            f_prev: self.f_prev,
            elastic: self.elastic,
        }
    }

    /// Back to a marked state.
    pub fn reset(&mut self, mark: SlabMark) {
        self.q.truncate(mark.len);
        self.forces.truncate(mark.len);
        self.a = mark.a;
        self.b = mark.b;
        self.f_prev = mark.f_prev;
        self.elastic = mark.elastic;
    }

    /// The slab's stress waves over the run: H = F + r H(t - T) on the step grid, read as any
    /// bar's (stress from the contact end to the free end).
    pub fn waves(&self) -> BarWaves {
        let g = self.geometry;
        let t = 2.0 * g.length_m / g.wave_speed_m_s;
        let tap = Tap::new(t, self.h);
        let r = self.round_decay;
        let mut hs = Series::with_capacity(self.forces.len());
        let gain = 1.0 / (1.0 - r * tap.newest_weight());
        for &f in &self.forces {
            let v = (f + r * tap.known_before_push(&hs)) * gain;
            hs.push(v);
        }
        BarWaves {
            body_length_m: g.length_m,
            zone_length_m: 0.0,
            wave_speed_m_s: g.wave_speed_m_s,
            area_m2: g.area_m2,
            impedance_n_s_m: g.impedance_n_s_m,
            initial_velocity_m_s: 0.0,
            push_direction: g.push_direction,
            end_s: (self.forces.len() - 1) as f64 * self.h,
            history: History::Uniform {
                dt_s: self.h,
                values: hs.into_samples(),
            },
            decay_per_s: g.decay_per_s,
        }
    }
}
