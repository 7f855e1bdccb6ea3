#![doc = include_str!("../README.md")]
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

// What the public signatures take, so that this crate alone is enough.
pub use glam::{self, DVec2};
pub use vorrt_colregs as colregs;
pub use vorrt_colregs::VesselState;
pub use vorrt_geometry as geometry;
