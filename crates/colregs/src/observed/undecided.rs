//! What a recording cannot decide (decisions 32 and 49): an encounter still
//! closing when the tracks end, a vessel whose reported rest its own motion
//! contradicts, and an encounter whose closest approach or in-force window
//! the target did not report. Such an encounter is **undecided**: its
//! findings so far stand, but neither its passing nor its clearance is a
//! verdict.

use super::status::NavigationalStatus;
use crate::compliance::EncounterSample;
use serde::{Deserialize, Serialize};
use vorrt_geometry::units;

/// A reported rest (at anchor, moored, aground) is believed of a vessel
/// whose median speed over ground stays below this, m/s (1 kn: AIS statuses
/// are set by hand and often stale; a moored vessel's fix-to-fix jitter of
/// 15 m a minute is 0.5 kn).
pub const REST_BELIEVED_BELOW_MPS: f64 = 0.514;

/// A stretch of the clock over which a target's positions are not its
/// reports: dead-reckoned before its first fix or after its last, or
/// bridged across a gap between fixes too long to trust. Which stretches
/// those are is the recording's to say (`vorrt judge`: the positions more
/// than half of `--max-gap-s` from the vessel's nearest fix; decision 49).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Unreported {
    /// The stretch's start, seconds.
    pub from_s: f64,
    /// Its end, seconds.
    pub to_s: f64,
    /// The vessel's last fix before it, seconds (`None`: before its first).
    pub last_fix_s: Option<f64>,
    /// Its next fix after it, seconds (`None`: after its last).
    pub next_fix_s: Option<f64>,
}

impl Unreported {
    /// Whether `time_s` lies in the stretch.
    #[must_use]
    pub fn contains(&self, time_s: f64) -> bool {
        (self.from_s..=self.to_s).contains(&time_s)
    }

    /// How much of `[from_s, to_s]` the stretch covers, seconds.
    #[must_use]
    pub fn overlap_s(&self, from_s: f64, to_s: f64) -> f64 {
        (self.to_s.min(to_s) - self.from_s.max(from_s)).max(0.0)
    }
}

/// Why an encounter is undecided.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", tag = "reason")]
pub enum Undecided {
    /// Risk of collision had arisen and the two were still closing at the
    /// last sample: the closest approach is the end of the tracks
    /// (decision 32).
    StillClosing,
    /// The target reported itself not under way (at anchor, moored,
    /// aground) but made way: her status and her motion contradict each
    /// other, so her duties are not known (rule 3(i) against what she did).
    /// Judged on clearance alone, as a vessel at rest; rules 13-17 not
    /// judged (decision 49).
    StatusContradictsMotion {
        /// The status reported.
        status: NavigationalStatus,
        /// Her median speed over ground, knots.
        speed_kn: f64,
    },
    /// The closest approach, or more than half of the time the encounter
    /// was in force, lies where the target did not report: the passing
    /// rests on dead reckoning or a long gap, not on what she did
    /// (decision 49).
    NotReported {
        /// The unreported stretch that decides it.
        stretch: Unreported,
        /// The time of the closest approach, seconds.
        closest_approach_s: f64,
        /// Whether the closest approach lies in an unreported stretch
        /// (else the in-force window mostly does).
        closest_approach_unreported: bool,
        /// The share of the in-force window not reported, in `[0, 1]`.
        in_force_unreported: f64,
    },
}

impl Undecided {
    /// A short name in snake case, as used in reports.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Self::StillClosing => "still_closing",
            Self::StatusContradictsMotion { .. } => "status_contradicts_motion",
            Self::NotReported { .. } => "not_reported",
        }
    }
}

