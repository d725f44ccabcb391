//! The Sears impact model: a contact law at the contact surface, d'Alembert waves in the bars.
//!
//! All three readings share one form (docs/model.md, the paper's Eq. 8 corrected):
//!
//!   delta(t) = w t - sum_i (1/Z_i) [Psi_i(t - s_i1) + Psi_i(t - s_i2)],
//!   Psi_i(t) = Phi(t) + Psi_i(t - T_i),  Phi(t) = integral of F,  F = f(delta),
//!
//! with T_i = 2 l_i / c_i and two lags per bar:
//! - paper: l = L, lags d/c and (2L - d)/c (the planes P_i at x = d_i);
//! - collocated: l = L - d (the zone is a massless spring), lags 0 and T;
//! - end: l = L, lags 0 and T (d -> 0).
//!
//! Numerics. On a uniform grid every lag of a step or more is a known look-up ([`Tap`]); lags
//! shorter than a step put a known weight on the unknown Phi_{n+1}, so each step reduces to
//!   delta_{n+1} = W - c0 Phi_{n+1},  Phi_{n+1} = P + q h F_{n+1},  F = f(delta),
//! i.e. the monotone scalar equation delta + c0 q h f(delta) = W - c0 P, with one root.
//! Where c0 = 0 (the paper reading with d/c >= h) the step is explicit and Phi is a quadrature.
//! The quadrature is a theta method whose weight follows the local stiffness z = c0 f'(delta) h
//! ([`theta_for`]): the trapezoid rule where the step resolves the contact, backward Euler where
//! it does not, never ringing (the trapezoid alone rings on stiff contact, docs/numerics.md). Where the
//! step does not resolve the contact's rise, the force jumps within a step and look-ups into the
//! history are linear (monotone) instead of cubic.
//! Onset and separation are located inside the step, and the impulse of the partial step is
//! integrated up to (from) that instant, so durations are not quantised to the grid.

use super::timestep::{choose_step, contact_time_scale};
use super::{ContactSpan, Raw, SearsDiagnostics, SolveError, Times, Warning, peak_between};
use crate::model::contact::{ContactLaw, LawKind};
use crate::model::control::{CHECK_EVERY, Control};
use crate::model::error::InputError;
use crate::model::field::{BarWaves, History};
use crate::model::history::{Series, Tap, push_reserved};
use crate::model::scenario::{ImpactScenario, Reading};

struct Channel {
    inv_z: f64,
    recur: Tap,
    /// The displacement look-ups at the lags s_i1, s_i2. The first is `None` where it reads the
    /// newest sample alone (lag 0: the collocated and end readings): its known part is zero,
    /// and skipping it keeps the stored samples off the chain from one step to the next.
    near: Option<Tap>,
    far: Tap,
    /// Psi_{n+1} = (Phi_{n+1} + known) * gain: 1 / (1 - weight of the newest sample in the
    /// recursion), 1 unless the round trip is shorter than a step.
    gain: f64,
    /// Sum of the displacement look-ups' weights on the newest sample.
    top: f64,
}

impl Channel {
    /// The known parts of this bar's look-ups for the sample about to be pushed: the
    /// recursion's, and the displacement look-ups' (without the newest sample's share).
    #[inline(always)]
    fn known(&self, psi: &Series) -> (f64, f64) {
        let near = self.near.map_or(0.0, |tap| tap.known_before_push(psi));
        (
            self.recur.known_before_push(psi),
            near + self.far.known_before_push(psi),
        )
    }

    /// [`Channel::known`] by [`Tap::known_steady`].
    ///
    /// # Safety
    /// `psi.len() >= self.steady_from()`.
    #[inline(always)]
    unsafe fn known_steady(&self, psi: &Series) -> (f64, f64) {
        // SAFETY: the caller's promise covers every look-up.
        unsafe {
            let near = self.near.map_or(0.0, |tap| tap.known_steady(psi));
            (
                self.recur.known_steady(psi),
                near + self.far.known_steady(psi),
            )
        }
    }

    /// The history length from which [`Channel::known_steady`] may read.
    fn steady_from(&self) -> usize {
        self.near
            .map_or(0, |tap| tap.steady_from())
            .max(self.far.steady_from())
            .max(self.recur.steady_from())
    }
}

