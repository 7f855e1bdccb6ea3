//! `replay.html` end to end through the binary: written by `simulate`,
//! `judge` and `demo`, self-contained (no URL it would fetch), its inline
//! JSON parses and holds the run's samples, and a `</script>` in a
//! scenario name cannot break out of the data element. The page's drawing
//! is tested in a browser by `scripts/browser/run.sh`.

use serde_json::Value;
use std::path::{Path, PathBuf};
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

fn assert_ran(output: &Output) {
    let code = output.status.code();
    assert!(
        code == Some(0) || code == Some(1),
        "exit {code:?}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
}

/// A scenario whose name and description try to end the page's script.
const HOSTILE: &str = r#"Scenario(
    name: "x</script><script>window.broken=1</script><!--",
    description: "A short crossing </SCRIPT> & <b>bold</b>.",
    ownship: Vessel(name: "own</script>", start_nm: (0.0, -1.0), course_deg: 0.0,
                    speed_kn: 12.0, length_m: 100.0, goal_nm: (0.0, 1.0)),
    targets: [
        Vessel(name: "TS1", start_nm: (1.0, 0.0), course_deg: 270.0, speed_kn: 12.0,
               length_m: 150.0, goal_nm: (-1.5, 0.0)),
    ],
    seed: 3,
)
"#;

/// The data element's JSON, parsed; panics unless the page has exactly the
/// one data element and the one script, each closed once.
fn replay_data(html: &str) -> Value {
    const OPEN: &str = "<script id=\"vorrt-data\" type=\"application/json\">";
    assert_eq!(html.matches(OPEN).count(), 1, "one data element");
    assert_eq!(
        html.to_ascii_lowercase().matches("</script").count(),
        2,
        "only the data element and the page's script end a script"
    );
    let start = html.find(OPEN).unwrap() + OPEN.len();
    let end = start + html[start..].find("</script>").unwrap();
    serde_json::from_str(&html[start..end]).expect("the inline data is JSON")
}

/// No address the page would fetch: no `src` or `href` to anything but
/// an anchor, no `http(s)://` at all.
fn assert_self_contained(html: &str) {
    let lower = html.to_ascii_lowercase();
    assert!(!lower.contains("http://") && !lower.contains("https://"));
    assert!(
        !lower.contains("src="),
        "no external script, image or frame"
    );
    assert!(!lower.contains("href="), "no stylesheet or link");
    assert!(!lower.contains("@import") && !lower.contains("url("));
}

/// The running sums of a delta-coded column, over `scale`.
fn decode(column: &Value, scale: f64) -> Vec<f64> {
    let mut sum = 0_i64;
    column
        .as_array()
        .unwrap()
        .iter()
        .map(|delta| {
            sum += delta.as_i64().unwrap();
            #[expect(clippy::cast_precision_loss, reason = "decimetres of a sea area")]
            let value = sum as f64 / scale;
            value
        })
        .collect()
}

/// `trajectory.csv`'s `(time_s, east_m, north_m)` rows of `vessel`.
fn csv_rows(path: &Path, vessel: &str) -> Vec<(f64, f64, f64)> {
    let mut reader = csv::Reader::from_path(path).unwrap();
    reader
        .records()
        .map(Result::unwrap)
        .filter(|row| &row[1] == vessel)
        .map(|row| {
            (
                row[0].parse().unwrap(),
                row[2].parse().unwrap(),
                row[3].parse().unwrap(),
            )
        })
        .collect()
}

fn simulate_hostile(dir: &Path) -> PathBuf {
    let scenario = dir.join("hostile.ron");
    std::fs::write(&scenario, HOSTILE).unwrap();
    let out = dir.join("out");
    assert_ran(&vorrt(&["simulate", text(&scenario), "--out", text(&out)]));
    out
}

#[test]
fn simulate_writes_a_self_contained_replay_of_every_sample() {
    let dir = tempfile::tempdir().unwrap();
    let out = simulate_hostile(dir.path());
    let html = std::fs::read_to_string(out.join("replay.html")).unwrap();
    assert_self_contained(&html);
    let data = replay_data(&html);
    assert_eq!(
        data["scenario"],
        "x</script><script>window.broken=1</script><!--"
    );
    assert!(
        html.contains("<title>x&lt;/script&gt;"),
        "the title is escaped"
    );
    let report: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap()).unwrap();
    assert_eq!(data["d_th_m"], report["d_th_m"]);
    let own = csv_rows(&out.join("trajectory.csv"), "own</script>");
    let times: Vec<f64> = data["times_s"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| t.as_f64().unwrap())
        .collect();
    assert_eq!(data["step_stride"], 1);
    assert_eq!(times.len(), own.len(), "every recorded step");
    let vessel = &data["vessels"][0];
    assert_eq!(vessel["name"], "own</script>");
    assert_eq!(vessel["role"], "ownship");
    let east = decode(&vessel["track"]["east_dm"], 10.0);
    let north = decode(&vessel["track"]["north_dm"], 10.0);
    for (k, (time_s, east_m, north_m)) in own.iter().enumerate() {
        assert!((times[k] - time_s).abs() < 1e-9);
        assert!((east[k] - east_m).abs() <= 0.05 && (north[k] - north_m).abs() <= 0.05);
    }
    assert_eq!(data["vessels"].as_array().unwrap().len(), 2);
    assert_eq!(
        data["vessels"][1]["encounter"]["encounter"],
        report["targets"][0]["encounter"]
    );
}

#[test]
fn judge_writes_the_replay_of_the_tracks_it_judged() {
    let dir = tempfile::tempdir().unwrap();
    let run = simulate_hostile(dir.path());
    let out = dir.path().join("judged");
    assert_ran(&vorrt(&[
        "judge",
        text(&run.join("trajectory.csv")),
        "--out",
        text(&out),
    ]));
    let html = std::fs::read_to_string(out.join("replay.html")).unwrap();
    assert_self_contained(&html);
    let data = replay_data(&html);
    let judgement: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("judgement.json")).unwrap())
            .unwrap();
    let findings: usize = judgement["targets"]
        .as_array()
        .unwrap()
        .iter()
        .map(|target| target["findings"].as_array().unwrap().len())
        .sum::<usize>()
        + judgement["path_quality"]["findings"]
            .as_array()
            .unwrap()
            .len();
    assert_eq!(data["findings"].as_array().unwrap().len(), findings);
    assert_eq!(
        data["times_s"].as_array().unwrap().len(),
        csv_rows(&run.join("trajectory.csv"), "own</script>").len()
    );
}

#[test]
fn every_demo_run_has_a_replay_linked_from_the_index() {
    let dir = tempfile::tempdir().unwrap();
    let fixtures = dir.path().join("fixtures");
    std::fs::create_dir_all(fixtures.join("paper")).unwrap();
    std::fs::write(fixtures.join("paper/hostile.ron"), HOSTILE).unwrap();
    let out = dir.path().join("demo");
    assert_ran(&vorrt(&[
        "demo",
        "--fixtures",
        text(&fixtures),
        "--out",
        text(&out),
    ]));
    let index = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(
        index.contains("<a href=\"paper/hostile/replay.html\">"),
        "{index}"
    );
    let html = std::fs::read_to_string(out.join("paper/hostile/replay.html")).unwrap();
    assert_self_contained(&html);
    assert!(replay_data(&html)["times_s"].as_array().unwrap().len() > 10);
}
