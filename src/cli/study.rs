//! `pounding study NAME`: one of the paper's figures (or `all`) rerun, written as PNG, SVG and CSV,
//! with the numbers its claims are checked against.

use anyhow::{Context as _, anyhow, bail};
use clap::Args;
use pounding::export::plot::LinePlot;
use pounding::study::{self, Context, Control, Finding, Study};
use serde::Serialize;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::Instant;

#[derive(Args, Debug, Default)]
pub struct StudyArgs {
    /// The study to run, or `all` (see --list)
    #[arg(value_name = "NAME", required_unless_present = "list")]
    pub name: Option<String>,
    /// List the built-in studies, and exit
    #[arg(long)]
    pub list: bool,
    /// Folder for the figures (created if missing)
    #[arg(long, value_name = "DIR", default_value = "pounding-studies")]
    pub out: PathBuf,
    /// What to write per figure: png|svg|csv (repeatable) [default: all three]
    #[arg(long = "format", value_name = "FMT")]
    pub formats: Vec<String>,
    /// Ground motion for the building studies: a built-in record (elcentro-1940), a PEER .AT2 or
    /// text file, or synthetic [default: the preset's, 8 s of El Centro 1940 as in the paper]
    #[arg(long, value_name = "FILE")]
    pub motion: Option<PathBuf>,
    /// Override a building setting for the building studies (see `pounding buildings --list-keys`)
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Pixel size of the PNGs, e.g. 3000x1800 [default: 1200x700]
    #[arg(long, value_name = "WxH", value_parser = super::parse_plot_size, allow_hyphen_values = true)]
    pub plot_size: Option<(u32, u32)>,
    /// Text and line size relative to the default (0.25 to 8) [default: 1]
    #[arg(long, value_name = "X", value_parser = super::parse_plot_scale, allow_hyphen_values = true)]
    pub plot_scale: Option<f64>,
    /// Print one JSON object instead of the summary
    #[arg(long)]
    pub json: bool,
    /// No progress bar
    #[arg(long)]
    pub quiet: bool,
}

const FORMATS: [&str; 3] = ["png", "svg", "csv"];

#[derive(Serialize)]
struct StudyReport {
    name: &'static str,
    paper: &'static str,
    about: &'static str,
    files: Vec<PathBuf>,
    findings: Vec<Finding>,
    notes: Vec<String>,
    solves: usize,
    wall_time_s: f64,
}

#[derive(Serialize)]
struct Report {
    studies: Vec<StudyReport>,
    solves: usize,
    wall_time_s: f64,
    threads: usize,
}

fn formats(args: &StudyArgs) -> anyhow::Result<Vec<&str>> {
    if args.formats.is_empty() {
        return Ok(FORMATS.to_vec());
    }
    args.formats
        .iter()
        .map(|f| {
            FORMATS
                .iter()
                .find(|k| k.eq_ignore_ascii_case(f))
                .copied()
                .ok_or_else(|| anyhow!("--format: unknown format '{f}': allowed png|svg|csv"))
        })
        .collect()
}

fn list(out: &mut dyn Write) -> anyhow::Result<()> {
    for s in study::studies() {
        writeln!(out, "{:20} {:22} {}", s.name, s.paper, s.about)?;
    }
    writeln!(out, "{:20} {:22} every study above", "all", "")?;
    Ok(())
}

