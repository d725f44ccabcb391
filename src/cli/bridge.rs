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
