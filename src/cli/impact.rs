//! `pounding impact`: one impact, summarised, as JSON, or as CSV histories.

use super::report::{ImpactReport, summary};
use clap::Args;
use pounding::export::plot::{LinePlot, Series};
use pounding::io::preset::{self, DEFAULT_PRESET};
use pounding::io::settings::ImpactSetup;
use pounding::model::impact::{ModelKind, solve};
use pounding::model::settings::IMPACT_SETTINGS;
use std::io::Write;

#[derive(Args, Debug, Default)]
pub struct ImpactArgs {
    #[command(flatten)]
    pub common: super::SceneArgs,
    /// Model: sears|wave|lumped-hertz|lumped-linear|kelvin|stereo|fe [default: the preset's]
    #[arg(long, value_name = "MODEL")]
    pub model: Option<String>,
}

/// Answers --list-keys and --list-presets for impact commands; `true` when it did.
pub(super) fn answered_lists(
    common: &super::SceneArgs,
    out: &mut dyn Write,
) -> anyhow::Result<bool> {
    if common.list_keys {
        super::list(
            out,
            22,
            IMPACT_SETTINGS.iter().map(|s| (s.key, s.describe())),
        )?;
    } else if common.list_presets {
        super::list_presets(out, "impact")?;
    }
    Ok(common.list_keys || common.list_presets)
}

/// The preset (or the default) with the --set overrides applied, and the preset's name.
pub(super) fn setup(common: &super::SceneArgs) -> anyhow::Result<(ImpactSetup, &str)> {
    let preset_name = common.preset.as_deref().unwrap_or(DEFAULT_PRESET);
    let mut setup: ImpactSetup =
        preset::load_for(preset_name, "impact").map_err(|e| anyhow::anyhow!("preset {e}"))?;
    for assignment in &common.set {
        setup
            .apply_assignment(assignment)
            .map_err(|e| anyhow::anyhow!("--set {e}"))?;
    }
    Ok((setup, preset_name))
}

pub(super) fn parse_model(name: &str) -> anyhow::Result<ModelKind> {
    ModelKind::from_name(name).ok_or_else(|| {
        anyhow::anyhow!(
            "--model: unknown model '{name}': allowed sears|wave|lumped-hertz|lumped-linear|kelvin|stereo|fe"
        )
    })
}

pub fn run(args: &ImpactArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if answered_lists(&args.common, out)? {
        return Ok(());
    }
    let (mut setup, preset_name) = setup(&args.common)?;
    if let Some(m) = &args.model {
        setup.model = parse_model(m)?;
    }
    let result = solve(setup.model, &setup.scenario)?;
    let estimate =
        pounding::model::impact::estimate::estimate_error(setup.model, &setup.scenario, &result)
            .ok();
    args.common.write_plot((1000, 600), || {
        let points = result
            .time_s
            .iter()
            .zip(&result.force_n)
            .map(|(t, f)| (t * 1e3, f * 1e-3))
            .collect();
        LinePlot::new(
            format!("Contact force: {} ({})", setup.model.name(), preset_name),
            "time [ms]",
            "force [kN]",
            vec![Series {
                name: setup.model.name().into(),
                points,
            }],
        )
    })?;
    if let Some(path) = &args.common.csv {
        super::write_csv(out, path, |w| {
            pounding::io::csv::write_impact_history(w, &result)
        })?;
    }
    if args.common.json {
        let report = ImpactReport::new(&setup, preset_name, &result, estimate.as_ref());
        writeln!(out, "{}", serde_json::to_string_pretty(&report)?)?;
    } else if !super::csv_to_stdout(args.common.csv.as_deref()) {
        write!(
            out,
            "{}",
            summary(&setup, preset_name, &result, estimate.as_ref())
        )?;
    }
    Ok(())
}
