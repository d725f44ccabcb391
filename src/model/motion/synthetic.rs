//! A seeded synthetic accelerogram: Kanai-Tajimi filtered white noise under a build-up / strong /
//! decay envelope (Amin & Ang), scaled to a chosen peak. The same seed gives the same record on
//! every machine (the generator is a fixed splitmix64, not a platform RNG).

use super::{G, GroundMotion};

/// What to generate. Defaults: a firm-soil record (ground frequency 2.5 Hz, ground damping 0.6),
/// 20 s long with 2 s build-up and 6 s of strong shaking, 0.3 g peak, sampled at 0.01 s: a
/// record of El Centro's size (0.32 g) that needs no file.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SyntheticSpec {
    /// Random seed.
    pub seed: u64,
    /// Peak ground acceleration the record is scaled to [g].
    pub pga_g: f64,
    /// Length [s].
    pub duration_s: f64,
    /// Sampling step [s].
    pub dt_s: f64,
    /// Kanai-Tajimi ground frequency [Hz].
    pub ground_frequency_hz: f64,
    /// Kanai-Tajimi ground damping ratio.
    pub ground_damping: f64,
    /// Envelope: rise time [s].
    pub rise_s: f64,
    /// Envelope: strong-motion duration [s].
    pub strong_s: f64,
    /// Decay rate of the envelope's tail [1/s].
    pub decay_per_s: f64,
}

impl Default for SyntheticSpec {
    fn default() -> Self {
        SyntheticSpec {
            seed: 1940,
            pga_g: 0.3,
            duration_s: 20.0,
            dt_s: 0.01,
            ground_frequency_hz: 2.5,
            ground_damping: 0.6,
            rise_s: 2.0,
            strong_s: 6.0,
            decay_per_s: 0.3,
        }
    }
}

struct SplitMix64(u64);

impl SplitMix64 {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn uniform(&mut self) -> f64 {
        ((self.next() >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    /// Standard normal (Box-Muller).
    fn normal(&mut self) -> f64 {
        let (u1, u2) = (self.uniform(), self.uniform());
        (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
    }
}

impl SyntheticSpec {
    /// The envelope at `t`: a quadratic rise, a plateau, an exponential decay.
    pub fn envelope(&self, t: f64) -> f64 {
        if t < self.rise_s {
            (t / self.rise_s).powi(2)
        } else if t < self.rise_s + self.strong_s {
            1.0
        } else {
            (-self.decay_per_s * (t - self.rise_s - self.strong_s)).exp()
        }
    }

    /// The record: filtered white noise under the envelope, scaled to the PGA.
    pub fn generate(&self) -> GroundMotion {
        let n = (self.duration_s / self.dt_s).round() as usize + 1;
        let mut rng = SplitMix64(self.seed);
        let wg = 2.0 * std::f64::consts::PI * self.ground_frequency_hz;
        let zg = self.ground_damping;
        // The soil filter x'' + 2 zg wg x' + wg^2 x = -w(t), a = 2 zg wg x' + wg^2 x, driven by
        // piecewise-constant white noise and integrated exactly enough with 10 RK2 sub-steps.
        let sub = 10;
        let h = self.dt_s / sub as f64;
        let (mut x, mut v) = (0.0f64, 0.0f64);
        let mut raw = Vec::with_capacity(n);
        for i in 0..n {
            let w = rng.normal() / self.dt_s.sqrt();
            for _ in 0..sub {
                let acc = |x: f64, v: f64| -w - 2.0 * zg * wg * v - wg * wg * x;
                let (a1, v1) = (acc(x, v), v);
                let (xm, vm) = (x + 0.5 * h * v1, v + 0.5 * h * a1);
                x += h * vm;
                v += h * acc(xm, vm);
            }
            raw.push((2.0 * zg * wg * v + wg * wg * x) * self.envelope(i as f64 * self.dt_s));
        }
        let peak = raw.iter().fold(0.0f64, |m, a| m.max(a.abs()));
        let scale = if peak > 0.0 {
            self.pga_g * G / peak
        } else {
            0.0
        };
        GroundMotion {
            name: format!(
                "synthetic Kanai-Tajimi (seed {}, {} g, {} s)",
                self.seed,
                crate::model::settings::shown(self.pga_g),
                crate::model::settings::shown(self.duration_s)
            ),
            dt_s: self.dt_s,
            accel_m_s2: raw.into_iter().map(|a| a * scale).collect(),
        }
    }
}
