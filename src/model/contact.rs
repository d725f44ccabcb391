//! Contact laws at the contact surface: force as a function of the approach delta.
//!
//! Every law is zero for delta <= 0 (no tension, no adhesion) and increasing for delta > 0, so
//! the implicit step equation `delta + beta f(delta) = rhs` (beta >= 0) has exactly one root;
//! [`ContactLaw::solve_implicit`] finds it.

use super::bar::Bar;

/// The paper's n in its linear contact stiffness E A / (L / n): each slab contributes the
/// stiffness of a tenth of its length, and the Sears zone of a slab is that tenth, d = L / n.
pub const PAPER_DIVISIONS: f64 = 10.0;

/// The overlap at which a Hertzian element's default stiffness gives the same force as the
/// linear default [m]: a millimetre, the scale of the paper's gap.
pub const REFERENCE_OVERLAP_M: f64 = 1e-3;

/// The form of a contact law.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LawKind {
    /// F = k delta^(3/2), rounded ends.
    Hertz,
    /// F = kL delta, flat ends (the paper's Eq. 10).
    Linear,
}

impl LawKind {
    /// Every law.
    pub const ALL: [LawKind; 2] = [LawKind::Hertz, LawKind::Linear];
    /// Every law's name, in the order of [`LawKind::ALL`].
    pub const NAMES: [&'static str; 2] = crate::model::names_of!(Self::ALL, 2);

    /// The name presets and the command line use.
    pub const fn name(self) -> &'static str {
        match self {
            LawKind::Hertz => "hertz",
            LawKind::Linear => "linear",
        }
    }

    /// The law of that name.
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|l| l.name() == s)
    }
}

/// A contact law with its stiffness (N/m^1.5 for Hertz, N/m for linear).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLaw {
    /// Hertz or linear.
    pub kind: LawKind,
    /// k: N/m^1.5 for Hertz, N/m for linear.
    pub stiffness: f64,
}

impl ContactLaw {
    /// F = k delta^1.5.
    pub fn hertz(k: f64) -> Self {
        ContactLaw {
            kind: LawKind::Hertz,
            stiffness: k,
        }
    }

    /// F = k delta.
    pub fn linear(k: f64) -> Self {
        ContactLaw {
            kind: LawKind::Linear,
            stiffness: k,
        }
    }

    /// Branch-free, so a solver step costs the same in and out of contact.
    #[inline]
    pub fn force(&self, delta: f64) -> f64 {
        let d = delta.max(0.0);
        match self.kind {
            LawKind::Hertz => self.stiffness * d * d.sqrt(),
            LawKind::Linear => self.stiffness * d,
        }
    }

    /// dF/d delta.
    #[inline]
    pub fn tangent(&self, delta: f64) -> f64 {
        if delta <= 0.0 {
            return 0.0;
        }
        match self.kind {
            LawKind::Hertz => 1.5 * self.stiffness * delta.sqrt(),
            LawKind::Linear => self.stiffness,
        }
    }

    /// Tangent stiffness at a given force level (used for the validity number a*tau).
    pub fn tangent_at_force(&self, force: f64) -> f64 {
        self.tangent(self.approach_at_force(force))
    }

    /// Inverse of the law: the approach that carries a force.
    pub fn approach_at_force(&self, force: f64) -> f64 {
        if force <= 0.0 {
            return 0.0;
        }
        match self.kind {
            LawKind::Hertz => (force / self.stiffness).powf(2.0 / 3.0),
            LawKind::Linear => force / self.stiffness,
        }
    }

    /// Elastic energy stored at approach delta [J].
    pub fn energy(&self, delta: f64) -> f64 {
        if delta <= 0.0 {
            return 0.0;
        }
        match self.kind {
            LawKind::Hertz => 0.4 * self.stiffness * delta * delta * delta.sqrt(),
            LawKind::Linear => 0.5 * self.stiffness * delta * delta,
        }
    }

    /// The unique root of `delta + beta f(delta) = rhs` for beta >= 0. `guess` is a hint (the
    /// previous step's delta); any value works.
    #[inline]
    pub fn solve_implicit(&self, beta: f64, rhs: f64, guess: f64) -> f64 {
        if rhs <= 0.0 {
            return rhs;
        }
        if beta == 0.0 {
            return rhs;
        }
        let bk = beta * self.stiffness;
        match self.kind {
            LawKind::Linear => rhs / (1.0 + bk),
            LawKind::Hertz => {
                // With s = sqrt(delta) the equation is the cubic bk s^3 + s^2 = rhs: convex and
                // increasing for s >= 0, so Newton from above converges monotonically, without
                // a square root per iteration. Iterated to round-off (the building elements and
                // FE rely on this exact sequence; the Sears loop takes the quicker
                // `solve_implicit_sqrt` from a close guess).
                let upper = rhs.sqrt().min((rhs / bk).cbrt());
                let mut s = if guess > 0.0 {
                    guess.sqrt().min(upper)
                } else {
                    upper
                };
                for _ in 0..60 {
                    let s2 = s * s;
                    let g = bk * s2 * s + s2 - rhs;
                    let dg = 3.0 * bk * s2 + 2.0 * s;
                    if dg <= 0.0 {
                        break;
                    }
                    let step = g / dg;
                    let next = (s - step).max(0.0);
                    if (next - s).abs() <= 1e-15 * s.max(f64::MIN_POSITIVE) {
                        s = next;
                        break;
                    }
                    s = next;
                }
                s * s
            }
        }
    }

