//! What `pounding buildings` prints: a readable summary and a JSON report.

use pounding::io::building_settings::BuildingSetup;
use pounding::model::building::{BuildingErrorEstimate, BuildingResult, ContactModel};
use pounding::model::motion::{G, GroundMotion};
use serde::Serialize;
use std::fmt::Write;

#[derive(Serialize)]
pub struct ImpactJson {
    pub start_s: f64,
    pub end_s: f64,
    pub duration_s: f64,
    pub peak_force_n: f64,
    pub impulse_ns: f64,
    pub approach_velocity_m_s: f64,
    /// Raw contacts inside this impact.
    pub contacts: usize,
    pub first_contact: usize,
}

#[derive(Serialize)]
pub struct ContactJson {
    pub start_s: f64,
    pub end_s: f64,
    pub peak_force_n: f64,
    pub impulse_ns: f64,
    pub approach_velocity_m_s: f64,
}

#[derive(Serialize)]
pub struct MotionJson {
    pub name: String,
    pub points: usize,
    pub dt_s: f64,
    pub duration_s: f64,
    pub pga_m_s2: f64,
    pub pga_g: f64,
    pub pgv_m_s: f64,
    pub arias_m_s: f64,
    pub significant_duration_s: f64,
    pub predominant_period_s: f64,
    pub peak_spectral_accel_m_s2: f64,
}

/// The `--json` object of `pounding buildings`; names carry SI units and are an interface.
#[derive(Serialize)]
pub struct BuildingReport {
    pub preset: String,
    pub contact_model: &'static str,
    pub motion: MotionJson,
    /// Impact events (raw contacts merged when closer than `merge_gap_s`).
    pub impacts: Vec<ImpactJson>,
    /// Raw contact intervals.
    pub contacts: Vec<ContactJson>,
    pub impact_count: usize,
    pub contact_count: usize,
    pub merge_gap_s: f64,
    pub max_pounding_force_n: f64,
    pub strongest_impact: Option<usize>,
    pub peak_displacement_left_m: f64,
    pub peak_displacement_right_m: f64,
    pub peak_displacement_left_no_pounding_m: f64,
    pub peak_displacement_right_no_pounding_m: f64,
    pub energy_input_j: f64,
    pub energy_building_damping_j: f64,
    pub energy_to_contact_j: f64,
    pub energy_balance_error: f64,
    pub steps: usize,
    pub contact_steps: usize,
    pub fine_step_s: f64,
    pub coarse_step_s: f64,
    pub solve_time_s: f64,
    /// Step-doubling estimate: relative errors of the max force and the peak displacements, and
    /// the change of the impact count with twice the step.
    pub error_estimate: Option<BuildingErrorJson>,
    pub warnings: Vec<String>,
}

#[derive(Serialize)]
pub struct BuildingErrorJson {
    pub max_force_rel: f64,
    pub peak_displacement_rel: f64,
    pub impact_count_change: i64,
    pub estimate_time_s: f64,
}

fn balance_error(r: &BuildingResult) -> f64 {
    let e = &r.energy;
    let residual = e.input_j - e.building_damping_j - e.contact_j - e.final_j - e.stored_contact_j;
    if e.input_j.abs() > 0.0 {
        residual / e.input_j.abs()
    } else {
        0.0
    }
}

