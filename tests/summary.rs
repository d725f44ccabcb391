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
