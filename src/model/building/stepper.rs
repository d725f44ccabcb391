//! The pounding run as named stages over both buildings' modes and every contact point:
//!
//! - **free step**: between contacts each mode is propagated exactly to the next sample of the
//!   record (the ground acceleration is linear between samples), and the motion is checked at
//!   every point of a fine grid for an onset at any level;
//! - **onset location**: the touching instant inside its fine step, on the cubic through the
//!   exact states at both ends (exact to round-off at these steps), or, for the Sears slabs, whose
//!   waves live on the grid, the grid point before it;
//! - **contact step**: Newmark's average acceleration on the modes with the contact forces
//!   implicit (stable for any stiffness), one coupled set of monotone equations for the levels in
//!   contact, solved by nonlinear Gauss-Seidel;
//! - **impact bookkeeping**: contacts opened and closed per level, their impulse and peak.
//!
//! Every stage writes to one energy [`Ledger`]: the free steps with the exact integrals of the
//! modal power, the contact steps with Newmark's discrete energy identity, so the ledger balances
//! to round-off and what it reports (work of the ground, damping, energy taken by the contact)
//! is exact for the discrete solution.

use super::elements::Element;
use super::levels::Level;
use super::modal::{Modes, Propagator, StepIntegrals, propagator, step_integrals};
use super::result::{BuildingEnergy, RawContact};
use super::slab::{SlabMark, SlabWaves};
use super::{BuildingScenario, ContactModel, SlabReading};
use crate::model::control::{CHECK_EVERY, Control};
use crate::model::impact::SolveError;
use crate::model::motion::GroundMotion;
use crate::model::root::bracket;

/// The time grid. The fine step h divides the record's step, so every sample of the record is a
/// grid point and the ground acceleration is linear over every free step.
#[derive(Debug, Clone, Copy)]
pub(super) struct Grid {
    pub h: f64,
    /// Fine steps per free step at most (a free step divides the record's step).
    pub per_free_step: usize,
    /// Fine steps over the record.
    pub total: usize,
}

/// One building in modal coordinates, with its precomputed exact steps.
struct Side {
    omega: Vec<f64>,
    zeta: Vec<f64>,
    gamma: Vec<f64>,
    /// `shapes[k][f]`: mode k at floor f.
    shapes: Vec<Vec<f64>>,
    heights: Vec<f64>,
    q: Vec<f64>,
    v: Vec<f64>,
    /// Modal accelerations, kept inside contacts (Newmark).
    a: Vec<f64>,
    /// `sub[j][k]`: mode k's exact step over (j + 1) h.
    sub: Vec<Vec<Propagator>>,
    /// Integrals over a whole free step, per mode.
    full: Vec<StepIntegrals>,
    /// Integrals over j fine steps, per mode, computed when first needed.
    part: Vec<Option<Vec<StepIntegrals>>>,
    /// Newmark's effective stiffness over h, per mode.
    k_hat: Vec<f64>,
}

impl Side {
    fn new(modes: &Modes, heights: Vec<f64>, v0: f64, grid: &Grid) -> Self {
        let n = modes.count();
        let h = grid.h;
        let first: Vec<[[f64; 4]; 4]> = (0..n)
            .map(|k| full_map(modes.omega_rad_s[k], modes.damping[k], h))
            .collect();
        // E((j + 1) h) = E(j h) E(h): one product per point instead of an exponential.
        let mut sub = Vec::with_capacity(grid.per_free_step);
        let mut current = first.clone();
        for j in 0..grid.per_free_step {
            if j > 0 {
                for k in 0..n {
                    current[k] = mul4(&current[k], &first[k]);
                }
            }
            sub.push(
                current
                    .iter()
                    .map(|e| Propagator { q: e[0], v: e[1] })
                    .collect(),
            );
        }
        let free_len = grid.per_free_step as f64 * h;
        Side {
            full: (0..n)
                .map(|k| step_integrals(modes.omega_rad_s[k], modes.damping[k], free_len))
                .collect(),
            k_hat: (0..n)
                .map(|k| newmark_k_hat(modes.omega_rad_s[k], modes.damping[k], h))
                .collect(),
            part: vec![None; grid.per_free_step + 1],
            omega: modes.omega_rad_s.clone(),
            zeta: modes.damping.clone(),
            gamma: modes.participation.clone(),
            shapes: modes.shapes.clone(),
            heights,
            q: vec![0.0; n],
            v: modes.participation.iter().map(|g| g * v0).collect(),
            a: vec![0.0; n],
            sub,
        }
    }

    fn modes(&self) -> usize {
        self.omega.len()
    }

    fn energy(&self) -> f64 {
        (0..self.modes())
            .map(|k| 0.5 * (self.v[k].powi(2) + (self.omega[k] * self.q[k]).powi(2)))
            .sum()
    }

    /// Floor f's displacement from modal coordinates `q`.
    fn floor(&self, q: &[f64], f: usize) -> f64 {
        (0..q.len()).map(|k| self.shapes[k][f] * q[k]).sum()
    }
}

/// The exact step's full 4 x 4 map in y = [q, q', g, g'].
fn full_map(omega: f64, zeta: f64, h: f64) -> [[f64; 4]; 4] {
    let p = propagator(omega, zeta, h);
    // g(s) = g + g' s, g' constant.
    [p.q, p.v, [0.0, 0.0, 1.0, h], [0.0, 0.0, 0.0, 1.0]]
}

fn mul4(a: &[[f64; 4]; 4], b: &[[f64; 4]; 4]) -> [[f64; 4]; 4] {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..4).map(|k| a[i][k] * b[k][j]).sum()))
}

fn newmark_k_hat(omega: f64, zeta: f64, h: f64) -> f64 {
    omega * omega + 4.0 * zeta * omega / h + 4.0 / (h * h)
}

/// The energy ledger every stage writes to.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Ledger {
    pub initial_j: f64,
    pub input_j: f64,
    pub damping_j: f64,
    /// Work of the contact forces on the buildings (negative: energy taken from them).
    pub contact_work_j: f64,
    /// Energy the stereomechanical exchanges took.
    pub exchanged_j: f64,
}

/// A contact point: its element, projections onto the modes, slabs and state.
struct Point {
    element: Element,
    /// `r[side][k]`: the point's displacement per unit of mode k.
    r: [Vec<f64>; 2],
    slabs: [Option<SlabWaves>; 2],
    force: f64,
    delta: f64,
    rate: f64,
    v0: f64,
    /// The open contact (an index into the contact list).
    open: Option<usize>,
    /// The grid step of the last stereomechanical exchange here: a sequence of exchanges that
    /// accumulates at an instant (floors pressed together, each rebound shorter by e) is cut at
    /// one exchange per level per step.
    exchanged_in: Option<usize>,
    max_closing: f64,
    max_force: f64,
}

impl Point {
    fn elastic(&self) -> f64 {
        self.slabs.iter().flatten().map(|s| s.elastic_m()).sum()
    }

