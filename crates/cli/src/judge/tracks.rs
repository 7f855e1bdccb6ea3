//! Recorded tracks as read from a file, before resampling: every vessel's
//! fixes (time, position, and course and speed where the file gives them),
//! and the reader for `trajectory.csv`.

use crate::error::CliError;
use std::collections::HashMap;
use vorrt_colregs::observed::NavigationalStatus;
use vorrt_geometry::DVec2;

/// Where a fix puts the vessel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Place {
    /// East and north in metres, in the frame of the file (or the scenario's).
    Local(DVec2),
    /// Latitude and longitude, degrees WGS84.
    LatLon(f64, f64),
}

/// One recorded fix of one vessel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Fix {
    /// Seconds: the file's `time_s`, or (absolute times) UNIX seconds.
    pub(crate) time_s: f64,
    /// The position.
    pub(crate) place: Place,
    /// Course over ground, degrees clockwise from north, when given.
    pub(crate) course_deg: Option<f64>,
    /// Speed over ground, knots, when given.
    pub(crate) speed_kn: Option<f64>,
    /// The navigational status reported with the fix (AIS), when given.
    pub(crate) status: Option<NavigationalStatus>,
}

/// One vessel's recorded track.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct Track {
    /// The vessel's name (an AIS vessel without one: its MMSI).
    pub(crate) name: String,
    /// Its MMSI, when the file gives it.
    pub(crate) mmsi: Option<u32>,
    /// Its length overall, metres, when the file gives it.
    pub(crate) length_m: Option<f64>,
    /// Its AIS ship and cargo type (ITU-R M.1371 table 53), when given.
    pub(crate) ship_type: Option<u8>,
    /// Whether the file marks it as the recording vessel (`role: "ownship"`
    /// in `GeoJSON`, `!AIVDO` in AIS).
    pub(crate) marked_ownship: bool,
    /// Its fixes, in file order.
    pub(crate) fixes: Vec<Fix>,
}

/// Everything read from a tracks file.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct Tracks {
    /// `csv`, `geojson` or `ais`.
    pub(crate) format: &'static str,
    /// Every vessel, in the order it first appears in the file.
    #[expect(
        clippy::struct_field_names,
        reason = "the file's tracks: one `Track` per vessel, as the readers name them"
    )]
    pub(crate) tracks: Vec<Track>,
    /// Whether the times are absolute (UNIX seconds: ISO 8601 times, AIS
    /// tag blocks) rather than seconds from the start of a run.
    pub(crate) absolute_times: bool,
    /// What the reader skipped or assumed, for the output.
    pub(crate) notes: Vec<String>,
}

/// A bad-input error naming the file and where in it.
pub(crate) fn bad(file: &str, what: impl std::fmt::Display) -> CliError {
    CliError::BadInput(format!("{file}: {what}"))
}

/// Groups fixes by vessel, keeping the order in which vessels first appear.
#[derive(Debug, Default)]
pub(crate) struct Collector {
    index: HashMap<String, usize>,
    tracks: Vec<Track>,
}

impl Collector {
    /// The track of `name`, created empty on its first mention.
    pub(crate) fn track(&mut self, name: &str) -> &mut Track {
        let next = self.tracks.len();
        let index = *self.index.entry(name.to_owned()).or_insert(next);
        if index == next {
            self.tracks.push(Track {
                name: name.to_owned(),
                ..Track::default()
            });
        }
        &mut self.tracks[index]
    }

    /// Whether a track of `name` exists.
    pub(crate) fn contains(&self, name: &str) -> bool {
        self.index.contains_key(name)
    }

    /// Every track, in order of first appearance.
    pub(crate) fn into_tracks(self) -> Vec<Track> {
        self.tracks
    }
}

/// The columns of a tracks CSV, by their index in the header.
struct Columns {
    time_s: Option<usize>,
    time: Option<usize>,
    vessel: usize,
    east: Option<(usize, usize)>,
    lat_lon: Option<(usize, usize)>,
    course: Option<usize>,
    speed: Option<usize>,
    length: Option<usize>,
    status: Option<usize>,
    ship_type: Option<usize>,
}

