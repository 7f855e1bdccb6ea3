//! From the tree to a plan: the search ladder from the root, and a branch
//! made into sailable legs.
//!
//! The order in which the planner looks for a plan is one value,
//! [`ROOT_LADDER`]: each manoeuvre shape (one alteration held, then two:
//! decisions 14 and 27 in `docs/decisions/`), each first at the preferred
//! clearance and then at `d_th` (decision 23); the first rung that finds a
//! plan wins, but for a plan of one alteration that sails more than
//! [`LONG_DETOUR_FACTOR`] times the straight line to the goal, which is
//! compared with the plans of two alterations at its clearance and the
//! shorter taken (decision 67). Only when no rung finds a plan is a tree
//! grown (decision 14), and its branch simplified by the same validity
//! check. The compliance levels of
//! the graded fallback (decision 17) are the ladder's outer dimension,
//! climbed by the closed loop ([`Compliance::relaxed`](crate::Compliance::relaxed)),
//! which skips a level that would only repeat a failed search
//! ([`Planner::would_repeat`]).
//!
//! A leg valid at the preferred clearance is valid at `d_th`, so of the two
//! clearances of one shape the preferred one wins whenever either finds a
//! plan, whichever is asked first; [`Probe`] says which is asked first, to
//! spare the search likelier to be wasted (decision 26). The plans are the
//! same either way.

use super::Planner;
use super::clearances::{AcrossClearances, ClearanceMemo};
use crate::config::PlannerConfig;
use crate::constraint::Constraint;
use crate::crossing::speed_on_course;
use crate::plan::{Plan, PlanSource, PlanStatistics, RejectionCounts, Waypoint};
use crate::problem::PlanningProblem;
use crate::replay::{Recording, Replaying};
use crate::safety::SafetyChecker;
use crate::simplify::{
    SimplifiedLeg, Speeds, hold_then_alter_shorter_than, length_of, simplify_after,
};
use crate::validity::EncounterState;
use glam::DVec2;
use std::cell::Cell;
use std::time::Instant;
use vorrt_geometry::angle;
use vorrt_jfs::{Leg, OwnshipModel, Pose, RateLimitedTurn};

/// The shape of a manoeuvre the search from the root tries.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ManeuverShape {
    /// One alteration (of course, or of speed) held, then the goal
    /// ([`simplify`](crate::simplify::simplify)): what a mariner makes.
    OneAlteration,
    /// Two alterations ([`hold_then_alter`](crate::simplify::hold_then_alter)): the course kept, then one
    /// action (a stand-on vessel's, rule 17); an alteration held, then the
    /// course before it resumed.
    TwoAlterations,
    /// A change of speed on the course to the goal held, then the goal
    /// ([`speed_on_course`]): a lane crossing, square to the flow (rule
    /// 10(c)), timed to a gap in the lane's traffic; first of
    /// [`LANE_CROSSING_LADDER`].
    SpeedOnCourse,
}

/// The clearance a rung is searched at.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ClearanceLevel {
    /// `d_th` times `PlannerConfig::preferred_clearance_factor`: where sea room allows.
    Preferred,
    /// `d_th` itself.
    Floor,
}

/// One rung of the search from the root.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Rung {
    /// The manoeuvre's shape.
    pub shape: ManeuverShape,
    /// The clearance it is searched at.
    pub clearance: ClearanceLevel,
}

/// The search from the root, in order of preference: the first rung that
/// finds a plan wins (module documentation).
pub const ROOT_LADDER: [Rung; 4] = [
    Rung {
        shape: ManeuverShape::OneAlteration,
        clearance: ClearanceLevel::Preferred,
    },
    Rung {
        shape: ManeuverShape::OneAlteration,
        clearance: ClearanceLevel::Floor,
    },
    Rung {
        shape: ManeuverShape::TwoAlterations,
        clearance: ClearanceLevel::Preferred,
    },
    Rung {
        shape: ManeuverShape::TwoAlterations,
        clearance: ClearanceLevel::Floor,
    },
];

/// A plan of one alteration from the root that sails more than this many
/// times the straight line to the goal is compared with the plans of two
/// alterations at the same clearance, and the shorter taken (decision 67).
pub const LONG_DETOUR_FACTOR: f64 = 1.25;

/// How many times the asks of the search from the root that found a long
/// detour ([`LONG_DETOUR_FACTOR`]) the comparison with two alterations may
/// ask the validity check about (decision 67).
pub const COMPARISON_ASKS: u64 = 1;

