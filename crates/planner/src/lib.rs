#![doc = include_str!("../README.md")]
#![forbid(missing_docs)]

pub mod config;
pub mod constraint;
pub mod crossing;
pub mod error;
pub mod evasion;
pub mod land;
pub mod plan;
pub mod problem;
mod replay;
pub mod safety;
pub mod sampler;
pub mod scheme;
pub mod simplify;
mod tree;
pub mod validity;
pub mod vorrt;

pub use config::{Compliance, NearestIndex, PlannerConfig, SearchEffort, Turning};
pub use constraint::{Constraint, ConstraintViolation, NoConstraint, Segment};
pub use error::PlannerError;
pub use evasion::{
    EVASION_HOLD_MARGIN_M, EvasionSearch, EvasiveManeuver, evasive_course, evasive_leg,
    evasive_leg_constrained, evasive_leg_holding, holds_manoeuvre_in_force, legs_min_distance,
};
pub use land::{LandConstraint, LandError};
pub use plan::{Plan, PlanSource, PlanStatistics, RejectionCause, RejectionCounts, Waypoint};
pub use problem::PlanningProblem;
pub use validity::{EncounterState, MotionValidator, check_legs, check_legs_with};
pub use vorrt::Planner;

// What a planner user handles, so that this crate alone is enough: the
// problem's vessels and encounters, the motion and prediction types of its
// legs and targets, and the layers below as modules.
pub use glam::{self, DVec2};
pub use vorrt_colregs as colregs;
pub use vorrt_colregs::{Encounter, EncounterLatch, Role, RuleParameters, VesselState};
pub use vorrt_geometry as geometry;
pub use vorrt_jfs as jfs;
pub use vorrt_jfs::{
    InstantTurn, Leg, LinearTrack, MotionModel, Pose, RateLimitedTurn, TargetState,
};
