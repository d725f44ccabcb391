//! The pounding run as named stages over both buildings' modes and every contact point:
//!
//! - **free stretch**: between contacts each mode is propagated exactly to the next sample of the
//!   record (the ground acceleration is linear between samples). The stretch is checked at a few
//!   points only: between two of them every signal is within a proven margin of the cubic
//!   through its ends ([`bound`]), so where that cubic plus its margin stays below the gap no
//!   contact can start, and where it stays below a running peak no peak is missed. Only the
//!   parts that a bound cannot clear are walked grid point by grid point, as a contact onset
//!   or a new peak needs;
//! - **onset location**: the touching instant inside its fine step, on the cubic through the
//!   exact states at both ends (exact to round-off at these steps), or, for the Sears slabs, whose
//!   waves live on the grid, the grid point before it;
//! - **contact step**: Newmark's average acceleration on the modes with the contact forces
//!   implicit (stable for any stiffness), one coupled set of monotone equations for the levels in
//!   contact, solved by nonlinear Gauss-Seidel;
//! - **impact bookkeeping**: contacts opened and closed per level, their impulse and peak;
//! - **recording**: the histories at the resolution a plot needs (every free stretch, and inside
//!   contacts a few samples per contact time scale); the peaks on the cubics between the grid
//!   points a free stretch reads, and between the ends of batches of up to 8 contact steps, where
//!   proofs on the steps' summed reach do not show a signal below its peak.
//!
//! Every stage writes to one energy [`Ledger`]: the free steps with the exact integrals of the
//! modal power, the contact steps with Newmark's discrete energy identity, so the ledger balances
//! to round-off and what it reports (work of the ground, damping, energy taken by the contact)
//! is exact for the discrete solution.

mod contact;
mod free;
pub(super) mod lanes;
mod onset;
mod record;
mod weights;
mod yielding;

pub(super) use record::Record;
use record::{Peaks, Signal, Sizes};
use yielding::Storeys;

use super::elements::Element;
use super::levels::Level;
use super::modal::{
    Modes, Propagator, StepIntegrals, doublings, integrals_over, powers, propagator, step_integrals,
};
use super::result::{BuildingEnergy, RawContact};
use super::slab::{SlabMark, SlabWaves};
use super::{BuildingScenario, ContactModel, SlabReading, Tracked};
use crate::model::control::{CHECK_EVERY, Control};
use crate::model::error::SolveError;
use crate::model::motion::GroundMotion;
use crate::model::root::bracket;

/// The time grid. The fine step h divides the record's step, so every sample of the record is a
/// grid point and the ground acceleration is linear over every free step.
#[derive(Debug, Clone, Copy)]
pub(super) struct Grid {
    pub h: f64,
    /// Fine steps per free step at most (a free step divides the record's step): the spacing of
    /// the histories' samples between contacts.
    pub per_free_step: usize,
    /// Fine steps a free stretch spans at most: a whole number of free steps, within a sample
    /// of the record.
    pub per_stretch: usize,
    /// Fine steps over the record.
    pub total: usize,
    /// Fine steps between two checks of a free stretch at most.
    pub check: usize,
    /// Contact steps the peaks' proofs take in one batch at most
    /// ([`Stepper::track_peaks_in_contact`]).
    pub read_every: usize,
    /// The spacing of the recorded samples inside contacts [s].
    pub contact_sample_s: f64,
    /// Where storeys yield: how far a storey's correction may depart from the line a piece of
    /// free motion takes it on, relative to the storey's force scale ([`Stepper::plan_piece`]).
    pub yield_departure: f64,
    /// The most forces each Sears slab keeps for drawing its waves (its part of
    /// [`SLAB_MEMORY_BUDGET`](super::super::solve::SLAB_MEMORY_BUDGET)).
    pub slab_share: usize,
    /// The most steps the run may take.
    pub max_steps: usize,
}

impl Grid {
    /// How many fine steps `len` is, where it is a whole number of them within a free stretch
    /// (whose exact maps and integrals the run keeps); `None` for another length (up to an
    /// event inside a step).
    pub fn whole_steps(&self, len: f64) -> Option<usize> {
        let steps = len / self.h;
        let whole = steps.round();
        ((steps - whole).abs() <= 1e-9 * steps.max(1.0))
            .then_some(whole as usize)
            .filter(|j| (1..=self.per_stretch).contains(j))
    }
}

