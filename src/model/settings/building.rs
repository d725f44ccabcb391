//! The settings of two buildings pounding, one const each; [`BUILDING_SETTINGS`] lists them in
//! the order `--list-keys` shows them.

// Each const is named for its key, and its `help` is its documentation.
#![allow(missing_docs)]

use super::{Kind, Range, Setting, number, number_or};
use crate::model::building::{ContactModel, DampingModel, Recording, SlabReading};
use crate::model::hysteresis::Hysteresis;
use crate::model::motion::Units;

pub const CONTACT_MODEL: Setting = Setting {
    key: "contact.model",
    label: "contact",
    unit: "",
    help: "the contact element (the --contact flag)",
    kind: Kind::Choice(&ContactModel::NAMES),
    default: "sears",
};

pub const STOREYS: Setting = Setting {
    key: "SIDE.storeys",
    label: "storeys",
    unit: "",
    help: "number of storeys N (SIDE is left or right)",
    kind: Kind::Count { min: 1, max: 100 },
    default: "1",
};

pub const MASSES: Setting = Setting {
    key: "SIDE.masses",
    label: "floor mass",
    unit: "kg",
    help: "floor masses: with the stiffnesses they set the periods",
    kind: Kind::List {
        range: Range::closed(1.0, 1e10),
        slider: (1e2, 1e8),
        log: true,
    },
    default: "36000 (left), 45000 (right)",
};

pub const STIFFNESSES: Setting = Setting {
    key: "SIDE.stiffnesses",
    label: "storey stiffness",
    unit: "N/m",
    help: "storey shear stiffnesses",
    kind: Kind::List {
        range: Range::closed(1e-6, 1e13),
        slider: (1e4, 1e11),
        log: true,
    },
    default: "1.16e7 (left), 7.11e6 (right)",
};

pub const HEIGHTS: Setting = Setting {
    key: "SIDE.heights",
    label: "storey height",
    unit: "m",
    help: "storey heights: the floors' elevations decide where the buildings meet",
    kind: Kind::List {
        range: Range::closed(0.01, 1e3),
        slider: (0.5, 10.0),
        log: false,
    },
    default: "4",
};

pub const MASS: Setting = Setting {
    key: "SIDE.mass",
    label: "mass",
    unit: "kg",
    help: "every floor's mass",
    kind: number(Range::closed(1.0, 1e10), (1e2, 1e8), true),
    default: "as SIDE.masses",
};

pub const STIFFNESS: Setting = Setting {
    key: "SIDE.stiffness",
    label: "stiffness",
    unit: "N/m",
    help: "every storey's stiffness",
    kind: number(Range::closed(1e-6, 1e13), (1e4, 1e11), true),
    default: "as SIDE.stiffnesses",
};

pub const HEIGHT: Setting = Setting {
    key: "SIDE.height",
    label: "height",
    unit: "m",
    help: "every storey's height",
    kind: number(Range::closed(0.01, 1e3), (0.5, 10.0), false),
    default: "4",
};

pub const PERIOD: Setting = Setting {
    key: "SIDE.period",
    label: "period",
    unit: "s",
    help: "fundamental period: scales every storey's stiffness to it",
    kind: number(Range::closed(1e-4, 1e4), (0.05, 5.0), true),
    default: "from the masses and stiffnesses",
};

pub const DAMPING_RATIO: Setting = Setting {
    key: "SIDE.damping_ratio",
    label: "damping",
    unit: "",
    help: "viscous damping ratio (5% is the design-code value for concrete)",
    kind: number(Range::below(0.0, 1.0), (0.0, 0.5), false),
    default: "0.05",
};

pub const DAMPING: Setting = Setting {
    key: "SIDE.damping",
    label: "damping model",
    unit: "",
    help: "modal: the ratio in every mode; rayleigh: C = a M + b K with the ratio in two modes",
    kind: Kind::Choice(&DampingModel::NAMES),
    default: "modal",
};

pub const RAYLEIGH_MODES: Setting = Setting {
    key: "SIDE.rayleigh_modes",
    label: "Rayleigh modes",
    unit: "",
    help: "the two modes (from 1) Rayleigh damping gives the ratio to, as i,j",
    kind: Kind::Text,
    default: "1,2",
};

pub const HYSTERESIS: Setting = Setting {
    key: "SIDE.hysteresis",
    label: "storey law",
    unit: "",
    help: "the storeys' shear springs: elastic, bilinear (kinematic hardening) or bouc-wen",
    kind: Kind::Choice(&Hysteresis::NAMES),
    default: "elastic",
};

pub const YIELD_FORCES: Setting = Setting {
    key: "SIDE.yield_forces",
    label: "yield force",
    unit: "N",
    help: "storey yield forces F_y, one for every storey or one each, or auto (bilinear, bouc-wen)",
    kind: Kind::List {
        range: Range::closed(1e-3, 1e15),
        slider: (1e3, 1e8),
        log: true,
    },
    default: "auto: the force at a drift of 0.5% of the storey height",
};

