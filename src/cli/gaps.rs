//! `pounding gaps`: the gap that avoids pounding for a building pair, record by record, against
//! the ABS and SRSS code rules.

use anyhow::{Context, anyhow, bail};
use clap::Args;
use pounding::export::plot::{LinePlot, Series};
use pounding::io::building_settings::BuildingSetup;
use pounding::io::motion::{MotionSpec, load};
use pounding::model::motion::GroundMotion;
use pounding::study::Control;
use pounding::study::gaps::{RecordGaps, record_gaps};
use serde::Serialize;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::Instant;

#[derive(Args, Debug, Default)]
pub struct GapsArgs {
    /// The building pair: a building preset (paper-buildings, mdof-3-5, mdof-unequal) or file
    #[arg(long, value_name = "NAME-or-FILE")]
    pub preset: Option<String>,
    /// Override a building setting (see `pounding buildings --list-keys`)
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// A record (repeatable): a built-in name (elcentro-1940), synthetic or synthetic:SEED, or
    /// a .AT2 or text file [default: the preset's record]
    #[arg(long = "motion", value_name = "RECORD")]
    pub motions: Vec<String>,
    /// Every record file in a folder (.AT2, .txt, .dat, .csv), in name order
    #[arg(long, value_name = "DIR")]
    pub motion_dir: Option<PathBuf>,
    /// Write one row per record as CSV (`-` for standard output)
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
    /// Plot the minimum gap, ABS and SRSS for each record (.png or .svg)
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
    /// Pixel size of a PNG --plot, e.g. 3000x1800 [default: 1200x600]
    #[arg(long, value_name = "WxH", value_parser = super::parse_plot_size, allow_hyphen_values = true)]
    pub plot_size: Option<(u32, u32)>,
    /// Text and line size of --plot relative to the default (0.25 to 8) [default: 1]
    #[arg(long, value_name = "X", value_parser = super::parse_plot_scale, allow_hyphen_values = true)]
    pub plot_scale: Option<f64>,
    /// Print one JSON object instead of the table
    #[arg(long)]
    pub json: bool,
    /// No progress bar
    #[arg(long)]
    pub quiet: bool,
}

#[derive(Serialize)]
struct LevelJson {
    min_gap_m: f64,
    abs_m: f64,
    srss_m: f64,
}

#[derive(Serialize)]
struct RecordJson {
    record: String,
    duration_s: Option<f64>,
    pga_g: Option<f64>,
    /// The smallest gap that avoids all contact [m].
    min_gap_m: Option<f64>,
    /// The level that sets it (an index into the buildings' levels).
    level: Option<usize>,
    abs_m: Option<f64>,
    srss_m: Option<f64>,
    abs_ratio: Option<f64>,
    srss_ratio: Option<f64>,
    levels: Vec<LevelJson>,
    error: Option<String>,
}

#[derive(Serialize)]
struct Report {
    preset: String,
    storeys_left: usize,
    storeys_right: usize,
    levels: usize,
    records: Vec<RecordJson>,
    solves: usize,
    wall_time_s: f64,
    threads: usize,
}

/// The records a run asks for: each --motion, then the folder's files; the preset's alone when
/// neither is given. What the preset says of units, duration and scale applies to each.
fn specs(args: &GapsArgs, base: &MotionSpec) -> anyhow::Result<Vec<MotionSpec>> {
    let mut out = Vec::new();
    for m in &args.motions {
        let mut spec = base.clone();
        spec.set_source(m).map_err(|e| anyhow!("--motion {e}"))?;
        out.push(spec);
    }
    if let Some(dir) = &args.motion_dir {
        let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
            .with_context(|| format!("--motion-dir: cannot read {}", dir.display()))?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| {
                p.is_file()
                    && ["at2", "txt", "dat", "csv"]
                        .contains(&pounding::export::extension(p).as_str())
            })
            .collect();
        files.sort();
        if files.is_empty() {
            bail!(
                "--motion-dir: no record files (.AT2, .txt, .dat, .csv) in {}",
                dir.display()
            );
        }
        for f in files {
            out.push(MotionSpec {
                file: Some(f.display().to_string()),
                ..base.clone()
            });
        }
    }
    if out.is_empty() {
        out.push(base.clone());
    }
    Ok(out)
}

