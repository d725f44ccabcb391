//! Plot series helpers.

/// At most about 20 000 points per line (min and max per bucket), so that drawing a plot costs the
/// same whatever the record's length.
pub fn decimate(time: &[f64], y: &[f64], scale: f64) -> Vec<[f64; 2]> {
    let n = time.len().min(y.len());
    if n <= 20_000 {
        return (0..n).map(|i| [time[i], y[i] * scale]).collect();
    }
    let buckets = 10_000;
    let mut out = Vec::with_capacity(2 * buckets);
    for b in 0..buckets {
        let (lo, hi) = (
            b * n / buckets,
            ((b + 1) * n / buckets).max(b * n / buckets + 1),
        );
        let (mut imin, mut imax) = (lo, lo);
        for i in lo..hi {
            if y[i] < y[imin] {
                imin = i;
            }
            if y[i] > y[imax] {
                imax = i;
            }
        }
        let (a, c) = if imin < imax {
            (imin, imax)
        } else {
            (imax, imin)
        };
        out.push([time[a], y[a] * scale]);
        if c != a {
            out.push([time[c], y[c] * scale]);
        }
    }
    out
}

/// At most about 20 000 points of a line given as pairs (see [`decimate`]).
pub fn thin(points: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
    if points.len() <= 20_000 {
        return points;
    }
    let (x, y): (Vec<f64>, Vec<f64>) = points.iter().map(|p| (p[0], p[1])).unzip();
    decimate(&x, &y, 1.0)
}
