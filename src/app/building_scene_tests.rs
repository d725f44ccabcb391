//! The Building pounding scene as its solve lands stage by stage: what it shows after the run
//! and before its checks, a run still solving, and a newer request's run that never carries an
//! older one's checks. The stages come from the scene's own job on a worker thread and are
//! handed to a scene one at a time, so what is on screen between two stages is checked without
//! racing the thread.

use super::*;
use crate::app::building_job::Stage;
use crate::app::building_view::BuildingDrawing;
use crate::app::worker::Landed;
use crate::model::building::{BuildingResult, solve_streaming};
use crate::model::control::Control;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use std::time::{Duration, Instant};

fn paper_buildings() -> BuildingSetup {
    crate::io::preset::load_for("paper-buildings", "buildings").expect("a shipped preset")
}

/// Every stage of one request of the scene's job, in the order the scene takes them.
fn stages_of(setup: BuildingSetup) -> Vec<Landed<Output>> {
    let mut slot = SolveSlot::staged(run_job, || {});
    slot.request(setup);
    let start = Instant::now();
    let mut landed = vec![];
    while slot.busy() {
        match slot.poll_stage() {
            Some(l) => landed.push(l),
            None => {
                slot.flush();
                assert!(start.elapsed() < Duration::from_secs(120), "no outcome");
                std::thread::sleep(Duration::from_millis(1));
            }
        }
    }
    assert_eq!(slot.error, None);
    landed
}

/// A scene whose own solve is stopped: what it shows is only what a test hands it.
fn quiet_scene() -> BuildingScene {
    let mut scene = BuildingScene::new(&egui::Context::default(), paper_buildings());
    scene.cancel();
    scene.playback.playing = false;
    scene
}

/// A harness drawing the scene's results as the window's central panel does.
fn harness(scene: BuildingScene) -> Harness<'static, BuildingScene> {
    let exporter = Exporter::default();
    Harness::builder()
        .with_size(egui::vec2(1280.0, 1500.0))
        .build_ui_state(
            move |ui, scene: &mut BuildingScene| {
                egui::ScrollArea::vertical().show(ui, |ui| scene.main_ui(ui, &exporter));
            },
            scene,
        )
}

/// Hands the scene one stage and draws it.
fn land(h: &mut Harness<'static, BuildingScene>, stage: Landed<Output>) {
    h.state_mut().land(stage);
    h.run_steps(2);
}

fn shows(h: &Harness<'static, BuildingScene>, text: &str) -> bool {
    h.query_all_by_label_contains(text).next().is_some()
}

#[test]
fn the_job_hands_out_the_run_so_far_then_the_run_then_the_run_without_contact_then_the_estimate() {
    let stages = stages_of(paper_buildings());
    let names: Vec<&str> = stages
        .iter()
        .map(|l| match &l.output {
            Ok(Stage::Partial(_)) => "partial",
            Ok(Stage::Run(_)) => "run",
            Ok(Stage::Baseline(_)) => "baseline",
            Ok(Stage::Estimate(_)) => "estimate",
            Err(_) => "error",
        })
        .collect();
    let runs_so_far = names.iter().take_while(|n| **n == "partial").count();
    assert_eq!(
        names[runs_so_far..],
        ["run", "baseline", "estimate"],
        "{names:?}"
    );
    let lasts: Vec<bool> = stages.iter().map(|l| l.last).collect();
    assert_eq!(lasts.iter().filter(|l| **l).count(), 1, "{lasts:?}");
    assert!(lasts[lasts.len() - 1]);
    // Each run so far reaches further than the one before, and short of the whole run.
    let reached: Vec<f64> = stages
        .iter()
        .filter_map(|l| match &l.output {
            Ok(Stage::Partial(d) | Stage::Run(d)) => Some(d.result.solved_to_s),
            _ => None,
        })
        .collect();
    assert!(reached.windows(2).all(|w| w[0] < w[1]), "{reached:?}");
    let Ok(Stage::Estimate(estimate)) = &stages[stages.len() - 1].output else {
        unreachable!("checked above")
    };
    assert!(estimate.is_some(), "the paper's buildings have an estimate");
}

#[test]
fn the_run_is_shown_with_its_checks_pending_and_each_check_once_it_lands() {
    let stages = stages_of(paper_buildings());
    let mut h = harness(quiet_scene());
    let mut later = stages
        .into_iter()
        .skip_while(|l| matches!(l.output, Ok(Stage::Partial(_))));
    land(&mut h, later.next().expect("the run"));
    // The run is on screen; the run without pounding and the estimate are on their way.
    assert!(shows(&h, "(without pounding pending)"));
    assert!(shows(&h, "left, no pounding (pending)"));
    assert!(shows(
        &h,
        "error bound (against a twice finer run): pending"
    ));
    assert!(!shows(
        &h,
        "error bound (against a twice finer run): max force"
    ));
    assert!(shows(&h, "impacts ("));
    assert!(h.state().lesson_context().is_none(), "no baseline yet");
    assert!(h.state().solving_note().contains("no-pounding run"));

    land(&mut h, later.next().expect("the baseline"));
    assert!(!shows(&h, "pending)"));
    assert!(shows(&h, "they pound"), "the gap once its run is in");
    assert!(shows(
        &h,
        "error bound (against a twice finer run): pending"
    ));
    assert!(h.state().solving_note().contains("error estimate pending"));

    land(&mut h, later.next().expect("the estimate"));
    assert!(!shows(&h, "pending"));
    assert!(shows(
        &h,
        "error bound (against a twice finer run): max force"
    ));
    assert!(later.next().is_none());
}

