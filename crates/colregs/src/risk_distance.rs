//! How near a predicted pass must come to be a risk of collision (rule 7),
//! for two vessels of given lengths in the sea room they have (decision 50).
//!
//! Rule 7 leaves the distance to "the prevailing circumstances and
//! conditions"; a fixed 1 nm makes two harbour launches passing 0.6 nm apart
//! in a river an encounter with duties, and gives a 300 m ship and a 20 m
//! launch the same distance. The one rule, [`RuleParameters::risk_distance_m`](crate::RuleParameters::risk_distance_m):
//!
//! 1. **Open sea**: the larger of [`risk_cpa_m`](crate::RuleParameters::risk_cpa_m)
//!    (1 nm: the mariners' open-sea passing distance; Goodwin 1975 measured
//!    the domain of North Sea ships at 0.7 nm to port, 0.85 nm to starboard
//!    and 0.45 nm astern) and [`length_factor`](RiskDistanceRule::length_factor)
//!    times the larger vessel's length (6.4: two of Fujii and Tanaka's 1971
//!    open-water domains side by side, each 3.2 lengths abeam, so that a pass
//!    nearer than that brings one vessel into the other's domain), no more
//!    than [`cap_m`](RiskDistanceRule::cap_m) (2 nm, the widest passing
//!    distance masters' standing orders ask in open water, decision 23).
//!    Up to a 289 m vessel this is the 1 nm of before.
//! 2. **Confined water**: where the sea room is known
//!    ([`sea_room_m`](RiskDistanceRule::sea_room_m), the width of navigable
//!    water the vessels are in), no more than
//!    [`sea_room_fraction`](RiskDistanceRule::sea_room_fraction) of it
//!    (0.25): two vessels each keeping to the starboard side of a channel
//!    (rule 9(a)) pass about half its width apart, so a predicted miss of
//!    less than half of that normal pass is a risk, and a wider one is the
//!    channel's ordinary passing, not an encounter.
//! 3. **Never under `d_th` between the hulls**: the distance is never less
//!    than half the sum of the lengths (hull contact, decision 16) plus
//!    [`clearance_floor_m`](RiskDistanceRule::clearance_floor_m) (the
//!    clearance `d_th`; the judges set it to theirs), nor more than the
//!    open-sea one.
//!
//! With the defaults and no sea room (the closed loop, the open-sea
//! generator, whose vessels are at most 250 m) the distance is
//! `risk_cpa_m` exactly, so the planner's and the campaigns' behaviour is
//! unchanged.

use serde::{Deserialize, Serialize};

/// The constants of the risk-of-collision distance (decision 50); each
/// default's source is in the [module documentation](self).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct RiskDistanceRule {
    /// Multiple of the larger vessel's length under which a predicted miss
    /// is a risk in open sea, above [`risk_cpa_m`](crate::RuleParameters::risk_cpa_m).
    /// Default 6.4 (twice Fujii and Tanaka's 3.2 lengths abeam).
    pub length_factor: f64,
    /// The most the length can raise the open-sea distance to, metres.
    /// Default 2 nm (3704 m).
    pub cap_m: f64,
    /// The width of navigable water the vessels are in, metres, where known
    /// (confined water); `None`: open sea. Default `None`.
    pub sea_room_m: Option<f64>,
    /// Fraction of the sea room that caps the distance in confined water.
    /// Default 0.25.
    pub sea_room_fraction: f64,
    /// The clearance between the hulls under which the distance never goes,
    /// metres. Default 200 m (the paper's open-sea `d_th`); `vorrt judge`
    /// sets it to the `d_th` it judges with.
    pub clearance_floor_m: f64,
}

impl Default for RiskDistanceRule {
    fn default() -> Self {
        Self {
            length_factor: 6.4,
            cap_m: 2.0 * 1852.0,
            sea_room_m: None,
            sea_room_fraction: 0.25,
            clearance_floor_m: 200.0,
        }
    }
}

