//! Hostile input at the command line (issue 23, and issue 22 part 7): every value the program
//! accepts is honoured, every refusal is true and names what to change, and files that are not
//! what they claim end in a named error, fast and in bounded memory.

use common::{json, pounding, refused, stderr, stdout};
use std::path::PathBuf;
use std::time::{Duration, Instant};

mod common;

/// A scratch file unique to this test process.
fn scratch(name: &str, bytes: &[u8]) -> PathBuf {
    common::scratch_file("pounding-hostile", name, bytes)
}

/// A short run of the paper buildings: the first second of El Centro.
const SHORT: [&str; 2] = ["--set", "motion.duration=1"];

#[test]
fn very_stiff_light_buildings_give_finite_energies_for_every_contact_element() {
    for contact in [
        "sears",
        "linear",
        "kelvin",
        "hertz",
        "hertzdamp",
        "jankowski",
        "stereo",
        "none",
    ] {
        let mut args = vec!["buildings", "--contact", contact, "--json"];
        for s in [
            "left.mass=1",
            "right.mass=1",
            "left.stiffness=1e13",
            "right.stiffness=1e13",
        ] {
            args.extend(["--set", s]);
        }
        args.extend(SHORT);
        let o = pounding(&args);
        if !o.status.success() {
            // A refusal is allowed if it names a key; NaN is not.
            let e = stderr(&o);
            assert!(e.contains("--set") || e.contains('.'), "{contact}: {e}");
            assert!(!e.contains("NaN"), "{contact}: {e}");
            continue;
        }
        let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
        let damping = v["energy_building_damping_j"].as_f64();
        let balance = v["energy_balance_error"].as_f64();
        assert!(
            damping.is_some_and(|d| d.is_finite() && d >= 0.0),
            "{contact}: {damping:?}"
        );
        assert!(
            balance.is_some_and(|b| b.abs() < 1e-3),
            "{contact}: balance {balance:?}"
        );
        assert!(!stdout(&o).contains("NaN"), "{contact}");
    }
}

#[test]
fn storeys_too_different_to_resolve_are_refused_not_given_an_infinite_period() {
    let e = refused(&[
        "buildings",
        "--set",
        "left.storeys=3",
        "--set",
        "left.stiffnesses=1e-06,1e13,1.16e7",
        "--set",
        "right.storeys=3",
        "--set",
        "right.stiffnesses=1e-06,1e13,1.16e7",
    ]);
    assert!(e.contains("left.stiffnesses"), "{e}");
    assert!(!e.contains("inf"), "{e}");
}

#[test]
fn a_seed_that_is_not_a_whole_number_is_refused() {
    for seed in ["1.5", "1e-300"] {
        let e = refused(&["buildings", "--set", &format!("motion.seed={seed}")]);
        assert!(
            e.contains("motion.seed") && e.contains("whole number"),
            "{seed}: {e}"
        );
    }
    let e = refused(&["buildings", "--set", "motion.seed=-1"]);
    assert!(e.contains("motion.seed"), "{e}");
}

#[test]
fn rayleigh_modes_a_one_storey_building_lacks_are_refused() {
    for modes in ["3,4", "1,1"] {
        let e = refused(&[
            "buildings",
            "--set",
            "right.damping=rayleigh",
            "--set",
            &format!("right.rayleigh_modes={modes}"),
        ]);
        assert!(e.contains("right.rayleigh_modes"), "{modes}: {e}");
    }
}

