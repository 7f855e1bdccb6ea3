//! How much of a track's course change is the data's own jitter: the fix
//! noise of each track, estimated from its fixes, and the observation window
//! and turn thresholds that keep the judgement above it (see the [module
//! documentation](super), "Noise", and decision 31).

use serde::{Deserialize, Serialize};
use vorrt_geometry::DVec2;

/// The scale from the median absolute deviation to the standard deviation of
/// a normal distribution (1 / Φ⁻¹(3/4)).
const MAD_TO_SIGMA: f64 = 1.482_6;

/// Half the baseline of the track's direction across which a fix's
/// deviation is measured, seconds.
const BASELINE_S: f64 = 60.0;

/// The largest sum of squared interpolation weights a fix is measured with:
/// beyond, its neighbours are too unevenly spaced to place it.
const MAX_SPREAD: f64 = 100.0;

/// Speeds below this are a vessel not making way: its course over ground is
/// no course, and its speed is no service speed (m/s; 0.5 kn).
pub const MAKING_WAY_MPS: f64 = 0.257;

/// The constants of the noise model, settable with the other parameters of
/// the observed judgement (defaults and sources in decision 31).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct NoiseParameters {
    /// The largest course-over-ground jitter (1 σ) at which the published
    /// thresholds (2° detectable, 5° action) are used as they are, radians.
    /// Default 0.4°: the 5° action detection is then 12 σ of the jitter of a
    /// change (two courses), the 2° detectable change 5 σ.
    pub course_noise_budget_rad: f64,
    /// The longest observation window the noise may call for, seconds
    /// (default 600 s: ten minutes, the longest look a watchkeeper takes to
    /// see a course change; beyond, the thresholds rise instead).
    pub max_window_s: f64,
    /// A detectable change must exceed this many σ of the jitter of a
    /// change of course (default 5).
    pub turn_sigmas: f64,
    /// An action is detected at this many σ of the jitter of a change of
    /// course (default 7: one false detection in about 10¹¹ samples).
    pub detection_sigmas: f64,
}

impl Default for NoiseParameters {
    fn default() -> Self {
        Self {
            course_noise_budget_rad: 0.3f64.to_radians(),
            max_window_s: 600.0,
            turn_sigmas: 6.0,
            detection_sigmas: 8.0,
        }
    }
}

/// The noise of one track and what the judgement makes of it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TrackNoise {
    /// The estimated position jitter of the fixes (1 σ), metres
    /// ([`position_noise_m`]); 0 for exact tracks.
    pub position_noise_m: f64,
    /// The speed the course jitter is judged at: the median speed over
    /// ground, observed over the longest window
    /// ([`max_window_s`](NoiseParameters::max_window_s), where jitter adds
    /// least), of the samples where the vessel made way, m/s.
    pub typical_speed_mps: f64,
    /// The observation window used for this track, seconds: the judgement's
    /// window, lengthened where the jitter calls for it.
    pub window_s: f64,
    /// The course-over-ground jitter (1 σ) over that window at the typical
    /// speed, radians: `√2 · position_noise_m / (typical_speed_mps · window_s)`.
    pub course_noise_rad: f64,
    /// The smallest detectable change of course used for this track, radians:
    /// the rule's 2° or `turn_sigmas · √2 · course_noise_rad`, the larger.
    pub turn_tolerance_rad: f64,
    /// The change of course at which an action is detected, radians: the
    /// evaluators' 5° or `detection_sigmas · √2 · course_noise_rad`, the larger.
    pub action_detection_rad: f64,
}