/// One building in modal coordinates, with its precomputed exact steps.
struct Side {
    omega: Vec<f64>,
    zeta: Vec<f64>,
    gamma: Vec<f64>,
    /// `shapes[k][f]`: mode k at floor f.
    shapes: Vec<Vec<f64>>,
    /// `by_floor[f][k]`: the same, floor by floor, so a floor's sum over the modes reads
    /// consecutive memory.
    by_floor: Vec<Vec<f64>>,
    heights: Vec<f64>,
    q: Vec<f64>,
    v: Vec<f64>,
    /// Modal accelerations, kept inside contacts (Newmark).
    a: Vec<f64>,
    /// `sub[j n + k]`: mode k's exact step over (j + 1) h ([`Side::maps`]).
    sub: Vec<Propagator>,
    /// Integrals over a whole free stretch, per mode.
    full: Vec<StepIntegrals>,
    /// Integrals over j fine steps, per mode, computed when first needed.
    part: Vec<Option<Vec<StepIntegrals>>>,
    /// Per mode, the integrals and the exact map over 2^b fine steps, b = 0, 1, ...: any number of
    /// fine steps joins a few of them.
    doublings: Vec<Vec<(StepIntegrals, [[f64; 4]; 4])>>,
    /// Newmark's effective stiffness over h, per mode.
    k_hat: Vec<f64>,
    /// Per mode, 2 zeta omega and omega^2 (as the equations of motion multiply them out).
    damping: Vec<f64>,
    stiffness: Vec<f64>,
    /// The storeys' springs where they may yield (None: all elastic, nothing to correct).
    storeys: Option<Storeys>,
}

impl Side {
    fn new(modes: &Modes, heights: Vec<f64>, v0: f64, grid: &Grid) -> Self {
        let n = modes.count();
        let h = grid.h;
        // Every mode's exact steps over h, 2h, ..., a block of the modes per number of steps,
        // in one allocation.
        let mut each: Vec<_> = (0..n)
            .map(|k| powers(modes.omega_rad_s[k], modes.damping[k], h))
            .collect();
        let mut sub: Vec<Propagator> = Vec::with_capacity(grid.per_stretch * n);
        for _ in 0..grid.per_stretch {
            sub.extend(each.iter_mut().map(|p| p.next().expect("without end")));
        }
        let free_len = grid.per_stretch as f64 * h;
        Side {
            full: (0..n)
                .map(|k| step_integrals(modes.omega_rad_s[k], modes.damping[k], free_len))
                .collect(),
            k_hat: (0..n)
                .map(|k| newmark_k_hat(modes.omega_rad_s[k], modes.damping[k], h))
                .collect(),
            part: vec![None; grid.per_stretch + 1],
            doublings: (0..n)
                .map(|k| doublings(modes.omega_rad_s[k], modes.damping[k], h, grid.per_stretch))
                .collect(),
            damping: (0..n)
                .map(|k| 2.0 * modes.damping[k] * modes.omega_rad_s[k])
                .collect(),
            stiffness: modes.omega_rad_s.iter().map(|w| w * w).collect(),
            omega: modes.omega_rad_s.clone(),
            zeta: modes.damping.clone(),
            gamma: modes.participation.clone(),
            shapes: modes.shapes.clone(),
            by_floor: (0..heights.len())
                .map(|f| (0..n).map(|k| modes.shapes[k][f]).collect())
                .collect(),
            heights,
            q: vec![0.0; n],
            v: modes.participation.iter().map(|g| g * v0).collect(),
            a: vec![0.0; n],
            sub,
            storeys: None,
        }
    }

    fn modes(&self) -> usize {
        self.omega.len()
    }

    /// Every mode's exact step over j fine steps (1 <= j <= the stretch's steps).
    fn maps(&self, j: usize) -> &[Propagator] {
        let n = self.modes();
        &self.sub[(j - 1) * n..j * n]
    }

    fn energy(&self) -> f64 {
        (0..self.modes())
            .map(|k| 0.5 * (self.v[k].powi(2) + (self.omega[k] * self.q[k]).powi(2)))
            .sum()
    }

    /// Floor f's displacement from modal coordinates `q`.
    fn floor(&self, q: &[f64], f: usize) -> f64 {
        dotv(&self.by_floor[f], q)
    }

