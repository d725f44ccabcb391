//! The record and its summary for the window's jobs. A slider that moves a building or a bridge
//! leaves the record as it was, so a built-in or synthetic record is read and summarised once and
//! kept for the next job, not on every change: for 8 s of El Centro that was 13 million
//! instructions (reading the text, and the 80 periods of the spectrum behind the predominant
//! period), about 4 ms of the 40 ms from a change to its result. A record file is read again
//! each time: it may have changed on disk.

use crate::io::motion::{MotionError, MotionSpec};
use crate::model::motion::{GroundMotion, MotionStats};
use std::sync::Mutex;

/// A record worked out, by the spec it came from.
type Kept = Mutex<Option<(MotionSpec, GroundMotion, MotionStats)>>;

/// The last record the window's jobs worked out.
static LAST: Kept = Mutex::new(None);

/// The record `spec` names and its summary.
pub(super) fn load(spec: &MotionSpec) -> Result<(GroundMotion, MotionStats), MotionError> {
    load_keeping(&LAST, spec)
}

/// [`load`], keeping the record in `last`.
fn load_keeping(
    last: &Kept,
    spec: &MotionSpec,
) -> Result<(GroundMotion, MotionStats), MotionError> {
    let kept = spec
        .file
        .as_deref()
        .is_none_or(crate::io::motion::is_built_in);
    if kept
        && let Some((s, m, stats)) = last.lock().unwrap_or_else(|e| e.into_inner()).as_ref()
        && s == spec
    {
        return Ok((m.clone(), *stats));
    }
    let motion = crate::io::motion::load(spec)?;
    let stats = motion.stats();
    if kept {
        *last.lock().unwrap_or_else(|e| e.into_inner()) =
            Some((spec.clone(), motion.clone(), stats));
    }
    Ok((motion, stats))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_record_file_is_read_again_and_a_built_in_one_kept() {
        // Its own keeper: the window's is shared by every job in the process.
        let last: Kept = Mutex::new(None);
        let load = |spec: &MotionSpec| load_keeping(&last, spec);
        let dir =
            std::env::temp_dir().join(format!("pounding-motion-cache-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("record.txt");
        let spec = MotionSpec {
            file: Some(path.to_string_lossy().into_owned()),
            dt_s: Some(0.01),
            ..MotionSpec::default()
        };
        std::fs::write(&path, "0.1\n0.2\n0.3\n").unwrap();
        let (first, _) = load(&spec).unwrap();
        std::fs::write(&path, "0.1\n0.5\n0.3\n").unwrap();
        let (second, stats) = load(&spec).unwrap();
        assert_ne!(
            first.accel_m_s2, second.accel_m_s2,
            "the edited file is read"
        );
        assert_eq!(stats, second.stats());
        std::fs::remove_dir_all(&dir).ok();

        let built_in = MotionSpec {
            file: Some("elcentro-1940".into()),
            ..MotionSpec::default()
        };
        let (a, sa) = load(&built_in).unwrap();
        assert_eq!(sa, crate::io::motion::load(&built_in).unwrap().stats());
        // What is kept is what the next load of the same record returns, not read again: a
        // mark put on the kept copy comes back.
        if let Some((_, m, _)) = last.lock().unwrap().as_mut() {
            m.accel_m_s2[0] = 12.5;
        }
        let (b, _) = load(&built_in).unwrap();
        assert_eq!(b.accel_m_s2[0], 12.5);
        assert_eq!(b.accel_m_s2[1..], a.accel_m_s2[1..]);
    }
}
