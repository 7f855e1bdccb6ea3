//! # vorrt-jfs
//!
//! Joint forward simulation (JFS) for the VORRT planner: how targets are
//! predicted to move, and the joint step that moves ownship toward a sampled
//! point while every target moves for the same time. Data in, data out; no I/O.
//!
//! ## Catalogue
//!
//! | module | what it gives |
//! |---|---|
//! | [`prediction`] | [`TargetState`]: constant course and speed, steer for a goal and stop there, or hold the course first and then steer for the goal; closed-form [`TargetState::predict`] and [`LinearTrack`] |
//! | [`motion`] | [`MotionModel`]: ownship's motion from a pose toward a point as a [`Leg`] (turn, then straight, with a speed profile: [`Leg::from_speed`]); [`InstantTurn`] (the paper's step) and [`RateLimitedTurn`] (arcs at a bounded rate of turn) |
//! | [`joint_state`] | [`JointState`] (every vessel at one time), [`step_ownship`] and [`JointState::step_toward`]: the paper's JFS step |
//! | [`error`] | [`JfsError`] |
#![forbid(missing_docs)]

pub mod error;
pub mod joint_state;
pub mod motion;
pub mod prediction;

pub use error::JfsError;
pub use joint_state::{JointState, OwnshipStep, step_ownship};
pub use motion::{
    InstantTurn, Leg, MotionModel, OwnshipModel, Piece, Pose, RateLimitedTurn, SpeedChange,
    default_speed_change_mps2, default_turn_rate_rad_s,
};
pub use prediction::{LinearTrack, TURN_TIMING_UNCERTAINTY_S, TargetState};
