//! A pounding run from start to result: the grid, the stepper, and what is reported.

use super::elements::Element;
use super::levels::Level;
use super::modal::Modes;
use super::result::{
    BuildingEnergy, BuildingResult, BuildingStats, ImpactEvent, RawContact, SlabRecord,
    group_impacts,
};
use super::stepper::{Grid, Record, Stepper};
use super::{BuildingScenario, ContactModel, SlabReading, Warning};
use crate::model::contact::ContactLaw;
use crate::model::control::Control;
use crate::model::error::SolveError;
use crate::model::impact::timestep::contact_time_scale;
use crate::model::motion::GroundMotion;
use std::time::Instant;

/// The most fine steps one free step spans (its exact sub-steps are precomputed).
pub(super) const MAX_FREE_STEP: usize = 4096;

/// How far a yielding storey's correction may depart from the line a piece of free motion takes
/// it on, in its middle, relative to the tolerance and to the storey's force scale: the
/// line's error in the response goes as that departure (a load error of that share of the
/// storey's force), and so does the energy ledger's gap.
const YIELD_DEPARTURE: f64 = 0.01;

/// Memory the Sears slabs' forces, kept for drawing their waves, may take [bytes]: 8 bytes a
/// force, shared out equally between the slabs. A slab keeps every grid point's force while they
/// fit in its share and every second one of those each time they outgrow it, so that this memory
/// is set by the number of slabs, never by the steps, and the step is not coarsened for it. 100
/// storeys a side (200 slabs) keep up to 160 000 forces each, and take about 4 000 each over 8 s
/// of El Centro: all of them.
pub const SLAB_MEMORY_BUDGET: f64 = 2.56e8;

/// The contact's own time scale at a level: the rise of a wave-limited force or the lumped
/// contact's period (1 m/s bounds the Hertzian elements' scale from below: pounding velocities
/// are a fraction of that).
fn level_scale(sc: &BuildingScenario, level: &Level, m_eff: f64) -> f64 {
    let k = sc.level_stiffness(level);
    let law = if sc.contact.is_hertzian() {
        ContactLaw::hertz(k)
    } else {
        ContactLaw::linear(k)
    };
    let z_eff = if sc.contact == ContactModel::Sears {
        sc.level_series_impedance_n_s_m(level)
    } else {
        f64::INFINITY
    };
    let mut resolve = contact_time_scale(&law, 1.0, m_eff, z_eff).resolve_s;
    if sc.contact == ContactModel::Kelvin {
        let c = Element::new(sc.contact, k, sc.restitution, m_eff).kelvin_damping();
        if c > 0.0 {
            resolve = resolve.min(m_eff / c);
        }
    }
    resolve
}

/// The effective mass of the two buildings at a level: the inverse of the point's velocity
/// change per unit impulse.
fn level_mass(level: &Level, modes: &[super::modal::Modes; 2]) -> f64 {
    let attach = [level.left, level.right];
    let inverse: f64 = (0..2)
        .map(|s| {
            let w = attach[s].weights();
            (0..modes[s].count())
                .map(|k| {
                    let r: f64 = w.iter().map(|(f, x)| x * modes[s].shapes[k][*f]).sum();
                    r * r
                })
                .sum::<f64>()
        })
        .sum();
    1.0 / inverse
}

