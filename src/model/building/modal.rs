//! A shear building's modes, and each mode's exact response over a step.
//!
//! Floor j (1..N) carries the mass m_j; storey j, between floors j-1 and j (floor 0 is the
//! ground), has the shear stiffness k_j. With u relative to the ground,
//! M u'' + C u' + K u = -M 1 a_g + f, K tridiagonal. Its modes (K phi = w^2 M phi,
//! phi^T M phi = 1) decouple the equations for any classical damping (modal, or Rayleigh
//! C = a M + b K): q_k'' + 2 zeta_k w_k q_k' + w_k^2 q_k = g_k(t) with g_k = phi_k^T (f - M 1 a_g).
//!
//! Between samples of a piecewise-linear forcing each mode's response is exact: the augmented
//! state y = [q, q', g, g'] obeys y' = A y with A constant, so y(s) = exp(A s) y(0). The same
//! exponential, through Van Loan's block matrices, gives the integrals an energy ledger needs
//! (the integral of q and of q'^2 over the step) exactly, so the ledger balances to round-off.

/// The modes of one building.
#[derive(Debug, Clone, PartialEq)]
pub struct Modes {
    /// Circular frequencies w_k [rad/s], ascending.
    pub omega_rad_s: Vec<f64>,
    /// Damping ratio of each mode.
    pub damping: Vec<f64>,
    /// Mass-normalised shapes: `shapes[k][j]` is mode k at floor j (0-based).
    pub shapes: Vec<Vec<f64>>,
    /// Participation factors Gamma_k = phi_k^T M 1 [sqrt(kg)].
    pub participation: Vec<f64>,
}

/// How a building's damping is built from its ratio zeta.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DampingModel {
    /// zeta in every mode: C = M Phi diag(2 zeta w) Phi^T M.
    Modal,
    /// C = a M + b K with zeta in modes i and j (1-based); the other modes get
    /// a / (2 w) + b w / 2.
    Rayleigh {
        /// The two modes (from 1) given the ratio exactly.
        modes: [usize; 2],
    },
}

impl DampingModel {
    /// Both models, Rayleigh with its default modes 1 and 2.
    pub const ALL: [DampingModel; 2] = [
        DampingModel::Modal,
        DampingModel::Rayleigh { modes: [1, 2] },
    ];
    /// Their names, in the order of [`DampingModel::ALL`].
    pub const NAMES: [&'static str; 2] = crate::model::names_of!(Self::ALL, 2);

    /// The name presets and the command line use.
    pub const fn name(self) -> &'static str {
        match self {
            DampingModel::Modal => "modal",
            DampingModel::Rayleigh { .. } => "rayleigh",
        }
    }

    /// The model of that name; Rayleigh damping keeps `modes`.
    pub fn from_name(s: &str, modes: [usize; 2]) -> Option<Self> {
        match Self::ALL.into_iter().find(|d| d.name() == s)? {
            DampingModel::Rayleigh { .. } => Some(DampingModel::Rayleigh { modes }),
            modal => Some(modal),
        }
    }
}

impl Modes {
    /// The modes of floors with `masses` [kg] over storeys of `stiffnesses` [N/m], damped by
    /// `zeta` as `model` says.
    pub fn of_shear_building(
        masses: &[f64],
        stiffnesses: &[f64],
        zeta: f64,
        model: DampingModel,
    ) -> Self {
        let n = masses.len();
        debug_assert_eq!(n, stiffnesses.len());
        // A = M^-1/2 K M^-1/2 is symmetric and tridiagonal; its eigenvectors v give
        // phi = M^-1/2 v.
        let inv_sqrt_m: Vec<f64> = masses.iter().map(|m| 1.0 / m.sqrt()).collect();
        let (diag, off) = scaled_stiffness(masses, stiffnesses);
        let (values, vectors) = tridiagonal_eigen(diag, off);
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&x, &y| values[x].total_cmp(&values[y]));
        let mut omega = Vec::with_capacity(n);
        let mut shapes = Vec::with_capacity(n);
        for &k in &order {
            omega.push(values[k].max(0.0).sqrt());
            let mut phi: Vec<f64> = (0..n).map(|j| vectors[j][k] * inv_sqrt_m[j]).collect();
            // The sign of a mode is arbitrary; pick the roof's positive so output is stable.
            if phi[n - 1] < 0.0 {
                phi.iter_mut().for_each(|x| *x = -*x);
            }
            shapes.push(phi);
        }
        let participation = shapes
            .iter()
            .map(|phi| phi.iter().zip(masses).map(|(p, m)| p * m).sum())
            .collect();
        let damping = match model {
            DampingModel::Modal => vec![zeta; n],
            DampingModel::Rayleigh { modes: [i, j] } => {
                let (wi, wj) = (omega[i.min(n) - 1], omega[j.min(n) - 1]);
                if n == 1 || wi == wj {
                    vec![zeta; n]
                } else {
                    let a = 2.0 * zeta * wi * wj / (wi + wj);
                    let b = 2.0 * zeta / (wi + wj);
                    omega.iter().map(|w| a / (2.0 * w) + b * w / 2.0).collect()
                }
            }
        };
        Modes {
            omega_rad_s: omega,
            damping,
            shapes,
            participation,
        }
    }

    /// How many modes (the number of storeys).
    pub fn count(&self) -> usize {
        self.omega_rad_s.len()
    }

    /// Periods [s], longest first.
    pub fn periods_s(&self) -> Vec<f64> {
        self.omega_rad_s
            .iter()
            .map(|w| 2.0 * std::f64::consts::PI / w)
            .collect()
    }
}

