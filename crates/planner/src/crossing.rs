//! The lane crossing a mariner makes (rule 10(c), decision 30): heading
//! for the goal across the lane, square to its flow, the gap in the lane's
//! traffic chosen by speed rather than by turning to pass astern of the
//! whole stream. The closed loop's replans keep the heading and adjust the
//! speed again as the traffic comes on.
//!
//! [`speed_on_course`] is the rung the search from the root tries first
//! when the constraint asks for it ([`Constraint::prefers_speed_changes`](crate::Constraint::prefers_speed_changes):
//! a route that crosses a lane); every leg is judged by the same validity
//! check as every other manoeuvre.

use crate::simplify::{HOLD_M, SimplifiedLeg, Speeds, reduction_held, return_to_goal};
use crate::validity::{EncounterState, MotionValidator};
use glam::DVec2;
use vorrt_geometry::angle;
use vorrt_jfs::{MotionModel, Pose};

/// The speeds a crossing slows to, as fractions of the service speed,
/// fastest first: the manoeuvre search's readily apparent reduction (0.45,
/// `simplify::SPEED_FACTORS`: at least halved, rules 8(b), 16), then
/// holding short of the lane at steerage way (three tenths; stopping is the
/// evasive fallback's). Milder reductions (0.75, 0.6) were judged not
/// readily apparent where they began before risk arose (decision 30).
pub const CROSSING_SPEED_FACTORS: [f64; 2] = [0.45, 0.3];

/// From `start` with `state` in force, the first manoeuvre "head for the
/// goal at a fraction of the service speed ([`CROSSING_SPEED_FACTORS`],
/// fastest first), hold it for one of [`HOLD_M`] (shortest first), then
/// one leg to the goal at service speed" that `validator` accepts: the hold
/// and the return, or `None`. As every reduction of the manoeuvre search,
/// a reduced speed is held until it is reached and every encounter in which
/// ownship gives way has passed (rule 8(d)).
///
/// ```
/// use vorrt_planner::crossing::speed_on_course;
/// use vorrt_planner::simplify::Speeds;
/// use vorrt_planner::validity::{EncounterState, MotionValidator};
/// use vorrt_planner::{DVec2, Leg, Pose, RateLimitedTurn, RejectionCause};
///
/// /// Refuses full speed before 1 km north (a lane vessel passing ahead).
/// struct Gap;
/// impl MotionValidator for Gap {
///     fn validate(&self, leg: &Leg, _t: f64, _s: &mut EncounterState) -> Result<(), RejectionCause> {
///         if leg.speed_mps > 4.0 && leg.start_m.y < 1000.0 { Err(RejectionCause::Clearance) } else { Ok(()) }
///     }
/// }
/// let model = RateLimitedTurn { turn_radius_m: 300.0 };
/// let start = Pose { position_m: DVec2::ZERO, course_rad: 0.0 };
/// let legs = speed_on_course(&model, &Gap, start, Speeds::constant(6.0), DVec2::new(0.0, 5000.0), &EncounterState::default()).unwrap();
/// assert_eq!(legs.len(), 2);
/// assert!((legs[0].leg.speed_mps - 0.45 * 6.0).abs() < 1e-9);
/// assert!(legs[1].leg.start_m.y >= 1000.0);
/// ```
pub fn speed_on_course<M: MotionModel, V: MotionValidator>(
    model: &M,
    validator: &V,
    start: Pose,
    speeds: Speeds,
    goal_m: DVec2,
    state: &EncounterState,
) -> Option<Vec<SimplifiedLeg>> {
    let course_rad = angle::unit_to_course(goal_m - start.position_m);
    let to_goal_m = start.position_m.distance(goal_m);
    for factor in CROSSING_SPEED_FACTORS {
        let hold_speed_mps = factor * speeds.service_mps;
        // Holds that end short of the goal: the return is a leg to it.
        for hold_m in HOLD_M.into_iter().filter(|hold_m| *hold_m < to_goal_m) {
            let hold = model
                .turn_onto(start, course_rad, hold_speed_mps, hold_m)
                .from_speed(speeds.start_mps, speeds.change_mps2);
            let mut after = state.clone();
            if validator.validate(&hold, 0.0, &mut after).is_err() {
                // Holding this far is already invalid: longer holds are too.
                break;
            }
            if !reduction_held(&hold, &after) {
                continue;
            }
            let hold = SimplifiedLeg {
                end_elapsed_s: hold.duration_s(),
                leg: hold,
                state: after,
            };
            if let Some(back) = return_to_goal(model, validator, &hold, speeds, goal_m) {
                return Some(std::iter::once(hold).chain(back).collect());
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::RejectionCause;
    use vorrt_jfs::{Leg, RateLimitedTurn};

    struct Never;
    impl MotionValidator for Never {
        fn validate(
            &self,
            _leg: &Leg,
            _start_elapsed_s: f64,
            _state: &mut EncounterState,
        ) -> Result<(), RejectionCause> {
            Err(RejectionCause::Clearance)
        }
    }

    struct Always;
    impl MotionValidator for Always {
        fn validate(
            &self,
            _leg: &Leg,
            _start_elapsed_s: f64,
            _state: &mut EncounterState,
        ) -> Result<(), RejectionCause> {
            Ok(())
        }
    }

    #[test]
    fn the_fastest_shortest_crossing_wins_and_none_is_found_where_nothing_is_valid() {
        let model = RateLimitedTurn {
            turn_radius_m: 300.0,
        };
        let start = Pose {
            position_m: DVec2::ZERO,
            course_rad: 0.3,
        };
        let goal_m = DVec2::new(0.0, 6000.0);
        let state = EncounterState::default();
        let speeds = Speeds::constant(6.0);
        assert!(speed_on_course(&model, &Never, start, speeds, goal_m, &state).is_none());
        let legs = speed_on_course(&model, &Always, start, speeds, goal_m, &state).expect("valid");
        // Turned onto the goal's bearing, at 45 %, for the shortest hold.
        assert!(legs[0].leg.course_rad.abs() < 1e-12);
        assert!((legs[0].leg.speed_mps - 2.7).abs() < 1e-12);
        assert!((legs.last().expect("legs").leg.end_m() - goal_m).length() < 1e-6);
    }
}
