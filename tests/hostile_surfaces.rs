//! Hostile input on the newer surfaces (issue 52): lesson files, bridges, yielding storeys'
//! keys, animation flags and sweeps. Every value is honoured as given or refused with a message
//! that is true and names what to change.

use common::{json, pounding, refused, stderr, stdout};
use std::path::PathBuf;
use std::time::{Duration, Instant};

mod common;

/// A scratch file unique to this test process.
fn scratch(name: &str, bytes: &[u8]) -> PathBuf {
    common::scratch_file("pounding-surfaces", name, bytes)
}

/// A one-step bar lesson whose step states `statement`, followed by `extra` TOML.
fn lesson(statement: &str, extra: &str) -> String {
    format!(
        "title = \"t\"\naudience = \"a\"\nduration_min = 5\ngoals = [\"g\"]\nteacher_notes = \"n\"\n\n\
         [[step]]\ntitle = \"s\"\ntext = \"x\"\nscene = \"bar\"\nshow = [\"readouts\"]\n\
         asserts = [\"{statement}\"]\n{extra}"
    )
}

#[test]
fn a_lesson_expression_nested_past_the_documented_depth_is_refused_by_file_and_line() {
    let n = 10_000;
    let deep = [
        format!("{}true", "not ".repeat(n)),
        format!("{}1 > 0", "-".repeat(n)),
        format!("{}1{} > 0", "(".repeat(n), ")".repeat(n)),
        format!("{} > 0", vec!["1"; n].join(" + ")),
    ];
    for (i, statement) in deep.iter().enumerate() {
        let path = scratch(&format!("deep{i}.toml"), lesson(statement, "").as_bytes());
        let e = refused(&["lesson", "--check", path.to_str().unwrap()]);
        assert!(e.contains(path.to_str().unwrap()), "{e}");
        assert!(e.contains("line 12"), "{e}");
        assert!(
            e.len() < 2000,
            "the error quotes the expression whole: {} bytes",
            e.len()
        );
        assert!(e.contains("nests more than 256 deep"), "{e}");
    }
}

#[test]
fn a_lesson_of_many_steps_or_long_lists_is_read_in_linear_time() {
    // Twenty thousand steps and two hundred thousand goals, the last step with an unknown field:
    // reading the whole file to that error took minutes when every field's line was counted
    // from the file's start.
    let goals = vec!["\"g\""; 200_000].join(", ");
    let mut text = format!(
        "title = \"t\"\naudience = \"a\"\nduration_min = 5\ngoals = [{goals}]\nteacher_notes = \"n\"\n"
    );
    for _ in 0..20_000 {
        text.push_str(
            "\n[[step]]\ntitle = \"s\"\ntext = \"x\"\nscene = \"bar\"\nshow = [\"readouts\"]\n",
        );
    }
    text.push_str("typo = 1\n");
    let path = scratch("long.toml", text.as_bytes());
    let start = Instant::now();
    let e = refused(&["lesson", "--check", path.to_str().unwrap()]);
    // A generous bound: linear reading takes well under a second; quadratic took minutes.
    assert!(
        start.elapsed() < Duration::from_secs(30),
        "{:?}",
        start.elapsed()
    );
    assert!(e.contains("step[20000].typo"), "{e}");
}

#[test]
fn a_lesson_file_with_a_byte_that_is_not_utf8_names_its_line_and_byte() {
    let mut bytes = lesson("true", "").into_bytes();
    // The x of `text = "x"`, on line 9.
    let at = bytes.windows(3).position(|w| w == b"\"x\"").unwrap() + 1;
    bytes[at] = 0xFF;
    let path = scratch("bad-utf8.toml", &bytes);
    let e = refused(&["lesson", "--check", path.to_str().unwrap()]);
    assert!(e.contains("line 9, byte 9"), "{e}");
    assert!(e.contains("0xFF"), "{e}");
}

