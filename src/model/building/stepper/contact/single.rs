//! The contact step of a pair with one contact level, while that level is in contact: the
//! general step ([`Stepper::contact_step_of`]) with what one level makes of it written out. No
//! level sleeps or is out of reach, the compliance is one number, the forces' sweep is one
//! scalar equation, and the step is a whole grid step: the same operations on the same numbers
//! in the same order, without the loops, look-ups and checks that serve several levels.

use super::*;

impl Stepper<'_> {
    /// Whether the next contact step is one the single level's step takes: one level, in
    /// contact (so awake, read exactly, its slabs live), on the grid, after a contact step (so
    /// Newmark's loads are the last trial's and the whole step's compliance is made), on
    /// elastic sides of few modes, with an element that does not let go inside a step. (No
    /// level sleeps and every slab is live once the one level has force: those two checks are
    /// the general step's assumptions kept in sight, not cases met.)
    #[inline(always)]
    pub(in crate::model::building::stepper) fn single_level_step(&self) -> bool {
        if !self.single_level {
            return false;
        }
        let cs = self
            .contact_scratch
            .as_deref()
            .expect("the scratch is home between stages");
        self.newmark
            && self.offset == 0.0
            && cs.g_full.is_some()
            && cs.awake.len() == 1
            && cs.sleep.due.is_empty()
            && cs.sleep.looked.is_empty()
            && self.points[0].force > 0.0
            && self.points[0].slabs.iter().flatten().all(|s| s.is_live())
    }

    /// The single level's contact step, where [`Stepper::single_level_step`] holds: one
    /// whole grid step, its trial and its commit written out for the one level.
    #[inline(always)]
    pub(in crate::model::building::stepper) fn contact_step_single(
        &mut self,
    ) -> Result<(), SolveError> {
        self.count_step()?;
        #[cfg(test)]
        super::super::SINGLE_STEPS.with(|c| c.set(c.get() + 1));
        let mut cs = self
            .contact_scratch
            .take()
            .expect("the scratch is home between stages");
        std::mem::swap(&mut cs.load_now, &mut cs.trial.load);
        cs.ground0 = self.motion.at(self.time());
        cs.clear_near_forced();
        // A side of one mode (the paper's buildings) has its sums unrolled.
        let n = self.mode_counts();
        if n == [1, 1] {
            self.trial_single(self.grid.h, [1, 1], &mut cs);
            self.commit_single([1, 1], &mut cs);
        } else {
            self.trial_single(self.grid.h, n, &mut cs);
            self.commit_single(n, &mut cs);
        }
        self.contact_scratch = Some(cs);
        Ok(())
    }

    /// [`Stepper::trial_once`] over a whole grid step for the one level, in contact.
    #[inline(always)]
    fn trial_single(&self, hh: f64, n: [usize; 2], cs: &mut Scratch) {
        let ground = self.motion.at(self.time() + hh);
        let ground_change = ground - cs.ground0;
        for (s, n) in n.into_iter().enumerate() {
            self.free_increment_of(s, n, hh, true, ground_change, cs);
        }
        // The overlap without new forces and the compliance (contact_compliance): a level
        // with force is within reach, its slabs' predictions read.
        let p = &self.points[0];
        let closing = self.closing_after_of(p, &cs.step, n) - self.sc.gap_m;
        let (e0, e1) = if self.sears {
            predict_slabs(p, self.n + 1, &mut cs.slab_predictions[0], true)
        } else {
            (0.0, 0.0)
        };
        cs.far[0] = false;
        cs.predicted[0] = closing - e0;
        cs.compliance[0] = e1;
        cs.use_full = true;
        // The force (contact_forces): one level's equation, no other level's force on it. The
        // others' forces summed as the general sweep sums them (over none: from -0), so that
        // the right-hand side rounds as there.
        let g = cs.g_full.as_ref().expect("made")[0];
        let others: f64 = std::iter::empty::<f64>().sum();
        let rhs = cs.predicted[0] - others;
        let d = p.element.solve_step(g, rhs, hh, p.delta, p.rate, p.v0);
        let rate = p.element.rate(hh, d, p.delta, p.rate);
        let f = self.trial_force(p, d, rate, true);
        let out = &mut cs.trial;
        out.forces[0] = f;
        out.deltas[0] = d;
        out.rates[0] = rate;
        self.end_trial(true, hh, ground, cs);
    }

    /// [`Stepper::commit_contact`] for the one level: no level asleep, no link let go, no
    /// storey yielding.
    #[inline(always)]
    fn commit_single(&mut self, n: [usize; 2], cs: &mut Scratch) {
        let hh = cs.trial.hh;
        let t0 = self.time();
        self.keep_closing_before(0, &mut cs.u_before, &cs.closing_step, n);
        let sizes = self.commit_modes(cs, n);
        self.advance(hh);
        self.push_slabs(0, cs.trial.forces[0], cs.slab_predictions[0]);
        let opened_or_closed = self.account_contact_of(0, cs, t0, n);
        self.contact_steps += 1;
        self.settle_if_free(0);
        self.track_peaks_in_contact(sizes, &cs.modal_before, hh);
        self.record_in_contact(opened_or_closed);
    }
}

