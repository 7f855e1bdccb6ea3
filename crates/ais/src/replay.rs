//! From an AIS log to a replay scenario (decision 40): ownship starts from
//! its recorded state and sails for where it went, every other vessel
//! follows its recorded track ([`Behaviour::Recorded`]), and the tracks,
//! ownship's among them (the human's track, for `vorrt judge`), go to a CSV
//! file beside the scenario.

use crate::error::AisError;
use crate::import::{ImportOptions, build_scenario};
use crate::log::{AisLog, VesselTrack};
use std::fmt::Write as _;
use vorrt_geometry::units;
use vorrt_scenarios::colregs::observed::MAKING_WAY_MPS;
use vorrt_scenarios::{Behaviour, Scenario};

/// What to replay.
#[derive(Debug, Clone, PartialEq)]
pub struct ReplayOptions {
    /// The log's name in messages (its path).
    pub log_name: String,
    /// Ownship's MMSI.
    pub ownship_mmsi: u32,
    /// Ownship's goal `(latitude, longitude)`, degrees; `None`: its last
    /// recorded position, where the human took it.
    pub goal_lat_lon: Option<(f64, f64)>,
    /// The replay's start, UNIX seconds; `None`: the latest first report
    /// of ownship and of the vessels in the log, so that every vessel has
    /// been seen when the run starts.
    pub at_unix_s: Option<f64>,
    /// Vessels farther than this from ownship at the start are left out,
    /// nautical miles.
    pub range_nm: f64,
    /// The tracks file's path as the scenario names it (relative to the
    /// scenario file's folder), e.g. `"channel.tracks.csv"`.
    pub tracks_file: String,
}

/// A replay made from a log.
#[derive(Debug, Clone)]
pub struct Replay {
    /// The geographic scenario (validated), its targets `Recorded`, naming
    /// the tracks file in `recorded_tracks`.
    pub scenario: Scenario,
    /// The tracks file's text: `vessel,mmsi,time_s,lat_deg,lon_deg,course_deg,speed_kn`,
    /// one row per dated position report of ownship and of every target,
    /// `time_s` in seconds from the start (negative before it).
    pub tracks_csv: String,
    /// Remarks for stderr.
    pub notes: Vec<String>,
}

/// A CSV field: quoted when it holds a comma, a quote or a line break.
fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_owned()
    }
}

/// Ownship's service speed in a replay (decision 48): the median of its
/// recorded speeds over ground from `from_s` (UNIX seconds) on, counting
/// only reports making way (the observed judgement's threshold,
/// [`MAKING_WAY_MPS`]); `None` when it never made
/// way. The speed at the start report alone is no service speed: a tug
/// leaving a berth at 6.7 kn then made 13 kn.
#[must_use]
pub fn service_speed_kn(track: &VesselTrack, from_s: f64) -> Option<f64> {
    let mut speeds_kn: Vec<f64> = track
        .reports
        .iter()
        .filter(|report| report.time_unix_s.is_some_and(|time_s| time_s >= from_s))
        .filter_map(|report| report.speed_kn)
        .filter(|speed_kn| units::knots_to_mps(*speed_kn) > MAKING_WAY_MPS)
        .collect();
    speeds_kn.sort_by(f64::total_cmp);
    let middle = speeds_kn.len() / 2;
    if speeds_kn.is_empty() {
        None
    } else if speeds_kn.len().is_multiple_of(2) {
        Some(f64::midpoint(speeds_kn[middle - 1], speeds_kn[middle]))
    } else {
        Some(speeds_kn[middle])
    }
}

/// The first dated report of `track`, UNIX seconds.
fn first_time_s(track: &VesselTrack) -> Option<f64> {
    track.reports.iter().find_map(|report| report.time_unix_s)
}

