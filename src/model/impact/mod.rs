//! Impact models behind one interface: `solve(model, scenario)` returns one [`ImpactResult`].
//!
//! Each model produces its raw histories and contact events; [`finish`] turns them into the
//! quantities every front end reports (impulse, rigid-body velocities, restitution, energy split).

pub mod energy;
pub mod estimate;
pub mod fe;
pub mod lumped;
pub mod sears;
pub mod timestep;
pub mod warning;
pub mod wave;

pub use sears::Workspace;
pub use warning::{KeptBecause, Outside, VALIDATED, Warning};

use crate::model::control::Control;

use super::contact::{ContactLaw, LawKind, hertz_stiffness};
use super::error::InputError;
use super::field::BarWaves;
use super::scenario::{ImpactScenario, Reading};
use std::time::Instant;

/// Energy created (relative to the kinetic energy of the relative motion) above which the paper
/// reading is said to create energy. The reading is never exactly conservative: on the paper's
/// base case (a tau = 0.12) it creates 0.115%, the same at every step size, so that is the
/// formula, not the numerics. The balance is reported with every result; the warning marks the
/// regimes where the creation matters (a tau beyond about 0.4).
pub const ENERGY_CREATION_TOL: f64 = 1e-2;

/// The impact models.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModelKind {
    /// Sears: contact law + stress waves, in the reading chosen by the scenario.
    Sears,
    /// Saint-Venant wave theory: rigid contact between elastic bars.
    Wave,
    /// Rigid masses with a Hertz contact.
    LumpedHertz,
    /// Rigid masses with a linear spring.
    LumpedLinear,
    /// Rigid masses with a Kelvin-Voigt (spring + dashpot) link tuned to a restitution.
    Kelvin,
    /// Instantaneous velocity exchange with a restitution coefficient.
    Stereo,
    /// Distributed-mass finite elements with a contact link between the end nodes.
    Fe,
}

impl ModelKind {
    /// Every model, in the order the front ends list them.
    pub const ALL: [ModelKind; 7] = [
        ModelKind::Sears,
        ModelKind::Wave,
        ModelKind::LumpedHertz,
        ModelKind::LumpedLinear,
        ModelKind::Kelvin,
        ModelKind::Stereo,
        ModelKind::Fe,
    ];

    /// Every model's name, in the order of [`ModelKind::ALL`].
    pub const NAMES: [&'static str; 7] = crate::model::names_of!(Self::ALL, 7);

    /// The name the command line and presets use.
    pub const fn name(self) -> &'static str {
        match self {
            ModelKind::Sears => "sears",
            ModelKind::Wave => "wave",
            ModelKind::LumpedHertz => "lumped-hertz",
            ModelKind::LumpedLinear => "lumped-linear",
            ModelKind::Kelvin => "kelvin",
            ModelKind::Stereo => "stereo",
            ModelKind::Fe => "fe",
        }
    }

    /// The model of that name.
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == s)
    }

    /// The contact law the model uses on `sc`, if it uses one (wave theory and stereomechanics
    /// have none): the one place that maps a model to its law.
    pub fn law(self, sc: &ImpactScenario) -> Option<Result<ContactLaw, InputError>> {
        match self {
            ModelKind::Sears | ModelKind::Fe => Some(sc.contact_law()),
            ModelKind::LumpedHertz => Some(sc.hertz_law()),
            ModelKind::LumpedLinear | ModelKind::Kelvin => Some(Ok(sc.linear_law())),
            ModelKind::Wave | ModelKind::Stereo => None,
        }
    }

    /// The kind of law the model uses on `sc`, without building it.
    pub fn law_kind(self, sc: &ImpactScenario) -> Option<LawKind> {
        match self {
            ModelKind::Sears | ModelKind::Fe => Some(sc.contact.law),
            ModelKind::LumpedHertz => Some(LawKind::Hertz),
            ModelKind::LumpedLinear | ModelKind::Kelvin => Some(LawKind::Linear),
            ModelKind::Wave | ModelKind::Stereo => None,
        }
    }

    /// What the model needs of `sc` beyond the ranges: only what it uses ("leave out what a
    /// given scene does not need"). The Hertz law needs a rounded end or a stiffness, but wave
    /// theory and stereomechanics have no contact law.
    pub fn validate(self, sc: &ImpactScenario) -> Result<(), InputError> {
        sc.validate()?;
        if self.law_kind(sc) == Some(LawKind::Hertz)
            && !(sc.contact.law == LawKind::Hertz && sc.contact.stiffness.is_some())
            && hertz_stiffness(&sc.bar1, &sc.bar2).is_none()
        {
            return Err(InputError::new(
                crate::model::settings::impact::CONTACT_LAW.key,
                "hertz needs a rounded end on at least one bar (bar1.end_radius or bar2.end_radius), or an explicit contact.stiffness; both ends are flat",
            ));
        }
        // A Kelvin-Voigt link that cannot pull reaches e = 0 only with infinite damping
        // (e ~ 1 / (4 xi^2)); stereomechanics takes e = 0 as a plastic impact.
        if self == ModelKind::Kelvin && sc.contact.restitution <= 0.0 {
            return Err(InputError::new(
                crate::model::settings::impact::RESTITUTION.key,
                format!(
                    "{} is not allowed for kelvin: a link that cannot pull gives e = 0 only with infinite damping; must lie in (0, 1]",
                    crate::model::settings::shown(sc.contact.restitution)
                ),
            ));
        }
        Ok(())
    }

    /// Whether the model conserves energy (an elastic contact and elastic bodies).
    pub fn energy_consistent(self, reading: Reading) -> bool {
        match self {
            ModelKind::Sears => reading.energy_consistent(),
            ModelKind::Kelvin => false,
            ModelKind::Stereo => false,
            _ => true,
        }
    }
}

