//! `docs/report-format.md` against the real outputs of the `vorrt` binary.
//!
//! The doc's examples and field tables cannot go stale: each documented
//! command is run here, every field of the real output must be named in the
//! doc's tables for that file and every name in those tables must be a field
//! of the real output, and every value an example shows must be the value
//! the command gives now (wall-clock planning times excepted).
//!
//! An example in the doc is the fenced block after a marker line
//! `<!-- example: NAME -->`; a JSON example may leave fields out (`…` lines
//! are dropped before parsing), a CSV example shows the first lines of the
//! file. A section is a `## ` heading; its fields are the backticked names in
//! the first column of its tables.

use serde_json::Value;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Runs the binary from the workspace root, so that scenario paths read as
/// the doc writes them (`crates/scenarios/fixtures/paper/head_on.ron`).
fn vorrt(args: &[&str]) -> Output {
    let output = Command::new(env!("CARGO_BIN_EXE_vorrt-cli"))
        .args(args)
        .current_dir(workspace_root())
        .output()
        .expect("the vorrt binary runs");
    assert!(
        output.status.success(),
        "vorrt {args:?} failed: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    output
}

fn doc() -> String {
    std::fs::read_to_string(workspace_root().join("docs/report-format.md"))
        .expect("docs/report-format.md is readable")
}

/// The text of the `## ` section whose heading contains `heading`.
fn section<'a>(doc: &'a str, heading: &str) -> &'a str {
    let start = doc
        .match_indices("\n## ")
        .map(|(at, _)| at + 1)
        .find(|&at| {
            doc[at..]
                .lines()
                .next()
                .is_some_and(|l| l.contains(heading))
        })
        .unwrap_or_else(|| panic!("no section {heading:?} in docs/report-format.md"));
    let end = doc[start + 3..]
        .find("\n## ")
        .map_or(doc.len(), |at| start + 3 + at);
    &doc[start..end]
}

/// The backticked names in the first column of the section's tables.
fn documented_fields(section: &str) -> BTreeSet<String> {
    let mut fields = BTreeSet::new();
    for line in section.lines() {
        let Some(row) = line.strip_prefix('|') else {
            continue;
        };
        let first = row.split('|').next().unwrap_or_default();
        for (index, name) in first.split('`').enumerate() {
            if index % 2 == 1 {
                fields.insert(name.to_owned());
            }
        }
    }
    fields
}

/// The fenced block after `<!-- example: NAME -->`.
fn example(doc: &str, name: &str) -> String {
    let marker = format!("<!-- example: {name} -->");
    let at = doc
        .find(&marker)
        .unwrap_or_else(|| panic!("no example {name:?} in docs/report-format.md"));
    let rest = &doc[at + marker.len()..];
    let open = rest.find("```").expect("a fenced block after the marker");
    let body = &rest[open..];
    let body = &body[body.find('\n').expect("a fence line") + 1..];
    let close = body.find("\n```").expect("the fence is closed");
    body[..=close].to_owned()
}

/// A JSON example, with the `…` lines that stand for left-out fields dropped.
fn json_example(doc: &str, name: &str) -> Value {
    let text: String = example(doc, name)
        .lines()
        .filter(|line| !line.trim().starts_with('…'))
        .flat_map(|line| [line, "\n"])
        .collect();
    serde_json::from_str(&text).unwrap_or_else(|error| panic!("example {name:?}: {error}"))
}

const PERCENTILES: [&str; 9] = [
    "count", "min", "p1", "p10", "p50", "p90", "p99", "max", "mean",
];

/// Field paths of `value`: `a`, `a.b`, `list[].field` (an array's objects
/// by their first element). A percentiles object (`summary.json`) is a leaf;
/// its own fields go into `percentile_fields`.
fn field_paths(value: &Value, prefix: &str, paths: &mut BTreeSet<String>) {
    let Value::Object(map) = value else {
        if let Value::Array(items) = value
            && let Some(first) = items.first()
        {
            field_paths(first, &format!("{prefix}[]"), paths);
        }
        return;
    };
    let is_percentiles =
        map.len() == PERCENTILES.len() && PERCENTILES.iter().all(|key| map.contains_key(*key));
    if is_percentiles && !prefix.is_empty() {
        paths.extend(PERCENTILES.iter().map(|key| (*key).to_owned()));
        return;
    }
    for (key, child) in map {
        let path = if prefix.is_empty() {
            key.clone()
        } else {
            format!("{prefix}.{key}")
        };
        paths.insert(path.clone());
        field_paths(child, &path, paths);
    }
}

