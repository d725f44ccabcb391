//! What the command line prints about an impact: a readable summary and a JSON report.

use pounding::io::settings::ImpactSetup;
use pounding::model::bar::{Bar, EndShape};
use pounding::model::impact::estimate::ErrorEstimate;
use pounding::model::impact::{ImpactResult, ModelKind};
use pounding::model::settings::shown;
use serde::Serialize;
use std::fmt::Write;

#[derive(Serialize)]
pub struct ContactJson {
    /// When the bars touch and part.
    pub start_s: f64,
    pub end_s: Option<f64>,
    /// How long the force stays above 1e-6 of its peak, and from when to when.
    pub duration_s: Option<f64>,
    pub loaded_start_s: f64,
    pub loaded_end_s: Option<f64>,
    /// How long the bars touch, loaded or not.
    pub touching_s: Option<f64>,
    pub peak_force_n: f64,
    pub impulse_ns: f64,
}

#[derive(Serialize)]
pub struct EnergyJson {
    pub initial_j: f64,
    pub rigid_body_j: f64,
    pub vibration_j: f64,
    pub dissipated_j: f64,
    pub contact_j: f64,
}

#[derive(Serialize)]
pub struct ErrorJson {
    pub method: &'static str,
    pub peak_force_rel: f64,
    pub contact_duration_rel: f64,
    pub impulse_rel: f64,
    pub restitution_abs: f64,
    pub estimate_time_s: f64,
}

#[derive(Serialize)]
pub struct SearsJson {
    pub reading: &'static str,
    pub zone_lengths_m: [f64; 2],
    pub plane_delays_s: [f64; 2],
    pub tangent_stiffness_n_m: f64,
    pub a_tau: f64,
    pub creates_energy: bool,
}

/// The `--json` object. Field names carry SI units; these names are an interface.
#[derive(Serialize)]
pub struct ImpactReport {
    pub preset: String,
    pub model: &'static str,
    pub impact: bool,
    pub peak_force_n: Option<f64>,
    /// How long the first contact's force stays above 1e-6 of its peak.
    pub contact_duration_s: f64,
    /// How long the bars touch in the first contact, loaded or not.
    pub touching_duration_s: f64,
    pub restitution: f64,
    pub restitution_first_contact: f64,
    pub impulse_ns: f64,
    /// Number of contact intervals in the simulated span.
    pub contacts: usize,
    pub contact_events: Vec<ContactJson>,
    pub recontact_s: Option<f64>,
    pub masses_kg: [f64; 2],
    pub velocities_before_m_s: [f64; 2],
    pub velocities_after_m_s: [f64; 2],
    pub energy: EnergyJson,
    pub energy_balance_error: f64,
    pub sears: Option<SearsJson>,
    pub steps: usize,
    pub dt_s: f64,
    pub refined_from_dt_s: Option<f64>,
    pub simulated_until_s: f64,
    pub solve_time_s: f64,
    /// Step-doubling estimate of the numerical error (null when it could not be made).
    pub error_estimate: Option<ErrorJson>,
    pub warnings: Vec<String>,
}

impl ImpactReport {
    pub fn new(
        setup: &ImpactSetup,
        preset: &str,
        r: &ImpactResult,
        est: Option<&ErrorEstimate>,
    ) -> Self {
        ImpactReport {
            preset: preset.to_string(),
            model: setup.model.name(),
            impact: r.impact,
            peak_force_n: r.peak_force_n,
            contact_duration_s: r.contact_duration_s,
            touching_duration_s: r.touching_duration_s,
            restitution: r.restitution,
            restitution_first_contact: r.restitution_first_contact,
            impulse_ns: r.impulse_ns,
            contacts: r.contacts.len(),
            contact_events: r
                .contacts
                .iter()
                .map(|c| ContactJson {
                    start_s: c.start_s,
                    end_s: c.end_s,
                    duration_s: c.duration_s(),
                    loaded_start_s: c.loaded_start_s,
                    loaded_end_s: c.loaded_end_s,
                    touching_s: c.touching_s(),
                    peak_force_n: c.peak_force_n,
                    impulse_ns: c.impulse_ns,
                })
                .collect(),
            recontact_s: r.recontact_s(),
            masses_kg: r.masses_kg,
            velocities_before_m_s: r.initial_velocities_m_s,
            velocities_after_m_s: r.velocities_after_m_s,
            energy: EnergyJson {
                initial_j: r.energy.initial_j,
                rigid_body_j: r.energy.rigid_body_j,
                vibration_j: r.energy.vibration_j,
                dissipated_j: r.energy.dissipated_j,
                contact_j: r.energy.contact_j,
            },
            energy_balance_error: r.energy.balance_error,
            sears: r.sears.map(|s| SearsJson {
                reading: s.reading.name(),
                zone_lengths_m: s.zone_lengths_m,
                plane_delays_s: s.plane_delays_s,
                tangent_stiffness_n_m: s.tangent_stiffness_n_m,
                a_tau: s.a_tau,
                creates_energy: s.creates_energy,
            }),
            steps: r.stats.steps,
            dt_s: r.stats.dt_s,
            refined_from_dt_s: r.stats.refined_from_s,
            simulated_until_s: r.end_s,
            solve_time_s: r.stats.wall_time_s,
            error_estimate: est.map(|e| ErrorJson {
                method: e.method,
                peak_force_rel: e.peak_force,
                contact_duration_rel: e.contact_duration,
                impulse_rel: e.impulse,
                restitution_abs: e.restitution,
                estimate_time_s: e.wall_time_s,
            }),
            warnings: r.warnings.iter().map(|w| w.to_string()).collect(),
        }
    }
}

