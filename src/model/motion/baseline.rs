//! A record with a linear baseline removed, and the ground at a point a travelling wave reaches
//! late: what a long structure on several supports needs, since the supports' different
//! displacements enter the joints between them.
//!
//! A raw accelerogram integrates to a velocity and a displacement that do not return to zero at
//! its end (noise, a tilted instrument, a cut record). One support alone does not feel that, but
//! two supports shaken at different times would drift apart for ever. Removing the baseline
//! c0 + c1 t, with c0 and c1 chosen so that the exactly integrated velocity and displacement
//! (from rest at t = 0) are both zero at the record's end T, leaves a ground that starts and ends
//! at rest, and stays at rest after the record.

use super::GroundMotion;

/// The removed baseline a(t) - a_c(t) = c0 + c1 t.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Baseline {
    /// Offset [m/s^2].
    pub c0_m_s2: f64,
    /// Slope [m/s^3].
    pub c1_m_s3: f64,
}

impl GroundMotion {
    /// The velocity and displacement at the record's end, from rest at t = 0, integrated exactly
    /// for an acceleration linear between samples.
    pub fn end_velocity_and_displacement(&self) -> (f64, f64) {
        self.integrated().last().expect("one pair at least")
    }

    /// The record less the linear baseline that leaves its end velocity and displacement zero,
    /// and that baseline. A record of one sample, or of zero length, is returned as it is.
    pub fn baseline_corrected(&self) -> (GroundMotion, Baseline) {
        let t_end = self.duration_s();
        if self.accel_m_s2.len() < 2 || t_end <= 0.0 {
            let none = Baseline {
                c0_m_s2: 0.0,
                c1_m_s3: 0.0,
            };
            return (self.clone(), none);
        }
        // V = int a, D = int (T - s) a(s) ds; the baseline integrates to c0 T + c1 T^2 / 2 and
        // c0 T^2 / 2 + c1 T^3 / 6. Equal to V and D when:
        let (v, d) = self.end_velocity_and_displacement();
        let t = t_end;
        let baseline = Baseline {
            c0_m_s2: -2.0 * v / t + 6.0 * d / (t * t),
            c1_m_s3: 6.0 * v / (t * t) - 12.0 * d / (t * t * t),
        };
        let accel_m_s2 = self
            .accel_m_s2
            .iter()
            .enumerate()
            .map(|(n, a)| a - (baseline.c0_m_s2 + baseline.c1_m_s3 * n as f64 * self.dt_s))
            .collect();
        let corrected = GroundMotion {
            name: format!("{} (baseline corrected)", self.name),
            dt_s: self.dt_s,
            accel_m_s2,
        };
        (corrected, baseline)
    }

    /// The acceleration at a support the motion reaches `delay_s` late: a(t - delay), zero
    /// before it arrives and after the record has passed.
    #[inline]
    pub fn delayed_at(&self, t_s: f64, delay_s: f64) -> f64 {
        self.at(t_s - delay_s)
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::record;
    use super::*;

    /// Velocity and displacement at T by the trapezoid and Simpson's rule on a grid 1000 times
    /// finer than the record: an integration independent of the exact recurrence.
    fn fine_end_state(m: &GroundMotion) -> (f64, f64) {
        let t_end = m.duration_s();
        let n = 1000 * (m.accel_m_s2.len() - 1);
        let h = t_end / n as f64;
        let (mut v, mut d) = (0.0, 0.0);
        for i in 0..n {
            let (t0, t1) = (i as f64 * h, (i + 1) as f64 * h);
            let (a0, am, a1) = (m.at(t0), m.at(0.5 * (t0 + t1)), m.at(t1));
            // Over a step: d gains h v + int_0^h (h - s) a(t0 + s) ds (Simpson on the kernel).
            d += h * v + h / 6.0 * (h * a0 + 4.0 * 0.5 * h * am);
            v += h / 6.0 * (a0 + 4.0 * am + a1);
        }
        (v, d)
    }

    #[test]
    fn a_symmetric_triangle_loses_half_its_peak_as_a_constant_baseline() {
        // a = A at T/2, zero at both ends: V = A T / 2, D = A T^2 / 4 (centroid at T / 2), so
        // c0 = -2 V / T + 6 D / T^2 = A / 2 and c1 = 0.
        let (a, t) = (3.0, 4.0);
        let (corrected, b) = record(vec![0.0, a, 0.0], t / 2.0).baseline_corrected();
        assert!((b.c0_m_s2 - a / 2.0).abs() < 1e-14, "{b:?}");
        assert!(b.c1_m_s3.abs() < 1e-14, "{b:?}");
        assert_eq!(corrected.accel_m_s2, vec![-a / 2.0, a / 2.0, -a / 2.0]);
    }

    #[test]
    fn a_ramp_is_all_baseline() {
        // a = A t / T is c1 t with c1 = A / T: nothing is left.
        let (a, t) = (2.5, 5.0);
        let m = record((0..=50).map(|i| a * i as f64 / 50.0).collect(), t / 50.0);
        let (corrected, b) = m.baseline_corrected();
        assert!(b.c0_m_s2.abs() < 1e-12, "{b:?}");
        assert!((b.c1_m_s3 - a / t).abs() < 1e-12, "{b:?}");
        assert!(corrected.accel_m_s2.iter().all(|x| x.abs() < 1e-12));
    }

    #[test]
    fn a_corrected_record_ends_at_rest_by_an_independent_integration() {
        // A burst with a drift in it, as a raw record has.
        let m = record(
            (0..400)
                .map(|i| {
                    let t = i as f64 * 0.01;
                    3.0 * (7.0 * t).sin() * (-0.5 * t).exp() + 0.2 + 0.05 * t
                })
                .collect(),
            0.01,
        );
        let (v_raw, d_raw) = fine_end_state(&m);
        assert!(
            v_raw.abs() > 0.5 && d_raw.abs() > 1.0,
            "the raw record drifts"
        );
        let (corrected, _) = m.baseline_corrected();
        let (v, d) = fine_end_state(&corrected);
        // The fine integration agrees with the exact one to its own error (Simpson on a
        // piecewise-linear integrand with kinks at the samples: about 1e-9 here).
        assert!(v.abs() < 1e-8, "end velocity {v}");
        assert!(d.abs() < 1e-8, "end displacement {d}");
        // And the ground stays at rest after the record: no acceleration past its end.
        assert_eq!(corrected.at(corrected.duration_s() + 0.5), 0.0);
    }

    #[test]
    fn a_delayed_support_sees_nothing_before_the_wave_arrives() {
        let m = record(vec![1.0, 2.0, 3.0], 0.1);
        assert_eq!(m.delayed_at(0.05, 0.1), 0.0);
        assert_eq!(m.delayed_at(0.15, 0.1), m.at(0.05));
        assert_eq!(m.delayed_at(0.35, 0.1), 0.0);
    }
}
