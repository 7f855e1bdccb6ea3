//! The judgements of an assessment, one step per rule group, each adding its
//! findings and setting the scores of the rules it judges (see the violation
//! list in the [module documentation](super)).

use super::measure::{EasedBack, Measurements, largest_signed, turn_of};
use super::precedence::{OtherDuty, Precedence, StandOnDeparture};
use super::{ComplianceViolation, EncounterSample, ScoringParameters};
use crate::encounter::Encounter;
use crate::encounter::Role;
use crate::latch::EncounterLatch;
use crate::parameters::RuleParameters;
use crate::passing::PassingSide;
use crate::rules::{
    STEADY_COURSE_WINDOW_S, course_change_rad, is_measured_readily_apparent, is_on_port_side,
    is_port_turn, is_port_turn_toward_vessel, is_speed_change, is_stand_on_course_change,
    steady_course_rad, within_action_range,
};
use crate::vessel::VesselState;

/// The findings and rule scores built up by the judgement steps.
#[derive(Debug, Default)]
pub(super) struct Findings {
    /// Every finding, safety findings first.
    pub(super) violations: Vec<ComplianceViolation>,
    /// Rule 13's score, when judged.
    pub(super) rule_13: Option<f64>,
    /// Rule 14's score, when judged.
    pub(super) rule_14: Option<f64>,
    /// Rule 15's score, when judged.
    pub(super) rule_15: Option<f64>,
    /// Rule 16's score, when judged.
    pub(super) rule_16: Option<f64>,
    /// Rule 17's score, when judged.
    pub(super) rule_17: Option<f64>,
    /// The stand-on departures before the action range, justified or not
    /// (decision 45).
    pub(super) stand_on_departures: Vec<StandOnDeparture>,
}

/// `1 - Σ penalties`, clamped to `[0, 1]`.
fn rule_score(penalties: &[f64]) -> f64 {
    (1.0 - penalties.iter().sum::<f64>()).clamp(0.0, 1.0)
}

impl Findings {
    /// The safety findings, whatever the role: the clearance broken between
    /// the hulls ([`keeps_clearance`](crate::rules::keeps_clearance)), and a
    /// collision (hull contact, [`in_contact`](crate::rules::in_contact)).
    pub(super) fn safety(measured: &Measurements) -> Self {
        let min_distance_m = measured.min_distance_m;
        let mut violations = Vec::new();
        if !measured.clearance_kept {
            violations.push(ComplianceViolation::ClearanceViolated { min_distance_m });
        }
        if measured.in_contact {
            violations.push(ComplianceViolation::Collision { min_distance_m });
        }
        Self {
            violations,
            ..Self::default()
        }
    }

