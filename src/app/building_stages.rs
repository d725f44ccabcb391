//! The Building pounding scene's side of its staged solve: the stages taken as they land (the
//! run so far, the run, the run without contact, the estimate), what is shown while the later
//! ones are on their way, and what a lesson may read. A child of the scene, so it keeps the
//! scene's state private.

use super::BuildingScene;
use crate::app::building_job::{Baseline, Output, Stage};
use crate::app::building_view::BuildingDrawing;
use crate::app::worker::Landed;
use crate::model::building::BuildingErrorEstimate;

pub(super) use crate::app::later::{Later, StageTimes};

/// What is on screen: one request's run (whole, or as far as it has solved) and its later
/// stages as they land.
pub(super) type Shown =
    crate::app::later::Shown<BuildingDrawing, Box<Baseline>, Option<BuildingErrorEstimate>>;

impl BuildingScene {
    /// Takes the stages that landed, in order.
    pub fn poll(&mut self) {
        // A panic's message stays as the error, and the last result on screen.
        while let Some(landed) = self.slot.poll_stage() {
            self.land(landed);
        }
        if !self.busy() {
            self.ended();
        }
    }

    /// Playback waits at the edge of a run still solving.
    fn hold_playback(&mut self) {
        self.playback.ready_s = self.shown.edge(|d| d.result.solved_to_s);
    }

    /// One stage of the newest request.
    pub(super) fn land(&mut self, landed: Landed<Output>) {
        match landed.output {
            Ok(Stage::Partial(drawing)) => self.show_run(drawing, false),
            Ok(Stage::Run(drawing)) => {
                // Change to result is the time to the first whole run: the checks that follow
                // it are timed apart.
                self.slot.record_run(landed.job_time, landed.since_request);
                self.show_run(drawing, true);
            }
            Ok(Stage::Baseline(b)) => {
                self.times.baseline = Some(landed.since_request);
                if let Some(s) = self.shown.newest_whole() {
                    s.baseline = Later::Ready(b);
                }
            }
            Ok(Stage::Estimate(e)) => {
                self.times.estimate = Some(landed.since_request);
                if let Some(s) = self.shown.newest_whole() {
                    s.estimate = Later::Ready(e);
                }
            }
            // The last result stays; the error says why the new one failed.
            Err(e) => self.slot.error = Some(e.to_string()),
        }
    }

    /// Shows the newest request's run, whole or so far; its later stages are on their way.
    fn show_run(&mut self, drawing: Box<BuildingDrawing>, whole: bool) {
        if !self.shown.current() {
            // A new run has its own impacts: the diagram goes back to the strongest.
            self.selected = None;
        }
        self.playback.t_max = drawing.motion.duration_s();
        self.playback.t = self.playback.t.min(self.playback.t_max);
        if self.level.is_some_and(|l| l >= drawing.result.levels.len()) {
            self.level = None;
        }
        self.shown.show(drawing, whole);
        self.hold_playback();
    }

    /// The newest request is done: a run it left unfinished gives way to the last whole one,
    /// and a stage it never delivered is not coming.
    pub(super) fn ended(&mut self) {
        self.shown.ended();
        self.hold_playback();
    }

    /// What the status bar says while the newest request solves: how far its run has got, or
    /// which checks of its run on screen are still to come.
    pub fn solving_note(&self) -> String {
        let Some(s) = self.shown.solved.as_ref().filter(|s| s.current) else {
            return "solving...".into();
        };
        if !s.whole {
            return format!(
                "solving: {:.1} s of {:.1} s",
                s.drawing.result.solved_to_s, self.playback.t_max
            );
        }
        crate::app::later::pending_note(&s.baseline, &s.estimate).into()
    }

    /// When the later stages of the newest request landed, from its change (the change to
    /// result being the time to its run).
    pub fn later_stages(&self) -> String {
        self.times.describe(self.busy())
    }

    /// What a lesson's expressions read: the run and the run without contact, both whole and
    /// the newest request's; `None` until they are.
    pub fn lesson_context(&self) -> Option<crate::lesson::Context> {
        let s = self.shown.solved.as_ref().filter(|s| s.whole)?;
        if self.busy() && !s.current {
            return None;
        }
        Some(crate::lesson::Context::buildings(
            &s.drawing.setup,
            &s.drawing.result,
            Some(&s.baseline.ready()?.result),
        ))
    }
}
