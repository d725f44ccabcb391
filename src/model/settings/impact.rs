//! The settings of one impact of two bars, one const each; [`IMPACT_SETTINGS`] lists them in
//! the order `--list-keys` shows them.

// Each const is named for its key, and its `help` is its documentation.
#![allow(missing_docs)]

use super::{Kind, Range, Setting, number, number_or};
use crate::model::contact::LawKind;
use crate::model::impact::ModelKind;
use crate::model::material::MaterialPreset;
use crate::model::scenario::Reading;

/// The most steps an impact run may take: its histories take about 48 bytes a step, so this
/// bounds them at a gigabyte.
pub const IMPACT_MAX_STEPS: u64 = 20_000_000;

pub const MODEL: Setting = Setting {
    key: "model",
    label: "model",
    unit: "",
    help: "the impact model",
    kind: Kind::Choice(&ModelKind::NAMES),
    default: "sears",
};

pub const MATERIAL: Setting = Setting {
    key: "barN.material",
    label: "material",
    unit: "",
    help: "sets E, nu and rho (later keys override them)",
    kind: Kind::Choice(&MaterialPreset::NAMES),
    default: "steel",
};

pub const YOUNGS_MODULUS: Setting = Setting {
    key: "barN.youngs_modulus",
    label: "E",
    unit: "Pa",
    help: "Young's modulus: stiffer bars carry faster waves and a stiffer Hertz contact",
    kind: number(Range::closed(1e3, 1e13), (1e8, 1e12), true),
    default: "2.1e11",
};

pub const POISSON_RATIO: Setting = Setting {
    key: "barN.poisson_ratio",
    label: "nu",
    unit: "",
    help: "Poisson's ratio",
    kind: number(Range::open(-1.0, 0.5), (0.0, 0.49), false),
    default: "0.3",
};

pub const DENSITY: Setting = Setting {
    key: "barN.density",
    label: "density",
    unit: "kg/m^3",
    help: "mass density: with E it sets the wave speed c = sqrt(E / rho)",
    kind: number(Range::closed(1.0, 1e5), (100.0, 30000.0), true),
    default: "7850",
};

pub const LENGTH: Setting = Setting {
    key: "barN.length",
    label: "length",
    unit: "m",
    help: "bar length L: the round trip 2L/c sets when reflections return to the contact",
    kind: number(Range::closed(1e-6, 1e6), (0.005, 100.0), true),
    default: "1 (bar1), 2 (bar2)",
};

pub const RADIUS: Setting = Setting {
    key: "barN.radius",
    label: "radius",
    unit: "m",
    help: "rod radius: sets the area (mass, impedance Z = A sqrt(E rho)) and Sears' zone length d",
    kind: number(Range::closed(1e-6, 1e3), (0.002, 2.0), true),
    default: "0.05",
};

pub const AREA: Setting = Setting {
    key: "barN.area",
    label: "area",
    unit: "m^2",
    help: "cross-section area of any section (instead of a radius)",
    kind: number(Range::closed(1e-12, 1e6), (1e-5, 10.0), true),
    default: "from the radius",
};

pub const ADDED_MASS: Setting = Setting {
    key: "barN.added_mass",
    label: "added mass",
    unit: "kg",
    help: "mass spread over the bar: slows the waves and shifts the impact towards lumped behaviour",
    kind: number(Range::closed(0.0, 1e12), (0.0, 1e5), true),
    default: "0",
};

pub const VELOCITY: Setting = Setting {
    key: "barN.velocity",
    label: "velocity",
    unit: "m/s",
    help: "rigid-body velocity before impact, positive to the right",
    kind: number(Range::closed(-1e5, 1e5), (-100.0, 100.0), false),
    default: "1 (bar1), 0 (bar2)",
};

pub const END_RADIUS: Setting = Setting {
    key: "barN.end_radius",
    label: "end radius",
    unit: "m",
    help: "radius of the rounded impacting end: a larger dome is a stiffer Hertz contact",
    kind: number_or(Range::closed(1e-6, 1e6), (0.002, 10.0), true, "flat"),
    default: "0.05 (bar1), flat (bar2)",
};

pub const CONTACT_LAW: Setting = Setting {
    key: "contact.law",
    label: "law",
    unit: "",
    help: "Hertz F = k delta^1.5 for rounded ends, linear F = kL delta for flat ones",
    kind: Kind::Choice(&LawKind::NAMES),
    default: "hertz",
};

