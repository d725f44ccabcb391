//! Ground motion: a uniformly sampled acceleration record and the numbers that describe it.
//! Parsing lives in `io::motion`; the synthetic generator in [`synthetic`].

pub mod baseline;
pub mod synthetic;

/// Standard gravity [m/s^2].
pub const G: f64 = 9.80665;

/// The units a text record's accelerations are written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Units {
    /// Multiples of standard gravity.
    G,
    /// m/s^2.
    MetresPerSecond2,
    /// cm/s^2 (gal).
    CentimetresPerSecond2,
}

impl Units {
    /// Every unit.
    pub const ALL: [Units; 3] = [
        Units::G,
        Units::MetresPerSecond2,
        Units::CentimetresPerSecond2,
    ];
    /// Their names, in the order of [`Units::ALL`].
    pub const NAMES: [&'static str; 3] = crate::model::names_of!(Self::ALL, 3);

    /// The unit of that name; the usual spellings with `^` and `gal` are understood too.
    pub fn from_name(s: &str) -> Option<Self> {
        match s {
            "m/s^2" => Some(Units::MetresPerSecond2),
            "cm/s^2" | "gal" => Some(Units::CentimetresPerSecond2),
            _ => Self::ALL.into_iter().find(|u| u.name() == s),
        }
    }
    /// The name presets and the command line use.
    pub const fn name(self) -> &'static str {
        match self {
            Units::G => "g",
            Units::MetresPerSecond2 => "m/s2",
            Units::CentimetresPerSecond2 => "cm/s2",
        }
    }
    /// One unit in m/s^2.
    pub fn to_m_s2(self) -> f64 {
        match self {
            Units::G => G,
            Units::MetresPerSecond2 => 1.0,
            Units::CentimetresPerSecond2 => 0.01,
        }
    }
}

/// Ground acceleration sampled at t = n dt.
#[derive(Debug, Clone, PartialEq)]
pub struct GroundMotion {
    /// What the record is (shown with results).
    pub name: String,
    /// Sampling step [s].
    pub dt_s: f64,
    /// Ground acceleration at t = n dt [m/s^2].
    pub accel_m_s2: Vec<f64>,
}

/// Summary numbers of a record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotionStats {
    /// Number of samples.
    pub points: usize,
    /// Length [s].
    pub duration_s: f64,
    /// Peak ground acceleration [m/s^2] and when.
    pub pga_m_s2: f64,
    /// When the peak ground acceleration occurs [s].
    pub pga_time_s: f64,
    /// Peak ground velocity [m/s] (trapezoid, no baseline correction).
    pub pgv_m_s: f64,
    /// Arias intensity pi / (2 g) times the integral of a^2 [m/s].
    pub arias_m_s: f64,
    /// Time between 5% and 95% of the Arias intensity [s].
    pub significant_duration_s: f64,
    /// Predominant period: where the 5%-damped pseudo-acceleration spectrum peaks [s].
    pub predominant_period_s: f64,
    /// That peak spectral pseudo-acceleration [m/s^2].
    pub peak_spectral_accel_m_s2: f64,
}

impl GroundMotion {
    /// The record's name without the note of where it came from (`[built in: ...]`), as a
    /// slide or a lecture shows it.
    pub fn short_name(&self) -> &str {
        self.name.split(" [").next().unwrap_or(&self.name).trim()
    }

    /// Length of the record [s].
    pub fn duration_s(&self) -> f64 {
        self.dt_s * self.accel_m_s2.len().saturating_sub(1) as f64
    }

    /// Acceleration at time t, linear between samples, zero outside the record.
    #[inline]
    pub fn at(&self, t_s: f64) -> f64 {
        if t_s < 0.0 || self.accel_m_s2.is_empty() {
            return 0.0;
        }
        let a = &self.accel_m_s2;
        let p = t_s / self.dt_s;
        // p >= 0: truncation is the floor, without a call to one. A signed integer's conversions
        // both ways are one instruction each on x86-64 (an unsigned one's are several), and
        // give the same whole number below 2^63 (p saturates above it, past every record; below
        // zero, as for a NaN, the first sample's interval is read, as `as usize` would give).
        let i = (p as i64).max(0);
        let last = (a.len() - 1) as i64;
        if i >= last {
            return if i == last && p == i as f64 {
                a[a.len() - 1]
            } else {
                0.0
            };
        }
        let x = p - i as f64;
        let i = i as usize;
        // SAFETY: 0 <= i < last, so i + 1 <= last is within the record.
        let (a0, a1) = unsafe { (*a.get_unchecked(i), *a.get_unchecked(i + 1)) };
        a0 * (1.0 - x) + a1 * x
    }

