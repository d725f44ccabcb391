//! The command-line front end: `pounding impact ...`.

pub mod accuracy;
pub mod bridge;
pub mod bridge_report;
pub mod building_report;
pub mod building_sweep;
pub mod buildings;
pub mod gaps;
pub mod impact;
pub mod lesson;
pub mod report;
pub mod study;
pub mod sweep;

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
    /// A bridge's girders pounding at their joints under a ground motion, uniform or travelling
    /// along the bridge: joint forces, openings against the seats, required gaps
    /// (`bridge-3-span` when given nothing).
    Bridge(bridge::BridgeArgs),
    /// Error against run time: every model on a ladder of steps (FE: meshes) against a much finer
    /// solve, with the observed order; a table, CSV and a work-precision plot.
    Accuracy(accuracy::AccuracyArgs),
    /// Vary one impact setting over a range (solved in parallel): peak force, contact duration
    /// and e against it for each model; with --buildings, one building setting: impacts, max
    /// force, peak sway, ductility demands and hysteretic energy against it.
    Sweep(sweep::SweepArgs),
    /// Rerun one of the paper's figures (or `all`): PNG, SVG and CSV per figure, and the numbers
    /// its claims are checked against (see `pounding study --list`).
    Study(study::StudyArgs),
    /// The gap that avoids pounding for a building pair, record by record (in parallel), against
    /// the ABS and SRSS code rules; a table, CSV, JSON and a plot.
    Gaps(gaps::GapsArgs),
    /// Guided lessons: --list them, --check a lesson file, or write one's worksheet (--handout).
    Lesson(lesson::LessonArgs),
    /// Open the explorer window (what `pounding` with no command does).
    #[cfg(feature = "gui")]
    Window(WindowArgs),
}

#[cfg(feature = "gui")]
#[derive(clap::Args, Debug, Default)]
pub struct WindowArgs {
    /// Scene to open: bar|compare|buildings|bridge|study
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
    /// Save a PNG of the window here before closing (needs --exit-after-frames)
    #[arg(long, requires = "exit_after_frames")]
    pub screenshot: Option<std::path::PathBuf>,
    /// Open a lesson: a shipped one's name (`pounding lesson --list`) or a lesson file
    #[arg(long)]
    pub lesson: Option<String>,
    /// The lesson's step to open, from 1 (default: where the lesson was left)
    #[arg(long, requires = "lesson")]
    pub step: Option<usize>,
    /// Lecture mode: large, high-contrast, only what the lesson step needs (View > Lecture mode)
    #[arg(long)]
    pub lecture: bool,
    /// Teacher mode: a lesson's teacher notes shown (View > Teacher mode); never on a
    /// student's screen otherwise
    #[arg(long)]
    pub teacher: bool,
    /// Measure liveness: move one setting of the buildings or bridge scene every frame, as a
    /// dragged slider does (KEY=FROM:TO, e.g. gap=0.01:0.03), and print on closing how soon the
    /// changes' runs were on screen (needs --exit-after-frames)
    #[arg(long, requires = "exit_after_frames")]
    pub drag: Option<String>,
}

#[cfg(feature = "gui")]
fn window(args: &WindowArgs) -> anyhow::Result<()> {
    let scene = match args.scene.as_deref() {
        None => None,
        Some(name) => Some(pounding::app::SceneKind::from_name(name).ok_or_else(|| {
            anyhow::anyhow!(
                "--scene: unknown scene '{name}': allowed bar|compare|buildings|bridge|study"
            )
        })?),
    };
    if let Some(name) = &args.lesson {
        // A wrong name or step is said here, before a window opens.
        let lesson = pounding::lesson::load(name).map_err(|e| anyhow::anyhow!("--lesson: {e}"))?;
        let n = lesson.steps.len();
        if let Some(k) = args.step
            && !(1..=n).contains(&k)
        {
            anyhow::bail!("--step: {k} is not a step of {name}: allowed 1 to {n}");
        }
    }
    let drag = match &args.drag {
        None => None,
        Some(text) => {
            Some(pounding::app::DragSpec::parse(text).map_err(|e| anyhow::anyhow!("--drag: {e}"))?)
        }
    };
    pounding::app::run(pounding::app::Launch {
        scene,
        preset: args.preset.clone(),
        exit_after_frames: args.exit_after_frames,
        time_s: args.time,
        screenshot: args.screenshot.clone(),
        lesson: args.lesson.clone(),
        lesson_step: args.step,
        lecture: args.lecture,
        teacher: args.teacher,
        drag,
        ..Default::default()
    })
    .map_err(|e| anyhow::anyhow!("the window could not start: {e}"))
}