pub const CONTACT_STIFFNESS: Setting = Setting {
    key: "contact.stiffness",
    label: "stiffness",
    unit: "N/m^1.5 (hertz) or N/m (linear)",
    help: "contact stiffness: stiffer contact means a shorter, more wave-like impact; auto is Hertz from the ends, linear from E A/(L/n)",
    kind: number_or(Range::closed(1.0, 1e20), (1e4, 1e16), true, "auto"),
    default: "auto",
};

pub const ZONE_SCALE: Setting = Setting {
    key: "contact.zone_scale",
    label: "zone scale",
    unit: "x d",
    help: "multiplier on Sears' compression-zone length d (the paper varies it from 0.01 to 10)",
    kind: number(Range::closed(1e-6, 1e3), (1e-4, 10.0), true),
    default: "1",
};

pub const ZONE_LENGTH: Setting = Setting {
    key: "contact.zone_length",
    label: "zone length",
    unit: "m",
    help: "zone length d for both bars instead of Sears' Eq. 5",
    kind: number_or(Range::closed(1e-9, 1e6), (1e-4, 10.0), true, "auto"),
    default: "auto",
};

pub const DIVISIONS: Setting = Setting {
    key: "contact.divisions",
    label: "divisions",
    unit: "",
    help: "n in the paper's linear stiffness E A/(L/n)",
    kind: number(Range::closed(1e-3, 1e6), (1.0, 100.0), true),
    default: "10",
};

pub const RESTITUTION: Setting = Setting {
    key: "contact.restitution",
    label: "restitution",
    unit: "",
    help: "target e of the Kelvin-Voigt and stereomechanics models",
    kind: number(Range::closed(0.0, 1.0), (0.0, 1.0), false),
    default: "0.65",
};

pub const SEARS_READING: Setting = Setting {
    key: "sears.reading",
    label: "Sears reading",
    unit: "",
    help: "paper: delayed planes (not energy-consistent); collocated: a massless zone spring; end: the law at the bar ends (d -> 0)",
    kind: Kind::Choice(&Reading::NAMES),
    default: "paper",
};

pub const DT: Setting = Setting {
    key: "solver.dt",
    label: "step",
    unit: "s",
    help: "time step; refined automatically where the contact is faster",
    kind: number(Range::closed(1e-15, 1.0), (1e-10, 1e-4), true),
    default: "1e-6",
};

pub const WINDOW: Setting = Setting {
    key: "solver.window",
    label: "window",
    unit: "s",
    help: "simulated span; 0 runs until the bars separate for good",
    kind: number(Range::closed(0.0, 1e4), (0.0, 0.1), false),
    default: "0",
};

pub const MAX_STEPS: Setting = Setting {
    key: "solver.max_steps",
    label: "step budget",
    unit: "",
    help: "the most steps a run may take (its histories take about 48 bytes a step)",
    kind: Kind::Count {
        min: 1,
        max: IMPACT_MAX_STEPS,
    },
    default: "4000000",
};

pub const REFINE: Setting = Setting {
    key: "solver.refine",
    label: "refine",
    unit: "",
    help: "refine a step too coarse for the contact's time scale",
    kind: Kind::Bool,
    default: "true",
};

pub const FE_SEGMENTS: Setting = Setting {
    key: "fe.segments",
    label: "FE segments",
    unit: "per bar",
    help: "finite elements per bar",
    kind: Kind::Count {
        min: 1,
        max: 1_000_000,
    },
    default: "100",
};

pub const FE_COURANT: Setting = Setting {
    key: "fe.courant",
    label: "Courant",
    unit: "",
    help: "fraction of the explicit stability limit min(dx / c) used as the FE step",
    kind: number(Range::open(0.0, 1.0), (0.1, 0.99), false),
    default: "0.9",
};

/// The settings of one impact of two bars.
pub static IMPACT_SETTINGS: &[Setting] = &[
    MODEL,
    MATERIAL,
    YOUNGS_MODULUS,
    POISSON_RATIO,
    DENSITY,
    LENGTH,
    RADIUS,
    AREA,
    ADDED_MASS,
    VELOCITY,
    END_RADIUS,
    CONTACT_LAW,
    CONTACT_STIFFNESS,
    ZONE_SCALE,
    ZONE_LENGTH,
    DIVISIONS,
    RESTITUTION,
    SEARS_READING,
    DT,
    WINDOW,
    MAX_STEPS,
    REFINE,
    FE_SEGMENTS,
    FE_COURANT,
];
