//! Every vessel onto one clock: the judged interval (ownship's whole track),
//! the common time step, linear interpolation between fixes, a target
//! dead-reckoned where it was not observed (before its first fix, after its
//! last: decision 48), and the gaps too long to trust. The rules are in
//! `docs/judge.md`, "Resampling".

use crate::error::CliError;
use crate::judge::tracks::{Place, Track};
use serde::{Deserialize, Serialize};
use vorrt_colregs::observed::Unreported;
use vorrt_geometry::{DVec2, angle, units};
use vorrt_scenarios::LocalFrame;

/// The most samples (vessels times clock ticks) the judge resamples to.
pub(crate) const MAX_SAMPLES: usize = 20_000_000;

/// A target is judged with ownship when it was observed over at least this
/// fraction of ownship's span (decision 48).
pub(crate) const MIN_INTERVAL_FRACTION: f64 = 0.5;

/// One vessel's fixes in the local frame, sorted by time, one per time.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Prepared {
    /// The vessel's name.
    pub(crate) name: String,
    /// Fix times, strictly increasing, seconds.
    pub(crate) times_s: Vec<f64>,
    /// Positions, metres east and north.
    pub(crate) positions_m: Vec<DVec2>,
    /// Recorded courses, radians (when every fix gives one).
    pub(crate) courses_rad: Option<Vec<f64>>,
    /// Recorded speeds, metres per second (when every fix gives one).
    pub(crate) speeds_mps: Option<Vec<f64>>,
    /// Fixes dropped because an earlier one had the same time.
    pub(crate) duplicates: usize,
}

impl Prepared {
    /// The track in the local frame (`frame` places latitude and longitude).
    pub(crate) fn new(track: &Track, frame: Option<&LocalFrame>) -> Self {
        let mut fixes = track.fixes.clone();
        fixes.sort_by(|a, b| a.time_s.total_cmp(&b.time_s));
        let before = fixes.len();
        #[expect(
            clippy::float_cmp,
            reason = "only fixes with the very same time stamp are duplicates"
        )]
        fixes.dedup_by(|later, earlier| later.time_s == earlier.time_s);
        let local = |place: Place| match (place, frame) {
            (Place::Local(position_m), _) => position_m,
            (Place::LatLon(lat_deg, lon_deg), Some(frame)) => frame.to_local_m(lat_deg, lon_deg),
            // The caller gives a frame whenever a fix is geographic.
            (Place::LatLon(..), None) => DVec2::NAN,
        };
        let all = |values: Vec<Option<f64>>| values.into_iter().collect::<Option<Vec<f64>>>();
        Self {
            name: track.name.clone(),
            times_s: fixes.iter().map(|fix| fix.time_s).collect(),
            positions_m: fixes.iter().map(|fix| local(fix.place)).collect(),
            courses_rad: all(fixes
                .iter()
                .map(|fix| fix.course_deg.map(f64::to_radians))
                .collect()),
            speeds_mps: all(fixes
                .iter()
                .map(|fix| fix.speed_kn.map(units::knots_to_mps))
                .collect()),
            duplicates: before - fixes.len(),
        }
    }

    /// First and last fix time.
    pub(crate) fn span_s(&self) -> (f64, f64) {
        (
            self.times_s.first().copied().unwrap_or(0.0),
            self.times_s.last().copied().unwrap_or(0.0),
        )
    }
}

/// One vessel on the common clock.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Sampled {
    /// Positions, metres.
    pub(crate) positions_m: Vec<DVec2>,
    /// Courses over ground, radians.
    pub(crate) courses_rad: Vec<f64>,
    /// Speeds over ground, metres per second.
    pub(crate) speeds_mps: Vec<f64>,
    /// Whether the courses were recorded (else taken from the track).
    pub(crate) courses_recorded: bool,
    /// Whether the speeds were recorded (else taken from the track).
    pub(crate) speeds_recorded: bool,
}

