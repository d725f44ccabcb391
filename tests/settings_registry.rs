//! The settings registry is the one place a setting meets a setup: every row of the settings
//! tables has its entry, a value set through a key reads back through the same key, and a saved
//! scene reads back to the same setup whichever key was changed.

use pounding::io::bridge_settings::{BRIDGE, BridgeSetup};
use pounding::io::building_settings::{BUILDINGS, BuildingSetup};
use pounding::io::preset::{self, apply_text, bridge_to_toml, buildings_to_toml, impact_to_toml};
use pounding::io::registry::Registry;
use pounding::io::settings::{IMPACT, ImpactSetup, SettingValue};
use pounding::model::settings::{
    BRIDGE_SETTINGS, BUILDING_SETTINGS, IMPACT_SETTINGS, Kind, Setting,
};

fn sci(x: f64) -> String {
    format!("{x:e}")
}

/// Values as a user would type them: both ends of the accepted range and the slider's, each
/// word it takes, and for a list two different storeys.
fn typed_values(s: &Setting) -> Vec<String> {
    match s.kind {
        Kind::Number {
            range,
            slider,
            word,
            ..
        } => {
            let mut v = vec![
                sci(range.low_accepted()),
                sci(range.high_accepted()),
                sci(slider.0),
                sci(slider.1),
            ];
            v.extend(word.map(String::from));
            v
        }
        Kind::List { range, slider, .. } => vec![
            sci(range.low_accepted()),
            sci(range.high_accepted()),
            format!("{},{}", sci(slider.0), sci(slider.1)),
        ],
        Kind::Count { min, max } => vec![min.to_string(), max.to_string(), (max / 2).to_string()],
        Kind::Choice(options) => options.iter().map(|o| o.to_string()).collect(),
        Kind::Bool => vec!["true".into(), "false".into()],
        // A record's name or a pair of modes: the stated default's first word.
        Kind::Text => vec![s.default.split(' ').next().unwrap().to_string()],
    }
}

#[test]
fn every_row_of_each_table_has_one_entry_in_its_registry_in_the_same_order() {
    let impact: Vec<&str> = IMPACT.settings().map(|s| s.key).collect();
    let table: Vec<&str> = IMPACT_SETTINGS.iter().map(|s| s.key).collect();
    assert_eq!(impact, table);
    let buildings: Vec<&str> = BUILDINGS.settings().map(|s| s.key).collect();
    let table: Vec<&str> = BUILDING_SETTINGS.iter().map(|s| s.key).collect();
    assert_eq!(buildings, table);
    let bridge: Vec<&str> = BRIDGE.settings().map(|s| s.key).collect();
    let table: Vec<&str> = BRIDGE_SETTINGS.iter().map(|s| s.key).collect();
    assert_eq!(bridge, table);
    for (registry, table) in [
        (IMPACT.settings().collect::<Vec<_>>(), IMPACT_SETTINGS),
        (BUILDINGS.settings().collect(), BUILDING_SETTINGS),
        (BRIDGE.settings().collect(), BRIDGE_SETTINGS),
    ] {
        for (entry, row) in registry.iter().zip(table) {
            assert_eq!(
                *entry, row,
                "{}: the entry's metadata is the row's",
                row.key
            );
        }
    }
}

/// Changes every concrete key of `registry` to each of its typed values on a default setup,
/// saves the setup as TOML and reads it back onto a default setup: the same setup. Returns
/// how many round trips ran.
fn round_trips<S: Default + Clone + PartialEq + std::fmt::Debug + preset::Configurable>(
    registry: &Registry<S>,
    to_toml: fn(&S) -> String,
) -> usize {
    let mut ran = 0;
    for entry in registry.entries {
        let s = entry.setting;
        for owner in 0..s.owner_count() {
            let key = s.key_of(owner);
            let mut accepted = 0;
            for text in typed_values(s) {
                let mut setup = S::default();
                let value = SettingValue::from_cli(&text);
                if registry.apply(&mut setup, &key, &value).is_err() {
                    continue;
                }
                let saved = to_toml(&setup);
                let mut back = S::default();
                apply_text(&mut back, &saved, "saved")
                    .unwrap_or_else(|e| panic!("{key}={text}: {e}\n{saved}"));
                assert_eq!(back, setup, "{key}={text}:\n{saved}");
                accepted += 1;
            }
            assert!(accepted > 0, "{key}: no typed value was accepted");
            ran += accepted;
        }
    }
    ran
}

