//! Lecture mode on a projector, every step of every shipped lesson, before and after its
//! prediction is answered: every widget and label the step shows lies inside the window (no
//! panel below the fold), no two overlap (a legend over a plot's data counts), and body text
//! and plot ticks are large enough for the back of a hall.
#![cfg(feature = "gui")]

use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use pounding::app::{HIDE_TIMINGS, LECTURE_ZOOM, Launch, PoundingApp};
use pounding::lesson;

mod common;

/// What a step shows, where (logical points).
struct Shown {
    what: String,
    rect: egui::Rect,
}

/// Every leaf of the window's accessibility tree: labels' text runs, buttons, sliders, the
/// plots' areas and the legend entries drawn in them.
fn leaves(h: &Harness<'static, PoundingApp>) -> Vec<Shown> {
    h.root()
        .children_recursive()
        .filter(|n| {
            let a = n.accesskit_node();
            a.children().next().is_none()
                && a.bounding_box().is_some()
                && a.role() != egui::accesskit::Role::Splitter
        })
        .map(|n| {
            let a = n.accesskit_node();
            let name = a.label().or_else(|| a.value()).unwrap_or_default();
            Shown {
                what: format!("{:?} {name:?}", a.role()),
                rect: n.rect(),
            }
        })
        .collect()
}

/// What lies outside the window or over something else.
fn faults(h: &Harness<'static, PoundingApp>, size: egui::Vec2) -> Vec<String> {
    let window = egui::Rect::from_min_size(egui::Pos2::ZERO, size).expand(0.5);
    let shown = leaves(h);
    let mut out = vec![];
    for s in &shown {
        if !window.contains_rect(s.rect) {
            out.push(format!("{} at {:?} leaves the window", s.what, s.rect));
        }
    }
    for (i, a) in shown.iter().enumerate() {
        for b in &shown[i + 1..] {
            let both = a.rect.shrink(1.0).intersect(b.rect.shrink(1.0));
            if both.is_positive() {
                out.push(format!("{} overlaps {}", a.what, b.what));
            }
        }
    }
    out
}

/// The height of a capital H over the font size, in egui's default proportional font.
fn cap_height_per_size() -> f32 {
    use ab_glyph::{Font, FontRef};
    let fonts = egui::FontDefinitions::default();
    let name = &fonts.families[&egui::FontFamily::Proportional][0];
    let font =
        FontRef::try_from_slice(fonts.font_data[name].font.as_ref().as_ref()).expect("a font");
    let h = font.outline(font.glyph_id('H')).expect("an outline");
    (h.bounds.max.y - h.bounds.min.y).abs() / font.units_per_em().expect("scalable")
}

fn lecture_window(name: &str, k: usize, size: egui::Vec2) -> Harness<'static, PoundingApp> {
    HIDE_TIMINGS.store(true, std::sync::atomic::Ordering::Relaxed);
    let launch = Launch {
        lesson: Some(name.to_string()),
        lesson_step: Some(k + 1),
        lecture: true,
        ..Default::default()
    };
    let mut h = Harness::builder()
        .with_size(size / LECTURE_ZOOM)
        .wgpu()
        .build_eframe(|cc| PoundingApp::new(cc, launch));
    common::settle(&mut h, &format!("{name} step {}", k + 1));
    h
}

/// Every step of every lesson at `size` physical pixels: its faults, before and after its
/// prediction.
fn every_step_at(size: egui::Vec2) -> Vec<String> {
    let mut out = vec![];
    for name in lesson::builtin_names() {
        let l = lesson::builtin(name).expect("shipped");
        for (k, step) in l.steps.iter().enumerate() {
            let at = format!("{name} step {} at {}x{}", k + 1, size.x, size.y);
            let mut h = lecture_window(name, k, size);
            let logical = size / LECTURE_ZOOM;
            out.extend(
                faults(&h, logical)
                    .into_iter()
                    .map(|f| format!("{at}: {f}")),
            );
            if let Some(p) = &step.prediction {
                common::answer(&mut h, p, &at);
                out.extend(
                    faults(&h, logical)
                        .into_iter()
                        .map(|f| format!("{at}, answered: {f}")),
                );
                // A step that asks first and sets a task after shows its task on a click.
                if step.task.is_some() {
                    h.get_by_label("On to the task >").click();
                    common::settle(&mut h, &format!("{at}: its task"));
                    out.extend(
                        faults(&h, logical)
                            .into_iter()
                            .map(|f| format!("{at}, its task: {f}")),
                    );
                }
            }
        }
    }
    out
}

