//! Each setting once: its row of the settings table (`model::settings`) with how to read its
//! value from a setup and how to write a typed value into it. Presets and `--set` (`apply`), a
//! saved scene's TOML, a lesson's values and the window's rows all go through a [`Registry`], so
//! a key is spelled only in its table row.
//!
//! A `barN.` or `SIDE.` setting is one entry for both bars or sides: its functions take the
//! owner's index (0: bar1 or left, 1: bar2 or right).

use super::settings::SettingValue;
use crate::model::error::InputError;
use crate::model::settings::{Kind, Setting, shown};
use std::borrow::Cow;

/// Where a value is written: the setting, its concrete key (what an error names) and its owner.
#[derive(Debug, Clone, Copy)]
pub struct Target<'a> {
    pub setting: &'static Setting,
    pub key: &'a str,
    pub owner: usize,
}

/// The value a setup holds for one owner, as a user would type it; `None` where it holds none
/// of its own (an automatic stiffness, an area given by a radius, a value set through another
/// key).
pub type Get<S> = fn(&S, usize) -> Option<SettingValue>;
/// Writes a typed value; ill-typed values are errors naming the key. Range checks are left to
/// the scenario's validation (it sees the final combination), except where noted.
pub type Set<S> = fn(&mut S, &Target, &SettingValue) -> Result<(), InputError>;
/// What a setting works out to where the setup holds no value of its own (the area of a round
/// bar, a building's period).
pub type Derive<S> = fn(&S, usize) -> Option<f64>;

/// One setting of a setup.
pub struct Entry<S: 'static> {
    pub setting: &'static Setting,
    pub get: Get<S>,
    pub set: Set<S>,
    pub derive: Option<Derive<S>>,
}

impl<S> Entry<S> {
    pub const fn new(setting: &'static Setting, get: Get<S>, set: Set<S>) -> Self {
        Entry {
            setting,
            get,
            set,
            derive: None,
        }
    }

    /// The same entry, showing `derive` where the setup holds no value.
    pub const fn derived(self, derive: Derive<S>) -> Self {
        Entry {
            derive: Some(derive),
            ..self
        }
    }

    /// The value as a reader sees it: the one held, else the one worked out.
    pub fn shown(&self, setup: &S, owner: usize) -> Option<SettingValue> {
        (self.get)(setup, owner).or_else(|| {
            self.derive
                .and_then(|d| d(setup, owner))
                .map(SettingValue::Number)
        })
    }

    /// The value shown as one number (a list whose values all agree reads as that value).
    pub fn number(&self, setup: &S, owner: usize) -> Option<f64> {
        match self.shown(setup, owner)? {
            SettingValue::Number(x) => Some(x),
            SettingValue::List(xs) => uniform(&xs),
            _ => None,
        }
    }

    /// Writes `value` for `owner`.
    pub fn set_value(
        &self,
        setup: &mut S,
        owner: usize,
        value: &SettingValue,
    ) -> Result<(), InputError> {
        let key = self.setting.key_of(owner);
        let target = Target {
            setting: self.setting,
            key: &key,
            owner,
        };
        (self.set)(setup, &target, value)
    }

    /// Writes a number for `owner`, rounded where the setting counts (a slider gives fractions).
    pub fn set_number(&self, setup: &mut S, owner: usize, x: f64) -> Result<(), InputError> {
        let x = match self.setting.kind {
            Kind::Count { .. } => x.round(),
            _ => x,
        };
        self.set_value(setup, owner, &SettingValue::Number(x))
    }

    /// The value a saved scene writes, as TOML: the one held, or the table's word (auto) where
    /// the program picks it; `None` for what is not saved (a value worked out from others).
    fn saved(&self, setup: &S, owner: usize) -> Option<String> {
        match (self.get)(setup, owner) {
            Some(v) => Some(toml_value(self.setting, &v)),
            None => self.setting.word().map(toml_text),
        }
    }
}

/// The one value all of `values` share, if they do.
pub fn uniform(values: &[f64]) -> Option<f64> {
    let first = *values.first()?;
    values.iter().all(|v| *v == first).then_some(first)
}

/// Every setting of one kind of setup.
pub struct Registry<S: 'static> {
    /// In the order of the settings table.
    pub entries: &'static [Entry<S>],
    /// What an unknown key's message says about the placeholders (barN, SIDE).
    pub placeholders: &'static str,
}

impl<S> Registry<S> {
    /// The entry of a concrete key, and the key's owner.
    pub fn lookup(&self, key: &str) -> Option<(&'static Entry<S>, usize)> {
        self.entries
            .iter()
            .find_map(|e| e.setting.owner_of(key).map(|i| (e, i)))
    }

