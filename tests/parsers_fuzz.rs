//! The preset (TOML) and ground-motion (AT2, text) parsers on mutated files: every outcome is a
//! parsed value or an error naming the line at fault (or the whole file, for a file with no
//! data); never a panic, never an allocation the file does not justify.

mod common;

use pounding::io::bridge_settings::BridgeSetup;
use pounding::io::building_settings::BuildingSetup;
use pounding::io::motion::{Units, parse};
use pounding::io::preset::{EMBEDDED, PresetError, apply_text, scene};
use pounding::io::settings::ImpactSetup;
use proptest::prelude::*;

const AT2: &str = "PEER NGA STRONG MOTION DATABASE RECORD\n\
TEST RECORD, NORTH\n\
ACCELERATION TIME SERIES IN UNITS OF G\n\
NPTS=    8, DT=   .0100 SEC\n\
  .1000E-02  .2000E-02 -.3000E-02  .4000E-02\n\
 -.5000E-02  .6000E-02  .7000E-02 -.8000E-02\n";

const TWO_COLUMNS: &str = "# time [s], acceleration [g]\n0 0\n0.01 0.1\n0.02 -0.2\n0.03 0.05\n";

const VALUES: &str = "% values in g\n0.0, 0.1, -0.2\n0.05 0.0\n";

/// Tokens a careless edit or a hostile file brings in.
const TOKENS: &[&str] = &[
    "1e308",
    "-1e308",
    "1e999",
    "nan",
    "inf",
    "-0",
    "99999999999999999999999",
    "NPTS=1e18",
    "NPTS=-3",
    "DT=0",
    "DT=1e-300",
    "=",
    "[",
    "]",
    "[[x]]",
    "\"",
    "'",
    "0x10",
    "1_000",
    "true",
    "[bar1]",
    "bar1.length = ",
    "= [1, \"a\"]",
    "{a = 1}",
    ",",
    "\t",
    "\u{feff}",
    "é",
    "\0",
];

#[derive(Debug, Clone)]
enum Edit {
    DeleteLine(usize),
    DuplicateLine(usize),
    ReplaceChar(usize, char),
    Insert(usize, usize),
    Truncate(usize),
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        any::<usize>().prop_map(Edit::DeleteLine),
        any::<usize>().prop_map(Edit::DuplicateLine),
        (
            any::<usize>(),
            prop::sample::select(&b"0123456789=[]\",.e-+ \n#%xE"[..])
        )
            .prop_map(|(i, c)| Edit::ReplaceChar(i, c as char)),
        (any::<usize>(), 0..TOKENS.len()).prop_map(|(i, t)| Edit::Insert(i, t)),
        any::<usize>().prop_map(Edit::Truncate),
    ]
}

fn apply(text: &str, edits: &[Edit]) -> String {
    let mut s = text.to_string();
    for e in edits {
        let chars: Vec<char> = s.chars().collect();
        let mut lines: Vec<String> = s.lines().map(String::from).collect();
        match e {
            Edit::DeleteLine(i) if !lines.is_empty() => {
                lines.remove(i % lines.len());
                s = lines.join("\n");
            }
            Edit::DuplicateLine(i) if !lines.is_empty() => {
                let k = i % lines.len();
                lines.insert(k, lines[k].clone());
                s = lines.join("\n");
            }
            Edit::ReplaceChar(i, c) if !chars.is_empty() => {
                let mut chars = chars;
                let k = i % chars.len();
                chars[k] = *c;
                s = chars.into_iter().collect();
            }
            Edit::Insert(i, t) => {
                let k = i % (chars.len() + 1);
                let (a, b) = chars.split_at(k);
                s = a.iter().collect::<String>() + TOKENS[*t] + &b.iter().collect::<String>();
            }
            Edit::Truncate(i) => {
                let k = i % (chars.len() + 1);
                s = chars[..k].iter().collect();
            }
            _ => {}
        }
    }
    s
}

/// The line an error names lies in the file (one past its end for "ends too early").
fn names_a_line(line: Option<usize>, text: &str) -> bool {
    line.is_some_and(|l| l >= 1 && l <= text.lines().count() + 1)
}

fn check_preset(original: &str, text: &str) -> Result<(), String> {
    let outcome: Result<(), PresetError> = match scene(original).as_str() {
        "buildings" => apply_text(&mut BuildingSetup::default(), text, "mutated.toml"),
        "bridge" => apply_text(&mut BridgeSetup::default(), text, "mutated.toml"),
        _ => apply_text(&mut ImpactSetup::default(), text, "mutated.toml"),
    };
    match outcome {
        Ok(()) => Ok(()),
        Err(e) if names_a_line(e.line, text) => Ok(()),
        // A file the TOML reader cannot place an error in at all (it had no span).
        Err(e) if text.trim().is_empty() => Err(format!("an empty file failed: {e}")),
        Err(e) => Err(format!("no line named: {e}\n---\n{text}")),
    }
}

fn check_motion(name: &str, text: &str, dt: Option<f64>) -> Result<(), String> {
    match parse(text, name, Units::G, dt) {
        Ok(m) => {
            if m.accel_m_s2.iter().all(|a| a.is_finite()) && m.dt_s > 0.0 && m.dt_s.is_finite() {
                Ok(())
            } else {
                Err(format!(
                    "a record with non-finite values or step\n---\n{text}"
                ))
            }
        }
        Err(e) if names_a_line(e.line, text) => Ok(()),
        // Whole-file faults: nothing in it, or a step the caller gave.
        Err(e)
            if e.line.is_none() && (e.message == "no data" || e.message.contains("motion.dt")) =>
        {
            Ok(())
        }
        Err(e) => Err(format!("no line named: {e}\n---\n{text}")),
    }
}

proptest! {
    #![proptest_config(common::proptest_config(1000))]

    #[test]
    fn mutated_presets_parse_or_name_the_line(
        which in 0..EMBEDDED.len(),
        edits in prop::collection::vec(edit(), 1..5),
    ) {
        let original = EMBEDDED[which].1;
        let text = apply(original, &edits);
        check_preset(original, &text).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn mutated_ground_motions_parse_or_name_the_line(
        which in 0..3usize,
        edits in prop::collection::vec(edit(), 1..5),
    ) {
        let (name, original, dt) = [
            ("mutated.AT2", AT2, None),
            ("mutated.txt", TWO_COLUMNS, None),
            ("mutated.txt", VALUES, Some(0.01)),
        ][which];
        let text = apply(original, &edits);
        check_motion(name, &text, dt).map_err(TestCaseError::fail)?;
    }
}

#[test]
fn the_unmutated_files_parse() {
    for (name, text) in EMBEDDED {
        check_preset(text, text).unwrap_or_else(|e| panic!("{name}: {e}"));
    }
    assert_eq!(
        parse(AT2, "x.AT2", Units::G, None)
            .unwrap()
            .accel_m_s2
            .len(),
        8
    );
    assert_eq!(
        parse(TWO_COLUMNS, "x.txt", Units::G, None)
            .unwrap()
            .accel_m_s2
            .len(),
        4
    );
    assert_eq!(
        parse(VALUES, "x.txt", Units::G, Some(0.01))
            .unwrap()
            .accel_m_s2
            .len(),
        5
    );
}

#[test]
fn a_header_promising_a_quintillion_values_is_refused_by_line_not_allocated() {
    let text = AT2.replace("NPTS=    8", "NPTS=1000000000000000000");
    let e = parse(&text, "x.AT2", Units::G, None).unwrap_err();
    assert!(e.to_string().contains("NPTS") && e.line.is_some(), "{e}");
}
