//! A run's impacts as a table, one row an impact in an engineer's numbers, each row's number a
//! button that picks it. The window scrolls a long list in a box of its own; a lecture turns it
//! a page at a time, as many rows as the panel holds, so that nothing scrolls out of sight.

use crate::model::building::result::ImpactEvent;
use crate::model::settings::engineering;
use eframe::egui;

/// Where an impact happened, as the scene names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Place {
    /// A building pair's level, from 1.
    Level,
    /// A bridge's joint, from 0 at the left abutment.
    Joint,
}

impl Place {
    fn name(self) -> &'static str {
        match self {
            Place::Level => "level",
            Place::Joint => "joint",
        }
    }

    fn of(self, e: &ImpactEvent) -> String {
        match self {
            Place::Level => (e.level + 1).to_string(),
            Place::Joint => e.level.to_string(),
        }
    }
}

/// The impacts `shown` (indices into `impacts`); returns the one whose number was clicked.
pub fn ui(
    ui: &mut egui::Ui,
    impacts: &[ImpactEvent],
    shown: &[usize],
    place: Place,
    page: &mut usize,
) -> Option<usize> {
    if super::lecture::on(ui.ctx()) {
        return pages_ui(ui, impacts, shown, place, page);
    }
    ui.label("impacts (click one here or in the force plot to zoom on it):");
    egui::ScrollArea::vertical()
        .id_salt(("impact-list", place.name()))
        .max_height(190.0)
        .show(ui, |ui| rows_ui(ui, impacts, shown, place))
        .inner
}

fn pages_ui(
    ui: &mut egui::Ui,
    impacts: &[ImpactEvent],
    shown: &[usize],
    place: Place,
    page: &mut usize,
) -> Option<usize> {
    // A row's pitch and the page's own rows (its title, the table's header), as measured last
    // frame; a first guess from the font before that.
    let measured = egui::Id::unique("impact-page-measure");
    let guess = ui.text_style_height(&egui::TextStyle::Button) + 2.0 * ui.spacing().item_spacing.y;
    let (pitch, overhead): (f32, f32) = ui
        .ctx()
        .data(|d| d.get_temp(measured))
        .unwrap_or((guess, 3.0 * guess));
    let h = super::fill::height(ui, overhead + 4.0 * pitch, overhead + pitch);
    let rows = (((h - overhead) / pitch).floor() as usize).max(1);
    let pages = shown.len().div_ceil(rows).max(1);
    *page = (*page).min(pages - 1);
    let first = *page * rows;
    let last = (first + rows).min(shown.len());
    let top = ui.cursor().min.y;
    ui.horizontal(|ui| {
        ui.label(format!(
            "impacts {}-{last} of {}",
            (first + 1).min(last),
            shown.len()
        ));
        if ui.add_enabled(*page > 0, egui::Button::new("<")).clicked() {
            *page -= 1;
        }
        if ui
            .add_enabled(*page + 1 < pages, egui::Button::new(">"))
            .clicked()
        {
            *page += 1;
        }
    });
    let table_top = ui.cursor().min.y;
    let clicked = rows_ui(ui, impacts, &shown[first..last], place);
    let (bottom, n) = (ui.cursor().min.y, (last - first) as f32);
    // The header is a row of the table: n + 1 rows between the table's top and its bottom.
    let pitch = (bottom - table_top) / (n + 1.0);
    ui.ctx()
        .data_mut(|d| d.insert_temp(measured, (pitch, bottom - top - n * pitch)));
    super::fill::took(ui.ctx(), h, bottom - top);
    clicked
}

/// One row an impact; a projector's narrow panel keeps when, how hard, how fast and where.
fn rows_ui(
    ui: &mut egui::Ui,
    impacts: &[ImpactEvent],
    shown: &[usize],
    place: Place,
) -> Option<usize> {
    type Column = (&'static str, bool, fn(&ImpactEvent) -> String);
    const COLUMNS: [Column; 6] = [
        ("start", true, |e| format!("{:.4} s", e.start_s)),
        ("duration", false, |e| engineering(e.duration_s(), "s")),
        ("peak force", true, |e| engineering(e.peak_force_n, "N")),
        ("impulse", false, |e| engineering(e.impulse_ns, "N s")),
        ("approach", true, |e| {
            format!("{:.3} m/s", e.approach_velocity_m_s)
        }),
        ("contacts", false, |e| e.contacts.len().to_string()),
    ];
    let lecture = super::lecture::on(ui.ctx());
    let columns: Vec<&Column> = COLUMNS.iter().filter(|c| c.1 || !lecture).collect();
    let mut clicked = None;
    egui::Grid::new(("impacts", place.name()))
        .striped(true)
        .num_columns(columns.len() + 2)
        .show(ui, |ui| {
            ui.strong("#");
            for c in &columns {
                ui.strong(c.0);
            }
            ui.strong(place.name());
            ui.end_row();
            for &i in shown {
                let e = &impacts[i];
                if ui.button(format!("{}", i + 1)).clicked() {
                    clicked = Some(i);
                }
                for c in &columns {
                    ui.label((c.2)(e));
                }
                ui.label(place.of(e));
                ui.end_row();
            }
        });
    clicked
}
