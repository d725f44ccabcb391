//! Storeys that yield, in the pseudo-force form: a storey's shear force is F = k u - c, where
//! k u is the elastic spring the modes already carry and c = k u - F(history) is the correction
//! the storey's law makes of it (zero while it is elastic from rest, (1 - b) k u_p for the
//! bilinear law, (1 - b) k (u - z) for Bouc-Wen). The correction acts on the floors above and
//! below the storey as a load, +c and -c, so the modes stay those of the elastic building, their
//! damping stays the one set on the initial stiffness, and every stage of the stepper takes the
//! corrections as one more load on the modes.
//!
//! Over a step the correction is taken linear in time between its values at both ends, and the
//! value at the end comes from the storey's law along the straight drift path of the step: a
//! fixed point, since the end drift depends on the correction. Over a fine step the map is a
//! strong contraction (its factor is about (w h)^2 / 6), so it settles in two or three passes.

use super::bound::{Envelope, envelope};
use super::*;
use crate::model::hysteresis::{Hysteresis, StoreyLaw, StoreyState};

/// The most passes of the fixed point over one step.
pub(super) const MAX_PASSES: usize = 60;

/// A building's storey springs and what they remember.
#[derive(Debug, Clone)]
pub(super) struct Storeys {
    laws: Vec<StoreyLaw>,
    /// Each storey's state where the current time stands.
    pub state: Vec<StoreyState>,
    /// `drift[j][k]`: storey j's drift per unit of mode k.
    drift: Vec<Vec<f64>>,
    /// The corrections now [N], and their load on each mode.
    c0: Vec<f64>,
    pub load0: Vec<f64>,
    /// The planned free step: each mode's load at its end, and its length.
    pub load1: Vec<f64>,
    pub len: f64,
    /// When each storey's drift first reached its yield drift F_y / k [s].
    pub first_yield_s: Vec<Option<f64>>,
}

impl Storeys {
    /// The storeys of a building with the given laws, on modes with `shapes[k][floor]`.
    pub fn new(laws: Vec<StoreyLaw>, shapes: &[Vec<f64>]) -> Self {
        let n = laws.len();
        let drift: Vec<Vec<f64>> = (0..n)
            .map(|j| {
                shapes
                    .iter()
                    .map(|shape| shape[j] - if j > 0 { shape[j - 1] } else { 0.0 })
                    .collect()
            })
            .collect();
        let modes = shapes.len();
        Storeys {
            laws,
            state: vec![StoreyState::default(); n],
            drift,
            c0: vec![0.0; n],
            load0: vec![0.0; modes],
            load1: vec![0.0; modes],
            len: 0.0,
            first_yield_s: vec![None; n],
        }
    }

    /// Storey j's drift with the modes at q [m].
    pub fn drift_of(&self, j: usize, q: &[f64]) -> f64 {
        dotv(&self.drift[j], q)
    }

    /// Storey j's drift with the modes at q + dq [m].
    fn drift_after(&self, j: usize, q: &[f64], dq: &[f64]) -> f64 {
        self.drift[j]
            .iter()
            .zip(q.iter().zip(dq))
            .map(|(d, (q, dq))| d * (q + dq))
            .sum()
    }

    /// Mode k's load over the planned free step: its value now and its rate.
    pub fn pseudo(&self, k: usize) -> (f64, f64) {
        let rate = if self.len > 0.0 {
            (self.load1[k] - self.load0[k]) / self.len
        } else {
            0.0
        };
        (self.load0[k], rate)
    }

    /// The correction c = k u - F of a storey in state `s` [N].
    fn correction(law: &StoreyLaw, s: &StoreyState) -> f64 {
        law.stiffness_n_m * s.drift_m - law.force_n(s)
    }

    /// Each mode's load from corrections `c` on storeys of drift rows `drift`, into `out`.
    fn loads(drift: &[Vec<f64>], c: &[f64], out: &mut Vec<f64>) {
        out.clear();
        out.resize(drift.first().map_or(0, Vec::len), 0.0);
        for (cj, dj) in c.iter().zip(drift) {
            if *cj != 0.0 {
                for (o, d) in out.iter_mut().zip(dj) {
                    *o += cj * d;
                }
            }
        }
    }

