//! Which targets can change a verdict of a leg: the reach of each
//! ([`SafetyChecker::reach_m`]) and the targets that may come within it
//! while ownship sails the leg ([`SafetyChecker::within_reach`], decision
//! 33; the early-action range while a turn to starboard shows, decision
//! 74), and the course held before a leg that both the pruning and the
//! leg's check start from.

use super::SafetyChecker;
use crate::constraint::Constraint;
use vorrt_colregs::EncounterLatch;
use vorrt_jfs::LinearTrack;

impl<C: Constraint> SafetyChecker<'_, C> {
    /// The farthest distance between reference points at which target
    /// `track` can change any verdict of the checks: MTD (the velocity
    /// obstacle, the clearance ahead, a new encounter and the settled turn
    /// look only at targets nearer than it), or the distance kept from the
    /// target ([`required_distance_m`](Self::required_distance_m)) plus
    /// the uncertainty of its second leg and `margin_m` (a chord's or a
    /// speed change's error), whichever is larger.
    #[must_use]
    pub fn reach_m(&self, track: &LinearTrack, margin_m: f64) -> f64 {
        self.config
            .rules
            .mtd_m
            .max(self.required_distance_m(track) + track.then_margin_m + margin_m)
    }

    /// Per target, whether it may come within its [`reach_m`](Self::reach_m)
    /// of ownship while ownship sails `leg` from `start_elapsed_s` after the
    /// plan's start, with `latches` and `alterations` in force at the leg's
    /// start. A target is out of reach when the distance between the two at
    /// the leg's start, less the most both can close it by during the leg
    /// (the leg's length for ownship, the target's highest speed on its
    /// track times the leg's duration for the target), is still no nearer
    /// than its reach. It then stays beyond MTD at every piece, so no
    /// velocity obstacle, clearance ahead (whose look-ahead only targets
    /// within MTD get), settled turn or new encounter looks at it, and
    /// beyond `d_th` with every margin, so the clearance holds: skipping
    /// it changes no verdict and no encounter, bit for bit (decision 33).
    /// Where a turn to starboard may show along the leg, the reach is at
    /// least the early-action range, within which such a turn latches a
    /// vessel it is made for (decision 74). A target with an encounter in
    /// force, or an alteration carried, is always in reach.
    #[must_use]
    pub fn within_reach(
        &self,
        leg: &vorrt_jfs::Leg,
        start_elapsed_s: f64,
        latches: &[Option<EncounterLatch>],
        alterations: &[f64],
    ) -> Vec<bool> {
        let rules = &self.config.rules;
        let before_course_rad = self.course_before(leg, start_elapsed_s);
        let floor_m = if crate::validity::may_show_starboard_turn(leg, before_course_rad, rules) {
            rules.early_action_range_m
        } else {
            0.0
        };
        // Out of reach: farther than its reach over the leg, and farther
        // than `floor_m` while the leg's turn is in view (an early latch
        // needs the turn to show: up to the turn's end plus the
        // observation window, and the piece that ends past it).
        let span_s = leg.duration_s();
        let own_reach_m = leg.length_m();
        let margin_m = leg.piece_error_m() + leg.timing_error_m();
        // While the turn shows: a piece more than the window past its end
        // (a piece lasts at most `step_m` at the lower of the two speeds).
        let own_top_mps = leg.start_speed_mps().max(leg.speed_mps);
        let own_low_mps = leg.start_speed_mps().min(leg.end_speed_mps());
        let piece_s = self.config.step_m / own_low_mps;
        let shown_s =
            (leg.turn_duration_s() + vorrt_colregs::rules::STEADY_COURSE_WINDOW_S + piece_s)
                .min(span_s);
        let own_shown_m = own_reach_m.min(own_top_mps * shown_s);
        self.tracks
            .iter()
            .enumerate()
            .map(|(index, track)| {
                if latches.get(index).copied().flatten().is_some()
                    || alterations
                        .get(index)
                        .is_some_and(|altered| *altered != 0.0)
                {
                    return true;
                }
                let target_speed_mps = track
                    .velocity_mps
                    .length()
                    .max(track.then_velocity_mps.length());
                let range_m = leg.start_m.distance(track.position_at(start_elapsed_s));
                let closing_m = own_reach_m + target_speed_mps * span_s;
                let shown_closing_m = own_shown_m + target_speed_mps * shown_s;
                // A metre to spare for rounding; a NaN keeps the target.
                let out_of_reach = range_m - closing_m >= self.reach_m(track, margin_m) + 1.0
                    && range_m - shown_closing_m >= floor_m + 1.0;
                !out_of_reach
            })
            .collect()
    }

    /// The course an observer sees held before `leg`, which starts
    /// `start_elapsed_s` after the plan's start: on the first leg of a plan
    /// that starts in a turn, the course held before that turn (the closed
    /// loop's history); otherwise the leg's own start course (a turn
    /// between legs begins with the next leg).
    pub(crate) fn course_before(&self, leg: &vorrt_jfs::Leg, start_elapsed_s: f64) -> f64 {
        if start_elapsed_s <= 0.0 {
            self.steady_course_rad
        } else {
            leg.start_course_rad
        }
    }
}
