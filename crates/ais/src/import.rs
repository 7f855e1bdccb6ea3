//! From tracks to a geographic scenario: each vessel's state at the chosen
//! time, dead-reckoned from its last position report, and the scenario.

use crate::error::AisError;
use crate::log::{AisLog, PositionReport, VesselTrack};
use vorrt_geometry::{DVec2, units};
use vorrt_scenarios::colregs::observed::NavigationalStatus;
use vorrt_scenarios::geo::{LocalFrame, check_lat_lon, format_utc_time};
use vorrt_scenarios::{MAX_LENGTH_M, Scenario, VesselSpec};

/// The length given to a vessel without a static report, metres (a typical
/// small coaster; said on stderr by `vorrt import-ais`).
pub const DEFAULT_LENGTH_M: f64 = 50.0;

/// The default `--range-nm`: vessels farther from ownship are left out.
pub const DEFAULT_RANGE_NM: f64 = 12.0;

/// What to import.
#[derive(Debug, Clone, PartialEq)]
pub struct ImportOptions {
    /// The log's name in messages (its path).
    pub log_name: String,
    /// Ownship's MMSI.
    pub ownship_mmsi: u32,
    /// Ownship's goal `(latitude, longitude)`, degrees.
    pub goal_lat_lon: (f64, f64),
    /// The time of the scenario's start, UNIX seconds; `None`: the log's last
    /// tag-block time (or, in a log without tag blocks, each vessel's last
    /// report, undated).
    pub at_unix_s: Option<f64>,
    /// Targets farther than this from ownship are left out, nautical miles.
    pub range_nm: f64,
}

/// A vessel's estimated state at the chosen time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StateEstimate {
    /// `(latitude, longitude)`, degrees.
    pub lat_lon: (f64, f64),
    /// Course over ground, degrees (0 when the reports give none).
    pub course_deg: f64,
    /// Speed over ground, knots (0 when the reports give none).
    pub speed_kn: f64,
    /// How far the estimate was dead-reckoned from the report, seconds
    /// (0 in a log without times).
    pub dead_reckoned_s: f64,
    /// The report it comes from.
    pub report: PositionReport,
}

/// The state of `track` at `at_unix_s`, dead-reckoned along the geodesic of its
/// course over ground at its speed from its last position report at or before
/// that time. Without `at_unix_s`, or for undated reports, the last report as
/// it stands. `None` when no report comes at or before the time.
#[must_use]
pub fn estimate(track: &VesselTrack, at_unix_s: Option<f64>) -> Option<StateEstimate> {
    let report =
        *track
            .reports
            .iter()
            .rev()
            .find(|report| match (at_unix_s, report.time_unix_s) {
                (Some(at), Some(time)) => time <= at,
                _ => true,
            })?;
    let course_deg = report.course_deg.or(report.heading_deg).unwrap_or(0.0);
    let speed_kn = report.speed_kn.unwrap_or(0.0);
    let dead_reckoned_s = match (at_unix_s, report.time_unix_s) {
        (Some(at), Some(time)) => at - time,
        _ => 0.0,
    };
    let run_m = units::knots_to_mps(speed_kn) * dead_reckoned_s;
    let course_rad = course_deg.to_radians();
    let lat_lon = LocalFrame::new(report.lat_deg, report.lon_deg)
        .to_lat_lon_deg(DVec2::new(course_rad.sin(), course_rad.cos()) * run_m);
    Some(StateEstimate {
        lat_lon,
        course_deg,
        speed_kn,
        dead_reckoned_s,
        report,
    })
}

/// The note on a log without time stamps.
const UNTIMED: &str = "the log has no time stamps (no NMEA 4.0 tag blocks): every vessel is taken at its last report, as if all were at the same time, with nothing dead-reckoned";

/// A scenario made from a log, with what a person should be told about it.
#[derive(Debug, Clone)]
pub struct Import {
    /// The geographic scenario (validated).
    pub scenario: Scenario,
    /// Remarks for stderr: default lengths used, vessels left out and why.
    pub notes: Vec<String>,
}

fn vessel_name(track: &VesselTrack) -> String {
    track
        .name
        .clone()
        .unwrap_or_else(|| format!("MMSI {}", track.mmsi))
}

