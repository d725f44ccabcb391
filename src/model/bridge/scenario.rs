//! A straight bridge's settings: its spans (girders on bearings on piers), its joints and seats,
//! the contact element at the joints, and how the ground motion reaches its supports.

use crate::model::building::ContactModel;
use crate::model::building::modal::{DampingModel, Modes};
use crate::model::building::scenario::steps_for_tolerance;
use crate::model::contact::REFERENCE_OVERLAP_M;
use crate::model::error::InputError;
use crate::model::settings::Setting;
use crate::model::settings::bridge as setting;

/// The Sears zone of a girder, as a fraction of its length: the automatic contact stiffness
/// is E A / (L / 10) of each girder meeting at a joint, in series (the buildings' rule).
pub const ZONE_DIVISIONS: f64 = 10.0;

/// A bridge: `spans` frames between two rigid abutments, longitudinal motion only.
#[derive(Debug, Clone, PartialEq)]
pub struct BridgeScenario {
    /// Number of frames N (1 to 20).
    pub spans: usize,
    /// Girder lengths [m]: one value for every span, or one each.
    pub span_length_m: Vec<f64>,
    /// Girder cross-section areas [m^2].
    pub span_area_m2: Vec<f64>,
    /// Girder Young's moduli [Pa].
    pub span_youngs_pa: Vec<f64>,
    /// Girder densities [kg/m^3].
    pub span_density_kg_m3: Vec<f64>,
    /// Mass carried by each girder besides its own (deck, barriers) [kg], spread over its length.
    pub span_added_mass_kg: Vec<f64>,
    /// Each girder's velocity relative to its ground at t = 0 [m/s] (isolated-impact studies).
    pub span_velocity_m_s: Vec<f64>,
    /// Pier-top masses [kg].
    pub pier_mass_kg: Vec<f64>,
    /// Pier stiffnesses [N/m].
    pub pier_stiffness_n_m: Vec<f64>,
    /// Bearing stiffnesses, girder to pier top [N/m].
    pub bearing_stiffness_n_m: Vec<f64>,
    /// Modal damping ratio of both modes of every frame.
    pub damping_ratio: f64,
    /// Joint gaps at rest [m]: one for every joint, or N + 1 from the left abutment.
    pub joint_gaps_m: Vec<f64>,
    /// Seat length [m]: a joint that opens further than this has unseated its girder.
    pub seat_length_m: f64,
    /// The element at every joint.
    pub contact: ContactModel,
    /// Element stiffness (N/m, N/m^1.5 for the Hertzian elements); None: per joint, E A/(L/10)
    /// of the girders there in series (an abutment is rigid), and for the Hertzian elements the
    /// force that gives at 1 mm.
    pub stiffness: Option<f64>,
    /// Target restitution of kelvin, hertzdamp, jankowski and stereo.
    pub restitution: f64,
    /// Apparent velocity of the ground motion along the bridge [m/s]; None: uniform excitation.
    pub apparent_velocity_m_s: Option<f64>,
    /// Damping ratio of the girders' fundamental axial mode (their waves decay with T/(2 pi zeta)).
    pub girder_damping: f64,
    /// Contacts at one joint closer in time than this form one impact [s].
    pub merge_gap_s: f64,
    /// Accuracy target of the contact steps (relative).
    pub tolerance: f64,
    /// Steps per contact time scale; None: from the tolerance.
    pub steps_per_scale: Option<f64>,
    /// Longest step [s]: the run takes one step throughout, the shorter of this and the
    /// contact's.
    pub max_step_s: f64,
    /// The step budget of a run.
    pub max_steps: usize,
}

/// One girder as a bar: what its waves and its frame need.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Girder {
    /// Length [m].
    pub length_m: f64,
    /// Area [m^2].
    pub area_m2: f64,
    /// Young's modulus [Pa].
    pub youngs_pa: f64,
    /// Its own mass and the added mass [kg].
    pub mass_kg: f64,
}