    /// Rule 16 (with 8): a give-way vessel's action was taken, early,
    /// readily apparent and held until the closest approach, and not as a
    /// succession of small alterations.
    pub(super) fn judge_give_way_action(
        &mut self,
        measured: &Measurements,
        latch: &EncounterLatch,
        rules: &RuleParameters,
        scoring: &ScoringParameters,
    ) {
        let weights = &scoring.penalties;
        let mut penalties = Vec::new();
        // A closest approach within one reaction time of the latch leaves no
        // time for an action to be taken, let alone seen over ground: rule 16
        // is not judged (the clearance and the manner of passing still are).
        let no_time_to_act = (latch.latched_at_s..=latch.latched_at_s + scoring.reaction_time_s)
            .contains(&measured.time_of_min_s);
        if no_time_to_act {
            return;
        }
        match (measured.action_time_s, measured.action_range_m) {
            // A pass predicted to keep d_th owes no action (decision 42).
            _ if !measured.action_required => {}
            (Some(action_time_s), Some(range_m)) => {
                let early_range_m = scoring.late_action_range_m;
                // Within the reaction time of the latch an action is never
                // late (it cannot begin before risk arises, and shows over
                // ground a little after it begins).
                let after_reaction = action_time_s - latch.latched_at_s > scoring.reaction_time_s;
                let late = after_reaction
                    && match measured.latch_range_m {
                        Some(latch_range_m) if latch_range_m >= early_range_m => {
                            range_m < early_range_m
                        }
                        _ => true,
                    };
                if late {
                    self.violations
                        .push(ComplianceViolation::LateAction { range_m });
                    let lateness = if early_range_m > 0.0 {
                        1.0 - range_m / early_range_m
                    } else {
                        0.0
                    };
                    penalties.push(weights.late_action * lateness.clamp(0.0, 1.0).max(0.1));
                }
                let by_turn = if is_measured_readily_apparent(measured.max_course_change_rad, rules)
                {
                    1.0
                } else {
                    measured.max_course_change_rad.abs() / rules.apparent_turn_rad
                };
                let apparent_reduction_mps =
                    scoring.apparent_speed_reduction_fraction * latch.reference_speed_mps;
                let by_speed = if apparent_reduction_mps > 0.0 {
                    measured.max_speed_reduction_mps / apparent_reduction_mps
                } else {
                    0.0
                };
                let apparentness = by_turn.max(by_speed);
                if apparentness < 1.0 {
                    self.violations
                        .push(ComplianceViolation::ActionNotApparent {
                            course_change_rad: measured.max_course_change_rad,
                            speed_change_mps: measured.max_speed_change_mps,
                        });
                    penalties.push(weights.not_apparent * (1.0 - apparentness).clamp(0.0, 1.0));
                }
                // Held until past: in head-on and crossing; an overtaking
                // vessel may come back to a parallel course once it has
                // opened its passing distance (as `check_action` allows).
                if let Some(eased) = measured.eased_back
                    && latch.encounter != Encounter::Overtaking
                {
                    let (course_change_rad, speed_change_mps) = match eased {
                        EasedBack::Course(change) => (change, 0.0),
                        EasedBack::Speed(change) => (0.0, change),
                    };
                    self.violations
                        .push(ComplianceViolation::AlterationNotHeld {
                            course_change_rad,
                            speed_change_mps,
                        });
                    penalties.push(weights.not_held);
                }
            }
            // Risk of collision was latched (rule 7), the encounter was in
            // force and the predicted pass would break d_th: a give-way
            // vessel acts.
            _ if measured.latch_range_m.is_some() => {
                self.violations.push(ComplianceViolation::NoAction);
                penalties.push(weights.no_action);
            }
            _ => {}
        }
        if measured.small_alterations >= 2 {
            self.violations.push(ComplianceViolation::SmallAlterations {
                episodes: measured.small_alterations,
            });
            penalties.push(weights.small_alterations);
        }
        self.rule_16 = Some(rule_score(&penalties));
    }

    /// Rules 13-15: the manner of giving way (no port turn in head-on and
    /// crossing, port to port in head-on, not across the bow of the stand-on
    /// or overtaken vessel), judged whether or not action was needed.
    pub(super) fn judge_manner_of_giving_way(
        &mut self,
        measured: &Measurements,
        encounter: Encounter,
        rules: &RuleParameters,
        scoring: &ScoringParameters,
    ) {
        let weights = &scoring.penalties;
        let port_turn = match measured.first_turn_rad {
            Some(first) if is_port_turn(first, rules) => Some(first),
            _ if is_port_turn(measured.max_course_change_rad, rules) => {
                Some(measured.max_course_change_rad)
            }
            _ => None,
        };
        let mut penalties = Vec::new();
        let port_turn = port_turn
            .filter(|_| matches!(encounter, Encounter::HeadOn | Encounter::CrossingGiveWay));
        if let Some(course_change_rad) = port_turn {
            self.violations
                .push(ComplianceViolation::PortTurn { course_change_rad });
            penalties.push(weights.port_turn);
        }
        match encounter {
            Encounter::HeadOn => {
                if measured.passing_side == Some(PassingSide::Starboard) {
                    self.violations
                        .push(ComplianceViolation::StarboardToStarboard);
                    penalties.push(weights.starboard_to_starboard);
                }
                self.rule_14 = Some(rule_score(&penalties));
            }
            Encounter::CrossingGiveWay => {
                // Within crossed_ahead_range_m and for a real change of side
                // only (measure.rs; decision 42).
                if let Some(distance_ahead_m) = measured.crossed_ahead_distance_m {
                    self.violations
                        .push(ComplianceViolation::CrossedAhead { distance_ahead_m });
                    penalties.push(weights.crossed_ahead);
                }
                self.rule_15 = Some(rule_score(&penalties));
            }
            Encounter::Overtaking => {
                if let Some(distance_ahead_m) = measured
                    .crossed_ahead_distance_m
                    .filter(|d| *d < scoring.clearance_m)
                {
                    self.violations
                        .push(ComplianceViolation::CrossedAhead { distance_ahead_m });
                    penalties.push(weights.crossed_ahead);
                }
                self.rule_13 = Some(rule_score(&penalties));
            }
            _ => {}
        }
    }

