//! The bundled log `fixtures/encounter.nmea` of this crate (made by
//! `scripts/make_ais_fixture.py` with pyais) read and imported.

use proptest::prelude::*;
use vorrt_ais::{AisError, ImportOptions, build_scenario, estimate, read_log};

const LOG: &str = include_str!("../fixtures/encounter.nmea");
const OWN: u32 = 235_000_001;
const HEAD_ON: u32 = 244_000_002;
const CROSSING: u32 = 338_000_003;
const FAR: u32 = 211_000_004;
const T0: f64 = 1_714_564_800.0;

fn options() -> ImportOptions {
    ImportOptions {
        log_name: "encounter.nmea".into(),
        ownship_mmsi: OWN,
        goal_lat_lon: (50.30, -0.80),
        at_unix_s: None,
        range_nm: 12.0,
    }
}

#[test]
fn reads_every_vessel_with_its_static_data() {
    let log = read_log(LOG);
    assert_eq!(log.vessels.len(), 4);
    let own = &log.vessels[&OWN];
    assert!(own.own_vessel, "ownship reports in !AIVDO");
    // Type 5 in two sentences, reassembled.
    assert_eq!(own.name.as_deref(), Some("VORRT TRIAL"));
    assert_eq!(own.length_m, Some(100.0));
    assert_eq!(
        log.vessels[&HEAD_ON].name.as_deref(),
        Some("NORTHSEA TRADER")
    );
    assert_eq!(log.vessels[&HEAD_ON].length_m, Some(150.0));
    // Class B: type 24 parts A and B, type 18 positions.
    let crossing = &log.vessels[&CROSSING];
    assert_eq!(crossing.name.as_deref(), Some("SEA BREEZE"));
    assert_eq!(crossing.length_m, Some(15.0));
    assert_eq!(crossing.reports.len(), 10);
    // Type 19 carries name and dimensions with the position.
    assert_eq!(log.vessels[&FAR].name.as_deref(), Some("FAR AWAY"));
    assert_eq!(log.vessels[&FAR].length_m, Some(25.0));
    assert_eq!(log.last_time_unix_s, Some(T0));
    let last = own.reports.last().unwrap();
    assert_eq!(last.time_unix_s, Some(T0 - 4.0));
    assert!((last.speed_kn.unwrap() - 12.0).abs() < 0.05);
    assert!((last.course_deg.unwrap() - 90.0).abs() < 0.05);
}