impl Girder {
    /// Effective density rho~ = m / (A L): the added mass spread over the bar.
    pub fn effective_density(&self) -> f64 {
        self.mass_kg / (self.area_m2 * self.length_m)
    }
    /// Axial wave speed c = sqrt(E / rho~) [m/s].
    pub fn wave_speed_m_s(&self) -> f64 {
        (self.youngs_pa / self.effective_density()).sqrt()
    }
    /// Impedance Z = A sqrt(E rho~) [N s/m].
    pub fn impedance_n_s_m(&self) -> f64 {
        self.area_m2 * (self.youngs_pa * self.effective_density()).sqrt()
    }
    /// Round trip 2 L / c [s].
    pub fn round_trip_s(&self) -> f64 {
        2.0 * self.length_m / self.wave_speed_m_s()
    }
    /// E A / (L / 10) [N/m].
    pub fn zone_stiffness_n_m(&self) -> f64 {
        self.youngs_pa * self.area_m2 / (self.length_m / ZONE_DIVISIONS)
    }
}

/// What meets at a joint on one side.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Member {
    /// A rigid abutment.
    Abutment,
    /// Girder i (from 0, left to right).
    Girder(usize),
}

/// A joint: the left and right members and where it is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Joint {
    /// The member on its left.
    pub left: Member,
    /// The member on its right.
    pub right: Member,
    /// Distance from the left abutment [m].
    pub position_m: f64,
    /// Gap at rest [m].
    pub gap_m: f64,
}

impl Joint {
    /// "abutment" or "girder".
    pub fn kind(&self) -> &'static str {
        if self.left == Member::Abutment || self.right == Member::Abutment {
            "abutment"
        } else {
            "girder"
        }
    }
}

impl Default for BridgeScenario {
    fn default() -> Self {
        Self::three_span()
    }
}

impl BridgeScenario {
    /// Three 40 m concrete box girders (A = 6.5 m^2, E = 34 GPa, rho = 2500 kg/m^3) on bearings
    /// of 1e8 N/m, pier tops of 1e5 kg on piers of 8e7, 2e8 and 4e7 N/m; 5% damping; gaps of
    /// 5 cm at the abutments and 3 cm between girders; seats 0.25 m; Sears contact.
    pub fn three_span() -> Self {
        BridgeScenario {
            spans: 3,
            span_length_m: vec![40.0],
            span_area_m2: vec![6.5],
            span_youngs_pa: vec![3.4e10],
            span_density_kg_m3: vec![2500.0],
            span_added_mass_kg: vec![0.0],
            span_velocity_m_s: vec![0.0],
            pier_mass_kg: vec![1e5],
            pier_stiffness_n_m: vec![8e7, 2e8, 4e7],
            bearing_stiffness_n_m: vec![1e8],
            damping_ratio: 0.05,
            joint_gaps_m: vec![0.05, 0.03, 0.03, 0.05],
            seat_length_m: 0.25,
            contact: ContactModel::Sears,
            stiffness: None,
            restitution: 0.65,
            apparent_velocity_m_s: None,
            girder_damping: 0.05,
            merge_gap_s: 0.02,
            tolerance: 1e-4,
            steps_per_scale: None,
            max_step_s: 1e-3,
            max_steps: 20_000_000,
        }
    }

    /// Value i of a per-span list (one value stands for every span).
    fn per_span(list: &[f64], i: usize) -> f64 {
        if list.len() == 1 { list[0] } else { list[i] }
    }

    /// Girder i.
    pub fn girder(&self, i: usize) -> Girder {
        let (l, a) = (
            Self::per_span(&self.span_length_m, i),
            Self::per_span(&self.span_area_m2, i),
        );
        Girder {
            length_m: l,
            area_m2: a,
            youngs_pa: Self::per_span(&self.span_youngs_pa, i),
            mass_kg: Self::per_span(&self.span_density_kg_m3, i) * a * l
                + Self::per_span(&self.span_added_mass_kg, i),
        }
    }

