//! The command line's JSON outputs: `report.json` of a run ([`Report`]) and
//! the plan printed by `vorrt plan` ([`PlanOutput`]).
//!
//! These structs are the schema, documented field by field in
//! `docs/report-format.md`; they are filled from the library's types but do
//! not expose them, so that the files stay stable when the library changes.
//! Distances are metres, times seconds, angles degrees clockwise from north,
//! positions `east`/`north` metres in the scenario's frame.

use serde::{Deserialize, Serialize};
use vorrt_colregs::StandOnDeparture;
use vorrt_geometry::units;
use vorrt_planner::{Plan, PlanStatistics, RejectionCounts, Waypoint};
use vorrt_scenarios::{
    Evaluation, PlanEvent, PlanTrigger, Scenario, SimulationRecord, TargetEvaluation,
};

/// The version of the report and plan schemas; raised on any incompatible change.
pub const FORMAT_VERSION: u32 = 1;

/// `report.json`: how one closed-loop run fared.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[expect(
    clippy::struct_excessive_bools,
    reason = "plain data: the documented yes/no fields of report.json"
)]
pub struct Report {
    /// Schema version, [`FORMAT_VERSION`].
    pub format_version: u32,
    /// The scenario's name.
    pub scenario: String,
    /// The scenario file the run was made from.
    pub scenario_file: String,
    /// The planner seed of the run.
    pub seed: u64,
    /// The clearance `d_th` the run is judged against, metres.
    pub d_th_m: f64,
    /// Whether ownship reached its goal.
    pub reached_goal: bool,
    /// When it did, seconds (`null` if it did not).
    pub arrival_time_s: Option<f64>,
    /// Whether any two hulls touched (centres closer than half the two lengths added).
    pub collision: bool,
    /// Smallest distance from ownship to any target, metres (`null` with no targets).
    pub min_distance_m: Option<f64>,
    /// Whether every target stayed at least `d_th_m` away.
    pub clearance_kept: bool,
    /// Whether ownship's track touched or crossed land (a safety failure
    /// beside a collision; decision 29).
    pub grounding: bool,
    /// The least distance from ownship's track to land, metres, measured
    /// along the curve sailed (`null` when the scenario has no land).
    pub min_land_distance_m: Option<f64>,
    /// The clearance from land the track is judged against
    /// (`land_clearance_m`), metres (`null` with no land).
    pub land_clearance_m: Option<f64>,
    /// Whether the track kept `land_clearance_m` from land (true with no land).
    pub land_clearance_kept: bool,
    /// Whether ownship obeyed COLREGs in every encounter, judged on the
    /// track as observed: no finding (see `docs/evaluation.md`, "Judging the
    /// track as observed").
    pub compliant: bool,
    /// Ownship's path quality as sailed.
    pub path_quality: PathQualityReport,
    /// `reached_goal && !collision && clearance_kept && !grounding &&
    /// land_clearance_kept`: the run succeeded
    /// (`vorrt_scenarios::Evaluation::success`; exit code 0 of `vorrt simulate`).
    pub reached_goal_safely: bool,
    /// Planner calls during the run.
    pub planning: PlanningReport,
    /// Every planner call, in time order: why, where its plan came from and
    /// the plan's waypoints.
    pub plans: Vec<PlanEventReport>,
    /// Length of ownship's sailed track, metres.
    pub path_length_m: f64,
    /// Straight-line distance from ownship's start to its goal, metres.
    pub straight_length_m: f64,
    /// Extra length over the straight route, percent.
    pub path_overhead_pct: f64,
    /// Time to the goal (or to the end of the run), seconds.
    pub duration_s: f64,
    /// Time the straight route takes at ownship's service speed (its speed
    /// at the start), seconds.
    pub straight_duration_s: f64,
    /// Extra time over the straight route at the service speed, percent
    /// (`vorrt_scenarios::Evaluation::time_overhead_pct`): slowing down
    /// shows here, not in the path overhead.
    pub time_overhead_pct: f64,
    /// The simulation time step, seconds.
    pub time_step_s: f64,
    /// Per target, in scenario order.
    pub targets: Vec<TargetReport>,
    /// Rule 10 (traffic separation schemes) on ownship's track; absent
    /// when the scenario has no lane and no separation zone.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rule10: Option<Rule10Report>,
}

