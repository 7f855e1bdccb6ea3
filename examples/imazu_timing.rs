//! Wall-clock time of the closed loop (`vorrt_scenarios::simulate`: plan,
//! sail, replan until the goal or the time limit) on each of the 22 Imazu
//! cases, for the comparison with the peer `colregs-planner` in
//! `docs/performance.md` (`scripts/peers/colregs_planner_imazu.py` times the
//! peer on the same cases).
//!
//! Prints one CSV row per case: the median wall time of `REPEATS` runs, the
//! time spent inside the planner, planner calls (by trigger: a new encounter,
//! a target off its prediction, a retry; failed; followed by a departure
//! from the rules), replanning triggers that kept the plan, the simulated
//! time, the time step, whether ownship reached its goal, and the smallest
//! distance between ownship's and any target's reference points. A last row
//! `total` sums the medians.
//!
//! Run with `cargo run --release --example imazu_timing -- [REPEATS] [SEED]`;
//! REPEATS defaults to 5, SEED to 1 (the seed of the criterion benchmarks).
#![allow(clippy::print_stdout)]

use std::process::ExitCode;
use std::time::Instant;
use vorrt::scenarios::{PlanTrigger, SimulationRecord, bundled_fixtures_dir, load_dir, simulate};

/// Planner calls by trigger: (new encounter, target off its prediction,
/// retry after a failure).
fn triggers(record: &SimulationRecord) -> (usize, usize, usize) {
    record
        .plans
        .iter()
        .fold((0, 0, 0), |(new, off, retry), event| match event.trigger {
            PlanTrigger::NewEncounter { .. } => (new + 1, off, retry),
            PlanTrigger::TargetOffPrediction { .. } => (new, off + 1, retry),
            PlanTrigger::Retry => (new, off, retry + 1),
            _ => (new, off, retry),
        })
}

/// Smallest distance between ownship and any target over the recorded
/// steps, metres (infinite without targets).
fn min_distance_m(record: &SimulationRecord) -> f64 {
    record
        .targets
        .iter()
        .flat_map(|track| {
            track
                .iter()
                .zip(&record.ownship)
                .map(|(target, own)| target.position_m.distance(own.position_m))
        })
        .fold(f64::INFINITY, f64::min)
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    let middle = values.len() / 2;
    if values.len() % 2 == 1 {
        values[middle]
    } else {
        0.5 * (values[middle - 1] + values[middle])
    }
}

fn main() -> ExitCode {
    let mut args = std::env::args().skip(1);
    let parse = |text: Option<String>, default: u64| text.map_or(Ok(default), |t| t.parse::<u64>());
    let (Ok(repeats), Ok(seed)) = (parse(args.next(), 5), parse(args.next(), 1)) else {
        eprintln!("usage: imazu_timing [REPEATS] [SEED] (whole numbers)");
        return ExitCode::from(2);
    };
    let repeats = repeats.max(1);
    let scenarios = match load_dir(&bundled_fixtures_dir().join("imazu")) {
        Ok(scenarios) => scenarios,
        Err(error) => {
            eprintln!("{error}");
            return ExitCode::from(2);
        }
    };
    println!(
        "case,wall_ms,planning_ms,planner_calls,new_encounter,target_off,retry,failed,rule_departures,kept,simulated_s,time_step_s,reached_goal,min_distance_m"
    );
    let (mut total_ms, mut total_planning_ms, mut total_calls) = (0.0, 0.0, 0usize);
    for (_, scenario) in &scenarios {
        let mut wall_samples_ms = Vec::new();
        let mut last = None;
        for _ in 0..repeats {
            let started = Instant::now();
            let outcome = simulate(scenario, seed);
            wall_samples_ms.push(started.elapsed().as_secs_f64() * 1e3);
            match outcome {
                Ok(record) => last = Some(record),
                Err(error) => {
                    eprintln!("{}: {error}", scenario.name);
                    return ExitCode::from(2);
                }
            }
        }
        let Some(record) = last else {
            return ExitCode::from(2);
        };
        let wall_ms = median(wall_samples_ms);
        let planning_ms = record.planning_time_s() * 1e3;
        total_ms += wall_ms;
        total_planning_ms += planning_ms;
        total_calls += record.plans.len();
        let (new, off, retry) = triggers(&record);
        println!(
            "{},{wall_ms:.3},{planning_ms:.3},{},{new},{off},{retry},{},{},{},{:.0},{},{},{:.1}",
            scenario.name,
            record.plans.len(),
            record.failed_plans(),
            record.rule_departures(),
            record.plans_kept.len(),
            record.times_s.last().copied().unwrap_or(0.0),
            record.time_step_s,
            record.reached_goal,
            min_distance_m(&record),
        );
    }
    println!("total,{total_ms:.3},{total_planning_ms:.3},{total_calls},,,,,,,,,,");
    ExitCode::SUCCESS
}
