//! When a weaker level of the graded fallback would only repeat a failed
//! search.
//!
//! A search is a pure function of the problem, the configuration, the seed
//! and the effort: every random draw follows from the seed, and what is kept
//! follows from the validity check's verdicts. The levels of
//! [`Compliance`](crate::Compliance) differ only in which duties that check
//! applies ([`Compliance::checks`](crate::Compliance::checks)), and a weaker
//! level applies a subset of a stricter level's checks, in the same order.
//! So when a stricter search refused no move for a cause the weaker level
//! does not check, every verdict of the weaker search is the same (what the
//! stricter one accepted passes fewer checks; what it refused is refused by
//! the same check, which the weaker one reaches because the checks before it
//! passed), it draws the same samples, grows the same trees and fails the
//! same way. Asking it costs a whole search and cannot change the answer.

use crate::config::{Compliance, PlannerConfig, SearchEffort};
use crate::plan::{RejectionCause, RejectionCounts};
use crate::problem::PlanningProblem;
use crate::validity::{EncounterState, MotionValidator};
use std::cell::Cell;
use std::time::Instant;
use vorrt_jfs::Leg;

/// A search that found no safe path, with every move its validity check
/// refused, by cause: in the tree, and in the path simplifier and the
/// manoeuvre search.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct FailedSearch {
    pub(crate) problem: PlanningProblem,
    pub(crate) config: PlannerConfig,
    pub(crate) seed: u64,
    pub(crate) effort: SearchEffort,
    pub(crate) refused: RejectionCounts,
    /// Every verdict of its validity check, in the order asked ([`Verdicts`]).
    pub(crate) verdicts: Vec<Verdict>,
}

impl FailedSearch {
    /// Whether a search of `problem` with `config`, `seed` and `effort` is
    /// this one at a compliance level at most as strict: the same problem,
    /// seed, effort and every other setting.
    fn same_search_at_weaker_level(
        &self,
        problem: &PlanningProblem,
        config: &PlannerConfig,
        seed: u64,
        effort: SearchEffort,
    ) -> bool {
        PlannerConfig {
            compliance: self.config.compliance,
            ..*config
        } == self.config
            && seed == self.seed
            && effort == self.effort
            && weaker_or_equal(config.compliance, self.config.compliance)
            && *problem == self.problem
    }

    /// Whether a search of the same problem with `config`, `seed` and
    /// `effort` would repeat this one (see the module documentation).
    pub(crate) fn repeated_by(
        &self,
        problem: &PlanningProblem,
        config: &PlannerConfig,
        seed: u64,
        effort: SearchEffort,
    ) -> bool {
        self.same_search_at_weaker_level(problem, config, seed, effort)
            && self
                .refused
                .by_cause()
                .iter()
                .all(|&(cause, count)| count == 0 || config.compliance.checks(cause))
    }

    /// Whether a search of the same problem with `config`, `seed` and
    /// `effort` asks the same moves in the same order as this one for as
    /// long as their verdicts agree, so that [`Verdicts`] may replay this
    /// one's: the same problem, seed, effort and settings but a compliance
    /// level at most as strict, and no time budget (a search cut short by
    /// the clock asks what the clock allows).
    ///
    /// A search that grows its tree only where constrained asks what the
    /// search that always grows it asks, and stops where it would grow the
    /// tree ([`SearchEffort::always_growing`]): the other search replays it
    /// too, and judges afresh from where it stopped (decision 66).
    pub(crate) fn replayable_by(
        &self,
        problem: &PlanningProblem,
        config: &PlannerConfig,
        seed: u64,
        effort: SearchEffort,
    ) -> bool {
        let as_asked = if effort == self.effort.always_growing() {
            self.effort
        } else {
            effort
        };
        config.time_budget_s.is_none()
            && self.same_search_at_weaker_level(problem, config, seed, as_asked)
    }
}

/// One verdict of the validity check.
pub(crate) type Verdict = Result<(), RejectionCause>;

