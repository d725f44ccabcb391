//! Sums over a tall building's modes in four interleaved partial sums: mode k in lane k mod 4,
//! the lanes joined pairwise. The compiler keeps the lanes in vector registers, so a sum over
//! 100 modes costs about half of one taken mode after mode. Where the processor has AVX, the
//! four lanes are one 256-bit register: the same multiplications and additions in the same lanes
//! (Rust never fuses them), so the same bits on every processor, in about half the instructions
//! again.

/// Modes from which a side's sums are taken in lanes; a few modes' sum is taken in order, the
/// cheapest there.
pub(super) const LANES_FROM: usize = 16;

/// `fn name(args) -> R` that calls `portable(args)` (`#[inline(always)]`, so compiled into each
/// caller), compiled a second time for AVX and taken where the processor has it.
macro_rules! with_avx {
    ($(#[$m:meta])* $vis:vis fn $name:ident($($arg:ident: $ty:ty),* $(,)?) $(-> $ret:ty)? = $portable:ident) => {
        $(#[$m])*
        $vis fn $name($($arg: $ty),*) $(-> $ret)? {
            #[cfg(target_arch = "x86_64")]
            if std::arch::is_x86_feature_detected!("avx") {
                #[target_feature(enable = "avx")]
                fn avx($($arg: $ty),*) $(-> $ret)? {
                    $portable($($arg),*)
                }
                // SAFETY: the processor has just been found to have AVX.
                return unsafe { avx($($arg),*) };
            }
            $portable($($arg),*)
        }
    };
}

/// The sum of c q (q at least as long as c).
#[inline(never)]
pub(super) fn dot(c: &[f64], q: &[f64]) -> f64 {
    dispatch(c, q, None)
}

/// The sum of c (q + d) (q and d at least as long as c): each term's sum q + d first, as a
/// state moved by an increment is.
#[inline(never)]
pub(super) fn dot_moved(c: &[f64], q: &[f64], d: &[f64]) -> f64 {
    dispatch(c, q, Some(d))
}

with_avx! {
    #[inline(always)]
    fn dispatch(c: &[f64], q: &[f64], d: Option<&[f64]>) -> f64 = portable
}

#[inline(always)]
fn portable(c: &[f64], q: &[f64], d: Option<&[f64]>) -> f64 {
    let n = c.len();
    let q = &q[..n];
    let mut u = [0.0f64; 4];
    let full = n - n % 4;
    match d {
        None => {
            for (c, q) in c[..full].chunks_exact(4).zip(q[..full].chunks_exact(4)) {
                for l in 0..4 {
                    u[l] += c[l] * q[l];
                }
            }
            for k in full..n {
                u[k - full] += c[k] * q[k];
            }
        }
        Some(d) => {
            let d = &d[..n];
            let chunks = c[..full]
                .chunks_exact(4)
                .zip(q[..full].chunks_exact(4))
                .zip(d[..full].chunks_exact(4));
            for ((c, q), d) in chunks {
                for l in 0..4 {
                    u[l] += c[l] * (q[l] + d[l]);
                }
            }
            for k in full..n {
                u[k - full] += c[k] * (q[k] + d[k]);
            }
        }
    }
    (u[0] + u[2]) + (u[1] + u[3])
}

/// A side's modes where a contact step starts, and what it moves them by.
pub(super) struct Ends<'a> {
    pub q0: &'a [f64],
    pub v0: &'a [f64],
    pub dq: &'a [f64],
    /// Each mode's omega, zeta and participation.
    pub coefficients: [&'a [f64]; 3],
    pub hh: f64,
    /// The ground's acceleration at both ends, summed.
    pub ground: f64,
}

/// What committing a contact step to a side's modes adds up, each sum in lanes.
pub(super) struct Committed {
    /// The ground's work and the damping's, by Newmark's discrete energy identity [J].
    pub input: f64,
    pub damping: f64,
    /// The sizes of dq and of the velocities at the end: [the sum of |x|, the Euclidean size].
    pub moved: [f64; 2],
    pub speed: [f64; 2],
}

with_avx! {
    /// A contact step committed to a side's modes: q, v and a (holding the accelerations where
    /// it starts) at its end, by Newmark's average acceleration from the increments `e.dq`; the
    /// energy terms and sizes summed in lanes.
    #[inline(never)]
    pub(super) fn commit(e: &Ends, q: &mut [f64], v: &mut [f64], a: &mut [f64]) -> Committed = commit_portable
}

#[inline(always)]
fn commit_portable(e: &Ends, q: &mut [f64], v: &mut [f64], a: &mut [f64]) -> Committed {
    let n = e.dq.len();
    let (q0, v0s, dqs) = (&e.q0[..n], &e.v0[..n], &e.dq[..n]);
    let [omega, zeta, gamma] = e.coefficients.map(|c| &c[..n]);
    let (q, v, a) = (&mut q[..n], &mut v[..n], &mut a[..n]);
    let hh = e.hh;
    // Per lane: the ground's work, the damping's, |dq|, dq^2, |v1|, v1^2.
    let mut acc = [[0.0f64; 4]; 6];
    let full = n - n % 4;
    for c in (0..full).step_by(4) {
        let four = |x: &[f64]| -> [f64; 4] { x[c..c + 4].try_into().expect("four") };
        let (q0, v0, dq) = (four(q0), four(v0s), four(dqs));
        let (omega, zeta, gamma, a0) = (four(omega), four(zeta), four(gamma), four(a));
        let mut ends = [[0.0f64; 4]; 3];
        for l in 0..4 {
            let (v1, a1) = newmark_end(dq[l], v0[l], a0[l], hh);
            let (input, damping) = energy_terms(
                dq[l],
                v0[l],
                v1,
                [omega[l], zeta[l], gamma[l]],
                hh,
                e.ground,
            );
            for (sum, term) in acc.iter_mut().zip([
                input,
                damping,
                dq[l].abs(),
                dq[l] * dq[l],
                v1.abs(),
                v1 * v1,
            ]) {
                sum[l] += term;
            }
            ends[0][l] = q0[l] + dq[l];
            ends[1][l] = v1;
            ends[2][l] = a1;
        }
        q[c..c + 4].copy_from_slice(&ends[0]);
        v[c..c + 4].copy_from_slice(&ends[1]);
        a[c..c + 4].copy_from_slice(&ends[2]);
    }
    for k in full..n {
        let l = k - full;
        let (v0, dq) = (v0s[k], dqs[k]);
        let (v1, a1) = newmark_end(dq, v0, a[k], hh);
        let (input, damping) =
            energy_terms(dq, v0, v1, [omega[k], zeta[k], gamma[k]], hh, e.ground);
        for (sum, term) in
            acc.iter_mut()
                .zip([input, damping, dq.abs(), dq * dq, v1.abs(), v1 * v1])
        {
            sum[l] += term;
        }
        q[k] = q0[k] + dq;
        v[k] = v1;
        a[k] = a1;
    }
    let join = |l: [f64; 4]| (l[0] + l[2]) + (l[1] + l[3]);
    Committed {
        input: join(acc[0]),
        damping: join(acc[1]),
        moved: [join(acc[2]), join(acc[3]).sqrt()],
        speed: [join(acc[4]), join(acc[5]).sqrt()],
    }
}

/// What a tall elastic side's modes' increments over a whole grid step are made from.
pub(super) struct Increment<'a> {
    /// Each mode's omega, zeta and participation.
    pub coefficients: [&'a [f64]; 3],
    /// Each mode's velocity and acceleration where the step starts.
    pub v: &'a [f64],
    pub a: &'a [f64],
    /// Each mode's effective stiffness over a whole grid step.
    pub k_hat: &'a [f64],
    /// Each mode's load from the contact forces where the step starts.
    pub load_now: &'a [f64],
    pub hh: f64,
    pub ground_change: f64,
}

with_avx! {
    /// Each mode's increment over the step without a change of the contact forces, into `step`:
    /// Newmark's incremental form, term by term as [`Stepper::free_increment`] takes it for a few
    /// modes (no sums across modes: the same bits in vector lanes).
    ///
    /// [`Stepper::free_increment`]: super::Stepper
    #[inline(never)]
    pub(super) fn increment(e: &Increment, step: &mut [f64]) = increment_portable
}

#[inline(always)]
fn increment_portable(e: &Increment, step: &mut [f64]) {
    let n = step.len();
    let [omega, zeta, gamma] = e.coefficients.map(|c| &c[..n]);
    let (v, a, k_hat, load_now) = (&e.v[..n], &e.a[..n], &e.k_hat[..n], &e.load_now[..n]);
    let hh = e.hh;
    for k in 0..n {
        // 0.0: an elastic side's corrections do not change.
        let load = increment_load(
            [omega[k], zeta[k], gamma[k]],
            e.ground_change,
            load_now[k],
            0.0,
            v[k],
            a[k],
            hh,
        );
        step[k] = load / k_hat[k];
    }
}

/// A mode's load in Newmark's incremental form, k_hat dq = dp + (4/h + 2c) v + 2a, over a step
/// of length hh: the ground's change (times the participation), the contact forces' load where
/// the step starts taken off, the yielding storeys' corrections' change, and the terms of the
/// velocity and acceleration where it starts. `[omega, zeta, gamma]` are the mode's.
#[inline(always)]
pub(super) fn increment_load(
    [omega, zeta, gamma]: [f64; 3],
    ground_change: f64,
    load_now: f64,
    pseudo_change: f64,
    v: f64,
    a: f64,
    hh: f64,
) -> f64 {
    let c = 2.0 * zeta * omega;
    -gamma * ground_change - load_now + pseudo_change + (4.0 / hh + 2.0 * c) * v + 2.0 * a
}

/// Newmark's discrete energy identity over a mode's step from v0 to v1 that moved it by dq
/// (`[omega, zeta, gamma]` the mode's, `ground` the ground's acceleration at both ends summed):
/// the ground's work, half the sum of its forces times the displacement, and the damping's,
/// h/4 c (v0 + v1)^2.
#[inline(always)]
pub(super) fn energy_terms(
    dq: f64,
    v0: f64,
    v1: f64,
    [omega, zeta, gamma]: [f64; 3],
    hh: f64,
    ground: f64,
) -> (f64, f64) {
    (
        0.5 * dq * (-gamma) * ground,
        0.25 * hh * 2.0 * zeta * omega * (v0 + v1).powi(2),
    )
}

/// A mode's velocity and acceleration at the end of a Newmark step of length hh that moved it
/// by dq from velocity v0 and acceleration a0, in incremental form.
#[inline(always)]
pub(super) fn newmark_end(dq: f64, v0: f64, a0: f64, hh: f64) -> (f64, f64) {
    let dv = 2.0 * dq / hh - 2.0 * v0;
    let da = 4.0 * (dq - hh * v0) / (hh * hh) - 2.0 * a0;
    (v0 + dv, a0 + da)
}

#[cfg(test)]
mod tests {
    use super::super::fixed_signed;
    use super::*;

    #[test]
    fn a_sum_in_lanes_has_the_same_bits_on_every_processor() {
        for n in 0..=130 {
            let (c, q, d) = (
                fixed_signed(n as u64, n),
                fixed_signed(7 + n as u64, n),
                fixed_signed(99, n),
            );
            assert_eq!(dot(&c, &q).to_bits(), portable(&c, &q, None).to_bits());
            assert_eq!(
                dot_moved(&c, &q, &d).to_bits(),
                portable(&c, &q, Some(&d)).to_bits()
            );
            // Mode k in lane k mod 4, the lanes joined pairwise: written out term by term.
            let mut lane = [0.0f64; 4];
            for k in 0..n {
                lane[k % 4] += c[k] * (q[k] + d[k]);
            }
            let by_hand = (lane[0] + lane[2]) + (lane[1] + lane[3]);
            assert_eq!(dot_moved(&c, &q, &d).to_bits(), by_hand.to_bits(), "{n}");
        }
    }
}
