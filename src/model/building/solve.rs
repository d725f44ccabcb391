//! Time stepping of the two buildings.
//!
//! Newmark's average-acceleration method (unconditionally stable, no numerical damping) for both
//! oscillators. Outside contacts the step follows the record (at most a hundredth of the shorter
//! building period); inside a contact it drops to the contact's own time scale / steps_per_scale,
//! on a fixed fine grid that the Sears slab histories also use. A coarse step is checked at every
//! fine grid point it spans (the oscillators interpolated as cubic Hermite curves, the slab waves
//! stepped exactly), so an onset is located to one fine step, never deferred to the next coarse
//! one. In contact, the force is implicit: each step is one monotone scalar equation for the
//! overlap, stable for any contact stiffness.

use super::elements::Element;
use super::slab::SlabWaves;
use super::{
    BuildingEnergy, BuildingResult, BuildingScenario, BuildingStats, ContactModel, RawContact,
    SlabReading, group_impacts,
};
use crate::model::contact::ContactLaw;
use crate::model::impact::SolveError;
use crate::model::impact::timestep::contact_time_scale;
use crate::model::motion::GroundMotion;
use std::time::Instant;

#[derive(Debug, Clone, Copy)]
struct Oscillator {
    m: f64,
    c: f64,
    k: f64,
    u: f64,
    v: f64,
    a: f64,
}

impl Oscillator {
    fn k_hat(&self, h: f64) -> f64 {
        self.k + 2.0 * self.c / h + 4.0 * self.m / (h * h)
    }
    /// Displacement after a step of h with ground acceleration `ag` at its end and no contact.
    fn predict(&self, h: f64, ag: f64) -> f64 {
        let p = -self.m * ag
            + self.m * (4.0 * self.u / (h * h) + 4.0 * self.v / h + self.a)
            + self.c * (2.0 * self.u / h + self.v);
        p / self.k_hat(h)
    }
    fn commit(&mut self, h: f64, u1: f64) {
        let v1 = 2.0 * (u1 - self.u) / h - self.v;
        let a1 = 4.0 * (u1 - self.u) / (h * h) - 4.0 * self.v / h - self.a;
        self.u = u1;
        self.v = v1;
        self.a = a1;
    }
    fn energy(&self) -> f64 {
        0.5 * self.m * self.v * self.v + 0.5 * self.k * self.u * self.u
    }
    /// Cubic Hermite position and velocity at fraction s of a step of h from `self` to `end`.
    fn hermite(&self, end: &Oscillator, h: f64, s: f64) -> (f64, f64) {
        let (s2, s3) = (s * s, s * s * s);
        let u = (2.0 * s3 - 3.0 * s2 + 1.0) * self.u
            + (s3 - 2.0 * s2 + s) * h * self.v
            + (-2.0 * s3 + 3.0 * s2) * end.u
            + (s3 - s2) * h * end.v;
        let v = ((6.0 * s2 - 6.0 * s) * self.u + (-6.0 * s2 + 6.0 * s) * end.u) / h
            + (3.0 * s2 - 4.0 * s + 1.0) * self.v
            + (3.0 * s2 - 2.0 * s) * end.v;
        (u, v)
    }
}

struct Recorder {
    time_s: Vec<f64>,
    ground: Vec<f64>,
    disp: [Vec<f64>; 2],
    vel: [Vec<f64>; 2],
    acc: [Vec<f64>; 2],
    force: Vec<f64>,
}

impl Recorder {
    fn push(&mut self, t: f64, ag: f64, osc: &[Oscillator; 2], f: f64) {
        self.time_s.push(t);
        self.ground.push(ag);
        for (i, o) in osc.iter().enumerate() {
            self.disp[i].push(o.u);
            self.vel[i].push(o.v);
            self.acc[i].push(o.a + ag);
        }
        self.force.push(f);
    }
}

