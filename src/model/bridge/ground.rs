//! The ground under a bridge: one record with its linear baseline removed (see
//! `motion::baseline`), reaching each support when the travelling wave gets there. Its
//! acceleration is linear between samples, so its velocity and displacement are exact cubics
//! between them; before the wave arrives and after the record has passed the ground is at rest
//! (the correction makes the end velocity and displacement zero).

use crate::model::motion::GroundMotion;
use crate::model::motion::baseline::Baseline;

/// The corrected record, with its exact velocity and displacement at every sample.
#[derive(Debug, Clone)]
pub struct Ground {
    /// The record less its baseline.
    pub corrected: GroundMotion,
    /// The baseline removed.
    pub baseline: Baseline,
    velocity: Vec<f64>,
    displacement: Vec<f64>,
    /// The record's length and the round-off [`Ground::side`] allows at its ends [s].
    end_s: f64,
    edge_eps: f64,
}

/// Acceleration, velocity and displacement of the ground at one support and instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct GroundState {
    /// [m/s^2]
    pub accel: f64,
    /// [m/s]
    pub velocity: f64,
    /// [m]
    pub displacement: f64,
}

impl Ground {
    /// The ground of `motion`, baseline corrected.
    pub fn new(motion: &GroundMotion) -> Self {
        let (corrected, baseline) = motion.baseline_corrected();
        let (velocity, displacement) = corrected.integrated().unzip();
        Ground {
            end_s: corrected.duration_s(),
            edge_eps: 1e-9 * corrected.dt_s,
            corrected,
            baseline,
            velocity,
            displacement,
        }
    }

    /// The record's length [s].
    pub fn duration_s(&self) -> f64 {
        self.corrected.duration_s()
    }

    /// The ground at a support the motion reaches `delay_s` late, at time `t_s`.
    pub fn at(&self, t_s: f64, delay_s: f64) -> GroundState {
        let a = &self.corrected.accel_m_s2;
        let t = t_s - delay_s;
        if t <= 0.0 || a.len() < 2 {
            return GroundState::default();
        }
        let h = self.corrected.dt_s;
        let p = t / h;
        let i = p as usize;
        if i + 1 >= a.len() {
            let last = a.len() - 1;
            return GroundState {
                accel: if p == last as f64 { a[last] } else { 0.0 },
                velocity: self.velocity[last],
                displacement: self.displacement[last],
            };
        }
        let s = t - i as f64 * h;
        let slope = (a[i + 1] - a[i]) / h;
        GroundState {
            accel: a[i] + slope * s,
            velocity: self.velocity[i] + a[i] * s + 0.5 * slope * s * s,
            displacement: self.displacement[i]
                + self.velocity[i] * s
                + 0.5 * a[i] * s * s
                + slope * s * s * s / 6.0,
        }
    }

    /// The acceleration at `t` (time since the wave arrived) where that is at one of the
    /// record's ends or outside it, to within round-off of a step: at its start the first
    /// sample if `at_start` (the right limit) else 0, at its end the last sample if `at_end`
    /// (the left limit) else 0, and 0 outside; `None` inside, where the record is continuous.
    fn side(&self, t: f64, at_start: bool, at_end: bool) -> Option<f64> {
        let a = &self.corrected.accel_m_s2;
        let eps = 1e-9 * self.corrected.dt_s;
        let end = self.duration_s();
        if a.is_empty() || t < -eps || t > end + eps {
            return Some(0.0);
        }
        if t.abs() <= eps {
            return Some(if at_start { a[0] } else { 0.0 });
        }
        if (t - end).abs() <= eps {
            return Some(if at_end { a[a.len() - 1] } else { 0.0 });
        }
        None
    }

    /// [`Ground::accel_after`] from the ground `now` at that instant and support (read once
    /// for every look at it).
    #[inline]
    pub fn accel_after_from(&self, t_s: f64, delay_s: f64, now: &GroundState) -> f64 {
        let t = t_s - delay_s;
        if self.inside(t) {
            return now.accel;
        }
        self.side(t, true, false).unwrap_or(now.accel)
    }

    /// [`Ground::accel_before`] from the ground `now` at that instant and support.
    #[inline]
    pub fn accel_before_from(&self, t_s: f64, delay_s: f64, now: &GroundState) -> f64 {
        let t = t_s - delay_s;
        if self.inside(t) {
            return now.accel;
        }
        self.side(t, false, true).unwrap_or(now.accel)
    }

    /// Whether `t` (time since the wave arrived) lies inside the record, clear of its ends by
    /// more than [`Ground::side`]'s round-off: where `side` has nothing to say (the common
    /// case, told by two comparisons).
    #[inline]
    fn inside(&self, t: f64) -> bool {
        t > self.edge_eps && t < self.end_s - self.edge_eps
    }

    /// The acceleration just after `t_s` (its right limit): the record's first sample at the
    /// instant the wave arrives, zero at its end.
    pub fn accel_after(&self, t_s: f64, delay_s: f64) -> f64 {
        self.side(t_s - delay_s, true, false)
            .unwrap_or_else(|| self.at(t_s, delay_s).accel)
    }

    /// The acceleration just before `t_s` (its left limit): zero at the instant the wave
    /// arrives, the record's last sample at its end.
    pub fn accel_before(&self, t_s: f64, delay_s: f64) -> f64 {
        self.side(t_s - delay_s, false, true)
            .unwrap_or_else(|| self.at(t_s, delay_s).accel)
    }
}
