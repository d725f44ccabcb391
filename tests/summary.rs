//! The summary path a sweep takes (no histories, a reused workspace) gives the numbers of a full
//! solve bit for bit.

mod common;

use pounding::model::bar::{EndShape, Section};
use pounding::model::contact::LawKind;
use pounding::model::impact::{ModelKind, Workspace, solve, summary_with};
use pounding::model::scenario::{ImpactScenario, Reading};
use proptest::prelude::*;

fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.ln()..hi.ln()).prop_map(f64::exp)
}

prop_compose! {
    fn scenario()(
        l1 in log_uniform(0.05, 5.0),
        l2 in log_uniform(0.05, 5.0),
        r2 in log_uniform(0.01, 0.1),
        w in log_uniform(0.01, 20.0),
        reading in 0usize..3,
        linear in any::<bool>(),
        k in log_uniform(1e7, 1e13),
        window in prop::option::of(log_uniform(1e-4, 1e-2)),
    ) -> ImpactScenario {
        let mut sc = ImpactScenario::default();
        sc.bar1.length_m = l1;
        sc.bar2.length_m = l2;
        sc.bar2.section = Section::Circular { radius_m: r2 };
        sc.bar1.velocity_m_s = w;
        sc.reading = Reading::ALL[reading];
        if linear {
            sc.contact.law = LawKind::Linear;
            sc.contact.stiffness = Some(k);
            sc.bar1.end = EndShape::Flat;
        }
        if let Some(t) = window {
            // A fixed span: several contacts, or one still open at its end.
            sc.solver.window_s = t;
        }
        sc
    }
}

proptest! {
    #![proptest_config(common::proptest_config(200))]

    #[test]
    fn a_summary_through_a_reused_workspace_is_the_full_solves_bit_for_bit(sc in scenario()) {
        let mut ws = Workspace::default();
        // Twice through the same workspace: what a previous run left must not matter.
        for _ in 0..2 {
            let full = solve(ModelKind::Sears, &sc);
            let summary = summary_with(ModelKind::Sears, &sc, &mut ws);
            match (full, summary) {
                (Ok(r), Ok(s)) => prop_assert_eq!(r.summary(), s),
                (Err(a), Err(b)) => prop_assert_eq!(a.to_string(), b.to_string()),
                (a, b) => prop_assert!(false, "{:?} against {:?}", a.map(|r| r.summary()), b),
            }
        }
    }
}

#[test]
fn every_model_summarises_as_its_full_solve() {
    let mut ws = Workspace::default();
    for model in ModelKind::ALL {
        let sc = ImpactScenario::default();
        let full = solve(model, &sc).expect("solves").summary();
        assert_eq!(
            summary_with(model, &sc, &mut ws).expect("solves"),
            full,
            "{}",
            model.name()
        );
    }
}

/// A building run keeping only some peaks (what an error estimate or a gap assessment reads)
/// finds those bit for bit as a run keeping every peak does, on a pair that pounds at several
/// levels and one that yields; the peaks it leaves out are NaN, never a stale number.
#[test]
fn a_building_run_keeping_some_peaks_finds_them_as_a_run_keeping_all() {
    use pounding::io::building_settings::BuildingSetup;
    use pounding::io::preset;
    use pounding::model::building::{ContactModel, Tracked, solve_summary_tracking};
    use pounding::model::control::Control;
    for (name, contact) in [
        ("mdof-3-5", ContactModel::Sears),
        ("mdof-3-5", ContactModel::None),
        ("mdof-unequal", ContactModel::Hertz),
        ("paper-buildings-yielding", ContactModel::Linear),
    ] {
        let setup = preset::load_for::<BuildingSetup>(name, "buildings").expect("a preset");
        let motion = pounding::io::motion::load(&setup.motion).expect("its record");
        let mut sc = setup.scenario;
        sc.contact = contact;
        let run = |t| solve_summary_tracking(&sc, &motion, Control::never(), t).expect("solves");
        let all = run(Tracked::All);
        let floors = run(Tracked::Floors);
        let levels = run(Tracked::Levels);
        let what = format!("{name}, {}", contact.name());
        assert!(all.peak_drift_ratio[0].iter().all(|d| *d > 0.0), "{what}");
        assert_eq!(
            floors.peak_floor_displacement_m, all.peak_floor_displacement_m,
            "{what}"
        );
        assert!(
            floors.peak_drift_ratio.iter().flatten().all(|d| d.is_nan()),
            "{what}"
        );
        assert_eq!(levels.max_closing_m, all.max_closing_m, "{what}");
        // Only a run without contact follows the levels' largest closing (the gaps it
        // reads); a run with contact leaves it out rather than keep a number nobody reads.
        let followed = contact == ContactModel::None;
        assert_eq!(!all.max_closing_m.is_empty(), followed, "{what}");
        assert_eq!(!floors.max_closing_m.is_empty(), followed, "{what}");
        assert_eq!(
            levels.peak_level_displacement_m, all.peak_level_displacement_m,
            "{what}"
        );
        for run in [&floors, &levels] {
            assert_eq!(run.max_pounding_force_n, all.max_pounding_force_n, "{what}");
            assert_eq!(run.contacts, all.contacts, "{what}");
        }
        // A floor above the levels is not followed for the gaps.
        let right = &levels.peak_floor_displacement_m[1];
        if right.len() > levels.levels.len() {
            assert!(right.last().expect("a roof").is_nan(), "{what}");
        }
    }
}
