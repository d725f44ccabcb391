//! Distributed-mass finite elements (Watanabe & Kawashima, Cole et al.): each bar is a chain of
//! N lumped masses and springs E A / dx, a contact link joins the two end nodes.
//!
//! Central differences at a fraction `fe.courant` of the stability limit min(dx / c). The contact
//! link is treated as in Newmark's average-acceleration method, F = f((delta_{n+1} +
//! delta_{n-1}) / 2), found from the end nodes' predicted approach (one monotone scalar equation
//! per step): stable for any contact stiffness while the chain stays explicit, and, unlike a
//! backward treatment, it does not dissipate the link's energy.
//! Momentum is conserved exactly; the force shows the oscillations about the wave-theory value
//! that the Sears model avoids.

use super::timestep::contact_time_scale;
use super::{ContactSpan, ElasticSamples, Raw, SolveError, Warning};
use crate::model::bar::Bar;
use crate::model::contact::ContactLaw;
use crate::model::control::{CHECK_EVERY, Control};
use crate::model::scenario::ImpactScenario;

/// A link this many times stiffer than the end elements is reported: the end nodes chatter.
pub const FE_LINK_RATIO: f64 = 10.0;

struct Chain {
    u: Vec<f64>,
    v: Vec<f64>,
    inv_m: Vec<f64>,
    mass: Vec<f64>,
    k: f64,
    spring: Vec<f64>,
}

impl Chain {
    fn new(bar: &Bar, n: usize) -> Self {
        let m_seg = bar.mass_kg() / n as f64;
        let mass: Vec<f64> = (0..=n)
            .map(|j| if j == 0 || j == n { 0.5 * m_seg } else { m_seg })
            .collect();
        Chain {
            u: vec![0.0; n + 1],
            v: vec![bar.velocity_m_s; n + 1],
            inv_m: mass.iter().map(|m| 1.0 / m).collect(),
            mass,
            k: bar.axial_rigidity_n() * n as f64 / bar.length_m,
            spring: vec![0.0; n],
        }
    }

    /// v += h a(u) from the springs alone (the contact is added by the caller).
    fn kick(&mut self, h: f64) {
        let n = self.spring.len();
        for j in 0..n {
            self.spring[j] = self.k * (self.u[j + 1] - self.u[j]);
        }
        self.v[0] += h * self.inv_m[0] * self.spring[0];
        for j in 1..n {
            self.v[j] += h * self.inv_m[j] * (self.spring[j] - self.spring[j - 1]);
        }
        self.v[n] -= h * self.inv_m[n] * self.spring[n - 1];
    }

    fn drift(&mut self, h: f64) {
        for (u, v) in self.u.iter_mut().zip(&self.v) {
            *u += h * v;
        }
    }

    /// The leapfrog's own energy at a whole step: 1/2 m v_{n-1/2} v_{n+1/2} for each node (the
    /// half-step velocities before and after the kick) plus the springs' strain at u_n. For a
    /// linear chain the scheme conserves exactly this, so it is the count to check a run by.
    fn energy_between_j(&self, before: &[f64]) -> f64 {
        let kinetic: f64 = self
            .mass
            .iter()
            .zip(before.iter().zip(&self.v))
            .map(|(m, (a, b))| 0.5 * m * a * b)
            .sum();
        kinetic + self.strain_j()
    }

    fn strain_j(&self) -> f64 {
        self.u
            .windows(2)
            .map(|p| 0.5 * self.k * (p[1] - p[0]).powi(2))
            .sum()
    }

    fn energy_j(&self) -> f64 {
        let kinetic: f64 = self
            .mass
            .iter()
            .zip(&self.v)
            .map(|(m, v)| 0.5 * m * v * v)
            .sum();
        kinetic + self.strain_j()
    }
}

/// The most node updates (nodes times steps) one FE run may take: about ten seconds here.
pub const FE_WORK_MAX: f64 = 5e9;

/// The step a run takes and the span it expects: the explicit limit, then the link's own
/// oscillation where the budget allows, and the work the mesh would cost.
struct StepChoice {
    h: f64,
    span_s: f64,
    warnings: Vec<Warning>,
}