impl std::fmt::Display for Undecided {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            Self::StillClosing => write!(
                f,
                "still closing when the tracks end; not passed, not judged safe"
            ),
            Self::StatusContradictsMotion { status, speed_kn } => write!(
                f,
                "reports {} but made way at {speed_kn:.1} kn (median): status contradicts motion, judged on clearance alone; rules 13-17 not judged",
                status.name()
            ),
            Self::NotReported {
                stretch,
                closest_approach_s,
                closest_approach_unreported,
                in_force_unreported,
            } => {
                match (stretch.last_fix_s, stretch.next_fix_s) {
                    (Some(last), None) => write!(f, "target not reported from {last:.0} s")?,
                    (None, Some(next)) => write!(f, "target not reported until {next:.0} s")?,
                    (Some(last), Some(next)) => {
                        write!(f, "target not reported from {last:.0} s to {next:.0} s")?;
                    }
                    (None, None) => write!(f, "target never reported")?,
                }
                let how = if stretch.next_fix_s.is_some() && stretch.last_fix_s.is_some() {
                    "bridged across the gap"
                } else {
                    "dead-reckoned"
                };
                if closest_approach_unreported {
                    write!(
                        f,
                        ": closest approach (at {closest_approach_s:.0} s) {how}; not passed, not judged safe"
                    )
                } else {
                    write!(
                        f,
                        ": {:.0} % of the encounter in force {how}; not passed, not judged safe",
                        in_force_unreported * 100.0
                    )
                }
            }
        }
    }
}

/// The reported rest that the vessel's motion contradicts, if any: a status
/// at anchor, moored or aground of a vessel whose median speed over ground
/// is [`REST_BELIEVED_BELOW_MPS`] or more.
///
/// ```
/// use vorrt_colregs::observed::{NavigationalStatus, rest_contradicted};
/// let moored = Some(NavigationalStatus::Moored);
/// assert!(rest_contradicted(moored, 0.1).is_none());
/// assert!(rest_contradicted(moored, 0.9).is_some());
/// assert!(rest_contradicted(Some(NavigationalStatus::UnderWayUsingEngine), 5.0).is_none());
/// ```
#[must_use]
pub fn rest_contradicted(
    status: Option<NavigationalStatus>,
    median_speed_mps: f64,
) -> Option<Undecided> {
    status
        .filter(|status| status.is_at_rest() && median_speed_mps >= REST_BELIEVED_BELOW_MPS)
        .map(|status| Undecided::StatusContradictsMotion {
            status,
            speed_kn: units::mps_to_knots(median_speed_mps),
        })
}

/// The median speed between consecutive samples of a track, m/s (0 with
/// fewer than two samples).
#[must_use]
pub fn median_step_speed_mps(times_s: &[f64], positions_m: &[glam::DVec2]) -> f64 {
    let mut speeds_mps: Vec<f64> = times_s
        .windows(2)
        .zip(positions_m.windows(2))
        .filter(|(times, _)| times[1] > times[0])
        .map(|(times, positions)| positions[0].distance(positions[1]) / (times[1] - times[0]))
        .collect();
    speeds_mps.sort_by(f64::total_cmp);
    speeds_mps.get(speeds_mps.len() / 2).copied().unwrap_or(0.0)
}

/// How far a vessel may be from where an unreported stretch puts her at
/// `time_s`, metres: twice her speed times the time from her nearest fix
/// (she may have stopped, or turned back, as soon as she fell silent).
#[must_use]
pub fn reach_m(stretch: &Unreported, time_s: f64, speed_mps: f64) -> f64 {
    let since_s = stretch.last_fix_s.map_or(f64::INFINITY, |t| time_s - t);
    let until_s = stretch.next_fix_s.map_or(f64::INFINITY, |t| t - time_s);
    2.0 * speed_mps * since_s.min(until_s).max(0.0)
}

