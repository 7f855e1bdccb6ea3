//! What the planner returns: waypoints with times, the predicted targets along
//! them, and statistics of the search.

use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_colregs::{EncounterLatch, ManeuverViolation, VesselState};
use vorrt_jfs::{Leg, Pose};

/// One point of the planned path.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Waypoint {
    /// Where ownship is, metres.
    pub position_m: DVec2,
    /// When ownship is there, seconds (same clock as the problem's start time).
    pub time_s: f64,
    /// Ownship's course on the segment that ends here, radians (the start
    /// course at the first waypoint).
    pub course_rad: f64,
}

/// Why a sample was not added to the tree.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RejectionCause {
    /// The new velocity lies in a target's velocity obstacle (paper, Algorithm 3).
    VelocityObstacle,
    /// A target comes within `d_th` during the segment (erratum 6).
    Clearance,
    /// A target in an encounter in force would come within `d_th` after the
    /// segment if ownship held the new velocity.
    ClearanceAhead,
    /// The move breaks a COLREGs rule for an encounter in force.
    Colregs(ManeuverViolation),
}

impl RejectionCause {
    /// A short description, for messages.
    #[must_use]
    pub fn description(self) -> String {
        match self {
            RejectionCause::VelocityObstacle => {
                "velocity obstacle of a target (paper Algorithm 3)".into()
            }
            RejectionCause::Clearance => "clearance d_th broken during the segment".into(),
            RejectionCause::ClearanceAhead => {
                "clearance d_th broken after the segment (encounter in force)".into()
            }
            RejectionCause::Colregs(violation) => format!("COLREGs: {violation}"),
        }
    }
}

/// Rejected samples, counted by cause.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct RejectionCounts {
    /// Rejected by a velocity obstacle.
    pub velocity_obstacle: u64,
    /// Rejected for breaking `d_th` during the segment.
    pub clearance: u64,
    /// Rejected for breaking `d_th` after the segment.
    pub clearance_ahead: u64,
    /// Rejected for a turn to port (rules 14, 15).
    pub port_turn: u64,
    /// Rejected for passing starboard to starboard in head-on (rule 14).
    pub starboard_passing: u64,
    /// Rejected for crossing ahead of a stand-on vessel (rule 15).
    pub crossing_ahead: u64,
    /// Rejected for a stand-on course change (rule 17(a)(i)).
    pub stand_on_course_change: u64,
    /// Rejected for a stand-on speed change (rule 17(a)(i)).
    pub stand_on_speed_change: u64,
    /// Rejected for a port turn for a vessel on the port side (rule 17(c)).
    pub port_turn_for_port_vessel: u64,
    /// Rejected for a give-way alteration too small to be apparent (rules 8(b), 16).
    pub insufficient_alteration: u64,
    /// Rejected for holding course at risk within the give-way action range (rules 8(a), 16).
    #[serde(default)]
    pub late_action: u64,
    /// Rejected for easing back from the alteration before the target is past (rule 8(d)).
    #[serde(default)]
    pub alteration_not_held: u64,
}

impl RejectionCounts {
    /// Counts one rejection.
    pub fn record(&mut self, cause: RejectionCause) {
        *self.slot(cause) += 1;
    }

    fn slot(&mut self, cause: RejectionCause) -> &mut u64 {
        match cause {
            RejectionCause::VelocityObstacle => &mut self.velocity_obstacle,
            RejectionCause::Clearance => &mut self.clearance,
            RejectionCause::ClearanceAhead => &mut self.clearance_ahead,
            RejectionCause::Colregs(ManeuverViolation::PortTurn) => &mut self.port_turn,
            RejectionCause::Colregs(ManeuverViolation::StarboardPassing) => {
                &mut self.starboard_passing
            }
            RejectionCause::Colregs(ManeuverViolation::CrossingAhead) => &mut self.crossing_ahead,
            RejectionCause::Colregs(ManeuverViolation::StandOnCourseChange) => {
                &mut self.stand_on_course_change
            }
            RejectionCause::Colregs(ManeuverViolation::StandOnSpeedChange) => {
                &mut self.stand_on_speed_change
            }
            RejectionCause::Colregs(ManeuverViolation::PortTurnForPortVessel) => {
                &mut self.port_turn_for_port_vessel
            }
            RejectionCause::Colregs(ManeuverViolation::InsufficientAlteration) => {
                &mut self.insufficient_alteration
            }
            RejectionCause::Colregs(ManeuverViolation::LateAction) => &mut self.late_action,
            RejectionCause::Colregs(ManeuverViolation::AlterationNotHeld) => {
                &mut self.alteration_not_held
            }
        }
    }

