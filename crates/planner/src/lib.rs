//! # vorrt-planner
//!
//! The VORRT-COLREGs planner of Dubey and Louis: a rapidly-exploring random
//! tree whose every node holds the joint state of all vessels, grown by a joint
//! forward simulation and pruned by velocity-obstacle, closest-point-of-approach
//! and COLREGs checks. The paper's errata are applied as
//! `docs/architecture.md` records.
//!
//! ## Catalogue
//!
//! | module | what it gives |
//! |---|---|
//! | [`config`] | [`PlannerConfig`]: `d'`, `d_th`, goal bias, node and sample budgets, turn bound, deadline; validated |
//! | [`constraint`] | [`Constraint`]: the seam for land, no-go areas and lanes, kept by every check of ownship's motion and by the sampler; [`NoConstraint`] |
//! | [`problem`] | [`PlanningProblem`]: ownship, goal, targets and the encounters in force |
//! | [`vorrt`] | [`Planner`]: Algorithms 1-2, seeded, restartable, bounded |
//! | [`safety`] | [`SafetyChecker`](safety::SafetyChecker): Algorithm 3 (VO, segment CPA, CPA ahead, COLREGs) |
//! | [`validity`] | [`MotionValidator`]: the one validity check of a [`Leg`](vorrt_jfs::Leg), used by tree growth, simplification and a closed loop; [`EncounterState`] carried along a branch |
//! | [`simplify`] | [`simplify`](simplify::simplify): a branch into the fewest sailable legs the same validator accepts; [`hold_then_alter`](simplify::hold_then_alter): the manoeuvres of two alterations (keep the course, then act; alter, then resume) |
//! | [`sampler`] | [`Sampler`](sampler::Sampler): ChaCha8 goal-biased sampling |
//! | [`evasion`] | [`evasive_course`]: the course that keeps farthest from every target, for when no safe path is found |
//! | [`plan`] | [`Plan`], [`Waypoint`], [`PlanStatistics`], [`RejectionCause`] |
//! | [`error`] | [`PlannerError`] |
#![forbid(missing_docs)]

// What the planner's signatures take and return, so that a user needs only
// this crate in `[dependencies]`.
pub use glam;
pub use vorrt_colregs as colregs;
pub use vorrt_geometry as geometry;
pub use vorrt_jfs as jfs;

pub mod config;
pub mod constraint;
pub mod error;
pub mod evasion;
pub mod plan;
pub mod problem;
mod replay;
pub mod safety;
pub mod sampler;
pub mod simplify;
mod tree;
pub mod validity;
pub mod vorrt;

pub use config::{Compliance, NearestIndex, PlannerConfig, SearchEffort, Turning};
pub use constraint::{Constraint, ConstraintViolation, NoConstraint, Segment};
pub use error::PlannerError;
pub use evasion::{
    EVASION_HOLD_MARGIN_M, EvasionSearch, EvasiveManeuver, evasive_course, evasive_leg,
    evasive_leg_constrained, evasive_leg_holding,
};
pub use plan::{Plan, PlanStatistics, RejectionCause, RejectionCounts, Waypoint};
pub use problem::PlanningProblem;
pub use validity::{EncounterState, MotionValidator, check_legs, check_legs_with};
pub use vorrt::Planner;
