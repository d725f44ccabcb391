//! The command-line front end: `pounding impact ...`.

pub mod building_report;
pub mod buildings;
pub mod impact;
pub mod report;

use clap::{Parser, Subcommand};

#[derive(Parser, Debug)]
#[command(
    name = "pounding",
    version,
    about = "Pounding Lab: the Sears impact model and its peers, headless"
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Solve one impact of two bars (the paper's base case when given nothing).
    Impact(impact::ImpactArgs),
    /// Two buildings under a ground motion, pounding (the paper's Section 4 when given nothing).
    Buildings(buildings::BuildingArgs),
}

/// Runs the command line, writing results to `out`; `Ok(())` means exit status 0.
pub fn run(cli: Cli, out: &mut dyn std::io::Write) -> anyhow::Result<()> {
    match cli.command {
        Some(Command::Impact(args)) => impact::run(&args, out),
        Some(Command::Buildings(args)) => buildings::run(&args, out),
        None => {
            // The window is a later front end; until then the default scene runs here.
            impact::run(&impact::ImpactArgs::default(), out)?;
            writeln!(
                out,
                "\n(The explorer window is not built yet; `pounding impact --help` lists what the command line can do.)"
            )?;
            Ok(())
        }
    }
}

/// Whether an error is only a closed output pipe (`pounding ... | head`), which ends the
/// program quietly like any Unix filter.
pub fn is_broken_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>()
            .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
    })
}
