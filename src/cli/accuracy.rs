//! `pounding accuracy`: error against run time. Each model runs on a ladder of steps (FE on a
//! ladder of meshes) against a much finer solve of the same model; each rung reports the errors
//! in peak force, contact duration, e and the L2 norm of the force history, the wall time, and
//! the observed order. The same for the building run (impact count, peak displacements, max
//! force against the steps per contact time scale).

use clap::Args;
use pounding::export::plot::{LinePlot, Series};
use pounding::io::building_settings::BuildingSetup;
use pounding::io::preset;
use pounding::io::settings::ImpactSetup;
use pounding::model::building::{BuildingScenario, ContactModel};
use pounding::model::impact::estimate::rel;
use pounding::model::impact::{ImpactResult, ModelKind, solve};
use pounding::model::scenario::{ImpactScenario, Reading};
use pounding::study::Control;
use serde::Serialize;
use std::io::Write;
use std::path::PathBuf;
use std::time::Instant;

#[derive(Args, Debug, Default)]
pub struct AccuracyArgs {
    /// impact (the bar models) or buildings
    #[arg(long, default_value = "impact")]
    pub scene: String,
    /// Preset name or file [default: paper-base, or paper-buildings]
    #[arg(long, value_name = "NAME-or-FILE")]
    pub preset: Option<String>,
    /// Override a setting (see `pounding impact --list-keys` or `pounding buildings --list-keys`)
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Ground motion for the buildings: a built-in record or a file [default: the preset's]
    #[arg(long, value_name = "FILE")]
    pub motion: Option<PathBuf>,
    /// Write the table as CSV
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
    /// Write the work-precision plot (.svg or .png)
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
    /// Print one JSON object instead of the table
    #[arg(long)]
    pub json: bool,
    /// Show no progress bar on standard error (it shows only on a terminal, and not with --json)
    #[arg(long)]
    pub quiet: bool,
}

/// One rung of a ladder.
#[derive(Serialize, Clone)]
pub struct Rung {
    pub model: String,
    /// Time step [s], or for FE the segments per bar, or for buildings steps per time scale.
    pub resolution: f64,
    pub steps: usize,
    pub wall_time_s: f64,
    pub peak_force_error: f64,
    pub duration_error: f64,
    pub restitution_error: f64,
    pub force_l2_error: f64,
    /// Observed order from the previous rung (by the L2 error; by max force for buildings).
    pub observed_order: Option<f64>,
    /// Buildings: impact count and its difference from the reference.
    pub impacts: Option<(usize, i64)>,
}

fn min_time<T>(f: impl Fn() -> T) -> (T, f64) {
    let mut best = f64::INFINITY;
    let mut out = None;
    for _ in 0..3 {
        let t = Instant::now();
        let r = f();
        best = best.min(t.elapsed().as_secs_f64());
        out = Some(r);
    }
    (out.expect("ran"), best)
}

/// Relative L2 distance of a force history from the reference's, at the history's own samples
/// (the much finer reference interpolated there), so that it measures the solver, not the
/// interpolation between a coarse run's samples.
fn l2_error(r: &ImpactResult, reference: &ImpactResult) -> f64 {
    let at = |x: &ImpactResult, t: f64| {
        let k = x.time_s.partition_point(|&s| s <= t);
        if k == 0 {
            return x.force_n.first().copied().unwrap_or(0.0);
        }
        if k >= x.time_s.len() {
            return 0.0;
        }
        let (t0, t1) = (x.time_s[k - 1], x.time_s[k]);
        let s = if t1 > t0 { (t - t0) / (t1 - t0) } else { 0.0 };
        x.force_n[k - 1] + s * (x.force_n[k] - x.force_n[k - 1])
    };
    let (mut num, mut den) = (0.0, 0.0);
    for (i, w) in r.time_s.windows(2).enumerate() {
        let dt = w[1] - w[0];
        for (t, f) in [(w[0], r.force_n[i]), (w[1], r.force_n[i + 1])] {
            let g = at(reference, t);
            num += 0.5 * dt * (f - g).powi(2);
            den += 0.5 * dt * g * g;
        }
    }
    (num / den.max(f64::MIN_POSITIVE)).sqrt()
}

fn order(prev: Option<&Rung>, err: f64, ratio: f64) -> Option<f64> {
    prev.filter(|p| p.force_l2_error > 0.0 && err > 0.0)
        .map(|p| (p.force_l2_error / err).ln() / ratio.ln())
}

/// Six steps halving from 4 dt (the reference a further 16 times finer), held inside the
/// range solver.dt accepts: the user's own dt is allowed, so its ladder must be too. Near an end
/// of the range the ladder slides along it, still halving.
pub fn step_ladder(dt: f64) -> Vec<f64> {
    let range = pounding::model::settings::impact::DT
        .range()
        .expect("the step is a number with a range");
    // Coarsest rung over the reference step: 2^5 rungs down, then 16.
    let span = 32.0 * 16.0;
    let top = (4.0 * dt)
        .min(range.max)
        .max(range.min * span)
        .min(range.max);
    (0..6).map(|i| top * 0.5f64.powi(i)).collect()
}

/// Counts a rung (or a reference) done, and stops when Ctrl-C asked.
fn rung_done(progress: &Control) -> anyhow::Result<()> {
    progress.tick();
    if progress.cancelled() {
        anyhow::bail!("cancelled");
    }
    Ok(())
}

/// The impact models' ladders.
pub fn impact_ladders(base: &ImpactScenario, progress: &Control) -> anyhow::Result<Vec<Rung>> {
    let cases: [(&str, ModelKind, Reading); 6] = [
        ("sears paper", ModelKind::Sears, Reading::Paper),
        ("sears collocated", ModelKind::Sears, Reading::Collocated),
        ("sears end", ModelKind::Sears, Reading::End),
        ("lumped-hertz", ModelKind::LumpedHertz, Reading::Paper),
        ("kelvin", ModelKind::Kelvin, Reading::Paper),
        ("fe", ModelKind::Fe, Reading::End),
    ];
    let steps = step_ladder(base.solver.dt_s);
    let meshes = [25usize, 50, 100, 200, 400, 800];
    progress.plan(cases.len() * (1 + steps.len().max(meshes.len())));
    let mut rows = vec![];
    for (name, model, reading) in cases {
        let mut sc = *base;
        sc.reading = reading;
        sc.solver.refine = false;
        let at = |res: f64| -> ImpactScenario {
            let mut s = sc;
            if model == ModelKind::Fe {
                s.fe.segments = res as usize;
                s.solver.dt_s = 1.0;
            } else {
                s.solver.dt_s = res;
            }
            s
        };
        let (ladder, reference_res): (Vec<f64>, f64) = if model == ModelKind::Fe {
            (meshes.iter().map(|&n| n as f64).collect(), 3200.0)
        } else {
            (steps.clone(), steps[steps.len() - 1] / 16.0)
        };
        let reference = solve(model, &at(reference_res))?;
        rung_done(progress)?;
        let mut prev: Option<Rung> = None;
        for &res in &ladder {
            let s = at(res);
            let (r, wall) = min_time(|| solve(model, &s));
            let r = r?;
            rung_done(progress)?;
            let err = l2_error(&r, &reference);
            let rung = Rung {
                model: name.into(),
                resolution: res,
                steps: r.stats.steps,
                wall_time_s: wall,
                peak_force_error: rel(
                    r.peak_force_n.unwrap_or(0.0),
                    reference.peak_force_n.unwrap_or(0.0),
                ),
                duration_error: rel(r.contact_duration_s, reference.contact_duration_s),
                restitution_error: (r.restitution - reference.restitution).abs(),
                force_l2_error: err,
                observed_order: order(prev.as_ref(), err, 2.0),
                impacts: None,
            };
            rows.push(rung.clone());
            prev = Some(rung);
        }
    }
    Ok(rows)
}

/// The building run's ladders (Sears and linear spring) against 128 steps per time scale.
pub fn building_ladders(
    setup: &BuildingSetup,
    motion: &pounding::model::motion::GroundMotion,
    progress: &Control,
) -> anyhow::Result<Vec<Rung>> {
    let ladder = [2.0, 4.0, 8.0, 16.0, 32.0];
    progress.plan(2 * (1 + ladder.len()));
    let mut rows = vec![];
    for model in [ContactModel::Sears, ContactModel::Linear] {
        // Every discretisation parameter with the steps per contact time scale: the grid on
        // which onsets are sought and peaks sampled follows the tolerance.
        let at = |sps: f64| BuildingScenario {
            contact: model,
            steps_per_scale: Some(sps),
            tolerance: (1e-3 * (8.0 / sps).powi(2)).min(0.1),
            ..setup.scenario.clone()
        };
        let reference = pounding::model::building::solve(&at(128.0), motion)?;
        rung_done(progress)?;
        let mut prev: Option<Rung> = None;
        for sps in ladder {
            let s = at(sps);
            let (r, wall) = min_time(|| pounding::model::building::solve(&s, motion));
            let r = r?;
            rung_done(progress)?;
            let force_err = rel(r.max_pounding_force_n, reference.max_pounding_force_n);
            let disp_err = rel(r.peak_displacement_m[0], reference.peak_displacement_m[0]).max(
                rel(r.peak_displacement_m[1], reference.peak_displacement_m[1]),
            );
            let rung = Rung {
                model: format!("buildings {}", model.name()),
                resolution: sps,
                steps: r.stats.steps,
                wall_time_s: wall,
                peak_force_error: force_err,
                duration_error: disp_err,
                restitution_error: 0.0,
                force_l2_error: force_err,
                observed_order: order(prev.as_ref(), force_err, 2.0),
                impacts: Some((
                    r.impacts.len(),
                    r.impacts.len() as i64 - reference.impacts.len() as i64,
                )),
            };
            rows.push(rung.clone());
            prev = Some(rung);
        }
    }
    Ok(rows)
}

pub fn run(args: &AccuracyArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let buildings = match args.scene.as_str() {
        "impact" => false,
        "buildings" => true,
        other => anyhow::bail!("--scene: unknown scene '{other}': allowed impact|buildings"),
    };
    let rows = ladders(args, buildings)?;
    if let Some(path) = &args.csv {
        write_rows_csv(out, path, &rows)?;
    }
    if let Some(path) = &args.plot {
        work_precision_plot(&rows, buildings).write(path)?;
    }
    if args.json {
        writeln!(
            out,
            "{}",
            serde_json::to_string_pretty(
                &serde_json::json!({ "scene": args.scene, "rungs": rows })
            )?
        )?;
    } else if !super::csv_to_stdout(args.csv.as_deref()) {
        table(out, &rows, buildings)?;
    }
    Ok(())
}

/// Every rung of the scene's ladders, from its preset and overrides, with a progress bar.
fn ladders(args: &AccuracyArgs, buildings: bool) -> anyhow::Result<Vec<Rung>> {
    let quiet = args.quiet || args.json;
    let progress = Control::new();
    if buildings {
        let (setup, _) =
            super::buildings::setup(args.preset.as_deref(), &args.set, args.motion.as_deref())?;
        let motion = super::buildings::load_motion(&setup)?;
        super::with_bar("accuracy", &progress, quiet, || {
            building_ladders(&setup, &motion, &progress)
        })
    } else {
        let mut setup: ImpactSetup = preset::load_for(
            args.preset.as_deref().unwrap_or(preset::DEFAULT_PRESET),
            "impact",
        )
        .map_err(super::preset_error)?;
        for a in &args.set {
            setup
                .apply_assignment(a)
                .map_err(|e| anyhow::anyhow!("--set {e}"))?;
        }
        super::with_bar("accuracy", &progress, quiet, || {
            impact_ladders(&setup.scenario, &progress)
        })
    }
}

/// The rungs as CSV, one row each.
fn write_rows_csv(
    out: &mut dyn Write,
    path: &std::path::Path,
    rows: &[Rung],
) -> anyhow::Result<()> {
    super::write_csv(out, path, |w| {
        writeln!(
            w,
            "model,resolution,steps,wall_time_s,peak_force_error,duration_error,restitution_error,force_l2_error,observed_order,impacts,impact_count_difference"
        )?;
        for r in rows {
            let (n, d) = r.impacts.map_or((String::new(), String::new()), |(n, d)| {
                (n.to_string(), d.to_string())
            });
            writeln!(
                w,
                "{},{:e},{},{:e},{:e},{:e},{:e},{:e},{},{},{}",
                r.model,
                r.resolution,
                r.steps,
                r.wall_time_s,
                r.peak_force_error,
                r.duration_error,
                r.restitution_error,
                r.force_l2_error,
                r.observed_order
                    .map_or(String::new(), |o| format!("{o:.3}")),
                n,
                d
            )?;
        }
        Ok(())
    })?;
    Ok(())
}

/// Error against wall time, one curve per model, both axes logarithmic.
fn work_precision_plot(rows: &[Rung], buildings: bool) -> LinePlot {
    let mut series: Vec<Series> = vec![];
    for r in rows {
        if series.last().is_none_or(|s| s.name != r.model) {
            series.push(Series {
                name: r.model.clone(),
                points: vec![],
            });
        }
        series
            .last_mut()
            .expect("pushed")
            .points
            .push((r.wall_time_s * 1e3, r.force_l2_error));
    }
    let (title, y) = if buildings {
        (
            "Work-precision: building pounding, 8 s",
            "max force error (relative)",
        )
    } else {
        (
            "Work-precision: bar impact",
            "force history L2 error (relative)",
        )
    };
    LinePlot {
        log_x: true,
        log_y: true,
        size: (900, 620),
        markers: true,
        ..LinePlot::new(title, "wall time per solve [ms]", y, series)
    }
}

/// The rungs as a text table.
fn table(out: &mut dyn Write, rows: &[Rung], buildings: bool) -> anyhow::Result<()> {
    let res = if buildings {
        "steps/scale"
    } else {
        "dt [s] / FE N"
    };
    writeln!(
        out,
        "{:18} {:>13} {:>8} {:>10} {:>11} {:>11} {:>11} {:>11} {:>7}{}",
        pounding::model::settings::impact::MODEL.label,
        res,
        "steps",
        "wall [ms]",
        if buildings { "max F err" } else { "peak err" },
        if buildings { "disp err" } else { "dur err" },
        if buildings { "" } else { "e err" },
        if buildings { "" } else { "L2 err" },
        "order",
        if buildings { "  impacts (diff)" } else { "" }
    )?;
    for r in rows {
        let extra = r
            .impacts
            .map_or(String::new(), |(n, d)| format!("  {n} ({d:+})"));
        let (c3, c4) = if buildings {
            (String::new(), String::new())
        } else {
            (
                format!("{:.2e}", r.restitution_error),
                format!("{:.2e}", r.force_l2_error),
            )
        };
        writeln!(
            out,
            "{:18} {:>13.4e} {:>8} {:>10.4} {:>11.2e} {:>11.2e} {:>11} {:>11} {:>7}{extra}",
            r.model,
            r.resolution,
            r.steps,
            r.wall_time_s * 1e3,
            r.peak_force_error,
            r.duration_error,
            c3,
            c4,
            r.observed_order.map_or("-".into(), |o| format!("{o:.2}"))
        )?;
    }
    Ok(())
}

#[cfg(test)]
mod ladder_tests {
    use super::step_ladder;

    #[test]
    fn the_step_ladder_of_the_largest_allowed_dt_stays_in_the_range_and_halves() {
        let range = pounding::model::settings::find(
            pounding::model::settings::IMPACT_SETTINGS,
            "solver.dt",
        )
        .and_then(|s| s.range())
        .unwrap();
        for dt in [range.max, range.min, 1e-6] {
            let ladder = step_ladder(dt);
            assert_eq!(ladder.len(), 6);
            // The reference solve runs 16 times finer than the finest rung.
            for &h in ladder.iter().chain([ladder[5] / 16.0].iter()) {
                assert!(range.contains(h), "dt {dt}: rung {h} outside {range}");
            }
            assert!(ladder.windows(2).all(|w| w[1] == w[0] / 2.0), "{ladder:?}");
        }
        assert_eq!(step_ladder(1e-6)[0], 4e-6);
    }
}
