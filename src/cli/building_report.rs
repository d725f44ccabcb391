//! What `pounding buildings` prints: a readable summary and a JSON report.

use pounding::io::building_settings::BuildingSetup;
use pounding::model::building::{
    Building, BuildingErrorEstimate, BuildingResult, BuildingScenario, ContactModel, Level,
    SlabReading,
};
use pounding::model::hysteresis::Hysteresis;
use pounding::model::motion::{G, GroundMotion};
use serde::Serialize;
use std::fmt::Write;

#[derive(Serialize)]
pub struct ImpactJson {
    /// The level it happened at (an index into `levels`).
    pub level: usize,
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
    pub level: usize,
    pub start_s: f64,
    pub end_s: f64,
    pub peak_force_n: f64,
    pub impulse_ns: f64,
    pub approach_velocity_m_s: f64,
}

#[derive(Serialize)]
pub struct LevelJson {
    pub elevation_m: f64,
    /// floor-floor or floor-column.
    pub kind: &'static str,
    /// Floors involved on each side, counted from 1 (0 is the ground): one floor, or the two
    /// floors a column point lies between.
    pub left_floors: Vec<usize>,
    pub right_floors: Vec<usize>,
    /// Where a column point lies between its floors (0 at the lower), if it is one.
    pub left_column_fraction: Option<f64>,
    pub right_column_fraction: Option<f64>,
    pub stiffness: f64,
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

/// The `--json` object of `pounding buildings`; names carry SI units and are an interface. The
/// single-valued displacement fields are the roofs'; impacts and contacts carry their level.
#[derive(Serialize)]
pub struct BuildingReport {
    pub preset: String,
    pub contact_model: &'static str,
    pub motion: MotionJson,
    pub storeys_left: usize,
    pub storeys_right: usize,
    /// Every mode's period, longest first.
    pub periods_left_s: Vec<f64>,
    pub periods_right_s: Vec<f64>,
    pub levels: Vec<LevelJson>,
    /// Impact events (raw contacts at one level merged when closer than `merge_gap_s`).
    pub impacts: Vec<ImpactJson>,
    /// Raw contact intervals.
    pub contacts: Vec<ContactJson>,
    pub impact_count: usize,
    pub contact_count: usize,
    pub merge_gap_s: f64,
    pub max_pounding_force_n: f64,
    pub max_force_by_level_n: Vec<f64>,
    pub strongest_impact: Option<usize>,
    pub peak_displacement_left_m: f64,
    pub peak_displacement_right_m: f64,
    pub peak_displacement_left_no_pounding_m: f64,
    pub peak_displacement_right_no_pounding_m: f64,
    pub peak_floor_displacements_left_m: Vec<f64>,
    pub peak_floor_displacements_right_m: Vec<f64>,
    pub peak_floor_displacements_left_no_pounding_m: Vec<f64>,
    pub peak_floor_displacements_right_no_pounding_m: Vec<f64>,
    pub peak_drift_ratios_left: Vec<f64>,
    pub peak_drift_ratios_right: Vec<f64>,
    pub peak_drift_ratios_left_no_pounding: Vec<f64>,
    pub peak_drift_ratios_right_no_pounding: Vec<f64>,
    /// Per storey, lowest first: peak drift over the yield drift F_y / k.
    pub ductility_demands_left: Vec<f64>,
    pub ductility_demands_right: Vec<f64>,
    pub ductility_demands_left_no_pounding: Vec<f64>,
    pub ductility_demands_right_no_pounding: Vec<f64>,
    /// Per storey: the drift at the end of the run (after `motion.settle_s`).
    pub residual_drifts_left_m: Vec<f64>,
    pub residual_drifts_right_m: Vec<f64>,
    pub residual_drifts_left_no_pounding_m: Vec<f64>,
    pub residual_drifts_right_no_pounding_m: Vec<f64>,
    /// Per storey: the energy its spring dissipated (zero for elastic storeys).
    pub hysteretic_energy_left_j: Vec<f64>,
    pub hysteretic_energy_right_j: Vec<f64>,
    pub hysteretic_energy_left_no_pounding_j: Vec<f64>,
    pub hysteretic_energy_right_no_pounding_j: Vec<f64>,
    /// Per storey: when its drift first reached the yield drift (null: never, or elastic).
    pub first_yield_left_s: Vec<Option<f64>>,
    pub first_yield_right_s: Vec<Option<f64>>,
    pub first_yield_left_no_pounding_s: Vec<Option<f64>>,
    pub first_yield_right_no_pounding_s: Vec<Option<f64>>,
    pub energy_initial_j: f64,
    pub energy_input_j: f64,
    pub energy_building_damping_j: f64,
    pub energy_to_contact_j: f64,
    pub energy_hysteretic_j: f64,
    pub energy_balance_error: f64,
    pub steps: usize,
    pub contact_steps: usize,
    pub fine_step_s: f64,
    pub coarse_step_s: f64,
    pub steps_per_scale: f64,
    pub tolerance: f64,
    pub solve_time_s: f64,
    /// Bounds on the relative errors, from the same run with every discretisation parameter
    /// refined twofold (twice the difference); the change in the impact count.
    pub error_estimate: Option<BuildingErrorJson>,
    pub warnings: Vec<String>,
}

#[derive(Serialize)]
pub struct BuildingErrorJson {
    pub max_force_rel: f64,
    pub peak_displacement_rel: f64,
    pub impact_time_rel: f64,
    pub impact_count_change: i64,
    pub estimate_time_s: f64,
}

impl MotionJson {
    /// The record's name, size and intensity.
    pub fn of(motion: &GroundMotion) -> Self {
        let s = motion.stats();
        MotionJson {
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
        }
    }
}

fn level_json(setup: &BuildingSetup, l: &Level) -> LevelJson {
    let fraction = |a: &pounding::model::building::Attachment| match a {
        pounding::model::building::Attachment::Column { s, .. } => Some(*s),
        _ => None,
    };
    LevelJson {
        elevation_m: l.elevation_m,
        kind: l.kind.name(),
        left_floors: l.left.floors_1_based(),
        right_floors: l.right.floors_1_based(),
        left_column_fraction: fraction(&l.left),
        right_column_fraction: fraction(&l.right),
        stiffness: setup.scenario.level_stiffness(l),
    }
}

fn strongest(r: &BuildingResult) -> Option<(usize, &pounding::model::building::ImpactEvent)> {
    r.impacts
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.peak_force_n.total_cmp(&b.1.peak_force_n))
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
        let sc = &setup.scenario;
        BuildingReport {
            preset: preset.to_string(),
            contact_model: r.contact.name(),
            motion: MotionJson::of(motion),
            storeys_left: sc.left.storeys,
            storeys_right: sc.right.storeys,
            periods_left_s: r.modes[0].periods_s(),
            periods_right_s: r.modes[1].periods_s(),
            levels: r.levels.iter().map(|l| level_json(setup, l)).collect(),
            impacts: r
                .impacts
                .iter()
                .map(|e| ImpactJson {
                    level: e.level,
                    start_s: e.start_s,
                    end_s: e.end_s,
                    duration_s: e.duration_s(),
                    peak_force_n: e.peak_force_n,
                    impulse_ns: e.impulse_ns,
                    approach_velocity_m_s: e.approach_velocity_m_s,
                    contacts: e.contacts.len(),
                    first_contact: e.contacts[0],
                })
                .collect(),
            contacts: r
                .contacts
                .iter()
                .map(|c| ContactJson {
                    level: c.level,
                    start_s: c.start_s,
                    end_s: c.end_s,
                    peak_force_n: c.peak_force_n,
                    impulse_ns: c.impulse_ns,
                    approach_velocity_m_s: c.approach_velocity_m_s,
                })
                .collect(),
            impact_count: r.impacts.len(),
            contact_count: r.contacts.len(),
            merge_gap_s: sc.merge_gap_s,
            max_pounding_force_n: r.max_pounding_force_n,
            max_force_by_level_n: r.max_force_by_level_n.clone(),
            strongest_impact: strongest(r).map(|(i, _)| i + 1),
            peak_displacement_left_m: r.peak_displacement_m[0],
            peak_displacement_right_m: r.peak_displacement_m[1],
            peak_displacement_left_no_pounding_m: baseline.peak_displacement_m[0],
            peak_displacement_right_no_pounding_m: baseline.peak_displacement_m[1],
            peak_floor_displacements_left_m: r.peak_floor_displacement_m[0].clone(),
            peak_floor_displacements_right_m: r.peak_floor_displacement_m[1].clone(),
            peak_floor_displacements_left_no_pounding_m: baseline.peak_floor_displacement_m[0]
                .clone(),
            peak_floor_displacements_right_no_pounding_m: baseline.peak_floor_displacement_m[1]
                .clone(),
            peak_drift_ratios_left: r.peak_drift_ratio[0].clone(),
            peak_drift_ratios_right: r.peak_drift_ratio[1].clone(),
            peak_drift_ratios_left_no_pounding: baseline.peak_drift_ratio[0].clone(),
            peak_drift_ratios_right_no_pounding: baseline.peak_drift_ratio[1].clone(),
            ductility_demands_left: r.ductility_demand[0].clone(),
            ductility_demands_right: r.ductility_demand[1].clone(),
            ductility_demands_left_no_pounding: baseline.ductility_demand[0].clone(),
            ductility_demands_right_no_pounding: baseline.ductility_demand[1].clone(),
            residual_drifts_left_m: r.residual_drift_m[0].clone(),
            residual_drifts_right_m: r.residual_drift_m[1].clone(),
            residual_drifts_left_no_pounding_m: baseline.residual_drift_m[0].clone(),
            residual_drifts_right_no_pounding_m: baseline.residual_drift_m[1].clone(),
            hysteretic_energy_left_j: r.hysteretic_energy_j[0].clone(),
            hysteretic_energy_right_j: r.hysteretic_energy_j[1].clone(),
            hysteretic_energy_left_no_pounding_j: baseline.hysteretic_energy_j[0].clone(),
            hysteretic_energy_right_no_pounding_j: baseline.hysteretic_energy_j[1].clone(),
            first_yield_left_s: r.first_yield_s[0].clone(),
            first_yield_right_s: r.first_yield_s[1].clone(),
            first_yield_left_no_pounding_s: baseline.first_yield_s[0].clone(),
            first_yield_right_no_pounding_s: baseline.first_yield_s[1].clone(),
            energy_initial_j: r.energy.initial_j,
            energy_input_j: r.energy.input_j,
            energy_building_damping_j: r.energy.building_damping_j,
            energy_to_contact_j: r.energy.contact_j,
            energy_hysteretic_j: r.energy.hysteretic_j,
            energy_balance_error: r.energy.balance_error(),
            steps: r.stats.steps,
            contact_steps: r.stats.contact_steps,
            fine_step_s: r.stats.fine_step_s,
            coarse_step_s: r.stats.coarse_step_s,
            steps_per_scale: r.stats.steps_per_scale,
            tolerance: sc.tolerance,
            solve_time_s: r.stats.wall_time_s,
            error_estimate: est.map(|e| BuildingErrorJson {
                max_force_rel: e.max_force,
                peak_displacement_rel: e.peak_displacement,
                impact_time_rel: e.impact_time,
                impact_count_change: e.impact_count_change,
                estimate_time_s: e.wall_time_s,
            }),
            warnings: r.warnings.iter().map(|w| w.to_string()).collect(),
        }
    }
}

