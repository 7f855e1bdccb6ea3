//! # vorrt
//!
//! The facade of the vorrt workspace: re-exports its crates.
#![forbid(missing_docs)]

pub use vorrt_colregs as colregs;
pub use vorrt_geometry as geometry;
pub use vorrt_jfs as jfs;
pub use vorrt_planner as planner;
pub use vorrt_scenarios as scenarios;
