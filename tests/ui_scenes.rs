//! The window driven as a user would, headless (egui_kittest on a wgpu adapter): scenes that
//! share the GPU stress-field resources each draw their own field after edits in both and tab
//! switches.
#![cfg(feature = "gui")]

use eframe::egui;
use eframe::egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use pounding::app::{HIDE_TIMINGS, Launch, PoundingApp, SceneKind};

mod common;

fn window(scene: SceneKind) -> Harness<'static, PoundingApp> {
    HIDE_TIMINGS.store(true, std::sync::atomic::Ordering::Relaxed);
    let launch = Launch {
        scene: Some(scene),
        preset: Some("paper-base".into()),
        time_s: Some(0.0),
        ..Default::default()
    };
    let mut h = Harness::builder()
        .with_size(egui::vec2(1280.0, 860.0))
        .wgpu()
        .build_eframe(|cc| PoundingApp::new(cc, launch));
    common::settle(&mut h, "launch");
    h
}

/// Clicks the widget labelled `label`, then lets the window settle.
fn click(h: &mut Harness<'static, PoundingApp>, label: &str) {
    h.get_by_label(label).click();
    common::settle(h, label);
}

/// Loads the impact preset `name` into the scene on screen through the top bar.
fn load_preset(h: &mut Harness<'static, PoundingApp>, name: &str) {
    h.get_by_role_and_label(Role::ComboBox, "preset").click();
    h.run_steps(2);
    h.get_by_label(name).click();
    h.run_steps(2);
    click(h, "Load preset");
}

/// Twenty animation steps: the waves are well into the bars.
fn step_in(h: &mut Harness<'static, PoundingApp>) {
    for _ in 0..20 {
        h.get_by_label("Step").click();
        h.run_steps(1);
    }
    common::settle(h, "steps");
}

/// Pixels whose colour differs by more than 24 in any channel, outside `skip` (the preset
/// chooser, whose text follows the last preset loaded in any scene).
fn differing(a: &Shot, b: &Shot, skip: egui::Rect) -> usize {
    assert_eq!((a.0, a.1.len()), (b.0, b.1.len()));
    let width = a.0 as usize;
    a.1.chunks_exact(4)
        .zip(b.1.chunks_exact(4))
        .enumerate()
        .filter(|(i, (p, q))| {
            let at = egui::pos2((i % width) as f32, (i / width) as f32);
            !skip.contains(at) && (0..3).any(|c| p[c].abs_diff(q[c]) > 24)
        })
        .count()
}

/// A rendered frame: its width and RGBA bytes.
type Shot = (u32, Vec<u8>);

fn shot(h: &mut Harness<'static, PoundingApp>) -> Shot {
    // The pointer (drawn, and hovering whatever was clicked last) away from the window.
    h.remove_cursor();
    h.run_steps(5);
    let image = h.render().expect("renders");
    (image.width(), image.into_raw())
}

#[test]
fn each_scene_draws_its_own_stress_field_after_edits_in_both_and_tab_switches() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    // Each scene alone: Bar impact on the paper's base case, Wave vs lumped on long bars.
    let mut alone_a = window(SceneKind::BarImpact);
    step_in(&mut alone_a);
    let image_a = shot(&mut alone_a);
    let mut alone_b = window(SceneKind::WaveVsLumped);
    load_preset(&mut alone_b, "long-bars");
    step_in(&mut alone_b);
    let image_b = shot(&mut alone_b);
    let chooser = |h: &Harness<'static, PoundingApp>| {
        h.get_by_role_and_label(Role::ComboBox, "preset").rect()
    };
    let chooser = chooser(&alone_a).union(chooser(&alone_b)).expand(4.0);

    // Both in one window: edits in each, then back and forth between the tabs.
    let mut both = window(SceneKind::BarImpact);
    step_in(&mut both);
    click(&mut both, "Wave vs lumped");
    load_preset(&mut both, "long-bars");
    step_in(&mut both);
    let b_after_edits = shot(&mut both);
    click(&mut both, "Bar impact");
    let a_after_switch = shot(&mut both);
    click(&mut both, "Wave vs lumped");
    let b_after_switch = shot(&mut both);

    // The two scenes differ by far more than a stale field could hide in rasterizer noise...
    let apart = differing(&image_a, &image_b, chooser);
    assert!(apart > 20_000, "the scenes differ in only {apart} pixels");
    // ...and each tab shows what its scene alone shows.
    for (what, shown, alone) in [
        ("Wave vs lumped after the edits", &b_after_edits, &image_b),
        ("Bar impact after the switch", &a_after_switch, &image_a),
        (
            "Wave vs lumped after switching back",
            &b_after_switch,
            &image_b,
        ),
    ] {
        let off = differing(shown, alone, chooser);
        assert!(
            off < 200,
            "{what}: {off} pixels differ from the scene alone"
        );
    }
}

#[test]
fn a_click_in_the_space_time_diagram_moves_the_animation_time_there() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    let mut h = window(SceneKind::BarImpact);
    assert_eq!(h.state().animation_time(), 0.0);
    let diagram = h.get_by_label("x-t diagram").rect();
    // A point 3/4 of the way up the plotting area (18 points of title above it, 16 of axis
    // below): time runs upward from 0 to the span shown.
    let (top, bottom) = (diagram.top() + 18.0, diagram.bottom() - 16.0);
    let y = bottom - 0.75 * (bottom - top);
    let at = egui::pos2(diagram.center().x, y);
    h.hover_at(at);
    h.run_steps(1);
    h.event(egui::Event::PointerButton {
        pos: at,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: Default::default(),
    });
    h.run_steps(1);
    h.event(egui::Event::PointerButton {
        pos: at,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: Default::default(),
    });
    h.run_steps(2);
    let t = h.state().animation_time();
    // The base case's span: the first separation (1.034 ms) and a round trip of bar 2 (0.773 ms).
    let span = 1.034e-3 + 2.0 * 2.0 / 5172.2;
    assert!(
        (t - 0.75 * span).abs() < 0.02 * span,
        "time {t:e} s after a click at 3/4 of the span {span:e} s"
    );
}
