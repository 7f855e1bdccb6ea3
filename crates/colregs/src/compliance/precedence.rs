//! Which duty took precedence when a stand-on ownship departed from its
//! course or speed before rule 17(a)(ii) let it act on its own (decision 45).
//!
//! Among several vessels ownship may stand on for one and, at the same time,
//! have to keep out of the way of another (rule 16) or be free to act for a
//! third that is already within the stand-on action range (rule 17(a)(ii)).
//! It cannot keep its course and speed for the first and act for the others:
//! rule 17(a)(i) yields, as rule 2(b) asks of a departure "necessary to
//! avoid immediate danger" and as the planner reads it
//! ([`may_act`](crate::rules::may_act)). A departure so explained is not a
//! finding; the report names the duty, the vessel and the rule. One without
//! such a duty stays a finding (`stand_on_course_changed`,
//! `stand_on_speed_changed`).

use crate::encounter::Encounter;
use crate::latch::EncounterLatch;
use crate::parameters::RuleParameters;
use crate::rules::{acting_for_any, gives_way};
use serde::{Deserialize, Serialize};

/// A duty toward another vessel that frees a stand-on ownship to act.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Duty {
    /// Ownship had to keep out of the way of the other vessel (rules 16 and
    /// 2(b): the duty to keep out of the way takes precedence over keeping
    /// course and speed for this one).
    KeepOutOfTheWay,
    /// Ownship stood on for the other vessel, which was within the stand-on
    /// action range, so it might act for it (rule 17(a)(ii), 17(b) as it
    /// closes), and so could not keep course for this one (2(b)).
    StandOnMayAct,
}

impl Duty {
    /// A short name in snake case, as used in reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::KeepOutOfTheWay => "keep_out_of_the_way",
            Self::StandOnMayAct => "stand_on_may_act",
        }
    }

    /// The rules that let the duty take precedence over rule 17(a)(i).
    #[must_use]
    pub fn rule(self) -> &'static str {
        match self {
            Self::KeepOutOfTheWay => "16, 2(b)",
            Self::StandOnMayAct => "17(a)(ii), 2(b)",
        }
    }

    /// The duty ownship has toward a vessel with which `latch` is in force at
    /// `range_m`, if it frees it to act ([`acting_for_any`](crate::rules::acting_for_any)
    /// for one vessel).
    #[must_use]
    pub fn of(latch: &EncounterLatch, range_m: f64, parameters: &RuleParameters) -> Option<Self> {
        if gives_way(latch.encounter) {
            Some(Self::KeepOutOfTheWay)
        } else if acting_for_any([(latch, range_m)], parameters) {
            Some(Self::StandOnMayAct)
        } else {
            None
        }
    }
}

/// Ownship's duty toward one other vessel at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct OtherDuty {
    /// The other vessel: its index among the recording's targets.
    pub vessel: usize,
    /// The encounter with it in force.
    pub encounter: Encounter,
    /// The duty it gives ownship.
    pub duty: Duty,
    /// The range to it then, metres.
    pub range_m: f64,
}

impl OtherDuty {
    /// The duty that takes precedence among several at one instant: keeping
    /// out of the way first (rule 16 binds, 17(a)(ii) only permits), then
    /// the nearest vessel.
    #[must_use]
    pub fn precedent<'a>(duties: impl IntoIterator<Item = &'a Self>) -> Option<Self> {
        duties.into_iter().copied().min_by(|a, b| {
            let rank = |d: &Self| u8::from(d.duty != Duty::KeepOutOfTheWay);
            rank(a).cmp(&rank(b)).then(a.range_m.total_cmp(&b.range_m))
        })
    }
}

/// A departure from the stand-on course or speed while the give-way vessel
/// was still beyond the stand-on action range (rule 17(a)(i)): the course
/// changed by more than the stand-on course tolerance from the course to
/// keep (decision 22), or the speed by more than the speed tolerance from
/// the reference speed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StandOnDeparture {
    /// When ownship was first seen off its course or speed, seconds.
    pub time_s: f64,
    /// The range to the vessel stood on for then, metres.
    pub range_m: f64,
    /// The course change from the course to keep, radians, positive to
    /// starboard.
    pub course_change_rad: f64,
    /// The speed change from the reference speed, m/s, negative = slower.
    pub speed_change_mps: f64,
    /// The duty that took precedence, if one did: then the departure is
    /// justified and no finding; `None`: a finding.
    pub precedence: Option<Precedence>,
}

/// The duty toward another vessel that justified a stand-on departure.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Precedence {
    /// The duty.
    pub duty: Duty,
    /// The rules that let it take precedence over 17(a)(i) ([`Duty::rule`]).
    pub rule: String,
    /// The other vessel's index among the recording's targets.
    pub vessel: usize,
    /// The other vessel's name (empty where the caller knows no names).
    #[serde(default)]
    pub vessel_name: String,
    /// The encounter with the other vessel.
    pub encounter: Encounter,
    /// The range to the other vessel then, metres.
    pub range_m: f64,
}

impl Precedence {
    /// The precedence of `duty`.
    #[must_use]
    pub fn of(duty: &OtherDuty) -> Self {
        Self {
            duty: duty.duty,
            rule: duty.duty.rule().to_owned(),
            vessel: duty.vessel,
            vessel_name: String::new(),
            encounter: duty.encounter,
            range_m: duty.range_m,
        }
    }
}
