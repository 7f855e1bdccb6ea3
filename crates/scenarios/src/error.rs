//! What can go wrong when reading a scenario.

use std::path::PathBuf;
use thiserror::Error;

/// Why a scenario could not be loaded.
///
/// Every variant names the file (or the source name given to
/// [`Scenario::from_ron_str`](crate::Scenario::from_ron_str)); a scenario that
/// parses but breaks a rule also names the field, in the file's own units and
/// with the vessel it belongs to, e.g. `targets[2] "TS3".speed_kn`.
#[derive(Debug, Error)]
pub enum ScenarioError {
    /// The file (or directory) could not be read.
    #[error("cannot read {}: {source}", path.display())]
    Io {
        /// The file or directory.
        path: PathBuf,
        /// What the operating system said.
        #[source]
        source: std::io::Error,
    },
    /// The text is not a scenario: a RON syntax error, an unknown or missing
    /// field, a misspelt variant, a value of the wrong type.
    #[error("{file}:{line}:{column}: {message}")]
    Syntax {
        /// The file or source name.
        file: String,
        /// Line of the error, counted from 1.
        line: usize,
        /// Column of the error, counted from 1.
        column: usize,
        /// What the parser found wrong.
        message: String,
    },
    /// The scenario parses but a value breaks a rule of the format
    /// (see `docs/scenario-format.md`, "Validation").
    #[error("{file}: {field} {problem}")]
    Invalid {
        /// The file or source name.
        file: String,
        /// The field, with its path in the file: `name`, `ownship.speed_kn`,
        /// `targets[2] "TS3".goal_nm`, `planner.step_m`, `lanes[0] "westbound".width_nm`.
        field: String,
        /// What is wrong with it.
        problem: String,
    },
}

impl ScenarioError {
    /// The field path of an [`Invalid`](Self::Invalid) error, else `None`.
    #[must_use]
    pub fn field(&self) -> Option<&str> {
        match self {
            Self::Invalid { field, .. } => Some(field),
            _ => None,
        }
    }
}
