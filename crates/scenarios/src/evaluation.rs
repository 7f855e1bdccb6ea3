//! Evaluation of a closed-loop run: did ownship arrive, how close did every
//! target come, did it obey COLREGs, and how seamanlike was its track?
//!
//! The run is judged **as sailed and as observed**, by the one judgement of
//! recorded tracks, `vorrt_colregs::observed::judge`: every vessel's course
//! and speed over ground observed over a 60 s window (as another vessel's
//! radar or AIS shows them), ownship's path quality (largest rate of turn,
//! turn-direction reversals, course change per nautical mile), and per
//! target the encounter latched on the observed states and assessed with
//! the published evaluators' criteria (Woerner 2019, Minne 2017, the NTNU
//! evaluator): action begun, early, readily apparent, first alteration to
//! starboard, held until the closest approach, no succession of small
//! alterations (rule 8(b)), stand-on kept (rule 17), with every finding named
//! and per-rule scores. A target with which no risk of collision ever arose
//! is judged on clearance alone. Definitions and parameters are in
//! `docs/evaluation.md`, "Judging the track as observed".
//!
//! The clearance `d_th` and the rule constants are those the run was made
//! with (`SimulationRecord::config`), and the rate-of-turn limit is the one
//! ownship sailed under (`SimulationRecord::max_turn_rate_rad_s`).
//!
//! Several targets at once: a vessel that must give way to one target cannot
//! also keep its course for another. While ownship has to give way to some
//! target, its stand-on encounters are judged as ones in which it may act
//! (rule 17(a)(ii)): an early course or speed change is not held against it,
//! a port turn for a vessel on its port side still is (rule 17(c)). The
//! planner applies the same reading (`vorrt_colregs::check_maneuver_acting`).
//! Each such departure before the action range is listed on the assessment
//! with the duty that took precedence, the other vessel and the rule
//! (`EncounterAssessment::stand_on_departures`, decision 45).

use crate::chart::Chart;
use crate::scenario::Scenario;
use crate::simulation::SimulationRecord;
use serde::{Deserialize, Serialize};
use vorrt_colregs::observed::{
    NavigationalStatus, ObservedEncounter, ObservedJudgement, ObservedParameters, RecordedTrack,
    Recording, TrackNoise, Undecided, judge,
};
use vorrt_colregs::rule10::{Rule10Judgement, judge_track};
use vorrt_colregs::{
    ComplianceViolation, Encounter, EncounterAssessment, Role, RuleParameters, ScoringParameters,
};

/// How ownship fared against one target.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TargetEvaluation {
    /// The target's name.
    pub name: String,
    /// The encounter type when risk first arose (`None` if it never did).
    pub encounter: Encounter,
    /// Ownship's role in it.
    pub role: Role,
    /// When risk first arose, seconds.
    pub risk_time_s: Option<f64>,
    /// Smallest distance between the two, metres.
    pub min_distance_m: f64,
    /// When it occurred, seconds.
    pub time_of_min_s: f64,
    /// Whether the minimum distance kept the clearance `d_th`.
    pub clearance_kept: bool,
    /// Whether the hulls touched: centres closer than half the two lengths added.
    pub collision: bool,
    /// Whether ownship's action obeyed every rule that applied.
    pub compliant: bool,
    /// Every finding under the observed evaluation (rules broken, and the
    /// clearance findings), as text naming the rule.
    pub violations: Vec<String>,
    /// The same findings, typed.
    pub findings: Vec<ComplianceViolation>,
    /// Range at which ownship's give-way action began as observed, metres
    /// (`None`: no action, or not giving way).
    pub action_range_m: Option<f64>,
    /// The first observed alteration (the course change at the first sample
    /// at or beyond the 5° detection threshold), degrees, positive to
    /// starboard.
    pub first_alteration_deg: Option<f64>,
    /// The largest observed course change from the reference course before
    /// the closest approach, degrees, positive to starboard.
    pub max_alteration_deg: Option<f64>,
    /// The overall score in `[0, 1]`: safety times every applicable rule score.
    pub score: f64,
    /// The full assessment on the observed states (`None` when no
    /// encounter arose).
    pub assessment: Option<EncounterAssessment>,
    /// The navigational status the target reported (tracks recorded at
    /// sea); at anchor, moored or aground it was judged as a stationary
    /// obstacle, on clearance alone.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub status: Option<NavigationalStatus>,
    /// Why the recording cannot decide the encounter, if it cannot (still
    /// closing when the tracks ended, a reported rest her motion
    /// contradicts, a closest approach she did not report: decisions 32 and
    /// 49): its clearance and passing are not a verdict.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub undecided: Option<Undecided>,
}

