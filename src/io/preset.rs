//! Presets: TOML files of settings. A name is a file stem in `assets/presets/` (the shipped ones
//! are also compiled in, so the binary works from any directory); a path is read as it is.

use super::settings::{ImpactSetup, SettingValue};
use std::path::Path;

/// Presets shipped with Pounding Lab, compiled in.
pub const EMBEDDED: &[(&str, &str)] = &[
    (
        "paper-base",
        include_str!("../../assets/presets/paper-base.toml"),
    ),
    (
        "equal-bars",
        include_str!("../../assets/presets/equal-bars.toml"),
    ),
    (
        "short-bars",
        include_str!("../../assets/presets/short-bars.toml"),
    ),
    (
        "long-bars",
        include_str!("../../assets/presets/long-bars.toml"),
    ),
    (
        "stiff-linear",
        include_str!("../../assets/presets/stiff-linear.toml"),
    ),
    (
        "paper-slabs",
        include_str!("../../assets/presets/paper-slabs.toml"),
    ),
    (
        "paper-buildings",
        include_str!("../../assets/presets/paper-buildings.toml"),
    ),
    (
        "paper-buildings-yielding",
        include_str!("../../assets/presets/paper-buildings-yielding.toml"),
    ),
    (
        "mdof-3-5",
        include_str!("../../assets/presets/mdof-3-5.toml"),
    ),
    (
        "mdof-unequal",
        include_str!("../../assets/presets/mdof-unequal.toml"),
    ),
    (
        "bridge-3-span",
        include_str!("../../assets/presets/bridge-3-span.toml"),
    ),
    (
        "bridge-3-span-passage",
        include_str!("../../assets/presets/bridge-3-span-passage.toml"),
    ),
    (
        "bridge-3-span-unseating",
        include_str!("../../assets/presets/bridge-3-span-unseating.toml"),
    ),
];

/// The default scene.
pub const DEFAULT_PRESET: &str = "paper-base";

/// A preset that could not be used: which file, which line, which key, why.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{file}{}{}: {message}", super::file::at_line(*.line), .key.as_ref().map(|k| format!(", {k}")).unwrap_or_default())]
pub struct PresetError {
    /// The file, or the name of a compiled-in preset.
    pub file: String,
    pub line: Option<usize>,
    pub key: Option<String>,
    pub message: String,
}

/// Finds a preset's text: an existing file path, else `assets/presets/NAME.toml` under the
/// working directory, else a compiled-in preset. Returns (text, where it came from).
pub fn find(name_or_path: &str) -> Result<(String, String), PresetError> {
    let path = Path::new(name_or_path);
    if path.exists() && !path.is_dir() {
        return super::file::read_text(path)
            .map(|t| (t, name_or_path.to_string()))
            .map_err(|e| PresetError {
                file: name_or_path.to_string(),
                line: None,
                key: None,
                message: e.to_string(),
            });
    }
    let local = Path::new("assets/presets").join(format!("{name_or_path}.toml"));
    if local.is_file()
        && let Ok(text) = std::fs::read_to_string(&local)
    {
        return Ok((text, local.display().to_string()));
    }
    if let Some((name, text)) = EMBEDDED.iter().find(|(n, _)| *n == name_or_path) {
        return Ok((text.to_string(), format!("preset {name}")));
    }
    let names: Vec<&str> = EMBEDDED.iter().map(|(n, _)| *n).collect();
    Err(PresetError {
        file: name_or_path.to_string(),
        line: None,
        key: None,
        message: format!("no such file or preset; presets: {}", names.join(", ")),
    })
}

fn line_of(text: &str, offset: usize) -> usize {
    text[..offset.min(text.len())]
        .bytes()
        .filter(|&b| b == b'\n')
        .count()
        + 1
}

