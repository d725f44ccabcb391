//! A bridge run's line plots, as `pounding bridge --plot` and a lesson's handout draw them: each
//! joint's force, each joint's opening against the seat length, each girder's displacement with
//! and without pounding.

use super::plot::{LinePlot, Series};
use crate::model::bridge::BridgeResult;

/// One history as a series, `scale` times its values.
fn series(name: String, t: &[f64], y: &[f64], scale: f64) -> Series {
    Series {
        name,
        points: t.iter().zip(y).map(|(t, y)| (*t, y * scale)).collect(),
    }
}

/// Each joint's force [MN] against time, `title` above.
pub fn joint_forces(r: &BridgeResult, title: String) -> LinePlot {
    let lines = r
        .joint_force_n
        .iter()
        .enumerate()
        .map(|(j, f)| {
            series(
                format!("joint {j} ({})", r.joints[j].kind()),
                &r.time_s,
                f,
                1e-6,
            )
        })
        .collect();
    LinePlot::new(title, "time [s]", "joint force [MN]", lines)
}

/// Each joint's opening [mm] against time, and the seat length it must stay under.
pub fn joint_openings(r: &BridgeResult, seat_length_m: f64) -> LinePlot {
    let mut lines: Vec<Series> = r
        .joint_opening_m
        .iter()
        .enumerate()
        .map(|(j, o)| series(format!("joint {j}"), &r.time_s, o, 1e3))
        .collect();
    lines.push(Series {
        name: "seat length".into(),
        points: vec![
            (0.0, seat_length_m * 1e3),
            (r.duration_s, seat_length_m * 1e3),
        ],
    });
    LinePlot::new(
        "Joint openings against the seat length",
        "time [s]",
        "joint opening [mm]",
        lines,
    )
}

/// Each girder's displacement relative to its ground [mm], with pounding and, from `free` (the
/// same bridge without contact), without.
pub fn girder_displacements(r: &BridgeResult, free: &BridgeResult) -> LinePlot {
    let mut lines: Vec<Series> = Vec::new();
    for (run, tag) in [(r, ""), (free, ", no pounding")] {
        lines.extend(
            run.girder_displacement_m
                .iter()
                .enumerate()
                .map(|(i, u)| series(format!("girder {}{tag}", i + 1), &run.time_s, u, 1e3)),
        );
    }
    LinePlot::new(
        "Girder displacements relative to their ground",
        "time [s]",
        "girder displacement [mm]",
        lines,
    )
}

/// The strongest impact's force [MN] against the time from its onset [ms], a contact's length
/// either side: how long a contact lasts, to read off. `None` for a run without impacts.
pub fn strongest_impact(r: &BridgeResult) -> Option<LinePlot> {
    let e = r
        .impacts
        .iter()
        .max_by(|a, b| a.peak_force_n.total_cmp(&b.peak_force_n))?;
    let margin = e.duration_s();
    let points = r
        .time_s
        .iter()
        .zip(&r.joint_force_n[e.level])
        .filter(|(t, _)| (e.start_s - margin..=e.end_s + margin).contains(*t))
        .map(|(t, f)| ((t - e.start_s) * 1e3, f * 1e-6))
        .collect();
    Some(LinePlot::new(
        format!("The strongest impact, at joint {}", e.level),
        "time from its onset [ms]",
        "joint force [MN]",
        vec![Series {
            name: format!("joint {}", e.level),
            points,
        }],
    ))
}
