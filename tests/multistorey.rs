//! Multi-storey buildings: against an exact solution of the piecewise-linear system, modal
//! damping by free decay, the floor-to-column force split, and the gap that avoids pounding.
// The reference's dense matrix code reads as the algebra it is, indexed.
#![allow(clippy::needless_range_loop)]

use pounding::io::building_settings::BuildingSetup;
use pounding::io::preset;
use pounding::model::building::{
    Attachment, BuildingResult, BuildingScenario, ContactModel, DampingModel, Modes, Recording,
    solve,
};
use pounding::model::motion::GroundMotion;

mod common;

fn preset_scenario(name: &str) -> BuildingScenario {
    preset::load_for::<BuildingSetup>(name, "buildings")
        .unwrap()
        .scenario
}

fn el_centro() -> GroundMotion {
    pounding::io::motion::built_in("elcentro-1940")
        .expect("built in")
        .truncated(8.0)
}

fn run(sc: &BuildingScenario, m: &GroundMotion) -> BuildingResult {
    solve(sc, m).unwrap_or_else(|e| panic!("{}: {e}", sc.contact.name()))
}

// ---- a small dense linear algebra for the reference -----------------------------------------

type Mat = Vec<Vec<f64>>;

fn zeros(n: usize, m: usize) -> Mat {
    vec![vec![0.0; m]; n]
}

fn eye(n: usize) -> Mat {
    let mut a = zeros(n, n);
    for (i, row) in a.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    a
}

fn mul(a: &Mat, b: &Mat) -> Mat {
    let (n, m, p) = (a.len(), b.len(), b[0].len());
    let mut c = zeros(n, p);
    for i in 0..n {
        for k in 0..m {
            if a[i][k] != 0.0 {
                for j in 0..p {
                    c[i][j] += a[i][k] * b[k][j];
                }
            }
        }
    }
    c
}

fn mulv(a: &Mat, x: &[f64]) -> Vec<f64> {
    a.iter()
        .map(|row| row.iter().zip(x).map(|(p, q)| p * q).sum())
        .collect()
}

fn inverse(a: &Mat) -> Mat {
    let n = a.len();
    let mut m: Mat = a.clone();
    let mut inv = eye(n);
    for c in 0..n {
        let p = (c..n)
            .max_by(|&i, &j| m[i][c].abs().total_cmp(&m[j][c].abs()))
            .unwrap();
        m.swap(c, p);
        inv.swap(c, p);
        let d = m[c][c];
        for j in 0..n {
            m[c][j] /= d;
            inv[c][j] /= d;
        }
        for i in 0..n {
            if i != c {
                let f = m[i][c];
                for j in 0..n {
                    m[i][j] -= f * m[c][j];
                    inv[i][j] -= f * inv[c][j];
                }
            }
        }
    }
    inv
}

/// exp(a) by scaling and squaring with a Taylor polynomial (written here, apart from the
/// solver's).
fn expm(a: &Mat) -> Mat {
    let n = a.len();
    let norm = (0..n)
        .map(|j| (0..n).map(|i| a[i][j].abs()).sum::<f64>())
        .fold(0.0, f64::max);
    let s = if norm > 0.5 {
        (norm / 0.5).log2().ceil() as i32
    } else {
        0
    };
    let scale = 0.5f64.powi(s);
    let x: Mat = a
        .iter()
        .map(|r| r.iter().map(|v| v * scale).collect())
        .collect();
    let mut sum = eye(n);
    let mut term = eye(n);
    for k in 1..=24 {
        term = mul(&term, &x);
        for r in term.iter_mut() {
            for v in r.iter_mut() {
                *v /= k as f64;
            }
        }
        for i in 0..n {
            for j in 0..n {
                sum[i][j] += term[i][j];
            }
        }
        // A term below the rounding of the sum (whose entries are about one) adds nothing.
        if term.iter().flatten().all(|v| v.abs() < 1e-18) {
            break;
        }
    }
    for _ in 0..s {
        sum = mul(&sum, &sum);
    }
    sum
}

