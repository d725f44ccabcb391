//! What a reader of an impact result must know besides its numbers. Each warning is a variant, so
//! a test matches the kind of warning, never a phrase; its message is its `Display`.

use crate::model::settings::impact;
use crate::model::settings::shown;
use std::fmt;

/// Why a step coarser than the contact's time scale was kept.
#[derive(Debug, Clone, PartialEq)]
pub enum KeptBecause {
    /// `solver.refine = false`.
    RefineOff,
    /// Refining would need about `steps` steps, over `solver.max_steps`.
    Budget {
        /// The step refining would need [s].
        refined_s: f64,
        /// Steps that would take.
        steps: f64,
        /// The budget.
        max_steps: usize,
    },
}

/// Which input lies outside the validated box.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Outside {
    /// Contact stiffness outside 1e4 to 1e16.
    Stiffness(f64),
    /// Approach velocity outside 1e-6 to 1e3 m/s.
    ApproachVelocity(f64),
    /// Length ratio above 1e4.
    LengthRatio(f64),
    /// Zone scale outside 1e-4 to 10.
    ZoneScale(f64),
    /// Added mass above 1000 times the bar's own.
    AddedMass {
        /// Which bar (1 or 2).
        bar: usize,
        /// The added mass [kg].
        kg: f64,
        /// How many times the bar's own mass it is.
        times_own: f64,
    },
}

impl fmt::Display for Outside {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Outside::Stiffness(k) => write!(f, "contact stiffness {k:.3e}"),
            Outside::ApproachVelocity(w) => write!(f, "approach velocity {w:e} m/s"),
            Outside::LengthRatio(r) => write!(f, "length ratio {r:.3e}"),
            Outside::ZoneScale(s) => write!(f, "zone scale {}", shown(*s)),
            Outside::AddedMass { bar, kg, times_own } => write!(
                f,
                "bar{bar} added mass {kg:.3e} kg, {times_own:.0} times its own"
            ),
        }
    }
}

/// One warning attached to an impact result.
#[derive(Debug, Clone, PartialEq)]
pub enum Warning {
    /// `solver.dt` was coarser than the contact's time scale and was refined.
    StepRefined {
        /// The step asked for [s].
        dt_s: f64,
        /// The contact's time scale [s].
        scale_s: f64,
        /// The step used [s].
        refined_s: f64,
    },
    /// `solver.dt` was coarser than the contact's time scale and was kept: stable, but the rise
    /// of the force is not resolved.
    StepKept {
        /// The step asked for and used [s].
        dt_s: f64,
        /// The contact's time scale [s].
        scale_s: f64,
        /// Why it was kept.
        because: KeptBecause,
    },
    /// The contact was still on when the simulated span ended.
    ContactOpenAtEnd {
        /// The end of the span [s].
        end_s: f64,
    },
    /// In the paper reading, a bar's zone d is longer than the bar itself.
    ZoneLongerThanBar {
        /// Which bar (1 or 2).
        bar: usize,
        /// Its zone length d [m].
        zone_m: f64,
        /// Its length [m].
        length_m: f64,
    },
    /// How the Kelvin-Voigt damping was calibrated, against Anagnostopoulos' formula.
    KelvinCalibration {
        /// The damping ratio used.
        xi: f64,
        /// The dashpot's coefficient [N s/m].
        damping_n_s_m: f64,
        /// The restitution asked for.
        restitution: f64,
        /// Anagnostopoulos' damping ratio for a link that may pull.
        anagnostopoulos_xi: f64,
    },
    /// Stereomechanics has no force history.
    Instantaneous,
    /// FE: the step does not resolve the link's oscillation and refining would exceed the budget.
    FeLinkUnresolved {
        /// The step used [s].
        dt_s: f64,
        /// The step the link needs [s].
        link_step_s: f64,
    },
    /// FE: the contact link is much stiffer than the end elements, so the end nodes chatter.
    FeLinkChatter {
        /// The link's tangent stiffness [N/m].
        link_n_m: f64,
        /// An end element's stiffness [N/m].
        element_n_m: f64,
    },
    /// An input lies outside the box the stability suite covers.
    OutsideValidated(Outside),
    /// The bars do not approach: no impact.
    NotApproaching {
        /// v1 - v2 [m/s].
        approach_m_s: f64,
    },
    /// The paper reading created energy.
    PaperCreatesEnergy {
        /// How much, in percent of the relative kinetic energy.
        percent: f64,
        /// The reading's validity number.
        a_tau: f64,
    },
    /// The paper reading is in its overshoot regime (a tau > 1/e).
    PaperOvershoots {
        /// The reading's validity number.
        a_tau: f64,
    },
}