/// The buffers a Sears solve steps through. Repeated solves (sweeps, studies, the window's
/// worker) keep one and reuse it: a solve clears and refills it, allocating only when its run is
/// longer than every one before.
#[derive(Debug, Default)]
pub struct Workspace {
    psi: [Series; 2],
    phi: Series,
    force: Vec<f64>,
    delta: Vec<f64>,
    contacts: Vec<ContactSpan>,
}

/// What a run leaves besides the workspace's histories.
struct Run {
    law: ContactLaw,
    lay: Layout,
    z: [f64; 2],
    h: f64,
    n: usize,
    on: bool,
    warnings: Vec<Warning>,
    refined_from_s: Option<f64>,
}

/// The geometry of one reading: body lengths, lags, masses.
struct Layout {
    body_m: [f64; 2],
    zone_m: [f64; 2],
    lags_s: [[f64; 2]; 2],
    round_trip_s: [f64; 2],
    masses_kg: [f64; 2],
}

fn layout(sc: &ImpactScenario) -> Result<Layout, InputError> {
    let bars = [sc.bar1, sc.bar2];
    let zones = sc.zone_lengths_m();
    let mut out = Layout {
        body_m: [0.0; 2],
        zone_m: [0.0; 2],
        lags_s: [[0.0; 2]; 2],
        round_trip_s: [0.0; 2],
        masses_kg: [0.0; 2],
    };
    // Limits are printed in full: a rounded bound (0.0000) would be false.
    let shown = crate::model::settings::shown;
    let zone_scale = &crate::model::settings::impact::ZONE_SCALE;
    for i in 0..2 {
        let (bar, d) = (&bars[i], zones[i]);
        let c = bar.wave_speed_m_s();
        let l = bar.length_m;
        let name = crate::model::settings::BARS[i];
        match sc.reading {
            Reading::Paper => {
                if d > 2.0 * l {
                    return Err(InputError::new(
                        zone_scale.key,
                        format!(
                            "the paper reading is undefined here: {name}'s zone d = {} m exceeds twice its length ({} m), so a reflection would arrive before it left; allowed: contact.zone_scale < {} (or sears.reading = end)",
                            shown(d),
                            shown(2.0 * l),
                            shown(sc.contact.zone_scale * 2.0 * l / d)
                        ),
                    ));
                }
                out.body_m[i] = l;
                out.lags_s[i] = [d / c, (2.0 * l - d) / c];
            }
            Reading::Collocated => {
                if d >= l {
                    return Err(InputError::new(
                        zone_scale.key,
                        format!(
                            "the collocated reading needs the zone shorter than the bar: {name}'s d = {} m >= L = {} m; allowed: contact.zone_scale < {}",
                            shown(d),
                            shown(l),
                            shown(sc.contact.zone_scale * l / d)
                        ),
                    ));
                }
                out.body_m[i] = l - d;
                out.zone_m[i] = d;
                out.lags_s[i] = [0.0, 2.0 * (l - d) / c];
            }
            Reading::End => {
                out.body_m[i] = l;
                out.lags_s[i] = [0.0, 2.0 * l / c];
            }
        }
        out.round_trip_s[i] = 2.0 * out.body_m[i] / c;
        out.masses_kg[i] = bar.effective_density_kg_m3() * bar.area_m2() * out.body_m[i];
    }
    Ok(out)
}

/// Values of a cubic (or, with fewer points, linear) interpolant of samples at x = -2, -1, 0, 1.
struct LocalPoly {
    y: [f64; 4],
    cubic: bool,
}

impl LocalPoly {
    fn eval(&self, x: f64) -> f64 {
        let [a, b, c, d] = self.y;
        if !self.cubic {
            return c + (d - c) * x;
        }
        let wa = -(x + 1.0) * x * (x - 1.0) / 6.0;
        let wb = (x + 2.0) * x * (x - 1.0) / 2.0;
        let wc = -(x + 2.0) * (x + 1.0) * (x - 1.0) / 2.0;
        let wd = (x + 2.0) * (x + 1.0) * x / 6.0;
        wa * a + wb * b + wc * c + wd * d
    }

    /// The root in [0, 1] between y(0) and y(1), which have opposite signs (or y(0) = 0).
    fn root(&self) -> f64 {
        crate::model::root::bracket(|x| self.eval(x), 0.0, 1.0, 1e-14).mid()
    }

