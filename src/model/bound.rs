//! Bounds that let a free stretch be checked at a few points instead of at every grid point.
//!
//! Between two samples of the record the ground acceleration is linear, so each mode is its
//! linear particular response plus a free (homogeneous) vibration. The particular part is a line,
//! whose fourth derivative is zero; the free part is Re(A e^(lambda t)) with |lambda| = w for an
//! underdamped mode, so its fourth derivative never exceeds |A| w^4. A signal that is a
//! combination of modes therefore has a known bound M4 on its fourth derivative over the whole
//! stretch, and the cubic through its values and rates at two points a distance l apart is within
//! l^4 M4 / 384 of it everywhere between them. A check that finds the cubic's largest value plus
//! that margin below the gap has proved that no contact starts there, without looking at the
//! points in between; and likewise for a peak.

/// What the rounding of the states at two points can move a cubic's maximum by, relative to the
/// size of its ends and slopes: far above the states' round-off, far below any gap or peak.
pub(crate) const ROUNDING: f64 = 1e-12;

/// Whether a signal's rate, known with its own rate (the acceleration) at both ends of a span
/// `l`, keeps one sign over it: the cubic through them, widened by its margin from the bound `m5`
/// on the rate's fourth derivative, stays off zero.
pub(crate) fn monotone(start: [f64; 2], end: [f64; 2], l: f64, m5: f64) -> bool {
    let margin = cubic_margin(m5, l)
        + ROUNDING * (start[0].abs() + end[0].abs() + l * (start[1].abs() + end[1].abs()));
    let high = cubic_max(start[0], start[1], end[0], end[1], l);
    let low = -cubic_max(-start[0], -start[1], -end[0], -end[1], l);
    low - margin > 0.0 || high + margin < 0.0
}

/// Bounds on one mode's response over a stretch of length `len` where its forcing is linear,
/// from the augmented state y = [q, q', g, g'] at its start: on |q| itself (the free
/// vibration's amplitude plus the particular line's larger end), on its fourth derivative and on
/// its fifth.
pub(crate) fn mode_bounds(omega: f64, zeta: f64, y: &[f64; 4], len: f64) -> [f64; 3] {
    let (m4, m5) = derivative_bounds(omega, zeta, y);
    let Some(Envelope { alpha, beta, free }) = envelope(omega, zeta, y) else {
        return [f64::INFINITY, m4, m5];
    };
    [free + alpha.abs().max((alpha + beta * len).abs()), m4, m5]
}

/// A mode's response where its forcing is linear: the particular line alpha + beta t, and a
/// bound on how far the free vibration takes it from that line.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Envelope {
    pub alpha: f64,
    pub beta: f64,
    pub free: f64,
}

/// A mode's response where its forcing is linear, split as the particular line alpha + beta t
/// and the free vibration about it.
struct Response {
    alpha: f64,
    beta: f64,
    w2: f64,
    free: Free,
}

/// The free vibration about the particular line, by damping.
enum Free {
    /// A e^(lambda t) with |lambda| = w: its amplitude.
    Under { amplitude: f64 },
    /// Near critical damping, (A + B t) e^(-w t).
    Critical { a: f64, b: f64 },
    /// a1 e^(l1 t) + a2 e^(l2 t).
    Over { a1: f64, a2: f64, l1: f64, l2: f64 },
}

impl Response {
    /// The response from the augmented state y = [q, q', g, g'] (none for a mode without
    /// stiffness).
    fn of(omega: f64, zeta: f64, y: &[f64; 4]) -> Option<Response> {
        if omega <= 0.0 || !omega.is_finite() {
            return None;
        }
        let w2 = omega * omega;
        // The particular response to g + g' s is alpha + beta s.
        let beta = y[3] / w2;
        let alpha = (y[2] - 2.0 * zeta * omega * beta) / w2;
        let (qh, vh) = (y[0] - alpha, y[1] - beta);
        let free = if zeta < 0.999 {
            let wd = omega * (1.0 - zeta * zeta).sqrt();
            let b = (vh + zeta * omega * qh) / wd;
            Free::Under {
                amplitude: (qh * qh + b * b).sqrt(),
            }
        } else if zeta <= 1.001 {
            Free::Critical {
                a: qh,
                b: vh + omega * qh,
            }
        } else {
            let root = (zeta * zeta - 1.0).sqrt();
            let (l1, l2) = (-omega * (zeta - root), -omega * (zeta + root));
            let a1 = (vh - l2 * qh) / (l1 - l2);
            Free::Over {
                a1,
                a2: qh - a1,
                l1,
                l2,
            }
        };
        Some(Response {
            alpha,
            beta,
            w2,
            free,
        })
    }

