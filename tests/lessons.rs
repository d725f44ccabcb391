//! Guided lessons: every shipped lesson passes `--check`, the format refuses what it does not
//! know with the line and field, and each lesson's statements about the model hold on the
//! solved model (beyond its own `asserts`: trends, other settings, the task's after-state).

mod common;

use pounding::lesson::{
    self, Context, Lesson, LessonScene, Panel, Prediction, Solved, parse_text, solve_step,
};
use pounding::model::control::Control;
use pounding::model::impact::ModelKind;

fn shipped(name: &str) -> Lesson {
    lesson::builtin(name).unwrap_or_else(|e| panic!("{e}"))
}

/// Step `i` (from 1) of a lesson solved with extra overrides.
fn solved(lesson: &Lesson, i: usize, extra: &[(&str, &str)]) -> Solved {
    let extra: Vec<(String, String, usize)> = extra
        .iter()
        .map(|(k, v)| (k.to_string(), v.to_string(), 0))
        .collect();
    solve_step(
        &lesson.steps[i - 1],
        &extra,
        Control::never(),
        &lesson.source,
    )
    .unwrap_or_else(|e| panic!("{e}"))
}

fn num(ctx: &Context, name: &str) -> f64 {
    match ctx.get(name) {
        Ok(lesson::Value::Number(x)) => x,
        other => panic!("{name}: {other:?}"),
    }
}

#[test]
fn every_shipped_lesson_passes_the_check() {
    assert_eq!(
        lesson::builtin_names(),
        [
            "lumped-or-wave",
            "reading-xt",
            "where-the-energy-goes",
            "soft-and-stiff-contact",
            "buildings-that-pound",
            "storeys-that-yield",
            "waves-in-a-bridge"
        ]
    );
    for name in lesson::builtin_names() {
        let l = shipped(name);
        let report = lesson::check(&l, Control::never()).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(report.steps.len(), l.steps.len(), "{name}");
        // Every task with a solution was unmet at the start and met by it.
        for (s, r) in l.steps.iter().zip(&report.steps) {
            if s.task.as_ref().is_some_and(|t| !t.solution.is_empty()) {
                assert_eq!(r.task_met_at_start, Some(false), "{name}: {}", s.title);
                assert_eq!(r.task_met_by_solution, Some(true), "{name}: {}", s.title);
            }
        }
    }
}

#[test]
fn shipped_lessons_follow_the_teaching_standards() {
    for name in lesson::builtin_names() {
        let l = shipped(name);
        assert!(l.steps.len() >= 3, "{name}: too few steps");
        assert!(!l.goals.is_empty() && !l.teacher_notes.trim().is_empty());
        for s in &l.steps {
            // Leave out what a step does not need.
            assert!(
                s.show.len() <= 4,
                "{name}: '{}' shows {} panels",
                s.title,
                s.show.len()
            );
            // A step that asks nothing and sets nothing to do must at least state a checked fact.
            assert!(
                s.prediction.is_some() || s.task.is_some() || !s.asserts.is_empty(),
                "{name}: '{}' has no question, task or checked statement",
                s.title
            );
        }
        // Every lesson asks at least one question before it answers.
        assert!(l.steps.iter().any(|s| s.prediction.is_some()), "{name}");
    }
}

fn docs_example() -> String {
    let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/lessons.md"))
        .expect("docs/lessons.md");
    let start = doc.find("```toml\n").expect("a toml block") + "```toml\n".len();
    let end = start + doc[start..].find("```").expect("its end");
    doc[start..end].to_string()
}

