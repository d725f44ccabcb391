//! The paper's building example (Section 4, Figures 12 and 13): the two buildings of Table 1 under
//! a ground motion, with Sears pounding and without contact.

use super::{Context, Figure, Finding, Study, StudyError, StudyOutput, finding, par_map};
use crate::export::plot::{LinePlot, Series};
use crate::model::building::{
    BuildingResult, BuildingScenario, ContactModel, ImpactEvent, SlabReading, solve,
};

pub const STUDIES: &[Study] = &[
    Study {
        name: "fig12-displacements",
        paper: "Fig. 12 (Section 4)",
        about: "displacements of the left and right buildings with and without pounding",
        buildings: true,
        run: displacements,
    },
    Study {
        name: "fig13-forces",
        paper: "Fig. 13 (Section 4)",
        about: "pounding forces through the record, and the strongest impact against wave theory",
        buildings: true,
        run: forces,
    },
];

/// The scenario as given and its variants, solved side by side.
fn solve_all(ctx: &Context, cases: &[BuildingScenario]) -> Result<Vec<BuildingResult>, StudyError> {
    let motion = ctx.motion.ok_or(StudyError::NoMotion)?;
    par_map(ctx.progress, cases, |sc| solve(sc, motion))?
        .into_iter()
        .zip(cases)
        .map(|(r, sc)| {
            r.map_err(|source| StudyError::Solve {
                what: format!("the buildings with the {} contact", sc.contact.name()),
                source,
            })
        })
        .collect()
}

/// The scenario as given (pounding) and without contact.
fn with_and_without(ctx: &Context) -> Result<(BuildingResult, BuildingResult), StudyError> {
    let free = BuildingScenario {
        contact: ContactModel::None,
        ..ctx.buildings.clone()
    };
    let mut out = solve_all(ctx, &[ctx.buildings.clone(), free])?.into_iter();
    Ok((out.next().expect("two"), out.next().expect("two")))
}

fn displacements(ctx: &Context) -> Result<StudyOutput, StudyError> {
    let (pounding, free) = with_and_without(ctx)?;
    let mut figures = Vec::new();
    let mut findings = Vec::new();
    for (i, (side, stem)) in [("left", "fig12a-left"), ("right", "fig12b-right")]
        .into_iter()
        .enumerate()
    {
        let series = |name: &str, r: &BuildingResult| Series {
            name: name.into(),
            points: r
                .time_s
                .iter()
                .zip(&r.displacement_m[i])
                .map(|(t, u)| (*t, u * 1e3))
                .collect(),
        };
        figures.push(Figure {
            stem: stem.into(),
            plot: LinePlot::new(
                format!("Displacement of the {side} building with and without pounding"),
                "time [s]",
                "displacement relative to the ground [mm]",
                vec![
                    series("without pounding", &free),
                    series(
                        &format!("with pounding ({})", pounding.contact.name()),
                        &pounding,
                    ),
                ],
            ),
        });
        findings.push(finding(
            format!("{side}: peak displacement with pounding"),
            pounding.peak_displacement_m[i],
            "m",
        ));
        findings.push(finding(
            format!("{side}: peak displacement without pounding"),
            free.peak_displacement_m[i],
            "m",
        ));
    }
    Ok(StudyOutput {
        figures,
        findings,
        notes: pounding.warnings.iter().map(|w| w.to_string()).collect(),
    })
}