/// The common clock.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct Clock {
    /// Every tick, seconds.
    #[serde(skip)]
    pub(crate) times_s: Vec<f64>,
    /// The step between ticks, seconds (the median where the input's own
    /// times are kept).
    pub(crate) step_s: f64,
    /// Whether the vessels were interpolated onto a new clock (`false`:
    /// they all shared their time stamps, which are kept).
    pub(crate) resampled: bool,
    /// The judged interval's start, seconds.
    pub(crate) from_s: f64,
    /// Its end, seconds.
    pub(crate) to_s: f64,
    /// Number of ticks.
    pub(crate) samples: usize,
}

/// A stretch without fixes longer than the gap limit: between two fixes,
/// bridged by a straight line; before a target's first fix or after its
/// last, dead-reckoned.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct Gap {
    /// The vessel.
    pub(crate) vessel: String,
    /// The last fix before it (or the clock's start), seconds.
    pub(crate) from_s: f64,
    /// The first fix after it (or the clock's end), seconds.
    pub(crate) to_s: f64,
    /// Whether the vessel was dead-reckoned over it (a target not observed
    /// at the start or the end of ownship's track), not bridged.
    pub(crate) dead_reckoned: bool,
}

impl Gap {
    /// The gap for the console and the notes, against the limit `max_gap_s`.
    pub(crate) fn describe(&self, max_gap_s: f64) -> String {
        format!(
            "gap: {:?} has no fix from {:.0} s to {:.0} s ({:.0} s > {max_gap_s:.0} s), {}",
            self.vessel,
            self.from_s,
            self.to_s,
            self.to_s - self.from_s,
            if self.dead_reckoned {
                "dead-reckoned on its nearest fix's course and speed"
            } else {
                "bridged by a straight line"
            }
        )
    }
}

/// The median of the positive steps between fix times of every vessel.
fn median_step_s(vessels: &[&Prepared]) -> Option<f64> {
    let mut steps: Vec<f64> = vessels
        .iter()
        .flat_map(|vessel| vessel.times_s.windows(2).map(|pair| pair[1] - pair[0]))
        .filter(|step| *step > 0.0)
        .collect();
    steps.sort_by(f64::total_cmp);
    steps.get(steps.len() / 2).copied()
}

/// The common clock over `[from_s, to_s]`: the vessels' own times when they
/// all share them, else ticks `step_s` apart (given, or the median step).
///
/// # Errors
/// [`CliError::BadInput`] when the interval holds fewer than two ticks or
/// too many samples.
pub(crate) fn clock(
    vessels: &[&Prepared],
    (from_s, to_s): (f64, f64),
    step_s: Option<f64>,
) -> Result<Clock, CliError> {
    let shared = vessels
        .windows(2)
        .all(|pair| pair[0].times_s == pair[1].times_s);
    let median = median_step_s(vessels).unwrap_or(0.0);
    let (times_s, step_s, resampled) = match (shared, step_s) {
        (true, None) => (
            vessels
                .first()
                .map(|vessel| vessel.times_s.clone())
                .unwrap_or_default(),
            median,
            false,
        ),
        (_, step) => {
            let step_s = step.unwrap_or(median);
            if !(step_s.is_finite() && step_s > 0.0) {
                return Err(CliError::BadInput(
                    "the tracks have no two fixes at different times: nothing to judge".into(),
                ));
            }
            let ticks = ((to_s - from_s) / step_s + 1e-9).floor();
            #[allow(clippy::cast_precision_loss)]
            if !(ticks.is_finite() && ticks * (vessels.len() as f64) < MAX_SAMPLES as f64) {
                return Err(CliError::BadInput(format!(
                    "resampling {:.0} s at a step of {step_s} s for {} vessels needs more than {MAX_SAMPLES} samples: give a larger --step-s",
                    to_s - from_s,
                    vessels.len()
                )));
            }
            #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
            let ticks = ticks as usize;
            #[allow(clippy::cast_precision_loss)]
            let mut times: Vec<f64> = (0..=ticks)
                .map(|tick| (from_s + tick as f64 * step_s).min(to_s))
                .collect();
            // The interval's end is a tick, the last step shorter if need be:
            // ownship's last fix is judged (decision 48), not cut off.
            if times.last().is_some_and(|last| to_s - last > 1e-9 * step_s) {
                times.push(to_s);
            }
            (times, step_s, true)
        }
    };
    if times_s.len() < 2 {
        return Err(CliError::BadInput(format!(
            "the judged interval {from_s} s to {to_s} s holds fewer than two samples: nothing to judge"
        )));
    }
    Ok(Clock {
        step_s,
        resampled,
        from_s: times_s.first().copied().unwrap_or(from_s),
        to_s: times_s.last().copied().unwrap_or(to_s),
        samples: times_s.len(),
        times_s,
    })
}

