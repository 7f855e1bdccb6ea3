//! What can go wrong when turning an AIS log into a scenario.

use thiserror::Error;

/// Why no scenario could be made from a log. Every message names the log.
#[derive(Debug, Error)]
pub enum AisError {
    /// The ownship MMSI does not occur in the log.
    #[error("{log}: MMSI {mmsi} (--ownship) is not in the log; vessels seen: {seen}")]
    UnknownMmsi {
        /// The log's name.
        log: String,
        /// The MMSI asked for.
        mmsi: u32,
        /// The MMSIs seen, for the message (at most ten).
        seen: String,
    },
    /// Ownship is in the log but has no usable position report (at or before
    /// the chosen time).
    #[error("{log}: MMSI {mmsi} (--ownship) has no position report{when}")]
    NoOwnshipPosition {
        /// The log's name.
        log: String,
        /// Ownship's MMSI.
        mmsi: u32,
        /// `" at or before <time>"` when a time was chosen, else empty.
        when: String,
    },
    /// An option is out of range (the range, the goal, the time).
    #[error("{option} {problem}")]
    Option {
        /// The option, e.g. `--range-nm`.
        option: &'static str,
        /// What is wrong with it.
        problem: String,
    },
    /// The scenario made from the log breaks a rule of the format (for
    /// example a target inside the planner clearance of ownship, or ownship
    /// at rest).
    #[error(transparent)]
    Scenario(#[from] vorrt_scenarios::ScenarioError),
}
