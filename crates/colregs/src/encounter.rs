//! Encounter classification by rules 13-15, and the role each gives ownship.
//!
//! With β the relative bearing of the target from ownship and α that of
//! ownship from the target, the tests run in the evaluators' order (notes,
//! "COLREGs geometry"):
//! 1. α in the stern sector (more than 22.5° abaft the target's beam) and
//!    ownship faster: **overtaking** (rule 13);
//! 2. β in ownship's stern sector and the target faster: **being overtaken**;
//! 3. either vessel in the other's stern sector otherwise: **none** (no rule
//!    applies: the vessels are not converging in a way the rules name);
//! 4. |β| and |α| both inside the head-on half-width: **head-on** (rule 14);
//! 5. otherwise **crossing** (rule 15): target on ownship's starboard side
//!    (β in `[0, π)`) makes ownship give way, on the port side stand on.
//!
//! Classification is purely geometric; whether the rules are in force is the
//! risk test's business ([`assess_risk`](crate::assess_risk)), and
//! [`EncounterLatch`] keeps the type once risk arises.

use crate::parameters::RuleParameters;
use crate::vessel::VesselState;
use serde::{Deserialize, Serialize};
use std::f64::consts::{PI, TAU};

/// The type of encounter between ownship and one target, from ownship's side.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Encounter {
    /// Meeting on reciprocal or nearly reciprocal courses (rule 14): both give way.
    HeadOn,
    /// Crossing with the target on ownship's starboard side (rule 15): ownship gives way.
    CrossingGiveWay,
    /// Crossing with the target on ownship's port side: ownship stands on (rule 17).
    CrossingStandOn,
    /// Ownship overtakes the target (rule 13): ownship keeps clear.
    Overtaking,
    /// The target overtakes ownship: ownship stands on (rule 17).
    BeingOvertaken,
    /// No rule of 13-15 applies.
    None,
}

/// What an encounter asks of ownship.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Role {
    /// Keep out of the way (rule 16).
    GiveWay,
    /// Keep course and speed (rule 17).
    StandOn,
    /// No obligation from rules 13-17.
    None,
}

impl Encounter {
    /// Every encounter type, in a fixed order.
    pub const ALL: [Encounter; 6] = [
        Encounter::HeadOn,
        Encounter::CrossingGiveWay,
        Encounter::CrossingStandOn,
        Encounter::Overtaking,
        Encounter::BeingOvertaken,
        Encounter::None,
    ];

    /// Ownship's role in this encounter.
    #[must_use]
    pub fn role(self) -> Role {
        match self {
            Encounter::HeadOn | Encounter::CrossingGiveWay | Encounter::Overtaking => Role::GiveWay,
            Encounter::CrossingStandOn | Encounter::BeingOvertaken => Role::StandOn,
            Encounter::None => Role::None,
        }
    }

    /// The same encounter seen from the target's side.
    #[must_use]
    pub fn swapped(self) -> Encounter {
        match self {
            Encounter::HeadOn => Encounter::HeadOn,
            Encounter::CrossingGiveWay => Encounter::CrossingStandOn,
            Encounter::CrossingStandOn => Encounter::CrossingGiveWay,
            Encounter::Overtaking => Encounter::BeingOvertaken,
            Encounter::BeingOvertaken => Encounter::Overtaking,
            Encounter::None => Encounter::None,
        }
    }

    /// A short name in snake case, as used in reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Encounter::HeadOn => "head_on",
            Encounter::CrossingGiveWay => "crossing_give_way",
            Encounter::CrossingStandOn => "crossing_stand_on",
            Encounter::Overtaking => "overtaking",
            Encounter::BeingOvertaken => "being_overtaken",
            Encounter::None => "none",
        }
    }

    /// The COLREGs rule that defines this encounter.
    #[must_use]
    pub fn rule(self) -> Option<u8> {
        match self {
            Encounter::HeadOn => Some(14),
            Encounter::CrossingGiveWay | Encounter::CrossingStandOn => Some(15),
            Encounter::Overtaking | Encounter::BeingOvertaken => Some(13),
            Encounter::None => None,
        }
    }
}

impl std::fmt::Display for Encounter {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl Role {
    /// A short name in snake case, as used in reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Role::GiveWay => "give_way",
            Role::StandOn => "stand_on",
            Role::None => "none",
        }
    }
}

