//! The paper's parametric study (Section 3, Figures 4 to 9) as built-in studies. Every study starts
//! from the paper's base case (the `paper-base` preset: steel rods of 0.1 m diameter, 1 m/s, a
//! rounded end of 0.1 m diameter against a flat end, Sears in the paper's reading) or, for the slab
//! study, from `paper-slabs`, and changes only what the figure varies.
//!
//! Restitution is the paper's: from the impulse of the first contact.

use super::{Context, Figure, Finding, Study, StudyOutput, finding, par_map};
use crate::export::plot::{LinePlot, Series};
use crate::io::preset;
use crate::io::settings::ImpactSetup;
use crate::model::impact::{ImpactResult, ModelKind, solve};
use anyhow::anyhow;

pub const STUDIES: &[Study] = &[
    Study {
        name: "fig4-lengths",
        paper: "Fig. 4 (Section 3.1)",
        about: "Sears force histories for bar pairs from 0.1/0.2 m to 5/10 m, against the wave-theory limit",
        buildings: false,
        run: lengths,
    },
    Study {
        name: "fig5-models",
        paper: "Fig. 5 (Section 3.1)",
        about: "Sears, lumped Hertz and wave theory for equal bars of 0.1, 1 and 10 m",
        buildings: false,
        run: models,
    },
    Study {
        name: "fig6-restitution",
        paper: "Fig. 6 (Section 3.1)",
        about: "e against the short bar's length for length ratios 1, 2, 4 and 10; wave theory and lumped Hertz alongside",
        buildings: false,
        run: restitution,
    },
    Study {
        name: "fig7-velocity",
        paper: "Fig. 7 (Section 3.2)",
        about: "contact duration and e against impact velocity (0.01 to 100 m/s) for 0.1/0.2, 1/2 and 10/20 m bars",
        buildings: false,
        run: velocity,
    },
    Study {
        name: "mass",
        paper: "Section 3.3",
        about: "contact duration and e against mass (x1 to x100), added as superimposed mass or as a larger section",
        buildings: false,
        run: mass,
    },
    Study {
        name: "stiffness",
        paper: "Section 3.4",
        about: "contact duration and e against the dome diameter (0.01 to 10 m) for short and long bars; force histories",
        buildings: false,
        run: stiffness,
    },
    Study {
        name: "zone",
        paper: "Section 3.5",
        about: "peak force against the zone length d (d/100 to 10 d) in the paper and collocated readings; force histories",
        buildings: false,
        run: zone,
    },
    Study {
        name: "fig8-material",
        paper: "Fig. 8 (Section 3.6)",
        about: "steel, M20 concrete, and concrete loaded to the steel bars' mass",
        buildings: false,
        run: material,
    },
    Study {
        name: "fig9-slab-n",
        paper: "Fig. 9 (Section 4)",
        about: "concrete slabs 10 m x 8 m x 0.15 m at 1 m/s, linear contact E A/(L/n) for n = 1 to 50",
        buildings: false,
        run: slab_n,
    },
];

fn load(preset_name: &str) -> anyhow::Result<ImpactSetup> {
    preset::load(preset_name).map_err(|e| anyhow!("preset {e}"))
}

/// `base` with `key=value` assignments applied, validated.
fn with(base: &ImpactSetup, sets: &[String]) -> anyhow::Result<ImpactSetup> {
    let mut s = *base;
    for a in sets {
        s.apply_assignment(a).map_err(|e| anyhow!("{a}: {e}"))?;
    }
    s.scenario
        .validate()
        .map_err(|e| anyhow!("{sets:?}: {e}"))?;
    Ok(s)
}

/// Bars of lengths `l1` and `l2` on top of `base`.
fn lengths_of(base: &ImpactSetup, l1: f64, l2: f64) -> anyhow::Result<ImpactSetup> {
    with(
        base,
        &[format!("bar1.length={l1}"), format!("bar2.length={l2}")],
    )
}

/// The quantities a curve is drawn from.
#[derive(Clone, Copy)]
struct Summary {
    peak_n: f64,
    duration_s: f64,
    e: f64,
}

fn summarise(r: &ImpactResult) -> Summary {
    Summary {
        peak_n: r.peak_force_n.unwrap_or(f64::NAN),
        duration_s: r.contact_duration_s,
        e: r.restitution_first_contact,
    }
}

