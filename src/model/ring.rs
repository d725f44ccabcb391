//! The newest samples of a history on a uniform grid, in a ring a look-up's reach deep, and
//! fixed-lag look-ups into it with a [`Tap`]'s stencil: what the Sears slabs of the buildings and
//! the girders of the bridges keep of their wave histories, whatever the run's length.

use crate::model::history::Tap;

/// A fixed-lag look-up into a [`Ring`]: the same stencil a [`Tap`] reads from a series.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Look {
    first: isize,
    stored: usize,
    w: [f64; 4],
    /// The weight the stencil puts on the sample about to be pushed (0 for a lag of a step or
    /// more).
    pub(crate) newest: f64,
}

impl Look {
    pub(crate) fn of(tap: Tap) -> Self {
        let (first, stored, w) = tap.stencil();
        Look {
            first,
            stored,
            w,
            newest: tap.newest_weight(),
        }
    }

    pub(crate) fn reach(&self) -> usize {
        (-self.first) as usize
    }

    /// The look-up as four weights on four samples from a fixed offset before the sample being
    /// made (a stencil of three stored samples reads that sample, still zero, with weight zero):
    /// (how far back the first is, the weights).
    pub(crate) fn stored_four(&self) -> (usize, [f64; 4]) {
        let w = if self.stored == 3 {
            [self.w[0], self.w[1], self.w[2], 0.0]
        } else {
            self.w
        };
        (self.reach(), w)
    }
}

/// The newest samples of a history on the grid, by absolute index (zero before index 0).
#[derive(Debug, Clone)]
pub(crate) struct Ring {
    data: Vec<f64>,
    mask: usize,
    /// The index the next sample will have.
    pub(crate) next: usize,
}

impl Ring {
    pub(crate) fn new(reach: usize) -> Self {
        let cap = (reach + 8).next_power_of_two();
        Ring {
            data: vec![0.0; cap],
            mask: cap - 1,
            next: 0,
        }
    }

    #[inline]
    pub(crate) fn push(&mut self, v: f64) {
        self.data[self.next & self.mask] = v;
        self.next += 1;
    }

    #[inline]
    pub(crate) fn at(&self, i: isize) -> f64 {
        if i < 0 { 0.0 } else { self.masked(i as usize) }
    }

    /// The sample at index i (at or after 0, within the ring's reach).
    #[inline(always)]
    fn masked(&self, i: usize) -> f64 {
        // SAFETY: the mask is the length less one, a power of two less one, so the index is
        // within the data.
        unsafe { *self.data.get_unchecked(i & self.mask) }
    }

    /// The look-up's part from stored samples, for the sample about to be pushed.
    #[inline(always)]
    pub(crate) fn known(&self, l: &Look) -> f64 {
        let base = self.next as isize + l.first;
        let w = &l.w;
        if base >= 0 && l.stored == 4 {
            // The common case, without a branch per sample: four stored samples, all at or after
            // index 0.
            let b = base as usize;
            return (w[0] * self.masked(b) + w[1] * self.masked(b + 1))
                + (w[2] * self.masked(b + 2) + w[3] * self.masked(b + 3));
        }
        if l.stored == 3 {
            w[0] * self.at(base) + w[1] * self.at(base + 1) + w[2] * self.at(base + 2)
        } else {
            (w[0] * self.at(base) + w[1] * self.at(base + 1))
                + (w[2] * self.at(base + 2) + w[3] * self.at(base + 3))
        }
    }

    /// The `len` newest samples, oldest first, into `out`.
    pub(crate) fn newest(&self, len: usize, out: &mut Vec<f64>) {
        out.clear();
        let next = self.next as isize;
        out.extend((next - len as isize..next).map(|i| self.at(i)));
    }
}