#[cfg(test)]
mod tests {
    use super::super::super::{GENERAL_STEPS_ONLY, SINGLE_STEPS};
    use crate::model::building::{
        BuildingResult, BuildingScenario, ContactModel, SlabReading, Tracked, solve,
    };
    use crate::model::control::Control;
    use crate::model::motion::GroundMotion;

    /// A run's every number (its wall time aside), bit for bit: the debug form of a float is
    /// the shortest that reads back as the same bits.
    fn every_number(r: &BuildingResult) -> String {
        let mut r = r.clone();
        r.stats.wall_time_s = 0.0;
        format!("{r:?}")
    }

    /// The run with its histories, and the error estimate's companion (a summary of the
    /// floors, every step halved), each with the number of single level's steps it took.
    fn both_runs(sc: &BuildingScenario, m: &GroundMotion) -> [(BuildingResult, usize); 2] {
        let counted = |run: &dyn Fn() -> BuildingResult| {
            SINGLE_STEPS.with(|c| c.set(0));
            let r = run();
            (r, SINGLE_STEPS.with(|c| c.get()))
        };
        [
            counted(&|| solve::solve(sc, m).expect("run")),
            counted(&|| {
                let never = Control::never();
                solve::solve_summary_refined(sc, m, never, Tracked::Floors, 2).expect("run")
            }),
        ]
    }

    #[test]
    fn one_levels_contact_step_is_the_general_step_bit_for_bit() {
        let m = solve::tests::el_centro_8s();
        let mut cases = Vec::new();
        for contact in [
            ContactModel::Sears,
            ContactModel::Linear,
            ContactModel::Hertz,
            ContactModel::HertzDamp,
            ContactModel::Jankowski,
        ] {
            let mut sc = BuildingScenario::paper();
            sc.contact = contact;
            cases.push(sc.clone());
            // One storey against three: one level, a side of three modes.
            sc.right.storeys = 3;
            cases.push(sc);
        }
        let mut sc = BuildingScenario::paper();
        sc.reading = SlabReading::End;
        sc.gap_m *= 0.5;
        cases.push(sc);
        // The left roof (4 m) against the right's column below its floor at 5 m: one slab at
        // the level.
        let mut sc = BuildingScenario::paper();
        sc.right.heights_m = vec![5.0];
        cases.push(sc);
        for sc in cases {
            let single = both_runs(&sc, &m);
            GENERAL_STEPS_ONLY.with(|g| g.set(true));
            let general = both_runs(&sc, &m);
            GENERAL_STEPS_ONLY.with(|g| g.set(false));
            for ((one, taken), (all, none)) in single.iter().zip(&general) {
                assert_eq!(*none, 0, "the general run took the single level's step");
                assert_eq!(one.levels.len(), 1, "{:?} {:?}", sc.contact, one.levels);
                // Not vacuous: most of the contact steps were the single level's.
                let steps = one.stats.contact_steps;
                assert!(
                    *taken > 1000 && 10 * taken > 9 * steps,
                    "{:?}: {taken} of {steps}",
                    sc.contact
                );
                let (a, b) = (every_number(one), every_number(all));
                if a != b {
                    let at = a.bytes().zip(b.bytes()).take_while(|(x, y)| x == y).count();
                    let around =
                        |s: &str| s[at.saturating_sub(200)..(at + 80).min(s.len())].to_string();
                    panic!(
                        "{:?} {:?}: the runs differ from\n{}\nto\n{}",
                        sc.contact,
                        sc.reading,
                        around(&a),
                        around(&b)
                    );
                }
            }
        }
    }
}
