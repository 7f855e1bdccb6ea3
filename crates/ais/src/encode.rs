//! AIS out: a run written as NMEA 0183 `!AIVDM`/`!AIVDO` sentences behind
//! NMEA 4.10 tag blocks (`\c:<UNIX seconds>*hh\`), which a chart plotter's
//! replay (`OpenCPN`'s VDR plugin, for one) and [`crate::read_log`] read back.
//!
//! Per vessel per recorded step one message type 1 (position report class
//! A: ITU-R M.1371-5, annex 8, table 46), and at the start and every
//! [`STATIC_INTERVAL_S`] one message type 5 (static and voyage related data,
//! table 52) with the vessel's name and length. Payloads are 6-bit armoured
//! (annex 8, 3.3.7), split into sentences of at most [`MAX_PAYLOAD_CHARS`]
//! characters (IEC 61162-1: 82 characters a sentence) with their fill bits
//! and checksum. Decision 39.

use crate::tag_block::nmea_checksum;
use thiserror::Error;
use vorrt_geometry::{angle, units};
use vorrt_scenarios::colregs::VesselState;
use vorrt_scenarios::{LocalFrame, Scenario, SimulationRecord};

/// Seconds between the type 5 messages of a vessel: ITU-R M.1371-5 sends
/// static data every 6 minutes.
pub const STATIC_INTERVAL_S: f64 = 360.0;

/// The most payload characters in one sentence: 82 characters less the
/// envelope `!AIVDM,n,m,s,A,` and `,f*hh` (IEC 61162-1).
pub const MAX_PAYLOAD_CHARS: usize = 60;

/// The MMSI given to ownship when its spec has none; target `i` (from 0)
/// without one gets this plus `i + 1`. ITU-R M.585 assigns no ship MMSIs
/// beginning with 9 below 970, so these name no real ship.
pub const SYNTHETIC_MMSI_BASE: u32 = 900_000_000;

/// The largest MMSI (nine digits).
const MAX_MMSI: u32 = 999_999_999;

/// Why a run could not be written as AIS.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum EncodeError {
    /// An MMSI of more than nine digits.
    #[error("vessel {vessel}: MMSI {mmsi} has more than nine digits")]
    Mmsi {
        /// The vessel's name.
        vessel: String,
        /// Its MMSI.
        mmsi: u32,
    },
    /// Two vessels with one MMSI: a replay would merge them.
    #[error("vessels {first} and {second} both have MMSI {mmsi}")]
    DuplicateMmsi {
        /// The first vessel's name.
        first: String,
        /// The second vessel's name.
        second: String,
        /// The MMSI.
        mmsi: u32,
    },
    /// A position, course, speed or time that is not a finite number, or a
    /// position off the globe.
    #[error("vessel {vessel} at {time_s} s: {problem}")]
    Value {
        /// The vessel's name.
        vessel: String,
        /// The run's time, seconds.
        time_s: f64,
        /// What is wrong.
        problem: String,
    },
}

/// One position report (message type 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PositionFix {
    /// The vessel's MMSI.
    pub mmsi: u32,
    /// Latitude, degrees.
    pub lat_deg: f64,
    /// Longitude, degrees.
    pub lon_deg: f64,
    /// Course over ground, degrees (`None`: not available).
    pub course_deg: Option<f64>,
    /// Speed over ground, knots (`None`: not available).
    pub speed_kn: Option<f64>,
    /// True heading, degrees (`None`: not available).
    pub heading_deg: Option<f64>,
    /// The UTC second of the fix, 0-59 (`None`: not available).
    pub utc_second: Option<u8>,
}

/// A vessel's static data (message type 5).
#[derive(Debug, Clone, PartialEq)]
pub struct StaticData {
    /// The vessel's MMSI.
    pub mmsi: u32,
    /// Its name: upper-cased, characters outside the AIS six-bit set become
    /// spaces, cut to 20 characters.
    pub name: String,
    /// Its length overall, metres (split half to the bow, half to the
    /// stern of the reference point; 511 m at most each way).
    pub length_m: Option<f64>,
}

/// Bits of a payload, most significant first.
#[derive(Debug, Default)]
struct Bits(Vec<bool>);

impl Bits {
    /// Appends the low `width` bits of `value`.
    fn push(&mut self, value: u64, width: u32) {
        for bit in (0..width).rev() {
            self.0.push((value >> bit) & 1 == 1);
        }
    }

