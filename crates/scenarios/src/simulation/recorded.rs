//! A target that follows a recorded, timed track (an AIS log, another
//! simulator's output, a replay), behind the same seam as the scenario's
//! behaviours ([`TargetMotion`]). (A recording judged after the fact is
//! `vorrt_colregs::observed::RecordedTrack`; this one moves a target in a
//! closed loop.)

use super::target::TargetMotion;
use serde::{Deserialize, Serialize};
use thiserror::Error;
use vorrt_colregs::observed::TrackObservation;
use vorrt_colregs::{Encounter, RuleParameters, VesselState};
use vorrt_geometry::angle;
use vorrt_jfs::TargetState;

/// One state of a recorded track.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TimedState {
    /// When, seconds on the closed loop's clock (0 at the run's start).
    pub time_s: f64,
    /// The vessel then: position, course and speed over ground, length.
    pub vessel: VesselState,
}

/// Why a recording cannot move a target.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RecordedMotionError {
    /// The recording has no state.
    #[error("a recorded track needs at least one state")]
    Empty,
    /// A state has a number that is not finite, a negative speed or a
    /// length that is not positive.
    #[error(
        "recorded state {index}: every number must be finite, the speed at least 0 and the length above 0"
    )]
    InvalidState {
        /// Index of the state in the recording.
        index: usize,
    },
    /// A state's time is not after the one before it.
    #[error("recorded state {index}: its time must be after the time of the state before it")]
    NotIncreasing {
        /// Index of the state in the recording.
        index: usize,
    },
}

/// A target that is where a recording says it is, at every step.
///
/// Between two recorded states its position, speed and length are
/// interpolated linearly in time, its course along the smaller turn; before
/// the first state and after the last it is dead-reckoned from that state
/// (its course and speed held). Ownship's planner is given only what the
/// target has reported by now, as AIS shows it: its last recorded state at
/// or before the present, dead-reckoned to the present on that state's
/// course and speed ([`TargetMotion::announced`], decision 40), never the
/// interpolation towards the next report nor anything later.
///
/// ```
/// use vorrt_scenarios::{RecordedMotion, TimedState};
/// use vorrt_colregs::VesselState;
/// use glam::DVec2;
/// let east = VesselState::new(DVec2::ZERO, 90f64.to_radians(), 5.0, 80.0);
/// let track = RecordedMotion::new(vec![
///     TimedState { time_s: 0.0, vessel: east },
///     TimedState { time_s: 100.0, vessel: VesselState { position_m: DVec2::new(500.0, 0.0), ..east } },
/// ]).unwrap();
/// assert_eq!(track.state_at(40.0).position_m, DVec2::new(200.0, 0.0));
/// assert_eq!(track.state_at(120.0).position_m.x, 600.0); // dead-reckoned
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct RecordedMotion {
    /// The recorded states, in time order.
    states: Vec<TimedState>,
    /// The target now.
    present: VesselState,
    /// The present time on the loop's clock, seconds.
    time_s: f64,
}

impl RecordedMotion {
    /// A target moved through `states` (in time order), at time 0.
    ///
    /// # Errors
    /// [`RecordedMotionError`] when there is no state, a state is not a
    /// vessel's (a number not finite, a negative speed, a length not
    /// positive), or the times do not increase.
    pub fn new(states: Vec<TimedState>) -> Result<Self, RecordedMotionError> {
        if states.is_empty() {
            return Err(RecordedMotionError::Empty);
        }
        for (index, state) in states.iter().enumerate() {
            let vessel = &state.vessel;
            if !state.time_s.is_finite()
                || !vessel.is_finite()
                || vessel.speed_mps < 0.0
                || vessel.length_m <= 0.0
            {
                return Err(RecordedMotionError::InvalidState { index });
            }
            if index > 0 && state.time_s <= states[index - 1].time_s {
                return Err(RecordedMotionError::NotIncreasing { index });
            }
        }
        let mut track = Self {
            present: states[0].vessel,
            states,
            time_s: 0.0,
        };
        track.present = track.state_at(0.0);
        Ok(track)
    }

    /// The recorded states, in time order.
    #[must_use]
    pub fn states(&self) -> &[TimedState] {
        &self.states
    }

