//! # vorrt-colregs
//!
//! The International Regulations for Preventing Collisions at Sea (COLREGs),
//! rules 13-17, as a planner needs them: data in, judgements out, no I/O.
//! Built on [`vorrt_geometry`]; SI units, x east / y north, nautical angles.
//!
//! ## Catalogue
//!
//! | module | what it gives |
//! |---|---|
//! | [`vessel`] | [`VesselState`]: position, course, speed, length; bearings and ranges |
//! | [`parameters`] | [`RuleParameters`]: MTD, head-on sector, stand-on tolerances, ... with the notes' defaults |
//! | [`risk`] | [`assess_risk`]: range under MTD, CPA under a threshold, CPA ahead in time |
//! | [`encounter`] | [`classify`]: head-on, crossing give-way / stand-on, overtaking, being overtaken, none (rules 13-15); [`Role`] |
//! | [`latch`] | [`EncounterLatch`], [`update_latch`], [`has_passed`]: keep an encounter's type until the vessels have passed |
//! | [`passing`] | [`passing_side`], [`crosses_ahead`]: how ownship passes a target |
//! | [`rules`] | the rule book: the shared predicates ([`rules::may_act`], [`rules::giving_way_to_any`], [`rules::is_port_turn`], [`rules::is_readily_apparent`], [`rules::in_contact`], ...) every check and score calls; the one definition of collision (hull contact) |
//! | [`observed`] | [`observed::judge`]: a recorded run judged as sailed and as observed (COG/SOG over a window, path quality, encounters assessed on the observed states) |
//! | [`compliance`] | [`assess_encounter`]: post-hoc scoring of one recorded encounter (safety, rules 13-17), [`ScoringParameters`] |
//! | [`maneuver`] | [`check_maneuver`]: whether a candidate velocity obeys rules 14-17 in an encounter in force; [`check_alteration`]: rule 16's readily apparent alteration |
//! | [`error`] | [`ColregsError`] |
//!
//! ## Example
//!
//! ```
//! use vorrt_colregs::{classify, update_latch, check_maneuver, Encounter, RuleParameters, VesselState};
//! use glam::DVec2;
//!
//! let params = RuleParameters::default();
//! let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
//! // A vessel 3 km east and 3 km north heading west: a crossing from starboard.
//! let target = VesselState::new(DVec2::new(3000.0, 3000.0), 270f64.to_radians(), 6.0, 80.0);
//! assert_eq!(classify(&own, &target, &params), Encounter::CrossingGiveWay);
//! let latch = update_latch(None, &own, &target, 0.0, &params).expect("risk of collision");
//! // A starboard turn that passes astern is allowed; holding course crosses ahead.
//! assert!(check_maneuver(&latch, own.position_m, 60f64.to_radians(), 6.0, &target, &params).is_ok());
//! assert!(check_maneuver(&latch, own.position_m, 0.0, 6.0, &target, &params).is_err());
//! ```
#![forbid(missing_docs)]

pub mod compliance;
pub mod encounter;
pub mod error;
pub mod latch;
pub mod maneuver;
pub mod observed;
pub mod parameters;
pub mod passing;
pub mod risk;
pub mod rules;
pub mod vessel;

pub use compliance::{
    ComplianceViolation, EncounterAssessment, EncounterSample, PenaltyWeights, RuleScores,
    ScoringParameters, assess_encounter, assess_encounter_acting, first_latch, safety_score,
};
pub use encounter::{Encounter, Role, classify};
pub use error::ColregsError;
pub use latch::{EncounterLatch, has_passed, update_latch, update_latch_steady};
pub use maneuver::{
    CandidateMotion, ManeuverViolation, check_action, check_alteration, check_heading,
    check_maneuver, check_maneuver_acting, check_motion, stand_on_may_act,
};
pub use parameters::RuleParameters;
pub use passing::{PassingSide, crosses_ahead, passing_side};
pub use risk::{RiskAssessment, assess_risk};
pub use vessel::VesselState;
