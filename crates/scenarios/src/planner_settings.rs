//! The `planner` section of a scenario file: [`PlannerConfig`] in file units.

use serde::{Deserialize, Serialize};
use vorrt_geometry::units;
use vorrt_planner::{NearestIndex, PlannerConfig, PlannerError};

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
    /// Restarts after both phases fail (default 3).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_restarts: Option<usize>,
    /// Largest course change at one node, degrees (default 45).
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
            ("step_m", self.step_m),
            ("goal_tolerance_m", self.goal_tolerance_m),
            ("goal_bias", self.goal_bias),
            ("phase_two_goal_bias", self.phase_two_goal_bias),
            ("max_turn_per_step_deg", self.max_turn_per_step_deg),
            ("sampling_margin_nm", self.sampling_margin_nm),
            ("lookahead_s", self.lookahead_s),
            ("time_budget_s", self.time_budget_s),
            ("mtd_nm", self.mtd_nm),
            ("risk_cpa_nm", self.risk_cpa_nm),
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
        let set = |target: &mut f64, value: Option<f64>, to_si: fn(f64) -> f64| {
            if let Some(value) = value {
                *target = to_si(value);
            }
        };
        let same = |value: f64| value;
        set(&mut config.clearance_m, self.clearance_m, same);
        set(&mut config.step_m, self.step_m, same);
        set(&mut config.goal_tolerance_m, self.goal_tolerance_m, same);
        set(&mut config.goal_bias, self.goal_bias, same);
        set(
            &mut config.phase_two_goal_bias,
            self.phase_two_goal_bias,
            same,
        );
        set(
            &mut config.max_turn_per_step_rad,
            self.max_turn_per_step_deg,
            f64::to_radians,
        );
        set(
            &mut config.sampling_margin_m,
            self.sampling_margin_nm,
            units::nautical_miles_to_m,
        );
        set(&mut config.lookahead_s, self.lookahead_s, same);
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
        let rules = &mut config.rules;
        set(&mut rules.mtd_m, self.mtd_nm, units::nautical_miles_to_m);
        set(
            &mut rules.risk_cpa_m,
            self.risk_cpa_nm,
            units::nautical_miles_to_m,
        );
        set(
            &mut rules.head_on_half_width_rad,
            self.head_on_half_width_deg,
            f64::to_radians,
        );
        set(
            &mut rules.abaft_beam_rad,
            self.abaft_beam_deg,
            f64::to_radians,
        );
        set(
            &mut rules.passed_angle_rad,
            self.passed_angle_deg,
            f64::to_radians,
        );
        set(
            &mut rules.turn_tolerance_rad,
            self.turn_tolerance_deg,
            f64::to_radians,
        );
        set(
            &mut rules.stand_on_course_tolerance_rad,
            self.stand_on_course_tolerance_deg,
            f64::to_radians,
        );
        set(
            &mut rules.stand_on_speed_tolerance_mps,
            self.stand_on_speed_tolerance_kn,
            units::knots_to_mps,
        );
        set(
            &mut rules.stand_on_action_range_m,
            self.stand_on_action_range_nm,
            units::nautical_miles_to_m,
        );
        set(
            &mut rules.apparent_turn_rad,
            self.apparent_turn_deg,
            f64::to_radians,
        );
        config
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
        } => (field, *value, expected),
        PlannerError::InvalidRules(vorrt_colregs::ColregsError::InvalidParameter {
            field,
            value,
            expected,
        }) => (field, *value, expected),
        other => return ("planner".to_owned(), other.to_string()),
    };
    let (file_field, file_value, expected) = to_file_units(field, value, expected);
    (
        format!("planner.{file_field}"),
        format!("is {file_value}, expected {expected}"),
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
