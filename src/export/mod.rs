//! Figures for lectures and papers: PNG and SVG plots with axes, units, legend and title, and
//! the x-t diagram.

pub mod plot;
pub mod xt;
