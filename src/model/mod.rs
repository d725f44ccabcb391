//! The physics core: no GUI, GPU, file formats or printing.

pub mod bar;
pub mod contact;
pub mod field;
pub mod history;
pub mod impact;
pub mod material;
pub mod scenario;