    /// e0 + e1 F: the slabs' elastic displacement after one more step.
    fn predict_elastic(&self) -> (f64, f64) {
        self.slabs
            .iter()
            .flatten()
            .map(|s| s.predict())
            .fold((0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1))
    }
}

fn dotv(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Peaks of each floor and each storey's drift ratio per side, and each point's per side.
pub(super) type PeakSummary = ([Vec<f64>; 2], [Vec<f64>; 2], Vec<[f64; 2]>);

/// The largest |value| of signals known with their rates at a sequence of instants: between
/// two instants a signal is the cubic through both values and rates, and its extremum there is
/// found, so a peak is not missed by the spacing of the instants (the error is that of the cubic,
/// (w h)^4 / 384 of the amplitude, against (w h)^2 / 8 for sampling).
#[derive(Default)]
struct Peaks {
    last_t: f64,
    last: Vec<(f64, f64)>,
    peak: Vec<f64>,
    started: bool,
}

impl Peaks {
    fn update(&mut self, t: f64, now: &[(f64, f64)]) {
        if !self.started {
            self.started = true;
            self.last = now.to_vec();
            self.peak = now.iter().map(|(u, _)| u.abs()).collect();
            self.last_t = t;
            return;
        }
        let l = t - self.last_t;
        for (i, &(u, v)) in now.iter().enumerate() {
            let mut p = self.peak[i].max(u.abs());
            let (u0, v0) = self.last[i];
            if l > 0.0 && (v0 > 0.0) != (v > 0.0) {
                let inside = if v0 > 0.0 {
                    hermite_max(u0, v0, u, v, l)
                } else {
                    -hermite_max(-u0, -v0, -u, -v, l)
                };
                if inside.is_finite() {
                    p = p.max(inside.abs());
                }
            }
            self.peak[i] = p;
            self.last[i] = (u, v);
        }
        self.last_t = t;
    }
}

/// The first fine step after an onset is split into steps of 1/2^G, 1/2^G, 1/2^(G-1), ... 1/2 of
/// it.
const ONSET_GRADING: u32 = 8;

/// Memory the recorded histories may take [bytes].
pub const SAMPLE_MEMORY_BUDGET: f64 = 2.0e9;

/// One sample of the histories.
pub(super) struct Sample {
    pub t: f64,
    pub ground: f64,
    /// Floors of each side, and their velocities.
    pub floors: [Vec<f64>; 2],
    pub floor_v: [Vec<f64>; 2],
    pub roof_v: [f64; 2],
    /// Roof acceleration relative to the ground.
    pub roof_a: [f64; 2],
    pub forces: Vec<f64>,
}

/// The run in progress.
pub(super) struct Stepper<'a> {
    sc: &'a BuildingScenario,
    motion: &'a GroundMotion,
    pub grid: Grid,
    sides: [Side; 2],
    points: Vec<Point>,
    /// Grid index of the current time, and how far past it the time is (after an event located
    /// inside a step).
    n: usize,
    offset: f64,
    pub ledger: Ledger,
    pub contacts: Vec<RawContact>,
    pub samples: Vec<Sample>,
    peaks: Peaks,
    pub steps: usize,
    pub contact_steps: usize,
    sears: bool,
    /// The modal accelerations are Newmark's (the last step was a contact step).
    newmark: bool,
    scratch: Scratch,
}

/// Buffers the free stretch reuses, so its grid points allocate nothing.
#[derive(Default)]
struct Scratch {
    q: [Vec<f64>; 2],
    v: [Vec<f64>; 2],
    prev: Vec<(f64, f64)>,
    marks: Vec<[Option<SlabMark>; 2]>,
    signals: Vec<(f64, f64)>,
}

/// What a free stretch ended with.
enum Free {
    /// It reached its end.
    Done,
    /// A contact starts at `level` inside (grid j - 1, grid j] of the stretch.
    Onset { j: usize, level: usize },
}

impl<'a> Stepper<'a> {
    pub fn new(
        sc: &'a BuildingScenario,
        motion: &'a GroundMotion,
        grid: Grid,
        levels: &[Level],
        modes: [Modes; 2],
    ) -> Self {
        let sides = [
            Side::new(
                &modes[0],
                sc.left.heights(),
                sc.initial_velocity_m_s[0],
                &grid,
            ),
            Side::new(
                &modes[1],
                sc.right.heights(),
                sc.initial_velocity_m_s[1],
                &grid,
            ),
        ];
        let sears = sc.contact == ContactModel::Sears;
        let points = levels
            .iter()
            .map(|level| {
                let attach = [level.left, level.right];
                let r: [Vec<f64>; 2] = std::array::from_fn(|s| {
                    let w = attach[s].weights();
                    (0..sides[s].modes())
                        .map(|k| w.iter().map(|(f, x)| x * sides[s].shapes[k][*f]).sum())
                        .collect()
                });
                // The point's effective mass: the inverse of its velocity change per unit impulse.
                let inverse_mass: f64 = r.iter().flatten().map(|x| x * x).sum();
                let element = Element::new(
                    sc.contact,
                    sc.level_stiffness(level),
                    sc.restitution,
                    1.0 / inverse_mass,
                );
                let zone = if sc.reading == SlabReading::Paper {
                    sc.level_zone_length(level)
                } else {
                    0.0
                };
                let slabs = sc.level_slabs(level);
                let slab = |i: usize| {
                    slabs[i].filter(|_| sears).map(|(slab, mass)| {
                        SlabWaves::new(
                            &slab,
                            mass,
                            zone,
                            sc.slab_damping,
                            grid.h,
                            grid.total + 2,
                            if i == 0 { -1.0 } else { 1.0 },
                        )
                    })
                };
                Point {
                    element,
                    r,
                    slabs: [slab(0), slab(1)],
                    force: 0.0,
                    delta: -sc.gap_m,
                    rate: 0.0,
                    v0: 0.0,
                    open: None,
                    exchanged_in: None,
                    max_closing: f64::NEG_INFINITY,
                    max_force: 0.0,
                }
            })
            .collect();
        let mut s = Stepper {
            sc,
            motion,
            grid,
            peaks: Peaks::default(),
            sides,
            points,
            n: 0,
            offset: 0.0,
            ledger: Ledger::default(),
            contacts: Vec::new(),
            samples: Vec::new(),
            steps: 0,
            contact_steps: 0,
            sears,
            newmark: false,
            scratch: Scratch::default(),
        };
        s.ledger.initial_j = s.sides[0].energy() + s.sides[1].energy();
        for p in s.points.iter_mut() {
            p.max_closing = 0.0;
        }
        s.record();
        s
    }

    fn time(&self) -> f64 {
        self.n as f64 * self.grid.h + self.offset
    }

