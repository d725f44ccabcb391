//! The command-line front end: `pounding impact ...`.

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
}

/// Runs the command line; `Ok(())` means exit status 0.
pub fn run(cli: Cli) -> anyhow::Result<()> {
    match cli.command {
        Some(Command::Impact(args)) => impact::run(&args),
        None => {
            // The window is a later front end; until then the default scene runs here.
            let args = impact::ImpactArgs::default();
            impact::run(&args)?;
            println!(
                "\n(The explorer window is not built yet; `pounding impact --help` lists what the command line can do.)"
            );
            Ok(())
        }
    }
}
