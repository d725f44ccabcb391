//! The physics core: no GUI, GPU, file formats or printing.

#![warn(missing_docs)]

pub mod bar;
pub mod building;
pub mod contact;
pub mod control;
pub mod error;
pub mod field;
pub mod history;
pub mod hysteresis;
pub mod impact;
pub mod material;
pub mod motion;
pub mod root;
pub mod scenario;
pub mod settings;
pub mod xt;