    /// How far the free vibration ever takes the mode from the line.
    fn free_size(&self, omega: f64) -> f64 {
        match self.free {
            Free::Under { amplitude } => amplitude,
            // (A + B t) e^(-w t) is at most |A| + |B| / (e w); doubled for zeta near, not at, 1.
            Free::Critical { a, b } => 2.0 * (a.abs() + b.abs() / (std::f64::consts::E * omega)),
            Free::Over { a1, a2, .. } => a1.abs() + a2.abs(),
        }
    }

    /// The bound on the mode's n-th time derivative (n = 2 or 4): the line has none, and each
    /// derivative of the free vibration is at most |lambda| times the one before.
    fn derivative(&self, omega: f64, n: i32) -> f64 {
        debug_assert!(n == 2 || n == 4);
        let w_n2 = if n == 4 { self.w2 } else { 1.0 };
        let w_n = w_n2 * self.w2;
        match self.free {
            Free::Under { amplitude } => amplitude * w_n,
            // Near critical damping the n-th derivative is within (|A| + |B| / (e w)) w^n +
            // n |B| w^(n-1); the factor 2 covers the few per mille by which zeta may differ from
            // 1 here.
            Free::Critical { a, b } => {
                2.0 * (a.abs() * w_n
                    + b.abs() * omega * w_n2 * (f64::from(n) + std::f64::consts::E.recip()))
            }
            Free::Over { a1, a2, l1, l2 } => a1.abs() * l1.powi(n) + a2.abs() * l2.powi(n),
        }
    }
}

/// The envelope of one mode from its augmented state y = [q, q', g, g'] (none for a mode
/// without stiffness).
pub(crate) fn envelope(omega: f64, zeta: f64, y: &[f64; 4]) -> Option<Envelope> {
    let r = Response::of(omega, zeta, y)?;
    Some(Envelope {
        alpha: r.alpha,
        beta: r.beta,
        free: r.free_size(omega),
    })
}

/// The bounds on the fourth and fifth time derivatives of one mode's response over a stretch
/// where its forcing is linear, from the augmented state y = [q, q', g, g'] at the stretch's
/// start: those of its value, and of its rate.
pub(crate) fn derivative_bounds(omega: f64, zeta: f64, y: &[f64; 4]) -> (f64, f64) {
    let m4 = fourth_derivative(omega, zeta, y);
    // Each derivative of the free vibration is at most |lambda| times the one before, with
    // |lambda| = w (underdamped), or the larger root (overdamped), or w with the (A + B t)
    // term's extra factor (near critical damping, covered by doubling).
    let rate = if zeta < 0.999 {
        omega
    } else if zeta <= 1.001 {
        2.0 * omega
    } else {
        omega * (zeta + (zeta * zeta - 1.0).sqrt())
    };
    (m4, m4 * rate)
}

/// The bound on the second time derivative of one mode's response over a stretch where its
/// forcing is linear, from the augmented state y = [q, q', g, g'] at its start.
pub(crate) fn second_derivative(omega: f64, zeta: f64, y: &[f64; 4]) -> f64 {
    Response::of(omega, zeta, y).map_or(f64::INFINITY, |r| r.derivative(omega, 2))
}

/// The bound on the fourth time derivative of one mode's response over a stretch where its
/// forcing is linear, from the augmented state y = [q, q', g, g'] at the stretch's start.
pub(crate) fn fourth_derivative(omega: f64, zeta: f64, y: &[f64; 4]) -> f64 {
    Response::of(omega, zeta, y).map_or(f64::INFINITY, |r| r.derivative(omega, 4))
}

