//! Repeats one bridge run, for instruction counts a benchmark cannot give:
//!
//! ```text
//! cargo build --release --example bridge_loop
//! valgrind --tool=callgrind target/release/examples/bridge_loop sears 3 all 1
//! valgrind --tool=callgrind target/release/examples/bridge_loop sears 3 solve 1
//! ```
//!
//! Arguments, all optional and in this order: the contact element (`sears`, the preset's, or
//! `linear`, or any `--contact` name), the number of spans (3, the preset's), the stage (`solve`:
//! one run with its histories; `estimate`: the error estimate's run with half the step (a
//! summary: no histories); `none`:
//! the run without contact; `all`: the three, the whole work of `pounding bridge --json` but
//! for reading the record and writing the report), the number of repeats (1), then `KEY=VALUE`
//! settings (as `--set`). The scene is the `bridge-3-span` preset on its record (the first 8 s
//! of El Centro 1940).
//!
//! With another number of spans, every per-span list of the preset that has neither one value
//! nor one for every span is repeated cyclically (pier.stiffness 8e7, 2e8, 4e7, 8e7, ...), and
//! the joint gaps keep the abutments' at the ends and repeat the inner ones between; the
//! settings are printed, as `--set` arguments that give `pounding bridge` the same scene.
//!
//! It prints the mean wall time per repeat to stderr, and the run's impacts, steps and steps
//! in contact.

use pounding::io::bridge_settings::{BRIDGE, BridgeSetup};
use pounding::io::preset;
use pounding::io::settings::SettingValue;
use pounding::model::bridge::{
    BridgeScenario, estimate, estimate_error, solve, solve_summary, solve_with,
};
use pounding::model::building::ContactModel;
use pounding::model::control::Control;
use pounding::model::settings::{BRIDGE_SETTINGS, Kind};

const PRESET: &str = "bridge-3-span";
const STAGES: [&str; 4] = ["solve", "estimate", "none", "all"];

/// The `KEY=VALUE` settings that make `setup` a bridge of `spans` spans: the count, then every
/// per-span list whose length fits neither, repeated cyclically (a joint list keeps its ends).
fn span_assignments(setup: &BridgeSetup, spans: usize) -> Vec<String> {
    let mut out = vec![format!("bridge.spans={spans}")];
    for s in BRIDGE_SETTINGS {
        if !matches!(s.kind, Kind::List { .. }) {
            continue;
        }
        let Some((_, SettingValue::List(v))) = BRIDGE.shown(setup, s.key) else {
            continue;
        };
        let joints = s.key == "joint.gaps";
        let count = if joints { spans + 1 } else { spans };
        if v.len() <= 1 || v.len() == count {
            continue;
        }
        let values: Vec<f64> = if joints && v.len() > 2 {
            let inner = &v[1..v.len() - 1];
            std::iter::once(v[0])
                .chain((0..spans - 1).map(|i| inner[i % inner.len()]))
                .chain(std::iter::once(v[v.len() - 1]))
                .collect()
        } else {
            (0..count).map(|i| v[i % v.len()]).collect()
        };
        let text: Vec<String> = values.iter().map(|x| x.to_string()).collect();
        out.push(format!("{}={}", s.key, text.join(",")));
    }
    out
}

fn fail(e: impl std::fmt::Display, code: i32) -> ! {
    eprintln!("{e}");
    std::process::exit(code);
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage =
        "usage: bridge_loop [CONTACT [SPANS [solve|estimate|none|all [REPEATS [KEY=VALUE ...]]]]]";
    let contact = args.get(1).map(|c| {
        ContactModel::from_name(c).unwrap_or_else(|| {
            fail(
                format!("{usage}\nCONTACT: {}", ContactModel::NAMES.join("|")),
                2,
            )
        })
    });
    let spans = args
        .get(2)
        .map(|n| n.parse::<usize>().unwrap_or_else(|_| fail(usage, 2)));
    let stage = args.get(3).map_or("all", |s| {
        STAGES
            .into_iter()
            .find(|x| x == s)
            .unwrap_or_else(|| fail(usage, 2))
    });
    let repeats = args
        .get(4)
        .map_or(1, |n| n.parse::<usize>().unwrap_or_else(|_| fail(usage, 2)));

    let mut setup: BridgeSetup = preset::load_for(PRESET, "bridge").unwrap_or_else(|e| fail(e, 2));
    let mut sets = match spans {
        Some(n) if n != setup.scenario.spans => span_assignments(&setup, n),
        _ => Vec::new(),
    };
    sets.extend(args.iter().skip(5).cloned());
    for a in &sets {
        setup.apply_assignment(a).unwrap_or_else(|e| fail(e, 2));
    }
    if let Some(c) = contact {
        setup.scenario.contact = c;
    }
    setup.scenario.validate().unwrap_or_else(|e| fail(e, 2));
    let motion = pounding::io::motion::load(&setup.motion).unwrap_or_else(|e| fail(e, 2));
    let sc = &setup.scenario;
    let free = BridgeScenario {
        contact: ContactModel::None,
        ..sc.clone()
    };
    let control = Control::never();

    let start = std::time::Instant::now();
    // The stage's runs of the last repeat, named.
    let mut last = Vec::new();
    for _ in 0..repeats {
        let runs = match stage {
            "solve" => solve(sc, &motion).map(|r| vec![("solve", r)]),
            "estimate" => solve_summary(&estimate::refined(sc, 2.0), &motion, control)
                .map(|r| vec![("estimate", r)]),
            "none" => solve(&free, &motion).map(|r| vec![("none", r)]),
            // As `pounding bridge`: the run, its error estimate (a failed one is left out of the
            // report, not an error) and the run without contact.
            _ => solve_with(sc, &motion, control).and_then(|r| {
                let e = estimate_error(sc, &motion, &r, control).ok();
                std::hint::black_box(e);
                let baseline = solve_with(&free, &motion, control)?;
                Ok(vec![("run", r), ("baseline (none)", baseline)])
            }),
        };
        last = runs.unwrap_or_else(|e| fail(e, 1));
    }
    let elapsed = start.elapsed().as_secs_f64();

    let sets: Vec<String> = sets.iter().map(|a| format!("--set {a}")).collect();
    eprintln!(
        "{PRESET} {} spans={} {stage} {}",
        sc.contact.name(),
        sc.spans,
        sets.join(" ")
    );
    eprintln!(
        "{:.3} ms per repeat ({repeats} repeats)",
        elapsed * 1e3 / repeats.max(1) as f64
    );
    for (name, r) in &last {
        let s = &r.stats;
        println!(
            "{name}: {} impacts, {} steps of {:.3e} s, {} in contact ({:.2} %), max force {:.4e} N",
            r.impacts.len(),
            s.steps,
            s.step_s,
            s.contact_steps,
            100.0 * s.contact_steps as f64 / s.steps.max(1) as f64,
            r.max_pounding_force_n
        );
    }
    if stage == "all" {
        println!("(and the error estimate's run with half the step: stage `estimate`)");
    }
}
