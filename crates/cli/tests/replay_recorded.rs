//! vorrt among recorded traffic, end to end through the binary (decision
//! 40): `vorrt import-ais --replay` on the bundled log, `vorrt simulate` on
//! the replay and `vorrt judge` on the human's track of the same encounter;
//! and a synthetic recording of two vessels that would run down an ownship
//! that held its course, so vorrt must act.

use std::path::Path;
use std::process::{Command, Output};

fn vorrt(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_vorrt-cli"))
        .args(args)
        .output()
        .expect("the vorrt binary runs")
}

fn text(path: &Path) -> &str {
    path.to_str().expect("temporary paths are UTF-8")
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).expect("written")).expect("JSON")
}

/// Asserts a report (or judgement) has no collision and kept `d_th`.
fn assert_safe(report: &serde_json::Value) {
    assert_eq!(report["collision"], false, "{report}");
    let min_m = report["min_distance_m"].as_f64().expect("a distance");
    let d_th_m = report["d_th_m"].as_f64().expect("d_th");
    assert!(
        min_m >= d_th_m,
        "min distance {min_m} m under d_th {d_th_m} m"
    );
}

#[test]
fn the_bundled_log_is_replayed_and_the_human_judged_beside_vorrt() {
    let dir = tempfile::tempdir().unwrap();
    let log = Path::new(env!("CARGO_MANIFEST_DIR")).join("../ais/fixtures/encounter.nmea");
    let scenario = dir.path().join("channel.ron");
    let import = vorrt(&[
        "import-ais",
        text(&log),
        "--ownship",
        "235000001",
        "--replay",
        "--goal",
        "50.30,-0.80",
        "--out",
        text(&scenario),
    ]);
    assert!(import.status.success(), "{import:?}");
    let tracks = dir.path().join("channel.tracks.csv");
    let csv = std::fs::read_to_string(&tracks).expect("the tracks beside the scenario");
    assert!(csv.starts_with("vessel,mmsi,time_s,lat_deg,lon_deg"));
    let ron = std::fs::read_to_string(&scenario).unwrap();
    assert!(
        ron.contains("recorded_tracks: \"channel.tracks.csv\""),
        "{ron}"
    );
    assert_eq!(ron.matches("behaviour: Recorded").count(), 2, "{ron}");

    let vorrt_out = dir.path().join("vorrt");
    let run = vorrt(&["simulate", text(&scenario), "--out", text(&vorrt_out)]);
    assert!(run.status.success(), "{run:?}");
    let report = json(&vorrt_out.join("report.json"));
    assert_safe(&report);
    assert_eq!(report["reached_goal"], true);
    // Ownship sails among the recorded vessels: one passes within 2 nm
    // (with decision 61's return part of the way, early enough that no risk
    // of collision arises on the tracks as observed).
    assert!(
        report["targets"]
            .as_array()
            .unwrap()
            .iter()
            .any(|target| target["min_distance_m"].as_f64().unwrap() < 2.0 * 1852.0),
        "{report}"
    );

    let human_out = dir.path().join("human");
    let judge = vorrt(&[
        "judge",
        text(&tracks),
        "--scenario",
        text(&scenario),
        "--out",
        text(&human_out),
    ]);
    let judgement = json(&human_out.join("judgement.json"));
    assert_eq!(judgement["input"]["tracks_format"], "csv", "{judge:?}");
    assert_eq!(judgement["input"]["ownship"], "VORRT TRIAL");
    // The human's track of the same recording: the same targets, met on
    // the same clock.
    assert_eq!(
        judgement["targets"].as_array().unwrap().len(),
        report["targets"].as_array().unwrap().len()
    );
}

/// Ownship's course-holding position at `time_s`: north at 12 kn from 0.
fn held_course_m(time_s: f64) -> (f64, f64) {
    (0.0, 12.0 * 1852.0 / 3600.0 * time_s)
}

