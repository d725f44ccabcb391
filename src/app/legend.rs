//! A plot's legend as a row above the plot: it never covers the data, and it wraps with the
//! width. Each entry draws its line as the plot does (colour, dashes) or its band's swatch.

use eframe::egui::{self, Color32, Stroke};

/// One entry.
pub struct Key {
    pub name: String,
    pub colour: Color32,
    pub dashed: bool,
    /// A filled band rather than a line.
    pub filled: bool,
}

impl Key {
    pub fn line(name: impl Into<String>, colour: Color32, dashed: bool) -> Self {
        Key {
            name: name.into(),
            colour,
            dashed,
            filled: false,
        }
    }

    pub fn band(name: impl Into<String>, colour: Color32) -> Self {
        Key {
            name: name.into(),
            colour,
            dashed: false,
            filled: true,
        }
    }

    /// A model's line in its palette colour (`sears`, `wave`, ...), or the `k`-th colour of the
    /// Okabe-Ito palette for any other series.
    pub fn of_series(name: &str, k: usize) -> Self {
        match crate::export::palette::style_of(name) {
            Some(s) => Key::line(
                name,
                Color32::from_rgb(s.rgb[0], s.rgb[1], s.rgb[2]),
                s.dashed,
            ),
            None => Key::line(name, okabe_ito(k), false),
        }
    }

    /// The plot's line for this entry, `points` drawn as the entry shows.
    pub fn plot_line<'a>(&self, points: Vec<[f64; 2]>, width: f32) -> egui_plot::Line<'a> {
        let line = egui_plot::Line::new(self.name.clone(), points)
            .color(self.colour)
            .width(width);
        if self.dashed {
            line.style(egui_plot::LineStyle::dashed_loose())
        } else {
            line
        }
    }
}

/// Okabe and Ito's colours, distinguishable with every common colour-vision deficiency, black
/// left out (it is the text's colour): blue, vermillion, bluish green, orange, reddish purple,
/// sky blue, yellow.
pub fn okabe_ito(k: usize) -> Color32 {
    const COLOURS: [[u8; 3]; 7] = [
        [0, 114, 178],
        [213, 94, 0],
        [0, 158, 115],
        [230, 159, 0],
        [204, 121, 167],
        [86, 180, 233],
        [240, 228, 66],
    ];
    let [r, g, b] = COLOURS[k % COLOURS.len()];
    Color32::from_rgb(r, g, b)
}

/// Draws `keys` as one row that wraps with the width: each entry one widget (its sample and
/// its name), so an entry never breaks across lines.
pub fn row(ui: &mut egui::Ui, keys: &[Key]) {
    let width = super::lecture::line_width(ui);
    ui.horizontal_wrapped(|ui| {
        ui.spacing_mut().item_spacing.x = 14.0;
        for key in keys {
            entry(ui, key, width);
        }
    });
}

fn entry(ui: &mut egui::Ui, key: &Key, width: f32) {
    let text = ui.visuals().text_color();
    let galley = ui.painter().layout_no_wrap(
        key.name.clone(),
        egui::TextStyle::Body.resolve(ui.style()),
        text,
    );
    let h = galley.size().y;
    let sample = egui::vec2(2.0 * h, h);
    let gap = 4.0;
    let (rect, response) = ui.allocate_exact_size(
        egui::vec2(sample.x + gap + galley.size().x, h),
        egui::Sense::hover(),
    );
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Label, true, key.name.clone()));
    let swatch = egui::Rect::from_min_size(rect.min, sample);
    let painter = ui.painter();
    if key.filled {
        painter.rect_filled(swatch.shrink(h * 0.2), 2.0, key.colour);
    } else {
        let (a, b) = (swatch.left_center(), swatch.right_center());
        let stroke = Stroke::new(width, key.colour);
        if key.dashed {
            painter.extend(egui::Shape::dashed_line(
                &[a, b],
                stroke,
                h * 0.35,
                h * 0.25,
            ));
        } else {
            painter.line_segment([a, b], stroke);
        }
    }
    painter.galley(egui::pos2(swatch.right() + gap, rect.top()), galley, text);
}
