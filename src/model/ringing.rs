//! A Sears bar's wave history once the force on it has stopped, in closed form: what the
//! buildings' slabs and the bridges' girders read between contacts instead of stepping.
//!
//! A bar loaded at one end keeps Q(t) = A(t) + r Q(t - T) on the grid (A the force's integral
//! against the material damping's kernel, r = exp(-T/t_d), T the round trip). Once the force is
//! zero A decays as exp(-t/t_d), B (its integral) as (B_q + A_q (t - t_q)) exp(-(t - t_q)/t_d),
//! and unrolling the recursion J round trips (r^j A(t - j T) = A(t)) gives
//!   Q(t) = J A(t) + r^J Q(t - J T),
//! with t - J T inside the last round trip before the force stopped: a window of Q's last
//! samples, frozen then, gives Q at any later instant.

use crate::model::ring::Ring;

/// The constants of the recursion on a grid of step h.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Ringing {
    pub h: f64,
    /// exp(-h / t_d) and r = exp(-T / t_d).
    pub step_decay: f64,
    pub round_decay: f64,
    /// T / h: the round trip in grid steps.
    pub round_steps: f64,
    /// 1 / t_d [1/s].
    pub decay_per_s: f64,
}

/// The history frozen when its force stopped: Q at grid indices n - len + 1 ..= n, and A and B
/// at n.
#[derive(Debug, Clone, Default)]
pub(crate) struct Frozen {
    pub n: usize,
    pub a: f64,
    pub b: f64,
    pub q: Vec<f64>,
}

impl Frozen {
    /// Whether nothing was ever pushed into it (a bar never struck rings with nothing).
    pub fn silent(&self) -> bool {
        self.a == 0.0 && self.b == 0.0 && self.q.iter().all(|&x| x == 0.0)
    }

    /// Q at indices n + 1 - len ..= n + `extra`, in one buffer: the window, then `extra` zeros
    /// for the steps a tabulation takes (before index 0 the history is zero).
    pub fn buffer(&self, extra: usize) -> Vec<f64> {
        let mut buf = vec![0.0; self.q.len() + extra];
        self.fill(&mut buf[..self.q.len()]);
        buf
    }

    /// The window into `out` (as long as it): Q at indices n + 1 - len ..= n, zero before 0.
    pub fn fill(&self, out: &mut [f64]) {
        let base = self.n as isize + 1 - self.q.len() as isize;
        for (k, (b, &v)) in out.iter_mut().zip(&self.q).enumerate() {
            *b = if base + k as isize >= 0 { v } else { 0.0 };
        }
    }
}

/// A look-up's four weights on four samples `back` before index `at` of a buffer (a
/// [`Look::stored_four`](crate::model::ring::Look::stored_four)).
#[inline]
pub(crate) fn read_four(buf: &[f64], at: usize, (back, w): (usize, [f64; 4])) -> f64 {
    stencil(&w, &buf[at - back..at - back + 4])
}

/// Four weights on the first four of `s`, summed in pairs: the order every stepped and
/// frozen reading of a history takes, so that they agree to the bit.
#[inline(always)]
pub(crate) fn stencil(w: &[f64; 4], s: &[f64]) -> f64 {
    (w[0] * s[0] + w[1] * s[1]) + (w[2] * s[2] + w[3] * s[3])
}

/// Cubic Lagrange interpolation in a window whose last sample has index `last`, at the fractional
/// index `s` (at most `last`); zero before index 0.
pub(crate) fn window_at(values: &[f64], last: usize, s: f64) -> f64 {
    let len = values.len() as isize;
    let first = last as isize - len + 1;
    // Four points j - 1 ..= j + 2 around s, moved back so that none lies past the window's end.
    let j = (floor_of(s) as isize).min(last as isize - 2);
    let x = s - j as f64;
    let at = |i: isize| {
        if i < 0 || i < first {
            0.0
        } else {
            values[(i - first) as usize]
        }
    };
    let (a, b, c, d) = (at(j - 1), at(j), at(j + 1), at(j + 2));
    let [wa, wb, wc, wd] = lagrange4(x);
    wa * a + wb * b + wc * c + wd * d
}

/// The weights of the cubic through samples -1, 0, 1, 2 at the fraction x in [0, 1).
#[inline]
fn lagrange4(x: f64) -> [f64; 4] {
    [
        -x * (x - 1.0) * (x - 2.0) / 6.0,
        (x + 1.0) * (x - 1.0) * (x - 2.0) / 2.0,
        -(x + 1.0) * x * (x - 2.0) / 2.0,
        (x + 1.0) * x * (x - 1.0) / 6.0,
    ]
}

