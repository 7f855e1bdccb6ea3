//! What a closed-loop run leaves behind: every vessel's state at every step,
//! every planner call and every plan kept ([`SimulationRecord`]).

use serde::{Deserialize, Serialize};
use vorrt_colregs::VesselState;
use vorrt_planner::{Compliance, PlanStatistics, PlannerConfig, Waypoint};

/// Why ownship planned.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum PlanTrigger {
    /// The first plan, at the start.
    Initial,
    /// A target was off the plan's prediction by more than the threshold.
    TargetOffPrediction {
        /// Index of the target.
        target: usize,
    },
    /// An encounter arose that the plan did not foresee (none, or another type).
    NewEncounter {
        /// Index of the target.
        target: usize,
    },
    /// A target's predicted return to its route (decision 25 in
    /// `docs/architecture.md`) appeared, vanished or moved by more than
    /// [`RETURN_MOVED_S`](crate::simulation::RETURN_MOVED_S) since the plan's prediction.
    PredictionChanged {
        /// Index of the target.
        target: usize,
    },
    /// The previous attempt failed; trying again.
    Retry,
    /// Every encounter in force since the plan was made has been released
    /// (the vessels are past and clear, `colregs::has_passed`) while the
    /// plan still holds an alteration off the route: ownship asks whether
    /// it may return sooner (rule 8(d): the action is held until the other
    /// vessel is past and clear, not longer). A plan found is put in force
    /// only where it reaches the goal sooner (decision 52).
    PastAndClear,
    /// The plan in force would reach the goal only after the run ends:
    /// ownship asks for one that arrives sooner, put in force only where it
    /// does (decision 63).
    LateArrival,
}

/// One call of the planner during a run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PlanEvent {
    /// Simulation time of the call, seconds.
    pub time_s: f64,
    /// Why ownship planned.
    pub trigger: PlanTrigger,
    /// The planner's seed for this call.
    pub seed: u64,
    /// Whether a plan came back.
    pub succeeded: bool,
    /// The planner's error, when it failed.
    pub error: Option<String>,
    /// Search statistics (on failure, those the error carried where it had them).
    pub statistics: PlanStatistics,
    /// The plan's waypoints (empty on failure).
    pub waypoints: Vec<Waypoint>,
    /// Ownship's planned speed at each waypoint, m/s
    /// (`Plan::waypoint_speeds_mps`; empty on failure, and in records
    /// written before the field existed).
    #[serde(default)]
    pub speeds_mps: Vec<f64>,
    /// On failure, the evasive course ownship turned to, degrees (`None` when
    /// it kept its previous plan: still valid, or held as the manoeuvre under
    /// way, decision 56).
    pub evasive_course_deg: Option<f64>,
    /// On failure, the speed the evasive manoeuvre settles at, m/s: the
    /// service speed, half of it or 0 (stop); `None` as for the course.
    #[serde(default)]
    pub evasive_speed_mps: Option<f64>,
    /// The COLREGs duties the plan that came back keeps: `full`, or a graded
    /// fallback (`directions`: a departure from rules 8 and 16; `safety_only`:
    /// from the steering rules, rules 2(b) and 17(b)). An evasive manoeuvre
    /// (failure) is `safety_only` too.
    #[serde(default)]
    pub compliance: Compliance,
    /// Random samples drawn by every search of this call, over every level
    /// of the graded fallback tried (`statistics` holds only the search
    /// whose plan came back): the call's work, independent of the machine.
    #[serde(default)]
    pub samples_drawn: u64,
}

impl PlanEvent {
    /// Whether ownship departed from the rules after this call (a fallback
    /// plan or the evasive manoeuvre), as rules 2(b) and 17(b) allow to avoid
    /// immediate danger.
    #[must_use]
    pub fn departs_from_rules(&self) -> bool {
        self.compliance != Compliance::Full
    }
}

/// A replanning trigger after which the plan in force passed the planner's
/// validity check again and was kept.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PlanCheck {
    /// Simulation time of the check, seconds.
    pub time_s: f64,
    /// What triggered it.
    pub trigger: PlanTrigger,
    /// Wall-clock time spent searching for a plan that was not put in
    /// force (a sooner plan asked for, or a retry while a fallback plan is
    /// sailed), seconds: 0 where only the validity check ran.
    #[serde(default)]
    pub search_time_s: f64,
}

