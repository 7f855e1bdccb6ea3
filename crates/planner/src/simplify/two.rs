//! The manoeuvres of two alterations from the planner's root (decision
//! 27), and the same shorter than a plan in hand (decision 67).

use super::{
    ALTERATIONS_DEG, Alterations, EncounterState, SimplifiedLeg, Speeds, abeam_of,
    alter_hold_return, holds_short_of, shortest_through_m,
};
use crate::validity::MotionValidator;
use glam::DVec2;
use vorrt_jfs::{MotionModel, Pose};

/// The manoeuvres of two alterations, tried where one alteration held
/// cannot be sailed: from `start` with `state` in force, a first course
/// held for one of [`HOLD_M`](super::HOLD_M) (shortest first), then a second course held,
/// then a leg to the goal. Neither hold ends past abeam of the goal: the
/// holds of [`HOLD_M`](super::HOLD_M) that would are replaced by one that ends abeam of
/// it. Three legs, all accepted by `validator`, or `None`. In order:
///
/// - **Keep the course, then act**: the present course held at service
///   speed, then any manoeuvre of the search of [`simplify`](super::simplify) (but holding on
///   further, which is a longer first hold). A stand-on vessel keeps her
///   course and speed (rule 17(a)(i)) until she may act, within the
///   stand-on action range (17(a)(ii)), then takes such action as will best
///   avoid collision (17(b)), to starboard first (17(c)); the shortest hold
///   the validator accepts is the earliest action the rules allow.
/// - **Alter, then resume**: each starboard alteration of
///   [`ALTERATIONS_DEG`](super::ALTERATIONS_DEG) (smallest first) held, then back onto the course
///   held before it, held in turn: the alteration is held until the other
///   vessel is past and clear (rule 8(d)), and the return toward the route
///   waits until heading for the goal meets no one.
/// - **Keep the course within the drift allowed, then act**: where both
///   fail, the first on the present course plus [`STAND_ON_DRIFT_DEG`].
///
/// ```
/// use vorrt_planner::simplify::{hold_then_alter, Speeds};
/// use vorrt_planner::validity::EncounterState;
/// use vorrt_planner::{safety::SafetyChecker, PlannerConfig};
/// use vorrt_colregs::VesselState;
/// use vorrt_jfs::{Pose, RateLimitedTurn};
/// use glam::DVec2;
/// let config = PlannerConfig::default();
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let goal_m = DVec2::new(3000.0, 3000.0);
/// let checker = SafetyChecker::new(&config, &[], own, goal_m, 0.0);
/// let legs = hold_then_alter(
///     &RateLimitedTurn { turn_radius_m: 300.0 },
///     &checker,
///     Pose { position_m: DVec2::ZERO, course_rad: 0.0 },
///     Speeds::constant(6.0),
///     goal_m,
///     &EncounterState::default(),
/// )
/// .unwrap();
/// // Nothing in the way: the course held for the shortest hold, then the
/// // smallest alteration.
/// assert_eq!(legs.len(), 3);
/// assert!((legs[0].leg.end_m().y - 250.0).abs() < 1e-6);
/// assert!((legs[2].leg.end_m() - goal_m).length() < 1e-6);
/// ```
pub fn hold_then_alter<M: MotionModel, V: MotionValidator>(
    model: &M,
    validator: &V,
    start: Pose,
    speeds: Speeds,
    goal_m: DVec2,
    state: &EncounterState,
) -> Option<Vec<SimplifiedLeg>> {
    hold_then_alter_shorter_than(
        model,
        validator,
        start,
        speeds,
        goal_m,
        state,
        f64::INFINITY,
    )
}

/// [`hold_then_alter`], trying only the manoeuvres shorter than
/// `shorter_than_m` (sailed to the goal): where a plan is known already and
/// only a shorter one would be taken instead. A hold whose length plus the
/// straight line from its end to the goal is no shorter cannot be (the
/// triangle inequality), nor can any longer hold.
///
/// ```
/// use vorrt_planner::simplify::{hold_then_alter_shorter_than, Speeds};
/// use vorrt_planner::validity::EncounterState;
/// use vorrt_planner::{safety::SafetyChecker, PlannerConfig};
/// use vorrt_colregs::VesselState;
/// use vorrt_jfs::{Pose, RateLimitedTurn};
/// use glam::DVec2;
/// let config = PlannerConfig::default();
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let goal_m = DVec2::new(3000.0, 3000.0);
/// let checker = SafetyChecker::new(&config, &[], own, goal_m, 0.0);
/// let model = RateLimitedTurn { turn_radius_m: 300.0 };
/// let start = Pose { position_m: DVec2::ZERO, course_rad: 0.0 };
/// let state = EncounterState::default();
/// let found = |bound_m| {
///     let speeds = Speeds::constant(6.0);
///     hold_then_alter_shorter_than(&model, &checker, start, speeds, goal_m, &state, bound_m)
/// };
/// // Nothing in the way: a manoeuvre of some 4.3 km; none is shorter than
/// // the straight line.
/// assert!(found(5000.0).is_some());
/// assert!(found(goal_m.length()).is_none());
/// ```
pub fn hold_then_alter_shorter_than<M: MotionModel, V: MotionValidator>(
    model: &M,
    validator: &V,
    start: Pose,
    speeds: Speeds,
    goal_m: DVec2,
    state: &EncounterState,
    shorter_than_m: f64,
) -> Option<Vec<SimplifiedLeg>> {
    // The stand-on drifts come last: every plan found before is kept.
    let firsts = ALTERATIONS_DEG.iter().filter(|deg| **deg >= 0.0);
    let drifts = STAND_ON_DRIFT_DEG.map(|deg| (deg, true));
    let firsts = firsts.map(|deg| (*deg, false)).chain(drifts);
    for (first_deg, drift) in firsts {
        let second = if first_deg == 0.0 || drift {
            Alterations::MarinersAfterHolding
        } else {
            Alterations::Resume(first_deg)
        };
        let course_rad = start.course_rad + first_deg.to_radians();
        let turn = model.turn_onto(start, course_rad, speeds.service_mps, 0.0);
        for hold_m in holds_short_of(abeam_of(goal_m, &turn)) {
            let hold = model
                .turn_onto(start, course_rad, speeds.service_mps, hold_m)
                .from_speed(speeds.start_mps, speeds.change_mps2);
            if shortest_through_m(&hold, goal_m) >= shorter_than_m {
                // This hold, and every longer one, sails no shorter.
                break;
            }
            let mut after = state.clone();
            if validator.validate(&hold, 0.0, &mut after).is_err() {
                // Holding this far is already invalid: longer holds are too.
                break;
            }
            let first_leg = SimplifiedLeg {
                end_elapsed_s: hold.duration_s(),
                leg: hold,
                state: after,
            };
            let rest_shorter_than_m = shorter_than_m - first_leg.leg.length_m();
            if let Some(rest) = alter_hold_return(
                model,
                validator,
                &first_leg,
                speeds,
                goal_m,
                (second, rest_shorter_than_m),
            ) {
                return Some(std::iter::once(first_leg).chain(rest).collect());
            }
        }
    }
    None
}

/// Starboard drifts of the stand-on hold of [`hold_then_alter`], degrees:
/// within rule 17(a)(i)'s 15° (decision 46).
pub const STAND_ON_DRIFT_DEG: [f64; 2] = [5.0, 10.0];