    /// The loads at the end of a step that brings storey j to the drift `drift(j)` (each storey
    /// along the straight path of its drift), into `out`; the largest change of a load from what
    /// `out` held, relative to the largest load before or after.
    fn end_loads(&self, drift: impl Fn(usize) -> f64, out: &mut [f64]) -> f64 {
        let mut c1 = Vec::with_capacity(self.laws.len());
        let mut scale = 0.0f64;
        for (j, law) in self.laws.iter().enumerate() {
            let u = drift(j);
            if !u.is_finite() {
                // No end state to follow (a trial that failed): the loads stay as they were.
                return 0.0;
            }
            let mut s = self.state[j];
            law.advance(&mut s, u);
            let c = Self::correction(law, &s);
            scale = scale.max(c.abs()).max(self.c0[j].abs());
            c1.push(c);
        }
        // Mode by mode, in the storeys' order (as `loads` sums), comparing as it writes.
        let (mut change, mut load_scale) = (0.0f64, 0.0f64);
        for (k, o) in out.iter_mut().enumerate() {
            let mut load = 0.0;
            for (cj, dj) in c1.iter().zip(&self.drift) {
                if *cj != 0.0 {
                    load += cj * dj[k];
                }
            }
            change = change.max((load - *o).abs());
            load_scale = load_scale.max(load.abs()).max(o.abs());
            *o = load;
        }
        if scale == 0.0 || load_scale == 0.0 {
            0.0
        } else {
            change / load_scale
        }
    }

    /// Storey j's shear force now [N].
    pub fn shear_n(&self, j: usize) -> f64 {
        self.laws[j].force_n(&self.state[j])
    }

    /// Moves every storey to the drifts of the modes at q, along the straight path from where
    /// they stand, over the step from `t0` to `t1`.
    pub fn commit(&mut self, q: &[f64], t0: f64, t1: f64) {
        for j in 0..self.laws.len() {
            let u = self.drift_of(j, q);
            let before = self.state[j].drift_m;
            let uy = self.laws[j].yield_drift_m();
            if self.first_yield_s[j].is_none() && u.abs() >= uy {
                // Within the step, where the straight drift path reaches the yield drift.
                let target = uy.copysign(u);
                let share = if u != before {
                    ((target - before) / (u - before)).clamp(0.0, 1.0)
                } else {
                    1.0
                };
                self.first_yield_s[j] = Some(t0 + share * (t1 - t0));
            }
            self.laws[j].advance(&mut self.state[j], u);
            self.c0[j] = Self::correction(&self.laws[j], &self.state[j]);
        }
        Self::loads(&self.drift, &self.c0, &mut self.load0);
    }

    /// Whether every storey provably stays inside its elastic range over a stretch of length
    /// `span` whose modes have the envelopes `env`: its drift is the line of the particular
    /// responses plus at most the free vibrations' reach. Only the bilinear law has a range.
    pub fn stays_elastic(&self, env: &[Option<Envelope>], span: f64) -> bool {
        if self.laws.first().map(|l| l.kind) != Some(Hysteresis::Bilinear) {
            return false;
        }
        for (j, law) in self.laws.iter().enumerate() {
            let (mut p0, mut p1, mut reach) = (0.0, 0.0, 0.0);
            for (d, e) in self.drift[j].iter().zip(env) {
                let Some(e) = e else { return false };
                p0 += d * e.alpha;
                p1 += d * (e.alpha + e.beta * span);
                reach += d.abs() * e.free;
            }
            let Some((lo, hi)) = law.elastic_range_m(&self.state[j]) else {
                return false;
            };
            // A hair inside the range: the bound's own round-off must not let a yield through.
            let margin = 1e-9 * (hi - lo);
            if p0.min(p1) - reach <= lo + margin || p0.max(p1) + reach >= hi - margin {
                return false;
            }
        }
        true
    }

    /// The energy the storeys have dissipated [J].
    pub fn dissipated_j(&self) -> f64 {
        self.state.iter().map(|s| s.dissipated_j).sum()
    }

    /// What the storeys store by their laws less what the modes count for them (1/2 k u^2) [J]:
    /// added to the modes' energy, the buildings' true energy.
    pub fn stored_less_elastic_j(&self) -> f64 {
        self.laws
            .iter()
            .zip(&self.state)
            .map(|(l, s)| l.stored_energy_j(s) - 0.5 * l.stiffness_n_m * s.drift_m * s.drift_m)
            .sum()
    }
}

/// What the storeys did over a run, per side and storey (lowest first).
#[derive(Debug, Clone, Default)]
pub(in crate::model::building) struct StoreySummary {
    pub ductility_demand: [Vec<f64>; 2],
    pub residual_drift_m: [Vec<f64>; 2],
    pub hysteretic_energy_j: [Vec<f64>; 2],
    pub first_yield_s: [Vec<Option<f64>>; 2],
    pub yield_drift_m: [Vec<f64>; 2],
}

