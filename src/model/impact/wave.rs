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

/// The histories the result keeps, sampled at every event (twice where the force jumps, so the
/// staircase is drawn with vertical risers).
#[derive(Default)]
struct Samples {
    time_s: Vec<f64>,
    force_n: Vec<f64>,
    approach_m: Vec<f64>,
    impulse_ns: Vec<f64>,
}

impl Samples {
    fn push(&mut self, t: f64, force: f64, approach: f64, impulse: f64) {
        self.time_s.push(t);
        self.force_n.push(force);
        self.approach_m.push(approach);
        self.impulse_ns.push(impulse);
    }
}

/// The contact between events: on or off, its force (constant until the next event), the ends'
/// approach and its rate while apart, the impulse so far, and every contact interval.
struct Contact {
    on: bool,
    force: f64,
    delta: f64,
    rate: f64,
    t_prev: f64,
    impulse: f64,
    /// The impulse when the open contact began.
    start_impulse: f64,
    spans: Vec<ContactSpan>,
}

impl Contact {
    /// Carries the impulse and, while apart, the approach to `t`: both change linearly between
    /// events.
    fn advance_to(&mut self, t: f64) {
        self.impulse += self.force * (t - self.t_prev);
        if !self.on {
            self.delta += self.rate * (t - self.t_prev);
        }
        self.t_prev = t;
    }

    /// Answers the force the bars' motion demands at `t`: a contact carries it while it is a
    /// compression (above `zero`, round-off), and ends where it would be a pull; bars apart meet
    /// again when their approach has closed (to `touching`) and the demand presses. Returns
    /// whether the contact ended here.
    fn respond(&mut self, t: f64, demand: f64, zero: f64, touching: f64) -> bool {
        if self.on {
            if demand > zero {
                self.force = demand;
                return false;
            }
            self.force = 0.0;
            self.on = false;
            self.delta = 0.0;
            let passed = self.impulse - self.start_impulse;
            self.spans
                .last_mut()
                .expect("open contact")
                .close(t, passed);
            return true;
        }
        if self.delta >= -touching && demand > zero {
            self.on = true;
            self.force = demand;
            self.delta = 0.0;
            self.start_impulse = self.impulse;
            self.spans.push(ContactSpan::opening(t));
        }
        false
    }
}

/// Each bar's waves from its history of H, for the field anywhere.
fn bar_waves(sc: &ImpactScenario, z: [f64; 2], h: &[Steps; 2], end_s: f64) -> [BarWaves; 2] {
    let bars = [sc.bar1, sc.bar2];
    std::array::from_fn(|i| BarWaves {
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
    })
}

/// Counts an event against the budget and reports progress.
fn count_event(
    events: usize,
    t: f64,
    sc: &ImpactScenario,
    control: &Control,
) -> Result<(), SolveError> {
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
    Ok(())
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
    // A demand that vanishes to round-off is a separation: the ends move together without
    // force (equal impedances at t = 2 L_short / c), and the classical contact ends there.
    let zero = 1e-12 * w / compliance;
    let touching = 1e-12 * w * rt[0].max(rt[1]);

    let mut h = [0, 1].map(|_| Steps {
        times: vec![],
        values: vec![],
    });
    let mut samples = Samples::default();
    let mut contact = Contact {
        on: true,
        force: 0.0,
        delta: 0.0,
        rate: 0.0,
        t_prev: 0.0,
        impulse: 0.0,
        start_impulse: 0.0,
        spans: vec![ContactSpan::opening(0.0)],
    };
    let mut queue = BinaryHeap::new();
    queue.push(At(0.0));
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
        count_event(events, t, sc, control)?;
        contact.advance_to(t);
        // An echo is due exactly one round trip after its step; t - T_i can land an ulp short of
        // the stored step time, so look up with the merging tolerance.
        let echoes = [h[0].at(t - rt[0] + eps), h[1].at(t - rt[1] + eps)];
        let demand = (w - 2.0 * echoes[0] / z[0] - 2.0 * echoes[1] / z[1]) / compliance;
        let f_old = contact.force;
        let separated = contact.respond(t, demand, zero, touching);
        if !contact.on {
            contact.rate = compliance * demand;
            if contact.rate > 0.0 {
                queue.push(At(t + (-contact.delta) / contact.rate));
            }
        }
        let f = contact.force;
        if f != f_old || t == 0.0 {
            samples.push(t, f_old, contact.delta, contact.impulse);
        }
        samples.push(t, f, contact.delta, contact.impulse);
        for i in 0..2 {
            let v = f + echoes[i];
            if h[i].times.is_empty() || v != h[i].last() {
                h[i].times.push(t);
                h[i].values.push(v);
                queue.push(At(t + rt[i]));
            }
        }
        end_s = t;
        if separated && window == 0.0 && w - contact.impulse / m_eff <= 0.0 {
            break;
        }
    }
    if window > 0.0 && end_s < window {
        contact.advance_to(window);
        end_s = window;
        samples.push(end_s, contact.force, contact.delta, contact.impulse);
    }
    let mut warnings = vec![];
    let impulse = contact.impulse;
    super::close_open_contact(
        &mut contact.spans,
        impulse,
        contact.start_impulse,
        end_s,
        &mut warnings,
    );
    let waves = bar_waves(sc, z, &h, end_s);
    let vibration_j = (0..2)
        .map(|i| waves[i].wave_energy_j(end_s) - impulse * impulse / (2.0 * masses[i]))
        .sum();
    Ok(Raw {
        time_s: samples.time_s,
        force_n: samples.force_n,
        approach_m: samples.approach_m,
        contacts: contact.spans,
        impulse_ns: impulse,
        masses_kg: masses,
        vibration_j,
        end_s,
        waves: Some(waves),
        impulse_history_ns: samples.impulse_ns,
        warnings,
        steps: events,
        dt_s: 0.0,
        ..Raw::default()
    })
}