    /// The first `duration_s` of the record.
    pub fn truncated(mut self, duration_s: f64) -> Self {
        let n = (duration_s / self.dt_s + 1e-9).floor() as usize + 1;
        self.accel_m_s2.truncate(n.max(1));
        self
    }

    /// The record followed by `settle_s` of rest (zero acceleration), at its own step: what a
    /// run needs to let the motion die out after the shaking.
    pub fn settled(mut self, settle_s: f64) -> Self {
        let extra = (settle_s / self.dt_s - 1e-9).ceil().max(0.0) as usize;
        self.accel_m_s2.extend(std::iter::repeat_n(0.0, extra));
        self
    }

    /// The record times a factor (a negative factor flips it).
    pub fn scaled(mut self, factor: f64) -> Self {
        for a in &mut self.accel_m_s2 {
            *a *= factor;
        }
        self
    }

    /// The ground's displacement at each sample [m], from rest at t = 0: the record integrated
    /// twice, exactly for an acceleration linear between samples (as the building solver takes
    /// it), without baseline correction.
    pub fn displacement_m(&self) -> Vec<f64> {
        self.integrated().map(|(_, d)| d).collect()
    }

    /// The ground's velocity and displacement at each sample, from rest at t = 0, exact for an
    /// acceleration linear between samples (one pair at t = 0 even for an empty record).
    pub fn integrated(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        let h = self.dt_s;
        let steps = self
            .accel_m_s2
            .windows(2)
            .scan((0.0, 0.0), move |(v, d), w| {
                *d += h * *v + h * h * (2.0 * w[0] + w[1]) / 6.0;
                *v += 0.5 * h * (w[0] + w[1]);
                Some((*v, *d))
            });
        std::iter::once((0.0, 0.0)).chain(steps)
    }

    /// Peak values, intensity and durations of the record.
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
        for i in 1..a.len() {
            v += 0.5 * (a[i - 1] + a[i]) * dt;
            pgv = pgv.max(v.abs());
            cumulative[i] = cumulative[i - 1] + 0.5 * (a[i - 1] * a[i - 1] + a[i] * a[i]) * dt;
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
        let spectrum = spectrum_peak(self);
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
            predominant_period_s: spectrum.0,
            peak_spectral_accel_m_s2: spectrum.1,
        }
    }

    /// Pseudo-acceleration w^2 max|u| of an oscillator of period `period_s` and damping ratio
    /// `damping` under the record (linear between samples), by Newmark's average-acceleration
    /// method with at least 40 steps per period (period error below 0.2%).
    pub fn spectral_accel(&self, period_s: f64, damping: f64) -> f64 {
        let sub = self.spectrum_steps(period_s);
        self.spectral_accels([period_s; 2], damping, sub)[0]
    }

    /// The steps a sample of the record is divided into for an oscillator of period `period_s`:
    /// 40 a period at least.
    fn spectrum_steps(&self, period_s: f64) -> usize {
        (40.0 * self.dt_s / period_s).ceil().max(1.0) as usize
    }

    /// [`GroundMotion::spectral_accel`] for two periods whose samples are divided into the same
    /// `sub` steps, side by side: the same operations lane by lane, which the compiler can make
    /// one vector operation each.
    fn spectral_accels(&self, period_s: [f64; 2], damping: f64, sub: usize) -> [f64; 2] {
        let h = self.dt_s / sub as f64;
        let (mut on_u, mut on_v, mut inv_k_hat, mut k) = ([0.0; 2], [0.0; 2], [0.0; 2], [0.0; 2]);
        let (two_h, four_h, four_hh) = (2.0 / h, 4.0 / h, 4.0 / (h * h));
        for l in 0..2 {
            let w = 2.0 * std::f64::consts::PI / period_s[l];
            let c = 2.0 * damping * w;
            k[l] = w * w;
            // The step's constants worked out once: a report's spectrum takes 80 periods of a
            // whole record, 130 000 steps for 8 s of El Centro.
            inv_k_hat[l] = 1.0 / (k[l] + c * two_h + four_hh);
            (on_u[l], on_v[l]) = (four_hh + c * two_h, four_h + c);
        }
        let (mut u, mut v) = ([0.0f64; 2], [0.0f64; 2]);
        let mut acc = [-self.accel_m_s2.first().copied().unwrap_or(0.0); 2];
        let mut peak = [0.0f64; 2];
        for pair in self.accel_m_s2.windows(2) {
            let slope = (pair[1] - pair[0]) / sub as f64;
            for j in 1..=sub {
                let ag = pair[0] + slope * j as f64;
                for l in 0..2 {
                    let u1 = (on_u[l] * u[l] + on_v[l] * v[l] + acc[l] - ag) * inv_k_hat[l];
                    let du = u1 - u[l];
                    acc[l] = four_hh * du - four_h * v[l] - acc[l];
                    v[l] = two_h * du - v[l];
                    u[l] = u1;
                    peak[l] = peak[l].max(u1.abs());
                }
            }
        }
        [k[0] * peak[0], k[1] * peak[1]]
    }
}