    /// The entry of a setting of the table.
    pub fn entry(&self, setting: &Setting) -> &'static Entry<S> {
        self.entries
            .iter()
            .find(|e| e.setting.key == setting.key)
            .unwrap_or_else(|| panic!("{} has an entry in the registry", setting.key))
    }

    /// The settings, in the table's order.
    pub fn settings(&self) -> impl Iterator<Item = &'static Setting> {
        self.entries.iter().map(|e| e.setting)
    }

    /// Sets one key. Unknown keys and ill-typed values are errors naming the key.
    pub fn apply(&self, setup: &mut S, key: &str, value: &SettingValue) -> Result<(), InputError> {
        let (entry, owner) = self.lookup(key).ok_or_else(|| self.unknown(key))?;
        let target = Target {
            setting: entry.setting,
            key,
            owner,
        };
        (entry.set)(setup, &target, value)
    }

    /// Sets one `KEY=VALUE` from the command line; `example` is a valid assignment the error
    /// shows where the `=` is missing.
    pub fn apply_assignment(
        &self,
        setup: &mut S,
        assignment: &str,
        example: &str,
    ) -> Result<(), InputError> {
        let (key, value) = assignment.split_once('=').ok_or_else(|| {
            InputError::new(
                assignment,
                format!("expected KEY=VALUE (for example {example})"),
            )
        })?;
        self.apply(setup, key.trim(), &SettingValue::from_cli(value))
    }

    fn unknown(&self, key: &str) -> InputError {
        let known: Vec<&str> = self.settings().map(|s| s.key).collect();
        InputError::new(
            key,
            format!(
                "unknown key; known keys: {} ({})",
                known.join(", "),
                self.placeholders
            ),
        )
    }

    /// The value of a concrete key as a reader sees it (see [`Entry::shown`]).
    pub fn shown(&self, setup: &S, key: &str) -> Option<(&'static Setting, SettingValue)> {
        let (entry, owner) = self.lookup(key)?;
        entry.shown(setup, owner).map(|v| (entry.setting, v))
    }

    /// The setup as a preset: `head` (its name and scene), the keys without a group, then one
    /// TOML table per group (`[bar1]`, `[contact]`) in the order the settings table meets them.
    /// Applied to a default setup, it gives this one back.
    pub fn to_toml(&self, setup: &S, head: &str) -> String {
        let mut top = String::new();
        let mut groups: Vec<(Cow<'static, str>, String)> = Vec::new();
        for entry in self.entries {
            let s = entry.setting;
            for owner in 0..s.owner_count() {
                let Some(value) = entry.saved(setup, owner) else {
                    continue;
                };
                if !s.key.contains('.') {
                    top.push_str(&format!("{} = {value}\n", s.key));
                    continue;
                }
                let group = s.group(owner);
                let line = format!("{} = {value}\n", s.name());
                match groups.iter_mut().find(|(g, _)| *g == group) {
                    Some((_, lines)) => lines.push_str(&line),
                    None => groups.push((group, line)),
                }
            }
        }
        let mut out = format!("{head}{top}");
        for (group, lines) in groups {
            out.push_str(&format!("\n[{group}]\n{lines}"));
        }
        out
    }
}

/// A value as TOML: counts as integers, numbers so that they read back to the same bits.
fn toml_value(setting: &Setting, value: &SettingValue) -> String {
    let count = matches!(setting.kind, Kind::Count { .. });
    match value {
        SettingValue::Number(x) if count && x.fract() == 0.0 && x.abs() < 9e15 => {
            format!("{x:.0}")
        }
        SettingValue::Number(x) => toml_number(*x),
        SettingValue::Bool(b) => b.to_string(),
        SettingValue::Text(t) => toml_text(t),
        SettingValue::List(xs) if xs.len() == 1 => toml_number(xs[0]),
        SettingValue::List(xs) => {
            let items: Vec<String> = xs.iter().map(|x| toml_number(*x)).collect();
            format!("[{}]", items.join(", "))
        }
    }
}

/// Rust's shortest round-trip digits, which TOML reads as a float; the exponent form outside
/// the range `shown` prints plainly (2.1e11 rather than twelve digits).
fn toml_number(x: f64) -> String {
    if x.is_nan() {
        "nan".into()
    } else if x.is_infinite() {
        if x > 0.0 { "inf" } else { "-inf" }.into()
    } else if shown(x).contains('e') {
        format!("{x:e}")
    } else {
        format!("{x:?}")
    }
}

fn toml_text(t: &str) -> String {
    toml::Value::String(t.to_string()).to_string()
}