    /// What ownship knows of the target at `time_s`: its last recorded state
    /// at or before `time_s` (the last AIS report received), dead-reckoned
    /// to `time_s` on that report's course and speed; before the first
    /// report, the first dead-reckoned back (a target seen from the start).
    #[must_use]
    pub fn reported_at(&self, time_s: f64) -> VesselState {
        let after = self.states.partition_point(|state| state.time_s <= time_s);
        let report = self.states[after.saturating_sub(1)];
        report.vessel.advanced(time_s - report.time_s)
    }

    /// Where the recording puts the target at `time_s`.
    #[must_use]
    #[expect(
        clippy::float_cmp,
        reason = "a query exactly at a recorded time returns that state"
    )]
    pub fn state_at(&self, time_s: f64) -> VesselState {
        // The first state after `time_s`.
        let after = self.states.partition_point(|state| state.time_s <= time_s);
        let (Some(last), Some(first)) = (self.states.last(), self.states.first()) else {
            // `new` refuses an empty recording.
            return self.present;
        };
        if after == 0 {
            return first.vessel.advanced(time_s - first.time_s);
        }
        if after == self.states.len() {
            return last.vessel.advanced(time_s - last.time_s);
        }
        let (from, to) = (&self.states[after - 1], &self.states[after]);
        if from.time_s == time_s {
            return from.vessel;
        }
        let fraction = (time_s - from.time_s) / (to.time_s - from.time_s);
        let lerp = |a: f64, b: f64| a + (b - a) * fraction;
        VesselState {
            position_m: from.vessel.position_m
                + (to.vessel.position_m - from.vessel.position_m) * fraction,
            course_rad: angle::normalize_2pi(
                from.vessel.course_rad
                    + angle::signed_turn(from.vessel.course_rad, to.vessel.course_rad) * fraction,
            ),
            speed_mps: lerp(from.vessel.speed_mps, to.vessel.speed_mps),
            length_m: lerp(from.vessel.length_m, to.vessel.length_m),
        }
    }
}

impl TargetMotion for RecordedMotion {
    fn vessel(&self) -> VesselState {
        self.present
    }

    fn advance(
        &mut self,
        _time_s: f64,
        next_time_s: f64,
        _own: &VesselState,
        _rules: &RuleParameters,
    ) {
        self.present = self.state_at(next_time_s);
        self.time_s = next_time_s;
    }

    /// Holding the course and speed of its last report, dead-reckoned from
    /// it ([`RecordedMotion::reported_at`]): a recording announces no
    /// destination, and its future is not known on board (decision 40).
    fn announced(
        &self,
        _own: &VesselState,
        _encounter: Option<Encounter>,
        _rules: &RuleParameters,
    ) -> TargetState {
        TargetState::constant_velocity(self.reported_at(self.time_s))
    }