/// Whether an encounter rests on what the target did not report (decision
/// 49): its closest approach (`closest_approach`: time, seconds, and
/// distance, metres) lies in an unreported stretch and, moved by her
/// [`reach_m`] at `speed_mps`, could break the clearance (`keeps_clearance`
/// of a distance says whether it is kept); or more than half of its
/// in-force window (from `in_force_s.0` to `in_force_s.1`) is unreported.
#[must_use]
pub fn not_reported(
    unreported: &[Unreported],
    closest_approach: (f64, f64),
    in_force_s: Option<(f64, f64)>,
    speed_mps: f64,
    keeps_clearance: impl Fn(f64) -> bool,
) -> Option<Undecided> {
    let (time_of_min_s, min_distance_m) = closest_approach;
    let (share, longest) = match in_force_s {
        Some((from_s, to_s)) if to_s > from_s => {
            let covered_s: f64 = unreported.iter().map(|s| s.overlap_s(from_s, to_s)).sum();
            let longest = unreported.iter().max_by(|a, b| {
                a.overlap_s(from_s, to_s)
                    .total_cmp(&b.overlap_s(from_s, to_s))
            });
            (covered_s / (to_s - from_s), longest)
        }
        _ => (0.0, None),
    };
    let at_closest = unreported.iter().find(|s| {
        s.contains(time_of_min_s)
            && !keeps_clearance(min_distance_m - reach_m(s, time_of_min_s, speed_mps))
    });
    let stretch = at_closest.or(longest.filter(|_| share > 0.5))?;
    Some(Undecided::NotReported {
        stretch: *stretch,
        closest_approach_s: time_of_min_s,
        closest_approach_unreported: at_closest.is_some(),
        in_force_unreported: share.clamp(0.0, 1.0),
    })
}

/// The in-force window of an encounter latched at `latched_at_s`: to the
/// first sample at which the vessels had passed, else to the last sample.
#[must_use]
pub fn in_force_window_s(
    samples: &[EncounterSample],
    latched_at_s: f64,
    passed_at_s: Option<f64>,
) -> Option<(f64, f64)> {
    let end_s = passed_at_s.or_else(|| samples.last().map(|s| s.time_s))?;
    Some((latched_at_s, end_s))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn after(last_fix_s: f64, from_s: f64, to_s: f64) -> Unreported {
        Unreported {
            from_s,
            to_s,
            last_fix_s: Some(last_fix_s),
            next_fix_s: None,
        }
    }

    #[test]
    fn a_closest_approach_unreported_is_undecided() {
        let stretch = [after(1000.0, 1060.0, 2000.0)];
        let keeps = |distance_m: f64| distance_m >= 200.0;
        let undecided = not_reported(
            &stretch,
            (1500.0, 1000.0),
            Some((900.0, 1600.0)),
            1.0,
            keeps,
        )
        .expect("undecided");
        assert!(undecided.to_string().contains("not reported from 1000 s"));
        assert!(undecided.to_string().contains("closest approach"));
        assert!(
            not_reported(
                &stretch,
                (1050.0, 1000.0),
                Some((900.0, 1200.0)),
                1.0,
                keeps
            )
            .is_none()
        );
        // 500 s silent at 0.5 m/s: she cannot have come within 500 m of
        // where she was put, so a closest approach of 800 m keeps 200 m.
        assert!(
            not_reported(&stretch, (1500.0, 800.0), Some((900.0, 1200.0)), 0.5, keeps).is_none()
        );
        assert!(
            not_reported(&stretch, (1500.0, 600.0), Some((900.0, 1200.0)), 0.5, keeps).is_some()
        );
    }

    #[test]
    fn an_in_force_window_mostly_unreported_is_undecided() {
        let stretch = [after(1000.0, 1060.0, 2000.0)];
        // In force 1000-1900 s, 840 of 900 s unreported; the closest
        // approach at the last fix.
        let keeps = |distance_m: f64| distance_m >= 200.0;
        let undecided = not_reported(
            &stretch,
            (1040.0, 300.0),
            Some((1000.0, 1900.0)),
            5.0,
            keeps,
        )
        .expect("undecided");
        assert!(undecided.to_string().contains("93 %"), "{undecided}");
        // Half or less: decided.
        assert!(
            not_reported(&stretch, (1040.0, 300.0), Some((200.0, 1900.0)), 5.0, keeps).is_none()
        );
    }

    #[test]
    fn a_rest_is_contradicted_only_by_way_made() {
        let status = Some(NavigationalStatus::AtAnchor);
        assert!(rest_contradicted(status, REST_BELIEVED_BELOW_MPS * 0.9).is_none());
        let contradicted = rest_contradicted(status, 2.0).expect("contradicted");
        assert!(contradicted.to_string().contains("rules 13-17 not judged"));
        assert!(rest_contradicted(None, 2.0).is_none());
    }
}
