//! Two shear buildings shaken by a ground motion, pounding across a gap (the paper's Section 4,
//! generalised to N storeys).
//!
//! Each building is a shear building of N storeys (one in the paper): floor j carries the mass
//! m_j, storey j has the shear stiffness k_j, and M u'' + C u' + K u = -M 1 a_g + f with u relative
//! to the ground ([`modal`]). Every floor of either building within the other's height gets a
//! contact point ([`levels`]), where the buildings touch when u_left - u_right reaches the gap.
//! The contact force comes from the chosen element: the Sears contact (floor slabs as uniaxial
//! bars, linear law, their elastic waves on top of the closing motion, see [`slab`]) or one of the
//! classic elements ([`elements`]). [`stepper`] runs it in named stages.

pub mod checked;
pub mod elements;
pub mod estimate;
pub mod gaps;
pub mod levels;
pub mod modal;
pub mod result;
pub mod scenario;
pub mod slab;
mod solve;
mod stepper;
pub mod warning;

pub use checked::{Checked, solve_checked, solve_checked_summary, solve_checked_with};
pub use estimate::{BuildingErrorEstimate, estimate_error, estimate_error_with};
pub use levels::{Attachment, Level, LevelKind};
pub use modal::{DampingModel, Modes};
pub use result::{
    BuildingEnergy, BuildingResult, BuildingStats, ImpactEvent, RawContact, SlabRecord,
    group_impacts,
};
pub use scenario::{Building, BuildingScenario, SLAB_YOUNGS_MODULUS_PA, Slab};
pub use solve::{
    PUBLISH_EVERY, SLAB_MEMORY_BUDGET, Tracked, planned_step_s, solve, solve_streaming,
    solve_summary, solve_summary_tracking, solve_summary_with, solve_with,
};
pub use warning::Warning;

/// The contact element between the buildings.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactModel {
    /// The Sears contact: the floor slabs as bars whose waves add to the overlap, a linear law.
    Sears,
    /// A linear spring.
    Linear,
    /// A Kelvin-Voigt spring and dashpot that cannot pull.
    Kelvin,
    /// A Hertzian spring, k delta^1.5.
    Hertz,
    /// Hertz with Muthukumar and DesRoches' damping.
    HertzDamp,
    /// Jankowski's nonlinear viscoelastic element.
    Jankowski,
    /// Stereomechanics: an instantaneous exchange with a restitution.
    Stereo,
    /// No contact: the buildings pass through each other.
    None,
}

impl ContactModel {
    /// Every element, in the order the front ends list them.
    pub const ALL: [ContactModel; 8] = [
        ContactModel::Sears,
        ContactModel::Linear,
        ContactModel::Kelvin,
        ContactModel::Hertz,
        ContactModel::HertzDamp,
        ContactModel::Jankowski,
        ContactModel::Stereo,
        ContactModel::None,
    ];
    /// Every element's name, in the order of [`ContactModel::ALL`].
    pub const NAMES: [&'static str; 8] = crate::model::names_of!(Self::ALL, 8);

    /// The name the command line and presets use.
    pub const fn name(self) -> &'static str {
        match self {
            ContactModel::Sears => "sears",
            ContactModel::Linear => "linear",
            ContactModel::Kelvin => "kelvin",
            ContactModel::Hertz => "hertz",
            ContactModel::HertzDamp => "hertzdamp",
            ContactModel::Jankowski => "jankowski",
            ContactModel::Stereo => "stereo",
            ContactModel::None => "none",
        }
    }
    /// The element of that name.
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == s)
    }
    /// The order at which the contact steps converge: 2 (the Newmark step with onsets located
    /// and graded), except Jankowski's element, whose dashpot grows as delta^(1/4), so its force
    /// rises as t^(1/4) after onset and the steps converge at order 1.25.
    pub fn contact_order(self) -> f64 {
        if self == ContactModel::Jankowski {
            1.25
        } else {
            2.0
        }
    }

    /// Whether the element's force grows as delta^1.5.
    pub fn is_hertzian(self) -> bool {
        matches!(
            self,
            ContactModel::Hertz | ContactModel::HertzDamp | ContactModel::Jankowski
        )
    }
}

/// What a run records of its histories.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Recording {
    /// What a plot needs: the end of every free step, a few samples per contact time scale
    /// inside contacts, and where a contact opens or closes.
    #[default]
    Plot,
    /// Every step the solver takes (the free steps' ends, and inside contacts each step): a
    /// contact exported in full.
    Steps,
}

impl Recording {
    /// Both, in the order the front ends list them.
    pub const ALL: [Recording; 2] = [Recording::Plot, Recording::Steps];
    /// Their names, in the order of [`Recording::ALL`].
    pub const NAMES: [&'static str; 2] = crate::model::names_of!(Self::ALL, 2);

    /// The name presets and the command line use.
    pub const fn name(self) -> &'static str {
        match self {
            Recording::Plot => "plot",
            Recording::Steps => "steps",
        }
    }

    /// The one of that name.
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|r| r.name() == s)
    }
}

/// Sears reading for buildings: the paper's delayed planes or the slab ends (d -> 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SlabReading {
    /// The paper's reading: the law on planes a zone length d inside the slabs.
    Paper,
    /// The law at the slab ends (d -> 0).
    End,
}

impl SlabReading {
    /// Both readings.
    pub const ALL: [SlabReading; 2] = [SlabReading::Paper, SlabReading::End];
    /// Their names, in the order of [`SlabReading::ALL`].
    pub const NAMES: [&'static str; 2] = crate::model::names_of!(Self::ALL, 2);

    /// The name presets and the command line use.
    pub const fn name(self) -> &'static str {
        match self {
            SlabReading::Paper => "paper",
            SlabReading::End => "end",
        }
    }

    /// The reading of that name.
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|r| r.name() == s)
    }
}