/// How a whole run fared.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[expect(
    clippy::struct_excessive_bools,
    reason = "a plain record of documented outcome flags"
)]
pub struct Evaluation {
    /// The scenario's name.
    pub scenario: String,
    /// The planner seed of the run.
    pub seed: u64,
    /// The clearance `d_th` judged against, metres.
    pub clearance_m: f64,
    /// Whether ownship reached its goal.
    pub reached_goal: bool,
    /// Whether any hull touched another.
    pub collision: bool,
    /// Smallest distance to any target, metres (infinite with no target).
    pub min_distance_m: f64,
    /// Whether every target kept `d_th`.
    pub clearance_kept: bool,
    /// The least distance from ownship's track to land, metres (`None`:
    /// the scenario has no land); measured along the curve sailed
    /// ([`Chart::judge_track`]).
    #[serde(default)]
    pub min_land_distance_m: Option<f64>,
    /// The clearance from land judged against (`land_clearance_m`), metres
    /// (`None`: no land).
    #[serde(default)]
    pub land_clearance_m: Option<f64>,
    /// Whether ownship's track touched or crossed land: a safety failure
    /// beside a collision (decision 29).
    #[serde(default)]
    pub grounding: bool,
    /// Whether the track kept `land_clearance_m` from land (true with no
    /// land).
    #[serde(default = "kept")]
    pub land_clearance_kept: bool,
    /// No finding under the observed evaluation: no rule broken in any
    /// encounter and no track finding.
    pub compliant: bool,
    /// Ownship's largest rate of turn, degrees per second (from the sailed
    /// course between consecutive samples).
    pub max_turn_rate_deg_s: f64,
    /// Ownship's rate-of-turn limit, degrees per second (`None`: the
    /// paper's instantaneous turns).
    pub turn_rate_limit_deg_s: Option<f64>,
    /// Ownship's turn-direction reversals (successive turn episodes of at
    /// least the detectable 2° turning opposite ways).
    pub turn_reversals: usize,
    /// Ownship's total course change per nautical mile sailed, degrees.
    pub course_change_deg_per_nm: f64,
    /// Findings about ownship's track as a whole (a rate of turn above the
    /// limit), or why the run could not be judged.
    pub track_findings: Vec<String>,
    /// Length of the sailed track, metres.
    pub path_length_m: f64,
    /// Straight-line distance from start to goal, metres.
    pub straight_length_m: f64,
    /// Extra length over the straight route, percent.
    pub path_overhead_pct: f64,
    /// Time to the goal (or to the end of the run), seconds.
    pub duration_s: f64,
    /// Time the straight route takes at ownship's speed, seconds.
    pub straight_duration_s: f64,
    /// Extra time over the straight route, percent.
    pub time_overhead_pct: f64,
    /// Planner calls that returned a plan.
    pub plans_made: usize,
    /// Planner calls after the first.
    pub replans: usize,
    /// Planner calls that failed.
    pub failed_plans: usize,
    /// Planner calls after which ownship departed from the rules (a graded
    /// fallback plan or the evasive manoeuvre; rules 2(b), 17(b)).
    #[serde(default)]
    pub rule_departures: usize,
    /// Wall-clock time spent planning, seconds.
    pub planning_time_s: f64,
    /// Per target, in scenario order.
    pub targets: Vec<TargetEvaluation>,
    /// Every track's jitter and the window and turn thresholds it was judged
    /// with, ownship first (exact tracks: no jitter, the published values).
    #[serde(default)]
    pub noise: Vec<TrackNoise>,
    /// Rule 10 (traffic separation schemes) on ownship's track as sailed,
    /// its heading at every sample (the rule speaks of heading): the lane
    /// crossings and the findings; empty without lanes and zones. A finding
    /// makes the run not `compliant`.
    #[serde(default)]
    pub rule10: Rule10Judgement,
    /// The same on the track as observed: course over ground over the
    /// observation window, as another vessel sees it (reported, not part
    /// of `compliant`: the COG lags a turn made just short of a lane).
    #[serde(default)]
    pub rule10_observed: Rule10Judgement,
}

impl Evaluation {
    /// Whether the run **succeeded**: ownship reached its goal, no hull
    /// touched another, every target kept the clearance `d_th`, and the
    /// track neither grounded nor came within `land_clearance_m` of land.
    /// COLREGs compliance is not part of it (see [`Self::safe_and_compliant`]).
    ///
    /// The one success criterion of a closed-loop run: `report.json`'s
    /// `reached_goal_safely`, exit code 0 of `vorrt simulate` and `vorrt demo`,
    /// a batch's `success_rate` ([`crate::BatchRow::success`]) and the examples'
    /// exit codes all read it.
    #[must_use]
    pub fn success(&self) -> bool {
        succeeded(
            self.reached_goal,
            self.collision || self.grounding,
            self.clearance_kept && self.land_clearance_kept,
        )
    }