impl BuildingReport {
    pub fn new(
        setup: &BuildingSetup,
        preset: &str,
        motion: &GroundMotion,
        r: &BuildingResult,
        baseline: &BuildingResult,
        est: Option<&BuildingErrorEstimate>,
    ) -> Self {
        let s = motion.stats();
        let strongest = r
            .impacts
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.peak_force_n.total_cmp(&b.1.peak_force_n))
            .map(|(i, _)| i + 1);
        BuildingReport {
            preset: preset.to_string(),
            contact_model: r.contact.name(),
            motion: MotionJson {
                name: motion.name.clone(),
                points: s.points,
                dt_s: motion.dt_s,
                duration_s: s.duration_s,
                pga_m_s2: s.pga_m_s2,
                pga_g: s.pga_m_s2 / G,
                pgv_m_s: s.pgv_m_s,
                arias_m_s: s.arias_m_s,
                significant_duration_s: s.significant_duration_s,
                predominant_period_s: s.predominant_period_s,
                peak_spectral_accel_m_s2: s.peak_spectral_accel_m_s2,
            },
            impacts: r
                .impacts
                .iter()
                .map(|e| ImpactJson {
                    start_s: e.start_s,
                    end_s: e.end_s,
                    duration_s: e.duration_s(),
                    peak_force_n: e.peak_force_n,
                    impulse_ns: e.impulse_ns,
                    approach_velocity_m_s: e.approach_velocity_m_s,
                    contacts: e.contacts.len(),
                    first_contact: e.contacts.start,
                })
                .collect(),
            contacts: r
                .contacts
                .iter()
                .map(|c| ContactJson {
                    start_s: c.start_s,
                    end_s: c.end_s,
                    peak_force_n: c.peak_force_n,
                    impulse_ns: c.impulse_ns,
                    approach_velocity_m_s: c.approach_velocity_m_s,
                })
                .collect(),
            impact_count: r.impacts.len(),
            contact_count: r.contacts.len(),
            merge_gap_s: setup.scenario.merge_gap_s,
            max_pounding_force_n: r.max_pounding_force_n,
            strongest_impact: strongest,
            peak_displacement_left_m: r.peak_displacement_m[0],
            peak_displacement_right_m: r.peak_displacement_m[1],
            peak_displacement_left_no_pounding_m: baseline.peak_displacement_m[0],
            peak_displacement_right_no_pounding_m: baseline.peak_displacement_m[1],
            energy_input_j: r.energy.input_j,
            energy_building_damping_j: r.energy.building_damping_j,
            energy_to_contact_j: r.energy.contact_j,
            energy_balance_error: balance_error(r),
            steps: r.stats.steps,
            contact_steps: r.stats.contact_steps,
            fine_step_s: r.stats.fine_step_s,
            coarse_step_s: r.stats.coarse_step_s,
            solve_time_s: r.stats.wall_time_s,
            error_estimate: est.map(|e| BuildingErrorJson {
                max_force_rel: e.max_force,
                peak_displacement_rel: e.peak_displacement,
                impact_count_change: e.impact_count_change,
                estimate_time_s: e.wall_time_s,
            }),
            warnings: r.warnings.clone(),
        }
    }
}

