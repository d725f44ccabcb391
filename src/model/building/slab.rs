//! A roof slab's elastic (wave) response to the pounding force, for the Sears contact.
//!
//! The slab is a free-free bar carrying the building's mass (rho~ = m / (A L)), so its rigid-body
//! response to F is the oscillator's. What the contact needs on top of u1 - u2 - gap is the
//! elastic part at the plane P (x = d from the contact end): d'Alembert's response minus the
//! rigid-body one,
//!   e(t) = (1/Z) [Psi(t - tau) + Psi(t - T + tau)] - (1/m) integral of Phi,
//! (tau = d/c, T = 2L/c; tau = 0 for the end reading). Material damping makes that elastic kernel
//! decay as exp(-t/t_d), rigid motion untouched. With A(t) = integral of exp(-(t-s)/t_d) F(s) ds
//! and B' = A - B/t_d, the decaying kernel keeps an O(1) recursion:
//!   Q(t) = A(t) + r Q(t - T),  r = exp(-T/t_d),
//!   e(t) = (1/Z) [exp(-tau/t_d) Q(t - tau) + exp(-(T - tau)/t_d) Q(t - T + tau)] - B(t)/m.
//! With no damping A = Phi, Q = Psi, B = integral of Phi: the undamped d'Alembert response.
//! t_d = T / (2 pi zeta): zeta is the damping ratio of the slab's fundamental axial mode.

use super::Building;
use crate::model::history::{Series, Tap};

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
    pub fn new(
        building: &Building,
        zone_m: f64,
        damping_ratio: f64,
        h: f64,
        capacity: usize,
    ) -> Self {
        let c = building.slab_wave_speed_m_s();
        let t = building.slab_round_trip_s();
        let tau = zone_m / c;
        let decay_time = if damping_ratio > 0.0 {
            t / (2.0 * std::f64::consts::PI * damping_ratio)
        } else {
            f64::INFINITY
        };
        let decay = |s: f64| (-s / decay_time).exp();
        let mut q = Series::with_capacity(capacity);
        q.push(0.0);
        SlabWaves {
            inv_z: 1.0 / building.slab_impedance_n_s_m(),
            inv_m: 1.0 / building.mass_kg,
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
        self.f_prev = force;
        self.elastic = e0 + e1 * force;
    }

    /// Elastic displacement of the plane at the newest step [m].
    pub fn elastic_m(&self) -> f64 {
        self.elastic
    }

    pub fn mark(&self) -> SlabMark {
        SlabMark {
            len: self.q.len(),
            a: self.a,
            b: self.b,
            f_prev: self.f_prev,
            elastic: self.elastic,
        }
    }

    pub fn reset(&mut self, mark: SlabMark) {
        self.q.truncate(mark.len);
        self.a = mark.a;
        self.b = mark.b;
        self.f_prev = mark.f_prev;
        self.elastic = mark.elastic;
    }
}