/// Rule 10 on ownship's track (`docs/evaluation.md`, "Rule 10").
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Rule10Report {
    /// No finding on the track as sailed (its heading): part of `compliant`.
    pub clean: bool,
    /// Every crossing of a lane, as sailed.
    pub crossings: Vec<LaneCrossingReport>,
    /// Every finding as sailed, as text naming the clause.
    pub findings: Vec<String>,
    /// Every finding on the track as observed (course over ground over the
    /// observation window), as text; reported, not part of `compliant`.
    pub observed_findings: Vec<String>,
}

/// One crossing of a lane.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LaneCrossingReport {
    /// The lane's index in the scenario's `lanes`.
    pub lane: usize,
    /// The first sample inside the lane, seconds.
    pub entry_time_s: f64,
    /// The last sample inside it, seconds.
    pub exit_time_s: f64,
    /// The largest angle of the heading from perpendicular to the flow, degrees.
    pub max_off_perpendicular_deg: f64,
    /// Whether it stayed within the crossing tolerance (rule 10(c)).
    pub square: bool,
}

impl Rule10Report {
    /// The rule-10 part of `evaluation`, or `None` when `scenario` has no scheme.
    #[must_use]
    pub fn new(scenario: &Scenario, evaluation: &Evaluation) -> Option<Self> {
        if scenario.lanes.is_empty() && scenario.separation_zones.is_empty() {
            return None;
        }
        let text = |judgement: &vorrt_scenarios::colregs::rule10::Rule10Judgement| {
            judgement.findings.iter().map(ToString::to_string).collect()
        };
        Some(Self {
            clean: evaluation.rule10.is_clean(),
            crossings: evaluation
                .rule10
                .crossings
                .iter()
                .map(|crossing| LaneCrossingReport {
                    lane: crossing.lane,
                    entry_time_s: crossing.entry_time_s,
                    exit_time_s: crossing.exit_time_s,
                    max_off_perpendicular_deg: crossing.max_off_perpendicular_deg,
                    square: crossing.square,
                })
                .collect(),
            findings: text(&evaluation.rule10),
            observed_findings: text(&evaluation.rule10_observed),
        })
    }

    /// Appends the "rule 10" lines that `simulate` and `judge` print.
    pub(crate) fn write_lines(&self, text: &mut String) {
        use std::fmt::Write as _;
        let square = self.crossings.iter().filter(|c| c.square).count();
        let worst = self
            .crossings
            .iter()
            .map(|c| c.max_off_perpendicular_deg)
            .fold(0.0, f64::max);
        let _ = writeln!(
            text,
            "rule 10:        {} lane crossings, {square} square (worst {worst:.1}° off perpendicular); {}",
            self.crossings.len(),
            if self.clean {
                "no finding"
            } else {
                "findings:"
            }
        );
        for finding in &self.findings {
            let _ = writeln!(text, "                - {finding}");
        }
        for finding in &self.observed_findings {
            let _ = writeln!(text, "                - as observed: {finding}");
        }
    }
}

/// Ownship's path quality as sailed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PathQualityReport {
    /// The largest rate of turn between consecutive samples, degrees per second.
    pub max_turn_rate_deg_s: f64,
    /// Ownship's rate-of-turn limit, degrees per second (`null`: instantaneous turns).
    pub turn_rate_limit_deg_s: Option<f64>,
    /// Turn-direction reversals: successive turn episodes (each a detectable
    /// change of more than 2°) turning opposite ways.
    pub turn_reversals: usize,
    /// Total course change per nautical mile sailed, degrees.
    pub course_change_deg_per_nm: f64,
    /// Findings about the track as a whole (a rate of turn above the limit).
    pub findings: Vec<String>,
}

/// Planner calls of a run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PlanningReport {
    /// Calls that returned a plan.
    pub plans_made: usize,
    /// Calls after the first (successful or not).
    pub replans: usize,
    /// Calls that found no plan.
    pub failed_plans: usize,
    /// Wall-clock time spent in the planner over the run, seconds.
    pub total_planning_time_s: f64,
}

