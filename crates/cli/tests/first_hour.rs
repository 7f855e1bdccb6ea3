//! End-to-end tests of what a new user meets in the first hour (issue 14):
//! output that cannot be written, long routes, long runs, batch output
//! folders, merging, failures, start states in collision, long names,
//! readable messages and bad options. Each fails without its fix.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

fn binary() -> Command {
    Command::new(env!("CARGO_BIN_EXE_vorrt-cli"))
}

fn vorrt(args: &[&str]) -> Output {
    binary().args(args).output().expect("the vorrt binary runs")
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

fn stdout(output: &Output) -> String {
    String::from_utf8_lossy(&output.stdout).into_owned()
}

fn path_str(path: &Path) -> &str {
    path.to_str().expect("test paths are UTF-8")
}

fn no_panic(output: &Output) {
    let text = stderr(output);
    assert!(!text.contains("panicked"), "{text}");
    assert_ne!(output.status.code(), Some(101), "{text}");
}

/// A short crossing, quick in debug builds; `{name}`, `{own}` (ownship's
/// start and goal, nm), `{len}` (target length, m), `{extra}` replaced.
const TEMPLATE: &str = r#"Scenario(
    name: "{name}",
    ownship: Vessel(name: "ownship", start_nm: {own_start}, course_deg: 0.0,
                    speed_kn: 12.0, length_m: 100.0, goal_nm: {own_goal}),
    targets: [
        Vessel(name: "TS1", start_nm: {target_start}, course_deg: 270.0, speed_kn: {speed},
               length_m: {len}, goal_nm: (-16.0, 0.0)),
    ],
    {extra}
    seed: 3,
)
"#;

struct Spec<'a> {
    name: &'a str,
    own_start: &'a str,
    own_goal: &'a str,
    target_start: &'a str,
    speed: &'a str,
    len: &'a str,
    extra: &'a str,
}

const SMALL: Spec<'static> = Spec {
    name: "small crossing",
    own_start: "(0.0, -1.0)",
    own_goal: "(0.0, 1.0)",
    target_start: "(1.0, 0.0)",
    speed: "12.0",
    len: "150.0",
    extra: "",
};

fn write(dir: &Path, file: &str, spec: &Spec<'_>) -> PathBuf {
    let text = TEMPLATE
        .replace("{name}", spec.name)
        .replace("{own_start}", spec.own_start)
        .replace("{own_goal}", spec.own_goal)
        .replace("{target_start}", spec.target_start)
        .replace("{speed}", spec.speed)
        .replace("{len}", spec.len)
        .replace("{extra}", spec.extra);
    let path = dir.join(file);
    std::fs::write(&path, text).unwrap();
    path
}

// 1. Output that cannot be written.

#[test]
fn plan_into_a_full_disk_says_so_and_exits_2() {
    let temp = tempfile::tempdir().unwrap();
    let scenario = write(temp.path(), "small.ron", &SMALL);
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .expect("/dev/full exists on Linux");
    let output = binary()
        .args(["plan", path_str(&scenario)])
        .stdout(full)
        .output()
        .unwrap();
    no_panic(&output);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("cannot write to standard output"),
        "{}",
        stderr(&output)
    );
}

/// Runs `args` with standard output a pipe whose reader has already left.
fn into_closed_pipe(args: &[&str]) -> Output {
    let mut child = binary()
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    child.wait_with_output().unwrap()
}

#[test]
fn simulate_into_a_closed_pipe_ends_quietly_and_writes_its_files() {
    let temp = tempfile::tempdir().unwrap();
    let scenario = write(temp.path(), "small.ron", &SMALL);
    let out = temp.path().join("out");
    let output = into_closed_pipe(&["simulate", path_str(&scenario), "--out", path_str(&out)]);
    no_panic(&output);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert!(out.join("report.json").is_file());
    assert!(out.join("distance.png").is_file());
}

#[test]
fn demo_into_a_closed_pipe_still_writes_index_html() {
    let temp = tempfile::tempdir().unwrap();
    let fixtures = temp.path().join("scenarios");
    std::fs::create_dir_all(&fixtures).unwrap();
    write(&fixtures, "a.ron", &SMALL);
    write(
        &fixtures,
        "b.ron",
        &Spec {
            name: "other",
            ..SMALL
        },
    );
    let out = temp.path().join("demo");
    let output = into_closed_pipe(&[
        "demo",
        "--fixtures",
        path_str(&fixtures),
        "--out",
        path_str(&out),
    ]);
    no_panic(&output);
    assert!(out.join("index.html").is_file(), "{}", stderr(&output));
}