    /// Whether the tracks were **safe and compliant**: no collision and no
    /// grounding, `d_th` kept from every target and `land_clearance_m`
    /// from land, and no finding under the observed evaluation
    /// (`compliant`). Whether ownship reached a goal is not asked: recorded
    /// tracks (`vorrt judge`) need not end at one. Exit code 0 of `vorrt judge`.
    #[must_use]
    pub fn safe_and_compliant(&self) -> bool {
        !self.collision
            && !self.grounding
            && self.clearance_kept
            && self.land_clearance_kept
            && self.compliant
    }

    /// The evaluation as a plain-text table: one row per target, then the run's
    /// totals. For examples and terminals; the command line writes JSON too.
    #[must_use]
    pub fn table(&self) -> String {
        use std::fmt::Write as _;
        let mut text = String::new();
        let _ = writeln!(
            text,
            "{:<10} {:<18} {:<9} {:>9} {:>8} {:>9} {:>6}  violations",
            "target", "encounter", "role", "min [m]", "at [min]", "compliant", "score"
        );
        for target in &self.targets {
            let _ = writeln!(
                text,
                "{:<10} {:<18} {:<9} {:>9.0} {:>8.1} {:>9} {:>6.2}  {}",
                target.name,
                target.encounter.name(),
                target.role.name(),
                target.min_distance_m,
                target.time_of_min_s / 60.0,
                if target.compliant { "yes" } else { "NO" },
                target.score,
                if target.violations.is_empty() {
                    "-".to_owned()
                } else {
                    target.violations.join("; ")
                },
            );
        }
        let _ = writeln!(
            text,
            "goal reached: {} | min distance {:.0} m (d_th {:.0} m): {} | collision: {} | path {:.0} m, +{:.1}% over straight | time +{:.1}% | plans {} (replans {}, failed {}), planning {:.1} ms",
            if self.reached_goal { "yes" } else { "NO" },
            self.min_distance_m,
            self.clearance_m,
            kept_or_broken(self.clearance_kept),
            if self.collision { "YES" } else { "no" },
            self.path_length_m,
            self.path_overhead_pct,
            self.time_overhead_pct,
            self.plans_made,
            self.replans,
            self.failed_plans,
            self.planning_time_s * 1e3,
        );
        if let (Some(distance_m), Some(clearance_m)) =
            (self.min_land_distance_m, self.land_clearance_m)
        {
            let _ = writeln!(
                text,
                "land: min distance {distance_m:.0} m (clearance {clearance_m:.0} m): {} | grounding: {}",
                kept_or_broken(self.land_clearance_kept),
                if self.grounding { "YES" } else { "no" },
            );
        }
        let _ = writeln!(
            text,
            "path quality: largest rate of turn {:.2}°/s{} | {} turn reversals | {:.1}° of course change per nm{}",
            self.max_turn_rate_deg_s,
            self.turn_rate_limit_deg_s
                .map_or_else(String::new, |limit| format!(" (limit {limit:.2}°/s)")),
            self.turn_reversals,
            self.course_change_deg_per_nm,
            if self.track_findings.is_empty() {
                String::new()
            } else {
                format!(" | {}", self.track_findings.join("; "))
            },
        );
        if !(self.rule10.crossings.is_empty() && self.rule10.is_clean()) {
            let worst = self
                .rule10
                .crossings
                .iter()
                .map(|crossing| crossing.max_off_perpendicular_deg)
                .fold(0.0, f64::max);
            let findings: Vec<String> = self
                .rule10
                .findings
                .iter()
                .map(ToString::to_string)
                .collect();
            let _ = writeln!(
                text,
                "rule 10: {} lane crossings, {} square (worst {worst:.1}° off perpendicular) | {}",
                self.rule10.crossings.len(),
                self.rule10.square_crossings(),
                if findings.is_empty() {
                    "no finding".to_owned()
                } else {
                    findings.join("; ")
                },
            );
        }
        text
    }
}

/// "kept" or "BROKEN", as the table says of a clearance.
fn kept_or_broken(kept: bool) -> &'static str {
    if kept { "kept" } else { "BROKEN" }
}

/// The default of [`Evaluation::land_clearance_kept`] in results written
/// before it existed: no land, so kept.
fn kept() -> bool {
    true
}

