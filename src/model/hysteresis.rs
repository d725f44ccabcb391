//! Storey springs that yield: the force a storey carries as a function of its drift history.
//!
//! - **elastic**: F = k u.
//! - **bilinear** (kinematic hardening): F = b k u + (1 - b) F_ep, where F_ep is an
//!   elastic-perfectly-plastic spring of stiffness k and yield force F_y, F_ep = k (u - u_p) with
//!   |F_ep| <= F_y. So the force stays between the lines b k u + (1 - b) F_y and
//!   b k u - (1 - b) F_y, rises with slope b k along them, and unloads with slope k. The plastic
//!   drift u_p moves only while F_ep sits at +-F_y and the drift keeps going that way.
//! - **Bouc-Wen**: F = b k u + (1 - b) k z with dz/du = 1 - |z|^n (beta sgn(u' z) + gamma) and
//!   beta = gamma = 0.5 / u_y^n, u_y = F_y / k. Moving towards larger |z|, dz/du = 1 - (|z| / u_y)^n,
//!   so z saturates at u_y; moving back, dz/du = 1 (the elastic unloading of the bilinear law). The
//!   larger n, the sharper the knee, and the curve tends to the bilinear one.
//!
//! Both laws are rate independent: the state after a drift path depends on the path, not on how
//! fast it was travelled, so a solver hands them the drift at the end of each straight piece of
//! path. What a storey dissipates (its hysteretic energy) is the work done on it less what it
//! stores: (1 - b) F_y |du_p| summed for the bilinear law, (1 - b) k z (du - dz) integrated for
//! Bouc-Wen. The stored part is 1/2 b k u^2 + 1/2 (1 - b) k (u - u_p)^2 (bilinear) or
//! 1/2 b k u^2 + 1/2 (1 - b) k z^2 (Bouc-Wen).

/// Which law a storey spring follows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Hysteresis {
    /// Linear: F = k u.
    Elastic,
    /// Bilinear with kinematic hardening.
    Bilinear,
    /// Bouc-Wen (smooth).
    BoucWen,
}

impl Hysteresis {
    /// Every law, in the order the front ends list them.
    pub const ALL: [Hysteresis; 3] = [
        Hysteresis::Elastic,
        Hysteresis::Bilinear,
        Hysteresis::BoucWen,
    ];

    /// Their names, in the order of [`Hysteresis::ALL`].
    pub const NAMES: [&'static str; 3] = crate::model::names_of!(Self::ALL, 3);

    /// The name the command line and presets use.
    pub const fn name(self) -> &'static str {
        match self {
            Hysteresis::Elastic => "elastic",
            Hysteresis::Bilinear => "bilinear",
            Hysteresis::BoucWen => "bouc-wen",
        }
    }

    /// The law of that name.
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|h| h.name() == s)
    }
}

/// One storey spring's law and its constants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StoreyLaw {
    /// Which law.
    pub kind: Hysteresis,
    /// Initial stiffness k [N/m].
    pub stiffness_n_m: f64,
    /// Yield force F_y [N] (unused by the elastic law).
    pub yield_force_n: f64,
    /// Post-yield stiffness ratio b, in [0, 1).
    pub hardening: f64,
    /// Bouc-Wen's exponent n (sharpness of the knee).
    pub bouc_wen_n: f64,
}

/// The history a storey spring remembers.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StoreyState {
    /// The drift u [m].
    pub drift_m: f64,
    /// Bilinear: the plastic drift u_p [m]. Bouc-Wen: the hysteretic drift z [m].
    pub inner_m: f64,
    /// Energy dissipated so far [J].
    pub dissipated_j: f64,
}

impl StoreyLaw {
    /// An elastic spring of stiffness k.
    pub fn elastic(stiffness_n_m: f64) -> Self {
        StoreyLaw {
            kind: Hysteresis::Elastic,
            stiffness_n_m,
            yield_force_n: f64::INFINITY,
            hardening: 0.0,
            bouc_wen_n: 2.0,
        }
    }

    /// The yield drift u_y = F_y / k [m].
    pub fn yield_drift_m(&self) -> f64 {
        self.yield_force_n / self.stiffness_n_m
    }

    /// The force the spring carries in `s` [N].
    pub fn force_n(&self, s: &StoreyState) -> f64 {
        let (k, b) = (self.stiffness_n_m, self.hardening);
        match self.kind {
            Hysteresis::Elastic => k * s.drift_m,
            Hysteresis::Bilinear => b * k * s.drift_m + (1.0 - b) * k * (s.drift_m - s.inner_m),
            Hysteresis::BoucWen => b * k * s.drift_m + (1.0 - b) * k * s.inner_m,
        }
    }