    /// Appends `value` as a `width`-bit two's complement number.
    fn push_signed(&mut self, value: i64, width: u32) {
        self.push(value.cast_unsigned() & ((1 << width) - 1), width);
    }

    /// Appends `text` as `chars` six-bit characters, padded with `@`.
    fn push_text(&mut self, text: &str, chars: usize) {
        let mut codes: Vec<u64> = text.chars().take(chars).map(six_bit_code).collect();
        codes.resize(chars, 0);
        for code in codes {
            self.push(code, 6);
        }
    }

    /// The armoured payload and its fill bits.
    fn armour(&self) -> (String, u8) {
        let fill = (6 - self.0.len() % 6) % 6;
        let mut payload = String::with_capacity(self.0.len().div_ceil(6));
        for chunk in self.0.chunks(6) {
            let mut value = 0u8;
            for index in 0..6 {
                value = (value << 1) | u8::from(chunk.get(index).copied().unwrap_or(false));
            }
            // ITU-R M.1371-5 annex 8, table 47: 0-39 as '0'-'W', 40-63 as '`'-'w'.
            payload.push(char::from(if value < 40 { value + 48 } else { value + 56 }));
        }
        #[expect(clippy::cast_possible_truncation, reason = "0-5 fill bits")]
        (payload, fill as u8)
    }
}

/// The six-bit code of a character (annex 8, table 47): `@`-`_` are 0-31,
/// space-`?` are 32-63; lower case is upper-cased, anything else a space.
fn six_bit_code(c: char) -> u64 {
    let c = c.to_ascii_uppercase();
    match u64::from(u32::from(c)) {
        code @ 64..=95 => code - 64,
        code @ 32..=63 => code,
        _ => 32,
    }
}

/// `value` scaled by `scale` and rounded, or `missing` when `None`.
#[expect(
    clippy::cast_possible_truncation,
    reason = "values checked in range, a few thousand at most"
)]
fn scaled(value: Option<f64>, scale: f64, missing: i64) -> i64 {
    value.map_or(missing, |value| (value * scale).round() as i64)
}

/// The armoured payload of a type 1 message, and its fill bits.
#[must_use]
pub fn position_report_payload(fix: &PositionFix) -> (String, u8) {
    let mut bits = Bits::default();
    bits.push(1, 6); // message type
    bits.push(0, 2); // repeat indicator
    bits.push(u64::from(fix.mmsi), 30);
    bits.push(0, 4); // navigational status: under way using engine
    bits.push_signed(-128, 8); // rate of turn: not available
    let speed = fix.speed_kn.map(|speed| speed.clamp(0.0, 102.2));
    bits.push(scaled(speed, 10.0, 1023).cast_unsigned(), 10);
    bits.push(0, 1); // position accuracy: low (> 10 m)
    // 1/10000 minute; 181 degrees and 91 degrees: not available.
    bits.push_signed(scaled(Some(fix.lon_deg), 600_000.0, 0), 28);
    bits.push_signed(scaled(Some(fix.lat_deg), 600_000.0, 0), 27);
    let course = fix
        .course_deg
        .map(|course| (course * 10.0).round().rem_euclid(3600.0) / 10.0);
    bits.push(scaled(course, 10.0, 3600).cast_unsigned(), 12);
    let heading = fix
        .heading_deg
        .map(|heading| heading.round().rem_euclid(360.0));
    bits.push(scaled(heading, 1.0, 511).cast_unsigned(), 9);
    bits.push(
        u64::from(fix.utc_second.filter(|s| *s < 60).unwrap_or(60)),
        6,
    );
    bits.push(0, 2); // special manoeuvre indicator: not available
    bits.push(0, 3); // spare
    bits.push(0, 1); // RAIM not in use
    bits.push(0, 19); // radio status
    bits.armour()
}

