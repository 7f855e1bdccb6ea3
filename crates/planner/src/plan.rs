//! What the planner returns: waypoints with times, the predicted targets along
//! them, and statistics of the search.

use crate::constraint::ConstraintViolation;
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

/// Why a sample was not added to the tree: the one list of the validity
/// check's verdicts, from which every count, report and message is derived
/// ([`RejectionCause::ALL`], [`RejectionCounts`]).
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
    /// The move breaks a user constraint (land, a no-go area, a lane:
    /// [`Constraint`](crate::constraint::Constraint)).
    Constraint(ConstraintViolation),
}

/// How many causes [`RejectionCause::ALL`] lists.
const CAUSES: usize = 3 + ManeuverViolation::ALL.len() + ConstraintViolation::ALL.len();

impl RejectionCause {
    /// Every cause, in a fixed order: the safety checks, the COLREGs
    /// duties ([`ManeuverViolation::ALL`]), then the user constraints
    /// ([`ConstraintViolation::ALL`]).
    pub const ALL: [RejectionCause; CAUSES] = {
        let mut all = [RejectionCause::VelocityObstacle; CAUSES];
        all[1] = RejectionCause::Clearance;
        all[2] = RejectionCause::ClearanceAhead;
        let mut index = 0;
        while index < ManeuverViolation::ALL.len() {
            all[3 + index] = RejectionCause::Colregs(ManeuverViolation::ALL[index]);
            index += 1;
        }
        let mut index = 0;
        while index < ConstraintViolation::ALL.len() {
            all[3 + ManeuverViolation::ALL.len() + index] =
                RejectionCause::Constraint(ConstraintViolation::ALL[index]);
            index += 1;
        }
        all
    };

    /// Its place in [`ALL`](Self::ALL).
    fn index(self) -> usize {
        match self {
            RejectionCause::VelocityObstacle => 0,
            RejectionCause::Clearance => 1,
            RejectionCause::ClearanceAhead => 2,
            RejectionCause::Colregs(violation) => {
                3 + ManeuverViolation::ALL
                    .iter()
                    .position(|candidate| *candidate == violation)
                    .unwrap_or_default()
            }
            RejectionCause::Constraint(violation) => {
                3 + ManeuverViolation::ALL.len()
                    + ConstraintViolation::ALL
                        .iter()
                        .position(|candidate| *candidate == violation)
                        .unwrap_or_default()
            }
        }
    }

    /// Its name in files (`report.json`'s and the plan output's
    /// `rejections`, batch rows): snake case, the rule's name for a COLREGs
    /// duty, the constraint's for a constraint.
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            RejectionCause::VelocityObstacle => "velocity_obstacle",
            RejectionCause::Clearance => "clearance",
            RejectionCause::ClearanceAhead => "clearance_ahead",
            RejectionCause::Colregs(violation) => match violation {
                ManeuverViolation::PortTurn => "port_turn",
                ManeuverViolation::StarboardPassing => "starboard_passing",
                ManeuverViolation::CrossingAhead => "crossing_ahead",
                ManeuverViolation::StandOnCourseChange => "stand_on_course_change",
                ManeuverViolation::StandOnSpeedChange => "stand_on_speed_change",
                ManeuverViolation::PortTurnForPortVessel => "port_turn_for_port_vessel",
                ManeuverViolation::InsufficientAlteration => "insufficient_alteration",
                ManeuverViolation::LateAction => "late_action",
                ManeuverViolation::AlterationNotHeld => "alteration_not_held",
                ManeuverViolation::PortTurnTowardVessel => "port_turn_toward_vessel",
            },
            RejectionCause::Constraint(violation) => violation.key(),
        }
    }

    /// The cause whose [`key`](Self::key) is `key`.
    #[must_use]
    pub fn from_key(key: &str) -> Option<RejectionCause> {
        RejectionCause::ALL
            .into_iter()
            .find(|cause| cause.key() == key)
    }

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
            RejectionCause::Constraint(violation) => format!("constraint: {violation}"),
        }
    }
}

/// Rejected samples, counted by cause ([`RejectionCause::ALL`]). In files
/// it is an object with one count per cause, named by
/// [`RejectionCause::key`]; a cause missing when read counts 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RejectionCounts {
    counts: [u64; CAUSES],
}

impl Default for RejectionCounts {
    fn default() -> Self {
        Self {
            counts: [0; CAUSES],
        }
    }
}

impl RejectionCounts {
    /// Counts one rejection.
    pub fn record(&mut self, cause: RejectionCause) {
        self.counts[cause.index()] += 1;
    }

    /// The rejections counted for `cause`.
    #[must_use]
    pub fn get(&self, cause: RejectionCause) -> u64 {
        self.counts[cause.index()]
    }

    /// Sets the count of `cause`.
    pub fn set(&mut self, cause: RejectionCause, count: u64) {
        self.counts[cause.index()] = count;
    }

    /// Adds every count of `other`.
    pub fn add(&mut self, other: &RejectionCounts) {
        for (mine, theirs) in self.counts.iter_mut().zip(other.counts) {
            *mine += theirs;
        }
    }

