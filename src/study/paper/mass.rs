//! Section 3.3, mass: superimposed mass against a larger section, x1 to x100.

use super::*;
use crate::study::StudyOutput;

pub(super) fn mass(ctx: &Context) -> Result<StudyOutput, StudyError> {
    let base = load("paper-base")?;
    let d = base.scenario.zone_lengths_m()[0];
    // The zone length follows the bar's radius in Eq. 5; it is held at the base case's so the
    // larger section changes the mass alone, as superimposed mass does.
    let base = with(&base, &[set(&impact::ZONE_LENGTH, 0, d)])?;
    let (m1, m2) = (base.scenario.bar1.mass_kg(), base.scenario.bar2.mass_kg());
    let r = base.scenario.bar1.radius_m();
    let added = move |k: f64| {
        vec![
            set(&impact::ADDED_MASS, 0, (k - 1.0) * m1),
            set(&impact::ADDED_MASS, 1, (k - 1.0) * m2),
        ]
    };
    let section = move |k: f64| {
        let rk = r * k.sqrt();
        vec![set(&impact::RADIUS, 0, rk), set(&impact::RADIUS, 1, rk)]
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
