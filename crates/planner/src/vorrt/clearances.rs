//! The verdicts of one manoeuvre search from the root, shared between the
//! two clearances of the ladder (decision 59).
//!
//! The search from the root asks each manoeuvre shape at the preferred
//! clearance and at `d_th` ([`ROOT_LADDER`](super::ROOT_LADDER)); the two
//! searches ask many of the same legs from the same encounters. The
//! validity check is a pure function of the leg, its start time and the
//! encounters in force for one planner call, and its clearance enters only
//! in tests of the form "a distance under the clearance refuses"
//! (`SafetyChecker::check`, `check_clearance`): every other test, and the
//! encounters carried to the leg's end, do not depend on it. Hence:
//!
//! - a leg accepted at a clearance is accepted at any narrower one, with
//!   the same encounters at its end (the premise of the ladder's
//!   [`Probe`](super::Probe));
//! - a leg refused at a clearance for a cause `X` is refused at any wider
//!   one, for `X` or for a clearance cause met on the way
//!   ([`RejectionCause::Clearance`], [`RejectionCause::ClearanceAhead`]);
//! - the same leg asked again at the same clearance gets the same verdict.
//!
//! The same holds of a refusal on a chord of a leg's turn for every leg with
//! the same start, turn, speeds, start time and encounters, whatever its
//! straight run (`SafetyChecker::validate_pieces`): the holds of one
//! alteration, and the courses astern of a vessel held 1, 2 or 4 km
//! (`simplify::return_to_goal`), are such legs, and a port turn is often
//! refused on its chords (decision 51).
//!
//! [`AcrossClearances`] gives a remembered verdict where these make it
//! certain. The verdict's cause is exact except for a refusal carried to a
//! wider clearance, which is given only where the search has already found
//! a plan whatever this one finds (the ladder's `d_th` rung found one and the
//! preferred is asked to widen it: its refusals are then not kept) and only
//! where the cause is not the one the manoeuvre search branches on
//! ([`ManeuverViolation::PortTurnTowardVessel`]: the return astern of a
//! vessel, `simplify::return_to_goal`), which a clearance cause is not
//! either. The plans are the same bit for bit; only the work differs.

use crate::constraint::Constraint;
use crate::plan::RejectionCause;
use crate::safety::SafetyChecker;
use crate::validity::key::{WordMap, key_of, start_key_of};
use crate::validity::{EncounterState, LegPrefixes, MotionValidator};
use std::cell::{Cell, RefCell};
use vorrt_colregs::ManeuverViolation;
use vorrt_jfs::Leg;

/// What one leg, from one start time and encounters, came to.
#[derive(Debug, Default)]
struct Known {
    /// The widest clearance it was accepted at, metres, and the encounters
    /// at its end.
    accepted: Option<(f64, EncounterState)>,
    /// The narrowest clearance it was refused at, metres, and the cause.
    refused: Option<(f64, RejectionCause)>,
}

/// The verdicts of one search from the root, by leg, start time and
/// encounters in force, and the refusals on a turn's chords by the same
/// less the straight run (module documentation).
#[derive(Debug, Default)]
pub(crate) struct ClearanceMemo {
    known: RefCell<WordMap<Known>>,
    /// The narrowest clearance a turn was refused at on a chord, metres,
    /// and the cause.
    turns: RefCell<WordMap<(f64, RejectionCause)>>,
    /// How many legs were passed on to be judged.
    judged: Cell<u64>,
    /// The legs accepted, for longer legs with the same start (decision 70).
    prefixes: LegPrefixes,
}

impl ClearanceMemo {
    /// How many legs were passed on to be judged (the others were given a
    /// remembered verdict).
    #[cfg(test)]
    pub(crate) fn judged(&self) -> u64 {
        self.judged.get()
    }
}

/// The shortest straight run, metres, of a leg whose refusal on a chord is
/// shared: every piece of a longer run ends clear of the turn
/// (`Leg::pieces` counts a piece ending within `SAME_POINT_M` of the arc
/// as a chord).
const SHARED_TURN_MIN_STRAIGHT_M: f64 = 1.0;

/// The key of `leg`'s turn (the leg less its straight run) from
/// `start_elapsed_s` with `state`, where its chords' verdicts are shared.
fn turn_key_of(leg: &Leg, start_elapsed_s: f64, state: &EncounterState) -> Option<Vec<u64>> {
    (leg.turn_rad != 0.0 && leg.straight_m >= SHARED_TURN_MIN_STRAIGHT_M)
        .then(|| start_key_of(leg, start_elapsed_s, state))
}