/// A contact counts as loaded while its force exceeds this fraction of its peak. The bars can
/// go on touching at zero force (a short bar on a longer one of equal impedance, after the short
/// one's round trip), and there the touching time is decided by round-off noise; the loaded time
/// is what wave theory calls the contact duration.
pub const LOADED_FRACTION: f64 = 1e-6;

/// Where the loaded interval ends (starts) within this fraction of its length of the touching
/// interval's end (start), the touching instant is kept: the solver locates it exactly, where the
/// threshold crossing is read off the samples. A smooth contact (force to zero at separation)
/// thereby keeps its exact duration.
pub const SNAP_FRACTION: f64 = 1e-3;

/// One interval of contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactEvent {
    /// When the bars (the planes, in the paper reading) first touch.
    pub start_s: f64,
    /// When they part; `None` when the contact is still on at the end of the simulated span.
    pub end_s: Option<f64>,
    /// When the force first exceeds [`LOADED_FRACTION`] of the peak.
    pub loaded_start_s: f64,
    /// When it last falls below that; `None` when still loaded at the end of the span.
    pub loaded_end_s: Option<f64>,
    /// Largest force of this contact [N].
    pub peak_force_n: f64,
    /// Integral of its force [N s].
    pub impulse_ns: f64,
}

impl ContactEvent {
    /// The contact duration: how long the force stays above [`LOADED_FRACTION`] of its peak.
    pub fn duration_s(&self) -> Option<f64> {
        self.loaded_end_s.map(|e| e - self.loaded_start_s)
    }

    /// How long the bars touch, loaded or not.
    pub fn touching_s(&self) -> Option<f64> {
        self.end_s.map(|e| e - self.start_s)
    }
}

/// The loaded part of the contact [start, end] of sampled force, by [`LOADED_FRACTION`] of
/// `peak`, crossings interpolated linearly and snapped to the touching ends by
/// [`SNAP_FRACTION`].
pub(crate) fn loaded_interval(
    time: Times,
    force: &[f64],
    start: f64,
    end: Option<f64>,
    peak: f64,
) -> (f64, Option<f64>) {
    let lo = time.partition_point(|t| t < start);
    let hi = time
        .partition_point(|t| t <= end.unwrap_or(f64::INFINITY))
        .min(force.len());
    let threshold = LOADED_FRACTION * peak;
    let above = |i: &usize| force[*i] > threshold;
    let (Some(first), Some(last)) = ((lo..hi).find(above), (lo..hi).rfind(above)) else {
        return (start, end);
    };
    let cross = |a: usize, b: usize| {
        let (fa, fb) = (force[a], force[b]);
        if fa == fb {
            time.at(a)
        } else {
            time.at(a) + (threshold - fa) / (fb - fa) * (time.at(b) - time.at(a))
        }
    };
    let mut loaded_start = if first > lo {
        cross(first - 1, first)
    } else {
        start
    };
    let mut loaded_end = if last + 1 < hi {
        Some(cross(last, last + 1))
    } else {
        end
    };
    let length = loaded_end.unwrap_or(time.at(last)) - loaded_start;
    if loaded_start - start <= SNAP_FRACTION * length {
        loaded_start = start;
    }
    if let (Some(e), Some(le)) = (end, loaded_end)
        && e - le <= SNAP_FRACTION * length
    {
        loaded_end = Some(e);
    }
    (loaded_start, loaded_end)
}

