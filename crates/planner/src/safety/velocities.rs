//! Each target's velocity worked out once per planner call: the states its
//! track gives while it moves have one course and speed per stretch, so
//! their velocities ([`VesselState::velocity_mps`]) are known before any leg
//! asks.

use glam::DVec2;
use vorrt_colregs::VesselState;
use vorrt_jfs::LinearTrack;

/// The velocities of the states a target's track gives
/// ([`LinearTrack::state_at`]) on its two stretches, each with the course
/// and speed it is the velocity of (as bits): a state of the same course
/// and speed has the very same velocity, which a leg's check then takes
/// from here rather than working it out again (a sine and a cosine per
/// target per leg, most of them on the tree's short legs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StateVelocities([(u64, u64, DVec2); 2]);

impl StateVelocities {
    /// The velocities of `track`'s states at its start and where its
    /// second stretch begins.
    ///
    /// ```
    /// use vorrt_planner::safety::StateVelocities;
    /// use vorrt_jfs::TargetState;
    /// use vorrt_colregs::VesselState;
    /// use glam::DVec2;
    /// let track = TargetState::constant_velocity(
    ///     VesselState::new(DVec2::ZERO, 1.0, 5.0, 50.0)).track();
    /// let known = StateVelocities::of(&track);
    /// let state = track.state_at(30.0);
    /// assert_eq!(known.velocity_of(&state), Some(state.velocity_mps()));
    /// ```
    #[must_use]
    pub fn of(track: &LinearTrack) -> Self {
        let entry = |state: VesselState| {
            (
                state.course_rad.to_bits(),
                state.speed_mps.to_bits(),
                state.velocity_mps(),
            )
        };
        Self([
            entry(track.state_at(0.0)),
            entry(track.state_at(track.turns_at_s.max(0.0))),
        ])
    }

    /// `state`'s velocity, if it has the course and speed (the same bits)
    /// of one of the two states kept; `None` otherwise (at rest, say).
    #[must_use]
    pub fn velocity_of(&self, state: &VesselState) -> Option<DVec2> {
        let key = (state.course_rad.to_bits(), state.speed_mps.to_bits());
        self.0
            .iter()
            .find(|(course, speed, _)| (*course, *speed) == key)
            .map(|&(_, _, velocity_mps)| velocity_mps)
    }
}

/// Target `index`'s velocity in state `target` from `known` (one entry per
/// target, [`StateVelocities::of`]; may be empty), where it applies.
pub(crate) fn known_velocity(
    known: &[StateVelocities],
    index: usize,
    target: &VesselState,
) -> Option<DVec2> {
    known.get(index).and_then(|known| known.velocity_of(target))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use vorrt_jfs::TargetState;

    proptest! {
        /// At every time on every kind of track (one leg, a hold then a
        /// turn for the goal, a goal reached, at rest), a velocity given is
        /// the state's own, bit for bit, and one is given wherever the
        /// target moves.
        #[test]
        fn a_known_velocity_is_the_states_own(
            course_rad in 0.0..std::f64::consts::TAU,
            speed_mps in 0.0..12.0f64,
            goal in proptest::option::of((-5000.0..5000.0f64, -5000.0..5000.0f64)),
            hold_s in proptest::option::of(0.0..600.0f64),
            elapsed_s in -10.0..4000.0f64,
        ) {
            let vessel = VesselState::new(DVec2::new(100.0, -50.0), course_rad, speed_mps, 80.0);
            let target = match (goal, hold_s) {
                (Some((x, y)), Some(hold_s)) => {
                    TargetState::holding_course_then_toward_goal(vessel, DVec2::new(x, y), hold_s)
                }
                (Some((x, y)), None) => TargetState::toward_goal(vessel, DVec2::new(x, y)),
                (None, _) => TargetState::constant_velocity(vessel),
            };
            let track = target.track();
            let known = StateVelocities::of(&track);
            let state = track.state_at(elapsed_s);
            if let Some(velocity_mps) = known.velocity_of(&state) {
                let want = state.velocity_mps();
                prop_assert_eq!(velocity_mps.x.to_bits(), want.x.to_bits());
                prop_assert_eq!(velocity_mps.y.to_bits(), want.y.to_bits());
            }
            if (0.0..track.moving_for_s).contains(&elapsed_s) {
                prop_assert!(known.velocity_of(&state).is_some());
            }
        }
    }
}