fn forces(ctx: &Context) -> Result<StudyOutput, StudyError> {
    // The end reading (no plane delay) alongside, where the scenario is Sears in the paper's
    // reading: it separates what the reading adds (the overshoot) from what the waves do.
    let end = BuildingScenario {
        reading: SlabReading::End,
        ..ctx.buildings.clone()
    };
    let with_end =
        ctx.buildings.contact == ContactModel::Sears && ctx.buildings.reading == SlabReading::Paper;
    let cases: Vec<_> = if with_end {
        vec![ctx.buildings.clone(), end]
    } else {
        vec![ctx.buildings.clone()]
    };
    let mut out = solve_all(ctx, &cases)?.into_iter();
    let r = out.next().expect("one");
    let r_end = out.next();
    let all = Series {
        name: r.contact.name().into(),
        points: r
            .time_s
            .iter()
            .zip(&r.force_n)
            .map(|(t, f)| (*t, f * 1e-6))
            .collect(),
    };
    let mut figures = vec![Figure {
        stem: "fig13a-forces".into(),
        plot: LinePlot::new(
            "Pounding forces through the record",
            "time [s]",
            "pounding force [MN]",
            vec![all],
        ),
    }];
    let mut findings = vec![
        finding("impacts (grouped)", r.impacts.len() as f64, ""),
        finding("contacts (raw)", r.contacts.len() as f64, ""),
        finding("largest pounding force", r.max_pounding_force_n, "N"),
    ];
    if let Some((k, strongest)) = r
        .impacts
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.peak_force_n.total_cmp(&b.1.peak_force_n))
    {
        let (figure, found) = strongest_impact(&ctx.buildings, &r, r_end.as_ref(), k, strongest);
        figures.push(figure);
        findings.extend(found);
    }
    Ok(StudyOutput {
        figures,
        findings,
        notes: r.warnings.iter().map(|w| w.to_string()).collect(),
    })
}

/// The strongest impact zoomed in, against the wave-theory force (and the end reading's run
/// where there is one), with the numbers that describe it.
fn strongest_impact(
    sc: &BuildingScenario,
    r: &BuildingResult,
    r_end: Option<&BuildingResult>,
    k: usize,
    strongest: &ImpactEvent,
) -> (Figure, Vec<Finding>) {
    let wave = sc.slab_series_impedance_n_s_m() * strongest.approach_velocity_m_s;
    let pad = 0.25 * strongest.duration_s().max(1e-3);
    let (t0, t1) = (strongest.start_s - pad, strongest.end_s + pad);
    let window = |r: &BuildingResult| -> Vec<(f64, f64)> {
        r.time_s
            .iter()
            .zip(&r.force_n)
            .filter(|(t, _)| (t0..=t1).contains(*t))
            .map(|(t, f)| ((t - strongest.start_s) * 1e3, f * 1e-6))
            .collect()
    };
    let zoom = Series {
        name: format!("impact {}", k + 1),
        points: window(r),
    };
    let t_end = (t1 - strongest.start_s) * 1e3;
    let level = Series {
        name: "wave theory Z1Z2/(Z1+Z2) v".into(),
        points: vec![(0.0, wave * 1e-6), (t_end, wave * 1e-6)],
    };
    let figure = Figure {
        stem: "fig13b-strongest".into(),
        plot: LinePlot::new(
            format!(
                "The strongest impact (number {} of {}), at {:.3} s",
                k + 1,
                r.impacts.len(),
                strongest.start_s
            ),
            "time from the impact's start [ms]",
            "pounding force [MN]",
            [Some(zoom), Some(level)]
                .into_iter()
                .chain([r_end.map(|e| Series {
                    name: "same record, end reading".into(),
                    points: window(e),
                })])
                .flatten()
                .collect(),
        ),
    };
    let mut findings = vec![
        finding("strongest impact: its number", (k + 1) as f64, ""),
        finding("strongest impact: peak force", strongest.peak_force_n, "N"),
        finding("strongest impact: duration", strongest.duration_s(), "s"),
        finding(
            "strongest impact: approach velocity",
            strongest.approach_velocity_m_s,
            "m/s",
        ),
        finding("strongest impact: wave-theory force", wave, "N"),
        finding(
            "strongest impact: slab round trip 2L/c",
            [&sc.left, &sc.right]
                .iter()
                .map(|b| b.slab(b.storeys - 1).round_trip_s(b.mass(b.storeys - 1)))
                .fold(0.0, f64::max),
            "s",
        ),
    ];
    if let Some(e) = r_end {
        findings.extend([
            finding("end reading: impacts (grouped)", e.impacts.len() as f64, ""),
            finding(
                "end reading: largest pounding force",
                e.max_pounding_force_n,
                "N",
            ),
        ]);
    }
    (figure, findings)
}
