//! The scenario data types: what a scenario file holds, field for field.
//!
//! Field names carry their units (`_nm`, `_m`, `_kn`, `_deg`, `_s`); positions
//! are `(east, north)` tuples. See `docs/scenario-format.md` for the format.

use crate::planner_settings::PlannerSettings;
use serde::{Deserialize, Serialize};

/// One encounter to plan or simulate: ownship, its goal, the targets, and
/// optional planner, simulation and traffic-lane settings.
///
/// Build one by hand, or load one with [`Scenario::from_ron_str`],
/// [`Scenario::load`] or [`load_dir`](crate::load_dir); loading validates
/// (see [`Scenario::validate`]).
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scenario {
    /// Short name, e.g. `"crossing"`. Must not be empty.
    pub name: String,
    /// What the scenario is and where its numbers come from.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    /// The vessel being planned for. It must move (speed > 0) and have a goal.
    pub ownship: VesselSpec,
    /// The other vessels, at most [`MAX_TARGETS`](crate::MAX_TARGETS).
    #[serde(default)]
    pub targets: Vec<VesselSpec>,
    /// Planner settings in file units; absent fields take
    /// `PlannerConfig::default()`.
    #[serde(default, skip_serializing_if = "PlannerSettings::is_empty")]
    pub planner: PlannerSettings,
    /// Closed-loop simulation settings.
    #[serde(default, skip_serializing_if = "SimulationSettings::is_default")]
    pub simulation: SimulationSettings,
    /// Traffic lanes of a traffic separation scheme (rule 10), if any.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub lanes: Vec<Lane>,
    /// The planner seed to use when none is given elsewhere.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// Where the scenario came from: the file path given to
    /// [`Scenario::load`] or the source name given to
    /// [`Scenario::from_ron_str`]; used in error messages. Not part of the
    /// file, not written out, and ignored by `==`.
    #[serde(skip)]
    pub source: String,
}

impl PartialEq for Scenario {
    fn eq(&self, other: &Self) -> bool {
        // Destructured so that a new field cannot be forgotten here.
        let Scenario {
            name,
            description,
            ownship,
            targets,
            planner,
            simulation,
            lanes,
            seed,
            source: _,
        } = self;
        *name == other.name
            && *description == other.description
            && *ownship == other.ownship
            && *targets == other.targets
            && *planner == other.planner
            && *simulation == other.simulation
            && *lanes == other.lanes
            && *seed == other.seed
    }
}

/// One vessel as a scenario file gives it (written `Vessel(...)` in RON).
///
/// Exactly one of `start_nm` / `start_m` must be given, and at most one of
/// `goal_nm` / `goal_m` (ownship needs one). Positions are `(east, north)`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename = "Vessel")]
pub struct VesselSpec {
    /// Unique, non-empty name (`"ownship"`, `"TS1"`, ...).
    pub name: String,
    /// Start position `(east, north)`, nautical miles.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start_nm: Option<(f64, f64)>,
    /// Start position `(east, north)`, metres.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start_m: Option<(f64, f64)>,
    /// Course over ground, degrees clockwise from north. Loading normalises it
    /// into `[0, 360)`. A goal-bound target steers for its goal at once, so its
    /// course is then replaced by the bearing of its goal.
    pub course_deg: f64,
    /// Speed over ground, knots. Ownship: > 0. Targets: >= 0 (0 = at anchor).
    pub speed_kn: f64,
    /// Length overall, metres (> 0): the radius of the vessel's disc.
    pub length_m: f64,
    /// Goal `(east, north)`, nautical miles.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub goal_nm: Option<(f64, f64)>,
    /// Goal `(east, north)`, metres.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub goal_m: Option<(f64, f64)>,
    /// How a target moves. Ignored for ownship (which the planner steers).
    #[serde(default, skip_serializing_if = "Behaviour::is_default")]
    pub behaviour: Behaviour,
}

impl VesselSpec {
    /// A vessel starting at `start_nm` (east, north; nautical miles) with no
    /// goal and the default behaviour.
    #[must_use]
    pub fn new(
        name: impl Into<String>,
        start_nm: (f64, f64),
        course_deg: f64,
        speed_kn: f64,
        length_m: f64,
    ) -> Self {
        Self {
            name: name.into(),
            start_nm: Some(start_nm),
            start_m: None,
            course_deg,
            speed_kn,
            length_m,
            goal_nm: None,
            goal_m: None,
            behaviour: Behaviour::default(),
        }
    }

    /// The same vessel bound for `goal_nm` (east, north; nautical miles).
    #[must_use]
    pub fn with_goal_nm(mut self, goal_nm: (f64, f64)) -> Self {
        self.goal_nm = Some(goal_nm);
        self.goal_m = None;
        self
    }

    /// The same vessel with another behaviour.
    #[must_use]
    pub fn with_behaviour(mut self, behaviour: Behaviour) -> Self {
        self.behaviour = behaviour;
        self
    }
}

/// How a target vessel moves during a scenario.
///
/// Written as a bare variant name in RON: `behaviour: ConstantVelocity`.
/// More variants (rule-following, noisy and manoeuvring targets) are expected;
/// match with a wildcard arm outside this crate.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub enum Behaviour {
    /// The paper's assumption (notes, erratum 9): steer straight for the goal
    /// at constant speed and stop there. Without a goal: hold course and speed.
    #[default]
    ConstantToGoal,
    /// Hold course and speed for ever, ignoring any goal.
    ConstantVelocity,
}

impl Behaviour {
    /// Whether this is the default, [`Behaviour::ConstantToGoal`].
    #[must_use]
    pub fn is_default(&self) -> bool {
        *self == Self::default()
    }
}

/// Settings of a closed-loop simulation of the scenario (written
/// `Simulation(...)` in RON; every field optional).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default, rename = "Simulation")]
pub struct SimulationSettings {
    /// Simulation time step, seconds. Default 5.0.
    pub time_step_s: f64,
    /// Longest simulated time, seconds. Default (`None`): three times the time
    /// ownship needs to sail straight to its goal (see
    /// [`Scenario::max_duration_s`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_duration_s: Option<f64>,
    /// Ownship replans when a target is this far from where the plan
    /// predicted it, metres. Default 50.0.
    pub replan_deviation_m: f64,
}

/// Default simulation time step, seconds.
pub const DEFAULT_TIME_STEP_S: f64 = 5.0;
/// Default replanning threshold, metres.
pub const DEFAULT_REPLAN_DEVIATION_M: f64 = 50.0;
/// Default longest simulated time, as a multiple of ownship's straight-line
/// time to its goal.
pub const DEFAULT_DURATION_FACTOR: f64 = 3.0;

impl Default for SimulationSettings {
    fn default() -> Self {
        Self {
            time_step_s: DEFAULT_TIME_STEP_S,
            max_duration_s: None,
            replan_deviation_m: DEFAULT_REPLAN_DEVIATION_M,
        }
    }
}

impl SimulationSettings {
    /// Whether every field has its default.
    #[must_use]
    pub fn is_default(&self) -> bool {
        *self == Self::default()
    }
}

/// One traffic lane of a traffic separation scheme: a strip `width_nm` wide
/// centred on the line from `from_nm` to `to_nm`, traffic flowing from `from`
/// toward `to`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Lane {
    /// Name, e.g. `"westbound"`.
    pub name: String,
    /// Upstream end of the centre line `(east, north)`, nautical miles.
    pub from_nm: (f64, f64),
    /// Downstream end of the centre line `(east, north)`, nautical miles.
    pub to_nm: (f64, f64),
    /// Full width of the lane, nautical miles (> 0).
    pub width_nm: f64,
}
