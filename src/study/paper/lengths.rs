//! Section 3.1, bar length: force histories against the length (Fig. 4), the models side by side
//! (Fig. 5), and restitution against the short bar's length (Fig. 6).

use super::*;
use crate::study::StudyOutput;

pub(super) fn lengths(ctx: &Context) -> Result<StudyOutput, StudyError> {
    let base = load("paper-base")?;
    let l1s = [0.1, 0.25, 0.5, 1.0, 2.5, 5.0];
    let jobs: Vec<_> = l1s
        .iter()
        .map(|&l| Ok((ModelKind::Sears, lengths_of(&base, l, 2.0 * l)?)))
        .collect::<Result<_, StudyError>>()?;
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

pub(super) fn models(ctx: &Context) -> Result<StudyOutput, StudyError> {
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

pub(super) fn restitution(ctx: &Context) -> Result<StudyOutput, StudyError> {
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
