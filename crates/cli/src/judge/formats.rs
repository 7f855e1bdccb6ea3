//! The other track formats: `GeoJSON` `LineStrings` with per-point times, and
//! AIS logs (read by `vorrt-ais`).

use crate::error::CliError;
use crate::judge::tracks::{Collector, Fix, Place, Tracks, bad, unix_seconds};
use geojson::{Feature, GeoJson, GeometryValue, JsonObject, JsonValue};

/// The time of one point as a `GeoJSON` property gives it: a number of
/// seconds, or an ISO 8601 string (absolute).
fn point_time(file: &str, where_: &str, value: &JsonValue) -> Result<(f64, bool), CliError> {
    match value {
        JsonValue::Number(number) => number
            .as_f64()
            .filter(|time_s| time_s.is_finite())
            .map(|time_s| (time_s, false))
            .ok_or_else(|| bad(file, format!("{where_}: {number} is not a finite number"))),
        JsonValue::String(text) => vorrt_scenarios::geo::parse_utc_time(text)
            .map(|time| (unix_seconds(time), true))
            .map_err(|problem| bad(file, format!("{where_} {problem}"))),
        other => Err(bad(
            file,
            format!("{where_}: {other} is neither seconds nor an ISO 8601 time"),
        )),
    }
}

/// The per-point times of a feature: `times_s` (seconds), else `coordTimes`
/// or `times` (ISO 8601 strings or seconds), flattened for a
/// `MultiLineString` whose times are nested per line.
fn feature_times(
    file: &str,
    label: &str,
    properties: &JsonObject,
) -> Result<(Vec<f64>, bool), CliError> {
    let Some((key, value)) = ["times_s", "coordTimes", "times"]
        .iter()
        .find_map(|key| properties.get(*key).map(|value| (*key, value)))
    else {
        return Err(bad(
            file,
            format!("{label}: no per-point times (a `times_s`, `coordTimes` or `times` property)"),
        ));
    };
    let mut flat = Vec::new();
    let mut stack = vec![value];
    // Depth-first, in order: nested arrays (MultiLineString) flatten.
    while let Some(value) = stack.pop() {
        match value {
            JsonValue::Array(items) => stack.extend(items.iter().rev()),
            other => flat.push(other),
        }
    }
    let mut absolute = None;
    let mut point_times = Vec::with_capacity(flat.len());
    for (index, value) in flat.into_iter().enumerate() {
        let (time_s, is_absolute) =
            point_time(file, &format!("{label}, property `{key}`[{index}]"), value)?;
        if *absolute.get_or_insert(is_absolute) != is_absolute {
            return Err(bad(
                file,
                format!("{label}, property `{key}` mixes ISO 8601 times and numbers"),
            ));
        }
        point_times.push(time_s);
    }
    Ok((point_times, absolute.unwrap_or(false)))
}

/// A feature's label for messages: its index and name.
fn label(index: usize, name: &str) -> String {
    format!("feature {index} ({name:?})")
}

/// The features of a `GeoJSON` text: those of a `FeatureCollection`, or the one Feature.
fn geojson_features(file: &str, text: &str) -> Result<Vec<Feature>, CliError> {
    let geojson: GeoJson = text
        .parse()
        .map_err(|error| bad(file, format!("not GeoJSON: {error}")))?;
    match geojson {
        GeoJson::FeatureCollection(collection) => Ok(collection.features),
        GeoJson::Feature(feature) => Ok(vec![feature]),
        GeoJson::Geometry(_) => Err(bad(
            file,
            "a bare geometry has no times: expected Features with a `times_s` or `coordTimes` property",
        )),
    }
}

/// A feature's `length_m` property, metres (`None` when absent or null).
fn feature_length_m(
    file: &str,
    label: &str,
    properties: &JsonObject,
) -> Result<Option<f64>, CliError> {
    match properties.get("length_m") {
        None | Some(JsonValue::Null) => Ok(None),
        Some(value) => value
            .as_f64()
            .filter(|length_m| length_m.is_finite() && *length_m > 0.0)
            .map(Some)
            .ok_or_else(|| {
                bad(
                    file,
                    format!("{label}, property `length_m`: {value} is not a length in metres greater than 0"),
                )
            }),
    }
}

