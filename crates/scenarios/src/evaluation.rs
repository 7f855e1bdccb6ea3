//! Evaluation of a closed-loop run: did ownship arrive, how close did every
//! target come, and did it obey COLREGs?
//!
//! Per target, the encounter is latched from the recorded states exactly as
//! the simulation latched it (`vorrt_colregs::first_latch`) and scored by
//! `vorrt_colregs::assess_encounter`: minimum distance and when, the action
//! taken (starboard turn, passing side, pass astern, stand-on kept) with every
//! violation named, and per-rule scores after Woerner (2019) and Minne (2017).
//! A target with which no risk of collision ever arose is judged on clearance
//! alone.
//!
//! Several targets at once: a vessel that must give way to one target cannot
//! also keep its course for another. While ownship has to give way to some
//! target, its stand-on encounters are judged as ones in which it may act (rule 17(a)(ii); `vorrt_colregs::assess_encounter_acting`):
//! an early course or speed change is not held against it, a port turn for a
//! vessel on its port side still is (rule 17(c)). The planner applies the same
//! reading (`vorrt_colregs::check_maneuver_acting`).

use crate::scenario::Scenario;
use crate::simulation::SimulationRecord;
use serde::{Deserialize, Serialize};
use vorrt_colregs::{
    ComplianceViolation, Encounter, EncounterAssessment, EncounterSample, Role, RuleParameters,
    ScoringParameters, assess_encounter_acting, first_latch, safety_score, update_latch,
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
    /// Every rule broken (and clearance findings), as text naming the rule.
    pub violations: Vec<String>,
    /// The overall score in `[0, 1]`: safety times every applicable rule score.
    pub score: f64,
    /// The full assessment (`None` when no encounter arose).
    pub assessment: Option<EncounterAssessment>,
}

/// How a whole run fared.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
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
    /// Whether every encounter was handled compliantly.
    pub compliant: bool,
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
    /// Wall-clock time spent planning, seconds.
    pub planning_time_s: f64,
    /// Per target, in scenario order.
    pub targets: Vec<TargetEvaluation>,
}

impl Evaluation {
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
            if self.clearance_kept {
                "kept"
            } else {
                "BROKEN"
            },
            if self.collision { "YES" } else { "no" },
            self.path_length_m,
            self.path_overhead_pct,
            self.time_overhead_pct,
            self.plans_made,
            self.replans,
            self.failed_plans,
            self.planning_time_s * 1e3,
        );
        text
    }
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

/// Evaluates a run of `scenario`.
///
/// ```
/// use vorrt_scenarios::{Scenario, evaluate, simulate};
/// let scenario = Scenario::load(std::path::Path::new(concat!(
///     env!("CARGO_MANIFEST_DIR"), "/../../fixtures/paper/crossing.ron"))).unwrap();
/// let record = simulate(&scenario, 1).unwrap();
/// let evaluation = evaluate(&scenario, &record);
/// assert!(evaluation.reached_goal && evaluation.clearance_kept);
/// ```
#[must_use]
pub fn evaluate(scenario: &Scenario, record: &SimulationRecord) -> Evaluation {
    let config = scenario.planner_config().unwrap_or_default();
    evaluate_with(scenario, record, &config.rules, config.clearance_m)
}

/// As [`evaluate`], with the rule constants and clearance given by the caller.
#[must_use]
pub fn evaluate_with(
    scenario: &Scenario,
    record: &SimulationRecord,
    rules: &RuleParameters,
    clearance_m: f64,
) -> Evaluation {
    let scoring = scoring_for(clearance_m);
    let samples: Vec<Vec<EncounterSample>> = record
        .targets
        .iter()
        .map(|track| {
            record
                .times_s
                .iter()
                .zip(&record.ownship)
                .zip(track)
                .map(|((time_s, own), target)| EncounterSample::new(*time_s, *own, *target))
                .collect()
        })
        .collect();
    // At each sample, whether ownship had to give way to some target: while
    // it does, it may act for the vessels it stands on for.
    let mut giving_way = vec![false; record.times_s.len()];
    for track in &samples {
        let mut latch = None;
        for (sample, giving) in track.iter().zip(giving_way.iter_mut()) {
            latch = update_latch(latch, &sample.own, &sample.target, sample.time_s, rules);
            *giving |= latch.is_some_and(|latch| latch.encounter.role() == Role::GiveWay);
        }
    }
    let targets: Vec<TargetEvaluation> = samples
        .iter()
        .enumerate()
        .map(|(index, track)| {
            let name = record.target_names.get(index).cloned().unwrap_or_default();
            evaluate_target(name, track, rules, &scoring, &giving_way)
        })
        .collect();
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
        collision: targets.iter().any(|target| target.collision),
        min_distance_m: targets
            .iter()
            .map(|target| target.min_distance_m)
            .fold(f64::INFINITY, f64::min),
        clearance_kept: targets.iter().all(|target| target.clearance_kept),
        compliant: targets.iter().all(|target| target.compliant),
        path_length_m,
        straight_length_m,
        path_overhead_pct: percent(path_length_m, straight_length_m),
        duration_s,
        straight_duration_s,
        time_overhead_pct: percent(duration_s, straight_duration_s),
        plans_made: record.plans_made(),
        replans: record.replans(),
        failed_plans: record.failed_plans(),
        planning_time_s: record.planning_time_s(),
        targets,
    }
}

fn evaluate_target(
    name: String,
    samples: &[EncounterSample],
    rules: &RuleParameters,
    scoring: &ScoringParameters,
    giving_way: &[bool],
) -> TargetEvaluation {
    let hull_contact_m = samples.first().map_or(0.0, |sample| {
        0.5 * (sample.own.length_m + sample.target.length_m)
    });
    match first_latch(samples, rules) {
        Some(latch) => {
            let assessment = assess_encounter_acting(samples, &latch, rules, scoring, giving_way);
            TargetEvaluation {
                name,
                encounter: assessment.encounter,
                role: assessment.role,
                risk_time_s: Some(latch.latched_at_s),
                min_distance_m: assessment.min_distance_m,
                time_of_min_s: assessment.time_of_min_s,
                clearance_kept: assessment.min_distance_m >= scoring.clearance_m,
                collision: assessment.min_distance_m < hull_contact_m,
                compliant: assessment.compliant,
                violations: assessment
                    .violations
                    .iter()
                    .map(ComplianceViolation::to_string)
                    .collect(),
                score: assessment.scores.overall,
                assessment: Some(assessment),
            }
        }
        None => {
            let (min_distance_m, time_of_min_s) = samples
                .iter()
                .map(|sample| (sample.range_m(), sample.time_s))
                .fold((f64::INFINITY, 0.0), |best, next| {
                    if next.0 < best.0 { next } else { best }
                });
            let clearance_kept = min_distance_m >= scoring.clearance_m;
            let violations = if clearance_kept {
                Vec::new()
            } else {
                vec![ComplianceViolation::ClearanceViolated { min_distance_m }.to_string()]
            };
            TargetEvaluation {
                name,
                encounter: Encounter::None,
                role: Role::None,
                risk_time_s: None,
                min_distance_m,
                time_of_min_s,
                clearance_kept,
                collision: min_distance_m < hull_contact_m,
                compliant: true,
                violations,
                score: safety_score(min_distance_m, scoring),
                assessment: None,
            }
        }
    }
}