/// Runs the command line, writing results to `out`; `Ok(())` means exit status 0.
pub fn run(cli: Cli, out: &mut dyn std::io::Write) -> anyhow::Result<()> {
    watch_interrupt();
    let result = dispatch(cli, out);
    if interrupted() {
        anyhow::bail!("cancelled by Ctrl-C; no result was written");
    }
    result
}

/// Where a command's --csv and --json both go: a `-` for --csv beside --json would write two
/// formats into one standard output, which no reader can take apart.
fn check_outputs(command: &Option<Command>) -> anyhow::Result<()> {
    let (csv, json) = match command {
        Some(Command::Impact(a)) => (a.common.csv.as_deref(), a.common.json),
        Some(Command::Buildings(a)) => (a.common.csv.as_deref(), a.common.json),
        Some(Command::Bridge(a)) => (a.common.csv.as_deref(), a.common.json),
        Some(Command::Sweep(a)) => (a.common.csv.as_deref(), a.common.json),
        Some(Command::Gaps(a)) => (a.csv.as_deref(), a.json),
        Some(Command::Accuracy(a)) => (a.csv.as_deref(), a.json),
        _ => (None, false),
    };
    if json && csv_to_stdout(csv) {
        anyhow::bail!(
            "--csv -: standard output already carries the --json report; write the CSV to a file (--csv FILE), or leave out --json"
        );
    }
    Ok(())
}

fn dispatch(cli: Cli, out: &mut dyn std::io::Write) -> anyhow::Result<()> {
    check_outputs(&cli.command)?;
    match cli.command {
        Some(Command::Impact(args)) => impact::run(&args, out),
        Some(Command::Buildings(args)) => buildings::run(&args, out),
        Some(Command::Bridge(args)) => bridge::run(&args, out),
        Some(Command::Accuracy(args)) => accuracy::run(&args, out),
        Some(Command::Sweep(args)) => sweep::run(&args, out),
        Some(Command::Study(args)) => study::run(&args, out),
        Some(Command::Gaps(args)) => gaps::run(&args, out),
        Some(Command::Lesson(args)) => lesson::run(&args, out),
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

/// Options every scene command takes.
#[derive(clap::Args, Debug, Default)]
pub struct SceneArgs {
    /// Preset name (a file stem in assets/presets/) or path to a TOML file [default: the scene's]
    #[arg(long, value_name = "NAME-or-FILE")]
    pub preset: Option<String>,
    /// Override a setting, e.g. --set bar2.length=5 (repeatable; see --list-keys)
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Write the histories as CSV (`-` for standard output)
    #[arg(long, value_name = "FILE")]
    pub csv: Option<std::path::PathBuf>,
    /// Write the force plot as an image (.png or .svg, by the extension)
    #[arg(long, value_name = "FILE")]
    pub plot: Option<std::path::PathBuf>,
    /// Pixel size of a PNG --plot, e.g. 3000x1800 [default: the scene's]
    #[arg(long, value_name = "WxH", value_parser = parse_plot_size, allow_hyphen_values = true)]
    pub plot_size: Option<(u32, u32)>,
    /// Text and line size of --plot relative to the default (0.25 to 8) [default: 1]
    #[arg(long, value_name = "X", value_parser = parse_plot_scale, allow_hyphen_values = true)]
    pub plot_scale: Option<f64>,
    /// Print one JSON object instead of the summary
    #[arg(long)]
    pub json: bool,
    /// Show no progress bar on standard error (it shows only on a terminal, and not with --json)
    #[arg(long)]
    pub quiet: bool,
    /// List the keys --set accepts, and exit
    #[arg(long)]
    pub list_keys: bool,
    /// List the shipped presets, and exit
    #[arg(long)]
    pub list_presets: bool,
}

impl SceneArgs {
    /// Writes the plot `make` builds to --plot, if given, at --plot-size (else `default_size`)
    /// and --plot-scale.
    pub(crate) fn write_plot(
        &self,
        default_size: (u32, u32),
        make: impl FnOnce() -> pounding::export::plot::LinePlot,
    ) -> anyhow::Result<()> {
        let Some(path) = &self.plot else {
            return Ok(());
        };
        let plot = pounding::export::plot::LinePlot {
            size: self.plot_size.unwrap_or(default_size),
            scale: self.plot_scale.unwrap_or(1.0),
            ..make()
        };
        plot.write(path).map_err(|e| anyhow::anyhow!("--plot: {e}"))
    }
}

fn parse_plot_size(text: &str) -> Result<(u32, u32), String> {
    let bad = || format!("'{text}': expected WIDTHxHEIGHT in pixels, each 100 to 10000");
    let (w, h) = text.split_once(['x', 'X']).ok_or_else(bad)?;
    let (w, h): (u32, u32) = (
        w.trim().parse().map_err(|_| bad())?,
        h.trim().parse().map_err(|_| bad())?,
    );
    if (100..=10_000).contains(&w) && (100..=10_000).contains(&h) {
        Ok((w, h))
    } else {
        Err(bad())
    }
}

fn parse_plot_scale(text: &str) -> Result<f64, String> {
    parse_number_in(text, 0.25, 8.0)
}

/// A number from `lo` to `hi`, refused with that range (a negative one too: the flags that take
/// these let a leading '-' through to here rather than to the argument parser).
pub(crate) fn parse_number_in(text: &str, lo: f64, hi: f64) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(v) if (lo..=hi).contains(&v) => Ok(v),
        _ => Err(format!("'{text}': expected a number from {lo} to {hi}")),
    }
}

