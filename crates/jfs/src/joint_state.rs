//! The joint state of all vessels and the paper's joint forward step.
//!
//! JFS (paper §III-D, Algorithm 2 line 5): ownship moves `d'` metres from its
//! node toward the sampled point at its own speed (or onto the point when it is
//! nearer), which takes `Δt = distance / speed`; every target moves for the same
//! `Δt` along its prediction. The heading change at the node is instantaneous,
//! as in the paper (erratum 10: a planner may bound it).

use crate::error::JfsError;
use crate::motion::{InstantTurn, MotionModel, Pose};
use crate::prediction::TargetState;
use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_colregs::VesselState;

/// Every vessel's state at one time.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct JointState {
    /// Time of this state, seconds.
    pub time_s: f64,
    /// Ownship.
    pub ownship: VesselState,
    /// The other vessels, in a fixed order.
    pub targets: Vec<TargetState>,
}

/// Where ownship ends after one step, and how long the step took.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct OwnshipStep {
    /// Ownship after the step: new position, course of the step, same speed.
    pub ownship: VesselState,
    /// Seconds the step took.
    pub duration_s: f64,
}

/// Moves ownship up to `step_m` toward `point_m` at its own speed.
///
/// # Errors
/// [`JfsError`] when ownship's speed is not positive, the step is not a finite
/// positive length, or the point is not finite.
pub fn step_ownship(
    own: &VesselState,
    point_m: DVec2,
    step_m: f64,
) -> Result<OwnshipStep, JfsError> {
    if !(own.speed_mps > 0.0 && own.speed_mps.is_finite()) {
        return Err(JfsError::OwnshipNotMoving {
            speed_mps: own.speed_mps,
        });
    }
    if !(step_m > 0.0 && step_m.is_finite()) {
        return Err(JfsError::InvalidStep { step_m });
    }
    if !point_m.is_finite() {
        return Err(JfsError::NotFinite {
            what: "the point to step toward",
        });
    }
    // The paper's step is the instantaneous-turn motion model with no bound
    // on the turn: one implementation for the planner and this API.
    let model = InstantTurn {
        max_turn_rad: std::f64::consts::PI,
    };
    let from = Pose {
        position_m: own.position_m,
        course_rad: own.course_rad,
    };
    let mut next = *own;
    let Some(leg) = model.steer(from, point_m, own.speed_mps, step_m) else {
        // Already on the point.
        return Ok(OwnshipStep {
            ownship: next,
            duration_s: 0.0,
        });
    };
    next.course_rad = leg.course_rad;
    next.position_m = if point_m.distance(own.position_m) <= step_m {
        // Exactly on a point within reach, whatever the rounding.
        point_m
    } else {
        leg.end_m()
    };
    Ok(OwnshipStep {
        ownship: next,
        duration_s: leg.duration_s(),
    })
}

impl JointState {
    /// A joint state from its parts.
    #[must_use]
    pub fn new(time_s: f64, ownship: VesselState, targets: Vec<TargetState>) -> Self {
        Self {
            time_s,
            ownship,
            targets,
        }
    }

    /// Every target predicted `duration_s` on; ownship unchanged.
    #[must_use]
    pub fn targets_after(&self, duration_s: f64) -> Vec<TargetState> {
        self.targets
            .iter()
            .map(|target| target.predict(duration_s))
            .collect()
    }

    /// The joint forward step: ownship moves up to `step_m` toward `point_m`;
    /// the targets move for the same time.
    ///
    /// ```
    /// use vorrt_jfs::{JointState, TargetState};
    /// use vorrt_colregs::VesselState;
    /// use glam::DVec2;
    /// let own = VesselState::new(DVec2::ZERO, 0.0, 5.0, 50.0);
    /// let target = TargetState::constant_velocity(VesselState::new(DVec2::new(1000.0, 0.0), 0.0, 2.0, 50.0));
    /// let state = JointState::new(0.0, own, vec![target]);
    /// let next = state.step_toward(DVec2::new(0.0, 1000.0), 100.0).unwrap();
    /// assert_eq!(next.time_s, 20.0);
    /// assert_eq!(next.ownship.position_m, DVec2::new(0.0, 100.0));
    /// assert_eq!(next.targets[0].vessel.position_m, DVec2::new(1000.0, 40.0));
    /// ```
    ///
    /// # Errors
    /// As [`step_ownship`].
    pub fn step_toward(&self, point_m: DVec2, step_m: f64) -> Result<JointState, JfsError> {
        let step = step_ownship(&self.ownship, point_m, step_m)?;
        Ok(JointState {
            time_s: self.time_s + step.duration_s,
            ownship: step.ownship,
            targets: self.targets_after(step.duration_s),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn near_point_is_reached_exactly() {
        let own = VesselState::new(DVec2::ZERO, 0.0, 5.0, 50.0);
        let step = step_ownship(&own, DVec2::new(30.0, 40.0), 100.0).unwrap();
        assert_eq!(step.ownship.position_m, DVec2::new(30.0, 40.0));
        assert!((step.duration_s - 10.0).abs() < 1e-12);
    }

    #[test]
    fn stopped_ownship_is_an_error() {
        let own = VesselState::new(DVec2::ZERO, 0.0, 0.0, 50.0);
        assert!(matches!(
            step_ownship(&own, DVec2::new(0.0, 10.0), 100.0),
            Err(JfsError::OwnshipNotMoving { .. })
        ));
    }

    #[test]
    fn bad_step_and_point_are_errors() {
        let own = VesselState::new(DVec2::ZERO, 0.0, 5.0, 50.0);
        assert!(step_ownship(&own, DVec2::new(0.0, 10.0), f64::NAN).is_err());
        assert!(step_ownship(&own, DVec2::new(f64::INFINITY, 10.0), 10.0).is_err());
    }
}