pub const HARDENING: Setting = Setting {
    key: "SIDE.hardening",
    label: "hardening",
    unit: "",
    help: "post-yield stiffness over the initial stiffness, b",
    kind: number(Range::below(0.0, 1.0), (0.0, 0.5), false),
    default: "0.05",
};

pub const BOUC_WEN_N: Setting = Setting {
    key: "SIDE.bouc_wen_n",
    label: "Bouc-Wen n",
    unit: "",
    help: "Bouc-Wen's exponent: the larger, the sharper the knee (the bilinear curve in the limit)",
    kind: number(Range::closed(1.0, 100.0), (1.0, 20.0), true),
    default: "2",
};

pub const VELOCITY: Setting = Setting {
    key: "SIDE.velocity",
    label: "velocity",
    unit: "m/s",
    help: "velocity of every floor relative to the ground at t = 0 (isolated-impact studies)",
    kind: number(Range::closed(-1e3, 1e3), (-2.0, 2.0), false),
    default: "0",
};

pub const SLAB_LENGTH: Setting = Setting {
    key: "SIDE.slab_length",
    label: "slab length",
    unit: "m",
    help: "floor slab length along the pounding direction",
    kind: Kind::List {
        range: Range::closed(0.01, 1e3),
        slider: (1.0, 50.0),
        log: false,
    },
    default: "10",
};

pub const SLAB_WIDTH: Setting = Setting {
    key: "SIDE.slab_width",
    label: "slab width",
    unit: "m",
    help: "floor slab width",
    kind: Kind::List {
        range: Range::closed(0.01, 1e3),
        slider: (1.0, 50.0),
        log: false,
    },
    default: "8",
};

pub const SLAB_THICKNESS: Setting = Setting {
    key: "SIDE.slab_thickness",
    label: "slab thickness",
    unit: "m",
    help: "floor slab thickness",
    kind: Kind::List {
        range: Range::closed(1e-3, 10.0),
        slider: (0.05, 1.0),
        log: false,
    },
    default: "0.15",
};

pub const SLAB_YOUNGS_MODULUS: Setting = Setting {
    key: "SIDE.youngs_modulus",
    label: "slab E",
    unit: "Pa",
    help: "floor slab Young's modulus",
    kind: Kind::List {
        range: Range::closed(1e3, 1e13),
        slider: (1e9, 1e11),
        log: true,
    },
    default: "2.5e10",
};

pub const GAP: Setting = Setting {
    key: "gap",
    label: "gap",
    unit: "m",
    help: "at-rest separation, the same at every level",
    kind: number(Range::closed(0.0, 1e3), (1e-4, 0.5), true),
    default: "0.001",
};

pub const CONTACT_STIFFNESS: Setting = Setting {
    key: "contact.stiffness",
    label: "stiffness",
    unit: "N/m (N/m^1.5 for hertz, hertzdamp, jankowski)",
    help: "element stiffness (the paper: 15 GN/m); auto is the paper's E A/(L/n) of the slabs at each level",
    kind: number_or(Range::closed(1.0, 1e20), (1e6, 1e14), true, "auto"),
    default: "auto",
};

pub const RESTITUTION: Setting = Setting {
    key: "contact.restitution",
    label: "restitution",
    unit: "",
    help: "target restitution of kelvin, hertzdamp, jankowski and stereo (below 0.01 the damped elements are dashpots whose time scale m/c the contact steps do not resolve)",
    kind: number(Range::closed(0.01, 1.0), (0.05, 1.0), false),
    default: "0.65",
};

pub const CONTACT_READING: Setting = Setting {
    key: "contact.reading",
    label: "Sears reading",
    unit: "",
    help: "the Sears reading: the paper's delayed planes or the slab ends",
    kind: Kind::Choice(&SlabReading::NAMES),
    default: "paper",
};

pub const ZONE_LENGTH: Setting = Setting {
    key: "contact.zone_length",
    label: "zone length",
    unit: "m",
    help: "Sears zone length d; auto is a tenth of the stiffer building's slab",
    kind: number_or(Range::closed(1e-6, 1e3), (0.01, 10.0), true, "auto"),
    default: "auto",
};

pub const SLAB_DAMPING: Setting = Setting {
    key: "slab.damping",
    label: "slab damping",
    unit: "",
    help: "damping ratio of the slabs' axial waves; 0 lets them ring through the record (undamped d'Alembert)",
    kind: number(Range::below(0.0, 1.0), (0.0, 0.5), false),
    default: "0.05",
};

pub const MERGE_GAP: Setting = Setting {
    key: "impact.merge_gap_s",
    label: "merge gap",
    unit: "s",
    help: "contacts at one level closer than this form one impact",
    kind: number(Range::closed(0.0, 1e3), (0.0, 0.5), false),
    default: "0.02",
};

pub const MOTION_FILE: Setting = Setting {
    key: "motion.file",
    label: "record",
    unit: "",
    help: "the ground motion: a built-in record (elcentro-1940), a file (.AT2 or text), or synthetic; the --motion flag",
    kind: Kind::Text,
    default: "elcentro-1940 (paper-buildings)",
};

pub const MOTION_UNITS: Setting = Setting {
    key: "motion.units",
    label: "units",
    unit: "",
    help: "units of a text file (AT2 files are in g)",
    kind: Kind::Choice(&Units::NAMES),
    default: "g",
};

