//! Reading an AIS log: lines of NMEA 0183 `!AIVDM`/`!AIVDO` sentences, each
//! perhaps behind an NMEA 4.0 tag block, into per-vessel tracks.
//!
//! The `ais` crate checks each sentence's checksum, reassembles multi-sentence
//! messages and decodes the payloads; this module adds the tag blocks
//! ([`crate::tag_block`]), keeps the position reports and static data of
//! message types 1, 2, 3, 5, 18, 19 and 24, and counts every line it skips.
//! Before a fragment reaches the crate its sequence is checked here (number
//! from 1 to the count, each the one after the last): the crate's own check
//! subtracts fragment numbers as `u8` and would overflow on an out-of-order
//! fragment.

use crate::tag_block::{TagBlockError, split_tag_block};
use ais::messages::AisMessage;
use ais::messages::position_report::NavigationStatus;
use ais::messages::static_data_report::MessagePart;
use ais::sentence::AisReportType;
use ais::{AisFragments, AisParser};
use std::collections::BTreeMap;

/// The message types the reader uses.
pub const SUPPORTED_TYPES: [u8; 7] = [1, 2, 3, 5, 18, 19, 24];

/// One position report.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PositionReport {
    /// Line of the log it completed on, counted from 1.
    pub line: usize,
    /// The time of the report, UNIX seconds: its tag block's `c:`, else that
    /// of the last tag block before it; `None` if none came before.
    pub time_unix_s: Option<f64>,
    /// Latitude, degrees.
    pub lat_deg: f64,
    /// Longitude, degrees.
    pub lon_deg: f64,
    /// Course over ground, degrees (`None`: not available).
    pub course_deg: Option<f64>,
    /// Speed over ground, knots (`None`: not available).
    pub speed_kn: Option<f64>,
    /// True heading, degrees (`None`: not available, AIS 511).
    pub heading_deg: Option<f64>,
    /// The navigational status, its AIS code (ITU-R M.1371-5, 0-14), from a
    /// class A report (types 1-3); `None`: 15 "not defined", or a class B
    /// report, which carries none.
    pub navigational_status: Option<u8>,
}

/// Everything the log says about one vessel.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct VesselTrack {
    /// Its MMSI.
    pub mmsi: u32,
    /// Its name from a static report (type 5, 19 or 24 part A), trimmed.
    pub name: Option<String>,
    /// Its length overall from a static report (bow + stern), metres.
    pub length_m: Option<f64>,
    /// Whether it reported itself in `!AIVDO` (own vessel) sentences.
    pub own_vessel: bool,
    /// Its position reports with a valid position, in log order.
    pub reports: Vec<PositionReport>,
}

/// How many lines the reader used and skipped, and why.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct LineCounts {
    /// Lines in the log (empty ones included).
    pub lines: usize,
    /// Empty lines (skipped silently).
    pub empty: usize,
    /// Messages decoded and used.
    pub messages: usize,
    /// Fragments of multi-sentence messages waiting for their other parts.
    pub fragments: usize,
    /// Lines that are not AIS sentences, or whose tag block, envelope or
    /// payload is malformed (out-of-sequence fragments included).
    pub malformed: usize,
    /// Lines whose sentence or tag block checksum is wrong.
    pub bad_checksum: usize,
    /// Messages of types the reader does not use.
    pub unsupported_type: usize,
    /// Position reports without a valid position (latitude 91, longitude 181).
    pub no_position: usize,
}

impl LineCounts {
    /// Lines skipped: malformed, bad checksum or unsupported type.
    #[must_use]
    pub fn skipped(&self) -> usize {
        self.malformed + self.bad_checksum + self.unsupported_type
    }
}

/// An AIS log read into tracks.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct AisLog {
    /// Every vessel seen, by MMSI.
    pub vessels: BTreeMap<u32, VesselTrack>,
    /// What was read and skipped.
    pub counts: LineCounts,
    /// The latest tag-block time of the log, UNIX seconds.
    pub last_time_unix_s: Option<f64>,
}

/// A position report's fields as the `ais` crate decodes them.
#[derive(Clone, Copy)]
struct RawPosition {
    mmsi: u32,
    lat_lon: (Option<f32>, Option<f32>),
    course_deg: Option<f32>,
    speed_kn: Option<f32>,
    heading_deg: Option<u16>,
    navigational_status: Option<u8>,
}

/// The envelope fields of a sentence the reader checks itself.
struct Envelope {
    count: u8,
    number: u8,
    id: Option<u8>,
}