fn length_m(track: &VesselTrack, notes: &mut Vec<String>) -> f64 {
    match track.length_m {
        Some(length) if length <= MAX_LENGTH_M => length,
        Some(length) => {
            notes.push(format!(
                "MMSI {}: length {length} m from its static report is more than {MAX_LENGTH_M} m; using {MAX_LENGTH_M} m",
                track.mmsi
            ));
            MAX_LENGTH_M
        }
        None => {
            notes.push(format!(
                "MMSI {}: no static report with dimensions; length set to the default {DEFAULT_LENGTH_M} m",
                track.mmsi
            ));
            DEFAULT_LENGTH_M
        }
    }
}

/// A vessel's scenario entry. Its navigational status (the report's, AIS)
/// is named in the notes where the rules read it: at anchor, moored or
/// aground it is imported at rest (speed 0, rule 3(i): not under way); a
/// rule 18 status is named with the responsibility it brings (decision 32).
fn spec(track: &VesselTrack, state: &StateEstimate, notes: &mut Vec<String>) -> VesselSpec {
    let status = state
        .report
        .navigational_status
        .and_then(NavigationalStatus::from_ais);
    let at_rest = status.is_some_and(NavigationalStatus::is_at_rest);
    if let Some(rule) = status.and_then(NavigationalStatus::rule_18) {
        notes.push(format!(
            "MMSI {}: reports {}{}: {rule}",
            track.mmsi,
            status.map_or("", NavigationalStatus::name),
            if at_rest {
                format!(
                    "; imported at rest (speed 0 kn, reported {:.1} kn)",
                    state.speed_kn
                )
            } else {
                String::new()
            }
        ));
    }
    if state.report.course_deg.is_none() {
        notes.push(format!(
            "MMSI {}: course over ground not available (AIS 360°){}",
            track.mmsi,
            match state.report.heading_deg {
                Some(heading) => format!(": its heading {heading:.0}° is taken"),
                None => " nor its heading (511): course 000° assumed".to_owned(),
            }
        ));
    }
    let mut vessel = VesselSpec::new(
        vessel_name(track),
        (0.0, 0.0),
        state.course_deg,
        if at_rest { 0.0 } else { state.speed_kn },
        length_m(track, notes),
    );
    vessel.start_nm = None;
    vessel.start_lat_lon = Some(state.lat_lon);
    vessel.mmsi = Some(track.mmsi);
    vessel
}

/// The error for an ownship MMSI not in `log`, naming the first ten seen.
fn unknown_mmsi(log: &AisLog, options: &ImportOptions) -> AisError {
    let mut seen: Vec<String> = log.vessels.keys().take(10).map(u32::to_string).collect();
    if log.vessels.len() > 10 {
        seen.push("...".into());
    }
    AisError::UnknownMmsi {
        log: options.log_name.clone(),
        mmsi: options.ownship_mmsi,
        seen: if seen.is_empty() {
            "none".into()
        } else {
            seen.join(", ")
        },
    }
}

