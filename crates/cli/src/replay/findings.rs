//! The findings of a run placed on the replay's timeline.
//!
//! A finding (`vorrt_colregs::ComplianceViolation`) carries no time: it is a
//! verdict on the encounter as a whole. The page puts each at the moment
//! the evaluation's own assessment dates what the finding is about (the
//! give-way action, the first risk, the closest approach), and says which
//! (decision 35). Nothing is judged here: the findings, their text and the
//! times all come from the evaluation and the report.

use crate::report::Report;
use serde::{Deserialize, Serialize};
use vorrt_colregs::ComplianceViolation;
use vorrt_scenarios::{Evaluation, TargetEvaluation};

/// One finding of the report, with the moment it is shown at.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct FindingMark {
    /// The target it concerns (`None`: a finding about ownship's whole track).
    pub(crate) vessel: Option<String>,
    /// The finding's name (`late_action`, ...; `track` for a track finding).
    pub(crate) name: String,
    /// The report's text of it, naming the rule.
    pub(crate) text: String,
    /// The COLREGs rule it is judged under (`None`: a safety or track finding).
    pub(crate) rule: Option<u8>,
    /// When it is shown, seconds (`None`: it concerns the whole track).
    pub(crate) time_s: Option<f64>,
    /// What that time is: `action` (ownship's action began), `risk` (risk of
    /// collision first arose), `closest_approach`, or `track`.
    pub(crate) at: String,
}

/// The moment a finding is about, from the assessment of its encounter:
/// `(time_s, what the time is)`.
#[must_use]
pub(crate) fn finding_time(
    finding: &ComplianceViolation,
    target: &TargetEvaluation,
) -> (f64, &'static str) {
    let closest = (target.time_of_min_s, "closest_approach");
    let action_time_s = target
        .assessment
        .as_ref()
        .and_then(|assessment| assessment.action_time_s);
    let risk = target.risk_time_s.map(|time_s| (time_s, "risk"));
    let action_or_risk = action_time_s
        .map(|time_s| (time_s, "action"))
        .or(risk)
        .unwrap_or(closest);
    match finding {
        // What ownship did, or did first, while the encounter was in force.
        ComplianceViolation::LateAction { .. }
        | ComplianceViolation::ActionNotApparent { .. }
        | ComplianceViolation::PortTurn { .. }
        | ComplianceViolation::SmallAlterations { .. }
        | ComplianceViolation::StandOnCourseChanged { .. }
        | ComplianceViolation::StandOnSpeedChanged { .. }
        | ComplianceViolation::StandOnTurnedToPort { .. } => action_or_risk,
        // Risk arose just after the turn toward the vessel (rule 17(c)).
        ComplianceViolation::PortTurnTowardVessel { .. } => risk.unwrap_or(closest),
        // Judged on the pass: the range, the side, no action by then; and
        // the findings whose moment the assessment does not record.
        ComplianceViolation::ClearanceViolated { .. }
        | ComplianceViolation::Collision { .. }
        | ComplianceViolation::NoAction
        | ComplianceViolation::StarboardToStarboard
        | ComplianceViolation::CrossedAhead { .. }
        | ComplianceViolation::AlterationNotHeld { .. } => closest,
    }
}

/// Every finding of the run: each target's, in the report's order, then
/// those about ownship's whole track.
#[must_use]
pub(crate) fn finding_marks(evaluation: &Evaluation, report: &Report) -> Vec<FindingMark> {
    let mut marks = Vec::new();
    for (target, reported) in evaluation.targets.iter().zip(&report.targets) {
        for (index, finding) in target.findings.iter().enumerate() {
            let (time_s, at) = finding_time(finding, target);
            marks.push(FindingMark {
                vessel: Some(reported.name.clone()),
                name: finding.name().to_owned(),
                text: reported
                    .violations
                    .get(index)
                    .cloned()
                    .unwrap_or_else(|| finding.to_string()),
                rule: finding.rule(),
                time_s: Some(time_s),
                at: at.to_owned(),
            });
        }
    }
    marks.extend(report.path_quality.findings.iter().map(|text| FindingMark {
        vessel: None,
        name: "track".to_owned(),
        text: text.clone(),
        rule: None,
        time_s: None,
        at: "track".to_owned(),
    }));
    marks
}

#[cfg(test)]
mod tests {
    use super::*;
    use vorrt_colregs::{Encounter, Role};

    fn target(risk_time_s: Option<f64>) -> TargetEvaluation {
        TargetEvaluation {
            name: "T".into(),
            encounter: Encounter::HeadOn,
            role: Role::GiveWay,
            risk_time_s,
            min_distance_m: 80.0,
            time_of_min_s: 600.0,
            clearance_kept: false,
            collision: false,
            compliant: false,
            violations: vec![],
            findings: vec![],
            action_range_m: None,
            first_alteration_deg: None,
            max_alteration_deg: None,
            score: 0.5,
            assessment: None,
            status: None,
            undecided: None,
        }
    }

    #[test]
    fn a_pass_finding_is_at_the_closest_approach() {
        let time = finding_time(
            &ComplianceViolation::ClearanceViolated {
                min_distance_m: 80.0,
            },
            &target(Some(100.0)),
        );
        assert_eq!(time, (600.0, "closest_approach"));
    }

    #[test]
    fn an_action_finding_without_an_action_is_at_the_first_risk() {
        let time = finding_time(
            &ComplianceViolation::PortTurn {
                course_change_rad: -0.5,
            },
            &target(Some(100.0)),
        );
        assert_eq!(time, (100.0, "risk"));
        let time = finding_time(
            &ComplianceViolation::LateAction { range_m: 900.0 },
            &target(None),
        );
        assert_eq!(time, (600.0, "closest_approach"));
    }
}
