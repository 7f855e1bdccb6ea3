//! Errors of the planner.

use crate::plan::PlanStatistics;
use std::fmt;
use thiserror::Error;
use vorrt_colregs::ColregsError;

/// A number as a person reads it in a message: plainly when it is of an
/// everyday size (`12.5`, `0.002`, `250000`), else in scientific notation
/// with four significant digits (`1.000e300`, `1.000e-300`), never as the
/// hundreds of digits `{}` gives for such values. A computed value of an
/// everyday size with more than six significant digits (a unit conversion's
/// `0.0019438444924406047`) is rounded to four (`0.001944`); one with six or
/// fewer, as a person types it, is shown as it is.
///
/// ```
/// use vorrt_planner::error::Readable;
/// assert_eq!(Readable(12.5).to_string(), "12.5");
/// assert_eq!(Readable(123.456).to_string(), "123.456");
/// assert_eq!(Readable(0.0019438444924406047).to_string(), "0.001944");
/// assert_eq!(Readable(30.000000001).to_string(), "30");
/// assert_eq!(Readable(1e300).to_string(), "1.000e300");
/// assert_eq!(Readable(-1e-300).to_string(), "-1.000e-300");
/// assert_eq!(Readable(f64::NAN).to_string(), "NaN");
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Readable(pub f64);

impl fmt::Display for Readable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let value = self.0;
        let size = value.abs();
        if !value.is_finite() || size == 0.0 {
            write!(f, "{value}")
        } else if (1e-3..1e7).contains(&size) {
            // The decimal exponent of the leading digit (-3 to 6 here), and
            // the decimals that leave `digits` significant digits.
            let exponent = (-3..=6)
                .rev()
                .find(|&exponent| size >= 10f64.powi(exponent))
                .unwrap_or(-3);
            let decimals = |digits: i32| usize::try_from(digits - 1 - exponent).unwrap_or(0);
            let six = format!("{value:.*}", decimals(6));
            if six.parse::<f64>() == Ok(value) {
                write!(f, "{value}")
            } else {
                let four = format!("{value:.*}", decimals(4));
                // 30.000000001 is "30.00" at four digits: the zeros say nothing.
                let trimmed = if four.contains('.') {
                    four.trim_end_matches('0').trim_end_matches('.')
                } else {
                    &four
                };
                f.write_str(trimmed)
            }
        } else {
            write!(f, "{value:.3e}")
        }
    }
}

/// What can stop the planner from returning a plan.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PlannerError {
    /// A [`PlannerConfig`](crate::PlannerConfig) field is out of range.
    #[error("planner setting `{field}` is {}, expected {expected}", Readable(*value))]
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
    /// Every phase of every restart accepted its whole node quota without
    /// reaching the goal: the node budget, not the traffic, is the cause
    /// (see [`PlannerConfig::for_route`](crate::PlannerConfig::for_route)).
    #[error(
        "no safe path found: the node budget is too small: every phase accepted its {nodes_per_phase} nodes without reaching the goal {route_m:.0} m away ({} samples, {} nodes, {} restarts); raise planner.nodes_per_phase or planner.nodes_per_route_step",
        statistics.samples, statistics.nodes, statistics.restarts
    )]
    NodeBudgetTooSmall {
        /// Accepted nodes per phase in the run that failed (after
        /// [`PlannerConfig::for_route`](crate::PlannerConfig::for_route)).
        nodes_per_phase: usize,
        /// The straight distance from start to goal, metres.
        route_m: f64,
        /// What the search did.
        statistics: Box<PlanStatistics>,
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

impl PlannerError {
    /// The search statistics of a failed search, if the error has them.
    #[must_use]
    pub fn statistics(&self) -> Option<&PlanStatistics> {
        match self {
            Self::NoSafePath { statistics }
            | Self::NodeBudgetTooSmall { statistics, .. }
            | Self::BudgetExhausted { statistics, .. } => Some(statistics),
            _ => None,
        }
    }

    /// Names the node budget as the cause of a
    /// [`NoSafePath`](Self::NoSafePath) when every phase of every restart
    /// accepted its whole node quota under `config` (the configuration the
    /// search ran with), for a route of `route_m` metres; any other error
    /// is returned as it is.
    #[must_use]
    pub fn blame_budget(self, config: &crate::PlannerConfig, route_m: f64) -> Self {
        let Self::NoSafePath { statistics } = self else {
            return self;
        };
        // Each tree holds its root and every node accepted in its two
        // phases: trees that are all full mean every phase ended on its node
        // quota, not on samples rejected by the traffic.
        let full_trees = (statistics.restarts + 1) * (2 * config.nodes_per_phase as u64 + 1);
        if statistics.nodes >= full_trees {
            Self::NodeBudgetTooSmall {
                nodes_per_phase: config.nodes_per_phase,
                route_m,
                statistics,
            }
        } else {
            Self::NoSafePath { statistics }
        }
    }
}