/// One implicit contact step of length hh from `osc` (and the slabs): returns the new overlap,
/// its rate and the force, and commits the oscillators and slabs.
#[allow(clippy::too_many_arguments)]
fn contact_step(
    osc: &mut [Oscillator; 2],
    slabs: &mut Option<[SlabWaves; 2]>,
    element: &Element,
    gap: f64,
    ag: f64,
    hh: f64,
    delta: f64,
    rate: f64,
    v0: f64,
) -> (f64, f64, f64) {
    let (u1h, u2h) = (osc[0].predict(hh, ag), osc[1].predict(hh, ag));
    let (k1, k2) = (osc[0].k_hat(hh), osc[1].k_hat(hh));
    let (e1, e2) = slabs.as_ref().map_or(((0.0, 0.0), (0.0, 0.0)), |s| {
        (s[0].predict(), s[1].predict())
    });
    let rhs = u1h - u2h - gap - e1.0 - e2.0;
    // The slabs' instantaneous compliance minus their rigid part can be a hair below zero (the
    // oscillators' springs and dampers stiffen the rigid response): clamp.
    let beta = (1.0 / k1 + 1.0 / k2 + e1.1 + e2.1).max(0.0);
    let d1 = element.solve_step(beta, rhs, hh, delta, rate, v0);
    let r1 = element.rate(hh, d1, delta, rate);
    let f1 = if slabs.is_some() {
        element.stiffness * d1.max(0.0)
    } else {
        element.force(d1, r1, v0)
    };
    osc[0].commit(hh, u1h - f1 / k1);
    osc[1].commit(hh, u2h + f1 / k2);
    if let Some(s) = slabs.as_mut() {
        s[0].push(f1);
        s[1].push(f1);
    }
    (d1, r1, f1)
}

/// Fraction s of a step at which a Kelvin-Voigt link's force k delta + c delta' (unclipped)
/// reaches zero, by bisection on Newmark sub-steps of s h.
#[allow(clippy::too_many_arguments)]
fn kelvin_release(
    osc: &[Oscillator; 2],
    element: &Element,
    h: f64,
    motion: &GroundMotion,
    t: f64,
    gap: f64,
    delta: f64,
    rate: f64,
) -> f64 {
    let push = |s: f64| {
        let hs = s * h;
        let ag = motion.at(t + hs);
        let (u1, u2) = (osc[0].predict(hs, ag), osc[1].predict(hs, ag));
        let beta = 1.0 / osc[0].k_hat(hs) + 1.0 / osc[1].k_hat(hs);
        let (k, c) = (element.stiffness, element.kelvin_damping);
        let th = element.rate_theta(hs);
        // delta + beta (k delta + c rate(delta)) = u1 - u2 - gap, with the element's rate
        // ((delta - delta_n)/hs - (1 - th) rate_n) / th: linear in delta.
        let d = (u1 - u2 - gap + beta * c * (delta / (hs * th) + (1.0 - th) * rate / th))
            / (1.0 + beta * (k + c / (hs * th)));
        k * d + c * element.rate(hs, d, delta, rate)
    };
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if push(mid) > 0.0 { lo = mid } else { hi = mid }
    }
    hi.max(1e-9)
}

/// Step sizes: (fine, coarse as a whole number of fine steps, a warning when the fine step could
/// not resolve the contact within the step budget).
fn steps(
    sc: &BuildingScenario,
    element: &Element,
    motion: &GroundMotion,
) -> (f64, usize, Option<String>) {
    let m_eff = sc.effective_mass_kg();
    let law = if sc.contact.is_hertzian() {
        ContactLaw::hertz(element.stiffness)
    } else {
        ContactLaw::linear(element.stiffness)
    };
    let z_eff = if sc.contact == ContactModel::Sears {
        sc.slab_series_impedance_n_s_m()
    } else {
        f64::INFINITY
    };
    // Pounding velocities are a fraction of a metre per second; 1 m/s bounds the Hertzian
    // elements' time scale from below.
    let scale = contact_time_scale(&law, 1.0, m_eff, z_eff);
    let mut resolve = scale.resolve_s;
    if sc.contact == ContactModel::Kelvin && element.kelvin_damping > 0.0 {
        resolve = resolve.min(m_eff / element.kelvin_damping);
    }
    let coarse = sc
        .max_step_s
        .min(motion.dt_s)
        .min(sc.left.period_s().min(sc.right.period_s()) / 100.0);
    if sc.contact == ContactModel::None {
        return (coarse, 1, None);
    }
    let mut fine = (resolve / sc.steps_per_scale).min(coarse);
    let mut warning = None;
    // The Sears slabs keep their history on the fine grid over the whole record: within half
    // the budget, or a coarser grid that no longer resolves the contact (stable: the contact
    // force is implicit), said out loud.
    let floor = motion.duration_s() / (0.5 * sc.max_steps as f64);
    if sc.contact == ContactModel::Sears && fine < floor {
        warning = Some(format!(
            "the contact's time scale ({resolve:.3e} s) needs a step of {fine:.3e} s, over the step budget (solver.max_steps = {}) for this record: using {floor:.3e} s, which does not resolve the force's rise; raise solver.max_steps or shorten the record for accurate forces",
            sc.max_steps
        ));
        fine = floor;
    }
    let ratio = (coarse / fine).floor().max(1.0) as usize;
    (fine, ratio, warning)
}