    /// Every floor's displacement from modal coordinates `q` into `out`: each floor's sum in
    /// the order [`Side::floor`] takes it (bit for bit), mode by mode over all floors at once,
    /// which the compiler can vectorise and a sum per floor it cannot.
    fn floors_into(&self, q: &[f64], out: &mut Vec<f64>) {
        out.clear();
        out.extend(self.shapes[0].iter().map(|s| s * q[0]));
        let n = out.len();
        let out = &mut out[..];
        // Four modes a pass, each floor's four terms added one after another as the mode-by-mode
        // loop adds them: the same sums, with a quarter of the loads and stores of `out`.
        let shapes = &self.shapes[1..];
        let q = &q[1..shapes.len() + 1];
        let mut blocks = shapes.chunks_exact(4).zip(q.chunks_exact(4));
        for (sh, qk) in blocks.by_ref() {
            let (s0, s1, s2, s3) = (&sh[0][..n], &sh[1][..n], &sh[2][..n], &sh[3][..n]);
            for f in 0..n {
                out[f] = out[f] + s0[f] * qk[0] + s1[f] * qk[1] + s2[f] * qk[2] + s3[f] * qk[3];
            }
        }
        let done = shapes.len() - shapes.len() % 4;
        for (shape, &qk) in shapes[done..].iter().zip(&q[done..]) {
            let shape = &shape[..n];
            for f in 0..n {
                out[f] += shape[f] * qk;
            }
        }
    }

    /// Mode k's load from the yielding storeys' corrections now (zero for elastic storeys).
    fn pseudo_now(&self, k: usize) -> f64 {
        self.storeys.as_ref().map_or(0.0, |st| st.load0[k])
    }
}

impl Side {
    /// Mode k's integrals over j fine steps, joined from its doublings.
    fn integrals_over(&self, k: usize, j: usize) -> StepIntegrals {
        integrals_over(&self.doublings[k], j)
    }
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
    /// The Euclidean size of `r[side]`: a change dq of a side's modes moves the point by at
    /// most this times the size of dq (Cauchy-Schwarz).
    norm: [f64; 2],
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
    /// The slabs' elastic displacement at grid index `n` (the newest step of a live slab).
    fn elastic_at(&self, n: usize) -> f64 {
        self.slabs.iter().flatten().map(|s| s.elastic_at(n)).sum()
    }

    /// What the newest force moves the slabs' planes by over one step (zero without slabs).
    fn instant_compliance(&self) -> f64 {
        self.slabs
            .iter()
            .flatten()
            .map(|s| s.instant_compliance())
            .sum()
    }

    /// A bound on the slabs' elastic displacement from grid index `n` on.
    fn elastic_bound_from(&self, n: usize) -> f64 {
        self.slabs
            .iter()
            .flatten()
            .map(|s| s.envelope_from(n))
            .sum()
    }
}

/// Fixed pseudo-random values in [0, 1) (a linear congruential generator's top 53 bits): the
/// same on every run, for the stepper's tests.
#[cfg(test)]
fn fixed_values(seed: u64, n: usize) -> Vec<f64> {
    let mut x = seed;
    (0..n)
        .map(|_| {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (x >> 11) as f64 / (1u64 << 53) as f64
        })
        .collect()
}

/// [`fixed_values`] spread over [-1, 1) (exactly: a power of two's scaling and a shift by one).
#[cfg(test)]
fn fixed_signed(seed: u64, n: usize) -> Vec<f64> {
    fixed_values(seed, n)
        .into_iter()
        .map(|u| 2.0 * u - 1.0)
        .collect()
}

/// [`lanes::dot`] out of the few modes' way: the loops that read a few modes' points keep
/// their registers, which the call inlined would take.
#[cold]
#[inline(never)]
fn dot_tall(a: &[f64], b: &[f64]) -> f64 {
    lanes::dot(a, b)
}

fn dotv(a: &[f64], b: &[f64]) -> f64 {
    dotv_of(a, b, a.len().min(b.len()))
}

/// [`dotv`] over the first n entries (a caller that knows n lets the compiler unroll the sum).
#[inline(always)]
fn dotv_of(a: &[f64], b: &[f64], n: usize) -> f64 {
    // Indexed: a few modes' loop without an iterator's set-up. The sum starts where
    // `Iterator::sum` starts for floats, at -0. A tall building's is taken in lanes.
    let (a, b) = (&a[..n], &b[..n]);
    if n >= lanes::LANES_FROM {
        return dot_tall(a, b);
    }
    let mut sum = -0.0;
    for k in 0..n {
        sum += a[k] * b[k];
    }
    sum
}

