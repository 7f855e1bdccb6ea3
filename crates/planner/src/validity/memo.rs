//! The memo a leg's check carries from piece to piece (decision 54):
//! each target's velocity, and the targets no risk can reach while the
//! velocities hold.

use super::{Constraint, DVec2, LinearTrack, SafetyChecker, VesselState, no_risk_while_steady};
use crate::safety::{StateVelocities, known_velocity};
use vorrt_colregs::rules::PortTurnGate;

impl<C: Constraint> SafetyChecker<'_, C> {
    /// The same checker without the memo of decision 54: each piece of a
    /// leg judges every target's risk afresh. The same verdicts and the same
    /// encounters, only slower: for comparing (`tests/leg_memo.rs`).
    #[must_use]
    pub fn without_leg_memo(mut self) -> Self {
        self.leg_memo = false;
        self
    }

    /// Whether a leg's check keeps the memo of decision 54
    /// ([`without_leg_memo`](Self::without_leg_memo)).
    #[must_use]
    pub fn leg_memo(&self) -> bool {
        self.leg_memo
    }

    /// Each target's velocities worked out once for every leg
    /// ([`with_state_velocities`](Self::with_state_velocities); may be
    /// empty).
    #[must_use]
    pub fn state_velocities(&self) -> &[StateVelocities] {
        self.state_velocities
    }
}

/// What a leg's check carries from one piece to the next, per target
/// ([`EncounterState::advance_reusing`]).
#[derive(Debug, Default, Clone)]
pub(crate) struct LegMemo {
    /// Each target's velocity, reused while its course and speed stay the
    /// same ([`velocity_of`]).
    pub(super) velocities: Vec<KnownVelocity>,
    /// Ownship's velocity as a new encounter sees it (its steady course at
    /// its speed) for which `clear` holds; `None` while ownship does not
    /// sail at it.
    pub(super) seen_mps: Option<DVec2>,
    /// Per target, the stretch of its track ([`LinearTrack::stretch_at`])
    /// on which no risk can arise while ownship keeps `seen_mps`
    /// ([`no_risk_while_steady`]), found on a piece with no encounter.
    pub(super) clear: Vec<Option<u8>>,
    /// The last few turns asked of the settled-turn predicate
    /// ([`LegMemo::turn_geometry`]), each with the (course turned to, course
    /// before, speed) it was worked out for, as bits, and the next slot to
    /// fill: a piece in a turn's window asks from up to four courses.
    turns: ([KeptTurn; TURNS_KEPT], usize),
    /// Ownship's velocity at a piece's end, and on the steady course as a
    /// new encounter sees it ([`Along::own_velocities`]), each with the
    /// course and speed it was worked out for: along a straight run every
    /// piece asks for the same.
    own_mps: (KnownVelocity, KnownVelocity),
}

impl LegMemo {
    /// The geometry of a turn from `course_before_rad` to `own`'s course
    /// at `own`'s speed: ownship's velocity on each ([`VesselState::velocity_mps`])
    /// and the bearing gate ([`PortTurnGate::new`]), kept from an earlier
    /// ask for the very same courses and speed (the same bits): along a
    /// straight run every piece asks the settled-turn predicate the same
    /// (decision 60).
    pub(crate) fn turn_geometry(
        &mut self,
        course_before_rad: f64,
        own: &VesselState,
    ) -> TurnGeometry {
        let key = [
            own.course_rad.to_bits(),
            course_before_rad.to_bits(),
            own.speed_mps.to_bits(),
        ];
        let (kept, next) = &mut self.turns;
        if let Some((_, geometry)) = kept.iter().flatten().find(|(known, _)| *known == key) {
            return *geometry;
        }
        let before = VesselState {
            course_rad: course_before_rad,
            ..*own
        };
        let geometry = TurnGeometry {
            own_mps: own.velocity_mps(),
            before_mps: before.velocity_mps(),
            gate: PortTurnGate::new(course_before_rad, own.course_rad),
        };
        kept[*next] = Some((key, geometry));
        *next = (*next + 1) % TURNS_KEPT;
        geometry
    }

    /// Target `index`'s velocity, `target` its state ([`velocity_of`]: the
    /// one the leg's latch step keeps, shared).
    pub(crate) fn target_velocity(&mut self, index: usize, target: &VesselState) -> DVec2 {
        if self.velocities.len() <= index {
            self.velocities.resize(index + 1, None);
        }
        velocity_of(&mut self.velocities[index], target)
    }
}

/// A turn kept by [`LegMemo::turn_geometry`]: the (course turned to, course
/// before, speed) as bits, and its geometry.
type KeptTurn = Option<([u64; 3], TurnGeometry)>;

/// How many turns [`LegMemo::turn_geometry`] keeps.
const TURNS_KEPT: usize = 4;

/// A turn as the settled-turn predicate asks it ([`LegMemo::turn_geometry`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct TurnGeometry {
    /// Ownship's velocity on the course turned to, m/s.
    pub(crate) own_mps: DVec2,
    /// Ownship's velocity on the course before, at the same speed, m/s.
    pub(crate) before_mps: DVec2,
    /// The bearings no vessel turned toward can have.
    pub(crate) gate: PortTurnGate,
}

