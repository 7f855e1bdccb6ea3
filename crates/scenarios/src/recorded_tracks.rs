//! The recorded tracks of a replay scenario (decision 40): the CSV file a
//! scenario names in `recorded_tracks`, read into timed states in the
//! scenario's frame, for its [`Behaviour::Recorded`](crate::Behaviour::Recorded)
//! targets to follow and for the human's track to be judged beside vorrt's.

use crate::error::ScenarioError;
use crate::geo::{LocalFrame, check_lat_lon};
use crate::simulation::TimedState;
use std::collections::BTreeMap;
use vorrt_colregs::VesselState;
use vorrt_geometry::{DVec2, angle, units};

/// Every recorded vessel's states, by vessel name, in time order.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RecordedTracks {
    /// The file they were read from, for messages.
    pub file: String,
    /// Each vessel's recorded states (times in seconds from the run's start,
    /// positions in the scenario's frame), strictly increasing in time.
    pub tracks: BTreeMap<String, Vec<TimedState>>,
}

/// The columns of a tracks CSV, by their index in the header.
struct Columns {
    vessel: usize,
    time_s: usize,
    east_north: Option<(usize, usize)>,
    lat_lon: Option<(usize, usize)>,
    course_deg: Option<usize>,
    speed_kn: Option<usize>,
}

/// A row as read, before the course and speed a row without them is given.
struct Row {
    time_s: f64,
    position_m: DVec2,
    course_rad: Option<f64>,
    speed_mps: Option<f64>,
}

impl RecordedTracks {
    /// Reads the tracks CSV `text` (named `file` in errors): a header with
    /// `vessel`, `time_s` (seconds from the run's start) and either
    /// `east_m,north_m` (a local scenario) or `lat_deg,lon_deg` (a
    /// geographic one, projected with `frame`), and optionally `course_deg`
    /// and `speed_kn` (over ground; else taken from the positions on to the
    /// next row). Only the vessels `length_m` knows (it gives their length)
    /// are kept; the others are skipped.
    ///
    /// # Errors
    /// [`ScenarioError::Invalid`] naming the file, the line and the field:
    /// a missing column, a value not a finite number, a latitude or
    /// longitude out of range, positions of the wrong kind for the scenario,
    /// a vessel's time not after its previous one, a negative speed.
    pub fn from_csv_str(
        text: &str,
        file: &str,
        frame: Option<&LocalFrame>,
        length_m: impl Fn(&str) -> Option<f64>,
    ) -> Result<Self, ScenarioError> {
        let invalid = |field: String, problem: String| ScenarioError::Invalid {
            file: file.to_owned(),
            field,
            problem,
        };
        let mut reader = csv::ReaderBuilder::new()
            .trim(csv::Trim::All)
            .from_reader(text.as_bytes());
        let header = reader
            .headers()
            .map_err(|error| invalid("line 1".into(), format!("is not a CSV header: {error}")))?
            .clone();
        let columns =
            Columns::new(&header, frame.is_some()).map_err(|p| invalid("line 1".into(), p))?;
        let mut rows: BTreeMap<String, Vec<Row>> = BTreeMap::new();
        for (index, record) in reader.records().enumerate() {
            let line = index + 2;
            let record =
                record.map_err(|error| invalid(format!("line {line}"), error.to_string()))?;
            let vessel = record.get(columns.vessel).unwrap_or("").to_owned();
            if length_m(&vessel).is_none() {
                continue;
            }
            let row = columns.row(&record, frame).map_err(|(field, problem)| {
                invalid(format!("line {line}, field `{field}`"), problem)
            })?;
            let rows = rows.entry(vessel.clone()).or_default();
            if let Some(previous) = rows.last()
                && row.time_s <= previous.time_s
            {
                return Err(invalid(
                    format!("line {line}, field `time_s`"),
                    format!(
                        "is {}, not after {} of the row before it of vessel {vessel:?}: each vessel's rows must be in time order",
                        row.time_s, previous.time_s
                    ),
                ));
            }
            rows.push(row);
        }
        let tracks = rows
            .into_iter()
            .map(|(vessel, rows)| {
                let length = length_m(&vessel).unwrap_or(1.0);
                (vessel, timed_states(&rows, length))
            })
            .collect();
        Ok(Self {
            file: file.to_owned(),
            tracks,
        })
    }

    /// The recorded states of `vessel`, if the file has any.
    #[must_use]
    pub fn track(&self, vessel: &str) -> Option<&[TimedState]> {
        self.tracks.get(vessel).map(Vec::as_slice)
    }
}

impl Columns {
    fn new(header: &csv::StringRecord, geographic: bool) -> Result<Self, String> {
        let find = |name: &str| header.iter().position(|column| column == name);
        let pair = |a: &str, b: &str| find(a).zip(find(b));
        let columns = Self {
            vessel: find("vessel").ok_or("has no `vessel` column")?,
            time_s: find("time_s")
                .ok_or("has no `time_s` column (seconds from the run's start)")?,
            east_north: pair("east_m", "north_m"),
            lat_lon: pair("lat_deg", "lon_deg"),
            course_deg: find("course_deg"),
            speed_kn: find("speed_kn"),
        };
        match (
            geographic,
            columns.lat_lon.is_some(),
            columns.east_north.is_some(),
        ) {
            (true, false, _) => Err(
                "has no `lat_deg,lon_deg` columns, which the tracks of a geographic scenario need"
                    .into(),
            ),
            (false, _, false) => Err(
                "has no `east_m,north_m` columns, which the tracks of a local scenario need".into(),
            ),
            _ => Ok(columns),
        }
    }

