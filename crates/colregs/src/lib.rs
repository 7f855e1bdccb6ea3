#![doc = include_str!("../README.md")]
#![forbid(missing_docs)]

pub mod compliance;
pub mod encounter;
pub mod error;
pub mod latch;
pub mod maneuver;
pub mod observed;
pub mod parameters;
pub mod passing;
mod port_turn_gate;
pub mod risk;
pub mod risk_distance;
pub mod rule10;
pub mod rules;
pub mod vessel;

pub use compliance::{
    ComplianceViolation, Duty, EncounterAssessment, EncounterSample, OtherDuty, PenaltyWeights,
    Precedence, RuleScores, ScoringParameters, StandOnDeparture, assess_encounter,
    assess_encounter_acting, first_latch, safety_score,
};
pub use encounter::{Encounter, Role, classify};
pub use error::ColregsError;
pub use latch::{
    EncounterLatch, has_passed, has_passed_moving, update_latch, update_latch_judged,
    update_latch_seen_moving, update_latch_steady, update_latch_steady_moving,
};
pub use maneuver::{
    CandidateMotion, ManeuverViolation, check_action, check_alteration, check_heading,
    check_maneuver, check_maneuver_acting, check_motion, stand_on_may_act,
};
pub use parameters::RuleParameters;
pub use passing::{PassingSide, crosses_ahead, passing_side};
pub use risk::{RiskAssessment, assess_risk};
pub use risk_distance::RiskDistanceRule;
pub use vessel::VesselState;

// What the public signatures take, so that this crate alone is enough.
pub use glam::{self, DVec2};
pub use vorrt_geometry as geometry;
