//! The Bridge pounding scene as its solve lands stage by stage: a run still solving, shown as
//! far as it has got and never played past it, then the whole run, and a newer request that
//! stops short giving way to the last whole run. Stages come from the scene's own job or the
//! model's stream and are handed to a scene one at a time, so nothing races a thread.

use super::*;
use crate::model::bridge::solve_streaming;
use crate::model::control::Control;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use std::time::{Duration, Instant};

fn bridge() -> BridgeSetup {
    crate::io::preset::load_for("bridge-3-span", "bridge").expect("a shipped preset")
}

/// Every stage of one request of the scene's job, in the order the scene takes them.
fn stages_of(setup: BridgeSetup) -> Vec<Landed<Output>> {
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
fn quiet_scene() -> BridgeScene {
    let mut scene = BridgeScene::new(&egui::Context::default(), bridge());
    scene.cancel();
    scene.playback.playing = false;
    scene
}

fn harness(scene: BridgeScene) -> Harness<'static, BridgeScene> {
    let exporter = Exporter::default();
    Harness::builder()
        .with_size(egui::vec2(1280.0, 1800.0))
        .build_ui_state(
            move |ui, scene: &mut BridgeScene| {
                egui::ScrollArea::vertical().show(ui, |ui| scene.main_ui(ui, &exporter));
            },
            scene,
        )
}

fn land(h: &mut Harness<'static, BridgeScene>, stage: Landed<Output>) {
    h.state_mut().land(stage);
    h.run_steps(2);
}

fn shows(h: &Harness<'static, BridgeScene>, text: &str) -> bool {
    h.query_all_by_label_contains(text).next().is_some()
}

fn landed(output: Output) -> Landed<Output> {
    Landed {
        output,
        last: false,
        job_time: Duration::ZERO,
        since_request: Duration::ZERO,
    }
}

/// The run the model streams, cut where it had solved about `fraction` of it, as the scene's
/// job hands it over.
fn part(setup: &BridgeSetup, fraction: f64) -> (Landed<Output>, f64) {
    let motion = crate::io::motion::load(&setup.motion).expect("the built-in record");
    let mut so_far = vec![];
    let whole = solve_streaming(
        &setup.scenario,
        &motion,
        Control::never(),
        Duration::ZERO,
        &mut |r| so_far.push(r),
    )
    .expect("solves");
    let at = fraction * whole.duration_s;
    let partial = so_far
        .into_iter()
        .find(|r| r.solved_to_s >= at)
        .expect("a run streamed at every look");
    let edge = partial.solved_to_s;
    let stats = motion.stats();
    let drawing = BridgeDrawing::with_stats(setup.clone(), motion, partial, stats);
    (landed(Ok(Stage::Partial(Box::new(drawing)))), edge)
}

#[test]
fn the_bridge_job_hands_out_the_run_so_far_then_the_run_then_its_checks() {
    let stages = stages_of(bridge());
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
    // How many parts come first depends on the machine's speed; their order does not.
    let parts = names.iter().take_while(|n| **n == "partial").count();
    assert_eq!(names[parts..], ["run", "baseline", "estimate"], "{names:?}");
    let reached: Vec<f64> = stages
        .iter()
        .filter_map(|l| match &l.output {
            Ok(Stage::Partial(d) | Stage::Run(d)) => Some(d.result.solved_to_s),
            _ => None,
        })
        .collect();
    assert!(reached.windows(2).all(|w| w[0] < w[1]), "{reached:?}");
}

#[test]
fn a_bridge_run_still_solving_is_shown_so_far_never_played_past_and_gives_way_if_it_stops() {
    let setup = bridge();
    let mut h = harness(quiet_scene());
    h.state_mut().playback.t = 7.5;
    let (stage, edge) = part(&setup, 0.3);
    land(&mut h, stage);
    assert!(edge < 7.5, "{edge}");
    assert!(shows(&h, &format!("solving: {edge:.1} s of")));
    assert!(shows(&h, "once the run is solved"));
    let scene = h.state_mut();
    assert_eq!(scene.playback.ready_s, Some(edge));
    assert_eq!(scene.playback.shown_t(), edge);
    scene.playback.t = 0.0;
    scene.playback.playing = true;
    for _ in 0..200 {
        scene.playback.advance(0.05);
        assert!(scene.playback.t <= edge, "{} past {edge}", scene.playback.t);
    }
    // The whole run: playback free, the diagram drawn, the checks pending.
    for l in stages_of(setup.clone())
        .into_iter()
        .filter(|l| matches!(l.output, Ok(Stage::Run(_))))
    {
        land(&mut h, l);
    }
    assert_eq!(h.state().playback.ready_s, None);
    assert!(!shows(&h, "solving:"));
    assert!(!shows(&h, "once the run is solved"));
    // A newer request shows its part, then stops short: the whole run comes back.
    h.state_mut().request();
    h.state_mut().cancel();
    let (stage, edge) = part(&setup, 0.5);
    land(&mut h, stage);
    assert_eq!(h.state().playback.ready_s, Some(edge));
    h.state_mut().ended();
    h.run_steps(2);
    assert_eq!(h.state().playback.ready_s, None);
    assert!(!shows(&h, "solving:"));
    assert!(h.state().shown.solved.as_ref().is_some_and(|s| s.whole));
}
