//! Files and text at the edge of the core: presets, settings, CSV histories.

pub mod csv;
pub mod preset;
pub mod settings;