/// The diagonal and the off-diagonal (entry j couples floors j and j + 1) of
/// M^-1/2 K M^-1/2, K the shear building's tridiagonal stiffness.
fn scaled_stiffness(masses: &[f64], stiffnesses: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let n = masses.len();
    let inv_sqrt_m: Vec<f64> = masses.iter().map(|m| 1.0 / m.sqrt()).collect();
    let diag = (0..n)
        .map(|j| {
            let above = if j + 1 < n { stiffnesses[j + 1] } else { 0.0 };
            (stiffnesses[j] + above) * inv_sqrt_m[j] * inv_sqrt_m[j]
        })
        .collect();
    let off = (0..n)
        .map(|j| {
            if j + 1 < n {
                -stiffnesses[j + 1] * inv_sqrt_m[j] * inv_sqrt_m[j + 1]
            } else {
                0.0
            }
        })
        .collect();
    (diag, off)
}

/// The smallest squared frequency of floors with `masses` over storeys of `stiffnesses`, by
/// bisection on the Sturm count: a few thousand operations for 100 storeys, where all the modes
/// take millions, for a caller that only compares fundamental frequencies.
pub fn fundamental_omega_squared(masses: &[f64], stiffnesses: &[f64]) -> f64 {
    let (diag, off) = scaled_stiffness(masses, stiffnesses);
    omega_squared_at(&diag, &off, 0)
}

/// The smallest and the largest squared frequency, by the same bisection (for a caller that
/// needs only their spread).
pub fn omega_squared_range(masses: &[f64], stiffnesses: &[f64]) -> (f64, f64) {
    let (diag, off) = scaled_stiffness(masses, stiffnesses);
    let last = diag.len().saturating_sub(1);
    (
        omega_squared_at(&diag, &off, 0),
        omega_squared_at(&diag, &off, last),
    )
}

/// The eigenvalue of index `index` (from the smallest) of the tridiagonal matrix, by bisection
/// on the Sturm count.
fn omega_squared_at(diag: &[f64], off: &[f64], index: usize) -> f64 {
    // Gershgorin: every eigenvalue lies in [0, max row sum]; K is positive definite.
    let mut hi = (0..diag.len())
        .map(|j| diag[j] + off[j].abs() + if j > 0 { off[j - 1].abs() } else { 0.0 })
        .fold(0.0, f64::max);
    let mut lo = 0.0;
    // Halving from the largest eigenvalue reaches the relative precision of the smallest only
    // after log2(spread) + 53 steps; 1100 covers any finite spread.
    for _ in 0..1100 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if below(diag, off, mid) > index {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

/// How many eigenvalues of the tridiagonal matrix lie below x (Sturm's sequence of the pivots
/// of A - x I).
fn below(diag: &[f64], off: &[f64], x: f64) -> usize {
    let mut count = 0;
    let mut pivot = 1.0;
    for j in 0..diag.len() {
        let coupling = if j > 0 { off[j - 1] * off[j - 1] } else { 0.0 };
        pivot = diag[j] - x - coupling / pivot;
        if pivot == 0.0 {
            // An exact zero pivot: nudge it so the next division stays finite.
            pivot = -f64::EPSILON * (diag[j].abs() + x.abs()).max(f64::MIN_POSITIVE);
        }
        if pivot < 0.0 {
            count += 1;
        }
    }
    count
}

/// Eigenvalues and eigenvectors (columns: `vectors[j][k]` is component j of vector k) of the
/// symmetric tridiagonal matrix with `diag` and `off` (`off[j]` couples j and j + 1; the last is
/// unused), by the QL algorithm with implicit shifts: O(n^2) for the values, O(n^3) with the
/// vectors, and backward stable (each eigenvalue within round-off of the largest).
fn tridiagonal_eigen(mut d: Vec<f64>, mut e: Vec<f64>) -> (Vec<f64>, Vec<Vec<f64>>) {
    let n = d.len();
    let mut z = vec![vec![0.0; n]; n];
    for (i, row) in z.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    if n > 0 {
        e[n - 1] = 0.0;
    }
    for l in 0..n {
        // Each eigenvalue takes a handful of sweeps; the cap only guards against a NaN input.
        for _sweep in 0..64 {
            let m = (l..n)
                .find(|&m| m + 1 == n || e[m].abs() <= f64::EPSILON * (d[m].abs() + d[m + 1].abs()))
                .unwrap_or(n - 1);
            if m == l {
                break;
            }
            let mut g = (d[l + 1] - d[l]) / (2.0 * e[l]);
            let mut r = g.hypot(1.0);
            g = d[m] - d[l] + e[l] / (g + r.copysign(g));
            let (mut s, mut c, mut p) = (1.0, 1.0, 0.0);
            let mut deflated = false;
            for i in (l..m).rev() {
                let f = s * e[i];
                let b = c * e[i];
                r = f.hypot(g);
                e[i + 1] = r;
                if r == 0.0 {
                    // Underflow: the matrix split; start again on the smaller block.
                    d[i + 1] -= p;
                    e[m] = 0.0;
                    deflated = true;
                    break;
                }
                s = f / r;
                c = g / r;
                g = d[i + 1] - p;
                r = (d[i] - g) * s + 2.0 * c * b;
                p = s * r;
                d[i + 1] = g + p;
                g = c * r - b;
                for row in z.iter_mut() {
                    let f = row[i + 1];
                    row[i + 1] = s * row[i] + c * f;
                    row[i] = c * row[i] - s * f;
                }
            }
            if deflated {
                continue;
            }
            d[l] -= p;
            e[l] = g;
            e[m] = 0.0;
        }
    }
    (d, z)
}

/// One mode's exact response over a step of length s with its forcing linear in time:
/// `q(s) = q . y0`, `q'(s) = v . y0` with y0 = [q(0), q'(0), g(0), g'].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Propagator {
    /// Weights giving q(s).
    pub q: [f64; 4],
    /// Weights giving q'(s).
    pub v: [f64; 4],
}

/// Integrals over the same step: the integral of q is `int_q . y0`, of q'^2 is `y0^T w y0`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StepIntegrals {
    /// Weights giving the integral of q over the step.
    pub int_q: [f64; 4],
    /// The quadratic form giving the integral of q'^2 over the step.
    pub w: [[f64; 4]; 4],
}

