//! What `pounding bridge` prints: a readable summary and a JSON report.

use super::building_report::{MotionJson, motion_line};
use pounding::io::bridge_settings::BridgeSetup;
use pounding::model::bridge::{BridgeErrorEstimate, BridgeResult};
use pounding::model::motion::GroundMotion;
use serde::Serialize;
use std::fmt::Write;

#[derive(Serialize)]
pub struct JointJson {
    pub index: usize,
    /// abutment or girder.
    pub kind: &'static str,
    /// Distance from the left abutment [m].
    pub position_m: f64,
    pub gap_m: f64,
    /// The element's stiffness there.
    pub stiffness: f64,
}

#[derive(Serialize)]
pub struct ImpactJson {
    /// The joint it happened at (an index into `joints`).
    pub joint: usize,
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
    pub joint: usize,
    pub start_s: f64,
    pub end_s: f64,
    pub peak_force_n: f64,
    pub impulse_ns: f64,
    pub approach_velocity_m_s: f64,
}

#[derive(Serialize)]
pub struct UnseatingJson {
    pub joint: usize,
    pub time_s: f64,
}

#[derive(Serialize)]
pub struct FrameJson {
    /// The two periods of the frame (pier top and girder) [s], longest first.
    pub periods_s: Vec<f64>,
    pub girder_mass_kg: f64,
    pub girder_wave_speed_m_s: f64,
    pub girder_round_trip_s: f64,
    /// Where its ground point is, and how late the motion reaches it [s].
    pub ground_point_m: f64,
    pub delay_s: f64,
}

#[derive(Serialize)]
pub struct BridgeErrorJson {
    pub max_force_rel: f64,
    pub peak_displacement_rel: f64,
    pub max_opening_rel: f64,
    pub impact_time_rel: f64,
    pub impact_count_change: i64,
    pub estimate_time_s: f64,
}

#[derive(Serialize)]
pub struct BridgeReport {
    pub preset: String,
    pub contact_model: &'static str,
    pub motion: MotionJson,
    /// The record's removed baseline c0 + c1 t [m/s^2, m/s^3].
    pub baseline_c0_m_s2: f64,
    pub baseline_c1_m_s3: f64,
    /// [m/s]; null: uniform excitation.
    pub apparent_velocity_m_s: Option<f64>,
    pub spans: usize,
    pub length_m: f64,
    pub run_duration_s: f64,
    pub frames: Vec<FrameJson>,
    pub joints: Vec<JointJson>,
    pub impacts: Vec<ImpactJson>,
    pub contacts: Vec<ContactJson>,
    pub impact_count: usize,
    pub contact_count: usize,
    pub merge_gap_s: f64,
    pub max_pounding_force_n: f64,
    pub max_force_by_joint_n: Vec<f64>,
    /// Per joint, the largest closing in the same run without contact.
    pub required_gaps_m: Vec<f64>,
    pub max_openings_m: Vec<f64>,
    pub max_openings_no_pounding_m: Vec<f64>,
    pub seat_length_m: f64,
    /// The seat length less the largest opening, per joint.
    pub seat_margins_m: Vec<f64>,
    pub unseating: Vec<UnseatingJson>,
    pub unseating_no_pounding: Vec<UnseatingJson>,
    pub peak_girder_displacements_m: Vec<f64>,
    pub peak_pier_displacements_m: Vec<f64>,
    pub peak_bearing_displacements_m: Vec<f64>,
    pub peak_girder_displacements_no_pounding_m: Vec<f64>,
    pub peak_pier_displacements_no_pounding_m: Vec<f64>,
    pub peak_bearing_displacements_no_pounding_m: Vec<f64>,
    pub energy_initial_j: f64,
    pub energy_input_j: f64,
    pub energy_differential_input_j: f64,
    pub energy_frame_damping_j: f64,
    pub energy_contact_j: f64,
    pub energy_girder_waves_j: f64,
    pub energy_stored_contact_j: f64,
    pub energy_final_j: f64,
    pub energy_balance_error: f64,
    pub steps: usize,
    pub contact_steps: usize,
    /// Contact steps over all steps.
    pub contact_share: f64,
    pub step_s: f64,
    pub steps_per_scale: f64,
    pub solve_time_s: f64,
    /// Bounds on the relative errors, from the same run with its step halved (twice the
    /// difference); the change in the impact count.
    pub error_estimate: Option<BridgeErrorJson>,
    pub warnings: Vec<String>,
}

fn unseating(r: &BridgeResult) -> Vec<UnseatingJson> {
    r.unseating
        .iter()
        .map(|u| UnseatingJson {
            joint: u.joint,
            time_s: u.time_s,
        })
        .collect()
}

