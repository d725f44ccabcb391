//! Plot series helpers.

/// At most about 20 000 points per line (min and max per bucket), so that drawing a plot costs the
/// same whatever the record's length.
pub fn decimate(time: &[f64], y: &[f64], scale: f64) -> Vec<[f64; 2]> {
    decimate_to(time, y, scale, 10_000)
}

/// At most `2 buckets + 2` points of a line: all of them where there are no more than
/// `2 buckets`, else its first and last and the smallest and the largest value of each of
/// `buckets` runs of samples, in time order (every peak and trough of the line is kept; only
/// what lies between them in a bucket is left out).
pub fn decimate_to(time: &[f64], y: &[f64], scale: f64, buckets: usize) -> Vec<[f64; 2]> {
    let n = time.len().min(y.len());
    let buckets = buckets.max(1);
    if n <= 2 * buckets {
        return (0..n).map(|i| [time[i], y[i] * scale]).collect();
    }
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
        // The line's first and last samples are always drawn, so that it spans the run.
        if b == 0 && a != 0 {
            out.push([time[0], y[0] * scale]);
        }
        out.push([time[a], y[a] * scale]);
        if c != a {
            out.push([time[c], y[c] * scale]);
        }
        if b + 1 == buckets && c != n - 1 {
            out.push([time[n - 1], y[n - 1] * scale]);
        }
    }
    out
}

/// The points a plot `width_px` wide draws of a line: two buckets of [`decimate_to`] a pixel
/// over the part of the run it showed last frame (`shown`, its x range; the whole run if none),
/// at least 1 000 and at most 10 000 over the run. Zoomed out, a long run's line is drawn
/// from a few thousand points instead of every sample (a frame's tessellation and the
/// rasterizer's triangles), and zooming in brings the samples back. What a plot exports stays
/// [`decimate`]'s: the samples.
pub fn for_plot(
    time: &[f64],
    y: &[f64],
    scale: f64,
    shown: Option<(f64, f64)>,
    width_px: f32,
) -> Vec<[f64; 2]> {
    let span = match (time.first(), time.last()) {
        (Some(a), Some(b)) if b > a => b - a,
        _ => return decimate(time, y, scale),
    };
    let visible = shown
        .map(|(a, b)| b - a)
        .filter(|v| v.is_finite() && *v > 0.0)
        .map_or(span, |v| v.min(span));
    let buckets = (2.0 * f64::from(width_px.max(1.0)) * span / visible).ceil();
    decimate_to(time, y, scale, buckets.clamp(1_000.0, 10_000.0) as usize)
}

/// A plot's line as it keeps it: its name and its points.
pub type NamedLine = (String, Vec<[f64; 2]>);

/// Named lines of a plot (name, times, values), scaled by `scale`: what the plot keeps to export
/// ([`decimate`]: the samples) and what it draws this frame ([`for_plot`] over the x range it
/// showed last, `shown`, `width_px` wide).
pub fn plot_lines(
    lines: Vec<(String, &[f64], &[f64])>,
    scale: f64,
    shown: Option<(f64, f64)>,
    width_px: f32,
) -> (Vec<NamedLine>, Vec<Vec<[f64; 2]>>) {
    let drawn = lines
        .iter()
        .map(|(_, time, y)| for_plot(time, y, scale, shown, width_px))
        .collect();
    let kept = lines
        .into_iter()
        .map(|(name, time, y)| (name, decimate(time, y, scale)))
        .collect();
    (kept, drawn)
}

/// At most about 20 000 points of a line given as pairs (see [`decimate`]).
pub fn thin(points: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
    if points.len() <= 20_000 {
        return points;
    }
    let (x, y): (Vec<f64>, Vec<f64>) = points.iter().map(|p| (p[0], p[1])).unzip();
    decimate(&x, &y, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 19 000-sample line (a bridge run's history) with one sharp spike and one dip.
    fn spiky() -> (Vec<f64>, Vec<f64>) {
        let n = 19_000;
        let t: Vec<f64> = (0..n).map(|i| i as f64 * 4.3e-4).collect();
        let mut y: Vec<f64> = t.iter().map(|&t| (7.0 * t).sin()).collect();
        y[12_345] = 5.0;
        y[777] = -4.0;
        (t, y)
    }

    #[test]
    fn a_plot_zoomed_out_draws_a_few_points_a_pixel_and_keeps_every_extreme() {
        let (t, y) = spiky();
        let drawn = for_plot(&t, &y, 2.0, None, 700.0);
        assert!(drawn.len() <= 2 * 1_400 + 2, "{} points", drawn.len());
        assert_eq!(
            (drawn[0][0], drawn[drawn.len() - 1][0]),
            (t[0], t[t.len() - 1])
        );
        let top = drawn.iter().map(|p| p[1]).fold(f64::MIN, f64::max);
        let bottom = drawn.iter().map(|p| p[1]).fold(f64::MAX, f64::min);
        assert_eq!((top, bottom), (10.0, -8.0));
        assert!(drawn.windows(2).all(|w| w[0][0] < w[1][0]), "in time order");
        // Each point drawn is a sample of the line, scaled.
        for p in &drawn {
            let i = (p[0] / 4.3e-4).round() as usize;
            assert_eq!(p, &[t[i], 2.0 * y[i]]);
        }
    }

    #[test]
    fn zooming_in_brings_the_samples_back() {
        let (t, y) = spiky();
        let span = t[t.len() - 1];
        let out = for_plot(&t, &y, 1.0, None, 700.0).len();
        let tenfold = for_plot(&t, &y, 1.0, Some((0.0, span / 10.0)), 700.0).len();
        assert!(
            tenfold > 5 * out,
            "{out} zoomed out, {tenfold} zoomed in tenfold"
        );
        let deep = for_plot(&t, &y, 1.0, Some((1.0, 1.01)), 700.0);
        assert_eq!(
            deep.len(),
            t.len(),
            "every sample where a pixel holds fewer than two"
        );
    }
}