    /// Every cause with its count, in the order of [`RejectionCause::ALL`].
    #[must_use]
    pub fn by_cause(&self) -> [(RejectionCause, u64); CAUSES] {
        let mut all = [(RejectionCause::VelocityObstacle, 0); CAUSES];
        for ((slot, cause), count) in all.iter_mut().zip(RejectionCause::ALL).zip(self.counts) {
            *slot = (cause, count);
        }
        all
    }

    /// All rejections.
    #[must_use]
    pub fn total(&self) -> u64 {
        self.counts.iter().sum()
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
            Some(cause) => format!(
                "{} ({} of {})",
                cause.description(),
                self.get(cause),
                self.total()
            ),
            None => "nothing (no sample was rejected; the node or sample budget ran out)".into(),
        }
    }
}

impl Serialize for RejectionCounts {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = serializer.serialize_map(Some(CAUSES))?;
        for (cause, count) in self.by_cause() {
            map.serialize_entry(cause.key(), &count)?;
        }
        map.end()
    }
}

impl<'de> Deserialize<'de> for RejectionCounts {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Counts;
        impl<'de> serde::de::Visitor<'de> for Counts {
            type Value = RejectionCounts;
            fn expecting(&self, formatter: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                formatter.write_str("a count per rejection cause")
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(
                self,
                mut map: A,
            ) -> Result<RejectionCounts, A::Error> {
                let mut counts = RejectionCounts::default();
                while let Some(key) = map.next_key::<String>()? {
                    let Some(cause) = RejectionCause::from_key(&key) else {
                        return Err(serde::de::Error::unknown_field(&key, &[]));
                    };
                    counts.counts[cause.index()] = map.next_value()?;
                }
                Ok(counts)
            }
        }
        deserializer.deserialize_map(Counts)
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
    /// Which search found the plan (`none` on failure).
    #[serde(default)]
    pub source: PlanSource,
}

/// Which search of the planner found a plan: the manoeuvre search from the
/// root ([`ROOT_LADDER`](crate::vorrt::ROOT_LADDER), by the shape of its
/// rung), or the tree.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PlanSource {
    /// No plan (a failed call), or statistics read from a file written
    /// before the field existed.
    #[default]
    None,
    /// The search from the root: one alteration held, then the goal.
    OneAlteration,
    /// The search from the root: two alterations (the course kept, then one
    /// action; or an alteration held, then the course before it resumed).
    TwoAlterations,
    /// The tree's branch to the goal, simplified into sailable legs.
    Tree,
}

impl PlanSource {
    /// Its name in files: `none`, `one_alteration`, `two_alterations`, `tree`.
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            PlanSource::None => "none",
            PlanSource::OneAlteration => "one_alteration",
            PlanSource::TwoAlterations => "two_alterations",
            PlanSource::Tree => "tree",
        }
    }
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

    /// Ownship's planned speed at each waypoint, m/s: at the end of the leg
    /// that ends there ([`speed_at`](Self::speed_at)), the start speed at the
    /// first. A plan without legs (ownship already on its goal) has 0 at its
    /// one waypoint.
    #[must_use]
    pub fn waypoint_speeds_mps(&self) -> Vec<f64> {
        self.waypoints
            .iter()
            .map(|waypoint| self.speed_at(waypoint.time_s).unwrap_or(0.0))
            .collect()
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_cause_has_its_own_place_and_key() {
        for (index, cause) in RejectionCause::ALL.into_iter().enumerate() {
            assert_eq!(cause.index(), index, "{cause:?}");
            assert_eq!(RejectionCause::from_key(cause.key()), Some(cause));
        }
        let keys: std::collections::HashSet<_> = RejectionCause::ALL
            .iter()
            .map(|cause| cause.key())
            .collect();
        assert_eq!(keys.len(), RejectionCause::ALL.len());
    }

    #[test]
    fn counts_are_written_by_key_and_read_back() {
        let mut counts = RejectionCounts::default();
        for (times, cause) in RejectionCause::ALL.into_iter().enumerate() {
            for _ in 0..times {
                counts.record(cause);
            }
        }
        let json = serde_json::to_string(&counts).unwrap();
        assert!(
            json.starts_with(r#"{"velocity_obstacle":0,"clearance":1,"#),
            "{json}"
        );
        assert!(json.contains(r#""late_action":"#) && json.contains(r#""land":"#));
        let back: RejectionCounts = serde_json::from_str(&json).unwrap();
        assert_eq!(back, counts);
        assert_eq!(counts.dominant_cause(), RejectionCause::ALL.last().copied());
        // A cause missing when read counts 0; an unknown one is an error.
        let partial: RejectionCounts = serde_json::from_str(r#"{"clearance":4}"#).unwrap();
        assert_eq!(partial.get(RejectionCause::Clearance), 4);
        assert_eq!(partial.total(), 4);
        assert!(serde_json::from_str::<RejectionCounts>(r#"{"sea_monster":1}"#).is_err());
    }

    #[test]
    fn added_counts_sum_per_cause() {
        let mut a = RejectionCounts::default();
        a.record(RejectionCause::Clearance);
        let mut b = RejectionCounts::default();
        b.record(RejectionCause::Clearance);
        b.record(RejectionCause::Constraint(ConstraintViolation::Land));
        a.add(&b);
        assert_eq!(a.get(RejectionCause::Clearance), 2);
        assert_eq!(a.total(), 3);
    }
}
