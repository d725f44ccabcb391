//! The lesson's lock, held where settings change rather than widget by widget: whatever a slider,
//! a choice, a menu, a preset, a dialog or a dropped file did to the step's scene during a frame
//! is compared, key by key through the settings registry, with the scene as the frame before left
//! it. A change that touched only locked settings is undone and said; so is a change of scene.
//! A change of an unlocked setting stands with what follows from it (a storey count resizes the
//! per-storey lists; stiffnesses move the period shown).

use super::impact_scene::ImpactScene;
use super::lesson_player::LessonPlayer;
use super::visibility::Lock;
use super::{PoundingApp, SceneKind};
use crate::io::bridge_settings::{BRIDGE, BridgeSetup};
use crate::io::building_settings::{BUILDINGS, BuildingSetup};
use crate::io::registry::Registry;
use crate::io::settings::{IMPACT, ImpactSetup};
use crate::lesson::LessonScene;
use crate::model::settings::{
    BRIDGE_SETTINGS, BUILDING_SETTINGS, IMPACT_SETTINGS, Setting, concrete_keys,
};

/// The step's scene as the last frame left it.
#[derive(Debug, Clone)]
#[allow(clippy::large_enum_variant)] // one a window, held by value
pub(super) enum Held {
    Impact(ImpactSetup),
    Buildings(BuildingSetup),
    Bridge(BridgeSetup),
}

/// The scene a lesson step plays in.
pub(super) fn scene_of(s: LessonScene) -> SceneKind {
    match s {
        LessonScene::Bar => SceneKind::BarImpact,
        LessonScene::Compare => SceneKind::WaveVsLumped,
        LessonScene::Buildings => SceneKind::Buildings,
        LessonScene::Bridge => SceneKind::Bridge,
    }
}

/// The keys whose value (as `--set` would write it) differs between two setups: none at once
/// where the setups are equal, as on nearly every frame.
fn changed<S: PartialEq>(
    registry: &Registry<S>,
    table: &'static [Setting],
    a: &S,
    b: &S,
) -> Vec<String> {
    if a == b {
        return vec![];
    }
    concrete_keys(table)
        .into_iter()
        .filter(|k| registry.shown(a, k).map(|(_, v)| v) != registry.shown(b, k).map(|(_, v)| v))
        .collect()
}