/// One planner call of a run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PlanEventReport {
    /// Simulation time of the call, seconds.
    pub time_s: f64,
    /// Why ownship planned: `initial`, `target_off_prediction`,
    /// `new_encounter`, `prediction_changed`, `retry` or `past_and_clear`.
    pub trigger: String,
    /// Whether a plan came back.
    pub succeeded: bool,
    /// Where ownship's course came from: the planner's search
    /// (`one_alteration` or `two_alterations` from the root, `tree`), or on
    /// failure `evasive` (the evasive manoeuvre) or `previous_plan` (the
    /// plan in force kept: still valid, `full`; or held as the manoeuvre
    /// under way when no evasive course is clearly better, `safety_only`,
    /// decision 56).
    pub source: String,
    /// The COLREGs duties the plan keeps: `full`, or the graded fallback
    /// level `directions` or `safety_only` (an evasive manoeuvre is
    /// `safety_only`).
    pub compliance: String,
    /// The plan's waypoints (empty on failure).
    pub waypoints: Vec<WaypointOutput>,
}

impl PlanEventReport {
    /// The report of one planner call.
    #[must_use]
    pub fn new(event: &PlanEvent) -> Self {
        let source = if event.succeeded {
            event.statistics.source.key()
        } else if event.evasive_course_deg.is_some() {
            "evasive"
        } else {
            "previous_plan"
        };
        let trigger = match event.trigger {
            PlanTrigger::Initial => "initial",
            PlanTrigger::TargetOffPrediction { .. } => "target_off_prediction",
            PlanTrigger::NewEncounter { .. } => "new_encounter",
            PlanTrigger::PredictionChanged { .. } => "prediction_changed",
            PlanTrigger::Retry => "retry",
            PlanTrigger::PastAndClear => "past_and_clear",
            PlanTrigger::LateArrival => "late_arrival",
        };
        Self {
            time_s: event.time_s,
            trigger: trigger.to_owned(),
            succeeded: event.succeeded,
            source: source.to_owned(),
            compliance: serde_json::to_value(event.compliance)
                .ok()
                .and_then(|value| value.as_str().map(str::to_owned))
                .unwrap_or_default(),
            waypoints: waypoint_outputs(&event.waypoints, &event.speeds_mps),
        }
    }
}

/// The waypoints of a plan as written, each with its planned speed
/// (`planned_mps[i]`; not a number, written `null`, where none was recorded).
fn waypoint_outputs(waypoints: &[Waypoint], planned_mps: &[f64]) -> Vec<WaypointOutput> {
    waypoints
        .iter()
        .enumerate()
        .map(|(index, waypoint)| {
            let speed_mps = planned_mps.get(index).copied().unwrap_or(f64::NAN);
            WaypointOutput {
                time_s: waypoint.time_s,
                east_m: waypoint.position_m.x,
                north_m: waypoint.position_m.y,
                course_deg: waypoint.course_rad.to_degrees().rem_euclid(360.0),
                speed_mps,
                speed_kn: units::mps_to_knots(speed_mps),
            }
        })
        .collect()
}

/// How ownship fared against one target.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TargetReport {
    /// The target's name.
    pub name: String,
    /// The encounter when risk of collision first arose: `head_on`,
    /// `crossing_give_way`, `crossing_stand_on`, `overtaking`,
    /// `being_overtaken`, or `none` if risk never arose.
    pub encounter: String,
    /// Ownship's role: `give_way`, `stand_on` or `none`.
    pub role: String,
    /// When risk of collision first arose, seconds (`null` if never).
    pub risk_time_s: Option<f64>,
    /// Smallest distance between ownship and the target, metres.
    pub min_distance_m: f64,
    /// When it occurred, seconds.
    pub time_of_min_s: f64,
    /// Whether the minimum distance kept `d_th`.
    pub clearance_kept: bool,
    /// Whether the hulls touched.
    pub collision: bool,
    /// Whether ownship's action obeyed every rule that applied.
    pub compliant: bool,
    /// Every rule broken and clearance finding, as text naming the rule.
    pub violations: Vec<String>,
    /// Overall score in `[0, 1]`: safety times every applicable rule score.
    pub score: f64,
    /// The findings' names (`late_action`, `small_alterations`, ...), in the
    /// order of `violations`.
    pub findings: Vec<String>,
    /// Range at which the give-way action began as observed, metres
    /// (`null`: none, or not giving way).
    pub action_range_m: Option<f64>,
    /// First observed alteration (at the 5° detection threshold), degrees,
    /// positive to starboard (`null`: none).
    pub first_alteration_deg: Option<f64>,
    /// Largest observed course change before the closest approach, degrees,
    /// positive to starboard (`null`: no encounter).
    pub max_alteration_deg: Option<f64>,
    /// Standing on, the departures from the course or speed to keep while
    /// this vessel was beyond the stand-on action range: the first justified
    /// by each other vessel whose duty took precedence, and the first
    /// unjustified one (a finding); empty when course and speed were kept
    /// (decision 45).
    #[serde(default)]
    pub stand_on_departures: Vec<StandOnDepartureReport>,
    /// Why the encounter is undecided, in words (tracks recorded at sea:
    /// still closing when the tracks end, a reported rest her motion
    /// contradicts, a closest approach she did not report; decisions 32 and
    /// 49); absent when decided.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub undecided: Option<String>,
}