/// What the ringing between grid points, and at the phases of later round trips that fall
/// between grid points, can exceed its largest value on the grid by: the cubic look-ups'
/// overshoot, with room to spare (a margin found by trying, not proven: tests/girder_ringing.rs
/// checks it on coarse grids and heavy damping).
pub(crate) const WINDOW_OVERSHOOT: f64 = 1.5;

impl Ringing {
    /// The grid steps a tabulation of the ringing takes per round trip: ceil(T / h) + 1, at
    /// least a round trip and a step.
    pub fn tabulated_steps(&self) -> usize {
        self.round_steps.ceil() as usize + 1
    }

    /// A bound on |ringing| at the grid index `offset` steps after the history was frozen, from
    /// its largest |value| on the grid over offsets 1 ..= s (`early`) and s + 1 ..= 2 s (`late`),
    /// s = [`Ringing::tabulated_steps`]: within those the larger of the two; later, the late one
    /// attenuated by the whole round trips k that bring the offset back into the late window
    /// (the ringing repeats attenuated once the force has stopped, w(t + T) = r w(t)), with
    /// o - k T in [s + 1, s + 1 + T), inside it since T <= s - 1.
    pub fn envelope_at(&self, [early, late]: [f64; 2], offset: usize) -> f64 {
        let s = self.tabulated_steps();
        let bound = if offset <= 2 * s {
            early.max(late)
        } else {
            let k = ((offset - s - 1) as f64 / self.round_steps).floor();
            late * self.round_decay.powi(k as i32)
        };
        WINDOW_OVERSHOOT * bound
    }

    /// exp(-steps h / t_d).
    pub fn decay(&self, steps: f64) -> f64 {
        if self.decay_per_s == 0.0 {
            1.0
        } else {
            (-steps * self.h * self.decay_per_s).exp()
        }
    }

    /// A(s) after the force stopped: its value then, decayed.
    pub fn a_at(&self, w: &Frozen, s: f64) -> f64 {
        w.a * self.decay(s - w.n as f64)
    }

    /// B(s) after the force stopped (exact for the grid's recursion at grid points).
    pub fn b_at(&self, w: &Frozen, s: f64) -> f64 {
        let steps = s - w.n as f64;
        self.decay(steps) * (w.b + steps * self.h * w.a)
    }

    /// Q at the fractional grid index `s`, given A(s): J A(s) + r^J Q(s - J T), with s - J T
    /// inside the window.
    pub fn fold_q(&self, w: &Frozen, s: f64, a: f64) -> f64 {
        let past = s - w.n as f64;
        if past <= 0.0 {
            return window_at(&w.q, w.n, s);
        }
        let j = (past / self.round_steps).ceil();
        j * a + self.round_decay.powi(j as i32) * window_at(&w.q, w.n, s - j * self.round_steps)
    }

    /// Pushes Q at grid indices `from..=to` from the closed form into `ring`. Along a run of
    /// indices folded back the same number of round trips J the look-up's fraction is the
    /// same, so its weights are too, and A(i) decays by one factor per step.
    pub fn rebuild(&self, w: &Frozen, ring: &mut Ring, from: usize, to: usize) {
        let (r_steps, last) = (self.round_steps, w.n as isize);
        let first = last - w.q.len() as isize + 1;
        let mut a = self.a_at(w, from as f64);
        let mut i = from;
        while i <= to {
            if i <= w.n {
                let k = i as isize - first;
                ring.push(if k >= 0 { w.q[k as usize] } else { 0.0 });
                i += 1;
                a *= self.step_decay;
                continue;
            }
            let j = ((i - w.n) as f64 / r_steps).ceil();
            let shift = j * r_steps;
            let run_end = ((w.n as f64 + shift).floor() as usize).min(to);
            let weight = self.round_decay.powi(j as i32);
            let s0 = i as f64 - shift;
            let wt = lagrange4(s0 - s0.floor());
            let at = |k: isize| {
                if k < first.max(0) {
                    0.0
                } else {
                    w.q[(k - first) as usize]
                }
            };
            let generic = |i: usize| {
                let s = i as f64 - shift;
                let base = floor_of(s) as isize;
                if base <= last - 2 {
                    stencil(&wt, &[at(base - 1), at(base), at(base + 1), at(base + 2)])
                } else {
                    window_at(&w.q, w.n, s)
                }
            };
            // Where the fraction is clear of a whole number, the stencil's base moves on by one
            // a step (the rounding of i - shift cannot move its floor), and inside the window it
            // reads four consecutive samples: the same sums without the per-sample tests.
            let fraction = s0 - floor_of(s0);
            let steady = fraction > 1e-6 && fraction < 1.0 - 1e-6;
            while i <= run_end {
                let base = floor_of(i as f64 - shift) as isize;
                if steady && base > first.max(0) && base <= last - 2 {
                    // Up to the run's end or the window's last stencil, whichever comes first.
                    let count = (run_end - i + 1).min((last - 2 - base) as usize + 1);
                    let start = (base - 1 - first) as usize;
                    let q = &w.q[start..start + count + 3];
                    for k in 0..count {
                        ring.push(j * a + weight * stencil(&wt, &q[k..k + 4]));
                        a *= self.step_decay;
                    }
                    i += count;
                    continue;
                }
                ring.push(j * a + weight * generic(i));
                i += 1;
                a *= self.step_decay;
            }
        }
    }
}