/// The grid for a run: fine enough for the contact's time scale (steps per scale from the
/// tolerance) and for the peaks of the motion, within the step budget (the slabs' memory sets
/// only how many of their forces they keep for drawing). `refine` divides every step the
/// tolerance sets and multiplies the budget: the error estimate's companion.
fn plan(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    levels: &[Level],
    modes: &[super::modal::Modes; 2],
    refine: u32,
) -> (Grid, Option<Warning>) {
    let dt = motion.dt_s;
    let duration = motion.duration_s();
    let steps = sc.steps_per_scale();
    let scale = if sc.contact == ContactModel::None {
        f64::INFINITY
    } else {
        levels
            .iter()
            .map(|l| level_scale(sc, l, level_mass(l, modes)))
            .fold(f64::INFINITY, f64::min)
    };
    // A peak sampled h apart is missed by at most (w h)^2 / 8 of itself: within a quarter of
    // the tolerance.
    let w1 = modes[0].omega_rad_s[0].max(modes[1].omega_rad_s[0]);
    let peaks = (2.0 * sc.tolerance).sqrt() / w1;
    // A refined run (the error estimate's companion) divides every step the tolerance sets,
    // and has a step budget as many times larger: a run held to its budget's step is refined
    // too, not held at the same step (its estimate would be zero).
    let wanted = ((scale / steps).min(peaks) / f64::from(refine))
        .min(dt)
        .min(sc.max_step_s);
    let max_steps = refined_budget(sc.max_steps, refine);
    let floor = duration / (0.5 * max_steps as f64);
    let held = wanted < floor;
    let h = wanted.max(floor);
    let slabs = if sc.contact == ContactModel::Sears {
        levels
            .iter()
            .map(|l| sc.level_slabs(l).iter().flatten().count())
            .sum::<usize>()
    } else {
        0
    };
    // Free steps divide the record's step, and fine steps the free step, so that every free
    // step but the first after a contact has the same, precomputed, exact map. A free step
    // spans MAX_FREE_STEP fine steps at most: where the fine step is shorter than that allows,
    // the free steps are (a free step held to the longest one would coarsen the fine step).
    let per_sample = |longest: f64| ((dt / longest) * (1.0 - 1e-12)).ceil().max(1.0) as usize;
    let free_per_sample = per_sample(sc.max_step_s).max(per_sample(h * MAX_FREE_STEP as f64));
    let free = dt / free_per_sample as f64;
    let per_free_step = ((free / h) * (1.0 - 1e-12))
        .ceil()
        .clamp(1.0, MAX_FREE_STEP as f64) as usize;
    let h = dt / (free_per_sample * per_free_step) as f64;
    let warning = held.then_some(Warning::GridOverBudget {
        scale_s: scale,
        wanted_s: wanted,
        used_s: h,
        max_steps: sc.max_steps,
    });
    let total = ((duration / h) - 1e-9).ceil().max(0.0) as usize;
    let per_stretch = stretch_steps(sc, modes, free_per_sample, per_free_step);
    // A free stretch is checked every 2.4 / w_max at most: between two checks the cubic through
    // them is then within (2.4^4 / 384) of the motion's amplitude (a part in 12), so that a check
    // clears all but the parts that come close to the gap or to a peak, and those are halved.
    // Denser checks clear more of each stretch but cost more checks than they save; sparser
    // ones leave whole stretches to be halved. What a run finds is the same whatever the
    // spacing, bit for bit: only the bounds' work changes.
    let w_max = modes
        .iter()
        .flat_map(|m| m.omega_rad_s.iter())
        .fold(0.0f64, |a, &w| a.max(w));
    let check = ((2.4 / w_max / h).floor() as usize).clamp(1, per_stretch);
    // Where storeys yield, a piece of free motion takes the correction linear in time: its
    // error goes as the correction's departure from that line over the piece, which each
    // piece measures ([`Grid::yield_departure`]); held to a share of the tolerance it refines
    // with the tolerance, and halves the pieces of a run refined twofold (the estimate's
    // companion), as the line's error goes as the square of the piece.
    let yield_departure = YIELD_DEPARTURE * sc.tolerance / f64::from(refine * refine);
    let slab_share = slab_share(slabs);
    // The peaks' proofs look at the signals once a batch of contact steps: at most a third of
    // the contact's time scale (steps per scale, not the step: the companion's batches are as
    // many of its steps, half as long), and at most 8 steps, past which a look costs little
    // more than the steps' sums of sizes.
    let read_every = ((steps / 3.0).floor() as usize).clamp(1, 8);
    #[cfg(test)]
    let read_every = tests::READ_EVERY.with(|r| r.get()).unwrap_or(read_every);
    (
        Grid {
            read_every,
            h,
            per_free_step,
            per_stretch,
            total,
            check,
            yield_departure,
            contact_sample_s: (scale / CONTACT_SAMPLES_PER_SCALE)
                .max(h)
                .max(duration / CONTACT_SAMPLE_BUDGET),
            slab_share,
            max_steps,
        },
        warning,
    )
}

/// The most exact maps a side keeps for the steps inside a free stretch (modes x fine steps):
/// 64 bytes each, 32 MiB a side: 100 storeys take it over a sample of El Centro for the run
/// (8.4 MiB a side) and for its companion at half its step (16.9 MiB a side).
const STRETCH_MAPS: usize = 1 << 19;