/// Where `time_s` falls among `fix_times_s`: the fix at or before it and the
/// fraction of the way to the next (0 at or beyond the last fix, and before
/// the first: [`sample`] dead-reckons there).
fn bracket(fix_times_s: &[f64], time_s: f64) -> (usize, usize, f64) {
    let after = fix_times_s.partition_point(|fix_s| *fix_s <= time_s);
    let before = after.saturating_sub(1);
    match fix_times_s.get(after) {
        Some(next_s) if after > 0 => {
            let span_s = next_s - fix_times_s[before];
            (
                before,
                after,
                ((time_s - fix_times_s[before]) / span_s).clamp(0.0, 1.0),
            )
        }
        _ => (before, before, 0.0),
    }
}

/// Course over ground from a track: the direction from the sample before to
/// the sample after (one-sided at the ends); a vessel that does not move
/// keeps the course it had.
fn courses_from_track(positions_m: &[DVec2]) -> Vec<f64> {
    let last = positions_m.len().saturating_sub(1);
    let mut courses: Vec<Option<f64>> = (0..positions_m.len())
        .map(|index| {
            let delta = positions_m[(index + 1).min(last)] - positions_m[index.saturating_sub(1)];
            (delta.length() > 1e-9).then(|| angle::normalize_2pi(delta.x.atan2(delta.y)))
        })
        .collect();
    // Forward, then backward fill over the stretches at rest.
    for index in 1..courses.len() {
        if courses[index].is_none() {
            courses[index] = courses[index - 1];
        }
    }
    for index in (0..courses.len().saturating_sub(1)).rev() {
        if courses[index].is_none() {
            courses[index] = courses[index + 1];
        }
    }
    courses.into_iter().map(|c| c.unwrap_or(0.0)).collect()
}

/// Speed over ground from a track: distance from the sample before to the
/// sample after over the time between them.
fn speeds_from_track(times_s: &[f64], positions_m: &[DVec2]) -> Vec<f64> {
    let last = positions_m.len().saturating_sub(1);
    (0..positions_m.len())
        .map(|index| {
            let (a, b) = (index.saturating_sub(1), (index + 1).min(last));
            let dt = times_s[b] - times_s[a];
            if dt > 0.0 {
                positions_m[b].distance(positions_m[a]) / dt
            } else {
                0.0
            }
        })
        .collect()
}

/// The speed of fix `index` where the file gives none: from the fix before
/// to the fix after (one-sided at the ends), metres per second.
fn fix_speed_mps(vessel: &Prepared, index: usize) -> f64 {
    let last = vessel.times_s.len().saturating_sub(1);
    let (a, b) = (index.saturating_sub(1), (index + 1).min(last));
    let dt = vessel.times_s[b] - vessel.times_s[a];
    if dt > 0.0 {
        vessel.positions_m[b].distance(vessel.positions_m[a]) / dt
    } else {
        0.0
    }
}

