//! Every command the README shows a newcomer runs as written: each `cargo run --release -- ...`
//! line (in code blocks and inline) through the `pounding` binary, in an empty folder of its own,
//! must succeed. A window command runs for a few frames where there is a display (CI's virtual
//! one) and is left out without one.

mod common;

use std::path::PathBuf;
use std::process::Command;

/// The README's `cargo run --release -- ARGS` commands, continuation lines joined and trailing
/// comments dropped.
fn readme_commands() -> Vec<Vec<String>> {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md"))
        .expect("the README");
    let joined = text.replace("\\\n", " ");
    let mut out = vec![];
    for line in joined.lines() {
        let mut rest = line;
        while let Some(i) = rest.find("cargo run --release -- ") {
            let after = &rest[i + "cargo run --release -- ".len()..];
            // Inline commands end at the closing backtick; block commands at a comment.
            let end = after
                .find('`')
                .or_else(|| after.find(" #"))
                .unwrap_or(after.len());
            let args: Vec<String> = after[..end].split_whitespace().map(String::from).collect();
            if !args.is_empty() {
                out.push(args);
            }
            rest = &after[end..];
        }
    }
    out
}

fn scratch(k: usize) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("pounding-readme-{}-{k}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("a scratch folder");
    dir
}

#[test]
fn every_command_line_in_the_readme_runs() {
    let commands = readme_commands();
    // The README shows impact, buildings, gaps, sweep, study and accuracy commands.
    for verb in ["impact", "buildings", "gaps", "sweep", "study", "accuracy"] {
        assert!(
            commands.iter().any(|c| c[0] == verb),
            "the README shows no `{verb}` command"
        );
    }
    assert!(
        commands.len() >= 20,
        "only {} commands found",
        commands.len()
    );
    for (k, args) in commands.iter().enumerate() {
        let mut args = args.clone();
        if args[0] == "window" {
            // A window command opens the window: where there is a display (CI's virtual one),
            // it runs for a few frames and closes; without one it is left to the smoke test.
            if std::env::var_os("DISPLAY").is_none()
                && std::env::var_os("WAYLAND_DISPLAY").is_none()
            {
                continue;
            }
            args.extend(["--exit-after-frames".to_string(), "5".to_string()]);
        }
        let dir = scratch(k);
        let o = common::output_in_own_session(
            Command::new(env!("CARGO_BIN_EXE_pounding"))
                .args(&args)
                .current_dir(&dir)
                .env("NO_COLOR", "1"),
        );
        assert!(
            o.status.success(),
            "`pounding {}` failed: {}",
            args.join(" "),
            common::stderr(&o)
        );
        // What a command says it writes is there.
        for (flag, path) in args.iter().zip(args.iter().skip(1)) {
            if matches!(flag.as_str(), "--csv" | "--plot" | "--out") && path != "-" {
                assert!(
                    dir.join(path).exists(),
                    "`pounding {}` did not write {path}",
                    args.join(" ")
                );
            }
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