/// The validator of one rung of the search from the root at `clearance_m`,
/// giving the verdicts `memo` makes certain and remembering the others
/// (module documentation).
pub(crate) struct AcrossClearances<'a, 'c, C> {
    pub(crate) validator: &'a SafetyChecker<'c, C>,
    pub(crate) memo: &'a ClearanceMemo,
    /// The clearance `validator` judges at, metres.
    pub(crate) clearance_m: f64,
    /// Whether a refusal at a narrower clearance may be given (the search
    /// has found a plan whatever this one finds, and no earlier search's
    /// verdicts are being replayed).
    pub(crate) widening: bool,
}

impl<C> AcrossClearances<'_, '_, C> {
    /// Whether a refusal for `cause` at `refused_m` is this validator's:
    /// at the same clearance, or carried wider where that may be given.
    fn refuses(&self, refused_m: f64, cause: RejectionCause) -> bool {
        refused_m.to_bits() == self.clearance_m.to_bits()
            || (self.widening
                && refused_m <= self.clearance_m
                && cause != RejectionCause::Colregs(ManeuverViolation::PortTurnTowardVessel))
    }
}

impl<C: Constraint> MotionValidator for AcrossClearances<'_, '_, C> {
    fn validate(
        &self,
        leg: &Leg,
        start_elapsed_s: f64,
        state: &mut EncounterState,
    ) -> Result<(), RejectionCause> {
        let key = key_of(leg, start_elapsed_s, state);
        if let Some(known) = self.memo.known.borrow().get(&key) {
            if let Some((accepted_m, after)) = &known.accepted
                && *accepted_m >= self.clearance_m
            {
                state.clone_from(after);
                return Ok(());
            }
            if let Some((refused_m, cause)) = known.refused
                && self.refuses(refused_m, cause)
            {
                return Err(cause);
            }
        }
        let turn_key = turn_key_of(leg, start_elapsed_s, state)
            .filter(|_| self.validator.turn_verdicts_shared());
        if let Some(turn_key) = &turn_key
            && let Some(&(refused_m, cause)) = self.memo.turns.borrow().get(turn_key)
            && self.refuses(refused_m, cause)
        {
            return Err(cause);
        }
        let mut on_turn = false;
        self.memo.judged.set(self.memo.judged.get() + 1);
        let verdict = self.validator.validate_pieces(
            leg,
            start_elapsed_s,
            state,
            &mut on_turn,
            Some((&self.memo.prefixes, self.clearance_m)),
        );
        if let (Err(cause), true, Some(turn_key)) = (verdict, on_turn, turn_key) {
            let mut turns = self.memo.turns.borrow_mut();
            let entry = turns.entry(turn_key).or_insert((self.clearance_m, cause));
            if self.clearance_m < entry.0 {
                *entry = (self.clearance_m, cause);
            }
        }
        let mut known = self.memo.known.borrow_mut();
        let entry = known.entry(key).or_default();
        match verdict {
            Ok(()) => {
                if entry
                    .accepted
                    .as_ref()
                    .is_none_or(|(accepted_m, _)| self.clearance_m > *accepted_m)
                {
                    entry.accepted = Some((self.clearance_m, state.clone()));
                }
            }
            Err(cause) => {
                if entry
                    .refused
                    .is_none_or(|(refused_m, _)| self.clearance_m < refused_m)
                {
                    entry.refused = Some((self.clearance_m, cause));
                }
            }
        }
        verdict
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::PlannerConfig;
    use glam::DVec2;
    use vorrt_colregs::VesselState;
    use vorrt_jfs::{MotionModel, Pose, RateLimitedTurn, TargetState};

    /// A target lying still at `at_m`, 50 m long.
    fn still_at(at_m: DVec2) -> Vec<vorrt_jfs::LinearTrack> {
        vec![TargetState::constant_velocity(VesselState::new(at_m, 0.0, 0.0, 50.0)).track()]
    }

    fn no_encounter() -> EncounterState {
        EncounterState::new(vec![None], vec![0.0])
    }

    /// The checkers at `d_th` and at the preferred clearance.
    fn configs() -> (PlannerConfig, PlannerConfig) {
        let floor = PlannerConfig::default();
        let preferred = PlannerConfig {
            clearance_m: floor.clearance_m * floor.preferred_clearance_factor,
            ..floor
        };
        (floor, preferred)
    }

    #[test]
    fn a_leg_accepted_wider_is_accepted_at_d_th_with_the_same_encounters_unjudged() {
        let (floor, preferred) = configs();
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
        let goal_m = DVec2::new(0.0, 5000.0);
        // Beyond MTD of the leg throughout.
        let tracks = still_at(DVec2::new(9000.0, 2500.0));
        let wide = SafetyChecker::new(&preferred, &tracks, own, goal_m, 0.0);
        let narrow = SafetyChecker::new(&floor, &tracks, own, goal_m, 0.0);
        let memo = ClearanceMemo::default();
        let leg = Leg::straight(DVec2::ZERO, 0.0, 5000.0, 6.0);
        let across = |checker, clearance_m| AcrossClearances {
            validator: checker,
            memo: &memo,
            clearance_m,
            widening: false,
        };
        let mut state = no_encounter();
        assert_eq!(
            across(&wide, preferred.clearance_m).validate(&leg, 0.0, &mut state),
            Ok(())
        );
        assert_eq!(memo.judged(), 1);
        let mut remembered = no_encounter();
        assert_eq!(
            across(&narrow, floor.clearance_m).validate(&leg, 0.0, &mut remembered),
            Ok(())
        );
        // Not judged again, and the encounters are those the check gives.
        assert_eq!(memo.judged(), 1);
        let mut judged = no_encounter();
        assert_eq!(narrow.validate(&leg, 0.0, &mut judged), Ok(()));
        assert_eq!(remembered, judged);
    }

    #[test]
    fn a_refusal_at_d_th_is_carried_wider_only_once_a_plan_is_found() {
        let (floor, preferred) = configs();
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
        let goal_m = DVec2::new(0.0, 5000.0);
        // 150 m off the leg: inside d_th.
        let tracks = still_at(DVec2::new(150.0, 1000.0));
        let wide = SafetyChecker::new(&preferred, &tracks, own, goal_m, 0.0);
        let narrow = SafetyChecker::new(&floor, &tracks, own, goal_m, 0.0);
        let memo = ClearanceMemo::default();
        let leg = Leg::straight(DVec2::ZERO, 0.0, 2000.0, 6.0);
        let refused = narrow.validate(&leg, 0.0, &mut no_encounter());
        assert!(refused.is_err());
        let at_floor = AcrossClearances {
            validator: &narrow,
            memo: &memo,
            clearance_m: floor.clearance_m,
            widening: false,
        };
        assert_eq!(at_floor.validate(&leg, 0.0, &mut no_encounter()), refused);
        // The same leg at the same clearance: the same verdict, not judged.
        assert_eq!(at_floor.validate(&leg, 0.0, &mut no_encounter()), refused);
        assert_eq!(memo.judged(), 1);
        let wider = |widening| AcrossClearances {
            validator: &wide,
            memo: &memo,
            clearance_m: preferred.clearance_m,
            widening,
        };
        // Wider before a plan is found: judged (the cause is kept exact).
        assert_eq!(
            wider(false).validate(&leg, 0.0, &mut no_encounter()),
            refused
        );
        assert_eq!(memo.judged(), 2);
        let other = Leg::straight(DVec2::ZERO, 0.0, 2500.0, 6.0);
        assert!(at_floor.validate(&other, 0.0, &mut no_encounter()).is_err());
        assert_eq!(memo.judged(), 3);
        // Once a plan is found, carried wider without being judged.
        assert!(
            wider(true)
                .validate(&other, 0.0, &mut no_encounter())
                .is_err()
        );
        assert_eq!(memo.judged(), 3);
    }

    #[test]
    fn a_refusal_on_a_turn_is_shared_by_every_straight_run_after_it() {
        let (floor, _) = configs();
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
        let goal_m = DVec2::new(3000.0, 300.0);
        // Inside the 90° turn to starboard of radius 300 m (its centre at
        // (300, 0)): 88 m off the arc.
        let tracks = still_at(DVec2::new(150.0, 150.0));
        let checker = SafetyChecker::new(&floor, &tracks, own, goal_m, 0.0);
        let model = RateLimitedTurn {
            turn_radius_m: 300.0,
        };
        let start = Pose {
            position_m: DVec2::ZERO,
            course_rad: 0.0,
        };
        let east = std::f64::consts::FRAC_PI_2;
        let (short, long) = (
            model.turn_onto(start, east, 6.0, 1000.0),
            model.turn_onto(start, east, 6.0, 2000.0),
        );
        let mut on_turn = false;
        let refused = checker.validate_pieces(&short, 0.0, &mut no_encounter(), &mut on_turn, None);
        assert_eq!(refused, Err(RejectionCause::Clearance));
        assert!(on_turn);
        let memo = ClearanceMemo::default();
        let across = AcrossClearances {
            validator: &checker,
            memo: &memo,
            clearance_m: floor.clearance_m,
            widening: false,
        };
        assert_eq!(across.validate(&short, 0.0, &mut no_encounter()), refused);
        assert_eq!(across.validate(&long, 0.0, &mut no_encounter()), refused);
        assert_eq!(memo.judged(), 1);
        assert_eq!(checker.validate(&long, 0.0, &mut no_encounter()), refused);
    }
}