impl Propagator {
    /// (q(s), q'(s)) from y0 = [q(0), q'(0), g(0), g'].
    #[inline]
    pub fn apply(&self, y: &[f64; 4]) -> (f64, f64) {
        (dot(&self.q, y), dot(&self.v, y))
    }
}

impl StepIntegrals {
    /// The integral of q'^2 over the step.
    #[inline]
    pub fn velocity_squared(&self, y: &[f64; 4]) -> f64 {
        let mut s = 0.0;
        for i in 0..4 {
            s += y[i] * dot(&self.w[i], y);
        }
        s
    }
}

#[inline]
fn dot(a: &[f64; 4], b: &[f64; 4]) -> f64 {
    (a[0] * b[0] + a[1] * b[1]) + (a[2] * b[2] + a[3] * b[3])
}

/// The augmented generator in balanced coordinates z = D y, D = diag(nu, 1, 1/nu, 1/nu^2) with
/// nu = max(w, 1/s): every entry is of the order of nu, so exp(A s) is well conditioned for any
/// frequency and step. Returns (A_z s, D).
fn balanced(omega: f64, zeta: f64, s: f64) -> ([[f64; 4]; 4], [f64; 4]) {
    let nu = omega.max(1.0 / s);
    let d = [nu, 1.0, 1.0 / nu, 1.0 / (nu * nu)];
    let mut a = [[0.0; 4]; 4];
    a[0][1] = nu * s;
    a[1][0] = -omega * omega / nu * s;
    a[1][1] = -2.0 * zeta * omega * s;
    a[1][2] = nu * s;
    a[2][3] = nu * s;
    (a, d)
}

/// One mode's exact state (q(s), q'(s)) a time s after y0 = [q, q', g, g'] under forcing linear
/// in time: the closed form for an underdamped mode (its line of particular response plus a
/// decaying sinusoid, one exponential and one sine-cosine), the exponential map otherwise. It
/// agrees with [`propagator`] to round-off, at a fraction of its cost where the time is not one
/// of the precomputed steps.
pub fn evaluate(omega: f64, zeta: f64, y: &[f64; 4], s: f64) -> (f64, f64) {
    if !(zeta < 0.99 && omega > 0.0) || s <= 0.0 {
        return propagator(omega, zeta, s).apply(y);
    }
    let w2 = omega * omega;
    let beta = y[3] / w2;
    let alpha = (y[2] - 2.0 * zeta * omega * beta) / w2;
    let (qh, vh) = (y[0] - alpha, y[1] - beta);
    let wd = omega * (1.0 - zeta * zeta).sqrt();
    let zw = zeta * omega;
    let e = (-zw * s).exp();
    let (sn, cs) = (wd * s).sin_cos();
    (
        alpha + beta * s + e * (qh * cs + (vh + zw * qh) / wd * sn),
        beta + e * (vh * cs - (zw * vh + w2 * qh) / wd * sn),
    )
}

