//! One hold of the manoeuvre search and its return, and the grades the
//! search prefers in order (decision 44).

use super::{SimplifiedLeg, Speeds, past_and_clear, reduction_held, return_to_goal};
use crate::validity::MotionValidator;
use glam::DVec2;
use vorrt_jfs::{Leg, MotionModel};

/// How many times [`alter_hold_return`](super::alter_hold_return) halves the gap between the longest
/// hold of [`HOLD_M`](super::HOLD_M) whose return was refused and the shortest whose return
/// is valid: three halvings find the return's start to an eighth of the
/// gap (at most 500 m of the 4 km between 8 and 12 km).
pub(super) const RETURN_BISECTIONS: usize = 3;

/// What holding one course for a given length, then returning to the goal,
/// came to.
pub(super) enum HoldOutcome {
    /// The hold itself is refused (or cannot win): longer ones are too.
    Invalid,
    /// The hold is valid, but no return from its end is (or a reduced speed
    /// is not yet held).
    Refused,
    /// The hold and its return.
    Found(Vec<SimplifiedLeg>),
}

/// `hold` (at `factor` of the service speed) validated after `from`, then
/// the return to the goal ([`return_to_goal`](super::return_to_goal)) from its end. With
/// `clear_only`, a return is wanted only from a hold that ends past and
/// clear ([`past_and_clear`](super::past_and_clear)): from any other the
/// hold is `Refused` without searching one (the caller would refuse it).
#[expect(
    clippy::too_many_arguments,
    reason = "one hold of the manoeuvre search: where it starts, the leg, its speed and what is wanted"
)]
pub(super) fn hold_and_return<M: MotionModel, V: MotionValidator>(
    model: &M,
    validator: &V,
    from: &SimplifiedLeg,
    hold: Leg,
    factor: f64,
    speeds: Speeds,
    goal_m: DVec2,
    clear_only: bool,
) -> HoldOutcome {
    let mut after_hold = from.state.clone();
    if validator
        .validate(&hold, from.end_elapsed_s, &mut after_hold)
        .is_err()
    {
        return HoldOutcome::Invalid;
    }
    if (factor < 1.0 && !reduction_held(&hold, &after_hold))
        || (clear_only && !past_and_clear(&after_hold))
    {
        return HoldOutcome::Refused;
    }
    let hold = SimplifiedLeg {
        end_elapsed_s: from.end_elapsed_s + hold.duration_s(),
        leg: hold,
        state: after_hold,
    };
    match return_to_goal(model, validator, &hold, speeds, goal_m) {
        Some(back) => HoldOutcome::Found(std::iter::once(hold).chain(back).collect()),
        None => HoldOutcome::Refused,
    }
}

/// The grades of the manoeuvre search, in the order [`Alterations::order`](super::Alterations::order)
/// gives them: a manoeuvre of an earlier grade is preferred to any of a
/// later one however short (rules 14-17: starboard first; a change of course
/// before a change of speed, rule 8(b), (e)), and within a grade the
/// shortest wins ([`alter_hold_return`](super::alter_hold_return)).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Grade {
    /// Holding on or a starboard alteration of at most [`MODERATE_DEG`], at
    /// service speed.
    Starboard,
    /// A larger starboard alteration, at service speed: its return swings
    /// back through as much, and an observer judging the swing over a
    /// window sees courses in between (decision 44: with 80° chosen for
    /// being shorter, the return of one run in 250 with 8 COLREGs-obeying
    /// targets turned 124° to port toward a vessel as observed).
    StarboardLarge,
    /// Holding on or a starboard alteration, at reduced speed.
    StarboardSlowed,
    /// A port alteration, at service speed.
    Port,
    /// A port alteration, at reduced speed.
    PortSlowed,
}

impl Grade {
    /// The grade of an alteration of `alteration_deg` at `factor` of the
    /// service speed.
    pub(super) fn of(alteration_deg: f64, factor: f64) -> Self {
        match (alteration_deg < 0.0, factor < 1.0) {
            (false, false) if alteration_deg <= MODERATE_DEG => Self::Starboard,
            (false, false) => Self::StarboardLarge,
            (false, true) => Self::StarboardSlowed,
            (true, false) => Self::Port,
            (true, true) => Self::PortSlowed,
        }
    }
}

/// The largest alteration, degrees, among which the search takes the
/// shortest manoeuvre; larger ones are tried only where none of these is
/// valid ([`Grade`]).
pub(super) const MODERATE_DEG: f64 = 55.0;