#[test]
fn a_geometric_sweep_hits_its_ends_exactly() {
    for (param, from, to) in [
        ("contact.stiffness", 1.0, 1e20),
        ("bar1.youngs_modulus", 1000.0, 1e13),
    ] {
        let v = json(&[
            "sweep",
            "--param",
            param,
            "--from",
            &from.to_string(),
            "--to",
            &to.to_string(),
            "--count",
            "3",
            "--log",
            "--json",
        ]);
        let values: Vec<f64> = v["values"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect();
        assert_eq!(values.first(), Some(&from), "{param}");
        assert_eq!(values.last(), Some(&to), "{param}");
    }
}

#[test]
fn the_synthetic_record_is_accepted_by_motion_everywhere() {
    for m in ["synthetic", "synthetic:1"] {
        let o = pounding(&["buildings", "--motion", m, "--set", "motion.length=2"]);
        assert!(o.status.success(), "{m}: {}", stderr(&o));
        assert!(stdout(&o).contains("synthetic"), "{m}: {}", stdout(&o));
    }
    let e = refused(&["buildings", "--motion", "synthetic:1.5"]);
    assert!(e.contains("whole number"), "{e}");
}

#[test]
fn a_building_preset_with_a_syntax_error_names_the_line_not_the_scene() {
    let text = std::fs::read_to_string("assets/presets/paper-buildings.toml")
        .unwrap()
        .replacen("mass = ", "mass = = ", 1);
    let bad = scratch("bad-syntax.toml", text.as_bytes());
    for cmd in ["buildings", "gaps"] {
        let e = refused(&[cmd, "--preset", bad.to_str().unwrap()]);
        assert!(e.contains("line "), "{cmd}: {e}");
        assert!(!e.contains("impact scene"), "{cmd}: {e}");
    }
}

#[test]
fn an_invalid_utf8_byte_is_named_by_line_and_position() {
    let mut preset = std::fs::read("assets/presets/paper-buildings.toml").unwrap();
    let at = preset.iter().position(|&b| b == b'\n').unwrap() + 3;
    preset[at] = 0xFF;
    let p = scratch("bad-utf8.toml", &preset);
    let e = refused(&["buildings", "--preset", p.to_str().unwrap()]);
    assert!(e.contains("line 2, byte 3") && e.contains("0xFF"), "{e}");

    let r = scratch("bad-utf8.txt", b"0.0 0.1\n0.02 0.2\n0.04 \xC30.3\n");
    let e = refused(&["buildings", "--motion", r.to_str().unwrap()]);
    assert!(e.contains("line 3, byte 6") && e.contains("0xC3"), "{e}");
}

#[test]
fn a_diverged_or_overlong_building_run_hints_at_keys_of_that_element_and_command() {
    for contact in ["linear", "hertz", "hertzdamp"] {
        let o = pounding(&[
            "buildings",
            "--contact",
            contact,
            "--set",
            "contact.stiffness=1e20",
            "--set",
            "motion.duration=1",
        ]);
        let e = stderr(&o);
        assert!(!e.contains("contact.reading"), "{contact}: {e}");
        assert!(!e.contains("Sears paper reading"), "{contact}: {e}");
    }
    let e = refused(&["buildings", "--set", "solver.max_steps=1"]);
    assert!(e.contains("solver.max_steps"), "{e}");
    assert!(
        !e.contains("solver.dt") && !e.contains("solver.window"),
        "{e}"
    );
}

#[test]
fn a_printed_limit_is_true_to_its_digits() {
    let e = refused(&["impact", "--set", "bar1.length=1e-6"]);
    assert!(e.contains("allowed"), "{e}");
    assert!(!e.contains("< 0.0000 ") && !e.contains("< 0.0000\n"), "{e}");
}

#[test]
fn gaps_fails_when_no_record_succeeded_and_names_failures_when_some_did() {
    let bad = scratch("not-a-record.txt", b"this is not a record\n");
    let e = refused(&["gaps", "--motion", bad.to_str().unwrap()]);
    assert!(
        e.contains("no record succeeded") && e.contains("not-a-record"),
        "{e}"
    );

    let o = pounding(&[
        "gaps",
        "--motion",
        bad.to_str().unwrap(),
        "--motion",
        "synthetic:3",
        "--set",
        "motion.length=2",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("not-a-record"), "{}", stderr(&o));
}

/// Runs `pounding` and asserts it ended with a named error within `limit`.
fn refused_within(args: &[&str], limit: Duration) -> String {
    let start = Instant::now();
    let e = refused(args);
    assert!(
        start.elapsed() < limit,
        "{args:?} took {:?}",
        start.elapsed()
    );
    e
}

#[test]
fn a_device_is_refused_as_a_record_or_preset() {
    let e = refused_within(
        &["buildings", "--set", "motion.file=/dev/zero"],
        Duration::from_secs(5),
    );
    assert!(e.contains("not a regular file"), "{e}");
    let e = refused_within(
        &["buildings", "--preset", "/dev/zero"],
        Duration::from_secs(5),
    );
    assert!(e.contains("not a regular file"), "{e}");
}

#[test]
fn a_huge_sparse_file_is_refused_by_size_before_it_is_read() {
    for name in ["huge.AT2", "huge.txt", "huge.toml"] {
        let path = scratch(name, b"");
        std::fs::File::options()
            .write(true)
            .open(&path)
            .unwrap()
            .set_len(1 << 30)
            .unwrap();
        let args: Vec<&str> = if name.ends_with("toml") {
            vec!["buildings", "--preset", path.to_str().unwrap()]
        } else {
            vec!["buildings", "--motion", path.to_str().unwrap()]
        };
        let e = refused_within(&args, Duration::from_secs(5));
        assert!(
            e.contains("larger than") && e.contains("MiB"),
            "{name}: {e}"
        );
        std::fs::remove_file(&path).unwrap();
    }
}

#[test]
fn a_bad_line_is_quoted_by_a_short_excerpt() {
    // A megabyte of NULs on one line, within the size limit: parsed, refused, barely quoted.
    let nul = scratch("nul.txt", &vec![0u8; 1 << 20]);
    let e = refused(&["buildings", "--motion", nul.to_str().unwrap()]);
    assert!(e.len() < 1000, "{} bytes of error", e.len());
    assert!(e.contains("line 1"), "{e}");

    let dir = nul.parent().unwrap().join("nul-dir");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::copy(&nul, dir.join("nul.txt")).unwrap();
    let o = pounding(&["gaps", "--motion-dir", dir.to_str().unwrap(), "--json"]);
    assert!(
        stdout(&o).len() + stderr(&o).len() < 10_000,
        "output too long"
    );
}

/// Ctrl-C reaches a run that watches for it: the sweep stops at its next solve. (100 000 FE
/// solves take some 20 s; the signal comes after 3, once the handler has long been set up.)
#[test]
fn ctrl_c_stops_a_long_sweep_with_a_message_and_a_failing_status() {
    let out = interrupted_run(
        &[
            "sweep",
            "--param",
            "bar1.length",
            "--from",
            "1e-3",
            "--to",
            "1",
            "--count",
            "100000",
            "--model",
            "fe",
            "--quiet",
        ],
        Duration::from_secs(20),
    );
    assert!(!out.status.success());
    let e = String::from_utf8_lossy(&out.stderr);
    assert!(e.contains("cancelled"), "{e}");
}

/// Starts `pounding ARGS`, sends it Ctrl-C after three seconds, and returns what it left.
fn interrupted_run(args: &[&str], limit: Duration) -> std::process::Output {
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_pounding"))
        .args(args)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_millis(3000));
    assert!(
        child.try_wait().unwrap().is_none(),
        "`pounding {}` ended before the Ctrl-C",
        args.join(" ")
    );
    let sent = std::process::Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(sent.success());
    let start = Instant::now();
    loop {
        if child.try_wait().unwrap().is_some() {
            return child.wait_with_output().unwrap();
        }
        assert!(start.elapsed() < limit, "still running after Ctrl-C");
        std::thread::sleep(Duration::from_millis(50));
    }
}

#[test]
fn ctrl_c_ends_a_run_that_does_not_watch_for_it_at_once() {
    // An animation export has no cancel of its own: Ctrl-C must still end it, as it would
    // without a handler, not be swallowed until the export is done.
    let dir = std::env::temp_dir().join(format!("pounding-ctrl-c-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let gif = dir.join("long.gif");
    let out = interrupted_run(
        &[
            "impact",
            "--preset",
            "long-bars",
            "--animate",
            gif.to_str().unwrap(),
            "--animate-frames",
            "2000",
            "--quiet",
        ],
        Duration::from_secs(10),
    );
    assert_eq!(out.status.code(), Some(130));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn accuracy_takes_the_users_own_step_at_the_top_of_the_range_and_keeps_its_ladder_inside_it() {
    // `accuracy --set solver.dt=1` was refused ("solver.dt: 4 is not allowed"): the ladder's
    // coarsest rung was four times the user's step, past the key's range.
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_pounding"))
        .args(["accuracy", "--set", "solver.dt=1", "--json"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let range =
        pounding::model::settings::find(pounding::model::settings::IMPACT_SETTINGS, "solver.dt")
            .and_then(|s| s.range())
            .unwrap();
    let steps: Vec<f64> = v["rungs"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|r| r["model"].as_str().unwrap().starts_with("sears"))
        .map(|r| r["resolution"].as_f64().unwrap())
        .collect();
    assert!(!steps.is_empty());
    assert!(steps.iter().all(|&h| range.contains(h)), "{steps:?}");
    assert!(
        steps.contains(&1.0),
        "the user's own step is a rung: {steps:?}"
    );
}

#[test]
fn study_reads_the_synthetic_record_as_buildings_does() {
    // `study ... --motion synthetic` said "cannot read: No such file or directory".
    let dir = std::env::temp_dir().join(format!("pounding-study-synth-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for motion in ["synthetic", "synthetic:1"] {
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_pounding"))
            .args([
                "study",
                "fig12-displacements",
                "--motion",
                motion,
                "--quiet",
            ])
            .current_dir(&dir)
            .output()
            .unwrap();
        let e = String::from_utf8_lossy(&o.stderr);
        assert!(o.status.success(), "{motion}: {e}");
        assert!(!e.contains("cannot read"), "{motion}: {e}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
