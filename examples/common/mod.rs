//! What the per-scenario examples share: load a bundled fixture, run it in
//! closed loop, print the evaluation.

use std::process::ExitCode;
use vorrt::scenarios::{Scenario, bundled_fixtures_dir, evaluate, simulate};

/// Runs the bundled fixture `relative` (under `crates/scenarios/fixtures/`)
/// with its own seed and prints the evaluation table. Exit code 0 when the
/// run succeeded (`Evaluation::success`: goal reached, no collision, `d_th`
/// kept), 1 otherwise, 2 for a fixture that does not load.
pub(crate) fn run_fixture(relative: &str) -> ExitCode {
    let path = bundled_fixtures_dir().join(relative);
    let scenario = match Scenario::load(&path) {
        Ok(scenario) => scenario,
        Err(error) => {
            eprintln!("{error}");
            return ExitCode::from(2);
        }
    };
    let seed = scenario.seed.unwrap_or(1);
    let record = match simulate(&scenario, seed) {
        Ok(record) => record,
        Err(error) => {
            eprintln!("{error}");
            return ExitCode::from(2);
        }
    };
    let evaluation = evaluate(&scenario, &record);
    println!("{} (seed {seed})", scenario.name);
    if let Some(description) = &scenario.description {
        println!("{description}");
    }
    println!();
    print!("{}", evaluation.table());
    if evaluation.success() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}
