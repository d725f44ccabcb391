//! A uniaxial elastic bar (or slab) and the quantities derived from it.

use super::material::Material;

/// Cross-section of a bar.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Section {
    /// Circular rod of the given radius [m].
    Circular {
        /// Radius [m].
        radius_m: f64,
    },
    /// Any section (a slab, say) of the given area [m^2]. Where a radius is needed (the Sears
    /// zone length), the radius of the circle of equal area is used.
    Area {
        /// Area [m^2].
        area_m2: f64,
    },
}

/// Shape of the impacting end.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EndShape {
    /// A flat end: no Hertz curvature.
    Flat,
    /// Spherical cap of the given radius [m].
    Rounded {
        /// Radius of the cap [m].
        radius_m: f64,
    },
}

impl EndShape {
    /// Curvature 1/r of the end [1/m]; a flat end has none.
    pub fn curvature_per_m(self) -> f64 {
        match self {
            EndShape::Flat => 0.0,
            EndShape::Rounded { radius_m } => 1.0 / radius_m,
        }
    }
}

/// One of the two colliding bodies. Bar 1 sits on the left and moves right; its impacting end
/// is its right end. Bar 2 sits on the right; its impacting end is its left end.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bar {
    /// Elastic constants and density.
    pub material: Material,
    /// Cross-section.
    pub section: Section,
    /// Length L [m].
    pub length_m: f64,
    /// Superimposed mass M [kg], spread uniformly over the bar (it adds inertia, not stiffness).
    pub added_mass_kg: f64,
    /// Rigid-body velocity before impact [m/s], positive to the right.
    pub velocity_m_s: f64,
    /// Shape of the impacting end.
    pub end: EndShape,
}

impl Bar {
    /// Cross-section area A [m^2].
    pub fn area_m2(&self) -> f64 {
        match self.section {
            Section::Circular { radius_m } => std::f64::consts::PI * radius_m * radius_m,
            Section::Area { area_m2 } => area_m2,
        }
    }

    /// Radius used by Sears' zone formula: the rod radius, or the equal-area radius.
    pub fn radius_m(&self) -> f64 {
        match self.section {
            Section::Circular { radius_m } => radius_m,
            Section::Area { area_m2 } => (area_m2 / std::f64::consts::PI).sqrt(),
        }
    }

    /// Effective density rho~ = rho + M/(A L) [kg/m^3].
    pub fn effective_density_kg_m3(&self) -> f64 {
        self.material.density_kg_m3 + self.added_mass_kg / (self.area_m2() * self.length_m)
    }

    /// Bar wave speed c = sqrt(E / rho~) [m/s].
    pub fn wave_speed_m_s(&self) -> f64 {
        (self.material.youngs_modulus_pa / self.effective_density_kg_m3()).sqrt()
    }

    /// Mechanical impedance Z = A sqrt(E rho~) [N s/m].
    pub fn impedance_n_s_m(&self) -> f64 {
        self.area_m2() * (self.material.youngs_modulus_pa * self.effective_density_kg_m3()).sqrt()
    }

    /// Axial stiffness E A [N].
    pub fn axial_rigidity_n(&self) -> f64 {
        self.material.youngs_modulus_pa * self.area_m2()
    }

    /// Total mass m = rho~ A L [kg].
    pub fn mass_kg(&self) -> f64 {
        self.effective_density_kg_m3() * self.area_m2() * self.length_m
    }

    /// Time for a wave to cross the bar and come back, 2 L / c [s].
    pub fn round_trip_s(&self) -> f64 {
        2.0 * self.length_m / self.wave_speed_m_s()
    }

    /// Sears' compression-zone length (paper Eq. 5), before any user scale:
    /// d = R [ sqrt(3/2) + (1 + nu)(3 - 2 nu) / sqrt(6) ] [m].
    pub fn sears_zone_length_m(&self) -> f64 {
        let nu = self.material.poisson_ratio;
        self.radius_m() * (1.5f64.sqrt() + (1.0 + nu) * (3.0 - 2.0 * nu) / 6f64.sqrt())
    }

    /// Rigid-body kinetic energy m v^2 / 2 before impact [J].
    pub fn kinetic_energy_j(&self) -> f64 {
        0.5 * self.mass_kg() * self.velocity_m_s * self.velocity_m_s
    }
}
