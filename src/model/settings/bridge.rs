//! The settings of a bridge whose girders pound at their joints, one const each;
//! [`BRIDGE_SETTINGS`] lists them in the order `--list-keys` shows them. The contact, motion
//! and solver settings the buildings have are the buildings' own rows.

// Each const is named for its key, and its `help` is its documentation.
#![allow(missing_docs)]

use super::{Kind, Range, Setting, number, number_or};

pub use super::building::{
    CONTACT_MODEL, MAX_STEPS, MERGE_GAP, MOTION_DT, MOTION_DURATION, MOTION_FILE, MOTION_LENGTH,
    MOTION_PGA, MOTION_SCALE, MOTION_SEED, MOTION_UNITS, RESTITUTION, STEPS_PER_SCALE, TOLERANCE,
};

pub const SPANS: Setting = Setting {
    key: "bridge.spans",
    label: "spans",
    unit: "",
    help: "number of frames N between the abutments (a girder on bearings on a pier each)",
    kind: Kind::Count { min: 1, max: 20 },
    default: "3",
};

const fn per_span(range: Range, slider: (f64, f64), log: bool) -> Kind {
    Kind::List { range, slider, log }
}

pub const SPAN_LENGTH: Setting = Setting {
    key: "span.length",
    label: "girder length",
    unit: "m",
    help: "girder lengths, one for every span or one each",
    kind: per_span(Range::closed(0.1, 2000.0), (5.0, 200.0), true),
    default: "40",
};

pub const SPAN_AREA: Setting = Setting {
    key: "span.area",
    label: "girder area",
    unit: "m^2",
    help: "girder cross-section areas",
    kind: per_span(Range::closed(1e-4, 1e3), (0.5, 50.0), true),
    default: "6.5",
};

pub const SPAN_YOUNGS_MODULUS: Setting = Setting {
    key: "span.youngs_modulus",
    label: "girder E",
    unit: "Pa",
    help: "girder Young's moduli",
    kind: per_span(Range::closed(1e6, 1e13), (1e9, 3e11), true),
    default: "3.4e10",
};

pub const SPAN_DENSITY: Setting = Setting {
    key: "span.density",
    label: "girder density",
    unit: "kg/m^3",
    help: "girder densities",
    kind: per_span(Range::closed(1.0, 1e5), (300.0, 10000.0), true),
    default: "2500",
};

pub const SPAN_ADDED_MASS: Setting = Setting {
    key: "span.added_mass",
    label: "added mass",
    unit: "kg",
    help: "mass each girder carries besides its own (deck, barriers), spread over its length",
    kind: per_span(Range::closed(0.0, 1e10), (0.0, 1e7), false),
    default: "0",
};

pub const SPAN_VELOCITY: Setting = Setting {
    key: "span.velocity",
    label: "initial velocity",
    unit: "m/s",
    help: "each girder's velocity relative to its ground at t = 0 (isolated-impact studies)",
    kind: per_span(Range::closed(-1e3, 1e3), (-2.0, 2.0), false),
    default: "0",
};

pub const PIER_MASS: Setting = Setting {
    key: "pier.mass",
    label: "pier-top mass",
    unit: "kg",
    help: "pier-top masses (with the pier cap and a share of the column)",
    kind: per_span(Range::closed(1.0, 1e10), (1e3, 1e7), true),
    default: "1e5",
};

pub const PIER_STIFFNESS: Setting = Setting {
    key: "pier.stiffness",
    label: "pier stiffness",
    unit: "N/m",
    help: "pier stiffnesses, ground to pier top",
    kind: per_span(Range::closed(1e-6, 1e13), (1e6, 1e10), true),
    default: "8e7, 2e8, 4e7",
};

pub const BEARING_STIFFNESS: Setting = Setting {
    key: "bearing.stiffness",
    label: "bearing stiffness",
    unit: "N/m",
    help: "bearing stiffnesses, pier top to girder",
    kind: per_span(Range::closed(1e-6, 1e13), (1e6, 1e10), true),
    default: "1e8",
};

pub const DAMPING_RATIO: Setting = Setting {
    key: "damping_ratio",
    label: "damping",
    unit: "",
    help: "modal damping ratio of both modes of every frame",
    kind: number(Range::below(0.0, 1.0), (0.0, 0.3), false),
    default: "0.05",
};

pub const JOINT_GAPS: Setting = Setting {
    key: "joint.gaps",
    label: "joint gap",
    unit: "m",
    help: "gaps at rest: one for every joint, or N + 1 from the left abutment",
    kind: per_span(Range::closed(0.0, 10.0), (0.0, 0.2), false),
    default: "0.05, 0.03, 0.03, 0.05",
};

pub const SEAT_LENGTH: Setting = Setting {
    key: "bridge.seat_length",
    label: "seat length",
    unit: "m",
    help: "a joint that opens further than this has unseated its girder (the run goes on)",
    kind: number(Range::above(0.0, 100.0), (0.02, 1.0), true),
    default: "0.25",
};

pub const CONTACT_STIFFNESS: Setting = Setting {
    key: "contact.stiffness",
    label: "stiffness",
    unit: "N/m (N/m^1.5 for hertz, hertzdamp, jankowski)",
    help: "element stiffness; auto is E A/(L/10) of the girders at each joint in series (an abutment is rigid)",
    kind: number_or(Range::closed(1.0, 1e20), (1e7, 1e13), true, "auto"),
    default: "auto",
};

pub const APPARENT_VELOCITY: Setting = Setting {
    key: "motion.apparent_velocity",
    label: "apparent velocity",
    unit: "m/s",
    help: "speed at which the ground motion travels along the bridge (a support at x sees a(t - x/v)); uniform: every support at once",
    kind: number_or(Range::closed(1.0, 1e15), (50.0, 1e5), true, "uniform"),
    default: "uniform",
};

pub const GIRDER_DAMPING: Setting = Setting {
    key: "girder.damping",
    label: "girder damping",
    unit: "",
    help: "damping ratio of the girders' axial waves (Sears); 0 lets them ring through the record",
    kind: number(Range::below(0.0, 1.0), (0.0, 0.5), false),
    default: "0.05",
};

pub const MAX_STEP: Setting = Setting {
    key: "solver.max_step",
    label: "longest step",
    unit: "s",
    help: "longest step; a bridge run takes one step throughout, the shorter of this and the contact's",
    kind: number(Range::above(0.0, 1.0), (1e-5, 0.01), true),
    default: "0.001",
};

/// The settings of a bridge.
pub static BRIDGE_SETTINGS: &[Setting] = &[
    CONTACT_MODEL,
    SPANS,
    SPAN_LENGTH,
    SPAN_AREA,
    SPAN_YOUNGS_MODULUS,
    SPAN_DENSITY,
    SPAN_ADDED_MASS,
    SPAN_VELOCITY,
    PIER_MASS,
    PIER_STIFFNESS,
    BEARING_STIFFNESS,
    DAMPING_RATIO,
    JOINT_GAPS,
    SEAT_LENGTH,
    CONTACT_STIFFNESS,
    RESTITUTION,
    GIRDER_DAMPING,
    MERGE_GAP,
    MOTION_FILE,
    MOTION_UNITS,
    MOTION_SCALE,
    MOTION_DURATION,
    MOTION_DT,
    MOTION_PGA,
    MOTION_SEED,
    MOTION_LENGTH,
    APPARENT_VELOCITY,
    TOLERANCE,
    STEPS_PER_SCALE,
    MAX_STEP,
    MAX_STEPS,
];
