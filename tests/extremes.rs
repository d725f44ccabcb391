//! Every numeric key of `impact` and `buildings` over its whole accepted range, extreme
//! magnitudes included: each value is refused naming its key, or the run ends within its budgets
//! with finite numbers, or ends with a named refusal of the run (over the step budget, diverged).
//! Never a panic, a NaN or a run without end.

mod common;

use pounding::io::building_settings::BuildingSetup;
use pounding::io::settings::ImpactSetup;
use pounding::model::building::{self, BuildingResult, ContactModel};
use pounding::model::impact::estimate::estimate_error;
use pounding::model::impact::{ImpactResult, ModelKind, SolveError, solve};
use pounding::model::settings::{BUILDING_SETTINGS, IMPACT_SETTINGS, Kind, Setting, concrete_keys};
use proptest::prelude::*;

/// The values tried for a setting: the ends of its accepted range and of the doubles, and
/// magnitudes on either side.
fn extremes(s: &Setting) -> Vec<f64> {
    let mut v = vec![
        0.0,
        f64::MIN_POSITIVE,
        1e-300,
        1e-12,
        1e12,
        1e300,
        f64::INFINITY,
        -1e300,
        f64::NAN,
    ];
    if let Some(r) = s.range() {
        v.extend([r.low_accepted(), r.high_accepted()]);
    }
    v
}

fn numeric(s: &Setting) -> bool {
    matches!(
        s.kind,
        Kind::Number { .. } | Kind::List { .. } | Kind::Count { .. }
    )
}

/// Numbers the run reports must be finite.
fn impact_is_finite(r: &ImpactResult) -> bool {
    r.force_n.iter().chain(&r.approach_m).all(|x| x.is_finite())
        && r.peak_force_n.is_none_or(f64::is_finite)
        && [
            r.contact_duration_s,
            r.impulse_ns,
            r.restitution,
            r.energy.initial_j,
            r.energy.rigid_body_j,
            r.energy.vibration_j,
            r.energy.balance_error,
        ]
        .iter()
        .all(|x| x.is_finite())
}

fn building_is_finite(r: &BuildingResult) -> bool {
    r.force_n.iter().all(|x| x.is_finite())
        && r.displacement_m.iter().flatten().all(|x| x.is_finite())
        && r.max_pounding_force_n.is_finite()
        && r.peak_displacement_m.iter().all(|x| x.is_finite())
        && r.energy.residual_j().is_finite()
}

/// A refusal of the run itself names what to change.
fn named_refusal(e: &SolveError) -> bool {
    match e {
        SolveError::Input(i) => !i.field.is_empty(),
        SolveError::Budget { .. }
        | SolveError::StepBudget { .. }
        | SolveError::Diverged { .. }
        | SolveError::FeWork { .. }
        | SolveError::Memory { .. } => true,
        SolveError::Cancelled => false,
    }
}

/// `key=value` on the default impact setup, then every model: a refusal naming the key, or runs
/// that end finite or refused by name.
fn check_impact(key: &str, value: f64) -> Result<(), String> {
    let mut setup = ImpactSetup::default();
    if let Err(e) = setup.apply_assignment(&format!("{key}={value:e}")) {
        return if e.field == key || e.field.ends_with(key) {
            Ok(())
        } else {
            Err(format!("{key}={value:e} refused under another name: {e}"))
        };
    }
    for model in ModelKind::ALL {
        match solve(model, &setup.scenario) {
            Ok(r) => {
                if !impact_is_finite(&r) {
                    return Err(format!(
                        "{key}={value:e}, {}: a non-finite result",
                        model.name()
                    ));
                }
                if let Err(e) = estimate_error(model, &setup.scenario, &r)
                    && !named_refusal(&e)
                {
                    return Err(format!("{key}={value:e}, {} estimate: {e}", model.name()));
                }
            }
            Err(e) if named_refusal(&e) => {}
            Err(e) => return Err(format!("{key}={value:e}, {}: {e}", model.name())),
        }
    }
    Ok(())
}