impl Columns {
    fn new(file: &str, header: &csv::StringRecord) -> Result<Self, CliError> {
        let find = |name: &str| header.iter().position(|column| column.trim() == name);
        let pair = |a: &str, b: &str| find(a).zip(find(b));
        let columns = Self {
            time_s: find("time_s"),
            time: find("time"),
            vessel: find("vessel").ok_or_else(|| {
                bad(
                    file,
                    "line 1: no `vessel` column (expected the header of trajectory.csv: time_s,vessel,east_m,north_m,...)",
                )
            })?,
            east: pair("east_m", "north_m"),
            lat_lon: pair("lat_deg", "lon_deg"),
            course: find("course_deg"),
            speed: find("speed_kn"),
            length: find("length_m"),
            status: find("status"),
            ship_type: find("ship_type"),
        };
        if columns.time_s.is_none() && columns.time.is_none() {
            return Err(bad(
                file,
                "line 1: no `time_s` column (seconds) or `time` column (ISO 8601 UTC)",
            ));
        }
        if columns.east.is_none() && columns.lat_lon.is_none() {
            return Err(bad(
                file,
                "line 1: no position columns: expected `east_m,north_m` or `lat_deg,lon_deg`",
            ));
        }
        Ok(columns)
    }

    /// A row's time, seconds, and whether it is absolute (Unix seconds from
    /// an ISO 8601 `time`) rather than `time_s`.
    fn time_s(
        &self,
        file: &str,
        line: u64,
        record: &csv::StringRecord,
    ) -> Result<(f64, bool), CliError> {
        match (self.time_s, self.time) {
            (Some(column), _) => Ok((required(file, line, record, column, "time_s")?, false)),
            (None, Some(column)) => {
                let text = record.get(column).unwrap_or("").trim();
                let time = vorrt_scenarios::geo::parse_utc_time(text)
                    .map_err(|problem| bad(file, format!("line {line}, field `time` {problem}")))?;
                Ok((unix_seconds(time), true))
            }
            (None, None) => unreachable_columns(file),
        }
    }

    /// A row's position: local metres when the file has them, else a
    /// checked latitude and longitude.
    fn place(&self, file: &str, line: u64, record: &csv::StringRecord) -> Result<Place, CliError> {
        let local = self
            .east
            .map(|(east, north)| {
                Ok::<_, CliError>(DVec2::new(
                    required(file, line, record, east, "east_m")?,
                    required(file, line, record, north, "north_m")?,
                ))
            })
            .transpose()?;
        Ok(match (local, self.lat_lon) {
            (Some(position), _) => Place::Local(position),
            (None, Some((lat, lon))) => {
                let lat_lon = (
                    required(file, line, record, lat, "lat_deg")?,
                    required(file, line, record, lon, "lon_deg")?,
                );
                vorrt_scenarios::geo::check_lat_lon(lat_lon).map_err(|problem| {
                    bad(
                        file,
                        format!("line {line}, fields `lat_deg,lon_deg` {problem}"),
                    )
                })?;
                Place::LatLon(lat_lon.0, lat_lon.1)
            }
            (None, None) => unreachable_columns(file)?,
        })
    }
}

/// One field of a CSV row as a finite number; `Ok(None)` when empty.
fn number(
    file: &str,
    line: u64,
    record: &csv::StringRecord,
    column: usize,
    name: &str,
) -> Result<Option<f64>, CliError> {
    let text = record.get(column).unwrap_or("").trim();
    if text.is_empty() {
        return Ok(None);
    }
    match text.parse::<f64>() {
        Ok(value) if value.is_finite() => Ok(Some(value)),
        _ => Err(bad(
            file,
            format!("line {line}, field `{name}`: {text:?} is not a finite number"),
        )),
    }
}

/// A required number.
fn required(
    file: &str,
    line: u64,
    record: &csv::StringRecord,
    column: usize,
    name: &str,
) -> Result<f64, CliError> {
    number(file, line, record, column, name)?
        .ok_or_else(|| bad(file, format!("line {line}, field `{name}` is empty")))
}

/// An optional number: `Ok(None)` when the column is absent or the field empty.
fn optional(
    file: &str,
    line: u64,
    record: &csv::StringRecord,
    column: Option<usize>,
    name: &str,
) -> Result<Option<f64>, CliError> {
    column
        .map(|column| number(file, line, record, column, name))
        .transpose()
        .map(Option::flatten)
}