/// A list of values for a summary line: one value once, several joined.
fn values(v: &[f64], scale: f64, decimals: usize) -> String {
    let shown: Vec<String> = v
        .iter()
        .map(|x| format!("{:.*}", decimals, x * scale))
        .collect();
    if shown.iter().all(|s| *s == shown[0]) && shown.len() > 1 {
        format!("{} x {}", shown.len(), shown[0])
    } else {
        shown.join(", ")
    }
}

fn building_line(name: &str, b: &Building, r: &BuildingResult, side: usize) -> String {
    let roof = b.storeys - 1;
    let slab = b.slab(roof);
    let periods = r.modes[side].periods_s();
    format!(
        "  {name}: {} storey{}, m = {} kg, k = {} N/m, h = {} m, T = {} s, damping {:.1}%, roof slab {} x {} x {} m (E = {:.3e} Pa, c = {:.0} m/s, round trip {:.2} ms)",
        b.storeys,
        if b.storeys == 1 { "" } else { "s" },
        values(&b.masses_kg, 1.0, 0),
        values(&b.stiffnesses_n_m, 1.0, 0),
        values(&b.heights_m, 1.0, 2),
        values(&periods, 1.0, 3),
        100.0 * b.damping_ratio,
        slab.length_m,
        slab.width_m,
        slab.thickness_m,
        slab.youngs_modulus_pa,
        slab.wave_speed_m_s(b.mass(roof)),
        1e3 * slab.round_trip_s(b.mass(roof))
    ) + &storey_law(b)
}