    /// Every girder, left to right.
    pub fn girders(&self) -> Vec<Girder> {
        (0..self.spans).map(|i| self.girder(i)).collect()
    }

    /// Frame i's masses (pier top, girder) [kg].
    pub fn frame_masses(&self, i: usize) -> [f64; 2] {
        [
            Self::per_span(&self.pier_mass_kg, i),
            self.girder(i).mass_kg,
        ]
    }

    /// Frame i's stiffnesses (pier, bearings) [N/m].
    pub fn frame_stiffnesses(&self, i: usize) -> [f64; 2] {
        [
            Self::per_span(&self.pier_stiffness_n_m, i),
            Self::per_span(&self.bearing_stiffness_n_m, i),
        ]
    }

    /// Frame i's two modes: a two-storey shear building (pier top, girder).
    pub fn frame_modes(&self, i: usize) -> Modes {
        Modes::of_shear_building(
            &self.frame_masses(i),
            &self.frame_stiffnesses(i),
            self.damping_ratio,
            DampingModel::Modal,
        )
    }

    /// Girder i's initial velocity relative to its ground [m/s].
    pub fn initial_velocity(&self, i: usize) -> f64 {
        Self::per_span(&self.span_velocity_m_s, i)
    }

    /// Where girder i starts [m] (X_0 = 0, laid end to end).
    pub fn girder_start_m(&self, i: usize) -> f64 {
        (0..i).map(|k| self.girder(k).length_m).sum()
    }

    /// The deck's length, abutment to abutment [m].
    pub fn length_m(&self) -> f64 {
        self.girder_start_m(self.spans)
    }

    /// Frame i's ground point: its girder's midpoint [m].
    pub fn frame_position_m(&self, i: usize) -> f64 {
        self.girder_start_m(i) + 0.5 * self.girder(i).length_m
    }

    /// The delay with which the motion reaches a support at x [s]; 0 for uniform excitation.
    pub fn delay_s(&self, x_m: f64) -> f64 {
        self.apparent_velocity_m_s.map_or(0.0, |v| x_m / v)
    }

    /// The joints, from the left abutment (joint 0) to the right one (joint N).
    pub fn joints(&self) -> Vec<Joint> {
        let n = self.spans;
        (0..=n)
            .map(|j| Joint {
                left: if j == 0 {
                    Member::Abutment
                } else {
                    Member::Girder(j - 1)
                },
                right: if j == n {
                    Member::Abutment
                } else {
                    Member::Girder(j)
                },
                position_m: self.girder_start_m(j),
                gap_m: if self.joint_gaps_m.len() == 1 {
                    self.joint_gaps_m[0]
                } else {
                    self.joint_gaps_m[j]
                },
            })
            .collect()
    }

    /// The girders meeting at a joint.
    fn joint_girders(&self, joint: &Joint) -> Vec<Girder> {
        [joint.left, joint.right]
            .into_iter()
            .filter_map(|m| match m {
                Member::Girder(i) => Some(self.girder(i)),
                Member::Abutment => None,
            })
            .collect()
    }

    /// The element stiffness at a joint (see [`BridgeScenario::stiffness`]).
    pub fn joint_stiffness(&self, joint: &Joint) -> f64 {
        if let Some(k) = self.stiffness {
            return k;
        }
        let linear = 1.0
            / self
                .joint_girders(joint)
                .iter()
                .map(|g| 1.0 / g.zone_stiffness_n_m())
                .sum::<f64>();
        if self.contact.is_hertzian() {
            linear / REFERENCE_OVERLAP_M.sqrt()
        } else {
            linear
        }
    }