/// The search from the root for a route that crosses a traffic lane
/// ([`Constraint::prefers_speed_changes`]): the crossing timed by speed
/// first, then [`ROOT_LADDER`] (decision 30).
pub const LANE_CROSSING_LADDER: [Rung; 6] = [
    Rung {
        shape: ManeuverShape::SpeedOnCourse,
        clearance: ClearanceLevel::Preferred,
    },
    Rung {
        shape: ManeuverShape::SpeedOnCourse,
        clearance: ClearanceLevel::Floor,
    },
    ROOT_LADDER[0],
    ROOT_LADDER[1],
    ROOT_LADDER[2],
    ROOT_LADDER[3],
];

/// Which clearance of a shape is asked first; the rung that wins is the
/// same either way (module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Probe {
    /// The preferred clearance first: spares the search at `d_th` where most
    /// searches succeed (a first call).
    PreferredFirst,
    /// `d_th` first: spares the wider search where most fail (a retry), since
    /// nothing is valid wider when nothing is valid at `d_th`.
    FloorFirst,
}

/// Climbs `ladder` with `search`, asking the clearances of each shape in
/// the order `probe` says, and returns what the highest rung that finds
/// something found. With `preferred` false (a preferred clearance no wider
/// than `d_th`) only the `d_th` rungs are asked.
///
/// `search` is also told whether a plan is already found whatever it finds
/// (the `d_th` rung found one and the preferred clearance is asked to widen
/// it: [`Probe::FloorFirst`]), so its refusals need not be kept
/// (`clearances`, decision 59).
fn climb<T>(
    ladder: &[Rung],
    probe: Probe,
    preferred: bool,
    mut search: impl FnMut(Rung, bool) -> Option<T>,
) -> Option<T> {
    let mut shapes: Vec<ManeuverShape> = Vec::with_capacity(ladder.len());
    for rung in ladder {
        if !shapes.contains(&rung.shape) {
            shapes.push(rung.shape);
        }
    }
    shapes.into_iter().find_map(|shape| {
        let at = |clearance| Rung { shape, clearance };
        let has = |clearance| ladder.contains(&at(clearance));
        let mut ask = |clearance, found| {
            if has(clearance) {
                search(at(clearance), found)
            } else {
                None
            }
        };
        if !preferred {
            return ask(ClearanceLevel::Floor, false);
        }
        match probe {
            Probe::PreferredFirst => {
                ask(ClearanceLevel::Preferred, false).or_else(|| ask(ClearanceLevel::Floor, false))
            }
            Probe::FloorFirst => ask(ClearanceLevel::Floor, false)
                .map(|floor| ask(ClearanceLevel::Preferred, true).unwrap_or(floor)),
        }
    })
}

/// The planner's time budget ran out during a manoeuvre search or a
/// branch's simplification.
pub(super) struct Expired;

/// What every extraction of one problem shares.
struct Sailing {
    /// Ownship at the start, at its service speed.
    own: vorrt_colregs::VesselState,
    /// How ownship sails; `None` for instantaneous turns (the plan is the
    /// tree's branch itself).
    model: Option<RateLimitedTurn>,
    speeds: Speeds,
    /// When the planner's time budget runs out, if it has one.
    deadline: Option<Instant>,
    /// Whether a search ran past `deadline`.
    expired: Cell<bool>,
    /// The legs the manoeuvre searches asked the validity check about.
    asked: Cell<u64>,
    /// How many they may ask in all.
    ask_limit: Cell<u64>,
}

impl<C: Constraint> Planner<C> {
    fn sailing(&self, problem: &PlanningProblem, deadline: Option<Instant>) -> Sailing {
        let own = problem.ownship_at_service_speed();
        // How ownship sails (the one model of `Turning::ownship_model`): a
        // rate-limited turn, or the tree's own instantaneous steps.
        let model = match self
            .config
            .turning
            .ownship_model(own.length_m, own.speed_mps)
        {
            OwnshipModel::RateLimited(model) => Some(model),
            OwnshipModel::Instant(_) => None,
        };
        let speeds = Speeds {
            start_mps: problem.ownship.speed_mps,
            service_mps: own.speed_mps,
            change_mps2: self
                .config
                .speed_change_rate_mps2(own.length_m, own.speed_mps),
        };
        Sailing {
            own,
            model,
            speeds,
            deadline,
            expired: Cell::new(false),
            asked: Cell::new(0),
            ask_limit: Cell::new(u64::MAX),
        }
    }

