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
    /// Open the explorer window (what `pounding` with no command does).
    #[cfg(feature = "gui")]
    Window(WindowArgs),
}

#[cfg(feature = "gui")]
#[derive(clap::Args, Debug, Default)]
pub struct WindowArgs {
    /// Scene to open: bar|compare|buildings
    #[arg(long)]
    pub scene: Option<String>,
    /// Impact preset to open with (instead of the last session's scene)
    #[arg(long)]
    pub preset: Option<String>,
    /// Start paused at this animation time [s]
    #[arg(long)]
    pub time: Option<f64>,
    /// Close the window after this many frames (smoke tests, screenshots)
    #[arg(long)]
    pub exit_after_frames: Option<u64>,
}

#[cfg(feature = "gui")]
fn window(args: &WindowArgs) -> anyhow::Result<()> {
    let scene = match args.scene.as_deref() {
        None => None,
        Some(name) => Some(crate::app::SceneKind::from_name(name).ok_or_else(|| {
            anyhow::anyhow!("--scene: unknown scene '{name}': allowed bar|compare|buildings")
        })?),
    };
    crate::app::run(crate::app::Launch {
        scene,
        preset: args.preset.clone(),
        exit_after_frames: args.exit_after_frames,
        time_s: args.time,
    })
}

/// Runs the command line, writing results to `out`; `Ok(())` means exit status 0.
pub fn run(cli: Cli, out: &mut dyn std::io::Write) -> anyhow::Result<()> {
    match cli.command {
        Some(Command::Impact(args)) => impact::run(&args, out),
        Some(Command::Buildings(args)) => buildings::run(&args, out),
        #[cfg(feature = "gui")]
        Some(Command::Window(args)) => window(&args),
        #[cfg(feature = "gui")]
        None => window(&WindowArgs::default()),
        #[cfg(not(feature = "gui"))]
        None => {
            // Built without the window: the default scene runs on the terminal.
            impact::run(&impact::ImpactArgs::default(), out)?;
            writeln!(
                out,
                "\n(Built without the window; `pounding impact --help` lists what the command line can do.)"
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
