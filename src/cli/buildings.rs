//! `pounding buildings`: two buildings under a ground motion, pounding.

use super::building_report::{BuildingReport, summary};
use clap::Args;
use pounding::io::building_settings::BuildingSetup;
use pounding::io::preset;
use pounding::model::building::ContactModel;
use pounding::model::motion::GroundMotion;
use pounding::model::settings::BUILDING_SETTINGS;
use std::io::Write;
use std::path::PathBuf;

#[derive(Args, Debug, Default)]
pub struct BuildingArgs {
    #[command(flatten)]
    pub common: super::SceneArgs,
    /// Ground motion: a built-in record (elcentro-1940) or a file, PEER .AT2 or text [default:
    /// the preset's]
    #[arg(long, value_name = "FILE")]
    pub motion: Option<PathBuf>,
    /// Contact model: sears|linear|kelvin|hertz|hertzdamp|jankowski|stereo|none [default: the preset's]
    #[arg(long, value_name = "MODEL")]
    pub contact: Option<String>,
    #[command(flatten)]
    pub animation: super::impact::AnimateArgs,
    /// The animation's drift exaggeration (1 to 500; the ground is drawn to scale)
    #[arg(long, value_name = "X", default_value_t = 20.0, requires = "animate", allow_hyphen_values = true, value_parser = parse_drift)]
    pub animate_drift: f64,
    /// Slow motion around one impact: `strongest`, or its number K from 1 (the frames span
    /// twice its duration before and after it)
    #[arg(long, value_name = "strongest|K", requires = "animate", conflicts_with_all = ["animate_from", "animate_to"])]
    pub animate_around: Option<String>,
}

fn parse_drift(text: &str) -> Result<f64, String> {
    super::parse_number_in(text, 1.0, 500.0)
}

/// Reads or generates the ground motion a setup asks for; errors phrased for the command line.
pub fn load_motion(setup: &BuildingSetup) -> anyhow::Result<GroundMotion> {
    pounding::io::motion::load(&setup.motion).map_err(|e| anyhow::anyhow!("--motion {e}"))
}

/// The preset (or `paper-buildings`) with the --set overrides and --motion applied, and the
/// preset's name.
pub(super) fn setup<'a>(
    preset_name: Option<&'a str>,
    sets: &[String],
    motion: Option<&std::path::Path>,
) -> anyhow::Result<(BuildingSetup, &'a str)> {
    let preset_name = preset_name.unwrap_or("paper-buildings");
    let mut setup: BuildingSetup =
        preset::load_for(preset_name, "buildings").map_err(super::preset_error)?;
    for a in sets {
        setup
            .apply_assignment(a)
            .map_err(|e| anyhow::anyhow!("--set {e}"))?;
    }
    if let Some(path) = motion {
        setup
            .motion
            .set_source(&path.display().to_string())
            .map_err(|e| anyhow::anyhow!("--motion {e}"))?;
    }
    Ok((setup, preset_name))
}

/// Writes --animate, if asked for.
#[cfg(feature = "gui")]
fn write_animation(
    args: &BuildingArgs,
    setup: &BuildingSetup,
    motion: &GroundMotion,
    result: &pounding::model::building::BuildingResult,
) -> anyhow::Result<()> {
    let a = &args.animation;
    if a.animate.is_none() {
        return Ok(());
    }
    let title = format!(
        "Two buildings: {} contact, {}",
        result.contact.name(),
        motion.short_name()
    );
    let mut animation = pounding::render::animate_buildings::BuildingAnimation::new(
        setup.clone(),
        motion.clone(),
        result.clone(),
        title,
        a.animate_size,
        a.animate_frames,
    );
    animation.exaggeration = args.animate_drift;
    animation.t_range = frames_range(
        a,
        args.animate_around.as_deref(),
        &result.impacts,
        animation.t_range,
    )?;
    a.write(
        args.common.json || args.common.quiet,
        |target, path, progress| animation.write(target, path, a.animate_fps, progress),
    )
}

/// The frames' time range: slow motion `around` an impact, else the whole run, within
/// `--animate-from` and `--animate-to`.
#[cfg(feature = "gui")]
pub(super) fn frames_range(
    a: &super::impact::AnimateArgs,
    around_which: Option<&str>,
    impacts: &[pounding::model::building::result::ImpactEvent],
    whole: (f64, f64),
) -> anyhow::Result<(f64, f64)> {
    let default = match around_which {
        None => whole,
        Some(which) => around(impacts, which, whole.1)?,
    };
    a.range(default, whole.1)
}

