//! wgpu pipelines drawn inside egui through paint callbacks (one file per pipeline), and the same
//! drawing offscreen.

pub mod animate;
pub mod animate_bridge;
pub mod animate_buildings;
pub mod animate_view;
pub mod bars;
pub mod offscreen;
