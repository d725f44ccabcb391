//! CSV output of histories, with a header naming quantities and units.

use crate::model::impact::ImpactResult;
use std::io::Write;

/// Writes time, force and approach histories: `time_s,force_n,approach_m`.
pub fn write_impact_history(
    out: &mut (impl Write + ?Sized),
    r: &ImpactResult,
) -> std::io::Result<()> {
    writeln!(out, "time_s,force_n,approach_m")?;
    for i in 0..r.time_s.len() {
        writeln!(
            out,
            "{:.12e},{:.12e},{:.12e}",
            r.time_s[i], r.force_n[i], r.approach_m[i]
        )?;
    }
    Ok(())
}

/// The bridge run's histories as CSV: time, then each joint's force and opening, each girder's
/// and pier top's displacement relative to its ground.
pub fn write_bridge_history(
    out: &mut (impl Write + ?Sized),
    r: &crate::model::bridge::BridgeResult,
) -> std::io::Result<()> {
    let mut columns: Vec<(String, &[f64])> = Vec::new();
    for (j, f) in r.joint_force_n.iter().enumerate() {
        columns.push((format!("force_joint_{j}_n"), f));
    }
    for (j, o) in r.joint_opening_m.iter().enumerate() {
        columns.push((format!("opening_joint_{j}_m"), o));
    }
    for (i, u) in r.girder_displacement_m.iter().enumerate() {
        columns.push((format!("u_girder_{}_m", i + 1), u));
    }
    for (i, u) in r.pier_displacement_m.iter().enumerate() {
        columns.push((format!("u_pier_{}_m", i + 1), u));
    }
    write!(out, "time_s")?;
    for (name, _) in &columns {
        write!(out, ",{name}")?;
    }
    writeln!(out)?;
    for (i, t) in r.time_s.iter().enumerate() {
        write!(out, "{t:.9e}")?;
        for (_, c) in &columns {
            write!(out, ",{:.9e}", c[i])?;
        }
        writeln!(out)?;
    }
    Ok(())
}

/// Writes the building histories, one row per solver step.
pub fn write_building_history(
    out: &mut (impl Write + ?Sized),
    r: &crate::model::building::BuildingResult,
) -> std::io::Result<()> {
    // A side whose storeys yield adds each storey's drift and shear: its hysteresis loops.
    let mut loops: Vec<(String, std::borrow::Cow<[f64]>)> = Vec::new();
    for (s, name) in ["left", "right"].into_iter().enumerate() {
        for (j, shear) in r.storey_shear_n[s].iter().enumerate() {
            let drift = r.storey_drift_m(s, j).into();
            loops.push((format!("drift_{name}_{}_m", j + 1), drift));
            loops.push((format!("shear_{name}_{}_n", j + 1), shear.as_slice().into()));
        }
    }
    write!(
        out,
        "time_s,ground_accel_m_s2,u_left_m,u_right_m,v_left_m_s,v_right_m_s,a_left_m_s2,a_right_m_s2,force_n"
    )?;
    for (name, _) in &loops {
        write!(out, ",{name}")?;
    }
    writeln!(out)?;
    for i in 0..r.time_s.len() {
        write!(
            out,
            "{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e}",
            r.time_s[i],
            r.ground_m_s2[i],
            r.displacement_m[0][i],
            r.displacement_m[1][i],
            r.velocity_m_s[0][i],
            r.velocity_m_s[1][i],
            r.acceleration_m_s2[0][i],
            r.acceleration_m_s2[1][i],
            r.force_n[i]
        )?;
        for (_, column) in &loops {
            write!(out, ",{:.9e}", column[i])?;
        }
        writeln!(out)?;
    }
    Ok(())
}

/// Writes an x-t grid: `bar,x_m,t_s,stress_pa,velocity_m_s`, bar 1 or 2, x from the bar's
/// contact face, stress positive in tension, velocity positive to the right.
pub fn write_xt(
    out: &mut (impl Write + ?Sized),
    g: &crate::model::xt::XtGrid,
) -> std::io::Result<()> {
    writeln!(out, "bar,x_m,t_s,stress_pa,velocity_m_s")?;
    for (b, bar) in g.bars.iter().enumerate() {
        let nx = bar.x_m.len();
        for (k, t) in g.times_s.iter().enumerate() {
            for (i, x) in bar.x_m.iter().enumerate() {
                writeln!(
                    out,
                    "{},{:.9e},{:.9e},{:.9e},{:.9e}",
                    b + 1,
                    x,
                    t,
                    bar.stress_pa[k * nx + i],
                    bar.velocity_m_s[k * nx + i]
                )?;
            }
        }
    }
    Ok(())
}

/// Writes an energy history: `time_s,rigid_kinetic_j,wave_j,contact_j,dissipated_j,total_j`,
/// then `wave_bar1_j,wave_bar2_j` where the model keeps each bar's waves.
pub fn write_energy(
    out: &mut (impl Write + ?Sized),
    h: &crate::model::impact::energy::EnergyHistory,
) -> std::io::Result<()> {
    let by_bar = h.wave_by_bar_j.as_ref();
    write!(
        out,
        "time_s,rigid_kinetic_j,wave_j,contact_j,dissipated_j,total_j"
    )?;
    if by_bar.is_some() {
        write!(out, ",wave_bar1_j,wave_bar2_j")?;
    }
    writeln!(out)?;
    for k in 0..h.time_s.len() {
        write!(
            out,
            "{:.12e},{:.12e},{:.12e},{:.12e},{:.12e},{:.12e}",
            h.time_s[k],
            h.rigid_kinetic_j[k],
            h.wave_j[k],
            h.contact_j[k],
            h.dissipated_j[k],
            h.total_j(k)
        )?;
        if let Some(w) = by_bar {
            write!(out, ",{:.12e},{:.12e}", w[0][k], w[1][k])?;
        }
        writeln!(out)?;
    }
    Ok(())
}