/// Fine steps a free stretch spans at most: a whole sample of the record, over which the ground
/// is linear and one exact map takes the motion anywhere (the free steps inside it only space
/// the histories' samples), so that a stretch is prepared and checked once a sample, not once a
/// free step. Where storeys yield (their pieces are planned free step by free step), or where a
/// side's maps over a sample would outgrow [`STRETCH_MAPS`], a stretch is a free step.
fn stretch_steps(
    sc: &BuildingScenario,
    modes: &[super::modal::Modes; 2],
    free_per_sample: usize,
    per_free_step: usize,
) -> usize {
    let per_sample = free_per_sample * per_free_step;
    let most_modes = modes.iter().map(|m| m.count()).max().unwrap_or(0);
    if sc.left.yields() || sc.right.yields() || most_modes * per_sample > STRETCH_MAPS {
        per_free_step
    } else {
        per_sample
    }
}

/// The most forces each of `slabs` slabs keeps for drawing its waves.
fn slab_share(slabs: usize) -> usize {
    if slabs == 0 {
        return 0;
    }
    let budget = SLAB_MEMORY_BUDGET;
    #[cfg(test)]
    let budget = tests::BUDGET.with(|b| b.get()).unwrap_or(budget);
    ((budget / (8.0 * slabs as f64)) as usize).max(1)
}

/// A run's step budget refined `refine` times: as many times the steps (beyond what a user may
/// set: the companion of a run held to the largest budget must still halve its step).
fn refined_budget(max_steps: usize, refine: u32) -> usize {
    max_steps.saturating_mul(refine as usize)
}

/// The fine step a run of `sc` under `motion` takes (its [`BuildingStats::fine_step_s`]),
/// planned without running it: what the error estimate's companion is refined from, so that it
/// can start beside the run.
///
/// [`BuildingStats::fine_step_s`]: super::BuildingStats::fine_step_s
pub fn planned_step_s(sc: &BuildingScenario, motion: &GroundMotion) -> Result<f64, SolveError> {
    Ok(planned(sc, motion, 1)?.grid.h)
}

/// What a run of `sc` under `motion` is made of before it steps: its levels, its buildings'
/// modes and its grid (with the grid's warning, if any).
struct Planned {
    levels: Vec<Level>,
    modes: [Modes; 2],
    grid: Grid,
    warning: Option<Warning>,
}

fn planned(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    refine: u32,
) -> Result<Planned, SolveError> {
    sc.validate()?;
    let levels = sc.levels();
    let modes = [sc.left.modes(), sc.right.modes()];
    let (grid, warning) = plan(sc, motion, &levels, &modes, refine);
    Ok(Planned {
        levels,
        modes,
        grid,
        warning,
    })
}

/// Samples recorded per contact time scale inside contacts: a force pulse is drawn by some tens
/// of points, whatever the step.
const CONTACT_SAMPLES_PER_SCALE: f64 = 8.0;

/// The most samples the contacts may add to a run's histories on their regular spacing (besides
/// one where each contact opens or closes): so that the histories' memory is set by the record's
/// length, not by how fine the contact steps are. A floor of 1 kg against the paper's buildings
/// stays in contact for 8 s on steps of 1.2 us: sampled every step, 2.1 million samples (215 MB
/// for the pair). On 8 s the spacing is then 20 us (30 us on the 12 s of the yielding preset),
/// finer than the 46-51 us the presets' contacts take, which their histories keep.
pub(super) const CONTACT_SAMPLE_BUDGET: f64 = 400_000.0;

/// Runs two buildings through a ground motion.
pub fn solve(sc: &BuildingScenario, motion: &GroundMotion) -> Result<BuildingResult, SolveError> {
    solve_with(sc, motion, Control::never())
}

/// [`solve`], reporting progress to `control` and stopping when it is cancelled.
pub fn solve_with(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    control: &Control,
) -> Result<BuildingResult, SolveError> {
    run_publishing(sc, motion, control, RunKind::FULL, None)
}

/// The run's summary alone: contacts, impacts, peaks, forces, energy and warnings, without the
/// histories and the slabs' waves (what an error estimate or a gap assessment compares).
pub fn solve_summary(
    sc: &BuildingScenario,
    motion: &GroundMotion,
) -> Result<BuildingResult, SolveError> {
    solve_summary_with(sc, motion, Control::never())
}

/// [`solve_summary`], reporting to `control`.
pub fn solve_summary_with(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    control: &Control,
) -> Result<BuildingResult, SolveError> {
    solve_summary_tracking(sc, motion, control, Tracked::All)
}