    /// h times the integral of f(y(x)) over [a, b] (3-point Gauss).
    fn integrate_force(&self, law: &ContactLaw, a: f64, b: f64, h: f64) -> f64 {
        let mid = 0.5 * (a + b);
        let half = 0.5 * (b - a);
        let g = (0.6f64).sqrt();
        let s = 5.0 * law.force(self.eval(mid - half * g))
            + 8.0 * law.force(self.eval(mid))
            + 5.0 * law.force(self.eval(mid + half * g));
        h * half * s / 9.0
    }
}

/// Weight of the new force in the theta method, from the step's stiffness ratio
/// z = c0 f'(delta) h: the trapezoid rule (second order) as z -> 0, backward Euler (L-stable,
/// exact in the quasi-static wave-theory limit) for z >= 2. The extra error against the
/// trapezoid is (theta - 1/2) = O(z^2) = O(h^2) per unit of local error, so the scheme stays second
/// order as the step shrinks; and theta >= 1 - 1/z everywhere, so the amplification factor
/// (1 - (1 - theta) z) / (1 + theta z) is never negative: stiff contact never rings.
fn theta_for(z: f64) -> f64 {
    theta_for_squared(z * z)
}

/// [`theta_for`] from z^2.
#[inline]
fn theta_for_squared(z2: f64) -> f64 {
    0.5 + 0.5 * (0.25 * z2).min(1.0)
}

/// What the step choice fixes for a run: the step, the span it expects, the histories' room and
/// whether look-ups may be cubic.
struct Plan {
    h: f64,
    expected_s: f64,
    capacity: usize,
    smooth: bool,
    warnings: Vec<Warning>,
    refined_from_s: Option<f64>,
}

/// The step from the contact's time scale and the bars' round trips (a bar rings with its round
/// trip during the contact: the step resolves that too).
fn plan(sc: &ImpactScenario, law: &ContactLaw, lay: &Layout, z: [f64; 2]) -> Plan {
    let w = sc.approach_velocity_m_s();
    let [m1, m2] = lay.masses_kg;
    let m_eff = m1 * m2 / (m1 + m2);
    let z_eff = z[0] * z[1] / (z[0] + z[1]);
    let mut scale = contact_time_scale(law, w, m_eff, z_eff);
    let t_short = lay.round_trip_s[0].min(lay.round_trip_s[1]);
    scale.resolve_s = scale.resolve_s.min(0.5 * t_short);
    let t_long = lay.round_trip_s[0].max(lay.round_trip_s[1]);
    let choice = choose_step(sc, scale, 2.0 * scale.lumped_duration_s.max(t_long));
    let h = choice.dt_s;
    // Room for the whole run up front (twice the likely span): a vector that grows mid-run
    // copies all its history.
    let expected_s = if sc.solver.window_s > 0.0 {
        sc.solver.window_s
    } else {
        2.0 * scale.lumped_duration_s.max(t_long)
    };
    Plan {
        h,
        expected_s,
        capacity: ((expected_s / h) as usize + 16).min(sc.solver.max_steps + 2),
        // Where the step resolves the contact's rise the histories are smooth on the grid and
        // cubic look-ups keep the error small; where it does not, the force jumps within a step
        // and only monotone (linear) look-ups avoid overshoot at the echoes of those jumps.
        smooth: h <= 0.5 * scale.resolve_s,
        warnings: choice.warning.into_iter().collect(),
        refined_from_s: choice.refined_from_s,
    }
}

/// The steps a run may take: up to its window, or until the bars part for good.
fn plan_steps(sc: &ImpactScenario, h: f64) -> usize {
    if sc.solver.window_s > 0.0 {
        (sc.solver.window_s / h).ceil() as usize
    } else {
        usize::MAX
    }
}

/// Each bar's look-ups: its recursion over the round trip and its displacement taps at the lags.
fn channels(lay: &Layout, z: [f64; 2], plan: &Plan) -> [Channel; 2] {
    let tap = |lag: f64| {
        if plan.smooth {
            Tap::new(lag, plan.h)
        } else {
            Tap::linear(lag, plan.h)
        }
    };
    std::array::from_fn(|i| {
        let recur = tap(lay.round_trip_s[i]);
        let taps = lay.lags_s[i].map(tap);
        let gain = 1.0 / (1.0 - recur.newest_weight());
        Channel {
            inv_z: 1.0 / z[i],
            recur,
            near: (!taps[0].newest_only()).then_some(taps[0]),
            far: taps[1],
            gain,
            top: taps[0].newest_weight() + taps[1].newest_weight(),
        }
    })
}