    /// One row: the time, the position in the scenario's frame, and the
    /// course and speed when given; `Err((field, problem))`.
    fn row(
        &self,
        record: &csv::StringRecord,
        frame: Option<&LocalFrame>,
    ) -> Result<Row, (&'static str, String)> {
        let number = |column: usize, name: &'static str| -> Result<f64, (&'static str, String)> {
            let text = record.get(column).unwrap_or("");
            match text.parse::<f64>() {
                Ok(value) if value.is_finite() => Ok(value),
                _ => Err((name, format!("is {text:?}, not a finite number"))),
            }
        };
        let optional = |column: Option<usize>, name: &'static str| {
            column
                .filter(|&column| !record.get(column).unwrap_or("").is_empty())
                .map(|column| number(column, name))
                .transpose()
        };
        let time_s = number(self.time_s, "time_s")?;
        let position_m = match (frame, self.lat_lon, self.east_north) {
            (Some(frame), Some((lat, lon)), _) => {
                let lat_lon = (number(lat, "lat_deg")?, number(lon, "lon_deg")?);
                check_lat_lon(lat_lon).map_err(|problem| ("lat_deg,lon_deg", problem))?;
                frame.to_local_m(lat_lon.0, lat_lon.1)
            }
            (_, _, Some((east, north))) => {
                DVec2::new(number(east, "east_m")?, number(north, "north_m")?)
            }
            // `Columns::new` refuses a header without the scenario's kind.
            _ => return Err(("east_m,north_m", "is missing".into())),
        };
        let speed_kn = optional(self.speed_kn, "speed_kn")?;
        if let Some(speed) = speed_kn
            && speed < 0.0
        {
            return Err(("speed_kn", format!("is {speed}, expected at least 0")));
        }
        Ok(Row {
            time_s,
            position_m,
            course_rad: optional(self.course_deg, "course_deg")?
                .map(|course| angle::normalize_2pi(course.to_radians())),
            speed_mps: speed_kn.map(units::knots_to_mps),
        })
    }
}

/// The timed states of one vessel's rows: a row without a course or speed
/// takes them from its run to the next row (the last from the one before).
fn timed_states(rows: &[Row], length_m: f64) -> Vec<TimedState> {
    rows.iter()
        .enumerate()
        .map(|(index, row)| {
            let run = match (rows.get(index + 1), index.checked_sub(1).map(|i| &rows[i])) {
                (Some(next), _) => Some((row, next)),
                (None, Some(previous)) => Some((previous, row)),
                (None, None) => None,
            };
            let (derived_course, derived_speed) = run.map_or((0.0, 0.0), |(from, to)| {
                let step = to.position_m - from.position_m;
                let course = if step.length() > 0.0 {
                    angle::unit_to_course(step)
                } else {
                    0.0
                };
                (course, step.length() / (to.time_s - from.time_s))
            });
            TimedState {
                time_s: row.time_s,
                vessel: VesselState::new(
                    row.position_m,
                    row.course_rad.unwrap_or(derived_course),
                    row.speed_mps.unwrap_or(derived_speed),
                    length_m,
                ),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn known(name: &str) -> Option<f64> {
        (name != "stranger").then_some(80.0)
    }

    #[test]
    fn reads_local_rows_and_derives_a_missing_course_and_speed() {
        let text = "vessel,time_s,east_m,north_m,course_deg,speed_kn\n\
                    A,0,0,0,,\n\
                    stranger,0,5,5,0,1\n\
                    A,10,100,0,,\n\
                    B,0,0,50,180,2\n";
        let tracks = RecordedTracks::from_csv_str(text, "t.csv", None, known).expect("valid");
        assert_eq!(tracks.tracks.len(), 2, "the stranger is skipped");
        let a = tracks.track("A").expect("A");
        assert_eq!(a.len(), 2);
        assert!((a[0].vessel.course_rad.to_degrees() - 90.0).abs() < 1e-9);
        assert!((a[1].vessel.speed_mps - 10.0).abs() < 1e-9);
        let b = tracks.track("B").expect("B")[0].vessel;
        assert!((b.speed_mps - units::knots_to_mps(2.0)).abs() < 1e-12);
        assert!((b.length_m - 80.0).abs() < 1e-12);
    }

    #[test]
    fn projects_latitude_and_longitude_with_the_frame() {
        let frame = LocalFrame::new(50.0, -1.0);
        let text = "vessel,time_s,lat_deg,lon_deg,course_deg,speed_kn\nA,0,50.01,-1.0,0,5\n";
        let tracks =
            RecordedTracks::from_csv_str(text, "t.csv", Some(&frame), known).expect("valid");
        let north_m = tracks.track("A").expect("A")[0].vessel.position_m.y;
        assert!((north_m - 1112.0).abs() < 5.0, "{north_m}");
    }

    #[test]
    fn bad_rows_are_named_by_file_line_and_field() {
        let cases = [
            ("vessel,east_m,north_m\nA,0,0\n", "line 1", "time_s"),
            (
                "vessel,time_s,lat_deg,lon_deg\nA,0,0,0\n",
                "line 1",
                "east_m,north_m",
            ),
            (
                "vessel,time_s,east_m,north_m\nA,0,0,x\n",
                "line 2, field `north_m`",
                "\"x\"",
            ),
            (
                "vessel,time_s,east_m,north_m\nA,5,0,0\nA,5,1,0\n",
                "line 3, field `time_s`",
                "time order",
            ),
            (
                "vessel,time_s,east_m,north_m,speed_kn\nA,0,0,0,-1\n",
                "line 2, field `speed_kn`",
                "at least 0",
            ),
        ];
        for (text, field, problem) in cases {
            let error = RecordedTracks::from_csv_str(text, "t.csv", None, known)
                .expect_err(text)
                .to_string();
            assert!(error.starts_with(&format!("t.csv: {field} ")), "{error}");
            assert!(error.contains(problem), "{error}");
        }
    }
}