/// The frames' range around one impact (`strongest`, or K from 1): twice its duration before
/// and after it, at least 20 ms a side, within the run.
#[cfg(feature = "gui")]
fn around(
    impacts: &[pounding::model::building::result::ImpactEvent],
    which: &str,
    end: f64,
) -> anyhow::Result<(f64, f64)> {
    let n = impacts.len();
    if n == 0 {
        anyhow::bail!("--animate-around: the run has no impact to show");
    }
    let k = match which.trim() {
        "strongest" => impacts
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.peak_force_n.total_cmp(&b.1.peak_force_n))
            .map(|(k, _)| k)
            .unwrap_or(0),
        text => match text.parse::<usize>() {
            Ok(k) if (1..=n).contains(&k) => k - 1,
            _ => anyhow::bail!(
                "--animate-around: '{text}': expected strongest or an impact's number from 1 to {n}"
            ),
        },
    };
    let i = &impacts[k];
    let pad = (2.0 * (i.end_s - i.start_s)).max(0.02);
    Ok(((i.start_s - pad).max(0.0), (i.end_s + pad).min(end)))
}

#[cfg(not(feature = "gui"))]
fn write_animation(
    _: &BuildingArgs,
    _: &BuildingSetup,
    _: &GroundMotion,
    _: &pounding::model::building::BuildingResult,
) -> anyhow::Result<()> {
    Ok(())
}

pub fn run(args: &BuildingArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if args.common.list_keys {
        return super::list(
            out,
            26,
            BUILDING_SETTINGS.iter().map(|s| (s.key, s.describe())),
        );
    }
    if args.common.list_presets {
        return super::list_presets(out, "buildings");
    }
    let (mut setup, preset_name) = setup(
        args.common.preset.as_deref(),
        &args.common.set,
        args.motion.as_deref(),
    )?;
    if let Some(c) = &args.contact {
        setup.scenario.contact = ContactModel::from_name(c)
            .ok_or_else(|| anyhow::anyhow!("--contact: unknown model '{c}': allowed sears|linear|kelvin|hertz|hertzdamp|jankowski|stereo|none"))?;
    }
    args.animation.check()?;
    if !(1.0..=500.0).contains(&args.animate_drift) {
        anyhow::bail!(
            "--animate-drift: {} is outside 1 to 500",
            args.animate_drift
        );
    }
    let motion = load_motion(&setup)?;
    let quiet = args.common.quiet || args.common.json;
    // The run with its error estimate and the run without contact, side by side, all three
    // under the bar and Ctrl-C. Histories only where a plot, a CSV or an animation draws them:
    // the report reads the summaries.
    let histories =
        args.common.plot.is_some() || args.common.csv.is_some() || args.animation.animate.is_some();
    let pounding::model::building::Checked {
        result,
        estimate,
        baseline,
    } = super::with_control("buildings", quiet, |control| {
        if histories {
            pounding::model::building::solve_checked(&setup.scenario, &motion, control)
        } else {
            pounding::model::building::solve_checked_summary(&setup.scenario, &motion, control)
        }
    })?;
    write_animation(args, &setup, &motion, &result)?;
    args.common.write_plot((1200, 600), || {
        let points = result
            .time_s
            .iter()
            .zip(&result.force_n)
            .map(|(t, f)| (*t, f * 1e-6))
            .collect();
        pounding::export::plot::LinePlot::new(
            format!(
                "Pounding force: {} contact, {}",
                result.contact.name(),
                motion.name
            ),
            "time [s]",
            "pounding force [MN]",
            vec![pounding::export::plot::Series {
                name: result.contact.name().into(),
                points,
            }],
        )
    })?;
    if let Some(path) = &args.common.csv {
        super::write_csv(out, path, |w| {
            pounding::io::csv::write_building_history(w, &result)
        })?;
    }
    let unused = super::unused_settings(&args.common.set, |k| setup.unused(k));
    if args.common.json {
        let mut report = BuildingReport::new(
            &setup,
            preset_name,
            &motion,
            &result,
            &baseline,
            estimate.as_ref(),
        );
        report.warnings.extend(unused);
        writeln!(out, "{}", serde_json::to_string_pretty(&report)?)?;
    } else if !super::csv_to_stdout(args.common.csv.as_deref()) {
        write!(
            out,
            "{}",
            summary(
                &setup,
                preset_name,
                &motion,
                &result,
                &baseline,
                estimate.as_ref()
            )
        )?;
        super::write_unused(out, &unused)?;
    }
    Ok(())
}
