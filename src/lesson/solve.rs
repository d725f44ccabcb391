//! A step's scene loaded and solved headless, with the existing solvers.

use super::context::Context;
use super::{LessonError, LessonScene, Step};
use crate::io::bridge_settings::BridgeSetup;
use crate::io::building_settings::BuildingSetup;
use crate::io::preset;
use crate::io::settings::{ImpactSetup, SettingValue};
use crate::model::bridge::{BridgeResult, BridgeScenario};
use crate::model::building::{BuildingResult, BuildingScenario, ContactModel};
use crate::model::control::Control;
use crate::model::error::InputError;
use crate::model::impact::{ImpactResult, ModelKind};

/// A scene's settings: the step's preset with its overrides.
// One per step solve: the variants' sizes do not matter, plain fields read better than boxes.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, PartialEq)]
pub enum SceneSetup {
    /// The bar and compare scenes.
    Impact(ImpactSetup),
    Buildings(BuildingSetup),
    Bridge(BridgeSetup),
}

impl SceneSetup {
    /// The preset (`None`: the scene's default) with `set` applied; the error says what failed.
    pub fn load(
        scene: LessonScene,
        preset_name: Option<&str>,
        set: &[(String, String, usize)],
    ) -> Result<Self, String> {
        let name = preset_name.unwrap_or(scene.default_preset());
        let mut setup = match scene {
            LessonScene::Bar | LessonScene::Compare => {
                SceneSetup::Impact(preset::load_for(name, "impact").map_err(|e| e.to_string())?)
            }
            LessonScene::Buildings => SceneSetup::Buildings(
                preset::load_for(name, "buildings").map_err(|e| e.to_string())?,
            ),
            LessonScene::Bridge => {
                SceneSetup::Bridge(preset::load_for(name, "bridge").map_err(|e| e.to_string())?)
            }
        };
        for (k, v, _) in set {
            setup
                .apply(k, v)
                .map_err(|e| format!("{}: {}", e.field, e.message))?;
        }
        Ok(setup)
    }

    /// Sets one key as `--set KEY=VALUE` would.
    pub fn apply(&mut self, key: &str, value: &str) -> Result<(), InputError> {
        let v = SettingValue::from_cli(value);
        match self {
            SceneSetup::Impact(s) => s.apply(key, &v),
            SceneSetup::Buildings(s) => s.apply(key, &v),
            SceneSetup::Bridge(s) => s.apply(key, &v),
        }
    }
}

/// A solved step: what the window would show, and the context its expressions read.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone)]
pub enum Solved {
    /// Each model's run (one in the bar scene, the compared models in the compare scene).
    Impact {
        setup: ImpactSetup,
        runs: Vec<(ModelKind, ImpactResult)>,
    },
    /// The run, and the same pair without contact (for the gaps and no-pounding peaks).
    Buildings {
        setup: BuildingSetup,
        result: BuildingResult,
        free: BuildingResult,
        motion_name: String,
    },
    /// The run, and the same bridge without contact (the gaps each joint needs, the openings
    /// and peaks without pounding).
    Bridge {
        setup: BridgeSetup,
        result: BridgeResult,
        free: BridgeResult,
    },
}

impl Solved {
    /// The values a step's expressions read.
    pub fn context(&self) -> Context {
        match self {
            Solved::Impact { setup, runs } => {
                let refs: Vec<(ModelKind, &ImpactResult)> =
                    runs.iter().map(|(m, r)| (*m, r)).collect();
                Context::impact(setup, &refs)
            }
            Solved::Buildings {
                setup,
                result,
                free,
                ..
            } => Context::buildings(setup, result, Some(free)),
            Solved::Bridge {
                setup,
                result,
                free,
            } => Context::bridge(setup, result, Some(free)),
        }
    }

    /// The run of one model (impact scenes).
    pub fn run(&self, model: ModelKind) -> Option<&ImpactResult> {
        match self {
            Solved::Impact { runs, .. } => runs.iter().find(|(m, _)| *m == model).map(|(_, r)| r),
            Solved::Buildings { .. } | Solved::Bridge { .. } => None,
        }
    }
}

/// Solves a step's scene with `extra` overrides on top of its own (a task's solution, a
/// student's slider): the error names the step.
pub fn solve_step(
    step: &Step,
    extra: &[(String, String, usize)],
    control: &Control,
    file: &str,
) -> Result<Solved, LessonError> {
    let err = |line: usize, message: String| LessonError {
        file: file.to_string(),
        line: Some(line),
        field: Some(format!("step '{}'", step.title)),
        message,
    };
    let all: Vec<(String, String, usize)> = step.set.iter().chain(extra).cloned().collect();
    let setup = SceneSetup::load(step.scene, step.preset.as_deref(), &all)
        .map_err(|m| err(step.line, m))?;
    match setup {
        SceneSetup::Impact(setup) => {
            let models: Vec<ModelKind> = if step.scene == LessonScene::Compare {
                let mut m = step.models.clone();
                if !m.contains(&setup.model) {
                    m.insert(0, setup.model);
                }
                m
            } else {
                vec![setup.model]
            };
            // As in the window, a peer that cannot solve this scene (lumped Hertz with two flat
            // ends) is left out, its fields unavailable; the lead model must solve.
            let mut runs = Vec::new();
            for m in models {
                match crate::model::impact::solve_with(m, &setup.scenario, control) {
                    Ok(r) => runs.push((m, r)),
                    Err(e) if m == setup.model => {
                        return Err(err(step.line, format!("{} could not solve: {e}", m.name())));
                    }
                    Err(_) => {}
                }
            }
            Ok(Solved::Impact { setup, runs })
        }
        SceneSetup::Buildings(setup) => {
            let motion = crate::io::motion::load(&setup.motion)
                .map_err(|e| err(step.line, format!("motion: {e}")))?;
            let solve = |sc: &BuildingScenario| {
                crate::model::building::solve_with(sc, &motion, control)
                    .map_err(|e| err(step.line, format!("the buildings could not solve: {e}")))
            };
            let result = solve(&setup.scenario)?;
            let free = solve(&BuildingScenario {
                contact: ContactModel::None,
                ..setup.scenario.clone()
            })?;
            Ok(Solved::Buildings {
                setup,
                result,
                free,
                motion_name: motion.name.clone(),
            })
        }
        SceneSetup::Bridge(setup) => {
            let motion = crate::io::motion::load(&setup.motion)
                .map_err(|e| err(step.line, format!("motion: {e}")))?;
            let solve = |sc: &BridgeScenario| {
                crate::model::bridge::solve_with(sc, &motion, control)
                    .map_err(|e| err(step.line, format!("the bridge could not solve: {e}")))
            };
            let result = solve(&setup.scenario)?;
            let free = solve(&BridgeScenario {
                contact: ContactModel::None,
                ..setup.scenario.clone()
            })?;
            Ok(Solved::Bridge {
                setup,
                result,
                free,
            })
        }
    }
}