/// `vessel` on `clock`: positions and recorded speeds interpolated linearly,
/// courses along the shorter turn (recorded ones, else the fixes' own, from
/// the fix before to the fix after); speeds the file does not give are taken
/// from the resampled track. Before its first fix and after its last, the
/// vessel is dead-reckoned from that fix on its course and speed, as a
/// replay's recorded target is (`RecordedMotion::state_at`, decisions 40
/// and 48), so that the human and vorrt are judged among the same targets.
pub(crate) fn sample(vessel: &Prepared, clock: &Clock) -> Sampled {
    let brackets: Vec<(usize, usize, f64)> = clock
        .times_s
        .iter()
        .map(|time_s| bracket(&vessel.times_s, *time_s))
        .collect();
    // Courses the file does not give are the fixes' own (from the fix before
    // to the fix after), turned between fixes like recorded ones: a rate of
    // turn is then never measured over less than the data's own interval.
    let fix_courses_rad = vessel
        .courses_rad
        .clone()
        .unwrap_or_else(|| courses_from_track(&vessel.positions_m));
    let (first_s, last_s) = vessel.span_s();
    let dead_reckoned = |index: usize, time_s: f64| {
        let speed_mps = vessel
            .speeds_mps
            .as_ref()
            .map_or_else(|| fix_speed_mps(vessel, index), |speeds| speeds[index]);
        let (sin, cos) = fix_courses_rad[index].sin_cos();
        vessel.positions_m[index]
            + DVec2::new(sin, cos) * (speed_mps * (time_s - vessel.times_s[index]))
    };
    let positions_m: Vec<DVec2> = brackets
        .iter()
        .zip(&clock.times_s)
        .map(|(&(a, b, u), &time_s)| {
            let (pa, pb) = (vessel.positions_m[a], vessel.positions_m[b]);
            if time_s < first_s || time_s > last_s {
                dead_reckoned(a, time_s)
            } else if u == 0.0 {
                pa
            } else {
                pa + (pb - pa) * u
            }
        })
        .collect();
    let courses_rad = brackets
        .iter()
        .map(|&(a, b, u)| {
            let (ca, cb) = (fix_courses_rad[a], fix_courses_rad[b]);
            if u == 0.0 {
                ca
            } else {
                angle::normalize_2pi(ca + angle::signed_turn(ca, cb) * u)
            }
        })
        .collect();
    let speeds_mps = match &vessel.speeds_mps {
        Some(speeds) => brackets
            .iter()
            .map(|&(a, b, u)| {
                let (sa, sb) = (speeds[a], speeds[b]);
                if u == 0.0 { sa } else { sa + (sb - sa) * u }
            })
            .collect(),
        None => speeds_from_track(&clock.times_s, &positions_m),
    };
    Sampled {
        positions_m,
        courses_rad,
        speeds_mps,
        courses_recorded: vessel.courses_rad.is_some(),
        speeds_recorded: vessel.speeds_mps.is_some(),
    }
}

/// The stretches of `vessel` within the judged interval longer than
/// `max_gap_s` without a fix: between fixes, and before its first fix or
/// after its last (dead-reckoned).
pub(crate) fn gaps(vessel: &Prepared, clock: &Clock, max_gap_s: f64) -> Vec<Gap> {
    let gap = |from_s: f64, to_s: f64, dead_reckoned: bool| Gap {
        vessel: vessel.name.clone(),
        from_s,
        to_s,
        dead_reckoned,
    };
    let (first_s, last_s) = vessel.span_s();
    let before = (first_s - clock.from_s > max_gap_s).then(|| gap(clock.from_s, first_s, true));
    let after = (clock.to_s - last_s > max_gap_s).then(|| gap(last_s, clock.to_s, true));
    before
        .into_iter()
        .chain(
            vessel
                .times_s
                .windows(2)
                .filter(|pair| {
                    pair[1] - pair[0] > max_gap_s && pair[1] > clock.from_s && pair[0] < clock.to_s
                })
                .map(|pair| gap(pair[0], pair[1], false)),
        )
        .chain(after)
        .collect()
}

