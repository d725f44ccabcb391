//! One place for each fact (issue 22): a setting's key is spelled in its row of the settings
//! table (`src/model/settings/`) and nowhere else in the sources outside tests; everything else
//! names the row's const. A key spelled by hand again is a second place that can drift.

use pounding::model::settings::{
    BRIDGE_SETTINGS, BUILDING_SETTINGS, IMPACT_SETTINGS, concrete_keys,
};
use std::path::{Path, PathBuf};

/// Quoted keys that are not the setting: (file, key, how many at most, why).
const NOT_THE_SETTING: &[(&str, &str, usize, &str)] = &[
    (
        "src/cli/sweep.rs",
        "model",
        1,
        "the --model flag's name in a clap attribute, which takes a literal",
    ),
    (
        "src/model/building/solve.rs",
        "solver.max_steps",
        1,
        "the step-budget error of the building solver, whose rewrite owns the file",
    ),
];

fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The index just past the `}` that closes the `{` at `open`, skipping strings, characters
/// and comments (a brace in `"{x}"` does not count).
fn block_end(text: &[u8], open: usize) -> usize {
    let mut depth = 0usize;
    let mut i = open;
    while i < text.len() {
        match text[i] {
            b'"' => {
                i += 1;
                while i < text.len() && text[i] != b'"' {
                    i += if text[i] == b'\\' { 2 } else { 1 };
                }
            }
            b'\'' if i + 2 < text.len() && (text[i + 2] == b'\'' || text[i + 1] == b'\\') => {
                i += if text[i + 1] == b'\\' { 3 } else { 2 };
            }
            b'/' if text.get(i + 1) == Some(&b'/') => {
                while i < text.len() && text[i] != b'\n' {
                    i += 1;
                }
            }
            b'{' => depth += 1,
            b'}' => {
                depth -= 1;
                if depth == 0 {
                    return i + 1;
                }
            }
            _ => {}
        }
        i += 1;
    }
    text.len()
}

/// The source without its `#[cfg(test)] mod ... { ... }` blocks.
fn without_tests(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(at) = rest.find("#[cfg(test)]") {
        let after = &rest[at..];
        let is_mod = after["#[cfg(test)]".len()..]
            .trim_start()
            .starts_with("mod ");
        let Some(open) = after.find('{').filter(|_| is_mod) else {
            out.push_str(&rest[..at + 1]);
            rest = &rest[at + 1..];
            continue;
        };
        out.push_str(&rest[..at]);
        rest = &after[block_end(after.as_bytes(), open)..];
    }
    out.push_str(rest);
    out
}

#[test]
fn the_test_blocks_are_left_out_and_the_rest_kept() {
    let text = "a\n#[cfg(test)]\nmod tests {\n fn f() { let s = \"}\"; let c = '{'; }\n}\nb";
    assert_eq!(without_tests(text), "a\n\nb");
}

#[test]
fn each_settings_key_is_spelled_only_in_the_settings_table() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    sources(&root.join("src"), &mut files);
    let table = root.join("src/model/settings");
    let mut keys: Vec<String> = [IMPACT_SETTINGS, BUILDING_SETTINGS, BRIDGE_SETTINGS]
        .iter()
        .flat_map(|t| {
            let generic = t.iter().map(|s| s.key.to_string());
            generic.chain(concrete_keys(t))
        })
        .collect();
    keys.sort();
    keys.dedup();
    assert!(keys.len() > 100, "only {} keys", keys.len());
    let mut found = Vec::new();
    let mut checked = 0;
    for file in files.iter().filter(|f| !f.starts_with(&table)) {
        let text = without_tests(&std::fs::read_to_string(file).unwrap());
        let name = file
            .strip_prefix(root)
            .unwrap()
            .to_string_lossy()
            .replace('\\', "/");
        checked += 1;
        for key in &keys {
            let n = text.matches(&format!("\"{key}\"")).count();
            let allowed = NOT_THE_SETTING
                .iter()
                .find(|(f, k, _, _)| *f == name && k == key)
                .map_or(0, |(_, _, most, _)| *most);
            if n > allowed {
                found.push(format!("{name}: \"{key}\" {n} times"));
            }
        }
    }
    assert!(checked > 100, "only {checked} source files read");
    assert!(
        found.is_empty(),
        "keys spelled outside the settings table:\n{}",
        found.join("\n")
    );
}
