//! The settings table is what users read (`--list-keys`, the window's hover text): its stated
//! defaults must be the defaults the solver runs with, and every key it lists must be one the
//! settings parser accepts.

use pounding::io::building_settings::BuildingSetup;
use pounding::io::settings::ImpactSetup;
use pounding::model::settings::{BUILDING_SETTINGS, IMPACT_SETTINGS, Setting, concrete_keys};

/// The default as typed for one concrete key: either one value for every bar or side, or
/// "A (bar1), B (bar2)". `None` where the table states it in words ("from the radius").
fn default_for(s: &Setting, key: &str) -> Option<String> {
    let d = s.default;
    if d.contains(" (") {
        let side = key.split('.').next()?;
        return d.split("), ").find_map(|part| {
            let (value, who) = part.split_once(" (")?;
            (who.trim_end_matches(')') == side).then(|| value.to_string())
        });
    }
    (!d.contains(' ')).then(|| d.to_string())
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
fn every_listed_key_is_accepted_by_the_parser_at_its_range_ends() {
    for (table, building) in [(IMPACT_SETTINGS, false), (BUILDING_SETTINGS, true)] {
        for s in table {
            let Some(range) = s.range() else { continue };
            for key in concrete_keys(std::slice::from_ref(s)) {
                for v in [range.low_accepted(), range.high_accepted()] {
                    let a = format!("{key}={v:e}");
                    let r = if building {
                        BuildingSetup::default().apply_assignment(&a)
                    } else {
                        ImpactSetup::default().apply_assignment(&a)
                    };
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
    for table in [IMPACT_SETTINGS, BUILDING_SETTINGS] {
        for s in table {
            let Some(options) = s.choices() else {
                continue;
            };
            for key in concrete_keys(std::slice::from_ref(s)) {
                let apply = |v: &str| {
                    let line = format!("{key}={v}");
                    if std::ptr::eq(table, IMPACT_SETTINGS) {
                        ImpactSetup::default().apply_assignment(&line).map(|_| ())
                    } else {
                        BuildingSetup::default().apply_assignment(&line).map(|_| ())
                    }
                };
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
