//! Errors of the planner.

use crate::plan::PlanStatistics;
use thiserror::Error;
use vorrt_colregs::ColregsError;

/// What can stop the planner from returning a plan.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PlannerError {
    /// A [`PlannerConfig`](crate::PlannerConfig) field is out of range.
    #[error("planner setting `{field}` is {value}, expected {expected}")]
    InvalidConfig {
        /// The field's name.
        field: &'static str,
        /// The value given.
        value: f64,
        /// What the field accepts.
        expected: &'static str,
    },
    /// A COLREGs constant is out of range.
    #[error(transparent)]
    InvalidRules(#[from] ColregsError),
    /// The planning problem itself is malformed (NaN positions, zero speed, ...).
    #[error("invalid planning problem: {field} {problem}")]
    InvalidProblem {
        /// Which part of the problem, e.g. `ownship.speed_mps` or `targets[2].position_m`.
        field: String,
        /// What is wrong with it.
        problem: String,
    },
    /// Every phase of every restart ended without reaching the goal.
    #[error(
        "no safe path found after {} samples, {} nodes and {} restarts; most samples were rejected by: {}",
        statistics.samples, statistics.nodes, statistics.restarts, statistics.rejections.dominant_cause_text()
    )]
    NoSafePath {
        /// What the search did, including rejections by cause.
        statistics: Box<PlanStatistics>,
    },
    /// The wall-clock budget ran out before a safe path to the goal was found.
    #[error(
        "no safe path within the time budget of {budget_s} s ({} samples, {} nodes); most samples were rejected by: {}",
        statistics.samples, statistics.nodes, statistics.rejections.dominant_cause_text()
    )]
    BudgetExhausted {
        /// The budget, seconds.
        budget_s: f64,
        /// What the search did before the budget ran out.
        statistics: Box<PlanStatistics>,
    },
}
