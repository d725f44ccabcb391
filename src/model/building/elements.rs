//! The classic contact elements between buildings. delta is the overlap u1 - u2 - gap, rate its
//! time derivative, v0 the approach velocity at the onset of the current contact.

use super::ContactModel;
use crate::model::impact::lumped::kelvin_damping_ratio;

#[derive(Debug, Clone, Copy)]
pub struct Element {
    pub model: ContactModel,
    /// N/m (linear, kelvin, sears) or N/m^1.5 (hertz, hertzdamp, jankowski).
    pub stiffness: f64,
    /// Kelvin-Voigt dashpot [N s/m].
    pub kelvin_damping: f64,
    /// Hertzdamp: 3 (1 - e^2) / 4 (divided by v0 at use).
    pub hertzdamp: f64,
    /// Jankowski's damping ratio.
    pub jankowski_xi: f64,
    pub effective_mass: f64,
}

impl Element {
    pub fn new(model: ContactModel, stiffness: f64, restitution: f64, effective_mass: f64) -> Self {
        let e = restitution;
        // Kelvin-Voigt as in the bar models: a link that cannot pull, its damping calibrated so
        // that an isolated impact has restitution e.
        let xi = kelvin_damping_ratio(e);
        Element {
            model,
            stiffness,
            kelvin_damping: 2.0 * xi * (stiffness * effective_mass).sqrt(),
            // Muthukumar & DesRoches (2006).
            hertzdamp: 0.75 * (1.0 - e * e),
            // Jankowski (2005).
            jankowski_xi: 9.0 * 5f64.sqrt() / 2.0 * (1.0 - e * e)
                / (e * (e * (9.0 * std::f64::consts::PI - 16.0) + 16.0)),
            effective_mass,
        }
    }

    /// Contact force, never a pull.
    pub fn force(&self, delta: f64, rate: f64, v0: f64) -> f64 {
        if delta <= 0.0 {
            return 0.0;
        }
        let k = self.stiffness;
        let f = match self.model {
            ContactModel::Linear | ContactModel::Sears => k * delta,
            ContactModel::Kelvin => k * delta + self.kelvin_damping * rate,
            ContactModel::Hertz => k * delta * delta.sqrt(),
            ContactModel::HertzDamp => {
                k * delta * delta.sqrt() * (1.0 + self.hertzdamp * rate / v0.max(1e-12))
            }
            ContactModel::Jankowski => {
                let elastic = k * delta * delta.sqrt();
                if rate > 0.0 {
                    elastic
                        + 2.0
                            * self.jankowski_xi
                            * (k * delta.sqrt() * self.effective_mass).sqrt()
                            * rate
                } else {
                    elastic
                }
            }
            ContactModel::Stereo | ContactModel::None => 0.0,
        };
        f.max(0.0)
    }

    /// Elastic energy stored at overlap delta [J] (the spring part).
    pub fn stored_energy(&self, delta: f64) -> f64 {
        if delta <= 0.0 {
            return 0.0;
        }
        if self.model.is_hertzian() {
            0.4 * self.stiffness * delta * delta * delta.sqrt()
        } else {
            0.5 * self.stiffness * delta * delta
        }
    }

    /// Tangent stiffness at a force level [N/m].
    pub fn tangent_at_force(&self, force: f64) -> f64 {
        if self.model.is_hertzian() {
            1.5 * self.stiffness.powf(2.0 / 3.0) * force.max(0.0).powf(1.0 / 3.0)
        } else {
            self.stiffness
        }
    }

    /// Weight of the new rate in the overlap rate's update, rate_{n+1} = ((delta_{n+1} -
    /// delta_n)/h - (1 - theta) rate_n) / theta: the trapezoid rule (theta = 1/2, what the
    /// oscillators use) while the dashpot's time scale is resolved, backward Euler where it is
    /// not (a stiff dashpot rings under the trapezoid rule and, clipped at zero force, pumps
    /// energy in). z = c h / m* measures it.
    pub fn rate_theta(&self, h: f64) -> f64 {
        let c = match self.model {
            ContactModel::Kelvin => self.kelvin_damping,
            // Hertzdamp and Jankowski's dashpots grow with the overlap; at 1 mm they are about
            // as stiff as a Kelvin-Voigt link of the same restitution.
            ContactModel::HertzDamp | ContactModel::Jankowski => {
                2.0 * self.jankowski_xi
                    * (self.stiffness * 1e-3f64.sqrt() * self.effective_mass).sqrt()
            }
            _ => 0.0,
        };
        let z = c * h / self.effective_mass;
        0.5 + 0.5 * (0.25 * z * z).min(1.0)
    }

    /// The overlap rate after a step of h (see [`Element::rate_theta`]).
    pub fn rate(&self, h: f64, delta: f64, delta_n: f64, rate_n: f64) -> f64 {
        let theta = self.rate_theta(h);
        ((delta - delta_n) / h - (1.0 - theta) * rate_n) / theta
    }

    /// Solves delta + beta F(delta, rate(delta)) = rhs for the step's overlap, with the rate
    /// from [`Element::rate`].
    /// beta >= 0 and F >= 0, increasing in delta, so the root in [0, rhs] is bracketed.
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
        let rate = |d: f64| self.rate(h, d, delta_n, rate_n);
        if self.model == ContactModel::Linear || self.model == ContactModel::Sears {
            return rhs / (1.0 + beta * self.stiffness);
        }
        let g = |d: f64| d + beta * self.force(d, rate(d), v0) - rhs;
        let (mut a, mut b) = (0.0, rhs);
        let (mut ga, mut gb) = (g(a), g(b));
        if gb <= 0.0 {
            return b;
        }
        let mut side = 0i8;
        for _ in 0..200 {
            let s = b - gb * (b - a) / (gb - ga);
            let s = if s > a && s < b { s } else { 0.5 * (a + b) };
            let gs = g(s);
            if gs == 0.0 {
                return s;
            }
            if gs < 0.0 {
                a = s;
                ga = gs;
                if side == -1 {
                    gb *= 0.5;
                }
                side = -1;
            } else {
                b = s;
                gb = gs;
                if side == 1 {
                    ga *= 0.5;
                }
                side = 1;
            }
            if b - a <= 1e-15 * rhs {
                break;
            }
        }
        0.5 * (a + b)
    }
}
