//! Two one-storey buildings shaken by a ground motion, pounding across a gap (paper Section 4).
//!
//! Each building is a single-degree-of-freedom oscillator, m u'' + c u' + k u = -m a_g -/+ F
//! (left building 1 pushed left, right building 2 pushed right), u relative to the ground. They
//! touch when u1 - u2 reaches the gap. The contact force F comes from the chosen element: the
//! Sears contact (roof slabs as uniaxial bars, linear law, their elastic waves on top of
//! u1 - u2 - gap, see [`slab`]), or one of the classic elements ([`elements`]).

pub mod elements;
pub mod slab;
mod solve;

pub use solve::solve;

use crate::model::scenario::InputError;

/// Concrete of the paper's slabs: E = 25 GPa (its contact stiffness, 15 GN/m, follows from it).
pub const SLAB_YOUNGS_MODULUS_PA: f64 = 25e9;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Slab {
    /// Length along the pounding direction [m].
    pub length_m: f64,
    pub width_m: f64,
    pub thickness_m: f64,
    pub youngs_modulus_pa: f64,
}

impl Slab {
    pub fn area_m2(&self) -> f64 {
        self.width_m * self.thickness_m
    }
}

/// One building as an oscillator.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Building {
    pub mass_kg: f64,
    pub stiffness_n_m: f64,
    /// Viscous damping ratio of the building's mode. Default 5%, the value design codes assume
    /// for reinforced concrete (the paper does not state its damping).
    pub damping_ratio: f64,
    pub storey_height_m: f64,
    pub slab: Slab,
}

impl Building {
    pub fn period_s(&self) -> f64 {
        2.0 * std::f64::consts::PI * (self.mass_kg / self.stiffness_n_m).sqrt()
    }
    pub fn damping_n_s_m(&self) -> f64 {
        2.0 * self.damping_ratio * (self.stiffness_n_m * self.mass_kg).sqrt()
    }
    /// The roof slab as a bar carrying the building's seismic mass: rho~ = m / (A L).
    pub fn slab_wave_speed_m_s(&self) -> f64 {
        (self.slab.youngs_modulus_pa * self.slab.area_m2() * self.slab.length_m / self.mass_kg)
            .sqrt()
    }
    pub fn slab_impedance_n_s_m(&self) -> f64 {
        (self.slab.youngs_modulus_pa * self.slab.area_m2() * self.mass_kg / self.slab.length_m)
            .sqrt()
    }
    pub fn slab_round_trip_s(&self) -> f64 {
        2.0 * self.slab.length_m / self.slab_wave_speed_m_s()
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactModel {
    Sears,
    Linear,
    Kelvin,
    Hertz,
    HertzDamp,
    Jankowski,
    Stereo,
    None,
}

impl ContactModel {
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
    pub fn name(self) -> &'static str {
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
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == s)
    }
    /// Whether the element's force grows as delta^1.5.
    pub fn is_hertzian(self) -> bool {
        matches!(
            self,
            ContactModel::Hertz | ContactModel::HertzDamp | ContactModel::Jankowski
        )
    }
}

/// Sears reading for buildings: the paper's delayed planes or the slab ends (d -> 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SlabReading {
    Paper,
    End,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BuildingScenario {
    pub left: Building,
    pub right: Building,
    /// At-rest separation [m].
    pub gap_m: f64,
    pub contact: ContactModel,
    /// Linear elements (sears, linear, kelvin) in N/m; None: the paper's 15 GN/m from E A/(L/n)
    /// with n = 10. Hertzian elements in N/m^1.5; None: 4.74e11, the force the linear default
    /// gives at 1 mm of overlap.
    pub stiffness: Option<f64>,
    /// Target restitution of kelvin, hertzdamp, jankowski and stereo. Default 0.65, a value
    /// measured for concrete-to-concrete impact (Jankowski).
    pub restitution: f64,
    pub reading: SlabReading,
    /// Sears zone length [m]; None: a tenth of the stiffer slab (the paper's choice).
    pub zone_length_m: Option<f64>,
    /// Damping ratio of the slabs' fundamental axial mode; all wave components decay with the
    /// same time constant T / (2 pi zeta) (T the slab's round trip). Default 0.05: undamped
    /// waves ring through the whole record, and 5% is the usual ratio for cracked concrete. 0
    /// reproduces the undamped d'Alembert response.
    pub slab_damping: f64,
    /// Contacts closer in time than this form one impact event [s]. Default 0.02 s: three round
    /// trips of the paper's slabs (about 7 ms each, the period of the wave-driven sub-contacts)
    /// and a seventeenth of the stiffer building's period (separate impacts are further apart).
    pub merge_gap_s: f64,
    /// Step inside a contact as a fraction of the contact's own time scale.
    pub steps_per_scale: f64,
    /// Longest step outside contacts [s] (also bounded by the record's step and a hundredth of
    /// the shorter building period).
    pub max_step_s: f64,
    pub max_steps: usize,
    /// Velocities of the buildings relative to the ground at t = 0 [m/s] (free-vibration and
    /// isolated-impact studies); zero for an earthquake.
    pub initial_velocity_m_s: [f64; 2],
}