    /// The energy the spring stores in `s` [J]: what it would give back on unloading to zero
    /// force along its elastic branch, plus the hardening spring's share.
    pub fn stored_energy_j(&self, s: &StoreyState) -> f64 {
        let (k, b, u) = (self.stiffness_n_m, self.hardening, s.drift_m);
        match self.kind {
            Hysteresis::Elastic => 0.5 * k * u * u,
            Hysteresis::Bilinear => {
                0.5 * b * k * u * u + 0.5 * (1.0 - b) * k * (u - s.inner_m).powi(2)
            }
            Hysteresis::BoucWen => 0.5 * b * k * u * u + 0.5 * (1.0 - b) * k * s.inner_m.powi(2),
        }
    }

    /// The lines the shear of a yielding law approaches at drift u, b k u -+ (1 - b) F_y [N]
    /// (the bilinear law's bounds, Bouc-Wen's asymptotes); `None` for the elastic law.
    pub fn bounding_shears_n(&self, u: f64) -> Option<[f64; 2]> {
        let (k, b, fy) = (self.stiffness_n_m, self.hardening, self.yield_force_n);
        (self.kind != Hysteresis::Elastic)
            .then_some([b * k * u - (1.0 - b) * fy, b * k * u + (1.0 - b) * fy])
    }

    /// The drifts between which the next move is elastic (slope k), for the bilinear law: the
    /// yield points either side of the plastic drift. `None` for the other laws (elastic: always;
    /// Bouc-Wen: never exactly).
    pub fn elastic_range_m(&self, s: &StoreyState) -> Option<(f64, f64)> {
        match self.kind {
            Hysteresis::Bilinear => {
                let uy = self.yield_drift_m();
                Some((s.inner_m - uy, s.inner_m + uy))
            }
            _ => None,
        }
    }

    /// The slope dF/du for a move in the direction of `direction` (its sign) from `s` [N/m].
    pub fn tangent_n_m(&self, s: &StoreyState, direction: f64) -> f64 {
        let (k, b) = (self.stiffness_n_m, self.hardening);
        match self.kind {
            Hysteresis::Elastic => k,
            Hysteresis::Bilinear => {
                let (lo, hi) = self.elastic_range_m(s).expect("bilinear");
                let yielding =
                    (direction > 0.0 && s.drift_m >= hi) || (direction < 0.0 && s.drift_m <= lo);
                if yielding { b * k } else { k }
            }
            Hysteresis::BoucWen => b * k + (1.0 - b) * k * self.dz_du(s.inner_m, direction),
        }
    }

    /// Moves the spring along a straight drift path from `s.drift_m` to `drift_m`.
    pub fn advance(&self, s: &mut StoreyState, drift_m: f64) {
        match self.kind {
            Hysteresis::Elastic => s.drift_m = drift_m,
            Hysteresis::Bilinear => self.advance_bilinear(s, drift_m),
            Hysteresis::BoucWen => self.advance_bouc_wen(s, drift_m),
        }
    }

    /// Exact: the elastic-perfectly-plastic part is elastic inside its range and flows at its
    /// edge, so the end of a straight path fixes the plastic drift.
    fn advance_bilinear(&self, s: &mut StoreyState, drift_m: f64) {
        let uy = self.yield_drift_m();
        let up = s.inner_m.clamp(drift_m - uy, drift_m + uy);
        let fy_share = (1.0 - self.hardening) * self.yield_force_n;
        s.dissipated_j += fy_share * (up - s.inner_m).abs();
        s.inner_m = up;
        s.drift_m = drift_m;
    }

    /// dz/du moving in the direction of `direction` at hysteretic drift z.
    fn dz_du(&self, z: f64, direction: f64) -> f64 {
        if direction * z > 0.0 {
            let w = (z.abs() / self.yield_drift_m()).min(1.0);
            1.0 - w.powf(self.bouc_wen_n)
        } else {
            1.0
        }
    }