    /// The masses meeting at a joint in series [kg]: a girder's alone at an abutment.
    pub fn joint_effective_mass(&self, joint: &Joint) -> f64 {
        1.0 / self
            .joint_girders(joint)
            .iter()
            .map(|g| 1.0 / g.mass_kg)
            .sum::<f64>()
    }

    /// The impedances meeting at a joint in series [N s/m]: times an approach velocity, the
    /// wave-theory force.
    pub fn joint_series_impedance(&self, joint: &Joint) -> f64 {
        1.0 / self
            .joint_girders(joint)
            .iter()
            .map(|g| 1.0 / g.impedance_n_s_m())
            .sum::<f64>()
    }

    /// The steps per contact time scale.
    pub fn steps_per_scale(&self) -> f64 {
        self.steps_per_scale
            .unwrap_or_else(|| steps_for_tolerance(self.tolerance, self.contact.contact_order()))
    }

    /// The shortest contact time scale over the joints [s]: sqrt(m*/k) for every element (the
    /// Hertzian ones at their tangent at 1 mm), and for Sears also the rise time Z/k; None for
    /// the elements without a duration (stereomechanics, none).
    pub fn contact_scale_s(&self) -> Option<f64> {
        if matches!(self.contact, ContactModel::None | ContactModel::Stereo) {
            return None;
        }
        let mut scale = f64::INFINITY;
        for joint in self.joints() {
            let k = self.joint_stiffness(&joint);
            let k_lin = if self.contact.is_hertzian() {
                1.5 * k * REFERENCE_OVERLAP_M.sqrt()
            } else {
                k
            };
            scale = scale.min((self.joint_effective_mass(&joint) / k_lin).sqrt());
            if self.contact == ContactModel::Sears {
                scale = scale.min(self.joint_series_impedance(&joint) / k_lin);
            }
        }
        Some(scale)
    }

    /// The step the run takes [s], before it is fitted to the record's samples. Under Sears
    /// it is also at most a sixteenth of the shortest round trip, so that every wave look-up
    /// reaches a few steps back.
    pub fn target_step_s(&self) -> f64 {
        let mut h = match self.contact_scale_s() {
            Some(scale) => (scale / self.steps_per_scale()).min(self.max_step_s),
            // An exchange is placed at its located instant, but the motion around it is first
            // order in the step: stereomechanics steps ten times finer than the free motion.
            None if self.contact == ContactModel::Stereo => self.max_step_s / 10.0,
            None => self.max_step_s,
        };
        if self.contact == ContactModel::Sears {
            for g in self.girders() {
                h = h.min(g.round_trip_s() / 16.0);
            }
        }
        h
    }

    /// What sets [`Self::target_step_s`], and the keys that would lengthen it or the run's
    /// budget: the advice of a step-budget refusal, naming only keys `pounding bridge` takes.
    pub fn step_advice(&self) -> String {
        let common = "raise solver.max_steps, or shorten the record (motion.duration)";
        let round_trip = if self.contact == ContactModel::Sears {
            self.girders()
                .iter()
                .map(|g| g.round_trip_s() / 16.0)
                .fold(f64::INFINITY, f64::min)
        } else {
            f64::INFINITY
        };
        let contact = self
            .contact_scale_s()
            .map_or(f64::INFINITY, |s| s / self.steps_per_scale());
        let h = self.target_step_s();
        if h == round_trip && round_trip < contact.min(self.max_step_s) {
            format!(
                "the step is a sixteenth of the shortest girder's wave round trip (span.length, span.youngs_modulus, span.density); lengthen the spans, or {common}"
            )
        } else if h == contact && contact < self.max_step_s {
            format!(
                "the step resolves the contact's time scale (contact.stiffness, solver.steps_per_scale, solver.tolerance); soften the contact, ask for fewer steps per scale or a looser tolerance, or {common}"
            )
        } else {
            format!(
                "the step is solver.max_step (a tenth of it under stereomechanics); raise it, or {common}"
            )
        }
    }

