//! Plans the paper's traffic separation scheme a number of times: the
//! workload profiled in `docs/performance.md`.
//!
//! ```text
//! cargo build --release --example profile_tss
//! valgrind --tool=callgrind target/release/examples/profile_tss 20
//! ```
//!
//! The first argument is how many plans (default 20), each with the
//! fixture's planner settings. A second argument fixes the seed of every
//! plan (as `plan/tss` does, with seed 1); without it the seeds are 1, 2, 3,
//! ... in turn.

use std::process::ExitCode;
use vorrt::planner::Planner;
use vorrt::scenarios::Scenario;

fn main() -> ExitCode {
    let number = |index: usize| -> Result<Option<u64>, String> {
        std::env::args()
            .nth(index)
            .map(|arg| arg.parse::<u64>())
            .transpose()
            .map_err(|error| format!("arguments must be whole numbers: {error}"))
    };
    let (runs, fixed_seed) = match (number(1), number(2)) {
        (Ok(runs), Ok(seed)) => (runs.unwrap_or(20), seed),
        (Err(error), _) | (_, Err(error)) => {
            eprintln!("{error}");
            return ExitCode::FAILURE;
        }
    };
    let path = vorrt::scenarios::bundled_fixtures_dir().join("paper/tss.ron");
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
    let (mut found, mut samples) = (0u64, 0u64);
    for run in 1..=runs {
        let seed = fixed_seed.unwrap_or(run);
        match planner.plan(&problem, seed) {
            Ok(plan) => {
                found += 1;
                samples += plan.statistics.samples;
            }
            Err(error) => eprintln!("run {run}, seed {seed}: {error}"),
        }
    }
    eprintln!("{found} of {runs} plans found, {samples} samples in those");
    ExitCode::SUCCESS
}