/// A feature's points (`[longitude, latitude]`, checked) with their times, as fixes.
fn lat_lon_fixes(
    file: &str,
    label: &str,
    points: &[&geojson::Position],
    times: Vec<f64>,
) -> Result<Vec<Fix>, CliError> {
    let mut fixes = Vec::with_capacity(points.len());
    for (point_index, (point, time_s)) in points.iter().zip(times).enumerate() {
        let (Some(lon_deg), Some(lat_deg)) = (point.as_slice().first(), point.as_slice().get(1))
        else {
            return Err(bad(
                file,
                format!("{label}, coordinates[{point_index}] has fewer than 2 numbers"),
            ));
        };
        vorrt_scenarios::geo::check_lat_lon((*lat_deg, *lon_deg)).map_err(|problem| {
            bad(
                file,
                format!("{label}, coordinates[{point_index}] [longitude, latitude] {problem}"),
            )
        })?;
        fixes.push(Fix {
            time_s,
            place: Place::LatLon(*lat_deg, *lon_deg),
            course_deg: None,
            speed_kn: None,
            status: None,
        });
    }
    Ok(fixes)
}

/// Reads `GeoJSON`: a `FeatureCollection` (or one Feature) of `LineStrings` or
/// `MultiLineStrings`, one per vessel, with per-point times (see
/// [`feature_times`]); `name` (else `vessel`, else `feature N`), optional
/// `length_m`, `mmsi` and `role` (`ownship` marks the recording vessel).
/// Other features (points, the closest approaches vorrt writes) are
/// skipped. Coordinates are `[longitude, latitude]` (RFC 7946).
///
/// # Errors
/// [`CliError::BadInput`] naming the file, the feature and the property.
pub(crate) fn read_geojson(file: &str, text: &str) -> Result<Tracks, CliError> {
    let features = geojson_features(file, text)?;
    let mut collector = Collector::default();
    let mut absolute_times = None;
    let mut notes = Vec::new();
    for (index, feature) in features.iter().enumerate() {
        let lines: Vec<&Vec<geojson::Position>> = match feature.geometry.as_ref().map(|g| &g.value)
        {
            Some(GeometryValue::LineString { coordinates }) => vec![coordinates],
            Some(GeometryValue::MultiLineString { coordinates }) => coordinates.iter().collect(),
            _ => continue,
        };
        let empty = JsonObject::new();
        let properties = feature.properties.as_ref().unwrap_or(&empty);
        let name = properties
            .get("name")
            .or_else(|| properties.get("vessel"))
            .and_then(JsonValue::as_str)
            .map_or_else(|| format!("feature {index}"), str::to_owned);
        let label = label(index, &name);
        let (times, absolute) = feature_times(file, &label, properties)?;
        let points: Vec<&geojson::Position> = lines.into_iter().flatten().collect();
        if times.len() != points.len() {
            return Err(bad(
                file,
                format!("{label}: {} times for {} points", times.len(), points.len()),
            ));
        }
        if *absolute_times.get_or_insert(absolute) != absolute {
            return Err(bad(
                file,
                format!("{label}: ISO 8601 times in some features and seconds in others"),
            ));
        }
        let length_m = feature_length_m(file, &label, properties)?;
        let mmsi = properties
            .get("mmsi")
            .and_then(JsonValue::as_u64)
            .and_then(|mmsi| u32::try_from(mmsi).ok());
        let marked_ownship = properties.get("role").and_then(JsonValue::as_str) == Some("ownship");
        let track = collector.track(&name);
        if !track.fixes.is_empty() {
            notes.push(format!(
                "{label}: a second line of vessel {name:?}, joined to the first"
            ));
        }
        track.length_m = track.length_m.or(length_m);
        track.mmsi = track.mmsi.or(mmsi);
        track.marked_ownship |= marked_ownship;
        track
            .fixes
            .extend(lat_lon_fixes(file, &label, &points, times)?);
    }
    let tracks = collector.into_tracks();
    if tracks.is_empty() {
        return Err(bad(file, "no LineString or MultiLineString features"));
    }
    Ok(Tracks {
        format: "geojson",
        tracks,
        absolute_times: absolute_times.unwrap_or(false),
        notes,
    })
}