/// A whole number from `lo` to `hi`, refused with that range.
pub(crate) fn parse_whole_in(text: &str, lo: usize, hi: usize) -> Result<usize, String> {
    match text.trim().parse::<usize>() {
        Ok(v) if (lo..=hi).contains(&v) => Ok(v),
        _ => Err(format!(
            "'{text}': expected a whole number from {lo} to {hi}"
        )),
    }
}

/// The `--set` assignments a run does not use, each with why (`unused` says it per key).
pub(crate) fn unused_settings(
    sets: &[String],
    unused: impl Fn(&str) -> Option<String>,
) -> Vec<String> {
    sets.iter()
        .filter_map(|a| {
            let key = a.split_once('=').map_or(a.as_str(), |(k, _)| k).trim();
            unused(key).map(|why| format!("--set {}: not used: {why}", a.trim()))
        })
        .collect()
}

/// Writes the settings a run did not use under the text summary.
pub(crate) fn write_unused(out: &mut dyn std::io::Write, unused: &[String]) -> anyhow::Result<()> {
    if !unused.is_empty() {
        writeln!(out, "settings not used")?;
        for w in unused {
            writeln!(out, "  - {w}")?;
        }
    }
    Ok(())
}

/// A preset that could not be loaded, said once as "preset NAME: ..." whether it is a shipped
/// preset (whose error already names it so) or a file.
pub(crate) fn preset_error(e: pounding::io::preset::PresetError) -> anyhow::Error {
    if e.file.starts_with("preset ") {
        anyhow::anyhow!("{e}")
    } else {
        anyhow::anyhow!("preset {e}")
    }
}

/// Writes one `name  description` line per entry (the --list-keys and --list-presets output).
pub(crate) fn list<'a>(
    out: &mut dyn std::io::Write,
    width: usize,
    rows: impl IntoIterator<Item = (&'a str, String)>,
) -> anyhow::Result<()> {
    for (name, what) in rows {
        writeln!(out, "{name:width$} {what}")?;
    }
    Ok(())
}

/// The shipped presets of one scene with their descriptions.
pub(crate) fn list_presets(out: &mut dyn std::io::Write, scene: &str) -> anyhow::Result<()> {
    use pounding::io::preset::{EMBEDDED, description, scene as scene_of};
    list(
        out,
        16,
        EMBEDDED
            .iter()
            .filter(|(_, t)| scene_of(t) == scene)
            .map(|(n, t)| (*n, description(t).unwrap_or_default())),
    )
}

/// Whether --csv is `-`: the CSV goes to standard output, so the summary must not.
pub(crate) fn csv_to_stdout(csv: Option<&std::path::Path>) -> bool {
    csv.is_some_and(|p| p.as_os_str() == "-")
}

/// Writes CSV to a file, or to `out` for `-`, saying which path failed and why.
pub(crate) fn write_csv(
    out: &mut dyn std::io::Write,
    path: &std::path::Path,
    write: impl Fn(&mut dyn std::io::Write) -> std::io::Result<()>,
) -> anyhow::Result<()> {
    use anyhow::Context;
    if csv_to_stdout(Some(path)) {
        return Ok(write(out)?);
    }
    if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
        std::fs::create_dir_all(parent)
            .with_context(|| format!("--csv: cannot create the folder of {}", path.display()))?;
    }
    let file = std::fs::File::create(path)
        .with_context(|| format!("--csv: cannot create {}", path.display()))?;
    let mut w = std::io::BufWriter::new(file);
    write(&mut w)
        .and_then(|_| std::io::Write::flush(&mut w))
        .with_context(|| format!("--csv: cannot write {}", path.display()))
}

