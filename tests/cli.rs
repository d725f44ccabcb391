//! The `pounding` binary as a user and a script would call it.

use common::{pounding, stderr, stdout};
use std::process::Command;

mod common;

/// Runs `pounding` and asserts it succeeded, showing its stderr where it did not.
fn succeeds(args: &[&str]) -> std::process::Output {
    let o = pounding(args);
    assert!(o.status.success(), "{}", stderr(&o));
    o
}

fn json(args: &[&str]) -> serde_json::Value {
    let mut all = args.to_vec();
    all.push("--json");
    let o = succeeds(&all);
    serde_json::from_str(&stdout(&o)).expect("one JSON object")
}

#[test]
fn impact_without_arguments_runs_the_papers_base_case() {
    let o = succeeds(&["impact"]);
    let out = stdout(&o);
    assert!(
        out.contains("preset paper-base") && out.contains("peak force") && out.contains("a tau"),
        "{out}"
    );
}

#[test]
fn the_window_starts_draws_and_closes_on_request() {
    // Needs a display (CI runs the tests under Xvfb); without one, the failure must be a clean
    // message, never a panic.
    let has_display =
        std::env::var_os("DISPLAY").is_some() || std::env::var_os("WAYLAND_DISPLAY").is_some();
    // CI provides a virtual display and a software adapter: there the window must really open.
    let has_display = has_display || std::env::var_os("CI").is_some();
    let shot = std::env::temp_dir().join(format!("pounding-smoke-{}.png", std::process::id()));
    let _ = std::fs::remove_file(&shot);
    let o = pounding(&[
        "window",
        "--preset",
        "paper-base",
        "--exit-after-frames",
        "20",
        "--screenshot",
        shot.to_str().unwrap(),
    ]);
    if has_display {
        assert!(o.status.success(), "{}", stderr(&o));
        // The frame it drew is not blank: many colours, and no one colour covers most of it.
        let (width, height, _, rgba) = common::read_png(&shot);
        assert!(width >= 400 && height >= 300, "{}x{}", width, height);
        let mut counts = std::collections::HashMap::new();
        for px in rgba.chunks(4) {
            *counts.entry([px[0], px[1], px[2]]).or_insert(0usize) += 1;
        }
        let pixels = (width * height) as usize;
        let commonest = counts.values().copied().max().unwrap();
        assert!(counts.len() > 200, "only {} colours", counts.len());
        assert!(
            commonest < pixels * 9 / 10,
            "one colour covers {commonest} of {pixels}"
        );
        let _ = std::fs::remove_file(&shot);
    } else {
        assert!(!stderr(&o).contains("panicked"), "{}", stderr(&o));
    }
}

#[test]
fn a_drag_is_refused_by_name_before_a_window_opens_and_measured_when_one_does() {
    for (spec, said) in [
        ("gap", "KEY=FROM:TO"),
        ("gap=0.01:wide", "'wide' is not a finite number"),
    ] {
        let o = pounding(&["window", "--drag", spec, "--exit-after-frames", "5"]);
        assert!(!o.status.success());
        let err = stderr(&o);
        assert!(err.contains("--drag") && err.contains(said), "{err}");
    }
    let o = pounding(&["window", "--drag", "gap=0.01:0.03"]);
    assert!(!o.status.success(), "a drag that never ends is refused");
    let has_display = std::env::var_os("DISPLAY").is_some() || std::env::var_os("CI").is_some();
    if !has_display {
        return;
    }
    let o = succeeds(&[
        "window",
        "--scene",
        "buildings",
        "--preset",
        "paper-buildings",
        "--drag",
        "gap=0.01:0.03",
        "--exit-after-frames",
        "30",
    ]);
    let err = stderr(&o);
    // How many frames it took for the first run to land, and how many runs landed while
    // dragging, depend on the machine; that it measured and said so does not.
    assert!(
        err.contains("--drag gap: ") && err.contains(" changes in "),
        "{err}"
    );
    assert!(
        err.contains("runs landed; change to result median"),
        "{err}"
    );
    let o = succeeds(&[
        "window",
        "--scene",
        "bar",
        "--drag",
        "gap=0.01:0.03",
        "--exit-after-frames",
        "5",
    ]);
    let err = stderr(&o);
    assert!(
        err.contains("--drag: stopped: only the buildings and bridge scenes"),
        "{err}"
    );
    let o = succeeds(&[
        "window",
        "--scene",
        "buildings",
        "--drag",
        "no.such.key=1:2",
        "--exit-after-frames",
        "5",
    ]);
    let err = stderr(&o);
    assert!(
        err.contains("--drag: stopped:") && err.contains("no.such.key"),
        "{err}"
    );
}