/// The settings of a preset as (key, value, line), material keys first so that explicit E, nu
/// and rho in the same table override them.
pub fn parse(text: &str, source: &str) -> Result<Vec<(String, SettingValue, usize)>, PresetError> {
    use toml::de::{DeTable, DeValue};
    let err = |line, key: Option<String>, message: String| PresetError {
        file: source.to_string(),
        line,
        key,
        message,
    };
    let table = DeTable::parse(text).map_err(|e| {
        err(
            e.span().map(|s| line_of(text, s.start)),
            None,
            e.message().to_string(),
        )
    })?;
    let mut out = Vec::new();
    let scalar = |key: &str, v: &DeValue, line: usize| -> Result<SettingValue, PresetError> {
        match v {
            DeValue::String(s) => Ok(SettingValue::Text(s.to_string())),
            DeValue::Boolean(b) => Ok(SettingValue::Bool(*b)),
            DeValue::Integer(i) => i64::from_str_radix(&i.as_str().replace('_', ""), i.radix())
                .map(|x| SettingValue::Number(x as f64))
                .map_err(|e| {
                    err(
                        Some(line),
                        Some(key.to_string()),
                        format!("bad integer: {e}"),
                    )
                }),
            DeValue::Float(x) => {
                let t = x.as_str().replace('_', "");
                let t = match t.as_str() {
                    "nan" | "+nan" | "-nan" => "NaN".to_string(),
                    "inf" | "+inf" => "inf".to_string(),
                    _ => t,
                };
                t.parse::<f64>().map(SettingValue::Number).map_err(|e| {
                    err(
                        Some(line),
                        Some(key.to_string()),
                        format!("bad number: {e}"),
                    )
                })
            }
            DeValue::Array(items) => items
                .iter()
                .map(|item| match item.get_ref() {
                    DeValue::Integer(i) => {
                        i64::from_str_radix(&i.as_str().replace('_', ""), i.radix())
                            .map(|x| x as f64)
                            .map_err(|e| e.to_string())
                    }
                    DeValue::Float(x) => x
                        .as_str()
                        .replace('_', "")
                        .parse::<f64>()
                        .map_err(|e| e.to_string()),
                    _ => Err("expected numbers".into()),
                })
                .collect::<Result<Vec<f64>, String>>()
                .map(SettingValue::List)
                .map_err(|e| err(Some(line), Some(key.to_string()), format!("bad list: {e}"))),
            _ => Err(err(
                Some(line),
                Some(key.to_string()),
                "expected a number, a word, true/false or a list of numbers".into(),
            )),
        }
    };
    for (k, v) in table.get_ref().iter() {
        let name = k.get_ref().to_string();
        let line = line_of(text, k.span().start);
        match v.get_ref() {
            DeValue::Table(inner) => {
                let mut keys = std::collections::HashSet::new();
                for (ik, iv) in inner.iter() {
                    let full = format!("{name}.{}", ik.get_ref());
                    let l = line_of(text, ik.span().start);
                    keys.insert(ik.get_ref().to_string());
                    out.push((full.clone(), scalar(&full, iv.get_ref(), l)?, l));
                }
                if keys.contains("radius") && keys.contains("area") {
                    return Err(err(
                        Some(line),
                        Some(format!("{name}.area")),
                        "give radius or area, not both".into(),
                    ));
                }
            }
            // Descriptive metadata, shown by front ends, not settings.
            DeValue::String(_) if name == "name" || name == "description" || name == "scene" => {}
            other => out.push((name.clone(), scalar(&name, other, line)?, line)),
        }
    }
    out.sort_by_key(|(k, _, _)| !k.ends_with(".material"));
    Ok(out)
}

/// Anything presets can configure: one `apply` per key.
pub trait Configurable {
    fn apply_setting(
        &mut self,
        key: &str,
        value: &SettingValue,
    ) -> Result<(), crate::model::error::InputError>;
}

impl Configurable for ImpactSetup {
    fn apply_setting(
        &mut self,
        key: &str,
        value: &SettingValue,
    ) -> Result<(), crate::model::error::InputError> {
        self.apply(key, value)
    }
}

impl Configurable for super::building_settings::BuildingSetup {
    fn apply_setting(
        &mut self,
        key: &str,
        value: &SettingValue,
    ) -> Result<(), crate::model::error::InputError> {
        self.apply(key, value)
    }
}