    /// Adds every count of `other`.
    pub fn add(&mut self, other: &RejectionCounts) {
        for (cause, count) in other.by_cause() {
            *self.slot(cause) += count;
        }
    }

    /// Every cause with its count, in a fixed order.
    #[must_use]
    pub fn by_cause(&self) -> [(RejectionCause, u64); 12] {
        [
            (RejectionCause::VelocityObstacle, self.velocity_obstacle),
            (RejectionCause::Clearance, self.clearance),
            (RejectionCause::ClearanceAhead, self.clearance_ahead),
            (
                RejectionCause::Colregs(ManeuverViolation::PortTurn),
                self.port_turn,
            ),
            (
                RejectionCause::Colregs(ManeuverViolation::StarboardPassing),
                self.starboard_passing,
            ),
            (
                RejectionCause::Colregs(ManeuverViolation::CrossingAhead),
                self.crossing_ahead,
            ),
            (
                RejectionCause::Colregs(ManeuverViolation::StandOnCourseChange),
                self.stand_on_course_change,
            ),
            (
                RejectionCause::Colregs(ManeuverViolation::StandOnSpeedChange),
                self.stand_on_speed_change,
            ),
            (
                RejectionCause::Colregs(ManeuverViolation::PortTurnForPortVessel),
                self.port_turn_for_port_vessel,
            ),
            (
                RejectionCause::Colregs(ManeuverViolation::InsufficientAlteration),
                self.insufficient_alteration,
            ),
            (
                RejectionCause::Colregs(ManeuverViolation::LateAction),
                self.late_action,
            ),
            (
                RejectionCause::Colregs(ManeuverViolation::AlterationNotHeld),
                self.alteration_not_held,
            ),
        ]
    }

    /// All rejections.
    #[must_use]
    pub fn total(&self) -> u64 {
        self.by_cause().iter().map(|(_, count)| count).sum()
    }

    /// The cause that rejected most samples, if any sample was rejected.
    #[must_use]
    pub fn dominant_cause(&self) -> Option<RejectionCause> {
        self.by_cause()
            .into_iter()
            .filter(|(_, count)| *count > 0)
            .max_by_key(|(_, count)| *count)
            .map(|(cause, _)| cause)
    }

    /// The dominant cause as text ("nothing" when no sample was rejected).
    #[must_use]
    pub fn dominant_cause_text(&self) -> String {
        match self.dominant_cause() {
            Some(cause) => {
                let count = self
                    .by_cause()
                    .into_iter()
                    .find(|(c, _)| *c == cause)
                    .map_or(0, |(_, n)| n);
                format!("{} ({count} of {})", cause.description(), self.total())
            }
            None => "nothing (no sample was rejected; the node or sample budget ran out)".into(),
        }
    }
}

/// What the search did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct PlanStatistics {
    /// Nodes in the tree that produced the plan (or in all trees, on failure).
    pub nodes: u64,
    /// Samples drawn, accepted or not, over all restarts.
    pub samples: u64,
    /// Rejected samples by cause, over all restarts.
    pub rejections: RejectionCounts,
    /// Times the tree was grown again from the root.
    pub restarts: u64,
    /// Branches that reached the goal but could not be simplified into legs
    /// ownship can sail at its rate of turn (each led to a restart).
    #[serde(default)]
    pub unsailable_branches: u64,
    /// Wall-clock time spent, seconds (not part of the deterministic output).
    pub elapsed_s: f64,
}

