//! The ground-motion settings (`motion.*`) as registry entries for any setup that carries a
//! [`MotionSpec`]: the building and bridge scenes read their records the same way.

use super::motion::{MotionSpec, Units};
use super::registry::{Entry, Target, number, put, word};
use super::settings::SettingValue;
use crate::model::error::InputError;
use crate::model::settings::building as setting;

/// The `motion.file` value that asks for the seeded synthetic record.
pub const SYNTHETIC: &str = "synthetic";

/// A setup with a ground motion.
pub trait WithMotion: 'static {
    /// Its record.
    fn motion(&self) -> &MotionSpec;
    /// Its record, to change.
    fn motion_mut(&mut self) -> &mut MotionSpec;
}

fn file<S: WithMotion>(s: &mut S, t: &Target, v: &SettingValue) -> Result<(), InputError> {
    let name = t.text(v)?;
    s.motion_mut()
        .set_source(name)
        .map_err(|e| InputError::new(t.key, e))
}

/// A factor on the record: 0 would erase it.
fn scale<S: WithMotion>(s: &mut S, t: &Target, v: &SettingValue) -> Result<(), InputError> {
    let x = t.checked(v)?;
    if x == 0.0 {
        return Err(InputError::new(
            t.key,
            "0 is not allowed: a factor in [-100, 100] other than 0 (negative flips the record)",
        ));
    }
    s.motion_mut().scale = x;
    Ok(())
}

fn seed<S: WithMotion>(s: &mut S, t: &Target, v: &SettingValue) -> Result<(), InputError> {
    put(&mut s.motion_mut().synthetic.seed, t.whole(v))
}

/// The record's source (`motion.file`).
pub const fn file_entry<S: WithMotion>() -> Entry<S> {
    Entry::new(
        &setting::MOTION_FILE,
        |s, _| word(s.motion().file.as_deref().unwrap_or(SYNTHETIC)),
        file::<S>,
    )
}

/// `motion.units`.
pub const fn units_entry<S: WithMotion>() -> Entry<S> {
    Entry::new(
        &setting::MOTION_UNITS,
        |s, _| word(s.motion().units.name()),
        |s, t, v| put(&mut s.motion_mut().units, t.choice(v, Units::from_name)),
    )
}

/// `motion.scale`.
pub const fn scale_entry<S: WithMotion>() -> Entry<S> {
    Entry::new(
        &setting::MOTION_SCALE,
        |s, _| number(s.motion().scale),
        scale::<S>,
    )
}

/// `motion.duration`.
pub const fn duration_entry<S: WithMotion>() -> Entry<S> {
    Entry::new(
        &setting::MOTION_DURATION,
        |s, _| s.motion().duration_s.and_then(number),
        |s, t, v| put(&mut s.motion_mut().duration_s, t.checked(v).map(Some)),
    )
}

/// `motion.dt`.
pub const fn dt_entry<S: WithMotion>() -> Entry<S> {
    Entry::new(
        &setting::MOTION_DT,
        |s, _| s.motion().dt_s.and_then(number),
        |s, t, v| put(&mut s.motion_mut().dt_s, t.checked(v).map(Some)),
    )
}

/// `motion.pga` of the synthetic record.
pub const fn pga_entry<S: WithMotion>() -> Entry<S> {
    Entry::new(
        &setting::MOTION_PGA,
        |s, _| number(s.motion().synthetic.pga_g),
        |s, t, v| put(&mut s.motion_mut().synthetic.pga_g, t.checked(v)),
    )
}

/// `motion.seed` of the synthetic record.
pub const fn seed_entry<S: WithMotion>() -> Entry<S> {
    Entry::new(
        &setting::MOTION_SEED,
        |s, _| number(s.motion().synthetic.seed as f64),
        seed::<S>,
    )
}

/// `motion.length` of the synthetic record.
pub const fn length_entry<S: WithMotion>() -> Entry<S> {
    Entry::new(
        &setting::MOTION_LENGTH,
        |s, _| number(s.motion().synthetic.duration_s),
        |s, t, v| put(&mut s.motion_mut().synthetic.duration_s, t.checked(v)),
    )
}
