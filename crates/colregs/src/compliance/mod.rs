//! Post-hoc compliance scoring of one recorded encounter (rules 8, 13-17).
//!
//! The run's evaluation feeds it the states **as observed** (course and
//! speed over ground over a window, [`crate::observed`]); it judges whatever
//! states it is given.
//!
//! Given the recorded tracks of ownship and one target
//! ([`EncounterSample`]s in increasing time, covering the whole run) and the
//! [`EncounterLatch`] fixed when risk of collision arose, [`assess_encounter`]
//! measures what ownship did and scores it, in the style of the evaluators of
//! Woerner et al. (Autonomous Robots, 2019) and Minne (NTNU, 2017) described in
//! `docs/evaluation.md`, "Judging the track as observed". The
//! definitions below are this crate's own; every constant is a field of
//! [`ScoringParameters`] or [`RuleParameters`].
//!
//! The assessment runs in named steps, one file each: the recording
//! (`recording.rs`), the measurements (`measure.rs`: closest approach,
//! in-force window, action), the judgements (`judge.rs`: safety, rule 16,
//! rules 13-15, rule 17), the constants and safety score (`scoring.rs`), the
//! findings (`violation.rs`) and the result (`assessment.rs`). Every rule
//! judgement they make is a predicate of the rule book, [`crate::rules`].
//!
//! ## Measurements
//! - **Closest approach**: the minimum range over the whole run. Between two
//!   samples both vessels are taken to move in straight lines, so the minimum
//!   inside a step is found exactly (CPA of the relative motion over the step),
//!   not only at sample instants.
//! - **In force**: from the first sample at or after the latch time up to (not
//!   including) the first sample at which the vessels have passed
//!   ([`has_passed`](crate::has_passed)), or to the end of the run.
//! - **Action**: the first in-force sample at which ownship's course differs
//!   from the latch's reference course by at least
//!   [`action_detection_rad`](ScoringParameters::action_detection_rad) (5°)
//!   or its speed has dropped by at least
//!   [`action_speed_drop_fraction`](ScoringParameters::action_speed_drop_fraction)
//!   (20 %) of the reference speed. The first turn is the course change at
//!   the first sample at or beyond the detection threshold.
//! - **Up to the closest approach**: the largest course and speed changes
//!   (readily apparent, held) are measured over the in-force samples up to
//!   the time of the minimum range.
//! - **Alteration episodes**: the turn episodes of ownship's course while in
//!   force, from the reference course
//!   ([`turn_episodes`](crate::observed::turn_episodes)).
//! - **Passing side**: the side of ownship (relative bearing from ownship's
//!   course in `(0, π)` = starboard) on which the target lies at the closest
//!   approach.
//! - **Crossed ahead**: while in force, ownship's track relative to the target
//!   crosses the target's heading line ahead of the target's bow.
//!
//! ## Violations, by role
//! - Always: [`ClearanceViolated`](ComplianceViolation::ClearanceViolated)
//!   when the minimum range is under `clearance_m` (`d_th`) and
//!   [`Collision`](ComplianceViolation::Collision) when the hulls touched at
//!   the closest approach: the minimum range under half the sum of the two
//!   lengths ([`in_contact`](crate::rules::in_contact), the workspace's one
//!   definition of collision). These are safety findings, not rule
//!   violations: they do not make an assessment non-compliant.
//! - Give way (head-on, crossing give-way, overtaking; rule 16, with rule 8(b)
//!   for "readily apparent"):
//!   - [`NoAction`](ComplianceViolation::NoAction): no action while in
//!     force, where an action was required: the pass predicted at the
//!     first in-force sample (both holding their velocities) would not keep
//!     `clearance_m` between the hulls. A pass predicted to keep it is
//!     already clear and none of the rule 16 findings below is judged
//!     (decision 42); the manner of passing (port turn,
//!     starboard-to-starboard, crossing ahead) is judged as well.
//!   - None of the rule 16 findings below where the closest approach comes
//!     within `reaction_time_s` of the latch: no action could be taken, let
//!     alone seen, in that time.
//!   - [`LateAction`](ComplianceViolation::LateAction): the action began
//!     more than `reaction_time_s` (60 s) after the latch and, where risk
//!     arose at or beyond `late_action_range_m` (2 nm), nearer than that.
//!   - [`ActionNotApparent`](ComplianceViolation::ActionNotApparent): up to
//!     the closest approach (and, where the encounter ended before it, up to
//!     `reaction_time_s` after it ended, as a turn begun in force shows over
//!     ground; and a turn under way at the closest approach to its end, up
//!     to `reaction_time_s` after it: decision 51), the largest course
//!     change is under
//!     [`apparent_turn_rad`](RuleParameters::apparent_turn_rad) (30°) and the
//!     largest speed reduction under `apparent_speed_reduction_fraction` of
//!     the reference speed (one half).
//!   - [`AlterationNotHeld`](ComplianceViolation::AlterationNotHeld) (rules
//!     8(d), 16): once readily apparent, the course change eased back more
//!     than [`turn_tolerance_rad`](RuleParameters::turn_tolerance_rad) below
//!     it (a speed reduction more than the stand-on speed tolerance below
//!     it) before the closest approach.
//!   - [`SmallAlterations`](ComplianceViolation::SmallAlterations) (rule
//!     8(b)): two or more alteration episodes while in force, each
//!     detectable and not readily apparent.
//!   - [`PortTurn`](ComplianceViolation::PortTurn) (head-on, rule 14(a);
//!     crossing give-way, rules 15 and 16): the first detectable course change
//!     is to port, or the largest one is.
//!   - [`StarboardToStarboard`](ComplianceViolation::StarboardToStarboard)
//!     (head-on, rule 14(a)): the target passed on ownship's starboard side.
//!   - [`CrossedAhead`](ComplianceViolation::CrossedAhead): in crossing
//!     give-way (rule 15) a crossing of the target's heading line within
//!     `crossed_ahead_range_m` (1 nm) of her bow, with a real change of
//!     side (clear of the line's uncertainty before and after: half her
//!     length plus the detectable change's swing; decision 42); when overtaking
//!     (rule 13) a crossing of the overtaken vessel's bow closer than
//!     `clearance_m` ahead of it (cutting in).
//! - Stand on (crossing stand-on, being overtaken; rule 17):
//!   - [`StandOnCourseChanged`](ComplianceViolation::StandOnCourseChanged) /
//!     [`StandOnSpeedChanged`](ComplianceViolation::StandOnSpeedChanged)
//!     (rule 17(a)(i)): course changed by more than
//!     [`stand_on_course_tolerance_rad`](RuleParameters::stand_on_course_tolerance_rad)
//!     or speed by more than
//!     [`stand_on_speed_tolerance_mps`](RuleParameters::stand_on_speed_tolerance_mps)
//!     while the range was still over
//!     [`stand_on_action_range_m`](RuleParameters::stand_on_action_range_m)
//!     and no duty toward another vessel freed ownship to act: the course
//!     and speed to keep are the reference ones, or those last had while
//!     such a duty was in force (decisions 22, 45). Every departure before
//!     the action range is listed in
//!     [`stand_on_departures`](EncounterAssessment::stand_on_departures),
//!     with the duty that took precedence where one did
//!     ([`Precedence`]: rules 16 and 2(b), or 17(a)(ii)).
//!   - [`StandOnTurnedToPort`](ComplianceViolation::StandOnTurnedToPort)
//!     (rule 17(c), crossing only): at its first detectable port turn ownship
//!     had the target on its port side (relative to the reference course).
//! - Whatever the role, the encounter is also judged from the course held
//!   before any turn:
//!   [`PortTurnTowardVessel`](ComplianceViolation::PortTurnTowardVessel)
//!   (rules 2(a), 8(a), 17(c)) when risk arose just after a port turn toward
//!   the target, on the port side of the course held before the turn (a
//!   window before the latch, or before the turn then under way) and
//!   forward of the beam of the new one, that made it a risk of collision
//!   (whichever vessel would cross ahead; the target taken on the course it
//!   held a window before, before any answer of its own: decision 51)
//!   ([`is_port_turn_toward_vessel`](crate::rules::is_port_turn_toward_vessel)).
//!
//! ## Scores (each in `[0, 1]`, 1 = best)
//! - **Safety** ([`safety_score`]): 1 at or above `clearance_m`, linear down
//!   to `near_miss_safety` at `near_miss_m`, linear down to 0 at `collision_m`
//!   and 0 below it; and 0 whenever the hulls touched (a collision), however
//!   far above `collision_m`. It never increases as the minimum range shrinks.
//! - **Rule scores**: 1 minus the sum of the penalties of that rule's
//!   violations (weights in [`PenaltyWeights`]), clamped to `[0, 1]`; `None`
//!   when the rule places no obligation on ownship in this encounter:
//!   rule 13 when overtaking; rule 14 in head-on; rule 15 in crossing
//!   give-way; rule 16 whenever ownship gives way; rule 17 whenever it stands
//!   on. Late action and a not-apparent action are graded by how far they
//!   fall short; every other penalty is its full weight.
//! - **Overall**: the product of safety and every applicable rule score, so a
//!   collision or a wholly broken rule gives 0 and only a safe, fully
//!   compliant encounter gives 1.