/// Modes from which a side is a tall building: its free stretches' bounds come from tables
/// and its signals and points are tested on where they are ([`weights`]). Below, a few modes'
/// sums are close to what they bound and cheaper taken one by one. (Its sums are taken in
/// vector lanes from [`lanes::LANES_FROM`] modes, the same count.)
const TALL: usize = 16;

/// The first fine step after an onset is split into steps of 1/2^G, 1/2^G, 1/2^(G-1), ... 1/2 of
/// it.
const ONSET_GRADING: u32 = 8;

/// Memory the recorded histories may take [bytes].
pub const SAMPLE_MEMORY_BUDGET: f64 = 2.0e9;

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
    /// n as a float, kept equal to it (by [`Stepper::at_step`], and by a contact step's advance
    /// of one): the time is read at every stage, and an unsigned integer's conversion is a
    /// sequence of operations on x86-64, not one.
    n_f: f64,
    offset: f64,
    pub ledger: Ledger,
    pub contacts: Vec<RawContact>,
    pub record: Record,
    signals: Vec<Signal>,
    /// The signals the run follows, with what the contact steps' proofs read of each, side by
    /// side in one array (the proofs run over every one of them once a batch of contact steps).
    watch: Vec<record::Watch>,
    /// The points' and the followed signals' |coefficients|, for a free stretch's bounds.
    bound_rows: weights::BoundRows,
    peaks: Peaks,
    /// What the proofs know of each signal.
    proof: Vec<record::Proof>,
    /// The contact steps since the proofs last looked at the signals.
    batch: record::Batch,
    pub steps: usize,
    pub contact_steps: usize,
    sears: bool,
    /// Whether the histories are recorded (not for a summary).
    histories: bool,
    /// The modal accelerations are Newmark's (the last step was a contact step).
    newmark: bool,
    /// A side is tall and elastic: a whole contact step's increments are taken in vector lanes.
    lanes_increment: bool,
    /// A side is tall: a contact step's modal loads are taken in vector lanes.
    tall: bool,
    /// One contact level, elastic sides of few modes, an element that does not let go inside
    /// a step: the level's contact steps on the grid after a contact step, with the level in
    /// contact, are the single level's (`contact/single.rs`).
    single_level: bool,
    /// The next free step is a planned piece (yielding storeys near or past their yield point).
    single_step: bool,
    /// Its length in fine steps, and the length the next one tries first.
    piece: usize,
    piece_guess: usize,
    /// Each level's largest closing motion is followed: in a run without contact, where it is
    /// the gap that avoids contact (a run with contact reports none).
    follow_closing: bool,
    /// Buffers, boxed so that a stage can take them out of the stepper for the step's length
    /// without copying them.
    scratch: Option<Box<Scratch>>,
    contact_scratch: Option<Box<contact::Scratch>>,
}

