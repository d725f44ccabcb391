//! Section 3.2, impact velocity: contact duration and e from 0.01 to 100 m/s (Fig. 7).

use super::*;
use crate::study::StudyOutput;

pub(super) fn velocity(ctx: &Context) -> Result<StudyOutput, StudyError> {
    let base = load("paper-base")?;
    let sets = |v: f64| vec![set(&impact::VELOCITY, 0, v)];
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