    /// The law on a straight drift path, in the normalised hysteretic drift w = z sgn(du) / u_y
    /// and the path's length x = |du| / u_y: first the unloading branch (w < 0, dw/dx = 1, no
    /// dissipation) up to w = 0, then the loading one, dw/dx = 1 - w^n, which saturates at w = 1
    /// ([`loading_branch`]). The cost is bounded whatever the path's length against u_y: once w
    /// is 1 to round-off, the rest of the path is the saturated line.
    fn advance_bouc_wen(&self, s: &mut StoreyState, drift_m: f64) {
        let du_total = drift_m - s.drift_m;
        if du_total == 0.0 {
            return;
        }
        let uy = self.yield_drift_m();
        // One division: a contact step follows every storey of a tall side on every pass.
        let per_uy = 1.0 / uy;
        let dir = du_total.signum();
        let mut x = du_total.abs() * per_uy;
        let mut w = (dir * s.inner_m * per_uy).clamp(-1.0, 1.0);
        if w < 0.0 {
            let back = x.min(-w);
            w += back;
            x -= back;
            if x <= 0.0 {
                // Still on the unloading line: z moved with u.
                s.inner_m = dir * uy * w;
                s.drift_m = drift_m;
                return;
            }
            w = w.max(0.0);
        }
        let n = self.bouc_wen_n;
        let (w1, dissipated) = if 16.0 * n.max(1.0) * x <= 1.0 {
            short_loading(w, x, n)
        } else {
            loading_branch(w, x, n)
        };
        let scale = (1.0 - self.hardening) * self.stiffness_n_m;
        s.inner_m = dir * uy * w1;
        s.dissipated_j += scale * uy * uy * dissipated.max(0.0);
        s.drift_m = drift_m;
    }
}

/// w^n, by multiplications where n is a small whole number (the usual exponents).
fn power(w: f64, n: f64) -> f64 {
    // A cast, not `round`: without SSE4.1 that is a call.
    let whole = n as i32;
    match whole {
        1 if n == 1.0 => w,
        2 if n == 2.0 => w * w,
        3 if n == 3.0 => w * w * w,
        _ if f64::from(whole) == n && whole <= 64 => w.powi(whole),
        _ => w.powf(n),
    }
}

/// [`loading_branch`] over a path short against the knee (at most u_y / (16 n)): one
/// Runge-Kutta step in w itself, where the knee is resolved and the step is well inside the
/// stability bound (its rate's slope is at most n), without the transcendental functions the
/// long paths' variable takes.
fn short_loading(w0: f64, x: f64, n: f64) -> (f64, f64) {
    let rates = |w: f64| {
        let wn = power(w.clamp(0.0, 1.0), n);
        (1.0 - wn, w * wn)
    };
    let (k1, d1) = rates(w0);
    let (k2, d2) = rates(w0 + 0.5 * x * k1);
    let (k3, d3) = rates(w0 + 0.5 * x * k2);
    let (k4, d4) = rates(w0 + x * k3);
    let w = w0 + x / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    (w.min(1.0), x / 6.0 * (d1 + 2.0 * d2 + 2.0 * d3 + d4))
}

/// Past this, 1 - w = e^-sigma is below half an ulp of 1: the branch is saturated to round-off.
const SATURATED: f64 = 40.0;

/// Bouc-Wen's loading branch dw/dx = 1 - w^n from w0 in [0, 1] over a path of length x: the end
/// w and the dissipation integral, of w (1 - dw/dx) = w^(n + 1) over the path.
///
/// It is integrated in sigma = -ln(1 - w), where dsigma/dx = (1 - w^n) / (1 - w) lies between 1
/// and n and tends to n at saturation: the equation is not stiff there, however short u_y, and
/// its derivatives fall as 1 - w does, so the steps grow as the branch saturates (the error
/// they leave in the dissipation goes as (1 - w) dsigma^5, in w as (1 - w)^2 dsigma^5) and
/// about eighty of them take any start to saturation. Near w = 0, sigma = w to round-off, so a branch that hardly yields keeps the
/// elastic drift exactly.
fn loading_branch(w0: f64, x: f64, n: f64) -> (f64, f64) {
    // (1 - w^n) / (1 - w) and w^(n + 1) from sigma, without cancellation at either end.
    let rates = |sigma: f64| {
        let s = (-sigma).exp();
        let w = -(-sigma).exp_m1();
        let one_less_wn = if s > 0.0 {
            -(n * (-s).ln_1p()).exp_m1()
        } else {
            1.0
        };
        let f = if s > 0.0 { one_less_wn / s } else { n };
        (f, w * (1.0 - one_less_wn))
    };
    let mut sigma = if w0 < 1.0 { -(-w0).ln_1p() } else { SATURATED };
    let (mut left, mut dissipated) = (x, 0.0);
    while left > 0.0 && sigma < SATURATED {
        let (f1, d1) = rates(sigma);
        // A sixteenth in sigma where the branch bends most, as the knee needs, and longer steps
        // as it flattens: the dissipation's error goes as (1 - w) dsigma^5.
        let reach = ((0.2 * sigma).exp() / 16.0).min(4.0);
        let h = left.min(reach / f1);
        let (f2, d2) = rates(sigma + 0.5 * h * f1);
        let (f3, d3) = rates(sigma + 0.5 * h * f2);
        let (f4, d4) = rates(sigma + h * f3);
        sigma += h / 6.0 * (f1 + 2.0 * f2 + 2.0 * f3 + f4);
        dissipated += h / 6.0 * (d1 + 2.0 * d2 + 2.0 * d3 + d4);
        left -= h;
    }
    if sigma >= SATURATED {
        // On the saturated line w = 1, where all the work is dissipated.
        return (1.0, dissipated + left.max(0.0));
    }
    (-(-sigma).exp_m1(), dissipated)
}

