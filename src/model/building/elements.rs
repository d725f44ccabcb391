//! The contact elements between buildings, built on the bar models' contact laws: each element
//! is a [`ContactLaw`] (linear or Hertz, with its force, stored energy and tangent) plus, for the
//! damped elements, a dashpot. delta is the overlap at the contact point, rate its time
//! derivative, v0 the approach velocity at the onset of the current contact.

use super::ContactModel;
use crate::model::contact::{ContactLaw, REFERENCE_OVERLAP_M};
use crate::model::impact::lumped::kelvin_damping_ratio;
use crate::model::root::bracket;

/// The damped part of an element.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Dashpot {
    None,
    /// Kelvin-Voigt: c delta'.
    Kelvin {
        c: f64,
    },
    /// Muthukumar & DesRoches (2006): the Hertz force times 1 + coef delta' / v0. `xi` is
    /// Jankowski's ratio for the same restitution, a measure of how stiff this dashpot is.
    HertzDamp {
        coef: f64,
        xi: f64,
    },
    /// Jankowski (2005): 2 xi sqrt(k sqrt(delta) m*) delta' while approaching.
    Jankowski {
        xi: f64,
    },
}

/// A contact element at one level: its law, its dashpot and the two buildings' effective mass there.
#[derive(Debug, Clone, Copy)]
pub struct Element {
    /// Which element.
    pub model: ContactModel,
    /// The elastic part: linear or Hertz.
    pub law: ContactLaw,
    dashpot: Dashpot,
    /// Effective mass of the two buildings at the contact point [kg].
    pub effective_mass: f64,
}

impl Element {
    /// The element of `model` with `stiffness` (N/m, or N/m^1.5 for the Hertzian ones), its
    /// damping calibrated so that an isolated impact has restitution `restitution`.
    pub fn new(model: ContactModel, stiffness: f64, restitution: f64, effective_mass: f64) -> Self {
        let e = restitution;
        let jankowski_xi = 9.0 * 5f64.sqrt() / 2.0 * (1.0 - e * e)
            / (e * (e * (9.0 * std::f64::consts::PI - 16.0) + 16.0));
        let law = if model.is_hertzian() {
            ContactLaw::hertz(stiffness)
        } else {
            ContactLaw::linear(stiffness)
        };
        let dashpot = match model {
            // Kelvin-Voigt as in the bar models: a link that cannot pull, its damping calibrated
            // so that an isolated impact has restitution e.
            ContactModel::Kelvin => Dashpot::Kelvin {
                c: 2.0 * kelvin_damping_ratio(e) * (stiffness * effective_mass).sqrt(),
            },
            ContactModel::HertzDamp => Dashpot::HertzDamp {
                coef: 0.75 * (1.0 - e * e),
                xi: jankowski_xi,
            },
            ContactModel::Jankowski => Dashpot::Jankowski { xi: jankowski_xi },
            _ => Dashpot::None,
        };
        Element {
            model,
            law,
            dashpot,
            effective_mass,
        }
    }

    /// The law's stiffness (N/m, or N/m^1.5 for the Hertzian elements).
    pub fn stiffness(&self) -> f64 {
        self.law.stiffness
    }

    /// The Kelvin-Voigt dashpot [N s/m], 0 for the other elements.
    pub fn kelvin_damping(&self) -> f64 {
        match self.dashpot {
            Dashpot::Kelvin { c } => c,
            _ => 0.0,
        }
    }

    /// Contact force before clipping (a Kelvin-Voigt link's sign says whether it still pushes).
    pub fn push(&self, delta: f64, rate: f64, v0: f64) -> f64 {
        let elastic = self.law.force(delta);
        match self.dashpot {
            Dashpot::None => elastic,
            Dashpot::Kelvin { c } => self.law.stiffness * delta + c * rate,
            Dashpot::HertzDamp { coef, .. } => elastic * (1.0 + coef * rate / v0.max(1e-12)),
            Dashpot::Jankowski { xi } => {
                if rate > 0.0 && delta > 0.0 {
                    elastic
                        + 2.0
                            * xi
                            * (self.law.stiffness * delta.sqrt() * self.effective_mass).sqrt()
                            * rate
                } else {
                    elastic
                }
            }
        }
    }

    /// Whether the force is the law's alone (a function of the overlap, rising with it).
    pub fn undamped(&self) -> bool {
        self.dashpot == Dashpot::None
    }

    /// Contact force, never a pull.
    pub fn force(&self, delta: f64, rate: f64, v0: f64) -> f64 {
        if delta <= 0.0 {
            return 0.0;
        }
        self.push(delta, rate, v0).max(0.0)
    }

