//! The recording an assessment reads: samples of both vessels in time, and the
//! first encounter latched in them.

use crate::latch::{EncounterLatch, update_latch};
use crate::parameters::RuleParameters;
use crate::vessel::VesselState;
use serde::{Deserialize, Serialize};

/// One instant of a recorded encounter.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct EncounterSample {
    /// Time of the sample, seconds.
    pub time_s: f64,
    /// Ownship's state at that time.
    pub own: VesselState,
    /// The target's state at that time.
    pub target: VesselState,
}

impl EncounterSample {
    /// A sample from its parts.
    #[must_use]
    pub fn new(time_s: f64, own: VesselState, target: VesselState) -> Self {
        Self {
            time_s,
            own,
            target,
        }
    }

    /// Distance between ownship and the target, metres.
    #[must_use]
    pub fn range_m(&self) -> f64 {
        self.own.range_to(&self.target)
    }
}

/// The first encounter latched in a recording: runs [`update_latch`] over the
/// samples in order and returns the first latch it makes.
#[must_use]
pub fn first_latch(samples: &[EncounterSample], rules: &RuleParameters) -> Option<EncounterLatch> {
    samples
        .iter()
        .find_map(|sample| update_latch(None, &sample.own, &sample.target, sample.time_s, rules))
}
