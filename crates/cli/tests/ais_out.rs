//! `vorrt simulate --ais`: the run as AIS sentences in `run.nmea`, read back
//! by the project's own reader; and the errors of a local run without a frame.

use std::path::PathBuf;
use std::process::{Command, Output};

fn vorrt(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_vorrt-cli"))
        .args(args)
        .output()
        .expect("the vorrt binary runs")
}

fn fixture(relative: &str) -> PathBuf {
    vorrt_scenarios::bundled_fixtures_dir().join(relative)
}

#[test]
fn geographic_run_as_ais_reads_back() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("channel");
    let scenario = fixture("geo/channel_ais.ron");
    let output = vorrt(&[
        "simulate",
        scenario.to_str().unwrap(),
        "--ais",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    assert!(String::from_utf8_lossy(&output.stdout).contains(",run.nmea}"));
    let text = std::fs::read_to_string(out.join("run.nmea")).unwrap();
    let log = vorrt_ais::read_log(&text);
    assert_eq!(log.counts.skipped(), 0, "{:?}", log.counts);
    // 2024-05-01T12:00:00Z, the fixture's start_time.
    let first = log.vessels[&235_000_001].reports[0];
    assert_eq!(first.time_unix_s, Some(1_714_564_800.0));
    assert!(log.vessels[&235_000_001].own_vessel);
    let names: Vec<Option<&str>> = log.vessels.values().map(|v| v.name.as_deref()).collect();
    assert_eq!(
        names,
        [
            Some("VORRT TRIAL"),
            Some("NORTHSEA TRADER"),
            Some("SEA BREEZE")
        ]
    );
    // The same run as the CSV: one report per vessel per row time.
    let csv = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    let rows = csv.lines().count() - 1;
    let reports: usize = log.vessels.values().map(|v| v.reports.len()).sum();
    assert_eq!(reports, rows);
}

#[test]
fn local_run_needs_an_origin() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("head_on");
    let scenario = fixture("paper/head_on.ron");
    let path = scenario.to_str().unwrap();
    let output = vorrt(&["simulate", path, "--ais", "--out", out.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(2));
    let message = String::from_utf8_lossy(&output.stderr);
    assert!(
        message.contains("head_on.ron") && message.contains("--ais-origin LAT,LON"),
        "{message}"
    );
    assert!(!out.join("report.json").exists(), "refused before the run");
    let output = vorrt(&["simulate", path, "--ais", "--ais-origin", "95,0"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("--ais-origin is \"95,0\""));
    let output = vorrt(&[
        "simulate",
        path,
        "--ais",
        "--ais-origin",
        "50.3,-1.0",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    let log = vorrt_ais::read_log(&std::fs::read_to_string(out.join("run.nmea")).unwrap());
    let ownship = &log.vessels[&vorrt_ais::encode::SYNTHETIC_MMSI_BASE];
    assert!((ownship.reports[0].lat_deg - 50.3).abs() < 0.1);
    // No start_time: timed from the UNIX epoch, as the GPX is.
    assert_eq!(ownship.reports[0].time_unix_s, Some(0.0));
}