/// The periods the spectrum is read at: 0.05 s to 4 s, 80 log-spaced.
fn spectrum_periods() -> impl Iterator<Item = f64> {
    (0..80).map(|i| 0.05 * (4.0f64 / 0.05).powf(i as f64 / 79.0))
}

/// The period ([`spectrum_periods`]) where the 5%-damped spectrum peaks, and the peak.
fn spectrum_peak(m: &GroundMotion) -> (f64, f64) {
    let periods: Vec<f64> = spectrum_periods().collect();
    // Two neighbours that divide the samples alike are worked out side by side.
    let mut sa = vec![0.0; periods.len()];
    let mut i = 0;
    while i < periods.len() {
        let sub = m.spectrum_steps(periods[i]);
        if i + 1 < periods.len() && m.spectrum_steps(periods[i + 1]) == sub {
            let both = m.spectral_accels([periods[i], periods[i + 1]], 0.05, sub);
            sa[i..i + 2].copy_from_slice(&both);
            i += 2;
        } else {
            sa[i] = m.spectral_accels([periods[i]; 2], 0.05, sub)[0];
            i += 1;
        }
    }
    let mut best = (0.0, 0.0);
    for (&t, &a) in periods.iter().zip(&sa) {
        if a > best.1 {
            best = (t, a);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    pub(super) fn record(accel_m_s2: Vec<f64>, dt_s: f64) -> GroundMotion {
        GroundMotion {
            name: "test".into(),
            dt_s,
            accel_m_s2,
        }
    }

    #[test]
    fn the_spectrum_worked_out_two_periods_at_a_time_is_each_period_worked_out_alone() {
        // A chirp from 0.5 to 20 Hz, so that the periods' responses differ widely.
        let dt = 0.01;
        let accel = (0..800)
            .map(|i| {
                let t = i as f64 * dt;
                (2.0 * std::f64::consts::PI * (0.5 + 2.4 * t) * t).sin()
            })
            .collect();
        let m = record(accel, dt);
        let (period, peak) = spectrum_peak(&m);
        let mut best = (0.0, 0.0);
        for t in spectrum_periods() {
            let alone = m.spectral_accels([t; 2], 0.05, m.spectrum_steps(t));
            assert_eq!(alone[0], alone[1], "lanes of one period at {t} s");
            if alone[0] > best.1 {
                best = (t, alone[0]);
            }
        }
        assert_eq!((period, peak), best);
        // And a pair's second lane is its period's own.
        let (a, b) = (0.3, 0.31);
        let sub = m.spectrum_steps(a);
        assert_eq!(sub, m.spectrum_steps(b));
        let pair = m.spectral_accels([a, b], 0.05, sub);
        assert_eq!(pair, [m.spectral_accel(a, 0.05), m.spectral_accel(b, 0.05)]);
    }

    #[test]
    fn ground_displacement_is_exact_for_constant_and_ramped_acceleration() {
        // a = 2: d = t^2; a = 3 t: d = t^3 / 2 (both zero velocity at rest).
        let n = 101;
        let dt = 0.01;
        let d = record(vec![2.0; n], dt).displacement_m();
        let ramp = record((0..n).map(|i| 3.0 * i as f64 * dt).collect(), dt).displacement_m();
        for i in 0..n {
            let t = i as f64 * dt;
            assert!((d[i] - t * t).abs() < 1e-12, "{} against {}", d[i], t * t);
            assert!(
                (ramp[i] - t.powi(3) / 2.0).abs() < 1e-12,
                "{} at {t}",
                ramp[i]
            );
        }
    }
}