/// A row's navigational status: an AIS code (0-15; 15 "not defined" is no
/// status) or its name ([`NavigationalStatus::name`]); `None` when empty.
fn status(
    file: &str,
    line: u64,
    record: &csv::StringRecord,
    column: Option<usize>,
) -> Result<Option<NavigationalStatus>, CliError> {
    let Some(text) = column.and_then(|column| record.get(column)).map(str::trim) else {
        return Ok(None);
    };
    if text.is_empty() {
        return Ok(None);
    }
    if let Ok(code) = text.parse::<u8>()
        && code <= 15
    {
        return Ok(NavigationalStatus::from_ais(code));
    }
    (0..15)
        .filter_map(NavigationalStatus::from_ais)
        .find(|status| status.name() == text)
        .map(Some)
        .ok_or_else(|| {
            bad(
                file,
                format!(
                    "line {line}, field `status`: {text:?} is neither an AIS navigational status code (0-15) nor a status name (at_anchor, moored, ...)"
                ),
            )
        })
}

/// A row's AIS ship type (0-255); `None` when empty.
fn ship_type(
    file: &str,
    line: u64,
    record: &csv::StringRecord,
    column: Option<usize>,
) -> Result<Option<u8>, CliError> {
    let Some(text) = column.and_then(|column| record.get(column)).map(str::trim) else {
        return Ok(None);
    };
    if text.is_empty() {
        return Ok(None);
    }
    text.parse::<u8>().map(Some).map_err(|_| {
        bad(
            file,
            format!("line {line}, field `ship_type`: {text:?} is not an AIS ship type (0-255)"),
        )
    })
}

/// Reads a tracks CSV: the `trajectory.csv` that `vorrt simulate` writes
/// (`time_s,vessel,east_m,north_m,course_deg,speed_kn[,lat_deg,lon_deg]`),
/// or any CSV with a header naming `vessel`, a time (`time_s` seconds or
/// `time` ISO 8601 UTC) and a position (`east_m,north_m` or
/// `lat_deg,lon_deg`); `course_deg`, `speed_kn`, `length_m`, `status` (AIS
/// navigational status) and `ship_type` (AIS ship type) are optional. A
/// course of 360° or more is AIS's "not available" (3600 in tenths): no
/// course. Columns are found by name; others are ignored.
///
/// # Errors
/// [`CliError::BadInput`] naming the file, the line and the field.
pub(crate) fn read_csv(file: &str, text: &str) -> Result<Tracks, CliError> {
    let mut reader = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let header = reader
        .headers()
        .map_err(|error| bad(file, format!("line 1: {error}")))?
        .clone();
    let columns = Columns::new(file, &header)?;
    let mut collector = Collector::default();
    let mut absolute_times = false;
    let mut courses_not_available = 0usize;
    for record in reader.records() {
        let record = record.map_err(|error| {
            let line = error.position().map_or(0, csv::Position::line);
            bad(file, format!("line {line}: {error}"))
        })?;
        let line = record.position().map_or(0, csv::Position::line);
        let vessel = record.get(columns.vessel).unwrap_or("").trim();
        if vessel.is_empty() {
            return Err(bad(file, format!("line {line}, field `vessel` is empty")));
        }
        let (time_s, absolute) = columns.time_s(file, line, &record)?;
        absolute_times |= absolute;
        let place = columns.place(file, line, &record)?;
        let mut course_deg = optional(file, line, &record, columns.course, "course_deg")?;
        if course_deg.is_some_and(|course| !(0.0..360.0).contains(&course)) {
            // AIS: 360.0 is "not available" (ITU-R M.1371-5, message 1).
            courses_not_available += 1;
            course_deg = None;
        }
        let speed_kn = optional(file, line, &record, columns.speed, "speed_kn")?;
        if let Some(speed_kn) = speed_kn
            && speed_kn < 0.0
        {
            return Err(bad(
                file,
                format!("line {line}, field `speed_kn` is {speed_kn}, expected at least 0"),
            ));
        }
        let length_m = optional(file, line, &record, columns.length, "length_m")?;
        if let Some(length_m) = length_m
            && length_m <= 0.0
        {
            return Err(bad(
                file,
                format!("line {line}, field `length_m` is {length_m}, expected more than 0"),
            ));
        }
        let status = status(file, line, &record, columns.status)?;
        let ship_type = ship_type(file, line, &record, columns.ship_type)?;
        let track = collector.track(vessel);
        if track.length_m.is_none() {
            track.length_m = length_m;
        }
        if track.ship_type.is_none() {
            track.ship_type = ship_type;
        }
        track.fixes.push(Fix {
            time_s,
            place,
            course_deg,
            speed_kn,
            status,
        });
    }
    let mut notes = Vec::new();
    if courses_not_available > 0 {
        notes.push(format!(
            "{courses_not_available} fixes with a course of 360° or more (AIS: not available) have no course"
        ));
    }
    Ok(Tracks {
        format: "csv",
        tracks: collector.into_tracks(),
        absolute_times,
        notes,
    })
}

