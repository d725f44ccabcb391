//! Where two shear buildings can strike each other: one contact point per floor of either
//! building that lies within the other's height.
//!
//! Where the other building has a floor at the same elevation (within 1e-6 m) the point joins the
//! two floors (floor to floor). Otherwise the floor strikes the other building's column at its
//! elevation z, between that building's floors i-1 and i (floor 0 is the ground): the point moves
//! as (1 - s) u_{i-1} + s u_i with s = (z - z_{i-1}) / (z_i - z_{i-1}), and the contact force goes
//! to those floors with the same weights (the ground takes its share).

/// Elevations closer than this are the same level [m].
pub const SAME_LEVEL_M: f64 = 1e-6;

/// What meets at a level.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LevelKind {
    /// A floor of each building at the same height.
    FloorFloor,
    /// A floor of one building against the other's column line.
    FloorColumn,
}

impl LevelKind {
    /// The name reports use.
    pub fn name(self) -> &'static str {
        match self {
            LevelKind::FloorFloor => "floor-floor",
            LevelKind::FloorColumn => "floor-column",
        }
    }
}

/// Where a contact point sits on one building.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Attachment {
    /// On floor `f` (0-based: floor 1 is 0).
    Floor(usize),
    /// On the column between floor `below` (`None`: the ground) and floor `above`, a fraction
    /// `s` of the way up.
    Column {
        /// The floor below (`None`: the ground).
        below: Option<usize>,
        /// The floor above.
        above: usize,
        /// How far up the storey, 0 to 1.
        s: f64,
    },
}

impl Attachment {
    /// The floors the point moves with and their weights (the ground's share left out).
    pub fn weights(&self) -> Vec<(usize, f64)> {
        match *self {
            Attachment::Floor(f) => vec![(f, 1.0)],
            Attachment::Column { below, above, s } => {
                let mut w = vec![(above, s)];
                if let Some(b) = below {
                    w.insert(0, (b, 1.0 - s));
                }
                w
            }
        }
    }

    /// The floor whose slab strikes here, if this side is a floor.
    pub fn floor(&self) -> Option<usize> {
        match *self {
            Attachment::Floor(f) => Some(f),
            Attachment::Column { .. } => None,
        }
    }

    /// The floors involved, 1-based as engineers count them (0 is the ground).
    pub fn floors_1_based(&self) -> Vec<usize> {
        match *self {
            Attachment::Floor(f) => vec![f + 1],
            Attachment::Column { below, above, .. } => {
                vec![below.map_or(0, |b| b + 1), above + 1]
            }
        }
    }
}

/// One contact point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Level {
    /// Height above the ground [m].
    pub elevation_m: f64,
    /// What meets here.
    pub kind: LevelKind,
    /// Where the point sits on the left building.
    pub left: Attachment,
    /// Where the point sits on the right building.
    pub right: Attachment,
}

/// Floor elevations z_j = h_1 + ... + h_j [m].
pub fn elevations(heights_m: &[f64]) -> Vec<f64> {
    heights_m
        .iter()
        .scan(0.0, |z, h| {
            *z += h;
            Some(*z)
        })
        .collect()
}

/// Where elevation `z` lies on a building with floors at `zs`: a floor, or a point of a column.
/// `None` above the roof.
fn attach(zs: &[f64], z: f64) -> Option<Attachment> {
    if let Some(f) = zs.iter().position(|&zf| (zf - z).abs() <= SAME_LEVEL_M) {
        return Some(Attachment::Floor(f));
    }
    let above = zs.iter().position(|&zf| zf > z)?;
    let (z0, below) = if above == 0 {
        (0.0, None)
    } else {
        (zs[above - 1], Some(above - 1))
    };
    Some(Attachment::Column {
        below,
        above,
        s: (z - z0) / (zs[above] - z0),
    })
}

/// Every contact point of two buildings with storey heights `left` and `right`, lowest first.
pub fn levels(left_heights_m: &[f64], right_heights_m: &[f64]) -> Vec<Level> {
    let (zl, zr) = (elevations(left_heights_m), elevations(right_heights_m));
    let mut out: Vec<Level> = Vec::new();
    for (i, &z) in zl.iter().enumerate() {
        if let Some(right) = attach(&zr, z) {
            let kind = match right {
                Attachment::Floor(_) => LevelKind::FloorFloor,
                Attachment::Column { .. } => LevelKind::FloorColumn,
            };
            out.push(Level {
                elevation_m: z,
                kind,
                left: Attachment::Floor(i),
                right,
            });
        }
    }
    for (j, &z) in zr.iter().enumerate() {
        if out
            .iter()
            .any(|l| l.kind == LevelKind::FloorFloor && (l.elevation_m - z).abs() <= SAME_LEVEL_M)
        {
            continue;
        }
        if let Some(left) = attach(&zl, z) {
            out.push(Level {
                elevation_m: z,
                kind: LevelKind::FloorColumn,
                left,
                right: Attachment::Floor(j),
            });
        }
    }
    out.sort_by(|a, b| a.elevation_m.total_cmp(&b.elevation_m));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_storeys_meet_floor_to_floor_up_to_the_lower_roof() {
        let l = levels(&[3.0; 3], &[3.0; 5]);
        assert_eq!(l.len(), 3);
        assert!(l.iter().all(|x| x.kind == LevelKind::FloorFloor));
        assert_eq!(l[2].left, Attachment::Floor(2));
        assert_eq!(l[2].right, Attachment::Floor(2));
    }

    #[test]
    fn unequal_storeys_strike_columns_with_the_interpolation_weights() {
        let l = levels(&[3.5; 3], &[3.0; 4]);
        assert_eq!(l.len(), 6, "{l:?}");
        assert!(l.iter().all(|x| x.kind == LevelKind::FloorColumn));
        // The right building's first floor (3 m) on the left column between the ground and
        // the left's first floor (3.5 m): s = 3/3.5, the ground's share left out.
        let first = l[0];
        assert!((first.elevation_m - 3.0).abs() < 1e-12);
        assert_eq!(first.right, Attachment::Floor(0));
        let w = first.left.weights();
        assert_eq!(w.len(), 1);
        assert_eq!(w[0].0, 0);
        assert!((w[0].1 - 3.0 / 3.5).abs() < 1e-12);
        // The left's first floor (3.5 m) on the right column between 3 m and 6 m: s = 1/6.
        let second = l[1];
        assert_eq!(second.left, Attachment::Floor(0));
        let w = second.right.weights();
        assert!((w[0].1 - 5.0 / 6.0).abs() < 1e-12 && (w[1].1 - 1.0 / 6.0).abs() < 1e-12);
        // The right roof at 12 m is above the left's 10.5 m: no point there.
        assert!(l.iter().all(|x| x.elevation_m <= 10.5 + 1e-9));
    }

    #[test]
    fn one_storey_each_of_equal_height_is_the_roofs() {
        let l = levels(&[4.0], &[4.0]);
        assert_eq!(l.len(), 1);
        assert_eq!(l[0].kind, LevelKind::FloorFloor);
    }
}
