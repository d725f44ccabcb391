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
    /// Write the space-time (x-t) diagram: an image (.png) or its grid (.csv, the rows
    /// bar,x_m,t_s,stress_pa,velocity_m_s)
    #[arg(long, value_name = "FILE")]
    pub xt: Option<std::path::PathBuf>,
    /// The field the x-t image shows: stress|velocity
    #[arg(long, value_name = "FIELD", default_value = "stress")]
    pub xt_field: String,
    /// The x-t grid: NX points along each bar, NT times
    #[arg(long, value_name = "NXxNT", default_value = "200x400", value_parser = parse_grid, allow_hyphen_values = true)]
    pub xt_grid: (usize, usize),
    /// Write the energy over time as CSV: time_s,rigid_kinetic_j,wave_j,contact_j,dissipated_j,total_j
    #[arg(long, value_name = "FILE")]
    pub energy: Option<std::path::PathBuf>,
    #[command(flatten)]
    pub animation: AnimateArgs,
    /// The animation's view: bars|xt|both
    #[arg(
        long,
        value_name = "VIEW",
        default_value = "both",
        requires = "animate"
    )]
    pub animate_view: String,
}

/// The animation flags `impact` and `buildings` share.
#[derive(Args, Debug, Default)]
pub struct AnimateArgs {
    /// Write an animation for slides: .gif, or .png (APNG), rendered offscreen by the window's
    /// GPU pipelines (a software adapter will do)
    #[arg(long, value_name = "FILE")]
    pub animate: Option<std::path::PathBuf>,
    /// Frames in the animation (2 to 2000)
    #[arg(long, value_name = "N", default_value_t = 120, requires = "animate", allow_hyphen_values = true, value_parser = parse_frames)]
    pub animate_frames: usize,
    /// Frames per second (1 to 50)
    #[arg(long, value_name = "F", default_value_t = 30.0, requires = "animate", allow_hyphen_values = true, value_parser = parse_fps)]
    pub animate_fps: f64,
    /// The animation's first frame at this time [s] (default: the run's start)
    #[arg(long, value_name = "S", requires = "animate", allow_hyphen_values = true, value_parser = parse_time)]
    pub animate_from: Option<f64>,
    /// The animation's last frame at this time [s] (default: the run's end)
    #[arg(long, value_name = "S", requires = "animate", allow_hyphen_values = true, value_parser = parse_time)]
    pub animate_to: Option<f64>,
    /// The animation's pixel size, WIDTHxHEIGHT, each 16 to 8192
    #[arg(long, value_name = "WxH", default_value = "1280x720", requires = "animate", allow_hyphen_values = true, value_parser = parse_animate_size)]
    pub animate_size: (u32, u32),
}

impl AnimateArgs {
    /// The frames' time range within a run of `0..=end` seconds: `--animate-from` and
    /// `--animate-to` where given (checked against the run), else `default`.
    #[cfg(feature = "gui")]
    pub fn range(&self, default: (f64, f64), end: f64) -> anyhow::Result<(f64, f64)> {
        let from = self.animate_from.unwrap_or(default.0);
        let to = self.animate_to.unwrap_or(default.1);
        for (flag, t) in [("--animate-from", from), ("--animate-to", to)] {
            if !(0.0..=end).contains(&t) {
                anyhow::bail!("{flag}: {t} s is outside the run, 0 to {end:.4} s");
            }
        }
        if to <= from {
            anyhow::bail!("--animate-to: {to} s is not after --animate-from ({from} s)");
        }
        Ok((from, to))
    }

    /// Checks the frame count and rate before a solve is spent on them.
    pub fn check(&self) -> anyhow::Result<()> {
        if let Some(path) = &self.animate {
            use pounding::export::animation::{AnimationError, AnimationFormat, check_timing};
            AnimationFormat::of_path(path).map_err(|e| anyhow::anyhow!("--animate: {e}"))?;
            check_timing(self.animate_frames, self.animate_fps).map_err(|e| match e {
                AnimationError::Frames(_) => anyhow::anyhow!("--animate-frames: {e}"),
                _ => anyhow::anyhow!("--animate-fps: {e}"),
            })?;
            #[cfg(not(feature = "gui"))]
            anyhow::bail!(
                "--animate: this pounding was built without the `gui` feature, which holds the \
                 GPU renderer the animation needs; build it with the default features"
            );
        }
        Ok(())
    }