    /// The modal ground forcing at `t`: g_k = -Gamma_k a_g(t), and its slope over the record
    /// interval that starts at or before t.
    fn ground(&self, t: f64) -> (f64, f64) {
        let dt = self.motion.dt_s;
        let i = ((t / dt) + 1e-9).floor();
        let t0 = i * dt;
        let slope = (self.motion.at(t0 + dt) - self.motion.at(t0)) / dt;
        (self.motion.at(t), slope)
    }

    fn count_step(&mut self) -> Result<(), SolveError> {
        self.steps += 1;
        if self.steps > self.sc.max_steps {
            return Err(SolveError::Budget {
                max_steps: self.sc.max_steps,
                dt_s: self.grid.h,
                reached_s: self.time(),
            });
        }
        Ok(())
    }

    /// Runs to the end of the record, telling `control` how far it got.
    pub fn run(&mut self, control: &Control) -> Result<(), SolveError> {
        let end = self.grid.total;
        let mut looked_at = 0;
        while self.n < end {
            // Free steps advance many grid steps at once: look every CHECK_EVERY grid steps.
            if self.n >= looked_at {
                control.report(self.n as f64 / end.max(1) as f64)?;
                self.check_bounded()?;
                self.check_memory()?;
                looked_at = self.n + CHECK_EVERY;
            }
            if self.points.iter().any(|p| p.force > 0.0) {
                self.contact_step()?;
                continue;
            }
            if self.offset > 0.0 {
                // Back onto the grid after an event inside a step.
                let rest = self.grid.h - self.offset;
                if let Some(level) = self.free_partial(rest)? {
                    self.onset_in_partial(level, rest)?;
                }
                continue;
            }
            match self.free_step()? {
                Free::Done => {}
                Free::Onset { j, level } => self.onset(j, level)?,
            }
        }
        self.check_bounded()
    }

    /// Bytes one recorded sample takes: its numbers and its vectors' headers and allocations.
    fn sample_bytes(&self) -> f64 {
        let floors = self.sides[0].heights.len() + self.sides[1].heights.len();
        let numbers = 2 + 2 * floors + 4 + self.points.len();
        (8 * numbers + 5 * (24 + 16)) as f64
    }

    /// Stops a run whose histories outgrow [`SAMPLE_MEMORY_BUDGET`] (checked every few thousand
    /// steps, so at most that many samples past it are ever held).
    fn check_memory(&self) -> Result<(), SolveError> {
        let bytes = self.samples.len() as f64 * self.sample_bytes();
        if bytes <= SAMPLE_MEMORY_BUDGET {
            return Ok(());
        }
        Err(SolveError::Memory {
            at_s: self.time(),
            bytes: SAMPLE_MEMORY_BUDGET,
        })
    }

    /// Stops a run whose contacts have handed the buildings more than ten times the energy that
    /// ever entered them (or an infinite amount): no element does that, so the numbers that
    /// would follow are meaningless. The Sears paper reading does it beyond a tau = pi/2.
    fn check_bounded(&self) -> Result<(), SolveError> {
        let l = &self.ledger;
        let entered = l.initial_j + l.input_j.abs();
        if l.contact_work_j.is_finite() && l.contact_work_j <= 10.0 * entered {
            return Ok(());
        }
        Err(SolveError::Diverged {
            at_s: self.time(),
            why: format!(
                "the contacts handed the buildings {:.3e} J against {:.3e} J that entered",
                l.contact_work_j, entered
            ),
        })
    }

    /// Floor displacements of both sides from modal coordinates.
    fn floors(&self, q: [&[f64]; 2]) -> [Vec<f64>; 2] {
        std::array::from_fn(|s| {
            let side = &self.sides[s];
            (0..side.heights.len())
                .map(|f| side.floor(q[s], f))
                .collect()
        })
    }

    /// Every signal whose peak is reported, with its rate, from modal states: each floor, each
    /// storey's drift ratio, each contact point on each side.
    fn signals(&self, q: [&[f64]; 2], v: [&[f64]; 2], out: &mut Vec<(f64, f64)>) {
        out.clear();
        for s in 0..2 {
            let side = &self.sides[s];
            for f in 0..side.heights.len() {
                out.push((side.floor(q[s], f), side.floor(v[s], f)));
            }
        }
        for s in 0..2 {
            let side = &self.sides[s];
            let mut below = (0.0, 0.0);
            for f in 0..side.heights.len() {
                let now = (side.floor(q[s], f), side.floor(v[s], f));
                let h = side.heights[f];
                out.push(((now.0 - below.0) / h, (now.1 - below.1) / h));
                below = now;
            }
        }
        for p in &self.points {
            for s in 0..2 {
                out.push((dotv(&p.r[s], q[s]), dotv(&p.r[s], v[s])));
            }
        }
    }

    fn track_peaks(&mut self, t: f64, q: [&[f64]; 2], v: [&[f64]; 2]) {
        let mut now = std::mem::take(&mut self.scratch.signals);
        self.signals(q, v, &mut now);
        self.peaks.update(t, &now);
        self.scratch.signals = now;
    }

    /// Peaks of each floor, each storey's drift ratio and each point.
    pub fn peaks(&self) -> PeakSummary {
        let n = [self.sides[0].heights.len(), self.sides[1].heights.len()];
        let p = &self.peaks.peak;
        let floors = [p[..n[0]].to_vec(), p[n[0]..n[0] + n[1]].to_vec()];
        let d0 = n[0] + n[1];
        let drifts = [p[d0..d0 + n[0]].to_vec(), p[d0 + n[0]..2 * d0].to_vec()];
        let points = p[2 * d0..].chunks(2).map(|c| [c[0], c[1]]).collect();
        (floors, drifts, points)
    }

    /// The roof acceleration relative to the ground from the modal state and forcing.
    fn roof_accelerations(&self, ground: f64, contact: bool) -> [f64; 2] {
        std::array::from_fn(|s| {
            let side = &self.sides[s];
            let roof = side.heights.len() - 1;
            (0..side.modes())
                .map(|k| {
                    let a = if contact {
                        side.a[k]
                    } else {
                        -side.gamma[k] * ground
                            - 2.0 * side.zeta[k] * side.omega[k] * side.v[k]
                            - side.omega[k].powi(2) * side.q[k]
                    };
                    side.shapes[k][roof] * a
                })
                .sum()
        })
    }

    fn record(&mut self) {
        let t = self.time();
        let ground = self.motion.at(t);
        let floors = self.floors([&self.sides[0].q, &self.sides[1].q]);
        let floor_v = self.floors([&self.sides[0].v, &self.sides[1].v]);
        let roof_v = std::array::from_fn(|s| {
            let side = &self.sides[s];
            side.floor(&side.v, side.heights.len() - 1)
        });
        let contact = self.points.iter().any(|p| p.force > 0.0);
        let roof_a = self.roof_accelerations(ground, contact);
        let (q0, q1) = (
            std::mem::take(&mut self.sides[0].q),
            std::mem::take(&mut self.sides[1].q),
        );
        let (v0, v1) = (
            std::mem::take(&mut self.sides[0].v),
            std::mem::take(&mut self.sides[1].v),
        );
        self.track_peaks(t, [&q0, &q1], [&v0, &v1]);
        (self.sides[0].q, self.sides[1].q) = (q0, q1);
        (self.sides[0].v, self.sides[1].v) = (v0, v1);
        self.samples.push(Sample {
            t,
            ground,
            floors,
            floor_v,
            roof_v,
            roof_a,
            forces: self.points.iter().map(|p| p.force).collect(),
        });
    }

