//! Section 4's slabs: concrete slabs with the linear contact E A/(L/n), n = 1 to 50 (Fig. 9).

use super::*;
use crate::model::scenario::Reading;
use crate::study::StudyOutput;

pub(super) fn slab_n(ctx: &Context) -> Result<StudyOutput, StudyError> {
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
                        set(&impact::DIVISIONS, 0, n),
                        set(&impact::ZONE_LENGTH, 0, l / n),
                    ],
                )?,
            ))
        })
        .collect::<Result<_, StudyError>>()?;
    // n = 10 once more in the end reading (no plane delay): what the waves do without the paper
    // reading's overshoot.
    let mut jobs = jobs;
    let end = with(
        &jobs[3].1,
        &[set(&impact::SEARS_READING, 0, Reading::End.name())],
    )?;
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