/// Lands the part of `setup`'s run streamed at about `fraction` of its record as a stage before
/// the last; returns the instant it was solved to.
fn land_part(h: &mut Harness<'static, BuildingScene>, setup: BuildingSetup, fraction: f64) -> f64 {
    let motion = crate::io::motion::load(&setup.motion).expect("the built-in record");
    let partial = run_so_far(&setup, fraction);
    let edge = partial.solved_to_s;
    let drawing = BuildingDrawing::new(setup, motion, partial);
    land(
        h,
        Landed {
            output: Ok(Stage::Partial(Box::new(drawing))),
            last: false,
            job_time: Duration::ZERO,
            since_request: Duration::ZERO,
        },
    );
    edge
}

/// The run `sc` streams, cut where it had solved about `fraction` of its record.
fn run_so_far(setup: &BuildingSetup, fraction: f64) -> BuildingResult {
    let motion = crate::io::motion::load(&setup.motion).expect("the built-in record");
    let mut so_far: Vec<BuildingResult> = vec![];
    let whole = solve_streaming(
        &setup.scenario,
        &motion,
        Control::never(),
        Duration::ZERO,
        &mut |r| so_far.push(r),
    )
    .expect("solves");
    let at = fraction * whole.solved_to_s;
    so_far
        .into_iter()
        .find(|r| r.solved_to_s >= at)
        .expect("a run streamed at every look")
}

#[test]
fn a_run_still_solving_never_plays_or_draws_past_how_far_it_has_solved() {
    let mut h = harness(quiet_scene());
    // A launch time beyond what is solved stays set, and is drawn at the edge.
    h.state_mut().playback.t = 7.5;
    let edge = land_part(&mut h, paper_buildings(), 0.2);
    assert!(edge < 7.5, "{edge}");
    assert!(shows(&h, &format!("solving: {edge:.1} s of 8.0 s; so far")));
    assert!(shows(&h, "once the run is solved"));
    let scene = h.state_mut();
    assert_eq!(scene.playback.ready_s, Some(edge));
    assert_eq!(scene.playback.shown_t(), edge);
    assert!(scene.animation_source().is_none(), "no animation of a part");
    // Played from the start at speed: it waits at the edge.
    scene.playback.t = 0.0;
    scene.playback.playing = true;
    for _ in 0..200 {
        scene.playback.advance(0.05);
        assert!(scene.playback.t <= edge, "{} past {edge}", scene.playback.t);
    }
    assert_eq!(scene.playback.t, edge);
}

#[test]
fn a_newer_requests_run_never_shows_an_older_ones_checks_and_gives_way_if_it_stops_short() {
    let setup = paper_buildings();
    let stages = stages_of(setup.clone());
    let mut h = harness(quiet_scene());
    for l in stages
        .into_iter()
        .filter(|l| !matches!(l.output, Ok(Stage::Partial(_))))
    {
        land(&mut h, l);
    }
    assert!(shows(
        &h,
        "error bound (against a twice finer run): max force"
    ));
    h.state_mut().request();
    h.state_mut().cancel();
    // The older request's checks stay with its run while nothing newer has landed...
    h.run_steps(2);
    assert!(!shows(&h, "pending"));
    // ...and a run of the newer one comes without them.
    land_part(&mut h, setup, 0.5);
    assert!(shows(&h, "(without pounding pending)"));
    assert!(shows(
        &h,
        "error bound (against a twice finer run): pending"
    ));
    // The newer request stops short (cancelled): the last whole run comes back, whole, with
    // its own checks.
    h.state_mut().ended();
    h.run_steps(2);
    assert!(!shows(&h, "solving:"));
    assert!(!shows(&h, "pending"));
    assert!(shows(
        &h,
        "error bound (against a twice finer run): max force"
    ));
    assert_eq!(h.state().playback.ready_s, None);
}

#[test]
fn a_preset_of_a_hundred_storeys_keeps_them_in_the_panel() {
    // The command line takes up to 100 storeys a side, and so does a preset; the panel showed at
    // most 20, and egui's field clamped the value it showed: such a preset opened as 20 storeys.
    let mut setup = paper_buildings();
    for a in ["left.storeys=100", "right.storeys=100"] {
        setup.apply_assignment(a).expect("key");
    }
    // A mass per storey, the list the panel would cut short.
    setup.scenario.left.masses_kg = (0..100).map(|i| 1e5 - 100.0 * i as f64).collect();
    let mut scene = quiet_scene();
    scene.setup = setup.clone();
    let mut h = Harness::builder()
        .with_size(egui::vec2(420.0, 1500.0))
        .build_ui_state(
            |ui, scene: &mut BuildingScene| {
                egui::ScrollArea::vertical().show(ui, |ui| scene.params_ui(ui));
            },
            scene,
        );
    h.run_steps(3);
    let shown = &h.state().setup.scenario;
    assert_eq!((shown.left.storeys, shown.right.storeys), (100, 100));
    assert_eq!(shown.left.masses_kg, setup.scenario.left.masses_kg);
}