#[cfg(test)]
mod tests {
    use super::*;

    const K: f64 = 2.0e7;
    const FY: f64 = 1.0e5;
    const B: f64 = 0.05;

    fn law(kind: Hysteresis, n: f64) -> StoreyLaw {
        StoreyLaw {
            kind,
            stiffness_n_m: K,
            yield_force_n: FY,
            hardening: B,
            bouc_wen_n: n,
        }
    }

    /// The drift path 0 -> +a -> -a -> +a in small straight pieces, with the force after each.
    fn cycle(l: &StoreyLaw, a: f64, pieces: usize) -> (Vec<(f64, f64)>, StoreyState) {
        let mut s = StoreyState::default();
        let mut path = vec![(0.0, 0.0)];
        let legs = [(0.0, a), (a, -a), (-a, a)];
        for (from, to) in legs {
            for i in 1..=pieces {
                let u = from + (to - from) * i as f64 / pieces as f64;
                l.advance(&mut s, u);
                path.push((u, l.force_n(&s)));
            }
        }
        (path, s)
    }

    #[test]
    fn a_quasi_static_cycle_traces_the_bilinear_loop_with_corners_at_the_yield_force() {
        let l = law(Hysteresis::Bilinear, 2.0);
        let uy = FY / K;
        let a = 4.0 * uy;
        let (path, _) = cycle(&l, a, 400);
        // The closed form of the loop, leg by leg: first loading k u up to (u_y, F_y), then
        // F_y + b k (u - u_y); unloading from the top (a, F_top) with slope k down to the lower
        // bound b k u - (1 - b) F_y, then along it; reloading likewise.
        let top = FY + B * K * (a - uy);
        let upper = |u: f64| B * K * u + (1.0 - B) * FY;
        let lower = |u: f64| B * K * u - (1.0 - B) * FY;
        let expected = |leg: usize, u: f64| match leg {
            0 => (K * u).min(upper(u)),
            1 => (top + K * (u - a)).max(lower(u)),
            _ => (-top + K * (u + a)).min(upper(u)),
        };
        for (i, &(u, f)) in path.iter().enumerate().skip(1) {
            let leg = (i - 1) / 400;
            let want = expected(leg, u);
            assert!(
                (f - want).abs() < 1e-9 * FY,
                "leg {leg} u = {u:e}: {f} against {want}"
            );
        }
        // The corner: first yield exactly at F_y.
        let mut s = StoreyState::default();
        l.advance(&mut s, uy);
        assert!((l.force_n(&s) - FY).abs() < 1e-9 * FY);
        assert_eq!(l.tangent_n_m(&s, 1.0), B * K);
        assert_eq!(l.tangent_n_m(&s, -1.0), K);
    }