/// Builds the replay of `log` for ownship `options.ownship_mmsi`.
///
/// # Errors
/// [`AisError`] as [`build_scenario`]; [`AisError::NoOwnshipPosition`]
/// when ownship has no dated report (a replay needs the log's times).
pub fn build_replay(log: &AisLog, options: &ReplayOptions) -> Result<Replay, AisError> {
    let no_dated_position = || AisError::NoOwnshipPosition {
        log: options.log_name.clone(),
        mmsi: options.ownship_mmsi,
        when: " with a time (a replay needs tag-block times)".into(),
    };
    let own_track = log.vessels.get(&options.ownship_mmsi);
    let own_last = own_track.and_then(|track| {
        track
            .reports
            .iter()
            .rev()
            .find(|report| report.time_unix_s.is_some())
    });
    let start_s = match options.at_unix_s {
        Some(at) => at,
        None if own_track.is_some() => log
            .vessels
            .values()
            .filter_map(first_time_s)
            .fold(f64::NEG_INFINITY, f64::max)
            .min(
                own_last
                    .and_then(|report| report.time_unix_s)
                    .unwrap_or(f64::INFINITY),
            ),
        // Unknown ownship: `build_scenario` says so.
        None => f64::NAN,
    };
    let goal_lat_lon = match (options.goal_lat_lon, own_last) {
        (Some(goal), _) => goal,
        (None, Some(last)) => (last.lat_deg, last.lon_deg),
        (None, None) if own_track.is_some() => return Err(no_dated_position()),
        (None, None) => (0.0, 0.0),
    };
    let import = build_scenario(
        log,
        &ImportOptions {
            log_name: options.log_name.clone(),
            ownship_mmsi: options.ownship_mmsi,
            goal_lat_lon,
            at_unix_s: start_s.is_finite().then_some(start_s),
            range_nm: options.range_nm,
        },
    )?;
    if !start_s.is_finite() {
        return Err(no_dated_position());
    }
    let mut scenario = import.scenario;
    let mut notes = import.notes;
    if let Some(speed_kn) = own_track.and_then(|track| service_speed_kn(track, start_s)) {
        notes.push(format!(
            "ownship's service speed is {speed_kn:.1} kn, the median of its recorded speeds making way from the start (decision 48; {:.1} kn at the start)",
            scenario.ownship.speed_kn
        ));
        scenario.ownship.speed_kn = speed_kn;
    }
    scenario.name = format!("replay-{}", options.ownship_mmsi);
    scenario.description = Some(format!(
        "Replay of the AIS log {} by vorrt import-ais --replay: ownship MMSI {} from its recorded state at {}, goal {}; {} targets follow their recorded tracks in {}.",
        options.log_name,
        options.ownship_mmsi,
        scenario.start_time.as_deref().unwrap_or("the start"),
        if options.goal_lat_lon.is_some() {
            "--goal"
        } else {
            "its last recorded position"
        },
        scenario.targets.len(),
        options.tracks_file
    ));
    for target in &mut scenario.targets {
        target.behaviour = Behaviour::Recorded;
    }
    scenario.recorded_tracks = Some(options.tracks_file.clone());
    let tracks_csv = tracks_csv(log, &scenario, start_s, &mut notes);
    // Validate as a loaded file would be: through the text.
    let text = scenario.to_ron_string()?;
    let scenario = Scenario::from_ron_str(&text, &scenario.source)?;
    Ok(Replay {
        scenario,
        tracks_csv,
        notes,
    })
}