/// Reads an AIS log (NMEA 0183 `!AIVDM`/`!AIVDO` with NMEA 4.0 tag-block
/// times) with `vorrt-ais`: one track per MMSI, named by its static report
/// (else `MMSI <n>`), with its reported length, course and speed over
/// ground. Reports without a time (no tag block before them) are left out
/// and counted.
///
/// # Errors
/// [`CliError::BadInput`] when the log holds no timed position report.
pub(crate) fn read_ais(file: &str, text: &str) -> Result<Tracks, CliError> {
    let log = vorrt_ais::read_log(text);
    let mut collector = Collector::default();
    let mut untimed = 0usize;
    for vessel in log.vessels.values() {
        let name = vessel
            .name
            .clone()
            .filter(|name| !name.is_empty())
            .unwrap_or_else(|| format!("MMSI {}", vessel.mmsi));
        let name = if collector.contains(&name) {
            format!("{name} (MMSI {})", vessel.mmsi)
        } else {
            name
        };
        let fixes: Vec<Fix> = vessel
            .reports
            .iter()
            .filter_map(|report| {
                let Some(time_s) = report.time_unix_s else {
                    untimed += 1;
                    return None;
                };
                Some(Fix {
                    time_s,
                    place: Place::LatLon(report.lat_deg, report.lon_deg),
                    course_deg: report.course_deg,
                    speed_kn: report.speed_kn,
                    status: report
                        .navigational_status
                        .and_then(vorrt_colregs::observed::NavigationalStatus::from_ais),
                })
            })
            .collect();
        if fixes.is_empty() {
            continue;
        }
        let track = collector.track(&name);
        track.mmsi = Some(vessel.mmsi);
        track.length_m = vessel.length_m;
        track.marked_ownship = vessel.own_vessel;
        track.fixes = fixes;
    }
    let counts = log.counts;
    let mut notes = vec![format!(
        "{} lines: {} messages used, {} skipped (malformed, bad checksum or unused type)",
        counts.lines,
        counts.messages,
        counts.skipped()
    )];
    if untimed > 0 {
        notes.push(format!(
            "{untimed} position reports without a time (no tag block before them) left out"
        ));
    }
    let tracks = collector.into_tracks();
    if tracks.is_empty() {
        return Err(bad(
            file,
            "no timed position report: AIS logs need NMEA 4.0 tag blocks (\\c:UNIXTIME*hh\\) for the times",
        ));
    }
    Ok(Tracks {
        format: "ais",
        tracks,
        absolute_times: true,
        notes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_linestrings_with_coord_times() {
        let text = r#"{"type":"FeatureCollection","features":[
            {"type":"Feature","properties":{"name":"own","role":"ownship","length_m":80,
             "coordTimes":["2024-05-01T12:00:00Z","2024-05-01T12:00:10Z"]},
             "geometry":{"type":"LineString","coordinates":[[-1.0,50.0],[-1.0,50.001]]}},
            {"type":"Feature","properties":{"kind":"closest_approach"},
             "geometry":{"type":"Point","coordinates":[-1.0,50.0]}}]}"#;
        let tracks = read_geojson("t.geojson", text).unwrap();
        assert!(tracks.absolute_times);
        assert_eq!(tracks.tracks.len(), 1);
        let own = &tracks.tracks[0];
        assert!(own.marked_ownship);
        assert_eq!(own.length_m, Some(80.0));
        assert!((own.fixes[1].time_s - own.fixes[0].time_s - 10.0).abs() < 1e-9);
        assert_eq!(own.fixes[1].place, Place::LatLon(50.001, -1.0));
    }

    #[test]
    fn names_the_feature_and_property_at_fault() {
        let text = r#"{"type":"Feature","properties":{"name":"own","times_s":[0]},
            "geometry":{"type":"LineString","coordinates":[[-1.0,50.0],[-1.0,50.001]]}}"#;
        let error = read_geojson("t.geojson", text).unwrap_err().to_string();
        assert!(
            error.contains("feature 0 (\"own\"): 1 times for 2 points"),
            "{error}"
        );
        let text = r#"{"type":"Feature","properties":{"name":"own"},
            "geometry":{"type":"LineString","coordinates":[[-1.0,50.0]]}}"#;
        let error = read_geojson("t.geojson", text).unwrap_err().to_string();
        assert!(error.contains("no per-point times"), "{error}");
        let error = read_geojson("t.geojson", "{not json")
            .unwrap_err()
            .to_string();
        assert!(error.contains("not GeoJSON"), "{error}");
    }

    #[test]
    fn reads_an_ais_log_with_tag_block_times() {
        #![expect(clippy::float_cmp, reason = "a whole-second tag block time, exact")]
        let text = "\\c:1700000000*5F\\!AIVDM,1,1,,A,13u?etgP2;0n9lPPwT`1U1B1P000,0*4F\n";
        let tracks = read_ais("t.nmea", text).unwrap();
        assert_eq!(tracks.tracks.len(), 1);
        assert_eq!(tracks.tracks[0].mmsi, Some(265_547_250));
        assert_eq!(tracks.tracks[0].fixes[0].time_s, 1_700_000_000.0);
        let error = read_ais("t.nmea", "garbage\n").unwrap_err().to_string();
        assert!(error.contains("no timed position report"), "{error}");
    }
}