/// The exact step of one mode (see [`Propagator`]); the identity for a step of zero.
pub fn propagator(omega: f64, zeta: f64, s: f64) -> Propagator {
    if s <= 0.0 {
        return Propagator {
            q: [1.0, 0.0, 0.0, 0.0],
            v: [0.0, 1.0, 0.0, 0.0],
        };
    }
    let (a, d) = balanced(omega, zeta, s);
    let e = expm(&a);
    // y(s) = D^-1 E D y(0): row i of the map is E[i][j] d_j / d_i.
    let row = |i: usize| std::array::from_fn(|j| e[i][j] * d[j] / d[i]);
    Propagator {
        q: row(0),
        v: row(1),
    }
}

/// The integrals of q and q'^2 over the step (see [`StepIntegrals`]), by Van Loan's block
/// exponentials.
pub fn step_integrals(omega: f64, zeta: f64, s: f64) -> StepIntegrals {
    if s <= 0.0 {
        return StepIntegrals::default();
    }
    // Van Loan's block holds exp(+zeta w s) beside exp(-zeta w s): past about e^700 it overflows
    // and the product is NaN (a stiff storey, w ~ 1e6 rad/s, over a record's step). A step that
    // long is halved until it is safe, then doubled back exactly.
    let halvings = (zeta * omega * s / MAX_DECAY).log2().ceil().max(0.0) as i32;
    if halvings > 0 {
        return doubled(omega, zeta, s, halvings);
    }
    let (a, d) = balanced(omega, zeta, s);
    // exp([[A, I], [0, 0]] s): its upper-right block is the integral of exp(A t) over [0, s].
    let mut c = [[0.0; 8]; 8];
    for i in 0..4 {
        for j in 0..4 {
            c[i][j] = a[i][j];
        }
        c[i][4 + i] = s;
    }
    let ec = expm(&c);
    // int q = (1/d_0) row 0 of the integral, times D.
    let int_q = std::array::from_fn(|j| ec[0][4 + j] * d[j] / d[0]);
    // Van Loan: exp([[-A^T, Q], [0, A]] s) = [[F11, F12], [0, F22]] and the integral of
    // exp(A^T t) Q exp(A t) over [0, s] is F22^T F12; Q picks z_1 = q'.
    let mut v = [[0.0; 8]; 8];
    for i in 0..4 {
        for j in 0..4 {
            v[i][j] = -a[j][i];
            v[4 + i][4 + j] = a[i][j];
        }
    }
    v[1][5] = s;
    let ev = expm(&v);
    let mut wz = [[0.0; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            wz[i][j] = (0..4).map(|k| ev[4 + k][4 + i] * ev[k][4 + j]).sum();
        }
    }
    // In y: W_y = D W_z D, symmetrised against round-off.
    let w =
        std::array::from_fn(|i| std::array::from_fn(|j| 0.5 * (wz[i][j] + wz[j][i]) * d[i] * d[j]));
    StepIntegrals { int_q, w }
}

/// The largest zeta w s a single Van Loan exponential is asked to span: its squarings carry
/// round-off of eps e^(2 zeta w s) into the decaying block, so the span stays near 1.
const MAX_DECAY: f64 = 1.0;

/// The integrals and exact maps over 1, 2, 4, ... fine steps of one mode, as many as `steps`
/// needs.
pub(crate) fn doublings(
    omega: f64,
    zeta: f64,
    h: f64,
    steps: usize,
) -> Vec<(StepIntegrals, [[f64; 4]; 4])> {
    let mut out = vec![(step_integrals(omega, zeta, h), full_map(omega, zeta, h))];
    while (1usize << out.len()) <= steps {
        let (ints, phi) = out.last().expect("one at least");
        out.push((joined(ints, phi, ints), mul4(phi, phi)));
    }
    out
}

/// A mode's integrals over j fine steps, joined from its [`doublings`].
pub(crate) fn integrals_over(
    doublings: &[(StepIntegrals, [[f64; 4]; 4])],
    j: usize,
) -> StepIntegrals {
    // The doublings j is made of, shortest first, joined one after another (the map over the
    // whole is not asked for: the last join needs none made).
    let mut parts = (0..doublings.len()).filter(|&b| j & (1 << b) != 0);
    let Some(first) = parts.next() else {
        return StepIntegrals::default();
    };
    let (mut ints, mut phi) = doublings[first];
    let mut next = parts.next();
    while let Some(b) = next {
        next = parts.next();
        let (b_ints, b_phi) = &doublings[b];
        ints = joined(&ints, &phi, b_ints);
        if next.is_some() {
            phi = mul4(b_phi, &phi);
        }
    }
    ints
}

