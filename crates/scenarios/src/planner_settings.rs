//! The `planner` section of a scenario file: [`PlannerConfig`] in file units.

use serde::{Deserialize, Serialize};
use vorrt_colregs::RuleParameters;
use vorrt_geometry::units;
use vorrt_planner::{NearestIndex, PlannerConfig, PlannerError, Turning};

/// Planner settings as a scenario file gives them (written `Planner(...)` or
/// just `(...)` in RON). Every field is optional; an absent field keeps the
/// value of [`PlannerConfig::default()`]. Units are the file's: metres,
/// nautical miles, degrees, knots, seconds, as each name says.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default, rename = "Planner")]
pub struct PlannerSettings {
    /// `d_th`, the clearance every target must keep, metres (default 200; the
    /// paper uses 100 in a traffic separation scheme).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub clearance_m: Option<f64>,
    /// The passing distance preferred where sea room allows, as a multiple
    /// of `clearance_m` (default 2; 1 turns it off).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub preferred_clearance_factor: Option<f64>,
    /// `d'`, the joint forward step, metres (default 100).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub step_m: Option<f64>,
    /// Distance from the goal at which a final segment onto it is tried,
    /// metres (default 100).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub goal_tolerance_m: Option<f64>,
    /// Probability of sampling the goal in phase 1 (default 0.5).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub goal_bias: Option<f64>,
    /// Probability of sampling the goal in phase 2 (default 0.0).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub phase_two_goal_bias: Option<f64>,
    /// Accepted nodes per phase (default 200, the paper's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nodes_per_phase: Option<usize>,
    /// Samples, accepted or not, per phase (default 4000).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub samples_per_phase: Option<usize>,
    /// Budgets follow the route: at least this many accepted nodes per phase
    /// for each step of the straight route, samples in proportion (default
    /// 2.5; 0 keeps `nodes_per_phase` and `samples_per_phase` as given; see
    /// `docs/scenario-format.md`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nodes_per_route_step: Option<f64>,
    /// Restarts after both phases fail (default 3).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_restarts: Option<usize>,
    /// Largest course change at one node, degrees (default 30).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_turn_per_step_deg: Option<f64>,
    /// Margin around the start-goal box for random samples, nautical miles
    /// (default 2).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sampling_margin_nm: Option<f64>,
    /// Look-ahead beyond a segment for encounters in force, seconds
    /// (default 1800).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lookahead_s: Option<f64>,
    /// Wall-clock budget for one plan, seconds (default: no limit).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub time_budget_s: Option<f64>,
    /// Nearest-node search: `linear` (default) or `r_tree`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nearest_index: Option<NearestIndex>,
    /// Minimum threshold distance: a target farther is not yet an encounter,
    /// nautical miles (default 5).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mtd_nm: Option<f64>,
    /// CPA distance under which there is risk of collision, nautical miles
    /// (default 1).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub risk_cpa_nm: Option<f64>,
    /// The width of navigable water the scenario's vessels are in, nautical
    /// miles, where the water is confined: the risk-of-collision distance is
    /// then at most a quarter of it, never under `d_th` between the hulls
    /// (decision 50). Default: open sea.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sea_room_nm: Option<f64>,
    /// Half-width of the head-on sector, degrees (default 13).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub head_on_half_width_deg: Option<f64>,
    /// Where the stern sector starts, degrees from dead ahead (default 112.5).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub abaft_beam_deg: Option<f64>,
    /// Angle beyond which a latched encounter counts as passed, degrees
    /// (default 112.5).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub passed_angle_deg: Option<f64>,
    /// Course change under which there is no turn, degrees (default 2).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub turn_tolerance_deg: Option<f64>,
    /// Course drift allowed to a stand-on vessel, degrees (default 15).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stand_on_course_tolerance_deg: Option<f64>,
    /// Speed drift allowed to a stand-on vessel, knots (default 1 m/s =
    /// 1.944 kn).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stand_on_speed_tolerance_kn: Option<f64>,
    /// Range under which a stand-on vessel may act alone, nautical miles
    /// (default 2).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stand_on_action_range_nm: Option<f64>,
    /// Course change that is "readily apparent", degrees (default 30).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub apparent_turn_deg: Option<f64>,
    /// `true`: the paper's instantaneous turns, the plan being the tree's
    /// branch (default `false`: turns at ownship's rate of turn, the branch
    /// simplified into legs).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub instant_turns: Option<bool>,
}

