//! Checks that a drawn target keeps the generator's promises: risk of
//! collision arises, in the intended encounter type, before the CPA.

use super::OpenSeaSpec;
use vorrt_colregs::{Encounter, RuleParameters, VesselState, assess_risk, classify};
use vorrt_geometry::{closest_point_of_approach, units};

/// Where ownship and a target would be `time_s` from the start if both held
/// course and speed.
fn straight(vessel: &VesselState, time_s: f64) -> VesselState {
    vessel.advanced(time_s)
}

/// The encounter (from ownship's side) when risk of collision first arises
/// with both holding course, and when; `None` if it never does within
/// `horizon_s`.
#[must_use]
pub fn encounter_at_risk(
    own: &VesselState,
    target: &VesselState,
    rules: &RuleParameters,
    horizon_s: f64,
) -> Option<(f64, Encounter)> {
    let step_s = 5.0;
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a bounded horizon over a 5 s step, rounded up; negatives saturate to 0"
    )]
    let last_step = (horizon_s / step_s).ceil() as usize;
    (0..=last_step).find_map(|step| {
        #[expect(clippy::cast_precision_loss, reason = "a step count, far below 2^52")]
        let time_s = step as f64 * step_s;
        let own_now = straight(own, time_s);
        let target_now = straight(target, time_s);
        assess_risk(&own_now, &target_now, rules)
            .at_risk
            .then(|| (time_s, classify(&own_now, &target_now, rules)))
    })
}

/// Whether a (rounded) target keeps the generator's promises: CPA under
/// `max_cpa_nm` (plus rounding) in the `tcpa_min` window, risk of collision
/// arising before the CPA, of the intended type, and a start clear of ownship.
pub(super) fn holds_as_intended(
    own: &VesselState,
    target: &VesselState,
    intended: Encounter,
    spec: &OpenSeaSpec,
    rules: &RuleParameters,
) -> bool {
    let cpa = closest_point_of_approach(
        own.position_m,
        own.velocity_mps(),
        target.position_m,
        target.velocity_mps(),
    );
    let window_s = (60.0 * spec.tcpa_min.0 - 1.0, 60.0 * spec.tcpa_min.1 + 1.0);
    if !(cpa.distance_m < rules.risk_cpa_m
        && cpa.distance_m <= units::nautical_miles_to_m(spec.max_cpa_nm) + 5.0
        && cpa.time_s >= window_s.0
        && cpa.time_s <= window_s.1)
    {
        return false;
    }
    if own.range_to(target) < units::nautical_miles_to_m(0.3) {
        return false;
    }
    matches!(
        encounter_at_risk(own, target, rules, cpa.time_s),
        Some((_, encounter)) if encounter == intended
    )
}
