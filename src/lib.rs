//! Pounding Lab: the Sears impact model, its peer models and structural pounding.
//!
//! `model` is the physics core (no GUI, GPU or file formats); `io` reads presets and writes
//! histories; `cli` is the command-line front end.

#[cfg(feature = "gui")]
pub mod app;
pub mod export;
pub mod io;
pub mod model;
#[cfg(feature = "gui")]
pub mod render;
pub mod study;