impl Stepper<'_> {
    /// Whether any storey yields (the run takes its corrections as loads).
    pub(super) fn yields(&self) -> bool {
        self.sides.iter().any(|s| s.storeys.is_some())
    }

    /// Plans the next free step from a grid point: where every yielding storey provably stays
    /// elastic over the whole stretch to the next free-step boundary, its corrections are
    /// constant and the stretch is taken whole, as an elastic run's; otherwise one fine step,
    /// with the corrections planned by the fixed point. Whether the stretch is whole.
    pub(super) fn plan_stretch(&mut self) -> bool {
        let g = self.grid;
        let len = (g.per_free_step - self.n % g.per_free_step).min(g.total - self.n);
        let span = len as f64 * g.h;
        let t0 = self.time();
        for s in 0..2 {
            if let Some(st) = self.sides[s].storeys.as_mut() {
                st.load1.clone_from(&st.load0);
                st.len = 0.0;
            }
        }
        let whole = (0..2).all(|s| {
            let Some(st) = self.sides[s].storeys.as_ref() else {
                return true;
            };
            let side = &self.sides[s];
            let y0 = self.initial(s, t0);
            let env: Vec<Option<Envelope>> = (0..side.modes())
                .map(|k| envelope(side.omega[k], side.zeta[k], &y0[k]))
                .collect();
            st.stays_elastic(&env, span)
        });
        if !whole {
            self.plan_free(g.h);
        }
        whole
    }

    /// Plans a free step of length `len` from now: each side's corrections at its end, by the
    /// fixed point over the exact step with the corrections linear in time.
    pub(super) fn plan_free(&mut self, len: f64) {
        let grid_step = (len - self.grid.h).abs() <= 1e-12 * len;
        let t0 = self.time();
        let mut y0 = Vec::new();
        for s in 0..2 {
            let Some(st) = self.sides[s].storeys.as_mut() else {
                continue;
            };
            st.load1.clone_from(&st.load0);
            st.len = len;
            let side = &self.sides[s];
            let props: Option<Vec<Propagator>> = (!grid_step).then(|| {
                (0..side.modes())
                    .map(|k| propagator(side.omega[k], side.zeta[k], len))
                    .collect()
            });
            let mut q1 = vec![0.0; side.modes()];
            for _ in 0..MAX_PASSES {
                self.initial_into(s, t0, &mut y0);
                let side = &self.sides[s];
                let props = props.as_deref().unwrap_or(&side.sub[0]);
                for (k, p) in props.iter().enumerate() {
                    q1[k] = p.apply(&y0[k]).0;
                }
                let st = self.sides[s].storeys.as_mut().expect("checked");
                let mut load1 = std::mem::take(&mut st.load1);
                let change = st.end_loads(|j| st.drift_of(j, &q1), &mut load1);
                st.load1 = load1;
                if change <= 1e-13 {
                    break;
                }
            }
        }
    }

    /// Every side's storeys moved to where the modes stand at the end of the step just
    /// committed, from `t0` to `t1`.
    pub(super) fn commit_storeys(&mut self, t0: f64, t1: f64) {
        for side in self.sides.iter_mut() {
            if let Some(st) = side.storeys.as_mut() {
                st.commit(&side.q, t0, t1);
                st.len = 0.0;
            }
        }
    }

    /// Inside a contact step: each side's corrections at the trial's end (its modes moved by
    /// `dq`) into `load1`; the largest relative change.
    pub(super) fn contact_end_loads(&self, dq: &[Vec<f64>; 2], load1: &mut [Vec<f64>; 2]) -> f64 {
        let mut worst = 0.0f64;
        for s in 0..2 {
            let side = &self.sides[s];
            if let Some(st) = side.storeys.as_ref() {
                let drift = |j| st.drift_after(j, &side.q, &dq[s]);
                worst = worst.max(st.end_loads(drift, &mut load1[s]));
            }
        }
        worst
    }

    /// Every storey's ductility demand, drift now and dissipated energy, per side, from the
    /// peak drift ratios of the run so far.
    pub fn storey_summary(
        &self,
        buildings: [&crate::model::building::Building; 2],
        peak_drift_ratio: &[Vec<f64>; 2],
    ) -> StoreySummary {
        let mut out = StoreySummary::default();
        for (s, b) in buildings.into_iter().enumerate() {
            let side = &self.sides[s];
            for j in 0..b.storeys {
                let yield_drift = b.yield_force(j) / b.stiffness(j);
                let peak = peak_drift_ratio[s].get(j).copied().unwrap_or(0.0) * b.height(j);
                out.ductility_demand[s].push(peak / yield_drift);
                out.yield_drift_m[s].push(yield_drift);
                out.first_yield_s[s].push(
                    side.storeys
                        .as_ref()
                        .and_then(|st| st.first_yield_s.get(j).copied().flatten()),
                );
                let (drift, dissipated) = match &side.storeys {
                    Some(st) => (st.drift_of(j, &side.q), st.state[j].dissipated_j),
                    None => {
                        let below = if j > 0 {
                            side.floor(&side.q, j - 1)
                        } else {
                            0.0
                        };
                        (side.floor(&side.q, j) - below, 0.0)
                    }
                };
                out.residual_drift_m[s].push(drift);
                out.hysteretic_energy_j[s].push(dissipated);
            }
        }
        out
    }
}
