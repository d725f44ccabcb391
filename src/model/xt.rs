//! The space-time (x-t) diagram of an impact: each bar's stress and particle velocity over its
//! length and over time. A front is a line of slope 1/c in it, a free end's reflection turns it
//! back, and its return to the contact ends a wave-theory impact.
//!
//! Positions are measured in each bar from its contact face (0) to its free end (L); stress is
//! positive in tension; velocity is in the lab frame, positive to the right (bar 1 is the left
//! bar). The d'Alembert models give the field from their wave histories; the lumped models
//! (rigid bodies) give their uniform-stress equivalent: F(t) / A across each bar and the rigid
//! velocity.

use super::field::BarWaves;
use super::impact::ImpactResult;

/// Which field a diagram shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum XtField {
    /// Axial stress [Pa], tension positive.
    Stress,
    /// Particle velocity [m/s], positive to the right.
    Velocity,
}

impl XtField {
    /// The name the command line uses.
    pub fn name(self) -> &'static str {
        match self {
            XtField::Stress => "stress",
            XtField::Velocity => "velocity",
        }
    }

    /// The field of that name.
    pub fn from_name(s: &str) -> Option<Self> {
        [XtField::Stress, XtField::Velocity]
            .into_iter()
            .find(|f| f.name() == s)
    }
}

/// One bar's field on the grid.
#[derive(Debug, Clone, PartialEq)]
pub struct XtBar {
    /// Grid positions from the contact face to the free end [m].
    pub x_m: Vec<f64>,
    /// Stress at (time k, position i), index `k * x_m.len() + i` [Pa].
    pub stress_pa: Vec<f64>,
    /// Velocity at the same points [m/s].
    pub velocity_m_s: Vec<f64>,
}

impl XtBar {
    /// The chosen field at (time k, position i).
    pub fn at(&self, field: XtField, k: usize, i: usize) -> f64 {
        let n = k * self.x_m.len() + i;
        match field {
            XtField::Stress => self.stress_pa[n],
            XtField::Velocity => self.velocity_m_s[n],
        }
    }
}

/// Both bars' fields at the same times.
#[derive(Debug, Clone, PartialEq)]
pub struct XtGrid {
    /// Grid times, from the start to the end of the span [s].
    pub times_s: Vec<f64>,
    /// Bar 1 (left) and bar 2 (right).
    pub bars: [XtBar; 2],
    /// Whether the field is the lumped models' uniform-stress equivalent.
    pub uniform: bool,
}

impl XtGrid {
    /// `nx` evenly spaced positions along each bar (ends included) and `nt` times over
    /// [t_start, t_end], from the bars' wave histories.
    pub fn from_waves(
        waves: &[BarWaves; 2],
        nx: usize,
        nt: usize,
        t_start: f64,
        t_end: f64,
    ) -> Self {
        let times_s = spaced(t_start, t_end, nt);
        Self::sampled(
            times_s,
            waves.each_ref().map(|w| w.length_m()),
            nx,
            false,
            |b, x, t| (waves[b].stress_pa(x, t), waves[b].velocity_m_s(x, t)),
        )
    }

    /// The uniform-stress equivalent of a result without waves: -F(t) / A_i across bar i, and
    /// each bar's rigid velocity, v1 - J(t) / m1 and v2 + J(t) / m2.
    pub fn uniform(
        r: &ImpactResult,
        areas_m2: [f64; 2],
        lengths_m: [f64; 2],
        nx: usize,
        nt: usize,
        t_end: f64,
    ) -> Self {
        let times_s = spaced(0.0, t_end, nt);
        Self::sampled(times_s, lengths_m, nx, true, |b, _, t| {
            let f = interpolate(&r.time_s, &r.force_n, t);
            (-f / areas_m2[b], r.rigid_velocities_at(t)[b])
        })
    }

    /// The grid of `nx` positions along each bar (ends included) at `times_s`, each point's
    /// (stress, velocity) from `at(bar, x, t)`.
    fn sampled(
        times_s: Vec<f64>,
        lengths_m: [f64; 2],
        nx: usize,
        uniform: bool,
        at: impl Fn(usize, f64, f64) -> (f64, f64),
    ) -> Self {
        let nt = times_s.len();
        let bars = std::array::from_fn(|b| {
            let x_m = spaced(0.0, lengths_m[b], nx);
            let mut stress_pa = Vec::with_capacity(nx * nt);
            let mut velocity_m_s = Vec::with_capacity(nx * nt);
            for &t in &times_s {
                for &x in &x_m {
                    let (s, v) = at(b, x, t);
                    stress_pa.push(s);
                    velocity_m_s.push(v);
                }
            }
            XtBar {
                x_m,
                stress_pa,
                velocity_m_s,
            }
        });
        XtGrid {
            times_s,
            bars,
            uniform,
        }
    }

    /// The diagram of a result over [0, t_end]: from its waves, or its uniform-stress
    /// equivalent. `areas_m2` and `lengths_m` are the bars' (only the equivalent reads them).
    pub fn of(
        r: &ImpactResult,
        areas_m2: [f64; 2],
        lengths_m: [f64; 2],
        nx: usize,
        nt: usize,
        t_end: f64,
    ) -> Self {
        match &r.waves {
            Some(w) => Self::from_waves(w, nx, nt, 0.0, t_end),
            None => Self::uniform(r, areas_m2, lengths_m, nx, nt, t_end),
        }
    }

    /// The largest |value| of a field over both bars (the colour bar's end).
    pub fn max_abs(&self, field: XtField) -> f64 {
        self.bars
            .iter()
            .flat_map(|b| match field {
                XtField::Stress => b.stress_pa.iter(),
                XtField::Velocity => b.velocity_m_s.iter(),
            })
            .fold(0.0, |m: f64, v| m.max(v.abs()))
    }
}

/// `n` evenly spaced values from a to b, both included (a alone for n = 1).
fn spaced(a: f64, b: f64, n: usize) -> Vec<f64> {
    if n <= 1 {
        return vec![a];
    }
    (0..n)
        .map(|k| a + (b - a) * k as f64 / (n - 1) as f64)
        .collect()
}

/// Linear interpolation in (t, y), the last value held after the end; at a repeated time (a
/// jump) the later sample.
pub(crate) fn interpolate(t: &[f64], y: &[f64], at: f64) -> f64 {
    if t.is_empty() {
        return 0.0;
    }
    let k = t.partition_point(|&x| x <= at);
    if k == 0 {
        return y[0];
    }
    if k >= t.len() {
        return y[t.len() - 1];
    }
    let (t0, t1) = (t[k - 1], t[k]);
    if t1 <= t0 {
        return y[k - 1];
    }
    y[k - 1] + (y[k] - y[k - 1]) * (at - t0) / (t1 - t0)
}
