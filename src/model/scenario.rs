//! Everything one impact run needs, with the validation that turns bad input into an error that
//! names the field and its allowed range.

use super::bar::{Bar, EndShape, Section};
use super::contact::{
    ContactLaw, LawKind, PAPER_DIVISIONS, hertz_stiffness, paper_linear_stiffness,
};
use super::material::MaterialPreset;
use super::settings::{Setting, impact};

/// Which reading of the Sears model (docs/model.md, "Three readings").
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Reading {
    /// The paper's delayed planes: the law acts on the planes P_i at d_i, the force on the ends.
    Paper,
    /// The zone of length d is a massless spring; the bodies are bars of length L - d.
    Collocated,
    /// d -> 0: Saint-Venant bars with the contact law at their ends.
    End,
}

impl Reading {
    /// Every reading.
    pub const ALL: [Reading; 3] = [Reading::Paper, Reading::Collocated, Reading::End];
    /// Every reading's name, in the order of [`Reading::ALL`].
    pub const NAMES: [&'static str; 3] = crate::model::names_of!(Self::ALL, 3);
    /// The name presets and the command line use.
    pub const fn name(self) -> &'static str {
        match self {
            Reading::Paper => "paper",
            Reading::Collocated => "collocated",
            Reading::End => "end",
        }
    }
    /// The reading of that name.
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|r| r.name() == s)
    }
    /// Whether this reading conserves energy for an elastic contact law.
    pub fn energy_consistent(self) -> bool {
        !matches!(self, Reading::Paper)
    }
}

/// The contact between the bars.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactSpec {
    /// Hertz or linear.
    pub law: LawKind,
    /// Explicit stiffness (N/m^1.5 Hertz, N/m linear); `None` derives it: Hertz from the ends,
    /// linear from the paper's E A / (L / n) helper with `divisions` = n.
    pub stiffness: Option<f64>,
    /// Multiplier on Sears' zone length d (the paper varies it from 0.01 to 10).
    pub zone_scale: f64,
    /// Zone length for both bars [m] instead of Sears' Eq. 5 (the paper's slabs use L/10).
    pub zone_length_m: Option<f64>,
    /// n in the paper's kL = E A / (L / n) helper.
    pub divisions: f64,
    /// Target coefficient of restitution for the Kelvin-Voigt and stereomechanics models.
    pub restitution: f64,
}

/// How the impact solvers step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverSettings {
    /// Time step [s].
    pub dt_s: f64,
    /// Simulated span [s]; 0 runs until the bars separate for good (the first separation after
    /// which their rigid-body velocities no longer approach).
    pub window_s: f64,
    /// Refuse runs longer than this many steps.
    pub max_steps: usize,
    /// Refine the step automatically when it is too coarse for the contact's own time scale.
    pub refine: bool,
}

/// The finite-element model's mesh and step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FeSettings {
    /// Segments per bar.
    pub segments: usize,
    /// Fraction of the explicit stability limit min(dx / c) used as the step.
    pub courant: f64,
}

/// Two bars about to collide, their contact and the solvers' settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactScenario {
    /// The left bar, moving right.
    pub bar1: Bar,
    /// The right bar.
    pub bar2: Bar,
    /// The contact law.
    pub contact: ContactSpec,
    /// The Sears reading.
    pub reading: Reading,
    /// Steps, span and budget.
    pub solver: SolverSettings,
    /// The FE model's settings.
    pub fe: FeSettings,
}

impl Default for ImpactScenario {
    /// The paper's parametric base case: steel rods of 0.1 m diameter, 1 m against 2 m, relative
    /// velocity 1 m/s, the first bar's end rounded with a 0.1 m diameter, the second flat, 1 us.
    fn default() -> Self {
        let steel = MaterialPreset::Steel.material();
        let rod = |length_m, velocity_m_s, end| Bar {
            material: steel,
            section: Section::Circular { radius_m: 0.05 },
            length_m,
            added_mass_kg: 0.0,
            velocity_m_s,
            end,
        };
        ImpactScenario {
            bar1: rod(1.0, 1.0, EndShape::Rounded { radius_m: 0.05 }),
            bar2: rod(2.0, 0.0, EndShape::Flat),
            contact: ContactSpec {
                law: LawKind::Hertz,
                stiffness: None,
                zone_scale: 1.0,
                zone_length_m: None,
                divisions: PAPER_DIVISIONS,
                restitution: 0.65,
            },
            reading: Reading::Paper,
            solver: SolverSettings {
                dt_s: 1e-6,
                window_s: 0.0,
                max_steps: 4_000_000,
                refine: true,
            },
            fe: FeSettings {
                segments: 100,
                courant: 0.9,
            },
        }
    }
}

pub use super::error::InputError;

/// The checked settings of a bar; [`bar_values`] gives the values in this order (`None` where
/// the bar has no such value: a radius for a bar given by its area, an end radius for a flat
/// end).
const BAR_CHECKED: [&Setting; 9] = [
    &impact::YOUNGS_MODULUS,
    &impact::POISSON_RATIO,
    &impact::DENSITY,
    &impact::LENGTH,
    &impact::RADIUS,
    &impact::AREA,
    &impact::ADDED_MASS,
    &impact::VELOCITY,
    &impact::END_RADIUS,
];

