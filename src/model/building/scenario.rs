//! Two shear buildings side by side, and everything a pounding run needs, with the validation
//! that names the field and its allowed range.

use super::levels::{Attachment, Level, elevations, levels};
use super::modal::{DampingModel, Modes};
use super::{ContactModel, SlabReading};
use crate::model::contact::{PAPER_DIVISIONS, REFERENCE_OVERLAP_M};
use crate::model::error::InputError;
use crate::model::hysteresis::{Hysteresis, StoreyLaw};
use crate::model::settings::{SIDES, building as setting};

/// Concrete of the paper's slabs: E = 25 GPa (its contact stiffness, 15 GN/m, follows from it).
pub const SLAB_YOUNGS_MODULUS_PA: f64 = 25e9;

/// The most storeys a building may have.
pub const MAX_STOREYS: usize = 100;

/// A floor slab, the bar that carries the Sears contact's waves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Slab {
    /// Length along the pounding direction [m].
    pub length_m: f64,
    /// Width across the pounding direction [m].
    pub width_m: f64,
    /// Thickness [m].
    pub thickness_m: f64,
    /// Young's modulus [Pa].
    pub youngs_modulus_pa: f64,
}

impl Slab {
    /// Cross-section area across the pounding direction [m^2].
    pub fn area_m2(&self) -> f64 {
        self.width_m * self.thickness_m
    }
    /// Wave speed with a floor's mass spread over the slab, rho~ = m / (A L) [m/s].
    pub fn wave_speed_m_s(&self, mass_kg: f64) -> f64 {
        (self.youngs_modulus_pa * self.area_m2() * self.length_m / mass_kg).sqrt()
    }
    /// Impedance A sqrt(E rho~) with the floor's mass spread over the slab [N s/m].
    pub fn impedance_n_s_m(&self, mass_kg: f64) -> f64 {
        (self.youngs_modulus_pa * self.area_m2() * mass_kg / self.length_m).sqrt()
    }
    /// Round trip 2 L / c with the floor's mass [s].
    pub fn round_trip_s(&self, mass_kg: f64) -> f64 {
        2.0 * self.length_m / self.wave_speed_m_s(mass_kg)
    }
    /// The paper's contact stiffness of this slab alone, E A / (L / n) [N/m].
    pub fn paper_stiffness_n_m(&self) -> f64 {
        self.youngs_modulus_pa * self.area_m2() * PAPER_DIVISIONS / self.length_m
    }
}

/// A value per storey: one for every storey, or one each.
fn per(values: &[f64], j: usize) -> f64 {
    if values.len() == 1 {
        values[0]
    } else {
        values[j]
    }
}

/// What a building's modes are remembered by: the bits of its masses, its stiffnesses and its
/// damping ratio, and its damping model.
type ModesKey = (Vec<u64>, Vec<u64>, u64, DampingModel);

/// The modes of the last few tall buildings asked for ([`Building::modes`]).
static RECENT_MODES: std::sync::Mutex<Vec<(ModesKey, Modes)>> = std::sync::Mutex::new(Vec::new());

/// How many buildings' modes are remembered: both sides of the run and of the window's last
/// change.
const REMEMBERED_MODES: usize = 4;

/// The fewest storeys whose modes are remembered.
const REMEMBERED_FROM_STOREYS: usize = 16;