    /// Renders `frames` frames with `frame` into --animate, showing a progress bar on standard
    /// error (a terminal only; hidden with `quiet`: --json or --quiet).
    #[cfg(feature = "gui")]
    pub fn write(
        &self,
        quiet: bool,
        write: impl FnOnce(
            &mut pounding::render::offscreen::Offscreen,
            &std::path::Path,
            &mut dyn FnMut(usize),
        ) -> Result<(), pounding::export::animation::AnimationError>,
    ) -> anyhow::Result<()> {
        let Some(path) = &self.animate else {
            return Ok(());
        };
        let mut target = pounding::render::offscreen::Offscreen::headless(self.animate_size)
            .map_err(|e| anyhow::anyhow!("--animate: {e}"))?;
        let bar = if quiet {
            indicatif::ProgressBar::hidden()
        } else {
            indicatif::ProgressBar::new(self.animate_frames as u64)
        };
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "{prefix:>12} [{bar:40}] {pos}/{len} frames, {elapsed}",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
            .progress_chars("=> "),
        );
        bar.set_prefix("animation");
        let done = write(&mut target, path, &mut |k| bar.set_position(k as u64));
        bar.finish_and_clear();
        done.map_err(|e| anyhow::anyhow!("--animate: {e}"))
    }
}

/// NXxNT, each 2 to 20000, at most 4e7 points in all.
fn parse_time(text: &str) -> Result<f64, String> {
    super::parse_number_in(text, 0.0, 1e6)
}

fn parse_frames(text: &str) -> Result<usize, String> {
    use pounding::export::animation::FRAMES_RANGE;
    super::parse_whole_in(text, *FRAMES_RANGE.start(), *FRAMES_RANGE.end())
}

fn parse_fps(text: &str) -> Result<f64, String> {
    use pounding::export::animation::FPS_RANGE;
    super::parse_number_in(text, *FPS_RANGE.start(), *FPS_RANGE.end())
}

/// An animation's size: the offscreen target's limits, not a plot's.
fn parse_animate_size(text: &str) -> Result<(u32, u32), String> {
    use pounding::export::animation::SIDE_RANGE;
    let (lo, hi) = (*SIDE_RANGE.start(), *SIDE_RANGE.end());
    let bad = || format!("'{text}': expected WIDTHxHEIGHT in pixels, each {lo} to {hi}");
    let (w, h) = text.split_once(['x', 'X']).ok_or_else(bad)?;
    let (w, h): (u32, u32) = (
        w.trim().parse().map_err(|_| bad())?,
        h.trim().parse().map_err(|_| bad())?,
    );
    if SIDE_RANGE.contains(&w) && SIDE_RANGE.contains(&h) {
        Ok((w, h))
    } else {
        Err(bad())
    }
}

fn parse_grid(text: &str) -> Result<(usize, usize), String> {
    let bad = || {
        format!(
            "'{text}': expected NXxNT, each 2 to 20000 (NX points along each bar, NT times), at most 4e7 points"
        )
    };
    let (a, b) = text.split_once(['x', 'X']).ok_or_else(bad)?;
    let (nx, nt): (usize, usize) = (
        a.trim().parse().map_err(|_| bad())?,
        b.trim().parse().map_err(|_| bad())?,
    );
    if (2..=20_000).contains(&nx) && (2..=20_000).contains(&nt) && nx * nt <= 40_000_000 {
        Ok((nx, nt))
    } else {
        Err(bad())
    }
}

