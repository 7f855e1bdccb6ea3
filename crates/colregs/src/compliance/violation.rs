//! The findings of an assessment: safety shortfalls and broken rules.

use serde::{Deserialize, Serialize};

/// A finding about one recorded encounter: a safety shortfall or a broken rule.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum ComplianceViolation {
    /// The minimum range was under the clearance `d_th` (rules 8(d), 16: "keep
    /// well clear"). A safety finding, not a rule violation.
    ClearanceViolated {
        /// The minimum range, metres.
        min_distance_m: f64,
    },
    /// The hulls touched: the minimum range was under half the sum of the two
    /// lengths ([`in_contact`](crate::rules::in_contact)). A safety finding.
    Collision {
        /// The minimum range, metres.
        min_distance_m: f64,
    },
    /// A give-way vessel took no action although action was needed (rule 16).
    NoAction,
    /// A give-way vessel's action began late (rule 16: "early action").
    LateAction {
        /// The range when the action began, metres.
        range_m: f64,
    },
    /// A give-way vessel's action was not readily apparent (rules 8(b), 16:
    /// "substantial action").
    ActionNotApparent {
        /// The largest course change while in force, radians, positive to starboard.
        course_change_rad: f64,
        /// The largest speed change while in force, m/s, negative = slower.
        speed_change_mps: f64,
    },
    /// A give-way vessel turned to port (rule 14(a) in head-on; rules 15, 16
    /// in crossing).
    PortTurn {
        /// The port turn judged (first detectable, or largest), radians (negative).
        course_change_rad: f64,
    },
    /// In head-on the target passed on ownship's starboard side (rule 14(a):
    /// pass port to port).
    StarboardToStarboard,
    /// Ownship crossed ahead of the target: of the stand-on vessel in crossing
    /// (rule 15), or cutting across the overtaken vessel's bow (rule 13).
    CrossedAhead {
        /// How far ahead of the target's bow the track was crossed, metres.
        distance_ahead_m: f64,
    },
    /// A stand-on vessel changed course before it might act (rule 17(a)(i)).
    StandOnCourseChanged {
        /// The largest course change while beyond the action range, radians.
        course_change_rad: f64,
    },
    /// A stand-on vessel changed speed before it might act (rule 17(a)(i)).
    StandOnSpeedChanged {
        /// The largest speed change while beyond the action range, m/s.
        speed_change_mps: f64,
    },
    /// A stand-on vessel in a crossing turned to port for a vessel on its own
    /// port side (rule 17(c)).
    StandOnTurnedToPort {
        /// The course change at that moment, radians (negative).
        course_change_rad: f64,
    },
    /// Risk of collision arose just after ownship turned to port toward this
    /// vessel, on its port side forward of the beam: the turn made the
    /// encounter (rule 17(c) where ownship then stands on, good seamanship,
    /// rules 2(a) and 8(a), where it gives way;
    /// [`is_port_turn_toward_vessel`](crate::rules::is_port_turn_toward_vessel)).
    PortTurnTowardVessel {
        /// The port turn, from the course held before it to the course on
        /// which risk arose, radians (negative).
        course_change_rad: f64,
    },
    /// A give-way vessel made a succession of small alterations while the
    /// encounter was in force: two or more alteration episodes each at least
    /// detectable and smaller than readily apparent (rule 8(b)).
    SmallAlterations {
        /// How many small alteration episodes.
        episodes: usize,
    },
    /// A give-way vessel eased its readily apparent alteration back below
    /// readily apparent before the closest approach (rules 8(d), 16: the
    /// action is held until the other vessel is past).
    AlterationNotHeld {
        /// The course change it eased back to, radians, positive to starboard
        /// (0 for an alteration of speed).
        course_change_rad: f64,
        /// The speed change it eased back to, m/s (0 for an alteration of
        /// course).
        speed_change_mps: f64,
    },
}

impl ComplianceViolation {
    /// The COLREGs rule the finding is judged under; `None` for the safety
    /// findings ([`ClearanceViolated`](Self::ClearanceViolated),
    /// [`Collision`](Self::Collision)), which the safety score covers.
    /// [`PortTurn`](Self::PortTurn) and [`CrossedAhead`](Self::CrossedAhead)
    /// depend on the encounter and give their usual rule (14 and 15), as
    /// does [`PortTurnTowardVessel`](Self::PortTurnTowardVessel) (17); the
    /// assessment books them against the encounter's own rule.
    #[must_use]
    pub fn rule(&self) -> Option<u8> {
        match self {
            Self::ClearanceViolated { .. } | Self::Collision { .. } => None,
            Self::NoAction | Self::LateAction { .. } | Self::ActionNotApparent { .. } => Some(16),
            Self::SmallAlterations { .. } | Self::AlterationNotHeld { .. } => Some(8),
            Self::PortTurn { .. } | Self::StarboardToStarboard => Some(14),
            Self::CrossedAhead { .. } => Some(15),
            Self::StandOnCourseChanged { .. }
            | Self::StandOnSpeedChanged { .. }
            | Self::StandOnTurnedToPort { .. }
            | Self::PortTurnTowardVessel { .. } => Some(17),
        }
    }