#[test]
fn the_documented_example_is_complete_and_passes_the_check() {
    let l = parse_text(&docs_example(), "example", "docs/lessons.md").unwrap();
    assert_eq!(l.steps.len(), 2);
    assert!(matches!(
        l.steps[0].prediction,
        Some(Prediction::Number { .. })
    ));
    assert!(matches!(
        l.steps[1].prediction,
        Some(Prediction::Choice { .. })
    ));
    assert!(l.steps[1].task.is_some());
    let report = lesson::check(&l, Control::never()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(report.steps[1].task_met_by_solution, Some(true));
}

/// The example with `from` replaced by `to`: the error it gives.
fn broken(from: &str, to: &str) -> lesson::LessonError {
    let text = docs_example();
    assert!(text.contains(from), "{from}");
    let text = text.replacen(from, to, 1);
    match parse_text(&text, "broken", "broken.toml") {
        Err(e) => e,
        Ok(l) => lesson::check(&l, Control::never()).expect_err("the check must fail"),
    }
}

fn line_of(text: &str, needle: &str) -> usize {
    text.lines()
        .position(|l| l.contains(needle))
        .expect("the line")
        + 1
}

#[test]
fn a_typo_in_a_field_name_is_an_error_naming_its_line_and_field() {
    let e = broken("hint = ", "hnit = ");
    let text = docs_example();
    assert_eq!(e.line, Some(line_of(&text, "hint = ")));
    assert_eq!(e.field.as_deref(), Some("step[2].task.hnit"));
    assert!(e.message.contains("unknown field"), "{e}");
    assert!(e.to_string().starts_with("broken.toml, line "), "{e}");
}

#[test]
fn an_unknown_name_in_an_expression_is_an_error_not_false() {
    let e = broken(
        "goal = \"contact_duration_s > 0.7e-3\"",
        "goal = \"contact_duraton_s > 0.7e-3\"",
    );
    assert_eq!(
        e.line,
        Some(line_of(&docs_example(), "goal = \"contact_duration_s"))
    );
    assert_eq!(e.field.as_deref(), Some("step[2].task.goal"));
    assert!(
        e.message.contains("unknown name 'contact_duraton_s'"),
        "{e}"
    );
    // A compare-scene name in a bar step is unknown there.
    let e = broken(
        "asserts = [\"within(contact_duration_s",
        "asserts = [\"within(wave.contact_duration_s",
    );
    assert!(
        e.message.contains("unknown name 'wave.contact_duration_s'"),
        "{e}"
    );
}

#[test]
fn wrong_panels_keys_and_values_are_errors_with_what_is_allowed() {
    let e = broken("show = [\"xt\", \"force\"", "show = [\"gaps\", \"force\"");
    assert!(
        e.message.contains("unknown panel 'gaps'") && e.message.contains("xt"),
        "{e}"
    );
    let e = broken("unlock = [\"bar1.length\"]", "unlock = [\"bar1.lenght\"]");
    assert_eq!(e.field.as_deref(), Some("step[2].unlock"));
    let e = broken("set = [\"model=wave\"]", "set = [\"model=waves\"]");
    assert!(e.message.contains("allowed"), "{e}");
    assert_eq!(
        e.line,
        Some(line_of(&docs_example(), "set = [\"model=wave\"]"))
    );
    let e = broken("tolerance = 0.1", "tolerance = 5");
    assert!(e.message.contains("(0, 1)"), "{e}");
    let e = broken("answer = 1\n", "answer = 3\n");
    assert!(e.message.contains("1 to 2"), "{e}");
    let e = broken("scene = \"bar\"", "scene = \"bars\"");
    assert!(e.message.contains("bar|compare|buildings"), "{e}");
}

#[test]
fn a_wrong_answer_key_or_a_task_already_met_fails_the_check() {
    // The key says option 2, the model picks option 1 (the rigid contact is the shortest).
    let e = broken("answer = 1\n", "answer = 2\n");
    assert_eq!(e.field.as_deref(), Some("step[2].prediction.answer"));
    assert!(e.message.contains("the model picks option 1"), "{e}");
    // Conditions that do not pick exactly one option.
    let e = broken(
        "\"wave.contact_duration_s >= lumped_hertz.contact_duration_s\"",
        "\"wave.contact_duration_s >= 0\"",
    );
    assert_eq!(e.field.as_deref(), Some("step[2].prediction.when"));
    assert!(e.message.contains("exactly one"), "{e}");
    let e = broken("> 0.7e-3\"", "> 0.1e-3\"");
    assert!(e.message.contains("already met"), "{e}");
    let e = broken(
        "solution = [\"bar1.length=1.9\"]",
        "solution = [\"bar1.length=1.1\"]",
    );
    assert!(e.message.contains("does not meet"), "{e}");
    let e = broken(
        "solution = [\"bar1.length=1.9\"]",
        "solution = [\"bar2.length=5\"]",
    );
    assert!(e.message.contains("locked"), "{e}");
    let e = broken(
        "asserts = [\"within(contact_duration_s, 2 * bar1.length / c1, 1e-3)\"]",
        "asserts = [\"within(contact_duration_s, 2 * bar2.length / c1, 1e-3)\"]",
    );
    assert!(e.message.contains("is false"), "{e}");
}

#[test]
fn predictions_judge_answers_by_the_model_and_the_stated_tolerance() {
    let l = parse_text(&docs_example(), "example", "docs/lessons.md").unwrap();
    let run = solved(&l, 1, &[]);
    let ctx = run.context();
    let p = l.steps[0].prediction.as_ref().unwrap();
    let truth = run.run(ModelKind::Wave).unwrap().contact_duration_s;
    assert!(p.judge_number(truth * 1.09, &ctx).unwrap().correct);
    assert!(!p.judge_number(truth * 1.11, &ctx).unwrap().correct);
    assert!(!p.judge_number(f64::NAN, &ctx).unwrap().correct);
    assert!(p.judge_choice(0, &ctx).is_err());
    let ctx2 = solved(&l, 2, &[]).context();
    let c = l.steps[1].prediction.as_ref().unwrap();
    assert!(c.judge_choice(0, &ctx2).unwrap().correct);
    assert!(!c.judge_choice(1, &ctx2).unwrap().correct);
}

#[test]
fn panels_and_scenes_round_trip_their_names() {
    for p in Panel::ALL {
        assert_eq!(Panel::from_name(p.name()), Some(p));
    }
    for s in LessonScene::ALL {
        assert_eq!(LessonScene::from_name(s.name()), Some(s));
    }
    assert_eq!(Panel::from_name("plot"), None);
}

// One test per lesson: the statements its text makes, checked on the model beyond the lesson's
// own asserts (which `every_shipped_lesson_passes_the_check` evaluates).

#[test]
fn lumped_or_wave_e_falls_toward_l1_over_l2_as_bar_2_lengthens() {
    let l = shipped("lumped-or-wave");
    // Short rods bounce like blocks in Sears and the lumped model alike.
    let short = solved(&l, 1, &[]).context();
    assert!(num(&short, "restitution") > 0.99);
    assert!(num(&short, "lumped_hertz.restitution") > 0.99);
    // Step 4: lengthening bar 2 lowers e, and for long rods e approaches L1/L2 from above.
    let mut last = f64::INFINITY;
    for l2 in ["20", "30", "40", "60", "80"] {
        let ctx = solved(&l, 4, &[("bar2.length", l2)]).context();
        let e = num(&ctx, "restitution");
        let ratio = 20.0 / l2.parse::<f64>().unwrap();
        assert!(e < last, "L2 = {l2}: e = {e} did not fall");
        if ratio <= 0.5 {
            assert!(e > ratio, "L2 = {l2}: e = {e} below L1/L2");
            assert!(e - ratio < 0.05, "L2 = {l2}: e = {e} not near {ratio}");
        }
        // Wave theory gives L1/L2 exactly.
        assert!(common::rel(num(&ctx, "wave.restitution"), ratio) < 1e-6);
        last = e;
    }
}

#[test]
fn reading_xt_the_free_end_returns_relief_and_the_shorter_bar_ends_the_contact() {
    let l = shipped("reading-xt");
    let run = solved(&l, 2, &[]);
    let r = run.run(ModelKind::Wave).unwrap();
    let ctx = run.context();
    let (c1, force) = (num(&ctx, "c1"), num(&ctx, "wave_force_n"));
    let waves = r.waves.as_ref().expect("wave theory's waves");
    let area = num(&ctx, "bar1.area");
    // Half-way along bar 1: compressed between the front (0.5 L/c) and the relief (1.5 L/c).
    let at = |t: f64| waves[0].stress_pa(0.5, t / c1);
    assert!(common::rel(-at(0.75), force / area) < 1e-3, "{}", at(0.75));
    assert!(at(0.25).abs() < 1e-6 * force / area, "before the front");
    assert!(
        at(1.75).abs() < 1e-6 * force / area,
        "after the relief: {}",
        at(1.75)
    );
    // The contact ends when the first relief arrives, from the shorter bar, either way round.
    for (l1, l2) in [("0.5", "2"), ("1.9", "2"), ("3", "2")] {
        let ctx = solved(&l, 4, &[("bar1.length", l1), ("bar2.length", l2)]).context();
        let short = num(&ctx, "round_trip_1_s").min(num(&ctx, "round_trip_2_s"));
        assert!(
            common::rel(num(&ctx, "contact_duration_s"), short) < 1e-3,
            "L1 = {l1}, L2 = {l2}"
        );
    }
}

#[test]
fn where_the_energy_goes_waves_hold_what_e_below_one_seems_to_lose() {
    let l = shipped("where-the-energy-goes");
    // Elastic contact, several length ratios: nothing dissipated, the ledger closes, and the
    // energy missing from the rigid-body motion is in the waves.
    for l2 in ["0.5", "1", "2", "4"] {
        let ctx = solved(&l, 3, &[("bar2.length", l2)]).context();
        assert_eq!(num(&ctx, "energy.dissipated_j"), 0.0);
        let sum = num(&ctx, "rigid_body_fraction") + num(&ctx, "vibration_fraction");
        assert!((sum - 1.0).abs() < 1e-5, "L2 = {l2}: {sum}");
        let e = num(&ctx, "restitution");
        assert!(e < 1.0 && e > 0.0, "L2 = {l2}: e = {e}");
    }
    // Wave theory: the velocities after follow from momentum and e = L1/L2.
    for l2 in ["2", "3", "4"] {
        let ctx = solved(&l, 2, &[("bar2.length", l2)]).context();
        let (m1, m2, e) = (num(&ctx, "m1"), num(&ctx, "m2"), num(&ctx, "restitution"));
        let v1_after = (m1 - e * m2) / (m1 + m2);
        assert!((num(&ctx, "velocity_after_1_m_s") - v1_after).abs() < 1e-6);
        assert!((num(&ctx, "velocity_after_2_m_s") - (v1_after + e)).abs() < 1e-6);
    }
    // The teacher notes: the paper's reading misses the ledger by about 0.1% on the base case.
    let paper = solved(&l, 1, &[("sears.reading", "paper")]).context();
    assert!((num(&paper, "energy_balance_error") - 1e-3).abs() < 5e-4);
    // Equal rods keep less than 1% in the waves (the task's statement).
    let equal = solved(&l, 3, &[("bar2.length", "1")]).context();
    assert!(num(&equal, "vibration_fraction") < 0.01);
}

#[test]
fn soft_and_stiff_contact_a_tau_grows_with_k_and_the_paper_reading_fails_at_any_step() {
    let l = shipped("soft-and-stiff-contact");
    // Step 2: stiffer contact, shorter contact and larger a tau, toward wave theory's 2 L1/c1.
    let mut last = (f64::INFINITY, 0.0);
    for k in ["1e9", "1e10", "1e11", "1e12"] {
        let ctx = solved(&l, 2, &[("contact.stiffness", k)]).context();
        let (d, at) = (num(&ctx, "contact_duration_s"), num(&ctx, "a_tau"));
        assert!(d < last.0 && at > last.1, "k = {k}");
        assert!(d >= num(&ctx, "round_trip_1_s") * (1.0 - 1e-3), "k = {k}");
        last = (d, at);
    }
    // Step 4: a tau is proportional to k for a linear spring.
    let a = num(&solved(&l, 4, &[]).context(), "a_tau");
    let b = num(
        &solved(&l, 4, &[("contact.stiffness", "1e10")]).context(),
        "a_tau",
    );
    assert!(common::rel(b, 10.0 * a) < 1e-6, "{a} {b}");
    assert!(b < std::f64::consts::FRAC_PI_2);
    // The teacher notes' thresholds for the paper reading on these rods.
    let at2 = solved(&l, 4, &[("contact.stiffness", "2e9")]).context();
    assert_eq!(
        at2.get("sears.creates_energy").unwrap(),
        lesson::Value::Bool(true)
    );
    assert!(num(&at2, "a_tau") < 0.31);
    let at4 = solved(&l, 4, &[("contact.stiffness", "4e9")]).context();
    assert!(num(&at4, "peak_force_n") > 1.1 * num(&at4, "wave_force_n"));
    assert!((num(&at4, "a_tau") - 0.6).abs() < 0.01);
    // Step 5: the paper reading creates energy at 1e12 N/m whatever the step.
    for dt in ["1e-7", "2.5e-8"] {
        let ctx = solved(&l, 5, &[("solver.dt", dt)]).context();
        assert_eq!(
            ctx.get("sears.creates_energy").unwrap(),
            lesson::Value::Bool(true),
            "dt = {dt}"
        );
        assert!(num(&ctx, "restitution") > 1.0, "dt = {dt}");
    }
    // ... while the end reading gives wave theory's e for the same rods.
    let end = solved(&l, 5, &[("sears.reading", "end")]).context();
    assert!(common::rel(num(&end, "restitution"), 0.5) < 0.01);
}

#[test]
fn buildings_that_pound_the_abs_gap_avoids_pounding_and_the_srss_gap_does_not() {
    let l = shipped("buildings-that-pound");
    let ctx = solved(&l, 3, &[]).context();
    let (min, abs, srss) = (
        num(&ctx, "min_gap_m"),
        num(&ctx, "abs_gap_m"),
        num(&ctx, "srss_gap_m"),
    );
    assert!(srss < min && min < abs);
    let impacts = |gap: f64| {
        num(
            &solved(&l, 4, &[("gap", &gap.to_string())]).context(),
            "impact_count",
        )
    };
    assert!(impacts(srss) >= 1.0, "the SRSS gap still pounds");
    assert_eq!(impacts(min), 0.0, "the minimum gap avoids pounding");
    assert_eq!(impacts(abs), 0.0, "the ABS gap avoids pounding");
    // With pounding the stiff building moves more and the flexible one less (step 2's claim),
    // and the right building is the more flexible one.
    let ctx = solved(&l, 2, &[]).context();
    assert!(num(&ctx, "period_right_s") > num(&ctx, "period_left_s"));
    assert!(
        num(&ctx, "peak_displacement_left_m") > num(&ctx, "peak_displacement_left_no_pounding_m")
    );
    assert!(
        num(&ctx, "peak_displacement_right_m") < num(&ctx, "peak_displacement_right_no_pounding_m")
    );
}

/// The bridge run of a solved bridge step.
fn bridge_run(solved: &Solved) -> &pounding::model::bridge::BridgeResult {
    match solved {
        Solved::Bridge { result, .. } => result,
        _ => panic!("not a bridge step"),
    }
}

#[test]
fn waves_in_a_bridge_an_abutment_takes_z_v_and_a_girder_joint_z_v_over_two() {
    let l = shipped("waves-in-a-bridge");
    let run = solved(&l, 2, &[]);
    let ctx = run.context();
    // The impedance from the girder's own numbers, not the context's.
    let (a, e, rho): (f64, f64, f64) = (6.5, 3.4e10, 2500.0);
    assert_eq!(num(&ctx, "span.area"), a);
    assert_eq!(num(&ctx, "span.youngs_modulus"), e);
    assert_eq!(num(&ctx, "span.density"), rho);
    let z = a * (e * rho).sqrt();
    let r = bridge_run(&run);
    let strongest_at = |abutment: bool| {
        r.impacts
            .iter()
            .filter(|i| (r.joints[i.level].kind() == "abutment") == abutment)
            .max_by(|x, y| x.peak_force_n.total_cmp(&y.peak_force_n))
            .expect("impacts of that kind")
    };
    // Against the rigid wall the girder's end is stopped: Z v; two equal girders share the
    // closing speed: Z v / 2.
    let wall = strongest_at(true);
    assert!(common::rel(wall.peak_force_n, z * wall.approach_velocity_m_s) < 0.02);
    let pair = strongest_at(false);
    assert!(common::rel(pair.peak_force_n, 0.5 * z * pair.approach_velocity_m_s) < 0.05);
}

#[test]
fn waves_in_a_bridge_a_contact_lasts_about_a_round_trip_whatever_the_girders_length() {
    let l = shipped("waves-in-a-bridge");
    let c = (3.4e10f64 / 2500.0).sqrt();
    let mut last = 0.0;
    for length in [25.0, 30.0, 40.0, 60.0, 80.0] {
        let ctx = solved(&l, 3, &[("span.length", &length.to_string())]).context();
        let trip = 2.0 * length / c;
        let d = num(&ctx, "strongest_impact_duration_s");
        assert!(
            d > trip && d < 1.1 * trip,
            "L = {length}: {d} s, 2L/c = {trip} s"
        );
        assert!(d > last, "L = {length}: a longer girder meets for longer");
        last = d;
    }
}

#[test]
fn waves_in_a_bridge_the_widest_opening_grows_as_the_motion_travels_slower_and_the_seat_only_flags()
{
    let l = shipped("waves-in-a-bridge");
    let opening = |v: &str, seat: &str| {
        let ctx = solved(
            &l,
            5,
            &[
                ("motion.apparent_velocity", v),
                ("bridge.seat_length", seat),
            ],
        )
        .context();
        (num(&ctx, "max_opening_m"), num(&ctx, "unseated_count"))
    };
    let mut last = 0.0;
    for v in [
        "uniform", "5000", "2000", "1000", "500", "300", "200", "100",
    ] {
        let (o, _) = opening(v, "0.1");
        assert!(o > last, "v = {v}: {o} m");
        last = o;
    }
    // The seat length flags unseating and changes nothing of the run.
    let (short, lost) = opening("200", "0.1");
    let (long, kept) = opening("200", "0.25");
    assert_eq!(short, long);
    assert_eq!((lost, kept), (1.0, 0.0));
}

#[test]
fn a_bridge_runs_unseating_warnings_come_first_one_per_unseated_joint() {
    // The window hides these with the seats' panels in a step that asks about the seats.
    let l = shipped("waves-in-a-bridge");
    for v in ["200", "150", "100"] {
        let run = solved(&l, 5, &[("motion.apparent_velocity", v)]);
        let r = bridge_run(&run);
        assert!(!r.unseating.is_empty(), "v = {v}");
        for (u, w) in r.unseating.iter().zip(&r.warnings) {
            assert!(
                w.starts_with(&format!("joint {} unseated", u.joint)),
                "v = {v}: {w}"
            );
        }
        let rest = &r.warnings[r.unseating.len()..];
        assert!(rest.iter().all(|w| !w.contains("unseated")), "v = {v}");
    }
}

#[test]
fn a_bridge_name_of_a_joint_the_bridge_lacks_has_no_value_and_a_misspelt_one_is_unknown() {
    let l = shipped("waves-in-a-bridge");
    let ctx = solved(&l, 1, &[]).context();
    assert_eq!(num(&ctx, "joint_count"), 4.0);
    let missing = ctx.get("joint5.impacts").unwrap_err().to_string();
    assert!(missing.contains("does not give it"), "{missing}");
    let typo = ctx.get("joint1.impact").unwrap_err().to_string();
    assert!(typo.contains("unknown name"), "{typo}");
    // Joints count from 0 at the left abutment, girders from 1.
    assert_eq!(
        ctx.get("joint0.abutment").unwrap(),
        lesson::Value::Bool(true)
    );
    assert!(ctx.get("girder0.round_trip_s").is_err());
    assert!(num(&ctx, "girder3.round_trip_s") > 0.0);
}

#[test]
fn a_bridge_prediction_whose_answer_an_earlier_openings_plot_shows_fails_the_check() {
    let ask = |first_show: &str| {
        let text = format!(
            r#"{HEADER}[[step]]
title = "Openings"
text = "The bridge."
scene = "bridge"
preset = "bridge-3-span-unseating"
show = [{first_show}]

[[step]]
title = "Joint 2"
text = "The same bridge."
scene = "bridge"
preset = "bridge-3-span-unseating"
show = ["joints"]

[step.prediction]
kind = "number"
question = "How far does joint 2 open?"
unit = "m"
answer = "joint2.max_opening_m"
tolerance = 0.1
explanation = "144 mm."
"#
        );
        let l = lesson::parse_text(&text, "t", "t.toml").expect("parses");
        lesson::check(&l, Control::never())
    };
    let e = ask("\"openings\"").expect_err("the opening was on screen");
    assert!(
        e.message.contains("joint2.max_opening_m") && e.message.contains("step 1's openings"),
        "{e}"
    );
    ask("\"bridge\", \"force\"").unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn the_command_line_lists_checks_and_writes_a_handout() {
    let o = common::pounding(&["lesson", "--list"]);
    assert!(o.status.success(), "{}", common::stderr(&o));
    let out = common::stdout(&o);
    for name in lesson::builtin_names() {
        assert!(out.contains(name), "{name} not listed");
    }
    let o = common::pounding(&["lesson", "--check", "reading-xt"]);
    assert!(o.status.success(), "{}", common::stderr(&o));
    assert!(common::stdout(&o).contains("ok: 4 steps checked"));

    let dir = std::env::temp_dir().join(format!("pounding-lesson-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let bad = dir.join("bad.toml");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(&bad, docs_example().replacen("hint = ", "hnit = ", 1)).unwrap();
    let o = common::pounding(&["lesson", "--check", bad.to_str().unwrap()]);
    assert!(!o.status.success());
    let err = common::stderr(&o);
    assert!(
        err.contains("bad.toml, line ") && err.contains("step[2].task.hnit"),
        "{err}"
    );

    let out_dir = dir.join("handout");
    let o = common::pounding(&[
        "lesson",
        "reading-xt",
        "--handout",
        out_dir.to_str().unwrap(),
        "--teacher",
    ]);
    assert!(o.status.success(), "{}", common::stderr(&o));
    let md = std::fs::read_to_string(out_dir.join("reading-xt-teacher.md")).unwrap();
    assert!(md.contains("## Teacher notes") && md.contains("**Answer:**"));
    let figures: Vec<_> = std::fs::read_dir(&out_dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.path().extension().is_some_and(|x| x == "png"))
        .collect();
    assert!(figures.len() >= 4, "{} figures", figures.len());
    for f in &figures {
        let bytes = std::fs::read(f.path()).unwrap();
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "{:?}", f.path());
        let name = f.file_name().to_string_lossy().to_string();
        assert!(md.contains(&name), "{name} not in the worksheet");
    }
    // The student's version has the questions but not the answers.
    let o = common::pounding(&[
        "lesson",
        "reading-xt",
        "--handout",
        out_dir.to_str().unwrap(),
    ]);
    assert!(o.status.success());
    let student = std::fs::read_to_string(out_dir.join("reading-xt.md")).unwrap();
    assert!(student.contains("**Predict first.**") && !student.contains("**Answer:**"));
    assert!(!student.contains("Teacher notes"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Two compare steps of the paper's base case: the first shows `first_show`, the second asks
/// wave theory's e.
/// A test lesson's lines before its first step.
const HEADER: &str =
    "title = \"t\"\naudience = \"a\"\nduration_min = 5\ngoals = [\"g\"]\nteacher_notes = \"n\"\n\n";

fn ask_after_showing(first_show: &str) -> Result<lesson::CheckReport, lesson::LessonError> {
    let text = format!(
        r#"{HEADER}[[step]]
title = "Five models"
text = "The base case."
scene = "compare"
show = [{first_show}]

[[step]]
title = "Wave theory's e"
text = "The same impact."
scene = "compare"
show = ["readouts"]

[step.prediction]
kind = "number"
question = "What e does wave theory give?"
unit = ""
answer = "wave.restitution"
tolerance = 0.05
explanation = "L1/L2."
"#
    );
    let l = lesson::parse_text(&text, "t", "t.toml").expect("parses");
    lesson::check(&l, Control::never())
}

#[test]
fn a_compare_step_solves_only_the_models_it_names() {
    let l = shipped("lumped-or-wave");
    // Step 4 names Sears and wave theory: the lumped blocks are neither solved nor shown.
    let ctx = solved(&l, 4, &[]).context();
    assert!(num(&ctx, "wave.restitution") > 0.0);
    assert!(ctx.get("lumped_hertz.restitution").is_err());
    // Step 3 names the lumped Hertz blocks too: they bounce with e = 1 off long rods.
    let ctx = solved(&l, 3, &[]).context();
    assert!(num(&ctx, "lumped_hertz.restitution") > 0.99);
}

/// A one-step compare lesson naming `models` whose statement reads `read`.
fn compare_lesson_naming(models: &str, read: &str) -> Result<lesson::Lesson, lesson::LessonError> {
    let text = format!(
        r#"{HEADER}[[step]]
title = "Two models"
text = "The base case."
scene = "compare"
show = ["force"]
models = [{models}]
asserts = ["{read} > 0"]
"#
    );
    lesson::parse_text(&text, "t", "t.toml")
}

#[test]
fn a_compare_step_that_reads_a_model_it_leaves_out_or_names_no_sears_is_refused_on_its_line() {
    compare_lesson_naming("\"sears\", \"wave\"", "wave.restitution")
        .unwrap_or_else(|e| panic!("{e}"));
    let e =
        compare_lesson_naming("\"sears\", \"wave\"", "fe.restitution").expect_err("fe is left out");
    assert_eq!(e.field.as_deref(), Some("step[1].models"), "{e}");
    assert!(
        e.message.contains("fe.restitution") && e.message.contains("fe"),
        "{e}"
    );
    assert_eq!(e.line, Some(7), "{e}");
    let e = compare_lesson_naming("\"wave\"", "wave.restitution").expect_err("no sears");
    assert!(e.message.contains("sears"), "{e}");
    let e =
        compare_lesson_naming("\"sears\", \"kelvin\"", "restitution").expect_err("not compared");
    assert!(
        e.message.contains("unknown model 'kelvin'") && e.message.contains("lumped-linear"),
        "{e}"
    );
    assert_eq!(e.line, Some(12), "{e}");
}

#[test]
fn a_prediction_whose_answer_an_earlier_step_shows_fails_the_check() {
    let e = ask_after_showing("\"force\", \"readouts\"").expect_err("the answer was on screen");
    assert_eq!(e.field.as_deref(), Some("step[2].prediction"), "{e}");
    assert!(
        e.message.contains("wave.restitution = 0.5") && e.message.contains("step 1's readouts"),
        "{e}"
    );
    // Without the table the answer is not on screen before its question.
    ask_after_showing("\"force\"").unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn a_handout_is_one_printable_html_page_a_copy_with_every_figure_inlined_and_no_result_before_its_question()
 {
    for name in ["buildings-that-pound", "waves-in-a-bridge"] {
        handout_is_printable(name);
    }
}

fn handout_is_printable(name: &str) {
    let dir = std::env::temp_dir().join(format!("pounding-handout-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let o = common::pounding(&[
        "lesson",
        name,
        "--handout",
        dir.to_str().unwrap(),
        "--teacher",
    ]);
    assert!(o.status.success(), "{}", common::stderr(&o));
    let pngs: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().to_string())
        .filter(|n| n.ends_with(".png"))
        .collect();
    assert!(!pngs.is_empty());
    for (file, teacher) in [
        (format!("{name}.html"), false),
        (format!("{name}-teacher.html"), true),
    ] {
        let html = std::fs::read_to_string(dir.join(&file)).unwrap();
        let doc = roxmltree::Document::parse_with_options(
            &html,
            roxmltree::ParsingOptions {
                allow_dtd: true,
                ..Default::default()
            },
        )
        .unwrap_or_else(|e| panic!("{file} does not parse: {e}"));
        let mut named = vec![];
        for img in doc.descendants().filter(|n| n.has_tag_name("img")) {
            let src = img.attribute("src").unwrap_or_default();
            // The PNG signature, base64-encoded.
            assert!(
                src.starts_with("data:image/png;base64,iVBORw0KGgo"),
                "{file}: {}",
                &src[..40.min(src.len())]
            );
            let title = img.attribute("title").expect("each image names its figure");
            assert!(
                pngs.iter().any(|p| p == title),
                "{file}: {title} is not a figure written"
            );
            assert!(!img.attribute("alt").unwrap_or_default().is_empty());
            named.push(title.to_string());
        }
        for p in &pngs {
            assert!(named.contains(p), "{file} does not embed {p}");
        }
        let text: String = doc.descendants().filter_map(|n| n.text()).collect();
        assert_eq!(text.contains("Answer:"), teacher, "{file}");
        assert_eq!(text.contains("Teacher notes"), teacher, "{file}");
    }
    // In the student's copy a questioning step's figures come after every question.
    let md = std::fs::read_to_string(dir.join(format!("{name}.md"))).unwrap();
    let results = md.find("## Results").expect("a results section");
    let lesson = shipped(name);
    for (k, step) in lesson.steps.iter().enumerate() {
        if step.prediction.is_none() && step.task.is_none() {
            continue;
        }
        let figure = format!("![Step {}, ", k + 1);
        if let Some(at) = md.find(&figure) {
            assert!(at > results, "step {}'s figure before the results", k + 1);
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}