/// Empties the workspace for a run of about `capacity` steps and returns each Psi's padding.
/// Each Psi starts with zeros for the history before t = 0, as far back as its look-ups reach (up
/// to the run's expected length): the look-ups then read stored samples from the first step on,
/// without a branch. Only the look-ups read Psi, so the padding is invisible.
fn reset(ws: &mut Workspace, channels: &[Channel; 2], capacity: usize) -> [usize; 2] {
    let pad = [0, 1].map(|i| channels[i].steady_from().min(capacity));
    for (series, pad) in ws.psi.iter_mut().zip(pad) {
        series.clear();
        series.reserve(capacity + pad);
        series.push_zeros(pad + 1);
    }
    ws.phi.clear();
    ws.phi.reserve(capacity);
    ws.phi.push(0.0);
    for v in [&mut ws.force, &mut ws.delta] {
        v.clear();
        v.reserve(capacity);
        v.push(0.0);
    }
    ws.contacts.clear();
    pad
}

/// The least room, in samples, among the histories (each holds n + 1 samples at step n, after
/// its padding).
fn room(ws: &Workspace, pad: [usize; 2]) -> usize {
    (ws.psi[0].capacity() - pad[0])
        .min(ws.psi[1].capacity() - pad[1])
        .min(ws.phi.capacity())
        .min(ws.force.capacity())
        .min(ws.delta.capacity())
}

/// A run's pace: its step, the steps it expects and the most it may take.
struct Pace {
    h: f64,
    expected_steps: f64,
    max_steps: usize,
}

/// The bookkeeping a run does every so often rather than every step: the step budget, progress
/// and cancelling, and room in the histories. Returns the next step at which to come back (one
/// comparison a step for the three).
fn checkpoint(
    n: usize,
    pace: &Pace,
    control: &Control,
    ws: &mut Workspace,
    pad: [usize; 2],
    cap: &mut usize,
) -> Result<usize, SolveError> {
    if n >= pace.max_steps {
        return Err(SolveError::Budget {
            max_steps: pace.max_steps,
            dt_s: pace.h,
            reached_s: n as f64 * pace.h,
        });
    }
    if n.is_multiple_of(CHECK_EVERY) {
        control.report(n as f64 / pace.expected_steps)?;
    }
    if n + 2 > *cap {
        let more = (n + 2).max(1024);
        for v in ws.psi.iter_mut().chain(std::iter::once(&mut ws.phi)) {
            v.reserve(more);
        }
        ws.force.reserve(more);
        ws.delta.reserve(more);
        *cap = room(ws, pad);
    }
    Ok(((n / CHECK_EVERY + 1) * CHECK_EVERY)
        .min(pace.max_steps)
        .min(*cap - 1))
}

/// The newest samples a step starts from, carried in registers: read back from their vectors
/// they would wait on the store of the step before.
#[derive(Clone, Copy)]
struct Newest {
    /// Force F_n.
    force: f64,
    /// Impulse Phi_n.
    phi: f64,
    /// Overlap delta_n.
    delta: f64,
}

/// What is fixed for every step of a run: the law, the step, and c0, the look-ups' weight on
/// the newest impulse (the lags fix it).
struct Stepper<'a> {
    law: &'a ContactLaw,
    h: f64,
    c0: f64,
    /// (1.5 k c0 h)^2: z^2 per unit of overlap, for theta without a square root.
    z2_per_delta: f64,
}

/// A step's outcome: the overlap, force and impulse at its end, and the theta it used.
struct Advanced {
    delta: f64,
    force: f64,
    phi: f64,
    theta: f64,
}