// 2. Long routes plan with default settings.

const LONG: Spec<'static> = Spec {
    name: "long crossing",
    own_start: "(0.0, -15.0)",
    own_goal: "(0.0, 15.0)",
    target_start: "(15.0, 0.0)",
    speed: "12.0",
    len: "150.0",
    extra: "",
};

#[test]
fn a_30_nm_route_plans_with_default_settings() {
    let temp = tempfile::tempdir().unwrap();
    let scenario = write(temp.path(), "long.ron", &LONG);
    let output = vorrt(&["plan", path_str(&scenario)]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    // Without the scaling, the error names the node budget as the cause.
    let fixed = write(
        temp.path(),
        "fixed.ron",
        &Spec {
            extra: "planner: (nodes_per_route_step: 0.0, instant_turns: true),",
            ..LONG
        },
    );
    let output = vorrt(&["plan", path_str(&fixed)]);
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("node budget is too small"),
        "{}",
        stderr(&output)
    );
}

// 3. Long runs show progress; extreme routes are refused with the limit.

// A line every millisecond: the run takes longer than that even in a
// release build (at 0.02 s a fast machine finished first, once).
#[test]
fn a_long_simulation_shows_progress_on_stderr() {
    let temp = tempfile::tempdir().unwrap();
    let scenario = write(temp.path(), "long.ron", &LONG);
    let output = binary()
        .args([
            "simulate",
            path_str(&scenario),
            "--out",
            path_str(&temp.path().join("out")),
        ])
        .env("VORRT_PROGRESS_EVERY_S", "0.001")
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("simulating") && stderr(&output).contains("still running"),
        "{}",
        stderr(&output)
    );
}

#[test]
fn check_refuses_a_route_too_long_to_plan_naming_the_limit() {
    let temp = tempfile::tempdir().unwrap();
    let scenario = write(
        temp.path(),
        "far.ron",
        &Spec {
            own_start: "(0.0, -4999.0)",
            own_goal: "(0.0, 4999.0)",
            ..LONG
        },
    );
    let started = Instant::now();
    let output = vorrt(&["check", path_str(&scenario)]);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    assert!(stderr(&output).contains("ownship.goal_nm"));
    assert!(
        stderr(&output).contains("more than the 10000"),
        "{}",
        stderr(&output)
    );
    assert!(started.elapsed() < Duration::from_secs(10));
}

// 4. The batch output folder is checked before any scenario runs.

#[test]
fn batch_into_an_unwritable_folder_fails_before_running() {
    let output = vorrt(&[
        "batch",
        "--generate",
        "open-sea",
        "--targets",
        "1",
        "--count",
        "3",
        "--out",
        "/proc/vorrt-cannot-be-here",
    ]);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    let text = stderr(&output);
    assert!(
        text.contains("cannot write into the output folder /proc/vorrt-cannot-be-here"),
        "{text}"
    );
    assert!(!text.contains("running"), "ran scenarios first: {text}");
}

// 5. Merge refuses shards of different batches and reports missing ones.

