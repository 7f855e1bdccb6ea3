//! The legs of one search judged so far, kept so that a longer leg with the
//! same start resumes where a shorter one ended (decision 70).
//!
//! The manoeuvre search asks one course held for 250 m, 500 m, 1 km, ... 12
//! km from the same pose, time and encounters ([`HOLD_M`](crate::simplify::HOLD_M)),
//! and a course astern of a vessel held 1, 2 and 4 km: each longer hold
//! sails the shorter one's pieces first ([`Leg::pieces`] cuts the turn into
//! the same chords and the straight run into pieces of `step_m` where
//! `step_m` divides it), and the check of a piece depends only on the
//! piece, the leg's start and turn, and what the pieces before it left (the
//! encounters and the leg's memo). So the check of the longer leg, from
//! where the shorter one ended, with what it left there, gives the verdict
//! and the encounters that judging it from its start gives, bit for bit.
//! Which pieces are shared is not assumed: the longer leg's first pieces
//! are compared, bit for bit, with the shorter leg's, and a leg whose
//! pieces differ is judged from its start.

use super::key::{WordMap, start_key_of};
use super::{EncounterState, LegMemo};
use std::cell::RefCell;
use vorrt_jfs::{Leg, Piece};

/// One leg accepted by the check, as the check left it after its last
/// piece.
#[derive(Debug)]
struct Judged {
    /// The leg's straight run, metres.
    straight_m: f64,
    /// Its pieces, in order.
    pieces: Vec<Piece>,
    /// The encounters after its last piece (the turn it leaves the next
    /// leg not yet set).
    state: EncounterState,
    /// The leg's memo after its last piece.
    memo: LegMemo,
    /// The heading at its last piece's end, radians.
    heading_rad: f64,
}

/// The legs accepted so far in one search, by start, turn, speeds, start
/// time, encounters and clearance (the leg less its straight run), kept for
/// longer legs with the same start (module documentation).
#[derive(Debug, Default)]
pub(crate) struct LegPrefixes {
    judged: RefCell<WordMap<Vec<Judged>>>,
}

/// A leg being judged that is to be kept if accepted: where it is kept,
/// its key and the pieces sailed so far; nothing where it is not kept.
pub(super) struct Keeping<'p>(Option<(&'p LegPrefixes, Vec<u64>, Vec<Piece>)>);

impl<'p> Keeping<'p> {
    /// Starts the check of `leg` (from `start_elapsed_s`, cut into pieces
    /// of `step_m`) with `carried` in force, kept in `prefixes` (judged at
    /// a clearance) if some: resumed after the longest shorter leg kept
    /// with the same start, with what the check carried then set in
    /// `carried`. The pieces still to judge.
    pub(super) fn start<'l>(
        prefixes: Option<(&'p LegPrefixes, f64)>,
        (leg, start_elapsed_s): (&'l Leg, f64),
        step_m: f64,
        mut carried: Carried<'_>,
    ) -> (impl Iterator<Item = Piece> + 'l, Self) {
        match prefixes {
            Some((prefixes, clearance_m)) => {
                let key = LegPrefixes::key_of(leg, start_elapsed_s, carried.state, clearance_m);
                let (rest, sailed) =
                    prefixes.resume(&key, leg, || leg.pieces(step_m), &mut carried);
                (rest, Self(Some((prefixes, key, sailed))))
            }
            None => (leg.pieces(step_m), Self(None)),
        }
    }

    /// Records `piece` as sailed.
    pub(super) fn sailed(&mut self, piece: Piece) {
        if let Some((_, _, sailed)) = &mut self.0 {
            sailed.push(piece);
        }
    }

    /// Keeps `leg`, accepted, as the check left it: the encounters (the
    /// turn it leaves the next leg not yet set), memo and heading.
    pub(super) fn keep(self, leg: &Leg, left: (&EncounterState, &LegMemo, f64)) {
        if let Some((prefixes, key, sailed)) = self.0 {
            prefixes.keep(key, leg, sailed, left);
        }
    }
}

/// What the check of a leg carries from piece to piece, set on a resume.
pub(super) struct Carried<'c> {
    pub(super) state: &'c mut EncounterState,
    pub(super) memo: &'c mut LegMemo,
    pub(super) heading_rad: &'c mut f64,
    pub(super) on_turn: &'c mut bool,
}

impl LegPrefixes {
    /// Resumes the check of `leg` (its key `key`) after the longest
    /// shorter leg with the same key whose pieces are the first of the
    /// leg's (`pieces` makes them from the start): sets what the check
    /// carried then in `carried`. The pieces still to judge, and those
    /// judged (empty: none was resumed from).
    fn resume<I: Iterator<Item = Piece>>(
        &self,
        key: &[u64],
        leg: &Leg,
        pieces: impl Fn() -> I,
        carried: &mut Carried<'_>,
    ) -> (I, Vec<Piece>) {
        let judged = self.judged.borrow();
        // Longest first (kept in order of straight run): a hold halfway
        // between two of `HOLD_M` is cut into other pieces than the holds
        // of `HOLD_M` (its pieces differ from the first straight piece on,
        // found at once).
        let shorter = judged
            .get(key)
            .into_iter()
            .flat_map(|legs| legs.iter().rev())
            .filter(|judged| judged.straight_m <= leg.straight_m);
        for shorter in shorter {
            let mut rest = pieces();
            if shorter
                .pieces
                .iter()
                .all(|known| rest.next().is_some_and(|piece| same_bits(&piece, known)))
            {
                carried.state.clone_from(&shorter.state);
                carried.memo.clone_from(&shorter.memo);
                *carried.heading_rad = shorter.heading_rad;
                if let Some(last) = shorter.pieces.last() {
                    *carried.on_turn = last.turning;
                }
                return (rest, shorter.pieces.clone());
            }
        }
        (pieces(), Vec::new())
    }