/// The armoured payload of a type 5 message, and its fill bits.
#[must_use]
pub fn static_data_payload(data: &StaticData) -> (String, u8) {
    let mut bits = Bits::default();
    bits.push(5, 6); // message type
    bits.push(0, 2); // repeat indicator
    bits.push(u64::from(data.mmsi), 30);
    bits.push(0, 2); // AIS version: ITU-R M.1371-1
    bits.push(0, 30); // IMO number: not available
    bits.push_text("", 7); // call sign: not available
    bits.push_text(&data.name, 20);
    bits.push(0, 8); // type of ship: not available
    let length = data
        .length_m
        .map_or(0.0, |length| length.clamp(0.0, 1022.0));
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "clamped to 0-1022 m"
    )]
    let (bow, stern) = {
        let bow = (length / 2.0).round() as u64;
        (
            bow.min(511),
            ((length.round() as u64).saturating_sub(bow)).min(511),
        )
    };
    bits.push(bow, 9);
    bits.push(stern, 9);
    bits.push(0, 6); // to port: not available
    bits.push(0, 6); // to starboard
    bits.push(0, 4); // position fixing device: undefined
    bits.push(0, 4); // ETA month: not available
    bits.push(0, 5); // ETA day
    bits.push(24, 5); // ETA hour
    bits.push(60, 6); // ETA minute
    bits.push(0, 8); // draught: not available
    bits.push_text("", 20); // destination: not available
    bits.push(0, 1); // data terminal ready
    bits.push(0, 1); // spare
    bits.armour()
}

/// The sentences of one message: `!AIVDO` for ownship's own reports, else
/// `!AIVDM`, on channel A; a message longer than [`MAX_PAYLOAD_CHARS`] is
/// split with the sequential message id `sequence_id` (0-9).
#[must_use]
pub fn sentences(payload: &str, fill_bits: u8, own: bool, sequence_id: u8) -> Vec<String> {
    let talker = if own { "AIVDO" } else { "AIVDM" };
    let parts: Vec<&str> = if payload.is_empty() {
        vec![""]
    } else {
        payload
            .as_bytes()
            .chunks(MAX_PAYLOAD_CHARS)
            .map(|chunk| std::str::from_utf8(chunk).unwrap_or_default())
            .collect()
    };
    let count = parts.len();
    let id = if count > 1 {
        (sequence_id % 10).to_string()
    } else {
        String::new()
    };
    parts
        .iter()
        .enumerate()
        .map(|(index, part)| {
            let fill = if index + 1 == count { fill_bits } else { 0 };
            let body = format!("{talker},{count},{},{id},A,{part},{fill}", index + 1);
            format!("!{body}*{:02X}", nmea_checksum(&body))
        })
        .collect()
}

/// An NMEA 4.10 tag block of the given fields (`c:1700000000`,
/// `g:1-2-7`), with its checksum.
#[must_use]
pub fn tag_block(fields: &[String]) -> String {
    let body = fields.join(",");
    format!("\\{body}*{:02X}\\", nmea_checksum(&body))
}

/// The MMSI of every vessel of `scenario`, ownship first: the spec's, else
/// a synthetic one ([`SYNTHETIC_MMSI_BASE`]).
///
/// # Errors
/// [`EncodeError::Mmsi`] for an MMSI of more than nine digits,
/// [`EncodeError::DuplicateMmsi`] when two vessels share one.
pub fn mmsis(scenario: &Scenario) -> Result<Vec<u32>, EncodeError> {
    let vessels = std::iter::once(&scenario.ownship).chain(&scenario.targets);
    let mut seen: Vec<(u32, &str)> = Vec::new();
    for (index, spec) in vessels.enumerate() {
        let synthetic = u32::try_from(index)
            .ok()
            .and_then(|index| SYNTHETIC_MMSI_BASE.checked_add(index))
            .unwrap_or(MAX_MMSI);
        let mmsi = spec.mmsi.unwrap_or(synthetic);
        if mmsi > MAX_MMSI {
            return Err(EncodeError::Mmsi {
                vessel: spec.name.clone(),
                mmsi,
            });
        }
        if let Some((_, first)) = seen.iter().find(|(other, _)| *other == mmsi) {
            return Err(EncodeError::DuplicateMmsi {
                first: (*first).to_owned(),
                second: spec.name.clone(),
                mmsi,
            });
        }
        seen.push((mmsi, &spec.name));
    }
    Ok(seen.into_iter().map(|(mmsi, _)| mmsi).collect())
}