/// The position jitter (1 σ, metres) of a track's fixes, robustly: for each
/// fix, its distance from where its neighbours put it: the cubic through the
/// two fixes either side, at its time (with fewer than five fixes, the chord
/// of the one either side), so that a steady turn or a change of speed is
/// motion, not noise. Measured across the track's direction over a minute
/// either side, and scaled to one fix's noise (the variance of that distance
/// is `σ² (1 + Σ wₖ²)`, `wₖ` the interpolation's weights); the median of
/// their absolute values over 0.6745 (the MAD of a normal, robust to the
/// tail and to the odd sharp turn), raised by `1 + 3 / √n` for `n`
/// deviations (an upper estimate, about three standard errors above: the MAD
/// of a few dozen fixes is itself uncertain). Turns sharper than the fixes
/// resolve still add to it: the judgement then grows more lenient, never
/// stricter. `None` with fewer than three fixes.
///
/// ```
/// use vorrt_colregs::observed::position_noise_m;
/// use glam::DVec2;
/// let times: Vec<f64> = (0..50).map(|i| f64::from(i) * 10.0).collect();
/// // North at 5 m/s, every other fix 4 m east: a few metres of jitter.
/// let fixes: Vec<DVec2> = times
///     .iter()
///     .enumerate()
///     .map(|(i, t)| DVec2::new(if i % 2 == 0 { 0.0 } else { 4.0 }, 5.0 * t))
///     .collect();
/// let noise = position_noise_m(&times, &fixes).unwrap();
/// assert!(noise > 3.0 && noise < 10.0, "{noise}");
/// // A steady turn (1°/s at 5 m/s) is no jitter.
/// let turn: Vec<DVec2> = times
///     .iter()
///     .map(|t| {
///         let radius = 5.0 / 1f64.to_radians();
///         let angle = (1.0 * t).to_radians();
///         DVec2::new(radius * (1.0 - angle.cos()), radius * angle.sin())
///     })
///     .collect();
/// assert!(position_noise_m(&times, &turn).unwrap() < 0.5);
/// ```
#[must_use]
pub fn position_noise_m(times_s: &[f64], positions_m: &[DVec2]) -> Option<f64> {
    let count = times_s.len().min(positions_m.len());
    let (times_s, positions_m) = (&times_s[..count], &positions_m[..count]);
    let reach = if count >= 5 { 2 } else { 1 };
    let mut deviations: Vec<f64> = (reach..count.saturating_sub(reach))
        .filter_map(|index| {
            // At most four neighbours, on the stack: two vectors allocated
            // per fix were 4 % of a campaign's instructions.
            let mut around = [0usize; 2 * 2];
            let mut neighbours = 0;
            for other in (index - reach..=index + reach).filter(|other| *other != index) {
                around[neighbours] = other;
                neighbours += 1;
            }
            let neighbours = &around[..neighbours];
            let at_s = times_s[index];
            // Lagrange weights of the neighbours at this fix's time.
            let mut weighed = [0.0f64; 2 * 2];
            for (weight, &k) in weighed.iter_mut().zip(neighbours) {
                *weight = neighbours
                    .iter()
                    .filter(|&&m| m != k)
                    .map(|&m| (at_s - times_s[m]) / (times_s[k] - times_s[m]))
                    .product::<f64>();
            }
            let weights = &weighed[..neighbours.len()];
            let spread: f64 = weights.iter().map(|w| w * w).sum();
            if !(spread.is_finite() && spread <= MAX_SPREAD) {
                return None;
            }
            let predicted = neighbours
                .iter()
                .zip(weights)
                .fold(DVec2::ZERO, |sum, (&k, w)| sum + positions_m[k] * *w);
            // Across the track's direction over a longer baseline: the
            // chord of two close fixes points as much by their jitter as by
            // the motion.
            let from = times_s
                .partition_point(|t| *t <= at_s - BASELINE_S)
                .saturating_sub(1);
            let to = times_s
                .partition_point(|t| *t < at_s + BASELINE_S)
                .min(count - 1);
            let direction = positions_m[to] - positions_m[from];
            if direction.length() <= 1e-9 {
                return None;
            }
            let across = direction
                .normalize()
                .perp_dot(positions_m[index] - predicted);
            Some((across / (1.0 + spread).sqrt()).abs())
        })
        .filter(|deviation| deviation.is_finite())
        .collect();
    if deviations.is_empty() {
        return None;
    }
    deviations.sort_by(f64::total_cmp);
    let middle = deviations.len() / 2;
    let median = if deviations.len() % 2 == 1 {
        deviations[middle]
    } else {
        f64::midpoint(deviations[middle - 1], deviations[middle])
    };
    // An upper estimate: about three standard errors of the MAD (whose
    // relative standard error for a normal is 1.17 / √n) above it, so that
    // a short track's luck does not lower its thresholds.
    #[expect(
        clippy::cast_precision_loss,
        reason = "a count of fixes is far below 2^52"
    )]
    let upper = 1.0 + 3.0 / (deviations.len() as f64).sqrt();
    Some(MAD_TO_SIGMA * median * upper)
}

/// The median of the speeds at which the vessel made way (more than 0.5 kn),
/// m/s; 0 when it never did.
#[must_use]
pub fn typical_speed_mps(speeds_mps: &[f64]) -> f64 {
    let mut moving: Vec<f64> = speeds_mps
        .iter()
        .copied()
        .filter(|speed| speed.is_finite() && *speed > MAKING_WAY_MPS)
        .collect();
    if moving.is_empty() {
        return 0.0;
    }
    moving.sort_by(f64::total_cmp);
    moving[moving.len() / 2]
}

