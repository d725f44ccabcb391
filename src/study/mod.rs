//! Studies: many solves run in parallel across cores, reported as figures (plots whose data is
//! also their CSV) and findings (the numbers a claim is checked against).
//!
//! [`Progress`] is shared with whoever runs a study: the command line draws a progress bar from
//! it, the window a progress bar and a cancel button.

pub mod buildings;
pub mod gaps;
pub mod paper;
pub mod sweep;

use crate::export::plot::LinePlot;
use crate::model::building::BuildingScenario;
use crate::model::motion::GroundMotion;
use rayon::prelude::*;
use serde::Serialize;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

/// Jobs planned and done, and a request to stop.
#[derive(Debug, Default)]
pub struct Progress {
    done: AtomicUsize,
    total: AtomicUsize,
    cancel: AtomicBool,
}

impl Progress {
    pub fn new() -> Self {
        Self::default()
    }
    /// Announces `n` more jobs.
    pub fn plan(&self, n: usize) {
        self.total.fetch_add(n, Ordering::Relaxed);
    }
    pub fn tick(&self) {
        self.done.fetch_add(1, Ordering::Relaxed);
    }
    pub fn done(&self) -> usize {
        self.done.load(Ordering::Relaxed)
    }
    pub fn total(&self) -> usize {
        self.total.load(Ordering::Relaxed)
    }
    /// Asks the running study to stop; jobs already started finish, no new one starts.
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }
    pub fn cancelled(&self) -> bool {
        self.cancel.load(Ordering::Relaxed)
    }
}

/// A study stopped by [`Progress::cancel`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("cancelled")]
pub struct Cancelled;

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
        source: crate::model::scenario::InputError,
    },
    /// A solve the study cannot do without failed.
    #[error("{what}: {source}")]
    Solve {
        what: String,
        source: crate::model::impact::SolveError,
    },
    /// The run a study's other numbers are relative to has no result.
    #[error("no reference: {0}")]
    Reference(String),
    #[error("the building studies need a ground motion")]
    NoMotion,
}

/// `f` over `items` on every core, counted in `progress`; stops early when cancelled.
pub fn par_map<I: Sync, T: Send>(
    progress: &Progress,
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
    pub progress: &'a Progress,
    /// The building studies' ground motion and buildings (the paper's Section 4 by default).
    pub motion: Option<&'a GroundMotion>,
    pub buildings: BuildingScenario,
}

impl<'a> Context<'a> {
    pub fn new(progress: &'a Progress) -> Self {
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
