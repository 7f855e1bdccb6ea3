//! # vorrt-planner
//!
//! The VORRT-COLREGs planner of Dubey and Louis: a rapidly-exploring random
//! tree whose every node holds the joint state of all vessels, grown by a joint
//! forward simulation and pruned by velocity-obstacle, closest-point-of-approach
//! and COLREGs checks. The paper's errata are applied as
//! `vorrt-paper-notes.md` prescribes (see `docs/architecture.md`).
//!
//! ## Catalogue
//!
//! | module | what it gives |
//! |---|---|
//! | [`config`] | [`PlannerConfig`]: `d'`, `d_th`, goal bias, node and sample budgets, turn bound, deadline; validated |
//! | [`problem`] | [`PlanningProblem`]: ownship, goal, targets and the encounters in force |
//! | [`vorrt`] | [`Planner`]: Algorithms 1-2, seeded, restartable, bounded |
//! | [`safety`] | [`SafetyChecker`](safety::SafetyChecker): Algorithm 3 (VO, segment CPA, CPA ahead, COLREGs) |
//! | [`tree`] | [`Tree`](tree::Tree): the node arena and nearest-node search (linear or R*-tree) |
//! | [`sampler`] | [`Sampler`](sampler::Sampler): ChaCha8 goal-biased sampling |
//! | [`evasion`] | [`evasive_course`]: the course that keeps farthest from every target, for when no safe path is found |
//! | [`plan`] | [`Plan`], [`Waypoint`], [`PlanStatistics`], [`RejectionCause`] |
//! | [`error`] | [`PlannerError`] |
#![forbid(missing_docs)]

pub mod config;
pub mod error;
pub mod evasion;
pub mod plan;
pub mod problem;
pub mod safety;
pub mod sampler;
pub mod tree;
pub mod vorrt;

pub use config::{NearestIndex, PlannerConfig};
pub use error::PlannerError;
pub use evasion::{EvasiveManeuver, evasive_course};
pub use plan::{Plan, PlanStatistics, RejectionCause, RejectionCounts, Waypoint};
pub use problem::PlanningProblem;
pub use vorrt::Planner;
