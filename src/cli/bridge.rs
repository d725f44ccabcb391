//! `pounding bridge`: a bridge's girders pounding at their joints under a ground motion.

use super::bridge_report::{BridgeReport, Runs, summary};
use clap::Args;
use pounding::io::bridge_settings::BridgeSetup;
use pounding::io::preset;
use pounding::model::bridge::{BridgeScenario, estimate_error, solve_with};
use pounding::model::building::ContactModel;
use pounding::model::motion::GroundMotion;
use pounding::model::settings::BRIDGE_SETTINGS;
use std::io::Write;
use std::path::PathBuf;

/// The preset `pounding bridge` runs when given none.
pub const DEFAULT_PRESET: &str = "bridge-3-span";

#[derive(Args, Debug, Default)]
pub struct BridgeArgs {
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
    /// Slow motion around one impact: `strongest`, or its number K from 1 (the frames span
    /// twice its duration before and after it)
    #[arg(long, value_name = "strongest|K", requires = "animate", conflicts_with_all = ["animate_from", "animate_to"])]
    pub animate_around: Option<String>,
}

/// Writes --animate, if asked for: the bridge in elevation as the window draws it.
#[cfg(feature = "gui")]
fn write_animation(
    args: &BridgeArgs,
    setup: &BridgeSetup,
    motion: &GroundMotion,
    result: &pounding::model::bridge::BridgeResult,
) -> anyhow::Result<()> {
    let a = &args.animation;
    if a.animate.is_none() {
        return Ok(());
    }
    let title = format!(
        "A bridge: {} contact, {}",
        result.contact.name(),
        motion.short_name()
    );
    let mut animation = pounding::render::animate_bridge::BridgeAnimation::new(
        setup.clone(),
        motion.clone(),
        result.clone(),
        title,
        a.animate_size,
        a.animate_frames,
    );
    animation.t_range = super::buildings::frames_range(
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

#[cfg(not(feature = "gui"))]
fn write_animation(
    _: &BridgeArgs,
    _: &BridgeSetup,
    _: &GroundMotion,
    _: &pounding::model::bridge::BridgeResult,
) -> anyhow::Result<()> {
    Ok(())
}

/// The preset (or `bridge-3-span`) with the --set overrides, --motion and --contact applied.
pub fn setup(args: &BridgeArgs) -> anyhow::Result<(BridgeSetup, &str)> {
    let preset_name = args.common.preset.as_deref().unwrap_or(DEFAULT_PRESET);
    let mut setup: BridgeSetup =
        preset::load_for(preset_name, "bridge").map_err(super::preset_error)?;
    for a in &args.common.set {
        setup
            .apply_assignment(a)
            .map_err(|e| anyhow::anyhow!("--set {e}"))?;
    }
    if let Some(path) = &args.motion {
        setup
            .motion
            .set_source(&path.display().to_string())
            .map_err(|e| anyhow::anyhow!("--motion {e}"))?;
    }
    if let Some(c) = &args.contact {
        setup.scenario.contact = ContactModel::from_name(c).ok_or_else(|| {
            anyhow::anyhow!(
                "--contact: unknown model '{c}': allowed {}",
                ContactModel::NAMES.join("|")
            )
        })?;
    }
    Ok((setup, preset_name))
}

fn force_plot(
    r: &pounding::model::bridge::BridgeResult,
    motion: &GroundMotion,
) -> pounding::export::plot::LinePlot {
    pounding::export::bridge_plots::joint_forces(
        r,
        format!(
            "Joint forces: {} contact, {}",
            r.contact.name(),
            motion.name
        ),
    )
}

pub fn run(args: &BridgeArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if args.common.list_keys {
        return super::list(
            out,
            28,
            BRIDGE_SETTINGS.iter().map(|s| (s.key, s.describe())),
        );
    }
    if args.common.list_presets {
        return super::list_presets(out, "bridge");
    }
    let (setup, preset_name) = setup(args)?;
    setup
        .scenario
        .validate()
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    args.animation.check()?;
    let motion =
        pounding::io::motion::load(&setup.motion).map_err(|e| anyhow::anyhow!("--motion {e}"))?;
    let quiet = args.common.quiet || args.common.json;
    let sc = &setup.scenario;
    let (result, estimate, baseline) = super::with_control("bridge", quiet, |control| {
        control.stage(0, 3);
        let result = solve_with(sc, &motion, control)?;
        control.stage(1, 3);
        let estimate = estimate_error(sc, &motion, &result, control).ok();
        control.stage(2, 3);
        let free = BridgeScenario {
            contact: ContactModel::None,
            ..sc.clone()
        };
        let baseline = solve_with(&free, &motion, control)?;
        Ok::<_, pounding::model::error::SolveError>((result, estimate, baseline))
    })?;
    write_animation(args, &setup, &motion, &result)?;
    let runs = Runs {
        result: &result,
        baseline: &baseline,
        estimate: estimate.as_ref(),
    };
    args.common
        .write_plot((1200, 600), || force_plot(&result, &motion))?;
    if let Some(path) = &args.common.csv {
        super::write_csv(out, path, |w| {
            pounding::io::csv::write_bridge_history(w, &result)
        })?;
    }
    let unused = super::unused_settings(&args.common.set, |k| setup.unused(k));
    if args.common.json {
        let mut report = BridgeReport::new(&setup, preset_name, &motion, &runs);
        report.warnings.extend(unused);
        writeln!(out, "{}", serde_json::to_string_pretty(&report)?)?;
    } else if !super::csv_to_stdout(args.common.csv.as_deref()) {
        write!(out, "{}", summary(&setup, preset_name, &motion, &runs))?;
        super::write_unused(out, &unused)?;
    }
    Ok(())
}
