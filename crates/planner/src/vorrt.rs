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

use crate::config::PlannerConfig;
use crate::error::PlannerError;
use crate::plan::{Plan, PlanStatistics, Waypoint};
use crate::problem::PlanningProblem;
use crate::safety::{Move, SafetyChecker};
use crate::sampler::Sampler;
use crate::tree::Tree;
use glam::DVec2;
use std::time::Instant;
use vorrt_colregs::{EncounterLatch, VesselState, update_latch};
use vorrt_geometry::angle;
use vorrt_jfs::LinearTrack;

/// How often (in samples) the wall clock is read when a budget is set.
const CLOCK_EVERY_SAMPLES: u64 = 32;

/// The VORRT-COLREGs planner. Holds its buffers between plans, so planning
/// again (as a closed loop does) reuses them.
///
/// ```
/// use vorrt_planner::{Planner, PlannerConfig, PlanningProblem};
/// use vorrt_colregs::VesselState;
/// use vorrt_jfs::TargetState;
/// use glam::DVec2;
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
///     .find(|course| vorrt_geometry::angle::signed_turn(0.0, *course).abs() > 1e-9).unwrap();
/// assert!(vorrt_geometry::angle::signed_turn(0.0, first_turn) > 0.0);
/// ```
#[derive(Debug)]
pub struct Planner {
    config: PlannerConfig,
    tree: Tree,
    tracks: Vec<LinearTrack>,
    latch_scratch: Vec<Option<EncounterLatch>>,
    alteration_scratch: Vec<f64>,
}

enum Growth {
    Reached(u32),
    Exhausted,
}

impl Planner {
    /// A planner with `config`.
    ///
    /// # Errors
    /// [`PlannerError::InvalidConfig`] (or `InvalidRules`) when a setting is out of range.
    pub fn new(config: PlannerConfig) -> Result<Self, PlannerError> {
        config.validate()?;
        Ok(Self {
            config,
            tree: Tree::default(),
            tracks: Vec::new(),
            latch_scratch: Vec::new(),
            alteration_scratch: Vec::new(),
        })
    }

    /// The tree of the last plan (for inspection and tests).
    #[must_use]
    pub fn debug_tree(&self) -> &Tree {
        &self.tree
    }

    /// The configuration in use.
    #[must_use]
    pub fn config(&self) -> &PlannerConfig {
        &self.config
    }