/// Which peaks a run keeps. A run made for one comparison tracks only the peaks it reads: each
/// signal's peak is found independently of the others, so those it keeps are bit for bit what a
/// run keeping all of them finds. The peaks it leaves out are NaN in its result.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tracked {
    /// Every floor, every storey's drift ratio, every contact point.
    All,
    /// The floors' displacements (what an error estimate compares).
    Floors,
    /// The floors at the contact levels (what a gap assessment reads).
    Levels,
}

/// [`solve_summary_with`], keeping only the peaks `tracked` names.
pub fn solve_summary_tracking(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    control: &Control,
    tracked: Tracked,
) -> Result<BuildingResult, SolveError> {
    run_publishing(sc, motion, control, RunKind::summary(tracked, 1), None)
}

/// [`solve_summary_tracking`] with every step the tolerance sets divided by `refine`, and a step
/// budget `refine` times larger: the error estimate's companion.
pub(super) fn solve_summary_refined(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    control: &Control,
    tracked: Tracked,
    refine: u32,
) -> Result<BuildingResult, SolveError> {
    run_publishing(sc, motion, control, RunKind::summary(tracked, refine), None)
}

/// A run without contact as a report sets it beside a run with contact (`histories` where the
/// report draws them): every peak and history of [`solve_with`] or [`solve_summary_with`], bit
/// for bit, without each level's largest closing motion (the gaps a gap assessment reads; its
/// `max_closing_m` is left empty), whose search on the exact motion a tall pair's run pays for.
pub(super) fn solve_comparison(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    control: &Control,
    histories: bool,
) -> Result<BuildingResult, SolveError> {
    let kind = if histories {
        RunKind::FULL
    } else {
        RunKind::summary(Tracked::All, 1)
    };
    let kind = RunKind {
        closings: false,
        ..kind
    };
    run_publishing(sc, motion, control, kind, None)
}

/// [`solve_with`], handing `publish` what the run has solved so far, at most once per `every`
/// of wall time (its histories to the instant solved, marked by
/// [`BuildingResult::solved_to_s`]), so a window can draw a long run while it solves. It is
/// called where the run looks at its control (every few thousand steps); `every` zero calls it
/// at each.
pub fn solve_streaming(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    control: &Control,
    every: std::time::Duration,
    publish: &mut dyn FnMut(BuildingResult),
) -> Result<BuildingResult, SolveError> {
    run_publishing(sc, motion, control, RunKind::FULL, Some((every, publish)))
}

/// How much wall time the window lets pass between two partial results of a long run.
pub const PUBLISH_EVERY: std::time::Duration = std::time::Duration::from_millis(40);

/// What a run keeps and how fine it is.
#[derive(Clone, Copy)]
struct RunKind {
    /// Its histories and the slabs' waves (not for a summary).
    histories: bool,
    tracked: Tracked,
    /// Every step the tolerance sets divided by this, the budget multiplied by it.
    refine: u32,
    /// Each level's largest closing motion is followed (in a run without contact).
    closings: bool,
}

impl RunKind {
    /// A run with everything a window or a report draws.
    const FULL: RunKind = RunKind {
        histories: true,
        tracked: Tracked::All,
        refine: 1,
        closings: true,
    };

    /// A summary keeping the peaks `tracked` names, refined `refine` times.
    fn summary(tracked: Tracked, refine: u32) -> Self {
        RunKind {
            histories: false,
            tracked,
            refine,
            closings: true,
        }
    }
}

/// What every run shares: the levels, the modes, the grid, the warnings known before it starts.
struct Setup {
    levels: Vec<Level>,
    modes: [Modes; 2],
    grid: Grid,
    warnings: Vec<Warning>,
    start: Instant,
}