    /// Whether this is a rule violation (as opposed to a safety finding).
    #[must_use]
    pub fn is_rule_violation(&self) -> bool {
        self.rule().is_some()
    }

    /// A short name in snake case, as used in reports.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Self::ClearanceViolated { .. } => "clearance_violated",
            Self::Collision { .. } => "collision",
            Self::NoAction => "no_action",
            Self::LateAction { .. } => "late_action",
            Self::ActionNotApparent { .. } => "action_not_apparent",
            Self::PortTurn { .. } => "port_turn",
            Self::StarboardToStarboard => "starboard_to_starboard",
            Self::CrossedAhead { .. } => "crossed_ahead",
            Self::StandOnCourseChanged { .. } => "stand_on_course_changed",
            Self::StandOnSpeedChanged { .. } => "stand_on_speed_changed",
            Self::StandOnTurnedToPort { .. } => "stand_on_turned_to_port",
            Self::PortTurnTowardVessel { .. } => "port_turn_toward_vessel",
            Self::SmallAlterations { .. } => "small_alterations",
            Self::AlterationNotHeld { .. } => "alteration_not_held",
        }
    }
}

impl std::fmt::Display for ComplianceViolation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            Self::ClearanceViolated { min_distance_m } => write!(
                f,
                "minimum range {min_distance_m:.0} m under the clearance (rules 8(d), 16: keep well clear)"
            ),
            Self::Collision { min_distance_m } => write!(
                f,
                "collision: minimum range {min_distance_m:.0} m, the hulls touched"
            ),
            Self::NoAction => f.write_str("give-way vessel took no action (rule 16)"),
            Self::LateAction { range_m } => write!(
                f,
                "give-way action began late, at {range_m:.0} m (rule 16: early action)"
            ),
            Self::ActionNotApparent {
                course_change_rad,
                speed_change_mps,
            } => write!(
                f,
                "give-way action not readily apparent: course change {:.1}°, speed change {speed_change_mps:.2} m/s (rules 8(b), 16)",
                course_change_rad.to_degrees()
            ),
            Self::PortTurn { course_change_rad } => write!(
                f,
                "give-way vessel turned {:.1}° to port (rules 14(a), 15)",
                -course_change_rad.to_degrees()
            ),
            Self::StarboardToStarboard => {
                f.write_str("head-on vessels passed starboard to starboard (rule 14(a))")
            }
            Self::CrossedAhead { distance_ahead_m } => write!(
                f,
                "crossed {distance_ahead_m:.0} m ahead of the other vessel's bow (rules 15, 13)"
            ),
            Self::StandOnCourseChanged { course_change_rad } => write!(
                f,
                "stand-on vessel changed course by {:.1}° before it might act (rule 17(a)(i))",
                course_change_rad.to_degrees()
            ),
            Self::StandOnSpeedChanged { speed_change_mps } => write!(
                f,
                "stand-on vessel changed speed by {speed_change_mps:.2} m/s before it might act (rule 17(a)(i))"
            ),
            Self::StandOnTurnedToPort { course_change_rad } => write!(
                f,
                "stand-on vessel turned {:.1}° to port for a vessel on its own port side (rule 17(c))",
                -course_change_rad.to_degrees()
            ),
            Self::PortTurnTowardVessel { course_change_rad } => write!(
                f,
                "turned {:.1}° to port toward a vessel on the port side forward of the beam, onto a risk of collision (rules 2(a), 8(a), 17(c))",
                -course_change_rad.to_degrees()
            ),
            Self::SmallAlterations { episodes } => write!(
                f,
                "succession of {episodes} small alterations, each under readily apparent (rule 8(b))"
            ),
            Self::AlterationNotHeld {
                course_change_rad,
                speed_change_mps,
            } => write!(
                f,
                "give-way alteration eased back to {:.1}°, {speed_change_mps:.2} m/s before the closest approach (rules 8(d), 16)",
                course_change_rad.to_degrees()
            ),
        }
    }
}
