//! The VORRT-COLREGs planner (paper, Algorithms 1 and 2).
//!
//! A run grows a tree from ownship's state: in phase 1 each sample is the goal
//! with probability `goal_bias` (erratum 5), else a uniform point; in phase 2
//! the goal bias is `phase_two_goal_bias` (the paper's 0). The nearest node is
//! extended (for a goal sample, the nearest node that faces the goal within
//! one bounded turn, when there is one) by the joint forward step (ownship `d'` toward the sample, turn
//! bounded by `max_turn_per_step_rad`; every target for the same time) and the
//! move is kept when [`SafetyChecker`] accepts
//! it. A phase ends after `nodes_per_phase` accepted nodes or
//! `samples_per_phase` samples (erratum 4). A node within `goal_tolerance_m` of
//! the goal tries a final, checked segment onto it; success returns the branch.
//! When both phases fail the tree is grown again from the root, up to
//! `max_restarts` times, then the planner says why it found no safe path.

use crate::config::{PlannerConfig, SearchEffort, Turning};
use crate::constraint::{Constraint, NoConstraint};
use crate::error::PlannerError;
use crate::evasion::{EvasionSearch, EvasiveManeuver, evasive_leg_constrained};
use crate::plan::{Plan, PlanStatistics, RejectionCause, RejectionCounts};
use crate::problem::PlanningProblem;
use crate::replay::{FailedSearch, Replaying, Verdicts};
use crate::safety::{SafetyChecker, StateVelocities};
use crate::sampler::Sampler;
use crate::tree::Tree;
use crate::validity::{EncounterState, MotionValidator, check_legs_with};
use extract::Expired;
pub use extract::{
    COMPARISON_ASKS, ClearanceLevel, LANE_CROSSING_LADDER, LONG_DETOUR_FACTOR, ManeuverShape,
    Probe, ROOT_LADDER, Rung,
};
use glam::DVec2;
use std::cell::RefCell;
use std::time::Instant;
use vorrt_colregs::{EncounterLatch, update_latch};
use vorrt_geometry::angle;
use vorrt_jfs::{InstantTurn, Leg, LinearTrack, MotionModel, TargetState};

mod clearances;
mod extract;

/// Whether a search of `effort` that failed from the root, having refused
/// `refused`, stops there (decision 66): traffic alone refused the
/// manoeuvres from the root, and an effort that grows its tree only where
/// the user constraint refused some. With instantaneous turns there are no
/// manoeuvres from the root, and the tree is the search.
fn grows_no_tree(config: &PlannerConfig, effort: SearchEffort, refused: &RejectionCounts) -> bool {
    effort.tree_only_where_constrained()
        && !matches!(config.turning, Turning::Instant)
        && !refused
            .by_cause()
            .iter()
            .any(|&(cause, count)| count > 0 && matches!(cause, RejectionCause::Constraint(_)))
}

/// How often (in samples) the wall clock is read when a budget is set.
const CLOCK_EVERY_SAMPLES: u64 = 32;

