//! Every constant of the observed judgement, in one struct.

use super::noise::NoiseParameters;
use crate::compliance::ScoringParameters;
use crate::error::ColregsError;
use crate::parameters::RuleParameters;
use serde::{Deserialize, Serialize};

/// The constants of the observed judgement: the observation window, the
/// vessel's rate-of-turn limit, the rule geometry and the evaluators'
/// thresholds. Every default and its source is in the table of the [module
/// documentation](super), "Parameters".
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ObservedParameters {
    /// The window over which course and speed over ground are observed,
    /// seconds. Default 60 s: what another vessel's radar or AIS shows of a
    /// turn over the last minute (Woerner 2019; the NTNU evaluator).
    pub window_s: f64,
    /// Ownship's largest rate of turn, radians per second: a sailed rate
    /// above it is a [`TrackFinding::TurnRateExceeded`](super::TrackFinding).
    /// Default `None` (no limit judged).
    pub max_turn_rate_rad_s: Option<f64>,
    /// The rule geometry: MTD, sectors, the 2° detectable change, the 30°
    /// readily apparent alteration, the stand-on tolerances (15°, 1 m/s)
    /// and action range (2 nm).
    pub rules: RuleParameters,
    /// The evaluators' thresholds: clearance `d_th`, the 5° action detection,
    /// the 20 % speed drop, the 2 nm early-action range, the 60 s grace
    /// time, the halved speed, the penalty weights.
    pub scoring: ScoringParameters,
    /// How the observation window and the turn thresholds rise above a
    /// track's jitter (decision 31).
    pub noise: NoiseParameters,
}

impl Default for ObservedParameters {
    fn default() -> Self {
        Self {
            window_s: 60.0,
            max_turn_rate_rad_s: None,
            rules: RuleParameters::default(),
            scoring: ScoringParameters::default(),
            noise: NoiseParameters::default(),
        }
    }
}

impl ObservedParameters {
    /// Checks every field: the window positive and finite, the rate-of-turn
    /// limit (if any) positive and finite, then the rule and scoring
    /// parameters ([`RuleParameters::validate`],
    /// [`ScoringParameters::validate`]).
    ///
    /// # Errors
    /// [`ColregsError::InvalidParameter`] naming the first field that is wrong.
    ///
    /// ```
    /// use vorrt_colregs::observed::ObservedParameters;
    /// assert!(ObservedParameters::default().validate().is_ok());
    /// let bad = ObservedParameters { window_s: 0.0, ..ObservedParameters::default() };
    /// assert!(bad.validate().unwrap_err().to_string().contains("window_s"));
    /// ```
    pub fn validate(&self) -> Result<(), ColregsError> {
        if !(self.window_s.is_finite() && self.window_s > 0.0) {
            return Err(ColregsError::InvalidParameter {
                field: "window_s",
                value: self.window_s,
                expected: "a finite number of seconds greater than 0",
            });
        }
        if let Some(rate) = self.max_turn_rate_rad_s
            && !(rate.is_finite() && rate > 0.0)
        {
            return Err(ColregsError::InvalidParameter {
                field: "max_turn_rate_rad_s",
                value: rate,
                expected: "a finite rate greater than 0",
            });
        }
        if let Err((field, value, expected)) = self.noise.check() {
            return Err(ColregsError::InvalidParameter {
                field,
                value,
                expected,
            });
        }
        self.rules.validate()?;
        self.scoring.validate()
    }
}