mod assessment;
pub(crate) mod episodes;
mod judge;
pub(crate) mod measure;
mod precedence;
mod recording;
mod scoring;
#[cfg(test)]
mod tests;
mod violation;

pub use assessment::{EncounterAssessment, RuleScores};
pub use precedence::{Duty, OtherDuty, Precedence, StandOnDeparture};
pub use recording::{EncounterSample, first_latch, steady_courses_rad};
pub use scoring::{PenaltyWeights, ScoringParameters, safety_score};
pub use violation::ComplianceViolation;

use crate::encounter::Role;
use crate::latch::EncounterLatch;
use crate::parameters::RuleParameters;
use crate::rules;
use judge::Findings;
use measure::{InForce, Measurements};

/// Assesses one recorded encounter between ownship and one target.
///
/// `samples` must be in increasing time and should cover the whole run
/// (before and after the latch); `latch` gives the encounter type and the
/// reference course and speed (see [`first_latch`]). The semantics of every
/// measurement, violation and score are in the [module documentation](self).
/// With no samples nothing is measured: the minimum range is `+∞`, nothing is
/// found and every score is 1.
///
/// ```
/// use vorrt_colregs::compliance::{assess_encounter, first_latch, EncounterSample, ScoringParameters};
/// use vorrt_colregs::{Encounter, PassingSide, RuleParameters, VesselState};
/// use glam::DVec2;
///
/// // Head-on at 6 m/s each; ownship turns 35° to starboard after one minute.
/// let rules = RuleParameters::default();
/// let mut own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// let mut target = VesselState::new(DVec2::new(0.0, 9000.0), std::f64::consts::PI, 6.0, 50.0);
/// let mut samples = Vec::new();
/// for step in 0..=150 {
///     let time_s = f64::from(step) * 10.0;
///     own.course_rad = if time_s >= 60.0 { 35f64.to_radians() } else { 0.0 };
///     samples.push(EncounterSample::new(time_s, own, target));
///     own = own.advanced(10.0);
///     target = target.advanced(10.0);
/// }
/// let latch = first_latch(&samples, &rules).expect("risk of collision");
/// assert_eq!(latch.encounter, Encounter::HeadOn);
/// let assessment = assess_encounter(&samples, &latch, &rules, &ScoringParameters::default());
/// assert!(assessment.compliant, "{:?}", assessment.violations);
/// assert_eq!(assessment.passing_side, Some(PassingSide::Port));
/// assert_eq!(assessment.scores.overall, 1.0);
/// ```
#[must_use]
pub fn assess_encounter(
    samples: &[EncounterSample],
    latch: &EncounterLatch,
    rules: &RuleParameters,
    scoring: &ScoringParameters,
) -> EncounterAssessment {
    assess_encounter_acting(samples, latch, rules, scoring, &[])
}

