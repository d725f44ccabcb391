//! Everything one impact run needs, with the validation that turns bad input into an error that
//! names the field and its allowed range.

use super::bar::{Bar, EndShape, Section};
use super::contact::{
    ContactLaw, LawKind, PAPER_DIVISIONS, hertz_stiffness, paper_linear_stiffness,
};
use super::material::MaterialPreset;

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
    /// The name presets and the command line use.
    pub fn name(self) -> &'static str {
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

/// A value checked against its row of the impact settings table.
fn check(field: &str, value: f64) -> Result<(), InputError> {
    super::settings::check(super::settings::IMPACT_SETTINGS, field, value)
}

fn validate_bar(prefix: &str, bar: &Bar) -> Result<(), InputError> {
    let f = |name: &str, value: f64| {
        super::settings::check_of(super::settings::IMPACT_SETTINGS, prefix, name, value)
    };
    f("youngs_modulus", bar.material.youngs_modulus_pa)?;
    f("poisson_ratio", bar.material.poisson_ratio)?;
    f("density", bar.material.density_kg_m3)?;
    f("length", bar.length_m)?;
    match bar.section {
        Section::Circular { radius_m } => f("radius", radius_m)?,
        Section::Area { area_m2 } => f("area", area_m2)?,
    }
    f("added_mass", bar.added_mass_kg)?;
    f("velocity", bar.velocity_m_s)?;
    if let EndShape::Rounded { radius_m } = bar.end {
        f("end_radius", radius_m)?;
    }
    Ok(())
}

/// The keys [`ImpactScenario::in_range`] checks, in its order.
const CHECKED: [&str; 16] = [
    "barN.youngs_modulus",
    "barN.poisson_ratio",
    "barN.density",
    "barN.length",
    "barN.radius",
    "barN.area",
    "barN.added_mass",
    "barN.velocity",
    "barN.end_radius",
    "contact.stiffness",
    "contact.zone_scale",
    "contact.zone_length",
    "contact.divisions",
    "contact.restitution",
    "solver.dt",
    "solver.window",
];

/// Their ranges, read from the settings table once per process.
fn checked_ranges() -> &'static [super::settings::Range; 16] {
    static RANGES: std::sync::OnceLock<[super::settings::Range; 16]> = std::sync::OnceLock::new();
    RANGES.get_or_init(|| {
        CHECKED.map(|key| {
            super::settings::find(super::settings::IMPACT_SETTINGS, key)
                .and_then(|s| s.range())
                .unwrap_or_else(|| panic!("the settings table gives {key} a range"))
        })
    })
}

impl ImpactScenario {
    /// Whether every value lies in its range: the quick look a sweep's thousand solves take,
    /// before the key-naming check that runs only where it fails.
    fn in_range(&self) -> bool {
        let r = checked_ranges();
        let bar_ok = |b: &Bar| {
            r[0].contains(b.material.youngs_modulus_pa)
                && r[1].contains(b.material.poisson_ratio)
                && r[2].contains(b.material.density_kg_m3)
                && r[3].contains(b.length_m)
                && match b.section {
                    Section::Circular { radius_m } => r[4].contains(radius_m),
                    Section::Area { area_m2 } => r[5].contains(area_m2),
                }
                && r[6].contains(b.added_mass_kg)
                && r[7].contains(b.velocity_m_s)
                && match b.end {
                    EndShape::Rounded { radius_m } => r[8].contains(radius_m),
                    EndShape::Flat => true,
                }
        };
        bar_ok(&self.bar1)
            && bar_ok(&self.bar2)
            && self.contact.stiffness.is_none_or(|k| r[9].contains(k))
            && r[10].contains(self.contact.zone_scale)
            && self.contact.zone_length_m.is_none_or(|d| r[11].contains(d))
            && r[12].contains(self.contact.divisions)
            && r[13].contains(self.contact.restitution)
            && r[14].contains(self.solver.dt_s)
            && r[15].contains(self.solver.window_s)
    }

    /// Checks every value against its range in the settings table; the error names the key.
    pub fn validate(&self) -> Result<(), InputError> {
        if self.in_range() {
            // The counts' checks are integer compares; keep them in the one path below.
            check("solver.max_steps", self.solver.max_steps as f64)?;
            check("fe.segments", self.fe.segments as f64)?;
            return check("fe.courant", self.fe.courant);
        }
        validate_bar("bar1", &self.bar1)?;
        validate_bar("bar2", &self.bar2)?;
        if let Some(k) = self.contact.stiffness {
            check("contact.stiffness", k)?;
        }
        check("contact.zone_scale", self.contact.zone_scale)?;
        if let Some(d) = self.contact.zone_length_m {
            check("contact.zone_length", d)?;
        }
        check("contact.divisions", self.contact.divisions)?;
        check("contact.restitution", self.contact.restitution)?;
        check("solver.dt", self.solver.dt_s)?;
        check("solver.window", self.solver.window_s)?;
        check("solver.max_steps", self.solver.max_steps as f64)?;
        check("fe.segments", self.fe.segments as f64)?;
        check("fe.courant", self.fe.courant)?;
        Ok(())
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
                    "bar1.end_radius",
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
