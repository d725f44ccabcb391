//! The lesson parser fuzzed: mutated shipped lessons (characters dropped, inserted or replaced,
//! lines deleted, duplicated or swapped, fields renamed) never panic; a refused file's error
//! names the file and a line inside it (or past its end for something missing), and the
//! expression parser never panics on any text. Fixed seed.

use pounding::lesson::{self, EMBEDDED, Expr, parse_text};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};

#[derive(Debug, Clone)]
enum Mutation {
    DropChar(usize),
    InsertChar(usize, char),
    ReplaceChar(usize, char),
    DropLine(usize),
    DuplicateLine(usize),
    SwapLines(usize, usize),
    RenameKey(usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let ch = prop::sample::select(vec![
        '=', '[', ']', '"', '\n', '.', 'x', '1', '-', '(', ')', ' ', '#', ',', '{', '}', '\'',
    ]);
    prop_oneof![
        any::<usize>().prop_map(Mutation::DropChar),
        (any::<usize>(), ch.clone()).prop_map(|(i, c)| Mutation::InsertChar(i, c)),
        (any::<usize>(), ch).prop_map(|(i, c)| Mutation::ReplaceChar(i, c)),
        any::<usize>().prop_map(Mutation::DropLine),
        any::<usize>().prop_map(Mutation::DuplicateLine),
        (any::<usize>(), any::<usize>()).prop_map(|(a, b)| Mutation::SwapLines(a, b)),
        any::<usize>().prop_map(Mutation::RenameKey),
    ]
}

fn apply(text: &str, m: &Mutation) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let n = lines.len();
    match *m {
        Mutation::DropChar(i) => {
            let i = i % chars.len();
            chars[..i].iter().chain(&chars[i + 1..]).collect()
        }
        Mutation::InsertChar(i, c) => {
            let i = i % (chars.len() + 1);
            let mut out: String = chars[..i].iter().collect();
            out.push(c);
            out.extend(&chars[i..]);
            out
        }
        Mutation::ReplaceChar(i, c) => {
            let i = i % chars.len();
            let mut v = chars.clone();
            v[i] = c;
            v.into_iter().collect()
        }
        Mutation::DropLine(i) => {
            lines.remove(i % n);
            lines.join("\n")
        }
        Mutation::DuplicateLine(i) => {
            let l = lines[i % n].clone();
            lines.insert(i % n, l);
            lines.join("\n")
        }
        Mutation::SwapLines(a, b) => {
            lines.swap(a % n, b % n);
            lines.join("\n")
        }
        Mutation::RenameKey(i) => {
            // A typo in a field's name: the first `key =` at or after line i gets a letter more.
            // Lines inside a multi-line string are text, not fields.
            let mut inside = false;
            let is_field: Vec<bool> = lines
                .iter()
                .map(|l| {
                    let was = inside;
                    if l.matches("\"\"\"").count() % 2 == 1 {
                        inside = !inside;
                    }
                    !was && l.split_once(" = ").is_some_and(|(key, _)| {
                        !key.is_empty() && key.chars().all(|c| c.is_ascii_lowercase() || c == '_')
                    })
                })
                .collect();
            let start = i % n;
            if let Some(k) = (start..n).chain(0..start).find(|&k| is_field[k]) {
                lines[k] = lines[k].replacen(" = ", "x = ", 1);
            }
            lines.join("\n")
        }
    }
}

proptest! {
    #![proptest_config(Config {
        cases: 600,
        rng_seed: RngSeed::Fixed(18),
        failure_persistence: None,
        ..Config::default()
    })]

    #[test]
    fn mutated_lessons_never_panic_and_errors_name_a_line(
        which in 0..EMBEDDED.len(),
        mutations in prop::collection::vec(mutation(), 1..4),
    ) {
        let (name, text) = EMBEDDED[which];
        let mut mutated = text.to_string();
        for m in &mutations {
            mutated = apply(&mutated, m);
        }
        let lines = mutated.lines().count().max(1);
        match parse_text(&mutated, name, "mutated.toml") {
            Ok(l) => prop_assert!(!l.steps.is_empty()),
            Err(e) => {
                prop_assert_eq!(&e.file, "mutated.toml");
                let shown = e.to_string();
                prop_assert!(shown.starts_with("mutated.toml"), "{}", shown);
                prop_assert!(!e.message.is_empty());
                // A missing [[step]] has no line; everything else points into the file.
                if e.field.as_deref() != Some("step") {
                    let line = e.line;
                    prop_assert!(line.is_some(), "no line: {}", shown);
                    prop_assert!(line.unwrap() >= 1 && line.unwrap() <= lines + 1, "{}", shown);
                }
            }
        }
    }

    #[test]
    fn a_renamed_field_is_always_refused_with_its_line(
        which in 0..EMBEDDED.len(),
        at in any::<usize>(),
    ) {
        let (name, text) = EMBEDDED[which];
        let mutated = apply(text, &Mutation::RenameKey(at));
        prop_assume!(mutated != text);
        let e = parse_text(&mutated, name, "renamed.toml").expect_err("a renamed field is refused");
        let renamed_line = mutated
            .lines()
            .zip(text.lines())
            .position(|(a, b)| a != b)
            .map(|k| k + 1);
        // Either the unknown field is named at its line, or the field it replaced is missing.
        let unknown = e.message.contains("unknown field") && e.line == renamed_line;
        let missing = e.message.contains("missing");
        prop_assert!(unknown || missing, "{}", e);
    }

    #[test]
    fn the_expression_parser_never_panics(text in "[a-z0-9_.()+*/^<>=! \"-]{0,40}") {
        if let Ok(e) = Expr::parse(&text) {
            let _ = e.eval(&lesson::Context::empty());
        }
    }
}
