#![doc = include_str!("../README.md")]
#![forbid(missing_docs)]

pub use glam;
pub use vorrt_colregs as colregs;
pub use vorrt_geometry as geometry;
pub use vorrt_jfs as jfs;
pub use vorrt_planner as planner;
pub use vorrt_scenarios as scenarios;