fn run_publishing(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    control: &Control,
    kind: RunKind,
    publish: Option<(std::time::Duration, &mut dyn FnMut(BuildingResult))>,
) -> Result<BuildingResult, SolveError> {
    let RunKind {
        histories,
        tracked,
        refine,
        closings,
    } = kind;
    let start = Instant::now();
    let Planned {
        levels,
        modes,
        grid,
        warning: grid_warning,
    } = planned(sc, motion, refine)?;
    if grid.total > grid.max_steps {
        return Err(step_budget(grid.max_steps, grid.h, 0.0));
    }
    let mut warnings: Vec<Warning> = grid_warning.into_iter().collect();
    warnings.extend(paper_reading_warnings(sc, &levels));
    let setup = Setup {
        levels,
        modes,
        grid,
        warnings,
        start,
    };
    let mut stepper = Stepper::new(
        sc,
        motion,
        grid,
        &setup.levels,
        setup.modes.clone(),
        histories,
        tracked,
    )
    .following_closings(closings);
    match publish {
        None => stepper.run(control)?,
        Some((every, publish)) => {
            let (mut last, mut reached) = (Instant::now(), 0.0);
            let mut sink = |s: &Stepper| {
                if s.time_s() > reached && last.elapsed() >= every {
                    publish(partial(s, sc, &setup));
                    (last, reached) = (Instant::now(), s.time_s());
                }
            };
            stepper.run_watched(control, &mut sink)?
        }
    }
    Ok(finished(stepper, sc, setup, histories))
}

/// The result of a run that reached its end.
fn finished(
    mut stepper: Stepper,
    sc: &BuildingScenario,
    mut setup: Setup,
    histories: bool,
) -> BuildingResult {
    let grid = setup.grid;
    let end_s = grid.total as f64 * grid.h;
    let mut warnings = std::mem::take(&mut setup.warnings);
    let (energy, still) = stepper.finish(end_s);
    if still {
        warnings.push(Warning::InContactAtEnd { end_s });
    }
    let scale = energy.initial_j + energy.input_j.abs();
    if energy.residual_j().abs() > 1e-6 * scale || !energy.residual_j().is_finite() {
        warnings.push(Warning::CreatedEnergy {
            joules: energy.residual_j(),
            relative: energy.balance_error(),
        });
    }
    let slabs = SlabRecord::new(
        if histories {
            stepper.take_slabs()
        } else {
            vec![]
        },
        end_s,
    );
    let record = std::mem::replace(&mut stepper.record, Record::new(0, 0, 0, 0.0));
    let contacts = std::mem::take(&mut stepper.contacts);
    let mut r = assemble(&stepper, sc, &setup, record, contacts, energy, slabs, end_s);
    if sc.contact == ContactModel::Stereo {
        r.warnings.extend(stereo_chatter(&r.impacts));
    }
    r.warnings.splice(0..0, warnings);
    r
}

/// What a run has solved so far: its histories to now, the contacts so far (an open one up to
/// now), the peaks so far, the energy so far.
fn partial(stepper: &Stepper, sc: &BuildingScenario, setup: &Setup) -> BuildingResult {
    let now = stepper.time_s();
    let mut contacts = stepper.contacts.clone();
    for c in contacts.iter_mut().filter(|c| c.end_s < c.start_s) {
        c.end_s = now;
    }
    let mut r = assemble(
        stepper,
        sc,
        setup,
        stepper.record.clone(),
        contacts,
        stepper.energy_so_far(),
        SlabRecord::default(),
        now,
    );
    r.warnings = setup.warnings.clone();
    r
}

/// A result from the stepper's state and what was taken from it.
#[allow(clippy::too_many_arguments)]
fn assemble(
    stepper: &Stepper,
    sc: &BuildingScenario,
    setup: &Setup,
    h: Record,
    contacts: Vec<RawContact>,
    energy: BuildingEnergy,
    slabs: SlabRecord,
    solved_to_s: f64,
) -> BuildingResult {
    let roofs = [
        h.floors[0].last().cloned().unwrap_or_default(),
        h.floors[1].last().cloned().unwrap_or_default(),
    ];
    let max_by_level = stepper.max_forces();
    let impacts = group_impacts(&contacts, sc.merge_gap_s);
    let (peak_floor, peak_drift, peak_points) = stepper.peaks();
    let storeys = stepper.storey_summary([&sc.left, &sc.right], &peak_drift);
    let grid = setup.grid;
    BuildingResult {
        contact: sc.contact,
        levels: setup.levels.clone(),
        modes: setup.modes.clone(),
        time_s: h.time_s,
        ground_m_s2: h.ground,
        displacement_m: roofs,
        velocity_m_s: h.roof_v,
        acceleration_m_s2: h.roof_a,
        peak_displacement_m: [
            *peak_floor[0].last().unwrap_or(&0.0),
            *peak_floor[1].last().unwrap_or(&0.0),
        ],
        peak_floor_displacement_m: peak_floor,
        peak_drift_ratio: peak_drift,
        ductility_demand: storeys.ductility_demand,
        residual_drift_m: storeys.residual_drift_m,
        hysteretic_energy_j: storeys.hysteretic_energy_j,
        yield_drift_m: storeys.yield_drift_m,
        first_yield_s: storeys.first_yield_s,
        storey_shear_n: h.storey_shear,
        floor_displacement_m: h.floors,
        floor_velocity_m_s: h.floor_v,
        force_n: h.force,
        level_force_n: h.level_force,
        max_pounding_force_n: max_by_level.iter().cloned().fold(0.0, f64::max),
        max_force_by_level_n: max_by_level,
        max_closing_m: stepper.max_closing(),
        peak_level_displacement_m: peak_points,
        slabs,
        contacts,
        impacts,
        energy,
        stats: BuildingStats {
            steps: stepper.steps,
            contact_steps: stepper.contact_steps,
            fine_step_s: grid.h,
            coarse_step_s: grid.per_free_step as f64 * grid.h,
            steps_per_scale: sc.steps_per_scale(),
            wall_time_s: setup.start.elapsed().as_secs_f64(),
        },
        solved_to_s,
        warnings: vec![],
    }
}

