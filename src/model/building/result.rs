//! What a pounding run returns: histories, contacts grouped into impacts, peaks, the energy
//! ledger, statistics and warnings.

use super::levels::Level;
use super::modal::Modes;
use super::slab::SlabWaves;
use super::{ContactModel, Warning};
use crate::model::field::BarWaves;
use std::sync::OnceLock;

/// One interval of contact at one level.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RawContact {
    /// Index into [`BuildingResult::levels`].
    pub level: usize,
    /// Onset [s].
    pub start_s: f64,
    /// Separation [s].
    pub end_s: f64,
    /// Largest force [N].
    pub peak_force_n: f64,
    /// Integral of the force [N s].
    pub impulse_ns: f64,
    /// Relative approach velocity at onset [m/s].
    pub approach_velocity_m_s: f64,
}

/// Contacts at one level merged into one impact (closer than `merge_gap_s`).
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactEvent {
    /// Index into [`BuildingResult::levels`].
    pub level: usize,
    /// Onset of its first contact [s].
    pub start_s: f64,
    /// Separation of its last contact [s].
    pub end_s: f64,
    /// Largest force of its contacts [N].
    pub peak_force_n: f64,
    /// Sum of its contacts' impulses [N s].
    pub impulse_ns: f64,
    /// Relative approach velocity at its first onset [m/s].
    pub approach_velocity_m_s: f64,
    /// Indices into the raw contact list.
    pub contacts: Vec<usize>,
}

impl ImpactEvent {
    /// From the first onset to the last separation [s].
    pub fn duration_s(&self) -> f64 {
        self.end_s - self.start_s
    }
}

/// Where the energy went [J]. The ledger balances:
/// initial + input = damping + contact + final + stored.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BuildingEnergy {
    /// Kinetic and strain energy of the buildings at t = 0 (an initial velocity).
    pub initial_j: f64,
    /// Work of the ground's inertial forces on the buildings.
    pub input_j: f64,
    /// Energy dissipated by the buildings' damping [J].
    pub building_damping_j: f64,
    /// Energy the contact took from the buildings and did not give back (dissipated by a damped
    /// element or by the restitution of stereomechanics, or carried into the slabs' waves).
    pub contact_j: f64,
    /// Kinetic and strain energy of the buildings at the end.
    pub final_j: f64,
    /// Energy still stored in the contact elements at the end.
    pub stored_contact_j: f64,
    /// Energy the yielding storeys dissipated (their work less what they store) [J]; zero for
    /// elastic storeys.
    pub hysteretic_j: f64,
}

impl BuildingEnergy {
    /// What the ledger fails to account for [J]: positive where energy appeared from nowhere.
    pub fn residual_j(&self) -> f64 {
        self.building_damping_j
            + self.contact_j
            + self.final_j
            + self.stored_contact_j
            + self.hysteretic_j
            - self.initial_j
            - self.input_j
    }

    /// The residual relative to the energy that entered (initial plus input).
    pub fn balance_error(&self) -> f64 {
        let scale = (self.initial_j + self.input_j.abs()).max(f64::MIN_POSITIVE);
        self.residual_j() / scale
    }
}

/// What a run cost.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BuildingStats {
    /// Steps of every kind: contact steps, and the free stretches' looks at the exact motion
    /// (each part a stretch's halving checks, each grid point it walks). What a run does not
    /// follow is not looked for: a run without contact that follows each level's largest
    /// closing takes more looks than one that does not.
    pub steps: usize,
    /// Steps taken inside contacts.
    pub contact_steps: usize,
    /// The step inside contacts, and the spacing at which the free motion is checked [s].
    pub fine_step_s: f64,
    /// The longest free step [s].
    pub coarse_step_s: f64,
    /// Steps per contact time scale used inside contacts.
    pub steps_per_scale: f64,
    /// Wall time of the solve [s].
    pub wall_time_s: f64,
}

/// A level's slabs' waves (Sears): left and right, `None` where a column meets the floor.
pub type LevelWaves = [Option<BarWaves>; 2];

/// The Sears slabs as the run left them (the forces they were pushed with), and their waves,
/// worked out from those when first asked for: a run that is not drawn does not pay for them.
#[derive(Debug, Clone, Default)]
pub struct SlabRecord {
    slabs: Vec<[Option<SlabWaves>; 2]>,
    end_s: f64,
    waves: OnceLock<Vec<LevelWaves>>,
}

impl SlabRecord {
    /// The slabs of each level (empty for the other elements) at the end of a run at `end_s`.
    pub(super) fn new(slabs: Vec<[Option<SlabWaves>; 2]>, end_s: f64) -> Self {
        SlabRecord {
            slabs,
            end_s,
            waves: OnceLock::new(),
        }
    }

    /// Each level's slabs' waves.
    pub fn waves(&self) -> &[LevelWaves] {
        self.waves.get_or_init(|| {
            self.slabs
                .iter()
                .map(|pair| std::array::from_fn(|i| pair[i].as_ref().map(|s| s.waves(self.end_s))))
                .collect()
        })
    }
}

