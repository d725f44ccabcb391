//! The paper's parametric study (Section 3, Figures 4 to 9) as built-in studies, one file per
//! section of the paper. Every study starts
//! from the paper's base case (the `paper-base` preset: steel rods of 0.1 m diameter, 1 m/s, a
//! rounded end of 0.1 m diameter against a flat end, Sears in the paper's reading) or, for the slab
//! study, from `paper-slabs`, and changes only what the figure varies.
//!
//! Restitution is the paper's: from the impulse of the first contact.

mod lengths;
mod mass;
mod material;
mod slabs;
mod stiffness;
mod velocity;
mod zone;

use super::{Context, Figure, Finding, Study, StudyError, finding, par_map};
use crate::export::plot::{LinePlot, Series};
use crate::io::preset;
use crate::io::settings::ImpactSetup;
use crate::model::impact::{ImpactResult, ModelKind, SolveError, solve};
use crate::model::settings::{Setting, impact};

pub const STUDIES: &[Study] = &[
    Study {
        name: "fig4-lengths",
        paper: "Fig. 4 (Section 3.1)",
        about: "Sears force histories for bar pairs from 0.1/0.2 m to 5/10 m, against the wave-theory limit",
        buildings: false,
        run: lengths::lengths,
    },
    Study {
        name: "fig5-models",
        paper: "Fig. 5 (Section 3.1)",
        about: "Sears, lumped Hertz and wave theory for equal bars of 0.1, 1 and 10 m",
        buildings: false,
        run: lengths::models,
    },
    Study {
        name: "fig6-restitution",
        paper: "Fig. 6 (Section 3.1)",
        about: "e against the short bar's length for length ratios 1, 2, 4 and 10; wave theory and lumped Hertz alongside",
        buildings: false,
        run: lengths::restitution,
    },
    Study {
        name: "fig7-velocity",
        paper: "Fig. 7 (Section 3.2)",
        about: "contact duration and e against impact velocity (0.01 to 100 m/s) for 0.1/0.2, 1/2 and 10/20 m bars",
        buildings: false,
        run: velocity::velocity,
    },
    Study {
        name: "mass",
        paper: "Section 3.3",
        about: "contact duration and e against mass (x1 to x100), added as superimposed mass or as a larger section",
        buildings: false,
        run: mass::mass,
    },
    Study {
        name: "stiffness",
        paper: "Section 3.4",
        about: "contact duration and e against the dome diameter (0.01 to 10 m) for short and long bars; force histories",
        buildings: false,
        run: stiffness::stiffness,
    },
    Study {
        name: "zone",
        paper: "Section 3.5",
        about: "peak force against the zone length d (d/100 to 10 d) in the paper and collocated readings; force histories",
        buildings: false,
        run: zone::zone,
    },
    Study {
        name: "fig8-material",
        paper: "Fig. 8 (Section 3.6)",
        about: "steel, M20 concrete, and concrete loaded to the steel bars' mass",
        buildings: false,
        run: material::material,
    },
    Study {
        name: "fig9-slab-n",
        paper: "Fig. 9 (Section 4)",
        about: "concrete slabs 10 m x 8 m x 0.15 m at 1 m/s, linear contact E A/(L/n) for n = 1 to 50",
        buildings: false,
        run: slabs::slab_n,
    },
];

pub(super) fn load(preset_name: &str) -> Result<ImpactSetup, StudyError> {
    Ok(preset::load(preset_name)?)
}

/// `base` with `key=value` assignments applied, validated.
pub(super) fn with(base: &ImpactSetup, sets: &[String]) -> Result<ImpactSetup, StudyError> {
    let mut s = *base;
    let refused = |source| StudyError::Setting {
        assignment: sets.join(", "),
        source,
    };
    for a in sets {
        s.apply_assignment(a).map_err(refused)?;
    }
    s.scenario.validate().map_err(refused)?;
    Ok(s)
}