    // ---- free step -------------------------------------------------------------------------

    /// The augmented initial states y0 = [q, q', g, g'] of every mode of a side.
    fn initial(&self, s: usize, t: f64) -> Vec<[f64; 4]> {
        let (a0, slope) = self.ground(t);
        let side = &self.sides[s];
        (0..side.modes())
            .map(|k| {
                [
                    side.q[k],
                    side.v[k],
                    -side.gamma[k] * a0,
                    -side.gamma[k] * slope,
                ]
            })
            .collect()
    }

    /// Writes a free stretch of length `len` from `y0` to the ledger and moves the state there:
    /// the exact integrals of the ground's power and of the damping.
    fn commit_free(&mut self, y0: [&[[f64; 4]]; 2], ends: [&[(f64, f64)]; 2], len: f64) {
        self.newmark = false;
        // A whole number of fine steps reuses its integrals; another length (up to an event
        // inside a step) needs its own.
        let steps = len / self.grid.h;
        let whole = steps.round();
        let j = ((steps - whole).abs() <= 1e-9 * steps.max(1.0))
            .then_some(whole as usize)
            .filter(|j| (1..=self.grid.per_free_step).contains(j));
        for s in 0..2 {
            let side = &mut self.sides[s];
            if let Some(j) = j
                && j < self.grid.per_free_step
                && side.part[j].is_none()
            {
                let l = j as f64 * self.grid.h;
                side.part[j] = Some(
                    (0..side.modes())
                        .map(|k| step_integrals(side.omega[k], side.zeta[k], l))
                        .collect(),
                );
            }
            for k in 0..side.modes() {
                let ints = match j {
                    Some(j) if j == self.grid.per_free_step => side.full[k],
                    Some(j) => side.part[j].as_ref().expect("just made")[k],
                    None => step_integrals(side.omega[k], side.zeta[k], len),
                };
                let y = &y0[s][k];
                let (q1, v1) = ends[s][k];
                let dq = q1 - y[0];
                let int_q: f64 = (0..4).map(|j| ints.int_q[j] * y[j]).sum();
                let int_s_v = len * q1 - int_q;
                self.ledger.input_j += y[2] * dq + y[3] * int_s_v;
                self.ledger.damping_j +=
                    2.0 * side.zeta[k] * side.omega[k] * ints.velocity_squared(y);
                side.q[k] = q1;
                side.v[k] = v1;
            }
        }
    }

    /// One free stretch from a grid point to the next sample of the record (or the longest free
    /// step), checked at every grid point.
    fn free_step(&mut self) -> Result<Free, SolveError> {
        self.newmark = false;
        let g = self.grid;
        // To the next free-step boundary (record samples are boundaries too).
        let len = (g.per_free_step - self.n % g.per_free_step).min(g.total - self.n);
        self.steps += len - 1;
        self.count_step()?;
        let t0 = self.time();
        let y0 = [self.initial(0, t0), self.initial(1, t0)];
        let mut w = std::mem::take(&mut self.scratch);
        w.marks.clear();
        w.marks.extend(
            self.points
                .iter()
                .map(|p| std::array::from_fn(|i| p.slabs[i].as_ref().map(|s| s.mark()))),
        );
        w.prev.clear();
        for p in &self.points {
            w.prev.push(self.point_now_of(p));
        }
        for s in 0..2 {
            w.q[s].resize(self.sides[s].modes(), 0.0);
            w.v[s].resize(self.sides[s].modes(), 0.0);
        }
        let contact = self.sc.contact;
        let gap = self.sc.gap_m;
        let needs_approach = matches!(contact, ContactModel::Kelvin | ContactModel::HertzDamp);
        let mut onset = None;
        for j in 1..=len {
            for (s, y) in y0.iter().enumerate() {
                for (k, p) in self.sides[s].sub[j - 1].iter().enumerate() {
                    let (q, v) = p.apply(&y[k]);
                    w.q[s][k] = q;
                    w.v[s][k] = v;
                }
            }
            for i in 0..self.points.len() {
                if self.sears {
                    for slab in self.points[i].slabs.iter_mut().flatten() {
                        slab.push(0.0);
                    }
                }
                let p = &mut self.points[i];
                let c = dotv(&p.r[0], &w.q[0]) - dotv(&p.r[1], &w.q[1]);
                let cv = dotv(&p.r[0], &w.v[0]) - dotv(&p.r[1], &w.v[1]);
                let (c0, cv0) = w.prev[i];
                w.prev[i] = (c, cv);
                // Between grid points the closing motion is the cubic through their exact
                // states: a maximum inside a step is found there, and a new largest one is
                // refined on the exact motion (the gap that avoids contact is this maximum).
                let inside = hermite_max(c0, cv0, c, cv, g.h);
                p.max_closing = p.max_closing.max(c);
                // The cubic is good to (w h)^4 / 384 of the amplitude: near the running maximum
                // the exact motion decides.
                if inside > p.max_closing - 1e-6 * p.max_closing.abs() {
                    let (a, b) = ((j - 1) as f64 * g.h, j as f64 * g.h);
                    let exact = self.exact_max_closing(i, &y0, a, b);
                    let m = &mut self.points[i].max_closing;
                    *m = m.max(exact);
                }
                let p = &mut self.points[i];
                if contact == ContactModel::None || onset.is_some() {
                    continue;
                }
                let delta = c - gap - p.elastic();
                let approaching = !needs_approach || cv > 0.0;
                let exchanged = p.exchanged_in == Some(self.n + j - 1);
                if !exchanged
                    && ((delta > 0.0 && approaching) || (!self.sears && inside > gap && cv0 > 0.0))
                {
                    onset = Some(i);
                }
            }
            if let Some(level) = onset {
                // Back to the start of the stretch: the caller redoes it up to the onset.
                for (p, m) in self.points.iter_mut().zip(&w.marks) {
                    for (slab, mark) in p.slabs.iter_mut().zip(m) {
                        if let (Some(s), Some(m)) = (slab.as_mut(), mark) {
                            s.reset(*m);
                        }
                    }
                }
                self.scratch = w;
                return Ok(Free::Onset { j, level });
            }
            // The motion up to here is free: its peaks count.
            let mut now = std::mem::take(&mut w.signals);
            self.signals([&w.q[0], &w.q[1]], [&w.v[0], &w.v[1]], &mut now);
            self.peaks.update(t0 + j as f64 * g.h, &now);
            w.signals = now;
        }
        let ends: [Vec<(f64, f64)>; 2] =
            std::array::from_fn(|s| w.q[s].iter().zip(&w.v[s]).map(|(q, v)| (*q, *v)).collect());
        self.scratch = w;
        self.commit_free([&y0[0], &y0[1]], [&ends[0], &ends[1]], len as f64 * g.h);
        self.n += len;
        self.record();
        Ok(Free::Done)
    }

