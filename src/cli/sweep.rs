//! `pounding sweep`: one impact setting varied over a range, every point solved in parallel, with
//! peak force, contact duration and e against it for each model asked for.

use anyhow::{anyhow, bail};
use clap::Args;
use pounding::export::plot::{LinePlot, Series};
use pounding::model::impact::ModelKind;
use pounding::model::settings::{IMPACT_SETTINGS, axis_label};
use pounding::study::Control;
use pounding::study::sweep::{self, Part, Point};
use serde::Serialize;
use std::io::Write;
use std::time::Instant;

/// The flags that answer without a sweep.
const LISTS: [&str; 2] = ["list_keys", "list_presets"];

#[derive(Args, Debug)]
pub struct SweepArgs {
    /// The setting to vary: any numeric --set key of `pounding impact` (see `pounding sweep
    /// --list-keys`), or with --buildings of `pounding buildings`
    #[arg(long, value_name = "KEY", required_unless_present_any = LISTS)]
    pub param: Option<String>,
    /// First value
    #[arg(long, value_name = "A", allow_negative_numbers = true, required_unless_present_any = LISTS)]
    pub from: Option<f64>,
    /// Last value
    #[arg(long, value_name = "B", allow_negative_numbers = true, required_unless_present_any = LISTS)]
    pub to: Option<f64>,
    /// Number of values, ends included (2 to 100000)
    #[arg(long, value_name = "N", default_value_t = 50, allow_hyphen_values = true, value_parser = |t: &str| super::parse_whole_in(t, 2, 100_000))]
    pub count: usize,
    /// Space the values geometrically (A and B > 0)
    #[arg(long)]
    pub log: bool,
    /// Sweep a setting of the building pair (`pounding buildings`: its presets, --set keys and
    /// record) instead of an impact setting
    #[arg(long)]
    pub buildings: bool,
    /// Model (repeatable to compare): sears|wave|lumped-hertz|lumped-linear|kelvin|stereo|fe [default: the preset's]
    #[arg(long = "model", value_name = "M")]
    pub models: Vec<String>,
    /// The preset, fixed --set overrides and outputs, as for `pounding impact`; --csv writes
    /// every point, --plot the peak force against the swept value.
    #[command(flatten)]
    pub common: super::SceneArgs,
}

#[derive(Serialize, Debug)]
pub struct SweepReport {
    pub param: String,
    pub models: Vec<String>,
    pub values: Vec<f64>,
    pub points: Vec<Point>,
    pub solves: usize,
    pub wall_time_s: f64,
    pub threads: usize,
}

pub fn run(args: &SweepArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if args.buildings {
        return super::building_sweep::run(args, out);
    }
    if super::impact::answered_lists(&args.common, out)? {
        return Ok(());
    }
    let (Some(param), Some(from), Some(to)) = (args.param.as_deref(), args.from, args.to) else {
        bail!("--param, --from and --to are required");
    };
    sweep::check(param, from, to, args.count, args.log).map_err(flagged)?;
    let (base, _) = super::impact::setup(&args.common)?;
    let models: Vec<ModelKind> = if args.models.is_empty() {
        vec![base.model]
    } else {
        args.models
            .iter()
            .map(|m| super::impact::parse_model(m))
            .collect::<anyhow::Result<_>>()?
    };
    let values = sweep::values(from, to, args.count, args.log);
    let setups = sweep::setups(&base, param, &values).map_err(flagged)?;
    let start = Instant::now();
    let progress = Control::new();
    let quiet = args.common.quiet || args.common.json;
    let points = super::with_bar("sweep", &progress, quiet, || {
        sweep::run(&setups, &values, &models, &progress)
    })?;
    let report = SweepReport {
        param: param.to_string(),
        models: models.iter().map(|m| m.name().to_string()).collect(),
        values,
        solves: points.len(),
        points,
        wall_time_s: start.elapsed().as_secs_f64(),
        threads: rayon::current_num_threads(),
    };
    if let Some(path) = &args.common.csv {
        write_csv(&report, path, out)?;
    }
    args.common
        .write_plot((1000, 600), || plot(&report, args.log))?;
    if args.common.json {
        serde_json::to_writer_pretty(&mut *out, &report)?;
        writeln!(out)?;
    } else if !super::csv_to_stdout(args.common.csv.as_deref()) {
        table(&report, out)?;
    }
    Ok(())
}