pub fn summary(
    setup: &BuildingSetup,
    preset: &str,
    motion: &GroundMotion,
    r: &BuildingResult,
    baseline: &BuildingResult,
    est: Option<&BuildingErrorEstimate>,
) -> String {
    let sc = &setup.scenario;
    let s = motion.stats();
    let mut o = String::new();
    let _ = writeln!(
        o,
        "Pounding Lab buildings: contact {}, preset {preset}",
        r.contact.name()
    );
    let _ = writeln!(
        o,
        "  motion: {} | {} points at {} s, {:.2} s | PGA {:.4} g at {:.2} s | PGV {:.3} m/s | Arias {:.3} m/s | 5-95% duration {:.2} s | 5% spectrum peaks at {:.2} s ({:.3} g)",
        motion.name,
        s.points,
        motion.dt_s,
        s.duration_s,
        s.pga_m_s2 / G,
        s.pga_time_s,
        s.pgv_m_s,
        s.arias_m_s,
        s.significant_duration_s,
        s.predominant_period_s,
        s.peak_spectral_accel_m_s2 / G
    );
    for (name, b) in [("left ", &sc.left), ("right", &sc.right)] {
        let _ = writeln!(
            o,
            "  {name}: m = {} kg, k = {:.4e} N/m, T = {:.3} s, damping {:.1}%, slab {} x {} x {} m (E = {:.3e} Pa, c = {:.0} m/s, round trip {:.2} ms)",
            b.mass_kg,
            b.stiffness_n_m,
            b.period_s(),
            100.0 * b.damping_ratio,
            b.slab.length_m,
            b.slab.width_m,
            b.slab.thickness_m,
            b.slab.youngs_modulus_pa,
            b.slab_wave_speed_m_s(),
            1e3 * b.slab_round_trip_s()
        );
    }
    let mut contact = format!(
        "  contact: gap {} m, stiffness {:.4e}",
        sc.gap_m,
        sc.element_stiffness()
    );
    if sc.contact == ContactModel::Sears {
        let _ = write!(
            contact,
            ", {} reading, zone d = {} m, slab damping {:.1}%",
            if sc.reading == pounding::model::building::SlabReading::Paper {
                "paper"
            } else {
                "end"
            },
            sc.zone_length(),
            100.0 * sc.slab_damping
        );
    }
    if matches!(
        sc.contact,
        ContactModel::Kelvin
            | ContactModel::HertzDamp
            | ContactModel::Jankowski
            | ContactModel::Stereo
    ) {
        let _ = write!(contact, ", restitution {}", sc.restitution);
    }
    let _ = writeln!(o, "{contact}");
    let _ = writeln!(o, "results");
    let _ = writeln!(
        o,
        "  impacts             {} events ({} raw contacts, merged when closer than {} s)",
        r.impacts.len(),
        r.contacts.len(),
        sc.merge_gap_s
    );
    let strongest = r
        .impacts
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.peak_force_n.total_cmp(&b.1.peak_force_n));
    if let Some((i, e)) = strongest {
        let _ = writeln!(
            o,
            "  max pounding force  {:.4e} N (impact {} of {}, at {:.3} s)",
            r.max_pounding_force_n,
            i + 1,
            r.impacts.len(),
            e.start_s
        );
    }
    let _ = writeln!(
        o,
        "  peak displacement   left {:.5} m (without pounding {:.5} m), right {:.5} m (without pounding {:.5} m)",
        r.peak_displacement_m[0],
        baseline.peak_displacement_m[0],
        r.peak_displacement_m[1],
        baseline.peak_displacement_m[1]
    );
    let e = &r.energy;
    let _ = writeln!(
        o,
        "  energy              input {:.4e} J = building damping {:.4e} + to the contact {:.4e} + left in the buildings {:.4e}; balance error {:+.2e}",
        e.input_j,
        e.building_damping_j,
        e.contact_j,
        e.final_j + e.stored_contact_j,
        balance_error(r)
    );
    let _ = writeln!(
        o,
        "  solve               {} steps ({} in contact, fine step {:.3e} s, coarse {:.3e} s), {:.2} ms",
        r.stats.steps,
        r.stats.contact_steps,
        r.stats.fine_step_s,
        r.stats.coarse_step_s,
        1e3 * r.stats.wall_time_s
    );
    if let Some(e) = est {
        let _ = writeln!(
            o,
            "  error estimate      max force {:.1e}, peak displacement {:.1e} (relative); impact count {:+} with twice the step ({:.2} ms)",
            e.max_force,
            e.peak_displacement,
            e.impact_count_change,
            1e3 * e.wall_time_s
        );
    }
    if !r.impacts.is_empty() {
        let _ = writeln!(
            o,
            "impacts\n    #   start [s]  duration [ms]  peak force [N]  impulse [N s]  approach [m/s]  contacts"
        );
        for (i, ev) in r.impacts.iter().enumerate() {
            let _ = writeln!(
                o,
                "  {:3}  {:9.4}  {:13.3}  {:14.4e}  {:13.4e}  {:14.4}  {:8}",
                i + 1,
                ev.start_s,
                1e3 * ev.duration_s(),
                ev.peak_force_n,
                ev.impulse_ns,
                ev.approach_velocity_m_s,
                ev.contacts.len()
            );
        }
    }
    if !r.warnings.is_empty() {
        let _ = writeln!(o, "warnings");
        for w in &r.warnings {
            let _ = writeln!(o, "  - {w}");
        }
    }
    o
}