/// A stand-on departure before the action range, and the duty toward
/// another vessel that took precedence, if one did.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StandOnDepartureReport {
    /// When ownship was first seen off its course or speed, seconds.
    pub time_s: f64,
    /// The range to this vessel then, metres.
    pub range_m: f64,
    /// The course change from the course to keep, degrees, positive to
    /// starboard.
    pub course_change_deg: f64,
    /// The speed change from the reference speed, m/s (negative: slower).
    pub speed_change_mps: f64,
    /// Whether a duty toward another vessel justified it (no finding).
    pub justified: bool,
    /// The duty that took precedence: `keep_out_of_the_way` (rules 16,
    /// 2(b)) or `stand_on_may_act` (17(a)(ii), 2(b)); `null` when none did.
    pub precedence: Option<String>,
    /// The rules that let it take precedence over rule 17(a)(i).
    pub rule: Option<String>,
    /// The other vessel's name.
    pub other_vessel: Option<String>,
    /// Ownship's encounter with the other vessel (`crossing_give_way`, ...).
    pub other_encounter: Option<String>,
    /// The range to the other vessel then, metres.
    pub other_range_m: Option<f64>,
}

impl StandOnDepartureReport {
    /// The report of one departure.
    #[must_use]
    pub fn new(departure: &StandOnDeparture) -> Self {
        let precedence = departure.precedence.as_ref();
        Self {
            time_s: departure.time_s,
            range_m: departure.range_m,
            course_change_deg: departure.course_change_rad.to_degrees(),
            speed_change_mps: departure.speed_change_mps,
            justified: precedence.is_some(),
            precedence: precedence.map(|p| p.duty.name().to_owned()),
            rule: precedence.map(|p| p.rule.clone()),
            other_vessel: precedence.map(|p| p.vessel_name.clone()),
            other_encounter: precedence.map(|p| p.encounter.name().to_owned()),
            other_range_m: precedence.map(|p| p.range_m),
        }
    }
}

impl Report {
    /// The report of a run of `scenario` recorded in `record` and judged in `evaluation`.
    #[must_use]
    pub fn new(scenario: &Scenario, record: &SimulationRecord, evaluation: &Evaluation) -> Self {
        Self {
            format_version: FORMAT_VERSION,
            scenario: evaluation.scenario.clone(),
            scenario_file: scenario.source.clone(),
            seed: evaluation.seed,
            d_th_m: evaluation.clearance_m,
            reached_goal: evaluation.reached_goal,
            arrival_time_s: record.arrival_time_s,
            collision: evaluation.collision,
            min_distance_m: evaluation
                .min_distance_m
                .is_finite()
                .then_some(evaluation.min_distance_m),
            clearance_kept: evaluation.clearance_kept,
            grounding: evaluation.grounding,
            min_land_distance_m: evaluation.min_land_distance_m,
            land_clearance_m: evaluation.land_clearance_m,
            land_clearance_kept: evaluation.land_clearance_kept,
            compliant: evaluation.compliant,
            path_quality: PathQualityReport {
                max_turn_rate_deg_s: evaluation.max_turn_rate_deg_s,
                turn_rate_limit_deg_s: evaluation.turn_rate_limit_deg_s,
                turn_reversals: evaluation.turn_reversals,
                course_change_deg_per_nm: evaluation.course_change_deg_per_nm,
                findings: evaluation.track_findings.clone(),
            },
            reached_goal_safely: evaluation.success(),
            planning: PlanningReport {
                plans_made: evaluation.plans_made,
                replans: evaluation.replans,
                failed_plans: evaluation.failed_plans,
                total_planning_time_s: evaluation.planning_time_s,
            },
            plans: record.plans.iter().map(PlanEventReport::new).collect(),
            path_length_m: evaluation.path_length_m,
            straight_length_m: evaluation.straight_length_m,
            path_overhead_pct: evaluation.path_overhead_pct,
            duration_s: evaluation.duration_s,
            straight_duration_s: evaluation.straight_duration_s,
            time_overhead_pct: evaluation.time_overhead_pct,
            time_step_s: record.time_step_s,
            targets: evaluation.targets.iter().map(TargetReport::new).collect(),
            rule10: Rule10Report::new(scenario, evaluation),
        }
    }
}