/// How near, m/s, the velocity sailed over a piece must be to the velocity
/// seen ([`LegMemo::seen_mps`]) for the memo to be kept: the same course
/// and speed, to rounding. Over an hour the two part by under 4 µm, far
/// within [`STEADY_ROUNDING_M`](vorrt_colregs::risk::STEADY_ROUNDING_M).
pub(super) const SAILED_TOLERANCE_MPS: f64 = 1e-9;

/// The memo of one leg's check at one piece: the targets' tracks, the
/// elapsed time of the piece's end, and ownship's velocity over the piece
/// when it sailed its settled course and speed.
pub(crate) struct Along<'m> {
    pub(super) memo: &'m mut LegMemo,
    pub(super) tracks: &'m [LinearTrack],
    /// Each target's velocities worked out once (may be empty).
    pub(super) known: &'m [StateVelocities],
    pub(super) elapsed_s: f64,
    pub(super) sailed_mps: Option<DVec2>,
}

impl Along<'_> {
    /// Whether the memo holds at this piece for ownship's velocity as seen
    /// (`seen_mps`): the piece was sailed at that velocity, and so was every
    /// piece since the memo was last cleared (else it is cleared now).
    /// `count`: the number of targets.
    pub(super) fn settle(&mut self, seen_mps: DVec2, count: usize) -> bool {
        let memo = &mut *self.memo;
        memo.velocities.resize(count, None);
        let seen_mps = self
            .sailed_mps
            .filter(|sailed| sailed.distance(seen_mps) <= SAILED_TOLERANCE_MPS)
            .map(|_| seen_mps);
        if memo.seen_mps != seen_mps || memo.clear.len() != count {
            memo.clear.clear();
            memo.clear.resize(count, None);
            memo.seen_mps = seen_mps;
        }
        seen_mps.is_some()
    }

    /// Whether no risk can arise with target `index` at this piece: found
    /// so on an earlier piece, on the stretch of its track it is still on.
    pub(super) fn clear(&self, index: usize) -> bool {
        self.memo
            .clear
            .get(index)
            .copied()
            .flatten()
            .is_some_and(|stretch| self.tracks[index].stretch_at(self.elapsed_s) == Some(stretch))
    }

    /// Ownship's velocity as `own_then`, and on `steady_course_rad` at its
    /// speed ([`VesselState::velocity_mps`]), each kept from an earlier
    /// piece where worked out for the same bits ([`velocity_of`]).
    pub(super) fn own_velocities(
        &mut self,
        own_then: &VesselState,
        steady_course_rad: f64,
    ) -> (DVec2, DVec2) {
        let (own, seen) = &mut self.memo.own_mps;
        let own_mps = velocity_of(own, own_then);
        let seen_mps = if steady_course_rad.to_bits() == own_then.course_rad.to_bits() {
            own_mps
        } else {
            let seen_then = VesselState {
                course_rad: steady_course_rad,
                ..*own_then
            };
            velocity_of(seen, &seen_then)
        };
        (own_mps, seen_mps)
    }

    /// `target`'s velocity: from the velocities worked out once where they
    /// apply, else [`velocity_of`].
    pub(super) fn velocity(&mut self, index: usize, target: &VesselState) -> DVec2 {
        if let Some(velocity_mps) = known_velocity(self.known, index, target) {
            return velocity_mps;
        }
        match self.memo.velocities.get_mut(index) {
            Some(slot) => velocity_of(slot, target),
            None => target.velocity_mps(),
        }
    }

    /// Keeps target `index` as one no risk can reach, if so, after a piece
    /// with no encounter with it: ownship at `own` (position and the
    /// velocity seen), the target's state `target` and velocity
    /// `target_mps`. Only where the target's
    /// state moves as its track does on this stretch.
    pub(super) fn remember(
        &mut self,
        index: usize,
        own: (DVec2, DVec2),
        target: &VesselState,
        target_mps: DVec2,
        risk_distance_m: f64,
    ) {
        let track = &self.tracks[index];
        let Some(stretch) = track.stretch_at(self.elapsed_s) else {
            return;
        };
        if target_mps.distance(track.velocity_at(self.elapsed_s)) <= SAILED_TOLERANCE_MPS
            && no_risk_while_steady(own.0, own.1, target.position_m, target_mps, risk_distance_m)
            && let Some(slot) = self.memo.clear.get_mut(index)
        {
            *slot = Some(stretch);
        }
    }
}

/// A target's velocity ([`VesselState::velocity_mps`]) with the course and
/// speed it was worked out for, radians, m/s, m/s; `None` before the first.
pub(crate) type KnownVelocity = Option<(f64, f64, DVec2)>;

/// `target`'s velocity: the one kept in `known` if worked out for the very
/// same course and speed (the same bits), otherwise worked out and kept.
pub(super) fn velocity_of(known: &mut KnownVelocity, target: &VesselState) -> DVec2 {
    match *known {
        Some((course_rad, speed_mps, velocity_mps))
            if course_rad.to_bits() == target.course_rad.to_bits()
                && speed_mps.to_bits() == target.speed_mps.to_bits() =>
        {
            velocity_mps
        }
        _ => {
            let velocity_mps = target.velocity_mps();
            *known = Some((target.course_rad, target.speed_mps, velocity_mps));
            velocity_mps
        }
    }
}
