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