/// The stretches of the judged interval over which `vessel`'s positions are
/// not its reports: farther than half of `max_gap_s` from its nearest fix
/// (decision 49). The judge bridges gaps up to `max_gap_s`, so every
/// position it bridges lies within half of it of a fix; beyond that, before
/// the first fix, after the last, or in the middle of a longer gap, the
/// position is dead reckoning or a straight line, not what the vessel did.
pub(crate) fn unreported(vessel: &Prepared, clock: &Clock, max_gap_s: f64) -> Vec<Unreported> {
    let half_s = max_gap_s / 2.0;
    let (first_s, last_s) = vessel.span_s();
    let stretch = |from_s: f64, to_s: f64, last_fix_s, next_fix_s| {
        let (from_s, to_s) = (from_s.max(clock.from_s), to_s.min(clock.to_s));
        (to_s > from_s).then_some(Unreported {
            from_s,
            to_s,
            last_fix_s,
            next_fix_s,
        })
    };
    let before = stretch(clock.from_s, first_s - half_s, None, Some(first_s));
    let after = stretch(last_s + half_s, clock.to_s, Some(last_s), None);
    let inside = vessel
        .times_s
        .windows(2)
        .filter(|pair| pair[1] - pair[0] > max_gap_s)
        .filter_map(|pair| {
            stretch(
                pair[0] + half_s,
                pair[1] - half_s,
                Some(pair[0]),
                Some(pair[1]),
            )
        });
    before.into_iter().chain(inside).chain(after).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::judge::tracks::Fix;

    fn track(name: &str, fixes: &[(f64, f64, f64)]) -> Track {
        Track {
            name: name.into(),
            fixes: fixes
                .iter()
                .map(|&(time_s, east, north)| Fix {
                    time_s,
                    place: Place::Local(DVec2::new(east, north)),
                    course_deg: None,
                    speed_kn: None,
                    status: None,
                })
                .collect(),
            ..Track::default()
        }
    }

    #[test]
    fn shared_times_are_kept_exactly() {
        let a = Prepared::new(&track("a", &[(0.0, 0.0, 0.0), (5.0, 0.0, 30.0)]), None);
        let b = Prepared::new(&track("b", &[(0.0, 9.0, 0.0), (5.0, 9.0, 10.0)]), None);
        let clock = clock(&[&a, &b], (0.0, 5.0), None).unwrap();
        assert!(!clock.resampled);
        assert_eq!(clock.times_s, vec![0.0, 5.0]);
        let sampled = sample(&a, &clock);
        assert_eq!(sampled.positions_m, a.positions_m);
        assert!((sampled.speeds_mps[0] - 6.0).abs() < 1e-12);
        assert!(sampled.courses_rad[0].abs() < 1e-12);
    }

    #[test]
    fn irregular_times_are_interpolated_at_the_median_step_without_extrapolation() {
        // Fixes at 0, 2, 4, 10 and 1, 3, ..., 9: median step 2; moving east 1 m/s.
        let a = Prepared::new(
            &track(
                "a",
                &[
                    (0.0, 0.0, 0.0),
                    (2.0, 2.0, 0.0),
                    (4.0, 4.0, 0.0),
                    (10.0, 10.0, 0.0),
                ],
            ),
            None,
        );
        let b = Prepared::new(
            &track(
                "b",
                &[
                    (1.0, 0.0, 5.0),
                    (3.0, 2.0, 5.0),
                    (5.0, 4.0, 5.0),
                    (7.0, 6.0, 5.0),
                    (9.0, 8.0, 5.0),
                ],
            ),
            None,
        );
        let clock = clock(&[&a, &b], (1.0, 9.0), None).unwrap();
        assert!(clock.resampled);
        assert_eq!(clock.times_s, vec![1.0, 3.0, 5.0, 7.0, 9.0]);
        let sampled = sample(&a, &clock);
        for (time_s, position) in clock.times_s.iter().zip(&sampled.positions_m) {
            assert!((position.x - time_s).abs() < 1e-9);
        }
        assert!((sampled.courses_rad[2] - std::f64::consts::FRAC_PI_2).abs() < 1e-9);
        let gaps = gaps(&a, &clock, 5.0);
        assert_eq!(gaps.len(), 1);
        assert_eq!((gaps[0].from_s, gaps[0].to_s), (4.0, 10.0));
    }

    #[test]
    fn recorded_courses_turn_the_short_way_and_duplicates_go() {
        let mut t = track("a", &[(0.0, 0.0, 0.0), (0.0, 5.0, 5.0), (10.0, 0.0, 10.0)]);
        t.fixes[0].course_deg = Some(350.0);
        t.fixes[1].course_deg = Some(0.0);
        t.fixes[2].course_deg = Some(10.0);
        let a = Prepared::new(&t, None);
        assert_eq!(a.duplicates, 1);
        let clock = clock(&[&a], (0.0, 10.0), Some(5.0)).unwrap();
        let sampled = sample(&a, &clock);
        assert!(sampled.courses_recorded);
        assert!(
            sampled.courses_rad[1].to_degrees().abs() < 1e-9,
            "{:?}",
            sampled.courses_rad
        );
    }

    #[test]
    fn a_target_not_observed_at_the_ends_is_dead_reckoned_and_its_stretch_reported() {
        // Ownship observed 0-600 s; the target only 100-300 s, moving north
        // at 2 m/s (recorded 000°, 2 m/s = 3.888 kn): the clock is ownship's,
        // the target dead-reckoned before 100 s and after 300 s.
        let own = Prepared::new(&track("own", &[(0.0, 0.0, 0.0), (600.0, 600.0, 0.0)]), None);
        let mut t = track(
            "t",
            &[
                (100.0, 50.0, 200.0),
                (200.0, 50.0, 400.0),
                (300.0, 50.0, 600.0),
            ],
        );
        for fix in &mut t.fixes {
            fix.course_deg = Some(0.0);
            fix.speed_kn = Some(units::mps_to_knots(2.0));
        }
        let target = Prepared::new(&t, None);
        let clock = clock(&[&own, &target], own.span_s(), Some(100.0)).unwrap();
        assert_eq!((clock.from_s, clock.to_s), (0.0, 600.0));
        // Off the step, ownship's last fix is still a tick (a shorter last step).
        let odd = super::clock(&[&own, &target], (0.0, 650.0), Some(100.0)).unwrap();
        assert_eq!(odd.times_s[6..], [600.0, 650.0]);
        let sampled = sample(&target, &clock);
        let norths: Vec<f64> = sampled.positions_m.iter().map(|p| p.y).collect();
        for (north, expected) in norths
            .iter()
            .zip([0.0, 200.0, 400.0, 600.0, 800.0, 1000.0, 1200.0])
        {
            assert!((north - expected).abs() < 1e-6, "{norths:?}");
        }
        // Without recorded speeds, the same from the fixes themselves.
        let mut bare = t.clone();
        for fix in &mut bare.fixes {
            fix.speed_kn = None;
        }
        let bare = sample(&Prepared::new(&bare, None), &clock);
        assert!((bare.positions_m[6].y - 1200.0).abs() < 1e-6);
        // 300 s to 600 s dead-reckoned is longer than a 120 s gap limit; the
        // first 100 s is not.
        let long = gaps(&target, &clock, 120.0);
        assert_eq!(long.len(), 1, "{long:?}");
        assert!(long[0].dead_reckoned);
        assert_eq!((long[0].from_s, long[0].to_s), (300.0, 600.0));
        // At 50 s: both ends dead-reckoned, and the 100 s between fixes bridged.
        let short = gaps(&target, &clock, 50.0);
        assert_eq!(short.iter().filter(|gap| gap.dead_reckoned).count(), 2);
        assert_eq!(short.len(), 4, "{short:?}");
    }

    #[test]
    fn positions_farther_than_half_the_gap_limit_from_a_fix_are_unreported() {
        // Fixes at 100, 200, 500 and 600 s on ownship's 0-1000 s; limit 120 s.
        let own = Prepared::new(&track("own", &[(0.0, 0.0, 0.0), (1000.0, 0.0, 1.0)]), None);
        let fixes = [100.0, 200.0, 500.0, 600.0].map(|t| (t, 0.0, t));
        let target = Prepared::new(&track("t", &fixes), None);
        let clock = clock(&[&own, &target], own.span_s(), Some(10.0)).unwrap();
        let stretches = unreported(&target, &clock, 120.0);
        let spans: Vec<(f64, f64, Option<f64>, Option<f64>)> = stretches
            .iter()
            .map(|s| (s.from_s, s.to_s, s.last_fix_s, s.next_fix_s))
            .collect();
        assert_eq!(
            spans,
            [
                (0.0, 40.0, None, Some(100.0)),
                (260.0, 440.0, Some(200.0), Some(500.0)),
                (660.0, 1000.0, Some(600.0), None),
            ]
        );
        // A limit above every gap leaves only the ends.
        assert_eq!(unreported(&target, &clock, 400.0).len(), 1);
    }
}