fn bar_values(bar: &Bar) -> [Option<f64>; 9] {
    let (radius, area) = match bar.section {
        Section::Circular { radius_m } => (Some(radius_m), None),
        Section::Area { area_m2 } => (None, Some(area_m2)),
    };
    let end_radius = match bar.end {
        EndShape::Rounded { radius_m } => Some(radius_m),
        EndShape::Flat => None,
    };
    [
        Some(bar.material.youngs_modulus_pa),
        Some(bar.material.poisson_ratio),
        Some(bar.material.density_kg_m3),
        Some(bar.length_m),
        radius,
        area,
        Some(bar.added_mass_kg),
        Some(bar.velocity_m_s),
        end_radius,
    ]
}

/// The other checked settings; [`ImpactScenario::other_values`] gives them in this order.
const OTHER_CHECKED: [&Setting; 10] = [
    &impact::CONTACT_STIFFNESS,
    &impact::ZONE_SCALE,
    &impact::ZONE_LENGTH,
    &impact::DIVISIONS,
    &impact::RESTITUTION,
    &impact::DT,
    &impact::WINDOW,
    &impact::MAX_STEPS,
    &impact::FE_SEGMENTS,
    &impact::FE_COURANT,
];

/// Every present value checked against its setting's range; the first refused names its key.
fn check_all(
    settings: &[&Setting],
    owner: usize,
    values: &[Option<f64>],
) -> Result<(), InputError> {
    for (s, v) in settings.iter().zip(values) {
        if let Some(x) = v {
            s.check_at(owner, *x)?;
        }
    }
    Ok(())
}

impl ImpactScenario {
    /// The values of [`OTHER_CHECKED`], in its order.
    fn other_values(&self) -> [Option<f64>; 10] {
        [
            self.contact.stiffness,
            Some(self.contact.zone_scale),
            self.contact.zone_length_m,
            Some(self.contact.divisions),
            Some(self.contact.restitution),
            Some(self.solver.dt_s),
            Some(self.solver.window_s),
            Some(self.solver.max_steps as f64),
            Some(self.fe.segments as f64),
            Some(self.fe.courant),
        ]
    }

    /// Checks every value against its range in the settings table; the error names the key
    /// (spelled out only then: a sweep's thousand solves run this).
    pub fn validate(&self) -> Result<(), InputError> {
        check_all(&BAR_CHECKED, 0, &bar_values(&self.bar1))?;
        check_all(&BAR_CHECKED, 1, &bar_values(&self.bar2))?;
        check_all(&OTHER_CHECKED, 0, &self.other_values())
    }

    /// Relative approach velocity v1 - v2 [m/s].
    pub fn approach_velocity_m_s(&self) -> f64 {
        self.bar1.velocity_m_s - self.bar2.velocity_m_s
    }

    /// The two bars' impedances in series, Z1 Z2 / (Z1 + Z2) [N s/m].
    pub fn series_impedance_n_s_m(&self) -> f64 {
        let (z1, z2) = (self.bar1.impedance_n_s_m(), self.bar2.impedance_n_s_m());
        z1 * z2 / (z1 + z2)
    }

    /// Wave theory's contact force Z1 Z2 / (Z1 + Z2) (v1 - v2) [N]: the most elastic bars can
    /// carry.
    pub fn wave_force_n(&self) -> f64 {
        self.series_impedance_n_s_m() * self.approach_velocity_m_s()
    }

    /// The contact law chosen by `contact.law`.
    pub fn contact_law(&self) -> Result<ContactLaw, InputError> {
        match self.contact.law {
            LawKind::Hertz => self.hertz_law(),
            LawKind::Linear => Ok(self.linear_law()),
        }
    }

    /// Hertz law: the explicit stiffness when `contact.law = hertz` gives one, else from the ends.
    pub fn hertz_law(&self) -> Result<ContactLaw, InputError> {
        if let (LawKind::Hertz, Some(k)) = (self.contact.law, self.contact.stiffness) {
            return Ok(ContactLaw::hertz(k));
        }
        hertz_stiffness(&self.bar1, &self.bar2)
            .map(ContactLaw::hertz)
            .ok_or_else(|| {
                InputError::new(
                    impact::END_RADIUS.key_of(0),
                    "a Hertz contact needs a rounded end on at least one bar; both ends are flat",
                )
            })
    }

    /// Linear law: the explicit stiffness when `contact.law = linear` gives one, else the paper's
    /// E A / (L / n) helper.
    pub fn linear_law(&self) -> ContactLaw {
        match (self.contact.law, self.contact.stiffness) {
            (LawKind::Linear, Some(k)) => ContactLaw::linear(k),
            _ => ContactLaw::linear(paper_linear_stiffness(
                &self.bar1,
                &self.bar2,
                self.contact.divisions,
            )),
        }
    }

    /// Sears' zone lengths d_i after the user's scale [m].
    pub fn zone_lengths_m(&self) -> [f64; 2] {
        let formula = [
            self.bar1.sears_zone_length_m(),
            self.bar2.sears_zone_length_m(),
        ];
        formula.map(|d| self.contact.zone_length_m.unwrap_or(d) * self.contact.zone_scale)
    }

    /// Effective mass m1 m2 / (m1 + m2) [kg].
    pub fn effective_mass_kg(&self) -> f64 {
        let (m1, m2) = (self.bar1.mass_kg(), self.bar2.mass_kg());
        m1 * m2 / (m1 + m2)
    }

    /// The same impact seen with the bars' roles exchanged (mirror image): bar 2 becomes the left
    /// bar and every velocity changes sign.
    pub fn mirrored(&self) -> Self {
        let mut m = *self;
        m.bar1 = self.bar2;
        m.bar2 = self.bar1;
        m.bar1.velocity_m_s = -self.bar2.velocity_m_s;
        m.bar2.velocity_m_s = -self.bar1.velocity_m_s;
        m
    }
}
