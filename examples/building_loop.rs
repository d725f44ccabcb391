//! Repeats one building run, for instruction counts a benchmark cannot give:
//!
//! ```text
//! cargo build --release --example building_loop
//! valgrind --tool=callgrind target/release/examples/building_loop paper-buildings sears solve 1
//! ```
//!
//! Arguments: a building preset, a contact element, the stage (`solve`: the run with its
//! histories; `estimate`: the error estimate's refined run; `none`: the run without contact;
//! `all`: the three, as `pounding buildings` makes them), the number of repeats, and optional
//! `KEY=VALUE` settings (as `--set`). It prints the mean wall time per repeat to stderr, and
//! the run's step counts.

use pounding::io::building_settings::BuildingSetup;
use pounding::io::preset;
use pounding::model::building::{BuildingScenario, ContactModel, estimate_error, solve};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage =
        "usage: building_loop PRESET CONTACT solve|estimate|none|all REPEATS [KEY=VALUE ...]";
    let (Some(preset_name), Some(contact), Some(stage), Some(Ok(repeats))) = (
        args.get(1),
        args.get(2).and_then(|c| ContactModel::from_name(c)),
        args.get(3)
            .filter(|s| ["solve", "estimate", "none", "all"].contains(&s.as_str())),
        args.get(4).map(|n| n.parse::<usize>()),
    ) else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let mut setup: BuildingSetup = match preset::load_for(preset_name, "buildings") {
        Ok(s) => s,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    for a in &args[5..] {
        if let Err(e) = setup.apply_assignment(a) {
            eprintln!("{e}");
            std::process::exit(2);
        }
    }
    setup.scenario.contact = contact;
    let motion = match pounding::io::motion::load(&setup.motion) {
        Ok(m) => m,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    let sc = &setup.scenario;
    let start = std::time::Instant::now();
    let mut steps = (0, 0);
    for _ in 0..repeats {
        let r = match stage.as_str() {
            "solve" => solve(sc, &motion),
            "estimate" => solve(sc, &motion).and_then(|r| {
                pounding::model::building::estimate::companion_run(
                    sc,
                    &motion,
                    r.stats.fine_step_s,
                    pounding::model::control::Control::never(),
                )
            }),
            "none" => solve(
                &BuildingScenario {
                    contact: ContactModel::None,
                    ..sc.clone()
                },
                &motion,
            ),
            _ => solve(sc, &motion).and_then(|r| {
                estimate_error(sc, &motion, &r)?;
                solve(
                    &BuildingScenario {
                        contact: ContactModel::None,
                        ..sc.clone()
                    },
                    &motion,
                )?;
                Ok(r)
            }),
        };
        match r {
            Ok(r) => steps = (r.stats.steps, r.stats.contact_steps),
            Err(e) => {
                eprintln!("{e}");
                std::process::exit(1);
            }
        }
    }
    eprintln!(
        "{preset_name} {} {stage}: {:.3} ms per run, {} steps ({} in contact)",
        contact.name(),
        start.elapsed().as_secs_f64() * 1e3 / repeats.max(1) as f64,
        steps.0,
        steps.1
    );
}
