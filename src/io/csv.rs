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

/// Writes the building histories, one row per solver step.
pub fn write_building_history(
    out: &mut (impl Write + ?Sized),
    r: &crate::model::building::BuildingResult,
) -> std::io::Result<()> {
    writeln!(
        out,
        "time_s,ground_accel_m_s2,u_left_m,u_right_m,v_left_m_s,v_right_m_s,a_left_m_s2,a_right_m_s2,force_n"
    )?;
    for i in 0..r.time_s.len() {
        writeln!(
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
    }
    Ok(())
}