    /// The largest closing motion of point i over [a, b] after the start of a free stretch from
    /// `y0`, on the exact motion: where its rate falls through zero.
    fn exact_max_closing(&self, i: usize, y0: &[Vec<[f64; 4]>; 2], a: f64, b: f64) -> f64 {
        let p = &self.points[i];
        let at = |s: f64| {
            let mut c = (0.0, 0.0);
            for (side, sign) in [(0, 1.0), (1, -1.0)] {
                let sd = &self.sides[side];
                for (k, y) in y0[side].iter().enumerate() {
                    let (q, v) = propagator(sd.omega[k], sd.zeta[k], s).apply(y);
                    c.0 += sign * p.r[side][k] * q;
                    c.1 += sign * p.r[side][k] * v;
                }
            }
            c
        };
        let (ca, va) = if a > 0.0 { at(a) } else { self.point_now_of(p) };
        let (cb, vb) = at(b);
        if va > 0.0 && vb < 0.0 {
            let s = bracket(|s| at(s).1, a, b, 1e-15 * b.max(1e-300)).mid();
            at(s).0.max(ca).max(cb)
        } else {
            ca.max(cb)
        }
    }

    /// A point's closing motion u_left - u_right and its rate, from modal states.
    fn point_state(&self, p: &Point, q: [&[f64]; 2], v: [&[f64]; 2]) -> (f64, f64) {
        (
            dotv(&p.r[0], q[0]) - dotv(&p.r[1], q[1]),
            dotv(&p.r[0], v[0]) - dotv(&p.r[1], v[1]),
        )
    }

    /// A free stretch of arbitrary length (back onto the grid after an event, or up to a
    /// located onset), exact, checked at its end. Returns a level where a contact starts by its
    /// end, if one does.
    fn free_partial(&mut self, len: f64) -> Result<Option<usize>, SolveError> {
        self.count_step()?;
        self.newmark = false;
        let t0 = self.time();
        let y0 = [self.initial(0, t0), self.initial(1, t0)];
        let before: Vec<(f64, f64)> = self
            .points
            .iter()
            .map(|p| {
                self.point_state(
                    p,
                    [&self.sides[0].q, &self.sides[1].q],
                    [&self.sides[0].v, &self.sides[1].v],
                )
            })
            .collect();
        let ends: [Vec<(f64, f64)>; 2] = std::array::from_fn(|s| {
            let side = &self.sides[s];
            (0..side.modes())
                .map(|k| propagator(side.omega[k], side.zeta[k], len).apply(&y0[s][k]))
                .collect()
        });
        let q: [Vec<f64>; 2] = std::array::from_fn(|s| ends[s].iter().map(|e| e.0).collect());
        let v: [Vec<f64>; 2] = std::array::from_fn(|s| ends[s].iter().map(|e| e.1).collect());
        let mut onset = None;
        for (i, &(c0, cv0)) in before.iter().enumerate() {
            let (c, cv) = self.point_state(&self.points[i], [&q[0], &q[1]], [&v[0], &v[1]]);
            let p = &mut self.points[i];
            p.max_closing = p.max_closing.max(c).max(hermite_max(c0, cv0, c, cv, len));
            if self.sc.contact == ContactModel::None || self.sears {
                continue;
            }
            let approaching = !matches!(
                self.sc.contact,
                ContactModel::Kelvin | ContactModel::HertzDamp
            ) || cv > 0.0;
            let inside = hermite_max(c0, cv0, c, cv, len) > self.sc.gap_m && cv0 > 0.0;
            // Leaving a contact just released, the closing motion starts at the gap: only a
            // new approach counts; and one exchange per level per step.
            let fresh = (c0 < self.sc.gap_m || cv0 > 0.0) && p.exchanged_in != Some(self.n);
            if onset.is_none() && fresh && ((c > self.sc.gap_m && approaching) || inside) {
                onset = Some(i);
            }
        }
        if onset.is_some() {
            return Ok(onset);
        }
        self.commit_free([&y0[0], &y0[1]], [&ends[0], &ends[1]], len);
        self.advance(len);
        if self.offset == 0.0 {
            self.record();
        } else {
            let t = self.time();
            let (q0, q1) = (self.sides[0].q.clone(), self.sides[1].q.clone());
            let (v0, v1) = (self.sides[0].v.clone(), self.sides[1].v.clone());
            self.track_peaks(t, [&q0, &q1], [&v0, &v1]);
        }
        Ok(None)
    }

    fn advance(&mut self, len: f64) {
        let t = self.offset + len;
        let whole = (t / self.grid.h + 1e-9).floor();
        self.n += whole as usize;
        self.offset = t - whole * self.grid.h;
        if self.offset < 1e-9 * self.grid.h {
            self.offset = 0.0;
        }
    }

    // ---- onset location --------------------------------------------------------------------

    /// A contact starts at `level` inside the j-th fine step of the free stretch that began at
    /// the current time: move there exactly, then into contact.
    fn onset(&mut self, j: usize, level: usize) -> Result<(), SolveError> {
        let g = self.grid;
        let t0 = self.time();
        if j > 1 {
            // Exactly to the grid point before, the slabs with it.
            let y0 = [self.initial(0, t0), self.initial(1, t0)];
            let ends: [Vec<(f64, f64)>; 2] = std::array::from_fn(|s| {
                self.sides[s].sub[j - 2]
                    .iter()
                    .zip(&y0[s])
                    .map(|(p, y)| p.apply(y))
                    .collect()
            });
            self.commit_free([&y0[0], &y0[1]], [&ends[0], &ends[1]], (j - 1) as f64 * g.h);
            if self.sears {
                for p in self.points.iter_mut() {
                    for slab in p.slabs.iter_mut().flatten() {
                        for _ in 0..j - 1 {
                            slab.push(0.0);
                        }
                    }
                }
            }
            self.n += j - 1;
            self.record();
        }
        self.onset_in_partial(level, g.h)
    }

