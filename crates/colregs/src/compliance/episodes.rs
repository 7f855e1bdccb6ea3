//! Turn episodes of a course series: the runs of same-direction course
//! change that an observer counts as one alteration (see the [module
//! documentation](crate::observed), "Turn episodes"). Here, below both their
//! users, so that the scoring (rule 8(b)'s small alterations) and the
//! judgement as observed (path quality) share them without depending on
//! each other; public as [`crate::observed`]'s.

use crate::parameters::RuleParameters;
use crate::rules::is_detectable_turn;
use serde::{Deserialize, Serialize};
use vorrt_geometry::angle::signed_turn;

/// One run of same-direction course change.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TurnEpisode {
    /// Index of the sample where the run starts (the previous turning point).
    pub start_index: usize,
    /// Index of the sample where the run ends (its turning point: the course
    /// farthest in the run's direction).
    pub end_index: usize,
    /// The course change of the run, radians: positive to starboard.
    pub change_rad: f64,
}

/// The turn episodes of `courses_rad` (one course per sample, radians).
///
/// The courses are unwrapped into a cumulative course change (each step the
/// shorter way round, [`signed_turn`]). An episode is a run from one turning
/// point to the next in which the cumulative course moves one way by a
/// detectable turn ([`is_detectable_turn`]: more than
/// [`turn_tolerance_rad`](RuleParameters::turn_tolerance_rad), 2°); a
/// counter-move smaller than that inside a run is absorbed into it (it is not
/// detectable), a larger one ends the run at its turning point and starts a
/// run the other way. Successive episodes therefore alternate in direction,
/// and the number of turn-direction reversals is the number of episodes less
/// one.
///
/// ```
/// use vorrt_colregs::observed::turn_episodes;
/// use vorrt_colregs::RuleParameters;
/// let deg = |d: &[f64]| d.iter().map(|x| x.to_radians()).collect::<Vec<_>>();
/// // 0 -> 35 (with a 1° wobble) -> 0: two episodes, one reversal.
/// let courses = deg(&[0.0, 10.0, 20.0, 19.0, 35.0, 35.0, 20.0, 0.0]);
/// let episodes = turn_episodes(&courses, &RuleParameters::default());
/// assert_eq!(episodes.len(), 2);
/// assert!((episodes[0].change_rad.to_degrees() - 35.0).abs() < 1e-9);
/// assert!((episodes[1].change_rad.to_degrees() + 35.0).abs() < 1e-9);
/// ```
#[must_use]
pub fn turn_episodes(courses_rad: &[f64], rules: &RuleParameters) -> Vec<TurnEpisode> {
    /// The run in progress: direction, where it started, its turning point.
    struct Run {
        direction: f64,
        start: (f64, usize),
        extreme: (f64, usize),
    }
    let mut episodes = Vec::new();
    let Some(&first) = courses_rad.first() else {
        return episodes;
    };
    let mut previous = first;
    let mut cumulative = 0.0;
    // Before the first episode: the lowest and highest cumulative course.
    let (mut low, mut high) = ((0.0, 0), (0.0, 0));
    let mut run: Option<Run> = None;
    for (index, &course) in courses_rad.iter().enumerate().skip(1) {
        if !course.is_finite() {
            continue;
        }
        cumulative += signed_turn(previous, course);
        previous = course;
        match &mut run {
            None => {
                if is_detectable_turn(cumulative - low.0, rules) && cumulative > low.0 {
                    run = Some(Run {
                        direction: 1.0,
                        start: low,
                        extreme: (cumulative, index),
                    });
                } else if is_detectable_turn(high.0 - cumulative, rules) && cumulative < high.0 {
                    run = Some(Run {
                        direction: -1.0,
                        start: high,
                        extreme: (cumulative, index),
                    });
                }
                if cumulative < low.0 {
                    low = (cumulative, index);
                }
                if cumulative > high.0 {
                    high = (cumulative, index);
                }
            }
            Some(current) => {
                let beyond = current.direction * (cumulative - current.extreme.0);
                if beyond > 0.0 {
                    current.extreme = (cumulative, index);
                } else if is_detectable_turn(beyond, rules) {
                    episodes.push(TurnEpisode {
                        start_index: current.start.1,
                        end_index: current.extreme.1,
                        change_rad: current.extreme.0 - current.start.0,
                    });
                    *current = Run {
                        direction: -current.direction,
                        start: current.extreme,
                        extreme: (cumulative, index),
                    };
                }
            }
        }
    }
    if let Some(current) = run {
        episodes.push(TurnEpisode {
            start_index: current.start.1,
            end_index: current.extreme.1,
            change_rad: current.extreme.0 - current.start.0,
        });
    }
    episodes
}

/// The number of turn-direction reversals in `courses_rad`: the episodes of
/// [`turn_episodes`] less one (0 for none or one).
#[must_use]
pub fn turn_reversals(courses_rad: &[f64], rules: &RuleParameters) -> usize {
    turn_episodes(courses_rad, rules).len().saturating_sub(1)
}
