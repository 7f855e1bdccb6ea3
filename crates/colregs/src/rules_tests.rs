//! Unit tests of the rule book (`rules.rs`).

use super::*;

#[test]
fn tolerances_bound_each_judgement_exclusively() {
    let params = RuleParameters::default();
    let tolerance = params.turn_tolerance_rad;
    assert!(!is_detectable_turn(tolerance, &params));
    assert!(!is_port_turn(-tolerance, &params));
    assert!(is_port_turn(-tolerance - 1e-9, &params));
    assert!(is_readily_apparent(-params.apparent_turn_rad, &params));
    assert!(!is_speed_change(
        params.stand_on_speed_tolerance_mps,
        &params
    ));
    assert!(!is_stand_on_course_change(
        params.stand_on_course_tolerance_rad,
        &params
    ));
}

#[test]
fn dead_astern_is_on_neither_side() {
    assert!(!is_on_port_side(DVec2::ZERO, 0.0, DVec2::new(0.0, -1000.0)));
    assert!(!is_on_port_side(DVec2::ZERO, 0.0, DVec2::new(0.0, 1000.0)));
}

#[test]
fn contact_is_strict() {
    assert!(in_contact(74.999, 50.0, 100.0));
    assert!(!in_contact(75.0, 50.0, 100.0));
    assert!(!in_contact(f64::NAN, 50.0, 100.0));
}