/// A sweep's error, phrased with the flag at fault.
pub(super) fn flagged(e: sweep::SweepError) -> anyhow::Error {
    let flag = match e.part() {
        Part::Param => "--param: ",
        Part::Count => "--count: ",
        Part::Range => "--from/--to: ",
        Part::Spacing => "--log: ",
        Part::Value => "--param ",
    };
    let hint = if e.part() == Part::Param {
        "; see `pounding sweep --list-keys`"
    } else {
        ""
    };
    anyhow!("{flag}{e}{hint}")
}

/// A point's error after its row, if it has one.
pub(super) fn error_note(error: Option<&str>) -> String {
    error.map_or(String::new(), |e| format!("  error: {e}"))
}

/// The last line of a sweep's table: how many solves, how long, on how many threads.
pub(super) fn solves_line(
    out: &mut dyn Write,
    solves: usize,
    wall_time_s: f64,
    threads: usize,
) -> anyhow::Result<()> {
    writeln!(
        out,
        "{solves} solves in {wall_time_s:.3} s on {threads} threads"
    )?;
    Ok(())
}

fn opt(v: Option<f64>, scale: f64) -> String {
    v.map_or("-".into(), |x| format!("{:.6e}", x * scale))
}

fn table(r: &SweepReport, out: &mut dyn Write) -> anyhow::Result<()> {
    writeln!(
        out,
        "{:>14}  {:<14} {:>14} {:>14} {:>8} {:>8}",
        r.param,
        pounding::model::settings::impact::MODEL.label,
        "peak [N]",
        "duration [ms]",
        "e",
        "contacts"
    )?;
    for p in &r.points {
        writeln!(
            out,
            "{:>14.6e}  {:<14} {:>14} {:>14} {:>8} {:>8}{}",
            p.value,
            p.model,
            opt(p.peak_force_n, 1.0),
            opt(p.contact_duration_s, 1e3),
            p.restitution.map_or("-".into(), |e| format!("{e:.4}")),
            p.contacts.map_or("-".into(), |c| c.to_string()),
            error_note(p.error.as_deref())
        )?;
    }
    solves_line(out, r.solves, r.wall_time_s, r.threads)
}

fn write_csv(r: &SweepReport, path: &std::path::Path, out: &mut dyn Write) -> anyhow::Result<()> {
    let mut text = format!(
        "{},model,peak_force_n,contact_duration_s,restitution,contacts,error\n",
        r.param
    );
    let f = |v: Option<f64>| v.map_or(String::new(), |x| format!("{x:.12e}"));
    for p in &r.points {
        text += &format!(
            "{:.12e},{},{},{},{},{},{}\n",
            p.value,
            p.model,
            f(p.peak_force_n),
            f(p.contact_duration_s),
            f(p.restitution),
            p.contacts.map_or(String::new(), |c| c.to_string()),
            p.error.as_deref().unwrap_or("").replace(',', ";")
        );
    }
    super::write_csv(out, path, |w| w.write_all(text.as_bytes()))
}

fn plot(r: &SweepReport, log: bool) -> LinePlot {
    let series = r
        .models
        .iter()
        .map(|m| Series {
            name: m.clone(),
            points: r
                .points
                .iter()
                .filter(|p| &p.model == m)
                .filter_map(|p| p.peak_force_n.map(|f| (p.value, f * 1e-3)))
                .collect(),
        })
        .collect();
    LinePlot {
        log_x: log,
        markers: r.values.len() <= 30,
        ..LinePlot::new(
            format!("Peak contact force against {}", r.param),
            axis_label(IMPACT_SETTINGS, &r.param),
            "peak force [kN]",
            series,
        )
    }
}