/// Writes the x-t diagram (`--xt`) and the energy history (`--energy`) asked for.
fn write_instruments(
    args: &ImpactArgs,
    setup: &ImpactSetup,
    preset_name: &str,
    r: &pounding::model::impact::ImpactResult,
    out: &mut dyn Write,
) -> anyhow::Result<()> {
    use pounding::model::xt::{XtField, XtGrid};
    if let Some(path) = &args.xt {
        let field = XtField::from_name(&args.xt_field).ok_or_else(|| {
            anyhow::anyhow!(
                "--xt-field: unknown field '{}': allowed stress|velocity",
                args.xt_field
            )
        })?;
        let sc = &setup.scenario;
        let (nx, nt) = args.xt_grid;
        let grid = XtGrid::of(
            r,
            [sc.bar1.area_m2(), sc.bar2.area_m2()],
            [sc.bar1.length_m, sc.bar2.length_m],
            nx,
            nt,
            r.view_span_s(),
        );
        let ext = pounding::export::extension(path);
        match ext.as_str() {
            "csv" => super::write_csv(out, path, |w| pounding::io::csv::write_xt(w, &grid))
                .map_err(|e| anyhow::anyhow!("--xt: {e}"))?,
            "png" => pounding::export::xt::XtImage {
                grid: &grid,
                field,
                title: format!(
                    "x-t diagram: {} ({}), {}",
                    setup.model.name(),
                    preset_name,
                    field.name()
                ),
                size: args.common.plot_size.unwrap_or((1000, 700)),
                scale: args.common.plot_scale.unwrap_or(1.0),
                zones_m: r
                    .sears
                    .filter(|s| s.reading != pounding::model::scenario::Reading::End)
                    .map(|s| s.zone_lengths_m),
            }
            .write_png(path)
            .map_err(|e| anyhow::anyhow!("--xt: {e}"))?,
            _ => anyhow::bail!(
                "--xt: {}: the extension must be .png (the image) or .csv (the grid)",
                path.display()
            ),
        }
    }
    if let Some(path) = &args.energy {
        let h = pounding::model::impact::energy::energy_history(&setup.scenario, r, 1000);
        super::write_csv(out, path, |w| pounding::io::csv::write_energy(w, &h))
            .map_err(|e| anyhow::anyhow!("--energy: {e}"))?;
    }
    Ok(())
}

#[cfg(feature = "gui")]
use pounding::render::animate::AnimView;

/// The views an animation may show (the names only, when the renderer is not built in).
#[cfg(not(feature = "gui"))]
struct AnimView;

#[cfg(not(feature = "gui"))]
impl AnimView {
    const NAMES: &str = "bars|xt|both";
    fn from_name(name: &str) -> Option<Self> {
        Self::NAMES
            .split('|')
            .any(|n| n == name)
            .then_some(AnimView)
    }
}

/// Writes --animate, if asked for.
#[cfg(feature = "gui")]
fn write_animation(
    args: &ImpactArgs,
    setup: &ImpactSetup,
    preset_name: &str,
    view: AnimView,
    r: &pounding::model::impact::ImpactResult,
) -> anyhow::Result<()> {
    let a = &args.animation;
    let shown = match view {
        AnimView::Bars => "stress waves in the bars",
        AnimView::Xt => "x-t diagram",
        AnimView::Both => "stress waves and their x-t diagram",
    };
    let title = format!("{} ({preset_name}): {shown}", setup.model.name());
    let mut animation = pounding::render::animate::ImpactAnimation::new(
        &setup.scenario,
        r,
        title,
        view,
        a.animate_size,
        a.animate_frames,
    );
    animation.t_range = a.range(animation.t_range, animation.t_range.1)?;
    a.write(
        args.common.json || args.common.quiet,
        |target, path, progress| animation.write(target, path, a.animate_fps, progress),
    )
}

#[cfg(not(feature = "gui"))]
fn write_animation(
    _: &ImpactArgs,
    _: &ImpactSetup,
    _: &str,
    _: AnimView,
    _: &pounding::model::impact::ImpactResult,
) -> anyhow::Result<()> {
    Ok(())
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
        preset::load_for(preset_name, "impact").map_err(super::preset_error)?;
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
    args.animation.check()?;
    let view = AnimView::from_name(&args.animate_view).ok_or_else(|| {
        anyhow::anyhow!(
            "--animate-view: unknown view '{}': allowed {}",
            args.animate_view,
            AnimView::NAMES
        )
    })?;
    let result = solve(setup.model, &setup.scenario)?;
    write_animation(args, &setup, preset_name, view, &result)?;
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
    write_instruments(args, &setup, preset_name, &result, out)?;
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