#[cfg(test)]
thread_local! {
    /// Set by a test on its own thread: the runs it starts take the general contact step only
    /// (to compare the single level's with it).
    static GENERAL_STEPS_ONLY: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
    /// The single level's contact steps taken on this thread.
    static SINGLE_STEPS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

/// Buffers the free stretch reuses, so its checks allocate nothing.
#[derive(Default)]
struct Scratch {
    y0: [Vec<[f64; 4]>; 2],
    q: [Vec<f64>; 2],
    v: [Vec<f64>; 2],
    /// Modal accelerations.
    acc: [Vec<f64>; 2],
    /// Each mode's bounds on its size and on its fourth and fifth derivatives over the stretch.
    size: [Vec<f64>; 2],
    m4: [Vec<f64>; 2],
    m5: [Vec<f64>; 2],
    /// And on its second derivative.
    m2: [Vec<f64>; 2],
    /// Each point's closing motion, its rate and acceleration at the last point looked at.
    prev: Vec<[f64; 3]>,
    /// Each signal's acceleration at its last instant.
    signal_acc: Vec<f64>,
    /// The bounds of each point's closing motion and of each signal, and of their rates.
    point_m4: Vec<f64>,
    point_m5: Vec<f64>,
    signal_m4: Vec<f64>,
    signal_m5: Vec<f64>,
    /// Per side, the bounds on each point's and each followed signal's size, its fourth and
    /// fifth derivatives and its second, by row of [`weights::BoundRows`].
    point_bounds: [[Vec<f64>; 4]; 2],
    signal_bounds: [[Vec<f64>; 4]; 2],
    /// What the stretch must be looked into for at all, and each depth of its halving.
    root: Depth,
    depths: Vec<Depth>,
    /// The live slabs' states before the grid step being walked.
    marks: Vec<[Option<SlabMark>; 2]>,
    /// Each side's modal displacements and velocities at a sample inside the stretch.
    inside: [[Vec<f64>; 2]; 2],
}

/// What a part at one depth of a stretch's halving must still be looked into for, of what its
/// parent left open: per point (an onset, its largest closing motion), per signal (its peak);
/// and every point's closing motion and every signal at the part's end, with their rates and
/// accelerations (points first).
///
/// The flags and values are indexed by point and signal, but only those of the parent's open
/// ones are written and read: the lists of what is open (ascending) are what the loops visit.
#[derive(Default)]
struct Depth {
    onset: Vec<bool>,
    closing: Vec<bool>,
    peak: Vec<bool>,
    values: Vec<[f64; 3]>,
    /// The points whose onset or largest closing motion is open, and the signals whose peak is.
    points: Vec<usize>,
    signals: Vec<usize>,
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
        histories: bool,
        tracked: Tracked,
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
        let mut sides = sides;
        for (side, b) in sides.iter_mut().zip([&sc.left, &sc.right]) {
            if b.yields() {
                let mut st = Storeys::new(b.storey_laws(), &side.shapes);
                st.set_rates(&side.v);
                side.storeys = Some(st);
            }
        }
        let sears = sc.contact == ContactModel::Sears;
        let zones = if sc.reading == SlabReading::Paper {
            sc.zone_lengths(levels)
        } else {
            vec![0.0; levels.len()]
        };
        let points: Vec<Point> = levels
            .iter()
            .zip(zones)
            .map(|(level, zone)| {
                // A summary's slabs keep no forces: their waves are not drawn.
                let share = if histories { grid.slab_share } else { 0 };
                new_point(sc, &sides, (level, zone), grid.h, sears, share)
            })
            .collect();
        let signals = Signal::all(&sides, &points, tracked);
        let lanes_increment = sides
            .iter()
            .any(|s| s.storeys.is_none() && s.modes() >= lanes::LANES_FROM);
        let tall = sides.iter().any(|s| s.modes() >= lanes::LANES_FROM);
        let single_level = points.len() == 1
            && !tall
            && sides.iter().all(|s| s.storeys.is_none())
            && sc.contact != ContactModel::Kelvin;
        #[cfg(test)]
        let single_level = single_level && !GENERAL_STEPS_ONLY.with(|g| g.get());
        let contact_scratch =
            contact::Scratch::sized([sides[0].modes(), sides[1].modes()], points.len());
        let mut s = Stepper {
            sc,
            motion,
            grid,
            peaks: Peaks::new(signals.len()),
            proof: vec![record::Proof::NONE; signals.len()],
            batch: record::Batch::new([sides[0].modes(), sides[1].modes()]),
            record: Record::new(
                sc.left.storeys,
                sc.right.storeys,
                levels.len(),
                grid.contact_sample_s,
            )
            .with_shears([&sc.left, &sc.right].map(|b| if b.yields() { b.storeys } else { 0 })),
            watch: record::Watch::all(&signals),
            bound_rows: weights::BoundRows::new(
                [sides[0].modes(), sides[1].modes()],
                &points,
                &signals,
            ),
            signals,
            sides,
            points,
            n: 0,
            n_f: 0.0,
            offset: 0.0,
            ledger: Ledger::default(),
            contacts: Vec::new(),
            steps: 0,
            contact_steps: 0,
            sears,
            histories,
            newmark: false,
            lanes_increment,
            tall,
            single_level,
            single_step: false,
            piece: 1,
            piece_guess: 1,
            follow_closing: sc.contact == ContactModel::None,
            scratch: Some(Box::default()),
            contact_scratch: Some(contact_scratch),
        };
        s.ledger.initial_j = s.sides[0].energy() + s.sides[1].energy();
        for p in s.points.iter_mut() {
            p.max_closing = 0.0;
        }
        s.track_peaks_now();
        s.record_now();
        s
    }

    /// Each side's number of modes.
    fn mode_counts(&self) -> [usize; 2] {
        [self.sides[0].modes(), self.sides[1].modes()]
    }

    fn time(&self) -> f64 {
        self.n_f * self.grid.h + self.offset
    }

    /// Moves the run to grid index n.
    fn at_step(&mut self, n: usize) {
        self.n = n;
        self.n_f = n as f64;
    }

    /// The modal ground forcing at `t`: g_k = -Gamma_k a_g(t), and its slope over the record
    /// interval that starts at or before t.
    pub(super) fn ground(&self, t: f64) -> (f64, f64) {
        let dt = self.motion.dt_s;
        // t >= 0: truncation is the floor.
        let i = (((t / dt) + 1e-9) as usize) as f64;
        let t0 = i * dt;
        let slope = (self.motion.at(t0 + dt) - self.motion.at(t0)) / dt;
        (self.motion.at(t), slope)
    }

    fn count_step(&mut self) -> Result<(), SolveError> {
        self.steps += 1;
        if self.steps > self.grid.max_steps {
            return Err(super::solve::step_budget(
                self.grid.max_steps,
                self.grid.h,
                self.time(),
            ));
        }
        Ok(())
    }

    /// Runs to the end of the record, telling `control` how far it got.
    pub fn run(&mut self, control: &Control) -> Result<(), SolveError> {
        self.run_watched(control, &mut |_| {})
    }

    /// The time reached [s].
    pub fn time_s(&self) -> f64 {
        self.time()
    }

    /// The energy ledger so far (the contacts' stored energy counted where they are open).
    pub fn energy_so_far(&self) -> BuildingEnergy {
        let stored: f64 = self
            .points
            .iter()
            .filter(|p| p.force > 0.0)
            .map(|p| p.element.stored_energy(p.delta))
            .sum();
        let l = self.ledger;
        let storeys = self
            .sides
            .iter()
            .filter_map(|s| s.storeys.as_ref().map(|st| (st, &s.q)));
        let (hysteretic, stored_less_elastic) = storeys.fold((0.0, 0.0), |(h, e), (st, q)| {
            (h + st.dissipated_j(), e + st.stored_less_elastic_j(q))
        });
        BuildingEnergy {
            initial_j: l.initial_j,
            input_j: l.input_j,
            building_damping_j: l.damping_j,
            contact_j: -l.contact_work_j - stored + l.exchanged_j,
            final_j: self.sides[0].energy() + self.sides[1].energy() + stored_less_elastic,
            stored_contact_j: stored,
            hysteretic_j: hysteretic,
        }
    }

    /// [`Stepper::run`], showing `watch` the run at every look at the control.
    pub fn run_watched(
        &mut self,
        control: &Control,
        watch: &mut dyn FnMut(&Stepper),
    ) -> Result<(), SolveError> {
        let end = self.grid.total;
        let mut looked_at = 0;
        let mut looked_steps = 0;
        // A step where storeys yield also moves every storey of its side: it costs about as
        // many elastic steps as the side has storeys, so the control is looked at as often in
        // time (a tall yielding pair streams its progress as an elastic one does).
        let storeys = self
            .sides
            .iter()
            .filter_map(|s| s.storeys.as_ref().map(Storeys::count))
            .max()
            .unwrap_or(1);
        let every = (CHECK_EVERY / storeys.max(1)).max(16);
        while self.n < end {
            // Look every `every` steps taken, and every CHECK_EVERY free stretches' worth of
            // the grid, whichever comes first.
            if self.n >= looked_at || self.steps >= looked_steps {
                control.report(self.n as f64 / end.max(1) as f64)?;
                self.check_bounded()?;
                self.check_memory()?;
                watch(self);
                looked_at = self.n + CHECK_EVERY * self.grid.per_free_step;
                looked_steps = self.steps + every;
            }
            if self.points.iter().any(|p| p.force > 0.0) {
                self.contact_step()?;
                continue;
            }
            // The free motion's plans and commits follow the storeys from where they stand.
            self.sync_storeys();
            self.close_batch();
            if self.offset > 0.0 {
                // Back onto the grid after an event inside a step.
                let mut piece = self.grid.h - self.offset;
                if self.yields() {
                    self.plan_free(piece);
                    piece = self.step_to_first_event(piece);
                }
                if let Some(level) = self.free_partial(piece)? {
                    self.onset_in_partial(level, piece)?;
                }
                continue;
            }
            self.single_step = self.yields() && !self.plan_stretch();
            if self.single_step {
                // A storey's law changing branch inside the piece: up to there first, the whole
                // fine steps before it as a piece of their own (a step off the grid is checked
                // at its end only, and a Sears slab's onset only on the grid).
                let planned = self.planned_piece();
                let first = self.first_storey_event(planned);
                if first < planned {
                    let whole = (first / self.grid.h + 1e-9) as usize;
                    if whole == 0 {
                        self.plan_free(first);
                        if let Some(level) = self.free_partial(first)? {
                            self.onset_in_partial(level, first)?;
                        }
                        continue;
                    }
                    self.piece = whole;
                    self.plan_free(whole as f64 * self.grid.h);
                }
            }
            match self.free_step()? {
                Free::Done => {}
                Free::Onset { j, level } => self.onset(j, level)?,
            }
        }
        self.check_bounded()
    }

    /// Stops a run whose histories outgrow [`SAMPLE_MEMORY_BUDGET`] (checked every few thousand
    /// steps, so at most that many samples past it are ever held).
    fn check_memory(&self) -> Result<(), SolveError> {
        if self.record.bytes() <= SAMPLE_MEMORY_BUDGET {
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
                "the contacts handed the buildings {:.3e} J against {:.3e} J that entered; {}",
                l.contact_work_j,
                entered,
                divergence_hint(self.sc)
            ),
        })
    }

    /// The contact elements' energy at the end, and the buildings'.
    pub fn finish(&mut self, end_s: f64) -> (BuildingEnergy, bool) {
        self.close_batch();
        let energy = self.energy_so_far();
        let still = self.points.iter().any(|p| p.force > 0.0);
        for p in self.points.iter_mut() {
            if let Some(c) = p.open.take() {
                self.contacts[c].end_s = end_s;
            }
        }
        if self.record.last_time() < end_s {
            self.record_now();
        }
        (energy, still)
    }

    /// The stepper of a run that follows each level's largest closing motion only where
    /// `follow` (a run without contact follows it unless told not to; a run with contact never).
    pub fn following_closings(mut self, follow: bool) -> Self {
        self.follow_closing &= follow;
        self
    }

    /// Each level's largest closing motion: empty where the run did not follow it.
    pub fn max_closing(&self) -> Vec<f64> {
        if !self.follow_closing {
            return Vec::new();
        }
        self.points.iter().map(|p| p.max_closing).collect()
    }

    pub fn max_forces(&self) -> Vec<f64> {
        self.points.iter().map(|p| p.max_force).collect()
    }

    /// The Sears slabs of every level, given up (none for the other elements).
    pub fn take_slabs(&mut self) -> Vec<[Option<SlabWaves>; 2]> {
        if !self.sears {
            return vec![];
        }
        self.points
            .iter_mut()
            .map(|p| std::mem::take(&mut p.slabs))
            .collect()
    }
}

