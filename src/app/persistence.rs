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
    let smooth = app.smooth_lines_chosen.then_some(app.smooth_lines);
    storage.set_string(UI_KEY, ui_state(app.dark, app.scene, smooth));
}

/// The theme, the scene shown and the lines' smoothing where the user chose it, as saved.
pub(super) fn ui_state(dark: bool, scene: super::SceneKind, smooth: Option<bool>) -> String {
    let smooth = match smooth {
        None => "",
        Some(true) => ";smooth=on",
        Some(false) => ";smooth=off",
    };
    format!(
        "{};scene={}{smooth}",
        if dark { "dark" } else { "light" },
        scene.name()
    )
}

#[cfg(test)]
mod tests {
    use super::super::{Launch, SceneKind, start};
    use super::*;

    /// What a window's storage holds, in memory.
    #[derive(Default)]
    struct Memory(std::collections::HashMap<String, String>);

    impl eframe::Storage for Memory {
        fn get_string(&self, key: &str) -> Option<String> {
            self.0.get(key).cloned()
        }
        fn set_string(&mut self, key: &str, value: String) {
            self.0.insert(key.into(), value);
        }
        fn remove_string(&mut self, key: &str) {
            self.0.remove(key);
        }
        fn flush(&mut self) {}
    }

    #[test]
    fn the_theme_scene_and_a_chosen_line_smoothing_come_back_and_an_unchosen_one_stays_unset() {
        for (dark, scene, smooth) in [
            (true, SceneKind::Bridge, Some(false)),
            (false, SceneKind::Buildings, Some(true)),
            (true, SceneKind::Study, None),
        ] {
            let mut storage = Memory::default();
            eframe::Storage::set_string(&mut storage, UI_KEY, ui_state(dark, scene, smooth));
            let mut errors = vec![];
            let back = start(Some(&storage), &Launch::default(), &mut errors);
            assert!(errors.is_empty(), "{errors:?}");
            assert_eq!(
                (back.dark, back.scene, back.smooth_lines),
                (dark, scene, smooth)
            );
        }
        // A value this build does not know is no choice.
        let mut storage = Memory::default();
        eframe::Storage::set_string(
            &mut storage,
            UI_KEY,
            "dark;scene=bridge;smooth=maybe".into(),
        );
        let back = start(Some(&storage), &Launch::default(), &mut vec![]);
        assert_eq!(back.smooth_lines, None);
    }
}
