//! wgpu pipelines drawn inside egui through paint callbacks; one file per pipeline.

pub mod bars;