/// The VORRT-COLREGs planner. Holds its buffers between plans, so planning
/// again (as a closed loop does) reuses them.
///
/// ```
/// use vorrt_planner::geometry::angle::signed_turn;
/// use vorrt_planner::{DVec2, Planner, PlannerConfig, PlanningProblem, TargetState, VesselState};
///
/// // Head-on: ownship north at 6 m/s, a target 4 km ahead heading south.
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let target = TargetState::toward_goal(
///     VesselState::new(DVec2::new(0.0, 4000.0), std::f64::consts::PI, 6.0, 50.0),
///     DVec2::new(0.0, -2000.0));
/// let problem = PlanningProblem::new(own, DVec2::new(0.0, 6000.0), vec![target]);
/// let config = PlannerConfig { nodes_per_phase: 400, ..PlannerConfig::default() };
/// let mut planner = Planner::new(config).unwrap();
/// let plan = planner.plan(&problem, 42).unwrap();
/// assert_eq!(plan.waypoints.last().unwrap().position_m, DVec2::new(0.0, 6000.0));
/// // Rule 14: the first course change is to starboard.
/// let first_turn = plan.waypoints.iter().skip(1).map(|w| w.course_rad)
///     .find(|course| signed_turn(0.0, *course).abs() > 1e-9).unwrap();
/// assert!(signed_turn(0.0, first_turn) > 0.0);
/// ```
///
/// A planner keeps a user [`Constraint`] too (land, a no-go area, a lane:
/// [`Planner::with_constraint`]) everywhere it judges a move; [`Planner::new`]
/// plans in open sea ([`NoConstraint`]).
#[derive(Debug)]
pub struct Planner<C = NoConstraint> {
    config: PlannerConfig,
    constraint: C,
    tree: Tree,
    tracks: Vec<LinearTrack>,
    /// Each track's state velocities, worked out once per call.
    track_velocities: Vec<StateVelocities>,
    scratch: EncounterState,
    /// The last search, when it found no safe path.
    last_failure: Option<Box<FailedSearch>>,
    /// The verdicts of the search under way, and those of an earlier one
    /// it replays (decision 53).
    verdicts: RefCell<Verdicts>,
}

enum Growth {
    Reached(u32),
    Exhausted,
}

impl Planner {
    /// A planner with `config`, in open sea (no user constraint).
    ///
    /// # Errors
    /// [`PlannerError::InvalidConfig`] (or `InvalidRules`) when a setting is out of range.
    pub fn new(config: PlannerConfig) -> Result<Self, PlannerError> {
        Planner::with_constraint(config, NoConstraint)
    }
}

impl<C: Constraint> Planner<C> {
    /// A planner with `config` that keeps `constraint` on every move it
    /// judges: in the tree, the manoeuvre search, the path simplifier,
    /// [`check_legs`](Self::check_legs) and [`evasive_leg`](Self::evasive_leg);
    /// the sampler draws only the points it admits.
    ///
    /// # Errors
    /// [`PlannerError::InvalidConfig`] (or `InvalidRules`) when a setting is out of range.
    pub fn with_constraint(config: PlannerConfig, constraint: C) -> Result<Self, PlannerError> {
        config.validate()?;
        Ok(Self {
            config,
            constraint,
            tree: Tree::default(),
            tracks: Vec::new(),
            track_velocities: Vec::new(),
            scratch: EncounterState::default(),
            last_failure: None,
            verdicts: RefCell::new(Verdicts::default()),
        })
    }

    /// The configuration in use.
    #[must_use]
    pub fn config(&self) -> &PlannerConfig {
        &self.config
    }

    /// The user constraint kept.
    #[must_use]
    pub fn constraint(&self) -> &C {
        &self.constraint
    }

    /// Whether `legs`, sailed one after the other from `problem`'s start,
    /// pass this planner's validity check (its COLREGs level and its
    /// constraint): how a closed loop asks whether the rest of its plan
    /// still holds ([`check_legs_with`]).
    ///
    /// # Errors
    /// The first [`RejectionCause`] a leg runs into.
    pub fn check_legs(
        &self,
        problem: &PlanningProblem,
        legs: &[Leg],
    ) -> Result<(), crate::RejectionCause> {
        check_legs_with(&self.config, problem, legs, &self.constraint)
    }

    /// The evasive manoeuvre ([`evasive_leg_holding`](crate::evasive_leg_holding)) among the courses
    /// whose leg keeps this planner's constraint, for when no safe path
    /// is found.
    #[must_use]
    pub fn evasive_leg<M: MotionModel>(
        &self,
        problem: &PlanningProblem,
        search: &EvasionSearch<'_, M>,
        holding: Option<EvasiveManeuver>,
    ) -> (Leg, EvasiveManeuver) {
        evasive_leg_constrained(problem, search, holding, &self.constraint)
    }

    /// Plans a safe, COLREGs-compliant path for `problem`, drawing every
    /// random choice from a `ChaCha8` stream seeded with `seed`.
    ///
    /// # Errors
    /// [`PlannerError::InvalidProblem`] for a malformed problem,
    /// [`PlannerError::NoSafePath`] when every restart failed, and
    /// [`PlannerError::BudgetExhausted`] when the time budget ran out.
    pub fn plan(&mut self, problem: &PlanningProblem, seed: u64) -> Result<Plan, PlannerError> {
        self.plan_with(problem, seed, SearchEffort::Full)
    }

    /// As [`plan`](Self::plan), running as much of the search as `effort`
    /// says (the manoeuvre search from the root always runs first).
    ///
    /// # Errors
    /// As [`plan`](Self::plan).
    pub fn plan_with(
        &mut self,
        problem: &PlanningProblem,
        seed: u64,
        effort: SearchEffort,
    ) -> Result<Plan, PlannerError> {
        self.plan_replaying(problem, seed, effort, None)
    }

    /// As [`plan_with`](Self::plan_with), after `earlier` (a planner of the
    /// graded fallback at a stricter level, or at the same) found no safe
    /// path for the same problem with the same settings but the level, seed
    /// and effort: the moves its search refused for a duty this level checks
    /// too are refused again without being judged, for as long as this
    /// search asks the same moves as that one (`Verdicts`, decision 53).
    /// The plan, or the failure, is the one [`plan_with`](Self::plan_with)
    /// gives, bit for bit; only the work differs. With any other `earlier`
    /// it is [`plan_with`](Self::plan_with).
    ///
    /// # Errors
    /// As [`plan`](Self::plan).
    pub fn plan_after(
        &mut self,
        problem: &PlanningProblem,
        seed: u64,
        effort: SearchEffort,
        earlier: &Planner<C>,
    ) -> Result<Plan, PlannerError> {
        let failed = earlier.last_failure.as_deref();
        self.plan_replaying(problem, seed, effort, failed)
    }

    /// How many verdicts the last search took from an earlier one
    /// ([`plan_after`](Self::plan_after)) rather than judged.
    #[must_use]
    pub fn verdicts_replayed(&self) -> u64 {
        self.verdicts.borrow().replayed
    }

    fn plan_replaying(
        &mut self,
        problem: &PlanningProblem,
        seed: u64,
        effort: SearchEffort,
        earlier: Option<&FailedSearch>,
    ) -> Result<Plan, PlannerError> {
        let earlier = earlier
            .filter(|failed| failed.replayable_by(problem, &self.config, seed, effort))
            .map(|failed| failed.verdicts.as_slice());
        self.verdicts
            .get_mut()
            .start(earlier, self.config.compliance);
        // Budgets follow the route length (`PlannerConfig::for_route`), and a
        // failure that spent every phase's node quota says so.
        let configured = self.config;
        let route_m = problem.ownship.position_m.distance(problem.goal_m);
        self.config = configured.for_route(route_m);
        let mut refused = RejectionCounts::default();
        let result = self.plan_within_budgets(problem, seed, effort, &mut refused);
        let config = std::mem::replace(&mut self.config, configured);
        self.last_failure = match &result {
            Err(PlannerError::NoSafePath { statistics }) => {
                refused.add(&statistics.rejections);
                Some(Box::new(FailedSearch {
                    problem: problem.clone(),
                    config: configured,
                    seed,
                    effort,
                    refused,
                    verdicts: std::mem::take(&mut self.verdicts.get_mut().log),
                }))
            }
            _ => None,
        };
        result.map_err(|error| error.blame_budget(&config, route_m))
    }

    /// Whether a planner with `config`, asked to plan `problem` with `seed`
    /// and `effort`, would only repeat this planner's last search, which
    /// found no safe path: the same problem, seed and effort, `config`
    /// equal to this planner's but for a compliance level at most as strict,
    /// and no move of that search (in the tree, the path simplifier or the
    /// manoeuvre search) refused for a duty `config`'s level does not check
    /// ([`Compliance::checks`](crate::Compliance::checks)). Every verdict of
    /// the validity check would then be the same, and so would the samples
    /// drawn and the failure: a closed loop's graded fallback skips that
    /// level.
    #[must_use]
    pub fn would_repeat(
        &self,
        problem: &PlanningProblem,
        config: &PlannerConfig,
        seed: u64,
        effort: SearchEffort,
    ) -> bool {
        self.last_failure
            .as_ref()
            .is_some_and(|failed| failed.repeated_by(problem, config, seed, effort))
    }

    fn plan_within_budgets(
        &mut self,
        problem: &PlanningProblem,
        seed: u64,
        effort: SearchEffort,
        refused: &mut RejectionCounts,
    ) -> Result<Plan, PlannerError> {
        problem.validate()?;
        let started = Instant::now();
        let config = self.config;
        // The searches without samples end within the time budget too.
        let deadline = deadline_of(&config, started);
        let own = problem.ownship;
        self.load_tracks(problem);
        let targets = self.tracks.len();
        let (root_latches, root_alterations) = self.root_encounters(problem);
        let margin = DVec2::splat(config.sampling_margin_m);
        let mut sampler = Sampler::new(
            seed,
            own.position_m.min(problem.goal_m) - margin,
            own.position_m.max(problem.goal_m) + margin,
        );
        let capacity = 2 * config.nodes_per_phase + 2;
        let mut statistics = PlanStatistics::default();
        let mut total_nodes = 0u64;
        // Whether the search from the root (its whole ladder) has failed.
        let mut root_searched = false;
        // A retry (first phase only) is a draw where most searches fail.
        let probe = match effort.phases() {
            1 => Probe::FloorFirst,
            _ => Probe::PreferredFirst,
        };

        for attempt in 0..=config.max_restarts {
            statistics.restarts = attempt as u64;
            self.tree.reset(capacity, targets, config.nearest_index);
            self.tree
                .set_goal(problem.goal_m, config.max_turn_per_step_rad.cos());
            self.tree.push(
                own.position_m,
                own.course_rad,
                problem.start_time_s,
                0,
                &root_latches,
                &root_alterations,
            );
            // The manoeuvre a mariner would make (one alteration held, then
            // the goal), when it is valid, needs no tree at all.
            statistics.nodes = 1;
            if attempt == 0 && own.position_m != problem.goal_m {
                let found = self.search_root(problem, &statistics, refused, probe, deadline);
                match found.map_err(|Expired| budget_exhausted(&config, &statistics, started))? {
                    Some(mut plan) => {
                        plan.statistics.elapsed_s = started.elapsed().as_secs_f64();
                        return Ok(plan);
                    }
                    // The leg to the goal and the manoeuvre search from the
                    // root failed: a branch's simplification, which starts
                    // with them, need not validate them again.
                    None => root_searched = true,
                }
                if grows_no_tree(&config, effort, refused) {
                    break;
                }
            }
            let reached = if own.position_m == problem.goal_m {
                Some(0)
            } else {
                self.grow_phases(problem, &mut sampler, effort, &mut statistics, started)?
            };
            total_nodes += self.tree.len() as u64;
            if let Some(node) = reached {
                statistics.nodes = self.tree.len() as u64;
                let found = self.extract_branch(
                    problem,
                    node,
                    &statistics,
                    refused,
                    root_searched,
                    deadline,
                );
                match found.map_err(|Expired| budget_exhausted(&config, &statistics, started))? {
                    Some(mut plan) => {
                        plan.statistics.elapsed_s = started.elapsed().as_secs_f64();
                        return Ok(plan);
                    }
                    // No sailable simplification of this branch: grow anew.
                    None => statistics.unsailable_branches += 1,
                }
            }
        }
        statistics.nodes = total_nodes;
        statistics.elapsed_s = started.elapsed().as_secs_f64();
        Err(PlannerError::NoSafePath {
            statistics: Box::new(statistics),
        })
    }

    /// Each target's track and its state velocities, worked out once per
    /// call.
    fn load_tracks(&mut self, problem: &PlanningProblem) {
        self.tracks.clear();
        self.tracks
            .extend(problem.targets.iter().map(TargetState::track));
        self.track_velocities.clear();
        self.track_velocities
            .extend(self.tracks.iter().map(StateVelocities::of));
    }

    /// The encounters in force at the root, each updated from the one a
    /// previous plan carried over (a closed loop passes them), and the
    /// alteration already made for each.
    fn root_encounters(
        &self,
        problem: &PlanningProblem,
    ) -> (Vec<Option<EncounterLatch>>, Vec<f64>) {
        let root_latches: Vec<Option<EncounterLatch>> = (0..self.tracks.len())
            .map(|index| {
                let previous = problem.encounters.get(index).copied().flatten();
                update_latch(
                    previous,
                    &problem.ownship,
                    &self.tracks[index].state_at(0.0),
                    problem.start_time_s,
                    &self.config.rules,
                )
            })
            .collect();
        // The alteration already made for an encounter carried over from a
        // previous plan (a closed loop passes it), else none.
        let root_alterations: Vec<f64> = (0..self.tracks.len())
            .map(|index| {
                let carried = problem.encounters.get(index).copied().flatten();
                match (carried, root_latches[index]) {
                    (Some(was), Some(now)) if was == now => {
                        problem.alterations.get(index).copied().unwrap_or(0.0)
                    }
                    _ => 0.0,
                }
            })
            .collect();
        (root_latches, root_alterations)
    }

    /// The phases `effort` asks for (the second with its own goal bias),
    /// each growing the tree until the goal is reached: the goal's node, or
    /// `None` when every phase was spent first.
    fn grow_phases(
        &mut self,
        problem: &PlanningProblem,
        sampler: &mut Sampler,
        effort: SearchEffort,
        statistics: &mut PlanStatistics,
        started: Instant,
    ) -> Result<Option<u32>, PlannerError> {
        let phases = effort.phases();
        for goal_bias in [self.config.goal_bias, self.config.phase_two_goal_bias]
            .into_iter()
            .take(phases)
        {
            if let Growth::Reached(node) =
                self.grow(problem, sampler, goal_bias, statistics, started)?
            {
                return Ok(Some(node));
            }
        }
        Ok(None)
    }

    /// One phase of Algorithm 2: grow until the goal is reached, the phase's
    /// node quota is met, or its sample budget is spent.
    fn grow(
        &mut self,
        problem: &PlanningProblem,
        sampler: &mut Sampler,
        goal_bias: f64,
        statistics: &mut PlanStatistics,
        started: Instant,
    ) -> Result<Growth, PlannerError> {
        let config = self.config;
        // The tree is grown at the service speed; the plan's legs start from
        // the present speed (`extract`).
        let own = problem.ownship_at_service_speed();
        let checker = SafetyChecker::new(
            &self.config,
            &self.tracks,
            own,
            problem.goal_m,
            problem.start_time_s,
        )
        .with_steady_course(problem.steady_course_rad)
        .with_turning_at_start(problem.turning_at_start)
        .with_state_velocities(&self.track_velocities)
        .with_constraint(&self.constraint);
        let checker = Replaying {
            validator: &checker,
            verdicts: &self.verdicts,
        };
        let model = InstantTurn {
            max_turn_rad: config.max_turn_per_step_rad,
        };
        let mut accepted = 0usize;
        let mut samples_drawn = 0usize;
        while accepted < config.nodes_per_phase && samples_drawn < config.samples_per_phase {
            samples_drawn += 1;
            statistics.samples += 1;
            check_time_budget(&config, statistics, started, &self.tree)?;
            let sample = sampler.sample(problem.goal_m, goal_bias);
            // Only where the user's constraint admits a point (in water).
            if sample != problem.goal_m && !self.constraint.admits_point(sample) {
                continue;
            }
            // A goal sample extends the nearest node that can head for the
            // goal within one bounded turn: the plainly nearest node often
            // points away and would only orbit the goal.
            let to_goal = sample == problem.goal_m;
            let parent = if to_goal {
                self.tree.nearest_facing_goal()
            } else {
                self.tree.nearest(sample)
            };
            let Some(parent) = parent else {
                break;
            };
            // The same node and the goal make the same move: answer a repeat
            // from the first verdict (erratum 5's repeated extension).
            if to_goal && let Some(cause) = self.tree.goal_rejections[parent as usize] {
                statistics.rejections.record(cause);
                continue;
            }
            let from = self.tree.pose_of(parent);
            let Some(leg) = model.steer(from, sample, own.speed_mps, config.step_m) else {
                continue;
            };
            let start_elapsed_s = self.tree.times[parent as usize] - problem.start_time_s;
            self.scratch.set(
                self.tree.latches_of(parent),
                self.tree.alterations_of(parent),
            );
            if let Err(cause) = checker.validate(&leg, start_elapsed_s, &mut self.scratch) {
                statistics.rejections.record(cause);
                if to_goal {
                    self.tree.goal_rejections[parent as usize] = Some(cause);
                }
                continue;
            }
            let node = self.tree.push(
                leg.end_m(),
                leg.course_rad,
                problem.start_time_s + start_elapsed_s + leg.duration_s(),
                parent,
                &self.scratch.latches,
                &self.scratch.alterations,
            );
            accepted += 1;
            let position = self.tree.positions[node as usize];
            let to_goal = position.distance(problem.goal_m);
            if to_goal == 0.0 {
                return Ok(Growth::Reached(node));
            }
            if to_goal <= config.goal_tolerance_m
                && let Some(goal) = close_onto_goal(
                    &mut self.tree,
                    &mut self.scratch,
                    &checker,
                    problem,
                    node,
                    own.speed_mps,
                    &mut statistics.rejections,
                )
            {
                return Ok(Growth::Reached(goal));
            }
        }
        Ok(Growth::Exhausted)
    }
}

/// When a search started at `started` must end, by `config`'s time budget
/// (`None` without one, or for a budget too large for the clock).
fn deadline_of(config: &PlannerConfig, started: Instant) -> Option<Instant> {
    config.time_budget_s.and_then(|budget_s| {
        std::time::Duration::try_from_secs_f64(budget_s)
            .ok()
            .and_then(|budget| started.checked_add(budget))
    })
}

/// [`PlannerError::BudgetExhausted`] after a search without samples (the
/// manoeuvre search, a branch's simplification) ran past the time budget.
fn budget_exhausted(
    config: &PlannerConfig,
    statistics: &PlanStatistics,
    started: Instant,
) -> PlannerError {
    let mut statistics = *statistics;
    statistics.elapsed_s = started.elapsed().as_secs_f64();
    PlannerError::BudgetExhausted {
        budget_s: config.time_budget_s.unwrap_or_default(),
        statistics: Box::new(statistics),
    }
}

/// Once the clock, read every [`CLOCK_EVERY_SAMPLES`] samples, passes the
/// configured time budget: [`PlannerError::BudgetExhausted`] with the
/// statistics so far, `tree` counted as grown.
fn check_time_budget(
    config: &PlannerConfig,
    statistics: &mut PlanStatistics,
    started: Instant,
    tree: &Tree,
) -> Result<(), PlannerError> {
    if let Some(budget_s) = config.time_budget_s
        && statistics.samples.is_multiple_of(CLOCK_EVERY_SAMPLES)
        && started.elapsed().as_secs_f64() > budget_s
    {
        statistics.nodes = tree.len() as u64;
        statistics.elapsed_s = started.elapsed().as_secs_f64();
        return Err(PlannerError::BudgetExhausted {
            budget_s,
            statistics: Box::new(*statistics),
        });
    }
    Ok(())
}

/// The final segment from `node`, within `goal_tolerance_m` of the goal,
/// onto the goal, checked like any other move: the goal's node when the
/// segment is valid, else `None` with its cause counted in `rejections`.
fn close_onto_goal<V: MotionValidator>(
    tree: &mut Tree,
    scratch: &mut EncounterState,
    checker: &V,
    problem: &PlanningProblem,
    node: u32,
    speed_mps: f64,
    rejections: &mut RejectionCounts,
) -> Option<u32> {
    let position = tree.positions[node as usize];
    let to_goal = position.distance(problem.goal_m);
    let final_leg = Leg::straight(
        position,
        angle::unit_to_course(problem.goal_m - position),
        to_goal,
        speed_mps,
    );
    let final_elapsed_s = tree.times[node as usize] - problem.start_time_s;
    scratch.set(tree.latches_of(node), tree.alterations_of(node));
    match checker.validate(&final_leg, final_elapsed_s, scratch) {
        // Exactly on the goal, whatever the rounding of start + velocity ×
        // duration.
        Ok(()) => Some(tree.push(
            problem.goal_m,
            final_leg.course_rad,
            problem.start_time_s + final_elapsed_s + final_leg.duration_s(),
            node,
            &scratch.latches,
            &scratch.alterations,
        )),
        Err(cause) => {
            rejections.record(cause);
            None
        }
    }
}

#[cfg(test)]
mod tests;