/// Every step of every lesson at `width` x `height` pixels, each fault listed.
fn every_step_fits(width: f32, height: f32) {
    if common::adapter_or_skip().is_none() {
        return;
    }
    let faults = every_step_at(egui::vec2(width, height));
    assert!(
        faults.is_empty(),
        "{} faults:\n{}",
        faults.len(),
        faults.join("\n")
    );
}

#[test]
fn every_lesson_step_fits_a_1280_by_720_projector_with_nothing_clipped_or_overlapping() {
    every_step_fits(1280.0, 720.0);
}

#[test]
fn every_lesson_step_fits_a_1920_by_1080_screen_with_nothing_clipped_or_overlapping() {
    every_step_fits(1920.0, 1080.0);
}

#[test]
fn lecture_body_text_and_plot_ticks_stand_20_px_tall_at_1280_by_720() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    let h = lecture_window("lumped-or-wave", 0, egui::vec2(1280.0, 720.0));
    let cap = cap_height_per_size();
    let style = h.ctx.global_style();
    let px = |s: egui::TextStyle| style.text_styles[&s].size * LECTURE_ZOOM * cap;
    // egui_plot draws its tick labels in the body style.
    for s in [egui::TextStyle::Body, egui::TextStyle::Button] {
        assert!(
            px(s.clone()) >= 20.0,
            "{s:?} text is {:.1} px cap height",
            px(s.clone())
        );
    }
    // The fonts a body label is laid out in: a text run's row height follows its size.
    let body = leaves(&h)
        .into_iter()
        .filter(|s| s.what.starts_with("TextRun"))
        .map(|s| s.rect.height() * LECTURE_ZOOM)
        .fold(f32::INFINITY, f32::min);
    assert!(
        body >= 20.0 / cap,
        "the smallest text line is {body:.1} px tall, under a 20 px cap height"
    );
}

/// A lecture step as the hall sees it: after its prediction (if any), paused at `time_s`.
fn lecture_snapshot(name: &str, k: usize, time_s: f64, snapshot: &str) {
    HIDE_TIMINGS.store(true, std::sync::atomic::Ordering::Relaxed);
    let launch = Launch {
        lesson: Some(name.to_string()),
        lesson_step: Some(k + 1),
        lecture: true,
        time_s: Some(time_s),
        ..Default::default()
    };
    let mut h = Harness::builder()
        .with_size(egui::vec2(1280.0, 720.0) / LECTURE_ZOOM)
        .wgpu()
        .build_eframe(|cc| PoundingApp::new(cc, launch));
    common::settle(&mut h, snapshot);
    let l = lesson::builtin(name).expect("shipped");
    if let Some(p) = &l.steps[k].prediction {
        common::answer(&mut h, p, snapshot);
    }
    h.snapshot_options(
        snapshot,
        &egui_kittest::SnapshotOptions::new().max_failed_pixels(common::MAX_FAILED_PIXELS),
    );
}

#[test]
fn lecture_x_t_step_shows_its_diagram_whole_at_1280_by_720() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    // reading-xt step 1, answered: the bars, the x-t diagram from t = 0 and the force.
    lecture_snapshot("reading-xt", 0, 0.2e-3, "lecture-reading-xt-1");
}

#[test]
fn lecture_compare_step_shows_plot_and_table_together_at_1280_by_720() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    // lumped-or-wave step 3, answered: the long rods' bars, forces and the e table.
    lecture_snapshot("lumped-or-wave", 2, 5e-3, "lecture-lumped-or-wave-3");
}

#[test]
fn lecture_buildings_task_shows_gap_slider_met_mark_and_impacts_at_1280_by_720() {
    if common::adapter_or_skip().is_none() {
        return;
    }
    // buildings-that-pound step 4: the gap slider, the task's mark and the impact list.
    lecture_snapshot(
        "buildings-that-pound",
        3,
        4.0,
        "lecture-buildings-that-pound-4",
    );
}