/// One shear building: N storeys, floor j carrying the mass m_j at elevation h_1 + ... + h_j,
/// storey j (between floors j-1 and j, floor 0 the ground) of shear stiffness k_j, and a slab at
/// every floor. Per-storey lists hold one value (for every storey) or N.
#[derive(Debug, Clone, PartialEq)]
pub struct Building {
    /// Number of storeys N.
    pub storeys: usize,
    /// Floor masses [kg]: one for every floor, or one each (bottom first).
    pub masses_kg: Vec<f64>,
    /// Storey shear stiffnesses [N/m], one or one each.
    pub stiffnesses_n_m: Vec<f64>,
    /// Storey heights [m], one or one each.
    pub heights_m: Vec<f64>,
    /// Viscous damping ratio. Default 5%, the value design codes assume for reinforced concrete
    /// (the paper does not state its damping).
    pub damping_ratio: f64,
    /// How the damping matrix is built from the ratio.
    pub damping: DampingModel,
    /// Floor slab lengths along the pounding direction [m], one or one each.
    pub slab_lengths_m: Vec<f64>,
    /// Floor slab widths [m], one or one each.
    pub slab_widths_m: Vec<f64>,
    /// Floor slab thicknesses [m], one or one each.
    pub slab_thicknesses_m: Vec<f64>,
    /// Floor slabs' Young's moduli [Pa], one or one each.
    pub slab_youngs_pa: Vec<f64>,
    /// The storeys' shear springs: elastic (default) or hysteretic.
    pub hysteresis: Hysteresis,
    /// Storey yield forces [N], one or one each; None: the force at a drift of
    /// [`AUTO_YIELD_DRIFT_RATIO`] of the storey's height.
    pub yield_forces_n: Option<Vec<f64>>,
    /// Post-yield stiffness ratio b, in [0, 1). Default 0.05.
    pub hardening: f64,
    /// Bouc-Wen's exponent n. Default 2.
    pub bouc_wen_n: f64,
}

/// A storey without a stated yield force yields at this drift over its height: 0.5%, about
/// where a reinforced-concrete frame's storey yields.
pub const AUTO_YIELD_DRIFT_RATIO: f64 = 0.005;

impl Building {
    /// Gives the building `n` storeys. A list with a value for each storey keeps its top
    /// storey's value for the storeys added and drops those removed; a list of one value for
    /// every storey stays as it is.
    pub fn set_storeys(&mut self, n: usize) {
        let each = [
            &mut self.masses_kg,
            &mut self.stiffnesses_n_m,
            &mut self.heights_m,
            &mut self.slab_lengths_m,
            &mut self.slab_widths_m,
            &mut self.slab_thicknesses_m,
            &mut self.slab_youngs_pa,
        ];
        for list in each.into_iter().chain(self.yield_forces_n.as_mut()) {
            if list.len() > 1
                && let Some(&top) = list.last()
            {
                list.resize(n, top);
            }
        }
        self.storeys = n;
    }

    /// A one-storey building with the given mass, stiffness, height and slab, 5% modal damping.
    pub fn one_storey(mass_kg: f64, stiffness_n_m: f64, height_m: f64, slab: Slab) -> Self {
        Building {
            storeys: 1,
            masses_kg: vec![mass_kg],
            stiffnesses_n_m: vec![stiffness_n_m],
            heights_m: vec![height_m],
            damping_ratio: 0.05,
            damping: DampingModel::Modal,
            slab_lengths_m: vec![slab.length_m],
            slab_widths_m: vec![slab.width_m],
            slab_thicknesses_m: vec![slab.thickness_m],
            slab_youngs_pa: vec![slab.youngs_modulus_pa],
            hysteresis: Hysteresis::Elastic,
            yield_forces_n: None,
            hardening: 0.05,
            bouc_wen_n: 2.0,
        }
    }

