//! Where the energy is at every instant of an impact: the bars' rigid-body motion, the waves in
//! each bar, the contact, and what a damped contact dissipated. The final split the readouts
//! give is the last row; this is how the run gets there.
//!
//! Each part comes from its own quantity, so their sum checks the run rather than restating it:
//! - rigid-body kinetic energy from the impulse so far J(t), as the model integrated it:
//!   m1 (v1 - J/m1)^2 / 2 + m2 (v2 + J/m2)^2 / 2;
//! - a bar's waves from its history H: (1/Z) times the integral of H^2 over the last round trip
//!   (its energy in its initial frame) less J^2 / (2 m), the part that is rigid motion;
//! - the contact's stored energy from the law at the approach delta(t);
//! - a damped contact's dissipation as the model integrated it.
//!
//! Models without waves (lumped masses, stereomechanics) have none. Finite elements keep no wave
//! histories: their waves are the kinetic and strain energy of their own elements, counted at the
//! samples the solver recorded it, less the rigid-body part. So for every model the total is a
//! sum of independent counts, and a run that does not keep its initial energy shows it.

use super::{ImpactResult, ModelKind};
use crate::model::scenario::ImpactScenario;

/// Energies at a sequence of instants [J].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct EnergyHistory {
    /// The instants [s].
    pub time_s: Vec<f64>,
    /// Rigid-body kinetic energy of both bars.
    pub rigid_kinetic_j: Vec<f64>,
    /// Energy of the waves in both bars.
    pub wave_j: Vec<f64>,
    /// The same bar by bar, where the model keeps each bar's waves (not finite elements).
    pub wave_by_bar_j: Option<[Vec<f64>; 2]>,
    /// Energy stored in the contact.
    pub contact_j: Vec<f64>,
    /// Energy a damped contact dissipated so far.
    pub dissipated_j: Vec<f64>,
}

impl EnergyHistory {
    /// The sum of the parts at sample `k`.
    pub fn total_j(&self, k: usize) -> f64 {
        self.rigid_kinetic_j[k] + self.wave_j[k] + self.contact_j[k] + self.dissipated_j[k]
    }
}

/// The energy history of `r` (solved from `sc`) at about `samples` instants: the result's own
/// samples, every one of them or evenly thinned, always with the first and the last.
pub fn energy_history(sc: &ImpactScenario, r: &ImpactResult, samples: usize) -> EnergyHistory {
    let n = r.time_s.len();
    if n == 0 {
        return EnergyHistory::default();
    }
    let picks = match &r.elastic_samples {
        Some(e) => thinned(&e.index, samples),
        None => thinned(&(0..n).collect::<Vec<_>>(), samples),
    };
    let elastic: Option<Vec<f64>> = r.elastic_samples.as_ref().map(|e| {
        picks
            .iter()
            .map(|k| e.energy_j[e.index.binary_search(k).expect("picked from it")])
            .collect()
    });
    let [m1, m2] = r.masses_kg;
    let [v1, v2] = r.initial_velocities_m_s;
    let law = r.model.law(sc).and_then(Result::ok);
    let mut h = EnergyHistory::default();
    let mut by_bar: [Vec<f64>; 2] = [Vec::new(), Vec::new()];
    for &k in &picks {
        let t = r.time_s[k];
        let j = r.impulse_history_ns[k];
        let [u1, u2] = super::rigid_velocities([v1, v2], [m1, m2], j);
        let rigid = 0.5 * m1 * u1 * u1 + 0.5 * m2 * u2 * u2;
        // A contact stores energy while it is on: the approach is positive.
        let contact = match (law, r.model) {
            // The Kelvin-Voigt link lets go with its spring stretched; its history ends at the
            // release, where the dissipation takes that energy.
            (Some(l), _) if r.force_n[k] > 0.0 || r.model != ModelKind::Kelvin => {
                l.energy(r.approach_m[k])
            }
            _ => 0.0,
        };
        let waves = match &r.waves {
            Some(w) => [0, 1].map(|i| w[i].wave_energy_j(t) - j * j / (2.0 * r.masses_kg[i])),
            None => [0.0, 0.0],
        };
        h.time_s.push(t);
        h.rigid_kinetic_j.push(rigid);
        h.contact_j.push(contact);
        h.dissipated_j.push(r.dissipated_history_j[k]);
        h.wave_j.push(waves[0] + waves[1]);
        by_bar[0].push(waves[0]);
        by_bar[1].push(waves[1]);
    }
    if r.waves.is_some() {
        h.wave_by_bar_j = Some(by_bar);
    } else if let Some(elastic) = elastic {
        for (k, e) in elastic.into_iter().enumerate() {
            h.wave_j[k] = e - h.rigid_kinetic_j[k];
        }
    }
    h
}

/// About `samples` of `indices`, evenly thinned, always with the first and the last.
fn thinned(indices: &[usize], samples: usize) -> Vec<usize> {
    let n = indices.len();
    if n == 0 {
        return vec![];
    }
    let stride = (n / samples.max(2)).max(1);
    let mut picks: Vec<usize> = indices.iter().copied().step_by(stride).collect();
    if picks.last() != indices.last() {
        picks.push(indices[n - 1]);
    }
    picks
}
