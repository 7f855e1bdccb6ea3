//! What `vorrt judge` knows of how each track was observed, beyond its
//! positions: fixes that jump further than a vessel sails (rejected), the
//! fixes' jitter (estimated before resampling), the navigational status and
//! ship type reported, and ownship's rate-of-turn limit where it is known
//! (decisions 31 and 32; `docs/judge.md`, "Real tracks").

use crate::error::CliError;
use crate::judge::resample::Prepared;
use crate::judge::tracks::Track;
use serde::{Deserialize, Serialize};
use vorrt_colregs::observed::{
    NavigationalStatus, TrackObservation, median_step_speed_mps, position_noise_m,
    rest_contradicted,
};
use vorrt_geometry::units;
use vorrt_scenarios::LocalFrame;

/// The default `--max-speed-kn`: a fix that needs more than this from the
/// fix before is a jump, not a passage (50 kn: above any merchant ship and
/// most fast craft; AIS reports speeds up to 102 kn).
pub(crate) const DEFAULT_MAX_SPEED_KN: f64 = 50.0;

/// The judged turning circle for a vessel of known length: a radius of one
/// length (a diameter of two), tighter than any displacement ship's
/// full-rudder turn (IMO MSC.137(76) asks a tactical diameter of at most 5
/// lengths; trials give 2.5-4), so that only a track no vessel of that
/// length could sail is found faster than it can turn.
pub(crate) const TURN_RADIUS_LENGTHS: f64 = 1.0;

/// One judged vessel as observed: the `observation` entries of
/// `judgement.json`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct VesselObservation {
    /// The vessel's name.
    pub(crate) name: String,
    /// Fixes rejected as jumps (more than `--max-speed-kn` from the fix
    /// before).
    pub(crate) jumps_rejected: usize,
    /// The estimated position jitter of its fixes (1 σ), metres.
    pub(crate) position_noise_m: Option<f64>,
    /// The observation window its courses were judged over, seconds.
    pub(crate) window_s: f64,
    /// The smallest course change it was judged to make, degrees (the
    /// rule's 2°, or more above its jitter).
    pub(crate) turn_tolerance_deg: f64,
    /// The course change at which its action was detected, degrees.
    pub(crate) action_detection_deg: f64,
    /// The navigational status it reported most often (AIS), snake case.
    pub(crate) status_reported: Option<String>,
    /// The status it was judged with: as reported (a reported rest is never
    /// latched as an encounter; one the vessel's motion contradicts makes
    /// the encounter undecided, `rule_18` says so: decision 49).
    pub(crate) status_judged: Option<String>,
    /// Its median speed over ground between fixes, knots (what tells whether
    /// a reported rest is believed).
    #[serde(default)]
    pub(crate) median_speed_kn: f64,
    /// The rule 18 responsibility or the rule 3(i) reading its status brings,
    /// in words.
    pub(crate) rule_18: Option<String>,
    /// Its AIS ship and cargo type, when reported.
    pub(crate) ship_type: Option<u8>,
}

/// Drops the fixes of `vessel` that need more than `max_speed_mps` from the
/// last fix kept; returns how many. The first fix is kept: a first fix far
/// from all the others shows as every later fix rejected, which the output
/// names.
pub(crate) fn reject_jumps(vessel: &mut Prepared, max_speed_mps: f64) -> usize {
    let mut keep = vec![true; vessel.times_s.len()];
    let mut last = 0;
    for (index, kept) in keep.iter_mut().enumerate().skip(1) {
        let elapsed_s = vessel.times_s[index] - vessel.times_s[last];
        let distance_m = vessel.positions_m[index].distance(vessel.positions_m[last]);
        if distance_m > max_speed_mps * elapsed_s {
            *kept = false;
        } else {
            last = index;
        }
    }
    let rejected = keep.iter().filter(|kept| !**kept).count();
    if rejected > 0 {
        let mut flags = keep.iter();
        vessel.times_s.retain(|_| *flags.next().unwrap_or(&true));
        let mut flags = keep.iter();
        vessel
            .positions_m
            .retain(|_| *flags.next().unwrap_or(&true));
        for values in [&mut vessel.courses_rad, &mut vessel.speeds_mps]
            .into_iter()
            .flatten()
        {
            let mut flags = keep.iter();
            values.retain(|_| *flags.next().unwrap_or(&true));
        }
    }
    rejected
}

