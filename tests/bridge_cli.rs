//! `pounding bridge` as a script uses it: the JSON fields the issue names, and refusals by key.

mod common;

#[test]
fn the_passage_preset_reports_forces_openings_seat_margins_and_required_gaps() {
    let out = common::pounding(&["bridge", "--preset", "bridge-3-span-passage", "--json"]);
    assert!(out.status.success(), "{}", common::stderr(&out));
    let v: serde_json::Value = serde_json::from_str(&common::stdout(&out)).unwrap();
    let joints = v["joints"].as_array().unwrap();
    assert_eq!(joints.len(), 4);
    assert_eq!(joints[0]["kind"], "abutment");
    assert_eq!(joints[1]["kind"], "girder");
    assert_eq!(joints[3]["position_m"], 120.0);
    for key in [
        "max_force_by_joint_n",
        "required_gaps_m",
        "max_openings_m",
        "seat_margins_m",
        "peak_girder_displacements_m",
        "peak_pier_displacements_m",
        "peak_bearing_displacements_m",
    ] {
        let n = if key.starts_with("peak_") { 3 } else { 4 };
        let xs = v[key].as_array().unwrap_or_else(|| panic!("{key}"));
        assert_eq!(xs.len(), n, "{key}");
        assert!(xs.iter().all(|x| x.as_f64().unwrap().is_finite()), "{key}");
    }
    // The margins come from the largest openings; the unseating list from the opening watched
    // step by step against the seat: a joint is listed exactly where its margin ran out.
    let margins = v["seat_margins_m"].as_array().unwrap();
    let listed = |v: &serde_json::Value, j: usize| {
        v["unseating"]
            .as_array()
            .unwrap()
            .iter()
            .any(|u| u["joint"] == j)
    };
    for (j, m) in margins.iter().enumerate() {
        assert_eq!(m.as_f64().unwrap() < 0.0, listed(&v, j), "joint {j}");
    }
    assert!(v["impact_count"].as_u64().unwrap() > 0);
    let impact = &v["impacts"][0];
    assert!(impact["joint"].as_u64().unwrap() < 4 && impact.get("level").is_none());
    assert!(v["contacts"][0]["joint"].is_u64());
    assert!(v["unseating"].as_array().unwrap().is_empty());
    assert_eq!(v["apparent_velocity_m_s"], 500.0);
    assert!(v["error_estimate"]["max_force_rel"].as_f64().unwrap() < 1e-3);
    assert!(v["energy_balance_error"].as_f64().unwrap().abs() < 1e-5);
    assert!(v["solve_time_s"].as_f64().unwrap() > 0.0);
    assert!(v["warnings"].is_array());
}

#[test]
fn the_unseating_preset_drops_a_girder_that_uniform_shaking_keeps() {
    let passage = common::pounding(&["bridge", "--preset", "bridge-3-span-unseating", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&common::stdout(&passage)).unwrap();
    let unseated = v["unseating"].as_array().unwrap();
    assert!(!unseated.is_empty());
    assert!(unseated[0]["time_s"].as_f64().unwrap() > 0.0);
    for u in unseated {
        let j = u["joint"].as_u64().unwrap() as usize;
        assert!(v["seat_margins_m"][j].as_f64().unwrap() < 0.0, "joint {j}");
    }
    let uniform = common::pounding(&[
        "bridge",
        "--preset",
        "bridge-3-span-unseating",
        "--set",
        "motion.apparent_velocity=uniform",
        "--json",
    ]);
    let u: serde_json::Value = serde_json::from_str(&common::stdout(&uniform)).unwrap();
    assert!(u["unseating"].as_array().unwrap().is_empty());
}

#[test]
fn bad_bridge_input_is_refused_by_its_key() {
    for (set, key) in [
        ("bridge.spans=21", "bridge.spans"),
        ("span.length=40,40", "span.length"),
        ("joint.gaps=-1", "joint.gaps"),
        ("bridge.seat_length=0", "bridge.seat_length"),
        ("motion.apparent_velocity=0", "motion.apparent_velocity"),
        ("girder.damping=1", "girder.damping"),
        ("span.lenght=3", "span.lenght"),
    ] {
        let out = common::pounding(&["bridge", "--set", set]);
        assert!(!out.status.success(), "{set}");
        assert!(
            common::stderr(&out).contains(key),
            "{set}: {}",
            common::stderr(&out)
        );
    }
    let out = common::pounding(&["bridge", "--preset", "paper-buildings"]);
    assert!(common::stderr(&out).contains("pounding buildings"));
}

#[test]
fn list_keys_shows_every_bridge_key() {
    let out = common::pounding(&["bridge", "--list-keys"]);
    let text = common::stdout(&out);
    for key in [
        "span.length",
        "span.area",
        "span.youngs_modulus",
        "span.density",
        "span.added_mass",
        "pier.mass",
        "pier.stiffness",
        "bearing.stiffness",
        "bridge.spans",
        "damping_ratio",
        "joint.gaps",
        "bridge.seat_length",
        "contact.stiffness",
        "contact.restitution",
        "motion.apparent_velocity",
        "girder.damping",
        "solver.max_step",
    ] {
        assert!(text.contains(key), "{key}");
    }
}