    /// Positions resampled from a recording's fixes, with their jitter:
    /// estimated from the track.
    fn observation(&self) -> TrackObservation {
        TrackObservation::default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    fn at(time_s: f64, x_m: f64, y_m: f64, course_deg: f64, speed_mps: f64) -> TimedState {
        TimedState {
            time_s,
            vessel: VesselState::new(
                DVec2::new(x_m, y_m),
                course_deg.to_radians(),
                speed_mps,
                80.0,
            ),
        }
    }

    #[test]
    fn between_states_it_is_interpolated_and_at_a_state_exact() {
        let track = RecordedMotion::new(vec![
            at(-10.0, 0.0, -50.0, 0.0, 5.0),
            at(90.0, 0.0, 450.0, 350.0, 5.0),
            at(190.0, 100.0, 450.0, 90.0, 1.0),
        ])
        .expect("valid");
        assert_eq!(track.state_at(90.0), track.states()[1].vessel);
        let half = track.state_at(40.0);
        assert_eq!(half.position_m, DVec2::new(0.0, 200.0));
        // Through north, the smaller turn: 0° to 350° passes 355°.
        assert!((half.course_rad.to_degrees() - 355.0).abs() < 1e-9);
        let later = track.state_at(165.0);
        assert_eq!(later.position_m, DVec2::new(75.0, 450.0));
        assert!((later.speed_mps - 2.0).abs() < 1e-12);
        // At time 0 (the loop's start) it is where the recording says.
        assert!(track.vessel().position_m.length() < 1e-9);
    }

    #[test]
    fn its_fixes_are_not_taken_for_exact() {
        let track = RecordedMotion::new(vec![at(10.0, 0.0, 0.0, 90.0, 2.0)]).expect("valid");
        // Its jitter is estimated from its positions; a simulated motion's
        // are exact.
        assert_eq!(track.observation(), TrackObservation::default());
        assert_ne!(track.observation(), TrackObservation::exact());
    }

    #[test]
    fn outside_its_times_it_is_dead_reckoned() {
        let track = RecordedMotion::new(vec![at(10.0, 0.0, 0.0, 90.0, 2.0)]).expect("valid");
        assert!((track.state_at(0.0).position_m - DVec2::new(-20.0, 0.0)).length() < 1e-9);
        assert!((track.state_at(60.0).position_m - DVec2::new(100.0, 0.0)).length() < 1e-9);
    }

    #[test]
    fn a_bad_recording_is_refused() {
        assert_eq!(
            RecordedMotion::new(Vec::new()),
            Err(RecordedMotionError::Empty)
        );
        let mut bad = at(0.0, 0.0, 0.0, 0.0, 1.0);
        bad.vessel.speed_mps = -1.0;
        assert_eq!(
            RecordedMotion::new(vec![bad]),
            Err(RecordedMotionError::InvalidState { index: 0 })
        );
        let twice = vec![at(5.0, 0.0, 0.0, 0.0, 1.0), at(5.0, 0.0, 5.0, 0.0, 1.0)];
        assert_eq!(
            RecordedMotion::new(twice),
            Err(RecordedMotionError::NotIncreasing { index: 1 })
        );
        let nan = vec![at(f64::NAN, 0.0, 0.0, 0.0, 1.0)];
        assert_eq!(
            RecordedMotion::new(nan),
            Err(RecordedMotionError::InvalidState { index: 0 })
        );
    }

    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn it_is_announced_from_its_present_state_alone() {
        // Two recordings alike up to 100 s; one then turns hard to port.
        let straight = vec![at(0.0, 0.0, 0.0, 0.0, 5.0), at(100.0, 0.0, 500.0, 0.0, 5.0)];
        let mut turning = straight.clone();
        turning.push(at(150.0, -250.0, 500.0, 270.0, 5.0));
        let rules = RuleParameters::default();
        let own = VesselState::new(DVec2::new(0.0, 3000.0), std::f64::consts::PI, 6.0, 100.0);
        let (mut a, mut b) = (
            RecordedMotion::new(straight).expect("valid"),
            RecordedMotion::new(turning).expect("valid"),
        );
        for step in 0..20 {
            let (time_s, next_s) = (f64::from(step) * 5.0, f64::from(step + 1) * 5.0);
            assert_eq!(
                a.announced(&own, None, &rules),
                b.announced(&own, None, &rules)
            );
            assert_eq!(
                b.announced(&own, None, &rules),
                TargetState::constant_velocity(b.reported_at(time_s))
            );
            a.advance(time_s, next_s, &own, &rules);
            b.advance(time_s, next_s, &own, &rules);
        }
        // At 100 s the one that will turn is still announced heading north.
        assert_eq!(b.announced(&own, None, &rules).vessel.course_rad, 0.0);
        // Half way to the report of the turn it has truly swung to 315°,
        // yet is announced on its last report: north, dead-reckoned.
        for _ in 20..25 {
            let time_s = b.time_s;
            b.advance(time_s, time_s + 5.0, &own, &rules);
        }
        assert!((b.vessel().course_rad.to_degrees() - 315.0).abs() < 1e-9);
        let announced = b.announced(&own, None, &rules).vessel;
        assert_eq!(announced.course_rad, 0.0);
        assert!((announced.position_m - DVec2::new(0.0, 625.0)).length() < 1e-9);
    }

    #[test]
    fn the_report_is_the_last_one_dead_reckoned() {
        let track = RecordedMotion::new(vec![
            at(0.0, 0.0, 0.0, 90.0, 2.0),
            at(10.0, 20.0, 0.0, 0.0, 4.0),
        ])
        .expect("valid");
        assert!((track.reported_at(5.0).position_m - DVec2::new(10.0, 0.0)).length() < 1e-9);
        assert!((track.reported_at(15.0).position_m - DVec2::new(20.0, 20.0)).length() < 1e-9);
        assert!((track.reported_at(-5.0).position_m - DVec2::new(-10.0, 0.0)).length() < 1e-9);
    }
}