#[test]
fn json_report_carries_the_promised_fields_in_si_units() {
    let v = json(&["impact"]);
    for key in [
        "peak_force_n",
        "contact_duration_s",
        "restitution",
        "impulse_ns",
        "contacts",
        "steps",
        "solve_time_s",
        "energy_balance_error",
        "warnings",
    ] {
        assert!(v.get(key).is_some(), "missing {key}: {v}");
    }
    let peak = v["peak_force_n"].as_f64().unwrap();
    assert!(peak > 1.3e5 && peak < 1.4e5, "{peak}");
    assert_eq!(v["contacts"].as_u64(), Some(1));
    assert!(v["warnings"].is_array());
    let solve = v["solve_time_s"].as_f64().unwrap();
    assert!(solve > 0.0 && solve < 1.0, "the solve alone: {solve}");
}

#[test]
fn every_model_runs_from_the_command_line() {
    for model in [
        "sears",
        "wave",
        "lumped-hertz",
        "lumped-linear",
        "kelvin",
        "stereo",
        "fe",
    ] {
        let v = json(&["impact", "--model", model]);
        assert_eq!(v["model"], model);
        let e = v["restitution"].as_f64().unwrap();
        assert!((0.0..=1.0).contains(&e), "{model}: e = {e}");
    }
    assert!(
        json(&["impact", "--model", "stereo"])["peak_force_n"].is_null(),
        "an instantaneous exchange has no peak"
    );
}

#[test]
fn set_overrides_reach_the_solver() {
    let v = json(&[
        "impact",
        "--set",
        "bar2.length=1",
        "--set",
        "sears.reading=end",
        "--set",
        "bar1.end_radius=0.1",
    ]);
    let e = v["restitution"].as_f64().unwrap();
    assert!(e > 0.95 && e <= 1.0, "equal bars: {e}");
    assert_eq!(v["sears"]["reading"], "end");
    let w = json(&["impact", "--preset", "long-bars", "--model", "wave"]);
    assert!((w["restitution"].as_f64().unwrap() - 0.5).abs() < 1e-12);
}

