//! `vorrt judge` against a scenario with land (decision 29): a track that
//! cuts a headland is a grounding, a safety failure (exit 1); the same
//! track past a headland that ends short of it keeps the land clearance.

use serde_json::Value;
use std::fmt::Write as _;
use std::path::Path;
use std::process::Command;

const NM: f64 = 1852.0;
const KN: f64 = 1852.0 / 3600.0;

/// A scenario: ownship north from (0, 0) to (0, 5) nm at 12 kn, a target
/// 4 nm to port on a parallel course, and a headland from the east whose tip
/// reaches `tip_east_nm` at 2 nm north.
fn scenario_ron(tip_east_nm: f64) -> String {
    format!(
        r#"Scenario(
    name: "headland",
    ownship: Vessel(name: "own", start_nm: (0.0, 0.0), course_deg: 0.0, speed_kn: 12.0,
                    length_m: 100.0, goal_nm: (0.0, 5.0)),
    targets: [Vessel(name: "T", start_nm: (-4.0, 0.0), course_deg: 0.0, speed_kn: 12.0,
                     length_m: 100.0, goal_nm: (-4.0, 6.0))],
    land: [Area(name: "headland", outer_nm: [({tip_east_nm}, 2.0), (5.0, 1.0), (5.0, 3.5), ({tip_east_nm}, 2.3)])],
)"#
    )
}

/// Both vessels straight north at 12 kn for 1500 s, every 5 s.
fn tracks_csv() -> String {
    let mut text = "time_s,vessel,east_m,north_m,course_deg,speed_kn,length_m\n".to_owned();
    for step in 0..=300 {
        let time_s = f64::from(step) * 5.0;
        let north_m = 12.0 * KN * time_s;
        writeln!(text, "{time_s},own,0,{north_m},0,12,100").unwrap();
        writeln!(text, "{time_s},T,{},{north_m},0,12,100", -4.0 * NM).unwrap();
    }
    text
}

/// Judges the tracks against the scenario with the headland's tip at
/// `tip_east_nm`: exit code, judgement.json and the printed table.
fn judge(dir: &Path, tip_east_nm: f64) -> (i32, Value, String) {
    let scenario = dir.join(format!("headland-{tip_east_nm}.ron"));
    std::fs::write(&scenario, scenario_ron(tip_east_nm)).unwrap();
    let tracks = dir.join("tracks.csv");
    std::fs::write(&tracks, tracks_csv()).unwrap();
    let out = dir.join(format!("out-{tip_east_nm}"));
    let output = Command::new(env!("CARGO_BIN_EXE_vorrt-cli"))
        .args([
            "judge",
            tracks.to_str().unwrap(),
            "--scenario",
            scenario.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .expect("the vorrt binary runs");
    let judgement: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("judgement.json")).unwrap())
            .unwrap();
    assert!(out.join("trajectories.svg").exists());
    (
        output.status.code().unwrap(),
        judgement,
        String::from_utf8_lossy(&output.stdout).into_owned(),
    )
}

#[test]
fn a_track_that_cuts_a_headland_is_a_grounding() {
    let dir = tempfile::tempdir().unwrap();
    let (code, judgement, table) = judge(dir.path(), -0.1);
    assert_eq!(code, 1, "{table}");
    assert_eq!(judgement["grounding"], true, "{judgement}");
    assert_eq!(judgement["min_land_distance_m"], 0.0);
    assert_eq!(judgement["land_clearance_kept"], false);
    assert_eq!(judgement["safe_and_compliant"], false);
    assert!(table.contains("GROUNDING"), "{table}");
}

#[test]
fn a_track_clear_of_the_headland_keeps_the_land_clearance() {
    let dir = tempfile::tempdir().unwrap();
    let (code, judgement, table) = judge(dir.path(), 0.5);
    assert_eq!(judgement["grounding"], false, "{judgement}");
    let distance_m = judgement["min_land_distance_m"].as_f64().unwrap();
    assert!((distance_m - 0.5 * NM).abs() < 1.0, "{distance_m}");
    assert_eq!(judgement["land_clearance_kept"], true);
    assert_eq!(judgement["land_clearance_m"], 463.0);
    assert_eq!(code, 0, "{table}");
    assert!(table.contains("land:"), "{table}");
}
