//! Rigid masses: Hertz, linear and Kelvin-Voigt contact (integrated), and stereomechanics.
//!
//! The relative coordinate obeys m* delta'' = -F, m* = m1 m2 / (m1 + m2). RK4 with at least 200
//! steps per contact and the end of contact located to round-off by secant iteration on single
//! RK4 sub-steps, so the closed forms (duration, peak) are reproduced to ~1e-9, an independent
//! check of them rather than a copy.

use super::timestep::contact_time_scale;
use super::{ContactSpan, Raw, SolveError, Warning};
use crate::model::contact::ContactLaw;
use crate::model::control::{CHECK_EVERY, Control};
use crate::model::root::bracket;
use crate::model::scenario::ImpactScenario;

/// Restitution of a Kelvin-Voigt contact that cannot pull (the contact ends when the spring and
/// dashpot force returns to zero, before delta does), as a function of the damping ratio xi.
pub fn kelvin_restitution(xi: f64) -> f64 {
    if xi <= 0.0 {
        return 1.0;
    }
    if xi < 1.0 {
        let s = (1.0 - xi * xi).sqrt();
        let th = (2.0 * xi * s).atan2(2.0 * xi * xi - 1.0);
        return -(-xi * th / s).exp() * (th.cos() - xi / s * th.sin());
    }
    let s = (xi * xi - 1.0).sqrt().max(1e-9);
    // r1 = -xi + s without the cancellation that large xi would bring.
    let (r1, r2) = (-1.0 / (xi + s), -xi - s);
    let (a1, a2) = (1.0 + 2.0 * xi * r1, 1.0 + 2.0 * xi * r2);
    let t = (a2 / a1).ln() / (r1 - r2);
    -(r1 * (r1 * t).exp() - r2 * (r2 * t).exp()) / (r1 - r2)
}

/// Damping ratio that gives restitution `e` with [`kelvin_restitution`] (bisection in log xi);
/// infinite for e <= 0, which no finite damping reaches.
pub fn kelvin_damping_ratio(e: f64) -> f64 {
    const XI_MAX: f64 = 1e4;
    if e >= 1.0 {
        return 0.0;
    }
    if e <= 0.0 {
        return f64::INFINITY;
    }
    // Beyond xi = 1e4, e = 1 / (4 xi^2) to 1e-8: the inverse in closed form.
    if e < kelvin_restitution(XI_MAX) {
        return 0.5 / e.sqrt();
    }
    // e falls from 1 as xi grows: a root in ln xi between 1e-12 and 1e4.
    let f = |ln_xi: f64| kelvin_restitution(ln_xi.exp()) - e;
    bracket(f, 1e-12f64.ln(), XI_MAX.ln(), 1e-14).mid().exp()
}

/// Anagnostopoulos' damping ratio for a Kelvin-Voigt link that may pull at the end of contact:
/// xi = -ln e / sqrt(pi^2 + ln^2 e). Reported for comparison; the solver uses the no-tension
/// calibration above so that the restitution it produces is the one asked for.
pub fn anagnostopoulos_damping_ratio(e: f64) -> f64 {
    let l = e.ln();
    -l / (std::f64::consts::PI.powi(2) + l * l).sqrt()
}

#[derive(Clone, Copy)]
struct Link {
    law: ContactLaw,
    damping_n_s_m: f64,
}

impl Link {
    /// Contact force before clipping (its sign tells whether the bodies still push).
    fn push(&self, d: f64, u: f64) -> f64 {
        self.law.force(d) + self.damping_n_s_m * u
    }
    /// The force reported while the contact lasts (never a pull).
    fn force(&self, d: f64, u: f64) -> f64 {
        self.push(d, u).max(0.0)
    }
}

type State = [f64; 3]; // delta, delta', dissipated energy

/// One RK4 step of the in-contact dynamics. No clipping: every step the integrator keeps lies
/// inside the contact (the release is located separately), and clipping would put a kink in the
/// stage that lands on the release instant (the dashpot's power c u^2 is finite there).
fn rk4(link: &Link, m: f64, y: State, h: f64) -> State {
    let rate = |y: State| {
        [
            y[1],
            -link.push(y[0], y[1]) / m,
            link.damping_n_s_m * y[1] * y[1],
        ]
    };
    let add = |y: State, k: State, s: f64| [y[0] + s * k[0], y[1] + s * k[1], y[2] + s * k[2]];
    let k1 = rate(y);
    let k2 = rate(add(y, k1, 0.5 * h));
    let k3 = rate(add(y, k2, 0.5 * h));
    let k4 = rate(add(y, k3, h));
    std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
}