/// The verdicts of one search, in the order its validity check is asked,
/// and those of an earlier, failed search of the same problem at a
/// stricter level of the graded fallback, replayed where they are known
/// (decision 53).
///
/// A search is a pure function of the problem, the settings, the seed and
/// the effort, and of its verdicts: which move it asks next follows from
/// the verdicts before (module documentation). So a weaker level asks the
/// stricter search's moves in the same order for as long as every verdict
/// agrees, and where the stricter search refused a move for a duty the
/// weaker level checks too ([`Compliance::checks`](crate::Compliance::checks)), the weaker level refuses it
/// for the same duty (the checks before it pass, being a subset of those
/// that passed): that verdict is taken from the earlier search instead of
/// judged again. Every other move is judged; from the first verdict that
/// differs from the earlier search's, the two searches part and nothing
/// more is replayed. A move the earlier search accepted is judged again,
/// for the encounters in force at its end. The verdicts, and so the plans,
/// are the same as without the replay; only the work differs.
#[derive(Debug, Default)]
pub(crate) struct Verdicts {
    /// The earlier search's verdicts (empty: none to replay).
    earlier: Vec<Verdict>,
    /// This search's level.
    level: Compliance,
    /// How many verdicts this search has given.
    asked: usize,
    /// Whether this search has parted from the earlier one.
    parted: bool,
    /// This search's verdicts, in order.
    pub(crate) log: Vec<Verdict>,
    /// How many verdicts were replayed rather than judged.
    pub(crate) replayed: u64,
}

impl Verdicts {
    /// Starts a search at `level`, replaying `earlier` where it can.
    pub(crate) fn start(&mut self, earlier: Option<&[Verdict]>, level: Compliance) {
        self.earlier.clear();
        self.earlier.extend_from_slice(earlier.unwrap_or_default());
        self.level = level;
        self.asked = 0;
        self.parted = earlier.is_none();
        self.log.clear();
        self.replayed = 0;
    }

    /// Whether the earlier search's verdicts are still being replayed (this
    /// search has not parted from it).
    pub(crate) fn replaying(&self) -> bool {
        !self.parted
    }

    /// The verdict of the next move, where the earlier search's is known
    /// to be this level's.
    fn known(&self) -> Option<Verdict> {
        if self.parted {
            return None;
        }
        match self.earlier.get(self.asked) {
            Some(&Err(cause)) if self.level.checks(cause) => Some(Err(cause)),
            _ => None,
        }
    }

    /// Records the next move's verdict.
    fn record(&mut self, verdict: Verdict) {
        if !self.parted && self.earlier.get(self.asked) != Some(&verdict) {
            self.parted = true;
        }
        self.asked += 1;
        self.log.push(verdict);
    }
}

/// A validator that records its verdicts in [`Verdicts`] and gives the
/// earlier search's where they are known, without judging the move (the
/// encounters in `state` are then left as they were: a refused move's
/// state is not used).
pub(crate) struct Replaying<'a, V> {
    pub(crate) validator: &'a V,
    pub(crate) verdicts: &'a std::cell::RefCell<Verdicts>,
}

impl<V: MotionValidator> MotionValidator for Replaying<'_, V> {
    fn validate(
        &self,
        leg: &Leg,
        start_elapsed_s: f64,
        state: &mut EncounterState,
    ) -> Result<(), RejectionCause> {
        let known = self.verdicts.borrow().known();
        let verdict = match known {
            Some(verdict) => {
                self.verdicts.borrow_mut().replayed += 1;
                verdict
            }
            None => self.validator.validate(leg, start_elapsed_s, state),
        };
        self.verdicts.borrow_mut().record(verdict);
        verdict
    }
}

/// Whether `level` is `than` or one of its relaxations.
fn weaker_or_equal(level: Compliance, than: Compliance) -> bool {
    std::iter::successors(Some(than), |level| level.relaxed()).any(|weaker| weaker == level)
}

