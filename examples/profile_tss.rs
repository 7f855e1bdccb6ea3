//! Plans the paper's traffic separation scheme a number of times: the
//! workload profiled in `docs/performance.md`.
//!
//! ```text
//! cargo build --release --example profile_tss
//! valgrind --tool=callgrind target/release/examples/profile_tss 20
//! ```
//!
//! The argument is how many plans (default 20), each with the fixture's
//! planner settings and seeds 1, 2, 3, ... in turn.

use std::path::Path;
use std::process::ExitCode;
use vorrt::planner::Planner;
use vorrt::scenarios::Scenario;

fn main() -> ExitCode {
    let runs: u64 = match std::env::args().nth(1).map(|arg| arg.parse()) {
        None => 20,
        Some(Ok(runs)) => runs,
        Some(Err(error)) => {
            eprintln!("the number of plans must be a whole number: {error}");
            return ExitCode::FAILURE;
        }
    };
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/paper/tss.ron");
    let scenario = match Scenario::load(&path) {
        Ok(scenario) => scenario,
        Err(error) => {
            eprintln!("{error}");
            return ExitCode::FAILURE;
        }
    };
    let config = match scenario.planner_config() {
        Ok(config) => config,
        Err(error) => {
            eprintln!("{error}");
            return ExitCode::FAILURE;
        }
    };
    let problem = scenario.planning_problem();
    let mut planner = Planner::new(config).expect("the fixture's settings are valid");
    let (mut planned, mut samples) = (0u64, 0u64);
    for seed in 1..=runs {
        match planner.plan(&problem, seed) {
            Ok(plan) => {
                planned += 1;
                samples += plan.statistics.samples;
            }
            Err(error) => eprintln!("seed {seed}: {error}"),
        }
    }
    eprintln!("{planned} of {runs} plans found, {samples} samples in those");
    ExitCode::SUCCESS
}