impl Stepper<'_> {
    /// The step from t_n to t_n+1 with the contact law on: `wv` is the overlap the bars' known
    /// motion alone would give, `free` the same less the newest impulse's share.
    #[inline(always)]
    fn advance(&self, n: usize, delta: &[f64], wv: f64, free: f64, now: Newest) -> Advanced {
        let (law, h, c0) = (self.law, self.h, self.c0);
        if c0 == 0.0 {
            // Explicit: delta_{n+1} depends on history alone; Phi by the trapezoid rule.
            let force = law.force(wv);
            return Advanced {
                delta: wv,
                force,
                phi: now.phi + 0.5 * h * (now.force + force),
                theta: 0.5,
            };
        }
        // The overlap at the end of the step, extrapolated by a cubic through four steps ending
        // two before it (taken three steps on: within 15 (h / T)^4 of it, relatively, on a
        // contact of time scale T): its square root starts Newton on s = sqrt(delta), and it
        // gives the step's stiffness for theta. Leaving out the last two steps keeps all of it
        // off the chain from one step to the next: it is ready before the step's look-ups are.
        // The overlap, not its root, is extrapolated because it is smooth at onset (delta ~ w t
        // there, where sqrt(delta) has no Taylor series). Elsewhere (linear law, the first
        // steps) the stiffness is the law's at the larger of the overlap now and the one the
        // step heads for.
        let guess = if law.kind == LawKind::Hertz && n >= 5 {
            let [a, b, c, d] = [delta[n - 2], delta[n - 3], delta[n - 4], delta[n - 5]];
            if a > 0.0 && b > 0.0 && c > 0.0 && d > 0.0 {
                20.0 * a - 45.0 * b + 36.0 * c - 10.0 * d
            } else {
                -1.0
            }
        } else {
            -1.0
        };
        // theta from z^2 = (1.5 k c0 h)^2 delta: no square root on the way to it.
        let theta = if guess > 0.0 {
            theta_for_squared(self.z2_per_delta * guess)
        } else {
            theta_for(c0 * h * law.tangent(now.delta.max(free)))
        };
        let p = now.phi + (1.0 - theta) * h * now.force;
        let (beta, rhs) = (c0 * theta * h, wv - c0 * p);
        let (d1, f1);
        if law.kind == LawKind::Hertz && rhs > 0.0 {
            // u = (rhs - G(s0)) / G'(s0), arranged so that only p waits on the step before.
            let step = (guess > 0.0).then(|| law.sqrt_step(beta, guess));
            let root = step.and_then(|st| st.root((wv - st.g0) * st.inv - (c0 * st.inv) * p));
            let s1 = match root {
                Some(s1) => s1,
                None => law.solve_implicit_sqrt(beta, rhs, step.map_or(-1.0, |st| st.s0)),
            };
            d1 = s1 * s1;
            f1 = d1 * (law.stiffness * s1);
        } else {
            d1 = law.solve_implicit(beta, rhs, now.delta);
            f1 = law.force(d1);
        }
        Advanced {
            delta: d1,
            force: f1,
            phi: p + theta * h * f1,
            theta,
        }
    }

    /// The cubic (linear in the first steps) through the overlaps at t_n-2 .. t_n, with
    /// `next` at t_n+1.
    fn local(n: usize, delta: &[f64], now: Newest, next: f64) -> LocalPoly {
        LocalPoly {
            y: [
                if n >= 2 { delta[n - 2] } else { 0.0 },
                if n >= 1 { delta[n - 1] } else { 0.0 },
                now.delta,
                next,
            ],
            cubic: n >= 2,
        }
    }

    /// The contact ends inside (t_n, t_n+1]: when, and the step's impulse and overlap at its end.
    fn separation(
        &self,
        n: usize,
        ws: &Workspace,
        wv: f64,
        now: Newest,
        step: &Advanced,
    ) -> (f64, f64, f64) {
        let (h, c0) = (self.h, self.c0);
        if c0 == 0.0 {
            let poly = Self::local(n, &ws.delta, now, step.delta);
            let x = poly.root();
            let phi1 = now.phi + poly.integrate_force(self.law, 0.0, x, h);
            return (n as f64 * h + x * h, phi1, step.delta);
        }
        // A theta sub-step of length s = x h ending where delta = 0 (so F = 0 there):
        // g(x) = W(t_n + x h) - c0 (Phi_n + (1 - theta) x h F_n) = 0, with W = delta + c0 Phi
        // smooth and known on the grid, so a cubic through W_{n-2..n+1} locates it.
        let theta = step.theta;
        let w_at = |k: usize| ws.delta[k] + c0 * ws.phi.get(k);
        let g = |x: f64, wk: f64| wk - c0 * (now.phi + (1.0 - theta) * x * h * now.force);
        let poly = LocalPoly {
            y: [
                if n >= 2 { g(-2.0, w_at(n - 2)) } else { 0.0 },
                if n >= 1 { g(-1.0, w_at(n - 1)) } else { 0.0 },
                g(0.0, w_at(n)),
                g(1.0, wv),
            ],
            cubic: n >= 2,
        };
        if poly.y[3] <= 0.0 {
            let x = poly.root();
            let phi1 = now.phi + x * h * (1.0 - theta) * now.force;
            (n as f64 * h + x * h, phi1, wv - c0 * phi1)
        } else {
            ((n + 1) as f64 * h, step.phi, step.delta)
        }
    }

    /// A contact begins inside (t_n, t_n+1]: when, and the step redone from there.
    fn onset(
        &self,
        n: usize,
        delta: &[f64],
        free: f64,
        now: Newest,
        step: &Advanced,
    ) -> (f64, Advanced) {
        let (law, h, c0) = (self.law, self.h, self.c0);
        if c0 == 0.0 {
            let poly = Self::local(n, delta, now, step.delta);
            let x = poly.root();
            let phi = now.phi + poly.integrate_force(law, x, 1.0, h);
            return (
                n as f64 * h + x * h,
                Advanced {
                    phi,
                    delta: step.delta,
                    force: step.force,
                    theta: step.theta,
                },
            );
        }
        let s0 = h * (-now.delta) / (free - now.delta);
        let hp = h - s0;
        let th = if c0 * hp * law.tangent(free) > 0.5 {
            1.0
        } else {
            0.5
        };
        let d1 = law.solve_implicit(c0 * th * hp, free, now.delta);
        let f1 = law.force(d1);
        (
            n as f64 * h + s0,
            Advanced {
                delta: d1,
                force: f1,
                phi: now.phi + th * hp * f1,
                theta: step.theta,
            },
        )
    }
}

