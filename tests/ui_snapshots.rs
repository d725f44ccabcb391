//! Each scene of the window rendered headless (egui_kittest on a wgpu adapter, Mesa's lavapipe in
//! CI) at a fixed state: a preset, a paused animation time, every background solve finished,
//! timings hidden. Compared with `tests/snapshots/<scene>.png`; `UPDATE_SNAPSHOTS=1` rewrites
//! them. The budget of differing pixels absorbs rasterizer noise in anti-aliased edges and text;
//! a missing bar (tens of thousands of pixels), a changed colour map or an empty plot (a curve is
//! over a thousand) exceeds it many times over.
#![cfg(feature = "gui")]

use eframe::egui;
use egui_kittest::{Harness, SnapshotOptions};
use pounding::app::{HIDE_TIMINGS, Launch, PoundingApp, SceneKind};

mod common;

use common::MAX_FAILED_PIXELS;

fn snapshot(scene: SceneKind, time_s: f64, name: &str) {
    snapshot_sized(scene, time_s, name, 860.0);
}

/// A window `height` points high: tall enough to reach a scene's lower parts.
fn snapshot_sized(scene: SceneKind, time_s: f64, name: &str, height: f32) {
    snapshot_of(scene, "paper-base", time_s, name, height);
}

/// The scene on `preset` (a buildings preset goes to the buildings scene).
fn snapshot_of(scene: SceneKind, preset: &str, time_s: f64, name: &str, height: f32) {
    if common::adapter_or_skip().is_none() {
        return;
    }
    HIDE_TIMINGS.store(true, std::sync::atomic::Ordering::Relaxed);
    let launch = Launch {
        scene: Some(scene),
        preset: Some(preset.into()),
        time_s: Some(time_s),
        ..Default::default()
    };
    let mut harness = Harness::builder()
        .with_size(egui::vec2(1280.0, height))
        .wgpu()
        .build_eframe(|cc| PoundingApp::new(cc, launch));
    // Solves run on worker threads: step until all of them have landed and stayed so.
    common::settle(&mut harness, name);
    harness.snapshot_options(
        name,
        &SnapshotOptions::new().max_failed_pixels(MAX_FAILED_PIXELS),
    );
}

#[test]
fn bar_impact_scene_matches_its_snapshot() {
    snapshot(SceneKind::BarImpact, 0.3e-3, "scene-bar-impact");
}

#[test]
fn wave_vs_lumped_scene_matches_its_snapshot() {
    snapshot(SceneKind::WaveVsLumped, 0.3e-3, "scene-wave-vs-lumped");
}

#[test]
fn building_scene_matches_its_snapshot() {
    snapshot(SceneKind::Buildings, 3.0, "scene-buildings");
}

#[test]
fn parameter_study_scene_matches_its_snapshot() {
    snapshot(SceneKind::Study, 0.0, "scene-parameter-study");
}

#[test]
fn building_scene_down_to_the_slabs_space_time_diagram_matches_its_snapshot() {
    // Tall enough for the impact list and the x-t diagram of the strongest impact's slabs.
    snapshot_sized(SceneKind::Buildings, 2.6537, "scene-buildings-xt", 1500.0);
}

#[test]
fn yielding_buildings_show_their_storeys_loops_grown_to_the_time_shown() {
    // Past the strongest impacts: both storeys have yielded (orange columns), and each loop has
    // grown to t = 4 s with the impacts marked on it.
    snapshot_of(
        SceneKind::Buildings,
        "paper-buildings-yielding",
        4.0,
        "scene-buildings-yielding",
        1100.0,
    );
}

#[test]
fn lecture_mode_at_projector_size_matches_its_snapshot() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    HIDE_TIMINGS.store(true, std::sync::atomic::Ordering::Relaxed);
    let launch = Launch {
        lesson: Some("lumped-or-wave".into()),
        // "Lengthen bar 2": one unlocked setting, a task, two plots.
        lesson_step: Some(4),
        lecture: true,
        // Paused, so that the time line stands where the snapshot has it.
        time_s: Some(5e-3),
        ..Default::default()
    };
    let mut harness = Harness::builder()
        .with_size(egui::vec2(1280.0, 720.0) / pounding::app::LECTURE_ZOOM)
        .wgpu()
        .build_eframe(|cc| PoundingApp::new(cc, launch));
    common::settle(&mut harness, "lecture");
    harness.snapshot_options(
        "lecture-mode",
        &SnapshotOptions::new().max_failed_pixels(MAX_FAILED_PIXELS),
    );
}

#[test]
fn bridge_scene_matches_its_snapshot() {
    // The travelling wave's preset while girders pound: fronts in the girders at joint 1.
    snapshot_of(
        SceneKind::Bridge,
        "bridge-3-span-passage",
        2.0,
        "scene-bridge",
        860.0,
    );
}

#[test]
fn an_unseated_joint_turns_its_seat_red_down_to_the_decks_space_time_diagram() {
    // Past 2.52 s, when joint 2 has opened further than its 0.1 m seat: its seat is red, the
    // table says when; tall enough for the impact list and the deck's x-t diagram.
    snapshot_of(
        SceneKind::Bridge,
        "bridge-3-span-unseating",
        2.6,
        "scene-bridge-unseated",
        1900.0,
    );
}