/// A mode's exact steps over h, 2h, ... `count` h, each the one before times the first (one
/// product per step instead of an exponential). Only the rows of q and q' are kept: a row of a
/// product is that row of the left factor times the right one, so they are [`mul4`]'s rows, bit
/// for bit, at half its work.
pub(crate) fn step_powers(omega: f64, zeta: f64, h: f64, count: usize) -> Vec<Propagator> {
    powers(omega, zeta, h).take(count).collect()
}

/// [`step_powers`] without end: the exact steps over h, 2h, 3h, ...
pub(crate) fn powers(omega: f64, zeta: f64, h: f64) -> impl Iterator<Item = Propagator> {
    let first = full_map(omega, zeta, h);
    let one = Propagator {
        q: first[0],
        v: first[1],
    };
    std::iter::successors(Some(one), move |p| Some(p.then(&first)))
}

impl Propagator {
    /// This step followed by the one whose full map is `next` (the rows of q and q' only: see
    /// [`step_powers`]).
    #[inline]
    pub(crate) fn then(&self, next: &[[f64; 4]; 4]) -> Propagator {
        let times =
            |row: [f64; 4]| std::array::from_fn(|c| (0..4).map(|k| row[k] * next[k][c]).sum());
        Propagator {
            q: times(self.q),
            v: times(self.v),
        }
    }
}

/// The exact step's full 4 x 4 map in y = [q, q', g, g'].
pub(crate) fn full_map(omega: f64, zeta: f64, h: f64) -> [[f64; 4]; 4] {
    let p = propagator(omega, zeta, h);
    // g(s) = g + g' s, g' constant.
    [p.q, p.v, [0.0, 0.0, 1.0, h], [0.0, 0.0, 0.0, 1.0]]
}

pub(crate) fn mul4(a: &[[f64; 4]; 4], b: &[[f64; 4]; 4]) -> [[f64; 4]; 4] {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..4).map(|k| a[i][k] * b[k][j]).sum()))
}

/// The integrals over a step of length a + b from those over a (whose exact map is `phi_a`) and
/// those over b: the second part's integrands start from the state at a, y(a) = Phi(a) y0.
pub fn joined(
    first: &StepIntegrals,
    phi_a: &[[f64; 4]; 4],
    second: &StepIntegrals,
) -> StepIntegrals {
    let int_q = std::array::from_fn(|j| {
        first.int_q[j] + (0..4).map(|k| second.int_q[k] * phi_a[k][j]).sum::<f64>()
    });
    let w_phi: [[f64; 4]; 4] = std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..4).map(|k| second.w[i][k] * phi_a[k][j]).sum())
    });
    let w = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            first.w[i][j] + (0..4).map(|k| phi_a[k][i] * w_phi[k][j]).sum::<f64>()
        })
    });
    StepIntegrals { int_q, w }
}

/// The integrals over `s` from those over s / 2^halvings: over [0, 2h] they are those over
/// [0, h] from the start and again from the state at h, y(h) = Phi(h) y0.
fn doubled(omega: f64, zeta: f64, s: f64, halvings: i32) -> StepIntegrals {
    let h = s * 0.5f64.powi(halvings);
    let mut ints = step_integrals(omega, zeta, h);
    let (a, d) = balanced(omega, zeta, h);
    let e = expm(&a);
    let mut phi: [[f64; 4]; 4] =
        std::array::from_fn(|i| std::array::from_fn(|j| e[i][j] * d[j] / d[i]));
    for _ in 0..halvings {
        ints = joined(&ints, &phi, &ints);
        phi = matmul(&phi, &phi);
    }
    ints
}

/// exp(a) by scaling and squaring with a Taylor polynomial: the scaled matrix has a norm of at
/// most 1/4, where 20 terms are exact to round-off.
fn expm<const N: usize>(a: &[[f64; N]; N]) -> [[f64; N]; N] {
    let norm = (0..N)
        .map(|j| (0..N).map(|i| a[i][j].abs()).sum::<f64>())
        .fold(0.0, f64::max);
    let squarings = if norm > 0.25 {
        (norm / 0.25).log2().ceil() as i32
    } else {
        0
    };
    let scale = 0.5f64.powi(squarings);
    let x: [[f64; N]; N] = std::array::from_fn(|i| std::array::from_fn(|j| a[i][j] * scale));
    let mut sum = identity::<N>();
    let mut term = identity::<N>();
    for k in 1..=20 {
        term = matmul(&term, &x);
        let inv = 1.0 / k as f64;
        for row in term.iter_mut() {
            for v in row.iter_mut() {
                *v *= inv;
            }
        }
        for i in 0..N {
            for j in 0..N {
                sum[i][j] += term[i][j];
            }
        }
    }
    for _ in 0..squarings {
        sum = matmul(&sum, &sum);
    }
    sum
}