    /// A contact starts at `level` within the next `len` of time from now.
    fn onset_in_partial(&mut self, level: usize, len: f64) -> Result<(), SolveError> {
        if self.sears {
            // The slabs' waves are known on the grid only: the contact starts from this grid
            // point, its first step implicit from zero force; its start is interpolated.
            let (c0, w) = self.point_now(level);
            let p = &mut self.points[level];
            p.delta = c0 - self.sc.gap_m - p.elastic();
            p.rate = 0.0;
            p.v0 = w;
            return self.contact_step();
        }
        // Where the closing motion reaches the gap, on the cubic through the exact states at
        // both ends (exact to round-off over a fine step).
        let t0 = self.time();
        let y0 = [self.initial(0, t0), self.initial(1, t0)];
        let (c0, v0) = self.point_now(level);
        let end: [Vec<(f64, f64)>; 2] = std::array::from_fn(|s| {
            let side = &self.sides[s];
            (0..side.modes())
                .map(|k| propagator(side.omega[k], side.zeta[k], len).apply(&y0[s][k]))
                .collect()
        });
        let q1: [Vec<f64>; 2] = std::array::from_fn(|s| end[s].iter().map(|e| e.0).collect());
        let v1: [Vec<f64>; 2] = std::array::from_fn(|s| end[s].iter().map(|e| e.1).collect());
        let (c1, cv1) = self.point_state(&self.points[level], [&q1[0], &q1[1]], [&v1[0], &v1[1]]);
        let gap = self.sc.gap_m;
        let cubic = |x: f64| hermite(c0, v0, c1, cv1, len, x) - gap;
        // The first crossing: up to the cubic's maximum where the end itself is still open.
        let upper = if cubic(len) > 0.0 {
            len
        } else {
            hermite_argmax(c0, v0, c1, cv1, len).unwrap_or(len)
        };
        let s_on = if c0 - gap >= 0.0 {
            0.0
        } else {
            bracket(cubic, 0.0, upper, 1e-14 * len).second_side
        };
        if s_on > 0.0 {
            let ends: [Vec<(f64, f64)>; 2] = std::array::from_fn(|s| {
                let side = &self.sides[s];
                (0..side.modes())
                    .map(|k| propagator(side.omega[k], side.zeta[k], s_on).apply(&y0[s][k]))
                    .collect()
            });
            self.commit_free([&y0[0], &y0[1]], [&ends[0], &ends[1]], s_on);
            self.advance(s_on);
        }
        let (c, w) = self.point_now(level);
        let t_on = self.time();
        if self.sc.contact == ContactModel::Stereo {
            // Floors already overlapping (after a cut sequence of exchanges) and not yet
            // approaching: nothing to exchange in this step.
            self.exchange(level, w, t_on);
            self.points[level].exchanged_in = Some(self.n);
            self.record();
            return Ok(());
        }
        let p = &mut self.points[level];
        p.delta = (c - gap).min(0.0);
        p.rate = w;
        p.v0 = w;
        // A Kelvin-Voigt link pushes with c delta' from the first instant.
        p.force = p.element.push(0.0, w, w).max(0.0);
        if p.force > 0.0 {
            p.open = Some(self.contacts.len());
            p.max_force = p.max_force.max(p.force);
            self.contacts.push(RawContact {
                level,
                start_s: t_on,
                end_s: t_on,
                peak_force_n: p.force,
                impulse_ns: 0.0,
                approach_velocity_m_s: w,
            });
        }
        self.record();
        // The force rises from the onset as a power of the time since it (t^1 linear, t^1.5
        // Hertz, t^0.25 for Jankowski's dashpot): steps graded towards the onset keep the
        // method's order where uniform ones would lose it.
        let mut rest = self.grid.h - self.offset;
        if rest < self.grid.h / 16.0 {
            // An onset at the end of a step: grade over the next step too, rather than take
            // steps far shorter than the contact's own scale.
            rest += self.grid.h;
        }
        let mut len = rest / (1u64 << ONSET_GRADING) as f64;
        self.contact_step_of(len)?;
        for _ in 0..ONSET_GRADING {
            if !self.points.iter().any(|p| p.force > 0.0) {
                break;
            }
            self.contact_step_of(len)?;
            len *= 2.0;
        }
        Ok(())
    }

    /// Whether the element's link takes hold only of approaching floors (a damped link that let
    /// go with them still overlapping).
    fn needs_approach(&self) -> bool {
        matches!(
            self.sc.contact,
            ContactModel::Kelvin | ContactModel::HertzDamp
        )
    }

    /// The closing motion and its rate at a level now.
    fn point_now(&self, level: usize) -> (f64, f64) {
        self.point_state(
            &self.points[level],
            [&self.sides[0].q, &self.sides[1].q],
            [&self.sides[0].v, &self.sides[1].v],
        )
    }

    /// Stereomechanics: the relative velocity at the point reverses with restitution e, at once.
    fn exchange(&mut self, level: usize, w: f64, t: f64) {
        if w <= 0.0 {
            return;
        }
        self.points[level].exchanged_in = Some(self.n);
        let energy = self.sides[0].energy() + self.sides[1].energy();
        let p = &self.points[level];
        let inverse_mass: f64 = p.r.iter().flatten().map(|x| x * x).sum();
        let impulse = (1.0 + self.sc.restitution) * w / inverse_mass;
        for (s, sign) in [(0, -1.0), (1, 1.0)] {
            for k in 0..self.sides[s].modes() {
                self.sides[s].v[k] += sign * p.r[s][k] * impulse;
            }
        }
        self.ledger.exchanged_j += energy - (self.sides[0].energy() + self.sides[1].energy());
        self.contacts.push(RawContact {
            level,
            start_s: t,
            end_s: t,
            peak_force_n: 0.0,
            impulse_ns: impulse,
            approach_velocity_m_s: w,
        });
    }

    // ---- contact step ----------------------------------------------------------------------

    /// One implicit step of every level in contact, to the next grid point (or a Kelvin-Voigt
    /// link's release inside it).
    fn contact_step(&mut self) -> Result<(), SolveError> {
        self.contact_step_of(self.grid.h - self.offset)
    }

    /// A contact step of length hh (the last one of a graded start lands on the grid).
    fn contact_step_of(&mut self, hh: f64) -> Result<(), SolveError> {
        self.count_step()?;
        if !self.newmark {
            self.equilibrium_accelerations();
            self.newmark = true;
        }
        // A level out of contact follows the motion: its overlap and rate are the kinematics
        // now, not what they were when it last let go.
        for i in 0..self.points.len() {
            if self.points[i].force <= 0.0 {
                let (c, w) = self.point_now(i);
                let p = &mut self.points[i];
                p.delta = c - self.sc.gap_m - p.elastic();
                p.rate = w;
            }
        }
        let trial = self.trial(hh);
        // A Kelvin-Voigt link lets go where k delta + c delta' reaches zero, inside the step.
        let released = (0..self.points.len()).find(|&i| {
            self.sc.contact == ContactModel::Kelvin
                && self.points[i].force > 0.0
                && trial.forces[i] <= 0.0
                && trial.deltas[i] > 0.0
        });
        let trial = match released {
            Some(i) => {
                let push = |x: f64| {
                    let t = self.trial(x * hh);
                    let p = &self.points[i];
                    p.element.push(t.deltas[i], t.rates[i], p.v0)
                };
                let x = bracket(push, 0.0, 1.0, 1e-12).second_side.max(1e-9);
                let mut t = self.trial(x * hh);
                t.forces[i] = 0.0;
                t.released = Some(i);
                t
            }
            None => trial,
        };
        self.commit_contact(trial);
        Ok(())
    }

