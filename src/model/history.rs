//! The delayed look-up engine shared by every d'Alembert model.
//!
//! A force F(t) on the end of a free-free bar of round-trip time T = 2L/c reaches a plane at x
//! as the history sum H(t) = F(t) + H(t - T) taken at t - x/c and t - (2L - x)/c. Its integral
//! Psi(t) = Phi(t) + Psi(t - T) (Phi = impulse so far) gives the plane's displacement. Both
//! recursions need one delayed look-up per step, so the work per step stays constant however
//! many reflections have happened.
//!
//! Histories are sampled on a uniform grid t_n = n dt with zeros before t = 0. A [`Tap`] reads a
//! history at a fixed lag behind the newest sample with 4-point (cubic) Lagrange interpolation;
//! because the lag is fixed, its stencil offset and weights are computed once. A lag shorter than
//! one step puts weight on the newest (still unknown) sample: [`Tap::newest_weight`] says how
//! much, so a solver can keep that part implicit.

/// A history sampled at t = n dt from n = 0, read as zero before t = 0.
#[derive(Debug, Clone, Default)]
pub struct Series {
    data: Vec<f64>,
}

impl Series {
    /// An empty history with room for `capacity` samples.
    pub fn with_capacity(capacity: usize) -> Self {
        Series {
            data: Vec::with_capacity(capacity),
        }
    }

    /// Appends the next sample.
    #[inline]
    pub fn push(&mut self, v: f64) {
        self.data.push(v);
    }

    /// Appends the next sample into room already reserved.
    ///
    /// # Safety
    /// `self.len() < self.capacity()`.
    #[inline(always)]
    pub unsafe fn push_reserved(&mut self, v: f64) {
        // SAFETY: the caller promises room for one more.
        unsafe { push_reserved(&mut self.data, v) }
    }

    /// Appends samples.
    pub fn extend(&mut self, values: impl Iterator<Item = f64>) {
        self.data.extend(values);
    }

    /// Appends `count` zero samples.
    pub fn push_zeros(&mut self, count: usize) {
        self.data.resize(self.data.len() + count, 0.0);
    }

    /// How many samples it has room for without reallocating.
    #[inline]
    pub fn capacity(&self) -> usize {
        self.data.capacity()
    }

    /// How many samples.
    #[inline]
    pub fn len(&self) -> usize {
        self.data.len()
    }

    /// Whether there are none.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.data.is_empty()
    }

    /// Sample n (n = 0 is t = 0).
    #[inline]
    pub fn get(&self, n: usize) -> f64 {
        self.data[n]
    }

    /// The newest sample (0 when empty).
    #[inline]
    pub fn last(&self) -> f64 {
        *self.data.last().unwrap_or(&0.0)
    }

    /// Sample k counted from the end (0 = newest); zero before the start.
    #[inline]
    pub fn back(&self, k: usize) -> f64 {
        let n = self.data.len();
        if k < n { self.data[n - 1 - k] } else { 0.0 }
    }

    /// Every sample, oldest first.
    pub fn samples(&self) -> &[f64] {
        &self.data
    }

    /// The samples, given up.
    pub fn into_samples(self) -> Vec<f64> {
        self.data
    }

    /// Forgets every sample, keeping the room.
    pub fn clear(&mut self) {
        self.data.clear();
    }

    /// Room for `additional` more samples.
    pub fn reserve(&mut self, additional: usize) {
        self.data.reserve(additional);
    }

    /// Drops samples after the first `len` (to undo a trial step).
    pub fn truncate(&mut self, len: usize) {
        self.data.truncate(len);
    }
}

/// Appends `x` to `v` without the capacity check of `Vec::push`, for hot loops that reserve
/// room ahead.
///
/// # Safety
/// `v.len() < v.capacity()`.
#[inline(always)]
pub unsafe fn push_reserved(v: &mut Vec<f64>, x: f64) {
    let n = v.len();
    debug_assert!(n < v.capacity());
    // SAFETY: slot n lies within the allocation (n < capacity), and is initialised before the
    // length covers it.
    unsafe {
        v.as_mut_ptr().add(n).write(x);
        v.set_len(n + 1);
    }
}