impl BuildingScenario {
    /// The paper's Table 1: left k = 1.16e7 N/m, m = 36 t (T = 0.35 s); right k = 7.11e6 N/m,
    /// m = 45 t (T = 0.5 s); 4 m storeys, 10 m x 8 m x 0.15 m concrete roof slabs, gap 1 mm.
    pub fn paper() -> Self {
        let slab = Slab {
            length_m: 10.0,
            width_m: 8.0,
            thickness_m: 0.15,
            youngs_modulus_pa: SLAB_YOUNGS_MODULUS_PA,
        };
        let b = |k, m| Building {
            mass_kg: m,
            stiffness_n_m: k,
            damping_ratio: 0.05,
            storey_height_m: 4.0,
            slab,
        };
        BuildingScenario {
            left: b(1.16e7, 36_000.0),
            right: b(7.11e6, 45_000.0),
            gap_m: 1e-3,
            contact: ContactModel::Sears,
            stiffness: None,
            restitution: 0.65,
            reading: SlabReading::Paper,
            zone_length_m: None,
            slab_damping: 0.05,
            merge_gap_s: 0.02,
            steps_per_scale: 8.0,
            max_step_s: 0.005,
            max_steps: 20_000_000,
            initial_velocity_m_s: [0.0, 0.0],
        }
    }

    /// Stiffness of the chosen element (see [`BuildingScenario::stiffness`]).
    pub fn element_stiffness(&self) -> f64 {
        if let Some(k) = self.stiffness {
            return k;
        }
        let each =
            |b: &Building| b.slab.youngs_modulus_pa * b.slab.area_m2() * 10.0 / b.slab.length_m;
        let (k1, k2) = (each(&self.left), each(&self.right));
        let linear = k1 * k2 / (k1 + k2);
        if self.contact.is_hertzian() {
            linear / 1e-3f64.sqrt()
        } else {
            linear
        }
    }

    /// The Sears zone length, the same for both slabs.
    pub fn zone_length(&self) -> f64 {
        self.zone_length_m.unwrap_or_else(|| {
            let stiffer = if self.left.stiffness_n_m >= self.right.stiffness_n_m {
                &self.left
            } else {
                &self.right
            };
            stiffer.slab.length_m / 10.0
        })
    }

    /// The two slabs' impedances in series, Z1 Z2 / (Z1 + Z2) [N s/m]: times an approach velocity,
    /// the wave-theory pounding force.
    pub fn slab_series_impedance_n_s_m(&self) -> f64 {
        let (z1, z2) = (
            self.left.slab_impedance_n_s_m(),
            self.right.slab_impedance_n_s_m(),
        );
        z1 * z2 / (z1 + z2)
    }

    pub fn effective_mass_kg(&self) -> f64 {
        self.left.mass_kg * self.right.mass_kg / (self.left.mass_kg + self.right.mass_kg)
    }