/// Whether an error is only a closed output pipe (`pounding ... | head`), which ends the
/// program quietly like any Unix filter.
pub fn is_broken_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>()
            .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
    })
}

/// Runs `work` while a progress bar on standard error shows what `progress` counts (hidden
/// with `quiet`, and until the work has planned its solves, so it never shows an empty 0/0 bar).
pub(crate) fn with_bar<T: Send>(
    name: &str,
    progress: &pounding::study::Control,
    quiet: bool,
    work: impl FnOnce() -> T + Send,
) -> T {
    let bar = indicatif::ProgressBar::hidden();
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "{prefix:>20} [{bar:40}] {pos}/{len} solves, {elapsed}",
        )
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
        .progress_chars("=> "),
    );
    bar.set_prefix(name.to_string());
    let _polling = Polling::start();
    let out = std::thread::scope(|scope| {
        let job = scope.spawn(work);
        let mut drawn = quiet;
        while !job.is_finished() {
            if interrupted() {
                progress.cancel();
            }
            if !drawn && progress.total() > 0 {
                bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
                drawn = true;
            }
            bar.set_length(progress.total() as u64);
            bar.set_position(progress.done() as u64);
            std::thread::sleep(std::time::Duration::from_millis(20));
        }
        job.join()
    });
    bar.finish_and_clear();
    match out {
        Ok(v) => v,
        Err(panic) => std::panic::resume_unwind(panic),
    }
}

/// Set by Ctrl-C: long runs poll it and stop at their next look (their cancel flag), so the
/// program ends with a message and a non-zero status instead of dying mid-write.
static INTERRUPTED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// How many runs are polling [`INTERRUPTED`] now (inside [`with_bar`] or [`with_control`]).
static POLLING: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);

/// Marks a run that polls [`interrupted`] while it lives.
struct Polling;

impl Polling {
    fn start() -> Self {
        POLLING.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        Polling
    }
}

impl Drop for Polling {
    fn drop(&mut self) {
        POLLING.fetch_sub(1, std::sync::atomic::Ordering::Relaxed);
    }
}

/// Routes SIGINT to [`INTERRUPTED`] while a run polls it, once per process; otherwise Ctrl-C
/// ends the process at once.
fn watch_interrupt() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        // Without a handler (one already set by an embedding program) Ctrl-C takes its
        // default action and ends the process, which is still a stop.
        let _ = ctrlc::set_handler(|| {
            if POLLING.load(std::sync::atomic::Ordering::Relaxed) > 0 {
                INTERRUPTED.store(true, std::sync::atomic::Ordering::Relaxed);
            } else {
                // Nothing is watching for the flag (a window, a short command): stop at once,
                // as an unhandled Ctrl-C would.
                std::process::exit(130);
            }
        });
    });
}

/// Whether Ctrl-C was pressed.
pub(crate) fn interrupted() -> bool {
    INTERRUPTED.load(std::sync::atomic::Ordering::Relaxed)
}

/// Runs one solve with a percentage bar on standard error (hidden with `quiet`, and off a
/// terminal); Ctrl-C cancels it through its [`Control`].
pub(crate) fn with_control<T: Send>(
    name: &str,
    quiet: bool,
    work: impl FnOnce(&pounding::model::control::Control) -> T + Send,
) -> T {
    let control = pounding::model::control::Control::new();
    let bar = if quiet {
        indicatif::ProgressBar::hidden()
    } else {
        indicatif::ProgressBar::with_draw_target(
            Some(1000),
            indicatif::ProgressDrawTarget::stderr(),
        )
    };
    bar.set_style(
        indicatif::ProgressStyle::with_template("{prefix:>20} [{bar:40}] {percent}%, {elapsed}")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
            .progress_chars("=> "),
    );
    bar.set_prefix(name.to_string());
    let _polling = Polling::start();
    let out = std::thread::scope(|scope| {
        // The job says when it ends, so the answer does not wait for the bar's next tick.
        let control = &control;
        pounding::model::control::spawn_told(scope, move || work(control)).wait_looking(
            std::time::Duration::from_millis(20),
            || {
                if interrupted() {
                    control.cancel();
                }
                bar.set_position((control.fraction().clamp(0.0, 1.0) * 1000.0) as u64);
            },
        )
    });
    bar.finish_and_clear();
    match out {
        Ok(v) => v,
        Err(panic) => std::panic::resume_unwind(panic),
    }
}