    /// For the Hertz law, the start of [`ContactLaw::solve_implicit_sqrt`]'s equation
    /// `bk s^3 + s^2 = rhs` (bk = beta k) at a close guess `delta0 > 0` of the overlap, before
    /// rhs is known: see [`SqrtStep`]. Only `G'(s0)`'s last term waits on the square root.
    #[inline]
    pub fn sqrt_step(&self, beta: f64, delta0: f64) -> SqrtStep {
        let bk = beta * self.stiffness;
        let s0 = delta0.sqrt();
        let inv = 1.0 / (3.0 * bk * delta0 + 2.0 * s0);
        SqrtStep {
            s0,
            g0: delta0 * (bk * s0 + 1.0),
            inv,
            curve: (3.0 * bk * s0 + 1.0) * inv,
        }
    }

    /// For the Hertz law: sqrt of the root of `delta + beta f(delta) = rhs`, from a guess `s0`
    /// of it (negative: none). With s = sqrt(delta) the equation is the cubic
    /// `bk s^3 + s^2 = rhs`: convex and increasing for s >= 0, so Newton from any start lands at
    /// or above the root after one step and then falls monotonically, without a square root per
    /// iteration. It stops once a step is below 1e-8 of s: Newton's error is then of the order
    /// of that step squared relative to s, 1e-16, below the rounding of s.
    #[inline]
    pub fn solve_implicit_sqrt(&self, beta: f64, rhs: f64, s0: f64) -> f64 {
        if rhs <= 0.0 {
            return 0.0;
        }
        let bk = beta * self.stiffness;
        if bk == 0.0 {
            return rhs.sqrt();
        }
        let mut s = if s0 > 0.0 {
            s0
        } else if rhs * bk * bk <= 1.0 {
            // Both sqrt(rhs) and cbrt(rhs / bk) bound the root from above; this one is the
            // smaller here, and the cube root is not needed.
            rhs.sqrt()
        } else {
            (rhs / bk).cbrt()
        };
        for _ in 0..60 {
            let s2 = s * s;
            let g = bk * s2 * s + s2 - rhs;
            let dg = 3.0 * bk * s2 + 2.0 * s;
            if dg <= 0.0 {
                // s = 0 with rhs > 0: restart from an upper bound.
                s = rhs.sqrt();
                continue;
            }
            let next = (s - g / dg).max(0.0);
            let small = (next - s).abs() <= 1e-8 * next;
            s = next;
            if small {
                break;
            }
        }
        s
    }
}

/// The root of `G(s) = bk s^3 + s^2 = rhs` as a Taylor series in rhs about a guess s0, to second
/// order: with u = (rhs - G(s0)) / G'(s0), s = s0 + u - (G''(s0) / 2 G'(s0)) u^2 + O(u^3).
/// Everything but rhs is known before rhs is, so in a stepping loop a few multiply-adds wait on
/// rhs and no division does.
#[derive(Debug, Clone, Copy)]
pub struct SqrtStep {
    /// The guess.
    pub s0: f64,
    /// G(s0).
    pub g0: f64,
    /// 1 / G'(s0).
    pub inv: f64,
    /// G''(s0) / (2 G'(s0)).
    pub curve: f64,
}

impl SqrtStep {
    /// The root for the correction `u = (rhs - G(s0)) / G'(s0)`, where |u| <= 1e-5 s0: the
    /// neglected term is then below 1e-15 s0 (G'' / G' is at most 2 / s0 for s0 > 0), the
    /// accuracy [`ContactLaw::solve_implicit_sqrt`] stops at. `None` further out.
    #[inline]
    pub fn root(&self, u: f64) -> Option<f64> {
        (u.abs() <= 1e-5 * self.s0).then_some((self.s0 + u) - (self.curve * u) * u)
    }
}

/// Hertz stiffness k = (4/3) E* sqrt(R*) for the two impacting ends (paper Eqs. 3-4), or `None`
/// when both ends are flat (Hertz theory needs a curved surface).
pub fn hertz_stiffness(bar1: &Bar, bar2: &Bar) -> Option<f64> {
    let curvature = bar1.end.curvature_per_m() + bar2.end.curvature_per_m();
    if curvature <= 0.0 {
        return None;
    }
    let compliance =
        |b: &Bar| (1.0 - b.material.poisson_ratio.powi(2)) / b.material.youngs_modulus_pa;
    let e_star = 1.0 / (compliance(bar1) + compliance(bar2));
    let r_star = 1.0 / curvature;
    Some(4.0 / 3.0 * e_star * r_star.sqrt())
}

/// The paper's linear contact stiffness: each bar contributes E A / (L / n), the two springs in
/// series. With n = 10, E = 25 GPa, A = 8 m x 0.15 m and L = 10 m this gives 15 GN/m.
pub fn paper_linear_stiffness(bar1: &Bar, bar2: &Bar, divisions: f64) -> f64 {
    let k = |b: &Bar| b.axial_rigidity_n() * divisions / b.length_m;
    let (k1, k2) = (k(bar1), k(bar2));
    k1 * k2 / (k1 + k2)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn implicit_root_satisfies_equation_for_both_laws() {
        for law in [ContactLaw::hertz(3.4e10), ContactLaw::linear(1e12)] {
            for &beta in &[0.0, 1e-12, 1e-9, 1e-6, 1.0] {
                for &rhs in &[-1e-3, 0.0, 1e-9, 1e-6, 3e-4, 1e-2] {
                    let d = law.solve_implicit(beta, rhs, 1e-5);
                    let residual = d + beta * law.force(d) - rhs;
                    assert!(
                        residual.abs() <= 1e-12 * rhs.abs().max(1e-12),
                        "{law:?} {beta} {rhs}"
                    );
                }
            }
        }
    }
}
