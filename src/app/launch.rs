//! How the window starts: the scene on screen and what `pounding window` asks for.

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SceneKind {
    BarImpact,
    WaveVsLumped,
    Buildings,
    Bridge,
    Study,
}

impl SceneKind {
    pub fn name(self) -> &'static str {
        match self {
            SceneKind::BarImpact => "bar",
            SceneKind::WaveVsLumped => "compare",
            SceneKind::Buildings => "buildings",
            SceneKind::Bridge => "bridge",
            SceneKind::Study => "study",
        }
    }
    pub fn from_name(s: &str) -> Option<Self> {
        [
            SceneKind::BarImpact,
            SceneKind::WaveVsLumped,
            SceneKind::Buildings,
            SceneKind::Bridge,
            SceneKind::Study,
        ]
        .into_iter()
        .find(|k| k.name() == s)
    }
}

/// How the window starts (from `pounding window` or the defaults).
#[derive(Debug, Clone, Default)]
pub struct Launch {
    pub scene: Option<SceneKind>,
    pub preset: Option<String>,
    /// Close after this many frames (smoke tests, screenshots).
    pub exit_after_frames: Option<u64>,
    /// Start paused at this animation time [s].
    pub time_s: Option<f64>,
    /// Save a screenshot here before closing (with `exit_after_frames`).
    pub screenshot: Option<std::path::PathBuf>,
    /// Open this lesson (a shipped name or a file).
    pub lesson: Option<String>,
    /// At this step, counted from 1 (without it, where the lesson was left).
    pub lesson_step: Option<usize>,
    /// Start in lecture mode.
    pub lecture: bool,
    /// Start in teacher mode: a lesson's teacher notes shown (never to a student otherwise).
    pub teacher: bool,
    /// Move this setting every frame and report how soon its runs land (with
    /// `exit_after_frames`).
    pub drag: Option<super::drag::DragSpec>,
    /// The panels leave their background to the frame's clear (the window; a test harness
    /// that clears to transparent keeps them filled).
    pub background_by_clear: bool,
    /// Lines are drawn without anti-aliasing on a software renderer unless the user chose
    /// otherwise (the window; a test harness keeps them anti-aliased, as its snapshots are).
    pub plain_lines_on_software: bool,
}

/// Set by snapshot tests: wall-clock timings (which differ run to run) print as "-".
pub static HIDE_TIMINGS: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);