/// The overlap the bars' known motion gives at the end of the step, before the new impulse's
/// share: the rigid approach `approach` less both bars' look-ups. Also each bar's recursion
/// part, which its new Psi sample needs.
///
/// # Safety
/// With `steady`, every Psi must hold as many samples as its look-ups reach (`steady_from`).
#[inline(always)]
unsafe fn known_motion(
    channels: &[Channel; 2],
    psi: &[Series; 2],
    steady: bool,
    approach: f64,
) -> (f64, [f64; 2]) {
    let [(r0, k0), (r1, k1)] = if steady {
        // SAFETY: the caller's promise.
        unsafe {
            [
                channels[0].known_steady(&psi[0]),
                channels[1].known_steady(&psi[1]),
            ]
        }
    } else {
        [channels[0].known(&psi[0]), channels[1].known(&psi[1])]
    };
    let wv = approach
        - channels[0].inv_z * (k0 + channels[0].top * (r0 * channels[0].gain))
        - channels[1].inv_z * (k1 + channels[1].top * (r1 * channels[1].gain));
    (wv, [r0, r1])
}

/// Steps an impact through `ws`: its histories of Psi, Phi, force and approach, its contacts.
fn run(sc: &ImpactScenario, control: &Control, ws: &mut Workspace) -> Result<Run, SolveError> {
    let law = sc.contact_law()?;
    let lay = layout(sc)?;
    let z = [sc.bar1, sc.bar2].map(|b| b.impedance_n_s_m());
    let w = sc.approach_velocity_m_s();
    let m_eff = lay.masses_kg[0] * lay.masses_kg[1] / (lay.masses_kg[0] + lay.masses_kg[1]);
    let plan = plan(sc, &law, &lay, z);
    let channels = channels(&lay, z, &plan);
    let pad = reset(ws, &channels, plan.capacity);
    let Plan {
        h,
        expected_s,
        mut warnings,
        refined_from_s,
        ..
    } = plan;
    let n_stop = plan_steps(sc, h);
    let mut contact_phi0 = 0.0;
    let mut on = true;
    ws.contacts.push(ContactSpan::opening(0.0));
    let mut n = 0usize;
    // c0 depends only on the lags, so it is the same every step.
    let c0: f64 = channels.iter().map(|ch| ch.inv_z * ch.top * ch.gain).sum();
    let stepper = Stepper {
        law: &law,
        h,
        c0,
        z2_per_delta: (1.5 * law.stiffness * c0 * h).powi(2),
    };
    let pace = Pace {
        h,
        expected_steps: (expected_s / h).max(1.0),
        max_steps: sc.solver.max_steps,
    };
    let mut now = Newest {
        force: 0.0,
        phi: 0.0,
        delta: 0.0,
    };
    // From step n = steady_after - 1 on, every Psi holds as many samples as its look-ups reach.
    let steady_after = (0..2)
        .map(|i| channels[i].steady_from().saturating_sub(pad[i]))
        .max()
        .unwrap_or(0);
    let mut cap = room(ws, pad);
    let mut next_event = 0usize;
    while n < n_stop {
        if n >= next_event {
            next_event = checkpoint(n, &pace, control, ws, pad, &mut cap)?;
        }
        // SAFETY: from step n = steady_after - 1 on, series i holds pad_i + n + 1 >=
        // steady_from_i samples.
        let (wv, [r0, r1]) = unsafe {
            known_motion(
                &channels,
                &ws.psi,
                n + 1 >= steady_after,
                w * ((n + 1) as f64 * h),
            )
        };
        let free = wv - c0 * now.phi;
        let mut step = stepper.advance(n, &ws.delta, wv, free, now);
        let mut separated = false;
        if on && step.delta <= 0.0 {
            let (t_star, phi1, d1) = stepper.separation(n, ws, wv, now, &step);
            (step.phi, step.delta, step.force) = (phi1, d1, 0.0);
            on = false;
            separated = true;
            ws.contacts
                .last_mut()
                .expect("a contact is open")
                .close(t_star, phi1 - contact_phi0);
        } else if !on && step.delta > 0.0 {
            let t_on;
            (t_on, step) = stepper.onset(n, &ws.delta, free, now, &step);
            on = true;
            contact_phi0 = now.phi;
            ws.contacts.push(ContactSpan::opening(t_on));
        }
        // Store the new samples: Psi_i(t_n+1) = Phi_n+1 + Psi_i(t_n+1 - T_i).
        // SAFETY: every vector holds n + 1 < cap samples (next_event <= cap - 1 makes room).
        unsafe {
            for ((ch, r), series) in channels.iter().zip([r0, r1]).zip(ws.psi.iter_mut()) {
                series.push_reserved((step.phi + r) * ch.gain);
            }
            ws.phi.push_reserved(step.phi);
            push_reserved(&mut ws.force, step.force);
            push_reserved(&mut ws.delta, step.delta);
        }
        now = Newest {
            force: step.force,
            phi: step.phi,
            delta: step.delta,
        };
        n += 1;
        if separated && sc.solver.window_s == 0.0 && w - step.phi / m_eff <= 0.0 {
            break;
        }
    }
    super::close_open_contact(
        &mut ws.contacts,
        ws.phi.last(),
        contact_phi0,
        n as f64 * h,
        &mut warnings,
    );
    Ok(Run {
        law,
        lay,
        z,
        h,
        n,
        on,
        warnings,
        refined_from_s,
    })
}