    /// The key of `leg` less its straight run, from `start_elapsed_s` with
    /// `state` in force, judged at `clearance_m`.
    pub(super) fn key_of(
        leg: &Leg,
        start_elapsed_s: f64,
        state: &EncounterState,
        clearance_m: f64,
    ) -> Vec<u64> {
        let mut key = start_key_of(leg, start_elapsed_s, state);
        key.push(clearance_m.to_bits());
        key
    }

    /// Keeps `leg` (its key `key`), accepted with `pieces`, as the check
    /// left it: `state` (the leg's turn for the next not yet set), `memo`
    /// and `heading_rad`.
    fn keep(
        &self,
        key: Vec<u64>,
        leg: &Leg,
        pieces: Vec<Piece>,
        (state, memo, heading_rad): (&EncounterState, &LegMemo, f64),
    ) {
        let judged = Judged {
            straight_m: leg.straight_m,
            pieces,
            state: state.clone(),
            memo: memo.clone(),
            heading_rad,
        };
        self.judged
            .borrow_mut()
            .entry(key)
            .or_default()
            .push(judged);
    }
}

/// Whether two pieces are the same, bit for bit (`-0.0` is not `0.0`).
fn same_bits(a: &Piece, b: &Piece) -> bool {
    let words = |piece: &Piece| {
        [
            piece.start_m.x,
            piece.start_m.y,
            piece.course_rad,
            piece.velocity_mps.x,
            piece.velocity_mps.y,
            piece.elapsed_s,
            piece.duration_s,
        ]
        .map(f64::to_bits)
    };
    words(a) == words(b) && a.turning == b.turning && a.changing_speed == b.changing_speed
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::PlannerConfig;
    use crate::safety::SafetyChecker;
    use crate::validity::MotionValidator;
    use glam::DVec2;
    use vorrt_colregs::VesselState;
    use vorrt_jfs::{MotionModel, Pose, RateLimitedTurn, TargetState};

    /// Holds of 35° to starboard, 250 m to 6 km, among vessels (a head-on
    /// encounter latched on the way and released by the longest): judged with the legs kept, each (longer ones
    /// resumed from shorter, a 1250 m hold whose pieces differ judged from
    /// its start) gives the verdict and encounters judged afresh gives, and
    /// the longer grid holds are resumed.
    #[test]
    fn a_longer_hold_resumed_is_judged_as_from_its_start() {
        let config = PlannerConfig::default();
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 100.0);
        let vessel = |x: f64, y: f64, course_deg: f64| {
            TargetState::constant_velocity(VesselState::new(
                DVec2::new(x, y),
                course_deg.to_radians(),
                5.0,
                100.0,
            ))
            .track()
        };
        // Head-on to port, crossing well ahead from port, and one
        // overtaking ownship far to port.
        let tracks = [
            vessel(-1500.0, 7000.0, 180.0),
            vessel(-6000.0, 9000.0, 80.0),
            vessel(-2500.0, -2000.0, 10.0),
        ];
        let checker = SafetyChecker::new(&config, &tracks, own, DVec2::new(0.0, 20_000.0), 0.0);
        let model = RateLimitedTurn {
            turn_radius_m: 600.0,
        };
        let start = Pose {
            position_m: DVec2::ZERO,
            course_rad: 0.0,
        };
        let prefixes = LegPrefixes::default();
        let fresh_state = || EncounterState::new(vec![None; 3], vec![0.0; 3]);
        let mut resumed = 0;
        for hold_m in [250.0, 500.0, 1000.0, 1250.0, 2000.0, 3000.0, 6000.0] {
            let leg = model.turn_onto(start, 35f64.to_radians(), 6.0, hold_m);
            let key = LegPrefixes::key_of(&leg, 0.0, &fresh_state(), config.clearance_m);
            let (mut state, mut memo, mut heading_rad, mut on_turn) =
                (fresh_state(), LegMemo::default(), 0.0, false);
            let mut carried = Carried {
                state: &mut state,
                memo: &mut memo,
                heading_rad: &mut heading_rad,
                on_turn: &mut on_turn,
            };
            let (_, judged) =
                prefixes.resume(&key, &leg, || leg.pieces(config.step_m), &mut carried);
            if !judged.is_empty() {
                resumed += 1;
            }
            let mut kept = fresh_state();
            let verdict = checker.validate_pieces(
                &leg,
                0.0,
                &mut kept,
                &mut false,
                Some((&prefixes, config.clearance_m)),
            );
            let mut afresh = fresh_state();
            assert_eq!(
                verdict,
                checker.validate(&leg, 0.0, &mut afresh),
                "{hold_m} m"
            );
            if verdict.is_ok() {
                assert_eq!(kept, afresh, "{hold_m} m");
            }
        }
        // 1000 m from 500 m, 2000 m from 1000 m, 6000 m from 2000 m: the
        // runs of a leg at one speed are of equal duration, and 3000 m's
        // (500 s / 30) round otherwise than 2000 m's (333.3 s / 20); the
        // 1250 m hold's pieces differ from every other's.
        assert_eq!(resumed, 3);
    }
}