/// The storeys' law where they yield (nothing for elastic storeys).
fn storey_law(b: &Building) -> String {
    if !b.yields() {
        return String::new();
    }
    let fy: Vec<f64> = (0..b.storeys).map(|j| b.yield_force(j)).collect();
    let n = if b.hysteresis == Hysteresis::BoucWen {
        format!(", n = {}", b.bouc_wen_n)
    } else {
        String::new()
    };
    format!(
        ", {} storeys F_y = {} N, b = {}{n}",
        b.hysteresis.name(),
        values(&fy, 1.0, 0),
        b.hardening
    )
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
    let mut o = String::new();
    let _ = writeln!(
        o,
        "Pounding Lab buildings: contact {}, preset {preset}",
        r.contact.name()
    );
    let _ = writeln!(o, "{}", motion_line(motion));
    let _ = writeln!(o, "{}", building_line("left ", &sc.left, r, 0));
    let _ = writeln!(o, "{}", building_line("right", &sc.right, r, 1));
    let _ = writeln!(o, "{}", contact_line(sc));
    levels_table(&mut o, r);
    let _ = writeln!(o, "results");
    results(&mut o, sc, r, baseline);
    cost(&mut o, sc, r, est);
    impacts_table(&mut o, r);
    if !r.warnings.is_empty() {
        let _ = writeln!(o, "warnings");
        for w in &r.warnings {
            let _ = writeln!(o, "  - {w}");
        }
    }
    o
}