    /// Rule 17: a stand-on vessel keeps course and speed while it may not act
    /// (17(a)(i); `may_act` says when it may, see
    /// [`may_act`](crate::rules::may_act)), and in a crossing does not turn
    /// to port for a vessel on its own port side (17(c)). `duty` gives, at a
    /// sample, the duty toward another vessel that frees ownship to act
    /// then (decision 45): the departures it explains are recorded with it
    /// as justified, the others are findings.
    pub(super) fn judge_stand_on(
        &mut self,
        in_force: &[EncounterSample],
        latch: &EncounterLatch,
        rules: &RuleParameters,
        scoring: &ScoringParameters,
        may_act: impl Fn(&EncounterSample) -> bool,
        duty: impl Fn(&EncounterSample) -> Option<OtherDuty>,
    ) {
        let weights = &scoring.penalties;
        let mut penalties = Vec::new();
        // The course and speed to keep: the reference, or those last taken
        // while a duty toward another vessel was in force (rule 17(a)(i)
        // read with decision 22: once free of that duty, the course and
        // speed ownship then has; rules::alteration_made carries the course
        // for the planner). A departure while a duty frees ownship is
        // measured from what was kept when that duty began (decision 45).
        let mut kept = Kept {
            course_rad: latch.reference_course_rad,
            speed_mps: latch.reference_speed_mps,
        };
        let mut duty_began_on = None;
        let (mut early_turns, mut early_speeds) = (Vec::new(), Vec::new());
        for s in in_force {
            let Some(other) = duty(s) else {
                duty_began_on = None;
                if !may_act(s) {
                    let change = kept.change_to(s);
                    self.note_departure(s, change, rules, None);
                    early_turns.push(change.course_rad);
                    early_speeds.push(change.speed_mps);
                }
                continue;
            };
            let began_on = *duty_began_on.get_or_insert(kept);
            if !within_action_range(s.range_m(), rules) {
                self.note_departure(s, began_on.change_to(s), rules, Some(&other));
            }
            kept = Kept {
                course_rad: s.own.course_rad,
                speed_mps: s.own.speed_mps,
            };
        }
        let early_turn = largest_signed(early_turns.into_iter());
        let early_speed = largest_signed(early_speeds.into_iter());
        if is_stand_on_course_change(early_turn, rules) {
            self.violations
                .push(ComplianceViolation::StandOnCourseChanged {
                    course_change_rad: early_turn,
                });
            penalties.push(weights.stand_on_course_change);
        }
        if is_speed_change(early_speed, rules) {
            self.violations
                .push(ComplianceViolation::StandOnSpeedChanged {
                    speed_change_mps: early_speed,
                });
            penalties.push(weights.stand_on_speed_change);
        }
        if latch.encounter == Encounter::CrossingStandOn
            && let Some(s) = first_port_turn_for_port_vessel(in_force, latch, rules, &may_act)
        {
            self.violations
                .push(ComplianceViolation::StandOnTurnedToPort {
                    course_change_rad: turn_of(latch, s),
                });
            penalties.push(weights.stand_on_port_turn);
        }
        self.rule_17 = Some(rule_score(&penalties));
    }
}

impl Findings {
    /// Records a stand-on departure at `s` (`change` from what was to be
    /// kept beyond the tolerances), once per duty that justified one (and
    /// once for the unjustified), so that the report names every vessel
    /// whose duty took precedence (decision 45).
    fn note_departure(
        &mut self,
        s: &EncounterSample,
        change: Kept,
        rules: &RuleParameters,
        other: Option<&OtherDuty>,
    ) {
        let departed = is_stand_on_course_change(change.course_rad, rules)
            || is_speed_change(change.speed_mps, rules);
        let vessel = other.map(|other| other.vessel);
        let noted = self
            .stand_on_departures
            .iter()
            .any(|d| d.precedence.as_ref().map(|p| p.vessel) == vessel);
        if departed && !noted {
            self.stand_on_departures.push(StandOnDeparture {
                time_s: s.time_s,
                range_m: s.range_m(),
                course_change_rad: change.course_rad,
                speed_change_mps: change.speed_mps,
                precedence: other.map(Precedence::of),
            });
        }
    }
}

/// A stand-on vessel's course and speed to keep (or a change from them).
#[derive(Debug, Clone, Copy)]
struct Kept {
    /// Course, radians (a change: positive to starboard).
    course_rad: f64,
    /// Speed, m/s (a change: negative = slower).
    speed_mps: f64,
}