impl TargetReport {
    /// The report of one target's evaluation.
    #[must_use]
    pub fn new(target: &TargetEvaluation) -> Self {
        Self {
            name: target.name.clone(),
            encounter: target.encounter.name().to_owned(),
            role: target.role.name().to_owned(),
            risk_time_s: target.risk_time_s,
            min_distance_m: target.min_distance_m,
            time_of_min_s: target.time_of_min_s,
            clearance_kept: target.clearance_kept,
            collision: target.collision,
            compliant: target.compliant,
            violations: target.violations.clone(),
            score: target.score,
            findings: target
                .findings
                .iter()
                .map(|finding| finding.name().to_owned())
                .collect(),
            action_range_m: target.action_range_m,
            first_alteration_deg: target.first_alteration_deg,
            max_alteration_deg: target.max_alteration_deg,
            stand_on_departures: target
                .assessment
                .iter()
                .flat_map(|a| &a.stand_on_departures)
                .map(StandOnDepartureReport::new)
                .collect(),
            undecided: target.undecided.map(|why| why.to_string()),
        }
    }
}

/// What `vorrt plan` prints: one plan from the start state.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PlanOutput {
    /// Schema version, [`FORMAT_VERSION`].
    pub format_version: u32,
    /// The scenario's name.
    pub scenario: String,
    /// The scenario file.
    pub scenario_file: String,
    /// The planner seed.
    pub seed: u64,
    /// The clearance `d_th`, metres.
    pub d_th_m: f64,
    /// Path length, metres.
    pub length_m: f64,
    /// Time from the first to the last waypoint, seconds.
    pub duration_s: f64,
    /// Which search found the plan: `one_alteration` or `two_alterations`
    /// (the manoeuvre search from the root), or `tree`.
    pub source: String,
    /// From ownship's start (first) to its goal (last).
    pub waypoints: Vec<WaypointOutput>,
    /// What the search did.
    pub statistics: StatisticsOutput,
}

/// One waypoint of a plan.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct WaypointOutput {
    /// When ownship is here, seconds from the start.
    pub time_s: f64,
    /// Position east, metres.
    pub east_m: f64,
    /// Position north, metres.
    pub north_m: f64,
    /// Course on the leg that ends here (the start course at the first
    /// waypoint), degrees clockwise from north in `[0, 360)`.
    pub course_deg: f64,
    /// Planned speed here (at the end of the leg that ends here; the start
    /// speed at the first waypoint), metres per second.
    pub speed_mps: f64,
    /// The same speed, knots.
    pub speed_kn: f64,
}

/// Search statistics of one planner call.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct StatisticsOutput {
    /// Nodes in the tree that produced the plan.
    pub nodes: u64,
    /// Samples drawn, accepted or not, over all restarts.
    pub samples: u64,
    /// Times the tree was grown again from the root.
    pub restarts: u64,
    /// Wall-clock planning time, seconds.
    pub planning_time_s: f64,
    /// Rejected samples, one count per cause of the planner's validity
    /// check (`vorrt_planner::RejectionCause::ALL`, named by its key).
    pub rejections: RejectionCounts,
}

impl From<&PlanStatistics> for StatisticsOutput {
    fn from(statistics: &PlanStatistics) -> Self {
        Self {
            nodes: statistics.nodes,
            samples: statistics.samples,
            restarts: statistics.restarts,
            planning_time_s: statistics.elapsed_s,
            rejections: statistics.rejections,
        }
    }
}

