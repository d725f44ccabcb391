//! `pounding impact`: one impact, summarised, as JSON, or as CSV histories.

use super::report::{ImpactReport, summary};
use crate::io::preset::{self, DEFAULT_PRESET};
use crate::io::settings::IMPACT_KEYS;
use crate::model::impact::{ModelKind, solve};
use anyhow::bail;
use clap::Args;
use std::io::Write;

#[derive(Args, Debug, Default)]
pub struct ImpactArgs {
    #[command(flatten)]
    pub common: super::SceneArgs,
    /// Model: sears|wave|lumped-hertz|lumped-linear|kelvin|stereo|fe [default: the preset's]
    #[arg(long, value_name = "MODEL")]
    pub model: Option<String>,
}

pub fn run(args: &ImpactArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if args.common.list_keys {
        return super::list(
            out,
            22,
            IMPACT_KEYS.iter().map(|(k, w)| (*k, w.to_string())),
        );
    }
    if args.common.list_presets {
        return super::list_presets(out, "impact");
    }
    let preset_name = args.common.preset.as_deref().unwrap_or(DEFAULT_PRESET);
    let mut setup: crate::io::settings::ImpactSetup =
        preset::load_for(preset_name, "impact").map_err(|e| anyhow::anyhow!("preset {e}"))?;
    for assignment in &args.common.set {
        setup
            .apply_assignment(assignment)
            .map_err(|e| anyhow::anyhow!("--set {e}"))?;
    }
    if let Some(m) = &args.model {
        setup.model = match ModelKind::from_name(m) {
            Some(k) => k,
            None => bail!(
                "--model: unknown model '{m}': allowed sears|wave|lumped-hertz|lumped-linear|kelvin|stereo|fe"
            ),
        };
    }
    let result = solve(setup.model, &setup.scenario)?;
    let estimate =
        crate::model::impact::estimate::estimate_error(setup.model, &setup.scenario, &result).ok();
    if let Some(path) = &args.common.plot {
        use crate::export::plot::{LinePlot, Series};
        let points = result
            .time_s
            .iter()
            .zip(&result.force_n)
            .map(|(t, f)| (t * 1e3, f * 1e-3))
            .collect();
        LinePlot {
            title: format!("Contact force: {} ({})", setup.model.name(), preset_name),
            x_label: "time [ms]".into(),
            y_label: "force [kN]".into(),
            log_x: false,
            log_y: false,
            series: vec![Series {
                name: setup.model.name().into(),
                points,
            }],
            size: args.common.plot_size.unwrap_or((1000, 600)),
            markers: false,
            scale: args.common.plot_scale,
            x_range: None,
            y_range: None,
        }
        .write(path)
        .map_err(|e| anyhow::anyhow!("--plot: {e}"))?;
    }
    if let Some(path) = &args.common.csv {
        super::write_csv(out, path, |w| {
            crate::io::csv::write_impact_history(w, &result)
        })?;
    }
    if args.common.json {
        let report = ImpactReport::new(&setup, preset_name, &result, estimate.as_ref());
        writeln!(out, "{}", serde_json::to_string_pretty(&report)?)?;
    } else if args
        .common
        .csv
        .as_ref()
        .is_none_or(|p| p.as_os_str() != "-")
    {
        write!(
            out,
            "{}",
            summary(&setup, preset_name, &result, estimate.as_ref())
        )?;
    }
    Ok(())
}