fn frames(setup: &BridgeSetup) -> Vec<FrameJson> {
    let sc = &setup.scenario;
    (0..sc.spans)
        .map(|i| {
            let g = sc.girder(i);
            let x = sc.frame_position_m(i);
            FrameJson {
                periods_s: sc.frame_modes(i).periods_s(),
                girder_mass_kg: g.mass_kg,
                girder_wave_speed_m_s: g.wave_speed_m_s(),
                girder_round_trip_s: g.round_trip_s(),
                ground_point_m: x,
                delay_s: sc.delay_s(x),
            }
        })
        .collect()
}

/// The result, its run without contact and its estimate.
pub struct Runs<'a> {
    pub result: &'a BridgeResult,
    pub baseline: &'a BridgeResult,
    pub estimate: Option<&'a BridgeErrorEstimate>,
}

impl BridgeReport {
    pub fn new(setup: &BridgeSetup, preset: &str, motion: &GroundMotion, runs: &Runs) -> Self {
        let (r, base) = (runs.result, runs.baseline);
        let sc = &setup.scenario;
        let correction = motion.baseline_corrected().1;
        BridgeReport {
            preset: preset.to_string(),
            contact_model: r.contact.name(),
            motion: MotionJson::of(motion),
            baseline_c0_m_s2: correction.c0_m_s2,
            baseline_c1_m_s3: correction.c1_m_s3,
            apparent_velocity_m_s: sc.apparent_velocity_m_s,
            spans: sc.spans,
            length_m: sc.length_m(),
            run_duration_s: r.duration_s,
            frames: frames(setup),
            joints: r
                .joints
                .iter()
                .enumerate()
                .map(|(index, j)| JointJson {
                    index,
                    kind: j.kind(),
                    position_m: j.position_m,
                    gap_m: j.gap_m,
                    stiffness: sc.joint_stiffness(j),
                })
                .collect(),
            impacts: r
                .impacts
                .iter()
                .map(|e| ImpactJson {
                    joint: e.level,
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
                    joint: c.level,
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
            max_force_by_joint_n: r.max_force_by_joint_n.clone(),
            required_gaps_m: base.max_closing_m.iter().map(|c| c.max(0.0)).collect(),
            max_openings_m: r.max_opening_m.clone(),
            max_openings_no_pounding_m: base.max_opening_m.clone(),
            seat_length_m: sc.seat_length_m,
            seat_margins_m: r
                .max_opening_m
                .iter()
                .map(|o| sc.seat_length_m - o)
                .collect(),
            unseating: unseating(r),
            unseating_no_pounding: unseating(base),
            peak_girder_displacements_m: r.peak_girder_displacement_m.clone(),
            peak_pier_displacements_m: r.peak_pier_displacement_m.clone(),
            peak_bearing_displacements_m: r.peak_bearing_displacement_m.clone(),
            peak_girder_displacements_no_pounding_m: base.peak_girder_displacement_m.clone(),
            peak_pier_displacements_no_pounding_m: base.peak_pier_displacement_m.clone(),
            peak_bearing_displacements_no_pounding_m: base.peak_bearing_displacement_m.clone(),
            energy_initial_j: r.energy.initial_j,
            energy_input_j: r.energy.input_j,
            energy_differential_input_j: r.energy.differential_j,
            energy_frame_damping_j: r.energy.damping_j,
            energy_contact_j: r.energy.contact_j,
            energy_girder_waves_j: r.energy.girder_waves_j,
            energy_stored_contact_j: r.energy.stored_contact_j,
            energy_final_j: r.energy.final_j,
            energy_balance_error: r.energy.balance_error(),
            steps: r.stats.steps,
            contact_steps: r.stats.contact_steps,
            contact_share: r.stats.contact_steps as f64 / r.stats.steps.max(1) as f64,
            step_s: r.stats.step_s,
            steps_per_scale: r.stats.steps_per_scale,
            solve_time_s: r.stats.wall_time_s,
            error_estimate: runs.estimate.map(|e| BridgeErrorJson {
                max_force_rel: e.max_force,
                peak_displacement_rel: e.peak_displacement,
                max_opening_rel: e.opening,
                impact_time_rel: e.impact_time,
                impact_count_change: e.impact_count_change,
                estimate_time_s: e.wall_time_s,
            }),
            warnings: r.warnings.clone(),
        }
    }
}

fn mm(xs: &[f64]) -> String {
    let v: Vec<String> = xs.iter().map(|x| format!("{:.1}", x * 1e3)).collect();
    v.join(" / ")
}

/// The readable summary.
pub fn summary(setup: &BridgeSetup, preset: &str, motion: &GroundMotion, runs: &Runs) -> String {
    let report = BridgeReport::new(setup, preset, motion, runs);
    let mut o = String::new();
    bridge_lines(&mut o, setup, preset, motion, runs, &report);
    joint_table(&mut o, runs, &report);
    result_lines(&mut o, runs);
    cost_lines(&mut o, runs, &report);
    o
}

/// The bridge, its record and each frame's periods, girder and round trip.
fn bridge_lines(
    o: &mut String,
    setup: &BridgeSetup,
    preset: &str,
    motion: &GroundMotion,
    runs: &Runs,
    report: &BridgeReport,
) {
    let r = runs.result;
    let sc = &setup.scenario;
    let _ = writeln!(
        o,
        "Pounding Lab bridge: contact {}, preset {preset}",
        r.contact.name()
    );
    let _ = writeln!(o, "{}", motion_line(motion));
    let _ = writeln!(
        o,
        "  {} spans, {:.1} m abutment to abutment; ground motion {}; run {:.2} s",
        sc.spans,
        sc.length_m(),
        match sc.apparent_velocity_m_s {
            Some(v) => format!(
                "travelling at {v} m/s (far abutment {:.3} s late)",
                sc.delay_s(sc.length_m())
            ),
            None => "uniform".into(),
        },
        r.duration_s
    );
    for (i, f) in report.frames.iter().enumerate() {
        let _ = writeln!(
            o,
            "  frame {}: periods {:.3} / {:.3} s, girder {:.0} t, round trip {:.1} ms",
            i + 1,
            f.periods_s[0],
            f.periods_s[1],
            f.girder_mass_kg * 1e-3,
            f.girder_round_trip_s * 1e3
        );
    }
}

/// Each joint's gap, the gap it needs, its opening against the seat, its force and impacts.
fn joint_table(o: &mut String, runs: &Runs, report: &BridgeReport) {
    let r = runs.result;
    let _ = writeln!(
        o,
        "joint  kind      gap [mm]  required [mm]  max opening [mm]  seat margin [mm]  max force [MN]  impacts"
    );
    for (j, joint) in report.joints.iter().enumerate() {
        let count = r.impacts.iter().filter(|e| e.level == j).count();
        let _ = writeln!(
            o,
            "{j:>5}  {:<8}  {:>8.1}  {:>13.1}  {:>16.1}  {:>16.1}  {:>14.3}  {count:>7}",
            joint.kind,
            joint.gap_m * 1e3,
            report.required_gaps_m[j] * 1e3,
            report.max_openings_m[j] * 1e3,
            report.seat_margins_m[j] * 1e3,
            report.max_force_by_joint_n[j] * 1e-6
        );
    }
}

/// The impacts, the peaks with and without pounding, and any unseating.
fn result_lines(o: &mut String, runs: &Runs) {
    let (r, base) = (runs.result, runs.baseline);
    let _ = writeln!(o, "results");
    let _ = writeln!(
        o,
        "  impacts {} ({} contacts), max force {:.4e} N",
        r.impacts.len(),
        r.contacts.len(),
        r.max_pounding_force_n
    );
    let _ = writeln!(
        o,
        "  peak girder displacement [mm] {} (without pounding {})",
        mm(&r.peak_girder_displacement_m),
        mm(&base.peak_girder_displacement_m)
    );
    let _ = writeln!(
        o,
        "  peak pier displacement [mm]   {} (without pounding {})",
        mm(&r.peak_pier_displacement_m),
        mm(&base.peak_pier_displacement_m)
    );
    let _ = writeln!(
        o,
        "  peak bearing displacement [mm] {} (without pounding {})",
        mm(&r.peak_bearing_displacement_m),
        mm(&base.peak_bearing_displacement_m)
    );
    for u in &r.unseating {
        let _ = writeln!(o, "  joint {} UNSEATED at {:.3} s", u.joint, u.time_s);
    }
}

/// Where the energy went, what the run cost, its error bounds and its warnings.
fn cost_lines(o: &mut String, runs: &Runs, report: &BridgeReport) {
    let r = runs.result;
    let e = &r.energy;
    let _ = writeln!(
        o,
        "  energy [kJ]: input {:.1}, differential {:.1}; frame damping {:.1}, contact {:.1}, girder waves {:.1}, left {:.1}; balance {:.1e}",
        e.input_j * 1e-3,
        e.differential_j * 1e-3,
        e.damping_j * 1e-3,
        e.contact_j * 1e-3,
        e.girder_waves_j * 1e-3,
        (e.final_j + e.stored_contact_j) * 1e-3,
        e.balance_error()
    );
    let _ = writeln!(
        o,
        "cost: {} steps of {:.3e} s, {} in contact ({:.1}%), {:.1} ms",
        r.stats.steps,
        r.stats.step_s,
        r.stats.contact_steps,
        100.0 * report.contact_share,
        r.stats.wall_time_s * 1e3
    );
    if let Some(est) = runs.estimate {
        let _ = writeln!(
            o,
            "error bounds (step halved, twice the difference): max force {:.1e}, peaks {:.1e}, openings {:.1e}, impact times {:.1e}; impacts {:+}",
            est.max_force,
            est.peak_displacement,
            est.opening,
            est.impact_time,
            est.impact_count_change
        );
    }
    if !r.warnings.is_empty() {
        let _ = writeln!(o, "warnings");
        for w in &r.warnings {
            let _ = writeln!(o, "  - {w}");
        }
    }
}