fn choose_step(
    sc: &ImpactScenario,
    law: &ContactLaw,
    chains: [&Chain; 2],
) -> Result<StepChoice, SolveError> {
    let n = sc.fe.segments;
    let bars = [sc.bar1, sc.bar2];
    let courant_step = bars
        .iter()
        .map(|b| b.length_m / n as f64 / b.wave_speed_m_s())
        .fold(f64::INFINITY, f64::min);
    let mut h = sc.solver.dt_s.min(sc.fe.courant * courant_step);
    let masses = [sc.bar1.mass_kg(), sc.bar2.mass_kg()];
    let m_eff = masses[0] * masses[1] / (masses[0] + masses[1]);
    let w = sc.approach_velocity_m_s();
    let mut warnings = vec![];
    // The link and the two end nodes oscillate at sqrt(k_t / m_ends): the link is stable at any
    // step, but accurate only where the step resolves that oscillation.
    let scale = contact_time_scale(law, w, m_eff, sc.series_impedance_n_s_m());
    // The wave-theory force bounds the force between elastic bars, so its tangent is the stiffest
    // the link gets.
    let f_est = sc.wave_force_n();
    let m_ends = 1.0 / (chains[0].inv_m[n] + chains[1].inv_m[0]);
    let link_step = 0.5 * (m_ends / law.tangent_at_force(f_est)).sqrt();
    let span_s = if sc.solver.window_s > 0.0 {
        sc.solver.window_s
    } else {
        2.0 * scale
            .lumped_duration_s
            .max(2.0 * sc.bar1.round_trip_s().max(sc.bar2.round_trip_s()))
    };
    if h > link_step {
        if span_s / link_step <= sc.solver.max_steps as f64 {
            h = link_step;
        } else {
            warnings.push(Warning::FeLinkUnresolved {
                dt_s: h,
                link_step_s: link_step,
            });
        }
    }
    // The step budget bounds the steps, this the work: a million segments per bar take seconds
    // a step.
    let expected = node_count(n) * (span_s / h).min(sc.solver.max_steps as f64);
    if expected > FE_WORK_MAX {
        return Err(SolveError::FeWork {
            segments: n,
            node_steps: expected,
            max: FE_WORK_MAX,
        });
    }
    Ok(StepChoice {
        h,
        span_s,
        warnings,
    })
}

/// Nodes in both chains of `segments` each.
fn node_count(segments: usize) -> f64 {
    2.0 * (segments as f64 + 1.0)
}

/// The link between the end nodes: its law, its overlaps at the last two steps, the impulse it
/// has passed and every contact interval.
struct Link {
    law: ContactLaw,
    /// h^2 (1/m_end1 + 1/m_end2): how the link's force moves its overlap over a step.
    beta: f64,
    on: bool,
    delta: f64,
    delta_prev: f64,
    impulse: f64,
    start_impulse: f64,
    spans: Vec<ContactSpan>,
}

impl Link {
    /// The link's force over a step from the end nodes' predicted overlap, in Newmark's average
    /// form F = f((delta_{n+1} + delta_{n-1}) / 2); applies it to the end nodes and returns it
    /// with the new overlap.
    fn push_ends(&mut self, left: &mut Chain, right: &mut Chain, h: f64) -> (f64, f64) {
        let n = left.u.len() - 1;
        let predicted = (left.u[n] + h * left.v[n]) - (right.u[0] + h * right.v[0]);
        // x = (delta_{n+1} + delta_{n-1}) / 2 with delta_{n+1} = predicted - beta f(x):
        // x + (beta / 2) f(x) = (predicted + delta_{n-1}) / 2.
        let x = self.law.solve_implicit(
            0.5 * self.beta,
            0.5 * (predicted + self.delta_prev),
            self.delta,
        );
        let f = self.law.force(x);
        let d1 = predicted - self.beta * f;
        left.v[n] -= h * f * left.inv_m[n];
        right.v[0] += h * f * right.inv_m[0];
        (f, d1)
    }

    /// Books the step that ends at `t` with overlap `d1` after force `f`: a contact that opens
    /// or closes inside it (at the overlap's linear zero). Returns whether one closed.
    fn book(&mut self, t: f64, h: f64, f: f64, d1: f64) -> bool {
        self.impulse += h * f;
        let mut separated = false;
        if self.on && d1 <= 0.0 {
            let te = t - h * d1 / (d1 - self.delta);
            let passed = self.impulse - self.start_impulse;
            self.spans
                .last_mut()
                .expect("open contact")
                .close(te, passed);
            self.on = false;
            separated = true;
        } else if !self.on && d1 > 0.0 {
            self.spans
                .push(ContactSpan::opening(t - h * d1 / (d1 - self.delta)));
            self.start_impulse = self.impulse - h * f;
            self.on = true;
        }
        self.delta_prev = self.delta;
        self.delta = d1;
        separated
    }
}

/// The elements' own energy at every `every`-th whole step, in the leapfrog's product form.
struct EnergyCount {
    every: usize,
    samples: ElasticSamples,
    /// The half-step velocities before the kick of a counted step.
    before: [Vec<f64>; 2],
}

impl EnergyCount {
    /// Whether `step` is counted; if so keeps the velocities before its kick.
    fn before_kick(&mut self, step: usize, chains: [&Chain; 2]) -> bool {
        let counted = step.is_multiple_of(self.every);
        if counted {
            self.before[0].clone_from(&chains[0].v);
            self.before[1].clone_from(&chains[1].v);
        }
        counted
    }

    /// Counts `step` (whose sample holds u_n) once the velocities after its kick are known.
    fn after_kick(&mut self, step: usize, chains: [&Chain; 2]) {
        self.samples.index.push(step);
        self.samples.energy_j.push(
            chains[0].energy_between_j(&self.before[0])
                + chains[1].energy_between_j(&self.before[1]),
        );
    }
}

