//! Section 3.6, material: steel, M20 concrete, and concrete loaded to steel's mass (Fig. 8).

use super::*;
use crate::model::material::MaterialPreset;
use crate::study::StudyOutput;

pub(super) fn material(ctx: &Context) -> Result<StudyOutput, StudyError> {
    let base = load("paper-base")?;
    let concrete = with(
        &base,
        &[
            set(&impact::MATERIAL, 0, MaterialPreset::Concrete.name()),
            set(&impact::MATERIAL, 1, MaterialPreset::Concrete.name()),
        ],
    )?;
    let steel_rho = base.scenario.bar1.material.density_kg_m3;
    let conc_rho = concrete.scenario.bar1.material.density_kg_m3;
    let extra = |b: &crate::model::bar::Bar| (steel_rho - conc_rho) * b.area_m2() * b.length_m;
    let loaded = with(
        &concrete,
        &[
            set(&impact::ADDED_MASS, 0, extra(&concrete.scenario.bar1)),
            set(&impact::ADDED_MASS, 1, extra(&concrete.scenario.bar2)),
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
