//! Every setting once: its key, label, unit, help, the range it is validated against, the range
//! a slider spans, whether that slider is logarithmic, and its default. The command line's
//! `--list-keys`, the window's rows, the sweeps' list of parameters and the validation messages
//! all read these tables.
//!
//! A key with `barN` stands for `bar1` and `bar2`, one with `SIDE` for `left` and `right`.

use super::error::InputError;
use std::fmt;

/// A closed or open interval of accepted values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    /// Lower end.
    pub min: f64,
    /// Upper end.
    pub max: f64,
    /// Whether `min` itself is refused.
    pub min_open: bool,
    /// Whether `max` itself is refused.
    pub max_open: bool,
}

impl Range {
    /// [min, max].
    pub const fn closed(min: f64, max: f64) -> Self {
        Range {
            min,
            max,
            min_open: false,
            max_open: false,
        }
    }
    /// (min, max]: a positive quantity.
    pub const fn above(min: f64, max: f64) -> Self {
        Range {
            min,
            max,
            min_open: true,
            max_open: false,
        }
    }
    /// [min, max): a ratio below one, say.
    pub const fn below(min: f64, max: f64) -> Self {
        Range {
            min,
            max,
            min_open: false,
            max_open: true,
        }
    }
    /// (min, max).
    pub const fn open(min: f64, max: f64) -> Self {
        Range {
            min,
            max,
            min_open: true,
            max_open: true,
        }
    }

    /// The smallest accepted value: `min`, or the next number above it when `min` is refused.
    pub fn low_accepted(&self) -> f64 {
        if self.min_open {
            self.min.next_up()
        } else {
            self.min
        }
    }

    /// The largest accepted value.
    pub fn high_accepted(&self) -> f64 {
        if self.max_open {
            self.max.next_down()
        } else {
            self.max
        }
    }

    /// Whether `x` is accepted (never a NaN or an infinity).
    pub fn contains(&self, x: f64) -> bool {
        x.is_finite()
            && (if self.min_open {
                x > self.min
            } else {
                x >= self.min
            })
            && (if self.max_open {
                x < self.max
            } else {
                x <= self.max
            })
    }
}

/// A number as messages show it: plain between 1e-3 and 1e4, in exponent form outside (1e300
/// would otherwise print three hundred digits).
pub fn shown(x: f64) -> String {
    if x != 0.0 && x.is_finite() && !(1e-3..1e4).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

impl fmt::Display for Range {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let num = shown;
        write!(
            f,
            "{}{}, {}{}",
            if self.min_open { '(' } else { '[' },
            num(self.min),
            num(self.max),
            if self.max_open { ')' } else { ']' }
        )
    }
}

/// What a setting holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kind {
    /// A number in `range`; a slider spans `slider`, logarithmically if `log`. `word` is a word
    /// that stands instead of a number (auto, flat), if the setting takes one.
    Number {
        /// Accepted values.
        range: Range,
        /// What the slider spans.
        slider: (f64, f64),
        /// Whether the slider is logarithmic.
        log: bool,
        /// A word accepted instead of a number.
        word: Option<&'static str>,
    },
    /// One number for every storey, or one per storey, each in `range`.
    List {
        /// Accepted values of each.
        range: Range,
        /// What the slider spans.
        slider: (f64, f64),
        /// Whether the slider is logarithmic.
        log: bool,
    },
    /// A whole number.
    Count {
        /// Smallest.
        min: u64,
        /// Largest.
        max: u64,
    },
    /// One of these words.
    Choice(&'static [&'static str]),
    /// true or false.
    Bool,
    /// Free text (a file).
    Text,
}

/// One setting.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Setting {
    /// The key (`barN` for bar1 and bar2, `SIDE` for left and right).
    pub key: &'static str,
    /// What the window's row shows.
    pub label: &'static str,
    /// Its unit (empty for none).
    pub unit: &'static str,
    /// One line on what it does.
    pub help: &'static str,
    /// What it holds and accepts.
    pub kind: Kind,
    /// As a user would type it.
    pub default: &'static str,
}