/// A fixed-lag cubic look-up into a [`Series`].
#[derive(Debug, Clone, Copy)]
pub struct Tap {
    /// Stencil start, in samples relative to the newest sample (<= -3).
    first: isize,
    weights: [f64; 4],
    /// The stored part of the stencil as four samples from `stored_at` (<= -4) before the
    /// newest: the same as `first` and `weights`, or, for a stencil of three stored samples,
    /// one more sample in front with weight zero. Read by [`Tap::known_steady`].
    stored_at: isize,
    stored_weights: [f64; 4],
}

/// The longest lag a tap resolves, in steps; see [`Tap::new`].
const LAG_STEPS_MAX: f64 = 1e15;

impl Tap {
    /// A cubic tap: fourth-order accurate on smooth histories.
    pub fn new(lag_s: f64, dt_s: f64) -> Self {
        Self::with_order(lag_s, dt_s, true)
    }

    /// A linear tap: second-order but monotone, for histories with kinks at the grid scale (a
    /// contact stiffer than the step resolves makes the force jump within a step, and a cubic
    /// would overshoot there).
    pub fn linear(lag_s: f64, dt_s: f64) -> Self {
        Self::with_order(lag_s, dt_s, false)
    }

    fn with_order(lag_s: f64, dt_s: f64, cubic: bool) -> Self {
        debug_assert!(lag_s >= 0.0 && dt_s > 0.0);
        // A lag beyond 1e15 steps never reaches back past t = 0 within any run the step budget
        // allows: clamped, its index arithmetic stays far from overflow (a 1e300 m bar or a
        // 1e-15 s step would otherwise give an index of -2^63).
        let p = (-lag_s / dt_s).max(-LAG_STEPS_MAX);
        // Snap lags that are a whole number of steps up to rounding, so that the natural cases
        // (lag 0, lag = T on a grid that divides T) read samples exactly.
        let p = if (p - p.round()).abs() < 1e-9 {
            p.round()
        } else {
            p
        };
        let j = p.floor() as isize;
        let top = if lag_s >= dt_s || p <= -1.0 {
            (j + 2).min(-1)
        } else {
            0
        };
        let first = top - 3;
        let mut weights = [0.0; 4];
        if !cubic {
            // Linear between the two nodes that bracket p (the stencil's last two when the lag is
            // under a step or lands at its end).
            let hi = (j + 1).min(top);
            let lo_node = hi - 1;
            let x = (p - lo_node as f64).clamp(0.0, 1.0);
            weights[(lo_node - first) as usize] = 1.0 - x;
            weights[(hi - first) as usize] = x;
            return Tap::of(first, weights);
        }
        for (k, w) in weights.iter_mut().enumerate() {
            let xk = (first + k as isize) as f64;
            let mut v = 1.0;
            for l in 0..4 {
                if l != k {
                    let xl = (first + l as isize) as f64;
                    v *= (p - xl) / (xk - xl);
                }
            }
            *w = v;
        }
        Tap::of(first, weights)
    }

    fn of(first: isize, weights: [f64; 4]) -> Self {
        let (stored_at, stored_weights) = if first == -3 {
            (-4, [0.0, weights[0], weights[1], weights[2]])
        } else {
            (first, weights)
        };
        Tap {
            first,
            weights,
            stored_at,
            stored_weights,
        }
    }

    /// The length a series must have for [`Tap::known_steady`] to read it.
    pub fn steady_from(&self) -> usize {
        (-self.stored_at) as usize
    }

    /// How many samples back the stencil reaches.
    pub fn reach(&self) -> usize {
        (-self.first) as usize
    }

    /// The stencil's start relative to the sample about to be pushed, the number of its stored
    /// samples (3 when the newest one is part of it, else 4) and its weights: what a reader of
    /// another container (a ring buffer) needs to give the same look-up.
    pub fn stencil(&self) -> (isize, usize, [f64; 4]) {
        let stored = if self.first == -3 { 3 } else { 4 };
        (self.first, stored, self.weights)
    }