    /// Newmark's step needs accelerations that satisfy the equations of motion where it starts:
    /// q'' = g - 2 zeta w q' - w^2 q with the ground's and the contact forces at this instant.
    fn equilibrium_accelerations(&mut self) {
        let ground = self.motion.at(self.time());
        for s in 0..2 {
            let sign = if s == 0 { -1.0 } else { 1.0 };
            for k in 0..self.sides[s].modes() {
                let contact: f64 = self.points.iter().map(|p| sign * p.r[s][k] * p.force).sum();
                let side = &mut self.sides[s];
                side.a[k] = -side.gamma[k] * ground + contact
                    - 2.0 * side.zeta[k] * side.omega[k] * side.v[k]
                    - side.omega[k].powi(2) * side.q[k];
            }
        }
    }

    /// A contact step of length hh, not yet taken.
    fn trial(&self, hh: f64) -> Trial {
        let t0 = self.time();
        let t1 = t0 + hh;
        let ground = self.motion.at(t1);
        let ground_change = ground - self.motion.at(t0);
        let full = (hh - self.grid.h).abs() <= 1e-12 * hh;
        // Newmark's step in incremental form, k_hat dq = dp + (4/h + 2c) v + 2a, so that short
        // steps lose nothing to cancellation; its increment without a change of contact forces.
        let mut k_hat: [Vec<f64>; 2] = [vec![], vec![]];
        let mut step: [Vec<f64>; 2] = [vec![], vec![]];
        for s in 0..2 {
            let side = &self.sides[s];
            let sign = if s == 0 { -1.0 } else { 1.0 };
            for k in 0..side.modes() {
                let kh = if full {
                    side.k_hat[k]
                } else {
                    newmark_k_hat(side.omega[k], side.zeta[k], hh)
                };
                let c = 2.0 * side.zeta[k] * side.omega[k];
                let contact_now: f64 = self.points.iter().map(|p| sign * p.r[s][k] * p.force).sum();
                let load = -side.gamma[k] * ground_change - contact_now
                    + (4.0 / hh + 2.0 * c) * side.v[k]
                    + 2.0 * side.a[k];
                k_hat[s].push(kh);
                step[s].push(load / kh);
            }
        }
        let pred: [Vec<f64>; 2] = std::array::from_fn(|s| {
            self.sides[s]
                .q
                .iter()
                .zip(&step[s])
                .map(|(q, dq)| q + dq)
                .collect()
        });
        let np = self.points.len();
        // delta_p = predicted - sum_q G_pq F_q, with the slabs' part.
        let mut predicted = vec![0.0; np];
        let mut g = vec![vec![0.0; np]; np];
        for (i, p) in self.points.iter().enumerate() {
            let (e0, e1) = if self.sears {
                p.predict_elastic()
            } else {
                (0.0, 0.0)
            };
            predicted[i] = dotv(&p.r[0], &pred[0]) - dotv(&p.r[1], &pred[1]) - self.sc.gap_m - e0;
            for (j, o) in self.points.iter().enumerate() {
                g[i][j] = (0..2)
                    .map(|s| {
                        (0..k_hat[s].len())
                            .map(|k| p.r[s][k] * o.r[s][k] / k_hat[s][k])
                            .sum::<f64>()
                    })
                    .sum();
            }
            // The slabs' instantaneous compliance minus their rigid part can be a hair below
            // zero (the storeys' springs and dampers stiffen the rigid response): clamp.
            g[i][i] = (g[i][i] + e1).max(0.0);
        }
        // Nonlinear Gauss-Seidel: each level's monotone scalar equation with the others' forces
        // fixed, swept until the forces settle (one sweep for one level; the levels couple
        // through the storeys only, weakly over a fine step).
        let mut forces: Vec<f64> = self.points.iter().map(|p| p.force).collect();
        let mut deltas = vec![0.0; np];
        let mut rates = vec![0.0; np];
        for _sweep in 0..200 {
            let mut change = 0.0f64;
            let mut scale = 0.0f64;
            for i in 0..np {
                let p = &self.points[i];
                let others: f64 = (0..np)
                    .filter(|&j| j != i)
                    .map(|j| g[i][j] * forces[j])
                    .sum();
                let rhs = predicted[i] - others;
                // A damped link that let go with the floors still overlapping takes hold again
                // only when they approach each other (as a free step starts a contact).
                let held =
                    p.force > 0.0 || p.delta <= 0.0 || p.rate > 0.0 || !self.needs_approach();
                let d = if held {
                    p.element
                        .solve_step(g[i][i], rhs, hh, p.delta, p.rate, p.v0)
                } else {
                    rhs
                };
                let rate = p.element.rate(hh, d, p.delta, p.rate);
                let f = if self.sears {
                    p.element.stiffness() * d.max(0.0)
                } else if held {
                    p.element.force(d, rate, p.v0)
                } else {
                    0.0
                };
                change = change.max((f - forces[i]).abs());
                scale = scale.max(f.abs());
                forces[i] = f;
                deltas[i] = d;
                rates[i] = rate;
            }
            if np == 1 || change <= 1e-13 * scale {
                break;
            }
        }
        let dq: [Vec<f64>; 2] = std::array::from_fn(|s| {
            let sign = if s == 0 { -1.0 } else { 1.0 };
            (0..step[s].len())
                .map(|k| {
                    let f: f64 = self
                        .points
                        .iter()
                        .zip(&forces)
                        .map(|(p, f)| p.r[s][k] * f)
                        .sum();
                    step[s][k] + sign * f / k_hat[s][k]
                })
                .collect()
        });
        Trial {
            hh,
            ground,
            dq,
            forces,
            deltas,
            rates,
            released: None,
        }
    }