/// Where the initial kinetic energy went [J].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EnergySplit {
    /// Kinetic energy before impact [J].
    pub initial_j: f64,
    /// Kinetic energy of the bars' rigid-body motion at the end of the run.
    pub rigid_body_j: f64,
    /// Energy left in the bars' vibration (waves) at the end of the run.
    pub vibration_j: f64,
    /// Energy dissipated by a damped contact.
    pub dissipated_j: f64,
    /// Energy still stored in the contact at the end of the run.
    pub contact_j: f64,
    /// (final total - initial) divided by the kinetic energy of the relative motion (the part
    /// an impact can redistribute; it does not depend on the frame): positive where energy was
    /// created, negative where it was lost.
    pub balance_error: f64,
}

/// What only the Sears model reports.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SearsDiagnostics {
    /// The reading used.
    pub reading: Reading,
    /// Zone lengths d_i after the user's scale [m].
    pub zone_lengths_m: [f64; 2],
    /// Delays d_i / c_i of the paper's planes [s].
    pub plane_delays_s: [f64; 2],
    /// Contact tangent stiffness at the peak force [N/m].
    pub tangent_stiffness_n_m: f64,
    /// Validity number a tau = k_t sum(tau_i / Z_i): above 1/e the paper reading overshoots,
    /// above pi/2 it oscillates and can create energy.
    pub a_tau: f64,
    /// Whether this run created more than [`ENERGY_CREATION_TOL`] of the initial energy.
    pub creates_energy: bool,
}

impl SearsDiagnostics {
    /// How this run's reading behaved, in words every front end shows: the energy check comes
    /// first (a run that created energy is never called well behaved, whatever its a tau), then
    /// a tau's regime, which rates the paper reading's delayed planes only.
    pub fn regime(&self) -> &'static str {
        match self.reading {
            Reading::Paper if self.creates_energy => "created energy (see the energy balance)",
            Reading::Paper if self.a_tau < (-1f64).exp() => "well behaved (< 1/e)",
            Reading::Paper if self.a_tau < std::f64::consts::FRAC_PI_2 => {
                "overshoot regime (1/e .. pi/2)"
            }
            Reading::Paper => "oscillating regime (> pi/2)",
            Reading::Collocated | Reading::End => "rates the paper reading, not this one",
        }
    }
}

/// What a solve cost.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SolveStats {
    /// Steps taken.
    pub steps: usize,
    /// The step used [s].
    pub dt_s: f64,
    /// The user's step when the solver refined it.
    pub refined_from_s: Option<f64>,
    /// Wall time of the solve alone [s].
    pub wall_time_s: f64,
}

/// The result of one impact solve.
#[derive(Debug, Clone)]
pub struct ImpactResult {
    /// The model that produced it.
    pub model: ModelKind,
    /// Whether the bars met at all (they must be approaching).
    pub impact: bool,
    /// Sample times [s].
    pub time_s: Vec<f64>,
    /// Contact force at the samples [N].
    pub force_n: Vec<f64>,
    /// Approach of the contact (of the planes P_i in the paper reading) [m].
    pub approach_m: Vec<f64>,
    /// Every contact interval in the simulated span.
    pub contacts: Vec<ContactEvent>,
    /// Duration of the first contact [s]: how long its force stays above [`LOADED_FRACTION`]
    /// of its peak (0 for an instantaneous or no impact).
    pub contact_duration_s: f64,
    /// How long the bars touch in the first contact, loaded or not [s].
    pub touching_duration_s: f64,
    /// Peak force of the run [N]; `None` for stereomechanics (an instantaneous exchange).
    pub peak_force_n: Option<f64>,
    /// Total impulse of the run [N s].
    pub impulse_ns: f64,
    /// The bars' masses [kg].
    pub masses_kg: [f64; 2],
    /// The bars' velocities before impact [m/s].
    pub initial_velocities_m_s: [f64; 2],
    /// Rigid-body velocities at the end of the run.
    pub velocities_after_m_s: [f64; 2],
    /// Effective restitution (V2 - V1) / (v1 - v2) at the end of the run.
    pub restitution: f64,
    /// The same after the first contact alone (what the paper reports).
    pub restitution_first_contact: f64,
    /// Where the initial kinetic energy went.
    pub energy: EnergySplit,
    /// What only the Sears model reports.
    pub sears: Option<SearsDiagnostics>,
    /// Wave histories of both bars, for stress and velocity anywhere (d'Alembert models).
    pub waves: Option<[BarWaves; 2]>,
    /// Impulse so far at each of `time_s` [N s], as the model integrates it: it ends at
    /// `impulse_ns`.
    pub impulse_history_ns: Vec<f64>,
    /// Energy the contact has dissipated by each of `time_s` [J] (zeros for elastic contacts).
    pub dissipated_history_j: Vec<f64>,
    /// Finite elements only: the kinetic and strain energy of both bars' own elements [J] at
    /// some of `time_s` (indices into it), counted node by node and spring by spring, so it
    /// checks the energy the other parts report instead of following from them.
    pub elastic_samples: Option<ElasticSamples>,
    /// End of the simulated span [s].
    pub end_s: f64,
    /// What the reader must know besides the numbers.
    pub warnings: Vec<Warning>,
    /// What the solve cost.
    pub stats: SolveStats,
}