pub fn run(args: &GapsArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let (setup, preset_name): (BuildingSetup, &str) =
        super::buildings::setup(args.preset.as_deref(), &args.set, None)?;
    setup
        .scenario
        .validate()
        .map_err(|e| anyhow!("--set {e}"))?;
    let motions: Vec<(String, Result<GroundMotion, String>)> = specs(args, &setup.motion)?
        .iter()
        .map(|s| {
            let name = s
                .file
                .clone()
                .unwrap_or_else(|| format!("synthetic (seed {})", s.synthetic.seed));
            (name, load(s).map_err(|e| e.to_string()))
        })
        .collect();
    let loaded: Vec<GroundMotion> = motions.iter().filter_map(|(_, m)| m.clone().ok()).collect();
    let progress = Control::new();
    let start = Instant::now();
    let results = super::with_bar("gaps", &progress, args.quiet, || {
        record_gaps(&setup.scenario, &loaded, &progress)
    })?;
    let wall_time_s = start.elapsed().as_secs_f64();
    // Put the records that could not be read back in their place.
    let mut solved = results.into_iter();
    let rows: Vec<RecordJson> = motions
        .iter()
        .map(|(name, m)| match m {
            Err(e) => error_row(name.clone(), e.clone()),
            Ok(motion) => match solved.next().expect("one result per record") {
                Ok(g) => row(&g),
                Err(e) => error_row(motion.name.clone(), e.to_string()),
            },
        })
        .collect();
    let report = Report {
        preset: preset_name.to_string(),
        storeys_left: setup.scenario.left.storeys,
        storeys_right: setup.scenario.right.storeys,
        levels: setup.scenario.levels().len(),
        solves: progress.done(),
        records: rows,
        wall_time_s,
        threads: rayon::current_num_threads(),
    };
    if let Some(path) = &args.csv {
        write_csv(&report, path, out)?;
    }
    if let Some(path) = &args.plot {
        LinePlot {
            size: args.plot_size.unwrap_or((1200, 600)),
            scale: args.plot_scale.unwrap_or(1.0),
            ..plot(&report)
        }
        .write(path)
        .map_err(|e| anyhow!("--plot: {e}"))?;
    }
    if args.json {
        serde_json::to_writer_pretty(&mut *out, &report)?;
        writeln!(out)?;
    } else if !super::csv_to_stdout(args.csv.as_deref()) {
        table(&report, out)?;
    }
    failures(&report.records)
}

/// Names each record that failed on stderr; an error (exit 2) when none succeeded, so a script
/// cannot take an empty result for a good one.
fn failures(rows: &[RecordJson]) -> anyhow::Result<()> {
    let failed: Vec<&RecordJson> = rows.iter().filter(|r| r.error.is_some()).collect();
    if failed.is_empty() {
        return Ok(());
    }
    if failed.len() == rows.len() {
        bail!(
            "no record succeeded ({} failed): {}",
            failed.len(),
            failed
                .iter()
                .map(|r| format!("{}: {}", r.record, r.error.as_deref().unwrap_or("")))
                .collect::<Vec<_>>()
                .join("; ")
        );
    }
    for r in failed {
        eprintln!(
            "warning: {} failed: {}",
            r.record,
            r.error.as_deref().unwrap_or("")
        );
    }
    Ok(())
}

fn row(g: &RecordGaps) -> RecordJson {
    let a = &g.gaps;
    let closes = a.min_gap_m > 0.0;
    RecordJson {
        record: g.record.clone(),
        duration_s: Some(g.duration_s),
        pga_g: Some(g.pga_g),
        min_gap_m: Some(a.min_gap_m),
        level: a.level,
        abs_m: Some(a.abs_m),
        srss_m: Some(a.srss_m),
        abs_ratio: closes.then_some(a.abs_ratio),
        srss_ratio: closes.then_some(a.srss_ratio),
        levels: a
            .levels
            .iter()
            .map(|l| LevelJson {
                min_gap_m: l.min_gap_m,
                abs_m: l.abs_m,
                srss_m: l.srss_m,
            })
            .collect(),
        error: None,
    }
}

fn error_row(record: String, error: String) -> RecordJson {
    RecordJson {
        record,
        duration_s: None,
        pga_g: None,
        min_gap_m: None,
        level: None,
        abs_m: None,
        srss_m: None,
        abs_ratio: None,
        srss_ratio: None,
        levels: vec![],
        error: Some(error),
    }
}

