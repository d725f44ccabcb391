//! Linear-elastic materials and the two presets the paper uses.

/// A linear-elastic, isotropic material. SI units throughout.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// Young's modulus E [Pa].
    pub youngs_modulus_pa: f64,
    /// Poisson's ratio nu [-], physically in (-1, 0.5).
    pub poisson_ratio: f64,
    /// Mass density rho [kg/m^3].
    pub density_kg_m3: f64,
}

/// Named materials. The values are stated here once so every front end quotes the same numbers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MaterialPreset {
    /// Structural steel: E = 210 GPa, nu = 0.30, rho = 7850 kg/m^3.
    Steel,
    /// M20 concrete: E = 5000 sqrt(fck) MPa with fck = 20 MPa (IS 456), i.e. 22.36 GPa,
    /// nu = 0.20, rho = 2400 kg/m^3 (plain concrete).
    Concrete,
}

impl MaterialPreset {
    /// Every preset.
    pub const ALL: [MaterialPreset; 2] = [MaterialPreset::Steel, MaterialPreset::Concrete];

    /// Every preset's name, in the order of [`MaterialPreset::ALL`].
    pub const NAMES: [&'static str; 2] = crate::model::names_of!(Self::ALL, 2);

    /// The name presets and the command line use.
    pub const fn name(self) -> &'static str {
        match self {
            MaterialPreset::Steel => "steel",
            MaterialPreset::Concrete => "concrete",
        }
    }

    /// The preset of that name.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == name)
    }

    /// Its elastic constants and density.
    pub fn material(self) -> Material {
        match self {
            MaterialPreset::Steel => Material {
                youngs_modulus_pa: 210e9,
                poisson_ratio: 0.30,
                density_kg_m3: 7850.0,
            },
            MaterialPreset::Concrete => Material {
                youngs_modulus_pa: 5000e6 * 20f64.sqrt(),
                poisson_ratio: 0.20,
                density_kg_m3: 2400.0,
            },
        }
    }
}

impl Default for Material {
    fn default() -> Self {
        MaterialPreset::Steel.material()
    }
}