/// The square root of a symmetric positive definite matrix (Denman-Beavers).
fn sqrtm(a: &Mat) -> Mat {
    let (mut y, mut z) = (a.clone(), eye(a.len()));
    for _ in 0..60 {
        let (yi, zi) = (inverse(&y), inverse(&z));
        let ny: Mat = y
            .iter()
            .zip(&zi)
            .map(|(r, s)| r.iter().zip(s).map(|(p, q)| 0.5 * (p + q)).collect())
            .collect();
        let nz: Mat = z
            .iter()
            .zip(&yi)
            .map(|(r, s)| r.iter().zip(s).map(|(p, q)| 0.5 * (p + q)).collect())
            .collect();
        y = ny;
        z = nz;
    }
    y
}

/// An exact solution of the two buildings with linear-spring contacts: in physical
/// coordinates, the state is propagated by matrix exponentials between events (each level's
/// overlap crossing zero), the events found by bisection on the exact propagation.
struct Reference {
    /// Degrees of freedom: the left floors, then the right.
    n: usize,
    masses: Vec<f64>,
    k: Mat,
    c: Mat,
    /// Each level's coupling: u_left(point) - u_right(point) = b . u.
    b: Vec<Vec<f64>>,
    kc: f64,
    gap: f64,
    /// Per degree of freedom: the storey height under it, and the floor below it on its side
    /// (none for a first floor), for the drift ratios.
    below: Vec<(f64, Option<usize>)>,
}

/// What the reference found.
struct Solution {
    /// (level, start, end, peak force) of each contact.
    contacts: Vec<(usize, f64, f64, f64)>,
    peak_floor: Vec<f64>,
    peak_drift: Vec<f64>,
}

impl Reference {
    fn new(sc: &BuildingScenario) -> Self {
        let (nl, nr) = (sc.left.storeys, sc.right.storeys);
        let n = nl + nr;
        let mut masses = sc.left.masses();
        masses.extend(sc.right.masses());
        let mut k = zeros(n, n);
        let mut c = zeros(n, n);
        for (off, b) in [(0, &sc.left), (nl, &sc.right)] {
            let ks = b.stiffnesses();
            let nb = b.storeys;
            let mut kb = zeros(nb, nb);
            for j in 0..nb {
                kb[j][j] += ks[j];
                if j + 1 < nb {
                    kb[j][j] += ks[j + 1];
                    kb[j][j + 1] = -ks[j + 1];
                    kb[j + 1][j] = -ks[j + 1];
                }
            }
            // Modal damping, zeta in every mode: C = 2 zeta M^1/2 sqrt(M^-1/2 K M^-1/2) M^1/2.
            let m = b.masses();
            let a: Mat = (0..nb)
                .map(|i| (0..nb).map(|j| kb[i][j] / (m[i] * m[j]).sqrt()).collect())
                .collect();
            let s = sqrtm(&a);
            for i in 0..nb {
                for j in 0..nb {
                    k[off + i][off + j] = kb[i][j];
                    c[off + i][off + j] = 2.0 * b.damping_ratio * (m[i] * m[j]).sqrt() * s[i][j];
                }
            }
        }
        // Without a contact element the levels never touch.
        let levels = if sc.contact == ContactModel::None {
            vec![]
        } else {
            sc.levels()
        };
        let b = levels
            .iter()
            .map(|l| {
                let mut v = vec![0.0; n];
                for (f, w) in l.left.weights() {
                    v[f] += w;
                }
                for (f, w) in l.right.weights() {
                    v[nl + f] -= w;
                }
                v
            })
            .collect();
        let below = [(0, &sc.left), (nl, &sc.right)]
            .iter()
            .flat_map(|&(off, b)| {
                b.heights()
                    .into_iter()
                    .enumerate()
                    .map(move |(j, h)| (h, (j > 0).then(|| off + j - 1)))
            })
            .collect();
        Reference {
            n,
            masses,
            k,
            c,
            b,
            kc: sc.stiffness.unwrap_or(0.0),
            gap: sc.gap_m,
            below,
        }
    }

    /// The generator of z = [u, v, a_g, a_g', 1] with the levels in `active` in contact.
    fn generator(&self, active: &[bool]) -> Mat {
        let n = self.n;
        let dim = 2 * n + 3;
        let mut a = zeros(dim, dim);
        let mut k = self.k.clone();
        let mut gap_force = vec![0.0; n];
        for (p, on) in active.iter().enumerate() {
            if *on {
                for i in 0..n {
                    gap_force[i] += self.kc * self.gap * self.b[p][i];
                    for j in 0..n {
                        k[i][j] += self.kc * self.b[p][i] * self.b[p][j];
                    }
                }
            }
        }
        for i in 0..n {
            a[i][n + i] = 1.0;
            for j in 0..n {
                a[n + i][j] = -k[i][j] / self.masses[i];
                a[n + i][n + j] = -self.c[i][j] / self.masses[i];
            }
            a[n + i][2 * n] = -1.0;
            a[n + i][2 * n + 2] = gap_force[i] / self.masses[i];
        }
        a[2 * n][2 * n + 1] = 1.0;
        a
    }

