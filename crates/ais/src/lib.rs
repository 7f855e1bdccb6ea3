//! # vorrt-ais
//!
//! AIS logs into geographic vorrt scenarios. Takes the log's text (no file
//! I/O): NMEA 0183 `!AIVDM`/`!AIVDO` sentences, message types 1, 2, 3, 5, 18,
//! 19 and 24, multi-sentence messages reassembled, NMEA 4.0 tag blocks
//! (`\c:UNIXTIME,...*hh\`) for the times. The payloads are decoded by the
//! `ais` crate; this crate adds the tag blocks, the tracks, the state
//! estimates (dead reckoning to the chosen time) and the scenario.
//! Malformed lines, bad checksums and unknown types are skipped and counted.
//! See `docs/real-data.md`.
//!
//! | module | what it gives |
//! |---|---|
//! | [`tag_block`] | [`split_tag_block`]: the NMEA 4.0 tag block of a line and its `c:` time |
//! | [`log`] | [`read_log`]: a log into [`AisLog`] (per-MMSI [`VesselTrack`]s, [`LineCounts`]) |
//! | [`import`] | [`estimate`] (dead reckoning) and [`build_scenario`] |
//! | [`error`] | [`AisError`] |
//!
//! ```
//! use vorrt_ais::read_log;
//! let log = read_log("\\c:1700000000*5F\\!AIVDM,1,1,,A,13u?etgP2;0n9lPPwT`1U1B1P000,0*4F\ngarbage\n");
//! assert_eq!(log.counts.messages, 1);
//! assert_eq!(log.counts.malformed, 1);
//! let track = &log.vessels[&265547250];
//! assert_eq!(track.reports[0].time_unix_s, Some(1_700_000_000.0));
//! ```
#![forbid(missing_docs)]

pub mod error;
pub mod import;
pub mod log;
pub mod tag_block;

pub use error::AisError;
pub use import::{
    DEFAULT_LENGTH_M, DEFAULT_RANGE_NM, Import, ImportOptions, StateEstimate, build_scenario,
    estimate,
};
pub use log::{AisLog, LineCounts, PositionReport, SUPPORTED_TYPES, VesselTrack, read_log};
pub use tag_block::{TagBlock, TagBlockError, split_tag_block};