    /// The legs the search at `config`'s clearance finds, by `shape` from
    /// the start through `points` (the goal alone, from the root), every
    /// leg the validity check refuses counted in `refused`. With
    /// `start_searched`, the manoeuvre search from the start is known to
    /// fail ([`simplify_after`]). `shared` holds the verdicts of the other
    /// rungs of the same search (`clearances`, decision 59), with whether a
    /// plan is already found whatever this search finds.
    #[expect(
        clippy::too_many_arguments,
        reason = "one search of the ladder: the problem, where it sails, and the rung"
    )]
    fn search_legs(
        &self,
        problem: &PlanningProblem,
        sailing: &Sailing,
        model: RateLimitedTurn,
        config: &PlannerConfig,
        (shape, shorter_than_m): (ManeuverShape, f64),
        points: &[DVec2],
        start_searched: bool,
        (shared, found): (&ClearanceMemo, bool),
        refused: &mut RejectionCounts,
    ) -> Option<Vec<SimplifiedLeg>> {
        let checker = SafetyChecker::new(
            config,
            &self.tracks,
            sailing.own,
            problem.goal_m,
            problem.start_time_s,
        )
        .with_steady_course(problem.steady_course_rad)
        .with_turning_at_start(problem.turning_at_start)
        .with_state_velocities(&self.track_velocities)
        .with_constraint(&self.constraint);
        // A refusal carried to a wider clearance may name another cause
        // than the check would: only where nothing refused is kept and no
        // earlier search's verdicts are being replayed (their order).
        let widening = found && !self.verdicts.borrow().replaying();
        let checker = AcrossClearances {
            validator: &checker,
            memo: shared,
            clearance_m: config.clearance_m,
            widening,
        };
        let checker = Replaying {
            validator: &checker,
            verdicts: &self.verdicts,
        };
        let recording = Recording::new(&checker, sailing.deadline)
            .with_asks(&sailing.asked, sailing.ask_limit.get());
        let start = Pose {
            position_m: sailing.own.position_m,
            course_rad: sailing.own.course_rad,
        };
        let root = EncounterState::new(
            self.tree.latches_of(0).to_vec(),
            self.tree.alterations_of(0).to_vec(),
        );
        let legs = match shape {
            ManeuverShape::TwoAlterations => hold_then_alter_shorter_than(
                &model,
                &recording,
                start,
                sailing.speeds,
                problem.goal_m,
                &root,
                shorter_than_m,
            ),
            ManeuverShape::SpeedOnCourse => speed_on_course(
                &model,
                &recording,
                start,
                sailing.speeds,
                problem.goal_m,
                &root,
            ),
            ManeuverShape::OneAlteration => simplify_after(
                &model,
                &recording,
                start,
                sailing.speeds,
                points,
                &root,
                start_searched,
            ),
        };
        refused.add(&recording.refused.get());
        if recording.expired.get() {
            sailing.expired.set(true);
            return None;
        }
        legs
    }

    /// The plan from the root alone, before any tree: the first rung of
    /// [`ROOT_LADDER`] that finds a plan, probed as `probe` says. `None`
    /// when none does, or with instantaneous turns (the paper's model has
    /// no manoeuvre search). Every leg refused is counted in `refused`.
    ///
    /// # Errors
    /// [`Expired`] when the search ran past `deadline`.
    pub(super) fn search_root(
        &self,
        problem: &PlanningProblem,
        statistics: &PlanStatistics,
        refused: &mut RejectionCounts,
        probe: Probe,
        deadline: Option<Instant>,
    ) -> Result<Option<Plan>, Expired> {
        let sailing = self.sailing(problem, deadline);
        let Some(model) = sailing.model else {
            return Ok(None);
        };
        // Where sea room allows, the manoeuvre passes wider than `d_th`
        // (PlannerConfig::preferred_clearance_factor); the same validator
        // judges it, with the wider clearance.
        let preferred = PlannerConfig {
            clearance_m: self.config.clearance_m * self.config.preferred_clearance_factor,
            ..self.config
        };
        let goal = [problem.goal_m];
        let ladder: &[Rung] = if self.constraint.prefers_speed_changes() {
            &LANE_CROSSING_LADDER
        } else {
            &ROOT_LADDER
        };
        // The rungs' verdicts, shared between the two clearances.
        let shared = ClearanceMemo::default();
        let mut search = |rung: Rung, found: bool, shorter_than_m: f64| {
            let config = match rung.clearance {
                ClearanceLevel::Preferred => &preferred,
                ClearanceLevel::Floor => &self.config,
            };
            if sailing.expired.get() {
                return None;
            }
            self.search_legs(
                problem,
                &sailing,
                model,
                config,
                (rung.shape, shorter_than_m),
                &goal,
                false,
                (&shared, found),
                refused,
            )
            .map(|legs| (rung, legs))
        };
        let widen = self.config.preferred_clearance_factor > 1.0;
        let mut legs = climb(ladder, probe, widen, |rung, found| {
            search(rung, found, f64::INFINITY)
        });
        // A one-alteration plan that sails far out of the way is compared
        // with the shorter two-alteration plans, if any (decision 67).
        let straight_m = sailing.own.position_m.distance(problem.goal_m);
        let long = |legs: &[SimplifiedLeg]| {
            let length_m = length_of(legs);
            (length_m > LONG_DETOUR_FACTOR * straight_m).then_some(length_m)
        };
        if let Some((found_rung, found)) = &legs
            && found_rung.shape == ManeuverShape::OneAlteration
            && let Some(found_m) = long(found)
            && !sailing.expired.get()
        {
            // At the clearance the plan was found at: the comparison is of
            // lengths, not of passing distances.
            let two = Rung {
                shape: ManeuverShape::TwoAlterations,
                clearance: found_rung.clearance,
            };
            // An allowance of asks, so the comparison costs at most so many
            // times the search it may improve on.
            let asked = sailing.asked.get();
            sailing
                .ask_limit
                .set(asked.saturating_add(asked.saturating_mul(COMPARISON_ASKS)));
            let shorter =
                search(two, false, found_m).filter(|(_, other)| length_of(other) < found_m);
            if shorter.is_some() {
                legs = shorter;
            }
        }
        if sailing.expired.get() {
            return Err(Expired);
        }
        Ok(legs.map(|(Rung { shape, .. }, legs)| {
            let mut plan = self.assemble(problem, &sailing, 0, legs, statistics);
            plan.statistics.source = match shape {
                // A change of speed held is one alteration.
                ManeuverShape::OneAlteration | ManeuverShape::SpeedOnCourse => {
                    PlanSource::OneAlteration
                }
                ManeuverShape::TwoAlterations => PlanSource::TwoAlterations,
            };
            plan
        }))
    }

    /// The plan along the tree's branch to `node`: the branch itself for
    /// instantaneous turns, else its simplification into sailable legs at
    /// `d_th` (`None` when there is none), every leg refused counted in
    /// `refused`. With `root_searched`, the search from the root is known
    /// to have failed, so the simplification does not ask it again.
    ///
    /// # Errors
    /// [`Expired`] when the simplification ran past `deadline`.
    pub(super) fn extract_branch(
        &self,
        problem: &PlanningProblem,
        node: u32,
        statistics: &PlanStatistics,
        refused: &mut RejectionCounts,
        root_searched: bool,
        deadline: Option<Instant>,
    ) -> Result<Option<Plan>, Expired> {
        let sailing = self.sailing(problem, deadline);
        if node == 0 {
            // Ownship is on its goal: the root is the whole branch.
            if sailing.model.is_some() {
                return self.search_root(
                    problem,
                    statistics,
                    refused,
                    Probe::PreferredFirst,
                    deadline,
                );
            }
            let mut plan = self.assemble(problem, &sailing, 0, Vec::new(), statistics);
            plan.statistics.source = PlanSource::Tree;
            return Ok(Some(plan));
        }
        let branch = self.tree.branch(node);
        let legs = match sailing.model {
            None => self.branch_legs(problem, &sailing, &branch),
            Some(model) => {
                let points: Vec<DVec2> = branch[1..]
                    .iter()
                    .map(|&index| self.tree.positions[index as usize])
                    .collect();
                let legs = self.search_legs(
                    problem,
                    &sailing,
                    model,
                    &self.config,
                    (ManeuverShape::OneAlteration, f64::INFINITY),
                    &points,
                    root_searched,
                    (&ClearanceMemo::default(), false),
                    refused,
                );
                if sailing.expired.get() {
                    return Err(Expired);
                }
                let Some(legs) = legs else {
                    return Ok(None);
                };
                legs
            }
        };
        let mut plan = self.assemble(problem, &sailing, node, legs, statistics);
        plan.statistics.source = PlanSource::Tree;
        Ok(Some(plan))
    }

    /// The branch's own steps as legs (instantaneous turns).
    fn branch_legs(
        &self,
        problem: &PlanningProblem,
        sailing: &Sailing,
        branch: &[u32],
    ) -> Vec<SimplifiedLeg> {
        branch
            .windows(2)
            .map(|pair| {
                let (from, to) = (pair[0] as usize, pair[1] as usize);
                let length_m = self.tree.positions[from].distance(self.tree.positions[to]);
                let mut leg = Leg::straight(
                    self.tree.positions[from],
                    self.tree.courses[to],
                    length_m,
                    sailing.own.speed_mps,
                );
                leg.start_course_rad = self.tree.courses[from];
                leg.turn_rad = angle::signed_turn(self.tree.courses[from], self.tree.courses[to]);
                SimplifiedLeg {
                    leg,
                    end_elapsed_s: self.tree.times[to] - problem.start_time_s,
                    state: EncounterState::new(
                        self.tree.latches_of(pair[1]).to_vec(),
                        self.tree.alterations_of(pair[1]).to_vec(),
                    ),
                }
            })
            .collect()
    }

    /// The plan of `legs` (for instantaneous turns, the branch to `node`
    /// exactly as the tree holds it), with the targets predicted at each
    /// waypoint and the encounters in force there.
    fn assemble(
        &self,
        problem: &PlanningProblem,
        sailing: &Sailing,
        node: u32,
        legs: Vec<SimplifiedLeg>,
        statistics: &PlanStatistics,
    ) -> Plan {
        let mut waypoints = Vec::with_capacity(legs.len() + 1);
        waypoints.push(Waypoint {
            position_m: sailing.own.position_m,
            time_s: problem.start_time_s,
            course_rad: self.tree.courses[0],
        });
        if sailing.model.is_none() {
            // The branch itself, exactly as the tree holds it.
            let branch = self.tree.branch(node);
            waypoints.extend(branch[1..].iter().map(|&index| Waypoint {
                position_m: self.tree.positions[index as usize],
                time_s: self.tree.times[index as usize],
                course_rad: self.tree.courses[index as usize],
            }));
        } else {
            waypoints.extend(legs.iter().enumerate().map(|(index, leg)| Waypoint {
                // The plan ends exactly on the goal.
                position_m: if index + 1 == legs.len() {
                    problem.goal_m
                } else {
                    leg.leg.end_m()
                },
                time_s: problem.start_time_s + leg.end_elapsed_s,
                course_rad: leg.leg.course_rad,
            }));
        }
        let target_states = waypoints
            .iter()
            .map(|waypoint| {
                let elapsed_s = waypoint.time_s - problem.start_time_s;
                self.tracks
                    .iter()
                    .map(|track| track.state_at(elapsed_s))
                    .collect()
            })
            .collect();
        let encounters = std::iter::once(self.tree.latches_of(0).to_vec())
            .chain(legs.iter().map(|leg| leg.state.latches.clone()))
            .collect();
        Plan {
            waypoints,
            legs: legs.into_iter().map(|leg| leg.leg).collect(),
            target_states,
            encounters,
            statistics: *statistics,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A search that finds something on the rungs `found` holds, and
    /// records every rung it is asked.
    fn run(probe: Probe, preferred: bool, found: &[Rung]) -> (Option<Rung>, Vec<Rung>) {
        let mut asked = Vec::new();
        let won = climb(&ROOT_LADDER, probe, preferred, |rung, _| {
            asked.push(rung);
            found.contains(&rung).then_some(rung)
        });
        (won, asked)
    }

    #[test]
    fn the_same_rung_wins_whichever_clearance_is_probed_first() {
        // A rung valid at the preferred clearance is valid at d_th: the
        // cases the ladder meets.
        let cases: [&[Rung]; 5] = [
            &[],
            &ROOT_LADDER[1..2],
            &ROOT_LADDER[0..2],
            &ROOT_LADDER[3..4],
            &ROOT_LADDER[1..4],
        ];
        for found in cases {
            let (first, _) = run(Probe::PreferredFirst, true, found);
            let (second, _) = run(Probe::FloorFirst, true, found);
            assert_eq!(first, second, "{found:?}");
            // And it is the first rung, in the ladder's order, that finds one.
            assert_eq!(
                first,
                ROOT_LADDER
                    .iter()
                    .copied()
                    .find(|rung| found.contains(rung))
            );
        }
    }

    #[test]
    fn probing_the_floor_first_spares_the_wider_search_when_it_fails() {
        let (won, asked) = run(Probe::FloorFirst, true, &ROOT_LADDER[3..4]);
        assert_eq!(won, Some(ROOT_LADDER[3]));
        // One alteration fails at d_th, so it is not asked wider.
        assert_eq!(asked, vec![ROOT_LADDER[1], ROOT_LADDER[3], ROOT_LADDER[2]]);
        let (_, asked) = run(Probe::PreferredFirst, true, &ROOT_LADDER[0..2]);
        assert_eq!(asked, vec![ROOT_LADDER[0]]);
    }

    #[test]
    fn without_a_wider_clearance_only_d_th_is_asked() {
        let (won, asked) = run(Probe::PreferredFirst, false, &ROOT_LADDER);
        assert_eq!(won, Some(ROOT_LADDER[1]));
        assert_eq!(asked, vec![ROOT_LADDER[1]]);
    }
}