fn identity<const N: usize>() -> [[f64; N]; N] {
    std::array::from_fn(|i| std::array::from_fn(|j| if i == j { 1.0 } else { 0.0 }))
}

pub(crate) fn matmul<const N: usize>(a: &[[f64; N]; N], b: &[[f64; N]; N]) -> [[f64; N]; N] {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..N).map(|k| a[i][k] * b[k][j]).sum()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_powers_of_a_step_are_the_rows_of_its_full_products() {
        for (omega, zeta, h) in [(12.7, 0.05, 1.6e-5), (84.5, 0.02, 1e-3), (3.0, 0.9, 0.01)] {
            let first = full_map(omega, zeta, h);
            let mut full = first;
            for (j, p) in step_powers(omega, zeta, h, 300).iter().enumerate() {
                if j > 0 {
                    full = mul4(&full, &first);
                }
                assert_eq!((p.q, p.v), (full[0], full[1]), "step {j}");
            }
        }
    }

    #[test]
    fn integrals_joined_from_two_steps_are_those_of_the_whole_step() {
        let (omega, zeta) = (17.95, 0.05);
        let (a, b) = (3.0e-3, 4.5e-3);
        let p = propagator(omega, zeta, a);
        let phi = [p.q, p.v, [0.0, 0.0, 1.0, a], [0.0, 0.0, 0.0, 1.0]];
        let both = joined(
            &step_integrals(omega, zeta, a),
            &phi,
            &step_integrals(omega, zeta, b),
        );
        let whole = step_integrals(omega, zeta, a + b);
        for j in 0..4 {
            assert!((both.int_q[j] - whole.int_q[j]).abs() <= 1e-13 * (1.0 + whole.int_q[j].abs()));
            for i in 0..4 {
                let scale = whole.w[i][i].abs().max(whole.w[j][j].abs()).max(1e-300);
                assert!(
                    (both.w[i][j] - whole.w[i][j]).abs() <= 1e-12 * scale,
                    "{i} {j}"
                );
            }
        }
    }

    #[test]
    fn the_closed_form_state_agrees_with_the_exponential_map() {
        for (omega, zeta) in [(17.95, 0.05), (3.0, 0.0), (200.0, 0.3), (40.0, 0.9)] {
            let y = [0.01, -0.2, 3.0, -40.0];
            for s in [1e-6, 1e-3, 0.05, 1.7] {
                let (q, v) = evaluate(omega, zeta, &y, s);
                let (qe, ve) = propagator(omega, zeta, s).apply(&y);
                let scale = qe.abs() + ve.abs() / omega + 1e-12;
                assert!(
                    (q - qe).abs() <= 1e-12 * scale && (v - ve).abs() <= 1e-12 * omega * scale,
                    "w {omega}, zeta {zeta}, s {s}: ({q}, {v}) against ({qe}, {ve})"
                );
            }
        }
    }

    #[test]
    fn one_storey_is_the_oscillator_and_modal_damping_its_ratio() {
        let m = Modes::of_shear_building(&[36_000.0], &[1.16e7], 0.05, DampingModel::Modal);
        assert!((m.omega_rad_s[0] - (1.16e7f64 / 36_000.0).sqrt()).abs() < 1e-12);
        assert!((m.shapes[0][0] - 1.0 / 36_000f64.sqrt()).abs() < 1e-18);
        assert!((m.participation[0] - 36_000f64.sqrt()).abs() < 1e-9);
        assert_eq!(m.damping, vec![0.05]);
    }

    #[test]
    fn two_storey_modes_are_mass_orthonormal_and_solve_the_eigenproblem() {
        let (ms, ks) = ([2.0e5, 1.5e5], [4.0e8, 3.0e8]);
        let m = Modes::of_shear_building(&ms, &ks, 0.05, DampingModel::Modal);
        let k = [[ks[0] + ks[1], -ks[1]], [-ks[1], ks[1]]];
        for a in 0..2 {
            for b in 0..2 {
                let mass: f64 = (0..2)
                    .map(|j| m.shapes[a][j] * ms[j] * m.shapes[b][j])
                    .sum();
                assert!((mass - if a == b { 1.0 } else { 0.0 }).abs() < 1e-12);
            }
            let w2 = m.omega_rad_s[a].powi(2);
            for j in 0..2 {
                let ku: f64 = (0..2).map(|i| k[j][i] * m.shapes[a][i]).sum();
                assert!((ku - w2 * ms[j] * m.shapes[a][j]).abs() < 1e-9 * ku.abs().max(1.0));
            }
        }
        // The participation factors' squares add up to the total mass.
        let total: f64 = m.participation.iter().map(|g| g * g).sum();
        assert!((total - 3.5e5).abs() < 1e-6);
    }

    #[test]
    fn a_uniform_hundred_storey_building_has_the_closed_form_frequencies_and_orthonormal_modes() {
        // Equal floors m on equal storeys k, fixed base and free roof:
        // w_j = 2 sqrt(k/m) sin((2j - 1) pi / (2 (2N + 1))).
        let n = 100;
        let (mass, k) = (3.0e5, 6.0e8);
        let m = Modes::of_shear_building(&vec![mass; n], &vec![k; n], 0.05, DampingModel::Modal);
        for (j, w) in m.omega_rad_s.iter().enumerate() {
            let angle = (2 * j + 1) as f64 * std::f64::consts::PI / (2.0 * (2 * n + 1) as f64);
            let exact = 2.0 * (k / mass).sqrt() * angle.sin();
            assert!(
                (w - exact).abs() <= 1e-10 * exact,
                "mode {j}: {w} against {exact}"
            );
        }
        for a in [0, 1, 49, 99] {
            for b in [0, 1, 49, 99] {
                let dot: f64 = (0..n).map(|j| m.shapes[a][j] * mass * m.shapes[b][j]).sum();
                let expected = if a == b { 1.0 } else { 0.0 };
                assert!((dot - expected).abs() < 1e-12, "modes {a}, {b}: {dot}");
            }
        }
        let total: f64 = m.participation.iter().map(|g| g * g).sum();
        assert!((total - n as f64 * mass).abs() < 1e-9 * n as f64 * mass);
    }

    #[test]
    fn the_sturm_fundamental_frequency_is_the_lowest_mode() {
        let ms: Vec<f64> = (0..37)
            .map(|j| 1.0e5 * (1.0 + 0.3 * (j as f64).sin()))
            .collect();
        let ks: Vec<f64> = (0..37).map(|j| 2.0e8 * (2.0 - 0.02 * j as f64)).collect();
        let w0 = Modes::of_shear_building(&ms, &ks, 0.05, DampingModel::Modal).omega_rad_s[0];
        let sturm = fundamental_omega_squared(&ms, &ks).sqrt();
        assert!((sturm - w0).abs() <= 1e-12 * w0, "{sturm} against {w0}");
        let one = fundamental_omega_squared(&[36_000.0], &[1.16e7]);
        assert!((one - 1.16e7 / 36_000.0).abs() <= 1e-13 * one);
    }

    #[test]
    fn the_sturm_range_of_frequencies_is_the_lowest_and_the_highest_mode() {
        // A 60-storey building whose stiffnesses fall and masses vary floor by floor, and one
        // storey (both ends the same frequency).
        let ms: Vec<f64> = (0..60)
            .map(|j| 2.0e5 * (1.0 + 0.4 * (0.7 * j as f64).cos()))
            .collect();
        let ks: Vec<f64> = (0..60).map(|j| 5.0e8 * (1.5 - 0.02 * j as f64)).collect();
        let w = Modes::of_shear_building(&ms, &ks, 0.05, DampingModel::Modal).omega_rad_s;
        let (lo, hi) = omega_squared_range(&ms, &ks);
        let (w_lo, w_hi) = (w[0] * w[0], w[59] * w[59]);
        assert!((lo - w_lo).abs() <= 1e-11 * w_lo, "{lo} against {w_lo}");
        assert!((hi - w_hi).abs() <= 1e-11 * w_hi, "{hi} against {w_hi}");
        let (a, b) = omega_squared_range(&[36_000.0], &[1.16e7]);
        assert_eq!(a, b);
        assert!((a - 1.16e7 / 36_000.0).abs() <= 1e-13 * a);
    }

    #[test]
    fn rayleigh_damping_gives_the_ratio_in_its_two_modes() {
        let ms = [1.0e5; 4];
        let ks = [2.0e8; 4];
        let m = Modes::of_shear_building(&ms, &ks, 0.05, DampingModel::Rayleigh { modes: [1, 3] });
        assert!((m.damping[0] - 0.05).abs() < 1e-12 && (m.damping[2] - 0.05).abs() < 1e-12);
        assert!(m.damping[1] < 0.05 && m.damping[3] > 0.05);
    }

    /// The response of q'' + 2 z w q' + w^2 q = g0 + g1 t: the closed form, or for a very low
    /// frequency (where the closed form cancels catastrophically) RK4 on fine steps.
    fn closed(w: f64, z: f64, y: [f64; 4], t: f64) -> (f64, f64) {
        if w < 1.0 {
            let f = |tt: f64, q: f64, v: f64| y[2] + y[3] * tt - 2.0 * z * w * v - w * w * q;
            let n = 20_000;
            let h = t / n as f64;
            let (mut q, mut v) = (y[0], y[1]);
            for i in 0..n {
                let tt = i as f64 * h;
                let (k1q, k1v) = (v, f(tt, q, v));
                let (k2q, k2v) = (
                    v + 0.5 * h * k1v,
                    f(tt + 0.5 * h, q + 0.5 * h * k1q, v + 0.5 * h * k1v),
                );
                let (k3q, k3v) = (
                    v + 0.5 * h * k2v,
                    f(tt + 0.5 * h, q + 0.5 * h * k2q, v + 0.5 * h * k2v),
                );
                let (k4q, k4v) = (v + h * k3v, f(tt + h, q + h * k3q, v + h * k3v));
                q += h / 6.0 * (k1q + 2.0 * k2q + 2.0 * k3q + k4q);
                v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
            }
            return (q, v);
        }
        let wd = w * (1.0 - z * z).sqrt();
        // Particular solution of q'' + 2 z w q' + w^2 q = g0 + g1 t: q_p = a + b t.
        let b = y[3] / (w * w);
        let a = (y[2] - 2.0 * z * w * b) / (w * w);
        let (c0, v0) = (y[0] - a, y[1] - b);
        let e = (-z * w * t).exp();
        let (s, c) = (wd * t).sin_cos();
        let h = e * (c0 * c + (v0 + z * w * c0) / wd * s);
        let hd = e * (v0 * c - (z * w * v0 + w * w * c0) / wd * s);
        (h + a + b * t, hd + b)
    }

    #[test]
    fn the_propagator_is_the_closed_form_for_short_and_long_steps_and_any_damping() {
        let y = [0.01, -0.3, 2.0, -15.0];
        for (w, z) in [(17.95, 0.05), (300.0, 0.0), (3.0, 0.9), (1e-3, 0.2)] {
            for s in [1e-6, 4.6e-5, 0.02, 0.35] {
                let p = propagator(w, z, s);
                let (q, v) = p.apply(&y);
                let (qc, vc) = closed(w, z, y, s);
                let tol = 1e-12 * (1.0 + qc.abs() + y[0].abs() + y[1].abs() * s);
                assert!((q - qc).abs() < tol, "w {w} z {z} s {s}: {q} vs {qc}");
                assert!(
                    (v - vc).abs() < 1e-10 * (1.0 + vc.abs()),
                    "w {w} s {s}: {v} vs {vc}"
                );
            }
        }
    }

    #[test]
    fn a_step_of_zero_changes_nothing() {
        let y = [0.01, -0.3, 2.0, -15.0];
        assert_eq!(propagator(17.95, 0.05, 0.0).apply(&y), (y[0], y[1]));
        assert_eq!(step_integrals(17.95, 0.05, 0.0).velocity_squared(&y), 0.0);
    }

    #[test]
    fn step_integrals_of_a_very_stiff_mode_over_a_long_step_are_finite() {
        // w = 3.16e6 rad/s over 0.02 s: zeta w s = 3162, where one Van Loan block overflows.
        let i = step_integrals(1e13f64.sqrt(), 0.05, 0.02);
        let v2 = i.velocity_squared(&[1e-9, 1e-3, 0.5, 0.0]);
        assert!(v2.is_finite() && v2 > 0.0, "{v2}");
    }

    #[test]
    fn step_integrals_match_quadrature_of_the_closed_form() {
        let y = [0.01, -0.3, 2.0, -15.0];
        // The last two are halved and doubled back (zeta w s = 200 and 400).
        for (w, z, s) in [
            (17.95, 0.05, 0.02),
            (300.0, 0.02, 0.02),
            (5.0, 0.5, 1e-4),
            (2000.0, 0.1, 1.0),
            (4000.0, 0.2, 0.5),
        ] {
            let i = step_integrals(w, z, s);
            // Gauss-Legendre, 400 panels of 3 points: exact to round-off for these.
            let (gx, gw) = (
                [-(0.6f64).sqrt(), 0.0, (0.6f64).sqrt()],
                [5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0],
            );
            let (mut int_q, mut int_v2) = (0.0, 0.0);
            let panels = 400.max((w * s * 20.0) as usize);
            for p in 0..panels {
                let (a, b) = (
                    s * p as f64 / panels as f64,
                    s * (p + 1) as f64 / panels as f64,
                );
                for k in 0..3 {
                    let t = 0.5 * (a + b) + 0.5 * (b - a) * gx[k];
                    let (q, v) = closed(w, z, y, t);
                    int_q += 0.5 * (b - a) * gw[k] * q;
                    int_v2 += 0.5 * (b - a) * gw[k] * v * v;
                }
            }
            let got_q: f64 = (0..4).map(|j| i.int_q[j] * y[j]).sum();
            assert!(
                (got_q - int_q).abs() < 1e-11 * int_q.abs().max(1e-12),
                "{got_q} vs {int_q}"
            );
            let got_v2 = i.velocity_squared(&y);
            assert!(
                (got_v2 - int_v2).abs() < 1e-10 * int_v2,
                "{got_v2} vs {int_v2}"
            );
        }
    }
}
