//! The gap that avoids pounding, against the code rules that estimate it.
//!
//! From a run without contact: at each level the smallest gap that avoids contact is the largest
//! closing motion u_left - u_right there over the record (located between the solver's points
//! on the exact motion), and the code estimates combine the two buildings' peak displacements
//! at that level: ABS = |u_left|max + |u_right|max, SRSS = sqrt(|u_left|max^2 + |u_right|max^2).
//! The building pair needs the largest over its levels of each.
//!
//! The largest closing motion is found on the exact motion (the run's cubic between its points
//! locates it, the exact propagation refines it), and reported rounded up by a part in 10^9, so
//! that the gap reported, applied, gives no contact: two runs on different grids (the contact
//! run steps finer) agree on the motion to about 1e-12 relatively, their round-off accumulated
//! over hundreds of thousands of exact steps.

/// What the minimum gap is rounded up by, relatively: well above the runs' round-off.
pub const ROUND_UP: f64 = 1e-9;

use super::BuildingResult;

/// One level's gaps [m].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelGap {
    /// The smallest gap that avoids contact at this level [m].
    pub min_gap_m: f64,
    /// The absolute-sum rule: the sum of the peak displacements there [m].
    pub abs_m: f64,
    /// The SRSS rule: the root of the sum of their squares [m].
    pub srss_m: f64,
}

/// The pair's gaps [m] and the code rules' ratios to the minimum.
#[derive(Debug, Clone, PartialEq)]
pub struct GapAssessment {
    /// The smallest gap that avoids all contact (0 where the buildings never close).
    pub min_gap_m: f64,
    /// The level that sets it.
    pub level: Option<usize>,
    /// The absolute-sum rule at the level that needs most [m].
    pub abs_m: f64,
    /// The SRSS rule at the level that needs most [m].
    pub srss_m: f64,
    /// ABS over the minimum gap (above 1: safe).
    pub abs_ratio: f64,
    /// SRSS over the minimum gap (below 1: the buildings would still touch).
    pub srss_ratio: f64,
    /// Each level's gaps, lowest first.
    pub levels: Vec<LevelGap>,
}

/// The gaps of a run made without contact (`contact = none`) that followed each level's
/// largest closing (not [`super::Checked`]'s comparison run, whose `max_closing_m` is empty).
pub fn assess(free: &BuildingResult) -> GapAssessment {
    debug_assert!(
        free.max_closing_m.len() == free.levels.len(),
        "a gap assessment reads a run that followed the levels' largest closings"
    );
    let levels: Vec<LevelGap> = free
        .max_closing_m
        .iter()
        .zip(&free.peak_level_displacement_m)
        .map(|(closing, [l, r])| LevelGap {
            min_gap_m: closing.max(0.0) * (1.0 + ROUND_UP),
            abs_m: l + r,
            srss_m: (l * l + r * r).sqrt(),
        })
        .collect();
    let level = levels
        .iter()
        .enumerate()
        .filter(|(_, g)| g.min_gap_m > 0.0)
        .max_by(|a, b| a.1.min_gap_m.total_cmp(&b.1.min_gap_m))
        .map(|(i, _)| i);
    let min_gap_m = level.map_or(0.0, |i| levels[i].min_gap_m);
    let abs_m = levels.iter().map(|g| g.abs_m).fold(0.0, f64::max);
    let srss_m = levels.iter().map(|g| g.srss_m).fold(0.0, f64::max);
    let ratio = |x: f64| {
        if min_gap_m > 0.0 {
            x / min_gap_m
        } else {
            f64::INFINITY
        }
    };
    GapAssessment {
        min_gap_m,
        level,
        abs_m,
        srss_m,
        abs_ratio: ratio(abs_m),
        srss_ratio: ratio(srss_m),
        levels,
    }
}
