//! Studies: many solves run in parallel across cores, reported as figures (plots whose data is
//! also their CSV) and findings (the numbers a claim is checked against).
//!
//! A [`Control`] is shared with whoever runs a study: the study counts its solves in it, the
//! command line draws a progress bar from it, the window a progress bar and a cancel button.

pub mod building_sweep;
pub mod buildings;
pub mod gaps;
pub mod paper;
pub mod sweep;

use crate::export::plot::LinePlot;
use crate::model::building::BuildingScenario;
use crate::model::motion::GroundMotion;
use rayon::prelude::*;
use serde::Serialize;

pub use crate::model::control::{Cancelled, Control};

/// Why a study produced nothing.
#[derive(Debug, thiserror::Error)]
pub enum StudyError {
    #[error(transparent)]
    Cancelled(#[from] Cancelled),
    #[error("preset {0}")]
    Preset(#[from] crate::io::preset::PresetError),
    /// A setting the study makes was refused.
    #[error("{assignment}: {source}")]
    Setting {
        assignment: String,
        source: crate::model::error::InputError,
    },
    /// A solve the study cannot do without failed.
    #[error("{what}: {source}")]
    Solve {
        what: String,
        source: crate::model::error::SolveError,
    },
    /// The run a study's other numbers are relative to has no result.
    #[error("no reference: {0}")]
    Reference(String),
    #[error("the building studies need a ground motion")]
    NoMotion,
}

/// `f` over `items` on every core, counted in `progress`; stops early when cancelled.
pub fn par_map<I: Sync, T: Send>(
    progress: &Control,
    items: &[I],
    f: impl Fn(&I) -> T + Sync,
) -> Result<Vec<T>, Cancelled> {
    progress.plan(items.len());
    items
        .par_iter()
        .map(|item| {
            if progress.cancelled() {
                return Err(Cancelled);
            }
            let out = f(item);
            progress.tick();
            Ok(out)
        })
        .collect()
}

/// One plot of a study; its CSV is the plot's own data.
pub struct Figure {
    /// File stem: `STEM.png`, `STEM.svg`, `STEM.csv`.
    pub stem: String,
    pub plot: LinePlot,
}

impl Figure {
    /// Long format: one row per point, `series,x,y`, headed by the axis labels (with units).
    pub fn csv(&self) -> String {
        let quote = |s: &str| {
            if s.contains([',', '"']) {
                format!("\"{}\"", s.replace('"', "\"\""))
            } else {
                s.to_string()
            }
        };
        let mut text = format!(
            "series,{},{}\n",
            quote(&self.plot.x_label),
            quote(&self.plot.y_label)
        );
        for s in &self.plot.series {
            let name = quote(&s.name);
            for (x, y) in &s.points {
                text += &format!("{name},{x:.9e},{y:.9e}\n");
            }
        }
        text
    }
}

/// A number a study measured, named for what it is.
#[derive(Debug, Clone, Serialize)]
pub struct Finding {
    pub what: String,
    pub value: f64,
    pub unit: &'static str,
}

pub fn finding(what: impl Into<String>, value: f64, unit: &'static str) -> Finding {
    Finding {
        what: what.into(),
        value,
        unit,
    }
}

pub struct StudyOutput {
    pub figures: Vec<Figure>,
    pub findings: Vec<Finding>,
    /// Remarks a reader needs with the numbers (which record was used, points that failed).
    pub notes: Vec<String>,
}

/// What a study runs with.
pub struct Context<'a> {
    pub progress: &'a Control,
    /// The building studies' ground motion and buildings (the paper's Section 4 by default).
    pub motion: Option<&'a GroundMotion>,
    pub buildings: BuildingScenario,
}

impl<'a> Context<'a> {
    pub fn new(progress: &'a Control) -> Self {
        Context {
            progress,
            motion: None,
            buildings: BuildingScenario::paper(),
        }
    }
}

/// A built-in study.
pub struct Study {
    pub name: &'static str,
    /// Where it is in the paper.
    pub paper: &'static str,
    pub about: &'static str,
    /// Runs on the buildings of Section 4 (needs a ground motion).
    pub buildings: bool,
    pub run: fn(&Context) -> Result<StudyOutput, StudyError>,
}

/// Every built-in study, in the paper's order.
pub fn studies() -> Vec<&'static Study> {
    paper::STUDIES
        .iter()
        .chain(buildings::STUDIES.iter())
        .collect()
}

pub fn find(name: &str) -> Option<&'static Study> {
    studies().into_iter().find(|s| s.name == name)
}
