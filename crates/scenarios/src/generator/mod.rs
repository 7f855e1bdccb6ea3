//! Seeded scenario generators for Monte Carlo campaigns: open-sea encounters
//! with a chosen mix of encounter types, the same among islands and a coast
//! (coastal), and crossings of a traffic separation scheme at a chosen
//! traffic density.
//!
//! Every draw comes from a `ChaCha8` stream of its own per scenario index
//! (seed = the batch seed, stream = the index), so scenario `k` of a batch is
//! the same however the batch is sharded, and a behaviour's own draws (when a
//! [`Behaviour::SuddenTurn`](crate::Behaviour::SuddenTurn) target turns) come from a second stream, so the
//! same seed and index give the same geometry under every behaviour: the
//! behaviours can be compared scenario by scenario.
//!
//! ```
//! use vorrt_scenarios::generator::{OpenSeaSpec, open_sea};
//! let spec = OpenSeaSpec::with_targets(4);
//! let scenario = open_sea(&spec, 7, 0).unwrap();
//! assert_eq!(scenario.targets.len(), 4);
//! assert_eq!(scenario, open_sea(&spec, 7, 0).unwrap()); // deterministic
//! ```
//!
//! ## Files
//!
//! | file | what it gives |
//! |---|---|
//! | `mod.rs` | [`GeneratorSpec`], [`GeneratorError`], the limits and the planner settings of a generated route |
//! | `random.rs` | [`scenario_stream`], [`run_seed`]: the seeded streams, uniform draws, rounding |
//! | `behaviour.rs` | [`TargetBehaviour`]: how the generated targets move |
//! | `open_sea.rs` | [`OpenSeaSpec`], [`EncounterMix`], [`open_sea`] |
//! | `coastal.rs` | [`CoastalSpec`], [`coastal`]: open-sea encounters among islands and a coast |
//! | `tss.rs` | [`TssSpec`], [`TssDirection`], [`tss`] |
//! | `verification.rs` | [`encounter_at_risk`] and the check that a drawn target keeps the generator's promises |

mod behaviour;
mod coastal;
mod open_sea;
mod random;
#[cfg(test)]
mod tests;
mod tss;
mod verification;

pub use behaviour::{DEFAULT_COURSE_SIGMA_DEG, DEFAULT_SPEED_SIGMA_KN, TargetBehaviour};
pub use coastal::{CoastalSpec, coastal};
pub use open_sea::{EncounterMix, OpenSeaSpec, open_sea};
pub use random::{run_seed, scenario_stream};
pub use tss::{TssDirection, TssSpec, tss};
pub use verification::encounter_at_risk;

use crate::error::ScenarioError;
use crate::planner_settings::PlannerSettings;
use crate::scenario::Scenario;
use serde::{Deserialize, Serialize};
use thiserror::Error;
use vorrt_colregs::Encounter;

/// The most targets an open-sea scenario may be generated with.
pub const MAX_GENERATED_TARGETS: usize = 256;

/// Ownship's length in every generated scenario, metres.
pub const OWNSHIP_LENGTH_M: f64 = 100.0;

/// Why a scenario could not be generated.
#[derive(Debug, Error)]
pub enum GeneratorError {
    /// The specification is unusable (no targets, weights all zero, a range
    /// the wrong way round, ...).
    #[error("invalid generator specification: {0}")]
    InvalidSpec(String),
    /// No placement of a target gave the intended encounter within the
    /// allowed number of draws.
    #[error(
        "scenario {index}: could not place target {target} as a {encounter} encounter in {attempts} draws"
    )]
    Placement {
        /// The scenario index.
        index: u64,
        /// The target's position in the scenario (from 0).
        target: usize,
        /// The intended encounter type.
        encounter: Encounter,
        /// How many draws were tried.
        attempts: usize,
    },
    /// No draw of land kept every start and goal clear of it.
    #[error(
        "scenario {index}: no draw of land kept ownship's start and goal and the targets' tracks clear of land in {attempts} draws"
    )]
    LandPlacement {
        /// The scenario index.
        index: u64,
        /// How many draws of land were tried.
        attempts: usize,
    },
    /// The generated scenario failed validation (a bug in the generator).
    #[error("generated scenario is invalid: {0}")]
    Invalid(#[from] ScenarioError),
}

/// What to generate: an open-sea encounter, a coastal one or a TSS crossing.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum GeneratorSpec {
    /// [`open_sea`].
    OpenSea(OpenSeaSpec),
    /// [`coastal`].
    Coastal(CoastalSpec),
    /// [`tss`].
    Tss(TssSpec),
}

impl GeneratorSpec {
    /// Scenario `index` of the batch seeded with `seed`.
    ///
    /// # Errors
    /// As [`open_sea`], [`coastal`] and [`tss`].
    pub fn generate(&self, seed: u64, index: u64) -> Result<Scenario, GeneratorError> {
        match self {
            Self::OpenSea(spec) => open_sea(spec, seed, index),
            Self::Coastal(spec) => coastal(spec, seed, index),
            Self::Tss(spec) => tss(spec, seed, index),
        }
    }
}

/// Checks that `(low, high)` is an ordered range of finite numbers within
/// `[min, max]`; the error names the field.
fn check_range(
    name: &str,
    (low, high): (f64, f64),
    min: f64,
    max: f64,
) -> Result<(), GeneratorError> {
    if low.is_finite() && high.is_finite() && min <= low && low <= high && high <= max {
        Ok(())
    } else {
        Err(GeneratorError::InvalidSpec(format!(
            "{name} is ({low}, {high}), expected low <= high within [{min}, {max}]"
        )))
    }
}

/// `nodes_per_phase` for a route of `route_m`: five nodes per step of the
/// default 100 m.
#[expect(
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    reason = "a positive route over a positive step, rounded up; far below `usize::MAX`"
)]
fn nodes_for_route(route_m: f64) -> usize {
    let step_m = vorrt_planner::PlannerConfig::default().step_m;
    ((5.0 * route_m / step_m).ceil() as usize).max(200)
}

/// The planner settings of a generated route of `route_m`: enough nodes
/// and samples for its length, and the clearance if given.
fn planner_for_route(route_m: f64, clearance_m: Option<f64>) -> PlannerSettings {
    let nodes = nodes_for_route(route_m);
    let default_samples = vorrt_planner::PlannerConfig::default().samples_per_phase;
    PlannerSettings {
        clearance_m,
        nodes_per_phase: Some(nodes),
        samples_per_phase: (4 * nodes > default_samples).then_some(4 * nodes),
        ..PlannerSettings::default()
    }
}
