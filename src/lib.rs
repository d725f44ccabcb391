//! Pounding Lab: the Sears impact model, its peer models and structural pounding.
//!
//! - `model`: the physics core (no GUI, GPU, files or printing): bars and contact laws, the
//!   impact models, ground motion, the buildings, the settings table every front end reads;
//! - `io`: presets (TOML), the settings keys, ground-motion files and the built-in record;
//! - `study`: parallel sweeps, the paper's figures, the gap study (with progress and cancel);
//! - `export`: plot images (PNG, SVG);
//! - `lesson`: guided lessons (TOML steps, predictions, tasks checked on the result);
//! - `app` and `render` (the `gui` feature, on by default): the window and its wgpu views.
//!
//! The `pounding` binary (`src/main.rs`, `src/cli/`) is the command-line front end and opens
//! the window. The model is described in `docs/model.md`.

#[cfg(feature = "gui")]
pub mod app;
pub mod export;
pub mod io;
pub mod lesson;
pub mod model;
#[cfg(feature = "gui")]
pub mod render;
pub mod study;