    /// The area inside a drift path's force curve, by the trapezoid: independent of how the law
    /// counts its dissipation.
    fn work(path: &[(f64, f64)]) -> f64 {
        path.windows(2)
            .map(|w| 0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0))
            .sum()
    }

    #[test]
    fn the_bilinear_loop_area_is_the_hysteretic_energy() {
        let l = law(Hysteresis::Bilinear, 2.0);
        let uy = FY / K;
        let a = 3.0 * uy;
        // With a = 3 u_y every corner falls a third of the way along its leg: pieces that are a
        // multiple of 3 put a path point on each, and the trapezoid is exact on the straight
        // branches between them.
        let (path, s) = cycle(&l, a, 2100);
        // Work done over the path = dissipated + stored at the end (the last leg ends at +a).
        let w = work(&path);
        let total = s.dissipated_j + l.stored_energy_j(&s);
        assert!(
            (w - total).abs() < 1e-9 * w.abs(),
            "work {w} against {total}"
        );
        // The elastic-perfectly-plastic share flows a - u_y on the first leg and 2 (a - u_y) on
        // each of the next two (it unloads elastically over 2 u_y first), each at (1 - b) F_y.
        let expected = (1.0 - B) * FY * 5.0 * (a - uy);
        assert!(
            (s.dissipated_j - expected).abs() < 1e-9 * expected,
            "{} against {expected}",
            s.dissipated_j
        );
    }

    #[test]
    fn bouc_wen_with_a_sharp_knee_approaches_the_bilinear_loop() {
        let uy = FY / K;
        let a = 4.0 * uy;
        let (bilinear, sb) = cycle(&law(Hysteresis::Bilinear, 2.0), a, 800);
        let mut last = f64::INFINITY;
        for n in [2.0, 8.0, 40.0] {
            let (smooth, sw) = cycle(&law(Hysteresis::BoucWen, n), a, 800);
            let gap = bilinear
                .iter()
                .zip(&smooth)
                .map(|(p, q)| (p.1 - q.1).abs())
                .fold(0.0, f64::max);
            assert!(
                gap < last,
                "n = {n}: the largest force gap {gap} did not shrink"
            );
            last = gap;
            // The loop's dissipation converges too.
            if n == 40.0 {
                assert!(gap < 0.05 * FY, "n = 40: force gap {gap} N");
                let rel = (sw.dissipated_j - sb.dissipated_j).abs() / sb.dissipated_j;
                assert!(rel < 0.03, "n = 40: dissipation off by {rel}");
            }
        }
    }

    #[test]
    fn the_bouc_wen_loop_area_is_its_hysteretic_energy() {
        let l = law(Hysteresis::BoucWen, 2.0);
        let a = 3.0 * FY / K;
        let (path, s) = cycle(&l, a, 4000);
        let w = work(&path);
        let total = s.dissipated_j + l.stored_energy_j(&s);
        // The trapezoid's own error on a curved branch: O(piece^2), about 1e-6 of the work here.
        assert!(
            (w - total).abs() < 1e-5 * w.abs(),
            "work {w} against {total}"
        );
        assert!(s.dissipated_j > 0.0);
    }

    #[test]
    fn a_long_bouc_wen_path_ends_where_the_same_path_in_short_pieces_does() {
        let uy = FY / K;
        let scale = (1.0 - B) * K;
        for n in [1.0, 2.0, 7.5, 100.0] {
            let l = law(Hysteresis::BoucWen, n);
            // From z = -u_y: unloading over 2 u_y, then the loading branch to saturation.
            let start = StoreyState {
                drift_m: 0.0,
                inner_m: -uy,
                dissipated_j: 0.0,
            };
            let x = 40.0;
            let mut long = start;
            l.advance(&mut long, x * uy);
            let mut short = start;
            let pieces = (x * 64.0 * n) as usize;
            for i in 1..=pieces {
                l.advance(&mut short, x * uy * i as f64 / pieces as f64);
            }
            assert!(
                (long.inner_m - short.inner_m).abs() < 1e-9 * uy,
                "n = {n}: z {} against {}",
                long.inner_m,
                short.inner_m
            );
            let rel = (long.dissipated_j - short.dissipated_j).abs() / short.dissipated_j;
            assert!(rel < 1e-8, "n = {n}: dissipated off by {rel:e}");
            // Far past saturation: z stays at u_y and the rest of the path dissipates
            // (1 - b) k u_y per unit of drift.
            let mut far = long;
            l.advance(&mut far, 1e6 * uy);
            assert_eq!(far.inner_m, uy, "n = {n}");
            let more = far.dissipated_j - long.dissipated_j;
            let want = scale * uy * (1e6 - x) * uy;
            assert!(
                (more - want).abs() < 1e-12 * want,
                "n = {n}: {more} against {want}"
            );
        }
    }

    #[test]
    fn a_very_large_yield_force_is_elastic_to_round_off() {
        for kind in [Hysteresis::Bilinear, Hysteresis::BoucWen] {
            let l = StoreyLaw {
                yield_force_n: 1e30,
                ..law(kind, 2.0)
            };
            let (path, s) = cycle(&l, 0.05, 100);
            for (u, f) in path {
                assert!((f - K * u).abs() <= 1e-9 * K * 0.05, "{kind:?}: {f} at {u}");
            }
            assert!(s.dissipated_j <= 1e-9 * 0.5 * K * 0.05 * 0.05, "{kind:?}");
        }
    }

    #[test]
    fn the_names_round_trip() {
        for h in Hysteresis::ALL {
            assert_eq!(Hysteresis::from_name(h.name()), Some(h));
        }
        assert_eq!(Hysteresis::from_name("plastic"), None);
    }
}