impl Setting {
    /// The values a choice accepts (`None` for other kinds).
    pub fn choices(&self) -> Option<&'static [&'static str]> {
        match self.kind {
            Kind::Choice(options) => Some(options),
            _ => None,
        }
    }

    /// The accepted range of a number or list.
    pub fn range(&self) -> Option<Range> {
        match self.kind {
            Kind::Number { range, .. } | Kind::List { range, .. } => Some(range),
            Kind::Count { min, max } => Some(Range::closed(min as f64, max as f64)),
            _ => None,
        }
    }

    /// A one-line description: help, what is accepted, the default.
    pub fn describe(&self) -> String {
        let unit = if self.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", self.unit)
        };
        let accepted = match self.kind {
            Kind::Number { range, word, .. } => match word {
                Some(w) => format!("{range}{unit}, or {w}"),
                None => format!("{range}{unit}"),
            },
            Kind::List { range, .. } => {
                format!("{range}{unit}; one value for every storey, or one each, by commas")
            }
            Kind::Count { min, max } => format!("a whole number in [{min}, {max}]"),
            Kind::Choice(options) => options.join("|"),
            Kind::Bool => "true|false".into(),
            Kind::Text => "text".into(),
        };
        format!("{}: {accepted}; default {}", self.help, self.default)
    }

    /// `value` checked against the accepted range; the error names `field` (the key with its
    /// bar or side) and the range.
    pub fn check(&self, field: &str, value: f64) -> Result<(), InputError> {
        let Some(range) = self.range() else {
            return Ok(());
        };
        if range.contains(value) {
            return Ok(());
        }
        let unit = if self.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", self.unit)
        };
        let or_word = match self.kind {
            Kind::Number { word: Some(w), .. } => format!(" (or {w})"),
            _ => String::new(),
        };
        Err(InputError::new(
            field,
            format!(
                "{} is not allowed: must lie in {range}{unit}{or_word}",
                shown(value)
            ),
        ))
    }
}

/// The key a table lists for `key`: `bar1.length` is `barN.length`, `left.masses` is
/// `SIDE.masses`.
pub fn generic(key: &str) -> String {
    for (prefix, general) in [
        ("bar1.", "barN."),
        ("bar2.", "barN."),
        ("left.", "SIDE."),
        ("right.", "SIDE."),
    ] {
        if let Some(rest) = key.strip_prefix(prefix) {
            return format!("{general}{rest}");
        }
    }
    key.to_string()
}