/// Puts `before` back over `now` where the frame's changes touched only locked keys; the keys,
/// where it did.
fn undo_locked<S: PartialEq>(
    lock: &Lock,
    (registry, table): (&Registry<S>, &'static [Setting]),
    before: S,
    now: &mut S,
) -> Option<Vec<String>> {
    let undo = refused(lock, changed(registry, table, &before, now));
    if undo.is_some() {
        *now = before;
    }
    undo
}

/// Whether a frame's changes stand: none, or at least one of them unlocked (the rest follow
/// from it). Otherwise the locked keys that moved.
pub(super) fn refused(lock: &Lock, changed: Vec<String>) -> Option<Vec<String>> {
    (!changed.is_empty() && !changed.iter().any(|k| lock.opens(k))).then_some(changed)
}

impl PoundingApp {
    /// Holds the step's scene as it stands now (after its load, and after each frame).
    pub(super) fn hold_lesson_scene(&mut self) {
        self.lesson_held = match &self.lesson {
            Some(p) if p.loaded && p.load_error.is_none() => Some(match p.current().scene {
                LessonScene::Bar => Held::Impact(self.bar.core.setup),
                LessonScene::Compare => Held::Impact(self.compare.core.setup),
                LessonScene::Buildings => Held::Buildings(self.buildings.setup.clone()),
                LessonScene::Bridge => Held::Bridge(self.bridge.setup.clone()),
            }),
            _ => None,
        };
    }

    /// Undoes what this frame did to a locked setting or to the scene, says so, and holds the
    /// scene for the next frame.
    pub(super) fn enforce_lesson_lock(&mut self) {
        let (Some(p), Some(held)) = (&self.lesson, self.lesson_held.take()) else {
            self.hold_lesson_scene();
            return;
        };
        let lock = Lock::unlocking(&p.current().unlock, false);
        let step_scene = scene_of(p.current().scene);
        let mut said = vec![];
        if self.scene != step_scene {
            self.scene = step_scene;
            said.push("the step chooses the scene".to_string());
        }
        let undone = match (held, p.current().scene) {
            (Held::Impact(before), scene @ (LessonScene::Bar | LessonScene::Compare)) => {
                let target: &mut dyn ImpactScene = if scene == LessonScene::Compare {
                    &mut self.compare
                } else {
                    &mut self.bar
                };
                let now = &mut target.core_mut().setup;
                let undo = undo_locked(&lock, (&IMPACT, IMPACT_SETTINGS), before, now);
                if undo.is_some() {
                    target.request();
                }
                undo
            }
            (Held::Buildings(before), LessonScene::Buildings) => {
                let now = &mut self.buildings.setup;
                let undo = undo_locked(&lock, (&BUILDINGS, BUILDING_SETTINGS), before, now);
                if undo.is_some() {
                    self.buildings.reset_fields();
                    self.buildings.request();
                }
                undo
            }
            (Held::Bridge(before), LessonScene::Bridge) => {
                let now = &mut self.bridge.setup;
                let undo = undo_locked(&lock, (&BRIDGE, BRIDGE_SETTINGS), before, now);
                if undo.is_some() {
                    self.bridge.reset_fields();
                    self.bridge.request();
                }
                undo
            }
            // The step turned under the hold: nothing of the old step to keep.
            _ => None,
        };
        if let Some(keys) = undone {
            said.push(format!("{} stays as the step set it", keys.join(", ")));
        }
        if !said.is_empty() {
            self.message = Some((
                format!(
                    "Locked in this lesson step: {}. Leave the lesson to explore freely.",
                    said.join("; ")
                ),
                true,
            ));
        }
        self.hold_lesson_scene();
    }

    /// The value of `key` in the lesson step's scene, as `--set` would write it (`None`
    /// without a lesson, or where the scene holds none of its own).
    pub fn lesson_setting(&self, key: &str) -> Option<String> {
        let p = self.lesson.as_ref()?;
        let value = match p.current().scene {
            LessonScene::Bar => IMPACT.shown(&self.bar.core.setup, key),
            LessonScene::Compare => IMPACT.shown(&self.compare.core.setup, key),
            LessonScene::Buildings => BUILDINGS.shown(&self.buildings.setup, key),
            LessonScene::Bridge => BRIDGE.shown(&self.bridge.setup, key),
        };
        value.map(|(_, v)| v.describe())
    }

    /// Whether the window's own ways of replacing a scene (scene tabs, presets, Reset, Open,
    /// dropped files) are closed: a lesson step decides its scene.
    pub(super) fn scene_locked(&self) -> bool {
        self.lesson.is_some()
    }
}

/// Whether `key` may be changed in the player's step.
pub(super) fn step_opens(p: &LessonPlayer, key: &str) -> bool {
    Lock::unlocking(&p.current().unlock, false).opens(key)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_a_frame_that_moved_nothing_unlocked_is_undone() {
        let lock = Lock::unlocking(["bar2.length", "left.storeys"], false);
        assert_eq!(refused(&lock, vec![]), None);
        assert_eq!(
            refused(&lock, vec!["bar1.length".into()]),
            Some(vec!["bar1.length".to_string()])
        );
        assert_eq!(refused(&lock, vec!["bar2.length".into()]), None);
        // A storey count resizes the lists of that side: they follow the unlocked key.
        assert_eq!(
            refused(&lock, vec!["left.storeys".into(), "left.masses".into()]),
            None
        );
    }

    #[test]
    fn a_preset_over_the_step_changes_locked_keys_the_registry_sees() {
        let base = ImpactSetup::default();
        let mut other = base;
        other
            .apply_assignment("bar1.length=0.5")
            .expect("a key of the table");
        assert_eq!(
            changed(&IMPACT, IMPACT_SETTINGS, &base, &other),
            vec!["bar1.length".to_string()]
        );
        let mut b = BuildingSetup::default();
        let before = b.clone();
        b.scenario.contact = crate::model::building::ContactModel::None;
        assert_eq!(
            changed(&BUILDINGS, BUILDING_SETTINGS, &before, &b),
            vec!["contact.model".to_string()]
        );
        let mut bridge = BridgeSetup::default();
        let before = bridge.clone();
        bridge.scenario.apparent_velocity_m_s = Some(500.0);
        assert_eq!(
            changed(&BRIDGE, BRIDGE_SETTINGS, &before, &bridge),
            vec!["motion.apparent_velocity".to_string()]
        );
    }
}
