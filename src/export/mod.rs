//! Figures for lectures and papers: PNG and SVG plots with axes, units, legend and title.

pub mod plot;