impl PlannerSettings {
    /// Whether no field is set.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        *self == Self::default()
    }

    /// The floating-point fields that are set, by their name in the file.
    pub(crate) fn set_numbers(&self) -> Vec<(&'static str, f64)> {
        [
            ("clearance_m", self.clearance_m),
            (
                "preferred_clearance_factor",
                self.preferred_clearance_factor,
            ),
            ("step_m", self.step_m),
            ("goal_tolerance_m", self.goal_tolerance_m),
            ("nodes_per_route_step", self.nodes_per_route_step),
            ("goal_bias", self.goal_bias),
            ("phase_two_goal_bias", self.phase_two_goal_bias),
            ("max_turn_per_step_deg", self.max_turn_per_step_deg),
            ("sampling_margin_nm", self.sampling_margin_nm),
            ("lookahead_s", self.lookahead_s),
            ("time_budget_s", self.time_budget_s),
            ("mtd_nm", self.mtd_nm),
            ("risk_cpa_nm", self.risk_cpa_nm),
            ("sea_room_nm", self.sea_room_nm),
            ("head_on_half_width_deg", self.head_on_half_width_deg),
            ("abaft_beam_deg", self.abaft_beam_deg),
            ("passed_angle_deg", self.passed_angle_deg),
            ("turn_tolerance_deg", self.turn_tolerance_deg),
            (
                "stand_on_course_tolerance_deg",
                self.stand_on_course_tolerance_deg,
            ),
            (
                "stand_on_speed_tolerance_kn",
                self.stand_on_speed_tolerance_kn,
            ),
            ("stand_on_action_range_nm", self.stand_on_action_range_nm),
            ("apparent_turn_deg", self.apparent_turn_deg),
        ]
        .into_iter()
        .filter_map(|(name, value)| value.map(|value| (name, value)))
        .collect()
    }

    /// `base` with every set field replaced, converted to SI. Not validated.
    #[must_use]
    pub fn apply_to(&self, base: PlannerConfig) -> PlannerConfig {
        let mut config = base;
        self.apply_search_to(&mut config);
        self.apply_rules_to(&mut config.rules);
        // The risk-of-collision distance never goes under d_th between the
        // hulls (decision 50): the scenario's d_th.
        config.rules.risk_distance.clearance_floor_m = config.clearance_m;
        config
    }

    /// Replaces the search and sailing settings of `config` that are set.
    fn apply_search_to(&self, config: &mut PlannerConfig) {
        let same = |value: f64| value;
        set_si(&mut config.clearance_m, self.clearance_m, same);
        set_si(
            &mut config.preferred_clearance_factor,
            self.preferred_clearance_factor,
            same,
        );
        set_si(&mut config.step_m, self.step_m, same);
        set_si(&mut config.goal_tolerance_m, self.goal_tolerance_m, same);
        set_si(&mut config.goal_bias, self.goal_bias, same);
        set_si(
            &mut config.nodes_per_route_step,
            self.nodes_per_route_step,
            same,
        );
        set_si(
            &mut config.phase_two_goal_bias,
            self.phase_two_goal_bias,
            same,
        );
        set_si(
            &mut config.max_turn_per_step_rad,
            self.max_turn_per_step_deg,
            f64::to_radians,
        );
        set_si(
            &mut config.sampling_margin_m,
            self.sampling_margin_nm,
            units::nautical_miles_to_m,
        );
        set_si(&mut config.lookahead_s, self.lookahead_s, same);
        if let Some(budget) = self.time_budget_s {
            config.time_budget_s = Some(budget);
        }
        if let Some(nodes) = self.nodes_per_phase {
            config.nodes_per_phase = nodes;
        }
        if let Some(samples) = self.samples_per_phase {
            config.samples_per_phase = samples;
        }
        if let Some(restarts) = self.max_restarts {
            config.max_restarts = restarts;
        }
        if let Some(index) = self.nearest_index {
            config.nearest_index = index;
        }
        if self.instant_turns == Some(true) {
            config.turning = Turning::Instant;
        }
    }

    /// Replaces the rule constants of `rules` that are set.
    fn apply_rules_to(&self, rules: &mut RuleParameters) {
        set_si(&mut rules.mtd_m, self.mtd_nm, units::nautical_miles_to_m);
        set_si(
            &mut rules.risk_cpa_m,
            self.risk_cpa_nm,
            units::nautical_miles_to_m,
        );
        if let Some(sea_room_nm) = self.sea_room_nm {
            rules.risk_distance.sea_room_m = Some(units::nautical_miles_to_m(sea_room_nm));
        }
        set_si(
            &mut rules.head_on_half_width_rad,
            self.head_on_half_width_deg,
            f64::to_radians,
        );
        set_si(
            &mut rules.abaft_beam_rad,
            self.abaft_beam_deg,
            f64::to_radians,
        );
        set_si(
            &mut rules.passed_angle_rad,
            self.passed_angle_deg,
            f64::to_radians,
        );
        set_si(
            &mut rules.turn_tolerance_rad,
            self.turn_tolerance_deg,
            f64::to_radians,
        );
        set_si(
            &mut rules.stand_on_course_tolerance_rad,
            self.stand_on_course_tolerance_deg,
            f64::to_radians,
        );
        set_si(
            &mut rules.stand_on_speed_tolerance_mps,
            self.stand_on_speed_tolerance_kn,
            units::knots_to_mps,
        );
        set_si(
            &mut rules.stand_on_action_range_m,
            self.stand_on_action_range_nm,
            units::nautical_miles_to_m,
        );
        set_si(
            &mut rules.apparent_turn_rad,
            self.apparent_turn_deg,
            f64::to_radians,
        );
    }
}

