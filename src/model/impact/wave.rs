//! Saint-Venant wave theory: elastic bars, rigid contact, solved exactly.
//!
//! With rigid contact the end velocities are equal while the bars touch:
//!   (1/Z1 + 1/Z2) F(t) = w - 2 H1(t - T1)/Z1 - 2 H2(t - T2)/Z2,
//! and the force is piecewise constant, changing only when a change of H_i comes back after a
//! round trip T_i. The solver walks those instants in order (an event queue), so the staircase is
//! exact: no step size, no discretisation error. When the formula asks for tension the bars
//! separate; the ends' approach then moves linearly and a later contact is located exactly.

use super::{ContactSpan, Raw, SolveError};
use crate::model::control::{CHECK_EVERY, Control};
use crate::model::field::{BarWaves, History};
use crate::model::scenario::ImpactScenario;
use std::cmp::Ordering;
use std::collections::BinaryHeap;

#[derive(PartialEq)]
struct At(f64);
impl Eq for At {}
impl PartialOrd for At {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for At {
    fn cmp(&self, other: &Self) -> Ordering {
        // Earliest first in a max-heap.
        other.0.total_cmp(&self.0)
    }
}

/// A right-continuous step function built in time order.
struct Steps {
    times: Vec<f64>,
    values: Vec<f64>,
}

impl Steps {
    fn at(&self, t: f64) -> f64 {
        let k = self.times.partition_point(|&x| x <= t);
        if k == 0 { 0.0 } else { self.values[k - 1] }
    }
    fn last(&self) -> f64 {
        *self.values.last().unwrap_or(&0.0)
    }
}

pub(crate) fn solve(sc: &ImpactScenario, control: &Control) -> Result<Raw, SolveError> {
    let bars = [sc.bar1, sc.bar2];
    let z = bars.map(|b| b.impedance_n_s_m());
    let rt = bars.map(|b| b.round_trip_s());
    let masses = bars.map(|b| b.mass_kg());
    let m_eff = masses[0] * masses[1] / (masses[0] + masses[1]);
    let w = sc.approach_velocity_m_s();
    let compliance = 1.0 / z[0] + 1.0 / z[1];
    let window = sc.solver.window_s;
    // Coincident instants (sums of round trips reached by different paths) are merged.
    let eps = 1e-12 * rt[0].min(rt[1]);

    let mut h = [
        Steps {
            times: vec![],
            values: vec![],
        },
        Steps {
            times: vec![],
            values: vec![],
        },
    ];
    let (mut time_s, mut force_n, mut approach_m, mut impulses) = (vec![], vec![], vec![], vec![]);
    let mut contacts = vec![ContactSpan::opening(0.0)];
    let mut queue = BinaryHeap::new();
    queue.push(At(0.0));
    let (mut on, mut f, mut delta, mut rate) = (true, 0.0, 0.0, 0.0);
    let (mut t_prev, mut impulse, mut contact_j0) = (0.0, 0.0, 0.0);
    let mut events = 0usize;
    let mut end_s = 0.0;
    while let Some(At(t)) = queue.pop() {
        while queue.peek().is_some_and(|At(u)| *u - t <= eps) {
            queue.pop();
        }
        if window > 0.0 && t > window {
            break;
        }
        events += 1;
        if events.is_multiple_of(CHECK_EVERY) {
            control.report(events as f64 / sc.solver.max_steps as f64)?;
        }
        if events > sc.solver.max_steps {
            return Err(SolveError::Budget {
                max_steps: sc.solver.max_steps,
                dt_s: 0.0,
                reached_s: t,
            });
        }
        impulse += f * (t - t_prev);
        if !on {
            delta += rate * (t - t_prev);
        }
        t_prev = t;
        // An echo is due exactly one round trip after its step; t - T_i can land an ulp short of
        // the stored step time, so look up with the merging tolerance.
        let echoes = [h[0].at(t - rt[0] + eps), h[1].at(t - rt[1] + eps)];
        let demand = (w - 2.0 * echoes[0] / z[0] - 2.0 * echoes[1] / z[1]) / compliance;
        let f_old = f;
        let mut separated = false;
        // A demand that vanishes to round-off is a separation: the ends move together without
        // force (equal impedances at t = 2 L_short / c), and the classical contact ends there.
        let zero = 1e-12 * w / compliance;
        if on {
            if demand > zero {
                f = demand;
            } else {
                f = 0.0;
                on = false;
                delta = 0.0;
                separated = true;
                contacts
                    .last_mut()
                    .expect("open contact")
                    .close(t, impulse - contact_j0);
            }
        } else if delta >= -1e-12 * w * rt[0].max(rt[1]) && demand > zero {
            on = true;
            f = demand;
            delta = 0.0;
            contact_j0 = impulse;
            contacts.push(ContactSpan::opening(t));
        }
        if !on {
            rate = compliance * demand;
            if rate > 0.0 {
                queue.push(At(t + (-delta) / rate));
            }
        }
        if f != f_old || t == 0.0 {
            time_s.push(t);
            force_n.push(f_old);
            approach_m.push(delta);
            impulses.push(impulse);
        }
        time_s.push(t);
        force_n.push(f);
        approach_m.push(delta);
        impulses.push(impulse);
        for i in 0..2 {
            let v = f + echoes[i];
            if h[i].times.is_empty() || v != h[i].last() {
                h[i].times.push(t);
                h[i].values.push(v);
                queue.push(At(t + rt[i]));
            }
        }
        end_s = t;
        if separated && window == 0.0 && w - impulse / m_eff <= 0.0 {
            break;
        }
    }
    if window > 0.0 && end_s < window {
        impulse += f * (window - end_s);
        if !on {
            delta += rate * (window - end_s);
        }
        end_s = window;
        time_s.push(end_s);
        force_n.push(f);
        approach_m.push(delta);
        impulses.push(impulse);
    }
    let mut warnings = vec![];
    super::close_open_contact(&mut contacts, impulse, contact_j0, end_s, &mut warnings);
    let waves: [BarWaves; 2] = std::array::from_fn(|i| BarWaves {
        body_length_m: bars[i].length_m,
        zone_length_m: 0.0,
        wave_speed_m_s: bars[i].wave_speed_m_s(),
        area_m2: bars[i].area_m2(),
        impedance_n_s_m: z[i],
        initial_velocity_m_s: bars[i].velocity_m_s,
        push_direction: if i == 0 { -1.0 } else { 1.0 },
        history: History::Steps {
            times: h[i].times.clone(),
            values: h[i].values.clone(),
        },
        end_s,
        decay_per_s: 0.0,
    });
    let vibration_j = (0..2)
        .map(|i| waves[i].wave_energy_j(end_s) - impulse * impulse / (2.0 * masses[i]))
        .sum();
    Ok(Raw {
        time_s,
        force_n,
        approach_m,
        contacts,
        impulse_ns: impulse,
        masses_kg: masses,
        vibration_j,
        end_s,
        waves: Some(waves),
        impulse_history_ns: impulses,
        warnings,
        steps: events,
        dt_s: 0.0,
        ..Raw::default()
    })
}