/// The recorded tracks: `A` head-on from 5 km ahead at 10 kn, reported
/// every 30 s; `B` crossing from starboard at 8 kn, on a line through
/// ownship's course-holding position at 600 s, reported every 10 s, and
/// turning away to starboard at 900 s, after the encounter.
fn synthetic_tracks() -> (String, Vec<(f64, &'static str, f64, f64)>) {
    let knots = 1852.0 / 3600.0;
    let mut rows = Vec::new();
    for step in 0..=40 {
        let time_s = 30.0 * f64::from(step);
        rows.push((time_s, "A", 0.0, 5000.0 - 10.0 * knots * time_s));
    }
    let crossing_y_m = held_course_m(600.0).1;
    for step in 0..=120 {
        let time_s = 10.0 * f64::from(step);
        let before = time_s.min(900.0);
        let (mut x_m, mut y_m) = (8.0 * knots * (600.0 - before), crossing_y_m);
        // After 900 s it heads north-west (315°).
        let after_s = time_s - before;
        x_m -= 8.0 * knots * after_s * std::f64::consts::FRAC_1_SQRT_2;
        y_m += 8.0 * knots * after_s * std::f64::consts::FRAC_1_SQRT_2;
        rows.push((time_s, "B", x_m, y_m));
    }
    let csv: String = std::iter::once("vessel,time_s,east_m,north_m\n".to_owned())
        .chain(
            rows.iter()
                .map(|(time_s, vessel, x_m, y_m)| format!("{vessel},{time_s},{x_m},{y_m}\n")),
        )
        .collect();
    (csv, rows)
}

#[test]
fn vorrt_keeps_clear_of_recorded_vessels_that_would_run_down_a_course_holder() {
    let (csv, rows) = synthetic_tracks();
    // Holding its course, ownship would pass within 100 m of both (hulls
    // of 100-120 m, d_th 200 m): vorrt must act.
    for vessel in ["A", "B"] {
        let closest_m = rows
            .iter()
            .filter(|row| row.1 == vessel)
            .map(|&(time_s, _, x_m, y_m)| {
                let (own_x, own_y) = held_course_m(time_s);
                (x_m - own_x).hypot(y_m - own_y)
            })
            .fold(f64::INFINITY, f64::min);
        assert!(closest_m < 100.0, "{vessel}: {closest_m} m");
    }
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("pair.tracks.csv"), csv).unwrap();
    let scenario = dir.path().join("pair.ron");
    std::fs::write(
        &scenario,
        r#"Scenario(
    name: "recorded_pair",
    ownship: Vessel(name: "own", start_m: (0.0, 0.0), course_deg: 0.0, speed_kn: 12.0, length_m: 100.0, goal_m: (0.0, 8000.0)),
    targets: [
        Vessel(name: "A", start_m: (0.0, 5000.0), course_deg: 180.0, speed_kn: 10.0, length_m: 120.0, behaviour: Recorded),
        Vessel(name: "B", start_m: (2469.3, 3704.0), course_deg: 270.0, speed_kn: 8.0, length_m: 80.0, behaviour: Recorded),
    ],
    recorded_tracks: "pair.tracks.csv",
)
"#,
    )
    .unwrap();
    let out = dir.path().join("vorrt");
    let run = vorrt(&["simulate", text(&scenario), "--out", text(&out)]);
    assert!(run.status.success(), "{run:?}");
    let report = json(&out.join("report.json"));
    assert_safe(&report);
    assert_eq!(report["reached_goal"], true);
    // vorrt acted: it left the straight line.
    assert!(
        report["path_overhead_pct"].as_f64().unwrap() > 1.0,
        "{report}"
    );
    // The targets moved as recorded: B's last row, at 1200 s, is in the run.
    let trajectory = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    assert!(
        trajectory.lines().any(|line| line.contains(",B,")),
        "B sailed"
    );

    // A target without a track is refused, naming the tracks file.
    std::fs::write(
        dir.path().join("pair.tracks.csv"),
        "vessel,time_s,east_m,north_m\nA,0,0,5000\n",
    )
    .unwrap();
    let refused = vorrt(&["simulate", text(&scenario), "--out", text(&out)]);
    assert!(!refused.status.success());
    let message = String::from_utf8_lossy(&refused.stderr);
    assert!(
        message.contains("targets[1] \"B\".behaviour is Recorded, but")
            && message.contains("pair.tracks.csv has no rows"),
        "{message}"
    );
}