/// [`Evaluation::success`] from its three parts, for results that keep them
/// apart from an [`Evaluation`] (a batch row read back from `rows.csv`).
pub(crate) fn succeeded(reached_goal: bool, collision: bool, clearance_kept: bool) -> bool {
    reached_goal && !collision && clearance_kept
}

/// Scoring constants for a scenario: its own clearance as `d_th`, with the
/// near-miss and collision ranges at the default proportions beneath it (1/2
/// and 1/8: 100 m and 25 m for the open-sea 200 m).
#[must_use]
pub fn scoring_for(clearance_m: f64) -> ScoringParameters {
    ScoringParameters {
        clearance_m,
        near_miss_m: clearance_m / 2.0,
        collision_m: clearance_m / 8.0,
        ..ScoringParameters::default()
    }
}

/// Evaluates a run of `scenario`, judged as observed with the clearance and
/// rules the run was made with (`record.config`).
///
/// ```
/// use vorrt_scenarios::{evaluate, fixtures, simulate};
/// let scenario = fixtures::find("paper/crossing").unwrap().load().unwrap();
/// let record = simulate(&scenario, 1).unwrap();
/// let evaluation = evaluate(&scenario, &record);
/// assert!(evaluation.success());
/// ```
#[must_use]
pub fn evaluate(scenario: &Scenario, record: &SimulationRecord) -> Evaluation {
    evaluate_with(
        scenario,
        record,
        &record.config.rules,
        record.config.clearance_m,
    )
}

/// As [`evaluate`], with the rule constants and clearance given by the caller.
#[must_use]
pub fn evaluate_with(
    scenario: &Scenario,
    record: &SimulationRecord,
    rules: &RuleParameters,
    clearance_m: f64,
) -> Evaluation {
    let parameters = ObservedParameters {
        max_turn_rate_rad_s: record.max_turn_rate_rad_s,
        rules: *rules,
        scoring: scoring_for(clearance_m),
        ..ObservedParameters::default()
    };
    let recording = recording_of(scenario, record);
    let judgement = judge(&recording, &parameters);
    let noise = judgement
        .as_ref()
        .map(|judgement| judgement.noise.clone())
        .unwrap_or_default();
    let (rule10, rule10_observed) = judge_rule10(scenario, &recording, judgement.as_ref().ok());
    let (targets, path, track_findings, compliant) = match &judgement {
        Ok(judgement) => (
            judgement.targets.iter().map(target_evaluation).collect(),
            Some(judgement.path),
            judgement
                .track_findings
                .iter()
                .map(ToString::to_string)
                .collect(),
            judgement.compliant,
        ),
        Err(error) => (
            Vec::new(),
            None,
            vec![format!("not judged: {error}")],
            false,
        ),
    };
    // The chart of a validated scenario always builds; one that does not
    // (areas never validated) has no land to judge.
    let land = Chart::from_scenario(scenario).ok().and_then(|chart| {
        chart.judge_track(&record.times_s, &record.ownship, record.max_turn_rate_rad_s)
    });
    let start = scenario.ownship_state().position_m;
    let straight_length_m = start.distance(scenario.ownship_goal_m());
    let speed = scenario.ownship_state().speed_mps;
    let straight_duration_s = straight_length_m / speed;
    let path_length_m = record.path_length_m();
    let duration_s = record
        .arrival_time_s
        .unwrap_or_else(|| record.times_s.last().copied().unwrap_or(0.0));
    let percent = |actual: f64, ideal: f64| {
        if ideal > 0.0 {
            100.0 * (actual / ideal - 1.0)
        } else {
            0.0
        }
    };
    Evaluation {
        scenario: record.scenario.clone(),
        seed: record.seed,
        clearance_m,
        reached_goal: record.reached_goal,
        collision: targets
            .iter()
            .any(|target: &TargetEvaluation| target.collision),
        min_distance_m: targets
            .iter()
            .map(|target| target.min_distance_m)
            .fold(f64::INFINITY, f64::min),
        clearance_kept: targets.iter().all(|target| target.clearance_kept),
        min_land_distance_m: land.map(|land| land.min_distance_m),
        land_clearance_m: land.map(|land| land.clearance_m),
        grounding: land.is_some_and(|land| land.grounding),
        land_clearance_kept: land.is_none_or(|land| land.clearance_kept),
        compliant: compliant && rule10.is_clean(),
        max_turn_rate_deg_s: path.map_or(0.0, |path| path.max_turn_rate_deg_s),
        turn_rate_limit_deg_s: record.max_turn_rate_rad_s.map(f64::to_degrees),
        turn_reversals: path.map_or(0, |path| path.turn_reversals),
        course_change_deg_per_nm: path.map_or(0.0, |path| path.course_change_deg_per_nm),
        track_findings,
        path_length_m,
        straight_length_m,
        path_overhead_pct: percent(path_length_m, straight_length_m),
        duration_s,
        straight_duration_s,
        time_overhead_pct: percent(duration_s, straight_duration_s),
        plans_made: record.plans_made(),
        replans: record.replans(),
        failed_plans: record.failed_plans(),
        rule_departures: record.rule_departures(),
        planning_time_s: record.planning_time_s(),
        targets,
        noise,
        rule10,
        rule10_observed,
    }
}

