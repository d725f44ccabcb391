//! Section 3.4, contact stiffness: the rounded end's diameter from 0.01 to 10 m.

use super::*;
use crate::study::StudyOutput;

pub(super) fn stiffness(ctx: &Context) -> Result<StudyOutput, StudyError> {
    let base = load("paper-base")?;
    let sets = |dome: f64| vec![set(&impact::END_RADIUS, 0, dome / 2.0)];
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
        .collect::<Result<_, StudyError>>()?;
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
