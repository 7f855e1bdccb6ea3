//! The 27 bundled scenarios (the paper's five and the 22 Imazu cases) in
//! closed loop with seed 1, judged on the track as sailed and as observed:
//! per scenario ownship's largest rate of turn, turn-direction reversals,
//! course change per nautical mile, and every finding, as a markdown table.
//!
//! Run with `cargo run --release --example observed`.
#![allow(clippy::print_stdout)]

use std::process::ExitCode;
use vorrt::scenarios::{Evaluation, bundled_fixtures_dir, evaluate, load_dir, simulate};

/// The seed of every run.
const SEED: u64 = 1;

fn main() -> ExitCode {
    let mut rows = Vec::new();
    for folder in ["paper", "imazu"] {
        let scenarios = match load_dir(&bundled_fixtures_dir().join(folder)) {
            Ok(scenarios) => scenarios,
            Err(error) => {
                eprintln!("{error}");
                return ExitCode::from(2);
            }
        };
        for (_, scenario) in scenarios {
            match simulate(&scenario, SEED) {
                Ok(record) => rows.push(evaluate(&scenario, &record)),
                Err(error) => {
                    eprintln!("{}: {error}", scenario.name);
                    return ExitCode::from(2);
                }
            }
        }
    }
    print_markdown(&rows);
    ExitCode::SUCCESS
}

/// The give-way encounters of a run: (action range in nm if begun, largest
/// alteration in degrees).
fn give_way(evaluation: &Evaluation) -> Vec<String> {
    evaluation
        .targets
        .iter()
        .filter(|target| target.role == vorrt::colregs::Role::GiveWay)
        .map(|target| {
            format!(
                "{} {}: {} / {:+.0}°",
                target.name,
                target.encounter,
                target.action_range_m.map_or_else(
                    || "-".to_owned(),
                    |range| format!("{:.1} nm", range / 1852.0)
                ),
                target.max_alteration_deg.unwrap_or(0.0),
            )
        })
        .collect()
}

/// Every finding of a run: track findings, then per target the names of the
/// findings.
fn findings(evaluation: &Evaluation) -> String {
    let mut all: Vec<String> = evaluation.track_findings.clone();
    for target in &evaluation.targets {
        if !target.findings.is_empty() {
            let names: Vec<&str> = target
                .findings
                .iter()
                .map(vorrt::colregs::ComplianceViolation::name)
                .collect();
            all.push(format!("{}: {}", target.name, names.join(", ")));
        }
    }
    if all.is_empty() {
        "-".to_owned()
    } else {
        all.join("; ")
    }
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    match values.len() {
        0 => 0.0,
        n if n % 2 == 1 => values[n / 2],
        n => 0.5 * (values[n / 2 - 1] + values[n / 2]),
    }
}

fn print_markdown(rows: &[Evaluation]) {
    println!(
        "| scenario | goal | min dist [m] | largest rate of turn [°/s] (limit) | reversals | course change [°/nm] | give way: action range / largest alteration | no finding | findings |"
    );
    println!("|---|---|---:|---:|---:|---:|---|---|---|");
    for row in rows {
        println!(
            "| {} | {} | {:.0} | {:.2} ({}) | {} | {:.1} | {} | {} | {} |",
            row.scenario,
            if row.reached_goal { "yes" } else { "no" },
            row.min_distance_m,
            row.max_turn_rate_deg_s,
            row.turn_rate_limit_deg_s
                .map_or_else(|| "none".to_owned(), |limit| format!("{limit:.2}")),
            row.turn_reversals,
            row.course_change_deg_per_nm,
            give_way(row).join("; "),
            if row.compliant { "yes" } else { "no" },
            findings(row),
        );
    }
    let count = rows.len();
    let give_way_targets: Vec<_> = rows
        .iter()
        .flat_map(|row| &row.targets)
        .filter(|target| target.role == vorrt::colregs::Role::GiveWay)
        .collect();
    let apparent = give_way_targets
        .iter()
        .filter(|target| {
            target
                .max_alteration_deg
                .is_some_and(|deg| deg.abs() >= 30.0)
        })
        .count();
    let early = give_way_targets
        .iter()
        .filter(|target| {
            !target
                .findings
                .iter()
                .any(|f| matches!(f.name(), "late_action" | "no_action"))
        })
        .count();
    #[expect(clippy::cast_precision_loss, reason = "a count of turn reversals")]
    let reversals: Vec<f64> = rows.iter().map(|row| row.turn_reversals as f64).collect();
    println!();
    println!(
        "{count} runs: median reversals {:.1}, median course change {:.1}°/nm, largest rate of turn {:.2}°/s; \
         {} of {} give-way encounters readily apparent by course, {} begun early; {} of {count} runs with no finding, \
         {} with d_th kept, {} reached the goal.",
        median(reversals),
        median(
            rows.iter()
                .map(|row| row.course_change_deg_per_nm)
                .collect()
        ),
        rows.iter()
            .map(|row| row.max_turn_rate_deg_s)
            .fold(0.0, f64::max),
        apparent,
        give_way_targets.len(),
        early,
        rows.iter().filter(|row| row.compliant).count(),
        rows.iter().filter(|row| row.clearance_kept).count(),
        rows.iter().filter(|row| row.reached_goal).count(),
    );
}
