//! Recording: the samples of the histories and the peaks between them.

use super::*;

/// Peaks of each floor and each storey's drift ratio per side, and each point's per side.
pub(super) type PeakSummary = ([Vec<f64>; 2], [Vec<f64>; 2], Vec<[f64; 2]>);

/// The largest |value| of signals known with their rates at a sequence of instants: between
/// two instants a signal is the cubic through both values and rates, and its extremum there is
/// found, so a peak is not missed by the spacing of the instants (the error is that of the cubic,
/// (w h)^4 / 384 of the amplitude, against (w h)^2 / 8 for sampling).
#[derive(Default)]
pub(super) struct Peaks {
    last_t: f64,
    last: Vec<(f64, f64)>,
    peak: Vec<f64>,
    started: bool,
}

impl Peaks {
    pub(super) fn update(&mut self, t: f64, now: &[(f64, f64)]) {
        if !self.started {
            self.started = true;
            self.last = now.to_vec();
            self.peak = now.iter().map(|(u, _)| u.abs()).collect();
            self.last_t = t;
            return;
        }
        let l = t - self.last_t;
        for (i, &(u, v)) in now.iter().enumerate() {
            let mut p = self.peak[i].max(u.abs());
            let (u0, v0) = self.last[i];
            if l > 0.0 && (v0 > 0.0) != (v > 0.0) {
                let inside = if v0 > 0.0 {
                    hermite_max(u0, v0, u, v, l)
                } else {
                    -hermite_max(-u0, -v0, -u, -v, l)
                };
                if inside.is_finite() {
                    p = p.max(inside.abs());
                }
            }
            self.peak[i] = p;
            self.last[i] = (u, v);
        }
        self.last_t = t;
    }
}

impl Stepper<'_> {
    /// Floor displacements of both sides from modal coordinates.
    pub(super) fn floors(&self, q: [&[f64]; 2]) -> [Vec<f64>; 2] {
        std::array::from_fn(|s| {
            let side = &self.sides[s];
            (0..side.heights.len())
                .map(|f| side.floor(q[s], f))
                .collect()
        })
    }

    /// Every signal whose peak is reported, with its rate, from modal states: each floor, each
    /// storey's drift ratio, each contact point on each side.
    pub(super) fn signals(&self, q: [&[f64]; 2], v: [&[f64]; 2], out: &mut Vec<(f64, f64)>) {
        out.clear();
        for s in 0..2 {
            let side = &self.sides[s];
            for f in 0..side.heights.len() {
                out.push((side.floor(q[s], f), side.floor(v[s], f)));
            }
        }
        for s in 0..2 {
            let side = &self.sides[s];
            let mut below = (0.0, 0.0);
            for f in 0..side.heights.len() {
                let now = (side.floor(q[s], f), side.floor(v[s], f));
                let h = side.heights[f];
                out.push(((now.0 - below.0) / h, (now.1 - below.1) / h));
                below = now;
            }
        }
        for p in &self.points {
            for s in 0..2 {
                out.push((dotv(&p.r[s], q[s]), dotv(&p.r[s], v[s])));
            }
        }
    }

    pub(super) fn track_peaks(&mut self, t: f64, q: [&[f64]; 2], v: [&[f64]; 2]) {
        let mut now = std::mem::take(&mut self.scratch.signals);
        self.signals(q, v, &mut now);
        self.peaks.update(t, &now);
        self.scratch.signals = now;
    }

    /// Peaks of each floor, each storey's drift ratio and each point.
    pub fn peaks(&self) -> PeakSummary {
        let n = [self.sides[0].heights.len(), self.sides[1].heights.len()];
        let p = &self.peaks.peak;
        let floors = [p[..n[0]].to_vec(), p[n[0]..n[0] + n[1]].to_vec()];
        let d0 = n[0] + n[1];
        let drifts = [p[d0..d0 + n[0]].to_vec(), p[d0 + n[0]..2 * d0].to_vec()];
        let points = p[2 * d0..].chunks(2).map(|c| [c[0], c[1]]).collect();
        (floors, drifts, points)
    }

    /// The roof acceleration relative to the ground from the modal state and forcing.
    pub(super) fn roof_accelerations(&self, ground: f64, contact: bool) -> [f64; 2] {
        std::array::from_fn(|s| {
            let side = &self.sides[s];
            let roof = side.heights.len() - 1;
            (0..side.modes())
                .map(|k| {
                    let a = if contact {
                        side.a[k]
                    } else {
                        -side.gamma[k] * ground
                            - 2.0 * side.zeta[k] * side.omega[k] * side.v[k]
                            - side.omega[k].powi(2) * side.q[k]
                    };
                    side.shapes[k][roof] * a
                })
                .sum()
        })
    }

    pub(super) fn record(&mut self) {
        let t = self.time();
        let ground = self.motion.at(t);
        let floors = self.floors([&self.sides[0].q, &self.sides[1].q]);
        let floor_v = self.floors([&self.sides[0].v, &self.sides[1].v]);
        let roof_v = std::array::from_fn(|s| {
            let side = &self.sides[s];
            side.floor(&side.v, side.heights.len() - 1)
        });
        let contact = self.points.iter().any(|p| p.force > 0.0);
        let roof_a = self.roof_accelerations(ground, contact);
        let (q0, q1) = (
            std::mem::take(&mut self.sides[0].q),
            std::mem::take(&mut self.sides[1].q),
        );
        let (v0, v1) = (
            std::mem::take(&mut self.sides[0].v),
            std::mem::take(&mut self.sides[1].v),
        );
        self.track_peaks(t, [&q0, &q1], [&v0, &v1]);
        (self.sides[0].q, self.sides[1].q) = (q0, q1);
        (self.sides[0].v, self.sides[1].v) = (v0, v1);
        self.samples.push(Sample {
            t,
            ground,
            floors,
            floor_v,
            roof_v,
            roof_a,
            forces: self.points.iter().map(|p| p.force).collect(),
        });
    }
}