/// Every vessel's fixes in the local frame, jumps rejected: ownship's (at
/// least two), the targets' in `order`, and the jumps rejected per track.
///
/// # Errors
/// [`CliError::BadInput`] when ownship has fewer than two fixes.
pub(crate) fn prepare(
    list: &[Track],
    own: usize,
    order: &[usize],
    frame: Option<&LocalFrame>,
    (file, max_speed_kn): (&str, f64),
) -> Result<Prepared3, CliError> {
    let max_speed_mps = units::knots_to_mps(max_speed_kn);
    let mut jumps = std::collections::HashMap::new();
    let mut own_prepared = Prepared::new(&list[own], frame);
    jumps.insert(own, reject_jumps(&mut own_prepared, max_speed_mps));
    if own_prepared.times_s.len() < 2 {
        return Err(CliError::BadInput(format!(
            "{file}: ownship {:?} has {} fix(es) at distinct times; at least 2 are needed",
            list[own].name,
            own_prepared.times_s.len()
        )));
    }
    let prepared: Vec<(usize, Prepared)> = order
        .iter()
        .map(|&index| {
            let mut vessel = Prepared::new(&list[index], frame);
            jumps.insert(index, reject_jumps(&mut vessel, max_speed_mps));
            (index, vessel)
        })
        .collect();
    Ok((own_prepared, prepared, jumps))
}

/// Ownship's fixes, the targets' by track index, and the jumps rejected
/// per track index.
pub(crate) type Prepared3 = (
    Prepared,
    Vec<(usize, Prepared)>,
    std::collections::HashMap<usize, usize>,
);

/// The status a track reported most often (ties: the first reported).
fn reported_status(track: &Track) -> Option<NavigationalStatus> {
    let mut counts: Vec<(NavigationalStatus, usize)> = Vec::new();
    for status in track.fixes.iter().filter_map(|fix| fix.status) {
        match counts.iter_mut().find(|(seen, _)| *seen == status) {
            Some((_, count)) => *count += 1,
            None => counts.push((status, 1)),
        }
    }
    counts
        .iter()
        .fold(
            None,
            |best: Option<(NavigationalStatus, usize)>, &(status, count)| match best {
                Some((_, most)) if most >= count => best,
                _ => Some((status, count)),
            },
        )
        .map(|(status, _)| status)
}

/// What the judgement is told of one vessel (its jitter, its status, its
/// median speed between fixes) and what the output says of it. Whether a
/// reported rest is believed is the observed judgement's to say
/// ([`rest_contradicted`]: AIS statuses are set by hand and often stale);
/// a contradicted one leaves the encounter undecided (decision 49).
pub(crate) fn observe(
    track: &Track,
    vessel: &Prepared,
    jumps_rejected: usize,
) -> (TrackObservation, VesselObservation) {
    let reported = reported_status(track);
    let median_mps = median_step_speed_mps(&vessel.times_s, &vessel.positions_m);
    let noise_m = position_noise_m(&vessel.times_s, &vessel.positions_m);
    let observation = TrackObservation {
        // A track with too few fixes to tell: no jitter assumed, but still a
        // track recorded at sea.
        position_noise_m: Some(noise_m.unwrap_or(0.0)),
        status: reported,
        median_speed_mps: Some(median_mps),
        unreported: Vec::new(),
    };
    let rule_18 = match rest_contradicted(reported, median_mps) {
        Some(contradicted) => Some(contradicted.to_string()),
        None => reported
            .and_then(NavigationalStatus::rule_18)
            .map(str::to_owned),
    };
    let output = VesselObservation {
        name: track.name.clone(),
        jumps_rejected,
        position_noise_m: noise_m,
        window_s: 0.0,
        turn_tolerance_deg: 0.0,
        action_detection_deg: 0.0,
        status_reported: reported.map(|status| status.name().to_owned()),
        status_judged: reported.map(|status| status.name().to_owned()),
        median_speed_kn: units::mps_to_knots(median_mps),
        rule_18,
        ship_type: track.ship_type,
    };
    (observation, output)
}

/// [`observe`] for every judged vessel (`judged`: indexes into `list`, in
/// the order of `vessels`), with the jumps rejected per track index.
pub(crate) fn observe_all(
    list: &[Track],
    judged: &[usize],
    vessels: &[&Prepared],
    jumps: &std::collections::HashMap<usize, usize>,
) -> (Vec<TrackObservation>, Vec<VesselObservation>) {
    judged
        .iter()
        .zip(vessels)
        .map(|(index, vessel)| {
            observe(
                &list[*index],
                vessel,
                jumps.get(index).copied().unwrap_or(0),
            )
        })
        .unzip()
}

