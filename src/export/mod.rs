//! Figures for lectures and papers: PNG and SVG plots with axes, units, legend and title, and
//! the x-t diagram.

pub mod animation;
pub mod bitmap;
pub mod bridge_plots;
pub mod palette;
pub mod plot;
pub mod xt;

/// A file's extension in lower case ("" for none): what picks a format.
pub fn extension(path: &std::path::Path) -> String {
    path.extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase()
}
