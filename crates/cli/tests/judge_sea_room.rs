//! `vorrt judge --sea-room-m` (decision 50): two launches passing half a
//! mile apart are an encounter in open sea and none in a narrow channel,
//! and the judgement says which risk-of-collision distance it used.

use serde_json::Value;
use std::fmt::Write as _;
use std::process::Command;

/// Two 20 m launches meeting on reciprocal courses at 5 m/s, set up to
/// pass 926 m (0.5 nm) apart, a fix every 10 s for 1800 s.
fn launches() -> String {
    let mut text = String::from("time_s,vessel,east_m,north_m,length_m\n");
    for step in 0..=180 {
        let t = f64::from(step * 10);
        let _ = writeln!(text, "{t},own,0,{},20", 5.0 * t);
        let _ = writeln!(text, "{t},TS1,-926,{},20", 9000.0 - 5.0 * t);
    }
    text
}

fn judge(text: &str, extra: &[&str]) -> Value {
    let dir = tempfile::tempdir().unwrap();
    let tracks = dir.path().join("tracks.csv");
    std::fs::write(&tracks, text).unwrap();
    let out = dir.path().join("out");
    let status = Command::new(env!("CARGO_BIN_EXE_vorrt-cli"))
        .args([
            "judge",
            tracks.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .args(extra)
        .output()
        .unwrap()
        .status;
    assert!(matches!(status.code(), Some(0 | 1)), "{status:?}");
    serde_json::from_str(&std::fs::read_to_string(out.join("judgement.json")).unwrap()).unwrap()
}

fn said(judgement: &Value) -> String {
    judgement["input"]["assumptions"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(Value::as_str)
        .find(|line| line.starts_with("risk of collision"))
        .expect("the risk distance is stated")
        .to_owned()
}

#[test]
fn launches_half_a_mile_apart_are_no_encounter_in_a_narrow_channel() {
    let open = judge(&launches(), &[]);
    assert_eq!(open["targets"][0]["encounter"], "head_on");
    assert!(said(&open).contains("under 1852 m"), "{}", said(&open));
    assert!(said(&open).contains("open sea"), "{}", said(&open));
    let channel = judge(&launches(), &["--sea-room-m", "1500"]);
    assert_eq!(channel["targets"][0]["encounter"], "none");
    assert!(said(&channel).contains("under 375 m"), "{}", said(&channel));
    assert!(
        said(&channel).contains("sea room 1500 m"),
        "{}",
        said(&channel)
    );
}
