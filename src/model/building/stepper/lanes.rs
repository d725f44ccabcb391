//! Sums over a tall building's modes in four interleaved partial sums: mode k in lane k mod 4,
//! the lanes joined pairwise. The compiler keeps the lanes in vector registers, so a sum over
//! 100 modes costs about half of one taken mode after mode. Where the processor has AVX, the
//! four lanes are one 256-bit register: the same multiplications and additions in the same lanes
//! (Rust never fuses them), so the same bits on every processor, in about half the instructions
//! again.

/// Modes from which a side's sums are taken in lanes; a few modes' sum is taken in order, the
/// cheapest there.
pub(super) const LANES_FROM: usize = 16;

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

#[inline(always)]
fn dispatch(c: &[f64], q: &[f64], d: Option<&[f64]>) -> f64 {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx") {
        // SAFETY: the processor has just been found to have AVX.
        return unsafe { with_avx(c, q, d) };
    }
    portable(c, q, d)
}

/// [`portable`] compiled for AVX.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
fn with_avx(c: &[f64], q: &[f64], d: Option<&[f64]>) -> f64 {
    portable(c, q, d)
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Fixed pseudo-random values in [-1, 1).
    fn values(seed: u64, n: usize) -> Vec<f64> {
        let mut x = seed;
        (0..n)
            .map(|_| {
                x = x
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                (x >> 11) as f64 / (1u64 << 52) as f64 - 1.0
            })
            .collect()
    }

    #[test]
    fn a_sum_in_lanes_has_the_same_bits_on_every_processor() {
        for n in 0..=130 {
            let (c, q, d) = (values(n as u64, n), values(7 + n as u64, n), values(99, n));
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