/// As [`assess_encounter`], for a stand-on ownship that also had duties
/// toward other vessels: `duties[i]` is the duty that took precedence at
/// `samples[i]` ([`OtherDuty::precedent`]; missing entries count as none):
/// it gave way to another vessel, or stood on for one within the action
/// range. With several targets, rule 17 yields to such a duty (rule 2(b);
/// the planner reads it the same way, [`rules::may_act`]), so while it is in
/// force an early course or speed change is not held against ownship but
/// recorded with the duty ([`EncounterAssessment::stand_on_departures`],
/// decision 45); rule 17(c) still is.
#[must_use]
pub fn assess_encounter_acting(
    samples: &[EncounterSample],
    latch: &EncounterLatch,
    rules: &RuleParameters,
    scoring: &ScoringParameters,
    duties: &[Option<OtherDuty>],
) -> EncounterAssessment {
    let window = InForce::of(samples, latch, rules);
    let measured = Measurements::of(samples, &window, latch, rules, scoring);
    let mut findings = Findings::safety(&measured);
    match latch.encounter.role() {
        Role::GiveWay => {
            findings.judge_give_way_action(&measured, latch, rules, scoring);
            findings.judge_manner_of_giving_way(&measured, latch.encounter, rules, scoring);
        }
        Role::StandOn => {
            let duty_at = duty_at(samples, duties);
            let duty = |s: &EncounterSample| duty_at.get(&s.time_s.to_bits()).copied();
            let may_act =
                |s: &EncounterSample| rules::may_act(s.range_m(), duty(s).is_some(), rules);
            findings.judge_stand_on(
                window.samples(samples),
                latch,
                rules,
                scoring,
                may_act,
                duty,
            );
        }
        Role::None => {}
    }
    findings.judge_turn_into_encounter(samples, latch, rules, scoring);
    let passed_at_s = window.passed_index.map(|index| samples[index].time_s);
    assemble(latch, &measured, findings, passed_at_s, scoring)
}

