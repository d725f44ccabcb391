//! One bracketing root finder for every event the solvers locate: the end of a contact, an
//! onset inside a step, a calibration. Illinois false position: superlinear on smooth functions,
//! and with a bisection fallback it never leaves the bracket, so it ends on any continuous one.

/// A bracket around a root: `f(keep)` has the sign `f` had at the first end given, `f(other)`
/// the sign at the second (or is zero).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bracket {
    /// The end on the side of the first end given (for an onset: the last instant before it).
    pub first_side: f64,
    /// The end on the side of the second end given (the first instant after it).
    pub second_side: f64,
}

impl Bracket {
    /// The middle of the bracket.
    pub fn mid(&self) -> f64 {
        0.5 * (self.first_side + self.second_side)
    }
}

/// Narrows [a, b] around a sign change of `f` until it is at most `tol` wide. `f(a)` and `f(b)`
/// must differ in sign or one of them be zero; if they do not, the bracket is returned as given.
pub fn bracket(mut f: impl FnMut(f64) -> f64, a: f64, b: f64, tol: f64) -> Bracket {
    let (mut x0, mut x1) = (a, b);
    let (mut f0, mut f1) = (f(a), f(b));
    if f0 == 0.0 {
        return Bracket {
            first_side: a,
            second_side: a,
        };
    }
    if f1 == 0.0 || (f0 > 0.0) == (f1 > 0.0) {
        return Bracket {
            first_side: a,
            second_side: b,
        };
    }
    let sign0 = f0 > 0.0;
    // Which end moved last: a false-position step that keeps moving the same end halves the other
    // end's value (Illinois), so both ends close in.
    let mut last = 0i8;
    // Bisect whenever two steps did not halve the bracket: never slower than bisection by more
    // than a factor of three.
    let mut widths = [f64::INFINITY; 2];
    for k in 0..400 {
        let width = (x1 - x0).abs();
        if width <= tol {
            break;
        }
        let mut x = x1 - f1 * (x1 - x0) / (f1 - f0);
        let (lo, hi) = (x0.min(x1), x0.max(x1));
        if !(x > lo && x < hi) || width > 0.5 * widths[k % 2] {
            x = 0.5 * (x0 + x1);
        }
        widths[k % 2] = width;
        let fx = f(x);
        if fx == 0.0 {
            return Bracket {
                first_side: x,
                second_side: x,
            };
        }
        if (fx > 0.0) == sign0 {
            x0 = x;
            f0 = fx;
            if last == 0 {
                f1 *= 0.5;
            }
            last = 0;
        } else {
            x1 = x;
            f1 = fx;
            if last == 1 {
                f0 *= 0.5;
            }
            last = 1;
        }
    }
    Bracket {
        first_side: x0,
        second_side: x1,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brackets_the_root_of_smooth_flat_and_kinked_functions_to_the_tolerance() {
        let cases: [(&dyn Fn(f64) -> f64, f64); 4] = [
            (&|x: f64| x * x - 2.0, 2f64.sqrt()),
            (&|x: f64| (x - 0.3).powi(9), 0.3),
            (&|x: f64| if x < 0.7 { -1.0 } else { 1.0 }, 0.7),
            (&|x: f64| 1.0 - (-40.0 * x).exp() * 1e6, 1e6f64.ln() / 40.0),
        ];
        for (f, root) in cases {
            let b = bracket(f, 0.0, 2.0, 1e-13);
            assert!((b.first_side - b.second_side).abs() <= 1e-13);
            assert!(b.first_side <= root + 1e-12 && b.second_side >= root - 1e-12);
            assert!(f(b.first_side) <= 0.0 && f(b.second_side) >= 0.0);
        }
        // Either orientation of the sign change.
        let b = bracket(|x| 1.0 - x, 0.0, 3.0, 1e-12);
        assert!((b.mid() - 1.0).abs() < 1e-12 && b.first_side <= 1.0);
    }
}
