//! Files and text at the edge of the core: presets, settings, CSV histories.

pub mod bridge_settings;
pub mod building_settings;
pub mod csv;
pub mod file;
pub mod motion;
pub mod motion_settings;
pub mod preset;
pub mod registry;
pub mod settings;
