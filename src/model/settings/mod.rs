//! Every setting once: its key, label, unit, help, the range it is validated against, the range
//! a slider spans, whether that slider is logarithmic, and its default. The command line's
//! `--list-keys`, the window's rows, the sweeps' list of parameters and the validation messages
//! all read these tables.
//!
//! A key with `barN` stands for `bar1` and `bar2`, one with `SIDE` for `left` and `right`.
//! Each setting is a const in [`impact`] or [`building`], so the code that reads, writes or
//! checks one names the const, never its key.

use super::error::InputError;
use std::borrow::Cow;
use std::fmt;

pub mod bridge;
pub mod building;
pub mod impact;

pub use bridge::BRIDGE_SETTINGS;
pub use building::BUILDING_SETTINGS;
pub use impact::{IMPACT_MAX_STEPS, IMPACT_SETTINGS};

/// The owners a `barN.` key is spelled out for: index 0 is the left bar, moving right.
pub const BARS: [&str; 2] = ["bar1", "bar2"];
/// The owners a `SIDE.` key is spelled out for: index 0 is the left building.
pub const SIDES: [&str; 2] = ["left", "right"];

/// The placeholder of a key's owner in the tables, and the owners it stands for.
const OWNERS: [(&str, &[&str; 2]); 2] = [("barN", &BARS), ("SIDE", &SIDES)];

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

/// A quantity as an engineer writes it: three significant figures with an SI prefix (30.1 J,
/// 1.59 MN, 7.73 ms, 0 Pa), no exponent and no negative zero.
pub fn engineering(x: f64, unit: &str) -> String {
    const PREFIXES: [(i32, &str); 9] = [
        (-12, "p"),
        (-9, "n"),
        (-6, "u"),
        (-3, "m"),
        (0, ""),
        (3, "k"),
        (6, "M"),
        (9, "G"),
        (12, "T"),
    ];
    if !x.is_finite() {
        return format!("{x} {unit}");
    }
    // Rounded to three figures first, so 999.96 reads 1.00 k, not 1000.
    let rounded = if x == 0.0 {
        0.0
    } else {
        let digits = 2 - x.abs().log10().floor() as i32;
        let f = 10f64.powi(digits);
        (x * f).round() / f
    };
    if rounded == 0.0 {
        return format!("0 {unit}");
    }
    let power = (rounded.abs().log10() / 3.0).floor() as i32 * 3;
    let (p, prefix) = PREFIXES
        .iter()
        .copied()
        .min_by_key(|(p, _)| (p - power).abs())
        .expect("prefixes");
    let m = rounded / 10f64.powi(p);
    let decimals = (2 - m.abs().log10().floor() as i32).max(0) as usize;
    format!("{m:.decimals$} {prefix}{unit}")
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

    /// The word a number setting takes instead of a number (auto, flat), if any.
    pub fn word(&self) -> Option<&'static str> {
        match self.kind {
            Kind::Number { word, .. } => word,
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
                format!("{range}{unit}; one value for all, or one each, by commas")
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

impl Setting {
    /// The owners its key is spelled out for (`bar1`, `bar2` for a `barN.` key), or none.
    pub fn owners(&self) -> &'static [&'static str] {
        let Some((placeholder, _)) = self.key.split_once('.') else {
            return &[];
        };
        OWNERS
            .iter()
            .find(|(p, _)| *p == placeholder)
            .map_or(&[], |(_, owners)| &owners[..])
    }

    /// How many concrete keys it has: two for a `barN.` or `SIDE.` key, else one.
    pub fn owner_count(&self) -> usize {
        self.owners().len().max(1)
    }

    /// Its concrete key for owner `owner` (0: bar1 or left, 1: bar2 or right); the key itself
    /// where it has no owner.
    pub fn key_of(&self, owner: usize) -> Cow<'static, str> {
        match (self.owners().get(owner), self.key.split_once('.')) {
            (Some(o), Some((_, name))) => Cow::Owned(format!("{o}.{name}")),
            _ => Cow::Borrowed(self.key),
        }
    }

    /// Which owner's concrete key `key` is (0 where the setting has no owner), if it is one of
    /// this setting's.
    pub fn owner_of(&self, key: &str) -> Option<usize> {
        let owners = self.owners();
        if owners.is_empty() {
            return (key == self.key).then_some(0);
        }
        let (owner, name) = key.split_once('.')?;
        let (_, own_name) = self.key.split_once('.')?;
        if name != own_name {
            return None;
        }
        owners.iter().position(|o| *o == owner)
    }

    /// The part of its key before the dot (`contact` of `contact.law`, `bar1` of `barN.length`
    /// for owner 0), or the whole key: the group a row belongs to, the table a preset writes it in.
    pub fn group(&self, owner: usize) -> Cow<'static, str> {
        match (self.owners().get(owner), self.key.split_once('.')) {
            (Some(o), _) => Cow::Borrowed(*o),
            (None, Some((group, _))) => Cow::Borrowed(group),
            (None, None) => Cow::Borrowed(self.key),
        }
    }

    /// The part of its key after the dot (`length` of `barN.length`), or the whole key.
    pub fn name(&self) -> &'static str {
        self.key.split_once('.').map_or(self.key, |(_, name)| name)
    }

    /// `value` of owner `owner` checked against the accepted range; the concrete key is only
    /// spelled out for an error (validation runs this for every solve of a sweep).
    pub fn check_at(&self, owner: usize, value: f64) -> Result<(), InputError> {
        match self.range() {
            Some(r) if !r.contains(value) => self.check(&self.key_of(owner), value),
            _ => Ok(()),
        }
    }
}