    fn overlap(&self, z: &[f64], p: usize) -> (f64, f64) {
        let n = self.n;
        let d: f64 = (0..n).map(|i| self.b[p][i] * z[i]).sum::<f64>() - self.gap;
        let v: f64 = (0..n).map(|i| self.b[p][i] * z[n + i]).sum();
        (d, v)
    }

    fn solve(&self, m: &GroundMotion, sub: usize) -> Solution {
        let n = self.n;
        let np = self.b.len();
        let mut active = vec![false; np];
        let mut z = vec![0.0; 2 * n + 3];
        z[2 * n + 2] = 1.0;
        let dt = m.dt_s;
        let h = dt / sub as f64;
        let mut cache: std::collections::HashMap<Vec<bool>, Mat> = Default::default();
        let mut open: Vec<Option<(f64, f64)>> = vec![None; np];
        let mut contacts = vec![];
        let mut peak = vec![0.0f64; n];
        let mut peak_drift = vec![0.0f64; n];
        for i in 0..m.accel_m_s2.len() - 1 {
            z[2 * n] = m.accel_m_s2[i];
            z[2 * n + 1] = (m.accel_m_s2[i + 1] - m.accel_m_s2[i]) / dt;
            let (t_start, t_end) = (i as f64 * dt, (i + 1) as f64 * dt);
            let mut t = t_start;
            while t < t_end - 1e-12 * dt {
                let next = (t_start + (((t - t_start) / h + 1e-9).floor() + 1.0) * h).min(t_end);
                let s = next - t;
                let full = (s - h).abs() < 1e-9 * h;
                let e = if full {
                    cache
                        .entry(active.clone())
                        .or_insert_with(|| expm(&scaled(&self.generator(&active), h)))
                        .clone()
                } else {
                    expm(&scaled(&self.generator(&active), s))
                };
                let z1 = mulv(&e, &z);
                // The earliest level whose overlap changes sign within the step.
                let mut event: Option<(f64, usize)> = None;
                let mut ladder: Option<Vec<Mat>> = None;
                for p in 0..np {
                    let (d0, _) = self.overlap(&z, p);
                    let (d1, _) = self.overlap(&z1, p);
                    let crosses = if active[p] {
                        d1 < 0.0
                    } else {
                        d1 > 0.0 && d0 <= 0.0
                    };
                    if crosses {
                        // Bisection from the step's start by halves of what is left: the
                        // propagators over s / 2^j, made once per step.
                        let ladder = ladder.get_or_insert_with(|| {
                            let g = self.generator(&active);
                            (1..=60)
                                .map(|j| expm(&scaled(&g, s * 0.5f64.powi(j))))
                                .collect::<Vec<_>>()
                        });
                        let (mut lo, mut z_lo) = (0.0, z.clone());
                        for (j, e) in ladder.iter().enumerate() {
                            let z_mid = mulv(e, &z_lo);
                            let (dm, _) = self.overlap(&z_mid, p);
                            if (dm > 0.0) != (d1 > 0.0) {
                                lo += s * 0.5f64.powi(j as i32 + 1);
                                z_lo = z_mid;
                            }
                        }
                        let hi = lo + s * 0.5f64.powi(60);
                        if event.is_none_or(|(e, _)| hi < e) {
                            event = Some((hi, p));
                        }
                    }
                }
                let (z_new, t_new, toggled) = match event {
                    Some((x, p)) => (
                        mulv(&expm(&scaled(&self.generator(&active), x)), &z),
                        t + x,
                        Some(p),
                    ),
                    None => (z1, next, None),
                };
                // Peaks: floors and forces, with the cubic between the two states.
                let dur = t_new - t;
                for j in 0..n {
                    let (u0, v0, u1, v1) = (z[j], z[n + j], z_new[j], z_new[n + j]);
                    peak[j] = peak[j]
                        .max(u1.abs())
                        .max(cubic_extreme(u0, v0, u1, v1, dur));
                    let (h, under) = self.below[j];
                    let drift = |z: &[f64], o: usize| match under {
                        Some(b) => (z[o + j] - z[o + b]) / h,
                        None => z[o + j] / h,
                    };
                    let (d0, w0, d1, w1) = (
                        drift(&z, 0),
                        drift(&z, n),
                        drift(&z_new, 0),
                        drift(&z_new, n),
                    );
                    peak_drift[j] = peak_drift[j]
                        .max(d1.abs())
                        .max(cubic_extreme(d0, w0, d1, w1, dur));
                }
                for p in 0..np {
                    if let Some((start, f)) = open[p] {
                        let (d0, w0) = self.overlap(&z, p);
                        let (d1, w1) = self.overlap(&z_new, p);
                        let top = d1.max(cubic_extreme(d0, w0, d1, w1, dur));
                        open[p] = Some((start, f.max(self.kc * top)));
                    }
                }
                z = z_new;
                t = t_new;
                if let Some(p) = toggled {
                    active[p] = !active[p];
                    if active[p] {
                        open[p] = Some((t, 0.0));
                    } else if let Some((start, f)) = open[p].take() {
                        contacts.push((p, start, t, f));
                    }
                }
            }
        }
        contacts.sort_by(|a, b| a.1.total_cmp(&b.1));
        Solution {
            contacts,
            peak_floor: peak,
            peak_drift,
        }
    }
}