    /// Elastic energy stored at overlap delta [J] (the spring part).
    pub fn stored_energy(&self, delta: f64) -> f64 {
        self.law.energy(delta)
    }

    /// Tangent stiffness at a force level [N/m].
    pub fn tangent_at_force(&self, force: f64) -> f64 {
        self.law.tangent_at_force(force)
    }

    /// The dashpot's own rate constant c / m* [1/s], 0 without one. Hertzdamp and Jankowski's
    /// dashpots grow with the overlap; at the reference overlap they are about as stiff as a
    /// Kelvin-Voigt link of the same restitution.
    fn dashpot_rate(&self) -> f64 {
        let c = match self.dashpot {
            Dashpot::None => 0.0,
            Dashpot::Kelvin { c } => c,
            Dashpot::HertzDamp { xi, .. } | Dashpot::Jankowski { xi } => {
                2.0 * xi
                    * (self.law.stiffness * REFERENCE_OVERLAP_M.sqrt() * self.effective_mass).sqrt()
            }
        };
        c / self.effective_mass
    }

    /// Weight of the new rate in the overlap rate's update, rate_{n+1} = ((delta_{n+1} -
    /// delta_n)/h - (1 - theta) rate_n) / theta: the trapezoid rule (theta = 1/2, what the
    /// buildings' Newmark step uses) while the dashpot's time scale is resolved, backward Euler
    /// where it is not (a stiff dashpot rings under the trapezoid rule and, clipped at zero
    /// force, pumps energy in). z = c h / m* measures it.
    pub fn rate_theta(&self, h: f64) -> f64 {
        let z = self.dashpot_rate() * h;
        0.5 + 0.5 * (0.25 * z * z).min(1.0)
    }

    /// The overlap rate after a step of h (see [`Element::rate_theta`]).
    pub fn rate(&self, h: f64, delta: f64, delta_n: f64, rate_n: f64) -> f64 {
        let theta = self.rate_theta(h);
        ((delta - delta_n) / h - (1.0 - theta) * rate_n) / theta
    }

    /// Solves delta + beta F(delta, rate(delta)) = rhs for the step's overlap, with the rate
    /// from [`Element::rate`]. beta >= 0 and F >= 0 increasing in delta: one root, in [0, rhs].
    #[inline]
    pub fn solve_step(
        &self,
        beta: f64,
        rhs: f64,
        h: f64,
        delta_n: f64,
        rate_n: f64,
        v0: f64,
    ) -> f64 {
        if rhs <= 0.0 || beta == 0.0 {
            return rhs;
        }
        if self.dashpot == Dashpot::None {
            return self.law.solve_implicit(beta, rhs, delta_n);
        }
        let g = |d: f64| d + beta * self.force(d, self.rate(h, d, delta_n, rate_n), v0) - rhs;
        if g(rhs) <= 0.0 {
            return rhs;
        }
        bracket(g, 0.0, rhs, 1e-15 * rhs).mid()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_elastic_parts_are_the_bar_contact_laws() {
        for model in ContactModel::ALL {
            let e = Element::new(model, 2e10, 0.65, 2e4);
            let law = if model.is_hertzian() {
                ContactLaw::hertz(2e10)
            } else {
                ContactLaw::linear(2e10)
            };
            for d in [1e-6, 1e-4, 2e-3] {
                assert_eq!(e.stored_energy(d), law.energy(d));
                assert_eq!(
                    e.tangent_at_force(law.force(d)),
                    law.tangent_at_force(law.force(d))
                );
                if matches!(
                    model,
                    ContactModel::Linear | ContactModel::Sears | ContactModel::Hertz
                ) {
                    assert_eq!(e.force(d, 0.3, 0.5), law.force(d));
                }
            }
        }
    }

    #[test]
    fn the_implicit_step_satisfies_its_equation_for_every_element() {
        for model in ContactModel::ALL {
            let e = Element::new(model, 1.5e10, 0.65, 2e4);
            for (beta, rhs) in [(1e-12, 1e-4), (1e-9, 3e-4), (1e-6, 1e-3)] {
                let d = e.solve_step(beta, rhs, 5e-5, 1e-5, 0.1, 0.2);
                // The root lies within 1e-12 of rhs of the overlap returned: the equation
                // changes sign across that interval (its slope can be large, its root is sharp).
                let g = |d: f64| d + beta * e.force(d, e.rate(5e-5, d, 1e-5, 0.1), 0.2) - rhs;
                let eps = 1e-12 * rhs;
                assert!(
                    g(d - eps) <= 0.0 && g(d + eps) >= 0.0,
                    "{model:?} {beta} {rhs}"
                );
            }
        }
    }
}
