//! End-to-end tests of `vorrt batch`, `vorrt generate` and `vorrt merge`.

use std::path::Path;
use std::process::{Command, Output};
use vorrt_scenarios::batch::{BatchSummary, read_csv};

fn vorrt(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_vorrt-cli"))
        .args(args)
        .output()
        .expect("the vorrt binary runs")
}

fn ok(output: &Output) {
    assert!(
        output.status.success(),
        "stdout: {}\nstderr: {}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
}

fn path_str(path: &Path) -> &str {
    path.to_str().expect("test paths are UTF-8")
}

fn summary(dir: &Path) -> BatchSummary {
    let text = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

#[test]
fn sharded_batch_merges_into_the_unsharded_one() {
    let temp = tempfile::tempdir().unwrap();
    let out = |name: &str| temp.path().join(name);
    let common = [
        "batch",
        "--generate",
        "open-sea",
        "--targets",
        "2",
        "--count",
        "5",
        "--seed",
        "9",
        "--jobs",
        "1",
    ];
    let run = |extra: &[&str], dir: &Path| {
        let mut args: Vec<&str> = common.to_vec();
        args.extend_from_slice(extra);
        args.extend_from_slice(&["--out", path_str(dir)]);
        ok(&vorrt(&args));
    };
    run(&[], &out("whole"));
    run(&["--shard", "0/2"], &out("s0"));
    run(&["--shard", "1/2"], &out("s1"));
    for file in [
        "rows.csv",
        "summary.json",
        "run.json",
        "min_distance.svg",
        "planning_time.svg",
    ] {
        assert!(out("whole").join(file).is_file(), "{file}");
    }
    let output = vorrt(&[
        "merge",
        path_str(&out("s0")),
        path_str(&out("s1")),
        "--out",
        path_str(&out("merged")),
    ]);
    ok(&output);
    let whole = read_csv(&out("whole").join("rows.csv")).unwrap();
    let merged = read_csv(&out("merged").join("rows.csv")).unwrap();
    assert_eq!(whole.len(), 5);
    assert_eq!(
        read_csv(&out("s0").join("rows.csv")).unwrap().len(),
        3,
        "indices 0, 2, 4"
    );
    for (a, b) in whole.iter().zip(&merged) {
        assert_eq!(a.index, b.index);
        assert_eq!(a.name, b.name);
        assert_eq!(a.seed, b.seed);
        assert_eq!(a.min_distance_m.to_bits(), b.min_distance_m.to_bits());
        assert_eq!(a.replans, b.replans);
    }
    let (mut a, b) = (summary(&out("whole")), summary(&out("merged")));
    assert_eq!(a.count, 5);
    // Wall-clock times differ between runs; everything else is equal.
    a.planning_time_ms = b.planning_time_ms;
    a.planning_time_per_plan_ms = b.planning_time_per_plan_ms;
    assert_eq!(a, b);
}

#[test]
fn generate_writes_the_scenarios_batch_runs() {
    let temp = tempfile::tempdir().unwrap();
    let files = temp.path().join("files");
    ok(&vorrt(&[
        "generate",
        "tss",
        "--density",
        "1",
        "--direction",
        "two-way",
        "--count",
        "2",
        "--seed",
        "4",
        "--out",
        path_str(&files),
    ]));
    let written: Vec<_> = std::fs::read_dir(&files).unwrap().collect();
    assert_eq!(written.len(), 2);
    // Checked by `vorrt check`, and run from the folder with the same seeds
    // as a generated batch.
    let from_dir = temp.path().join("from-dir");
    ok(&vorrt(&[
        "batch",
        "--dir",
        path_str(&files),
        "--out",
        path_str(&from_dir),
    ]));
    let generated = temp.path().join("generated");
    ok(&vorrt(&[
        "batch",
        "--generate",
        "tss",
        "--density",
        "1",
        "--direction",
        "two-way",
        "--count",
        "2",
        "--seed",
        "4",
        "--out",
        path_str(&generated),
    ]));
    let a = read_csv(&from_dir.join("rows.csv")).unwrap();
    let b = read_csv(&generated.join("rows.csv")).unwrap();
    for (a, b) in a.iter().zip(&b) {
        assert_eq!((&a.name, a.seed, a.replans), (&b.name, b.seed, b.replans));
        assert_eq!(a.min_distance_m.to_bits(), b.min_distance_m.to_bits());
    }
}

#[test]
fn bad_batch_options_exit_2() {
    let temp = tempfile::tempdir().unwrap();
    let out = path_str(temp.path());
    for args in [
        vec!["batch", "--generate", "open-sea", "--out", out],
        vec![
            "batch",
            "--generate",
            "open-sea",
            "--targets",
            "257",
            "--out",
            out,
        ],
        vec!["batch", "--generate", "tss", "--targets", "3", "--out", out],
        vec![
            "batch",
            "--generate",
            "open-sea",
            "--targets",
            "2",
            "--shard",
            "2/2",
            "--out",
            out,
        ],
        vec!["batch", "--out", out],
        vec!["merge", "/nonexistent/shard", "--out", out],
    ] {
        let output = vorrt(&args);
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        assert!(
            String::from_utf8_lossy(&output.stderr).contains("error"),
            "{args:?}"
        );
    }
}

/// The saved scenario files of `dir/folder`, sorted (none without the folder).
fn saved(dir: &Path, folder: &str) -> Vec<String> {
    let mut files: Vec<String> = std::fs::read_dir(dir.join(folder))
        .map(|entries| {
            entries
                .map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    files.sort();
    files
}

#[test]
fn progress_headline_and_saved_runs_count_colregs() {
    let temp = tempfile::tempdir().unwrap();
    let out = temp.path().join("batch");
    // Targets that turn unannounced: some runs succeed with a finding.
    let output = vorrt(&[
        "batch",
        "--generate",
        "open-sea",
        "--targets",
        "2",
        "--behaviour",
        "sudden-turn",
        "--count",
        "12",
        "--seed",
        "3",
        "--jobs",
        "1",
        "--out",
        path_str(&out),
    ]);
    ok(&output);
    let rows = read_csv(&out.join("rows.csv")).unwrap();
    let with_findings: Vec<_> = rows
        .iter()
        .filter(|row| row.success() && !row.compliant)
        .collect();
    assert!(
        !with_findings.is_empty(),
        "the premise: a run that succeeded with a finding"
    );
    let log = String::from_utf8_lossy(&output.stderr);
    for row in &rows {
        let label = if !row.success() {
            "unsafe (".to_owned()
        } else if row.compliant {
            "compliant, min".to_owned()
        } else {
            format!("findings: {}", row.violations)
        };
        let line = format!("{}: {label}", row.name);
        assert!(log.contains(&line), "no {line:?} in {log}");
    }
    assert!(!log.contains(": ok"), "{log}");
    let summary = summary(&out);
    let headline = format!(
        "success              {:.1} %   compliant {:.1} %",
        100.0 * summary.success_rate,
        100.0 * summary.compliance_rate
    );
    let printed = String::from_utf8_lossy(&output.stdout);
    assert!(printed.contains(&headline), "{printed}");
    assert!(printed.contains("time overhead %"), "{printed}");
    let name = |row: &vorrt_scenarios::BatchRow| format!("{:06}-{}.ron", row.index, row.name);
    assert_eq!(
        saved(&out, "findings"),
        with_findings
            .iter()
            .map(|row| name(row))
            .collect::<Vec<_>>()
    );
    assert_eq!(
        saved(&out, "failures"),
        rows.iter()
            .filter(|row| !row.success())
            .map(name)
            .collect::<Vec<_>>()
    );
    // The time overhead is in the rows and summarised like the path's.
    assert!(rows.iter().all(|row| row.time_overhead_pct.is_finite()));
    assert_eq!(summary.time_overhead_pct.count, rows.len());
}

#[test]
fn a_coastal_batch_writes_land_rows_and_generate_coastal_writes_files_with_land() {
    let temp = tempfile::tempdir().unwrap();
    let out = temp.path().join("coastal");
    ok(&vorrt(&[
        "batch",
        "--generate",
        "coastal",
        "--count",
        "3",
        "--seed",
        "11",
        "--jobs",
        "1",
        "--out",
        path_str(&out),
    ]));
    let summary = summary(&out);
    assert_eq!(summary.count, 3);
    assert_eq!(summary.groundings, 0);
    assert_eq!(summary.land_clearance_violations, 0);
    assert!(summary.min_land_distance_m.count == 3, "{summary:?}");
    let files = temp.path().join("files");
    ok(&vorrt(&[
        "generate",
        "coastal",
        "--count",
        "2",
        "--seed",
        "11",
        "--out",
        path_str(&files),
    ]));
    for entry in std::fs::read_dir(&files).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(text.contains("island"), "{}", path.display());
        ok(&vorrt(&["check", path_str(&path)]));
    }
    let refused = vorrt(&[
        "batch",
        "--generate",
        "coastal",
        "--density",
        "1",
        "--out",
        path_str(&out),
    ]);
    assert!(!refused.status.success());
    assert!(String::from_utf8_lossy(&refused.stderr).contains("--density"));
}
