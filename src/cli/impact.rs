//! `pounding impact`: one impact, summarised, as JSON, or as CSV histories.

use super::report::{ImpactReport, summary};
use crate::io::preset::{self, DEFAULT_PRESET, EMBEDDED};
use crate::io::settings::IMPACT_KEYS;
use crate::model::impact::{ModelKind, solve};
use anyhow::{Context, bail};
use clap::Args;
use std::io::Write;
use std::path::PathBuf;

#[derive(Args, Debug, Default)]
pub struct ImpactArgs {
    /// Preset name (a file stem in assets/presets/) or path to a TOML file [default: paper-base]
    #[arg(long, value_name = "NAME-or-FILE")]
    pub preset: Option<String>,
    /// Override a setting, e.g. --set bar2.length=5 (repeatable; see --list-keys)
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Model: sears|wave|lumped-hertz|lumped-linear|kelvin|stereo|fe [default: the preset's]
    #[arg(long, value_name = "MODEL")]
    pub model: Option<String>,
    /// Write the force and approach histories as CSV (`-` for standard output)
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
    /// Print one JSON object instead of the summary
    #[arg(long)]
    pub json: bool,
    /// List the keys --set accepts, and exit
    #[arg(long)]
    pub list_keys: bool,
    /// List the shipped presets, and exit
    #[arg(long)]
    pub list_presets: bool,
}

pub fn run(args: &ImpactArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if args.list_keys {
        for (k, what) in IMPACT_KEYS {
            writeln!(out, "{k:22} {what}")?;
        }
        return Ok(());
    }
    if args.list_presets {
        for (name, text) in EMBEDDED
            .iter()
            .filter(|(_, t)| preset::scene(t) == "impact")
        {
            writeln!(
                out,
                "{name:14} {}",
                preset::description(text).unwrap_or_default()
            )?;
        }
        return Ok(());
    }
    let preset_name = args.preset.as_deref().unwrap_or(DEFAULT_PRESET);
    let mut setup: crate::io::settings::ImpactSetup =
        preset::load_for(preset_name, "impact").map_err(|e| anyhow::anyhow!("preset {e}"))?;
    for assignment in &args.set {
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
    if let Some(path) = &args.csv {
        if path.as_os_str() == "-" {
            crate::io::csv::write_impact_history(out, &result)?;
        } else {
            let file = std::fs::File::create(path)
                .with_context(|| format!("--csv: cannot create {}", path.display()))?;
            let mut w = std::io::BufWriter::new(file);
            crate::io::csv::write_impact_history(&mut w, &result)
                .and_then(|_| w.flush())
                .with_context(|| format!("--csv: cannot write {}", path.display()))?;
        }
    }
    if args.json {
        let report = ImpactReport::new(&setup, preset_name, &result);
        writeln!(out, "{}", serde_json::to_string_pretty(&report)?)?;
    } else if args.csv.as_ref().is_none_or(|p| p.as_os_str() != "-") {
        write!(out, "{}", summary(&setup, preset_name, &result))?;
    }
    Ok(())
}