pub fn solve(sc: &BuildingScenario, motion: &GroundMotion) -> Result<BuildingResult, SolveError> {
    sc.validate()?;
    let start = Instant::now();
    let element = Element::new(
        sc.contact,
        sc.element_stiffness(),
        sc.restitution,
        sc.effective_mass_kg(),
    );
    let (h, ratio, step_warning) = steps(sc, &element, motion);
    let t_end = motion.duration_s();
    let total_fine = (t_end / h).ceil() as usize;
    let sears = sc.contact == ContactModel::Sears;
    if sears && total_fine > sc.max_steps {
        return Err(SolveError::Budget {
            max_steps: sc.max_steps,
            dt_s: h,
            reached_s: 0.0,
        });
    }
    let zone = if sc.reading == SlabReading::Paper {
        sc.zone_length()
    } else {
        0.0
    };
    let mut slabs: Option<[SlabWaves; 2]> = sears.then(|| {
        [
            SlabWaves::new(&sc.left, zone, sc.slab_damping, h, total_fine + 2),
            SlabWaves::new(&sc.right, zone, sc.slab_damping, h, total_fine + 2),
        ]
    });
    let osc_of = |b: &super::Building, v: f64| {
        let c = b.damping_n_s_m();
        Oscillator {
            m: b.mass_kg,
            c,
            k: b.stiffness_n_m,
            u: 0.0,
            v,
            a: -motion.at(0.0) - c * v / b.mass_kg,
        }
    };
    let mut osc = [
        osc_of(&sc.left, sc.initial_velocity_m_s[0]),
        osc_of(&sc.right, sc.initial_velocity_m_s[1]),
    ];
    let mut rec = Recorder {
        time_s: vec![],
        ground: vec![],
        disp: [vec![], vec![]],
        vel: [vec![], vec![]],
        acc: [vec![], vec![]],
        force: vec![],
    };
    rec.push(0.0, motion.at(0.0), &osc, 0.0);

    let mut n = 0usize; // fine grid index of the current time
    let mut energy = BuildingEnergy::default();
    let mut work_contact = 0.0; // work of the contact force on the buildings
    let (mut steps_taken, mut contact_steps) = (0usize, 0usize);
    let (mut in_contact, mut delta, mut rate, mut force, mut v0) =
        (false, -sc.gap_m, 0.0, 0.0, 0.0);
    let mut contacts: Vec<RawContact> = vec![];
    let mut warnings: Vec<String> = step_warning.into_iter().collect();
    if sears && sc.reading == SlabReading::Paper {
        // The validity number of the paper reading (physics.md): a tau = k sum(tau_i / Z_i).
        let d = sc.zone_length();
        let a_tau = element.stiffness
            * [sc.left, sc.right]
                .iter()
                .map(|b| d / b.slab_wave_speed_m_s() / b.slab_impedance_n_s_m())
                .sum::<f64>();
        if a_tau > std::f64::consts::FRAC_PI_2 {
            warnings.push(format!(
                "the Sears paper reading's validity number a tau = {a_tau:.3} exceeds pi/2: this reading oscillates and creates energy once separation clips the force (physics.md); use contact.reading = end or a softer contact"
            ));
        }
    }
    let overlap = |osc: &[Oscillator; 2], slabs: &Option<[SlabWaves; 2]>| {
        let e = slabs
            .as_ref()
            .map_or(0.0, |s| s[0].elastic_m() + s[1].elastic_m());
        osc[0].u - osc[1].u - sc.gap_m - e
    };
    // Energy bookkeeping over one step from `before` to `after` (trapezoid, as Newmark).
    let account = |energy: &mut BuildingEnergy,
                   work: &mut f64,
                   hh: f64,
                   before: &[Oscillator; 2],
                   after: &[Oscillator; 2],
                   ag0: f64,
                   ag1: f64,
                   f0: f64,
                   f1: f64| {
        for i in 0..2 {
            energy.input_j -= 0.5 * hh * before[i].m * (ag0 * before[i].v + ag1 * after[i].v);
            energy.building_damping_j +=
                0.5 * hh * before[i].c * (before[i].v.powi(2) + after[i].v.powi(2));
        }
        *work -= 0.5 * hh * (f0 * (before[0].v - before[1].v) + f1 * (after[0].v - after[1].v));
    };

    while (n as f64) * h < t_end - 1e-12 * h {
        if steps_taken >= sc.max_steps {
            return Err(SolveError::Budget {
                max_steps: sc.max_steps,
                dt_s: h,
                reached_s: n as f64 * h,
            });
        }
        let t = n as f64 * h;
        if in_contact {
            // One fine, implicit step.
            let t1 = t + h;
            let ag = motion.at(t1);
            let before = osc;
            let (mut d1, mut r1, mut f1) = contact_step(
                &mut osc, &mut slabs, &element, sc.gap_m, ag, h, delta, rate, v0,
            );
            let mut hs = h;
            if f1 <= 0.0 && force > 0.0 && sc.contact == ContactModel::Kelvin {
                // The link lets go inside this step, where k delta + c delta' reaches zero: take
                // the step only up to that instant (a free step brings us back onto the grid).
                osc = before;
                hs = kelvin_release(&osc, &element, h, motion, t, sc.gap_m, delta, rate) * h;
                (d1, r1, _) = contact_step(
                    &mut osc,
                    &mut slabs,
                    &element,
                    sc.gap_m,
                    motion.at(t + hs),
                    hs,
                    delta,
                    rate,
                    v0,
                );
                f1 = 0.0;
            }
            account(
                &mut energy,
                &mut work_contact,
                hs,
                &before,
                &osc,
                motion.at(t),
                motion.at(t + hs),
                force,
                f1,
            );
            let c = contacts.last_mut().expect("a contact is open");
            c.impulse_ns += 0.5 * hs * (force + f1);
            c.peak_force_n = c.peak_force_n.max(f1);
            if f1 <= 0.0 {
                c.end_s = if hs < h {
                    t + hs
                } else {
                    t + h * delta.max(0.0) / (delta.max(0.0) - d1).max(f64::MIN_POSITIVE)
                };
                in_contact = false;
                if c.impulse_ns == 0.0 {
                    // The touch carried no force (a grazing approach): not a contact.
                    contacts.pop();
                }
            }
            if hs < h {
                let b2 = osc;
                let ht = h - hs;
                osc[0].commit(ht, osc[0].predict(ht, ag));
                osc[1].commit(ht, osc[1].predict(ht, ag));
                account(
                    &mut energy,
                    &mut work_contact,
                    ht,
                    &b2,
                    &osc,
                    motion.at(t + hs),
                    ag,
                    0.0,
                    0.0,
                );
                d1 = overlap(&osc, &slabs);
                r1 = osc[0].v - osc[1].v;
            }
            delta = d1;
            rate = r1;
            force = f1;
            n += 1;
            steps_taken += 1;
            contact_steps += 1;
            rec.push(t1, ag, &osc, f1);
            continue;
        }
        // A free step of up to `ratio` fine steps, checked at every fine grid point.
        let m = ratio.min(((t_end - t) / h).ceil().max(1.0) as usize);
        let hh = m as f64 * h;
        let ag = motion.at(t + hh);
        let before = osc;
        let slab_mark = slabs.as_ref().map(|s| [s[0].mark(), s[1].mark()]);
        let mut trial = osc;
        trial[0].commit(hh, osc[0].predict(hh, ag));
        trial[1].commit(hh, osc[1].predict(hh, ag));
        let mut first_touch = None;
        if sc.contact != ContactModel::None {
            for j in 1..=m {
                let s = j as f64 / m as f64;
                if let Some(sl) = slabs.as_mut() {
                    sl[0].push(0.0);
                    sl[1].push(0.0);
                }
                let e = slabs
                    .as_ref()
                    .map_or(0.0, |sl| sl[0].elastic_m() + sl[1].elastic_m());
                let ((u1, v1), (u2, v2)) = (
                    before[0].hermite(&trial[0], hh, s),
                    before[1].hermite(&trial[1], hh, s),
                );
                let d = u1 - u2 - sc.gap_m - e;
                // A contact starts where the element would push: a Kelvin-Voigt link that let go
                // with the slabs still overlapping does not grab them again while they part.
                // A damped link that let go with the slabs still overlapping takes hold again only
                // when they approach each other; otherwise any overlap starts a contact.
                let pushes = match sc.contact {
                    ContactModel::Kelvin | ContactModel::HertzDamp => d > 0.0 && v1 - v2 > 0.0,
                    _ => d > 0.0,
                };
                if pushes {
                    first_touch = Some(j);
                    break;
                }
            }
        }
        match first_touch {
            None => {
                osc = trial;
                account(
                    &mut energy,
                    &mut work_contact,
                    hh,
                    &before,
                    &osc,
                    motion.at(t),
                    ag,
                    0.0,
                    0.0,
                );
                n += m;
                steps_taken += 1;
                delta = overlap(&osc, &slabs);
                rate = osc[0].v - osc[1].v;
                rec.push(t + hh, ag, &osc, 0.0);
            }
            Some(j) => {
                // Back to the start of the step, then free up to the last grid point before the
                // touch; the contact starts within the next fine step.
                if let (Some(sl), Some(mk)) = (slabs.as_mut(), slab_mark) {
                    sl[0].reset(mk[0]);
                    sl[1].reset(mk[1]);
                }
                if j > 1 {
                    let hj = (j - 1) as f64 * h;
                    let agj = motion.at(t + hj);
                    osc[0].commit(hj, osc[0].predict(hj, agj));
                    osc[1].commit(hj, osc[1].predict(hj, agj));
                    if let Some(sl) = slabs.as_mut() {
                        for _ in 0..j - 1 {
                            sl[0].push(0.0);
                            sl[1].push(0.0);
                        }
                    }
                    account(
                        &mut energy,
                        &mut work_contact,
                        hj,
                        &before,
                        &osc,
                        motion.at(t),
                        agj,
                        0.0,
                        0.0,
                    );
                    n += j - 1;
                    steps_taken += 1;
                    rec.push(t + hj, agj, &osc, 0.0);
                }
                let t_on = n as f64 * h;
                delta = overlap(&osc, &slabs);
                rate = osc[0].v - osc[1].v;
                v0 = rate;
                if sc.contact == ContactModel::Stereo {
                    // Instantaneous exchange: the relative velocity reverses with restitution e.
                    let (m1, m2) = (osc[0].m, osc[1].m);
                    let w = osc[0].v - osc[1].v;
                    if w > 0.0 {
                        let impulse = (1.0 + sc.restitution) * m1 * m2 / (m1 + m2) * w;
                        let ke_before = osc[0].energy() + osc[1].energy();
                        osc[0].v -= impulse / m1;
                        osc[1].v += impulse / m2;
                        // Equilibrium at the new velocities (the dampers' forces changed with them).
                        let ag_on = motion.at(t_on);
                        for o in osc.iter_mut() {
                            o.a = -ag_on - (o.c * o.v + o.k * o.u) / o.m;
                        }
                        energy.contact_j += ke_before - (osc[0].energy() + osc[1].energy());
                        contacts.push(RawContact {
                            start_s: t_on,
                            end_s: t_on,
                            peak_force_n: 0.0,
                            impulse_ns: impulse,
                            approach_velocity_m_s: w,
                        });
                    }
                    // Step on past the touching instant with the new velocities.
                    let ag1 = motion.at(t_on + h);
                    let b = osc;
                    osc[0].commit(h, osc[0].predict(h, ag1));
                    osc[1].commit(h, osc[1].predict(h, ag1));
                    account(
                        &mut energy,
                        &mut work_contact,
                        h,
                        &b,
                        &osc,
                        motion.at(t_on),
                        ag1,
                        0.0,
                        0.0,
                    );
                    n += 1;
                    steps_taken += 1;
                    rec.push(t_on + h, ag1, &osc, 0.0);
                    continue;
                }
                in_contact = true;
                force = 0.0;
                if sears {
                    contacts.push(RawContact {
                        start_s: t_on,
                        end_s: t_on,
                        peak_force_n: 0.0,
                        impulse_ns: 0.0,
                        approach_velocity_m_s: v0,
                    });
                    continue;
                }
                // Locate the touch inside the next step (on the free motion's Hermite curve), step
                // freely to it, then in contact back onto the grid. A Kelvin-Voigt link pushes
                // with c delta' from the first instant: that force enters the accelerations there.
                let ag1 = motion.at(t_on + h);
                let mut free = osc;
                free[0].commit(h, osc[0].predict(h, ag1));
                free[1].commit(h, osc[1].predict(h, ag1));
                let gap_at = |x: f64| {
                    osc[0].hermite(&free[0], h, x).0 - osc[1].hermite(&free[1], h, x).0 - sc.gap_m
                };
                let (mut lo, mut hi) = (0.0f64, 1.0f64);
                // Search the touching instant only where the slabs are still apart at the step's
                // start (a re-engaging link starts where it is).
                if gap_at(0.0) <= 0.0 && gap_at(1.0) > 0.0 {
                    for _ in 0..60 {
                        let mid = 0.5 * (lo + hi);
                        if gap_at(mid) > 0.0 {
                            hi = mid
                        } else {
                            lo = mid
                        }
                    }
                }
                let hs = lo * h;
                if hs > 0.0 {
                    let b0 = osc;
                    let ags = motion.at(t_on + hs);
                    osc[0].commit(hs, osc[0].predict(hs, ags));
                    osc[1].commit(hs, osc[1].predict(hs, ags));
                    account(
                        &mut energy,
                        &mut work_contact,
                        hs,
                        &b0,
                        &osc,
                        motion.at(t_on),
                        ags,
                        0.0,
                        0.0,
                    );
                }
                rate = osc[0].v - osc[1].v;
                v0 = rate;
                delta = (osc[0].u - osc[1].u - sc.gap_m).max(0.0);
                if hs > 0.0 {
                    delta = 0.0;
                }
                if sc.contact == ContactModel::Kelvin {
                    force = element
                        .force(delta, rate, v0)
                        .max(element.kelvin_damping * rate.max(0.0));
                    osc[0].a -= force / osc[0].m;
                    osc[1].a += force / osc[1].m;
                }
                contacts.push(RawContact {
                    start_s: t_on + hs,
                    end_s: t_on + hs,
                    peak_force_n: force,
                    impulse_ns: 0.0,
                    approach_velocity_m_s: v0,
                });
                let ht = h - hs;
                let b1 = osc;
                let (d1, r1, f1) = contact_step(
                    &mut osc, &mut slabs, &element, sc.gap_m, ag1, ht, delta, rate, v0,
                );
                account(
                    &mut energy,
                    &mut work_contact,
                    ht,
                    &b1,
                    &osc,
                    motion.at(t_on + hs),
                    ag1,
                    force,
                    f1,
                );
                let c = contacts.last_mut().expect("just opened");
                c.impulse_ns += 0.5 * ht * (force + f1);
                c.peak_force_n = c.peak_force_n.max(f1);
                if f1 <= 0.0 {
                    c.end_s = t_on + h;
                    in_contact = false;
                    if c.impulse_ns == 0.0 {
                        contacts.pop();
                    }
                }
                delta = d1;
                rate = r1;
                force = f1;
                n += 1;
                steps_taken += 1;
                contact_steps += 1;
                rec.push(t_on + h, ag1, &osc, f1);
            }
        }
    }
    if in_contact && let Some(c) = contacts.last_mut() {
        c.end_s = t_end;
        warnings.push(format!(
            "the buildings were still in contact at the end of the record (t = {t_end} s)"
        ));
    }
    // The contact's start is refined to where the overlap crossed zero inside its first step.
    let stored = if delta > 0.0 {
        element.stored_energy(delta)
    } else {
        0.0
    };
    energy.final_j = osc[0].energy() + osc[1].energy();
    energy.stored_contact_j = stored;
    energy.contact_j += -work_contact - stored;
    let residual = energy.input_j
        - energy.building_damping_j
        - energy.contact_j
        - energy.final_j
        - energy.stored_contact_j;
    if residual < -0.01 * energy.input_j.abs() || !residual.is_finite() {
        warnings.push(format!("the run created energy: the buildings end with {:.3e} J more than the ground put in and the damping took out", -residual));
    }
    let impacts = group_impacts(&contacts, sc.merge_gap_s);
    let peak = |d: &Vec<f64>| d.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let max_force = rec.force.iter().cloned().fold(0.0, f64::max);
    let peak_displacement_m = [peak(&rec.disp[0]), peak(&rec.disp[1])];
    let wall = start.elapsed().as_secs_f64();
    Ok(BuildingResult {
        contact: sc.contact,
        time_s: rec.time_s,
        ground_m_s2: rec.ground,
        displacement_m: rec.disp,
        velocity_m_s: rec.vel,
        acceleration_m_s2: rec.acc,
        force_n: rec.force,
        contacts,
        impacts,
        peak_displacement_m,
        max_pounding_force_n: max_force,
        energy,
        stats: BuildingStats {
            steps: steps_taken,
            contact_steps,
            fine_step_s: h,
            coarse_step_s: ratio as f64 * h,
            wall_time_s: wall,
        },
        warnings,
    })
}
