//! What the README and the documents under docs/ show a reader holds: every
//! `cargo run --release -- ...` line (in code blocks and inline) runs as written through the
//! `pounding` binary, in an empty folder of its own, and succeeds; every link to another file of
//! the repository finds it, and its heading where it names one; the version `pounding
//! --version` prints is the newest one CHANGELOG.md describes. A window command runs for a few
//! frames where there is a display (CI's virtual one) and is left out without one.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// The README, CONTRIBUTING.md and every Markdown file under docs/, as (path from the
/// repository's root, text).
fn documents() -> Vec<(PathBuf, String)> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let mut entries: Vec<_> = std::fs::read_dir(dir)
            .expect("a docs folder")
            .map(|e| e.expect("an entry").path())
            .collect();
        entries.sort();
        for path in entries {
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "md") {
                out.push(path);
            }
        }
    }
    let root = Path::new(ROOT);
    let mut paths = vec![root.join("README.md"), root.join("CONTRIBUTING.md")];
    walk(&root.join("docs"), &mut paths);
    paths
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{p:?}: {e}"));
            (p.strip_prefix(root).expect("inside").to_path_buf(), text)
        })
        .collect()
}

/// A document's `cargo run --release -- ARGS` commands, continuation lines joined and trailing
/// comments dropped.
fn commands_in(text: &str) -> Vec<Vec<String>> {
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

/// Runs `pounding ARGS` in an empty folder and checks it succeeds and writes what it says it
/// writes.
fn runs_as_written(k: usize, args: &[String], source: &Path) {
    let mut args = args.to_vec();
    if args[0] == "window" {
        // A window command opens the window: where there is a display (CI's virtual one),
        // it runs for a few frames and closes; without one it is left to the smoke test.
        if std::env::var_os("DISPLAY").is_none() && std::env::var_os("WAYLAND_DISPLAY").is_none() {
            return;
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
        "{source:?}: `pounding {}` failed: {}",
        args.join(" "),
        common::stderr(&o)
    );
    // What a command says it writes is there.
    for (flag, path) in args.iter().zip(args.iter().skip(1)) {
        if matches!(flag.as_str(), "--csv" | "--plot" | "--out") && path != "-" {
            assert!(
                dir.join(path).exists(),
                "{source:?}: `pounding {}` did not write {path}",
                args.join(" ")
            );
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn every_command_line_in_the_readme_and_the_docs_runs() {
    let documents = documents();
    let readme = commands_in(&documents[0].1);
    // The README shows a newcomer every command at least once.
    for verb in [
        "impact",
        "buildings",
        "gaps",
        "bridge",
        "sweep",
        "study",
        "accuracy",
        "lesson",
        "window",
    ] {
        assert!(
            readme.iter().any(|c| c[0] == verb),
            "the README shows no `{verb}` command"
        );
        // Each command's page shows it at work.
        let page = Path::new("docs/commands").join(format!("{verb}.md"));
        let (_, text) = documents
            .iter()
            .find(|(p, _)| *p == page)
            .unwrap_or_else(|| panic!("no {page:?}"));
        assert!(
            commands_in(text).iter().any(|c| c[0] == verb),
            "{page:?} shows no `{verb}` command"
        );
    }
    let all: Vec<(&Path, Vec<String>)> = documents
        .iter()
        .flat_map(|(p, text)| commands_in(text).into_iter().map(move |c| (p.as_path(), c)))
        .collect();
    assert!(all.len() >= 40, "only {} commands found", all.len());
    for (k, (source, args)) in all.iter().enumerate() {
        runs_as_written(k, args, source);
    }
}

/// GitHub's anchor for a heading: lower case, punctuation dropped, spaces as hyphens.
fn anchor(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter(|c| c.is_alphanumeric() || matches!(c, ' ' | '-' | '_'))
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// The anchors of a Markdown file's headings (outside code blocks).
fn anchors(text: &str) -> Vec<String> {
    let mut fenced = false;
    let mut out = vec![];
    for line in text.lines() {
        if line.starts_with("```") {
            fenced = !fenced;
        } else if !fenced && line.starts_with('#') {
            out.push(anchor(line.trim_start_matches('#')));
        }
    }
    out
}

/// The targets of a text's Markdown links `[...](target)`.
fn link_targets(text: &str) -> Vec<String> {
    let mut out = vec![];
    let mut rest = text;
    while let Some(i) = rest.find("](") {
        let after = &rest[i + 2..];
        let Some(end) = after.find(')') else { break };
        out.push(after[..end].to_string());
        rest = &after[end..];
    }
    out
}

#[test]
fn every_link_between_the_documents_finds_its_file_and_heading() {
    let root = Path::new(ROOT);
    let mut checked = 0;
    for (path, text) in documents() {
        let dir = root.join(&path).parent().expect("a folder").to_path_buf();
        for target in link_targets(&text) {
            if target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            let (file, heading) = match target.split_once('#') {
                Some((f, h)) => (f, Some(h)),
                None => (target.as_str(), None),
            };
            let resolved = if file.is_empty() {
                root.join(&path)
            } else {
                dir.join(file)
            };
            assert!(
                resolved.exists(),
                "{path:?} links to {target}, which is not there"
            );
            if let Some(h) = heading {
                let text = std::fs::read_to_string(&resolved).expect("a document");
                assert!(
                    anchors(&text).iter().any(|a| a == h),
                    "{path:?} links to {target}: no such heading"
                );
            }
            checked += 1;
        }
    }
    assert!(checked >= 50, "only {checked} links checked");
}

#[test]
fn the_version_pounding_prints_is_the_newest_the_changelog_describes() {
    let changelog =
        std::fs::read_to_string(Path::new(ROOT).join("CHANGELOG.md")).expect("CHANGELOG.md");
    // Versions are second-level headings, newest first, after the unreleased changes.
    let newest = changelog
        .lines()
        .filter_map(|l| l.strip_prefix("## "))
        .find(|h| !h.starts_with("Unreleased"))
        .expect("a released version in CHANGELOG.md");
    let version = newest.split_whitespace().next().expect("a version");
    let o = common::pounding(&["--version"]);
    assert!(o.status.success(), "{}", common::stderr(&o));
    assert_eq!(
        common::stdout(&o).trim(),
        format!("pounding {version}"),
        "CHANGELOG.md's newest version is {version}"
    );
}