    /// Plans a safe, COLREGs-compliant path for `problem`, drawing every
    /// random choice from a ChaCha8 stream seeded with `seed`.
    ///
    /// # Errors
    /// [`PlannerError::InvalidProblem`] for a malformed problem,
    /// [`PlannerError::NoSafePath`] when every restart failed, and
    /// [`PlannerError::BudgetExhausted`] when the time budget ran out.
    pub fn plan(&mut self, problem: &PlanningProblem, seed: u64) -> Result<Plan, PlannerError> {
        problem.validate()?;
        let started = Instant::now();
        let config = self.config;
        let own = problem.ownship;
        self.tracks.clear();
        self.tracks
            .extend(problem.targets.iter().map(|target| target.track()));
        let targets = self.tracks.len();
        let root_latches: Vec<Option<EncounterLatch>> = (0..targets)
            .map(|index| {
                let previous = problem.encounters.get(index).copied().flatten();
                update_latch(
                    previous,
                    &own,
                    &self.tracks[index].state_at(0.0),
                    problem.start_time_s,
                    &config.rules,
                )
            })
            .collect();

        let margin = DVec2::splat(config.sampling_margin_m);
        let mut sampler = Sampler::new(
            seed,
            own.position_m.min(problem.goal_m) - margin,
            own.position_m.max(problem.goal_m) + margin,
        );
        let capacity = 2 * config.nodes_per_phase + 2;
        let mut statistics = PlanStatistics::default();
        let mut total_nodes = 0u64;

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
                &vec![0.0; targets],
            );
            let reached = if own.position_m == problem.goal_m {
                Some(0)
            } else {
                let mut found = None;
                for goal_bias in [config.goal_bias, config.phase_two_goal_bias] {
                    match self.grow(problem, &mut sampler, goal_bias, &mut statistics, started)? {
                        Growth::Reached(node) => {
                            found = Some(node);
                            break;
                        }
                        Growth::Exhausted => {}
                    }
                }
                found
            };
            total_nodes += self.tree.len() as u64;
            if let Some(node) = reached {
                statistics.nodes = self.tree.len() as u64;
                statistics.elapsed_s = started.elapsed().as_secs_f64();
                return Ok(self.extract(problem, node, statistics));
            }
        }
        statistics.nodes = total_nodes;
        statistics.elapsed_s = started.elapsed().as_secs_f64();
        Err(PlannerError::NoSafePath {
            statistics: Box::new(statistics),
        })
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
        let own = problem.ownship;
        let checker = SafetyChecker {
            config: &self.config,
            tracks: &self.tracks,
            own_length_m: own.length_m,
            own_speed_mps: own.speed_mps,
            goal_m: problem.goal_m,
        };
        let mut accepted = 0usize;
        let mut samples = 0usize;
        while accepted < config.nodes_per_phase && samples < config.samples_per_phase {
            samples += 1;
            statistics.samples += 1;
            if let Some(budget_s) = config.time_budget_s
                && statistics.samples.is_multiple_of(CLOCK_EVERY_SAMPLES)
                && started.elapsed().as_secs_f64() > budget_s
            {
                statistics.nodes = self.tree.len() as u64;
                statistics.elapsed_s = started.elapsed().as_secs_f64();
                return Err(PlannerError::BudgetExhausted {
                    budget_s,
                    statistics: Box::new(*statistics),
                });
            }
            let sample = sampler.sample(problem.goal_m, goal_bias);
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
            let candidate = steer(
                &self.tree,
                parent,
                sample,
                &config,
                own.speed_mps,
                problem.start_time_s,
            );
            let Some(candidate) = candidate else {
                continue;
            };
            if let Err(cause) = checker.check(
                &candidate,
                self.tree.latches_of(parent),
                self.tree.alterations_of(parent),
            ) {
                statistics.rejections.record(cause);
                if to_goal {
                    self.tree.goal_rejections[parent as usize] = Some(cause);
                }
                continue;
            }
            let node = add_node(
                &mut self.tree,
                &mut self.latch_scratch,
                &mut self.alteration_scratch,
                &self.tracks,
                &own,
                parent,
                &candidate,
                problem.start_time_s,
                &config,
            );
            accepted += 1;
            let position = self.tree.positions[node as usize];
            let to_goal = position.distance(problem.goal_m);
            if to_goal == 0.0 {
                return Ok(Growth::Reached(node));
            }
            if to_goal <= config.goal_tolerance_m {
                // The final segment onto the goal, checked like any other.
                let offset = problem.goal_m - position;
                let final_move = Move {
                    start_m: position,
                    start_elapsed_s: self.tree.times[node as usize] - problem.start_time_s,
                    course_rad: angle::unit_to_course(offset),
                    velocity_mps: offset / to_goal * own.speed_mps,
                    duration_s: to_goal / own.speed_mps,
                };
                match checker.check(
                    &final_move,
                    self.tree.latches_of(node),
                    self.tree.alterations_of(node),
                ) {
                    Ok(()) => {
                        let goal = add_node(
                            &mut self.tree,
                            &mut self.latch_scratch,
                            &mut self.alteration_scratch,
                            &self.tracks,
                            &own,
                            node,
                            &final_move,
                            problem.start_time_s,
                            &config,
                        );
                        // Exactly on the goal, whatever the rounding of
                        // start + velocity × duration.
                        self.tree.positions[goal as usize] = problem.goal_m;
                        return Ok(Growth::Reached(goal));
                    }
                    Err(cause) => statistics.rejections.record(cause),
                }
            }
        }
        Ok(Growth::Exhausted)
    }

    fn extract(&self, problem: &PlanningProblem, node: u32, statistics: PlanStatistics) -> Plan {
        let branch = self.tree.branch(node);
        let mut waypoints = Vec::with_capacity(branch.len());
        let mut target_states = Vec::with_capacity(branch.len());
        let mut encounters = Vec::with_capacity(branch.len());
        for &index in &branch {
            let time_s = self.tree.times[index as usize];
            waypoints.push(Waypoint {
                position_m: self.tree.positions[index as usize],
                time_s,
                course_rad: self.tree.courses[index as usize],
            });
            let elapsed = time_s - problem.start_time_s;
            target_states.push(
                self.tracks
                    .iter()
                    .map(|track| track.state_at(elapsed))
                    .collect(),
            );
            encounters.push(self.tree.latches_of(index).to_vec());
        }
        Plan {
            waypoints,
            target_states,
            encounters,
            statistics,
        }
    }
}