/// The elastic energy of a discretised model's bars at some of its samples.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ElasticSamples {
    /// Indices into the result's `time_s`, increasing.
    pub index: Vec<usize>,
    /// Kinetic plus strain energy of both bars at those samples [J] (the rigid-body motion's
    /// kinetic energy included).
    pub energy_j: Vec<f64>,
}

/// The bars' rigid-body velocities after the contact has passed impulse `j`: bar 1 slowed by
/// j/m1, bar 2 pushed on by j/m2 (momentum is exchanged, never made).
pub fn rigid_velocities([v1, v2]: [f64; 2], [m1, m2]: [f64; 2], j: f64) -> [f64; 2] {
    [v1 - j / m1, v2 + j / m2]
}

impl ImpactResult {
    /// The impulse the contact has passed by time `t` [N s], from the model's own history
    /// (linear between its samples; a stereomechanical impact passes all of it at t = 0).
    pub fn impulse_at(&self, t: f64) -> f64 {
        crate::model::xt::interpolate(&self.time_s, &self.impulse_history_ns, t)
    }

    /// The bars' rigid-body velocities at time `t` [m/s].
    pub fn rigid_velocities_at(&self, t: f64) -> [f64; 2] {
        rigid_velocities(
            self.initial_velocities_m_s,
            self.masses_kg,
            self.impulse_at(t),
        )
    }

    /// The span worth showing: the impact and a round trip of the waves after it (the whole
    /// run where that is longer) [s].
    pub fn view_span_s(&self) -> f64 {
        let rt = self
            .waves
            .as_ref()
            .map_or(0.0, |w| w[0].round_trip_s().max(w[1].round_trip_s()));
        (self.end_s + rt).max(self.end_s * 1.5).max(1e-6)
    }

    /// Start of the second contact, if the bars touched again within the simulated span.
    pub fn recontact_s(&self) -> Option<f64> {
        self.contacts.get(1).map(|c| c.start_s)
    }
}

pub use crate::model::error::SolveError;

/// What a model hands to [`finish`].
/// One contact interval as a solver records it: when it began, when it ended (`None` while it is
/// still open) and the impulse it passed; its peak is taken from the force samples later.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ContactSpan {
    /// When the bars began to touch [s].
    pub start_s: f64,
    /// When they parted [s]; `None` while the contact is open.
    pub end_s: Option<f64>,
    /// The impulse the contact passed [N s] (set when it closes).
    pub impulse_ns: f64,
}

impl ContactSpan {
    /// A contact that opens at `start_s`.
    pub fn opening(start_s: f64) -> Self {
        ContactSpan {
            start_s,
            end_s: None,
            impulse_ns: 0.0,
        }
    }

    /// A contact over [start_s, end_s] that passed `impulse_ns`.
    pub fn closed(start_s: f64, end_s: f64, impulse_ns: f64) -> Self {
        ContactSpan {
            start_s,
            end_s: Some(end_s),
            impulse_ns,
        }
    }

    /// Closes it at `end_s`, having passed `impulse_ns`.
    pub fn close(&mut self, end_s: f64, impulse_ns: f64) {
        self.end_s = Some(end_s);
        self.impulse_ns = impulse_ns;
    }
}