impl std::fmt::Display for Role {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// Classifies the encounter of `own` with `target` (rules 13-15).
///
/// ```
/// use vorrt_colregs::{classify, Encounter, RuleParameters, VesselState};
/// use glam::DVec2;
/// let params = RuleParameters::default();
/// let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
/// // From starboard, heading west: ownship gives way.
/// let crossing = VesselState::new(DVec2::new(3000.0, 3000.0), 1.5 * std::f64::consts::PI, 6.0, 50.0);
/// assert_eq!(classify(&own, &crossing, &params), Encounter::CrossingGiveWay);
/// assert_eq!(classify(&crossing, &own, &params), Encounter::CrossingStandOn);
/// ```
#[must_use]
pub fn classify(own: &VesselState, target: &VesselState, parameters: &RuleParameters) -> Encounter {
    let beta = own.bearing_to(target);
    let alpha = target.bearing_to(own);
    let in_stern_sector = |bearing: f64| {
        bearing > parameters.abaft_beam_rad && bearing < TAU - parameters.abaft_beam_rad
    };
    let own_in_target_stern = in_stern_sector(alpha);
    let target_in_own_stern = in_stern_sector(beta);
    if own_in_target_stern && own.speed_mps > target.speed_mps {
        return Encounter::Overtaking;
    }
    if target_in_own_stern && target.speed_mps > own.speed_mps {
        return Encounter::BeingOvertaken;
    }
    if own_in_target_stern || target_in_own_stern {
        return Encounter::None;
    }
    let near_ahead = |bearing: f64| {
        bearing < parameters.head_on_half_width_rad
            || bearing > TAU - parameters.head_on_half_width_rad
    };
    if near_ahead(beta) && near_ahead(alpha) {
        return Encounter::HeadOn;
    }
    if beta < PI {
        Encounter::CrossingGiveWay
    } else {
        Encounter::CrossingStandOn
    }
}

/// An encounter in force: its type, fixed when risk was first detected, and
/// ownship's course and speed at that moment (the reference against which
/// turns and stand-on drift are judged).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct EncounterLatch {
    /// The encounter type, fixed while the latch holds.
    pub encounter: Encounter,
    /// Ownship's course when the encounter began, radians.
    pub reference_course_rad: f64,
    /// Ownship's speed when the encounter began, m/s.
    pub reference_speed_mps: f64,
    /// When the encounter began, seconds.
    pub latched_at_s: f64,
    /// The pair's risk-of-collision distance when the encounter began
    /// ([`RuleParameters::risk_distance_m`](crate::RuleParameters::risk_distance_m),
    /// decision 50), metres; `None` for a latch made without the target's
    /// length (then the distance for vessels of no length is used).
    #[serde(default)]
    pub risk_distance_m: Option<f64>,
}

impl EncounterLatch {
    /// Latches `encounter` with ownship's present course and speed as reference.
    #[must_use]
    pub fn new(encounter: Encounter, own: &VesselState, time_s: f64) -> Self {
        Self {
            encounter,
            reference_course_rad: own.course_rad,
            reference_speed_mps: own.speed_mps,
            latched_at_s: time_s,
            risk_distance_m: None,
        }
    }

    /// The same latch, made with the pair's risk-of-collision distance.
    #[must_use]
    pub fn with_risk_distance(self, risk_distance_m: f64) -> Self {
        Self {
            risk_distance_m: Some(risk_distance_m),
            ..self
        }
    }

    /// The risk-of-collision distance the encounter is judged with: the
    /// pair's, else that of `parameters` for vessels of no length.
    #[must_use]
    pub fn risk_distance_or(&self, parameters: &crate::RuleParameters) -> f64 {
        self.risk_distance_m
            .unwrap_or_else(|| parameters.risk_distance_m(0.0, 0.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    fn vessel(x: f64, y: f64, course_deg: f64, speed: f64) -> VesselState {
        VesselState::new(DVec2::new(x, y), course_deg.to_radians(), speed, 50.0)
    }

    #[test]
    fn head_on() {
        let p = RuleParameters::default();
        assert_eq!(
            classify(
                &vessel(0.0, 0.0, 0.0, 6.0),
                &vessel(100.0, 5000.0, 180.0, 6.0),
                &p
            ),
            Encounter::HeadOn
        );
    }

    #[test]
    fn overtaking_and_being_overtaken() {
        let p = RuleParameters::default();
        let own = vessel(0.0, 0.0, 0.0, 6.0);
        let slow_ahead = vessel(0.0, 2000.0, 0.0, 4.0);
        assert_eq!(classify(&own, &slow_ahead, &p), Encounter::Overtaking);
        assert_eq!(classify(&slow_ahead, &own, &p), Encounter::BeingOvertaken);
        let fast_ahead = vessel(0.0, 2000.0, 0.0, 8.0);
        assert_eq!(classify(&own, &fast_ahead, &p), Encounter::None);
    }

    #[test]
    fn port_crossing_is_stand_on() {
        let p = RuleParameters::default();
        assert_eq!(
            classify(
                &vessel(0.0, 0.0, 0.0, 6.0),
                &vessel(-3000.0, 3000.0, 90.0, 6.0),
                &p
            ),
            Encounter::CrossingStandOn
        );
    }

    #[test]
    fn roles_and_swaps() {
        for encounter in Encounter::ALL {
            assert_eq!(encounter.swapped().swapped(), encounter);
        }
        assert_eq!(Encounter::HeadOn.role(), Role::GiveWay);
        assert_eq!(Encounter::BeingOvertaken.role(), Role::StandOn);
    }
}