/// The budgets a run checks between steps: steps, and the work of a mesh larger than its span
/// estimate.
fn check_budgets(
    step: usize,
    sc: &ImpactScenario,
    h: f64,
    n_stop: usize,
    control: &Control,
) -> Result<(), SolveError> {
    if step.is_multiple_of(CHECK_EVERY) {
        control.report(step as f64 / n_stop.min(sc.solver.max_steps) as f64)?;
        let nodes = node_count(sc.fe.segments);
        if nodes * step as f64 > FE_WORK_MAX {
            return Err(SolveError::FeWork {
                segments: sc.fe.segments,
                node_steps: nodes * step as f64,
                max: FE_WORK_MAX,
            });
        }
    }
    if step + 1 > sc.solver.max_steps {
        return Err(SolveError::Budget {
            max_steps: sc.solver.max_steps,
            dt_s: h,
            reached_s: step as f64 * h,
        });
    }
    Ok(())
}

pub(crate) fn solve(sc: &ImpactScenario, control: &Control) -> Result<Raw, SolveError> {
    let law = sc.contact_law()?;
    let n = sc.fe.segments;
    let mut left = Chain::new(&sc.bar1, n);
    let mut right = Chain::new(&sc.bar2, n);
    let masses = [sc.bar1.mass_kg(), sc.bar2.mass_kg()];
    let m_eff = masses[0] * masses[1] / (masses[0] + masses[1]);
    let w = sc.approach_velocity_m_s();
    let StepChoice {
        h,
        span_s,
        mut warnings,
    } = choose_step(sc, &law, [&left, &right])?;
    let n_stop = if sc.solver.window_s > 0.0 {
        (sc.solver.window_s / h).ceil() as usize
    } else {
        usize::MAX
    };
    let (mut time_s, mut force_n, mut approach_m) = (vec![0.0], vec![0.0], vec![0.0]);
    let mut impulses = vec![0.0];
    let mut link = Link {
        law,
        beta: h * h * (left.inv_m[n] + right.inv_m[0]),
        on: true,
        delta: 0.0,
        // delta at t = -h: the bars were approaching rigidly.
        delta_prev: -sc.approach_velocity_m_s() * h,
        impulse: 0.0,
        start_impulse: 0.0,
        spans: vec![ContactSpan::opening(0.0)],
    };
    // The elements' energy at about 1000 whole steps of the span estimate (a run that ends at
    // separation stops well before it): an O(nodes) count each, a few per cent of the run.
    let mut count = EnergyCount {
        every: (((span_s / h).min(sc.solver.max_steps as f64) / 1000.0) as usize).max(1),
        samples: ElasticSamples::default(),
        before: [Vec::new(), Vec::new()],
    };
    let mut step = 0usize;
    // The half-step velocities start at v(-h/2) = v0: the bars move rigidly before contact.
    while step < n_stop {
        let counted = count.before_kick(step, [&left, &right]);
        check_budgets(step, sc, h, n_stop, control)?;
        left.kick(h);
        right.kick(h);
        let (f, d1) = link.push_ends(&mut left, &mut right, h);
        if counted {
            count.after_kick(step, [&left, &right]);
        }
        left.drift(h);
        right.drift(h);
        step += 1;
        let t = step as f64 * h;
        let separated = link.book(t, h, f, d1);
        time_s.push(t);
        force_n.push(f);
        approach_m.push(d1);
        impulses.push(link.impulse);
        if separated && sc.solver.window_s == 0.0 && w - link.impulse / m_eff <= 0.0 {
            break;
        }
    }
    let stiffest = link
        .law
        .tangent_at_force(force_n.iter().cloned().fold(0.0, f64::max));
    let element = left.k.min(right.k);
    if stiffest > FE_LINK_RATIO * element {
        warnings.push(Warning::FeLinkChatter {
            link_n_m: stiffest,
            element_n_m: element,
        });
    }
    super::close_open_contact(
        &mut link.spans,
        link.impulse,
        link.start_impulse,
        step as f64 * h,
        &mut warnings,
    );
    let impulse = link.impulse;
    // Energies at an integer time level: advance the velocities half a step from the springs.
    left.kick(0.5 * h);
    right.kick(0.5 * h);
    let rigid = [
        sc.bar1.velocity_m_s - impulse / masses[0],
        sc.bar2.velocity_m_s + impulse / masses[1],
    ];
    let elastic_end = left.energy_j() + right.energy_j();
    let mut elastic = count.samples;
    if elastic.index.last() != Some(&step) {
        elastic.index.push(step);
        elastic.energy_j.push(elastic_end);
    }
    let vibration_j =
        elastic_end - 0.5 * masses[0] * rigid[0].powi(2) - 0.5 * masses[1] * rigid[1].powi(2);
    Ok(Raw {
        end_s: step as f64 * h,
        time_s,
        force_n,
        approach_m,
        contacts: link.spans,
        impulse_ns: impulse,
        impulse_history_ns: impulses,
        masses_kg: masses,
        vibration_j,
        contact_j: link.law.energy(link.delta),
        warnings,
        steps: step,
        dt_s: h,
        refined_from_s: (h < sc.solver.dt_s).then_some(sc.solver.dt_s),
        elastic_samples: Some(elastic),
        ..Raw::default()
    })
}