    pub fn validate(&self) -> Result<(), InputError> {
        let pos = |field: &str, v: f64, unit: &str| {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(InputError::new(
                    field,
                    format!("{v} is not allowed: must be a finite number > 0 {unit}"),
                ))
            }
        };
        for (name, b) in [("left", &self.left), ("right", &self.right)] {
            pos(&format!("{name}.mass"), b.mass_kg, "kg")?;
            pos(&format!("{name}.stiffness"), b.stiffness_n_m, "N/m")?;
            if !(b.damping_ratio.is_finite() && (0.0..1.0).contains(&b.damping_ratio)) {
                return Err(InputError::new(
                    format!("{name}.damping_ratio"),
                    format!("{} is not allowed: must lie in [0, 1)", b.damping_ratio),
                ));
            }
            pos(&format!("{name}.height"), b.storey_height_m, "m")?;
            pos(&format!("{name}.slab_length"), b.slab.length_m, "m")?;
            pos(&format!("{name}.slab_width"), b.slab.width_m, "m")?;
            pos(&format!("{name}.slab_thickness"), b.slab.thickness_m, "m")?;
            pos(
                &format!("{name}.youngs_modulus"),
                b.slab.youngs_modulus_pa,
                "Pa",
            )?;
        }
        if !(self.gap_m.is_finite() && self.gap_m >= 0.0) {
            return Err(InputError::new(
                "gap",
                format!(
                    "{} is not allowed: must be a finite number >= 0 m",
                    self.gap_m
                ),
            ));
        }
        if let Some(k) = self.stiffness {
            pos(
                "contact.stiffness",
                k,
                "(N/m, or N/m^1.5 for hertz, hertzdamp, jankowski)",
            )?;
        }
        if !(self.restitution.is_finite() && self.restitution > 0.0 && self.restitution <= 1.0) {
            return Err(InputError::new(
                "contact.restitution",
                format!("{} is not allowed: must lie in (0, 1]", self.restitution),
            ));
        }
        if let Some(d) = self.zone_length_m {
            pos("contact.zone_length", d, "m")?;
        }
        let d = self.zone_length();
        for (name, b) in [("left", &self.left), ("right", &self.right)] {
            if self.contact == ContactModel::Sears
                && self.reading == SlabReading::Paper
                && d >= 2.0 * b.slab.length_m
            {
                return Err(InputError::new(
                    "contact.zone_length",
                    format!(
                        "{d} m is not allowed: the paper reading needs d < 2 L = {} m of the {name} slab",
                        2.0 * b.slab.length_m
                    ),
                ));
            }
        }
        if !(self.slab_damping.is_finite() && (0.0..1.0).contains(&self.slab_damping)) {
            return Err(InputError::new(
                "slab.damping",
                format!("{} is not allowed: must lie in [0, 1)", self.slab_damping),
            ));
        }
        if !(self.merge_gap_s.is_finite() && self.merge_gap_s >= 0.0) {
            return Err(InputError::new(
                "impact.merge_gap_s",
                format!(
                    "{} is not allowed: must be a finite number >= 0 s",
                    self.merge_gap_s
                ),
            ));
        }
        if !(self.steps_per_scale.is_finite() && self.steps_per_scale >= 1.0) {
            return Err(InputError::new(
                "solver.steps_per_scale",
                format!("{} is not allowed: must be >= 1", self.steps_per_scale),
            ));
        }
        pos("solver.max_step", self.max_step_s, "s")?;
        if self.max_steps == 0 {
            return Err(InputError::new(
                "solver.max_steps",
                "0 is not allowed: must be at least 1",
            ));
        }
        for (name, v) in [
            ("left.velocity", self.initial_velocity_m_s[0]),
            ("right.velocity", self.initial_velocity_m_s[1]),
        ] {
            if !v.is_finite() {
                return Err(InputError::new(
                    name,
                    format!("{v} is not allowed: must be a finite number in m/s"),
                ));
            }
        }
        Ok(())
    }
}

/// One interval of contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RawContact {
    pub start_s: f64,
    pub end_s: f64,
    pub peak_force_n: f64,
    pub impulse_ns: f64,
    /// Relative approach velocity v1 - v2 at onset [m/s].
    pub approach_velocity_m_s: f64,
}

/// Contacts merged into one impact (closer than `merge_gap_s`).
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactEvent {
    pub start_s: f64,
    pub end_s: f64,
    pub peak_force_n: f64,
    pub impulse_ns: f64,
    pub approach_velocity_m_s: f64,
    /// Indices into the raw contact list.
    pub contacts: std::ops::Range<usize>,
}

