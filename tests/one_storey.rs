//! One storey each: with N = 1 the multi-storey solver gives exactly the one-storey results
//! recorded in tests/golden/one-storey.json (the paper's buildings on 8 s of El Centro, every
//! contact element), to 14 significant digits, so a change that moves any result is seen.
//!
//! `UPDATE_GOLDEN=1 cargo test --test one_storey` rewrites the file. A change may do so only
//! where a test proves the recorded values wrong or, for a change of method, no better than the
//! new ones: the new method checked against an independent truth by its own test, and the
//! figures moved by less than each run's own error estimate (1.2e-5 to 2.4e-4 of them here).
//! The commit that rewrites the file says by how much they moved. The record holds the methods
//! the solver uses: the Sears slabs' ringing between contacts read in closed form (the same
//! ringing as stepping it, to round-off: tests/slab_ringing.rs), the largest force of an
//! undamped element read between the contact steps, at the cubic's largest overlap (it converges
//! monotonically: docs/buildings.md), and a free stretch spanning a whole sample of the record
//! with one exact map (the exact motion to round-off: tests/multistorey.rs).

use pounding::model::building::{BuildingResult, BuildingScenario, ContactModel, solve};

fn figures(r: &BuildingResult) -> Vec<f64> {
    let mut v = vec![
        r.impacts.len() as f64,
        r.contacts.len() as f64,
        r.peak_displacement_m[0],
        r.peak_displacement_m[1],
        r.max_pounding_force_n,
        r.energy.input_j,
        r.energy.building_damping_j,
        r.energy.contact_j,
        r.energy.final_j,
    ];
    for e in &r.impacts {
        v.extend([e.start_s, e.end_s, e.peak_force_n, e.impulse_ns]);
    }
    v
}

#[test]
fn one_storey_buildings_reproduce_their_recorded_results_to_the_last_digit() {
    let motion = pounding::io::motion::built_in("elcentro-1940")
        .unwrap()
        .truncated(8.0);
    let mut now = serde_json::Map::new();
    for model in ContactModel::ALL {
        let sc = BuildingScenario {
            contact: model,
            ..BuildingScenario::paper()
        };
        assert_eq!((sc.left.storeys, sc.right.storeys), (1, 1));
        let r = solve(&sc, &motion).unwrap();
        now.insert(model.name().into(), serde_json::json!(figures(&r)));
    }
    let path = std::path::Path::new("tests/golden/one-storey.json");
    if std::env::var_os("UPDATE_GOLDEN").is_some() {
        std::fs::write(path, serde_json::to_string_pretty(&now).unwrap()).unwrap();
        return;
    }
    let golden: serde_json::Map<String, serde_json::Value> =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    // Every element the product has must have its record: a model missing from the file would
    // otherwise never be checked.
    assert_eq!(
        golden.len(),
        ContactModel::ALL.len(),
        "the file records {:?}",
        golden.keys().collect::<Vec<_>>()
    );
    for model in ContactModel::ALL.map(|m| m.name()) {
        let values = golden
            .get(model)
            .unwrap_or_else(|| panic!("tests/golden/one-storey.json has no record of {model}"));
        let want: Vec<f64> = serde_json::from_value(values.clone()).unwrap();
        let got: Vec<f64> = serde_json::from_value(now[model].clone()).unwrap();
        assert_eq!(got.len(), want.len(), "{model}: impact count");
        for (i, (g, w)) in got.iter().zip(&want).enumerate() {
            assert!(
                (g - w).abs() <= 1e-14 * w.abs(),
                "{model}: figure {i} is {g:e}, recorded {w:e}"
            );
        }
    }
}