/// The joint forward step's ownship part: up to `d'` from `parent` toward
/// `sample`, with the course change bounded. `None` when the sample is the
/// parent itself.
fn steer(
    tree: &Tree,
    parent: u32,
    sample: DVec2,
    config: &PlannerConfig,
    speed_mps: f64,
    start_time_s: f64,
) -> Option<Move> {
    let start_m = tree.positions[parent as usize];
    let offset = sample - start_m;
    let distance = offset.length();
    if distance == 0.0 {
        return None;
    }
    let parent_course = tree.courses[parent as usize];
    let wanted = angle::unit_to_course(offset);
    let turn = angle::signed_turn(parent_course, wanted);
    let limit = config.max_turn_per_step_rad;
    let (course_rad, length_m) = if turn.abs() <= limit {
        (wanted, distance.min(config.step_m))
    } else {
        (
            angle::normalize_2pi(parent_course + limit.copysign(turn)),
            config.step_m,
        )
    };
    Some(Move {
        start_m,
        start_elapsed_s: tree.times[parent as usize] - start_time_s,
        course_rad,
        velocity_mps: angle::velocity(course_rad, speed_mps),
        duration_s: length_m / speed_mps,
    })
}

/// Adds the node a checked move ends in, updating each target's encounter
/// latch and the alteration made for it (rule 16).
#[allow(clippy::too_many_arguments)]
fn add_node(
    tree: &mut Tree,
    scratch: &mut Vec<Option<EncounterLatch>>,
    alterations: &mut Vec<f64>,
    tracks: &[LinearTrack],
    own: &VesselState,
    parent: u32,
    candidate: &Move,
    start_time_s: f64,
    config: &PlannerConfig,
) -> u32 {
    let end_m = candidate.start_m + candidate.velocity_mps * candidate.duration_s;
    let end_elapsed_s = candidate.start_elapsed_s + candidate.duration_s;
    let time_s = start_time_s + end_elapsed_s;
    let own_then = VesselState {
        position_m: end_m,
        course_rad: candidate.course_rad,
        ..*own
    };
    scratch.clear();
    scratch.extend_from_slice(tree.latches_of(parent));
    alterations.clear();
    alterations.extend_from_slice(tree.alterations_of(parent));
    for ((latch, altered), track) in scratch.iter_mut().zip(alterations.iter_mut()).zip(tracks) {
        let before = *latch;
        *latch = update_latch(
            before,
            &own_then,
            &track.state_at(end_elapsed_s),
            time_s,
            &config.rules,
        );
        *altered = match (*latch, before) {
            (Some(now), Some(was)) if now == was => altered
                .max(angle::signed_turn(now.reference_course_rad, candidate.course_rad).abs()),
            _ => 0.0,
        };
    }
    tree.push(
        end_m,
        candidate.course_rad,
        time_s,
        parent,
        scratch,
        alterations,
    )
}