/// Rule 10 on ownship's track, as sailed (the recorded headings; the
/// course over ground where the recording has none) and as observed,
/// against the scenario's scheme.
fn judge_rule10(
    scenario: &Scenario,
    recording: &Recording,
    judgement: Option<&ObservedJudgement>,
) -> (Rule10Judgement, Rule10Judgement) {
    let scheme = scenario.traffic_scheme();
    if scheme.is_empty() {
        return (Rule10Judgement::default(), Rule10Judgement::default());
    }
    let observed: Vec<f64> = judgement.map_or_else(Vec::new, |judgement| {
        judgement
            .ownship
            .iter()
            .map(|over| over.course_rad)
            .collect()
    });
    let own = &recording.ownship;
    let sailed = own.courses_rad.as_ref().unwrap_or(&observed);
    (
        judge_track(&scheme, &recording.times_s, &own.positions_m, sailed),
        judge_track(&scheme, &recording.times_s, &own.positions_m, &observed),
    )
}

/// The observed judgement of a run, for callers that want more than the
/// [`Evaluation`] (every observed course and speed, the assessments).
///
/// # Errors
/// The judgement's error when the rules or the record are malformed.
pub fn observed_judgement(
    scenario: &Scenario,
    record: &SimulationRecord,
) -> Result<ObservedJudgement, vorrt_colregs::ColregsError> {
    let parameters = ObservedParameters {
        max_turn_rate_rad_s: record.max_turn_rate_rad_s,
        rules: record.config.rules,
        scoring: scoring_for(record.config.clearance_m),
        ..ObservedParameters::default()
    };
    judge(&recording_of(scenario, record), &parameters)
}

/// The recorded tracks of a run, as the observed judgement reads them:
/// positions and recorded courses of every vessel on the run's time base.
fn recording_of(scenario: &Scenario, record: &SimulationRecord) -> Recording {
    let observation = |index: usize| record.observations.get(index).cloned().unwrap_or_default();
    let track = |name: &str, states: &[vorrt_colregs::VesselState], length_m: f64, index: usize| {
        RecordedTrack {
            name: name.to_owned(),
            length_m: states.first().map_or(length_m, |state| state.length_m),
            positions_m: states.iter().map(|state| state.position_m).collect(),
            courses_rad: Some(states.iter().map(|state| state.course_rad).collect()),
            observation: observation(index),
        }
    };
    Recording {
        times_s: record.times_s.clone(),
        ownship: track(
            &scenario.ownship.name,
            &record.ownship,
            scenario.ownship.length_m,
            0,
        ),
        targets: record
            .targets
            .iter()
            .enumerate()
            .map(|(index, states)| {
                let name = record.target_names.get(index).map_or("", String::as_str);
                let length_m = scenario.targets.get(index).map_or(1.0, |t| t.length_m);
                track(name, states, length_m, index + 1)
            })
            .collect(),
    }
}

/// One target's evaluation from its observed judgement.
fn target_evaluation(observed: &ObservedEncounter) -> TargetEvaluation {
    let assessment = observed.assessment.as_ref();
    let latch = observed.latch;
    TargetEvaluation {
        name: observed.name.clone(),
        encounter: latch.map_or(Encounter::None, |latch| latch.encounter),
        role: latch.map_or(Role::None, |latch| latch.encounter.role()),
        risk_time_s: latch.map(|latch| latch.latched_at_s),
        min_distance_m: observed.min_distance_m,
        time_of_min_s: observed.time_of_min_s,
        clearance_kept: observed.clearance_kept,
        collision: observed.collision,
        compliant: observed.compliant,
        violations: observed.findings.iter().map(ToString::to_string).collect(),
        findings: observed.findings.clone(),
        action_range_m: assessment.and_then(|a| a.action_range_m),
        first_alteration_deg: assessment.and_then(|a| a.first_turn_rad.map(f64::to_degrees)),
        max_alteration_deg: assessment.map(|a| a.max_course_change_rad.to_degrees()),
        score: observed.score,
        assessment: assessment.cloned(),
        status: observed.status,
        undecided: observed.undecided,
    }
}