fn envelope(sentence: &str) -> Option<Envelope> {
    let mut fields = sentence.split(',');
    let head = fields.next()?;
    if !(head.len() == 6
        && head.starts_with('!')
        && (head.ends_with("VDM") || head.ends_with("VDO")))
    {
        return None;
    }
    let count: u8 = fields.next()?.parse().ok()?;
    let number: u8 = fields.next()?.parse().ok()?;
    let id_field = fields.next()?;
    let id = if id_field.is_empty() {
        None
    } else {
        Some(id_field.parse().ok()?)
    };
    ((1..=9).contains(&count) && (1..=count).contains(&number)).then_some(Envelope {
        count,
        number,
        id,
    })
}

/// Reads a whole log. Never fails: what cannot be read is counted in
/// [`AisLog::counts`].
#[must_use]
pub fn read_log(text: &str) -> AisLog {
    let mut reader = Reader::default();
    for (index, line) in text.lines().enumerate() {
        reader.line(index + 1, line.trim());
    }
    reader.log.counts.fragments = usize::from(reader.expected.is_some());
    reader.log
}

#[derive(Default)]
struct Reader {
    log: AisLog,
    parser: AisParser,
    /// The fragment the crate's parser expects next: (count, id, number).
    expected: Option<(u8, Option<u8>, u8)>,
    /// The time of the last tag block.
    time_unix_s: Option<f64>,
}

impl Reader {
    fn line(&mut self, number: usize, line: &str) {
        self.log.counts.lines += 1;
        if line.is_empty() {
            self.log.counts.empty += 1;
            return;
        }
        let sentence = match split_tag_block(line) {
            Ok((tag, sentence)) => {
                if let Some(time) = tag.and_then(|tag| tag.time_unix_s) {
                    self.time_unix_s = Some(time);
                    self.log.last_time_unix_s = Some(
                        self.log
                            .last_time_unix_s
                            .map_or(time, |last| last.max(time)),
                    );
                }
                sentence
            }
            Err(TagBlockError::Checksum) => {
                self.log.counts.bad_checksum += 1;
                return;
            }
            Err(TagBlockError::Malformed) => {
                self.log.counts.malformed += 1;
                return;
            }
        };
        let Some(envelope) = envelope(sentence) else {
            self.log.counts.malformed += 1;
            return;
        };
        if envelope.count > 1 && envelope.number > 1 {
            let next = (envelope.count, envelope.id, envelope.number);
            if self.expected != Some(next) {
                self.expected = None;
                self.parser = AisParser::new();
                self.log.counts.malformed += 1;
                return;
            }
        }
        match self.parser.parse(sentence.as_bytes(), false) {
            Ok(AisFragments::Incomplete(_)) => {
                self.expected = Some((envelope.count, envelope.id, envelope.number + 1));
            }
            Ok(AisFragments::Complete(complete)) => {
                self.expected = None;
                if !payload_type(&complete.data).is_some_and(|kind| SUPPORTED_TYPES.contains(&kind))
                {
                    self.log.counts.unsupported_type += 1;
                    return;
                }
                let own = complete.report_type == AisReportType::VDO;
                let decoded =
                    ais::messages::unarmor(&complete.data, usize::from(complete.fill_bit_count))
                        .and_then(|bits| ais::messages::parse(&bits));
                match decoded {
                    Ok(message) => self.message(number, own, &message),
                    Err(_) => self.log.counts.malformed += 1,
                }
            }
            Err(ais::errors::Error::Checksum { .. }) => {
                self.expected = None;
                self.log.counts.bad_checksum += 1;
            }
            Err(_) => {
                self.expected = None;
                self.parser = AisParser::new();
                self.log.counts.malformed += 1;
            }
        }
    }

    fn track(&mut self, mmsi: u32, own: bool) -> &mut VesselTrack {
        let track = self.log.vessels.entry(mmsi).or_insert_with(|| VesselTrack {
            mmsi,
            ..VesselTrack::default()
        });
        track.own_vessel |= own;
        track
    }

    fn position(&mut self, line: usize, own: bool, raw: RawPosition) {
        let RawPosition {
            mmsi,
            lat_lon,
            course_deg,
            speed_kn,
            heading_deg,
            navigational_status,
        } = raw;
        let time_unix_s = self.time_unix_s;
        let (Some(lat), Some(lon)) = lat_lon else {
            self.track(mmsi, own);
            self.log.counts.no_position += 1;
            return;
        };
        let (lat_deg, lon_deg) = (f64::from(lat), f64::from(lon));
        if !((-90.0..=90.0).contains(&lat_deg) && (-180.0..=180.0).contains(&lon_deg)) {
            self.track(mmsi, own);
            self.log.counts.no_position += 1;
            return;
        }
        let finite = |value: Option<f32>, high: f64| {
            value
                .map(f64::from)
                .filter(|value| (0.0..high).contains(value))
        };
        let report = PositionReport {
            line,
            time_unix_s,
            lat_deg,
            lon_deg,
            course_deg: finite(course_deg, 360.0),
            speed_kn: finite(speed_kn, 102.3),
            heading_deg: finite(heading_deg.map(f32::from), 360.0),
            navigational_status,
        };
        self.track(mmsi, own).reports.push(report);
    }

