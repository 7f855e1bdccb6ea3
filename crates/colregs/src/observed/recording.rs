//! What the observed judgement reads: the recorded tracks of ownship and
//! every target on one time base.

use super::status::NavigationalStatus;
use super::undecided::Unreported;
use crate::error::ColregsError;
use glam::DVec2;
use serde::{Deserialize, Serialize};

/// One vessel's recorded track.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RecordedTrack {
    /// The vessel's name, for findings and errors.
    pub name: String,
    /// Length overall, metres.
    pub length_m: f64,
    /// Position at every sample time, metres (x east, y north).
    pub positions_m: Vec<DVec2>,
    /// Recorded course (heading) at every sample time, radians clockwise from
    /// north, where the recording gives it; `None` where it gives positions
    /// only (the path quality then reads the observed course over ground).
    pub courses_rad: Option<Vec<f64>>,
    /// What is known of how the track was observed: the fixes' jitter and
    /// the vessel's navigational status (default: nothing known, the
    /// jitter estimated from `positions_m`).
    #[serde(default)]
    pub observation: TrackObservation,
}

/// What a recording knows of how one track was observed, beyond its
/// positions.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(default)]
pub struct TrackObservation {
    /// The position jitter of the vessel's fixes (1 σ), metres, estimated
    /// from the fixes themselves before any resampling
    /// ([`position_noise_m`](super::position_noise_m)); `None`: estimated
    /// from `positions_m` (0 for a closed-loop run's exact tracks).
    pub position_noise_m: Option<f64>,
    /// The navigational status the vessel reported (AIS); `None`: not
    /// reported, a vessel under way. At anchor, moored or aground the
    /// vessel is never latched as an encounter; if she nevertheless made way
    /// (`median_speed_mps`), her encounter is undecided (decision 49).
    pub status: Option<NavigationalStatus>,
    /// The vessel's median speed over ground between consecutive fixes, m/s,
    /// from the fixes themselves (`None`: from `positions_m`); it tells
    /// whether a reported rest is believed
    /// ([`rest_contradicted`](super::rest_contradicted)).
    pub median_speed_mps: Option<f64>,
    /// The stretches of the clock over which the vessel's positions are not
    /// its reports (dead-reckoned, or bridged across a long gap); empty for a
    /// closed-loop run. An encounter whose closest approach, or most of
    /// whose in-force window, lies in one is undecided
    /// ([`not_reported`](super::not_reported); decision 49).
    pub unreported: Vec<Unreported>,
}

impl TrackObservation {
    /// A track of exact positions, as a closed-loop run records them: no
    /// jitter in its fixes (`position_noise_m` 0, which the estimate from
    /// such a track's positions gives too but for 1e-12 m of rounding,
    /// at more cost), under way, every position a report.
    ///
    /// ```
    /// use vorrt_colregs::observed::TrackObservation;
    /// let exact = TrackObservation::exact();
    /// assert_eq!(exact.position_noise_m, Some(0.0));
    /// assert!(exact.unreported.is_empty());
    /// ```
    #[must_use]
    pub fn exact() -> Self {
        Self {
            position_noise_m: Some(0.0),
            ..Self::default()
        }
    }
}

/// A recorded run: sample times, ownship's track and every target's, each
/// track with one entry per sample time.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Recording {
    /// Sample times, seconds, strictly increasing.
    pub times_s: Vec<f64>,
    /// Ownship's track.
    pub ownship: RecordedTrack,
    /// The targets' tracks.
    pub targets: Vec<RecordedTrack>,
}

impl Recording {
    /// Checks the recording: times finite and strictly increasing; every
    /// track as long as the times, its length positive and finite, its
    /// positions and courses finite.
    ///
    /// # Errors
    /// [`ColregsError::InvalidRecording`] naming the vessel, the field and the
    /// sample that is wrong.
    ///
    /// ```
    /// use vorrt_colregs::observed::{Recording, RecordedTrack};
    /// use glam::DVec2;
    /// let track = |n: usize| RecordedTrack {
    ///     name: "ownship".into(), length_m: 100.0,
    ///     positions_m: vec![DVec2::ZERO; n], courses_rad: None,
    ///     observation: Default::default(),
    /// };
    /// let good = Recording { times_s: vec![0.0, 5.0], ownship: track(2), targets: vec![] };
    /// assert!(good.validate().is_ok());
    /// let short = Recording { times_s: vec![0.0, 5.0], ownship: track(1), targets: vec![] };
    /// assert!(short.validate().unwrap_err().to_string().contains("ownship"));
    /// ```
    pub fn validate(&self) -> Result<(), ColregsError> {
        let invalid = |what: String| Err(ColregsError::InvalidRecording { what });
        if let Some(index) = self.times_s.iter().position(|t| !t.is_finite()) {
            return invalid(format!("times_s[{index}] is not a finite number"));
        }
        for (index, pair) in self.times_s.windows(2).enumerate() {
            if pair[1] <= pair[0] {
                return invalid(format!(
                    "times_s[{}] = {} does not follow times_s[{index}] = {}: times must be strictly increasing",
                    index + 1,
                    pair[1],
                    pair[0]
                ));
            }
        }
        let samples = self.times_s.len();
        for track in std::iter::once(&self.ownship).chain(&self.targets) {
            let name = &track.name;
            if !(track.length_m.is_finite() && track.length_m > 0.0) {
                return invalid(format!(
                    "vessel `{name}`: length_m is {}, expected a finite length greater than 0",
                    track.length_m
                ));
            }
            if track.positions_m.len() != samples {
                return invalid(format!(
                    "vessel `{name}`: {} positions for {samples} sample times",
                    track.positions_m.len()
                ));
            }
            if let Some(index) = track.positions_m.iter().position(|p| !p.is_finite()) {
                return invalid(format!(
                    "vessel `{name}`: positions_m[{index}] is not finite"
                ));
            }
            if let Some(noise_m) = track.observation.position_noise_m
                && !(noise_m.is_finite() && noise_m >= 0.0)
            {
                return invalid(format!(
                    "vessel `{name}`: observation.position_noise_m is {noise_m}, expected a finite distance of at least 0"
                ));
            }
            if let Some(speed) = track.observation.median_speed_mps
                && !(speed.is_finite() && speed >= 0.0)
            {
                return invalid(format!(
                    "vessel `{name}`: observation.median_speed_mps is {speed}, expected a finite speed of at least 0"
                ));
            }
            if let Some(stretch) = track
                .observation
                .unreported
                .iter()
                .find(|s| !(s.from_s.is_finite() && s.to_s.is_finite() && s.from_s <= s.to_s))
            {
                return invalid(format!(
                    "vessel `{name}`: observation.unreported stretch from {} s to {} s, expected finite times in order",
                    stretch.from_s, stretch.to_s
                ));
            }
            if let Some(courses) = &track.courses_rad {
                if courses.len() != samples {
                    return invalid(format!(
                        "vessel `{name}`: {} courses for {samples} sample times",
                        courses.len()
                    ));
                }
                if let Some(index) = courses.iter().position(|c| !c.is_finite()) {
                    return invalid(format!(
                        "vessel `{name}`: courses_rad[{index}] is not finite"
                    ));
                }
            }
        }
        Ok(())
    }
}