/// What a track's jitter makes of the judgement: the window lengthened until
/// the course jitter is within the budget (at most `max_window_s`), and
/// the turn thresholds raised above what remains. With no jitter, the
/// judgement's window and the published thresholds, unchanged.
///
/// ```
/// use vorrt_colregs::observed::{NoiseParameters, track_noise};
/// let p = NoiseParameters::default();
/// let (deg2, deg5) = (2f64.to_radians(), 5f64.to_radians());
/// let exact = track_noise(0.0, 6.0, 60.0, deg2, deg5, &p);
/// assert_eq!((exact.window_s, exact.turn_tolerance_rad), (60.0, deg2));
/// // 5 m of jitter at 5 m/s: a longer look, same thresholds.
/// let noisy = track_noise(5.0, 5.0, 60.0, deg2, deg5, &p);
/// assert!(noisy.window_s > 200.0 && noisy.window_s < 600.0);
/// assert_eq!(noisy.action_detection_rad, deg5);
/// // At 1 m/s even ten minutes are not enough: the thresholds rise.
/// let slow = track_noise(15.0, 1.0, 60.0, deg2, deg5, &p);
/// assert_eq!(slow.window_s, 600.0);
/// assert!(slow.action_detection_rad > deg5);
/// ```
#[must_use]
pub fn track_noise(
    position_noise_m: f64,
    typical_speed_mps: f64,
    window_s: f64,
    turn_tolerance_rad: f64,
    action_detection_rad: f64,
    parameters: &NoiseParameters,
) -> TrackNoise {
    let jitter_m = std::f64::consts::SQRT_2 * position_noise_m.max(0.0);
    let (window_s, course_noise_rad) = if jitter_m <= 0.0 {
        (window_s, 0.0)
    } else if typical_speed_mps <= MAKING_WAY_MPS {
        // Never making way: no course to judge, the longest look.
        (
            parameters.max_window_s.max(window_s),
            std::f64::consts::FRAC_PI_2,
        )
    } else {
        let needed_s = jitter_m / (typical_speed_mps * parameters.course_noise_budget_rad);
        let window_s = needed_s.clamp(window_s, parameters.max_window_s.max(window_s));
        (
            window_s,
            (jitter_m / (typical_speed_mps * window_s)).min(std::f64::consts::FRAC_PI_2),
        )
    };
    // A change is the difference of two courses: √2 their jitter.
    let change_noise_rad = std::f64::consts::SQRT_2 * course_noise_rad;
    TrackNoise {
        position_noise_m: position_noise_m.max(0.0),
        typical_speed_mps,
        window_s,
        course_noise_rad,
        turn_tolerance_rad: turn_tolerance_rad
            .max(parameters.turn_sigmas * change_noise_rad)
            .min(std::f64::consts::PI),
        action_detection_rad: action_detection_rad
            .max(parameters.detection_sigmas * change_noise_rad)
            .min(std::f64::consts::PI),
    }
}

impl NoiseParameters {
    /// Checks every field: the budget an angle in (0, π/2), the window and
    /// the multiples positive and finite.
    ///
    /// # Errors
    /// The name of the first field that is wrong, its value and what was
    /// expected.
    pub(super) fn check(&self) -> Result<(), (&'static str, f64, &'static str)> {
        let budget = self.course_noise_budget_rad;
        if !(budget.is_finite() && budget > 0.0 && budget < std::f64::consts::FRAC_PI_2) {
            return Err((
                "noise.course_noise_budget_rad",
                budget,
                "an angle in (0, π/2) radians",
            ));
        }
        for (field, value) in [
            ("noise.max_window_s", self.max_window_s),
            ("noise.turn_sigmas", self.turn_sigmas),
            ("noise.detection_sigmas", self.detection_sigmas),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err((field, value, "a finite number greater than 0"));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn typical_speed_ignores_a_vessel_at_rest() {
        assert!((typical_speed_mps(&[0.0, 0.1, 4.0, 5.0, 6.0]) - 5.0).abs() < 1e-12);
        assert!(typical_speed_mps(&[0.0, 0.1]).abs() < 1e-12);
    }

    #[test]
    fn defaults_check_and_bad_fields_are_named() {
        assert!(NoiseParameters::default().check().is_ok());
        let bad = NoiseParameters {
            turn_sigmas: 0.0,
            ..NoiseParameters::default()
        };
        assert_eq!(bad.check().unwrap_err().0, "noise.turn_sigmas");
    }

    #[test]
    fn a_vessel_never_making_way_gets_the_longest_look_and_no_course() {
        let noise = track_noise(3.0, 0.0, 60.0, 0.035, 0.087, &NoiseParameters::default());
        assert!((noise.window_s - 600.0).abs() < 1e-9);
        assert!(noise.turn_tolerance_rad > 1.0);
    }
}