fn scaled(a: &Mat, s: f64) -> Mat {
    a.iter()
        .map(|r| r.iter().map(|v| v * s).collect())
        .collect()
}

/// The largest |value| of the cubic through (0, y0) and (l, y1) with slopes v0, v1 inside.
fn cubic_extreme(y0: f64, v0: f64, y1: f64, v1: f64, l: f64) -> f64 {
    if (v0 > 0.0) == (v1 > 0.0) || l <= 0.0 {
        return 0.0;
    }
    let d = |s: f64| {
        let a = 6.0 * s * s - 6.0 * s;
        (a * y0 + (3.0 * s * s - 4.0 * s + 1.0) * l * v0 - a * y1
            + (3.0 * s * s - 2.0 * s) * l * v1)
            / l
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if (d(mid) > 0.0) == (v0 > 0.0) {
            lo = mid
        } else {
            hi = mid
        }
    }
    let s = 0.5 * (lo + hi);
    let (s2, s3) = (s * s, s * s * s);
    ((2.0 * s3 - 3.0 * s2 + 1.0) * y0
        + (s3 - 2.0 * s2 + s) * l * v0
        + (-2.0 * s3 + 3.0 * s2) * y1
        + (s3 - s2) * l * v1)
        .abs()
}

/// Groups the reference's contacts into impacts per level, as the solver does: (level, start,
/// peak force).
fn impacts(contacts: &[(usize, f64, f64, f64)], merge: f64) -> Vec<(usize, f64, f64)> {
    let mut out: Vec<(usize, f64, f64, f64)> = vec![];
    let mut last: std::collections::HashMap<usize, usize> = Default::default();
    for &(p, start, end, f) in contacts {
        match last.get(&p) {
            Some(&i) if start - out[i].3 < merge => {
                out[i].2 = out[i].2.max(f);
                out[i].3 = out[i].3.max(end);
            }
            _ => {
                last.insert(p, out.len());
                out.push((p, start, f, end));
            }
        }
    }
    out.into_iter().map(|(p, s, f, _)| (p, s, f)).collect()
}

fn against_the_exact_piecewise_linear_solution(preset_name: &str) {
    against_the_exact_solution(
        preset_name,
        &linear_spring(preset_scenario(preset_name)),
        100,
    );
}

/// The scenario pounding through the linear spring of 1.5e10 N/m the exact solution takes.
fn linear_spring(sc: BuildingScenario) -> BuildingScenario {
    BuildingScenario {
        contact: ContactModel::Linear,
        stiffness: Some(1.5e10),
        ..sc
    }
}

/// mdof-3-5 with `left` and `right` storeys.
fn mdof_pair(left: usize, right: usize) -> BuildingScenario {
    let mut sc = preset_scenario("mdof-3-5");
    sc.left.storeys = left;
    sc.right.storeys = right;
    sc
}