/// The whole run as an AIS log: at every recorded step, a tag block with
/// the time (`start_unix_s` plus the run's time, whole seconds) and a type 1
/// report per vessel, ownship first as `!AIVDO`; before the first report of
/// each vessel and every [`STATIC_INTERVAL_S`] after, its type 5. Positions
/// go through `frame` (the scenario's own for a geographic run; a frame
/// placed by the caller for a local one).
///
/// # Errors
/// [`EncodeError`] for a bad MMSI, or a state that is not a finite number or
/// falls off the globe.
pub fn simulation_log(
    scenario: &Scenario,
    record: &SimulationRecord,
    frame: &LocalFrame,
    start_unix_s: f64,
) -> Result<String, EncodeError> {
    let mmsis = mmsis(scenario)?;
    let vessels: Vec<(&str, Option<f64>, &[VesselState])> =
        std::iter::once((&scenario.ownship, record.ownship.as_slice()))
            .chain(
                scenario
                    .targets
                    .iter()
                    .zip(record.targets.iter().map(Vec::as_slice)),
            )
            .map(|(spec, states)| (spec.name.as_str(), Some(spec.length_m), states))
            .collect();
    let mut log = String::new();
    let mut sequence_id = 0u8;
    let mut next_static_s = 0.0;
    for (step, &time_s) in record.times_s.iter().enumerate() {
        let time_unix_s = (start_unix_s + time_s).round();
        if !time_unix_s.is_finite() || time_unix_s < 0.0 {
            return Err(EncodeError::Value {
                vessel: scenario.ownship.name.clone(),
                time_s,
                problem: format!("time {time_unix_s} is not a UNIX time"),
            });
        }
        let statics = time_s >= next_static_s;
        if statics {
            next_static_s = time_s + STATIC_INTERVAL_S;
        }
        for (index, ((name, length_m, states), &mmsi)) in vessels.iter().zip(&mmsis).enumerate() {
            let Some(state) = states.get(step) else {
                continue;
            };
            let own = index == 0;
            if statics {
                let data = StaticData {
                    mmsi,
                    name: (*name).to_owned(),
                    length_m: *length_m,
                };
                let (payload, fill) = static_data_payload(&data);
                push_message(&mut log, &payload, fill, own, sequence_id, time_unix_s);
                sequence_id = (sequence_id + 1) % 10;
            }
            let fix =
                fix(mmsi, state, frame, time_unix_s).map_err(|problem| EncodeError::Value {
                    vessel: (*name).to_owned(),
                    time_s,
                    problem,
                })?;
            let (payload, fill) = position_report_payload(&fix);
            push_message(&mut log, &payload, fill, own, sequence_id, time_unix_s);
        }
    }
    Ok(log)
}

/// The position report of `state` at `time_unix_s`.
fn fix(
    mmsi: u32,
    state: &VesselState,
    frame: &LocalFrame,
    time_unix_s: f64,
) -> Result<PositionFix, String> {
    let (lat_deg, lon_deg) = frame.to_lat_lon_deg(state.position_m);
    if !((-90.0..=90.0).contains(&lat_deg) && (-180.0..=180.0).contains(&lon_deg)) {
        return Err(format!("position ({lat_deg}, {lon_deg}) is off the globe"));
    }
    let course_deg = angle::normalize_2pi(state.course_rad).to_degrees();
    let speed_kn = units::mps_to_knots(state.speed_mps);
    if !(course_deg.is_finite() && speed_kn.is_finite() && speed_kn >= 0.0) {
        return Err(format!(
            "course {course_deg} deg or speed {speed_kn} kn is not a finite number"
        ));
    }
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a second of the minute, 0-59"
    )]
    let utc_second = time_unix_s.rem_euclid(60.0) as u8;
    Ok(PositionFix {
        mmsi,
        lat_deg,
        lon_deg,
        course_deg: Some(course_deg),
        speed_kn: Some(speed_kn),
        heading_deg: Some(course_deg),
        utc_second: Some(utc_second),
    })
}

