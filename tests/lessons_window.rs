//! Every step of every shipped lesson walked through in the window, headless (egui_kittest on a
//! wgpu adapter), as a student would: the step loads its scene, the result views stay hidden
//! until the prediction is answered (an option clicked, or a number typed, then Answer), and a
//! scripted change of the step's unlocked settings (its `solution`) meets its task.
#![cfg(feature = "gui")]

use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use pounding::app::{HIDE_TIMINGS, Launch, PoundingApp, SceneKind};
use pounding::lesson::{self, LessonScene};

mod common;

const WAITING: &str = "The results appear once you have answered.";

fn window(launch: Launch, size: egui::Vec2) -> Harness<'static, PoundingApp> {
    HIDE_TIMINGS.store(true, std::sync::atomic::Ordering::Relaxed);
    let mut h = Harness::builder()
        .with_size(size)
        .wgpu()
        .build_eframe(|cc| PoundingApp::new(cc, launch));
    common::settle(&mut h, "launch");
    h
}

/// The window on lesson `name`, at its first step.
fn lesson_window(name: &str, size: egui::Vec2) -> Harness<'static, PoundingApp> {
    window(
        Launch {
            lesson: Some(name.to_string()),
            lesson_step: Some(1),
            ..Default::default()
        },
        size,
    )
}

/// Turns to step `k` and waits for its solves.
fn go_to(h: &mut Harness<'static, PoundingApp>, k: usize, at: &str) {
    h.state_mut().lesson_go_to(k);
    common::settle(h, at);
}

fn scene_of(s: LessonScene) -> SceneKind {
    match s {
        LessonScene::Bar => SceneKind::BarImpact,
        LessonScene::Compare => SceneKind::WaveVsLumped,
        LessonScene::Buildings => SceneKind::Buildings,
        LessonScene::Bridge => SceneKind::Bridge,
    }
}

fn player<'a>(h: &'a Harness<'static, PoundingApp>) -> &'a pounding::app::LessonPlayer {
    h.state().lesson_player().expect("a lesson is open")
}

#[test]
fn every_lesson_step_loads_hides_results_until_predicted_and_its_task_is_met_by_its_solution() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    for name in lesson::builtin_names() {
        let lesson = lesson::builtin(name).expect("shipped lessons parse");
        let mut h = lesson_window(name, egui::vec2(1280.0, 900.0));
        for (k, step) in lesson.steps.iter().enumerate() {
            let at = format!("{name} step {}", k + 1);
            go_to(&mut h, k, &at);
            assert_eq!(player(&h).step, k, "{at}");
            assert!(
                player(&h).load_error.is_none(),
                "{at}: {:?}",
                player(&h).load_error
            );
            assert_eq!(h.state().scene_kind(), scene_of(step.scene), "{at}: scene");
            h.get_by_label(&step.title);
            if let Some(p) = &step.prediction {
                assert!(
                    h.state().lesson_hides_results(),
                    "{at}: results before the answer"
                );
                h.get_by_label(WAITING);
                common::answer(&mut h, p, &format!("{name} step {}", k + 1));
                let judged = player(&h).judged.clone();
                assert!(matches!(judged, Some(Ok(_))), "{at}: judged {judged:?}");
                assert!(
                    !h.state().lesson_hides_results(),
                    "{at}: results after the answer"
                );
                assert!(h.query_by_label(WAITING).is_none(), "{at}");
                h.get_by_label(&pounding::app::reflow(p.explanation()));
            }
            if let Some(task) = &step.task {
                if task.solution.is_empty() {
                    continue;
                }
                assert_ne!(
                    player(&h).task,
                    Some(Ok(true)),
                    "{at}: met before any change"
                );
                for (key, value, _) in &task.solution {
                    h.state_mut()
                        .lesson_set(key, value)
                        .unwrap_or_else(|e| panic!("{at}: {key}={value}: {e}"));
                }
                common::settle(&mut h, &format!("{at}: solution"));
                assert_eq!(
                    player(&h).task,
                    Some(Ok(true)),
                    "{at}: the solution meets the task"
                );
                h.get_by_label("met");
            }
        }
    }
}

#[test]
fn a_lesson_opened_at_a_step_in_lecture_mode_shows_that_step_and_only_its_unlocked_settings() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    let lesson = lesson::builtin("lumped-or-wave").expect("shipped");
    let (k, step) = lesson
        .steps
        .iter()
        .enumerate()
        .find(|(_, s)| !s.unlock.is_empty())
        .expect("a step with unlocked settings");
    let h = window(
        Launch {
            lesson: Some("lumped-or-wave".into()),
            lesson_step: Some(k + 1),
            lecture: true,
            ..Default::default()
        },
        egui::vec2(1280.0, 720.0) / pounding::app::LECTURE_ZOOM,
    );
    assert!(h.state().lecture());
    assert_eq!(player(&h).step, k);
    h.get_by_label(&step.title);
    // The Lessons and View menus stay; the scene tabs and preset controls are gone.
    h.get_by_label("Lessons");
    assert!(h.query_by_label("Building pounding").is_none());
    assert!(h.query_by_label("Load preset").is_none());
}

