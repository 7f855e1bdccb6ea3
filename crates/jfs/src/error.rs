//! Errors of the joint forward simulation.

use thiserror::Error;

/// What can go wrong in a joint forward step.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum JfsError {
    /// Ownship cannot move toward a point: its speed is zero or negative.
    #[error("ownship speed is {speed_mps} m/s; a forward step needs a speed greater than 0")]
    OwnshipNotMoving {
        /// The speed found.
        speed_mps: f64,
    },
    /// A step length that is not a finite positive number.
    #[error("step length is {step_m} m; expected a finite number greater than 0")]
    InvalidStep {
        /// The step length given.
        step_m: f64,
    },
    /// A point or state holds NaN or an infinity.
    #[error("{what} is not finite")]
    NotFinite {
        /// Which input.
        what: &'static str,
    },
}