/// Everything that happened in one closed-loop run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SimulationRecord {
    /// The scenario's name.
    pub scenario: String,
    /// The seed the run was made with.
    pub seed: u64,
    /// The time step, seconds.
    pub time_step_s: f64,
    /// The time of every recorded step, seconds.
    pub times_s: Vec<f64>,
    /// Ownship at every step.
    pub ownship: Vec<VesselState>,
    /// Name of every target.
    pub target_names: Vec<String>,
    /// Every target at every step: `targets[target][step]`.
    pub targets: Vec<Vec<VesselState>>,
    /// Every planner call.
    pub plans: Vec<PlanEvent>,
    /// Every time a replanning trigger fired but the plan in force still
    /// passed the planner's validity check, so ownship kept it.
    #[serde(default)]
    pub plans_kept: Vec<PlanCheck>,
    /// The planner configuration the run was made with (`d_th` and the rules
    /// that judge it come from here).
    pub config: PlannerConfig,
    /// Ownship's largest rate of turn, radians per second (`None`:
    /// instantaneous turns, the paper's model).
    #[serde(default)]
    pub max_turn_rate_rad_s: Option<f64>,
    /// How each track was observed, ownship first, then the targets in
    /// order: the fixes' jitter and the reported navigational status, for
    /// tracks recorded at sea (`vorrt judge`). A closed-loop run's tracks
    /// are exact ([`TrackObservation::exact`](vorrt_colregs::observed::TrackObservation::exact)),
    /// but a recorded target's, whose jitter is estimated; empty: every
    /// track's estimated.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub observations: Vec<vorrt_colregs::observed::TrackObservation>,
    /// Whether ownship reached its goal.
    pub reached_goal: bool,
    /// When it did, seconds.
    pub arrival_time_s: Option<f64>,
}

impl SimulationRecord {
    /// Every replanning trigger of the run with its time, whether it led to
    /// a planner call or the plan in force was kept, in time order.
    #[must_use]
    pub fn triggers(&self) -> Vec<(f64, PlanTrigger)> {
        let mut all: Vec<(f64, PlanTrigger)> = self
            .plans
            .iter()
            .map(|event| (event.time_s, event.trigger))
            .chain(
                self.plans_kept
                    .iter()
                    .map(|kept| (kept.time_s, kept.trigger)),
            )
            .collect();
        all.sort_by(|a, b| a.0.total_cmp(&b.0));
        all
    }

    /// Planner calls that returned a plan.
    #[must_use]
    pub fn plans_made(&self) -> usize {
        self.plans.iter().filter(|event| event.succeeded).count()
    }

    /// Planner calls after the first.
    #[must_use]
    pub fn replans(&self) -> usize {
        self.plans.len().saturating_sub(1)
    }

    /// Planner calls after which ownship departed from the rules (a graded
    /// fallback plan or the evasive manoeuvre).
    #[must_use]
    pub fn rule_departures(&self) -> usize {
        self.plans
            .iter()
            .filter(|event| event.departs_from_rules())
            .count()
    }

    /// Planner calls that failed.
    #[must_use]
    pub fn failed_plans(&self) -> usize {
        self.plans.iter().filter(|event| !event.succeeded).count()
    }

    /// Wall-clock time spent planning, seconds: every planner call, and
    /// the searches whose plan was not put in force ([`PlanCheck::search_time_s`]).
    #[must_use]
    pub fn planning_time_s(&self) -> f64 {
        self.plans
            .iter()
            .map(|event| event.statistics.elapsed_s)
            .chain(self.plans_kept.iter().map(|kept| kept.search_time_s))
            .sum()
    }

    /// Length of ownship's sailed track, metres.
    #[must_use]
    pub fn path_length_m(&self) -> f64 {
        self.ownship
            .windows(2)
            .map(|pair| pair[0].position_m.distance(pair[1].position_m))
            .sum()
    }
}

/// The seed of the `call`-th planner call of a run seeded with `seed`: a
/// fixed mix, so that every call draws a different but reproducible stream.
#[must_use]
pub fn call_seed(seed: u64, call: usize) -> u64 {
    seed ^ (call as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
}