/// A validator that counts the moves it refuses, by cause, and refuses
/// every move once `deadline` has passed (a search without samples, such
/// as the manoeuvre search, then ends within the planner's time budget;
/// `expired` says so and the planner reports the budget exhausted).
pub(crate) struct Recording<'a, V> {
    pub(crate) validator: &'a V,
    pub(crate) refused: Cell<RejectionCounts>,
    pub(crate) deadline: Option<Instant>,
    pub(crate) expired: Cell<bool>,
    /// The legs asked so far, and how many may be: past it every leg is
    /// refused, not judged and not counted.
    pub(crate) asks: Option<(&'a Cell<u64>, u64)>,
}

impl<'a, V> Recording<'a, V> {
    pub(crate) fn new(validator: &'a V, deadline: Option<Instant>) -> Self {
        Self {
            validator,
            refused: Cell::new(RejectionCounts::default()),
            deadline,
            expired: Cell::new(false),
            asks: None,
        }
    }

    /// Counts the legs asked in `asked`, refusing every one past `limit`.
    pub(crate) fn with_asks(self, asked: &'a Cell<u64>, limit: u64) -> Self {
        Self {
            asks: Some((asked, limit)),
            ..self
        }
    }
}

impl<V: MotionValidator> MotionValidator for Recording<'_, V> {
    fn validate(
        &self,
        leg: &Leg,
        start_elapsed_s: f64,
        state: &mut EncounterState,
    ) -> Result<(), RejectionCause> {
        if self.expired.get()
            || self
                .deadline
                .is_some_and(|deadline| Instant::now() > deadline)
        {
            // Not a verdict of the check: not counted.
            self.expired.set(true);
            return Err(RejectionCause::Clearance);
        }
        if let Some((asked, limit)) = self.asks {
            if asked.get() >= limit {
                // Past the search's allowance: not a verdict of the check.
                return Err(RejectionCause::Clearance);
            }
            asked.set(asked.get() + 1);
        }
        let verdict = self.validator.validate(leg, start_elapsed_s, state);
        if let Err(cause) = verdict {
            let mut refused = self.refused.get();
            refused.record(cause);
            self.refused.set(refused);
        }
        verdict
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use vorrt_colregs::ManeuverViolation;

    /// A validator that accepts every leg and counts the legs it judged.
    struct Counting(Cell<u64>);

    impl MotionValidator for Counting {
        fn validate(&self, _: &Leg, _: f64, _: &mut EncounterState) -> Result<(), RejectionCause> {
            self.0.set(self.0.get() + 1);
            Ok(())
        }
    }

    #[test]
    fn an_allowance_of_asks_refuses_past_it_without_judging_or_counting() {
        let inner = Counting(Cell::new(0));
        let asked = Cell::new(3);
        let recording = Recording::new(&inner, None).with_asks(&asked, 5);
        let leg = Leg::straight(glam::DVec2::ZERO, 0.0, 100.0, 5.0);
        let mut state = EncounterState::default();
        let verdicts: Vec<_> = (0..4)
            .map(|_| recording.validate(&leg, 0.0, &mut state))
            .collect();
        assert_eq!(verdicts[..2], [Ok(()), Ok(())]);
        assert_eq!(verdicts[2..], [Err(RejectionCause::Clearance); 2]);
        // Two judged, the allowance used up, nothing counted as refused
        // and the deadline not taken for passed.
        assert_eq!((inner.0.get(), asked.get()), (2, 5));
        assert_eq!(recording.refused.get(), RejectionCounts::default());
        assert!(!recording.expired.get());
    }

    #[test]
    fn only_a_weaker_or_equal_level_can_repeat_a_search() {
        assert!(weaker_or_equal(Compliance::Directions, Compliance::Full));
        assert!(weaker_or_equal(Compliance::SafetyOnly, Compliance::Full));
        assert!(weaker_or_equal(Compliance::Full, Compliance::Full));
        assert!(!weaker_or_equal(Compliance::Full, Compliance::Directions));
        assert!(!weaker_or_equal(
            Compliance::Directions,
            Compliance::SafetyOnly
        ));
    }

    #[test]
    fn a_refusal_for_a_duty_the_weaker_level_drops_makes_another_search() {
        let problem = PlanningProblem::new(
            vorrt_colregs::VesselState::new(glam::DVec2::ZERO, 0.0, 6.0, 50.0),
            glam::DVec2::new(0.0, 3000.0),
            Vec::new(),
        );
        let full = PlannerConfig::default();
        let at = |compliance| PlannerConfig { compliance, ..full };
        let mut failed = FailedSearch {
            problem: problem.clone(),
            config: full,
            seed: 1,
            effort: SearchEffort::Full,
            refused: RejectionCounts::default(),
            verdicts: Vec::new(),
        };
        failed.refused.set(RejectionCause::Clearance, 10);
        failed
            .refused
            .set(RejectionCause::Colregs(ManeuverViolation::PortTurn), 3);
        let repeats = |failed: &FailedSearch, compliance| {
            failed.repeated_by(&problem, &at(compliance), 1, SearchEffort::Full)
        };
        assert!(repeats(&failed, Compliance::Directions));
        // Safety only drops the port-turn duty.
        assert!(!repeats(&failed, Compliance::SafetyOnly));
        failed
            .refused
            .set(RejectionCause::Colregs(ManeuverViolation::LateAction), 1);
        assert!(!repeats(&failed, Compliance::Directions));
        assert!(repeats(&failed, Compliance::Full));
        // Any other setting: another search.
        let other = PlannerConfig {
            compliance: Compliance::Full,
            step_m: 50.0,
            ..full
        };
        assert!(!failed.repeated_by(&problem, &other, 1, SearchEffort::Full));
    }

    #[test]
    fn a_weaker_level_that_would_repeat_a_failed_search_draws_the_same() {
        // The blocked goal, with no encounter ever latched (a latch needs the
        // target within MTD, or within the early-action range): every
        // refusal is for safety.
        let own = vorrt_colregs::VesselState::new(glam::DVec2::ZERO, 0.0, 6.0, 50.0);
        let goal_m = glam::DVec2::new(0.0, 3000.0);
        let blocker = vorrt_jfs::TargetState::constant_velocity(vorrt_colregs::VesselState::new(
            goal_m, 0.0, 0.0, 50.0,
        ));
        let problem = PlanningProblem::new(own, goal_m, vec![blocker]);
        let mut config = PlannerConfig {
            nodes_per_phase: 40,
            samples_per_phase: 40,
            nodes_per_route_step: 0.0,
            max_restarts: 1,
            ..PlannerConfig::default()
        };
        config.rules.mtd_m = 1.0;
        // Nor latched early, for a turn made beyond MTD (decision 74).
        config.rules.early_action_range_m = 1.0;
        let samples_of = |result: Result<crate::Plan, crate::PlannerError>| {
            result
                .expect_err("blocked")
                .statistics()
                .expect("statistics")
                .samples
        };
        let mut full = crate::Planner::new(config).expect("valid");
        let failure = samples_of(full.plan_with(&problem, 5, SearchEffort::FirstPhase));
        let directions = PlannerConfig {
            compliance: Compliance::Directions,
            ..config
        };
        // Nothing was refused for the manner of an action: the directions
        // level would make the same search.
        assert!(full.would_repeat(&problem, &directions, 5, SearchEffort::FirstPhase));
        let mut weaker = crate::Planner::new(directions).expect("valid");
        let again = weaker.plan_with(&problem, 5, SearchEffort::FirstPhase);
        assert_eq!(samples_of(again), failure);
        // Another seed, effort or problem, or a stricter level: another search.
        assert!(!full.would_repeat(&problem, &directions, 6, SearchEffort::FirstPhase));
        assert!(!full.would_repeat(&problem, &directions, 5, SearchEffort::Full));
        assert!(!weaker.would_repeat(&problem, &config, 5, SearchEffort::FirstPhase));
        let mut moved = problem.clone();
        moved.ownship.position_m.x += 1.0;
        assert!(!full.would_repeat(&moved, &directions, 5, SearchEffort::FirstPhase));
        // A plan found forgets the failure.
        let open = PlanningProblem::new(problem.ownship, glam::DVec2::new(3000.0, 0.0), Vec::new());
        full.plan(&open, 5).expect("open water");
        assert!(!full.would_repeat(&problem, &directions, 5, SearchEffort::FirstPhase));
    }
}