#[derive(Debug, Default)]
pub(crate) struct Raw {
    pub time_s: Vec<f64>,
    pub force_n: Vec<f64>,
    pub approach_m: Vec<f64>,
    /// Each contact; peaks are taken from the samples.
    pub contacts: Vec<ContactSpan>,
    pub impulse_ns: f64,
    pub masses_kg: [f64; 2],
    pub vibration_j: f64,
    pub dissipated_j: f64,
    pub contact_j: f64,
    pub end_s: f64,
    pub waves: Option<[BarWaves; 2]>,
    /// Impulse so far at each sample, as the model integrates it (empty: [`finish`] takes the
    /// trapezoid rule over the force samples).
    pub impulse_history_ns: Vec<f64>,
    /// Energy a damped contact has dissipated by each sample (empty: none).
    pub dissipated_history_j: Vec<f64>,
    /// The bars' elastic energy at some samples, where the model counts it (finite elements).
    pub elastic_samples: Option<ElasticSamples>,
    pub peak_override_n: Option<Option<f64>>,
    pub sears: Option<SearsDiagnostics>,
    pub warnings: Vec<Warning>,
    pub steps: usize,
    pub dt_s: f64,
    pub refined_from_s: Option<f64>,
}

/// Warnings for each input outside the validated box.
pub fn outside_validated_range(sc: &ImpactScenario) -> Vec<Warning> {
    let mut out = vec![];
    let mut flag = |what: Outside| out.push(Warning::OutsideValidated(what));
    if let Ok(law) = sc.contact_law()
        && !(1e4..=1e16).contains(&law.stiffness)
    {
        flag(Outside::Stiffness(law.stiffness));
    }
    let w = sc.approach_velocity_m_s();
    if w > 0.0 && !(1e-6..=1e3).contains(&w) {
        flag(Outside::ApproachVelocity(w));
    }
    let (l1, l2) = (sc.bar1.length_m, sc.bar2.length_m);
    if l1.max(l2) / l1.min(l2) > 1e4 {
        flag(Outside::LengthRatio(l1.max(l2) / l1.min(l2)));
    }
    if !(1e-4..=10.0).contains(&sc.contact.zone_scale) {
        flag(Outside::ZoneScale(sc.contact.zone_scale));
    }
    for (i, b) in [&sc.bar1, &sc.bar2].into_iter().enumerate() {
        let own = b.material.density_kg_m3 * b.area_m2() * b.length_m;
        if b.added_mass_kg > 1000.0 * own {
            flag(Outside::AddedMass {
                bar: i + 1,
                kg: b.added_mass_kg,
                times_own: b.added_mass_kg / own,
            });
        }
    }
    out
}

/// Closes a contact still open at the end of the run: its impulse so far, and a warning.
pub(crate) fn close_open_contact(
    contacts: &mut [ContactSpan],
    impulse_ns: f64,
    contact_start_impulse_ns: f64,
    end_s: f64,
    warnings: &mut Vec<Warning>,
) {
    if let Some(c) = contacts.last_mut()
        && c.end_s.is_none()
    {
        c.impulse_ns = impulse_ns - contact_start_impulse_ns;
        warnings.push(Warning::ContactOpenAtEnd { end_s });
    }
}

/// What a sweep reports of one impact: the numbers of [`ImpactResult`] without its histories.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactSummary {
    /// Whether the bars met at all.
    pub impact: bool,
    /// Peak force of the run [N]; `None` for stereomechanics.
    pub peak_force_n: Option<f64>,
    /// The first contact's duration (force above [`LOADED_FRACTION`] of its peak) [s].
    pub contact_duration_s: f64,
    /// How long the bars touch in the first contact [s].
    pub touching_duration_s: f64,
    /// Effective restitution at the end of the run.
    pub restitution: f64,
    /// The same after the first contact alone.
    pub restitution_first_contact: f64,
    /// Total impulse [N s].
    pub impulse_ns: f64,
    /// Contact intervals in the simulated span.
    pub contacts: usize,
    /// Start of the second contact, if any [s].
    pub recontact_s: Option<f64>,
}

impl ImpactResult {
    /// The numbers a sweep reports.
    pub fn summary(&self) -> ImpactSummary {
        ImpactSummary {
            impact: self.impact,
            peak_force_n: self.peak_force_n,
            contact_duration_s: self.contact_duration_s,
            touching_duration_s: self.touching_duration_s,
            restitution: self.restitution,
            restitution_first_contact: self.restitution_first_contact,
            impulse_ns: self.impulse_ns,
            contacts: self.contacts.len(),
            recontact_s: self.recontact_s(),
        }
    }
}

