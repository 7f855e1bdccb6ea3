#![doc = include_str!("../README.md")]
#![forbid(missing_docs)]

pub mod area;
pub mod batch;
pub mod chart;
pub mod coastline;
pub mod convert;
pub mod error;
pub mod evaluation;
pub mod fixtures;
pub mod generator;
pub mod geo;
pub mod geojson_land;
pub mod io;
pub mod planner_settings;
pub mod recorded_tracks;
pub mod scenario;
pub mod scheme;
pub mod simulation;
pub mod validate;

pub use area::{Area, DEFAULT_LAND_CLEARANCE_M, MAX_LAND_CLEARANCE_M};
pub use batch::{BatchError, BatchItem, BatchRow, BatchSummary, Shard, run_batch};
pub use chart::{Chart, planning_constraint};
pub use error::ScenarioError;
pub use evaluation::{
    Evaluation, TargetEvaluation, evaluate, evaluate_with, observed_judgement, scoring_for,
};
pub use generator::{
    EncounterMix, GeneratorError, GeneratorSpec, OpenSeaSpec, TargetBehaviour, TssDirection,
    TssSpec,
};
pub use geo::{LocalFrame, MAX_GEO_EXTENT_NM, ProjectedPositions};
pub use io::{
    JSON_SCENARIO_EXTENSION, SCENARIO_EXTENSION, ScenarioFormat, bundled_fixtures_dir, load_dir,
};
pub use planner_settings::PlannerSettings;
pub use recorded_tracks::RecordedTracks;
pub use scenario::{
    Behaviour, COLREGS_TURN_DEG, DEFAULT_DURATION_FACTOR, DEFAULT_REPLAN_DEVIATION_M,
    DEFAULT_TIME_STEP_S, Lane, NOISE_TIME_CONSTANT_S, Scenario, SimulationSettings, VesselSpec,
};
pub use scheme::{Rule10Settings, SeparationZoneSpec, scenario_constraint};
pub use simulation::{
    COMMANDED_GOAL_TOLERANCE_M, ClosedLoop, CommandError, CommandedRun, Decision, LoopState,
    PlanCheck, PlanEvent, PlanTrigger, RecordedMotion, RecordedMotionError, RunStatus,
    SimulationRecord, StepOutcome, TargetMotion, TimedState, simulate, simulate_with,
};
pub use validate::{MAX_EXTENT_NM, MAX_LENGTH_M, MAX_SIMULATION_STEPS, MAX_SPEED_KN, MAX_TARGETS};

// The layers below, whose types the conversions and the closed loop return
// (`PlanningProblem`, `PlannerConfig`, `VesselState`, ...), so that this
// crate alone is enough.
pub use glam::{self, DVec2};
pub use vorrt_colregs as colregs;
pub use vorrt_geometry as geometry;
pub use vorrt_jfs as jfs;
pub use vorrt_planner as planner;
