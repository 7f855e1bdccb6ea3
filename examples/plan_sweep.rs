//! Open-loop planner success over the bundled scenarios: every fixture of a
//! folder planned from its start state with seeds 0..N, each with its own
//! planner settings; prints the success rate, the mean path overhead and plan
//! time, and which (scenario, seed) failed. The measure used to tune the
//! planner's defaults (see `docs/architecture.md`).
//!
//! Run with `cargo run --release --example plan_sweep -- [FOLDER] [SEEDS]`;
//! FOLDER defaults to `imazu` (under `crates/scenarios/fixtures/`), SEEDS to 10.
#![allow(clippy::print_stdout)]

use std::process::ExitCode;
use std::time::Instant;
use vorrt::planner::Planner;
use vorrt::scenarios::{bundled_fixtures_dir, load_dir};

fn main() -> ExitCode {
    let folder = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "imazu".to_owned());
    let Ok(seeds) = std::env::args()
        .nth(2)
        .map_or(Ok(10), |text| text.parse::<u64>())
    else {
        eprintln!("SEEDS must be a whole number");
        return ExitCode::from(2);
    };
    let scenarios = match load_dir(&bundled_fixtures_dir().join(&folder)) {
        Ok(scenarios) => scenarios,
        Err(error) => {
            eprintln!("{error}");
            return ExitCode::from(2);
        }
    };
    let (mut found, mut total, mut overhead_pct, mut elapsed_s) = (0u32, 0u32, 0.0, 0.0);
    let mut failures = Vec::new();
    for (_, scenario) in &scenarios {
        let config = match scenario.planner_config() {
            Ok(config) => config,
            Err(error) => {
                eprintln!("{error}");
                return ExitCode::from(2);
            }
        };
        let Ok(mut planner) = Planner::new(config) else {
            return ExitCode::from(2);
        };
        let problem = scenario.planning_problem();
        let straight_m = problem.ownship.position_m.distance(problem.goal_m);
        for seed in 0..seeds {
            total += 1;
            let started = Instant::now();
            let outcome = planner.plan(&problem, seed);
            elapsed_s += started.elapsed().as_secs_f64();
            match outcome {
                Ok(plan) => {
                    found += 1;
                    overhead_pct += 100.0 * (plan.length_m() / straight_m - 1.0);
                }
                Err(_) => failures.push(format!("{} seed {seed}", scenario.name)),
            }
        }
    }
    println!(
        "{folder}: {found} of {total} plans found; mean path overhead {:.1} %; mean plan time {:.2} ms",
        overhead_pct / f64::from(found.max(1)),
        1e3 * elapsed_s / f64::from(total.max(1)),
    );
    if !failures.is_empty() {
        println!("no safe path: {}", failures.join(", "));
    }
    ExitCode::SUCCESS
}