/// A safe path from ownship's position to its goal.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Plan {
    /// From the start (first) to the goal (last): where each leg ends.
    pub waypoints: Vec<Waypoint>,
    /// The legs ownship sails, one between each pair of waypoints: a turn
    /// (an arc at its rate of turn, or instantaneous) then a straight run.
    pub legs: Vec<Leg>,
    /// The predicted state of every target at each waypoint's time:
    /// `target_states[waypoint][target]`.
    pub target_states: Vec<Vec<VesselState>>,
    /// The encounters in force at each waypoint: `encounters[waypoint][target]`.
    pub encounters: Vec<Vec<Option<EncounterLatch>>>,
    /// Statistics of the search.
    pub statistics: PlanStatistics,
}

impl Plan {
    /// Path length, metres.
    #[must_use]
    pub fn length_m(&self) -> f64 {
        self.waypoints
            .windows(2)
            .map(|pair| pair[0].position_m.distance(pair[1].position_m))
            .sum()
    }

    /// Time from the first to the last waypoint, seconds.
    #[must_use]
    pub fn duration_s(&self) -> f64 {
        match (self.waypoints.first(), self.waypoints.last()) {
            (Some(first), Some(last)) => last.time_s - first.time_s,
            _ => 0.0,
        }
    }

    /// Ownship's planned pose at `time_s`, along the legs as sailed (arcs
    /// included); clamped to the plan's span. `None` for an empty plan.
    #[must_use]
    pub fn pose_at(&self, time_s: f64) -> Option<Pose> {
        let first = self.waypoints.first()?;
        let Some(first_leg) = self.legs.first() else {
            return Some(Pose {
                position_m: first.position_m,
                course_rad: first.course_rad,
            });
        };
        if time_s <= first.time_s {
            return Some(first_leg.pose_at(0.0));
        }
        // Waypoint k + 1 ends leg k.
        let index = self.waypoints[1..]
            .partition_point(|waypoint| waypoint.time_s < time_s)
            .min(self.legs.len() - 1);
        let leg_start_s = self.waypoints[index].time_s;
        let mut pose = self.legs[index].pose_at(time_s - leg_start_s);
        if index + 1 == self.legs.len()
            && time_s >= self.duration_s() + first.time_s
            && let Some(last) = self.waypoints.last()
        {
            // Exactly on the plan's end, whatever the rounding of the legs.
            pose.position_m = last.position_m;
        }
        Some(pose)
    }

    /// Ownship's planned speed at `time_s`, m/s, along the legs' speed
    /// profiles (before the plan, its start speed; after it, its last leg's
    /// settled speed). `None` for a plan without legs.
    #[must_use]
    pub fn speed_at(&self, time_s: f64) -> Option<f64> {
        let first_leg = self.legs.first()?;
        let first = self.waypoints.first()?;
        if time_s <= first.time_s {
            return Some(first_leg.start_speed_mps());
        }
        let index = self.waypoints[1..]
            .partition_point(|waypoint| waypoint.time_s < time_s)
            .min(self.legs.len() - 1);
        let leg_start_s = self.waypoints.get(index)?.time_s;
        Some(self.legs[index].speed_at(time_s - leg_start_s))
    }

    /// Ownship's planned position and course at `time_s` (clamped to the
    /// plan's span): [`pose_at`](Self::pose_at) as a pair.
    #[must_use]
    pub fn position_at(&self, time_s: f64) -> Option<(DVec2, f64)> {
        self.pose_at(time_s)
            .map(|pose| (pose.position_m, pose.course_rad))
    }

    /// For each target, every distinct encounter the plan latches with it
    /// along its path, in the order they arise (empty for a target it never
    /// meets). A closed loop compares them with the encounters it observes.
    #[must_use]
    pub fn anticipated_encounters(&self) -> Vec<Vec<EncounterLatch>> {
        let targets = self.encounters.first().map_or(0, Vec::len);
        let mut anticipated: Vec<Vec<EncounterLatch>> = vec![Vec::new(); targets];
        for row in &self.encounters {
            for (seen, latch) in anticipated.iter_mut().zip(row) {
                if let Some(latch) = latch
                    && !seen.contains(latch)
                {
                    seen.push(*latch);
                }
            }
        }
        anticipated
    }
}
