//! The settings table is what users read (`--list-keys`, the window's hover text): its stated
//! defaults must be the defaults the solver runs with, and every key it lists must be one the
//! settings parser accepts.

use pounding::io::bridge_settings::BridgeSetup;
use pounding::io::building_settings::BuildingSetup;
use pounding::io::settings::ImpactSetup;
use pounding::model::settings::{
    BRIDGE_SETTINGS, BUILDING_SETTINGS, IMPACT_SETTINGS, Setting, concrete_keys,
};

/// The default as typed for one concrete key: one value for every bar, side or span,
/// "A (bar1), B (bar2)", or a list in full ("8e7, 2e8, 4e7", one value a span), typed without
/// its spaces. `None` where the table states it in words ("from the radius").
fn default_for(s: &Setting, key: &str) -> Option<String> {
    let d = s.default;
    if d.contains(" (") {
        let side = key.split('.').next()?;
        return d.split("), ").find_map(|part| {
            let (value, who) = part.split_once(" (")?;
            (who.trim_end_matches(')') == side).then(|| value.to_string())
        });
    }
    let typed = d.replace(", ", ",");
    (!typed.contains(' ')).then_some(typed)
}

fn stated_defaults(table: &'static [Setting]) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for s in table {
        for key in concrete_keys(std::slice::from_ref(s)) {
            if let Some(v) = default_for(s, &key) {
                out.push((key, v));
            }
        }
    }
    out
}

/// `KEY=VALUE` applied to the default setup of the scene whose table `table` is.
fn apply_to_default(
    table: &'static [Setting],
    assignment: &str,
) -> Result<(), pounding::model::error::InputError> {
    if std::ptr::eq(table, IMPACT_SETTINGS) {
        ImpactSetup::default().apply_assignment(assignment)
    } else if std::ptr::eq(table, BUILDING_SETTINGS) {
        BuildingSetup::default().apply_assignment(assignment)
    } else {
        BridgeSetup::default().apply_assignment(assignment)
    }
}

#[test]
fn the_impact_table_states_the_defaults_the_solver_runs_with() {
    let base = ImpactSetup::default();
    let defaults = stated_defaults(IMPACT_SETTINGS);
    assert!(
        defaults.len() >= 20,
        "only {} defaults checked",
        defaults.len()
    );
    for (key, value) in defaults {
        let mut s = base;
        s.apply_assignment(&format!("{key}={value}"))
            .unwrap_or_else(|e| panic!("{key}={value}: {e}"));
        assert_eq!(s, base, "{key}: the table says {value}");
    }
}

#[test]
fn the_building_table_states_the_defaults_the_solver_runs_with() {
    let base = BuildingSetup::default();
    let defaults = stated_defaults(BUILDING_SETTINGS);
    assert!(
        defaults.len() >= 30,
        "only {} defaults checked",
        defaults.len()
    );
    for (key, value) in defaults {
        // Record keys describe a record the default does not read (a text file's step, a
        // synthetic record); they are checked by the parser, not against the default.
        // Naming Rayleigh modes asks for Rayleigh damping, so it changes the default on purpose.
        if key.starts_with("motion.") || key.ends_with(".rayleigh_modes") {
            continue;
        }
        let mut s = base.clone();
        s.apply_assignment(&format!("{key}={value}"))
            .unwrap_or_else(|e| panic!("{key}={value}: {e}"));
        assert_eq!(s, base, "{key}: the table says {value}");
    }
}

#[test]
fn the_bridge_table_states_the_defaults_the_solver_runs_with() {
    let base = BridgeSetup::default();
    let defaults = stated_defaults(BRIDGE_SETTINGS);
    assert!(
        defaults.len() >= 20,
        "only {} defaults checked",
        defaults.len()
    );
    // The per-span lists stated in full must be among them: the piers' stiffnesses and the
    // joints' gaps differ span by span.
    for key in ["pier.stiffness", "joint.gaps"] {
        assert!(
            defaults.iter().any(|(k, v)| k == key && v.contains(',')),
            "{key}: no list default checked"
        );
    }
    for (key, value) in defaults {
        // The record keys are the buildings' rows: they describe a record the default does not
        // read, and are checked by the parser. How the record travels along the bridge is the
        // bridge's own, and checked.
        if key.starts_with("motion.") && key != "motion.apparent_velocity" {
            continue;
        }
        let mut s = base.clone();
        s.apply_assignment(&format!("{key}={value}"))
            .unwrap_or_else(|e| panic!("{key}={value}: {e}"));
        assert_eq!(s, base, "{key}: the table says {value}");
    }
}

#[test]
fn every_listed_key_is_accepted_by_the_parser_at_its_range_ends() {
    for table in [IMPACT_SETTINGS, BUILDING_SETTINGS, BRIDGE_SETTINGS] {
        for s in table {
            let Some(range) = s.range() else { continue };
            for key in concrete_keys(std::slice::from_ref(s)) {
                for v in [range.low_accepted(), range.high_accepted()] {
                    let a = format!("{key}={v:e}");
                    let r = apply_to_default(table, &a);
                    // A period sets the storey stiffnesses: the periods a building can take
                    // depend on its masses, so an end of the table's range may be refused, by
                    // the period's own name and with the periods this building can take.
                    if key.ends_with(".period")
                        && let Err(e) = &r
                    {
                        assert!(
                            e.field == key && e.message.contains("periods from"),
                            "{a}: {e}"
                        );
                        continue;
                    }
                    assert!(r.is_ok(), "{a}: {:?}", r.err());
                }
            }
        }
    }
}

#[test]
fn every_choice_the_table_lists_is_accepted_and_a_wrong_one_is_refused_with_the_list() {
    for table in [IMPACT_SETTINGS, BUILDING_SETTINGS, BRIDGE_SETTINGS] {
        for s in table {
            let Some(options) = s.choices() else {
                continue;
            };
            for key in concrete_keys(std::slice::from_ref(s)) {
                let apply = |v: &str| apply_to_default(table, &format!("{key}={v}"));
                for option in options {
                    apply(option).unwrap_or_else(|e| panic!("{key}={option}: {e}"));
                }
                let err = apply("no-such-choice").expect_err(&key).to_string();
                assert!(
                    err.contains(&key) && err.contains(&options.join("|")),
                    "{key}: {err}"
                );
            }
        }
    }
}