/// A contact (start, end, impulse) with its peak and loaded interval read off the samples.
fn contact_event(
    time: Times,
    force: &[f64],
    ContactSpan {
        start_s,
        end_s,
        impulse_ns,
    }: ContactSpan,
) -> ContactEvent {
    let peak_force_n = peak_between(time, force, start_s, end_s.unwrap_or(f64::INFINITY));
    let (loaded_start_s, loaded_end_s) = loaded_interval(time, force, start_s, end_s, peak_force_n);
    ContactEvent {
        start_s,
        end_s,
        loaded_start_s,
        loaded_end_s,
        peak_force_n,
        impulse_ns,
    }
}

/// Effective restitution after impulse `j`: (V2 - V1) / (v1 - v2), 1 where the bars do not
/// approach.
fn restitution_after(sc: &ImpactScenario, [m1, m2]: [f64; 2], j: f64) -> f64 {
    let (v1, v2) = (sc.bar1.velocity_m_s, sc.bar2.velocity_m_s);
    let w = v1 - v2;
    if w > 0.0 {
        let [after1, after2] = rigid_velocities([v1, v2], [m1, m2], j);
        (after2 - after1) / w
    } else {
        1.0
    }
}

/// The summary from a run's contacts and force samples, by the same arithmetic as [`finish`]
/// (so a summary and a full result agree bit for bit).
pub(crate) fn summarize(
    sc: &ImpactScenario,
    contacts: &[ContactSpan],
    time: Times,
    force: &[f64],
    impulse_ns: f64,
    masses: [f64; 2],
) -> ImpactSummary {
    let first = contacts.first().map(|&c| contact_event(time, force, c));
    let peak = contacts
        .iter()
        .map(|c| peak_between(time, force, c.start_s, c.end_s.unwrap_or(f64::INFINITY)))
        .fold(0.0, f64::max);
    ImpactSummary {
        impact: sc.approach_velocity_m_s() > 0.0,
        peak_force_n: Some(peak),
        contact_duration_s: first.and_then(|c| c.duration_s()).unwrap_or(0.0),
        touching_duration_s: first.and_then(|c| c.touching_s()).unwrap_or(0.0),
        restitution: restitution_after(sc, masses, impulse_ns),
        restitution_first_contact: restitution_after(
            sc,
            masses,
            first.map_or(0.0, |c| c.impulse_ns),
        ),
        impulse_ns,
        contacts: contacts.len(),
        recontact_s: contacts.get(1).map(|c| c.start_s),
    }
}

/// [`solve`] reduced to its summary, through a workspace kept between calls: the Sears model
/// keeps no histories and, once `ws` has seen a run as long, allocates nothing; the other
/// models solve in full and summarise.
pub fn summary_with(
    model: ModelKind,
    scenario: &ImpactScenario,
    ws: &mut Workspace,
) -> Result<ImpactSummary, SolveError> {
    if model != ModelKind::Sears || scenario.approach_velocity_m_s() <= 0.0 {
        return solve(model, scenario).map(|r| r.summary());
    }
    model.validate(scenario)?;
    sears::summary(scenario, Control::never(), ws)
}

/// Solve one impact with the chosen model.
pub fn solve(model: ModelKind, scenario: &ImpactScenario) -> Result<ImpactResult, SolveError> {
    solve_with(model, scenario, Control::never())
}