/// Sets `target` to `value` converted to SI by `to_si`, when `value` is set.
fn set_si(target: &mut f64, value: Option<f64>, to_si: fn(f64) -> f64) {
    if let Some(value) = value {
        *target = to_si(value);
    }
}

/// A [`PlannerError`] from [`PlannerConfig::validate`] as `(field in the
/// file, problem in file units)`.
pub(crate) fn describe_config_error(error: &PlannerError) -> (String, String) {
    let (field, value, expected): (&str, f64, &str) = match error {
        PlannerError::InvalidConfig {
            field,
            value,
            expected,
        }
        | PlannerError::InvalidRules(vorrt_colregs::ColregsError::InvalidParameter {
            field,
            value,
            expected,
        }) => (field, *value, expected),
        other => return ("planner".to_owned(), other.to_string()),
    };
    let (file_field, file_value, expected) = to_file_units(field, value, expected);
    (
        format!("planner.{file_field}"),
        format!(
            "is {}, expected {expected}",
            vorrt_planner::error::Readable(file_value)
        ),
    )
}

/// The file's name, value and expectation for a [`PlannerConfig`] field.
fn to_file_units(field: &str, value: f64, expected: &str) -> (String, f64, String) {
    match field {
        "max_turn_per_step_rad" => (
            "max_turn_per_step_deg".into(),
            value.to_degrees(),
            "an angle in (0, 180] degrees".into(),
        ),
        "sampling_margin_m" | "mtd_m" | "risk_cpa_m" | "stand_on_action_range_m" => (
            format!("{}_nm", field.trim_end_matches("_m")),
            units::m_to_nautical_miles(value),
            expected.replace("a finite number", "a finite number of nautical miles"),
        ),
        "risk_distance.sea_room_m" => (
            "sea_room_nm".into(),
            units::m_to_nautical_miles(value),
            expected.replace(
                "a finite number of metres",
                "a finite number of nautical miles",
            ),
        ),
        "stand_on_speed_tolerance_mps" => (
            "stand_on_speed_tolerance_kn".into(),
            units::mps_to_knots(value),
            expected.replace("a finite number", "a finite number of knots"),
        ),
        _ if field.ends_with("_rad") => (
            format!("{}_deg", field.trim_end_matches("_rad")),
            value.to_degrees(),
            expected.to_owned(),
        ),
        _ => (field.to_owned(), value, expected.to_owned()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-9 * b.abs().max(1.0)
    }

    #[test]
    fn empty_settings_are_the_default_config() {
        assert!(PlannerSettings::default().is_empty());
        assert_eq!(
            PlannerSettings::default().apply_to(PlannerConfig::default()),
            PlannerConfig::default()
        );
    }

    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn every_field_maps_to_si() {
        let settings = PlannerSettings {
            clearance_m: Some(100.0),
            preferred_clearance_factor: Some(1.5),
            step_m: Some(50.0),
            goal_tolerance_m: Some(60.0),
            goal_bias: Some(0.3),
            phase_two_goal_bias: Some(0.1),
            nodes_per_phase: Some(600),
            samples_per_phase: Some(9000),
            nodes_per_route_step: Some(4.0),
            max_restarts: Some(5),
            max_turn_per_step_deg: Some(30.0),
            sampling_margin_nm: Some(1.5),
            lookahead_s: Some(900.0),
            time_budget_s: Some(2.0),
            nearest_index: Some(NearestIndex::RTree),
            mtd_nm: Some(4.0),
            risk_cpa_nm: Some(0.5),
            sea_room_nm: Some(0.8),
            head_on_half_width_deg: Some(10.0),
            abaft_beam_deg: Some(110.0),
            passed_angle_deg: Some(100.0),
            turn_tolerance_deg: Some(3.0),
            stand_on_course_tolerance_deg: Some(12.0),
            stand_on_speed_tolerance_kn: Some(2.0),
            stand_on_action_range_nm: Some(1.5),
            apparent_turn_deg: Some(35.0),
            instant_turns: Some(true),
        };
        assert_eq!(settings.set_numbers().len(), 22);
        let config = settings.apply_to(PlannerConfig::default());
        config.validate().expect("valid");
        assert_eq!(config.clearance_m, 100.0);
        assert_eq!(config.preferred_clearance_factor, 1.5);
        assert_eq!(config.step_m, 50.0);
        assert_eq!(config.goal_tolerance_m, 60.0);
        assert_eq!(config.nodes_per_route_step, 4.0);
        assert_eq!(config.turning, Turning::Instant);
        assert_eq!(config.goal_bias, 0.3);
        assert_eq!(config.phase_two_goal_bias, 0.1);
        assert_eq!(config.nodes_per_phase, 600);
        assert_eq!(config.samples_per_phase, 9000);
        assert_eq!(config.max_restarts, 5);
        assert!(close(config.max_turn_per_step_rad, 30f64.to_radians()));
        assert!(close(config.sampling_margin_m, 1.5 * 1852.0));
        assert_eq!(config.lookahead_s, 900.0);
        assert_eq!(config.time_budget_s, Some(2.0));
        assert_eq!(config.nearest_index, NearestIndex::RTree);
        let rules = config.rules;
        assert!(close(rules.mtd_m, 4.0 * 1852.0));
        assert!(close(rules.risk_cpa_m, 926.0));
        assert!(close(
            rules.risk_distance.sea_room_m.expect("set"),
            0.8 * 1852.0
        ));
        assert!(close(rules.risk_distance.clearance_floor_m, 100.0));
        assert!(close(rules.head_on_half_width_rad, 10f64.to_radians()));
        assert!(close(rules.abaft_beam_rad, 110f64.to_radians()));
        assert!(close(rules.passed_angle_rad, 100f64.to_radians()));
        assert!(close(rules.turn_tolerance_rad, 3f64.to_radians()));
        assert!(close(
            rules.stand_on_course_tolerance_rad,
            12f64.to_radians()
        ));
        assert!(close(
            rules.stand_on_speed_tolerance_mps,
            2.0 * 1852.0 / 3600.0
        ));
        assert!(close(rules.stand_on_action_range_m, 1.5 * 1852.0));
        assert!(close(rules.apparent_turn_rad, 35f64.to_radians()));
    }

    #[test]
    fn config_errors_are_named_in_file_units() {
        let bad = |settings: PlannerSettings| {
            let error = settings
                .apply_to(PlannerConfig::default())
                .validate()
                .expect_err("invalid");
            describe_config_error(&error)
        };
        let (field, problem) = bad(PlannerSettings {
            sampling_margin_nm: Some(-2.0),
            ..PlannerSettings::default()
        });
        assert_eq!(field, "planner.sampling_margin_nm");
        assert!(problem.starts_with("is -2,"), "{problem}");
        let (field, problem) = bad(PlannerSettings {
            stand_on_speed_tolerance_kn: Some(-1.0),
            ..PlannerSettings::default()
        });
        assert_eq!(field, "planner.stand_on_speed_tolerance_kn");
        assert!(problem.starts_with("is -1,"), "{problem}");
        let (field, problem) = bad(PlannerSettings {
            abaft_beam_deg: Some(45.0),
            ..PlannerSettings::default()
        });
        assert_eq!(field, "planner.abaft_beam_deg");
        assert!(problem.starts_with("is 45"), "{problem}");
        let (field, _) = bad(PlannerSettings {
            samples_per_phase: Some(10),
            ..PlannerSettings::default()
        });
        assert_eq!(field, "planner.samples_per_phase");
    }
}
