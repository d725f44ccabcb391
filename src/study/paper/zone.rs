//! Section 3.5, the compression zone: peak force from d/100 to 10 d in the paper and collocated
//! readings.

use super::*;
use crate::model::scenario::Reading;
use crate::study::StudyOutput;

pub(super) fn zone(ctx: &Context) -> Result<StudyOutput, StudyError> {
    let base = load("paper-base")?;
    let xs = geometric(0.01, 10.0, 25);
    let readings = [Reading::Paper, Reading::Collocated].map(Reading::name);
    let mut jobs = Vec::new();
    for reading in readings {
        let s = with(&base, &[set(&impact::SEARS_READING, 0, reading)])?;
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
            .map_err(|e| StudyError::Reference(format!("{reading} reading at d: {e}")))?
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
                with(&base, &[set(&impact::ZONE_SCALE, 0, x)])?,
            ))
        })
        .collect::<Result<_, StudyError>>()?;
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
