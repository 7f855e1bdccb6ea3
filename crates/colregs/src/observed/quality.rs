//! Path quality of a sailed track: how fast it turns, how often it reverses
//! its turn, how much it turns per mile (see the [module
//! documentation](super), "Path quality").

use crate::compliance::episodes::turn_reversals;
use crate::parameters::RuleParameters;
use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_geometry::angle::signed_turn;

/// Metres in a nautical mile.
const NAUTICAL_MILE_M: f64 = 1852.0;

/// Path-quality figures of one track.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PathQuality {
    /// The largest rate of turn between consecutive samples, degrees per
    /// second.
    pub max_turn_rate_deg_s: f64,
    /// Turn-direction reversals: sign changes between successive turn
    /// episodes ([`turn_episodes`](super::turn_episodes)).
    pub turn_reversals: usize,
    /// The total course change, degrees (every step's change, either way).
    pub course_change_deg: f64,
    /// The distance sailed, nautical miles.
    pub distance_nm: f64,
    /// `course_change_deg / distance_nm` (0 over no distance), degrees per
    /// nautical mile.
    pub course_change_deg_per_nm: f64,
}

/// The path quality of a track: `courses_rad` is the course at each sample
/// (the recorded course where the recording gives one, else the observed
/// course over ground), `times_s` and `positions_m` the samples.
///
/// ```
/// use vorrt_colregs::observed::path_quality;
/// use vorrt_colregs::RuleParameters;
/// use glam::DVec2;
/// // A straight nautical mile: no turn.
/// let times = [0.0, 100.0, 200.0];
/// let positions = [DVec2::ZERO, DVec2::new(0.0, 926.0), DVec2::new(0.0, 1852.0)];
/// let quality = path_quality(&times, &positions, &[0.0; 3], &RuleParameters::default());
/// assert_eq!(quality.turn_reversals, 0);
/// assert_eq!(quality.course_change_deg_per_nm, 0.0);
/// assert!((quality.distance_nm - 1.0).abs() < 1e-12);
/// ```
#[must_use]
pub fn path_quality(
    times_s: &[f64],
    positions_m: &[DVec2],
    courses_rad: &[f64],
    rules: &RuleParameters,
) -> PathQuality {
    let mut max_turn_rate_deg_s: f64 = 0.0;
    let mut course_change_deg = 0.0;
    for (times, courses) in times_s.windows(2).zip(courses_rad.windows(2)) {
        let change_deg = signed_turn(courses[0], courses[1]).abs().to_degrees();
        if !change_deg.is_finite() {
            continue;
        }
        course_change_deg += change_deg;
        let step_s = times[1] - times[0];
        if step_s > 0.0 {
            max_turn_rate_deg_s = max_turn_rate_deg_s.max(change_deg / step_s);
        }
    }
    let distance_nm = positions_m
        .windows(2)
        .map(|pair| pair[0].distance(pair[1]))
        .sum::<f64>()
        / NAUTICAL_MILE_M;
    PathQuality {
        max_turn_rate_deg_s,
        turn_reversals: turn_reversals(courses_rad, rules),
        course_change_deg,
        distance_nm,
        course_change_deg_per_nm: if distance_nm > 0.0 {
            course_change_deg / distance_nm
        } else {
            0.0
        },
    }
}