/// [`solve`], reporting progress to `control` and stopping when it is cancelled.
pub fn solve_with(
    model: ModelKind,
    scenario: &ImpactScenario,
    control: &Control,
) -> Result<ImpactResult, SolveError> {
    model.validate(scenario)?;
    let start = Instant::now();
    let w = scenario.approach_velocity_m_s();
    let mut raw = if w <= 0.0 {
        no_impact(model, scenario)
    } else {
        match model {
            ModelKind::Sears => sears::solve(scenario, control)?,
            ModelKind::Wave => wave::solve(scenario, control)?,
            ModelKind::LumpedHertz | ModelKind::LumpedLinear => {
                let law = model.law(scenario).expect("a lumped model has a law")?;
                lumped::solve_elastic(scenario, law, control)?
            }
            ModelKind::Kelvin => lumped::solve_kelvin(scenario, control)?,
            ModelKind::Stereo => lumped::solve_stereo(scenario),
            ModelKind::Fe => fe::solve(scenario, control)?,
        }
    };
    let wall = start.elapsed().as_secs_f64();
    raw.warnings.extend(outside_validated_range(scenario));
    if w <= 0.0 {
        raw.warnings
            .push(Warning::NotApproaching { approach_m_s: w });
    }
    let mut result = finish(model, scenario, raw);
    result.stats.wall_time_s = wall;
    if let Some(d) = &mut result.sears {
        d.creates_energy = result.energy.balance_error > ENERGY_CREATION_TOL;
        if d.creates_energy {
            result.warnings.push(Warning::PaperCreatesEnergy {
                percent: 100.0 * result.energy.balance_error,
                a_tau: d.a_tau,
            });
        } else if d.reading == Reading::Paper && d.a_tau > (-1f64).exp() {
            result
                .warnings
                .push(Warning::PaperOvershoots { a_tau: d.a_tau });
        }
    }
    Ok(result)
}

fn no_impact(model: ModelKind, sc: &ImpactScenario) -> Raw {
    let _ = model;
    Raw {
        time_s: vec![0.0],
        force_n: vec![0.0],
        approach_m: vec![0.0],
        masses_kg: [sc.bar1.mass_kg(), sc.bar2.mass_kg()],
        peak_override_n: Some(Some(0.0)),
        dt_s: sc.solver.dt_s,
        ..Raw::default()
    }
}

/// Sample times: stored, or the uniform grid k h of a solve that keeps no time array (the same
/// numbers either way, so a summary and a full result agree bit for bit).
#[derive(Debug, Clone, Copy)]
pub(crate) enum Times<'a> {
    Stored(&'a [f64]),
    Uniform { h: f64, len: usize },
}

impl Times<'_> {
    fn len(&self) -> usize {
        match self {
            Times::Stored(t) => t.len(),
            Times::Uniform { len, .. } => *len,
        }
    }

    fn at(&self, k: usize) -> f64 {
        match self {
            Times::Stored(t) => t[k],
            Times::Uniform { h, .. } => k as f64 * h,
        }
    }

    /// The first index whose time fails `pred` (which holds on a prefix).
    fn partition_point(&self, pred: impl Fn(f64) -> bool) -> usize {
        let (mut lo, mut hi) = (0, self.len());
        while lo < hi {
            let mid = lo + (hi - lo) / 2;
            if pred(self.at(mid)) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        lo
    }
}

/// Peak of sampled data between two times, refined by a parabola through the largest sample and
/// its neighbours (the samples alone miss a smooth maximum by O(dt^2)).
pub(crate) fn peak_between(time: Times, force: &[f64], start: f64, end: f64) -> f64 {
    let lo = time.partition_point(|t| t < start);
    let hi = time.partition_point(|t| t <= end);
    let hi = hi.min(force.len());
    let (fmax, i) = if lo < hi {
        first_max(&force[lo..hi]).map_or((0.0, usize::MAX), |(k, f)| (f, lo + k))
    } else {
        (0.0, usize::MAX)
    };
    if i == usize::MAX || i == 0 || i + 1 >= force.len() {
        return fmax;
    }
    let (t0, t1, t2) = (time.at(i - 1), time.at(i), time.at(i + 1));
    let (f0, f1, f2) = (force[i - 1], force[i], force[i + 1]);
    // Only on a uniform, strictly interior stencil; jumps (wave theory) keep the sample.
    let h = t1 - t0;
    if h <= 0.0 || ((t2 - t1) - h).abs() > 1e-9 * h || f0 <= 0.0 || f2 <= 0.0 {
        return fmax;
    }
    let denom = f0 - 2.0 * f1 + f2;
    // A parabola only where the samples resolve a smooth maximum (second difference small against
    // the peak); at a kink or an unresolved rise it would invent an overshoot.
    if denom >= 0.0 || -denom > 0.01 * f1 {
        return fmax;
    }
    let x = 0.5 * (f0 - f2) / denom;
    if x.abs() > 1.0 {
        return fmax;
    }
    f1 - 0.25 * (f0 - f2) * x
}

