//! What the window keeps between sessions: each scene's settings (in the preset format) and the
//! theme and scene on screen, under keys that carry their format's version so that an older save
//! is never misread; what cannot be read is reported and the defaults used.

use super::PoundingApp;
use crate::io::preset;
use crate::io::settings::ImpactSetup;

/// Storage keys; the suffix is the format's version, so an older save is never misread.
pub(super) const IMPACT_KEY: &str = "impact-scene-v1";
pub(super) const COMPARE_KEY: &str = "compare-scene-v1";
pub(super) const UI_KEY: &str = "ui-v1";
pub(super) const BUILDINGS_KEY: &str = "buildings-scene-v1";
pub(super) const STUDY_KEY: &str = "study-scene-v1";
pub(super) const BRIDGE_KEY: &str = "bridge-scene-v1";

pub(super) fn restore(
    storage: Option<&dyn eframe::Storage>,
    key: &str,
    errors: &mut Vec<String>,
) -> ImpactSetup {
    let mut setup =
        preset::load_for::<ImpactSetup>(preset::DEFAULT_PRESET, "impact").unwrap_or_default();
    if let Some(text) = storage.and_then(|s| s.get_string(key)) {
        let mut restored = setup;
        match preset::apply_text(&mut restored, &text, "the last session's scene") {
            Ok(()) => setup = restored,
            Err(e) => errors.push(format!("{e} (the default scene is used)")),
        }
    }
    setup
}

/// Writes every scene's settings and the window's state.
pub(super) fn save(app: &PoundingApp, storage: &mut dyn eframe::Storage) {
    storage.set_string(IMPACT_KEY, preset::impact_to_toml(&app.bar.core.setup));
    storage.set_string(COMPARE_KEY, preset::impact_to_toml(&app.compare.core.setup));
    storage.set_string(STUDY_KEY, app.study.state());
    let mut progress = app.progress.clone();
    if let Some(p) = &app.lesson {
        p.record(&mut progress);
    }
    storage.set_string(super::lesson_player::PROGRESS_KEY, progress.to_stored());
    storage.set_string(
        BUILDINGS_KEY,
        preset::buildings_to_toml(&app.buildings.setup),
    );
    storage.set_string(BRIDGE_KEY, preset::bridge_to_toml(&app.bridge.setup));
    let smooth = match (app.smooth_lines_chosen, app.smooth_lines) {
        (false, _) => "",
        (true, true) => ";smooth=on",
        (true, false) => ";smooth=off",
    };
    storage.set_string(
        UI_KEY,
        format!(
            "{};scene={}{smooth}",
            if app.dark { "dark" } else { "light" },
            app.scene.name()
        ),
    );
}
