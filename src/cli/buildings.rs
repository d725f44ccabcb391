//! `pounding buildings`: two buildings under a ground motion, pounding.

use super::building_report::{BuildingReport, summary};
use crate::io::building_settings::{BUILDING_KEYS, BuildingSetup};
use crate::io::preset::{self, EMBEDDED};
use crate::model::building::{BuildingScenario, ContactModel, solve};
use crate::model::motion::GroundMotion;
use anyhow::{Context, bail};
use clap::Args;
use std::io::Write;
use std::path::PathBuf;

#[derive(Args, Debug, Default)]
pub struct BuildingArgs {
    /// Preset name (a file stem in assets/presets/) or path to a TOML file [default: paper-buildings]
    #[arg(long, value_name = "NAME-or-FILE")]
    pub preset: Option<String>,
    /// Ground motion file: PEER .AT2 or text [default: a seeded synthetic record]
    #[arg(long, value_name = "FILE")]
    pub motion: Option<PathBuf>,
    /// Contact model: sears|linear|kelvin|hertz|hertzdamp|jankowski|stereo|none [default: the preset's]
    #[arg(long, value_name = "MODEL")]
    pub contact: Option<String>,
    /// Override a setting, e.g. --set left.damping_ratio=0.02 (repeatable; see --list-keys)
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Write the histories as CSV (`-` for standard output)
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

/// Reads or generates the ground motion a setup asks for.
pub fn load_motion(setup: &BuildingSetup) -> anyhow::Result<GroundMotion> {
    let m = &setup.motion;
    let mut motion = match &m.file {
        Some(path) => {
            let text = std::fs::read_to_string(path)
                .with_context(|| format!("--motion: cannot read {path}"))?;
            crate::io::motion::parse(&text, path, m.units, m.dt_s)
                .map_err(|e| anyhow::anyhow!("--motion {e}"))?
        }
        None => m.synthetic.generate(),
    };
    if let Some(d) = m.duration_s {
        motion = motion.truncated(d);
    }
    if m.scale != 1.0 {
        motion = motion.scaled(m.scale);
    }
    if motion.accel_m_s2.len() < 2 {
        bail!("the ground motion has fewer than two samples");
    }
    Ok(motion)
}

pub fn run(args: &BuildingArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if args.list_keys {
        for (k, what) in BUILDING_KEYS {
            writeln!(out, "{k:26} {what}")?;
        }
        return Ok(());
    }
    if args.list_presets {
        for (name, text) in EMBEDDED
            .iter()
            .filter(|(_, t)| preset::scene(t) == "buildings")
        {
            writeln!(
                out,
                "{name:16} {}",
                preset::description(text).unwrap_or_default()
            )?;
        }
        return Ok(());
    }
    let preset_name = args.preset.as_deref().unwrap_or("paper-buildings");
    let mut setup: BuildingSetup =
        preset::load_for(preset_name, "buildings").map_err(|e| anyhow::anyhow!("preset {e}"))?;
    for a in &args.set {
        setup
            .apply_assignment(a)
            .map_err(|e| anyhow::anyhow!("--set {e}"))?;
    }
    if let Some(c) = &args.contact {
        setup.scenario.contact = ContactModel::from_name(c)
            .ok_or_else(|| anyhow::anyhow!("--contact: unknown model '{c}': allowed sears|linear|kelvin|hertz|hertzdamp|jankowski|stereo|none"))?;
    }
    if let Some(path) = &args.motion {
        setup.motion.file = Some(path.display().to_string());
    }
    let motion = load_motion(&setup)?;
    let result = solve(&setup.scenario, &motion)?;
    let baseline = solve(
        &BuildingScenario {
            contact: ContactModel::None,
            ..setup.scenario
        },
        &motion,
    )?;
    if let Some(path) = &args.csv {
        if path.as_os_str() == "-" {
            crate::io::csv::write_building_history(out, &result)?;
        } else {
            let file = std::fs::File::create(path)
                .with_context(|| format!("--csv: cannot create {}", path.display()))?;
            let mut w = std::io::BufWriter::new(file);
            crate::io::csv::write_building_history(&mut w, &result)
                .and_then(|_| w.flush())
                .with_context(|| format!("--csv: cannot write {}", path.display()))?;
        }
    }
    if args.json {
        let report = BuildingReport::new(&setup, preset_name, &motion, &result, &baseline);
        writeln!(out, "{}", serde_json::to_string_pretty(&report)?)?;
    } else if args.csv.as_ref().is_none_or(|p| p.as_os_str() != "-") {
        write!(
            out,
            "{}",
            summary(&setup, preset_name, &motion, &result, &baseline)
        )?;
    }
    Ok(())
}
