//! Robustness (issue 7): every kind of bad scenario file makes `vorrt check`
//! exit 2 with one message naming the file and the field at fault, never a
//! panic; a missing file exits 2; an empty target list is valid.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, missing_docs)]

use std::fmt::Write as _;
use std::path::Path;
use std::process::{Command, Output};

/// A valid scenario that each test breaks in one place.
const GOOD: &str = r#"Scenario(
    name: "small crossing",
    ownship: Vessel(name: "ownship", start_nm: (0.0, -1.0), course_deg: 0.0,
                    speed_kn: 12.0, length_m: 100.0, goal_nm: (0.0, 1.0)),
    targets: [
        Vessel(name: "TS1", start_nm: (1.0, 0.0), course_deg: 270.0, speed_kn: 12.0,
               length_m: 150.0, goal_nm: (-1.5, 0.0)),
    ],
    seed: 3,
)
"#;

const TS1: &str = r#"Vessel(name: "TS1", start_nm: (1.0, 0.0), course_deg: 270.0, speed_kn: 12.0,
               length_m: 150.0, goal_nm: (-1.5, 0.0)),"#;

fn check(text: &str) -> (Output, String) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("broken.ron");
    std::fs::write(&path, text).unwrap();
    let output = Command::new(env!("CARGO_BIN_EXE_vorrt-cli"))
        .args(["check", path.to_str().unwrap()])
        .env_remove("RUST_BACKTRACE")
        .output()
        .expect("the vorrt binary runs");
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    (output, stderr)
}

/// `text` must differ from [`GOOD`], make `vorrt check` exit 2 and print a
/// message naming the file and every one of `expected`, without a panic.
fn assert_rejected(text: &str, expected: &[&str]) {
    assert_ne!(text, GOOD, "the test must break the file");
    let (output, message) = check(text);
    assert_eq!(output.status.code(), Some(2), "stderr: {message}");
    assert!(!message.contains("panicked"), "{message}");
    assert!(!message.contains("RUST_BACKTRACE"), "{message}");
    assert!(message.contains("broken.ron"), "file not named: {message}");
    for word in expected {
        assert!(message.contains(word), "{word:?} not in {message}");
    }
}

#[test]
fn the_unbroken_file_is_valid() {
    let (output, message) = check(GOOD);
    assert_eq!(output.status.code(), Some(0), "stderr: {message}");
}

#[test]
fn syntax_error_gives_line_and_column() {
    // Line 4 (the ownship) lacks the comma after `speed_kn: 12.0`.
    let text = GOOD.replacen(
        "speed_kn: 12.0, length_m: 100.0",
        "speed_kn: 12.0 length_m: 100.0",
        1,
    );
    assert_rejected(&text, &["broken.ron:4:"]);
    let (_, message) = check(&text);
    let after = message.split("broken.ron:4:").nth(1).unwrap();
    assert!(
        after.chars().next().is_some_and(|c| c.is_ascii_digit()),
        "no column: {message}"
    );
}

#[test]
fn unknown_field_is_named() {
    assert_rejected(&GOOD.replacen("seed: 3,", "sede: 3,", 1), &["sede"]);
}

#[test]
fn nan_speed_is_named() {
    assert_rejected(
        &GOOD.replacen(
            "course_deg: 270.0, speed_kn: 12.0",
            "course_deg: 270.0, speed_kn: NaN",
            1,
        ),
        &["targets[0]", "speed_kn", "NaN"],
    );
}

#[test]
fn negative_speed_is_named() {
    assert_rejected(
        &GOOD.replacen(
            "speed_kn: 12.0, length_m: 100.0",
            "speed_kn: -3.0, length_m: 100.0",
            1,
        ),
        &["ownship.speed_kn"],
    );
}

#[test]
fn zero_length_is_named() {
    assert_rejected(
        &GOOD.replacen("length_m: 150.0", "length_m: 0.0", 1),
        &["targets[0]", "length_m"],
    );
}

#[test]
fn goal_equal_to_start_is_named() {
    assert_rejected(
        &GOOD.replacen("goal_nm: (0.0, 1.0)", "goal_nm: (0.0, -1.0)", 1),
        &["ownship.goal_nm"],
    );
}

#[test]
fn ownship_inside_a_target_clearance_is_named() {
    // 0.05 nm = 93 m, inside the default clearance of 200 m.
    assert_rejected(
        &GOOD.replacen("start_nm: (1.0, 0.0)", "start_nm: (0.0, -0.95)", 1),
        &["targets[0]", "start_nm", "clearance"],
    );
}

#[test]
fn duplicate_vessel_names_are_named() {
    let two = format!(
        "{TS1}\n        {}",
        TS1.replacen("(1.0, 0.0)", "(2.0, 0.0)", 1)
    );
    assert_rejected(
        &GOOD.replacen(TS1, &two, 1),
        &["targets[1]", "name", "unique"],
    );
}

#[test]
fn more_than_max_targets_are_refused() {
    let many = (0..=vorrt_scenarios::MAX_TARGETS).fold(String::new(), |mut many, index| {
        writeln!(
            many,
            "Vessel(name: \"T{index}\", start_nm: ({}, 2.0), course_deg: 0.0, speed_kn: 5.0, length_m: 50.0),",
            f64::from(u32::try_from(index).unwrap()) * 0.2 - 25.0
        )
        .unwrap();
        many
    });
    assert_rejected(&GOOD.replacen(TS1, &many, 1), &["targets", "257", "256"]);
}

#[test]
fn zero_width_lane_is_named() {
    let text = GOOD.replacen(
        "seed: 3,",
        "seed: 3,\n    lanes: [Lane(name: \"westbound\", from_nm: (3.0, 0.5), to_nm: (-3.0, 0.5), width_nm: 0.0)],",
        1,
    );
    assert_rejected(&text, &["lanes[0]", "width_nm"]);
}

#[test]
fn a_missing_file_exits_2() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("absent.ron");
    let output = Command::new(env!("CARGO_BIN_EXE_vorrt-cli"))
        .args(["check", path.to_str().unwrap()])
        .output()
        .unwrap();
    let message = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{message}");
    assert!(message.contains("absent.ron"), "{message}");
    assert!(!message.contains("panicked"), "{message}");
    assert!(!Path::new(&path).exists());
}

#[test]
fn an_empty_target_list_is_valid() {
    let (output, message) = check(&GOOD.replacen(TS1, "", 1));
    assert_eq!(output.status.code(), Some(0), "stderr: {message}");
    let (output, message) =
        check(&GOOD.replacen(&format!("targets: [\n        {TS1}\n    ],"), "", 1));
    assert_eq!(output.status.code(), Some(0), "stderr: {message}");
}