    /// Takes a trial step: the modes, the slabs, the ledger and the contacts.
    fn commit_contact(&mut self, tr: Trial) {
        let hh = tr.hh;
        let t0 = self.time();
        let ground0 = self.motion.at(t0);
        let before: Vec<f64> = self.points.iter().map(|p| p.force).collect();
        let u_before: Vec<(f64, f64)> = self.points.iter().map(|p| self.point_now_of(p)).collect();
        for s in 0..2 {
            let side = &mut self.sides[s];
            for k in 0..side.modes() {
                let (v0, a0) = (side.v[k], side.a[k]);
                let dq = tr.dq[s][k];
                let dv = 2.0 * dq / hh - 2.0 * v0;
                let da = 4.0 * (dq - hh * v0) / (hh * hh) - 2.0 * a0;
                let v1 = v0 + dv;
                // Newmark's discrete energy identity: the work of the ground is half the sum of
                // its forces times the displacement; the damping takes h/4 c (v0 + v1)^2.
                self.ledger.input_j += 0.5 * dq * (-side.gamma[k]) * (ground0 + tr.ground);
                self.ledger.damping_j +=
                    0.25 * hh * 2.0 * side.zeta[k] * side.omega[k] * (v0 + v1).powi(2);
                side.q[k] += dq;
                side.v[k] = v1;
                side.a[k] = a0 + da;
            }
        }
        self.advance(hh);
        let t1 = self.time();
        for (i, p) in self.points.iter_mut().enumerate() {
            let f1 = tr.forces[i];
            for slab in p.slabs.iter_mut().flatten() {
                slab.push(f1);
            }
        }
        let u_after: Vec<(f64, f64)> = self.points.iter().map(|p| self.point_now_of(p)).collect();
        for (i, p) in self.points.iter_mut().enumerate() {
            let (f0, f1) = (before[i], tr.forces[i]);
            // The contact's work on the buildings: -(F0 + F1)/2 times the closing displacement.
            self.ledger.contact_work_j -= 0.5 * (f0 + f1) * (u_after[i].0 - u_before[i].0);
            let delta0 = p.delta;
            p.delta = if self.sears {
                u_after[i].0
                    - self.sc.gap_m
                    - p.slabs.iter().flatten().map(|s| s.elastic_m()).sum::<f64>()
            } else {
                tr.deltas[i]
            };
            p.rate = tr.rates[i];
            p.force = f1;
            p.max_force = p.max_force.max(f1);
            if f0 <= 0.0 && f1 > 0.0 {
                // Opened inside this step: where the overlap crossed zero.
                let start = if delta0 < 0.0 && p.delta > delta0 {
                    t0 + hh * (-delta0 / (p.delta - delta0)).clamp(0.0, 1.0)
                } else {
                    t0
                };
                if p.v0 <= 0.0 {
                    p.v0 = u_after[i].1.max(1e-12);
                }
                p.open = Some(self.contacts.len());
                self.contacts.push(RawContact {
                    level: i,
                    start_s: start,
                    end_s: start,
                    peak_force_n: 0.0,
                    impulse_ns: 0.0,
                    approach_velocity_m_s: p.v0,
                });
            }
            if let Some(c) = p.open {
                let contact = &mut self.contacts[c];
                contact.impulse_ns += 0.5 * hh * (f0 + f1);
                contact.peak_force_n = contact.peak_force_n.max(f1);
                if f1 <= 0.0 {
                    contact.end_s = if tr.released == Some(i) || p.delta > 0.0 {
                        t1
                    } else {
                        t0 + hh
                            * (delta0.max(0.0) / (delta0.max(0.0) - p.delta).max(f64::MIN_POSITIVE))
                                .clamp(0.0, 1.0)
                    };
                    p.open = None;
                    p.v0 = 0.0;
                    if contact.impulse_ns <= 0.0 {
                        // The touch carried no force (a grazing approach): not a contact.
                        self.contacts.pop();
                    }
                } else {
                    contact.end_s = t1;
                }
            }
        }
        self.contact_steps += 1;
        // Accelerations stay Newmark's inside contacts; leaving one, the free steps need none.
        self.record();
    }

    fn point_now_of(&self, p: &Point) -> (f64, f64) {
        self.point_state(
            p,
            [&self.sides[0].q, &self.sides[1].q],
            [&self.sides[0].v, &self.sides[1].v],
        )
    }

    /// The contact elements' energy at the end, and the buildings'.
    pub fn finish(&mut self, end_s: f64) -> (BuildingEnergy, bool) {
        let stored: f64 = self
            .points
            .iter()
            .filter(|p| p.force > 0.0)
            .map(|p| p.element.stored_energy(p.delta))
            .sum();
        let still = self.points.iter().any(|p| p.force > 0.0);
        for p in self.points.iter_mut() {
            if let Some(c) = p.open.take() {
                self.contacts[c].end_s = end_s;
            }
        }
        let final_j = self.sides[0].energy() + self.sides[1].energy();
        let l = self.ledger;
        (
            BuildingEnergy {
                initial_j: l.initial_j,
                input_j: l.input_j,
                building_damping_j: l.damping_j,
                contact_j: -l.contact_work_j - stored + l.exchanged_j,
                final_j,
                stored_contact_j: stored,
            },
            still,
        )
    }

    pub fn max_closing(&self) -> Vec<f64> {
        self.points.iter().map(|p| p.max_closing).collect()
    }

    pub fn max_forces(&self) -> Vec<f64> {
        self.points.iter().map(|p| p.max_force).collect()
    }

    pub fn slab_waves(&self) -> Vec<[Option<crate::model::field::BarWaves>; 2]> {
        if !self.sears {
            return vec![];
        }
        self.points
            .iter()
            .map(|p| std::array::from_fn(|i| p.slabs[i].as_ref().map(|s| s.waves())))
            .collect()
    }
}

/// A contact step computed but not taken.
struct Trial {
    hh: f64,
    ground: f64,
    /// The modal displacements' increments.
    dq: [Vec<f64>; 2],
    forces: Vec<f64>,
    deltas: Vec<f64>,
    rates: Vec<f64>,
    /// The level whose Kelvin-Voigt link let go at the end of this (shortened) step.
    released: Option<usize>,
}

/// The cubic through (0, y0) and (l, y1) with slopes v0 and v1, at x.
fn hermite(y0: f64, v0: f64, y1: f64, v1: f64, l: f64, x: f64) -> f64 {
    let s = x / l;
    let (s2, s3) = (s * s, s * s * s);
    (2.0 * s3 - 3.0 * s2 + 1.0) * y0
        + (s3 - 2.0 * s2 + s) * l * v0
        + (-2.0 * s3 + 3.0 * s2) * y1
        + (s3 - s2) * l * v1
}

/// Where that cubic has an interior maximum, if it has one (slope falling through zero).
fn hermite_argmax(y0: f64, v0: f64, y1: f64, v1: f64, l: f64) -> Option<f64> {
    if !(v0 > 0.0 && v1 < 0.0) {
        return None;
    }
    // The derivative is a quadratic in s with a root in (0, 1) (it changes sign).
    let d = |s: f64| {
        let (a, b) = (6.0 * s * s - 6.0 * s, 3.0 * s * s - 4.0 * s + 1.0);
        (a * y0 + b * l * v0 - a * y1 + (3.0 * s * s - 2.0 * s) * l * v1) / l
    };
    Some(bracket(d, 0.0, 1.0, 1e-14).mid() * l)
}

/// The cubic's largest value inside the step (or minus infinity).
fn hermite_max(y0: f64, v0: f64, y1: f64, v1: f64, l: f64) -> f64 {
    hermite_argmax(y0, v0, y1, v1, l).map_or(f64::NEG_INFINITY, |x| hermite(y0, v0, y1, v1, l, x))
}
