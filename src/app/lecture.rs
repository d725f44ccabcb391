//! Lecture mode: readable from the back of a hall on a 1280 x 720 projector. Everything is
//! scaled up and the text more so (body text and plot ticks at least 20 px cap height at
//! 1280 x 720), plot lines are thicker, the theme is a high-contrast light one, and the
//! parameter panel keeps only what the lesson step unlocks.

use eframe::egui::{self, Color32, FontFamily, FontId, Stroke, TextStyle};

/// How much larger everything is drawn.
pub const ZOOM: f32 = 1.5;

/// Lecture mode's text sizes [points, before the zoom]. Body text sets plot tick labels too
/// (egui_plot draws them in the body style); 20 points at the zoom is a 20.8 px cap height in
/// the default font.
fn text_styles() -> std::collections::BTreeMap<TextStyle, FontId> {
    [
        (
            TextStyle::Small,
            FontId::new(16.0, FontFamily::Proportional),
        ),
        (TextStyle::Body, FontId::new(20.0, FontFamily::Proportional)),
        (
            TextStyle::Button,
            FontId::new(20.0, FontFamily::Proportional),
        ),
        (
            TextStyle::Heading,
            FontId::new(24.0, FontFamily::Proportional),
        ),
        (
            TextStyle::Monospace,
            FontId::new(18.0, FontFamily::Monospace),
        ),
    ]
    .into()
}

/// Plot line widths [points], normal and in lecture mode (before the zoom).
const LINE: f32 = 1.5;
const LECTURE_LINE: f32 = 2.5;

fn flag() -> egui::Id {
    egui::Id::unique("lecture-mode")
}

/// Whether lecture mode is on in this window.
pub fn on(ctx: &egui::Context) -> bool {
    ctx.data(|d| d.get_temp::<bool>(flag())).unwrap_or(false)
}

/// The width of a plot's data lines.
pub fn line_width(ui: &egui::Ui) -> f32 {
    if on(ui.ctx()) { LECTURE_LINE } else { LINE }
}

/// Whether the window is still drawn as lecture mode draws it (a host may reset the theme or
/// the zoom after start-up).
pub fn holds(ctx: &egui::Context) -> bool {
    on(ctx)
        && ctx.theme() == egui::Theme::Light
        && ctx.zoom_factor() == ZOOM
        && ctx.style_of(egui::Theme::Light).text_styles == text_styles()
}

/// Switches lecture mode on or off; off restores the user's theme.
pub fn apply(ctx: &egui::Context, lecture: bool, dark: bool) {
    ctx.data_mut(|d| d.insert_temp(flag(), lecture));
    if lecture {
        ctx.set_visuals_of(egui::Theme::Light, high_contrast());
        ctx.style_mut_of(egui::Theme::Light, |s| s.text_styles = text_styles());
        ctx.set_theme(egui::Theme::Light);
        ctx.set_zoom_factor(ZOOM);
    } else {
        ctx.set_visuals_of(egui::Theme::Light, egui::Visuals::light());
        ctx.style_mut_of(egui::Theme::Light, |s| {
            s.text_styles = egui::Style::default().text_styles;
        });
        ctx.set_theme(if dark {
            egui::Theme::Dark
        } else {
            egui::Theme::Light
        });
        ctx.set_zoom_factor(1.0);
    }
}

/// Black on white, strong outlines, no faint greys that wash out on a projector.
fn high_contrast() -> egui::Visuals {
    let mut v = egui::Visuals::light();
    let ink = Color32::BLACK;
    v.override_text_color = Some(ink);
    v.panel_fill = Color32::WHITE;
    v.window_fill = Color32::WHITE;
    v.extreme_bg_color = Color32::WHITE;
    v.faint_bg_color = Color32::from_gray(232);
    v.window_stroke = Stroke::new(1.5, ink);
    v.hyperlink_color = Color32::from_rgb(0, 60, 200);
    v.selection.bg_fill = Color32::from_rgb(255, 210, 60);
    v.selection.stroke = Stroke::new(2.0, ink);
    for w in [
        &mut v.widgets.noninteractive,
        &mut v.widgets.inactive,
        &mut v.widgets.hovered,
        &mut v.widgets.active,
        &mut v.widgets.open,
    ] {
        w.fg_stroke = Stroke::new(1.5, ink);
        w.bg_stroke = Stroke::new(1.0, Color32::from_gray(40));
    }
    v.widgets.noninteractive.bg_stroke = Stroke::new(1.0, Color32::from_gray(90));
    v.widgets.inactive.bg_fill = Color32::from_gray(225);
    v.widgets.inactive.weak_bg_fill = Color32::from_gray(225);
    v.widgets.hovered.bg_fill = Color32::from_gray(200);
    v.widgets.hovered.weak_bg_fill = Color32::from_gray(200);
    v.widgets.active.bg_fill = Color32::from_gray(170);
    v.widgets.active.weak_bg_fill = Color32::from_gray(170);
    v
}

/// The font of a view's own text (labels painted in a diagram: the x-t diagram's ticks, the
/// bars' colour scale) of `size` points. Lecture mode draws it a quarter larger: the smallest,
/// 11 points, is then a 20 px font at 1280 x 720, and a diagram's margins still hold it.
pub fn font(ctx: &egui::Context, size: f32) -> FontId {
    let k = if on(ctx) { 1.25 } else { 1.0 };
    FontId::proportional(size * k)
}