/// The tracks file of `scenario`'s vessels from `log`: each dated report,
/// its time in seconds from `start_s`; the reports left out go to `notes`.
/// Ownship's track, the human's, starts at its last report at or before
/// the start (the state the run starts from), so that `vorrt judge` judges
/// it over the run's time, not before it.
fn tracks_csv(log: &AisLog, scenario: &Scenario, start_s: f64, notes: &mut Vec<String>) -> String {
    let mut csv = String::from("vessel,mmsi,time_s,lat_deg,lon_deg,course_deg,speed_kn\n");
    for (index, vessel) in std::iter::once(&scenario.ownship)
        .chain(&scenario.targets)
        .enumerate()
    {
        let Some(track) = vessel.mmsi.and_then(|mmsi| log.vessels.get(&mmsi)) else {
            continue;
        };
        let from_s = if index == 0 {
            track
                .reports
                .iter()
                .filter_map(|report| report.time_unix_s)
                .filter(|&time_s| time_s <= start_s)
                .fold(f64::NEG_INFINITY, f64::max)
        } else {
            f64::NEG_INFINITY
        };
        let mut last_s = f64::NEG_INFINITY;
        let mut skipped = 0;
        for report in &track.reports {
            // Two reports in one second of the tag-block clock: the first stands.
            match report.time_unix_s {
                Some(time_s) if time_s < from_s => continue,
                Some(time_s) if time_s > last_s => last_s = time_s,
                _ => {
                    skipped += 1;
                    continue;
                }
            }
            let optional = |value: Option<f64>| value.map(|v| v.to_string()).unwrap_or_default();
            // Writing to a String cannot fail.
            let _ = writeln!(
                csv,
                "{},{},{},{},{},{},{}",
                csv_field(&vessel.name),
                track.mmsi,
                last_s - start_s,
                report.lat_deg,
                report.lon_deg,
                optional(report.course_deg),
                optional(report.speed_kn),
            );
        }
        if skipped > 0 {
            notes.push(format!(
                "MMSI {}: {skipped} reports without a time, or not after the one before, left out of the tracks",
                track.mmsi
            ));
        }
    }
    csv
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::log::read_log;

    const LOG: &str = include_str!("../fixtures/encounter.nmea");

    fn options() -> ReplayOptions {
        ReplayOptions {
            log_name: "encounter.nmea".into(),
            ownship_mmsi: 235_000_001,
            goal_lat_lon: None,
            at_unix_s: None,
            range_nm: 12.0,
            tracks_file: "encounter.tracks.csv".into(),
        }
    }

    #[test]
    fn every_target_follows_its_track_and_ownship_sails_for_where_it_went() {
        let log = read_log(LOG);
        let replay = build_replay(&log, &options()).expect("a replay");
        let scenario = &replay.scenario;
        assert!(!scenario.targets.is_empty());
        assert!(
            scenario
                .targets
                .iter()
                .all(|target| target.behaviour == Behaviour::Recorded)
        );
        assert_eq!(
            scenario.recorded_tracks.as_deref(),
            Some("encounter.tracks.csv")
        );
        let own = &log.vessels[&235_000_001];
        let last = own.reports.last().expect("reports");
        assert_eq!(
            scenario.ownship.goal_lat_lon,
            Some((last.lat_deg, last.lon_deg))
        );
        // Every vessel has rows, ownship's first; times start before 0 or at it.
        let mut lines = replay.tracks_csv.lines().skip(1);
        // Ownship's (the human's) rows begin at its report the run starts from.
        let time_s = |line: &str| -> f64 {
            line.split(',')
                .nth(2)
                .expect("time_s")
                .parse()
                .expect("a number")
        };
        let first = lines.next().expect("a row");
        assert!(first.starts_with(&scenario.ownship.name));
        assert!(time_s(first) <= 0.0, "{first}");
        assert!(time_s(lines.next().expect("a second row")) > 0.0);
        for target in &scenario.targets {
            assert!(
                replay
                    .tracks_csv
                    .lines()
                    .any(|line| line.starts_with(&format!("{},", csv_field(&target.name)))),
                "{}",
                target.name
            );
        }
    }

    #[test]
    fn the_service_speed_is_the_median_speed_making_way_from_the_start() {
        let report = |time_s: f64, speed_kn: Option<f64>| crate::log::PositionReport {
            line: 1,
            time_unix_s: Some(time_s),
            lat_deg: 50.0,
            lon_deg: -1.0,
            course_deg: Some(90.0),
            speed_kn,
            heading_deg: None,
            navigational_status: None,
        };
        let track = VesselTrack {
            mmsi: 1,
            reports: [
                (0.0, Some(20.0)),
                (10.0, Some(6.7)),
                (20.0, Some(0.2)),
                (30.0, None),
                (40.0, Some(13.0)),
                (50.0, Some(12.0)),
            ]
            .into_iter()
            .map(|(time_s, speed_kn)| report(time_s, speed_kn))
            .collect(),
            ..VesselTrack::default()
        };
        // From 10 s: 6.7, 13.0, 12.0 making way (0.2 kn is not; None unknown).
        assert_eq!(service_speed_kn(&track, 10.0), Some(12.0));
        assert_eq!(service_speed_kn(&track, 45.0), Some(12.0));
        assert_eq!(service_speed_kn(&track, 0.0), Some(12.5));
        assert_eq!(service_speed_kn(&track, 60.0), None);
        // The replay's ownship sails at the rule's speed, from its start.
        let log = read_log(LOG);
        let replay = build_replay(&log, &options()).expect("a replay");
        let start_s = log
            .vessels
            .values()
            .filter_map(first_time_s)
            .fold(f64::NEG_INFINITY, f64::max);
        let expected = service_speed_kn(&log.vessels[&235_000_001], start_s).expect("made way");
        assert!((replay.scenario.ownship.speed_kn - expected).abs() < 1e-9);
    }

    #[test]
    fn a_log_without_times_cannot_be_replayed() {
        let undated: String = LOG
            .lines()
            .map(|line| line.rsplit('\\').next().unwrap_or(line))
            .collect::<Vec<_>>()
            .join("\n");
        let error = build_replay(&read_log(&undated), &options()).expect_err("no times");
        assert!(
            error.to_string().contains("a replay needs tag-block times"),
            "{error}"
        );
        assert_eq!(csv_field("a,b \"c\""), "\"a,b \"\"c\"\"\"");
    }
}