    /// Floor j's mass (0-based) [kg].
    pub fn mass(&self, j: usize) -> f64 {
        per(&self.masses_kg, j)
    }
    /// Storey j's stiffness (0-based) [N/m].
    pub fn stiffness(&self, j: usize) -> f64 {
        per(&self.stiffnesses_n_m, j)
    }
    /// Storey j's height (0-based) [m].
    pub fn height(&self, j: usize) -> f64 {
        per(&self.heights_m, j)
    }
    /// Floor j's slab (0-based).
    pub fn slab(&self, j: usize) -> Slab {
        Slab {
            length_m: per(&self.slab_lengths_m, j),
            width_m: per(&self.slab_widths_m, j),
            thickness_m: per(&self.slab_thicknesses_m, j),
            youngs_modulus_pa: per(&self.slab_youngs_pa, j),
        }
    }
    /// Storey j's yield force (0-based) [N].
    pub fn yield_force(&self, j: usize) -> f64 {
        match &self.yield_forces_n {
            Some(list) => per(list, j),
            None => self.stiffness(j) * AUTO_YIELD_DRIFT_RATIO * self.height(j),
        }
    }
    /// Every storey's spring law, bottom first.
    pub fn storey_laws(&self) -> Vec<StoreyLaw> {
        (0..self.storeys).map(|j| self.storey_law(j)).collect()
    }
    /// Storey j's law (lowest 0).
    pub fn storey_law(&self, j: usize) -> StoreyLaw {
        StoreyLaw {
            kind: self.hysteresis,
            stiffness_n_m: self.stiffness(j),
            yield_force_n: self.yield_force(j),
            hardening: self.hardening,
            bouc_wen_n: self.bouc_wen_n,
        }
    }
    /// Whether any storey yields (its law is not elastic).
    pub fn yields(&self) -> bool {
        self.hysteresis != Hysteresis::Elastic
    }
    /// Every floor's mass, bottom first [kg].
    pub fn masses(&self) -> Vec<f64> {
        (0..self.storeys).map(|j| self.mass(j)).collect()
    }
    /// Every storey's stiffness, bottom first [N/m].
    pub fn stiffnesses(&self) -> Vec<f64> {
        (0..self.storeys).map(|j| self.stiffness(j)).collect()
    }
    /// Every storey's height, bottom first [m].
    pub fn heights(&self) -> Vec<f64> {
        (0..self.storeys).map(|j| self.height(j)).collect()
    }
    /// Floor elevations [m].
    pub fn elevations_m(&self) -> Vec<f64> {
        elevations(&self.heights())
    }
    /// Height of the roof [m].
    pub fn total_height_m(&self) -> f64 {
        self.heights().iter().sum()
    }
    /// The building's mass [kg].
    pub fn total_mass_kg(&self) -> f64 {
        self.masses().iter().sum()
    }
    /// Its modes, with its damping.
    ///
    /// A tall building's are remembered for the last few buildings asked for: a run, its error
    /// estimate's companion, the run without contact and the window's next change ask for the
    /// same buildings, and a tall building's eigenproblem is the costliest part of setting up
    /// a run. The modes are a function
    /// of the masses, the stiffnesses and the damping alone, so a remembered answer is the one
    /// computing it again would give, bit for bit.
    pub fn modes(&self) -> Modes {
        let (masses, stiffnesses) = (self.masses(), self.stiffnesses());
        let compute =
            || Modes::of_shear_building(&masses, &stiffnesses, self.damping_ratio, self.damping);
        // A few storeys take less to solve than to look up.
        if masses.len() < REMEMBERED_FROM_STOREYS {
            return compute();
        }
        let bits = |x: &[f64]| x.iter().map(|v| v.to_bits()).collect::<Vec<u64>>();
        let key = (
            bits(&masses),
            bits(&stiffnesses),
            self.damping_ratio.to_bits(),
            self.damping,
        );
        let recent = || RECENT_MODES.lock().unwrap_or_else(|e| e.into_inner());
        if let Some((_, m)) = recent().iter().find(|(k, _)| *k == key) {
            return m.clone();
        }
        let modes = compute();
        let mut kept = recent();
        if kept.len() >= REMEMBERED_MODES {
            kept.remove(0);
        }
        kept.push((key, modes.clone()));
        modes
    }
    /// The square of the fundamental circular frequency [rad^2/s^2], without the other modes.
    pub fn fundamental_omega_squared(&self) -> f64 {
        super::modal::fundamental_omega_squared(&self.masses(), &self.stiffnesses())
    }
    /// The fundamental period [s].
    pub fn period_s(&self) -> f64 {
        self.modes().periods_s()[0]
    }
    /// Scales every storey's stiffness so that the fundamental period becomes `period_s` (for
    /// one storey: k = m (2 pi / T)^2).
    pub fn set_period(&mut self, period_s: f64) {
        let now = self.period_s();
        let factor = (now / period_s).powi(2);
        for k in self.stiffnesses_n_m.iter_mut() {
            *k *= factor;
        }
    }
}

