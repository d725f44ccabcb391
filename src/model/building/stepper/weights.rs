//! The bounds a free stretch starts from, for every followed signal and every point at once.
//!
//! A signal's (or a point's) bound on its size over a stretch is the sum over its side's modes
//! of |c_k| times the mode's bound, and so are its fourth and fifth derivatives'. Taken signal
//! by signal, a hundred-storey pair spends a third of a free stretch in these sums. Here the
//! |c_k| of a side are kept mode by mode over all its rows, and eight rows' sums are taken over
//! every mode at once: the same sums in the same order (bit for bit), four rows a vector
//! register ([`lanes::weigh_rows`]).

use super::{Point, Signal, TALL, lanes};

/// The tables of a run: each tall side's points and followed signals.
pub(super) struct BoundRows {
    pub points: [AbsRows; 2],
    pub signals: [AbsRows; 2],
    /// Each signal's row in its side's table (none for a signal not followed).
    pub row_of: Vec<Option<usize>>,
}

impl BoundRows {
    pub(super) fn new(modes: [usize; 2], points: &[Point], signals: &[Signal]) -> Self {
        let mut row_of = vec![None; signals.len()];
        let mut count = [0; 2];
        for (i, sig) in signals.iter().enumerate() {
            if sig.watched() {
                let s = sig.side_and_coefficients().0;
                row_of[i] = Some(count[s]);
                count[s] += 1;
            }
        }
        // Only a tall side reads its tables; a few modes' side has none.
        let rows_of = |s: usize, rows: Vec<&[f64]>| {
            AbsRows::new(modes[s], if modes[s] >= TALL { rows } else { vec![] })
        };
        BoundRows {
            points: std::array::from_fn(|s| {
                rows_of(s, points.iter().map(|p| p.r[s].as_slice()).collect())
            }),
            signals: std::array::from_fn(|s| {
                let rows = signals
                    .iter()
                    .filter(|sig| sig.watched())
                    .map(|sig| sig.side_and_coefficients())
                    .filter(|&(side, _)| side == s)
                    .map(|(_, c)| c);
                rows_of(s, rows.collect())
            }),
            row_of,
        }
    }
}

/// |c| of a set of rows (signals or points) over one side's modes, mode-major.
pub(super) struct AbsRows {
    rows: usize,
    /// `abs[k * rows + j]` = |c_k| of row j.
    abs: Vec<f64>,
}

impl AbsRows {
    /// The table of the given rows, each the coefficients of one row over the side's `modes`.
    pub(super) fn new(modes: usize, rows: Vec<&[f64]>) -> Self {
        let n = rows.len();
        let mut abs = vec![0.0; modes * n];
        for (j, row) in rows.iter().enumerate() {
            for (k, c) in row.iter().enumerate().take(modes) {
                abs[k * n + j] = c.abs();
            }
        }
        AbsRows { rows: n, abs }
    }

    /// Each row's sums of |c_k| m_k for each of the four bounds `m` (a size, derivatives), into
    /// `out`, each `rows` long: mode after mode, as a row's own sum takes them.
    pub(super) fn weigh(&self, m: [&[f64]; 4], out: &mut [Vec<f64>; 4]) {
        let n = self.rows;
        for o in out.iter_mut() {
            // The same length at every stretch of a run; every row is written.
            if o.len() != n {
                o.resize(n, 0.0);
            }
        }
        if n == 0 {
            return;
        }
        let [o0, o1, o2, o3] = out;
        let modes = self.abs.len() / n;
        let m = m.map(|m| &m[..modes]);
        lanes::weigh_rows(&self.abs, n, m, [o0, o1, o2, o3]);
    }
}

#[cfg(test)]
mod tests {
    use super::AbsRows;

    #[test]
    fn the_rows_sums_are_each_rows_own_sum_bit_for_bit() {
        let mut x = 11u64;
        let mut next = || {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (x >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        for modes in [1, 3, 17, 100] {
            let rows: Vec<Vec<f64>> = (0..7)
                .map(|_| (0..modes).map(|_| next() * 1e3).collect())
                .collect();
            let m: [Vec<f64>; 4] =
                std::array::from_fn(|_| (0..modes).map(|_| next().abs()).collect());
            let table = AbsRows::new(modes, rows.iter().map(|r| r.as_slice()).collect());
            let mut out = [vec![], vec![], vec![], vec![]];
            table.weigh([&m[0], &m[1], &m[2], &m[3]], &mut out);
            for (j, row) in rows.iter().enumerate() {
                for b in 0..4 {
                    let own: f64 = row.iter().zip(&m[b]).map(|(c, m)| c.abs() * m).sum();
                    assert_eq!(out[b][j].to_bits(), own.to_bits(), "row {j}, bound {b}");
                }
            }
        }
    }
}