impl RiskDistanceRule {
    /// The distance for vessels of `own_length_m` and `target_length_m`
    /// with `open_floor_m` the open-sea distance of small vessels
    /// ([`risk_cpa_m`](crate::RuleParameters::risk_cpa_m)); see
    /// [`RuleParameters::risk_distance_m`](crate::RuleParameters::risk_distance_m).
    #[must_use]
    pub fn distance_m(&self, open_floor_m: f64, own_length_m: f64, target_length_m: f64) -> f64 {
        let larger_m = own_length_m.max(target_length_m).max(0.0);
        let open_m = open_floor_m.max((self.length_factor * larger_m).min(self.cap_m));
        let Some(sea_room_m) = self.sea_room_m else {
            return open_m;
        };
        let hulls_m =
            0.5 * (own_length_m.max(0.0) + target_length_m.max(0.0)) + self.clearance_floor_m;
        open_m
            .min(self.sea_room_fraction * sea_room_m)
            .max(hulls_m.min(open_m))
    }

    /// Checks every field: `(field, value, expected)` of the first one out
    /// of range.
    pub(crate) fn check(&self) -> Result<(), (&'static str, f64, &'static str)> {
        let finite_non_negative = [
            ("risk_distance.length_factor", self.length_factor),
            ("risk_distance.clearance_floor_m", self.clearance_floor_m),
        ];
        for (field, value) in finite_non_negative {
            if !(value.is_finite() && value >= 0.0) {
                return Err((field, value, "a finite number of at least 0"));
            }
        }
        if !(self.cap_m.is_finite() && self.cap_m > 0.0) {
            return Err((
                "risk_distance.cap_m",
                self.cap_m,
                "a finite number greater than 0",
            ));
        }
        if let Some(sea_room_m) = self.sea_room_m
            && !(sea_room_m.is_finite() && sea_room_m > 0.0)
        {
            return Err((
                "risk_distance.sea_room_m",
                sea_room_m,
                "a finite number of metres greater than 0",
            ));
        }
        if !(self.sea_room_fraction.is_finite()
            && self.sea_room_fraction > 0.0
            && self.sea_room_fraction <= 1.0)
        {
            return Err((
                "risk_distance.sea_room_fraction",
                self.sea_room_fraction,
                "a fraction greater than 0 and at most 1",
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::RuleParameters;

    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn open_sea_keeps_one_mile_up_to_289_m() {
        let rules = RuleParameters::default();
        for (own, target) in [(20.0, 20.0), (100.0, 250.0), (289.0, 50.0)] {
            assert_eq!(rules.risk_distance_m(own, target), rules.risk_cpa_m);
        }
        // A 300 m ship: 6.4 lengths, 1920 m; a 700 m one: the 2 nm cap.
        assert!((rules.risk_distance_m(20.0, 300.0) - 1920.0).abs() < 1e-9);
        assert_eq!(rules.risk_distance_m(700.0, 20.0), 2.0 * 1852.0);
    }

    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn sea_room_shrinks_it_never_under_d_th_between_the_hulls() {
        let mut rules = RuleParameters::default();
        rules.risk_distance.sea_room_m = Some(1500.0);
        // Two 20 m launches in a 1500 m channel: a quarter of it, 375 m.
        assert!((rules.risk_distance_m(20.0, 20.0) - 375.0).abs() < 1e-9);
        // In a 400 m channel, the floor: 200 m between the hulls.
        rules.risk_distance.sea_room_m = Some(400.0);
        assert!((rules.risk_distance_m(20.0, 20.0) - 220.0).abs() < 1e-9);
        // Wide water is open sea.
        rules.risk_distance.sea_room_m = Some(50_000.0);
        assert_eq!(rules.risk_distance_m(20.0, 20.0), rules.risk_cpa_m);
    }

    #[test]
    fn a_bad_field_is_named() {
        let mut rules = RuleParameters::default();
        rules.risk_distance.sea_room_fraction = 0.0;
        let message = rules.validate().expect_err("zero").to_string();
        assert!(message.contains("sea_room_fraction"), "{message}");
        rules.risk_distance.sea_room_fraction = 0.25;
        rules.risk_distance.sea_room_m = Some(f64::NAN);
        assert!(rules.validate().is_err());
    }
}
