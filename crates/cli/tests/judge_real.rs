//! `vorrt judge` on tracks as recorded at sea (decisions 32 and 49): a vessel
//! at anchor is no encounter, one reporting moored but making way is no
//! encounter and undecided, an unfinished encounter or one the target did not
//! report is undecided, a jump is rejected and a length-less ownship's rate
//! of turn is not judged.

use serde_json::Value;
use std::fmt::Write as _;
use std::process::Command;

/// Ownship north at 6 m/s from the origin, a fix every 10 s up to
/// `duration_s`; the target 9 km ahead, still (`status` given) or meeting
/// it at 6 m/s. A jump of 20 nm in one fix at 300 s when `jump`.
fn csv(duration_s: u32, target_speed_mps: f64, status: &str, jump: bool) -> String {
    csv_until(duration_s, target_speed_mps, status, jump, duration_s)
}

/// [`csv`] with the target's last report at `target_until_s`.
fn csv_until(
    duration_s: u32,
    target_speed_mps: f64,
    status: &str,
    jump: bool,
    target_until_s: u32,
) -> String {
    let mut text = String::from("time_s,vessel,east_m,north_m,status\n");
    for step in 0..=duration_s / 10 {
        let t = f64::from(step * 10);
        let own_north = if jump && step == 30 {
            37_040.0
        } else {
            6.0 * t
        };
        let _ = writeln!(text, "{t},own,0,{own_north},0");
        if step * 10 > target_until_s {
            continue;
        }
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
    let (code, judgement, console) = judge(&csv(1800, 0.0, "at_anchor", false));
    assert_eq!(judgement["targets"][0]["encounter"], "none");
    assert!(judgement["undecided"].as_array().unwrap().is_empty());
    // 100 m abeam, inside d_th: not safe, but decided.
    assert_eq!(code, 1);
    assert!(!console.contains("(undecided)"), "{console}");
    let target = &judgement["input"]["observation"][1];
    assert_eq!(target["status_judged"], "at_anchor");
    assert!(console.contains("3(i)"), "{console}");
    // Stated, not judged: no length, so no limit.
    assert!(judgement["path_quality"]["turn_rate_limit_deg_s"].is_null());
    assert!(console.contains("reported, not judged"), "{console}");
}

#[test]
fn a_moored_vessel_making_way_is_no_encounter_and_undecided() {
    // Reports moored, meets ownship head-on at 6 m/s (11.7 kn): her status
    // contradicts her motion (decision 49).
    let (code, judgement, console) = judge(&csv(1800, 6.0, "moored", false));
    let target = &judgement["targets"][0];
    assert_eq!(target["encounter"], "none");
    assert!(
        target["findings"]
            .as_array()
            .unwrap()
            .iter()
            .all(|f| { ["clearance_violated", "collision"].contains(&f.as_str().unwrap()) })
    );
    let why = target["undecided"].as_str().unwrap();
    assert!(
        why.contains("reports moored but made way at 11.7 kn"),
        "{why}"
    );
    assert!(why.contains("status contradicts motion"), "{why}");
    assert!(why.contains("rules 13-17 not judged"), "{why}");
    assert_eq!(judgement["undecided"][0], "TS1");
    assert_eq!(code, 1);
    assert!(
        console.contains("NOT safe and compliant (undecided)"),
        "{console}"
    );
    assert!(
        judgement["input"]["observation"][1]["rule_18"]
            .as_str()
            .unwrap()
            .contains("status contradicts motion")
    );
    // Under way, the same motion is an encounter, judged as before.
    let (_, judgement, _) = judge(&csv(1800, 6.0, "0", false));
    assert_eq!(judgement["targets"][0]["encounter"], "head_on");
    assert!(judgement["targets"][0]["undecided"].is_null());
}

#[test]
fn a_target_silent_before_the_closest_approach_is_undecided() {
    // Head-on, closest approach at 750 s; the target's reports stop at
    // 600 s (half of ownship's 1200 s, so she is judged), dead-reckoned
    // after: unreported from 660 s (half the 120 s gap limit on).
    let (code, judgement, console) = judge(&csv_until(1200, 6.0, "0", false, 600));
    let target = &judgement["targets"][0];
    assert_eq!(target["encounter"], "head_on");
    let why = target["undecided"].as_str().unwrap();
    assert!(why.contains("target not reported from 600 s"), "{why}");
    assert!(
        why.contains("closest approach (at 750 s) dead-reckoned"),
        "{why}"
    );
    assert_eq!(code, 1);
    assert!(console.contains("(undecided)"), "{console}");
    // Reporting through the closest approach: judged.
    let (_, judgement, _) = judge(&csv_until(1200, 6.0, "0", false, 800));
    assert!(judgement["targets"][0]["undecided"].is_null());
    assert!(judgement["undecided"].as_array().unwrap().is_empty());
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
