//! Repeats one base-case Sears solve, for instruction counts a benchmark cannot give:
//!
//! ```text
//! cargo build --release --example solve_loop
//! valgrind --tool=callgrind target/release/examples/solve_loop end summary 200
//! ```
//!
//! divides callgrind's total by 200 solves and by the solve's steps (`pounding impact --json`
//! reports them). Arguments: the reading (paper, collocated, end), `summary` or `full`, and the
//! number of solves. It prints the mean wall time per solve to stderr.

use pounding::model::impact::{ModelKind, Workspace, solve, summary_with};
use pounding::model::scenario::{ImpactScenario, Reading};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage = "usage: solve_loop paper|collocated|end summary|full SOLVES";
    let (Some(reading), Some(mode), Some(Ok(solves))) = (
        args.get(1)
            .and_then(|a| Reading::ALL.into_iter().find(|r| r.name() == a)),
        args.get(2).filter(|m| *m == "summary" || *m == "full"),
        args.get(3).map(|n| n.parse::<usize>()),
    ) else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let sc = ImpactScenario {
        reading,
        ..Default::default()
    };
    let mut ws = Workspace::default();
    let mut checksum = 0.0;
    let start = std::time::Instant::now();
    for _ in 0..solves {
        let impulse = if mode == "summary" {
            summary_with(ModelKind::Sears, &sc, &mut ws).map(|s| s.impulse_ns)
        } else {
            solve(ModelKind::Sears, &sc).map(|r| r.impulse_ns)
        };
        match impulse {
            Ok(j) => checksum += j,
            Err(e) => {
                eprintln!("{e}");
                std::process::exit(1);
            }
        }
    }
    let per_solve = start.elapsed().as_secs_f64() / solves.max(1) as f64;
    eprintln!(
        "{} {mode}: {:.2} us per solve (checksum {checksum})",
        reading.name(),
        per_solve * 1e6
    );
}