impl ImpactEvent {
    pub fn duration_s(&self) -> f64 {
        self.end_s - self.start_s
    }
}

/// Where the energy put in by the ground went [J].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BuildingEnergy {
    /// Work of the ground's inertial forces on the buildings.
    pub input_j: f64,
    pub building_damping_j: f64,
    /// Energy the contact took from the buildings and did not give back (dissipated by a damped
    /// element or by the restitution of stereomechanics, or carried into the slabs' waves).
    pub contact_j: f64,
    /// Kinetic and strain energy of the buildings at the end.
    pub final_j: f64,
    /// Energy still stored in the contact element at the end.
    pub stored_contact_j: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BuildingStats {
    pub steps: usize,
    pub contact_steps: usize,
    pub fine_step_s: f64,
    pub coarse_step_s: f64,
    pub wall_time_s: f64,
}

#[derive(Debug, Clone)]
pub struct BuildingResult {
    pub contact: ContactModel,
    pub time_s: Vec<f64>,
    pub ground_m_s2: Vec<f64>,
    /// Displacement relative to the ground [m].
    pub displacement_m: [Vec<f64>; 2],
    pub velocity_m_s: [Vec<f64>; 2],
    /// Absolute acceleration [m/s^2].
    pub acceleration_m_s2: [Vec<f64>; 2],
    pub force_n: Vec<f64>,
    pub contacts: Vec<RawContact>,
    pub impacts: Vec<ImpactEvent>,
    pub peak_displacement_m: [f64; 2],
    pub max_pounding_force_n: f64,
    pub energy: BuildingEnergy,
    pub stats: BuildingStats,
    pub warnings: Vec<String>,
}

/// Groups raw contacts into impact events: a contact starting within `merge_gap_s` of the
/// previous one's end joins its event.
pub fn group_impacts(contacts: &[RawContact], merge_gap_s: f64) -> Vec<ImpactEvent> {
    let mut out: Vec<ImpactEvent> = Vec::new();
    for (i, c) in contacts.iter().enumerate() {
        match out.last_mut() {
            Some(e) if c.start_s - e.end_s < merge_gap_s => {
                e.end_s = c.end_s;
                e.peak_force_n = e.peak_force_n.max(c.peak_force_n);
                e.impulse_ns += c.impulse_ns;
                e.contacts.end = i + 1;
            }
            _ => out.push(ImpactEvent {
                start_s: c.start_s,
                end_s: c.end_s,
                peak_force_n: c.peak_force_n,
                impulse_ns: c.impulse_ns,
                approach_velocity_m_s: c.approach_velocity_m_s,
                contacts: i..i + 1,
            }),
        }
    }
    out
}

/// A building run's own error estimate by step doubling: the same run with half the steps per
/// contact time scale and twice the outside step; Richardson's |q(h) - q(2h)| / 3 for the peaks
/// (second order), and the change in the impact count.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BuildingErrorEstimate {
    pub max_force: f64,
    pub peak_displacement: f64,
    pub impact_count_change: i64,
    pub wall_time_s: f64,
}

pub fn estimate_error(
    sc: &BuildingScenario,
    motion: &crate::model::motion::GroundMotion,
    r: &BuildingResult,
) -> Result<BuildingErrorEstimate, crate::model::impact::SolveError> {
    let coarse = BuildingScenario {
        steps_per_scale: (sc.steps_per_scale / 2.0).max(1.0),
        max_step_s: 2.0 * sc.max_step_s,
        ..*sc
    };
    let start = std::time::Instant::now();
    let c = solve(&coarse, motion)?;
    let rel = |a: f64, b: f64| {
        if b == 0.0 {
            (a - b).abs()
        } else {
            ((a - b) / b).abs()
        }
    };
    Ok(BuildingErrorEstimate {
        max_force: rel(r.max_pounding_force_n, c.max_pounding_force_n) / 3.0,
        peak_displacement: rel(r.peak_displacement_m[0], c.peak_displacement_m[0])
            .max(rel(r.peak_displacement_m[1], c.peak_displacement_m[1]))
            / 3.0,
        impact_count_change: r.impacts.len() as i64 - c.impacts.len() as i64,
        wall_time_s: start.elapsed().as_secs_f64(),
    })
}