/// Appends one message's sentences, each behind a tag block: the first
/// with the time, and the sentences of a multi-sentence message grouped
/// (`g:<n>-<count>-<id>`, NMEA 4.10).
fn push_message(
    log: &mut String,
    payload: &str,
    fill: u8,
    own: bool,
    sequence_id: u8,
    time_unix_s: f64,
) {
    let parts = sentences(payload, fill, own, sequence_id);
    let count = parts.len();
    for (index, sentence) in parts.iter().enumerate() {
        let mut fields = Vec::new();
        if index == 0 {
            fields.push(format!("c:{time_unix_s:.0}"));
        }
        if count > 1 {
            fields.push(format!(
                "g:{}-{count}-{}",
                index + 1,
                u32::from(sequence_id) + 1
            ));
        }
        log.push_str(&tag_block(&fields));
        log.push_str(sentence);
        log.push_str("\r\n");
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::read_log;

    /// gpsd's AIVDM documentation decodes this type 1 sentence; ours for
    /// the same fix reads back to the same values, and matches it bit for
    /// bit where the two agree on what they say (not status, rate of turn,
    /// manoeuvre, RAIM or radio).
    #[test]
    fn position_report_matches_a_known_sentence() {
        let known = read_log("!AIVDM,1,1,,B,177KQJ5000G?tO`K>RA1wUbN0TKH,0*5C");
        assert_eq!(known.counts.messages, 1, "{:?}", known.counts);
        let reference = known.vessels[&477_553_000].reports[0];
        let fix = PositionFix {
            mmsi: 477_553_000,
            // The sentence's own integers (1/10000 minute): the reader's
            // f32 would round the last unit.
            lat_deg: 28_549_700.0 / 600_000.0,
            lon_deg: -73_407_500.0 / 600_000.0,
            course_deg: reference.course_deg,
            speed_kn: reference.speed_kn,
            heading_deg: reference.heading_deg,
            utc_second: Some(15),
        };
        let (payload, fill) = position_report_payload(&fix);
        assert_eq!((payload.len(), fill), (28, 0));
        let log = read_log(&sentences(&payload, fill, false, 0).join("\n"));
        let report = log.vessels[&477_553_000].reports[0];
        assert!((report.lat_deg - 47.582_833).abs() < 1e-5, "{report:?}");
        assert!((report.lon_deg + 122.345_833).abs() < 1e-5, "{report:?}");
        assert_eq!(report.course_deg, Some(51.0));
        assert_eq!(report.heading_deg, Some(181.0));
        assert_eq!(report.speed_kn, Some(0.0));
        // Type, repeat and MMSI (the first 38 bits: 6 characters and 2 bits).
        assert_eq!(&payload[..6], "177KQJ");
        // Speed to heading and second (bits 50-142): characters 9-22 whole.
        assert_eq!(&payload[9..23], "0G?tO`K>RA1wUb");
    }

    #[test]
    fn armour_and_checksum() {
        let mut bits = Bits::default();
        bits.push(0, 6);
        bits.push(39, 6);
        bits.push(40, 6);
        bits.push(63, 6);
        bits.push(1, 2);
        assert_eq!(bits.armour(), ("0W`w@".to_owned(), 4));
        let sentence = &sentences("0W`w@", 4, true, 0)[0];
        let checksum = nmea_checksum("AIVDO,1,1,,A,0W`w@,4");
        assert_eq!(*sentence, format!("!AIVDO,1,1,,A,0W`w@,4*{checksum:02X}"));
        assert_eq!(six_bit_code('a'), 1);
        assert_eq!(six_bit_code('é'), 32);
    }

    #[test]
    fn static_data_splits_and_reads_back() {
        let data = StaticData {
            mmsi: 235_000_001,
            name: "Northern spirit".to_owned(),
            length_m: Some(183.0),
        };
        let (payload, fill) = static_data_payload(&data);
        assert_eq!((payload.len(), fill), (71, 2));
        let parts = sentences(&payload, fill, false, 3);
        assert_eq!(parts.len(), 2);
        assert!(parts.iter().all(|part| part.len() <= 82));
        assert!(parts[0].starts_with("!AIVDM,2,1,3,A,") && parts[1].starts_with("!AIVDM,2,2,3,A,"));
        let log = read_log(&parts.join("\n"));
        let track = &log.vessels[&235_000_001];
        assert_eq!(track.name.as_deref(), Some("NORTHERN SPIRIT"));
        assert_eq!(track.length_m, Some(183.0));
    }

    #[test]
    fn tag_block_reads_back() {
        let block = tag_block(&["c:1700000000".to_owned(), "g:1-2-4".to_owned()]);
        let line = format!("{block}!AIVDM");
        let (tag, rest) = crate::split_tag_block(&line).unwrap();
        assert_eq!(tag.unwrap().time_unix_s, Some(1_700_000_000.0));
        assert_eq!(rest, "!AIVDM");
    }
}