/// The setting of `key` in `table`.
pub fn find(table: &'static [Setting], key: &str) -> Option<&'static Setting> {
    // Without building the generic key: validation runs this for every solve of a sweep.
    let (prefix, rest) = key.split_once('.').unwrap_or(("", key));
    let general = match prefix {
        "bar1" | "bar2" => Some("barN"),
        "left" | "right" => Some("SIDE"),
        _ => None,
    };
    table.iter().find(|s| match general {
        Some(g) => s.key.split_once('.') == Some((g, rest)),
        None => s.key == key,
    })
}

/// Checks `value` of `field` against its row of `table`; a key the table does not list is an
/// error too (a check that passed for a misspelt key would check nothing).
pub fn check(table: &'static [Setting], field: &str, value: f64) -> Result<(), InputError> {
    match find(table, field) {
        Some(s) => s.check(field, value),
        None => Err(not_listed(field)),
    }
}

fn not_listed(field: &str) -> InputError {
    InputError::new(field, "no such setting in the settings table")
}

/// Checks `value` of `owner.name` (`bar1.length`) against its row of `table`; the key is only
/// spelled out for an error.
pub fn check_of(
    table: &'static [Setting],
    owner: &str,
    name: &str,
    value: f64,
) -> Result<(), InputError> {
    let general = match owner {
        "bar1" | "bar2" => "barN",
        "left" | "right" => "SIDE",
        other => other,
    };
    let row = table
        .iter()
        .find(|s| s.key.split_once('.') == Some((general, name)));
    match row {
        Some(s) if s.range().is_some_and(|r| !r.contains(value)) => {
            s.check(&format!("{owner}.{name}"), value)
        }
        Some(_) => Ok(()),
        None => Err(not_listed(&format!("{owner}.{name}"))),
    }
}

/// An axis label for a concrete key: "bar 2 length [m]" for `bar2.length`, "left period [s]"
/// for `left.period`, the key itself where the table does not list it.
pub fn axis_label(table: &'static [Setting], key: &str) -> String {
    let Some(s) = find(table, key) else {
        return key.to_string();
    };
    let owner = match key.split_once('.') {
        Some(("bar1", _)) => "bar 1 ",
        Some(("bar2", _)) => "bar 2 ",
        Some(("left", _)) => "left ",
        Some(("right", _)) => "right ",
        _ => "",
    };
    if s.unit.is_empty() {
        format!("{owner}{}", s.label)
    } else {
        format!("{owner}{} [{}]", s.label, s.unit)
    }
}

/// Every concrete key of a table: `barN` and `SIDE` keys spelled out for both.
pub fn concrete_keys(table: &[Setting]) -> Vec<String> {
    table
        .iter()
        .flat_map(|s| {
            if let Some(rest) = s.key.strip_prefix("barN.") {
                vec![format!("bar1.{rest}"), format!("bar2.{rest}")]
            } else if let Some(rest) = s.key.strip_prefix("SIDE.") {
                vec![format!("left.{rest}"), format!("right.{rest}")]
            } else {
                vec![s.key.to_string()]
            }
        })
        .collect()
}

const fn number(range: Range, slider: (f64, f64), log: bool) -> Kind {
    Kind::Number {
        range,
        slider,
        log,
        word: None,
    }
}

const fn number_or(range: Range, slider: (f64, f64), log: bool, word: &'static str) -> Kind {
    Kind::Number {
        range,
        slider,
        log,
        word: Some(word),
    }
}

/// The most steps an impact run may take: its histories take about 48 bytes a step, so this
/// bounds them at a gigabyte.
pub const IMPACT_MAX_STEPS: u64 = 20_000_000;

/// The settings of one impact of two bars.
pub static IMPACT_SETTINGS: &[Setting] = &[
    Setting {
        key: "model",
        label: "model",
        unit: "",
        help: "the impact model",
        kind: Kind::Choice(&[
            "sears",
            "wave",
            "lumped-hertz",
            "lumped-linear",
            "kelvin",
            "stereo",
            "fe",
        ]),
        default: "sears",
    },
    Setting {
        key: "barN.material",
        label: "material",
        unit: "",
        help: "sets E, nu and rho (later keys override them)",
        kind: Kind::Choice(&["steel", "concrete"]),
        default: "steel",
    },
    Setting {
        key: "barN.youngs_modulus",
        label: "E",
        unit: "Pa",
        help: "Young's modulus: stiffer bars carry faster waves and a stiffer Hertz contact",
        kind: number(Range::closed(1e3, 1e13), (1e8, 1e12), true),
        default: "2.1e11",
    },
    Setting {
        key: "barN.poisson_ratio",
        label: "nu",
        unit: "",
        help: "Poisson's ratio",
        kind: number(Range::open(-1.0, 0.5), (0.0, 0.49), false),
        default: "0.3",
    },
    Setting {
        key: "barN.density",
        label: "density",
        unit: "kg/m^3",
        help: "mass density: with E it sets the wave speed c = sqrt(E / rho)",
        kind: number(Range::closed(1.0, 1e5), (100.0, 30000.0), true),
        default: "7850",
    },
    Setting {
        key: "barN.length",
        label: "length",
        unit: "m",
        help: "bar length L: the round trip 2L/c sets when reflections return to the contact",
        kind: number(Range::closed(1e-6, 1e6), (0.005, 100.0), true),
        default: "1 (bar1), 2 (bar2)",
    },
    Setting {
        key: "barN.radius",
        label: "radius",
        unit: "m",
        help: "rod radius: sets the area (mass, impedance Z = A sqrt(E rho)) and Sears' zone length d",
        kind: number(Range::closed(1e-6, 1e3), (0.002, 2.0), true),
        default: "0.05",
    },
    Setting {
        key: "barN.area",
        label: "area",
        unit: "m^2",
        help: "cross-section area of any section (instead of a radius)",
        kind: number(Range::closed(1e-12, 1e6), (1e-5, 10.0), true),
        default: "from the radius",
    },
    Setting {
        key: "barN.added_mass",
        label: "added mass",
        unit: "kg",
        help: "mass spread over the bar: slows the waves and shifts the impact towards lumped behaviour",
        kind: number(Range::closed(0.0, 1e12), (0.0, 1e5), true),
        default: "0",
    },
    Setting {
        key: "barN.velocity",
        label: "velocity",
        unit: "m/s",
        help: "rigid-body velocity before impact, positive to the right",
        kind: number(Range::closed(-1e5, 1e5), (-100.0, 100.0), false),
        default: "1 (bar1), 0 (bar2)",
    },
    Setting {
        key: "barN.end_radius",
        label: "end radius",
        unit: "m",
        help: "radius of the rounded impacting end: a larger dome is a stiffer Hertz contact",
        kind: number_or(Range::closed(1e-6, 1e6), (0.002, 10.0), true, "flat"),
        default: "0.05 (bar1), flat (bar2)",
    },
    Setting {
        key: "contact.law",
        label: "law",
        unit: "",
        help: "Hertz F = k delta^1.5 for rounded ends, linear F = kL delta for flat ones",
        kind: Kind::Choice(&["hertz", "linear"]),
        default: "hertz",
    },
    Setting {
        key: "contact.stiffness",
        label: "stiffness",
        unit: "N/m^1.5 (hertz) or N/m (linear)",
        help: "contact stiffness: stiffer contact means a shorter, more wave-like impact; auto is Hertz from the ends, linear from E A/(L/n)",
        kind: number_or(Range::closed(1.0, 1e20), (1e4, 1e16), true, "auto"),
        default: "auto",
    },
    Setting {
        key: "contact.zone_scale",
        label: "zone scale",
        unit: "x d",
        help: "multiplier on Sears' compression-zone length d (the paper varies it from 0.01 to 10)",
        kind: number(Range::closed(1e-6, 1e3), (1e-4, 10.0), true),
        default: "1",
    },
    Setting {
        key: "contact.zone_length",
        label: "zone length",
        unit: "m",
        help: "zone length d for both bars instead of Sears' Eq. 5",
        kind: number_or(Range::closed(1e-9, 1e6), (1e-4, 10.0), true, "auto"),
        default: "auto",
    },
    Setting {
        key: "contact.divisions",
        label: "divisions",
        unit: "",
        help: "n in the paper's linear stiffness E A/(L/n)",
        kind: number(Range::closed(1e-3, 1e6), (1.0, 100.0), true),
        default: "10",
    },
    Setting {
        key: "contact.restitution",
        label: "restitution",
        unit: "",
        help: "target e of the Kelvin-Voigt and stereomechanics models",
        kind: number(Range::closed(0.0, 1.0), (0.0, 1.0), false),
        default: "0.65",
    },
    Setting {
        key: "sears.reading",
        label: "Sears reading",
        unit: "",
        help: "paper: delayed planes (not energy-consistent); collocated: a massless zone spring; end: the law at the bar ends (d -> 0)",
        kind: Kind::Choice(&["paper", "collocated", "end"]),
        default: "paper",
    },
    Setting {
        key: "solver.dt",
        label: "step",
        unit: "s",
        help: "time step; refined automatically where the contact is faster",
        kind: number(Range::closed(1e-15, 1.0), (1e-10, 1e-4), true),
        default: "1e-6",
    },
    Setting {
        key: "solver.window",
        label: "window",
        unit: "s",
        help: "simulated span; 0 runs until the bars separate for good",
        kind: number(Range::closed(0.0, 1e4), (0.0, 0.1), false),
        default: "0",
    },
    Setting {
        key: "solver.max_steps",
        label: "step budget",
        unit: "",
        help: "the most steps a run may take (its histories take about 48 bytes a step)",
        kind: Kind::Count {
            min: 1,
            max: IMPACT_MAX_STEPS,
        },
        default: "4000000",
    },
    Setting {
        key: "solver.refine",
        label: "refine",
        unit: "",
        help: "refine a step too coarse for the contact's time scale",
        kind: Kind::Bool,
        default: "true",
    },
    Setting {
        key: "fe.segments",
        label: "FE segments",
        unit: "per bar",
        help: "finite elements per bar",
        kind: Kind::Count {
            min: 1,
            max: 1_000_000,
        },
        default: "100",
    },
    Setting {
        key: "fe.courant",
        label: "Courant",
        unit: "",
        help: "fraction of the explicit stability limit min(dx / c) used as the FE step",
        kind: number(Range::open(0.0, 1.0), (0.1, 0.99), false),
        default: "0.9",
    },
];

/// The settings of two buildings pounding.
pub static BUILDING_SETTINGS: &[Setting] = &[
    Setting {
        key: "contact.model",
        label: "contact",
        unit: "",
        help: "the contact element (the --contact flag)",
        kind: Kind::Choice(&[
            "sears",
            "linear",
            "kelvin",
            "hertz",
            "hertzdamp",
            "jankowski",
            "stereo",
            "none",
        ]),
        default: "sears",
    },
    Setting {
        key: "SIDE.storeys",
        label: "storeys",
        unit: "",
        help: "number of storeys N (SIDE is left or right)",
        kind: Kind::Count { min: 1, max: 100 },
        default: "1",
    },
    Setting {
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
    },
    Setting {
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
    },
    Setting {
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
    },
    Setting {
        key: "SIDE.mass",
        label: "mass",
        unit: "kg",
        help: "every floor's mass",
        kind: number(Range::closed(1.0, 1e10), (1e2, 1e8), true),
        default: "as SIDE.masses",
    },
    Setting {
        key: "SIDE.stiffness",
        label: "stiffness",
        unit: "N/m",
        help: "every storey's stiffness",
        kind: number(Range::closed(1e-6, 1e13), (1e4, 1e11), true),
        default: "as SIDE.stiffnesses",
    },
    Setting {
        key: "SIDE.height",
        label: "height",
        unit: "m",
        help: "every storey's height",
        kind: number(Range::closed(0.01, 1e3), (0.5, 10.0), false),
        default: "4",
    },
    Setting {
        key: "SIDE.period",
        label: "period",
        unit: "s",
        help: "fundamental period: scales every storey's stiffness to it",
        kind: number(Range::closed(1e-4, 1e4), (0.05, 5.0), true),
        default: "from the masses and stiffnesses",
    },
    Setting {
        key: "SIDE.damping_ratio",
        label: "damping",
        unit: "",
        help: "viscous damping ratio (5% is the design-code value for concrete)",
        kind: number(Range::below(0.0, 1.0), (0.0, 0.5), false),
        default: "0.05",
    },
    Setting {
        key: "SIDE.damping",
        label: "damping model",
        unit: "",
        help: "modal: the ratio in every mode; rayleigh: C = a M + b K with the ratio in two modes",
        kind: Kind::Choice(&["modal", "rayleigh"]),
        default: "modal",
    },
    Setting {
        key: "SIDE.rayleigh_modes",
        label: "Rayleigh modes",
        unit: "",
        help: "the two modes (from 1) Rayleigh damping gives the ratio to, as i,j",
        kind: Kind::Text,
        default: "1,2",
    },
    Setting {
        key: "SIDE.velocity",
        label: "velocity",
        unit: "m/s",
        help: "velocity of every floor relative to the ground at t = 0 (isolated-impact studies)",
        kind: number(Range::closed(-1e3, 1e3), (-2.0, 2.0), false),
        default: "0",
    },
    Setting {
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
    },
    Setting {
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
    },
    Setting {
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
    },
    Setting {
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
    },
    Setting {
        key: "gap",
        label: "gap",
        unit: "m",
        help: "at-rest separation, the same at every level",
        kind: number(Range::closed(0.0, 1e3), (1e-4, 0.5), true),
        default: "0.001",
    },
    Setting {
        key: "contact.stiffness",
        label: "stiffness",
        unit: "N/m (N/m^1.5 for hertz, hertzdamp, jankowski)",
        help: "element stiffness (the paper: 15 GN/m); auto is the paper's E A/(L/n) of the slabs at each level",
        kind: number_or(Range::closed(1.0, 1e20), (1e6, 1e14), true, "auto"),
        default: "auto",
    },
    Setting {
        key: "contact.restitution",
        label: "restitution",
        unit: "",
        help: "target restitution of kelvin, hertzdamp, jankowski and stereo (below 0.01 the damped elements are dashpots whose time scale m/c the contact steps do not resolve)",
        kind: number(Range::closed(0.01, 1.0), (0.05, 1.0), false),
        default: "0.65",
    },
    Setting {
        key: "contact.reading",
        label: "Sears reading",
        unit: "",
        help: "the Sears reading: the paper's delayed planes or the slab ends",
        kind: Kind::Choice(&["paper", "end"]),
        default: "paper",
    },
    Setting {
        key: "contact.zone_length",
        label: "zone length",
        unit: "m",
        help: "Sears zone length d; auto is a tenth of the stiffer building's slab",
        kind: number_or(Range::closed(1e-6, 1e3), (0.01, 10.0), true, "auto"),
        default: "auto",
    },
    Setting {
        key: "slab.damping",
        label: "slab damping",
        unit: "",
        help: "damping ratio of the slabs' axial waves; 0 lets them ring through the record (undamped d'Alembert)",
        kind: number(Range::below(0.0, 1.0), (0.0, 0.5), false),
        default: "0.05",
    },
    Setting {
        key: "impact.merge_gap_s",
        label: "merge gap",
        unit: "s",
        help: "contacts at one level closer than this form one impact",
        kind: number(Range::closed(0.0, 1e3), (0.0, 0.5), false),
        default: "0.02",
    },
    Setting {
        key: "motion.file",
        label: "record",
        unit: "",
        help: "the ground motion: a built-in record (elcentro-1940), a file (.AT2 or text), or synthetic; the --motion flag",
        kind: Kind::Text,
        default: "elcentro-1940 (paper-buildings)",
    },
    Setting {
        key: "motion.units",
        label: "units",
        unit: "",
        help: "units of a text file (AT2 files are in g)",
        kind: Kind::Choice(&["g", "m/s2", "cm/s2"]),
        default: "g",
    },
    Setting {
        key: "motion.scale",
        label: "scale",
        unit: "x",
        help: "factor on the record; negative flips it, 0 is refused",
        kind: number(Range::closed(-100.0, 100.0), (-5.0, 5.0), false),
        default: "1",
    },
    Setting {
        key: "motion.duration",
        label: "duration",
        unit: "s",
        help: "use only the first seconds of the record",
        kind: number(Range::above(0.0, 1e6), (0.0, 120.0), false),
        default: "the whole record (8 s in paper-buildings)",
    },
    Setting {
        key: "motion.dt",
        label: "record step",
        unit: "s",
        help: "step of a values-only text file",
        kind: number(Range::closed(1e-6, 10.0), (1e-3, 0.1), true),
        default: "none",
    },
    Setting {
        key: "motion.pga",
        label: "PGA",
        unit: "g",
        help: "synthetic record: peak ground acceleration",
        kind: number(Range::above(0.0, 100.0), (0.01, 2.0), false),
        default: "0.3",
    },
    Setting {
        key: "motion.seed",
        label: "seed",
        unit: "",
        help: "synthetic record: random seed",
        kind: Kind::Count {
            min: 0,
            max: 1 << 53,
        },
        default: "1940",
    },
    Setting {
        key: "motion.length",
        label: "length",
        unit: "s",
        help: "synthetic record: length",
        kind: number(Range::above(0.0, 1e5), (1.0, 120.0), false),
        default: "20",
    },
    Setting {
        key: "solver.tolerance",
        label: "tolerance",
        unit: "",
        help: "accuracy target of the contact steps, relative (the motion between contacts is exact)",
        kind: number(Range::closed(1e-12, 0.1), (1e-6, 1e-2), true),
        default: "1e-4",
    },
    Setting {
        key: "solver.steps_per_scale",
        label: "steps per scale",
        unit: "",
        help: "steps per contact time scale inside contacts; auto follows the tolerance",
        kind: number_or(Range::closed(1.0, 1e6), (2.0, 200.0), true, "auto"),
        default: "auto",
    },
    Setting {
        key: "solver.max_step",
        label: "longest free step",
        unit: "s",
        help: "longest step between contacts (the motion there is exact: it sets how densely it is recorded)",
        kind: number(Range::above(0.0, 1e3), (1e-4, 0.02), true),
        default: "0.005",
    },
    Setting {
        key: "solver.max_steps",
        label: "step budget",
        unit: "",
        help: "the most steps a run may take",
        kind: Kind::Count {
            min: 1,
            max: 100_000_000,
        },
        default: "20000000",
    },
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_say_what_they_accept() {
        let r = Range::above(0.0, 1e6);
        assert!(!r.contains(0.0) && r.contains(1e6) && !r.contains(f64::NAN));
        assert_eq!(r.to_string(), "(0, 1e6]");
        assert_eq!(Range::below(0.0, 1.0).to_string(), "[0, 1)");
        let s = find(IMPACT_SETTINGS, "bar2.length").unwrap();
        let e = s.check("bar2.length", -1.0).unwrap_err();
        assert_eq!(e.field, "bar2.length");
        assert!(e.message.contains("[1e-6, 1e6] m"), "{}", e.message);
    }

    #[test]
    fn a_key_the_table_does_not_list_fails_its_check() {
        let e = check(IMPACT_SETTINGS, "bar2.lenght", 1.0).unwrap_err();
        assert_eq!(e.field, "bar2.lenght");
        assert!(check(IMPACT_SETTINGS, "bar2.length", 1.0).is_ok());
        assert!(check_of(BUILDING_SETTINGS, "left", "masess", 1.0).is_err());
        assert!(check_of(BUILDING_SETTINGS, "left", "masses", 1.0).is_ok());
    }

    #[test]
    fn axis_labels_name_the_bar_the_quantity_and_its_unit() {
        assert_eq!(
            axis_label(IMPACT_SETTINGS, "bar2.length"),
            "bar 2 length [m]"
        );
        assert_eq!(
            axis_label(BUILDING_SETTINGS, "left.period"),
            "left period [s]"
        );
        assert_eq!(axis_label(IMPACT_SETTINGS, "nonsense"), "nonsense");
    }

    #[test]
    fn every_key_is_listed_once() {
        for table in [IMPACT_SETTINGS, BUILDING_SETTINGS] {
            let mut keys: Vec<&str> = table.iter().map(|s| s.key).collect();
            keys.sort();
            let n = keys.len();
            keys.dedup();
            assert_eq!(keys.len(), n);
        }
    }
}