/// The cubic through (0, y0) and (l, y1) with slopes v0 and v1: its largest value over [0, l],
/// the ends included.
pub(crate) fn cubic_max(y0: f64, v0: f64, y1: f64, v1: f64, l: f64) -> f64 {
    let mut best = y0.max(y1);
    // p(s) for s in [0, 1] with p'(0) = l v0, p'(1) = l v1: p'(s) = a s^2 + b s + c.
    let (m0, m1) = (l * v0, l * v1);
    let a = 6.0 * y0 + 3.0 * m0 - 6.0 * y1 + 3.0 * m1;
    let b = -6.0 * y0 - 4.0 * m0 + 6.0 * y1 - 2.0 * m1;
    let c = m0;
    let p = |s: f64| {
        let (s2, s3) = (s * s, s * s * s);
        (2.0 * s3 - 3.0 * s2 + 1.0) * y0
            + (s3 - 2.0 * s2 + s) * m0
            + (-2.0 * s3 + 3.0 * s2) * y1
            + (s3 - s2) * m1
    };
    let mut consider = |s: f64| {
        if s > 0.0 && s < 1.0 {
            best = best.max(p(s));
        }
    };
    if a.abs() <= 1e-14 * (b.abs() + c.abs()) {
        if b != 0.0 {
            consider(-c / b);
        }
    } else {
        let disc = b * b - 4.0 * a * c;
        if disc >= 0.0 {
            let r = disc.sqrt();
            // The root that avoids cancellation, and the other from the product of the roots.
            let q = -0.5 * (b + b.signum() * r);
            if q != 0.0 {
                consider(q / a);
                consider(c / q);
            } else {
                consider(0.0);
            }
        }
    }
    best
}

/// A bound on the cubic's largest value over [0, l] at the cost of a few operations: its Hermite
/// weights on the ends sum to one and are positive, those on the slopes are at most 4/27 in size.
#[inline]
pub(crate) fn cubic_bound(y0: f64, v0: f64, y1: f64, v1: f64, l: f64) -> f64 {
    y0.max(y1) + 4.0 / 27.0 * l * (v0.abs() + v1.abs())
}

/// The cubic's largest |value| over [0, l].
pub(crate) fn cubic_max_abs(y0: f64, v0: f64, y1: f64, v1: f64, l: f64) -> f64 {
    cubic_max(y0, v0, y1, v1, l).max(cubic_max(-y0, -v0, -y1, -v1, l))
}