    /// Checks every value against its range in the settings table; the error names the key.
    pub fn validate(&self) -> Result<(), InputError> {
        setting::SPANS.check_at(0, self.spans as f64)?;
        let n = self.spans;
        for (s, list) in [
            (&setting::SPAN_LENGTH, &self.span_length_m),
            (&setting::SPAN_AREA, &self.span_area_m2),
            (&setting::SPAN_YOUNGS_MODULUS, &self.span_youngs_pa),
            (&setting::SPAN_DENSITY, &self.span_density_kg_m3),
            (&setting::SPAN_ADDED_MASS, &self.span_added_mass_kg),
            (&setting::SPAN_VELOCITY, &self.span_velocity_m_s),
            (&setting::PIER_MASS, &self.pier_mass_kg),
            (&setting::PIER_STIFFNESS, &self.pier_stiffness_n_m),
            (&setting::BEARING_STIFFNESS, &self.bearing_stiffness_n_m),
        ] {
            check_list(s, list, n, "spans")?;
        }
        check_list(&setting::JOINT_GAPS, &self.joint_gaps_m, n + 1, "joints")?;
        setting::DAMPING_RATIO.check_at(0, self.damping_ratio)?;
        setting::SEAT_LENGTH.check_at(0, self.seat_length_m)?;
        if let Some(k) = self.stiffness {
            setting::CONTACT_STIFFNESS.check_at(0, k)?;
        }
        setting::RESTITUTION.check_at(0, self.restitution)?;
        if let Some(v) = self.apparent_velocity_m_s {
            setting::APPARENT_VELOCITY.check_at(0, v)?;
        }
        setting::GIRDER_DAMPING.check_at(0, self.girder_damping)?;
        setting::MERGE_GAP.check_at(0, self.merge_gap_s)?;
        setting::TOLERANCE.check_at(0, self.tolerance)?;
        if let Some(s) = self.steps_per_scale {
            setting::STEPS_PER_SCALE.check_at(0, s)?;
        }
        setting::MAX_STEP.check_at(0, self.max_step_s)?;
        setting::MAX_STEPS.check_at(0, self.max_steps as f64)?;
        for i in 0..n {
            self.check_frame(i)?;
        }
        Ok(())
    }

    /// Refuses a frame whose two modes are so far apart that the slower is lost to round-off.
    fn check_frame(&self, i: usize) -> Result<(), InputError> {
        let w = self.frame_modes(i).omega_rad_s;
        let (lo, hi) = (w[0] * w[0], w[1] * w[1]);
        if lo > 0.0 && hi.is_finite() && hi / lo <= 1e10 {
            return Ok(());
        }
        // Either stiffness (or a mass) can spread the frame's modes: both keys are named, with
        // the frame's values, since the one a user changed is not known here.
        let [pier, bearing] = self.frame_stiffnesses(i);
        Err(InputError::new(
            format!(
                "{} and {}",
                setting::PIER_STIFFNESS.key,
                setting::BEARING_STIFFNESS.key
            ),
            format!(
                "frame {}: its pier ({} N/m) and bearings ({} N/m), with the pier top's and girder's masses, give squared frequencies more than 1e10 apart, so the slower mode is lost to round-off; bring the pier and bearing stiffnesses (and the masses) within a factor of about 1e9 of each other",
                i + 1,
                crate::model::settings::shown(pier),
                crate::model::settings::shown(bearing),
            ),
        ))
    }
}

/// A list of one value for every member or one each, each within the setting's range.
fn check_list(setting: &Setting, list: &[f64], count: usize, what: &str) -> Result<(), InputError> {
    if list.len() != 1 && list.len() != count {
        return Err(InputError::new(
            setting.key,
            format!(
                "{} values for {count} {what}: give one value for all of them, or {count}",
                list.len()
            ),
        ));
    }
    for &v in list {
        setting.check_at(0, v)?;
    }
    Ok(())
}