/// The box the stability suite (tests/stability.rs) covers; a run outside it says so.
pub const VALIDATED: &str = "contact stiffness 1e4 to 1e16, approach velocity 1e-6 to 1e3 m/s, length ratio up to 1e4, zone scale 1e-4 to 10, added mass up to 1000 times a bar's own";

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Warning::StepRefined {
                dt_s,
                scale_s,
                refined_s,
            } => write!(
                f,
                "{} = {dt_s:e} s is coarser than the contact's time scale {scale_s:.3e} s: refined to {refined_s:.3e} s",
                impact::DT.key
            ),
            Warning::StepKept {
                dt_s,
                scale_s,
                because,
            } => {
                let why = match because {
                    KeptBecause::RefineOff => format!("{} = false", impact::REFINE.key),
                    KeptBecause::Budget {
                        refined_s,
                        steps,
                        max_steps,
                    } => format!(
                        "refining to {refined_s:.3e} s would need about {steps:.0} steps, over solver.max_steps = {max_steps}"
                    ),
                };
                write!(
                    f,
                    "{dt} = {dt_s:e} s is coarser than the contact's time scale {scale_s:.3e} s and was kept ({why}): the run is stable but the force's rise is not resolved; use {dt} <= {scale_s:.1e} s for accurate peaks",
                    dt = impact::DT.key
                )
            }
            Warning::ContactOpenAtEnd { end_s } => write!(
                f,
                "the contact was still on at the end of the simulated span (t = {end_s:.4e} s)"
            ),
            Warning::ZoneLongerThanBar {
                bar,
                zone_m,
                length_m,
            } => write!(
                f,
                "bar{bar}'s zone d = {zone_m:.4} m is longer than the bar ({length_m:.4} m): its plane P lies past the far end's mirror image; the paper reading is still defined (d < 2L) but physically doubtful"
            ),
            Warning::KelvinCalibration {
                xi,
                damping_n_s_m,
                restitution,
                anagnostopoulos_xi,
            } => write!(
                f,
                "Kelvin-Voigt damping ratio {xi:.4} (c = {damping_n_s_m:.4e} N s/m) gives e = {} with a link that cannot pull; Anagnostopoulos' formula, which lets the link pull at the end of contact, would give {anagnostopoulos_xi:.4}",
                shown(*restitution)
            ),
            Warning::Instantaneous => write!(
                f,
                "stereomechanics exchanges the impulse instantaneously: no force history, no peak force, zero duration"
            ),
            Warning::FeLinkUnresolved { dt_s, link_step_s } => write!(
                f,
                "the step {dt_s:.3e} s does not resolve the contact link's oscillation with the end nodes ({link_step_s:.3e} s) and refining would exceed solver.max_steps: stable, but the link's energy is not accurate"
            ),
            Warning::FeLinkChatter {
                link_n_m,
                element_n_m,
            } => write!(
                f,
                "the contact link ({link_n_m:.3e} N/m at the peak force) is {:.0} times stiffer than the end elements (E A / dx = {element_n_m:.3e} N/m): the end nodes chatter and the run is not converged in the mesh; raise fe.segments (Watanabe & Kawashima match the link to the element stiffness)",
                link_n_m / element_n_m
            ),
            Warning::OutsideValidated(what) => write!(
                f,
                "outside the validated range: {what} (validated: {VALIDATED})"
            ),
            Warning::NotApproaching { approach_m_s } => write!(
                f,
                "the bars are not approaching (v1 - v2 = {} m/s <= 0): no impact; give bar1.velocity > bar2.velocity",
                shown(*approach_m_s)
            ),
            Warning::PaperCreatesEnergy { percent, a_tau } => write!(
                f,
                "the paper reading created energy: the bars end with {percent:.3}% more energy than they started with (a tau = {a_tau:.3}; above pi/2 this reading oscillates and creates energy once separation clips the force); use sears.reading = collocated or end for an energy-consistent answer"
            ),
            Warning::PaperOvershoots { a_tau } => write!(
                f,
                "a tau = {a_tau:.3} > 1/e: the paper reading overshoots the wave-theory force in this regime"
            ),
        }
    }
}