/// `Columns::new` guarantees a time and a position column; this keeps the
/// match total without a panic.
fn unreachable_columns<T>(file: &str) -> Result<T, CliError> {
    Err(bad(file, "line 1: missing time or position columns"))
}

/// Shifts absolute fix times (Unix seconds) so that the earliest fix is at
/// second 0; returns that instant as ISO 8601 UTC (`None` for relative times).
pub(crate) fn to_relative_times(tracks: &mut Tracks) -> Option<String> {
    if !tracks.absolute_times {
        return None;
    }
    let base = tracks
        .tracks
        .iter()
        .flat_map(|track| &track.fixes)
        .map(|fix| fix.time_s)
        .fold(f64::INFINITY, f64::min);
    if !base.is_finite() {
        return None;
    }
    for fix in tracks.tracks.iter_mut().flat_map(|track| &mut track.fixes) {
        fix.time_s -= base;
    }
    #[expect(
        clippy::cast_possible_truncation,
        reason = "a finite UNIX time in nanoseconds is far inside i128 (and the cast saturates)"
    )]
    let base_ns = (base * 1e9).round() as i128;
    time::OffsetDateTime::from_unix_timestamp_nanos(base_ns)
        .ok()
        .map(vorrt_scenarios::geo::format_utc_time)
}

/// A UTC time as UNIX seconds.
#[allow(clippy::cast_precision_loss)]
pub(crate) fn unix_seconds(time: time::OffsetDateTime) -> f64 {
    time.unix_timestamp_nanos() as f64 / 1e9
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_the_simulate_format_and_names_bad_fields() {
        let text = "time_s,vessel,east_m,north_m,course_deg,speed_kn\n\
                    0,own,0,0,0,10\n0,T1,100,2000,180,8\n5,own,0,25.7,0,10\n";
        let tracks = read_csv("t.csv", text).unwrap();
        assert_eq!(tracks.tracks.len(), 2);
        assert_eq!(tracks.tracks[0].name, "own");
        assert_eq!(tracks.tracks[0].fixes.len(), 2);
        assert_eq!(
            tracks.tracks[0].fixes[1].place,
            Place::Local(DVec2::new(0.0, 25.7))
        );
        let error = read_csv("t.csv", "time_s,vessel,east_m,north_m\n0,own,x,0\n")
            .unwrap_err()
            .to_string();
        assert!(error.contains("t.csv: line 2, field `east_m`"), "{error}");
        let error = read_csv("t.csv", "time_s,vessel\n0,own\n")
            .unwrap_err()
            .to_string();
        assert!(error.contains("no position columns"), "{error}");
        let error = read_csv("t.csv", "time_s,vessel,lat_deg,lon_deg\n0,own,91,0\n")
            .unwrap_err()
            .to_string();
        assert!(
            error.contains("line 2") && error.contains("latitude"),
            "{error}"
        );
    }

    #[test]
    fn reads_status_and_ship_type_and_course_not_available() {
        let text = "time_s,vessel,east_m,north_m,course_deg,status,ship_type\n\
                    0,own,0,0,360,0,70\n5,own,0,1,10,at_anchor,\n10,own,0,2,10,15,\n";
        let tracks = read_csv("t.csv", text).unwrap();
        let own = &tracks.tracks[0];
        assert_eq!(own.ship_type, Some(70));
        assert_eq!(own.fixes[0].course_deg, None);
        assert_eq!(
            own.fixes[0].status,
            Some(NavigationalStatus::UnderWayUsingEngine)
        );
        assert_eq!(own.fixes[1].status, Some(NavigationalStatus::AtAnchor));
        assert_eq!(own.fixes[2].status, None);
        assert!(
            tracks.notes[0].contains("not available"),
            "{:?}",
            tracks.notes
        );
        let error = read_csv(
            "t.csv",
            "time_s,vessel,east_m,north_m,status\n0,own,0,0,docked\n",
        )
        .unwrap_err()
        .to_string();
        assert!(error.contains("line 2, field `status`"), "{error}");
    }

    #[test]
    fn reads_iso_times_as_absolute() {
        let text = "time,vessel,lat_deg,lon_deg\n2024-05-01T12:00:00Z,own,50,-1\n";
        let tracks = read_csv("t.csv", text).unwrap();
        assert!(tracks.absolute_times);
        assert!((tracks.tracks[0].fixes[0].time_s - 1_714_564_800.0).abs() < 1e-6);
    }
}