#[test]
fn a_device_or_folder_given_as_a_lesson_is_not_a_regular_file() {
    for path in ["/dev/null", "/proc"] {
        let e = refused(&["lesson", "--check", path]);
        assert!(e.contains("not a regular file"), "{path}: {e}");
        assert!(!e.contains("no such lesson"), "{path}: {e}");
    }
}

#[test]
fn a_seed_past_what_the_key_holds_exactly_is_refused_in_both_grammars() {
    for seed in [
        "9007199254740992",
        "9007199254740993",
        "18446744073709551615",
    ] {
        let e = refused(&["buildings", "--set", &format!("motion.seed={seed}")]);
        assert!(
            e.contains("motion.seed") && e.contains("[0, 9007199254740991]"),
            "{seed}: {e}"
        );
        let e = refused(&["buildings", "--motion", &format!("synthetic:{seed}")]);
        assert!(e.contains("0 to 9007199254740991"), "{seed}: {e}");
    }
    // The largest seed is run as typed.
    let v = json(&[
        "buildings",
        "--motion",
        "synthetic:9007199254740991",
        "--set",
        "motion.length=1",
        "--json",
    ]);
    assert!(
        v["motion"]["name"]
            .as_str()
            .is_some_and(|n| n.contains("9007199254740991")),
        "{}",
        v["motion"]
    );
}

fn warnings(v: &serde_json::Value) -> Vec<String> {
    v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_str().unwrap().to_string())
        .collect()
}