#[test]
fn bad_values_exit_nonzero_and_name_the_field_and_range() {
    for (set, field, range) in [
        ("bar1.poisson_ratio=0.7", "bar1.poisson_ratio", "(-1, 0.5)"),
        (
            "bar2.youngs_modulus=-5",
            "bar2.youngs_modulus",
            "[1000, 1e13] Pa",
        ),
        ("bar1.length=nan", "bar1.length", "[1e-6, 1e6] m"),
        ("bar1.length=inf", "bar1.length", "[1e-6, 1e6] m"),
        ("solver.dt=0", "solver.dt", "[1e-15, 1] s"),
        ("bar1.radius=0", "bar1.radius", "[1e-6, 1000] m"),
        ("contact.restitution=1.5", "contact.restitution", "[0, 1]"),
        ("bar1.material=wood", "bar1.material", "steel|concrete"),
        ("bar1.lenght=1", "bar1.lenght", "unknown key"),
        (
            "sears.reading=sideways",
            "sears.reading",
            "paper|collocated|end",
        ),
        ("bar1.velocity=fast", "bar1.velocity", "expected a number"),
    ] {
        let o = pounding(&["impact", "--set", set]);
        assert!(!o.status.success(), "{set} must fail");
        let err = stderr(&o);
        assert!(err.contains(field) && err.contains(range), "{set}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

#[test]
fn bars_that_do_not_approach_report_no_impact() {
    let v = json(&["impact", "--set", "bar2.velocity=2"]);
    assert_eq!(v["impact"], false);
    assert!(
        v["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .any(|w| w.as_str().unwrap().contains("not approaching"))
    );
}

#[test]
fn a_malformed_preset_is_reported_with_file_line_and_key() {
    let dir = std::env::temp_dir().join(format!("pounding-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("typo.toml");
    std::fs::write(
        &file,
        "model = \"sears\"\n\n[bar1]\nlength = 1.0\nlenght = 2.0\n",
    )
    .unwrap();
    let o = pounding(&["impact", "--preset", file.to_str().unwrap()]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("typo.toml") && err.contains("line 5") && err.contains("bar1.lenght"),
        "{err}"
    );
    std::fs::write(&file, "[bar1\nlength = 1.0\n").unwrap();
    let err = stderr(&pounding(&["impact", "--preset", file.to_str().unwrap()]));
    assert!(err.contains("typo.toml") && err.contains("line 1"), "{err}");
    let err = stderr(&pounding(&["impact", "--preset", "no-such-preset"]));
    assert!(
        err.contains("no-such-preset") && err.contains("paper-base"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn csv_has_a_header_with_units_and_one_row_per_sample() {
    let dir = std::env::temp_dir().join(format!("pounding-csv-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("force.csv");
    let o = pounding(&["impact", "--csv", file.to_str().unwrap(), "--json"]);
    assert!(o.status.success());
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let text = std::fs::read_to_string(&file).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("time_s,force_n,approach_m"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len() as u64, v["steps"].as_u64().unwrap() + 1);
    let peak = rows.iter().map(|r| r[1]).fold(0.0, f64::max);
    assert!((peak - v["peak_force_n"].as_f64().unwrap()).abs() < 1e-3 * peak);
    let err = stderr(&pounding(&[
        "impact",
        "--csv",
        "/dev/null/inside-a-file/x.csv",
    ]));
    assert!(err.contains("/dev/null/inside-a-file/x.csv"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_run_over_the_step_budget_stops_with_a_message_naming_it() {
    let o = pounding(&[
        "impact",
        "--set",
        "solver.window=1",
        "--set",
        "solver.max_steps=1000",
    ]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("solver.max_steps = 1000"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn every_shipped_preset_runs() {
    let o = pounding(&["impact", "--list-presets"]);
    let names: Vec<String> = stdout(&o)
        .lines()
        .map(|l| l.split_whitespace().next().unwrap().to_string())
        .collect();
    assert!(names.len() >= 5 && names.contains(&"paper-base".to_string()));
    for name in names {
        let v = json(&["impact", "--preset", &name]);
        assert!(v["peak_force_n"].as_f64().unwrap() > 0.0, "{name}");
    }
}

#[test]
fn a_closed_output_pipe_ends_quietly() {
    use std::io::Read;
    use std::process::Stdio;
    let mut child = Command::new(env!("CARGO_BIN_EXE_pounding"))
        .args(["impact", "--csv", "-", "--set", "solver.dt=1e-8"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 16];
    child.stdout.take().unwrap().read_exact(&mut first).unwrap();
    // stdout is dropped here: the reader went away, like `| head`.
    let out = child.wait_with_output().unwrap();
    assert!(!String::from_utf8_lossy(&out.stderr).contains("panicked"));
}

#[test]
fn buildings_runs_the_papers_case_on_el_centro_by_default() {
    let v = json(&["buildings"]);
    for key in [
        "impacts",
        "contacts",
        "max_pounding_force_n",
        "peak_displacement_left_m",
        "peak_displacement_right_m",
        "solve_time_s",
        "warnings",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    assert!(v["impacts"].as_array().unwrap().len() as u64 == v["impact_count"].as_u64().unwrap());
    assert!(
        v["motion"]["name"]
            .as_str()
            .unwrap()
            .contains("El Centro 1940")
    );
    assert_eq!(v["motion"]["points"], 401);
    assert_eq!(v["contact_model"], "sears");
    let synthetic = json(&["buildings", "--set", "motion.file=synthetic"]);
    assert!(
        synthetic["motion"]["name"]
            .as_str()
            .unwrap()
            .contains("synthetic")
    );
}

#[test]
fn buildings_takes_every_contact_model_and_the_shipped_record_by_name_or_path() {
    for motion in ["elcentro-1940", "assets/motions/elcentro-1940-ns.txt"] {
        for model in [
            "sears",
            "linear",
            "kelvin",
            "hertz",
            "hertzdamp",
            "jankowski",
            "stereo",
            "none",
        ] {
            let v = json(&["buildings", "--contact", model, "--motion", motion]);
            assert_eq!(v["contact_model"], model);
            assert_eq!(v["motion"]["points"], 401, "{motion}: the preset's 8 s");
            let pounds = v["impact_count"].as_u64().unwrap() > 0;
            assert_eq!(pounds, model != "none", "{model}");
        }
    }
}

#[test]
fn buildings_bad_input_names_the_field() {
    for (set, field) in [
        ("left.damping_ratio=2", "left.damping_ratio"),
        ("gap=-1", "gap"),
        ("slab.damping=1", "slab.damping"),
        ("motion.units=furlongs", "motion.units"),
        ("contact.reading=middle", "contact.reading"),
    ] {
        let o = pounding(&["buildings", "--set", set]);
        assert!(!o.status.success(), "{set}");
        assert!(stderr(&o).contains(field), "{set}: {}", stderr(&o));
    }
    let o = pounding(&["buildings", "--motion", "/no/such/record.AT2"]);
    assert!(!o.status.success() && stderr(&o).contains("/no/such/record.AT2"));
    let o = pounding(&["impact", "--preset", "paper-buildings"]);
    assert!(
        !o.status.success() && stderr(&o).contains("pounding buildings"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn buildings_csv_has_a_header_with_units() {
    let o = pounding(&["buildings", "--csv", "-", "--set", "motion.length=2"]);
    assert!(o.status.success());
    let out = stdout(&o);
    assert!(out.starts_with("time_s,ground_accel_m_s2,u_left_m,u_right_m,"));
    assert!(out.lines().count() > 100);
}

#[test]
fn accuracy_reports_a_ladder_with_second_order_and_writes_the_work_precision_plot() {
    let dir = std::env::temp_dir().join(format!("pounding-acc-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (csv, svg, png) = (dir.join("acc.csv"), dir.join("wp.svg"), dir.join("wp.png"));
    succeeds(&[
        "accuracy",
        "--csv",
        csv.to_str().unwrap(),
        "--plot",
        svg.to_str().unwrap(),
    ]);
    let table = std::fs::read_to_string(&csv).unwrap();
    assert!(table.starts_with("model,resolution,steps,wall_time_s,peak_force_error"));
    // The Sears paper rows: each halving of the step divides the L2 error by about 4.
    let orders: Vec<f64> = table
        .lines()
        .filter(|l| l.starts_with("sears paper"))
        .filter_map(|l| l.split(',').nth(8).and_then(|x| x.parse().ok()))
        .collect();
    assert!(
        orders.len() >= 4 && orders.iter().all(|p| (*p - 2.0).abs() < 0.2),
        "{orders:?}"
    );
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(
        text.contains("<svg") && text.contains("Work-precision") && text.contains("sears paper")
    );
    succeeds(&["accuracy", "--plot", png.to_str().unwrap(), "--json"]);
    let bytes = std::fs::read(&png).unwrap();
    assert!(bytes.starts_with(&[0x89, b'P', b'N', b'G']) && bytes.len() > 10_000);
    let err = stderr(&pounding(&[
        "accuracy",
        "--plot",
        dir.join("wp.gif").to_str().unwrap(),
    ]));
    assert!(err.contains(".svg or .png"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn impact_and_buildings_write_their_force_plot_as_png_or_svg() {
    let dir = std::env::temp_dir().join(format!("pounding-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (png, svg) = (dir.join("force.png"), dir.join("force.svg"));
    assert!(
        pounding(&["impact", "--plot", png.to_str().unwrap()])
            .status
            .success()
    );
    let (width, height, _, pixels) = common::read_png(&png);
    assert_eq!((width, height), (1000, 600));
    // A white page with a drawn curve, axes and text: not one colour.
    let white = pixels.iter().filter(|&&b| b == 255).count();
    assert!(
        white < pixels.len() * 99 / 100 && white > pixels.len() / 2,
        "{white} of {}",
        pixels.len()
    );
    assert!(
        pounding(&[
            "buildings",
            "--set",
            "motion.length=3",
            "--plot",
            svg.to_str().unwrap()
        ])
        .status
        .success()
    );
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(
        text.contains("<svg")
            && text.contains("pounding force [MN]")
            && text.trim_end().ends_with("</svg>")
    );
    let big = dir.join("big.png");
    succeeds(&[
        "impact",
        "--plot",
        big.to_str().unwrap(),
        "--plot-size",
        "1500x900",
        "--plot-scale",
        "1.5",
    ]);
    let (width, height, _, _) = common::read_png(&big);
    assert_eq!((width, height), (1500, 900));
    for (flag, value) in [("--plot-size", "20x20"), ("--plot-scale", "0")] {
        let err = stderr(&pounding(&["impact", "--plot", "x.png", flag, value]));
        assert!(err.contains(flag) && err.contains("expected"), "{err}");
    }
    let err = stderr(&pounding(&[
        "impact",
        "--plot",
        "/dev/null/inside-a-file/f.png",
    ]));
    assert!(
        err.contains("--plot") && err.contains("/dev/null/inside-a-file/f.png"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_sweep_point_is_the_same_impact_solved_alone() {
    let v = json(&[
        "sweep",
        "--param",
        "bar2.length",
        "--from",
        "0.5",
        "--to",
        "10",
        "--count",
        "5",
    ]);
    assert_eq!(v["solves"].as_u64(), Some(5));
    assert!(v["wall_time_s"].as_f64().unwrap() > 0.0);
    let values: Vec<f64> = v["values"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert_eq!(values, vec![0.5, 2.875, 5.25, 7.625, 10.0]);
    for i in [0, 3] {
        let point = &v["points"][i];
        let alone = json(&["impact", "--set", &format!("bar2.length={}", values[i])]);
        assert_eq!(point["value"].as_f64(), Some(values[i]));
        assert_eq!(
            point["peak_force_n"], alone["peak_force_n"],
            "at {}",
            values[i]
        );
        assert_eq!(
            point["restitution"], alone["restitution"],
            "at {}",
            values[i]
        );
    }
}

#[test]
fn wave_theory_peak_force_does_not_depend_on_the_struck_bar_length() {
    // Z1 Z2 / (Z1 + Z2) v for equal steel rods: the length only sets how long the force lasts.
    let v = json(&[
        "sweep",
        "--param",
        "bar2.length",
        "--from",
        "0.5",
        "--to",
        "20",
        "--count",
        "12",
        "--log",
        "--model",
        "wave",
        "--model",
        "sears",
    ]);
    assert_eq!(v["solves"].as_u64(), Some(24));
    let points = v["points"].as_array().unwrap();
    let wave: Vec<f64> = points
        .iter()
        .filter(|p| p["model"] == "wave")
        .map(|p| p["peak_force_n"].as_f64().unwrap())
        .collect();
    assert_eq!(wave.len(), 12);
    for f in &wave {
        assert!((f - wave[0]).abs() <= 1e-9 * wave[0], "{wave:?}");
    }
    // Geometric spacing, ends included.
    let values = v["values"].as_array().unwrap();
    assert_eq!(values[0].as_f64(), Some(0.5));
    assert!((values[11].as_f64().unwrap() - 20.0).abs() < 1e-12);
    let ratio = values[1].as_f64().unwrap() / values[0].as_f64().unwrap();
    assert!((ratio - 40f64.powf(1.0 / 11.0)).abs() < 1e-12);
}

#[test]
fn sweep_writes_csv_and_plot_and_refuses_bad_ranges_by_name() {
    let dir = std::env::temp_dir().join(format!("pounding-sweep-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (csv, svg) = (dir.join("s.csv"), dir.join("s.svg"));
    let o = succeeds(&[
        "sweep",
        "--param",
        "bar1.velocity",
        "--from",
        "0.1",
        "--to",
        "5",
        "--count",
        "4",
        "--csv",
        csv.to_str().unwrap(),
        "--plot",
        svg.to_str().unwrap(),
    ]);
    assert!(stdout(&o).contains("4 solves in"), "{}", stdout(&o));
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("bar1.velocity,model,peak_force_n,contact_duration_s,restitution,contacts,error")
    );
    assert_eq!(lines.count(), 4);
    assert!(
        std::fs::read_to_string(&svg)
            .unwrap()
            .contains("peak force [kN]")
    );
    for (args, want) in [
        (
            vec!["--param", "bar9.length", "--from", "1", "--to", "2"],
            "--param",
        ),
        (
            vec!["--param", "model", "--from", "1", "--to", "2"],
            "--param",
        ),
        (
            vec![
                "--param",
                "bar2.length",
                "--from",
                "0",
                "--to",
                "2",
                "--log",
            ],
            "--log",
        ),
        (
            vec![
                "--param",
                "bar2.length",
                "--from",
                "1",
                "--to",
                "2",
                "--count",
                "1",
            ],
            "--count",
        ),
        (
            vec!["--param", "bar2.length", "--from", "-1", "--to", "2"],
            "bar2.length=-1",
        ),
        (
            vec![
                "--param",
                "bar2.length",
                "--from",
                "1",
                "--to",
                "2",
                "--model",
                "x",
            ],
            "--model",
        ),
    ] {
        let mut all = vec!["sweep"];
        all.extend(args);
        let o = pounding(&all);
        assert!(!o.status.success());
        let err = stderr(&o);
        assert!(
            err.contains(want) && !err.contains("panicked"),
            "{all:?}: {err}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn wave_theory_has_no_contact_law_so_flat_ends_run_while_hertz_models_name_the_missing_radius() {
    // Wave theory and the spring models never read the Hertz law: both ends flat must run.
    for model in ["wave", "lumped-linear", "fe"] {
        let v = json(&[
            "impact",
            "--model",
            model,
            "--set",
            "bar1.end_radius=flat",
            "--set",
            "contact.law=linear",
        ]);
        assert!(v["peak_force_n"].as_f64().unwrap() > 0.0, "{model}: {v}");
    }
    let v = json(&["impact", "--model", "wave", "--set", "bar1.end_radius=flat"]);
    assert!(v["peak_force_n"].as_f64().unwrap() > 0.0, "{v}");
    // The Hertzian models do read it: they refuse, naming the law and both end radii.
    let o = pounding(&[
        "impact",
        "--model",
        "lumped-hertz",
        "--set",
        "bar1.end_radius=flat",
    ]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("contact.law") && err.contains("bar1.end_radius"),
        "{err}"
    );
}

#[test]
fn xt_and_energy_exports_write_their_documented_columns_and_refuse_bad_requests() {
    let dir = std::env::temp_dir().join(format!("pounding-xt-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (csv, png, energy) = (
        dir.join("xt.csv"),
        dir.join("xt.png"),
        dir.join("energy.csv"),
    );
    succeeds(&[
        "impact",
        "--model",
        "wave",
        "--xt",
        csv.to_str().unwrap(),
        "--xt-grid",
        "20x30",
        "--energy",
        energy.to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("bar,x_m,t_s,stress_pa,velocity_m_s"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 2 * 20 * 30);
    // Bar 1's rows, then bar 2's; x from 0 at the contact face to L; at t = 0 at rest in bar 2,
    // moving at 1 m/s in bar 1 (positive to the right).
    assert!(rows[..600].iter().all(|r| r[0] == 1.0) && rows[600..].iter().all(|r| r[0] == 2.0));
    assert_eq!((rows[0][1], rows[19][1]), (0.0, 1.0));
    assert_eq!((rows[600][1], rows[619][1]), (0.0, 2.0));
    assert!((rows[5][4] - 1.0).abs() < 1e-12 && rows[605][4].abs() < 1e-12);
    // Wave theory's plateau is compression: negative stress somewhere, never tension above it.
    assert!(rows.iter().any(|r| r[3] < -1e6));
    let e = std::fs::read_to_string(&energy).unwrap();
    assert!(e.starts_with(
        "time_s,rigid_kinetic_j,wave_j,contact_j,dissipated_j,total_j,wave_bar1_j,wave_bar2_j\n"
    ));
    succeeds(&[
        "impact",
        "--xt",
        png.to_str().unwrap(),
        "--xt-field",
        "velocity",
        "--plot-size",
        "600x400",
    ]);
    let (w, h, _, _) = common::read_png(&png);
    assert_eq!((w, h), (600, 400));
    for (args, want) in [
        (vec!["--xt", "x.svg"], "--xt"),
        (vec!["--xt", "x.png", "--xt-field", "strain"], "--xt-field"),
        (vec!["--xt", "x.csv", "--xt-grid", "1x10"], "--xt-grid"),
        (
            vec!["--xt", "x.csv", "--xt-grid", "30000x30000"],
            "--xt-grid",
        ),
    ] {
        let mut all = vec!["impact"];
        all.extend(args);
        let o = pounding(&all);
        assert!(!o.status.success(), "{all:?}");
        let err = stderr(&o);
        assert!(
            err.contains(want) && !err.contains("panicked"),
            "{all:?}: {err}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn gaps_reports_each_record_in_table_csv_json_and_plot_and_refuses_bad_records_by_name() {
    let dir = std::env::temp_dir().join(format!("pounding-gaps-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (csv, plot) = (dir.join("gaps.csv"), dir.join("gaps.png"));
    let o = succeeds(&[
        "gaps",
        "--preset",
        "mdof-3-5",
        "--motion",
        "elcentro-1940",
        "--motion",
        "synthetic:3",
        "--csv",
        csv.to_str().unwrap(),
        "--plot",
        plot.to_str().unwrap(),
        "--quiet",
    ]);
    assert!(
        stdout(&o).contains("mean ratio to the minimum gap"),
        "{}",
        stdout(&o)
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("record,duration_s,pga_g,min_gap_m,level,abs_m,abs_ratio,srss_m,srss_ratio,error")
    );
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 2, "{text}");
    // ABS adds the peaks, so it is never below the minimum gap.
    for row in &rows {
        let cells: Vec<&str> = row.rsplitn(7, ',').collect();
        let abs_ratio: f64 = cells[3].parse().unwrap();
        assert!(abs_ratio >= 1.0, "{row}");
    }
    assert!(common::read_png(&plot).0 > 0);
    let v = json(&["gaps", "--preset", "paper-buildings", "--quiet"]);
    let r = &v["records"][0];
    // The paper's pair on El Centro: 62.46 mm, ABS 1.28 times it, SRSS 0.98.
    assert!(
        (r["min_gap_m"].as_f64().unwrap() - 0.06246).abs() < 1e-4,
        "{v}"
    );
    assert!(r["abs_ratio"].as_f64().unwrap() > 1.0 && r["srss_ratio"].as_f64().unwrap() < 1.0);
    for (args, want) in [
        (
            vec!["gaps", "--motion", "/no/such/record.AT2"],
            "record.AT2",
        ),
        (
            vec!["gaps", "--motion-dir", "/no/such/folder"],
            "/no/such/folder",
        ),
        (vec!["gaps", "--set", "left.storeys=0"], "left.storeys"),
        (vec!["gaps", "--preset", "paper-base"], "paper-base"),
    ] {
        let o = pounding(&args);
        let err = stderr(&o);
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        // A record that cannot be read fails its row or the run, naming it.
        assert!(
            err.contains(want) || stdout(&o).contains(want),
            "{args:?}: {err}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn gaps_takes_the_yielding_storeys_keys_and_yielding_changes_the_gap_that_avoids_pounding() {
    let gap = |extra: &[&str]| {
        let mut args = vec!["gaps", "--quiet"];
        args.extend_from_slice(extra);
        let v = json(&args);
        v["records"][0]["min_gap_m"]
            .as_f64()
            .unwrap_or_else(|| panic!("{extra:?}: {v}"))
    };
    let elastic = gap(&["--preset", "paper-buildings"]);
    let yielding = gap(&["--preset", "paper-buildings-yielding"]);
    // Storeys that never reach their yield force: the elastic pair's gap (the preset's settling
    // after the record adds free vibration that decays, no larger closing).
    let never = gap(&[
        "--preset",
        "paper-buildings-yielding",
        "--set",
        "left.yield_forces=1e15",
        "--set",
        "right.yield_forces=1e15",
    ]);
    assert!(
        (never - elastic).abs() <= 1e-9 * elastic,
        "{never} against {elastic}"
    );
    // On El Centro the yielding pair sways less towards each other: 36 mm against 62 mm.
    assert!(yielding < 0.7 * elastic, "{yielding} against {elastic}");
    let smooth = gap(&[
        "--preset",
        "paper-buildings-yielding",
        "--set",
        "left.hysteresis=bouc-wen",
        "--set",
        "right.hysteresis=bouc-wen",
    ]);
    assert!(smooth < 0.8 * elastic && smooth != yielding, "{smooth}");
    let o = pounding(&["gaps", "--set", "left.hardening=1"]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("left.hardening"), "{}", stderr(&o));
}

#[test]
fn sweep_of_a_building_setting_agrees_with_the_gap_that_avoids_pounding_and_names_bad_keys() {
    let need =
        json(&["gaps", "--quiet", "--set", "contact.model=linear"])["records"][0]["min_gap_m"]
            .as_f64()
            .unwrap();
    let v = json(&[
        "sweep",
        "--buildings",
        "--set",
        "contact.model=linear",
        "--param",
        "gap",
        "--from",
        "0.05",
        "--to",
        "0.07",
        "--count",
        "5",
        "--quiet",
    ]);
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 5, "{v}");
    for p in points {
        let gap = p["value"].as_f64().unwrap();
        let impacts = p["impact_count"].as_u64().unwrap();
        // A gap wider than the largest closing motion without contact never closes.
        assert_eq!(impacts == 0, gap > need, "gap {gap} against {need}: {p}");
        assert!(p["error"].is_null());
    }
    for (args, want) in [
        (
            vec!["--param", "left.hysteresis", "--to", "0.9"],
            "left.hysteresis",
        ),
        (
            vec!["--param", "left.hardening", "--to", "1"],
            "left.hardening",
        ),
    ] {
        let mut all = vec!["sweep", "--buildings", "--from", "0.5"];
        all.extend(args);
        let o = pounding(&all);
        assert!(!o.status.success());
        assert!(stderr(&o).contains(want), "{all:?}: {}", stderr(&o));
    }
}
