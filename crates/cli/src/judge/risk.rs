//! What `vorrt judge` says of the risk-of-collision distance it judged
//! with (decision 50).

use vorrt_colregs::RuleParameters;

/// The risk-of-collision distance the judgement rests on, in words
/// (decision 50): open sea or the sea room, and each target's distance.
pub(crate) fn risk_distance_said(
    rules: &RuleParameters,
    own_length_m: f64,
    target_lengths_m: &[f64],
) -> String {
    let distances: Vec<String> = target_lengths_m
        .iter()
        .map(|target_length_m| {
            format!(
                "{:.0}",
                rules.risk_distance_m(own_length_m, *target_length_m)
            )
        })
        .collect();
    let water = rules.risk_distance.sea_room_m.map_or_else(
        || "open sea (no sea room given: --sea-room-m or the scenario's planner.sea_room_nm)".to_owned(),
        |sea_room_m| {
            format!(
                "confined water, sea room {sea_room_m:.0} m (at most {:.2} of it, never under d_th {:.0} m between the hulls)",
                rules.risk_distance.sea_room_fraction, rules.risk_distance.clearance_floor_m
            )
        },
    );
    format!(
        "risk of collision: a predicted miss under {} m with each target (decision 50: {:.0} m, or {} times the larger length up to {:.0} m; {water}; from the lengths above)",
        distances.join(", "),
        rules.risk_cpa_m,
        rules.risk_distance.length_factor,
        rules.risk_distance.cap_m,
    )
}