impl Kept {
    /// The change from these to ownship's course and speed at `s`.
    fn change_to(self, s: &EncounterSample) -> Self {
        Self {
            course_rad: course_change_rad(self.course_rad, s.own.course_rad),
            speed_mps: s.own.speed_mps - self.speed_mps,
        }
    }
}

impl Findings {
    /// The encounter judged from the course held before any turn (rules
    /// 2(a), 8(a), 17(c)): where risk arose just after ownship turned to port
    /// toward this vessel, on its port side forward of the beam, and made it
    /// a risk ([`is_port_turn_toward_vessel`], with the course ownship held a
    /// window before the latch, or before the turn then under way:
    /// [`steady_course_rad`] looking back [`STEADY_COURSE_WINDOW_S`]), the
    /// turn made the encounter. Latched on the new course alone, a vessel
    /// crossing from port is one ownship stands on for, and the port turn
    /// onto it would go unjudged. Booked against the encounter's own rule
    /// (17 standing on, 16 giving way) with the weight of 17(c).
    pub(super) fn judge_turn_into_encounter(
        &mut self,
        samples: &[EncounterSample],
        latch: &EncounterLatch,
        rules: &RuleParameters,
        scoring: &ScoringParameters,
    ) {
        let Some(index) = samples.iter().position(|s| s.time_s >= latch.latched_at_s) else {
            return;
        };
        let history = &samples[..=index];
        let times_s: Vec<f64> = history.iter().map(|s| s.time_s).collect();
        let courses_rad: Vec<f64> = history.iter().map(|s| s.own.course_rad).collect();
        let Some(before_rad) = steady_course_rad(&times_s, &courses_rad, STEADY_COURSE_WINDOW_S)
        else {
            return;
        };
        let at_latch = &samples[index];
        // The other vessel as it was moving when ownship turned: its course
        // held before any turn of its own of the last window, by the same
        // rule. A vessel that answers the turn (giving way to starboard, or
        // turning away) is seen part way round at the latch, and what it
        // then does is no part of whether ownship's turn put it in danger;
        // the planner, predicting its steady motion, judges the same
        // (decision 51).
        let target_courses_rad: Vec<f64> = history.iter().map(|s| s.target.course_rad).collect();
        let target = VesselState {
            course_rad: steady_course_rad(&times_s, &target_courses_rad, STEADY_COURSE_WINDOW_S)
                .unwrap_or(at_latch.target.course_rad),
            ..at_latch.target
        };
        if !is_port_turn_toward_vessel(before_rad, &at_latch.own, &target, rules) {
            return;
        }
        self.violations
            .push(ComplianceViolation::PortTurnTowardVessel {
                course_change_rad: course_change_rad(before_rad, at_latch.own.course_rad),
            });
        let score = match latch.encounter.role() {
            Role::StandOn => &mut self.rule_17,
            _ => &mut self.rule_16,
        };
        *score =
            Some((score.unwrap_or(1.0) - scoring.penalties.stand_on_port_turn).clamp(0.0, 1.0));
    }
}

/// Rule 17(c): in a crossing, a vessel that acts does not alter course to
/// port (of the course held when the encounter began) for a vessel on its
/// port side. Only a newly taken course counts, and before the stand-on
/// vessel may act (17(a)(ii)) only one beyond the stand-on tolerance: drift
/// within it is not action, nor is holding such a course into the action
/// range. The first such port turn, if the target was then on the port side.
#[expect(
    clippy::float_cmp,
    reason = "a course is newly taken when it differs at all from the last"
)]
fn first_port_turn_for_port_vessel<'a>(
    in_force: &'a [EncounterSample],
    latch: &EncounterLatch,
    rules: &RuleParameters,
    may_act: &impl Fn(&EncounterSample) -> bool,
) -> Option<&'a EncounterSample> {
    let port_turn = in_force
        .iter()
        .zip(std::iter::once(None).chain(in_force.iter().map(Some)))
        .find(|(s, previous)| {
            let altered = previous.is_none_or(|p| p.own.course_rad != s.own.course_rad);
            let turn = turn_of(latch, s);
            let acting = may_act(s) || is_stand_on_course_change(turn, rules);
            altered && acting && is_port_turn(turn, rules)
        })
        .map(|(s, _)| s)?;
    is_on_port_side(
        port_turn.own.position_m,
        latch.reference_course_rad,
        port_turn.target.position_m,
    )
    .then_some(port_turn)
}