fn shard(temp: &Path, name: &str, seed: &str, shard: &str) -> PathBuf {
    let out = temp.join(name);
    let output = vorrt(&[
        "batch",
        "--generate",
        "open-sea",
        "--targets",
        "1",
        "--count",
        "2",
        "--seed",
        seed,
        "--shard",
        shard,
        "--jobs",
        "1",
        "--out",
        path_str(&out),
    ]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    out
}

#[test]
fn merge_refuses_mixed_batches_and_reports_missing_shards() {
    let temp = tempfile::tempdir().unwrap();
    let a = shard(temp.path(), "a", "1", "0/2");
    let b = shard(temp.path(), "b", "2", "1/2");
    let merged = temp.path().join("merged");
    let output = vorrt(&[
        "merge",
        path_str(&a),
        path_str(&b),
        "--out",
        path_str(&merged),
    ]);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("seed differ"),
        "{}",
        stderr(&output)
    );

    // A missing shard is an error unless asked for, and nothing is written.
    let output = vorrt(&["merge", path_str(&a), "--out", path_str(&merged)]);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("shards missing from the merge: 1/2"),
        "{}",
        stderr(&output)
    );
    assert!(!merged.join("run.json").exists());

    // --out naming an input is refused before the shard is touched.
    let rows_before = std::fs::read_to_string(a.join("rows.csv")).unwrap();
    let same = a.join("..").join("a");
    let output = vorrt(&[
        "merge",
        path_str(&a),
        "--allow-missing",
        "--out",
        path_str(&same),
    ]);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("would overwrite that shard"),
        "{}",
        stderr(&output)
    );
    assert_eq!(
        std::fs::read_to_string(a.join("rows.csv")).unwrap(),
        rows_before
    );

    let output = vorrt(&[
        "merge",
        path_str(&a),
        "--allow-missing",
        "--out",
        path_str(&merged),
    ]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert!(stderr(&output).contains("missing"), "{}", stderr(&output));
    let run: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(merged.join("run.json")).unwrap()).unwrap();
    assert_eq!(run["missing_shards"], serde_json::json!(["1/2"]));
    assert_eq!(run["merged_shards"], serde_json::json!(["0/2"]));
}

// 6. Failures are named by index; an old failures/ folder is cleaned.

#[test]
fn failures_are_named_uniquely_and_old_ones_removed() {
    let temp = tempfile::tempdir().unwrap();
    let dir = temp.path().join("scenarios");
    std::fs::create_dir_all(&dir).unwrap();
    // Two runs with one name, both cut short before the goal: failures.
    let short = Spec {
        name: "crossing",
        extra: "simulation: (max_duration_s: 60.0),",
        ..SMALL
    };
    write(&dir, "a.ron", &short);
    write(&dir, "b.ron", &short);
    let out = temp.path().join("out");
    std::fs::create_dir_all(out.join("failures")).unwrap();
    std::fs::write(out.join("failures/stale.ron"), "old").unwrap();
    let output = vorrt(&["batch", "--dir", path_str(&dir), "--out", path_str(&out)]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let mut files: Vec<String> = std::fs::read_dir(out.join("failures"))
        .unwrap()
        .map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    files.sort();
    assert_eq!(files, ["000000-crossing.ron", "000001-crossing.ron"]);
}

// 7. A start in collision is refused.

#[test]
fn check_refuses_a_start_in_collision_naming_the_vessels() {
    let temp = tempfile::tempdir().unwrap();
    // Two 1000 m ships 300 m apart (more than the 200 m clearance).
    let text = TEMPLATE
        .replace("{name}", "touching")
        .replace("{own_start}", "(0.0, 0.0)")
        .replace("{own_goal}", "(0.0, 3.0)")
        .replace("{target_start}", "(0.162, 0.0)")
        .replace("{speed}", "12.0")
        .replace("{len}", "1000.0")
        .replace("{extra}", "")
        .replace("length_m: 100.0", "length_m: 1000.0");
    let path = temp.path().join("touching.ron");
    std::fs::write(&path, text).unwrap();
    let output = vorrt(&["check", path_str(&path)]);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    let text = stderr(&output);
    assert!(text.contains("targets[0] \"TS1\".start_nm"), "{text}");
    assert!(text.contains("ownship \"ownship\""), "{text}");
    assert!(text.contains("collision"), "{text}");
}

// 8. Names are bounded.

#[test]
fn check_refuses_a_very_long_name_quickly() {
    let temp = tempfile::tempdir().unwrap();
    let name = "x".repeat(1_000_000);
    let path = write(
        temp.path(),
        "long-name.ron",
        &Spec {
            name: &name,
            ..SMALL
        },
    );
    let started = Instant::now();
    let output = vorrt(&["simulate", path_str(&path), "--out", path_str(temp.path())]);
    assert_eq!(output.status.code(), Some(2));
    let text = stderr(&output);
    assert!(text.contains("name holds 1000000 characters, more than the 200 allowed"));
    assert!(text.len() < 1000, "the message repeats the name");
    assert!(started.elapsed() < Duration::from_secs(10));
}

// 9. Messages: readable numbers and the field of a type error.

#[test]
fn messages_show_readable_numbers_and_name_the_field() {
    let temp = tempfile::tempdir().unwrap();
    let huge = write(
        temp.path(),
        "huge.ron",
        &Spec {
            speed: "1e300",
            ..SMALL
        },
    );
    let output = vorrt(&["check", path_str(&huge)]);
    assert_eq!(output.status.code(), Some(2));
    let text = stderr(&output);
    assert!(
        text.contains("is 1.000e300, more than the 100 kn allowed"),
        "{text}"
    );
    assert!(text.len() < 300, "{text}");

    // A limit converted from m/s: a few significant digits, not seventeen.
    let slow = write(
        temp.path(),
        "slow.ron",
        &Spec {
            name: "slow",
            ..SMALL
        },
    );
    let text =
        std::fs::read_to_string(&slow)
            .unwrap()
            .replacen("speed_kn: 12.0", "speed_kn: 0.0001", 1);
    std::fs::write(&slow, text).unwrap();
    let output = vorrt(&["check", path_str(&slow)]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output)
            .contains("ownship.speed_kn is 1.000e-4, ownship must move: at least 0.001944 kn"),
        "{}",
        stderr(&output)
    );

    let wrong = write(
        temp.path(),
        "wrong.ron",
        &Spec {
            speed: "\"fast\"",
            ..SMALL
        },
    );
    let output = vorrt(&["check", path_str(&wrong)]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("targets[0].speed_kn: Expected float"),
        "{}",
        stderr(&output)
    );
}

