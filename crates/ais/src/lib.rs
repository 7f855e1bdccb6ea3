#![doc = include_str!("../README.md")]
#![forbid(missing_docs)]

pub mod encode;
pub mod error;
pub mod import;
pub mod log;
pub mod replay;
pub mod tag_block;

pub use encode::{EncodeError, simulation_log};
pub use error::AisError;
pub use import::{
    DEFAULT_LENGTH_M, DEFAULT_RANGE_NM, Import, ImportOptions, StateEstimate, build_scenario,
    estimate,
};
pub use log::{AisLog, LineCounts, PositionReport, SUPPORTED_TYPES, VesselTrack, read_log};
pub use replay::{Replay, ReplayOptions, build_replay, service_speed_kn};
pub use tag_block::{TagBlock, TagBlockError, split_tag_block};

// The scenario an import builds, so that this crate alone is enough.
pub use vorrt_scenarios as scenarios;
pub use vorrt_scenarios::Scenario;