/// The record and the numbers that describe it.
pub(super) fn motion_line(motion: &GroundMotion) -> String {
    let s = motion.stats();
    format!(
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
    )
}

/// The gap and the element, with what only some elements use.
fn contact_line(sc: &BuildingScenario) -> String {
    let mut contact = format!(
        "  contact: gap {} m, stiffness {:.4e}",
        pounding::model::settings::shown(sc.gap_m),
        sc.element_stiffness()
    );
    if sc.contact == ContactModel::Sears {
        let _ = write!(
            contact,
            ", {} reading, zone d = {} m, slab damping {:.1}%",
            if sc.reading == SlabReading::Paper {
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
    contact
}

/// The contact levels, where there is more than one.
fn levels_table(o: &mut String, r: &BuildingResult) {
    if r.levels.len() <= 1 {
        return;
    }
    let _ = writeln!(o, "  levels");
    for (i, l) in r.levels.iter().enumerate() {
        let _ = writeln!(
            o,
            "    {:2}  {:7.3} m  {:12}  left floors {:?}, right floors {:?}",
            i + 1,
            l.elevation_m,
            l.kind.name(),
            l.left.floors_1_based(),
            l.right.floors_1_based()
        );
    }
}

/// Impacts, the strongest, the peaks with and without pounding, and the energy.
fn results(o: &mut String, sc: &BuildingScenario, r: &BuildingResult, baseline: &BuildingResult) {
    let _ = writeln!(
        o,
        "  impacts             {} events ({} raw contacts, merged when closer than {} s)",
        r.impacts.len(),
        r.contacts.len(),
        sc.merge_gap_s
    );
    if let Some((i, e)) = strongest(r) {
        let _ = writeln!(
            o,
            "  max pounding force  {:.4e} N (impact {} of {}, at {:.3} s{})",
            r.max_pounding_force_n,
            i + 1,
            r.impacts.len(),
            e.start_s,
            if r.levels.len() > 1 {
                format!(", level {}", e.level + 1)
            } else {
                String::new()
            }
        );
    }
    let storeys = sc.left.storeys > 1 || sc.right.storeys > 1;
    let _ = writeln!(
        o,
        "  peak displacement   left {:.5} m (without pounding {:.5} m), right {:.5} m (without pounding {:.5} m){}",
        r.peak_displacement_m[0],
        baseline.peak_displacement_m[0],
        r.peak_displacement_m[1],
        baseline.peak_displacement_m[1],
        if storeys { " (roofs)" } else { "" }
    );
    if storeys {
        for (side, name) in [(0, "left "), (1, "right")] {
            let _ = writeln!(
                o,
                "  {name} floors        peak {} mm (without pounding {}); drift ratio {} (without {})",
                values(&r.peak_floor_displacement_m[side], 1e3, 2),
                values(&baseline.peak_floor_displacement_m[side], 1e3, 2),
                values(&r.peak_drift_ratio[side], 1.0, 5),
                values(&baseline.peak_drift_ratio[side], 1.0, 5),
            );
        }
    }
    for (side, b) in [&sc.left, &sc.right].into_iter().enumerate() {
        if b.yields() {
            let _ = writeln!(
                o,
                "  {} storeys        ductility demand {} (without pounding {}); residual drift {} mm (without {}); hysteretic energy {} J (without {})",
                ["left ", "right"][side],
                values(&r.ductility_demand[side], 1.0, 3),
                values(&baseline.ductility_demand[side], 1.0, 3),
                values(&r.residual_drift_m[side], 1e3, 3),
                values(&baseline.residual_drift_m[side], 1e3, 3),
                values(&r.hysteretic_energy_j[side], 1.0, 1),
                values(&baseline.hysteretic_energy_j[side], 1.0, 1),
            );
        }
    }
    let e = &r.energy;
    let yielding = if e.hysteretic_j > 0.0 {
        format!(" + storeys' yielding {:.4e}", e.hysteretic_j)
    } else {
        String::new()
    };
    let initial = if e.initial_j > 0.0 {
        format!("initial {:.4e} J + ", e.initial_j)
    } else {
        String::new()
    };
    let _ = writeln!(
        o,
        "  energy              {initial}input {:.4e} J = building damping {:.4e}{yielding} + to the contact {:.4e} + left in the buildings {:.4e}; balance error {:+.2e}",
        e.input_j,
        e.building_damping_j,
        e.contact_j,
        e.final_j + e.stored_contact_j,
        e.balance_error()
    );
}

/// What the run cost, and its error estimate.
fn cost(
    o: &mut String,
    sc: &BuildingScenario,
    r: &BuildingResult,
    est: Option<&BuildingErrorEstimate>,
) {
    let _ = writeln!(
        o,
        "  solve               {} steps ({} in contact, fine step {:.3e} s, free steps up to {:.3e} s, {:.1} steps per contact time scale for a tolerance of {:e}), {:.2} ms",
        r.stats.steps,
        r.stats.contact_steps,
        r.stats.fine_step_s,
        r.stats.coarse_step_s,
        r.stats.steps_per_scale,
        sc.tolerance,
        1e3 * r.stats.wall_time_s
    );
    if let Some(e) = est {
        let _ = writeln!(
            o,
            "  error estimate      max force {:.1e}, peak displacement {:.1e}, impact times {:.1e} (relative bounds); impact count {:+} against a twice finer run ({:.2} ms)",
            e.max_force,
            e.peak_displacement,
            e.impact_time,
            e.impact_count_change,
            1e3 * e.wall_time_s
        );
    }
}

/// One row per impact.
fn impacts_table(o: &mut String, r: &BuildingResult) {
    if r.impacts.is_empty() {
        return;
    }
    let many = r.levels.len() > 1;
    let _ = writeln!(
        o,
        "impacts\n    #   start [s]  duration [ms]  peak force [N]  impulse [N s]  approach [m/s]  contacts{}",
        if many { "  level" } else { "" }
    );
    for (i, ev) in r.impacts.iter().enumerate() {
        let _ = writeln!(
            o,
            "  {:3}  {:9.4}  {:13.3}  {:14.4e}  {:13.4e}  {:14.4}  {:8}{}",
            i + 1,
            ev.start_s,
            1e3 * ev.duration_s(),
            ev.peak_force_n,
            ev.impulse_ns,
            ev.approach_velocity_m_s,
            ev.contacts.len(),
            if many {
                format!("  {:5}", ev.level + 1)
            } else {
                String::new()
            }
        );
    }
}