/// Two buildings, the gap between them, the contact element and the solver's settings.
#[derive(Debug, Clone, PartialEq)]
pub struct BuildingScenario {
    /// The building on the left.
    pub left: Building,
    /// The building on the right.
    pub right: Building,
    /// At-rest separation, the same at every level [m].
    pub gap_m: f64,
    /// The element at every level.
    pub contact: ContactModel,
    /// Linear elements (sears, linear, kelvin) in N/m; None: at each level the paper's
    /// E A/(L/n) with n = 10 of the slabs that meet there (in series for two; 15 GN/m for the
    /// paper's). Hertzian elements in N/m^1.5; None: the force the linear default gives at
    /// 1 mm of overlap (4.74e11 for the paper's slabs).
    pub stiffness: Option<f64>,
    /// Target restitution of kelvin, hertzdamp, jankowski and stereo. Default 0.65, a value
    /// measured for concrete-to-concrete impact (Jankowski).
    pub restitution: f64,
    /// Where the Sears element reads its law.
    pub reading: SlabReading,
    /// Sears zone length [m]; None: a tenth of the slab (the stiffer building's where two meet:
    /// the paper's choice).
    pub zone_length_m: Option<f64>,
    /// Damping ratio of the slabs' fundamental axial mode; all wave components decay with the
    /// same time constant T / (2 pi zeta) (T the slab's round trip). Default 0.05: undamped
    /// waves ring through the whole record, and 5% is the usual ratio for cracked concrete. 0
    /// reproduces the undamped d'Alembert response.
    pub slab_damping: f64,
    /// Contacts at one level closer in time than this form one impact event [s]. Default
    /// 0.02 s: three round trips of the paper's slabs (about 7 ms each, the period of the
    /// wave-driven sub-contacts) and a seventeenth of the stiffer building's period.
    pub merge_gap_s: f64,
    /// Accuracy target: the relative error the contact steps aim at (they are refined as
    /// 1/sqrt of it). The motion between contacts is integrated exactly.
    pub tolerance: f64,
    /// Steps per contact time scale inside contacts; None: from the tolerance.
    pub steps_per_scale: Option<f64>,
    /// Longest step outside contacts [s] (also bounded by the record's step).
    pub max_step_s: f64,
    /// The step budget of a run.
    pub max_steps: usize,
    /// What the run records of its histories.
    pub recording: super::Recording,
    /// Velocities of the buildings relative to the ground at t = 0 [m/s], every floor alike
    /// (free-vibration and isolated-impact studies); zero for an earthquake.
    pub initial_velocity_m_s: [f64; 2],
}