impl Target<'_> {
    pub fn number(&self, v: &SettingValue) -> Result<f64, InputError> {
        match v {
            SettingValue::Number(x) => Ok(*x),
            other => Err(self.expected("a number", other)),
        }
    }

    /// One number or a list of them.
    pub fn numbers(&self, v: &SettingValue) -> Result<Vec<f64>, InputError> {
        match v {
            SettingValue::Number(x) => Ok(vec![*x]),
            SettingValue::List(xs) if !xs.is_empty() => Ok(xs.clone()),
            other => Err(self.expected("a number or numbers separated by commas", other)),
        }
    }

    pub fn text<'v>(&self, v: &'v SettingValue) -> Result<&'v str, InputError> {
        match v {
            SettingValue::Text(s) => Ok(s),
            other => Err(self.expected("a word", other)),
        }
    }

    pub fn boolean(&self, v: &SettingValue) -> Result<bool, InputError> {
        match v {
            SettingValue::Bool(b) => Ok(*b),
            other => Err(self.expected("true or false", other)),
        }
    }

    /// A whole number in the table row's range (a count's bounds), refused with that range.
    pub fn whole(&self, v: &SettingValue) -> Result<u64, InputError> {
        let (min, max) = match self.setting.kind {
            Kind::Count { min, max } => (min, max),
            _ => (0, 1 << 50),
        };
        let x = self.number(v)?;
        if x.is_finite() && x.fract() == 0.0 && x >= min as f64 && x <= max as f64 {
            Ok(x as u64)
        } else {
            Err(InputError::new(
                self.key,
                format!(
                    "{} is not allowed: a whole number in [{min}, {max}]",
                    // A whole number as digits where f64 holds it (2^53 rather than 9.007e15).
                    if x.fract() == 0.0 && x.abs() < 1e17 {
                        format!("{x:.0}")
                    } else {
                        shown(x)
                    }
                ),
            ))
        }
    }

    /// [`Target::whole`] as a count of things.
    pub fn count(&self, v: &SettingValue) -> Result<usize, InputError> {
        self.whole(v).map(|n| n as usize)
    }

    /// A number, or `None` for the word the table row takes instead (auto: the program picks).
    pub fn number_or_word(&self, v: &SettingValue) -> Result<Option<f64>, InputError> {
        match v {
            SettingValue::Text(s) if Some(s.as_str()) == self.setting.word() => Ok(None),
            SettingValue::Number(x) => Ok(Some(*x)),
            other => {
                // The refusal says both forms the key takes: the word and the numbers' range.
                let unit = if self.setting.unit.is_empty() {
                    String::new()
                } else {
                    format!(" {}", self.setting.unit)
                };
                let numbers = self.setting.range().map_or_else(
                    || "a number".to_string(),
                    |r| format!("a number in {r}{unit}"),
                );
                let what = match self.setting.word() {
                    Some(w) => format!("{w} or {numbers}"),
                    None => numbers,
                };
                Err(self.expected(&what, other))
            }
        }
    }

    /// A number checked at once against the table row's range (the ground motion's settings
    /// are read before any run validates them).
    pub fn checked(&self, v: &SettingValue) -> Result<f64, InputError> {
        let x = self.number(v)?;
        self.setting.check(self.key, x)?;
        Ok(x)
    }

    /// One of the words the table row lists, parsed; a word it does not list is refused with
    /// the list, as `--list-keys` shows it.
    pub fn choice<T>(
        &self,
        v: &SettingValue,
        parse: impl Fn(&str) -> Option<T>,
    ) -> Result<T, InputError> {
        let s = self.text(v)?;
        parse(s).ok_or_else(|| {
            let allowed = self.setting.choices().unwrap_or_default().join("|");
            InputError::new(self.key, format!("unknown value '{s}': allowed {allowed}"))
        })
    }

    /// An error naming the key: what it expects, and what it got.
    pub fn expected(&self, what: &str, got: &SettingValue) -> InputError {
        InputError::new(self.key, format!("expected {what}, got {}", got.describe()))
    }
}

/// A number held, as a [`Get`] function returns it.
pub fn number(x: f64) -> Option<SettingValue> {
    Some(SettingValue::Number(x))
}

/// A word held (a choice), as a [`Get`] function returns it.
pub fn word(w: &str) -> Option<SettingValue> {
    Some(SettingValue::Text(w.to_string()))
}

/// Stores a parsed value: the one-line body of most [`Set`] functions.
pub fn put<T>(slot: &mut T, value: Result<T, InputError>) -> Result<(), InputError> {
    *slot = value?;
    Ok(())
}