/// Everything one building run reports.
#[derive(Debug, Clone)]
pub struct BuildingResult {
    /// The element used.
    pub contact: ContactModel,
    /// The contact points, lowest first.
    pub levels: Vec<Level>,
    /// Both buildings' modes.
    pub modes: [Modes; 2],
    /// Sample times [s].
    pub time_s: Vec<f64>,
    /// Ground acceleration at the samples [m/s^2].
    pub ground_m_s2: Vec<f64>,
    /// Roof displacement relative to the ground [m].
    pub displacement_m: [Vec<f64>; 2],
    /// Roof velocity relative to the ground [m/s].
    pub velocity_m_s: [Vec<f64>; 2],
    /// Roof absolute acceleration [m/s^2].
    pub acceleration_m_s2: [Vec<f64>; 2],
    /// Every floor's displacement: `floor_displacement_m[side][floor][sample]` [m].
    pub floor_displacement_m: [Vec<Vec<f64>>; 2],
    /// Every floor's velocity relative to the ground [m/s].
    pub floor_velocity_m_s: [Vec<Vec<f64>>; 2],
    /// The pounding force summed over the levels [N].
    pub force_n: Vec<f64>,
    /// Each level's force: `level_force_n[level][sample]` [N].
    pub level_force_n: Vec<Vec<f64>>,
    /// Every contact, at every level, in time order.
    pub contacts: Vec<RawContact>,
    /// Contacts grouped into impacts (`merge_gap_s`).
    pub impacts: Vec<ImpactEvent>,
    /// Roof peaks |u| over the whole motion (located between samples too) [m].
    pub peak_displacement_m: [f64; 2],
    /// Every floor's peak |u| [m].
    pub peak_floor_displacement_m: [Vec<f64>; 2],
    /// Every storey's peak |u_j - u_{j-1}| / h_j.
    pub peak_drift_ratio: [Vec<f64>; 2],
    /// Every storey's peak drift over its yield drift F_y / k (the storey's ductility demand;
    /// for elastic storeys, against the yield force they are given or its default).
    pub ductility_demand: [Vec<f64>; 2],
    /// Every storey's drift at the end of the run [m].
    pub residual_drift_m: [Vec<f64>; 2],
    /// The energy each storey's spring dissipated [J] (zero for elastic storeys).
    pub hysteretic_energy_j: [Vec<f64>; 2],
    /// Every storey's yield drift F_y / k [m].
    pub yield_drift_m: [Vec<f64>; 2],
    /// When each yielding storey's drift first reached its yield drift [s] (`None`: never, or
    /// an elastic storey).
    pub first_yield_s: [Vec<Option<f64>>; 2],
    /// Each storey's shear force at the samples, `storey_shear_n[side][storey][sample]` [N], for
    /// a side whose storeys yield; empty for an elastic side.
    pub storey_shear_n: [Vec<Vec<f64>>; 2],
    /// Largest contact force of the run [N].
    pub max_pounding_force_n: f64,
    /// Largest contact force at each level [N].
    pub max_force_by_level_n: Vec<f64>,
    /// The largest |u| of each level's contact point on each side [m]: a floor's, or a column
    /// point's between two floors.
    pub peak_level_displacement_m: Vec<[f64; 2]>,
    /// The largest closing motion at each level, u_left - u_right at the point, over the run
    /// [m]: the smallest gap that avoids contact there. Only a run without contact follows it:
    /// empty for a run with contact, and for the run without contact that [`super::Checked`]
    /// sets beside a run with contact (the window's, the lessons' and `pounding gaps`' runs
    /// without contact follow it).
    pub max_closing_m: Vec<f64>,
    /// The Sears slabs at each level (empty for the other elements), whose waves
    /// [`BuildingResult::slab_waves`] gives.
    pub slabs: SlabRecord,
    /// Where the energy went.
    pub energy: BuildingEnergy,
    /// What the run cost.
    pub stats: BuildingStats,
    /// How far the run has solved [s]: the record's end once it has finished, less while a
    /// streaming solve hands out what it has so far.
    pub solved_to_s: f64,
    /// What the reader must know besides the numbers.
    pub warnings: Vec<Warning>,
}

impl BuildingResult {
    /// The Sears slabs' waves at each level (empty for the other elements).
    pub fn slab_waves(&self) -> &[LevelWaves] {
        self.slabs.waves()
    }

    /// Storey j's drift on a side at the samples: its floor's displacement less the one below
    /// (the ground's, zero, for the first storey) [m].
    pub fn storey_drift_m(&self, side: usize, j: usize) -> Vec<f64> {
        let floors = &self.floor_displacement_m[side];
        match j {
            0 => floors[0].clone(),
            _ => floors[j]
                .iter()
                .zip(&floors[j - 1])
                .map(|(a, b)| a - b)
                .collect(),
        }
    }

    /// Whether storey j on a side has yielded by time t.
    pub fn yielded_by(&self, side: usize, j: usize, t: f64) -> bool {
        self.first_yield_s[side]
            .get(j)
            .copied()
            .flatten()
            .is_some_and(|y| y <= t)
    }
}

/// Groups raw contacts into impact events, level by level: a contact starting within
/// `merge_gap_s` of the previous one's end at the same level joins its event. Events are listed
/// by start time.
pub fn group_impacts(contacts: &[RawContact], merge_gap_s: f64) -> Vec<ImpactEvent> {
    let mut out: Vec<ImpactEvent> = Vec::new();
    let mut open: Vec<Option<usize>> = Vec::new();
    for (i, c) in contacts.iter().enumerate() {
        if open.len() <= c.level {
            open.resize(c.level + 1, None);
        }
        match open[c.level] {
            Some(e) if c.start_s - out[e].end_s < merge_gap_s => {
                let ev = &mut out[e];
                ev.end_s = ev.end_s.max(c.end_s);
                ev.peak_force_n = ev.peak_force_n.max(c.peak_force_n);
                ev.impulse_ns += c.impulse_ns;
                ev.contacts.push(i);
            }
            _ => {
                open[c.level] = Some(out.len());
                out.push(ImpactEvent {
                    level: c.level,
                    start_s: c.start_s,
                    end_s: c.end_s,
                    peak_force_n: c.peak_force_n,
                    impulse_ns: c.impulse_ns,
                    approach_velocity_m_s: c.approach_velocity_m_s,
                    contacts: vec![i],
                })
            }
        }
    }
    out
}
