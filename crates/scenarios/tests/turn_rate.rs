//! A vessel's `max_turn_rate_deg_s` and the planner's `instant_turns`: the
//! rate given bounds the track sailed, a bad rate is refused naming the
//! field, and the paper's instantaneous model stays available.

use std::path::PathBuf;
use vorrt_geometry::angle::signed_turn;
use vorrt_scenarios::{Scenario, SimulationRecord, simulate};

fn fixture(relative: &str) -> Scenario {
    let path: PathBuf = [env!("CARGO_MANIFEST_DIR"), "fixtures", relative]
        .iter()
        .collect();
    Scenario::load(&path).expect("fixture loads")
}

/// The largest rate of turn between consecutive recorded steps, °/s.
fn sailed_rate_deg_s(record: &SimulationRecord) -> f64 {
    record
        .ownship
        .windows(2)
        .zip(record.times_s.windows(2))
        .map(|(pair, times)| {
            signed_turn(pair[0].course_rad, pair[1].course_rad)
                .abs()
                .to_degrees()
                / (times[1] - times[0])
        })
        .fold(0.0, f64::max)
}

#[test]
fn the_given_rate_bounds_the_sailed_track() {
    for rate in [0.2, 0.8] {
        let mut scenario = fixture("paper/crossing.ron");
        scenario.ownship.max_turn_rate_deg_s = Some(rate);
        let record = simulate(&scenario, 1).expect("valid settings");
        assert!(record.reached_goal, "rate {rate}");
        let expected = Some(rate.to_radians());
        assert_eq!(record.max_turn_rate_rad_s, expected);
        let sailed = sailed_rate_deg_s(&record);
        assert!(
            sailed <= rate * (1.0 + 1e-9),
            "sailed {sailed}°/s > {rate}°/s"
        );
        // It did turn, at the rate given: the limit is met, not avoided.
        assert!(sailed >= 0.99 * rate, "sailed only {sailed}°/s");
    }
}

#[test]
fn a_bad_rate_is_refused_naming_the_field() {
    for bad in ["-1.0", "0.0", "31.0"] {
        let text = std::fs::read_to_string(
            [
                env!("CARGO_MANIFEST_DIR"),
                "fixtures",
                "paper",
                "head_on.ron",
            ]
            .iter()
            .collect::<PathBuf>(),
        )
        .expect("fixture");
        let patched = text.replacen(
            "length_m:",
            &format!("max_turn_rate_deg_s: {bad}, length_m:"),
            1,
        );
        let error = Scenario::from_ron_str(&patched, "bad.ron").expect_err(bad);
        assert_eq!(
            error.field(),
            Some("ownship.max_turn_rate_deg_s"),
            "{error}"
        );
    }
}

#[test]
fn instant_turns_give_the_papers_model() {
    let mut scenario = fixture("paper/head_on.ron");
    scenario.planner.instant_turns = Some(true);
    let record = simulate(&scenario, 1).expect("valid settings");
    assert_eq!(record.max_turn_rate_rad_s, None);
    assert!(record.reached_goal);
    // The branch's course changes are instantaneous: far above any ship's rate.
    assert!(sailed_rate_deg_s(&record) > 1.0);
}