/// Every job solved in parallel; failures are kept per point (a curve skips them, a note says why).
fn summaries(
    ctx: &Context,
    jobs: &[(ModelKind, ImpactSetup)],
) -> anyhow::Result<Vec<Result<Summary, String>>> {
    Ok(par_map(ctx.progress, jobs, |(m, s)| {
        solve(*m, &s.scenario)
            .map(|r| summarise(&r))
            .map_err(|e| e.to_string())
    })?)
}

/// Full results, for force histories; any failure fails the study.
fn histories(
    ctx: &Context,
    jobs: &[(ModelKind, ImpactSetup)],
) -> anyhow::Result<Vec<ImpactResult>> {
    par_map(ctx.progress, jobs, |(m, s)| solve(*m, &s.scenario))?
        .into_iter()
        .map(|r| r.map_err(|e| anyhow!(e)))
        .collect()
}

/// Force history in ms and kN, closed by a zero after separation so the fall shows.
fn force_series(name: impl Into<String>, r: &ImpactResult) -> Series {
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

fn level(name: &str, y: f64, t_end_ms: f64) -> Series {
    Series {
        name: name.into(),
        points: vec![(0.0, y), (t_end_ms, y)],
    }
}

fn end_ms(results: &[ImpactResult]) -> f64 {
    results
        .iter()
        .filter_map(|r| r.time_s.last())
        .fold(0.0, |a, &t| a.max(t * 1e3))
}

fn force_plot(title: &str, series: Vec<Series>) -> LinePlot {
    LinePlot::new(title, "time [ms]", "contact force [kN]", series)
}

/// One curve of a family against x, skipping failed points.
fn curve(
    name: impl Into<String>,
    xs: &[f64],
    points: &[Result<Summary, String>],
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

fn failures(points: &[Result<Summary, String>], xs: &[f64], what: &str) -> Vec<String> {
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

fn geometric(from: f64, to: f64, count: usize) -> Vec<f64> {
    super::sweep::values(from, to, count, true)
}

/// Time to reach 90% of the peak [s].
fn rise_time_s(r: &ImpactResult) -> f64 {
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
fn plateau_share(r: &ImpactResult, level: f64) -> f64 {
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

fn lengths(ctx: &Context) -> anyhow::Result<StudyOutput> {
    let base = load("paper-base")?;
    let l1s = [0.1, 0.25, 0.5, 1.0, 2.5, 5.0];
    let jobs: Vec<_> = l1s
        .iter()
        .map(|&l| Ok((ModelKind::Sears, lengths_of(&base, l, 2.0 * l)?)))
        .collect::<anyhow::Result<_>>()?;
    let results = histories(ctx, &jobs)?;
    let limit = base.scenario.wave_force_n();
    let mut series: Vec<Series> = l1s
        .iter()
        .zip(&results)
        .map(|(l, r)| force_series(format!("{l} m on {} m", 2.0 * l), r))
        .collect();
    series.push(level(
        "wave limit Z/2 (v1-v2)",
        limit * 1e-3,
        end_ms(&results),
    ));
    let mut findings = vec![finding(
        "wave-theory limit 0.5 rho A c (v1 - v2)",
        limit,
        "N",
    )];
    for (l, r) in l1s.iter().zip(&results) {
        findings.push(finding(
            format!("peak / limit, {l} m on {} m", 2.0 * l),
            r.peak_force_n.unwrap_or(0.0) / limit,
            "",
        ));
    }
    let longest = results.last().expect("six lengths");
    findings.push(finding(
        "share of contact within 2% of the limit, 5 m on 10 m",
        plateau_share(longest, limit),
        "",
    ));
    findings.push(finding(
        "rise time to 90% of the peak, 5 m on 10 m",
        rise_time_s(longest),
        "s",
    ));
    Ok(StudyOutput {
        figures: vec![Figure {
            stem: "fig4-lengths".into(),
            plot: force_plot(
                "Sears: impact force for different bar lengths (steel, 0.1 m diameter, 1 m/s)",
                series,
            ),
        }],
        findings,
        notes: vec![],
    })
}

fn models(ctx: &Context) -> anyhow::Result<StudyOutput> {
    let base = load("paper-base")?;
    let lengths = [0.1, 1.0, 10.0];
    let kinds = [ModelKind::Sears, ModelKind::LumpedHertz, ModelKind::Wave];
    let mut jobs = Vec::new();
    for &l in &lengths {
        let s = lengths_of(&base, l, l)?;
        jobs.extend(kinds.iter().map(|&m| (m, s)));
    }
    let results = histories(ctx, &jobs)?;
    let mut figures = Vec::new();
    let mut findings = Vec::new();
    for (i, l) in lengths.iter().enumerate() {
        let rs = &results[3 * i..3 * i + 3];
        let series = kinds
            .iter()
            .zip(rs)
            .map(|(m, r)| force_series(m.name(), r))
            .collect();
        figures.push(Figure {
            stem: format!("fig5-models-{l}m"),
            plot: force_plot(
                &format!("Equal bars of {l} m: Sears, lumped Hertz and wave theory"),
                series,
            ),
        });
        let peak = |r: &ImpactResult| r.peak_force_n.unwrap_or(f64::NAN);
        findings.push(finding(
            format!("{l} m: Sears peak / lumped-Hertz peak"),
            peak(&rs[0]) / peak(&rs[1]),
            "",
        ));
        findings.push(finding(
            format!("{l} m: Sears peak / wave force"),
            peak(&rs[0]) / peak(&rs[2]),
            "",
        ));
        findings.push(finding(
            format!("{l} m: Sears duration / lumped-Hertz duration"),
            rs[0].contact_duration_s / rs[1].contact_duration_s,
            "",
        ));
        findings.push(finding(
            format!("{l} m: Sears duration / wave duration 2L/c"),
            rs[0].contact_duration_s / rs[2].contact_duration_s,
            "",
        ));
    }
    Ok(StudyOutput {
        figures,
        findings,
        notes: vec![],
    })
}

fn restitution(ctx: &Context) -> anyhow::Result<StudyOutput> {
    let base = load("paper-base")?;
    let xs = geometric(0.07, 50.0, 30);
    let ratios = [1.0, 2.0, 4.0, 10.0];
    let mut jobs = Vec::new();
    for &r in &ratios {
        for &l in &xs {
            let s = lengths_of(&base, l, r * l)?;
            jobs.push((ModelKind::Sears, s));
            jobs.push((ModelKind::Wave, s));
        }
    }
    for &l in &xs {
        jobs.push((ModelKind::LumpedHertz, lengths_of(&base, l, 2.0 * l)?));
    }
    let points = summaries(ctx, &jobs)?;
    let n = xs.len();
    let mut series = Vec::new();
    let mut findings = Vec::new();
    for (k, r) in ratios.iter().enumerate() {
        let block = &points[2 * n * k..2 * n * (k + 1)];
        let sears: Vec<_> = block.iter().step_by(2).cloned().collect();
        let wave: Vec<_> = block.iter().skip(1).step_by(2).cloned().collect();
        series.push(curve(format!("Sears, ratio {r}"), &xs, &sears, |s| s.e));
        series.push(curve(format!("wave, ratio {r}"), &xs, &wave, |s| s.e));
        for (i, label) in [(0, "shortest"), (n - 1, "longest")] {
            if let Ok(s) = &sears[i] {
                findings.push(finding(
                    format!("Sears e, ratio {r}, short bar {:.3} m ({label})", xs[i]),
                    s.e,
                    "",
                ));
            }
        }
        let min_e = sears
            .iter()
            .filter_map(|p| p.as_ref().ok().map(|s| s.e))
            .fold(f64::INFINITY, f64::min);
        findings.push(finding(format!("Sears lowest e, ratio {r}"), min_e, ""));
    }
    let hertz = &points[2 * n * ratios.len()..];
    series.push(curve("lumped Hertz, ratio 2", &xs, hertz, |s| s.e));
    let mut plot = LinePlot::new(
        "Coefficient of restitution for unequal bars (steel, 0.1 m diameter, 1 m/s)",
        "length of the short bar [m]",
        "coefficient of restitution e",
        series,
    );
    plot.log_x = true;
    Ok(StudyOutput {
        figures: vec![Figure {
            stem: "fig6-restitution".into(),
            plot,
        }],
        findings,
        notes: {
            // Jobs run Sears and wave per length for each ratio, then lumped Hertz per length.
            let job_xs: Vec<f64> = ratios
                .iter()
                .flat_map(|_| xs.iter().flat_map(|x| [*x, *x]))
                .chain(xs.iter().copied())
                .collect();
            failures(&points, &job_xs, "short bar length")
        },
    })
}

/// Duration and e of a few bar pairs against one swept setting; returns the two figures.
struct Family<'a> {
    stem: &'a str,
    key: &'a str,
    x_label: &'a str,
    xs: Vec<f64>,
    /// What to set for each x (the swept key alone by default).
    sets: &'a dyn Fn(f64) -> Vec<String>,
}

fn duration_and_e(
    ctx: &Context,
    fam: &Family,
    pairs: &[(String, ImpactSetup)],
    title: &str,
) -> anyhow::Result<(Vec<Figure>, Vec<Finding>, Vec<String>)> {
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

fn pairs(base: &ImpactSetup, short: &[f64]) -> anyhow::Result<Vec<(String, ImpactSetup)>> {
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

fn velocity(ctx: &Context) -> anyhow::Result<StudyOutput> {
    let base = load("paper-base")?;
    let sets = |v: f64| vec![format!("bar1.velocity={v}")];
    let fam = Family {
        stem: "fig7",
        key: "v",
        x_label: "relative impact velocity [m/s]",
        xs: geometric(0.01, 100.0, 25),
        sets: &sets,
    };
    let (mut figures, findings, notes) = duration_and_e(
        ctx,
        &fam,
        &pairs(&base, &[0.1, 1.0, 10.0])?,
        "impact velocity",
    )?;
    figures[0].stem = "fig7a-duration".into();
    figures[1].stem = "fig7b-restitution".into();
    Ok(StudyOutput {
        figures,
        findings,
        notes,
    })
}

fn mass(ctx: &Context) -> anyhow::Result<StudyOutput> {
    let base = load("paper-base")?;
    let d = base.scenario.zone_lengths_m()[0];
    // The zone length follows the bar's radius in Eq. 5; it is held at the base case's so the
    // larger section changes the mass alone, as superimposed mass does.
    let base = with(&base, &[format!("contact.zone_length={d}")])?;
    let (m1, m2) = (base.scenario.bar1.mass_kg(), base.scenario.bar2.mass_kg());
    let r = base.scenario.bar1.radius_m();
    let added = move |k: f64| {
        vec![
            format!("bar1.added_mass={}", (k - 1.0) * m1),
            format!("bar2.added_mass={}", (k - 1.0) * m2),
        ]
    };
    let section = move |k: f64| {
        let rk = r * k.sqrt();
        vec![format!("bar1.radius={rk}"), format!("bar2.radius={rk}")]
    };
    let xs = geometric(1.0, 100.0, 20);
    let mut figures = Vec::new();
    let mut findings = Vec::new();
    let mut notes = Vec::new();
    for (name, sets) in [
        ("superimposed mass", &added as &dyn Fn(f64) -> Vec<String>),
        ("larger section", &section),
    ] {
        let fam = Family {
            stem: "mass",
            key: "mass factor",
            x_label: "mass factor (x the steel bars' own mass)",
            xs: xs.clone(),
            sets,
        };
        let (figs, f, n) =
            duration_and_e(ctx, &fam, &[(format!("1 m on 2 m, {name}"), base)], "mass")?;
        findings.extend(f);
        notes.extend(n);
        if figures.is_empty() {
            figures = figs;
        } else {
            for (all, more) in figures.iter_mut().zip(figs) {
                all.plot.series.extend(more.plot.series);
            }
        }
    }
    Ok(StudyOutput {
        figures,
        findings,
        notes,
    })
}

fn stiffness(ctx: &Context) -> anyhow::Result<StudyOutput> {
    let base = load("paper-base")?;
    let sets = |dome: f64| vec![format!("bar1.end_radius={}", dome / 2.0)];
    let fam = Family {
        stem: "stiffness",
        key: "dome diameter",
        x_label: "diameter of the rounded end [m]",
        xs: geometric(0.01, 10.0, 20),
        sets: &sets,
    };
    let (mut figures, mut findings, notes) =
        duration_and_e(ctx, &fam, &pairs(&base, &[0.1, 1.0])?, "contact stiffness")?;
    let domes = [0.01, 0.1, 1.0, 10.0];
    let jobs: Vec<_> = domes
        .iter()
        .map(|&dome| Ok((ModelKind::Sears, with(&base, &sets(dome))?)))
        .collect::<anyhow::Result<_>>()?;
    let results = histories(ctx, &jobs)?;
    let limit = base.scenario.wave_force_n();
    let mut series: Vec<Series> = domes
        .iter()
        .zip(&results)
        .map(|(d, r)| force_series(format!("dome {d} m"), r))
        .collect();
    series.push(level("wave force", limit * 1e-3, end_ms(&results)));
    for (d, r) in domes.iter().zip(&results) {
        findings.push(finding(
            format!("1 m on 2 m, dome {d} m: peak / wave force"),
            r.peak_force_n.unwrap_or(0.0) / limit,
            "",
        ));
        if let Some(s) = &r.sears {
            findings.push(finding(
                format!("1 m on 2 m, dome {d} m: a tau"),
                s.a_tau,
                "",
            ));
        }
    }
    figures.push(Figure {
        stem: "stiffness-forces".into(),
        plot: force_plot(
            "Force histories, 1 m on 2 m, against the rounded end's diameter",
            series,
        ),
    });
    Ok(StudyOutput {
        figures,
        findings,
        notes,
    })
}

fn zone(ctx: &Context) -> anyhow::Result<StudyOutput> {
    let base = load("paper-base")?;
    let xs = geometric(0.01, 10.0, 25);
    let readings = ["paper", "collocated"];
    let mut jobs = Vec::new();
    for reading in readings {
        let s = with(&base, &[format!("sears.reading={reading}")])?;
        for &x in &xs {
            // A zone longer than a reading allows is that point's error (solve validates), not
            // the study's.
            let mut p = s;
            p.scenario.contact.zone_scale = x;
            jobs.push((ModelKind::Sears, p));
        }
        jobs.push((ModelKind::Sears, s));
    }
    let points = summaries(ctx, &jobs)?;
    let n = xs.len();
    let mut series = Vec::new();
    let mut findings = Vec::new();
    let mut notes = Vec::new();
    for (k, reading) in readings.iter().enumerate() {
        let block = &points[(n + 1) * k..(n + 1) * k + n];
        let reference = points[(n + 1) * k + n]
            .as_ref()
            .map_err(|e| anyhow!("{reading} reading at d: {e}"))?
            .peak_n;
        series.push(curve(format!("{reading} reading"), &xs, block, |s| {
            100.0 * (s.peak_n / reference - 1.0)
        }));
        for scale in [0.01, 2.0, 5.0, 10.0] {
            let i = xs
                .iter()
                .position(|x| (x / scale - 1.0).abs() < 1e-9)
                .unwrap_or_else(|| {
                    xs.iter()
                        .enumerate()
                        .min_by(|a, b| {
                            (a.1.ln() - scale.ln())
                                .abs()
                                .total_cmp(&(b.1.ln() - scale.ln()).abs())
                        })
                        .map_or(0, |(i, _)| i)
                });
            if let Ok(s) = &block[i] {
                findings.push(finding(
                    format!("{reading}: peak change at d x {:.3}", xs[i]),
                    100.0 * (s.peak_n / reference - 1.0),
                    "%",
                ));
            }
        }
        notes.extend(failures(block, &xs, &format!("{reading} reading, d scale")));
    }
    let mut change = LinePlot::new(
        "Peak force against the compression-zone length (1 m on 2 m steel rods)",
        "zone length / Sears' d",
        "change in peak force [%]",
        series,
    );
    change.log_x = true;
    let scales = [0.01, 1.0, 2.0, 5.0, 10.0];
    let jobs: Vec<_> = scales
        .iter()
        .map(|&x| {
            Ok((
                ModelKind::Sears,
                with(&base, &[format!("contact.zone_scale={x}")])?,
            ))
        })
        .collect::<anyhow::Result<_>>()?;
    let results = histories(ctx, &jobs)?;
    let forces = scales
        .iter()
        .zip(&results)
        .map(|(x, r)| force_series(format!("d x {x}"), r))
        .collect();
    Ok(StudyOutput {
        figures: vec![
            Figure {
                stem: "zone-peak".into(),
                plot: change,
            },
            Figure {
                stem: "zone-forces".into(),
                plot: force_plot(
                    "Force histories against the zone length (paper reading)",
                    forces,
                ),
            },
        ],
        findings,
        notes,
    })
}

fn material(ctx: &Context) -> anyhow::Result<StudyOutput> {
    let base = load("paper-base")?;
    let concrete = with(
        &base,
        &[
            "bar1.material=concrete".into(),
            "bar2.material=concrete".into(),
        ],
    )?;
    let steel_rho = base.scenario.bar1.material.density_kg_m3;
    let conc_rho = concrete.scenario.bar1.material.density_kg_m3;
    let extra = |b: &crate::model::bar::Bar| (steel_rho - conc_rho) * b.area_m2() * b.length_m;
    let loaded = with(
        &concrete,
        &[
            format!("bar1.added_mass={}", extra(&concrete.scenario.bar1)),
            format!("bar2.added_mass={}", extra(&concrete.scenario.bar2)),
        ],
    )?;
    let cases = [
        ("steel", base),
        ("M20 concrete", concrete),
        ("concrete + mass to steel's", loaded),
    ];
    let jobs: Vec<_> = cases.iter().map(|(_, s)| (ModelKind::Sears, *s)).collect();
    let results = histories(ctx, &jobs)?;
    let mut series = Vec::new();
    let mut findings = Vec::new();
    for ((name, s), r) in cases.iter().zip(&results) {
        series.push(force_series(*name, r));
        findings.push(finding(
            format!("{name}: peak"),
            r.peak_force_n.unwrap_or(0.0),
            "N",
        ));
        findings.push(finding(
            format!("{name}: peak / wave force"),
            r.peak_force_n.unwrap_or(0.0) / s.scenario.wave_force_n(),
            "",
        ));
        findings.push(finding(
            format!("{name}: duration"),
            r.contact_duration_s,
            "s",
        ));
        findings.push(finding(
            format!("{name}: e"),
            r.restitution_first_contact,
            "",
        ));
    }
    Ok(StudyOutput {
        figures: vec![Figure {
            stem: "fig8-material".into(),
            plot: force_plot(
                "Effect of material: steel, concrete and concrete of steel's mass (1 m on 2 m)",
                series,
            ),
        }],
        findings,
        notes: vec![],
    })
}

fn slab_n(ctx: &Context) -> anyhow::Result<StudyOutput> {
    let base = load("paper-slabs")?;
    let ns = [1.0, 2.0, 5.0, 10.0, 20.0, 50.0];
    let l = base.scenario.bar1.length_m;
    let jobs: Vec<_> = ns
        .iter()
        .map(|&n| {
            Ok((
                ModelKind::Sears,
                with(
                    &base,
                    &[
                        format!("contact.divisions={n}"),
                        format!("contact.zone_length={}", l / n),
                    ],
                )?,
            ))
        })
        .collect::<anyhow::Result<_>>()?;
    // n = 10 once more in the end reading (no plane delay): what the waves do without the paper
    // reading's overshoot.
    let mut jobs = jobs;
    let end = with(&jobs[3].1, &["sears.reading=end".into()])?;
    jobs.push((ModelKind::Sears, end));
    let mut results = histories(ctx, &jobs)?;
    let end = results.pop().expect("the end-reading run");
    let limit = base.scenario.wave_force_n();
    let mut series: Vec<Series> = ns
        .iter()
        .zip(&results)
        .map(|(n, r)| force_series(format!("n = {n}"), r))
        .collect();
    series.push(force_series("n = 10, end reading", &end));
    series.push(level("wave force", limit * 1e-3, end_ms(&results)));
    let mut findings = vec![
        finding("wave force Z/2 (v1 - v2)", limit, "N"),
        finding(
            "n = 10, end reading: peak / wave force",
            end.peak_force_n.unwrap_or(0.0) / limit,
            "",
        ),
        finding("n = 10, end reading: duration", end.contact_duration_s, "s"),
    ];
    for (n, r) in ns.iter().zip(&results) {
        findings.push(finding(
            format!("n = {n}: rise time to 90%"),
            rise_time_s(r),
            "s",
        ));
        findings.push(finding(
            format!("n = {n}: duration"),
            r.contact_duration_s,
            "s",
        ));
        findings.push(finding(
            format!("n = {n}: peak / wave force"),
            r.peak_force_n.unwrap_or(0.0) / limit,
            "",
        ));
    }
    Ok(StudyOutput {
        figures: vec![Figure {
            stem: "fig9-slab-n".into(),
            plot: force_plot(
                "Concrete slabs 10 m x 8 m x 0.15 m at 1 m/s: linear contact E A/(L/n)",
                series,
            ),
        }],
        findings,
        notes: vec![],
    })
}