pub fn run(args: &StudyArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if args.list {
        return list(out);
    }
    let name = args.name.as_deref().unwrap_or_default();
    let chosen: Vec<&Study> = if name == "all" {
        study::studies()
    } else {
        let names: Vec<&str> = study::studies().iter().map(|s| s.name).collect();
        vec![study::find(name).ok_or_else(|| {
            anyhow!(
                "unknown study '{name}': allowed {} or all (see `pounding study --list`)",
                names.join(", ")
            )
        })?]
    };
    let formats = formats(args)?;
    let needs_buildings = chosen.iter().any(|s| s.buildings);
    if !needs_buildings && (!args.set.is_empty() || args.motion.is_some()) {
        bail!(
            "--set and --motion apply to the building studies (fig12-displacements, fig13-forces) only"
        );
    }
    let (buildings, motion) = if needs_buildings {
        let (setup, _) = super::buildings::setup(None, &args.set, args.motion.as_deref())?;
        let motion = super::buildings::load_motion(&setup)?;
        (setup.scenario, Some(motion))
    } else {
        (pounding::model::building::BuildingScenario::paper(), None)
    };
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("--out: cannot create {}", args.out.display()))?;
    let start = Instant::now();
    let mut reports = Vec::new();
    let mut solves = 0;
    for s in chosen {
        let progress = Control::new();
        let ctx = Context {
            progress: &progress,
            motion: motion.as_ref(),
            buildings: buildings.clone(),
        };
        let (output, wall_time_s) = super::with_bar(s.name, &progress, args.quiet, || {
            let t = Instant::now();
            ((s.run)(&ctx), t.elapsed().as_secs_f64())
        });
        let output = output.with_context(|| format!("study {}", s.name))?;
        let mut notes = vec![];
        if s.buildings {
            notes.extend(
                motion
                    .as_ref()
                    .map(|m| format!("ground motion: {}", m.name)),
            );
            if motion
                .as_ref()
                .is_some_and(|m| !m.name.contains("El Centro 1940"))
            {
                notes.push(
                    "the paper used 8 s of El Centro 1940: --motion elcentro-1940 gives it".into(),
                );
            }
        }
        notes.extend(output.notes);
        let mut files = Vec::new();
        for fig in &output.figures {
            for f in &formats {
                let path = args.out.join(format!("{}.{f}", fig.stem));
                write_figure(&fig.plot, &fig.csv(), &path, f, args)?;
                files.push(path);
            }
        }
        solves += progress.done();
        reports.push(StudyReport {
            name: s.name,
            paper: s.paper,
            about: s.about,
            files,
            findings: output.findings,
            notes,
            solves: progress.done(),
            wall_time_s,
        });
    }
    let report = Report {
        studies: reports,
        solves,
        wall_time_s: start.elapsed().as_secs_f64(),
        threads: rayon::current_num_threads(),
    };
    if args.json {
        serde_json::to_writer_pretty(&mut *out, &report)?;
        writeln!(out)?;
    } else {
        summary(&report, out)?;
    }
    Ok(())
}

/// Runs `work` while a progress bar on standard error follows `progress` (drawn only on a
/// terminal).
fn write_figure(
    plot: &LinePlot,
    csv: &str,
    path: &Path,
    format: &str,
    args: &StudyArgs,
) -> anyhow::Result<()> {
    if format == "csv" {
        return std::fs::write(path, csv)
            .with_context(|| format!("cannot write {}", path.display()));
    }
    let sized = LinePlot {
        size: args.plot_size.unwrap_or((1200, 700)),
        scale: args.plot_scale.unwrap_or(1.0),
        ..plot.clone()
    };
    Ok(sized.write(path)?)
}

fn summary(r: &Report, out: &mut dyn Write) -> anyhow::Result<()> {
    for s in &r.studies {
        writeln!(out, "{}: {} — {}", s.name, s.paper, s.about)?;
        for f in &s.findings {
            let value = if f.value.fract() == 0.0 && f.value.abs() < 1e6 {
                format!("{}", f.value)
            } else {
                format!("{:.5e}", f.value)
            };
            writeln!(out, "  {:64} {value} {}", f.what, f.unit)?;
        }
        for n in &s.notes {
            writeln!(out, "  note: {n}")?;
        }
        writeln!(
            out,
            "  {} solves in {:.3} s; wrote {} files to {}",
            s.solves,
            s.wall_time_s,
            s.files.len(),
            s.files
                .first()
                .and_then(|p| p.parent())
                .map_or("-".into(), |p| p.display().to_string())
        )?;
    }
    super::sweep::solves_line(out, r.solves, r.wall_time_s, r.threads)
}