#[test]
fn counts_what_it_skips() {
    let counts = read_log(LOG).counts;
    // One sentence with a wrong checksum, one tag block with a wrong one.
    assert_eq!(counts.bad_checksum, 2, "{counts:?}");
    // Plain text, $GPGGA, a lone second fragment.
    assert_eq!(counts.malformed, 3, "{counts:?}");
    // The type 4 base station report.
    assert_eq!(counts.unsupported_type, 1, "{counts:?}");
    assert_eq!(counts.lines, 73);
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn imports_the_encounter() {
    let log = read_log(LOG);
    let import = build_scenario(&log, &options()).unwrap();
    let scenario = &import.scenario;
    assert!(scenario.is_geographic());
    assert_eq!(scenario.start_time.as_deref(), Some("2024-05-01T12:00:00Z"));
    assert_eq!(scenario.ownship.name, "VORRT TRIAL");
    assert_eq!(scenario.ownship.mmsi, Some(OWN));
    let names: Vec<&str> = scenario.targets.iter().map(|t| t.name.as_str()).collect();
    assert_eq!(names, ["NORTHSEA TRADER", "SEA BREEZE"]);
    assert!(
        import
            .notes
            .iter()
            .any(|note| note.contains("211000004") && note.contains("left out")),
        "{:?}",
        import.notes
    );
    // Ownship dead-reckoned 4 s at 12 kn east: about 24.7 m from its fix.
    let own = estimate(&log.vessels[&OWN], Some(T0)).unwrap();
    assert_eq!(own.dead_reckoned_s, 4.0);
    let fix = own.report;
    let frame = vorrt_scenarios::LocalFrame::new(fix.lat_deg, fix.lon_deg);
    let moved = frame.to_local_m(own.lat_lon.0, own.lat_lon.1);
    assert!(
        (moved.x - 24.69).abs() < 0.1 && moved.y.abs() < 0.5,
        "{moved}"
    );
    // And the scenario is written and read back as a file would be.
    let text = scenario.to_ron_string().unwrap();
    let again = vorrt_scenarios::Scenario::from_ron_str(&text, "again.ron").unwrap();
    assert_eq!(&again, scenario);
}

#[test]
fn a_wider_range_takes_the_far_vessel() {
    let mut options = options();
    options.range_nm = 40.0;
    let import = build_scenario(&read_log(LOG), &options).unwrap();
    assert_eq!(import.scenario.targets.len(), 3);
}

#[test]
fn an_earlier_time_dead_reckons_from_earlier_reports() {
    let mut options = options();
    options.at_unix_s = Some(T0 - 300.0);
    let import = build_scenario(&read_log(LOG), &options).unwrap();
    assert_eq!(
        import.scenario.start_time.as_deref(),
        Some("2024-05-01T11:55:00Z")
    );
    let start = import.scenario.ownship.start_lat_lon.unwrap();
    // Both come from reports 4 s old: 300 s apart at 12 kn, 1852 m.
    let late = build_scenario(&read_log(LOG), &self::options()).unwrap();
    let frame = import.scenario.local_frame().unwrap();
    let late_start = late.scenario.ownship.start_lat_lon.unwrap();
    let east = frame.to_local_m(late_start.0, late_start.1);
    assert!(
        (east.x - 300.0 * 12.0 * 1852.0 / 3600.0).abs() < 1.0 && east.y.abs() < 1.0,
        "{east} from {start:?}"
    );
}

#[test]
fn bad_requests_are_errors() {
    let log = read_log(LOG);
    let mut options = options();
    options.ownship_mmsi = 1;
    let error = build_scenario(&log, &options).unwrap_err();
    assert!(matches!(error, AisError::UnknownMmsi { .. }));
    assert!(error.to_string().contains("235000001"), "{error}");
    let mut options = self::options();
    options.at_unix_s = Some(T0 - 3600.0);
    let error = build_scenario(&log, &options).unwrap_err();
    assert!(
        matches!(error, AisError::NoOwnshipPosition { .. }),
        "{error}"
    );
    let mut options = self::options();
    options.goal_lat_lon = (95.0, 0.0);
    let error = build_scenario(&log, &options).unwrap_err();
    assert!(error.to_string().contains("--goal"), "{error}");
    // Only static data for ownship: no position.
    let statics: String = LOG
        .lines()
        .filter(|line| !line.contains("13P7@h"))
        .flat_map(|line| [line, "\n"])
        .collect();
    let error = build_scenario(&read_log(&statics), &self::options()).unwrap_err();
    assert!(
        matches!(error, AisError::NoOwnshipPosition { .. }),
        "{error}"
    );
}

proptest! {
    /// Any text, and any line of the log cut or altered, is read without
    /// panicking, and every line is accounted for at most once.
    #[test]
    fn any_text_is_read(text in "\\PC{0,400}") {
        let log = read_log(&text);
        prop_assert!(log.counts.skipped() + log.counts.empty <= log.counts.lines);
    }

    #[test]
    fn damaged_logs_are_read(cut in 0usize..4000, byte in 32u8..127) {
        let mut bytes = LOG.as_bytes().to_vec();
        let index = cut % bytes.len();
        bytes[index] = byte;
        let text = String::from_utf8_lossy(&bytes);
        let log = read_log(&text);
        prop_assert!(log.counts.lines <= 73);
        let _ = build_scenario(&log, &options());
    }
}

/// Fragments out of sequence are counted as malformed, not handed to the
/// `ais` crate, whose own check subtracts fragment numbers as `u8` and
/// overflows (a panic in debug builds) on a fragment numbered below the last.
#[test]
fn out_of_sequence_fragments_are_malformed() {
    let sentence = |count: u8, number: u8| {
        let body = format!("AIVDM,{count},{number},7,A,0000,0");
        format!(
            "!{body}*{:02X}\n",
            vorrt_ais::tag_block::nmea_checksum(&body)
        )
    };
    let log: String = [(5, 1), (5, 2), (5, 3), (5, 4), (5, 3), (5, 0), (5, 6)]
        .into_iter()
        .map(|(count, number)| sentence(count, number))
        .collect();
    let counts = read_log(&log).counts;
    assert_eq!(counts.malformed, 3, "{counts:?}");
    assert_eq!(counts.lines, 7);
}