/// The validity number of the paper reading at each level (docs/model.md), a tau = k sum(tau_i /
/// Z_i): a warning where it passes pi/2.
fn paper_reading_warnings(sc: &BuildingScenario, levels: &[Level]) -> Vec<Warning> {
    if !(sc.contact == ContactModel::Sears && sc.reading == SlabReading::Paper) {
        return vec![];
    }
    let mut warnings = vec![];
    for (i, (level, d)) in levels.iter().zip(sc.zone_lengths(levels)).enumerate() {
        let a_tau = sc.level_stiffness(level)
            * sc.level_slabs(level)
                .iter()
                .flatten()
                .map(|(s, m)| d / s.wave_speed_m_s(*m) / s.impedance_n_s_m(*m))
                .sum::<f64>();
        if a_tau > std::f64::consts::FRAC_PI_2 {
            warnings.push(Warning::PaperReadingUnstable { level: i, a_tau });
        }
    }
    warnings
}

/// Stereomechanics chattering: impacts of more than ten exchanges.
fn stereo_chatter(impacts: &[ImpactEvent]) -> Option<Warning> {
    let chattering: Vec<usize> = impacts
        .iter()
        .map(|e| e.contacts.len())
        .filter(|&n| n > 10)
        .collect();
    (!chattering.is_empty()).then(|| Warning::StereoChatter {
        impacts: chattering.len(),
        exchanges: chattering.iter().sum(),
    })
}

