//! `pounding window --drag KEY=FROM:TO`: moves one setting of the scene on screen as a hand
//! dragging its slider does (a new value every frame, FROM to TO and back), and says on closing
//! how soon the changes' runs were on screen. This is how the scenes' liveness is measured in
//! the window itself, with its drawing and its solver thread competing for the same cores.

use super::worker::SolveSlot;
use crate::model::error::InputError;
use std::time::{Duration, Instant};

/// Frames from FROM to TO (and as many back): two seconds of a drag at 60 frames a second.
const HALF_PERIOD_FRAMES: u64 = 120;

/// What `--drag` asks for.
#[derive(Debug, Clone, PartialEq)]
pub struct DragSpec {
    pub key: String,
    pub from: f64,
    pub to: f64,
}

impl DragSpec {
    /// Reads `KEY=FROM:TO`; the key itself is checked by the scene the value goes to.
    pub fn parse(text: &str) -> Result<Self, String> {
        let shape = "expected KEY=FROM:TO, as in gap=0.01:0.03";
        let (key, range) = text.split_once('=').ok_or(shape)?;
        let (from, to) = range.split_once(':').ok_or(shape)?;
        let number = |s: &str| {
            s.trim()
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| format!("'{s}' is not a finite number ({shape})"))
        };
        let key = key.trim();
        if key.is_empty() {
            return Err(shape.into());
        }
        Ok(DragSpec {
            key: key.into(),
            from: number(from)?,
            to: number(to)?,
        })
    }

    /// The value at frame `k` of the drag: a triangle between FROM and TO, never the same
    /// value twice running (every frame is a change).
    fn value(&self, k: u64) -> f64 {
        let phase = k % (2 * HALF_PERIOD_FRAMES);
        let up = if phase <= HALF_PERIOD_FRAMES {
            phase
        } else {
            2 * HALF_PERIOD_FRAMES - phase
        };
        self.from + (self.to - self.from) * (up as f64 + 0.5) / (HALF_PERIOD_FRAMES as f64 + 1.0)
    }
}

/// A drag under way and what it has measured.
pub(super) struct Drag {
    pub spec: DragSpec,
    changes: u64,
    /// The scene's count of landed runs when last seen.
    runs_seen: Option<u64>,
    /// Each landed run's change to result.
    latencies: Vec<Duration>,
    /// When each run landed (for the longest wait between two).
    landings: Vec<Instant>,
    started: Option<Instant>,
    frame_times: Vec<Duration>,
    /// The app's own part of each frame (its `ui`, before egui paints).
    ui_times: Vec<Duration>,
    last_frame: Option<Instant>,
    /// Why the drag stopped (a key the scene does not take, a value it refuses).
    pub refused: Option<String>,
}

impl Drag {
    pub fn new(spec: DragSpec) -> Self {
        Drag {
            spec,
            changes: 0,
            runs_seen: None,
            latencies: vec![],
            landings: vec![],
            started: None,
            frame_times: vec![],
            ui_times: vec![],
            last_frame: None,
            refused: None,
        }
    }

    /// One frame of the drag on a scene: what landed since the last frame is counted, and the
    /// setting takes its next value; true when it did (the scene is to solve again).
    pub fn step<I, O, S>(
        &mut self,
        slot: &SolveSlot<I, O>,
        setup: &mut S,
        apply: impl Fn(&mut S, &str) -> Result<(), InputError>,
    ) -> bool {
        // The drag starts once the scene's first run is on screen, as a hand's would.
        if slot.runs == 0 {
            return false;
        }
        self.observe(slot.runs, slot.latency);
        let Some(assignment) = self.next_assignment() else {
            return false;
        };
        match apply(setup, &assignment) {
            Ok(()) => true,
            Err(e) => {
                self.refused = Some(e.to_string());
                false
            }
        }
    }

    /// The app's part of the last frame.
    pub fn ui_time(&mut self, t: Duration) {
        if self.changes > 0 {
            self.ui_times.push(t);
        }
    }

    /// The assignment for this frame's change (`None` once refused).
    fn next_assignment(&mut self) -> Option<String> {
        if self.refused.is_some() {
            return None;
        }
        let now = Instant::now();
        self.started.get_or_insert(now);
        if let Some(last) = self.last_frame.replace(now) {
            self.frame_times.push(now - last);
        }
        let value = self.spec.value(self.changes);
        self.changes += 1;
        Some(format!("{}={value}", self.spec.key))
    }

    /// Takes the scene's count of landed runs and the last one's change to result: a run that
    /// landed since the last frame is counted (not the one the window opened with).
    fn observe(&mut self, runs: u64, latency: Duration) {
        let seen = self.runs_seen.replace(runs);
        if self.changes > 0 && seen.is_some_and(|s| runs > s) {
            self.latencies.push(latency);
            self.landings.push(Instant::now());
        }
    }

    /// What the drag measured, in a few lines.
    pub fn report(&self) -> String {
        if let Some(why) = &self.refused {
            return format!("--drag: stopped: {why}");
        }
        let span = self
            .started
            .zip(self.last_frame)
            .map_or(0.0, |(a, b)| (b - a).as_secs_f64());
        let mut lines = vec![format!(
            "--drag {}: {} changes in {:.2} s ({:.1} frames/s; frame interval median {}, max {}; the app's ui median {})",
            self.spec.key,
            self.changes,
            span,
            self.frame_times.len() as f64 / span.max(1e-9),
            ms(median(&self.frame_times)),
            ms(self.frame_times.iter().max().copied()),
            ms(median(&self.ui_times)),
        )];
        let waits: Vec<Duration> = self.landings.windows(2).map(|w| w[1] - w[0]).collect();
        lines.push(format!(
            "  {} runs landed; change to result median {}, max {}; longest wait between two landed runs {}",
            self.latencies.len(),
            ms(median(&self.latencies)),
            ms(self.latencies.iter().max().copied()),
            ms(waits.iter().max().copied()),
        ));
        lines.join("\n")
    }
}

fn median(xs: &[Duration]) -> Option<Duration> {
    let mut v = xs.to_vec();
    v.sort();
    v.get(v.len() / 2).copied()
}

fn ms(d: Option<Duration>) -> String {
    d.map_or("-".into(), |d| super::status::ms(d.as_secs_f64(), 1))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_drag_reads_key_and_range_and_names_what_is_wrong() {
        let d = DragSpec::parse("gap = 0.01:0.03").unwrap();
        assert_eq!((d.key.as_str(), d.from, d.to), ("gap", 0.01, 0.03));
        assert!(DragSpec::parse("gap").unwrap_err().contains("KEY=FROM:TO"));
        assert!(
            DragSpec::parse("gap=0.01")
                .unwrap_err()
                .contains("KEY=FROM:TO")
        );
        assert!(DragSpec::parse("gap=x:1").unwrap_err().contains("'x'"));
        assert!(DragSpec::parse("gap=1:inf").unwrap_err().contains("finite"));
        assert!(DragSpec::parse("=1:2").is_err());
    }

    #[test]
    fn a_drag_changes_the_value_every_frame_within_its_range() {
        let d = DragSpec::parse("gap=1:2").unwrap();
        let values: Vec<f64> = (0..600).map(|k| d.value(k)).collect();
        assert!(values.iter().all(|v| (1.0..=2.0).contains(v)));
        assert!(values.windows(2).all(|w| w[0] != w[1]));
        let (lo, hi) = values
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
        assert!(
            lo < 1.01 && hi > 1.99,
            "the drag spans its range: {lo} {hi}"
        );
    }
}