/// `KEY=VALUE` for `setting` of owner `owner` (0: bar1), as `--set` takes it.
pub(super) fn set(setting: &Setting, owner: usize, value: impl std::fmt::Display) -> String {
    format!("{}={value}", setting.key_of(owner))
}

/// Bars of lengths `l1` and `l2` on top of `base`.
pub(super) fn lengths_of(base: &ImpactSetup, l1: f64, l2: f64) -> Result<ImpactSetup, StudyError> {
    with(
        base,
        &[set(&impact::LENGTH, 0, l1), set(&impact::LENGTH, 1, l2)],
    )
}

/// The quantities a curve is drawn from.
#[derive(Clone, Copy)]
pub(super) struct Summary {
    pub peak_n: f64,
    pub duration_s: f64,
    pub e: f64,
}

pub(super) fn summarise(r: &ImpactResult) -> Summary {
    Summary {
        peak_n: r.peak_force_n.unwrap_or(f64::NAN),
        duration_s: r.contact_duration_s,
        e: r.restitution_first_contact,
    }
}

/// Every job solved in parallel; failures are kept per point (a curve skips them, a note says why).
pub(super) fn summaries(
    ctx: &Context,
    jobs: &[(ModelKind, ImpactSetup)],
) -> Result<Vec<Result<Summary, SolveError>>, StudyError> {
    Ok(par_map(ctx.progress, jobs, |(m, s)| {
        solve(*m, &s.scenario).map(|r| summarise(&r))
    })?)
}

/// Full results, for force histories; any failure fails the study.
pub(super) fn histories(
    ctx: &Context,
    jobs: &[(ModelKind, ImpactSetup)],
) -> Result<Vec<ImpactResult>, StudyError> {
    par_map(ctx.progress, jobs, |(m, s)| solve(*m, &s.scenario))?
        .into_iter()
        .zip(jobs)
        .map(|(r, (m, _))| {
            r.map_err(|source| StudyError::Solve {
                what: format!("a {} solve", m.name()),
                source,
            })
        })
        .collect()
}

/// Force history in ms and kN, closed by a zero after separation so the fall shows.
pub(super) fn force_series(name: impl Into<String>, r: &ImpactResult) -> Series {
    let mut points: Vec<(f64, f64)> = r
        .time_s
        .iter()
        .zip(&r.force_n)
        .map(|(t, f)| (t * 1e3, f * 1e-3))
        .collect();
    if let Some(&(t, _)) = points.last() {
        points.push((t, 0.0));
    }
    Series {
        name: name.into(),
        points,
    }
}

pub(super) fn level(name: &str, y: f64, t_end_ms: f64) -> Series {
    Series {
        name: name.into(),
        points: vec![(0.0, y), (t_end_ms, y)],
    }
}

pub(super) fn end_ms(results: &[ImpactResult]) -> f64 {
    results
        .iter()
        .filter_map(|r| r.time_s.last())
        .fold(0.0, |a, &t| a.max(t * 1e3))
}

pub(super) fn force_plot(title: &str, series: Vec<Series>) -> LinePlot {
    LinePlot::new(title, "time [ms]", "contact force [kN]", series)
}

/// One curve of a family against x, skipping failed points.
pub(super) fn curve(
    name: impl Into<String>,
    xs: &[f64],
    points: &[Result<Summary, SolveError>],
    f: impl Fn(&Summary) -> f64,
) -> Series {
    Series {
        name: name.into(),
        points: xs
            .iter()
            .zip(points)
            .filter_map(|(x, p)| p.as_ref().ok().map(|s| (*x, f(s))))
            .filter(|(_, y)| y.is_finite())
            .collect(),
    }
}

pub(super) fn failures(
    points: &[Result<Summary, SolveError>],
    xs: &[f64],
    what: &str,
) -> Vec<String> {
    points
        .iter()
        .zip(xs.iter().cycle())
        .filter_map(|(p, x)| {
            p.as_ref()
                .err()
                .map(|e| format!("{what} = {x:.4}: no result ({e})"))
        })
        .collect()
}

