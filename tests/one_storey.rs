//! One storey each: with N = 1 the multi-storey solver gives exactly the one-storey results
//! recorded in tests/golden/one-storey.json (the paper's buildings on 8 s of El Centro, every
//! contact element), to 14 significant digits. `UPDATE_GOLDEN=1 cargo test --test one_storey`
//! rewrites the file, which a change may do only where a test proves the old values wrong or,
//! for a change of method, no better than the new ones. The Sears record was rewritten once so:
//! its slabs' ringing between contacts came to be read in closed form instead of stepped, which
//! tests/slab_ringing.rs shows is the same ringing to round-off, both d'Alembert's to 1e-5; the
//! figures moved by at most 5e-9 (an impact's peak force), far inside the run's own error
//! estimate (2.4e-4). The linear and Hertz records were rewritten once, for a change of method:
//! their largest force came to be read between the contact steps (at the cubic's largest overlap)
//! instead of at the steps alone, whose phase-dependent miss made the max force converge
//! erratically (linear: errors -1.9e-5, +4.8e-6, +1.4e-6 as the step was halved against a run
//! refined 40-fold), so that twice a refinement's change no longer bounded the error: a Bouc-Wen
//! run's max force was 2.0e-5 off against a bound of 1.8e-5 (tests/yielding.rs checks it). Read
//! between the steps it converges monotonically (2.5e-5, 5.1e-6, 1.8e-6), inside each run's
//! estimate; the figures moved by at most 4.4e-5 (linear max force: 4.3e-5, against an estimate
//! of 4.3e-5 and a refined-run error of 2.5e-5). The energies moved by round-off (4e-15).
//! Every record was rewritten once more, for a change of method: a free stretch came to span a
//! whole sample of the record with one exact map, where four exact maps, a free step each, were
//! chained before (both the exact motion to round-off: tests/multistorey.rs). Without contact the
//! figures moved by round-off (6e-15 the peaks, 4e-14 the energies); through the contacts, whose
//! solvers stop at tolerances of 1e-12 to 1e-13 and whose sequence amplifies what differs, the
//! peaks moved by at most 9.2e-10, the impacts' times by 8.4e-10 s and their forces and
//! impulses by 2.6e-8 (the Jankowski element), against each run's own estimate of 1.2e-5 to
//! 2.4e-4; the linear spring's contact energy, a small remainder of large works, by 1.8e-7.

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