fn assert_same_fields(real: &BTreeSet<String>, documented: &BTreeSet<String>, what: &str) {
    let undocumented: Vec<_> = real.difference(documented).collect();
    let unknown: Vec<_> = documented.difference(real).collect();
    assert!(
        undocumented.is_empty() && unknown.is_empty(),
        "{what}: fields not in docs/report-format.md: {undocumented:?}; \
         documented but not in the output: {unknown:?}"
    );
}

/// Wall-clock times: the one thing a rerun changes.
fn varies(key: &str) -> bool {
    key.contains("planning_time") || key == "wall_time_s"
}

fn numbers_match(shown: f64, real: f64) -> bool {
    (shown - real).abs() <= 1e-9 * (1.0 + real.abs())
}

/// Every value `shown` holds is the value `real` holds at the same place.
fn assert_shown_matches(shown: &Value, real: &Value, path: &str) {
    match (shown, real) {
        (Value::Object(shown), Value::Object(real)) => {
            for (key, value) in shown {
                let inner = format!("{path}.{key}");
                let other = real
                    .get(key)
                    .unwrap_or_else(|| panic!("{inner}: in the doc's example, not in the output"));
                if !varies(key) {
                    assert_shown_matches(value, other, &inner);
                }
            }
        }
        (Value::Array(shown), Value::Array(real)) => {
            assert_eq!(shown.len(), real.len(), "{path}: length");
            for (index, (a, b)) in shown.iter().zip(real).enumerate() {
                assert_shown_matches(a, b, &format!("{path}[{index}]"));
            }
        }
        (Value::Number(a), Value::Number(b)) => {
            let (a, b) = (
                a.as_f64().unwrap_or(f64::NAN),
                b.as_f64().unwrap_or(f64::NAN),
            );
            assert!(
                numbers_match(a, b),
                "{path}: the doc shows {a}, the output is {b}"
            );
        }
        _ => assert_eq!(
            shown, real,
            "{path}: the doc's example differs from the output"
        ),
    }
}

/// The shown CSV lines are the first lines of `real`, cell by cell.
fn assert_csv_prefix(shown: &str, real: &str, what: &str) {
    let real_lines: Vec<&str> = real.lines().collect();
    let header: Vec<&str> = real_lines
        .first()
        .map(|h| h.split(',').collect())
        .unwrap_or_default();
    for (number, line) in shown.lines().enumerate() {
        let other = real_lines
            .get(number)
            .unwrap_or_else(|| panic!("{what}: the doc shows more lines than the output has"));
        let cells: Vec<&str> = line.split(',').collect();
        let real_cells: Vec<&str> = other.split(',').collect();
        assert_eq!(cells.len(), real_cells.len(), "{what} line {number}: cells");
        for (column, (a, b)) in cells.iter().zip(&real_cells).enumerate() {
            let name = header.get(column).copied().unwrap_or_default();
            if number > 0 && varies(name) {
                continue;
            }
            let same = match (a.parse::<f64>(), b.parse::<f64>()) {
                (Ok(x), Ok(y)) => numbers_match(x, y),
                _ => a == b,
            };
            assert!(
                same,
                "{what} line {number}, {name}: the doc shows {a}, the output is {b}"
            );
        }
    }
}

fn read_json(path: &Path) -> Value {
    let text = std::fs::read_to_string(path).expect("the output file is readable");
    serde_json::from_str(&text).expect("the output file is JSON")
}

#[test]
fn report_json_fields_and_example_match_a_run() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("head_on");
    vorrt(&[
        "simulate",
        "crates/scenarios/fixtures/paper/head_on.ron",
        "--out",
        out.to_str().unwrap(),
    ]);
    let report = read_json(&out.join("report.json"));
    let doc = doc();
    let mut real = BTreeSet::new();
    field_paths(&report, "", &mut real);
    assert_same_fields(
        &real,
        &documented_fields(section(&doc, "`report.json`")),
        "report.json",
    );
    assert_shown_matches(&json_example(&doc, "report.json"), &report, "report.json");

    let trajectory = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    let columns = documented_fields(section(&doc, "Trajectories"));
    for column in trajectory.lines().next().unwrap().split(',') {
        assert!(
            columns.contains(column),
            "trajectory.csv column {column} is not documented"
        );
    }
}

