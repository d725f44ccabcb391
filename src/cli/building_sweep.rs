//! `pounding sweep --buildings`: one building setting varied over a range, every point solved in
//! parallel, with the pounding, the sway and, where storeys yield, their ductility demand and
//! dissipated energy against it.

use super::sweep::{SweepArgs, flagged};
use anyhow::bail;
use pounding::export::plot::{LinePlot, Series};
use pounding::model::settings::{BUILDING_SETTINGS, axis_label};
use pounding::study::Control;
use pounding::study::building_sweep::{self, BuildingPoint};
use pounding::study::sweep::values;
use serde::Serialize;
use std::io::Write;
use std::time::Instant;

#[derive(Serialize, Debug)]
pub struct BuildingSweepReport {
    pub param: String,
    pub preset: String,
    pub values: Vec<f64>,
    pub points: Vec<BuildingPoint>,
    pub solves: usize,
    pub wall_time_s: f64,
    pub threads: usize,
}

pub fn run(args: &SweepArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let common = &args.common;
    if common.list_keys {
        return super::list(
            out,
            26,
            building_sweep::numeric_settings()
                .iter()
                .map(|s| (s.key, s.describe())),
        );
    }
    if common.list_presets {
        return super::list_presets(out, "buildings");
    }
    let (Some(param), Some(from), Some(to)) = (args.param.as_deref(), args.from, args.to) else {
        bail!("--param, --from and --to are required");
    };
    if !args.models.is_empty() {
        bail!(
            "--model: a building sweep runs the preset's contact element (set it with --set contact.model=...)"
        );
    }
    building_sweep::check(param, from, to, args.count, args.log).map_err(flagged)?;
    let (base, preset) = super::buildings::setup(common.preset.as_deref(), &common.set, None)?;
    let values = values(from, to, args.count, args.log);
    let setups = building_sweep::setups(&base, param, &values).map_err(flagged)?;
    let start = Instant::now();
    let progress = Control::new();
    let quiet = common.quiet || common.json;
    let points = super::with_bar("sweep", &progress, quiet, || {
        building_sweep::run(&setups, &values, &progress)
    })?;
    let report = BuildingSweepReport {
        param: param.to_string(),
        preset: preset.to_string(),
        values,
        solves: points.len(),
        points,
        wall_time_s: start.elapsed().as_secs_f64(),
        threads: rayon::current_num_threads(),
    };
    if let Some(path) = &common.csv {
        let text = csv(&report);
        super::write_csv(out, path, |w| w.write_all(text.as_bytes()))?;
    }
    common.write_plot((1000, 600), || plot(&report, args.log))?;
    if common.json {
        serde_json::to_writer_pretty(&mut *out, &report)?;
        writeln!(out)?;
    } else if !super::csv_to_stdout(common.csv.as_deref()) {
        table(&report, out)?;
    }
    Ok(())
}

/// A table cell: the value times `scale`, or "-" where there is none.
fn cell(v: Option<f64>, scale: f64) -> String {
    v.map_or("-".into(), |x| format!("{:.5e}", x * scale))
}

fn table(r: &BuildingSweepReport, out: &mut dyn Write) -> anyhow::Result<()> {
    writeln!(
        out,
        "{:>22} {:>8} {:>13} {:>12} {:>12} {:>12} {:>12} {:>13} {:>13}",
        r.param,
        "impacts",
        "max force [N]",
        "left [mm]",
        "right [mm]",
        "mu left",
        "mu right",
        "E_hyst [J]",
        "residual [mm]"
    )?;
    for p in &r.points {
        writeln!(
            out,
            "{:>22.6e} {:>8} {:>13} {:>12} {:>12} {:>12} {:>12} {:>13} {:>13}{}",
            p.value,
            p.impact_count.map_or("-".into(), |c| c.to_string()),
            cell(p.max_pounding_force_n, 1.0),
            cell(p.peak_displacement_left_m, 1e3),
            cell(p.peak_displacement_right_m, 1e3),
            cell(p.max_ductility_left, 1.0),
            cell(p.max_ductility_right, 1.0),
            cell(p.hysteretic_energy_j, 1.0),
            cell(p.max_residual_drift_m, 1e3),
            super::sweep::error_note(p.error.as_deref())
        )?;
    }
    super::sweep::solves_line(out, r.solves, r.wall_time_s, r.threads)
}

fn csv(r: &BuildingSweepReport) -> String {
    let mut text = format!(
        "{},impact_count,max_pounding_force_n,peak_displacement_left_m,peak_displacement_right_m,max_ductility_left,max_ductility_right,hysteretic_energy_j,max_residual_drift_m,error\n",
        r.param
    );
    let f = |v: Option<f64>| v.map_or(String::new(), |x| format!("{x:.12e}"));
    for p in &r.points {
        text += &format!(
            "{:.12e},{},{},{},{},{},{},{},{},{}\n",
            p.value,
            p.impact_count.map_or(String::new(), |c| c.to_string()),
            f(p.max_pounding_force_n),
            f(p.peak_displacement_left_m),
            f(p.peak_displacement_right_m),
            f(p.max_ductility_left),
            f(p.max_ductility_right),
            f(p.hysteretic_energy_j),
            f(p.max_residual_drift_m),
            p.error.as_deref().unwrap_or("").replace(',', ";")
        );
    }
    text
}

fn plot(r: &BuildingSweepReport, log: bool) -> LinePlot {
    let points = |get: fn(&BuildingPoint) -> Option<f64>| -> Vec<(f64, f64)> {
        r.points
            .iter()
            .filter_map(|p| get(p).map(|y| (p.value, y)))
            .collect()
    };
    LinePlot {
        log_x: log,
        markers: r.values.len() <= 30,
        ..LinePlot::new(
            format!("Max pounding force against {}", r.param),
            axis_label(BUILDING_SETTINGS, &r.param),
            "max pounding force [kN]",
            vec![Series {
                name: "max force".into(),
                points: points(|p| p.max_pounding_force_n.map(|f| f * 1e-3)),
            }],
        )
    }
}