#[test]
fn a_saved_impact_reads_back_identically_whichever_key_was_changed() {
    let ran = round_trips(&IMPACT, impact_to_toml);
    assert!(ran > 80, "only {ran} round trips");
}

#[test]
fn a_saved_building_scene_reads_back_identically_whichever_key_was_changed() {
    let ran = round_trips(&BUILDINGS, buildings_to_toml);
    assert!(ran > 100, "only {ran} round trips");
}

#[test]
fn a_saved_bridge_scene_reads_back_identically_whichever_key_was_changed() {
    let ran = round_trips(&BRIDGE, bridge_to_toml);
    assert!(ran > 60, "only {ran} round trips");
}

#[test]
fn every_shipped_bridge_preset_reads_back_identically() {
    let mut read = 0;
    for (name, text) in preset::EMBEDDED {
        if preset::scene(text) != "bridge" {
            continue;
        }
        let setup: BridgeSetup = preset::load_for(name, "bridge").unwrap();
        let mut back = BridgeSetup::default();
        apply_text(&mut back, &bridge_to_toml(&setup), "saved").unwrap();
        assert_eq!(back, setup, "{name}");
        read += 1;
    }
    assert_eq!(read, 3);
}

#[test]
fn every_shipped_building_preset_reads_back_identically() {
    for (name, text) in preset::EMBEDDED {
        if preset::scene(text) != "buildings" {
            continue;
        }
        let setup: BuildingSetup = preset::load_for(name, "buildings").unwrap();
        let mut back = BuildingSetup::default();
        apply_text(&mut back, &buildings_to_toml(&setup), "saved").unwrap();
        assert_eq!(back, setup, "{name}");
    }
}

/// A number set through a key reads back through the same key: exactly, or for a period,
/// which scales the stiffnesses, to round-off.
fn set_numbers_read_back<S: Default>(registry: &Registry<S>) {
    for entry in registry.entries {
        let s = entry.setting;
        let Some(range) = s.range() else { continue };
        if s.choices().is_some() {
            continue;
        }
        for owner in 0..s.owner_count() {
            let x = match s.kind {
                Kind::Count { .. } => range.high_accepted(),
                _ => range.low_accepted().max(range.high_accepted().min(1.5)),
            };
            let mut setup = S::default();
            entry.set_number(&mut setup, owner, x).unwrap();
            let back = entry.number(&setup, owner).unwrap_or(f64::NAN);
            assert!(
                (back - x).abs() <= 1e-9 * x.abs(),
                "{}: set {x}, read {back}",
                s.key_of(owner)
            );
        }
    }
}

#[test]
fn a_number_set_through_a_key_reads_back_through_it() {
    set_numbers_read_back(&IMPACT);
    set_numbers_read_back(&BUILDINGS);
    set_numbers_read_back(&BRIDGE);
}

#[test]
fn an_automatic_value_reads_as_none_and_is_saved_as_its_word() {
    let setup = ImpactSetup::default();
    let stiffness = IMPACT.lookup("contact.stiffness").unwrap().0;
    assert_eq!(stiffness.shown(&setup, 0), None);
    assert!(impact_to_toml(&setup).contains("stiffness = \"auto\""));
    let area = IMPACT.lookup("bar2.area").unwrap().0;
    let expected = setup.scenario.bar2.area_m2();
    assert_eq!(area.number(&setup, 1), Some(expected));
    assert!(!impact_to_toml(&setup).contains("area"));
}
