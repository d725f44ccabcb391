//! wgpu pipelines drawn inside egui through paint callbacks (one file per pipeline), and the same
//! drawing offscreen.

pub mod animate;
pub mod animate_buildings;
pub mod bars;
pub mod offscreen;