/// Ownship's rate-of-turn limit, radians per second, and what was assumed:
/// the one given (`--max-turn-rate-deg-s`, or the scenario's); else, for a known length, a turn
/// of [`TURN_RADIUS_LENGTHS`] at its largest speed on the clock; else none:
/// the rate is reported, not judged.
pub(crate) fn turn_rate_limit(
    given_deg_s: Option<f64>,
    length_m: f64,
    length_known: bool,
    largest_speed_mps: f64,
) -> (Option<f64>, String) {
    if let Some(rate) = given_deg_s {
        return (
            Some(rate.to_radians()),
            format!(
                "ownship's rate-of-turn limit is {rate:.2}°/s (given: --max-turn-rate-deg-s, else the scenario's)"
            ),
        );
    }
    if length_known && largest_speed_mps > 0.0 {
        let limit = largest_speed_mps / (TURN_RADIUS_LENGTHS * length_m);
        return (
            Some(limit),
            format!(
                "ownship's rate-of-turn limit is {:.2}°/s: a turn of radius {TURN_RADIUS_LENGTHS} length ({length_m:.0} m) at its largest speed, {:.1} kn (give --max-turn-rate-deg-s for the vessel's own)",
                limit.to_degrees(),
                units::mps_to_knots(largest_speed_mps)
            ),
        );
    }
    (
        None,
        "ownship's rate of turn is reported, not judged: neither its limit nor its length is known (give --max-turn-rate-deg-s or a length)"
            .to_owned(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::judge::tracks::{Fix, Place};
    use vorrt_geometry::DVec2;

    fn prepared(fixes: &[(f64, f64)]) -> Prepared {
        Prepared {
            name: "v".into(),
            times_s: fixes.iter().map(|fix| fix.0).collect(),
            positions_m: fixes.iter().map(|fix| DVec2::new(0.0, fix.1)).collect(),
            courses_rad: None,
            speeds_mps: Some(vec![1.0; fixes.len()]),
            duplicates: 0,
        }
    }

    #[test]
    fn a_jump_of_twenty_miles_in_a_minute_is_rejected() {
        let mut vessel = prepared(&[(0.0, 0.0), (60.0, 300.0), (120.0, 37_040.0), (180.0, 900.0)]);
        assert_eq!(reject_jumps(&mut vessel, units::knots_to_mps(50.0)), 1);
        assert_eq!(vessel.times_s, vec![0.0, 60.0, 180.0]);
        assert_eq!(vessel.speeds_mps.as_ref().map(Vec::len), Some(3));
    }

    #[test]
    fn a_reported_rest_contradicted_by_the_motion_is_said() {
        let fixes = |speed_mps: f64| Track {
            name: "v".into(),
            fixes: (0..10)
                .map(|i| Fix {
                    time_s: f64::from(i) * 60.0,
                    place: Place::Local(DVec2::new(0.0, speed_mps * f64::from(i) * 60.0)),
                    course_deg: None,
                    speed_kn: None,
                    status: Some(NavigationalStatus::AtAnchor),
                })
                .collect(),
            ..Track::default()
        };
        let resting = fixes(0.0);
        let (observation, output) = observe(&resting, &Prepared::new(&resting, None), 0);
        assert_eq!(observation.status, Some(NavigationalStatus::AtAnchor));
        assert!(output.rule_18.unwrap().contains("3(i)"));
        let moving = fixes(5.0);
        let (observation, output) = observe(&moving, &Prepared::new(&moving, None), 0);
        assert_eq!(observation.status, Some(NavigationalStatus::AtAnchor));
        assert!(observation.median_speed_mps.unwrap() > 4.9);
        assert!(
            output
                .rule_18
                .unwrap()
                .contains("status contradicts motion")
        );
    }

    #[test]
    fn no_limit_is_invented_for_a_vessel_of_unknown_length() {
        assert!(turn_rate_limit(None, 50.0, false, 5.0).0.is_none());
        let (limit, said) = turn_rate_limit(None, 50.0, true, 5.0);
        assert!((limit.unwrap() - 0.1).abs() < 1e-12, "{said}");
        let (limit, said) = turn_rate_limit(Some(3.0), 50.0, false, 5.0);
        assert!((limit.unwrap() - 3f64.to_radians()).abs() < 1e-12, "{said}");
    }
}
