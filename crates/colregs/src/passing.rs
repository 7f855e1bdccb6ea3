//! How one vessel passes another: the side, and whether it crosses ahead.
//!
//! Both tests work in the target's frame, where the target stands still and
//! ownship moves along the relative velocity `V_A - V_B`:
//! - ownship **crosses ahead** of the target when its relative track meets the
//!   target's bow ray (the half-line from the target along its heading) at a
//!   future time: ownship passes through the target's track before the target
//!   gets there (rule 15: "avoid crossing ahead");
//! - the target **passes to port** when the relative track leaves it on
//!   ownship's left: the line of sight turns anticlockwise relative to the
//!   relative velocity (head-on, rule 14: pass port to port).

use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_geometry::cross;

/// The side of ownship on which a target passes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PassingSide {
    /// The target passes on ownship's port side (port to port in head-on).
    Port,
    /// The target passes on ownship's starboard side.
    Starboard,
}

/// The side on which the target passes if both keep their velocities.
///
/// ```
/// use vorrt_colregs::{passing_side, PassingSide};
/// use glam::DVec2;
/// // Target dead ahead, meeting; ownship bears away to starboard (north-east).
/// let side = passing_side(DVec2::ZERO, DVec2::new(2.0, 5.0), DVec2::new(0.0, 5000.0), DVec2::new(0.0, -5.0));
/// assert_eq!(side, PassingSide::Port);
/// ```
#[must_use]
pub fn passing_side(
    own_position_m: DVec2,
    own_velocity_mps: DVec2,
    target_position_m: DVec2,
    target_velocity_mps: DVec2,
) -> PassingSide {
    let line_of_sight = target_position_m - own_position_m;
    let relative_velocity = own_velocity_mps - target_velocity_mps;
    if cross(line_of_sight, relative_velocity) <= 0.0 {
        PassingSide::Port
    } else {
        PassingSide::Starboard
    }
}

/// Whether ownship, keeping its velocity, crosses the target's track ahead of
/// the target (through its bow ray, in the target's frame). A stationary
/// target has no bow ray and is never crossed ahead of.
///
/// ```
/// use vorrt_colregs::crosses_ahead;
/// use glam::DVec2;
/// // Target 3 km east, 3 km north, heading west; ownship heads north or north-east.
/// let target = DVec2::new(3000.0, 3000.0);
/// let target_velocity = DVec2::new(-5.0, 0.0);
/// assert!(crosses_ahead(DVec2::ZERO, DVec2::new(0.0, 8.0), target, target_velocity));
/// assert!(!crosses_ahead(DVec2::ZERO, DVec2::new(4.0, 4.0), target, target_velocity));
/// ```
#[must_use]
pub fn crosses_ahead(
    own_position_m: DVec2,
    own_velocity_mps: DVec2,
    target_position_m: DVec2,
    target_velocity_mps: DVec2,
) -> bool {
    let heading = target_velocity_mps.normalize_or_zero();
    if heading == DVec2::ZERO {
        return false;
    }
    let relative_position = own_position_m - target_position_m;
    let relative_velocity = own_velocity_mps - target_velocity_mps;
    let offset = cross(heading, relative_position);
    let drift = cross(heading, relative_velocity);
    if drift == 0.0 {
        // Moving parallel to the target's track: crossing only if already on it, ahead.
        return offset == 0.0 && heading.dot(relative_position) > 0.0;
    }
    let time_to_track = -offset / drift;
    if time_to_track < 0.0 {
        return false;
    }
    heading.dot(relative_position + relative_velocity * time_to_track) > 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holding_course_into_a_head_on_target_passes_port_or_starboard_by_offset() {
        let target_velocity = DVec2::new(0.0, -5.0);
        let own_velocity = DVec2::new(0.0, 5.0);
        // Target slightly to port of the bow: it passes to port.
        assert_eq!(
            passing_side(
                DVec2::ZERO,
                own_velocity,
                DVec2::new(-50.0, 5000.0),
                target_velocity
            ),
            PassingSide::Port
        );
        assert_eq!(
            passing_side(
                DVec2::ZERO,
                own_velocity,
                DVec2::new(50.0, 5000.0),
                target_velocity
            ),
            PassingSide::Starboard
        );
    }

    #[test]
    fn passing_astern_is_not_crossing_ahead() {
        // Target heading west from the starboard bow; ownship turns east-south-east.
        let target = DVec2::new(3000.0, 3000.0);
        assert!(!crosses_ahead(
            DVec2::ZERO,
            DVec2::new(5.0, -1.0),
            target,
            DVec2::new(-5.0, 0.0)
        ));
    }

    #[test]
    fn stationary_target_is_never_crossed_ahead() {
        assert!(!crosses_ahead(
            DVec2::ZERO,
            DVec2::new(0.0, 5.0),
            DVec2::new(0.0, 100.0),
            DVec2::ZERO
        ));
    }
}
