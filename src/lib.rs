//! Pounding Lab: the Sears impact model, its peer models and structural pounding.
//!
//! `model` is the physics core (no GUI, GPU or file formats); `io` reads presets and writes
//! histories; `cli` is the command-line front end.

pub mod cli;
pub mod io;
pub mod model;