/// The tolerance the defaults aim at.
pub const DEFAULT_TOLERANCE: f64 = 1e-4;

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
        BuildingScenario {
            left: Building::one_storey(36_000.0, 1.16e7, 4.0, slab),
            right: Building::one_storey(45_000.0, 7.11e6, 4.0, slab),
            gap_m: 1e-3,
            contact: ContactModel::Sears,
            stiffness: None,
            restitution: 0.65,
            reading: SlabReading::Paper,
            zone_length_m: None,
            slab_damping: 0.05,
            merge_gap_s: 0.02,
            tolerance: DEFAULT_TOLERANCE,
            steps_per_scale: None,
            max_step_s: 0.005,
            max_steps: 20_000_000,
            recording: super::Recording::Plot,
            initial_velocity_m_s: [0.0, 0.0],
        }
    }

    /// The buildings' contact points.
    pub fn levels(&self) -> Vec<Level> {
        levels(&self.left.heights(), &self.right.heights())
    }

    /// The building with the higher fundamental frequency: 0 left, 1 right.
    fn stiffer(&self) -> usize {
        if self.left.fundamental_omega_squared() >= self.right.fundamental_omega_squared() {
            0
        } else {
            1
        }
    }

    /// The slabs meeting at a level, with their floors' masses: (left, right).
    pub fn level_slabs(&self, level: &Level) -> [Option<(Slab, f64)>; 2] {
        let side = |b: &Building, a: &Attachment| a.floor().map(|f| (b.slab(f), b.mass(f)));
        [
            side(&self.left, &level.left),
            side(&self.right, &level.right),
        ]
    }

    /// The element stiffness at a level (see [`BuildingScenario::stiffness`]).
    pub fn level_stiffness(&self, level: &Level) -> f64 {
        if let Some(k) = self.stiffness {
            return k;
        }
        let ks: Vec<f64> = self
            .level_slabs(level)
            .iter()
            .flatten()
            .map(|(s, _)| s.paper_stiffness_n_m())
            .collect();
        let linear = 1.0 / ks.iter().map(|k| 1.0 / k).sum::<f64>();
        if self.contact.is_hertzian() {
            linear / REFERENCE_OVERLAP_M.sqrt()
        } else {
            linear
        }
    }

    /// The element stiffness at the highest level (the roofs' for the paper's buildings).
    pub fn element_stiffness(&self) -> f64 {
        self.levels()
            .last()
            .map_or(f64::NAN, |l| self.level_stiffness(l))
    }

    /// The Sears zone length at a level: the same for both slabs that meet there.
    pub fn level_zone_length(&self, level: &Level) -> f64 {
        self.zone_length_with(level, || self.stiffer())
    }

    /// The Sears zone length at each of `levels`, the stiffer building found once (a tall
    /// building's fundamental frequency takes a thousand passes over its storeys).
    pub fn zone_lengths(&self, levels: &[Level]) -> Vec<f64> {
        let stiffer = std::cell::OnceCell::new();
        levels
            .iter()
            .map(|l| self.zone_length_with(l, || *stiffer.get_or_init(|| self.stiffer())))
            .collect()
    }

    /// The zone length at `level`, `stiffer` asked for only where no zone length is set.
    fn zone_length_with(&self, level: &Level, stiffer: impl FnOnce() -> usize) -> f64 {
        self.zone_length_m.unwrap_or_else(|| {
            let slabs = self.level_slabs(level);
            let stiffer = stiffer();
            let slab = slabs[stiffer]
                .or(slabs[1 - stiffer])
                .expect("a level has a floor on one side at least");
            slab.0.length_m / PAPER_DIVISIONS
        })
    }

    /// The Sears zone length at the highest level.
    pub fn zone_length(&self) -> f64 {
        self.levels()
            .last()
            .map_or(f64::NAN, |l| self.level_zone_length(l))
    }

    /// The impedances of the slabs meeting at a level in series [N s/m]: times an approach
    /// velocity, the wave-theory pounding force. A column side counts as rigid.
    pub fn level_series_impedance_n_s_m(&self, level: &Level) -> f64 {
        let zs: Vec<f64> = self
            .level_slabs(level)
            .iter()
            .flatten()
            .map(|(s, m)| s.impedance_n_s_m(*m))
            .collect();
        1.0 / zs.iter().map(|z| 1.0 / z).sum::<f64>()
    }

    /// The roof slabs' impedances in series (the highest level's).
    pub fn slab_series_impedance_n_s_m(&self) -> f64 {
        self.levels()
            .last()
            .map_or(f64::NAN, |l| self.level_series_impedance_n_s_m(l))
    }

    /// The steps per contact time scale a run uses.
    pub fn steps_per_scale(&self) -> f64 {
        self.steps_per_scale
            .unwrap_or_else(|| steps_for_tolerance(self.tolerance, self.contact.contact_order()))
    }

    /// Checks every value against its range in the settings table; the error names the key.
    pub fn validate(&self) -> Result<(), InputError> {
        for (i, b) in [&self.left, &self.right].into_iter().enumerate() {
            b.validate(i)?;
        }
        setting::GAP.check_at(0, self.gap_m)?;
        if let Some(k) = self.stiffness {
            setting::CONTACT_STIFFNESS.check_at(0, k)?;
        }
        setting::RESTITUTION.check_at(0, self.restitution)?;
        if let Some(d) = self.zone_length_m {
            setting::ZONE_LENGTH.check_at(0, d)?;
        }
        self.zone_fits_the_slabs()?;
        setting::SLAB_DAMPING.check_at(0, self.slab_damping)?;
        setting::MERGE_GAP.check_at(0, self.merge_gap_s)?;
        setting::TOLERANCE.check_at(0, self.tolerance)?;
        if let Some(s) = self.steps_per_scale {
            setting::STEPS_PER_SCALE.check_at(0, s)?;
        }
        setting::MAX_STEP.check_at(0, self.max_step_s)?;
        setting::MAX_STEPS.check_at(0, self.max_steps as f64)?;
        for (i, v) in self.initial_velocity_m_s.into_iter().enumerate() {
            setting::VELOCITY.check_at(i, v)?;
        }
        Ok(())
    }

    /// The paper reading puts the law a zone length inside each slab: a zone longer than the
    /// slab's round trip would read the law outside it.
    fn zone_fits_the_slabs(&self) -> Result<(), InputError> {
        if !(self.contact == ContactModel::Sears && self.reading == SlabReading::Paper) {
            return Ok(());
        }
        let levels = self.levels();
        for (level, d) in levels.iter().zip(self.zone_lengths(&levels)) {
            for (name, slab) in SIDES.iter().zip(self.level_slabs(level)) {
                if let Some((s, _)) = slab
                    && d >= 2.0 * s.length_m
                {
                    return Err(InputError::new(
                        setting::ZONE_LENGTH.key,
                        format!(
                            "{d} m is not allowed: the paper reading needs d < 2 L = {} m of the {name} slab",
                            2.0 * s.length_m
                        ),
                    ));
                }
            }
        }
        Ok(())
    }
}