/// A contact point at `level`: its element, its projections onto both buildings' modes and, for
/// the Sears contact, its slabs (read at `zone` from their contact ends).
fn new_point(
    sc: &BuildingScenario,
    sides: &[Side; 2],
    (level, zone): (&Level, f64),
    h: f64,
    sears: bool,
    share: usize,
) -> Point {
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
    let slabs = sc.level_slabs(level);
    let slab = |i: usize| {
        slabs[i].filter(|_| sears).map(|(slab, mass)| {
            SlabWaves::new(
                &slab,
                mass,
                zone,
                sc.slab_damping,
                h,
                if i == 0 { -1.0 } else { 1.0 },
                share,
            )
        })
    };
    Point {
        element,
        norm: std::array::from_fn(|s| r[s].iter().map(|x| x * x).sum::<f64>().sqrt()),
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

/// What to change when a run diverges, for the element that diverged: only the Sears paper
/// reading has a reading to change.
fn divergence_hint(sc: &BuildingScenario) -> &'static str {
    if sc.contact == ContactModel::Sears && sc.reading == SlabReading::Paper {
        "the Sears paper reading does this above a tau = pi/2 (use contact.reading = end or a softer contact.stiffness)"
    } else {
        "use a softer contact.stiffness or a smaller solver.max_step"
    }
}