fn bar_line(name: &str, b: &Bar) -> String {
    let end = match b.end {
        EndShape::Flat => "flat end".to_string(),
        EndShape::Rounded { radius_m } => format!("end rounded r = {} m", shown(radius_m)),
    };
    format!(
        "  {name}: L = {} m, A = {:.4e} m^2, E = {:.4e} Pa, rho~ = {:.1} kg/m^3, m = {:.4} kg, c = {:.1} m/s, Z = {:.4e} N s/m, v = {} m/s, {end}\n",
        shown(b.length_m),
        b.area_m2(),
        b.material.youngs_modulus_pa,
        b.effective_density_kg_m3(),
        b.mass_kg(),
        b.wave_speed_m_s(),
        b.impedance_n_s_m(),
        shown(b.velocity_m_s)
    )
}

/// The human-readable summary.
pub fn summary(
    setup: &ImpactSetup,
    preset: &str,
    r: &ImpactResult,
    est: Option<&ErrorEstimate>,
) -> String {
    let sc = &setup.scenario;
    let mut s = String::new();
    let reading = if setup.model == ModelKind::Sears {
        format!(" ({} reading)", sc.reading.name())
    } else {
        String::new()
    };
    let _ = writeln!(
        s,
        "Pounding Lab impact: model {}{reading}, preset {preset}",
        setup.model.name()
    );
    s += &bar_line("bar 1", &sc.bar1);
    s += &bar_line("bar 2", &sc.bar2);
    if let Ok(law) = sc.contact_law() {
        let unit = if law.kind == pounding::model::contact::LawKind::Hertz {
            "N/m^1.5"
        } else {
            "N/m"
        };
        let _ = writeln!(
            s,
            "  contact: {} law, k = {:.4e} {unit}",
            law.kind.name(),
            law.stiffness
        );
    }
    let _ = writeln!(s, "results");
    outcome(&mut s, r);
    energy_and_sears(&mut s, r);
    cost(&mut s, r, est);
    if !r.warnings.is_empty() {
        let _ = writeln!(s, "warnings");
        for w in &r.warnings {
            let _ = writeln!(s, "  - {w}");
        }
    }
    s
}

/// What the impact did: force, duration, impulse, rebound and contacts.
fn outcome(s: &mut String, r: &ImpactResult) {
    if !r.impact {
        let _ = writeln!(s, "  no impact");
    }
    match r.peak_force_n {
        Some(p) => {
            let _ = writeln!(s, "  peak force          {p:.6e} N");
        }
        None => {
            let _ = writeln!(s, "  peak force          none (instantaneous exchange)");
        }
    }
    let _ = writeln!(
        s,
        "  contact duration    {:.6e} s (force above 1e-6 of its peak; touching {:.6e} s)",
        r.contact_duration_s, r.touching_duration_s
    );
    let _ = writeln!(s, "  impulse             {:.6e} N s", r.impulse_ns);
    let _ = writeln!(
        s,
        "  restitution e       {:.6} (after the first contact: {:.6})",
        r.restitution, r.restitution_first_contact
    );
    let [v1, v2] = r.velocities_after_m_s;
    let _ = writeln!(
        s,
        "  velocities after    V1 = {v1:.6} m/s, V2 = {v2:.6} m/s"
    );
    let recontact = match r.recontact_s() {
        Some(t) => format!("touched again at {t:.6e} s"),
        None => "no second contact in the simulated span".into(),
    };
    let _ = writeln!(
        s,
        "  contacts            {} ({recontact}; simulated until {:.6e} s)",
        r.contacts.len(),
        r.end_s
    );
}

/// Where the energy went, and the Sears model's own numbers.
fn energy_and_sears(s: &mut String, r: &ImpactResult) {
    let e = &r.energy;
    let _ = writeln!(
        s,
        "  energy              initial {:.6e} J = rigid body {:.6e} + vibration {:.6e} + dissipated {:.6e} + contact {:.6e}; balance error {:+.3e}",
        e.initial_j, e.rigid_body_j, e.vibration_j, e.dissipated_j, e.contact_j, e.balance_error
    );
    if let Some(d) = &r.sears {
        let regime = d.regime();
        let _ = writeln!(
            s,
            "  Sears               zone d = {:.4e} / {:.4e} m, plane delays {:.4e} / {:.4e} s, a tau = {:.4} {regime}",
            d.zone_lengths_m[0],
            d.zone_lengths_m[1],
            d.plane_delays_s[0],
            d.plane_delays_s[1],
            d.a_tau
        );
    }
}

/// The steps the run took, its time and its error estimate.
fn cost(s: &mut String, r: &ImpactResult, est: Option<&ErrorEstimate>) {
    let refined = r
        .stats
        .refined_from_s
        .map(|d| format!(", refined from {d:e} s"))
        .unwrap_or_default();
    let _ = writeln!(
        s,
        "  solve               {} steps of {:.4e} s{refined}, {:.3} ms",
        r.stats.steps,
        r.stats.dt_s,
        r.stats.wall_time_s * 1e3
    );
    if let Some(e) = est {
        let _ = if e.method == "exact" {
            writeln!(s, "  error estimate      exact (no step)")
        } else {
            writeln!(
                s,
                "  error estimate      peak {:.1e}, duration {:.1e}, impulse {:.1e} (relative), e {:.1e} (by {} doubling, {:.3} ms)",
                e.peak_force,
                e.contact_duration,
                e.impulse,
                e.restitution,
                e.method,
                e.wall_time_s * 1e3
            )
        };
    }
}
