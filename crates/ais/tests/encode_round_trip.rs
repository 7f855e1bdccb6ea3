//! AIS out, read back in: a closed-loop run of the bundled geographic
//! fixture written by `simulation_log` and read by `read_log` gives every
//! vessel's name, length, times, positions, courses and speeds back.

use vorrt_ais::encode::{SYNTHETIC_MMSI_BASE, mmsis};
use vorrt_ais::scenarios::{LocalFrame, evaluate, fixtures, simulate};
use vorrt_ais::{read_log, simulation_log};

#[test]
fn a_run_reads_back_as_it_was_sailed() {
    let scenario = fixtures::find("geo/channel_ais").unwrap().load().unwrap();
    let record = simulate(&scenario, 1).unwrap();
    assert!(evaluate(&scenario, &record).success());
    let frame = scenario.local_frame().unwrap();
    let start_unix_s = 1_714_564_800.0; // 2024-05-01T12:00:00Z, the fixture's start_time
    let text = simulation_log(&scenario, &record, &frame, start_unix_s).unwrap();
    assert!(
        text.lines().all(|line| line.len() <= 82 + 40),
        "sentence plus tag block"
    );
    let log = read_log(&text);
    assert_eq!(log.counts.skipped(), 0, "{:?}", log.counts);
    assert_eq!(log.counts.fragments, 0);
    let vessels = std::iter::once((&scenario.ownship, &record.ownship))
        .chain(scenario.targets.iter().zip(&record.targets));
    for (spec, states) in vessels {
        let track = &log.vessels[&spec.mmsi.unwrap()];
        assert_eq!(track.name.as_deref(), Some(spec.name.as_str()));
        assert_eq!(track.length_m, Some(spec.length_m.round()));
        assert_eq!(track.own_vessel, spec.name == scenario.ownship.name);
        assert_eq!(track.reports.len(), states.len());
        for ((report, state), time_s) in track.reports.iter().zip(states).zip(&record.times_s) {
            assert_eq!(report.time_unix_s, Some((start_unix_s + time_s).round()));
            let (lat_deg, lon_deg) = frame.to_lat_lon_deg(state.position_m);
            // AIS resolution 1/10000 minute; the reader decodes to f32.
            assert!((report.lat_deg - lat_deg).abs() < 1e-5, "{report:?}");
            assert!((report.lon_deg - lon_deg).abs() < 1e-5, "{report:?}");
            let back_m = frame.to_local_m(report.lat_deg, report.lon_deg);
            assert!((back_m - state.position_m).length() < 1.5);
            let speed_kn = vorrt_ais::scenarios::geometry::units::mps_to_knots(state.speed_mps);
            assert!((report.speed_kn.unwrap() - speed_kn).abs() <= 0.051);
            let course_deg = state.course_rad.to_degrees().rem_euclid(360.0);
            let course_error = (report.course_deg.unwrap() - course_deg + 540.0) % 360.0 - 180.0;
            assert!(
                course_error.abs() <= 0.051,
                "{report:?} against {course_deg}"
            );
        }
    }
}

/// A local scenario placed by a frame the caller picks; vessels without an
/// MMSI get synthetic ones, in order.
#[test]
fn local_run_with_synthetic_mmsis() {
    let scenario = fixtures::find("paper/head_on").unwrap().load().unwrap();
    assert!(scenario.ownship.mmsi.is_none());
    let record = simulate(&scenario, 1).unwrap();
    let frame = LocalFrame::new(50.0, -1.0);
    let text = simulation_log(&scenario, &record, &frame, 0.0).unwrap();
    let log = read_log(&text);
    let ids = mmsis(&scenario).unwrap();
    assert_eq!(ids[0], SYNTHETIC_MMSI_BASE);
    assert_eq!(ids[1], SYNTHETIC_MMSI_BASE + 1);
    assert!(log.vessels[&ids[0]].own_vessel);
    let first = log.vessels[&ids[0]].reports[0];
    let (lat, lon) = frame.to_lat_lon_deg(record.ownship[0].position_m);
    assert!((first.lat_deg - lat).abs() < 1e-5 && (first.lon_deg - lon).abs() < 1e-5);
    assert_eq!(first.time_unix_s, Some(0.0));
}

#[test]
fn duplicate_mmsis_are_refused() {
    let mut scenario = fixtures::find("geo/channel_ais").unwrap().load().unwrap();
    scenario.targets[1].mmsi = scenario.targets[0].mmsi;
    let error = mmsis(&scenario).unwrap_err();
    assert_eq!(
        error.to_string(),
        "vessels NORTHSEA TRADER and SEA BREEZE both have MMSI 244000002"
    );
    scenario.targets[1].mmsi = Some(1_000_000_000);
    assert!(
        mmsis(&scenario)
            .unwrap_err()
            .to_string()
            .contains("more than nine digits")
    );
}