/// One Sears solve, every history kept.
pub(crate) fn solve(sc: &ImpactScenario, control: &Control) -> Result<Raw, SolveError> {
    // The histories the result keeps move out of the workspace; Psi (internal to the run) and
    // its room stay in a per-thread one for the next solve.
    thread_local! {
        static SCRATCH: std::cell::RefCell<Workspace> = std::cell::RefCell::default();
    }
    let (outcome, phi, force, delta, contacts) = SCRATCH.with(|cell| {
        // Were the cell ever in use (a solve within a solve on this thread), a fresh workspace
        // would serve.
        let mut fresh = Workspace::default();
        let mut guard = cell.try_borrow_mut().ok();
        let ws = guard.as_deref_mut().unwrap_or(&mut fresh);
        let outcome = run(sc, control, ws);
        (
            outcome,
            std::mem::take(&mut ws.phi),
            std::mem::take(&mut ws.force),
            std::mem::take(&mut ws.delta),
            std::mem::take(&mut ws.contacts),
        )
    });
    let Run {
        law,
        lay,
        z,
        h,
        n,
        on,
        mut warnings,
        refined_from_s,
    } = outcome?;
    let bars = [sc.bar1, sc.bar2];
    let end_s = n as f64 * h;
    let time_s: Vec<f64> = (0..n + 1).map(|k| k as f64 * h).collect();
    let impulse = phi.last();
    let waves = build_waves(sc, &lay, &force, h, end_s);
    let vibration_j: f64 = (0..2)
        .map(|i| waves[i].wave_energy_j(end_s) - impulse * impulse / (2.0 * lay.masses_kg[i]))
        .sum();
    let contact_j = if on {
        law.energy(*delta.last().unwrap_or(&0.0))
    } else {
        0.0
    };

    let zones = sc.zone_lengths_m();
    let c = bars.map(|b| b.wave_speed_m_s());
    let plane_delays_s = [zones[0] / c[0], zones[1] / c[1]];
    let first = contacts[0];
    let peak = peak_between(
        Times::Stored(&time_s),
        &force,
        first.start_s,
        first.end_s.unwrap_or(f64::INFINITY),
    );
    let kt = law.tangent_at_force(peak);
    let a_tau = kt * (plane_delays_s[0] / z[0] + plane_delays_s[1] / z[1]);
    if sc.reading == Reading::Paper {
        for (i, bar) in bars.iter().enumerate() {
            if zones[i] > bar.length_m {
                warnings.push(Warning::ZoneLongerThanBar {
                    bar: i + 1,
                    zone_m: zones[i],
                    length_m: bar.length_m,
                });
            }
        }
    }
    Ok(Raw {
        time_s,
        force_n: force,
        approach_m: delta,
        contacts,
        impulse_ns: impulse,
        masses_kg: lay.masses_kg,
        vibration_j,
        contact_j,
        end_s,
        waves: Some(waves),
        impulse_history_ns: phi.into_samples(),
        sears: Some(SearsDiagnostics {
            reading: sc.reading,
            zone_lengths_m: zones,
            plane_delays_s,
            tangent_stiffness_n_m: kt,
            a_tau,
            creates_energy: false,
        }),
        warnings,
        steps: n,
        dt_s: h,
        refined_from_s,
        ..Raw::default()
    })
}