// 10. Options that mean nothing are refused.

#[test]
fn empty_batches_and_zero_options_are_refused() {
    let temp = tempfile::tempdir().unwrap();
    let out = temp.path().join("out");
    let out = path_str(&out);
    for args in [
        vec![
            "batch",
            "--generate",
            "open-sea",
            "--targets",
            "1",
            "--jobs",
            "0",
            "--out",
            out,
        ],
        vec![
            "batch",
            "--generate",
            "open-sea",
            "--targets",
            "1",
            "--count",
            "0",
            "--out",
            out,
        ],
        vec![
            "generate",
            "open-sea",
            "--targets",
            "1",
            "--count",
            "0",
            "--out",
            out,
        ],
        vec![
            "batch",
            "--generate",
            "open-sea",
            "--targets",
            "1",
            "--count",
            "2",
            "--shard",
            "5/7",
            "--out",
            out,
        ],
    ] {
        let output = vorrt(&args);
        assert_eq!(
            output.status.code(),
            Some(2),
            "{args:?}: {}",
            stderr(&output)
        );
    }
    let empty = temp.path().join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    let output = vorrt(&["batch", "--dir", path_str(&empty), "--out", out]);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("holds no scenario files"),
        "{}",
        stderr(&output)
    );
}

#[test]
fn a_huge_count_split_into_as_many_shards_is_quick() {
    let temp = tempfile::tempdir().unwrap();
    let started = Instant::now();
    let output = vorrt(&[
        "generate",
        "open-sea",
        "--targets",
        "1",
        "--count",
        "1000000000000",
        "--shard",
        "7/1000000000000",
        "--out",
        path_str(temp.path()),
    ]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert!(
        stdout(&output).contains("wrote 1 scenarios"),
        "{}",
        stdout(&output)
    );
    assert!(started.elapsed() < Duration::from_secs(20));
    // One shard that would hold too many is refused with the limit.
    let output = vorrt(&[
        "generate",
        "open-sea",
        "--targets",
        "1",
        "--count",
        "1000000000000",
        "--out",
        path_str(temp.path()),
    ]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("more than the 1000000"),
        "{}",
        stderr(&output)
    );
}

// Issue 10: the bundled scenarios are inside the binary.

#[test]
fn demo_runs_from_an_empty_folder_on_the_embedded_fixtures() {
    let temp = tempfile::tempdir().unwrap();
    let output = binary()
        .args(["demo", "--only", "crossing", "--out", "demo"])
        .current_dir(temp.path())
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let report: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(temp.path().join("demo/paper/crossing/report.json")).unwrap(),
    )
    .unwrap();
    // The name in the repository, not a path of the machine that built it.
    assert_eq!(report["scenario_file"], "fixtures/paper/crossing.ron");
    assert!(temp.path().join("demo/index.html").is_file());
}