    fn static_data(
        &mut self,
        own: bool,
        mmsi: u32,
        name: Option<&str>,
        dimensions: Option<(u16, u16)>,
    ) {
        let track = self.track(mmsi, own);
        if let Some(name) = name.map(clean_name).filter(|name| !name.is_empty()) {
            track.name = Some(name);
        }
        if let Some((bow, stern)) = dimensions {
            let length_m = f64::from(bow) + f64::from(stern);
            if length_m > 0.0 {
                track.length_m = Some(length_m);
            }
        }
    }

    fn message(&mut self, line: usize, own: bool, message: &AisMessage) {
        self.log.counts.messages += 1;
        match message {
            AisMessage::PositionReport(report) => self.position(
                line,
                own,
                RawPosition {
                    mmsi: report.mmsi,
                    lat_lon: (report.latitude, report.longitude),
                    course_deg: report.course_over_ground,
                    speed_kn: report.speed_over_ground,
                    heading_deg: report.true_heading,
                    navigational_status: report.navigation_status.map(status_code),
                },
            ),
            AisMessage::StandardClassBPositionReport(report) => self.position(
                line,
                own,
                RawPosition {
                    mmsi: report.mmsi,
                    lat_lon: (report.latitude, report.longitude),
                    course_deg: report.course_over_ground,
                    speed_kn: report.speed_over_ground,
                    heading_deg: report.true_heading,
                    navigational_status: None,
                },
            ),
            AisMessage::ExtendedClassBPositionReport(report) => {
                self.position(
                    line,
                    own,
                    RawPosition {
                        mmsi: report.mmsi,
                        lat_lon: (report.latitude, report.longitude),
                        course_deg: report.course_over_ground,
                        speed_kn: report.speed_over_ground,
                        heading_deg: report.true_heading,
                        navigational_status: None,
                    },
                );
                self.static_data(
                    own,
                    report.mmsi,
                    Some(report.name.as_str()),
                    Some((report.dimension_to_bow, report.dimension_to_stern)),
                );
            }
            AisMessage::StaticAndVoyageRelatedData(data) => self.static_data(
                own,
                data.mmsi,
                Some(data.vessel_name.as_str()),
                Some((data.dimension_to_bow, data.dimension_to_stern)),
            ),
            AisMessage::StaticDataReport(report) => match &report.message_part {
                MessagePart::PartA { vessel_name } => {
                    self.static_data(own, report.mmsi, Some(vessel_name.as_str()), None);
                }
                MessagePart::PartB {
                    dimension_to_bow,
                    dimension_to_stern,
                    ..
                } => self.static_data(
                    own,
                    report.mmsi,
                    None,
                    Some((*dimension_to_bow, *dimension_to_stern)),
                ),
                MessagePart::Unknown(_) => {
                    self.log.counts.messages -= 1;
                    self.log.counts.malformed += 1;
                }
            },
            _ => {
                self.log.counts.messages -= 1;
                self.log.counts.unsupported_type += 1;
            }
        }
    }
}

/// The message type of an armoured payload: the six bits of its first
/// character (the crate's `AisSentence::message_type` is not that).
/// The AIS code of a navigational status as the `ais` crate decodes it.
fn status_code(status: NavigationStatus) -> u8 {
    match status {
        NavigationStatus::UnderWayUsingEngine => 0,
        NavigationStatus::AtAnchor => 1,
        NavigationStatus::NotUnderCommand => 2,
        NavigationStatus::RestrictedManouverability => 3,
        NavigationStatus::ConstrainedByDraught => 4,
        NavigationStatus::Moored => 5,
        NavigationStatus::Aground => 6,
        NavigationStatus::EngagedInFishing => 7,
        NavigationStatus::UnderWaySailing => 8,
        NavigationStatus::ReservedForHSC => 9,
        NavigationStatus::ReservedForWIG => 10,
        NavigationStatus::Reserved01 => 11,
        NavigationStatus::Reserved02 => 12,
        NavigationStatus::Reserved03 => 13,
        NavigationStatus::AisSartIsActive => 14,
        NavigationStatus::Unknown(code) => code,
    }
}

fn payload_type(payload: &[u8]) -> Option<u8> {
    let first = *payload.first()?;
    let bits = first.checked_sub(48)?;
    let bits = if bits > 40 {
        bits.checked_sub(8)?
    } else {
        bits
    };
    (bits < 64).then_some(bits)
}

/// An AIS name without its `@` padding and surrounding spaces.
fn clean_name(name: &str) -> String {
    name.trim_end_matches(['@', ' ']).trim().to_owned()
}