/// The same for the buildings, on 3 s of El Centro (a synthetic record for the record's own
/// keys), every element for the contact keys.
fn check_buildings(key: &str, value: f64) -> Result<(), String> {
    let mut setup = BuildingSetup::default();
    setup.motion.duration_s = Some(3.0);
    if key.starts_with("motion.") && !matches!(key, "motion.scale" | "motion.duration") {
        setup
            .apply_assignment("motion.file=synthetic")
            .map_err(|e| e.to_string())?;
        setup.motion.synthetic.duration_s = 3.0;
    }
    if let Err(e) = setup.apply_assignment(&format!("{key}={value:e}")) {
        return if e.field == key {
            Ok(())
        } else {
            Err(format!("{key}={value:e} refused under another name: {e}"))
        };
    }
    let motion = match pounding::io::motion::load(&setup.motion) {
        Ok(m) => m,
        // A record refused on load names the key that made it so.
        Err(e) if e.to_string().contains(key) => return Ok(()),
        Err(e) => return Err(format!("{key}={value:e}: the record: {e}")),
    };
    let elements: &[ContactModel] = if key.starts_with("contact.") {
        &ContactModel::ALL
    } else {
        &[ContactModel::Sears]
    };
    for &contact in elements {
        let mut sc = setup.scenario.clone();
        sc.contact = contact;
        match building::solve(&sc, &motion) {
            Ok(r) if building_is_finite(&r) => {}
            Ok(_) => return Err(format!("{key}={value:e}, {}: non-finite", contact.name())),
            Err(e) if named_refusal(&e) => {}
            Err(e) => return Err(format!("{key}={value:e}, {}: {e}", contact.name())),
        }
    }
    Ok(())
}

/// Every numeric key of `table` at each of its extremes through `check`; the failures, all of
/// them at once.
fn at_extremes(table: &'static [Setting], check: fn(&str, f64) -> Result<(), String>) {
    let failures: Vec<String> = table
        .iter()
        .filter(|s| numeric(s))
        .flat_map(|s| {
            concrete_keys(std::slice::from_ref(s))
                .into_iter()
                .flat_map(move |key| extremes(s).into_iter().map(move |v| (key.clone(), v)))
        })
        .filter_map(|(key, v)| check(&key, v).err())
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn every_impact_key_at_its_extremes_is_refused_by_name_or_runs_finite() {
    at_extremes(IMPACT_SETTINGS, check_impact);
}

#[test]
fn every_building_key_at_its_extremes_is_refused_by_name_or_runs_finite() {
    at_extremes(BUILDING_SETTINGS, check_buildings);
}

/// A value anywhere in a setting's accepted range: log-uniform where the range is positive,
/// uniform otherwise.
fn inside(s: &Setting, u: f64) -> f64 {
    let r = s.range().expect("a numeric setting");
    let (lo, hi) = (r.low_accepted(), r.high_accepted());
    if lo > 0.0 {
        (lo.ln() + u * (hi.ln() - lo.ln())).exp().clamp(lo, hi)
    } else {
        (lo + u * (hi - lo)).clamp(lo, hi)
    }
}

fn any_key(table: &'static [Setting]) -> impl Strategy<Value = (String, &'static Setting)> {
    let keys: Vec<(String, &'static Setting)> = table
        .iter()
        .filter(|s| numeric(s))
        .flat_map(|s| {
            concrete_keys(std::slice::from_ref(s))
                .into_iter()
                .map(move |k| (k, s))
        })
        .collect();
    proptest::sample::select(keys)
}

proptest! {
    #![proptest_config(common::proptest_config(64))]

    #[test]
    fn any_impact_key_anywhere_in_its_range_runs_finite_or_is_refused_by_name(
        (key, s) in any_key(IMPACT_SETTINGS), u in 0.0..=1.0f64,
    ) {
        let v = inside(s, u);
        // Counts take whole numbers.
        let v = if matches!(s.kind, Kind::Count { .. }) { v.round() } else { v };
        check_impact(&key, v).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn any_building_key_anywhere_in_its_range_runs_finite_or_is_refused_by_name(
        (key, s) in any_key(BUILDING_SETTINGS), u in 0.0..=1.0f64,
    ) {
        let v = inside(s, u);
        let v = if matches!(s.kind, Kind::Count { .. }) { v.round() } else { v };
        check_buildings(&key, v).map_err(TestCaseError::fail)?;
    }
}