/// One Sears solve through `ws`, reduced to what a sweep reports: no histories kept, nothing
/// allocated once `ws` has seen a run as long.
pub(crate) fn summary(
    sc: &ImpactScenario,
    control: &Control,
    ws: &mut Workspace,
) -> Result<super::ImpactSummary, SolveError> {
    let run = run(sc, control, ws)?;
    let times = Times::Uniform {
        h: run.h,
        len: run.n + 1,
    };
    Ok(super::summarize(
        sc,
        &ws.contacts,
        times,
        &ws.force,
        ws.phi.last(),
        run.lay.masses_kg,
    ))
}

/// H_i on the grid from the force samples: H_n = F_n + H(t_n - T_i).
#[inline(never)]
fn build_waves(
    sc: &ImpactScenario,
    lay: &Layout,
    force: &[f64],
    h: f64,
    end_s: f64,
) -> [BarWaves; 2] {
    let bars = [sc.bar1, sc.bar2];
    std::array::from_fn(|i| {
        let bar = &bars[i];
        let tap = Tap::new(lay.round_trip_s[i], h);
        let mut hs = Series::with_capacity(force.len());
        let b = 1.0 / (1.0 - tap.newest_weight());
        let warm = tap.steady_from().min(force.len());
        // While the series is shorter than this, the look-up reads only the zeros before t = 0.
        let zero = tap.steady_from().saturating_sub(3).min(warm);
        hs.extend(force[..zero].iter().map(|&f| f * b));
        for &f in &force[zero..warm] {
            let v = (f + tap.known_before_push(&hs)) * b;
            hs.push(v);
        }
        for &f in &force[warm..] {
            // SAFETY: hs holds at least steady_from samples here, and room for all of `force`.
            unsafe {
                let v = (f + tap.known_steady(&hs)) * b;
                hs.push_reserved(v);
            }
        }
        BarWaves {
            body_length_m: lay.body_m[i],
            zone_length_m: lay.zone_m[i],
            wave_speed_m_s: bar.wave_speed_m_s(),
            area_m2: bar.area_m2(),
            impedance_n_s_m: bar.impedance_n_s_m(),
            initial_velocity_m_s: bar.velocity_m_s,
            push_direction: if i == 0 { -1.0 } else { 1.0 },
            history: History::Uniform {
                dt_s: h,
                values: hs.into_samples(),
            },
            end_s,
            decay_per_s: 0.0,
        }
    })
}