#[test]
fn geographic_trajectory_example_matches_a_run() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("geo");
    vorrt(&[
        "simulate",
        "crates/scenarios/fixtures/geo/channel_ais.ron",
        "--out",
        out.to_str().unwrap(),
    ]);
    let trajectory = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    let doc = doc();
    let columns = documented_fields(section(&doc, "Trajectories"));
    for column in trajectory.lines().next().unwrap().split(',') {
        assert!(
            columns.contains(column),
            "trajectory.csv column {column} is not documented"
        );
    }
    assert_csv_prefix(
        &example(&doc, "trajectory.csv"),
        &trajectory,
        "trajectory.csv",
    );
}

#[test]
fn plan_output_fields_and_example_match_a_run() {
    let output = vorrt(&["plan", "crates/scenarios/fixtures/paper/crossing.ron"]);
    let plan: Value = serde_json::from_slice(&output.stdout).expect("plan prints JSON");
    let doc = doc();
    let mut real = BTreeSet::new();
    field_paths(&plan, "", &mut real);
    let documented = documented_fields(section(&doc, "`vorrt plan` output"));
    assert_same_fields(&real, &documented, "plan output");
    assert_shown_matches(&json_example(&doc, "plan"), &plan, "plan");
}

#[test]
fn batch_outputs_fields_and_examples_match_a_run() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("batch");
    vorrt(&[
        "batch",
        "--generate",
        "open-sea",
        "--targets",
        "1",
        "--count",
        "2",
        "--seed",
        "11",
        "--out",
        out.to_str().unwrap(),
    ]);
    let doc = doc();

    let rows = std::fs::read_to_string(out.join("rows.csv")).unwrap();
    let header: BTreeSet<String> = rows
        .lines()
        .next()
        .unwrap()
        .split(',')
        .map(str::to_owned)
        .collect();
    assert_same_fields(
        &header,
        &documented_fields(section(&doc, "`rows.csv`")),
        "rows.csv",
    );
    assert_csv_prefix(&example(&doc, "rows.csv"), &rows, "rows.csv");

    let summary = read_json(&out.join("summary.json"));
    let mut real = BTreeSet::new();
    field_paths(&summary, "", &mut real);
    assert_same_fields(
        &real,
        &documented_fields(section(&doc, "`summary.json`")),
        "summary.json",
    );
    assert_shown_matches(
        &json_example(&doc, "summary.json"),
        &summary,
        "summary.json",
    );

    // run.json: its top-level fields; a merge adds the shards it merged.
    let merged = dir.path().join("merged");
    vorrt(&[
        "merge",
        "--out",
        merged.to_str().unwrap(),
        out.to_str().unwrap(),
    ]);
    let mut real: BTreeSet<String> = BTreeSet::new();
    for run in [
        read_json(&out.join("run.json")),
        read_json(&merged.join("run.json")),
    ] {
        real.extend(run.as_object().unwrap().keys().cloned());
    }
    // Written only when a merge lacks some shards of the batch.
    real.insert("missing_shards".to_owned());
    assert_same_fields(
        &real,
        &documented_fields(section(&doc, "`run.json`")),
        "run.json",
    );
}

/// Decision 45: on Imazu problem 16 ownship departs from its stand-on course
/// for TS1 while it gives way to another vessel; each entry of
/// `targets[].stand_on_departures` has exactly the fields the doc's
/// "Stand-on departures" section names, and the duty is named.
#[test]
fn stand_on_departure_fields_match_a_run() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("imazu_16");
    vorrt(&[
        "simulate",
        "crates/scenarios/fixtures/imazu/imazu_16.ron",
        "--out",
        out.to_str().unwrap(),
    ]);
    let report = read_json(&out.join("report.json"));
    let departures: Vec<&Value> = report["targets"]
        .as_array()
        .expect("targets")
        .iter()
        .flat_map(|target| {
            target["stand_on_departures"]
                .as_array()
                .into_iter()
                .flatten()
        })
        .collect();
    let justified = departures
        .iter()
        .find(|d| d["justified"] == Value::Bool(true))
        .expect("a justified stand-on departure on imazu_16");
    assert_eq!(
        justified["precedence"], "keep_out_of_the_way",
        "{justified}"
    );
    assert_eq!(justified["rule"], "16, 2(b)", "{justified}");
    let mut real = BTreeSet::new();
    field_paths(justified, "", &mut real);
    assert_same_fields(
        &real,
        &documented_fields(section(&doc(), "Stand-on departures")),
        "targets[].stand_on_departures[]",
    );
}