fn integrate(sc: &ImpactScenario, link: Link, control: &Control) -> Result<Raw, SolveError> {
    let masses = [sc.bar1.mass_kg(), sc.bar2.mass_kg()];
    let m = sc.effective_mass_kg();
    let w = sc.approach_velocity_m_s();
    let scale = contact_time_scale(&link.law, w, m, f64::INFINITY);
    // Resolve both the spring's and (for a damped link) the dashpot's time scale m*/c.
    let damping_time = if link.damping_n_s_m > 0.0 {
        m / link.damping_n_s_m
    } else {
        f64::INFINITY
    };
    let h = sc
        .solver
        .dt_s
        .min(scale.lumped_duration_s / 200.0)
        .min(damping_time / 50.0);
    let still_pushing =
        |y: &State| link.push(y[0], y[1]) > 0.0 && (link.damping_n_s_m > 0.0 || y[0] > 0.0);
    let mut y: State = [0.0, w, 0.0];
    let (mut time_s, mut force_n, mut approach_m) =
        (vec![0.0], vec![link.force(0.0, w)], vec![0.0]);
    // The impulse m* (w - delta') and the dashpot's dissipation, as integrated.
    let (mut impulses, mut dissipated) = (vec![0.0], vec![0.0]);
    let mut t = 0.0;
    let mut steps = 0usize;
    let expected_steps = (2.0 * scale.lumped_duration_s / h).max(1.0);
    loop {
        if steps.is_multiple_of(CHECK_EVERY) {
            control.report(steps as f64 / expected_steps)?;
        }
        if steps >= sc.solver.max_steps {
            return Err(SolveError::Budget {
                max_steps: sc.solver.max_steps,
                dt_s: h,
                reached_s: t,
            });
        }
        let next = rk4(&link, m, y, h);
        steps += 1;
        if !still_pushing(&next) {
            // Secant on the sub-step length s for g(s) = push force (delta for elastic laws).
            let g = |s: f64| {
                let ys = rk4(&link, m, y, s);
                if link.damping_n_s_m == 0.0 {
                    ys[0]
                } else {
                    link.push(ys[0], ys[1])
                }
            };
            // The end of contact to round-off; the bracket's pushing side is the last instant of
            // contact.
            let s = bracket(g, 0.0, h, 1e-14 * h).first_side;
            y = rk4(&link, m, y, s);
            t += s;
            time_s.push(t);
            force_n.push(0.0);
            approach_m.push(y[0]);
            impulses.push(m * (w - y[1]));
            // A Kelvin-Voigt link lets go with its spring still stretched: that energy is lost
            // as the massless link relaxes.
            let relaxed = if link.damping_n_s_m > 0.0 {
                link.law.energy(y[0])
            } else {
                0.0
            };
            dissipated.push(y[2] + relaxed);
            break;
        }
        y = next;
        t += h;
        time_s.push(t);
        force_n.push(link.force(y[0], y[1]));
        approach_m.push(y[0]);
        impulses.push(m * (w - y[1]));
        dissipated.push(y[2]);
    }
    let end_contact = t;
    let impulse = m * (w - y[1]);
    // A Kelvin-Voigt link releases at delta > 0; its spring energy is lost as the massless link
    // relaxes.
    let dissipated_total =
        y[2] + link.law.energy(y[0]) * if link.damping_n_s_m > 0.0 { 1.0 } else { 0.0 };
    let contact_j = if link.damping_n_s_m > 0.0 {
        0.0
    } else {
        link.law.energy(y[0])
    };
    if sc.solver.window_s > end_contact {
        time_s.push(sc.solver.window_s);
        force_n.push(0.0);
        approach_m.push(y[0] + y[1] * (sc.solver.window_s - end_contact));
        impulses.push(impulse);
        dissipated.push(dissipated.last().copied().unwrap_or(0.0));
    }
    Ok(Raw {
        end_s: *time_s.last().unwrap_or(&0.0),
        time_s,
        force_n,
        approach_m,
        contacts: vec![ContactSpan::closed(0.0, end_contact, impulse)],
        impulse_ns: impulse,
        impulse_history_ns: impulses,
        dissipated_history_j: dissipated,
        masses_kg: masses,
        dissipated_j: dissipated_total,
        contact_j,
        steps,
        dt_s: h,
        refined_from_s: (h < sc.solver.dt_s).then_some(sc.solver.dt_s),
        ..Raw::default()
    })
}

pub(crate) fn solve_elastic(
    sc: &ImpactScenario,
    law: ContactLaw,
    control: &Control,
) -> Result<Raw, SolveError> {
    integrate(
        sc,
        Link {
            law,
            damping_n_s_m: 0.0,
        },
        control,
    )
}

pub(crate) fn solve_kelvin(sc: &ImpactScenario, control: &Control) -> Result<Raw, SolveError> {
    let law = sc.linear_law();
    let m = sc.effective_mass_kg();
    let e = sc.contact.restitution;
    let xi = kelvin_damping_ratio(e);
    let c = 2.0 * xi * (law.stiffness * m).sqrt();
    let mut raw = integrate(
        sc,
        Link {
            law,
            damping_n_s_m: c,
        },
        control,
    )?;
    raw.warnings.push(Warning::KelvinCalibration {
        xi,
        damping_n_s_m: c,
        restitution: e,
        anagnostopoulos_xi: anagnostopoulos_damping_ratio(e),
    });
    Ok(raw)
}

pub(crate) fn solve_stereo(sc: &ImpactScenario) -> Raw {
    let m = sc.effective_mass_kg();
    let w = sc.approach_velocity_m_s();
    let e = sc.contact.restitution;
    let impulse = (1.0 + e) * m * w;
    Raw {
        time_s: vec![0.0, 0.0],
        force_n: vec![0.0, 0.0],
        approach_m: vec![0.0, 0.0],
        contacts: vec![ContactSpan::closed(0.0, 0.0, impulse)],
        impulse_ns: impulse,
        impulse_history_ns: vec![0.0, impulse],
        dissipated_history_j: vec![0.0, 0.5 * m * w * w * (1.0 - e * e)],
        masses_kg: [sc.bar1.mass_kg(), sc.bar2.mass_kg()],
        dissipated_j: 0.5 * m * w * w * (1.0 - e * e),
        peak_override_n: Some(None),
        warnings: vec![Warning::Instantaneous],
        dt_s: 0.0,
        ..Raw::default()
    }
}