impl PlanOutput {
    /// The output for `plan`, planned for `scenario` with `seed`.
    #[must_use]
    pub fn new(scenario: &Scenario, seed: u64, d_th_m: f64, plan: &Plan) -> Self {
        Self {
            format_version: FORMAT_VERSION,
            scenario: scenario.name.clone(),
            scenario_file: scenario.source.clone(),
            seed,
            d_th_m,
            length_m: plan.length_m(),
            duration_s: plan.duration_s(),
            source: plan.statistics.source.key().to_owned(),
            waypoints: waypoint_outputs(&plan.waypoints, &plan.waypoint_speeds_mps()),
            statistics: StatisticsOutput::from(&plan.statistics),
        }
    }
}

impl Report {
    /// Appends the per-target table that `simulate` and `judge` print: one
    /// line per target (encounter, role, closest approach, compliance,
    /// score), each finding on a line of its own under it.
    pub(crate) fn write_target_table(&self, text: &mut String) {
        use std::fmt::Write as _;
        let name_width = self
            .targets
            .iter()
            .map(|target| target.name.chars().count())
            .chain([6])
            .max()
            .unwrap_or(6);
        let _ = writeln!(
            text,
            "\n{:<name_width$}  {:<17}  {:<8}  {:>10}  {:>10}  {:<9}  {:>5}",
            "target", "encounter", "role", "min dist m", "at min", "compliant", "score"
        );
        for target in &self.targets {
            let _ = writeln!(
                text,
                "{:<name_width$}  {:<17}  {:<8}  {:>10.1}  {:>6.1} min  {:<9}  {:>5.2}",
                target.name,
                target.encounter,
                target.role,
                target.min_distance_m,
                target.time_of_min_s / 60.0,
                if target.undecided.is_some() {
                    "undecided"
                } else {
                    yes_no(target.compliant)
                },
                target.score
            );
            for violation in &target.violations {
                let _ = writeln!(text, "{:<name_width$}    - {violation}", "");
            }
        }
        if self.targets.is_empty() {
            let _ = writeln!(text, "(no targets)");
        }
    }
}

impl Report {
    /// Appends the "min distance" and "COLREGs" lines that `simulate` and
    /// `judge` print under the target table.
    pub(crate) fn write_safety_lines(&self, text: &mut String) {
        use std::fmt::Write as _;
        let minimum = match self.min_distance_m {
            Some(distance) => format!(
                "{distance:.1} m vs d_th {:.0} m: {}",
                self.d_th_m,
                if self.clearance_kept {
                    "kept"
                } else {
                    "BROKEN"
                }
            ),
            None => "- (no targets)".to_owned(),
        };
        let _ = writeln!(text, "min distance:   {minimum}");
        if let (Some(distance), Some(clearance)) = (self.min_land_distance_m, self.land_clearance_m)
        {
            let _ = writeln!(
                text,
                "land:           {distance:.1} m vs land clearance {clearance:.0} m: {}",
                if self.grounding {
                    "GROUNDING"
                } else if self.land_clearance_kept {
                    "kept"
                } else {
                    "BROKEN"
                }
            );
        }
        let _ = writeln!(
            text,
            "COLREGs:        {}",
            if self.compliant {
                "compliant"
            } else {
                "violated"
            }
        );
    }
}

impl Report {
    /// Appends the "path" and "time" lines that `simulate` and `judge` print:
    /// the sailed length and the time taken, each against the straight
    /// route (at the service speed, for the time) with its overhead.
    pub(crate) fn write_overhead_lines(&self, text: &mut String) {
        use std::fmt::Write as _;
        let _ = writeln!(
            text,
            "path:           {:.0} m sailed vs {:.0} m straight: overhead {:.1} %",
            self.path_length_m, self.straight_length_m, self.path_overhead_pct
        );
        let _ = writeln!(
            text,
            "time:           {:.1} min vs {:.1} min straight at the service speed: overhead {:.1} %",
            self.duration_s / 60.0,
            self.straight_duration_s / 60.0,
            self.time_overhead_pct
        );
    }
}

/// "yes" or "no", for the console tables.
pub(crate) fn yes_no(value: bool) -> &'static str {
    if value { "yes" } else { "no" }
}
