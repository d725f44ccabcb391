//! `pounding sweep`: one impact setting varied over a range, every point solved in parallel, with
//! peak force, contact duration and e against it for each model asked for.

use crate::export::plot::{LinePlot, Series};
use crate::io::settings::{IMPACT_KEYS, ImpactSetup};
use crate::model::impact::{ModelKind, solve};
use anyhow::{anyhow, bail};
use clap::Args;
use rayon::prelude::*;
use serde::Serialize;
use std::io::Write;
use std::time::Instant;

/// The flags that answer without a sweep.
const LISTS: [&str; 2] = ["list_keys", "list_presets"];

#[derive(Args, Debug)]
pub struct SweepArgs {
    /// The setting to vary: any --set key of `pounding impact` (see `pounding impact --list-keys`)
    #[arg(long, value_name = "KEY", required_unless_present_any = LISTS)]
    pub param: Option<String>,
    /// First value
    #[arg(long, value_name = "A", allow_negative_numbers = true, required_unless_present_any = LISTS)]
    pub from: Option<f64>,
    /// Last value
    #[arg(long, value_name = "B", allow_negative_numbers = true, required_unless_present_any = LISTS)]
    pub to: Option<f64>,
    /// Number of values, ends included (2 to 100000)
    #[arg(long, value_name = "N", default_value_t = 50)]
    pub count: usize,
    /// Space the values geometrically (A and B > 0)
    #[arg(long)]
    pub log: bool,
    /// Model (repeatable to compare): sears|wave|lumped-hertz|lumped-linear|kelvin|stereo|fe [default: the preset's]
    #[arg(long = "model", value_name = "M")]
    pub models: Vec<String>,
    /// The preset, fixed --set overrides and outputs, as for `pounding impact`; --csv writes
    /// every point, --plot the peak force against the swept value.
    #[command(flatten)]
    pub common: super::SceneArgs,
}

#[derive(Serialize, Debug, Clone)]
pub struct Point {
    pub model: String,
    pub value: f64,
    pub peak_force_n: Option<f64>,
    pub contact_duration_s: Option<f64>,
    pub restitution: Option<f64>,
    pub contacts: Option<usize>,
    /// Why this point has no result (a solver error), if so.
    pub error: Option<String>,
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

/// The swept values: linear or geometric, ends included.
pub fn values(from: f64, to: f64, count: usize, log: bool) -> Vec<f64> {
    (0..count)
        .map(|i| {
            let f = i as f64 / (count - 1) as f64;
            if log {
                (from.ln() + f * (to.ln() - from.ln())).exp()
            } else {
                from + f * (to - from)
            }
        })
        .collect()
}

/// The swept key and range, checked.
fn check(args: &SweepArgs) -> anyhow::Result<(&str, f64, f64)> {
    let (Some(key), Some(from), Some(to)) = (args.param.as_deref(), args.from, args.to) else {
        bail!("--param, --from and --to are required");
    };
    if !(2..=100_000).contains(&args.count) {
        bail!("--count: {} is outside 2 to 100000", args.count);
    }
    if !from.is_finite() || !to.is_finite() {
        bail!("--from/--to: values must be finite numbers");
    }
    if args.log && (from <= 0.0 || to <= 0.0) {
        bail!("--log: --from and --to must be > 0 (got {from} and {to})");
    }
    let known = IMPACT_KEYS.iter().any(|(k, _)| {
        *k == key
            || (k.starts_with("barN.")
                && ["bar1.", "bar2."]
                    .iter()
                    .any(|b| key == format!("{b}{}", &k[5..])))
    });
    if !known || key == "model" {
        bail!("--param: '{key}' is not a numeric impact setting; see `pounding sweep --list-keys`");
    }
    Ok((key, from, to))
}

pub fn run(args: &SweepArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if super::impact::answered_lists(&args.common, out)? {
        return Ok(());
    }
    let (param, from, to) = check(args)?;
    let (base, _) = super::impact::setup(&args.common)?;
    let models: Vec<ModelKind> = if args.models.is_empty() {
        vec![base.model]
    } else {
        args.models
            .iter()
            .map(|m| super::impact::parse_model(m))
            .collect::<anyhow::Result<_>>()?
    };
    let values = values(from, to, args.count, args.log);
    // Every setup is built and validated before any solve, so a bad range fails at once and
    // names the value.
    let setups: Vec<ImpactSetup> = values
        .iter()
        .map(|v| {
            let mut s = base;
            s.apply_assignment(&format!("{param}={v}"))
                .and_then(|()| s.scenario.validate())
                .map(|()| s)
                .map_err(|e| anyhow!("--param {param}={v}: {e}"))
        })
        .collect::<anyhow::Result<_>>()?;
    let jobs: Vec<(ModelKind, usize)> = models
        .iter()
        .flat_map(|&m| (0..setups.len()).map(move |i| (m, i)))
        .collect();
    let start = Instant::now();
    let points: Vec<Point> = jobs
        .par_iter()
        .map(|&(model, i)| {
            let value = values[i];
            match solve(model, &setups[i].scenario) {
                Ok(r) => Point {
                    model: model.name().into(),
                    value,
                    peak_force_n: r.peak_force_n,
                    contact_duration_s: Some(r.contact_duration_s),
                    restitution: Some(r.restitution),
                    contacts: Some(r.contacts.len()),
                    error: None,
                },
                Err(e) => Point {
                    model: model.name().into(),
                    value,
                    peak_force_n: None,
                    contact_duration_s: None,
                    restitution: None,
                    contacts: None,
                    error: Some(e.to_string()),
                },
            }
        })
        .collect();
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
    } else if args.common.csv.as_deref() != Some(std::path::Path::new("-")) {
        table(&report, out)?;
    }
    Ok(())
}

fn opt(v: Option<f64>, scale: f64) -> String {
    v.map_or("-".into(), |x| format!("{:.6e}", x * scale))
}

fn table(r: &SweepReport, out: &mut dyn Write) -> anyhow::Result<()> {
    writeln!(
        out,
        "{:>14}  {:<14} {:>14} {:>14} {:>8} {:>8}",
        r.param, "model", "peak [N]", "duration [ms]", "e", "contacts"
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
            p.error
                .as_ref()
                .map_or(String::new(), |e| format!("  error: {e}"))
        )?;
    }
    writeln!(
        out,
        "{} solves in {:.3} s on {} threads",
        r.solves, r.wall_time_s, r.threads
    )?;
    Ok(())
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
    if path == std::path::Path::new("-") {
        out.write_all(text.as_bytes())?;
    } else {
        std::fs::write(path, text).map_err(|e| anyhow!("--csv: {}: {e}", path.display()))?;
    }
    Ok(())
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
            r.param.clone(),
            "peak force [kN]",
            series,
        )
    }
}