    /// Weight on the newest sample (nonzero only for lags shorter than a step).
    #[inline]
    pub fn newest_weight(&self) -> f64 {
        if self.first == -3 {
            self.weights[3]
        } else {
            0.0
        }
    }

    /// Whether the look-up reads the newest sample alone (a lag of zero): its known part is
    /// then zero, and a solver can skip it, keeping the stored samples off the step's chain.
    pub fn newest_only(&self) -> bool {
        self.first == -3 && self.weights[..3].iter().all(|&w| w == 0.0)
    }

    /// The look-up's value from samples already stored, for a newest sample that is about to be
    /// pushed (index `series.len()`): everything except `newest_weight() * newest`.
    #[inline(always)]
    pub fn known_before_push(&self, series: &Series) -> f64 {
        let raw = series.samples();
        // The newest sample would sit at raw.len(); the stencil starts `first` before it.
        let base = raw.len() as isize + self.first;
        let w = &self.weights;
        if base >= 0 {
            let b = base as usize;
            // A stencil of four stored samples starts at least four before the newest
            // (first <= -4), one of three exactly three before it: inside `raw` either way.
            if self.first == -3 {
                debug_assert!(b + 3 <= raw.len());
                // SAFETY: b + 3 = raw.len() (first = -3).
                let s = unsafe { raw.get_unchecked(b..b + 3) };
                w[0] * s[0] + w[1] * s[1] + w[2] * s[2]
            } else {
                debug_assert!(b + 4 <= raw.len());
                // SAFETY: b + 4 = raw.len() + first + 4 <= raw.len() (first <= -4).
                let s = unsafe { raw.get_unchecked(b..b + 4) };
                (w[0] * s[0] + w[1] * s[1]) + (w[2] * s[2] + w[3] * s[3])
            }
        } else if base + 4 <= 0 {
            // The whole stencil lies before t = 0, where the history is zero.
            0.0
        } else {
            self.straddling(raw, base)
        }
    }

    /// [`Tap::known_before_push`] once the series is long enough: four stored samples read
    /// without a branch (a stencil of three adds one with weight zero, so the sum may differ
    /// from [`Tap::known_before_push`]'s in the last bit).
    ///
    /// # Safety
    /// `series.len() >= self.steady_from()`.
    #[inline(always)]
    pub unsafe fn known_steady(&self, series: &Series) -> f64 {
        let raw = series.samples();
        debug_assert!(raw.len() >= self.steady_from());
        let b = (raw.len() as isize + self.stored_at) as usize;
        let w = &self.stored_weights;
        // SAFETY: b + 4 = raw.len() + stored_at + 4 <= raw.len() (stored_at <= -4), and b >= 0
        // by the caller's promise.
        let s = unsafe { raw.get_unchecked(b..b + 4) };
        (w[0] * s[0] + w[1] * s[1]) + (w[2] * s[2] + w[3] * s[3])
    }

    /// A few early steps: the stencil straddles t = 0.
    #[cold]
    fn straddling(&self, raw: &[f64], base: isize) -> f64 {
        let stored = if self.first == -3 { 3 } else { 4 };
        (((-base).max(0) as usize)..stored)
            .map(|k| self.weights[k] * raw[(base + k as isize) as usize])
            .sum()
    }
}

/// Cubic Lagrange interpolation of a uniformly sampled signal at time `t_s`, with zeros before
/// the first sample and the last sample held after the end.
pub fn sample_at(values: &[f64], dt_s: f64, t_s: f64) -> f64 {
    if values.is_empty() || t_s < 0.0 {
        return 0.0;
    }
    sample_at_unit(values, t_s / dt_s)
}