pub(super) fn geometric(from: f64, to: f64, count: usize) -> Vec<f64> {
    super::sweep::values(from, to, count, true)
}

/// Time to reach 90% of the peak [s].
pub(super) fn rise_time_s(r: &ImpactResult) -> f64 {
    let peak = r.peak_force_n.unwrap_or(0.0);
    r.time_s
        .iter()
        .zip(&r.force_n)
        .find(|(_, f)| **f >= 0.9 * peak)
        .map_or(f64::NAN, |(t, _)| {
            *t - r.contacts.first().map_or(0.0, |c| c.start_s)
        })
}

/// Share of the first contact spent within 2% of `level`.
pub(super) fn plateau_share(r: &ImpactResult, level: f64) -> f64 {
    let n = r.time_s.len();
    if n < 2 || r.contact_duration_s <= 0.0 {
        return 0.0;
    }
    let dt = r.time_s[1] - r.time_s[0];
    let near = r
        .force_n
        .iter()
        .filter(|f| (**f - level).abs() <= 0.02 * level)
        .count();
    (near as f64 * dt / r.contact_duration_s).min(1.0)
}

/// Duration and e of a few bar pairs against one swept setting; returns the two figures.
/// A family's figures, findings and notes.
pub(super) type FamilyOutput = (Vec<Figure>, Vec<Finding>, Vec<String>);

pub(super) struct Family<'a> {
    pub stem: &'a str,
    pub key: &'a str,
    pub x_label: &'a str,
    pub xs: Vec<f64>,
    /// What to set for each x (the swept key alone by default).
    pub sets: &'a dyn Fn(f64) -> Vec<String>,
}

pub(super) fn duration_and_e(
    ctx: &Context,
    fam: &Family,
    pairs: &[(String, ImpactSetup)],
    title: &str,
) -> Result<FamilyOutput, StudyError> {
    let mut jobs = Vec::new();
    for (_, s) in pairs {
        for &x in &fam.xs {
            jobs.push((ModelKind::Sears, with(s, &(fam.sets)(x))?));
        }
    }
    let points = summaries(ctx, &jobs)?;
    let n = fam.xs.len();
    let mut dur = Vec::new();
    let mut e = Vec::new();
    let mut findings = Vec::new();
    for (k, (name, _)) in pairs.iter().enumerate() {
        let block = &points[n * k..n * (k + 1)];
        dur.push(curve(name.clone(), &fam.xs, block, |s| s.duration_s * 1e3));
        e.push(curve(name.clone(), &fam.xs, block, |s| s.e));
        for i in [0, n - 1] {
            if let Ok(s) = &block[i] {
                let at = format!("{name}, {} = {:.4}", fam.key, fam.xs[i])
                    .trim_end_matches('0')
                    .trim_end_matches('.')
                    .to_string();
                findings.push(finding(format!("duration, {at}"), s.duration_s, "s"));
                findings.push(finding(format!("e, {at}"), s.e, ""));
            }
        }
    }
    let plot = |y: &str, series, what: &str| LinePlot {
        log_x: true,
        ..LinePlot::new(format!("{what} against {title}"), fam.x_label, y, series)
    };
    let figures = vec![
        Figure {
            stem: format!("{}-duration", fam.stem),
            plot: plot("contact duration [ms]", dur, "Contact duration"),
        },
        Figure {
            stem: format!("{}-restitution", fam.stem),
            plot: plot("coefficient of restitution e", e, "Restitution"),
        },
    ];
    Ok((figures, findings, failures(&points, &fam.xs, fam.key)))
}

pub(super) fn pairs(
    base: &ImpactSetup,
    short: &[f64],
) -> Result<Vec<(String, ImpactSetup)>, StudyError> {
    short
        .iter()
        .map(|&l| {
            Ok((
                format!("{l} m on {} m", 2.0 * l),
                lengths_of(base, l, 2.0 * l)?,
            ))
        })
        .collect()
}