fn mm(v: Option<f64>) -> String {
    v.map_or("-".into(), |x| format!("{:.3}", x * 1e3))
}

fn ratio(v: Option<f64>) -> String {
    v.map_or("-".into(), |x| format!("{x:.3}"))
}

fn table(r: &Report, out: &mut dyn Write) -> anyhow::Result<()> {
    writeln!(
        out,
        "Pounding Lab gaps: preset {}, {} storey{} against {}, {} level{}; the gap that avoids all contact against the code rules",
        r.preset,
        r.storeys_left,
        if r.storeys_left == 1 { "" } else { "s" },
        r.storeys_right,
        r.levels,
        if r.levels == 1 { "" } else { "s" }
    )?;
    writeln!(
        out,
        "  {:<44} {:>9} {:>8} {:>13} {:>6} {:>10} {:>8} {:>10} {:>9}",
        "record",
        "length",
        "PGA [g]",
        "min gap [mm]",
        "level",
        "ABS [mm]",
        "ABS/min",
        "SRSS [mm]",
        "SRSS/min"
    )?;
    for row in &r.records {
        let name: String = row.record.chars().take(44).collect();
        if let Some(e) = &row.error {
            writeln!(out, "  {name:<44} error: {e}")?;
            continue;
        }
        writeln!(
            out,
            "  {name:<44} {:>8.2}s {:>8.4} {:>13} {:>6} {:>10} {:>8} {:>10} {:>9}",
            row.duration_s.unwrap_or(0.0),
            row.pga_g.unwrap_or(0.0),
            mm(row.min_gap_m),
            row.level.map_or("-".into(), |l| (l + 1).to_string()),
            mm(row.abs_m),
            ratio(row.abs_ratio),
            mm(row.srss_m),
            ratio(row.srss_ratio)
        )?;
    }
    let mean = |f: fn(&RecordJson) -> Option<f64>| {
        let v: Vec<f64> = r.records.iter().filter_map(f).collect();
        (!v.is_empty()).then(|| v.iter().sum::<f64>() / v.len() as f64)
    };
    writeln!(
        out,
        "  mean ratio to the minimum gap: ABS {}, SRSS {} ({} record{} in {:.3} s on {} threads)",
        ratio(mean(|x| x.abs_ratio)),
        ratio(mean(|x| x.srss_ratio)),
        r.records.len(),
        if r.records.len() == 1 { "" } else { "s" },
        r.wall_time_s,
        r.threads
    )?;
    Ok(())
}

fn write_csv(r: &Report, path: &Path, out: &mut dyn Write) -> anyhow::Result<()> {
    let mut text =
        "record,duration_s,pga_g,min_gap_m,level,abs_m,abs_ratio,srss_m,srss_ratio,error\n"
            .to_string();
    let f = |v: Option<f64>| v.map_or(String::new(), |x| format!("{x:.12e}"));
    for row in &r.records {
        text += &format!(
            "\"{}\",{},{},{},{},{},{},{},{},\"{}\"\n",
            row.record.replace('"', "'"),
            f(row.duration_s),
            f(row.pga_g),
            f(row.min_gap_m),
            row.level.map_or(String::new(), |l| (l + 1).to_string()),
            f(row.abs_m),
            f(row.abs_ratio),
            f(row.srss_m),
            f(row.srss_ratio),
            row.error.as_deref().unwrap_or("").replace('"', "'")
        );
    }
    super::write_csv(out, path, |w| w.write_all(text.as_bytes()))
}

fn plot(r: &Report) -> LinePlot {
    let series = |name: &str, get: fn(&RecordJson) -> Option<f64>| Series {
        name: name.into(),
        points: r
            .records
            .iter()
            .enumerate()
            .filter_map(|(i, row)| get(row).map(|v| ((i + 1) as f64, v * 1e3)))
            .collect(),
    };
    LinePlot {
        markers: true,
        ..LinePlot::new(
            format!(
                "The gap that avoids pounding, record by record ({})",
                r.preset
            ),
            "record",
            "gap [mm]",
            vec![
                series("minimum gap (no contact)", |x| x.min_gap_m),
                series("ABS", |x| x.abs_m),
                series("SRSS", |x| x.srss_m),
            ],
        )
    }
}