#[test]
fn settings_a_run_does_not_use_are_named_in_its_warnings() {
    // The synthetic record's keys beside a built-in record, on a bridge.
    let v = json(&[
        "bridge",
        "--set",
        "motion.pga=5",
        "--set",
        "motion.seed=3",
        "--set",
        "motion.duration=1",
        "--json",
    ]);
    let w = warnings(&v);
    for key in ["motion.pga=5", "motion.seed=3"] {
        assert!(
            w.iter().any(|x| x.contains(key) && x.contains("not used")),
            "{key}: {w:?}"
        );
    }
    assert!(!w.iter().any(|x| x.contains("motion.duration")), "{w:?}");
    // The yielding laws' constants on storeys that do not follow that law.
    let v = json(&[
        "buildings",
        "--set",
        "left.yield_forces=1e5",
        "--set",
        "left.hardening=0.1",
        "--set",
        "right.hysteresis=bilinear",
        "--set",
        "right.bouc_wen_n=2",
        "--set",
        "motion.duration=1",
        "--json",
    ]);
    let w = warnings(&v);
    for key in ["left.yield_forces", "left.hardening", "right.bouc_wen_n"] {
        assert!(
            w.iter().any(|x| x.contains(key) && x.contains("not used")),
            "{key}: {w:?}"
        );
    }
    // A key the run uses is not named.
    let v = json(&[
        "buildings",
        "--set",
        "left.hysteresis=bouc-wen",
        "--set",
        "left.bouc_wen_n=2",
        "--set",
        "motion.duration=1",
        "--json",
    ]);
    assert!(
        !warnings(&v).iter().any(|x| x.contains("bouc_wen_n")),
        "{v}"
    );
    // The text summary says it too.
    let o = pounding(&[
        "bridge",
        "--set",
        "motion.length=3",
        "--set",
        "motion.duration=1",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("motion.length=3: not used"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn a_swept_point_without_an_impact_has_no_restitution_and_says_why() {
    let v = json(&[
        "sweep",
        "--param",
        "bar1.velocity",
        "--from",
        "-1",
        "--to",
        "1",
        "--count",
        "3",
        "--json",
    ]);
    for p in v["points"].as_array().unwrap() {
        let contacts = p["contacts"].as_u64().unwrap();
        if contacts == 0 {
            assert!(p["restitution"].is_null(), "{p}");
            assert!(
                p["no_restitution"].as_str().unwrap().contains("no impact"),
                "{p}"
            );
        } else {
            assert!(p["restitution"].as_f64().is_some(), "{p}");
            assert!(p["no_restitution"].is_null(), "{p}");
        }
    }
}

#[test]
fn animation_flags_without_an_animation_and_two_formats_on_one_stdout_are_refused() {
    for args in [
        &["impact", "--animate-frames", "50"][..],
        &["impact", "--animate-fps", "10"],
        &["impact", "--animate-size", "640x360"],
        &["impact", "--animate-view", "xt"],
        &["buildings", "--animate-drift", "10"],
    ] {
        let e = refused(args);
        assert!(e.contains("--animate <FILE>"), "{args:?}: {e}");
    }
    for cmd in ["impact", "buildings", "bridge"] {
        let e = refused(&[cmd, "--csv", "-", "--json"]);
        assert!(e.contains("--csv -") && e.contains("--json"), "{cmd}: {e}");
    }
}

#[test]
fn the_bridge_step_budget_names_only_keys_the_bridge_takes() {
    let o = pounding(&["bridge", "--list-keys"]);
    let keys: Vec<String> = stdout(&o)
        .lines()
        .filter_map(|l| l.split_whitespace().next().map(String::from))
        .collect();
    for set in [
        "span.length=0.1",
        "contact.stiffness=1e20",
        "solver.tolerance=1e-12",
        "solver.steps_per_scale=1e6",
    ] {
        let e = refused(&["bridge", "--set", set]);
        assert!(e.contains("solver.max_steps"), "{set}: {e}");
        let named: Vec<&str> = e
            .split(|c: char| !(c.is_ascii_alphanumeric() || c == '.' || c == '_'))
            .filter(|w| w.starts_with("solver.") || w.starts_with("motion."))
            .map(|w| w.trim_end_matches('.'))
            .collect();
        assert!(!named.is_empty(), "{set}: {e}");
        for k in named {
            assert!(
                keys.iter().any(|x| x == k),
                "{set}: names {k}, which bridge refuses: {e}"
            );
        }
    }
}

#[test]
fn an_animation_size_is_refused_with_the_one_range_it_has() {
    for size in ["10000x100", "10x100", "100x9000"] {
        let e = refused(&["impact", "--animate", "a.gif", "--animate-size", size]);
        assert!(e.contains("each 16 to 8192"), "{size}: {e}");
    }
}

#[test]
fn keys_that_also_take_a_word_say_the_word_and_the_range() {
    for (cmd, set, word) in [
        ("bridge", "motion.apparent_velocity=UNIFORM", "uniform"),
        ("bridge", "contact.stiffness=stiff", "auto"),
        ("buildings", "solver.steps_per_scale=many", "auto"),
    ] {
        let e = refused(&[cmd, "--set", set]);
        assert!(e.contains(word) && e.contains('['), "{set}: {e}");
    }
}

#[test]
fn negative_values_of_numeric_flags_name_the_flag_and_its_range() {
    for (args, range) in [
        (
            &["buildings", "--animate", "a.gif", "--animate-drift", "-20"][..],
            "1 to 500",
        ),
        (&["impact", "--plot-scale", "-2"], "0.25 to 8"),
        (
            &["impact", "--animate", "a.gif", "--animate-frames", "-20"],
            "2 to 2000",
        ),
        (
            &["impact", "--animate", "a.gif", "--animate-fps", "-5"],
            "1 to 50",
        ),
        (&["impact", "--xt-grid", "-20x5"], "2 to 20000"),
        (
            &[
                "sweep", "--param", "gap", "--from", "0", "--to", "1", "--count", "-3",
            ],
            "2 to 100000",
        ),
    ] {
        let e = refused(args);
        let flag = args.iter().rev().nth(1).unwrap();
        assert!(e.contains(flag) && e.contains(range), "{args:?}: {e}");
        assert!(!e.contains("unexpected argument"), "{args:?}: {e}");
    }
}

#[test]
fn whole_number_keys_state_their_own_bounds() {
    for (cmd, set, range) in [
        ("bridge", "bridge.spans=1.5", "[1, 20]"),
        ("buildings", "left.storeys=1.5", "[1, 100]"),
        ("buildings", "solver.max_steps=0", "[1, "),
        ("bridge", "solver.max_steps=1.5", "[1, "),
    ] {
        let e = refused(&[cmd, "--set", set]);
        let key = set.split('=').next().unwrap();
        assert!(e.contains(key) && e.contains(range), "{set}: {e}");
        assert!(!e.contains(">= 0"), "{set}: {e}");
    }
}

#[test]
fn a_bearing_too_soft_for_its_pier_names_the_bearing() {
    let e = refused(&["bridge", "--set", "bearing.stiffness=1e-6"]);
    assert!(e.contains("bearing.stiffness"), "{e}");
    assert!(e.contains("1e-6 N/m"), "{e}");
}

#[test]
fn the_default_yield_force_word_is_accepted() {
    let v = json(&[
        "buildings",
        "--preset",
        "paper-buildings-yielding",
        "--set",
        "left.yield_forces=1e6",
        "--set",
        "left.yield_forces=auto",
        "--set",
        "motion.duration=1",
        "--json",
    ]);
    let w = json(&[
        "buildings",
        "--preset",
        "paper-buildings-yielding",
        "--set",
        "motion.duration=1",
        "--json",
    ]);
    assert_eq!(v["max_pounding_force_n"], w["max_pounding_force_n"]);
}

#[test]
fn accuracy_takes_the_synthetic_record_as_every_command_does() {
    let o = pounding(&[
        "accuracy",
        "--scene",
        "buildings",
        "--motion",
        "synthetic:3",
        "--set",
        "motion.length=1",
        "--quiet",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn a_period_past_the_stiffnesses_range_is_refused_as_the_period() {
    let e = refused(&["gaps", "--set", "left.period=1e-4"]);
    assert!(e.contains("left.period"), "{e}");
    assert!(e.starts_with("error: --set left.period"), "{e}");
    assert!(e.contains("periods from about"), "{e}");
}

#[test]
fn tiny_numbers_print_in_exponent_form_and_a_preset_is_named_once() {
    let o = pounding(&[
        "buildings",
        "--set",
        "gap=1e-300",
        "--set",
        "motion.duration=1",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("gap 1e-300 m"), "{}", stdout(&o));
    let o = pounding(&[
        "impact",
        "--set",
        "bar2.velocity=-1e-300",
        "--set",
        "bar1.velocity=-1",
    ]);
    assert!(!stdout(&o).contains("0.000000000"), "{}", stdout(&o));
    // The shipped preset (run away from the checkout's assets/).
    let o = common::output_in_own_session(
        std::process::Command::new(env!("CARGO_BIN_EXE_pounding"))
            .args(["buildings", "--preset", "paper-base"])
            .current_dir(std::env::temp_dir()),
    );
    let e = stderr(&o);
    assert!(e.contains("preset paper-base"), "{e}");
    assert!(!e.contains("preset preset"), "{e}");
}

#[test]
fn an_animations_time_range_is_refused_outside_the_run_or_past_its_impacts() {
    let e = refused(&[
        "buildings",
        "--animate",
        "a.gif",
        "--animate-around",
        "99",
        "--set",
        "motion.duration=1",
    ]);
    assert!(
        e.contains("--animate-around") && e.contains("from 1 to"),
        "{e}"
    );
    let e = refused(&[
        "impact",
        "--animate",
        "a.gif",
        "--animate-from",
        "0.5",
        "--animate-to",
        "0.1",
    ]);
    assert!(
        e.contains("--animate-from") && e.contains("outside the run"),
        "{e}"
    );
    let e = refused(&["impact", "--animate-from", "0.001"]);
    assert!(e.contains("--animate <FILE>"), "{e}");
    let e = refused(&[
        "buildings",
        "--animate",
        "a.gif",
        "--animate-around",
        "strongest",
        "--animate-from",
        "1",
    ]);
    assert!(e.contains("cannot be used with"), "{e}");
}
