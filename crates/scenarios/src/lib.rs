//! # vorrt-scenarios
//!
//! Scenario files for the VORRT planner: the RON format (units in the field
//! names, positions as `(east, north)`), loading with errors that name the file,
//! line and field, validation, and conversion to the planner's SI types. The
//! bundled fixtures (the paper's reference encounters and the 22 Imazu
//! problems) live in `fixtures/` at the workspace root; the format is
//! described in `docs/scenario-format.md`.
//!
//! ## Catalogue
//!
//! | module | what it gives |
//! |---|---|
//! | [`scenario`] | [`Scenario`], [`VesselSpec`], [`Behaviour`], [`SimulationSettings`], [`Lane`] |
//! | [`planner_settings`] | [`PlannerSettings`]: the `planner` section, mapped onto [`vorrt_planner::PlannerConfig`] |
//! | [`validate`] | [`Scenario::validate`], [`Scenario::planner_config`] and the format's limits ([`MAX_TARGETS`]) |
//! | [`geo`] | geographic scenarios: [`LocalFrame`] (latitude/longitude to the local frame), coordinate and start-time checks |
//! | [`convert`] | [`Scenario::planning_problem`] and the other conversions to SI |
//! | [`io`] | [`Scenario::from_ron_str`], [`Scenario::load`], [`Scenario::to_ron_string`], [`load_dir`] |
//! | [`simulation`] | [`simulate`]: the closed loop — ownship follows its plan and replans when it stops being valid; every trajectory recorded. [`ClosedLoop`]: the same run as a value, stepped one time step at a time; [`TargetMotion`]: how a target moves ([`RecordedMotion`]: along a recording) |
//! | [`generator`] | seeded Monte Carlo scenarios: [`OpenSeaSpec`] (targets on near-collision courses in a chosen mix of encounter types) and [`TssSpec`] (crossing a traffic lane at a chosen density), one random stream per scenario index |
//! | [`batch`] | Monte Carlo batches: [`run_batch`] in parallel (rayon), one [`BatchRow`] per scenario, [`BatchSummary`] (rates, per-rule compliance, percentiles), CSV rows, deterministic [`Shard`]s and merging |
//! | [`evaluation`] | [`evaluate`]: goal reached, minimum distance per target, COLREGs compliance with violations named, per-rule scores, path overhead |
//! | [`error`] | [`ScenarioError`] |
//!
//! ## Example
//!
//! ```
//! use vorrt_scenarios::Scenario;
//! let text = r#"
//! Scenario(
//!     name: "crossing",
//!     ownship: Vessel(name: "ownship", start_nm: (0.0, -3.0), course_deg: 0.0,
//!                     speed_kn: 12.0, length_m: 100.0, goal_nm: (0.0, 3.0)),
//!     targets: [
//!         Vessel(name: "TS1", start_nm: (3.0, 0.0), course_deg: -90.0, speed_kn: 12.0,
//!                length_m: 150.0, goal_nm: (-4.0, 0.0)),
//!     ],
//! )"#;
//! let scenario = Scenario::from_ron_str(text, "example.ron").unwrap();
//! assert_eq!(scenario.targets[0].course_deg, 270.0); // normalised
//! let problem = scenario.planning_problem();
//! assert_eq!(problem.ownship.position_m.y, -3.0 * 1852.0);
//! ```
#![forbid(missing_docs)]

pub mod batch;
pub mod convert;
pub mod error;
pub mod evaluation;
pub mod generator;
pub mod geo;
pub mod io;
pub mod planner_settings;
pub mod scenario;
pub mod simulation;
pub mod validate;

pub use batch::{BatchError, BatchItem, BatchRow, BatchSummary, Shard, run_batch};
pub use error::ScenarioError;
pub use evaluation::{
    Evaluation, TargetEvaluation, evaluate, evaluate_with, observed_judgement, scoring_for,
};
pub use generator::{
    EncounterMix, GeneratorError, GeneratorSpec, OpenSeaSpec, TargetBehaviour, TssDirection,
    TssSpec,
};
pub use geo::{LocalFrame, MAX_GEO_EXTENT_NM, ProjectedPositions};
pub use io::{SCENARIO_EXTENSION, bundled_fixtures_dir, load_dir};
pub use planner_settings::PlannerSettings;
pub use scenario::{
    Behaviour, COLREGS_TURN_DEG, DEFAULT_DURATION_FACTOR, DEFAULT_REPLAN_DEVIATION_M,
    DEFAULT_TIME_STEP_S, Lane, NOISE_TIME_CONSTANT_S, Scenario, SimulationSettings, VesselSpec,
};
pub use simulation::{
    ClosedLoop, Decision, LoopState, PlanCheck, PlanEvent, PlanTrigger, RecordedMotion,
    RecordedMotionError, RunStatus, SimulationRecord, StepOutcome, TargetMotion, TimedState,
    simulate, simulate_with,
};
pub use validate::{MAX_EXTENT_NM, MAX_LENGTH_M, MAX_SIMULATION_STEPS, MAX_SPEED_KN, MAX_TARGETS};