/// How far a signal can stray from the cubic through its ends over a span `l`, given the bound
/// `m4` on its fourth derivative: l^4 m4 / 384, three times over. Once for the signal against
/// the cubic, once for the cubic through any two points inside the span against the signal (a
/// check that clears a span clears every shorter cubic in it, as the buildings' walks draw them
/// between grid points; the bridges read grid points only, where the first suffices), and once
/// for the rounding of the bound itself.
#[inline]
pub(crate) fn cubic_margin(m4: f64, l: f64) -> f64 {
    let l2 = l * l;
    3.0 * m4 * l2 * l2 / 384.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::building::modal::propagator;

    /// The exact response of one mode sampled densely, and its largest fourth derivative by
    /// finite differences (400 points a period: the differences' truncation is (w h)^2 / 6, a
    /// part in 10^4, and their rounding, which grows as 1 / h^4, smaller still).
    fn sampled_fourth(omega: f64, zeta: f64, y: [f64; 4], span: f64) -> f64 {
        let n = 400;
        let h = span / n as f64;
        let q: Vec<f64> = (0..=n)
            .map(|i| propagator(omega, zeta, i as f64 * h).apply(&y).0)
            .collect();
        (2..n - 2)
            .map(|i| {
                (q[i - 2] - 4.0 * q[i - 1] + 6.0 * q[i] - 4.0 * q[i + 1] + q[i + 2]).abs()
                    / h.powi(4)
            })
            .fold(0.0, f64::max)
    }

    /// Modes from light damping through critical to heavy: (omega [rad/s], zeta).
    const DAMPINGS: [(f64, f64); 5] = [
        (18.0, 0.05),
        (3.0, 0.0),
        (40.0, 0.6),
        (10.0, 1.0),
        (7.0, 3.0),
    ];

    #[test]
    fn the_fourth_derivative_bound_holds_for_light_critical_and_heavy_damping() {
        for (omega, zeta) in DAMPINGS {
            for y in [
                [0.01, 0.0, 0.0, 0.0],
                [0.0, 0.3, 0.0, 0.0],
                [0.004, -0.2, 2.0, -15.0],
                [-0.02, 0.1, -1.0, 40.0],
            ] {
                let span = 2.0 * std::f64::consts::PI / omega;
                let bound = fourth_derivative(omega, zeta, &y);
                let seen = sampled_fourth(omega, zeta, y, span);
                assert!(
                    seen <= bound * (1.0 + 1e-3),
                    "w {omega}, zeta {zeta}, y {y:?}: seen {seen:e} above the bound {bound:e}"
                );
                // Not loose by orders of magnitude either: the bound is the free vibration's
                // amplitude, which the sampled response reaches within its first period for
                // light damping.
                if zeta < 0.1 && (y[0] != 0.0 || y[1] != 0.0) {
                    assert!(
                        seen >= 0.5 * bound,
                        "w {omega}, zeta {zeta}: {seen:e} vs {bound:e}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_value_bound_holds_over_the_stretch() {
        for (omega, zeta) in DAMPINGS {
            for y in [
                [0.01, 0.0, 0.0, 0.0],
                [0.004, -0.2, 2.0, -15.0],
                [-0.02, 0.1, -1.0, 40.0],
            ] {
                let len = 0.3;
                let [bound, ..] = mode_bounds(omega, zeta, &y, len);
                let seen = (0..=3000)
                    .map(|i| {
                        propagator(omega, zeta, len * i as f64 / 3000.0)
                            .apply(&y)
                            .0
                            .abs()
                    })
                    .fold(0.0, f64::max);
                assert!(
                    seen <= bound * (1.0 + 1e-12),
                    "w {omega}, zeta {zeta}: {seen} > {bound}"
                );
            }
        }
    }

    #[test]
    fn a_cubic_through_a_signal_stays_within_its_margin_of_it() {
        let (omega, zeta) = (25.0, 0.05);
        let y = [0.01, 0.4, -3.0, 20.0];
        let m4 = fourth_derivative(omega, zeta, &y);
        for l in [1e-3, 1e-2, 0.05] {
            let (y1, v1) = propagator(omega, zeta, l).apply(&y);
            let worst = (0..=200)
                .map(|i| {
                    let s = l * i as f64 / 200.0;
                    let exact = propagator(omega, zeta, s).apply(&y).0;
                    let x = s / l;
                    let cubic = (2.0 * x.powi(3) - 3.0 * x * x + 1.0) * y[0]
                        + (x.powi(3) - 2.0 * x * x + x) * l * y[1]
                        + (-2.0 * x.powi(3) + 3.0 * x * x) * y1
                        + (x.powi(3) - x * x) * l * v1;
                    (exact - cubic).abs()
                })
                .fold(0.0, f64::max);
            assert!(worst <= cubic_margin(m4, l), "l {l}: {worst:e}");
        }
    }

    #[test]
    fn the_cubic_maximum_finds_interior_humps_and_the_ends() {
        // A hump inside: y = s (1 - s) on [0, 1] has slopes 1 and -1, maximum 1/4.
        assert!((cubic_max(0.0, 1.0, 0.0, -1.0, 1.0) - 0.25).abs() < 1e-15);
        // Rising throughout: the end.
        assert_eq!(cubic_max(0.0, 1.0, 1.0, 1.0, 1.0), 1.0);
        // Slopes of the same sign at both ends and a wiggle between: x^3-type with a local
        // maximum inside, found although neither end's slope says so.
        let (y0, v0, y1, v1, l) = (0.0, 3.0, 0.1, 3.0, 1.0);
        let dense = (0..=10_000)
            .map(|i| {
                let x = i as f64 / 10_000.0;
                (2.0 * x.powi(3) - 3.0 * x * x + 1.0) * y0
                    + (x.powi(3) - 2.0 * x * x + x) * l * v0
                    + (-2.0 * x.powi(3) + 3.0 * x * x) * y1
                    + (x.powi(3) - x * x) * l * v1
            })
            .fold(f64::NEG_INFINITY, f64::max);
        assert!(dense > 0.1, "the wiggle rises above the end");
        assert!((cubic_max(y0, v0, y1, v1, l) - dense).abs() < 1e-8);
        assert!((cubic_max_abs(0.0, -1.0, 0.0, 1.0, 1.0) - 0.25).abs() < 1e-15);
    }

    #[test]
    fn the_quick_bound_is_never_below_the_cubics_maximum() {
        let mut worst: f64 = f64::INFINITY;
        for i in 0..2000 {
            // A fixed spread of ends and slopes, steep and flat.
            let x = i as f64;
            let (y0, v0, y1, v1) = (
                (x * 0.37).sin(),
                5.0 * (x * 0.91).cos(),
                (x * 1.3).cos(),
                3.0 * (x * 0.17).sin(),
            );
            let l = 0.1 + (x * 0.07).sin().abs();
            let slack = cubic_bound(y0, v0, y1, v1, l) - cubic_max(y0, v0, y1, v1, l);
            worst = worst.min(slack);
        }
        assert!(
            worst >= -1e-12,
            "the bound fell below the maximum by {worst:e}"
        );
    }
}