/// [`sample_at`] at the fractional sample index `p` (the time over the step).
#[inline]
pub fn sample_at_unit(values: &[f64], p: f64) -> f64 {
    if values.is_empty() || p < 0.0 {
        return 0.0;
    }
    let n = values.len();
    if p >= (n - 1) as f64 {
        return values[n - 1];
    }
    // p >= 0 here, where truncation is the floor (without a call to libm's).
    let j = p as isize;
    let x = p - j as f64;
    // Inside the series the four samples are read as one slice (a bounds check, not four);
    // the weights and their sum are the same below.
    let (a, b, c, d) = if j >= 1 && (j as usize) + 2 < n {
        let s = &values[j as usize - 1..j as usize + 3];
        (s[0], s[1], s[2], s[3])
    } else {
        sample_edges(values, j)
    };
    // Cubic through (-1, a), (0, b), (1, c), (2, d) evaluated at x.
    let wa = -x * (x - 1.0) * (x - 2.0) / 6.0;
    let wb = (x + 1.0) * (x - 1.0) * (x - 2.0) / 2.0;
    let wc = -(x + 1.0) * x * (x - 2.0) / 2.0;
    let wd = (x + 1.0) * x * (x - 1.0) / 6.0;
    wa * a + wb * b + wc * c + wd * d
}

/// The four samples around index j near the series' ends: zero before it, the last after it.
fn sample_edges(values: &[f64], j: isize) -> (f64, f64, f64, f64) {
    let n = values.len();
    let at = |i: isize| {
        if i < 0 {
            0.0
        } else {
            values[(i as usize).min(n - 1)]
        }
    };
    (at(j - 1), at(j), at(j + 1), at(j + 2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_tap_reproduces_lines_exactly_at_any_lag() {
        let dt = 0.1;
        let f = |t: f64| 1.0 + 2.0 * t;
        for &lag in &[0.0, 0.03, 0.1, 0.1234, 0.25, 1.0, 2.37] {
            let tap = Tap::linear(lag, dt);
            let mut s = Series::with_capacity(100);
            for n in 0..60 {
                s.push(f(n as f64 * dt - 3.0));
            }
            let got = tap.known_before_push(&s) + tap.newest_weight() * f(60.0 * dt - 3.0);
            assert!((got - f(60.0 * dt - 3.0 - lag)).abs() < 1e-12, "lag {lag}");
            assert!(
                tap.weights.iter().all(|&w| (0.0..=1.0).contains(&w)),
                "monotone weights"
            );
        }
    }

    #[test]
    fn tap_reproduces_cubics_exactly_at_any_lag() {
        let dt = 0.1;
        let f = |t: f64| 1.0 + 2.0 * t - 0.5 * t * t + 0.25 * t * t * t;
        for &lag in &[0.0, 0.03, 0.1, 0.1234, 0.25, 1.0, 2.37] {
            let tap = Tap::new(lag, dt);
            let mut s = Series::with_capacity(100);
            for n in 0..60 {
                s.push(f(n as f64 * dt - 3.0));
            }
            let newest = f(60.0 * dt - 3.0);
            let got = tap.known_before_push(&s) + tap.newest_weight() * newest;
            let want = f(60.0 * dt - 3.0 - lag);
            assert!((got - want).abs() < 1e-10, "lag {lag}: {got} vs {want}");
            assert_eq!(tap.newest_weight() != 0.0, lag < dt, "lag {lag}");
        }
    }

    #[test]
    fn a_lag_of_astronomically_many_steps_reads_the_zero_history_before_t0() {
        // 1e300 s on a 1e-15 s step: 1e315 steps back, where -lag/dt as an index would overflow.
        for (lag, dt) in [(1e300, 1e-15), (1e20, 1e-6), (f64::MAX, 1e-300)] {
            for tap in [Tap::new(lag, dt), Tap::linear(lag, dt)] {
                let mut s = Series::with_capacity(8);
                for v in [1.0, 2.0, 3.0] {
                    s.push(v);
                }
                assert_eq!(tap.known_before_push(&s), 0.0, "lag {lag:e} on {dt:e}");
                assert_eq!(tap.newest_weight(), 0.0);
            }
        }
    }
}