impl Configurable for super::bridge_settings::BridgeSetup {
    fn apply_setting(
        &mut self,
        key: &str,
        value: &SettingValue,
    ) -> Result<(), crate::model::error::InputError> {
        self.apply(key, value)
    }
}

/// Loads a preset by name or path onto a fresh default setup.
pub fn load<S: Configurable + Default>(name_or_path: &str) -> Result<S, PresetError> {
    let (text, source) = find(name_or_path)?;
    let mut setup = S::default();
    apply_text(&mut setup, &text, &source)?;
    Ok(setup)
}

/// Applies a preset's text onto a setup.
pub fn apply_text<S: Configurable>(
    setup: &mut S,
    text: &str,
    source: &str,
) -> Result<(), PresetError> {
    for (key, value, line) in parse(text, source)? {
        setup.apply_setting(&key, &value).map_err(|e| PresetError {
            file: source.to_string(),
            line: Some(line),
            key: Some(e.field.clone()),
            message: e.message,
        })?;
    }
    Ok(())
}

fn metadata(text: &str, key: &str) -> Option<String> {
    let table = toml::de::DeTable::parse(text).ok()?;
    table
        .get_ref()
        .iter()
        .find(|(k, _)| k.get_ref() == key)
        .and_then(|(_, v)| match v.get_ref() {
            toml::de::DeValue::String(s) => Some(s.to_string()),
            _ => None,
        })
}

/// The description line of a preset.
pub fn description(text: &str) -> Option<String> {
    metadata(text, "description")
}

/// Which scene a preset configures: `impact` (the default) or `buildings`.
pub fn scene(text: &str) -> String {
    metadata(text, "scene").unwrap_or_else(|| "impact".to_string())
}

/// Loads a preset for a given scene, refusing one written for another scene.
pub fn load_for<S: Configurable + Default>(
    name_or_path: &str,
    wanted: &str,
) -> Result<S, PresetError> {
    let (text, source) = find(name_or_path)?;
    // A syntax error hides the scene line, so it is reported before the scene is judged.
    parse(&text, &source)?;
    let found = scene(&text);
    if found != wanted {
        return Err(PresetError {
            file: source,
            line: None,
            key: Some("scene".into()),
            message: format!("this preset is for the {found} scene; use `pounding {found}`"),
        });
    }
    let mut setup = S::default();
    apply_text(&mut setup, &text, &source)?;
    Ok(setup)
}

/// A setup written back as a preset (the inverse of [`apply_text`]): what "save scene" writes
/// and what the window keeps between sessions.
pub fn impact_to_toml(setup: &ImpactSetup) -> String {
    super::settings::IMPACT.to_toml(setup, "name = \"saved scene\"\nscene = \"impact\"\n")
}

/// The bridge scene written back as a preset.
pub fn bridge_to_toml(setup: &super::bridge_settings::BridgeSetup) -> String {
    super::bridge_settings::BRIDGE
        .to_toml(setup, "name = \"saved bridge scene\"\nscene = \"bridge\"\n")
}

/// The building scene written back as a preset.
pub fn buildings_to_toml(setup: &super::building_settings::BuildingSetup) -> String {
    super::building_settings::BUILDINGS.to_toml(
        setup,
        "name = \"saved building scene\"\nscene = \"buildings\"\n",
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_saved_scene_reads_back_identically() {
        for (name, _) in EMBEDDED.iter().filter(|(_, t)| scene(t) == "impact") {
            let setup: ImpactSetup = load_for(name, "impact").unwrap();
            let mut back = ImpactSetup::default();
            apply_text(&mut back, &impact_to_toml(&setup), "saved").unwrap();
            assert_eq!(back, setup, "{name}");
        }
        let buildings: super::super::building_settings::BuildingSetup =
            load_for("paper-buildings", "buildings").unwrap();
        let mut back = super::super::building_settings::BuildingSetup::default();
        apply_text(&mut back, &buildings_to_toml(&buildings), "saved").unwrap();
        assert_eq!(back, buildings);
    }
}
