//! `vorrt judge` on tracks as recorded at sea (decision 32): a vessel at
//! anchor is no encounter, an unfinished encounter is undecided, a jump is
//! rejected and a length-less ownship's rate of turn is not judged.

use serde_json::Value;
use std::fmt::Write as _;
use std::process::Command;

/// Ownship north at 6 m/s from the origin, a fix every 10 s up to
/// `duration_s`; the target 9 km ahead, still (`status` given) or meeting
/// it at 6 m/s. A jump of 20 nm in one fix at 300 s when `jump`.
fn csv(duration_s: u32, target_speed_mps: f64, status: &str, jump: bool) -> String {
    let mut text = String::from("time_s,vessel,east_m,north_m,status\n");
    for step in 0..=duration_s / 10 {
        let t = f64::from(step * 10);
        let own_north = if jump && step == 30 {
            37_040.0
        } else {
            6.0 * t
        };
        let _ = writeln!(text, "{t},own,0,{own_north},0");
        let _ = writeln!(
            text,
            "{t},TS1,100,{},{status}",
            9000.0 - target_speed_mps * t
        );
    }
    text
}

fn judge(text: &str) -> (i32, Value, String) {
    let dir = tempfile::tempdir().unwrap();
    let tracks = dir.path().join("tracks.csv");
    std::fs::write(&tracks, text).unwrap();
    let out = dir.path().join("out");
    let output = Command::new(env!("CARGO_BIN_EXE_vorrt-cli"))
        .args([
            "judge",
            tracks.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    let judgement =
        serde_json::from_str(&std::fs::read_to_string(out.join("judgement.json")).unwrap())
            .unwrap();
    (
        output.status.code().unwrap(),
        judgement,
        String::from_utf8_lossy(&output.stdout).into_owned(),
    )
}

#[test]
fn a_vessel_at_anchor_is_an_obstacle_and_its_status_is_said() {
    let (_, judgement, console) = judge(&csv(1800, 0.0, "at_anchor", false));
    assert_eq!(judgement["targets"][0]["encounter"], "none");
    let target = &judgement["input"]["observation"][1];
    assert_eq!(target["status_judged"], "at_anchor");
    assert!(console.contains("3(i)"), "{console}");
    // Stated, not judged: no length, so no limit.
    assert!(judgement["path_quality"]["turn_rate_limit_deg_s"].is_null());
    assert!(console.contains("reported, not judged"), "{console}");
    // Moving, the same status is not believed.
    let (_, judgement, _) = judge(&csv(1800, 6.0, "moored", false));
    assert_eq!(judgement["targets"][0]["encounter"], "head_on");
    assert!(
        judgement["input"]["observation"][1]["rule_18"]
            .as_str()
            .unwrap()
            .contains("judged as under way")
    );
}

#[test]
fn tracks_ending_before_the_pass_are_undecided() {
    let (code, judgement, console) = judge(&csv(600, 6.0, "0", false));
    assert_eq!(code, 1);
    assert_eq!(judgement["undecided"][0], "TS1");
    assert!(console.contains("(undecided)"), "{console}");
    let (_, judgement, _) = judge(&csv(1200, 6.0, "0", false));
    assert!(judgement["undecided"].as_array().unwrap().is_empty());
}

#[test]
fn a_jump_of_twenty_miles_is_rejected() {
    let (_, judgement, _) = judge(&csv(1200, 6.0, "0", true));
    assert_eq!(judgement["input"]["observation"][0]["jumps_rejected"], 1);
    assert_eq!(judgement["input"]["vessels"][0]["fixes"], 120);
}