/// Every label of a widget that could replace a step's scene or change a setting by a choice:
/// the scene tabs, the presets' buttons, and every choice the scenes offer.
fn tempting_labels() -> Vec<String> {
    use pounding::model::building::{ContactModel, DampingModel, SlabReading};
    use pounding::model::hysteresis::Hysteresis;
    use pounding::model::impact::ModelKind;
    let mut labels: Vec<String> = [
        "Bar impact",
        "Wave vs lumped",
        "Building pounding",
        "Bridge pounding",
        "Parameter study",
        "Load preset",
        "Reset",
        "Paper's buildings",
        "Load",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    labels.extend(ContactModel::ALL.iter().map(|m| m.name().to_string()));
    labels.extend(Hysteresis::ALL.iter().map(|m| m.name().to_string()));
    labels.extend(DampingModel::ALL.iter().map(|m| m.name().to_string()));
    labels.extend(SlabReading::ALL.iter().map(|m| m.name().to_string()));
    labels.extend(ModelKind::ALL.iter().map(|m| m.name().to_string()));
    labels.sort();
    labels.dedup();
    labels
}

#[test]
fn every_step_holds_its_scene_and_locked_settings_against_tabs_presets_and_choices() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    let labels = tempting_labels();
    for name in lesson::builtin_names() {
        let lesson = lesson::builtin(name).expect("shipped lessons parse");
        let mut h = lesson_window(name, egui::vec2(1600.0, 1000.0));
        for (k, step) in lesson.steps.iter().enumerate() {
            let at = format!("{name} step {}", k + 1);
            go_to(&mut h, k, &at);
            if let Some(p) = &step.prediction {
                common::answer(&mut h, p, &format!("{name} step {}", k + 1));
            }
            let locked = locked_values(&h, step);
            for label in &labels {
                let nodes: Vec<_> = h.query_all_by_label(label).collect();
                if nodes.is_empty() {
                    continue;
                }
                for node in nodes {
                    node.click();
                }
                h.run_steps(2);
                assert_eq!(
                    h.state().scene_kind(),
                    scene_of(step.scene),
                    "{at}: '{label}' changed the scene"
                );
            }
            common::settle(&mut h, &format!("{at}: after the clicks"));
            assert_still(&h, &locked, &at);
            // A scripted change of a locked key is refused by name.
            if let Some((key, _)) = locked.iter().find(|(_, v)| v.is_some()) {
                let e = h.state_mut().lesson_set(key, "1").unwrap_err();
                assert!(e.contains(key) && e.contains("locked"), "{at}: {e}");
            }
        }
    }
}

#[test]
fn teacher_notes_show_only_in_teacher_mode() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    let mut h = window(
        Launch {
            lesson: Some("buildings-that-pound".into()),
            lesson_step: Some(1),
            ..Default::default()
        },
        egui::vec2(1280.0, 900.0),
    );
    assert!(h.query_by_label("Teacher notes").is_none());
    h.state_mut().set_teacher(true);
    h.run_steps(2);
    h.get_by_label("Teacher notes");
}