/// The key a table lists for `key`: `bar1.length` is `barN.length`, `left.masses` is
/// `SIDE.masses`.
pub fn generic(key: &str) -> String {
    if let Some((owner, rest)) = key.split_once('.')
        && let Some((placeholder, _)) = OWNERS.iter().find(|(_, os)| os.contains(&owner))
    {
        return format!("{placeholder}.{rest}");
    }
    key.to_string()
}

/// The setting of `key` in `table`.
pub fn find(table: &'static [Setting], key: &str) -> Option<&'static Setting> {
    table.iter().find(|s| s.owner_of(key).is_some())
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
    let row = table.iter().find_map(|s| {
        let index = if s.owners().is_empty() {
            (s.group(0) == owner).then_some(0)
        } else {
            s.owners().iter().position(|o| *o == owner)
        };
        index.filter(|_| s.name() == name).map(|i| (s, i))
    });
    match row {
        Some((s, i)) => s.check_at(i, value),
        None => Err(not_listed(&format!("{owner}.{name}"))),
    }
}

/// An axis label for a concrete key: "bar 2 length [m]" for `bar2.length`, "left period [s]"
/// for `left.period`, the key itself where the table does not list it.
pub fn axis_label(table: &'static [Setting], key: &str) -> String {
    let Some(s) = find(table, key) else {
        return key.to_string();
    };
    let owners = s.owners();
    let owner = match s.owner_of(key) {
        Some(i) if owners == BARS => format!("bar {} ", i + 1),
        Some(i) if !owners.is_empty() => format!("{} ", owners[i]),
        _ => String::new(),
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
        .flat_map(|s| (0..s.owner_count()).map(|i| s.key_of(i).into_owned()))
        .collect()
}

pub(crate) const fn number(range: Range, slider: (f64, f64), log: bool) -> Kind {
    Kind::Number {
        range,
        slider,
        log,
        word: None,
    }
}

pub(crate) const fn number_or(
    range: Range,
    slider: (f64, f64),
    log: bool,
    word: &'static str,
) -> Kind {
    Kind::Number {
        range,
        slider,
        log,
        word: Some(word),
    }
}

#[cfg(test)]
mod tests {

    #[test]
    fn engineering_numbers_read_as_an_engineer_writes_them() {
        for (x, unit, want) in [
            (30.13, "J", "30.1 J"),
            (-0.0, "Pa", "0 Pa"),
            (1.5944e5, "N", "159 kN"),
            (7.7337e-3, "s", "7.73 ms"),
            (999.96, "N", "1.00 kN"),
            (2.1e11, "Pa", "210 GPa"),
            (-20.301e6, "Pa", "-20.3 MPa"),
        ] {
            assert_eq!(engineering(x, unit), want, "{x} {unit}");
        }
    }

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
        for table in [IMPACT_SETTINGS, BUILDING_SETTINGS, BRIDGE_SETTINGS] {
            let mut keys: Vec<&str> = table.iter().map(|s| s.key).collect();
            keys.sort();
            let n = keys.len();
            keys.dedup();
            assert_eq!(keys.len(), n);
        }
    }
}