pub const MOTION_SCALE: Setting = Setting {
    key: "motion.scale",
    label: "scale",
    unit: "x",
    help: "factor on the record; negative flips it, 0 is refused",
    kind: number(Range::closed(-100.0, 100.0), (-5.0, 5.0), false),
    default: "1",
};

pub const MOTION_DURATION: Setting = Setting {
    key: "motion.duration",
    label: "duration",
    unit: "s",
    help: "use only the first seconds of the record",
    kind: number(Range::above(0.0, 1e6), (0.0, 120.0), false),
    default: "the whole record (8 s in paper-buildings)",
};

pub const MOTION_DT: Setting = Setting {
    key: "motion.dt",
    label: "record step",
    unit: "s",
    help: "step of a values-only text file",
    kind: number(Range::closed(1e-6, 10.0), (1e-3, 0.1), true),
    default: "none",
};

pub const MOTION_PGA: Setting = Setting {
    key: "motion.pga",
    label: "PGA",
    unit: "g",
    help: "synthetic record: peak ground acceleration",
    kind: number(Range::above(0.0, 100.0), (0.01, 2.0), false),
    default: "0.3",
};

/// The largest seed: every whole number up to it is held exactly by the f64 a setting's value
/// travels as, so a seed is run as typed or refused, never rounded.
pub const MAX_SEED: u64 = (1 << 53) - 1;

pub const MOTION_SEED: Setting = Setting {
    key: "motion.seed",
    label: "seed",
    unit: "",
    help: "synthetic record: random seed",
    kind: Kind::Count {
        min: 0,
        max: MAX_SEED,
    },
    default: "1940",
};

pub const MOTION_LENGTH: Setting = Setting {
    key: "motion.length",
    label: "length",
    unit: "s",
    help: "synthetic record: length",
    kind: number(Range::above(0.0, 1e5), (1.0, 120.0), false),
    default: "20",
};

pub const MOTION_SETTLE: Setting = Setting {
    key: "motion.settle_s",
    label: "settling",
    unit: "s",
    help: "seconds of rest appended to the record, so a residual drift settles before it is read",
    kind: number(Range::closed(0.0, 1e4), (0.0, 30.0), false),
    default: "0",
};

pub const TOLERANCE: Setting = Setting {
    key: "solver.tolerance",
    label: "tolerance",
    unit: "",
    help: "accuracy target of the contact steps, relative (the motion between contacts is exact)",
    kind: number(Range::closed(1e-12, 0.1), (1e-6, 1e-2), true),
    default: "1e-4",
};

pub const STEPS_PER_SCALE: Setting = Setting {
    key: "solver.steps_per_scale",
    label: "steps per scale",
    unit: "",
    help: "steps per contact time scale inside contacts; auto follows the tolerance",
    kind: number_or(Range::closed(1.0, 1e6), (2.0, 200.0), true, "auto"),
    default: "auto",
};

pub const MAX_STEP: Setting = Setting {
    key: "solver.max_step",
    label: "longest free step",
    unit: "s",
    help: "longest step between contacts (the motion there is exact: it sets how densely it is recorded)",
    kind: number(Range::above(0.0, 1e3), (1e-4, 0.02), true),
    default: "0.005",
};

pub const MAX_STEPS: Setting = Setting {
    key: "solver.max_steps",
    label: "step budget",
    unit: "",
    help: "the most steps a run may take",
    kind: Kind::Count {
        min: 1,
        max: 100_000_000,
    },
    default: "20000000",
};

pub const RECORD: Setting = Setting {
    key: "solver.record",
    label: "recorded samples",
    unit: "",
    help: "what the histories keep: what a plot needs (a few samples per contact time scale), or every step the solver takes",
    kind: Kind::Choice(&Recording::NAMES),
    default: "plot",
};

/// The settings of two buildings pounding.
pub static BUILDING_SETTINGS: &[Setting] = &[
    CONTACT_MODEL,
    STOREYS,
    MASSES,
    STIFFNESSES,
    HEIGHTS,
    MASS,
    STIFFNESS,
    HEIGHT,
    PERIOD,
    DAMPING_RATIO,
    DAMPING,
    RAYLEIGH_MODES,
    HYSTERESIS,
    YIELD_FORCES,
    HARDENING,
    BOUC_WEN_N,
    VELOCITY,
    SLAB_LENGTH,
    SLAB_WIDTH,
    SLAB_THICKNESS,
    SLAB_YOUNGS_MODULUS,
    GAP,
    CONTACT_STIFFNESS,
    RESTITUTION,
    CONTACT_READING,
    ZONE_LENGTH,
    SLAB_DAMPING,
    MERGE_GAP,
    MOTION_FILE,
    MOTION_UNITS,
    MOTION_SCALE,
    MOTION_DURATION,
    MOTION_DT,
    MOTION_PGA,
    MOTION_SEED,
    MOTION_LENGTH,
    MOTION_SETTLE,
    TOLERANCE,
    STEPS_PER_SCALE,
    MAX_STEP,
    MAX_STEPS,
    RECORD,
];