/// The bridge lesson's last step under a `--drag` of `drag`, its frames turned until `done`
/// holds (a drag solves on every frame, so the window never settles); `each` is checked after
/// every frame.
fn bridge_step_dragged(
    drag: &str,
    each: impl Fn(&Harness<'static, PoundingApp>),
    done: impl Fn(&Harness<'static, PoundingApp>) -> bool,
) {
    HIDE_TIMINGS.store(true, std::sync::atomic::Ordering::Relaxed);
    let lesson = lesson::builtin("waves-in-a-bridge").expect("shipped");
    let launch = Launch {
        lesson: Some("waves-in-a-bridge".into()),
        lesson_step: Some(lesson.steps.len()),
        // A drag goes to the scene on screen from the first frame: the step's.
        scene: Some(SceneKind::Bridge),
        drag: Some(pounding::app::DragSpec::parse(drag).expect("a drag")),
        ..Default::default()
    };
    let mut h = Harness::builder()
        .with_size(egui::vec2(1280.0, 900.0))
        .wgpu()
        .build_eframe(|cc| PoundingApp::new(cc, launch));
    let start = std::time::Instant::now();
    while !done(&h) {
        assert!(
            start.elapsed() < std::time::Duration::from_secs(120),
            "{drag}: never done"
        );
        h.step();
        each(&h);
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
}

#[test]
fn a_bridge_step_undoes_a_locked_settings_change_and_keeps_an_unlocked_one() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    // The step travels at 200 m/s and unlocks only the seat length.
    let said = "motion.apparent_velocity stays as the step set it";
    bridge_step_dragged(
        "motion.apparent_velocity=300:400",
        |h| {
            assert_eq!(
                h.state()
                    .lesson_setting("motion.apparent_velocity")
                    .as_deref(),
                Some("200")
            )
        },
        |h| h.query_by_label_contains(said).is_some(),
    );
    bridge_step_dragged(
        "bridge.seat_length=0.12:0.2",
        |_| {},
        |h| {
            h.state()
                .lesson_setting("bridge.seat_length")
                .is_some_and(|v| v != "0.1")
        },
    );
}

#[test]
fn a_launch_time_holds_a_bridge_lesson_steps_animation_there_paused() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    let mut h = window(
        Launch {
            lesson: Some("waves-in-a-bridge".into()),
            lesson_step: Some(1),
            time_s: Some(2.5),
            ..Default::default()
        },
        egui::vec2(1280.0, 900.0),
    );
    assert_eq!(h.state().scene_kind(), SceneKind::Bridge);
    h.run_steps(5);
    assert_eq!(h.state().animation_time(), 2.5);
    // Played on, then turned to another step: that step's scene is held at the launch time.
    h.key_press(egui::Key::Space);
    h.run_steps(10);
    assert!(h.state().animation_time() > 2.5, "Space plays on");
    go_to(&mut h, 3, "waves-in-a-bridge step 4");
    h.run_steps(5);
    assert_eq!(h.state().animation_time(), 2.5);
}

/// The locked settings of `step` and their values now.
fn locked_values(
    h: &Harness<'static, PoundingApp>,
    step: &lesson::Step,
) -> Vec<(String, Option<String>)> {
    pounding::model::settings::concrete_keys(step.scene.settings().0)
        .into_iter()
        .filter(|key| {
            !step
                .unlock
                .iter()
                .any(|u| key == u || key.starts_with(&format!("{u}.")))
        })
        .map(|key| {
            let v = h.state().lesson_setting(&key);
            (key, v)
        })
        .collect()
}

/// Every locked setting still has the value it had.
fn assert_still(h: &Harness<'static, PoundingApp>, locked: &[(String, Option<String>)], at: &str) {
    for (key, before) in locked {
        assert_eq!(
            &h.state().lesson_setting(key),
            before,
            "{at}: the locked {key} changed"
        );
    }
}

/// The lesson's own controls (they turn steps, answer, leave), the menus (they open popups;
/// their items are tried by the tabs-and-presets test) and the buttons that write files (the
/// exports, Save): every other widget is tried.
const LESSON_CONTROLS: [&str; 16] = [
    "png",
    "svg",
    "csv",
    "Save",
    "Open",
    "File",
    "Lessons",
    "View",
    "Leave",
    "< Back",
    "Next >",
    "Reset",
    "Reset step",
    "Hint",
    "Answer",
    "On to the task >",
];

#[test]
fn every_widget_of_every_step_leaves_the_scene_and_the_locked_settings_as_they_were() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    use egui::accesskit::Role;
    let tried = [
        Role::Button,
        Role::CheckBox,
        Role::RadioButton,
        Role::ComboBox,
        Role::Slider,
        Role::SpinButton,
        Role::DisclosureTriangle,
    ];
    for name in lesson::builtin_names() {
        let lesson = lesson::builtin(name).expect("shipped lessons parse");
        let mut h = lesson_window(name, egui::vec2(1600.0, 1000.0));
        for (k, step) in lesson.steps.iter().enumerate() {
            let at = format!("{name} step {}", k + 1);
            go_to(&mut h, k, &at);
            if let Some(p) = &step.prediction {
                common::answer(&mut h, p, &at);
            }
            let locked = locked_values(&h, step);
            let widgets: Vec<(Role, String)> = h
                .root()
                .children_recursive()
                .filter_map(|n| {
                    let a = n.accesskit_node();
                    let label = a.label()?;
                    (tried.contains(&a.role()) && !LESSON_CONTROLS.contains(&label.as_str()))
                        .then(|| (a.role(), label))
                })
                .collect();
            assert!(
                widgets.len() > 3,
                "{at}: only {} widgets found",
                widgets.len()
            );
            for (i, (role, label)) in widgets.iter().enumerate() {
                // The same label twice (each plot's png button): its own occurrence.
                let nth = widgets[..i]
                    .iter()
                    .filter(|w| w == &&(*role, label.clone()))
                    .count();
                let Some(node) = h.query_all_by_role_and_label(*role, label).nth(nth) else {
                    continue;
                };
                if matches!(role, Role::Slider | Role::SpinButton) {
                    // A slider or a field moves from the keyboard.
                    node.focus();
                    h.run_steps(1);
                    h.key_press(egui::Key::ArrowRight);
                } else {
                    node.click();
                }
                h.run_steps(2);
                // A popup a click opened closes again.
                h.key_press(egui::Key::Escape);
                h.run_steps(1);
                assert_eq!(
                    h.state().scene_kind(),
                    scene_of(step.scene),
                    "{at}: {role:?} '{label}' changed the scene"
                );
            }
            common::settle(&mut h, &format!("{at}: after every widget"));
            assert_still(&h, &locked, &at);
        }
    }
}
