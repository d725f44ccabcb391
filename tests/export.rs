//! Plot files as a reader of a lecture or paper gets them: a PNG of the asked pixel size whose
//! text and lines grow with the scale, and an SVG that is well-formed XML with the title, axis
//! labels (units included) and legend.

use pounding::export::plot::{LinePlot, Series};
use std::path::PathBuf;

mod common;

fn plot(scale: f64) -> LinePlot {
    LinePlot {
        size: (800, 500),
        scale,
        ..LinePlot::new(
            "Contact force",
            "time [ms]",
            "force [kN]",
            vec![Series {
                name: "sears".into(),
                points: (0..200)
                    .map(|i| {
                        let t = i as f64 / 199.0;
                        (t, (std::f64::consts::PI * t).sin() * 135.0)
                    })
                    .collect(),
            }],
        )
    }
}

fn temp(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("pounding-export-{}-{name}", std::process::id()))
}

/// Pixel size, the share of pixels that are not white, and the curve's thickness: the median
/// over columns of the count of pixels in the curve's blue (the curve is one stroke per column
/// except where it is steep).
fn png_ink(path: &std::path::Path) -> ((u32, u32), f64, f64) {
    let (width, height, channels, buf) = common::read_png(path);
    let (w, h) = (width as usize, height as usize);
    let px = |x: usize, y: usize| &buf[(y * w + x) * channels..(y * w + x) * channels + 3];
    let inked = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .filter(|&(x, y)| px(x, y).iter().any(|&c| c < 200))
        .count();
    let blue = |p: &[u8]| p[2] > 120 && p[2] as i32 > p[0] as i32 + 60;
    let mut thickness: Vec<usize> = (0..w)
        .map(|x| (0..h).filter(|&y| blue(px(x, y))).count())
        .filter(|&n| n > 0)
        .collect();
    thickness.sort_unstable();
    (
        (width, height),
        inked as f64 / (w * h) as f64,
        thickness[thickness.len() / 2] as f64,
    )
}

#[test]
fn png_has_the_asked_size_and_its_lines_thicken_with_the_scale() {
    let (a, b) = (temp("s1.png"), temp("s2.png"));
    plot(1.0).write(&a).unwrap();
    plot(2.0).write(&b).unwrap();
    let (size1, ink1, curve1) = png_ink(&a);
    let (size2, ink2, curve2) = png_ink(&b);
    assert_eq!(size1, (800, 500));
    assert_eq!(size2, (800, 500));
    // Axes, text and a curve, on a mostly white page.
    assert!(ink1 > 0.005 && ink1 < 0.5, "ink {ink1}");
    // The stroke goes from 2 to 4 px: the median column of the curve is 2 px thicker (3 where
    // rounding falls the other way), and the larger text adds ink.
    assert!(
        curve2 - curve1 >= 2.0 && curve2 - curve1 <= 3.0,
        "curve {curve2} px thick at scale 2 vs {curve1}"
    );
    assert!(ink2 > ink1, "ink {ink2} at scale 2 vs {ink1}");
    let _ = (std::fs::remove_file(a), std::fs::remove_file(b));
}

#[test]
fn svg_is_well_formed_and_carries_title_axes_with_units_and_legend() {
    let path = temp("p.svg");
    plot(1.0).write(&path).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let doc = roxmltree::Document::parse(&text).expect("well-formed XML");
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    assert_eq!(root.attribute("width"), Some("800"));
    assert_eq!(root.attribute("height"), Some("500"));
    let texts: Vec<&str> = doc.descendants().filter_map(|n| n.text()).collect();
    for want in ["Contact force", "time [ms]", "force [kN]", "sears"] {
        assert!(
            texts.iter().any(|t| t.contains(want)),
            "no text {want}: {texts:?}"
        );
    }
    // The curve: a polyline with the 200 points.
    let longest = doc
        .descendants()
        .filter_map(|n| n.attribute("points"))
        .map(|p| p.split_whitespace().count())
        .max()
        .unwrap_or(0);
    assert!(longest >= 150, "longest polyline has {longest} points");
    let _ = std::fs::remove_file(path);
}

#[test]
fn an_unknown_extension_is_refused_with_the_allowed_ones() {
    let e = plot(1.0).write(&temp("p.jpg")).unwrap_err().to_string();
    assert!(e.contains(".svg or .png") && e.contains("p.jpg"), "{e}");
}