/// The run of `sc` against the exact solution stepped `sub` times per record interval: its
/// impacts, and every floor's and storey's peak.
fn against_the_exact_solution(preset_name: &str, sc: &BuildingScenario, sub: usize) {
    let m = el_centro();
    let r = run(sc, &m);
    let exact = Reference::new(sc).solve(&m, sub);
    let want = impacts(&exact.contacts, sc.merge_gap_s);
    eprintln!(
        "{preset_name}: {} impacts here, {} exact",
        r.impacts.len(),
        want.len()
    );
    assert_eq!(r.impacts.len(), want.len(), "{preset_name}: impact count");
    let mut worst = [0.0f64; 4];
    let max_exact = want.iter().map(|w| w.2).fold(0.0, f64::max);
    for (got, (level, start, peak)) in r.impacts.iter().zip(&want) {
        assert_eq!(got.level, *level, "{preset_name}: level at {start} s");
        worst[0] = worst[0].max((got.start_s - start).abs() / start);
        // Against the run's largest force: a grazing impact's own peak (a hundredth of the
        // largest) is as sensitive as its tiny approach velocity.
        let e = (got.peak_force_n - peak).abs() / max_exact;
        if e > 1e-3 {
            eprintln!(
                "  impact at {start:.6} s, level {}: peak {:.6e} against {peak:.6e}",
                level + 1,
                got.peak_force_n
            );
        }
        worst[1] = worst[1].max(e);
    }
    let nl = sc.left.storeys;
    let side_of = |j: usize| if j < nl { (0, j) } else { (1, j - nl) };
    for (j, (p, d)) in exact.peak_floor.iter().zip(&exact.peak_drift).enumerate() {
        let (s, f) = side_of(j);
        worst[2] = worst[2].max((r.peak_floor_displacement_m[s][f] - p).abs() / p);
        worst[3] = worst[3].max((r.peak_drift_ratio[s][f] - d).abs() / d);
    }
    eprintln!(
        "{preset_name}: worst relative differences: start times {:.1e}, impact peaks {:.1e}, floor peaks {:.1e}, drift peaks {:.1e}; max force {:.6e} against {:.6e}",
        worst[0], worst[1], worst[2], worst[3], r.max_pounding_force_n, max_exact
    );
    assert!(
        (r.max_pounding_force_n - max_exact).abs() <= 1e-3 * max_exact,
        "{preset_name}: max force"
    );
    assert!(worst[0] < 1e-4, "{preset_name}: impact times {worst:?}");
    assert!(worst[1] < 1e-3, "{preset_name}: impact peaks {worst:?}");
    assert!(worst[2] < 1e-3, "{preset_name}: floor peaks {worst:?}");
    assert!(worst[3] < 1e-3, "{preset_name}: drift peaks {worst:?}");
}

#[test]
fn floor_to_floor_pounding_matches_an_exact_solution_of_the_piecewise_linear_system() {
    against_the_exact_piecewise_linear_solution("mdof-3-5");
}

#[test]
fn floor_to_column_pounding_matches_an_exact_solution_of_the_piecewise_linear_system() {
    against_the_exact_piecewise_linear_solution("mdof-unequal");
}

#[test]
fn a_tall_pair_without_contact_peaks_as_the_exact_solution_on_every_floor_and_storey() {
    // Sixteen modes a side and more: the free stretches' tall-building bounds (tables, and a
    // signal left alone where its value, rate and acceleration keep it below its peak).
    let sc = BuildingScenario {
        contact: ContactModel::None,
        ..mdof_pair(17, 20)
    };
    against_the_exact_solution("17 and 20 storeys, no contact", &sc, 100);
}

#[test]
fn a_tall_pair_pounding_peaks_as_the_exact_solution_on_every_floor_and_storey() {
    // The contact steps' proofs over sixteen modes a side and more (a rate read alone where the
    // bound on its kick fails).
    let sc = linear_spring(mdof_pair(16, 18));
    against_the_exact_solution("16 and 18 storeys, linear", &sc, 100);
}