/// Builds the geographic scenario of `log`: ownship and every vessel within
/// the range at the chosen time, each dead-reckoned ([`estimate`]); targets
/// hold their course and speed. The scenario is validated as `vorrt check`
/// would.
///
/// # Errors
/// [`AisError`] when ownship is not in the log or has no position, an option
/// is out of range, or the scenario breaks a rule of the format.
pub fn build_scenario(log: &AisLog, options: &ImportOptions) -> Result<Import, AisError> {
    if !(options.range_nm.is_finite() && options.range_nm > 0.0) {
        return Err(AisError::Option {
            option: "--range-nm",
            problem: format!("is {}, expected a number greater than 0", options.range_nm),
        });
    }
    check_lat_lon(options.goal_lat_lon).map_err(|problem| AisError::Option {
        option: "--goal",
        problem,
    })?;
    let Some(own_track) = log.vessels.get(&options.ownship_mmsi) else {
        return Err(unknown_mmsi(log, options));
    };
    let at_unix_s = options.at_unix_s.or(log.last_time_unix_s);
    let mut notes: Vec<String> = at_unix_s
        .is_none()
        .then(|| UNTIMED.to_owned())
        .into_iter()
        .collect();
    let Some(own) = estimate(own_track, at_unix_s) else {
        return Err(AisError::NoOwnshipPosition {
            log: options.log_name.clone(),
            mmsi: options.ownship_mmsi,
            when: options
                .at_unix_s
                .map(|at| format!(" at or before {}", describe_time(at)))
                .unwrap_or_default(),
        });
    };
    let mut ownship = spec(own_track, &own, &mut notes);
    ownship.goal_lat_lon = Some(options.goal_lat_lon);
    let frame = LocalFrame::new(own.lat_lon.0, own.lat_lon.1);
    let range_m = units::nautical_miles_to_m(options.range_nm);
    let mut targets: Vec<VesselSpec> = Vec::new();
    for track in log.vessels.values() {
        if track.mmsi == options.ownship_mmsi {
            continue;
        }
        let Some(state) = estimate(track, at_unix_s) else {
            notes.push(format!(
                "MMSI {}: left out, no position report at or before the chosen time",
                track.mmsi
            ));
            continue;
        };
        let range = frame.to_local_m(state.lat_lon.0, state.lat_lon.1).length();
        if range > range_m {
            notes.push(format!(
                "MMSI {}: left out, {:.1} nm from ownship (range {} nm)",
                track.mmsi,
                range / units::NAUTICAL_MILE_M,
                options.range_nm
            ));
            continue;
        }
        let mut target = spec(track, &state, &mut notes);
        if target.name == ownship.name || targets.iter().any(|other| other.name == target.name) {
            target.name = format!("{} ({})", target.name, track.mmsi);
        }
        targets.push(target);
    }
    let start_time = at_unix_s.map(describe_time);
    let mut scenario = Scenario::new(format!("ais-{}", options.ownship_mmsi), ownship);
    scenario.description = Some(format!(
        "Imported from the AIS log {} by vorrt import-ais: ownship MMSI {}, {} targets within {} nm{}.",
        options.log_name,
        options.ownship_mmsi,
        targets.len(),
        options.range_nm,
        start_time
            .as_deref()
            .map(|time| format!(", states dead-reckoned to {time}"))
            .unwrap_or_default()
    ));
    scenario.targets = targets;
    scenario.start_time = start_time;
    scenario.source = format!("{} (imported)", options.log_name);
    // Validate as a loaded file would be: through the text.
    let text = scenario.to_ron_string()?;
    let scenario = Scenario::from_ron_str(&text, &scenario.source)?;
    Ok(Import { scenario, notes })
}

/// A UNIX time as ISO 8601 UTC, or as seconds if it is out of range.
fn describe_time(unix_s: f64) -> String {
    let nanos = (unix_s * 1e9).round();
    if !(nanos.is_finite() && nanos.abs() < 1e27) {
        return format!("{unix_s} s");
    }
    #[allow(clippy::cast_possible_truncation)]
    match time::OffsetDateTime::from_unix_timestamp_nanos(nanos as i128) {
        Ok(time) => format_utc_time(time),
        Err(_) => format!("{unix_s} s"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn report(lat_deg: f64, course_deg: Option<f64>, speed_kn: f64, status: u8) -> PositionReport {
        PositionReport {
            line: 1,
            time_unix_s: None,
            lat_deg,
            lon_deg: -1.0,
            course_deg,
            speed_kn: Some(speed_kn),
            heading_deg: None,
            navigational_status: Some(status),
        }
    }

    #[test]
    fn a_vessel_at_anchor_is_imported_at_rest_and_what_is_assumed_is_said() {
        let mut log = AisLog::default();
        for (mmsi, report) in [
            (1, report(50.0, Some(90.0), 12.0, 0)),
            (2, report(50.01, None, 0.3, 1)),
            (3, report(49.99, Some(0.0), 6.0, 7)),
        ] {
            log.vessels.insert(
                mmsi,
                VesselTrack {
                    mmsi,
                    name: Some(format!("V{mmsi}")),
                    length_m: Some(40.0),
                    own_vessel: false,
                    reports: vec![report],
                },
            );
        }
        let options = ImportOptions {
            log_name: "t.nmea".into(),
            ownship_mmsi: 1,
            goal_lat_lon: (50.0, -0.9),
            at_unix_s: None,
            range_nm: 12.0,
        };
        let import = build_scenario(&log, &options).unwrap();
        let anchored = &import.scenario.targets[0];
        assert!(anchored.speed_kn.abs() < 1e-12);
        let said = import.notes.join("\n");
        for expected in [
            "no time stamps",
            "MMSI 2: reports at_anchor",
            "imported at rest",
            "course 000° assumed",
            "MMSI 3: reports engaged_in_fishing",
            "18(a)(iii)",
        ] {
            assert!(said.contains(expected), "{expected:?} in {said}");
        }
    }
}
