//! The recording an assessment reads: samples of both vessels in time, and the
//! first encounter latched in them.

use crate::latch::{EncounterLatch, update_latch_judged};
use crate::parameters::RuleParameters;
use crate::rules::steady_course_rad;
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

/// The first encounter latched in a recording: runs [`update_latch_judged`]
/// over the samples in order, with ownship's steady course at each
/// ([`steady_courses_rad`]), and returns the first latch it makes.
#[must_use]
pub fn first_latch(samples: &[EncounterSample], rules: &RuleParameters) -> Option<EncounterLatch> {
    samples
        .iter()
        .zip(steady_courses_rad(samples))
        .find_map(|(sample, steady_course_rad)| {
            update_latch_judged(
                None,
                &sample.own,
                steady_course_rad,
                &sample.target,
                sample.time_s,
                rules,
            )
        })
}

/// At each sample, the course ownship held steadily before any turn under
/// way ([`steady_course_rad`] looking back 0 s: the samples' courses are
/// observed over ground, or steered by a vessel whose turn shows at once),
/// the course a new encounter is judged against.
#[must_use]
pub fn steady_courses_rad(samples: &[EncounterSample]) -> Vec<f64> {
    let times_s: Vec<f64> = samples.iter().map(|s| s.time_s).collect();
    let courses_rad: Vec<f64> = samples.iter().map(|s| s.own.course_rad).collect();
    (1..=samples.len())
        .map(|count| {
            steady_course_rad(&times_s[..count], &courses_rad[..count], 0.0)
                .unwrap_or(courses_rad[count - 1])
        })
        .collect()
}