#[test]
fn modal_damping_gives_every_mode_its_ratio_and_rayleigh_its_two() {
    // A ground pulse, then free decay: each mode's coordinate q_k = phi_k^T M u decays at its own
    // rate; the logarithmic decrement over whole periods gives its damping ratio.
    let pulse: Vec<f64> = (0..=1500)
        .map(|i| if (1..=3).contains(&i) { 3.0 } else { 0.0 })
        .collect();
    let m = GroundMotion {
        name: "pulse".into(),
        dt_s: 0.002,
        accel_m_s2: pulse,
    };
    for (damping, modes_with_zeta) in [
        (DampingModel::Modal, vec![0, 1, 2, 3]),
        (DampingModel::Rayleigh { modes: [1, 3] }, vec![0, 2]),
    ] {
        let mut sc = preset_scenario("mdof-3-5");
        sc.contact = ContactModel::None;
        sc.right.storeys = 4;
        sc.right.masses_kg = vec![4e4, 5e4, 6e4, 3e4];
        sc.right.stiffnesses_n_m = vec![1.4e8, 1.2e8, 1.0e8, 0.8e8];
        sc.right.damping = damping;
        sc.max_step_s = 2e-4;
        let r = run(&sc, &m);
        let b = &sc.right;
        let modes: Modes = b.modes();
        let masses = b.masses();
        for (k, zeta_k) in modes.damping.iter().enumerate() {
            let q: Vec<f64> = (0..r.time_s.len())
                .map(|i| {
                    (0..b.storeys)
                        .map(|f| modes.shapes[k][f] * masses[f] * r.floor_displacement_m[1][f][i])
                        .sum()
                })
                .collect();
            // Positive peaks after the pulse, located by parabolas on the samples.
            let mut peaks = vec![];
            for i in 1..q.len() - 1 {
                if r.time_s[i] > 0.05 && q[i] > q[i - 1] && q[i] >= q[i + 1] && q[i] > 0.0 {
                    let (a, b2, c) = (q[i - 1], q[i], q[i + 1]);
                    let x = 0.5 * (a - c) / (a - 2.0 * b2 + c);
                    peaks.push((r.time_s[i], b2 - 0.25 * (a - c) * x));
                }
            }
            let w = modes.omega_rad_s[k];
            let td = 2.0 * std::f64::consts::PI / (w * (1.0 - zeta_k * zeta_k).sqrt());
            // Between two peaks n periods apart, well above round-off.
            let (t0, p0) = peaks[0];
            let (t1, p1) = *peaks
                .iter()
                .rev()
                .find(|(t, p)| *p > 1e-6 * p0 && t - t0 > 5.0 * td)
                .expect("enough cycles");
            let n = ((t1 - t0) / td).round();
            let delta = (p0 / p1).ln() / n;
            let measured = delta / (4.0 * std::f64::consts::PI.powi(2) + delta * delta).sqrt();
            eprintln!(
                "{damping:?}: mode {} zeta {measured:.5} (model {zeta_k:.5})",
                k + 1
            );
            assert!(
                (measured - zeta_k).abs() < 0.01 * zeta_k,
                "{damping:?} mode {}: {measured} against {zeta_k}",
                k + 1
            );
            if modes_with_zeta.contains(&k) {
                assert!((zeta_k - 0.05).abs() < 1e-12, "{damping:?} mode {}", k + 1);
            }
        }
    }
}