impl Building {
    /// Checks the building's values against the settings table; `side` is 0 for the left one.
    fn validate(&self, side: usize) -> Result<(), InputError> {
        let b = self;
        setting::STOREYS.check_at(side, b.storeys as f64)?;
        for (setting, list) in [
            (&setting::MASSES, &b.masses_kg),
            (&setting::STIFFNESSES, &b.stiffnesses_n_m),
            (&setting::HEIGHTS, &b.heights_m),
            (&setting::SLAB_LENGTH, &b.slab_lengths_m),
            (&setting::SLAB_WIDTH, &b.slab_widths_m),
            (&setting::SLAB_THICKNESS, &b.slab_thicknesses_m),
            (&setting::SLAB_YOUNGS_MODULUS, &b.slab_youngs_pa),
        ] {
            check_per_storey(setting, side, list, b.storeys)?;
        }
        setting::DAMPING_RATIO.check_at(side, b.damping_ratio)?;
        b.validate_yielding(side)?;
        spread_of_modes(side, b)?;
        b.check_rayleigh_modes(side)
    }

    /// The yield forces (one or one per storey), the hardening and Bouc-Wen's exponent.
    fn validate_yielding(&self, side: usize) -> Result<(), InputError> {
        if let Some(list) = &self.yield_forces_n {
            check_per_storey(&setting::YIELD_FORCES, side, list, self.storeys)?;
        }
        setting::HARDENING.check_at(side, self.hardening)?;
        setting::BOUC_WEN_N.check_at(side, self.bouc_wen_n)
    }

    /// Rayleigh damping's two modes must be two of the building's.
    fn check_rayleigh_modes(&self, side: usize) -> Result<(), InputError> {
        let DampingModel::Rayleigh { modes: [i, j] } = self.damping else {
            return Ok(());
        };
        let key = setting::RAYLEIGH_MODES.key_of(side);
        // One storey has one mode, which Rayleigh damping gives the ratio: only the default
        // pair 1,2 is meaningful there, and any other pair would be silently ignored.
        if self.storeys == 1 && !matches!((i, j), (1, 2) | (2, 1)) {
            return Err(InputError::new(
                key,
                format!(
                    "modes {i} and {j} are not allowed: one storey has one mode, which Rayleigh damping gives the ratio; leave {} at 1,2 or use {} = {}",
                    setting::RAYLEIGH_MODES.name(),
                    setting::DAMPING.key_of(side),
                    DampingModel::Modal.name()
                ),
            ));
        }
        if (i == 0 || j == 0 || i > self.storeys || j > self.storeys || i == j) && self.storeys > 1
        {
            return Err(InputError::new(
                key,
                format!(
                    "modes {i} and {j} are not allowed: two different modes in [1, {}]",
                    self.storeys
                ),
            ));
        }
        Ok(())
    }
}

/// A per-storey list: one value for every storey or one each, each within the setting's range.
fn check_per_storey(
    setting: &crate::model::settings::Setting,
    side: usize,
    list: &[f64],
    storeys: usize,
) -> Result<(), InputError> {
    if list.len() != 1 && list.len() != storeys {
        return Err(InputError::new(
            setting.key_of(side),
            format!(
                "{} values for {storeys} storeys: give one value for every storey, or {storeys}",
                list.len()
            ),
        ));
    }
    for &v in list {
        setting.check_at(side, v)?;
    }
    Ok(())
}