/// A building run over its step budget, with the building command's own keys as the remedy
/// (the impact scene's solver.dt and solver.window do not exist here).
pub(crate) fn step_budget(max_steps: usize, dt_s: f64, reached_s: f64) -> SolveError {
    SolveError::Input(crate::model::error::InputError::new(
        "solver.max_steps",
        format!(
            "step budget exceeded: the run needs more than solver.max_steps = {max_steps} steps (step {dt_s:e} s, reached t = {reached_s:e} s); raise solver.max_steps, or shorten the record with motion.duration"
        ),
    ))
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use std::cell::Cell;

    /// The first 8 s of the built-in El Centro record: the paper's run.
    pub(in crate::model::building) fn el_centro_8s() -> GroundMotion {
        crate::io::motion::built_in("elcentro-1940")
            .unwrap()
            .truncated(8.0)
    }

    thread_local! {
        /// The slabs' memory budget a test sets on its own thread.
        pub(super) static BUDGET: Cell<Option<f64>> = const { Cell::new(None) };
        /// The contact steps a batch of the peaks' proofs takes, as a test sets it.
        pub(super) static READ_EVERY: Cell<Option<usize>> = const { Cell::new(None) };
    }

    /// Peaks a batch of contact steps finds against those a look at every step finds: the
    /// cubic through a batch's ends against the steps' own cubics.
    #[test]
    fn peaks_looked_at_once_a_batch_of_contact_steps_are_the_steps_own_within_a_part_in_ten_million()
     {
        let m = el_centro_8s();
        let mut cases = Vec::new();
        for contact in [
            ContactModel::Sears,
            ContactModel::Kelvin,
            ContactModel::Hertz,
        ] {
            let setup: crate::io::building_settings::BuildingSetup =
                crate::io::preset::load_for("mdof-3-5", "buildings").expect("preset");
            let mut sc = setup.scenario;
            sc.contact = contact;
            cases.push(sc.clone());
            sc.left.storeys = 12;
            sc.right.storeys = 20;
            cases.push(sc);
        }
        for sc in cases {
            let grid = planned(&sc, &m, 1).expect("plan").grid;
            assert_eq!(
                grid.read_every, 8,
                "{:?}: batches of 8 at the default",
                sc.contact
            );
            let batched = solve(&sc, &m).expect("run");
            READ_EVERY.with(|r| r.set(Some(1)));
            let stepwise = solve(&sc, &m);
            READ_EVERY.with(|r| r.set(None));
            let stepwise = stepwise.expect("run");
            assert!(batched.stats.contact_steps > 1000, "{:?}", sc.contact);
            for s in 0..2 {
                let pairs = [
                    (
                        &batched.peak_floor_displacement_m[s],
                        &stepwise.peak_floor_displacement_m[s],
                    ),
                    (&batched.peak_drift_ratio[s], &stepwise.peak_drift_ratio[s]),
                ];
                for (a, b) in pairs {
                    for (x, y) in a.iter().zip(b) {
                        assert!(
                            (x - y).abs() <= 1e-7 * y.abs(),
                            "{:?}, {} storeys: {x} against {y}",
                            sc.contact,
                            sc.left.storeys
                        );
                    }
                }
            }
            assert_eq!(batched.max_pounding_force_n, stepwise.max_pounding_force_n);
        }
    }

    /// The paper's buildings, 100 storeys a side (200 slabs), over 8 s of El Centro.
    fn tall() -> (BuildingScenario, GroundMotion) {
        let mut setup: crate::io::building_settings::BuildingSetup =
            crate::io::preset::load_for("paper-buildings", "buildings").expect("preset");
        for a in ["left.storeys=100", "right.storeys=100"] {
            setup.apply_assignment(a).expect("key");
        }
        let m = crate::io::motion::load(&setup.motion).expect("record");
        (setup.scenario, m)
    }

    #[test]
    fn a_step_held_to_the_budget_is_no_longer_than_the_budget_allows() {
        // A 1 kg floor asks for a step of 1.4e-7 s; the budget of 20 million steps holds it to
        // 8e-7 s over 8 s. That is 6 250 steps a free step of 5 ms, more than one free step may
        // span: the free steps are shortened, not the fine step lengthened (it once was, to
        // 1.22e-6 s, while the warning said 8e-7 s).
        let mut sc = BuildingScenario::paper();
        sc.left.masses_kg = vec![1.0];
        let m = el_centro_8s();
        let run = planned(&sc, &m, 1).unwrap();
        let floor = m.duration_s() / (0.5 * sc.max_steps as f64);
        assert!(run.grid.h <= floor, "{} s against {floor} s", run.grid.h);
        assert!(run.grid.h > 0.999 * floor, "{} s", run.grid.h);
        assert!(run.grid.per_free_step <= MAX_FREE_STEP);
        match run.warning {
            Some(Warning::GridOverBudget { used_s, .. }) => assert_eq!(used_s, run.grid.h),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn two_hundred_slabs_keep_every_force_of_8_s_within_the_budget() {
        use crate::model::field::History;
        // The contacts of 8 s take about 4 000 steps a slab (120 000 contact steps over 100
        // levels, each in contact for a part of them): each slab keeps every one, drawn on the
        // run's own grid, and all of them together stay within the budget.
        let (sc, m) = tall();
        let r = solve(&sc, &m).unwrap();
        let mut kept = 0;
        let mut slabs = 0;
        for w in r.slab_waves().iter().flat_map(|l| l.iter().flatten()) {
            let History::Segments { dt_s, segments } = &w.history else {
                panic!("a slab's history is kept in stretches");
            };
            assert_eq!(*dt_s, r.stats.fine_step_s, "every grid point's force kept");
            kept += segments.iter().map(|s| s.values.len()).sum::<usize>();
            slabs += 1;
        }
        assert_eq!(slabs, 200);
        assert!(8.0 * kept as f64 <= SLAB_MEMORY_BUDGET, "{kept} samples");
    }

    #[test]
    fn a_refined_plan_halves_a_step_held_to_the_budget() {
        let (mut sc, m) = tall();
        sc.max_steps = 500_000;
        let run = planned(&sc, &m, 1).unwrap();
        let refined = planned(&sc, &m, 2).unwrap();
        assert!(run.warning.is_some(), "held to the budget");
        // Each grid divides the free step, rounding it by at most one step in a free step.
        let ratio = run.grid.h / refined.grid.h;
        let rounding = 2.0 / run.grid.per_free_step as f64;
        assert!((ratio - 2.0).abs() <= rounding, "{ratio}");
        assert_eq!(refined.grid.max_steps, 1_000_000);
    }

    #[test]
    fn the_companion_of_a_run_held_to_the_largest_budget_still_halves_its_step() {
        // The largest budget a user may set, and a tolerance no budget meets over 8 s.
        let (mut sc, m) = tall();
        sc.max_steps = 100_000_000;
        sc.tolerance = 1e-12;
        let run = planned(&sc, &m, 1).unwrap();
        // As the estimate plans it: its free step halved too where the run's spans the most fine
        // steps a free step may.
        let companion = super::super::estimate::companion_scenario(&sc, run.grid.h);
        let refined = planned(&companion, &m, 2).unwrap();
        assert!(run.warning.is_some(), "held to the budget");
        assert_eq!(refined.grid.max_steps, 200_000_000);
        let ratio = run.grid.h / refined.grid.h;
        assert!(
            (ratio - 2.0).abs() <= 2.0 / run.grid.per_free_step as f64,
            "{ratio}"
        );
    }

    #[test]
    fn slabs_over_their_share_draw_the_same_waves_and_leave_the_run_as_it_was() {
        use crate::model::field::History;
        let mut setup: crate::io::building_settings::BuildingSetup =
            crate::io::preset::load_for("paper-buildings", "buildings").expect("preset");
        setup.apply_assignment("motion.duration=3").expect("key");
        let m = crate::io::motion::load(&setup.motion).expect("record");
        let sc = &setup.scenario;
        let full = solve(sc, &m).unwrap();
        // A budget of 1 500 forces a slab: the contacts of 3 s take a few thousand.
        BUDGET.with(|b| b.set(Some(8.0 * 2.0 * 1500.0)));
        let thin = solve(sc, &m);
        BUDGET.with(|b| b.set(None));
        let thin = thin.unwrap();
        // What the run finds does not depend on what its drawing keeps.
        assert_eq!(thin.force_n, full.force_n);
        assert_eq!(thin.max_pounding_force_n, full.max_pounding_force_n);
        assert_eq!(
            thin.peak_floor_displacement_m,
            full.peak_floor_displacement_m
        );
        let segments = |h: &History| match h {
            History::Segments { dt_s, segments } => (*dt_s, segments.clone()),
            _ => panic!("a slab's history is kept in stretches"),
        };
        let mut thinned = 0;
        for (level_full, level_thin) in full.slab_waves().iter().zip(thin.slab_waves()) {
            for (a, b) in level_full.iter().zip(level_thin) {
                let (a, b) = (a.as_ref().unwrap(), b.as_ref().unwrap());
                let ((dt_a, seg_a), (dt_b, seg_b)) = (segments(&a.history), segments(&b.history));
                let keep = (dt_b / dt_a).round() as usize;
                assert!(keep.is_power_of_two() && (dt_b - keep as f64 * dt_a).abs() < 1e-12 * dt_b);
                let kept: usize = seg_b.iter().map(|s| s.values.len()).sum();
                let all: usize = seg_a.iter().map(|s| s.values.len()).sum();
                if keep > 1 {
                    thinned += 1;
                    assert!(kept < all, "{kept} of {all}");
                }
                // Off by no more than H changes over one kept step (a cubic look-up across the
                // force's kinks), found on the full history.
                let change = seg_a
                    .iter()
                    .flat_map(|s| s.values.windows(keep + 1).map(|w| (w[keep] - w[0]).abs()))
                    .fold(0.0f64, f64::max);
                let (mut worst, mut largest) = (0.0f64, 0.0f64);
                for i in 0..=6000 {
                    let t = full.time_s.last().unwrap() * i as f64 / 6000.0;
                    let (x, y) = (a.history_at(t), b.history_at(t));
                    worst = worst.max((x - y).abs());
                    largest = largest.max(x.abs());
                }
                assert!(largest > 0.0);
                assert!(
                    worst <= change,
                    "every {keep}: off by {worst:.3e}, H changing by {change:.3e} over a kept step"
                );
            }
        }
        assert_eq!(thinned, 2, "both slabs outgrew their share");
    }
}
