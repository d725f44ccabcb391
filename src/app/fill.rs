//! Views that take the space there is, in lecture mode: a scene's plots and diagrams share the
//! height its fixed rows (readouts, tables, controls, legends) leave in the central panel. The fixed rows are
//! measured the frame before, so a step's views settle to fill the panel within a frame.

use eframe::egui;

/// One frame's accounts.
#[derive(Debug, Clone, Copy, Default)]
struct Ledger {
    /// The height the scene may fill.
    panel: f32,
    /// What the scene's content took in all.
    used: f32,
    /// What of it went to the flexible views.
    flexible: f32,
    /// How many flexible views there were.
    count: usize,
    /// Their natural heights, summed: each takes a share in proportion to its own.
    natural: f32,
}

fn id(last: bool) -> egui::Id {
    egui::Id::unique(("fill-ledger", last))
}

/// Opens this frame's accounts: `panel` is the height the scene may fill.
pub fn begin(ctx: &egui::Context, panel: f32) {
    ctx.data_mut(|d| {
        d.insert_temp(
            id(false),
            Ledger {
                panel,
                ..Ledger::default()
            },
        )
    });
}

/// Closes them: the scene's content took `used` points.
pub fn end(ctx: &egui::Context, used: f32) {
    ctx.data_mut(|d| {
        let mut now: Ledger = d.get_temp(id(false)).unwrap_or_default();
        now.used = used;
        d.insert_temp(id(true), now);
    });
}

/// The height of a flexible view: its share of what the fixed rows left last frame, in
/// proportion to its `natural` height (a diagram takes more than a strip of bars), at least
/// `min`; `natural` until there is a frame to go by.
///
/// Only a lecture's screen is shared out, down to `min`: everything must fit the projector.
/// The window otherwise draws each view at its natural height and scrolls, the same whatever
/// was on screen before.
pub fn height(ui: &egui::Ui, natural: f32, min: f32) -> f32 {
    if !super::lecture::on(ui.ctx()) {
        return natural;
    }
    ui.ctx().data_mut(|d| {
        let last: Option<Ledger> = d.get_temp(id(true));
        let mut now: Ledger = d.get_temp(id(false)).unwrap_or_default();
        let h = match last {
            Some(l) if l.count > 0 && l.natural > 0.0 => {
                let fixed = l.used - l.flexible;
                ((now.panel - fixed) * natural / l.natural).floor().max(min)
            }
            _ => natural.max(min),
        };
        now.count += 1;
        now.natural += natural;
        now.flexible += h;
        d.insert_temp(id(false), now);
        h
    })
}

/// Corrects the last view's account: it was given `given` and took `took` (a view that draws
/// whole rows takes less than its share; the rest is the fixed rows', not its own).
pub fn took(ctx: &egui::Context, given: f32, took: f32) {
    ctx.data_mut(|d| {
        let mut now: Ledger = d.get_temp(id(false)).unwrap_or_default();
        now.flexible += took - given;
        d.insert_temp(id(false), now);
    });
}
