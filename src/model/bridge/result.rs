//! What a bridge run returns: histories at plot resolution, contacts grouped into impacts at
//! each joint, openings and seats, peaks, the energy ledger, statistics and warnings.

use super::scenario::Joint;
use crate::model::building::ContactModel;
use crate::model::building::result::{ImpactEvent, RawContact};
use crate::model::field::BarWaves;

/// A joint that opened further than its seat: when it first did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unseating {
    /// The joint (from 0, the left abutment's).
    pub joint: usize,
    /// When its opening first exceeded the seat length [s].
    pub time_s: f64,
}

/// Where the energy went [J]. The ledger balances:
/// initial + input + differential = damping + contact + girder waves + stored + final.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BridgeEnergy {
    /// Kinetic and strain energy of the frames at t = 0 (an initial velocity).
    pub initial_j: f64,
    /// Work of the ground's inertial forces on the frames (relative to their own ground).
    pub input_j: f64,
    /// Work the supports' different motions do through the joints: a joint squeezed by its
    /// two grounds moving towards each other takes that energy from the ground, not from the
    /// frames (zero under uniform excitation).
    pub differential_j: f64,
    /// Dissipated by the frames' damping.
    pub damping_j: f64,
    /// Dissipated by the contact elements (their dashpots, stereomechanics' restitution).
    pub contact_j: f64,
    /// Carried into the girders' axial waves (Sears): what they hold at the end and what their
    /// damping took.
    pub girder_waves_j: f64,
    /// Still stored in the contact elements at the end.
    pub stored_contact_j: f64,
    /// Kinetic and strain energy of the frames at the end.
    pub final_j: f64,
}

impl BridgeEnergy {
    /// What the ledger fails to account for [J].
    pub fn residual_j(&self) -> f64 {
        self.damping_j + self.contact_j + self.girder_waves_j + self.stored_contact_j + self.final_j
            - self.initial_j
            - self.input_j
            - self.differential_j
    }

    /// The residual relative to the energy that entered.
    pub fn balance_error(&self) -> f64 {
        let scale = (self.initial_j + self.input_j.abs() + self.differential_j.abs())
            .max(f64::MIN_POSITIVE);
        self.residual_j() / scale
    }
}

/// What a run cost.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BridgeStats {
    /// Steps taken.
    pub steps: usize,
    /// Steps with a joint in contact.
    pub contact_steps: usize,
    /// The step [s].
    pub step_s: f64,
    /// Steps per contact time scale.
    pub steps_per_scale: f64,
    /// Wall time of the solve [s].
    pub wall_time_s: f64,
}

/// Everything one bridge run reports.
#[derive(Debug, Clone)]
pub struct BridgeResult {
    /// The element used.
    pub contact: ContactModel,
    /// The joints, left abutment first.
    pub joints: Vec<Joint>,
    /// Sample times of the histories [s].
    pub time_s: Vec<f64>,
    /// Each joint's force at the samples [N].
    pub joint_force_n: Vec<Vec<f64>>,
    /// Each joint's opening at the samples (minus its closing) [m].
    pub joint_opening_m: Vec<Vec<f64>>,
    /// Each girder's displacement relative to its own ground at the samples [m].
    pub girder_displacement_m: Vec<Vec<f64>>,
    /// Each pier top's displacement relative to its ground at the samples [m].
    pub pier_displacement_m: Vec<Vec<f64>>,
    /// Each girder's absolute displacement at the samples [m]: its frame's and its ground's.
    pub girder_absolute_m: Vec<Vec<f64>>,
    /// Every contact, at every joint (`level` is the joint), in time order.
    pub contacts: Vec<RawContact>,
    /// Contacts grouped into impacts (`merge_gap_s`); `level` is the joint.
    pub impacts: Vec<ImpactEvent>,
    /// Largest joint force of the run [N].
    pub max_pounding_force_n: f64,
    /// Largest force at each joint [N].
    pub max_force_by_joint_n: Vec<f64>,
    /// Each joint's largest closing, left member's absolute displacement minus the right
    /// member's [m]: for a run without contact, the gap the joint needs.
    pub max_closing_m: Vec<f64>,
    /// Each joint's largest opening [m].
    pub max_opening_m: Vec<f64>,
    /// Joints whose opening passed the seat length, with the first time.
    pub unseating: Vec<Unseating>,
    /// Each girder's peak |u| relative to its ground [m].
    pub peak_girder_displacement_m: Vec<f64>,
    /// Each pier top's peak |u| relative to its ground [m].
    pub peak_pier_displacement_m: Vec<f64>,
    /// Each bearing's peak |u_girder - u_pier| [m].
    pub peak_bearing_displacement_m: Vec<f64>,
    /// Under Sears, each girder's stress waves from its left end and from its right end (see
    /// [`super::girder::GirderWaves::waves`]); empty for the other elements, whose girders are
    /// rigid.
    pub girder_waves: Vec<[BarWaves; 2]>,
    /// Where the energy went.
    pub energy: BridgeEnergy,
    /// What the run cost.
    pub stats: BridgeStats,
    /// The run's length: the record and the latest support's delay [s].
    pub duration_s: f64,
    /// How far the run had got [s]: `duration_s` once whole, less for a run still solving
    /// (see [`super::solve::solve_streaming`]).
    pub solved_to_s: f64,
    /// What the reader must know besides the numbers: first one per entry of `unseating`, in
    /// its order (a lesson step that hides the seats hides these), then the others.
    pub warnings: Vec<String>,
}

impl BridgeResult {
    /// Axial stress in girder `i` at distance `x_m` from its left end at time `t_s` [Pa],
    /// tension positive: the waves from both ends added (zero for rigid girders).
    pub fn girder_stress_pa(&self, i: usize, x_m: f64, t_s: f64) -> f64 {
        self.girder_waves.get(i).map_or(0.0, |[left, right]| {
            left.stress_pa(x_m, t_s) + right.stress_pa(left.body_length_m - x_m, t_s)
        })
    }

    /// The waves' particle velocity in girder `i` at `x_m` from its left end [m/s], on top of
    /// the girder's rigid motion (its frame's), positive to the right.
    pub fn girder_wave_velocity_m_s(&self, i: usize, x_m: f64, t_s: f64) -> f64 {
        self.girder_waves.get(i).map_or(0.0, |[left, right]| {
            left.velocity_m_s(x_m, t_s) + right.velocity_m_s(left.body_length_m - x_m, t_s)
        })
    }
}