#[test]
fn a_floor_striking_a_column_loads_the_two_floors_by_the_interpolation_weights() {
    // From each column floor's own motion: its share of a contact's impulse is what the storeys,
    // the damping and the ground do not account for, m dv - integral of the other forces (the
    // trapezoid rule, as Newmark's velocity update integrates).
    let m = el_centro();
    let mut sc = preset_scenario("mdof-unequal");
    sc.contact = ContactModel::Linear;
    // Newmark's update is reproduced step by step: every step must be in the histories.
    sc.recording = Recording::Steps;
    let r = run(&sc, &m);
    let modes = [sc.left.modes(), sc.right.modes()];
    let buildings = [&sc.left, &sc.right];
    let damping: Vec<Mat> = (0..2)
        .map(|s| {
            let b = buildings[s];
            let mass = b.masses();
            let n = b.storeys;
            let md = &modes[s];
            let mut c = zeros(n, n);
            for k in 0..n {
                let cw = 2.0 * md.damping[k] * md.omega_rad_s[k];
                for i in 0..n {
                    for j in 0..n {
                        c[i][j] += mass[i] * md.shapes[k][i] * cw * md.shapes[k][j] * mass[j];
                    }
                }
            }
            c
        })
        .collect();
    let mut checked = 0;
    for c in r.contacts.iter().filter(|c| c.impulse_ns > 1e3) {
        let level = &r.levels[c.level];
        let i0 = r
            .time_s
            .partition_point(|&t| t < c.start_s)
            .saturating_sub(1);
        let i0 = if r.force_n[i0 + 1] == 0.0 { i0 + 1 } else { i0 };
        let i1 = r.time_s.partition_point(|&t| t < c.end_s);
        // Only a contact alone in its time: another level's would load the same floors.
        let alone = (0..r.levels.len())
            .filter(|&l| l != c.level)
            .all(|l| r.level_force_n[l][i0..=i1].iter().all(|f| *f == 0.0));
        if !alone {
            continue;
        }
        for (s, attach) in [(0, &level.left), (1, &level.right)] {
            let Attachment::Column {
                below,
                above,
                s: frac,
            } = *attach
            else {
                continue;
            };
            let b = buildings[s];
            let (mass, ks) = (b.masses(), b.stiffnesses());
            let force_on = |f: usize, j: usize| {
                let u = |g: usize| r.floor_displacement_m[s][g][j];
                let storey = ks[f] * (u(f) - if f > 0 { u(f - 1) } else { 0.0 })
                    - if f + 1 < b.storeys {
                        ks[f + 1] * (u(f + 1) - u(f))
                    } else {
                        0.0
                    };
                let damper: f64 = (0..b.storeys)
                    .map(|g| damping[s][f][g] * r.floor_velocity_m_s[s][g][j])
                    .sum();
                -mass[f] * r.ground_m_s2[j] - storey - damper
            };
            let share = |f: usize| {
                let mut other = 0.0;
                for j in i0..i1 {
                    other += 0.5
                        * (r.time_s[j + 1] - r.time_s[j])
                        * (force_on(f, j) + force_on(f, j + 1));
                }
                let dp =
                    mass[f] * (r.floor_velocity_m_s[s][f][i1] - r.floor_velocity_m_s[s][f][i0]);
                // The column is on the side the floor pushes away from the striking building.
                (dp - other).abs()
            };
            let upper = share(above);
            assert!(
                (upper - frac * c.impulse_ns).abs() < 1e-6 * c.impulse_ns,
                "level {}: floor {} takes {upper} of {} (s = {frac})",
                c.level + 1,
                above + 1,
                c.impulse_ns
            );
            if let Some(below) = below {
                let lower = share(below);
                assert!(
                    (lower - (1.0 - frac) * c.impulse_ns).abs() < 1e-6 * c.impulse_ns,
                    "level {}: floor {} takes {lower} of {}",
                    c.level + 1,
                    below + 1,
                    c.impulse_ns
                );
            }
            checked += 1;
        }
    }
    assert!(checked >= 4, "{checked} column sides checked");
}

#[test]
fn multistorey_runs_balance_their_energy_for_every_element() {
    let m = el_centro();
    for preset_name in ["mdof-3-5", "mdof-unequal"] {
        for model in ContactModel::ALL {
            let mut sc = preset_scenario(preset_name);
            sc.contact = model;
            let r = run(&sc, &m);
            assert!(
                r.energy.balance_error().abs() < 1e-8,
                "{preset_name} {}: {}",
                model.name(),
                r.energy.balance_error()
            );
            assert_eq!(
                r.impacts.is_empty(),
                model == ContactModel::None,
                "{preset_name} {}",
                model.name()
            );
        }
    }
}

#[test]
fn the_gap_reported_avoids_all_contact_and_one_percent_less_does_not() {
    for preset_name in ["paper-buildings", "mdof-3-5", "mdof-unequal"] {
        let out = common::pounding(&["gaps", "--preset", preset_name, "--json", "--quiet"]);
        assert!(out.status.success(), "{}", common::stderr(&out));
        let v: serde_json::Value = serde_json::from_str(&common::stdout(&out)).unwrap();
        let gap = v["records"][0]["min_gap_m"].as_f64().unwrap();
        assert!(gap > 0.0);
        let m = el_centro();
        for model in [ContactModel::Linear, ContactModel::Sears] {
            let mut sc = preset_scenario(preset_name);
            sc.contact = model;
            sc.gap_m = gap;
            assert_eq!(
                run(&sc, &m).contacts.len(),
                0,
                "{preset_name} {} at {gap} m",
                model.name()
            );
            sc.gap_m = 0.99 * gap;
            assert!(
                !run(&sc, &m).contacts.is_empty(),
                "{preset_name} {} at 0.99 x {gap} m",
                model.name()
            );
        }
    }
}