/// The duty toward another vessel in force at each sample (keyed by the
/// time's bits): then, standing on, ownship may act ([`rules::may_act`]).
fn duty_at(
    samples: &[EncounterSample],
    duties: &[Option<OtherDuty>],
) -> std::collections::HashMap<u64, OtherDuty> {
    samples
        .iter()
        .zip(duties)
        .filter_map(|(sample, duty)| duty.map(|duty| (sample.time_s.to_bits(), duty)))
        .collect()
}

/// The assessment from the measurements and findings: the safety score (0
/// on hull contact), the overall product and the verdicts.
fn assemble(
    latch: &EncounterLatch,
    measured: &Measurements,
    findings: Findings,
    passed_at_s: Option<f64>,
    scoring: &ScoringParameters,
) -> EncounterAssessment {
    let safety = if measured.in_contact {
        0.0
    } else {
        safety_score(measured.min_distance_m, scoring)
    };
    let Findings {
        violations,
        rule_13,
        rule_14,
        rule_15,
        rule_16,
        rule_17,
        stand_on_departures,
    } = findings;
    let overall = [rule_13, rule_14, rule_15, rule_16, rule_17]
        .into_iter()
        .flatten()
        .fold(safety, |product, score| product * score)
        .clamp(0.0, 1.0);
    let compliant = violations.iter().all(|v| !v.is_rule_violation());
    EncounterAssessment {
        encounter: latch.encounter,
        role: latch.encounter.role(),
        min_distance_m: measured.min_distance_m,
        time_of_min_s: measured.time_of_min_s,
        latch_range_m: measured.latch_range_m,
        latch_cpa_m: measured.latch_cpa_m,
        passed_at_s,
        action_time_s: measured.action_time_s,
        action_range_m: measured.action_range_m,
        max_course_change_rad: measured.max_course_change_rad,
        max_speed_change_mps: measured.max_speed_change_mps,
        first_turn_rad: measured.first_turn_rad,
        small_alterations: measured.small_alterations,
        passing_side: measured.passing_side,
        crossed_ahead: measured.crossed_ahead_distance_m.is_some(),
        crossed_ahead_distance_m: measured.crossed_ahead_distance_m,
        violations,
        stand_on_departures,
        scores: RuleScores {
            safety,
            rule_13,
            rule_14,
            rule_15,
            rule_16,
            rule_17,
            overall,
        },
        safe: measured.clearance_kept,
        compliant,
    }
}