/// The largest positive value and the first index holding it (`None` where none is
/// positive). Two passes: the maximum four lanes at a time (the compiler vectorises it), then
/// its first position; a single pass that tracks the index cannot be vectorised.
fn first_max(xs: &[f64]) -> Option<(usize, f64)> {
    let mut lanes = [0.0f64; 4];
    let chunks = xs.chunks_exact(4);
    let rest = chunks.remainder();
    for c in chunks {
        for (m, &x) in lanes.iter_mut().zip(c) {
            *m = if x > *m { x } else { *m };
        }
    }
    let mut top = 0.0f64;
    for &x in lanes.iter().chain(rest) {
        top = if x > top { x } else { top };
    }
    (top > 0.0)
        .then(|| xs.iter().position(|&x| x == top).map(|k| (k, top)))
        .flatten()
}

/// The integral of `y` over `t` from the start to each sample.
fn cumulative_trapezoid(t: &[f64], y: &[f64]) -> Vec<f64> {
    let mut out = Vec::with_capacity(t.len());
    let mut sum = 0.0;
    for i in 0..t.len() {
        if i > 0 {
            sum += 0.5 * (y[i] + y[i - 1]) * (t[i] - t[i - 1]);
        }
        out.push(sum);
    }
    out
}

fn finish(model: ModelKind, sc: &ImpactScenario, raw: Raw) -> ImpactResult {
    let [m1, m2] = raw.masses_kg;
    let (v1, v2) = (sc.bar1.velocity_m_s, sc.bar2.velocity_m_s);
    let w = v1 - v2;
    let after = |j: f64| rigid_velocities([v1, v2], [m1, m2], j);
    let contacts: Vec<ContactEvent> = raw
        .contacts
        .iter()
        .map(|&c| contact_event(Times::Stored(&raw.time_s), &raw.force_n, c))
        .collect();
    let peak_force_n = match raw.peak_override_n {
        Some(p) => p,
        None => Some(contacts.iter().map(|c| c.peak_force_n).fold(0.0, f64::max)),
    };
    let velocities_after_m_s = after(raw.impulse_ns);
    let initial_j = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2;
    let rigid_body_j =
        0.5 * m1 * velocities_after_m_s[0].powi(2) + 0.5 * m2 * velocities_after_m_s[1].powi(2);
    let total = rigid_body_j + raw.vibration_j + raw.dissipated_j + raw.contact_j;
    // Measure the balance against the energy that can change hands: the kinetic energy of the
    // relative motion (the centre of mass keeps the rest whatever happens).
    let relative_j = 0.5 * m1 * m2 / (m1 + m2) * w * w;
    let balance_error = if relative_j > 0.0 {
        (total - initial_j) / relative_j
    } else {
        0.0
    };
    let first = contacts.first();
    let impulse_history_ns = if raw.impulse_history_ns.len() == raw.time_s.len() {
        raw.impulse_history_ns
    } else {
        cumulative_trapezoid(&raw.time_s, &raw.force_n)
    };
    let dissipated_history_j = if raw.dissipated_history_j.len() == raw.time_s.len() {
        raw.dissipated_history_j
    } else {
        vec![0.0; raw.time_s.len()]
    };
    ImpactResult {
        model,
        impact: w > 0.0,
        contact_duration_s: first.and_then(|c| c.duration_s()).unwrap_or(0.0),
        touching_duration_s: first.and_then(|c| c.touching_s()).unwrap_or(0.0),
        restitution_first_contact: restitution_after(
            sc,
            raw.masses_kg,
            first.map(|c| c.impulse_ns).unwrap_or(0.0),
        ),
        restitution: restitution_after(sc, raw.masses_kg, raw.impulse_ns),
        time_s: raw.time_s,
        force_n: raw.force_n,
        approach_m: raw.approach_m,
        contacts,
        peak_force_n,
        impulse_ns: raw.impulse_ns,
        masses_kg: raw.masses_kg,
        initial_velocities_m_s: [v1, v2],
        velocities_after_m_s,
        energy: EnergySplit {
            initial_j,
            rigid_body_j,
            vibration_j: raw.vibration_j,
            dissipated_j: raw.dissipated_j,
            contact_j: raw.contact_j,
            balance_error,
        },
        sears: raw.sears,
        impulse_history_ns,
        dissipated_history_j,
        elastic_samples: raw.elastic_samples,
        waves: raw.waves,
        end_s: raw.end_s,
        warnings: raw.warnings,
        stats: SolveStats {
            steps: raw.steps,
            dt_s: raw.dt_s,
            refined_from_s: raw.refined_from_s,
            wall_time_s: 0.0,
        },
    }
}
