//! Ground motion: a uniformly sampled acceleration record and the numbers that describe it.
//! Parsing lives in `io::motion`; the synthetic generator in [`synthetic`].

pub mod synthetic;

/// Standard gravity [m/s^2].
pub const G: f64 = 9.80665;

/// Ground acceleration sampled at t = n dt.
#[derive(Debug, Clone, PartialEq)]
pub struct GroundMotion {
    pub name: String,
    pub dt_s: f64,
    pub accel_m_s2: Vec<f64>,
}

/// Summary numbers of a record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotionStats {
    pub points: usize,
    pub duration_s: f64,
    /// Peak ground acceleration [m/s^2] and when.
    pub pga_m_s2: f64,
    pub pga_time_s: f64,
    /// Peak ground velocity [m/s] (trapezoid, no baseline correction).
    pub pgv_m_s: f64,
    /// Arias intensity pi / (2 g) times the integral of a^2 [m/s].
    pub arias_m_s: f64,
    /// Time between 5% and 95% of the Arias intensity [s].
    pub significant_duration_s: f64,
    /// Mean period: 1 / (mean zero-crossing rate / 2) of the acceleration [s].
    pub mean_crossing_period_s: f64,
}

impl GroundMotion {
    pub fn duration_s(&self) -> f64 {
        self.dt_s * self.accel_m_s2.len().saturating_sub(1) as f64
    }

    /// Acceleration at time t, linear between samples, zero outside the record.
    #[inline]
    pub fn at(&self, t_s: f64) -> f64 {
        if t_s < 0.0 || self.accel_m_s2.is_empty() {
            return 0.0;
        }
        let p = t_s / self.dt_s;
        let i = p.floor() as usize;
        if i + 1 >= self.accel_m_s2.len() {
            return if i < self.accel_m_s2.len() && p == i as f64 {
                self.accel_m_s2[i]
            } else {
                0.0
            };
        }
        let x = p - i as f64;
        self.accel_m_s2[i] * (1.0 - x) + self.accel_m_s2[i + 1] * x
    }

    /// The first `duration_s` of the record.
    pub fn truncated(mut self, duration_s: f64) -> Self {
        let n = (duration_s / self.dt_s + 1e-9).floor() as usize + 1;
        self.accel_m_s2.truncate(n.max(1));
        self
    }

    /// The record times a factor (a negative factor flips it).
    pub fn scaled(mut self, factor: f64) -> Self {
        for a in &mut self.accel_m_s2 {
            *a *= factor;
        }
        self
    }

    pub fn stats(&self) -> MotionStats {
        let a = &self.accel_m_s2;
        let dt = self.dt_s;
        let (mut pga, mut pga_i) = (0.0f64, 0usize);
        for (i, &x) in a.iter().enumerate() {
            if x.abs() > pga.abs() {
                pga = x;
                pga_i = i;
            }
        }
        let (mut v, mut pgv) = (0.0f64, 0.0f64);
        let mut cumulative = vec![0.0; a.len()];
        let mut crossings = 0usize;
        for i in 1..a.len() {
            v += 0.5 * (a[i - 1] + a[i]) * dt;
            pgv = pgv.max(v.abs());
            cumulative[i] = cumulative[i - 1] + 0.5 * (a[i - 1] * a[i - 1] + a[i] * a[i]) * dt;
            if (a[i - 1] < 0.0) != (a[i] < 0.0) {
                crossings += 1;
            }
        }
        let total = *cumulative.last().unwrap_or(&0.0);
        let when = |frac: f64| {
            cumulative
                .iter()
                .position(|&c| c >= frac * total)
                .unwrap_or(0) as f64
                * dt
        };
        let duration = self.duration_s();
        MotionStats {
            points: a.len(),
            duration_s: duration,
            pga_m_s2: pga.abs(),
            pga_time_s: pga_i as f64 * dt,
            pgv_m_s: pgv,
            arias_m_s: std::f64::consts::PI / (2.0 * G) * total,
            significant_duration_s: if total > 0.0 {
                when(0.95) - when(0.05)
            } else {
                0.0
            },
            mean_crossing_period_s: if crossings > 0 {
                2.0 * duration / crossings as f64
            } else {
                f64::INFINITY
            },
        }
    }
}