/// Steps per contact time scale that aim at a relative error `tolerance` with contact steps of
/// convergence order p: the error goes as (1/steps)^p, and 8 steps gave about 1e-3 in the max
/// force of the paper's case, hence 8 (1e-3 / tolerance)^(1/p).
pub fn steps_for_tolerance(tolerance: f64, order: f64) -> f64 {
    (8.0 * (1e-3 / tolerance).powf(1.0 / order)).max(1.0)
}

/// The widest spread of squared frequencies whose smallest is still computed to about 1e-6:
/// the eigen solver's round-off is relative to the largest.
const MAX_MODE_SPREAD: f64 = 1e10;

/// Refuses a building whose storeys differ so much that its longest period is lost to
/// round-off (it would come out as infinite, or as noise).
fn spread_of_modes(side: usize, b: &Building) -> Result<(), InputError> {
    if b.storeys < 2 {
        return Ok(());
    }
    // By bisection: the whole eigen solution takes millions of operations for 100 storeys.
    let (lo, hi) = super::modal::omega_squared_range(&b.masses(), &b.stiffnesses());
    if lo > 0.0 && hi.is_finite() && hi / lo <= MAX_MODE_SPREAD {
        return Ok(());
    }
    Err(InputError::new(
        setting::STIFFNESSES.key_of(side),
        format!(
            "the storeys' stiffnesses and masses differ so much that the squared frequencies span more than {MAX_MODE_SPREAD:e}, so the longest period is lost to round-off; bring the storey stiffnesses (and masses) within a factor of about 1e9 of each other"
        ),
    ))
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_new_storey_count_resizes_each_per_storey_list_and_leaves_single_values() {
        let mut b = super::Building::one_storey(
            1e5,
            1e7,
            3.0,
            super::Slab {
                length_m: 10.0,
                width_m: 1.0,
                thickness_m: 0.2,
                youngs_modulus_pa: 3e10,
            },
        );
        b.masses_kg = vec![1e5, 2e5, 3e5];
        b.yield_forces_n = Some(vec![4e5, 5e5, 6e5]);
        b.storeys = 3;
        b.set_storeys(5);
        assert_eq!(b.storeys, 5);
        assert_eq!(b.masses_kg, [1e5, 2e5, 3e5, 3e5, 3e5]);
        assert_eq!(
            b.yield_forces_n.as_deref(),
            Some(&[4e5, 5e5, 6e5, 6e5, 6e5][..])
        );
        assert_eq!(
            b.stiffnesses_n_m,
            [1e7],
            "one value for every storey stays one"
        );
        b.set_storeys(2);
        assert_eq!(b.masses_kg, [1e5, 2e5]);
        assert_eq!(b.yield_forces_n.as_deref(), Some(&[4e5, 5e5][..]));
        assert!(b.validate(0).is_ok(), "{:?}", b.validate(0));
    }

    use super::*;

    /// A building of `storeys` storeys of the paper's left building's values.
    fn tall(storeys: usize) -> Building {
        Building {
            storeys,
            ..BuildingScenario::paper().left
        }
    }

    #[test]
    fn a_tall_buildings_remembered_modes_are_its_own_and_a_changed_one_gets_its_own() {
        let direct = |b: &Building| {
            Modes::of_shear_building(&b.masses(), &b.stiffnesses(), b.damping_ratio, b.damping)
        };
        let a = tall(30);
        // Asked twice: the second answer is the remembered one, the same bits as solving again.
        assert_eq!(a.modes(), direct(&a));
        assert_eq!(a.modes(), direct(&a));
        // One storey's stiffness, the damping ratio, the damping model changed: each is another
        // building, whose modes are its own, not the remembered ones.
        let mut stiffer = a.clone();
        stiffer.stiffnesses_n_m = (0..30)
            .map(|j| a.stiffnesses()[j] * if j == 7 { 1.5 } else { 1.0 })
            .collect();
        let damped = Building {
            damping_ratio: 0.02,
            ..a.clone()
        };
        let rayleigh = Building {
            damping: DampingModel::Rayleigh { modes: [1, 3] },
            ..a.clone()
        };
        for other in [&stiffer, &damped, &rayleigh, &tall(31)] {
            let (got, expected) = (other.modes(), direct(other));
            assert_eq!(got, expected);
            assert_ne!(got, direct(&a));
        }
        // Five buildings asked for since: the first is solved again, still its own.
        assert_eq!(a.modes(), direct(&a));
    }
}
