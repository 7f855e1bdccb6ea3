//! The judgement of a recorded run **as sailed and as observed**: what
//! another vessel's radar or AIS shows of ownship's track, judged with the
//! criteria of the published evaluators (Woerner et al., Autonomous Robots
//! 2019; Minne, NTNU 2017; the NTNU evaluator of Hagen et al., Ocean
//! Engineering 2023). Data in, data out, no I/O: [`judge`] takes a
//! [`Recording`] (sample times, every vessel's positions, lengths and,
//! where known, recorded courses) and [`ObservedParameters`], and returns an
//! [`ObservedJudgement`]. It reads the tracks of any planner, so a
//! command that scores recorded tracks can call it as it is.
//!
//! ## Observed course and speed
//! At each sample, course over ground (COG) is the direction of
//! `p(t) - p(t - W)` and speed over ground (SOG) `|p(t) - p(t - W)| / W`,
//! over the window `W` ([`window_s`](ObservedParameters::window_s), 60 s):
//! positions interpolated linearly between samples ([`over_ground`]). Near
//! the start, where the window reaches back before the first sample: for a
//! vessel whose recording gives courses, the vessel is taken to have held
//! its first recorded course at its first step's speed before the start (a
//! run starts in steady motion; [`over_ground_from`]), so the COG at the
//! first samples is the course it was on, not a chord of a turn just begun;
//! for a track of positions only, the shortest available window (at the
//! first sample, the first step). A 30° heading held for one
//! 16 s leg moves the COG by about 8°; a turn held for the whole window moves
//! it fully. Every judgement of an encounter reads these observed states,
//! never a planner's waypoint courses.
//!
//! ## Noise
//! Tracks recorded at sea jitter (AIS: about 3 m, a tail to 15 m); over a
//! 60 s window that alone moves a slow vessel's COG by more than the 2°
//! detectable change. Each track's jitter is estimated from its positions,
//! or taken from the recording where it knows it better
//! ([`TrackObservation::position_noise_m`], from the fixes before any
//! resampling): [`position_noise_m`]. Its courses are then observed over a
//! window lengthened until the COG jitter is within
//! [`course_noise_budget_rad`](NoiseParameters::course_noise_budget_rad)
//! (0.3°), up to [`max_window_s`](NoiseParameters::max_window_s) (600 s),
//! and ownship's detectable change and action detection rise to 6 and 8 σ
//! of the jitter of a change where that is more than 2° and 5°
//! ([`track_noise`]; decision 31). An exact track (a closed-loop run's) has
//! no jitter and is judged with the window and thresholds as given; every
//! track's figures are in [`ObservedJudgement::noise`].
//!
//! ## Status and what a recording cannot decide
//! A target reporting itself at anchor, moored or aground
//! ([`TrackObservation::status`], [`NavigationalStatus::is_at_rest`]) is not
//! under way (rule 3(i)): judged on clearance alone, never latched. If she
//! nevertheless made way (median speed over ground of
//! [`REST_BELIEVED_BELOW_MPS`], 1 kn, or more: [`rest_contradicted`]), her
//! status and her motion contradict each other and her duties are not
//! known: still judged on clearance alone, rules 13-17 not judged, and the
//! encounter [`undecided`](ObservedEncounter::undecided)
//! ([`Undecided::StatusContradictsMotion`]). An encounter is also undecided
//! when its vessels are still closing at the last sample
//! ([`Undecided::StillClosing`], decision 32), and when its closest
//! approach, or more than half of its in-force window (from the latch to
//! the first sample passed, else to the end), lies in a stretch the target
//! did not report ([`TrackObservation::unreported`], [`not_reported`],
//! [`Undecided::NotReported`]); a target never latched is undecided so
//! only where its clearance was broken at an unreported closest approach
//! (decision 49). The findings so far stand; the passing and the clearance
//! are not a verdict.
//!
//! ## Path quality
//! Of ownship's track ([`path_quality`]), from the recorded course where the
//! recording gives one (the heading as sailed), else from the observed COG:
//! - **largest rate of turn**: the largest `|Δcourse| / Δt` between
//!   consecutive samples, degrees per second; above the vessel's limit
//!   ([`max_turn_rate_rad_s`](ObservedParameters::max_turn_rate_rad_s)) it is
//!   a [`TrackFinding::TurnRateExceeded`];
//! - **turn-direction reversals**: the number of turn episodes less one (see
//!   below);
//! - **course change per nautical mile**: the sum of `|Δcourse|` over the
//!   track divided by the distance sailed.
//!
//! ### Turn episodes
//! The course series is unwrapped into a cumulative course change. A **turn
//! episode** is a run between two turning points over which the cumulative
//! course moves one way by a detectable change (more than
//! [`turn_tolerance_rad`](crate::RuleParameters::turn_tolerance_rad), 2°,
//! the smallest change an observer detects); a counter-move of 2° or less
//! inside a run is absorbed, a larger one ends the run at its turning point
//! and starts one the other way ([`turn_episodes`]). Episodes alternate in
//! direction, so each one after the first is a turn-direction reversal. Two
//! same-way steps (20° then 15°) are one 35° episode.
//!
//! ## Encounters
//! Per target, the encounter is latched on the observed states with
//! [`update_latch`](crate::update_latch) / [`first_latch`](crate::first_latch),
//! exactly as a planner latches (the reference course and speed are the
//! observed COG and SOG at the latch), and assessed by the compliance module
//! ([`assess_encounter_acting`](crate::assess_encounter_acting)) on the
//! observed states: the one place where the rules are judged after the fact,
//! with the per-rule scores after Woerner 2019 / Minne 2017. As observed:
//! - **Give way** (head-on, crossing give-way, overtaking; rules 8, 14-16):
//!   - *action begun*: the first in-force sample whose COG differs from the
//!     reference by at least [`action_detection_rad`](crate::ScoringParameters::action_detection_rad)
//!     (5°) or whose SOG has dropped by
//!     [`action_speed_drop_fraction`](crate::ScoringParameters::action_speed_drop_fraction)
//!     (20 %); the range then is the action range. None while in force:
//!     [`NoAction`](crate::ComplianceViolation::NoAction). Only where an
//!     action was required: the pass predicted at the first in-force
//!     sample would not keep `d_th` between the hulls; a pass already clear
//!     owes none of these action findings (decision 42).
//!   - *early*: where risk arose at or beyond
//!     [`late_action_range_m`](crate::ScoringParameters::late_action_range_m)
//!     (2 nm), begun at that range or more; where it arose nearer, begun
//!     within [`reaction_time_s`](crate::ScoringParameters::reaction_time_s)
//!     (60 s) of the latch. Otherwise
//!     [`LateAction`](crate::ComplianceViolation::LateAction).
//!   - *readily apparent*: before the closest approach, the largest observed
//!     COG change at least [`apparent_turn_rad`](crate::RuleParameters::apparent_turn_rad)
//!     (30°) or the SOG at most half the reference
//!     ([`apparent_speed_reduction_fraction`](crate::ScoringParameters::apparent_speed_reduction_fraction)).
//!     Otherwise [`ActionNotApparent`](crate::ComplianceViolation::ActionNotApparent).
//!   - *first alteration direction*: the course change at the first sample
//!     at or beyond the detection threshold; to port in head-on or crossing
//!     is a [`PortTurn`](crate::ComplianceViolation::PortTurn) (as is a
//!     largest change to port).
//!   - *held until past*: once readily apparent, the COG change does not
//!     ease back more than the detectable 2° below 30° (a speed reduction not
//!     more than the 1 m/s speed tolerance below half) before the closest
//!     approach; otherwise [`AlterationNotHeld`](crate::ComplianceViolation::AlterationNotHeld).
//!   - *no succession of small alterations* (rule 8(b)): two or more turn
//!     episodes of the observed COG while in force, each detectable (over 2°)
//!     and not readily apparent (under 30°), are
//!     [`SmallAlterations`](crate::ComplianceViolation::SmallAlterations).
//!   - the manner of passing as before: port to port in head-on, not across
//!     the bow in crossing or overtaking (rules 13-15): across it within
//!     [`crossed_ahead_range_m`](crate::ScoringParameters::crossed_ahead_range_m)
//!     (1 nm) and with a real change of side, not a jitter of the heading
//!     line (decision 42).
//! - **Stand on** (crossing stand-on, being overtaken; rule 17): observed COG
//!   within [`stand_on_course_tolerance_rad`](crate::RuleParameters::stand_on_course_tolerance_rad)
//!   (15°) and SOG within [`stand_on_speed_tolerance_mps`](crate::RuleParameters::stand_on_speed_tolerance_mps)
//!   (1 m/s) of the reference while the range exceeds
//!   [`stand_on_action_range_m`](crate::RuleParameters::stand_on_action_range_m)
//!   (2 nm) and ownship gives way to no other target; and in a crossing no
//!   port turn for a vessel on the port side (17(c)).
//! - **Port turn toward a vessel**, whatever the role: where risk arose just
//!   after ownship turned to port toward the target (on the port side of the
//!   COG held a window before the latch, forward of the beam of the new one)
//!   and the turn made it a risk of collision (the target on the course it
//!   held a window before: decision 51),
//!   [`PortTurnTowardVessel`](crate::ComplianceViolation::PortTurnTowardVessel)
//!   ([`is_port_turn_toward_vessel`](crate::rules::is_port_turn_toward_vessel)).
//! - **Safety**, whatever the role: minimum distance (exact between
//!   samples), hull contact ([`in_contact`](crate::rules::in_contact)), `d_th`
//!   kept.
//!
//! The run is **compliant** when it has no finding: no track finding and no
//! rule broken in any encounter (the safety findings are reported beside).
//!
//! ## Parameters
//!
//! | parameter | default | source |
//! |---|---|---|
//! | [`window_s`](ObservedParameters::window_s) | 60 s | COG/SOG over the last minute, as radar or AIS shows it (Woerner 2019; NTNU evaluator) |
//! | [`turn_tolerance_rad`](crate::RuleParameters::turn_tolerance_rad) | 2° | smallest detectable change (Woerner 2019; NTNU `evaluator.yaml`) |
//! | [`action_detection_rad`](crate::ScoringParameters::action_detection_rad) | 5° | above the detectable 2°, below the NTNU evaluator's 10° starboard manoeuvre |
//! | [`action_speed_drop_fraction`](crate::ScoringParameters::action_speed_drop_fraction) | 20 % | a speed change an observer sees within a minute |
//! | [`apparent_turn_rad`](crate::RuleParameters::apparent_turn_rad) | 30° | readily apparent course change (Woerner 2019; Minne 2017) |
//! | [`apparent_speed_reduction_fraction`](crate::ScoringParameters::apparent_speed_reduction_fraction) | 0.5 | readily apparent speed change: half the speed (Woerner 2019) |
//! | [`late_action_range_m`](crate::ScoringParameters::late_action_range_m) | 2 nm | give-way action begun at 2 nm or more (Woerner 2019) |
//! | [`reaction_time_s`](crate::ScoringParameters::reaction_time_s) | 60 s | grace where risk arises nearer (one window; `CommonOcean`'s monitor allows about 2 min) |
//! | [`stand_on_course_tolerance_rad`](crate::RuleParameters::stand_on_course_tolerance_rad) | 15° | stand-on drift (NTNU evaluator) |
//! | [`stand_on_speed_tolerance_mps`](crate::RuleParameters::stand_on_speed_tolerance_mps) | 1 m/s | stand-on drift (NTNU evaluator) |
//! | [`stand_on_action_range_m`](crate::RuleParameters::stand_on_action_range_m) | 2 nm | rule 17(a)(ii) action range (Woerner 2019) |
//! | [`clearance_m`](crate::ScoringParameters::clearance_m) | 200 m | `d_th` (the paper's open-sea value; a run passes its own) |
//! | [`risk_distance`](crate::RuleParameters::risk_distance) | 1 nm, 6.4 lengths up to 2 nm, ¼ of the sea room | the risk-of-collision distance by the pair's lengths and the sea room, never under `d_th` between the hulls (Goodwin 1975; Fujii and Tanaka 1971; decision 50) |
//! | [`crossed_ahead_range_m`](crate::ScoringParameters::crossed_ahead_range_m) | 1 nm | crossing ahead of the bow beyond the risk-of-collision miss (`risk_cpa_m`) is an already-clear pass (decision 42) |
//! | [`max_turn_rate_rad_s`](ObservedParameters::max_turn_rate_rad_s) | none | the vessel's limit, when the recording has one |
//! | [`noise`](ObservedParameters::noise) | 0.3°, 600 s, 6 σ, 8 σ | course-jitter budget, longest window, detectable change and action detection above the jitter (decision 31) |
//!
//! ## Example
//!
//! ```
//! use vorrt_colregs::observed::{judge, ObservedParameters, RecordedTrack, Recording};
//! use vorrt_colregs::Encounter;
//! use glam::DVec2;
//! // Head-on at 6 m/s each, 9 km apart, set to pass 150 m apart (50 m
//! // between the hulls, under d_th); ownship holds course: no action.
//! let times_s: Vec<f64> = (0..=150).map(|i| f64::from(i) * 10.0).collect();
//! let track = |name: &str, start: DVec2, velocity: DVec2| RecordedTrack {
//!     name: name.into(),
//!     length_m: 100.0,
//!     positions_m: times_s.iter().map(|t| start + velocity * *t).collect(),
//!     courses_rad: None,
//!     observation: Default::default(),
//! };
//! let recording = Recording {
//!     ownship: track("ownship", DVec2::ZERO, DVec2::new(0.0, 6.0)),
//!     targets: vec![track("TS1", DVec2::new(150.0, 9000.0), DVec2::new(0.0, -6.0))],
//!     times_s: times_s.clone(),
//! };
//! let judgement = judge(&recording, &ObservedParameters::default()).unwrap();
//! let target = &judgement.targets[0];
//! assert_eq!(target.latch.unwrap().encounter, Encounter::HeadOn);
//! assert!(target.findings.iter().any(|f| f.name() == "no_action"));
//! assert!(!judgement.compliant);
//! assert_eq!(judgement.path.turn_reversals, 0);
//! ```

mod judge;
#[cfg(test)]
mod mariner_tests;
mod noise;
#[cfg(test)]
mod noise_tests;
mod observe;
mod parameters;
mod quality;
#[cfg(test)]
mod real_tests;
mod recording;
#[cfg(test)]
mod risk_distance_tests;
mod status;
#[cfg(test)]
mod tests;
mod undecided;

pub use crate::compliance::episodes::{TurnEpisode, turn_episodes, turn_reversals};
pub use judge::{ObservedEncounter, ObservedJudgement, TrackFinding, judge};
pub use noise::{
    MAKING_WAY_MPS, NoiseParameters, TrackNoise, position_noise_m, track_noise, typical_speed_mps,
};
pub use observe::{OverGround, over_ground, over_ground_from};
pub use parameters::ObservedParameters;
pub use quality::{PathQuality, path_quality};
pub use recording::{RecordedTrack, Recording, TrackObservation};
pub use status::NavigationalStatus;
pub use undecided::{
    REST_BELIEVED_BELOW_MPS, Undecided, Unreported, in_force_window_s, median_step_speed_mps,
    not_reported, reach_m, rest_contradicted,
};