/// The floor of x (finite, within i64's range; the sign of a zero aside) by truncation: the
/// baseline x86-64 has no rounding instruction, and `f64::floor` is a call to libm there, many
/// times a truncation's cost in the look-ups' inner loop.
#[inline]
fn floor_of(x: f64) -> f64 {
    let t = x as i64 as f64;
    if t > x { t - 1.0 } else { t }
}

/// The ceiling of x the same way ([`floor_of`]).
#[inline]
fn ceil_of(x: f64) -> f64 {
    let t = x as i64 as f64;
    if t < x { t + 1.0 } else { t }
}

/// A look-up of a frozen history at the grid indices m - lag for integer m, folded back `j`
/// round trips: where m - lag - j T falls between grid points depends on the lag and j alone, so
/// its stencil does too (made once for a run of grid indices with the same j).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Fold {
    /// The round trips folded back, and r^j.
    pub j: f64,
    weight: f64,
    /// floor(-lag - j T) in grid steps: the stencil's base is m plus this.
    offset: isize,
    /// The stencil's fraction, and its cubic Lagrange weights on base - 1 ..= base + 2.
    x: f64,
    w: [f64; 4],
}

impl Ringing {
    /// How many round trips back grid index m - `lag` lies in the window frozen at `n` (0
    /// inside it).
    #[inline]
    pub fn trips_back(&self, n: usize, m: usize, lag: f64) -> f64 {
        // Signed 64-bit conversions: a single instruction each, where unsigned ones are not.
        let past = (m as i64 - n as i64) as f64 - lag;
        if past <= 0.0 {
            return 0.0;
        }
        ceil_of(past / self.round_steps)
    }

    /// The look-up at m - `lag` folded back `j` round trips.
    pub fn fold(&self, lag: f64, j: f64) -> Fold {
        let at = -lag - j * self.round_steps;
        let base = at.floor();
        let x = at - base;
        Fold {
            j,
            weight: self.round_decay.powi(j as i32),
            offset: base as isize,
            x,
            w: lagrange4(x),
        }
    }
}

impl Fold {
    /// Where, in a window of `len` samples ending at grid index `last`, the stencil for grid
    /// index m starts (its four samples inside the window, clear of its last two), or `None`
    /// where the generic reading is needed (the window's start, its last two samples).
    #[inline]
    pub fn start(&self, last: usize, len: usize, m: usize) -> Option<usize> {
        let base = m as isize + self.offset;
        let (last, first) = (last as isize, last as isize - len as isize + 1);
        (base > first.max(0) && base <= last - 2).then(|| (base - 1 - first) as usize)
    }

    /// Q at grid index m - lag from the frozen window `w`, given A there: j A + r^J Q(m - lag -
    /// j T), as [`Ringing::fold_q`] reads it; `start` from [`Fold::start`].
    #[inline]
    pub fn read_at(&self, w: &Frozen, start: Option<usize>, m: usize, a: f64) -> f64 {
        let inside = match start {
            Some(k) => {
                let s = &w.q[k..k + 4];
                self.w[0] * s[0] + self.w[1] * s[1] + self.w[2] * s[2] + self.w[3] * s[3]
            }
            // Near the window's ends (its start, or its last two samples) the generic reading.
            None => window_at(&w.q, w.n, (m as isize + self.offset) as f64 + self.x),
        };
        self.j * a + self.weight * inside
    }
}

#[cfg(test)]
mod tests {
    use super::{ceil_of, floor_of};

    #[test]
    fn the_floor_and_ceiling_by_truncation_are_the_floor_and_ceiling() {
        // Integers, halves and their neighbours on both sides of zero, and a spread of magnitudes.
        let mut xs = vec![0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 1e15 + 0.5, -1e15 - 0.5];
        for k in -1000..=1000 {
            let x = k as f64 * 0.25;
            xs.extend([x, x.next_up(), x.next_down()]);
        }
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        for _ in 0..10_000 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let unit = (seed >> 11) as f64 / (1u64 << 53) as f64;
            xs.push((unit - 0.5) * 10f64.powi((seed % 17) as i32));
        }
        for x in xs {
            assert_eq!(floor_of(x), x.floor(), "{x:e}");
            assert_eq!(ceil_of(x), x.ceil(), "{x:e}");
        }
    }
}
