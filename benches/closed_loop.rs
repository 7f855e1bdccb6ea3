//! Benchmarks of the whole closed loop (`vorrt_scenarios::simulate`: plan,
//! follow, replan, until the goal or the time limit): all 22 Imazu cases in
//! one iteration (also with the paper's instantaneous turns,
//! `imazu_all_instant`), and the paper's traffic separation scheme.
//!
//! Run with `cargo bench --bench closed_loop`; see `docs/performance.md`.

// criterion_group! and criterion_main! generate undocumented public functions.
#![allow(missing_docs)]

mod support;

use criterion::{Criterion, SamplingMode, black_box, criterion_group, criterion_main};
use std::time::Duration;
use support::{SEED, fixture};
use vorrt::planner::{PlannerConfig, Turning};
use vorrt::scenarios::{Scenario, simulate, simulate_with};

fn imazu_all() -> Vec<Scenario> {
    (1..=22)
        .map(|case| fixture("imazu", &format!("imazu_{case:02}")))
        .collect()
}

fn closed_loop(c: &mut Criterion) {
    let mut group = c.benchmark_group("closed_loop");
    // One iteration of imazu_all takes a few hundred milliseconds: ten
    // samples of equal size (flat sampling) in 15 s.
    group.sample_size(10);
    group.sampling_mode(SamplingMode::Flat);
    group.warm_up_time(Duration::from_secs(2));
    group.measurement_time(Duration::from_secs(15));

    let imazu = imazu_all();
    let reached = imazu
        .iter()
        .filter(|scenario| simulate(scenario, SEED).is_ok_and(|record| record.reached_goal))
        .count();
    eprintln!(
        "closed_loop/imazu_all: {reached} of {} reach the goal",
        imazu.len()
    );
    group.bench_function("imazu_all", |b| {
        b.iter(|| {
            let mut plans = 0usize;
            for scenario in &imazu {
                let record = simulate(black_box(scenario), black_box(SEED)).expect("valid");
                plans += record.plans_made();
            }
            plans
        });
    });

    // The same cases with the paper's instantaneous turns: the difference
    // is the cost of turn-rate-limited plans and tracks in closed loop.
    let instant: Vec<(&Scenario, PlannerConfig)> = imazu
        .iter()
        .map(|scenario| {
            let config = scenario.planner_config().expect("valid planner section");
            (
                scenario,
                PlannerConfig {
                    turning: Turning::Instant,
                    ..config
                },
            )
        })
        .collect();
    let reached = instant
        .iter()
        .filter(|(scenario, config)| {
            simulate_with(scenario, config, SEED).is_ok_and(|record| record.reached_goal)
        })
        .count();
    eprintln!(
        "closed_loop/imazu_all_instant: {reached} of {} reach the goal",
        instant.len()
    );
    group.bench_function("imazu_all_instant", |b| {
        b.iter(|| {
            let mut plans = 0usize;
            for (scenario, config) in &instant {
                let record =
                    simulate_with(black_box(scenario), config, black_box(SEED)).expect("valid");
                plans += record.plans_made();
            }
            plans
        });
    });

    let tss = fixture("paper", "tss");
    if let Ok(record) = simulate(&tss, SEED) {
        eprintln!(
            "closed_loop/tss: reached goal {}, {} plans ({} replans, {} failed)",
            record.reached_goal,
            record.plans_made(),
            record.replans(),
            record.failed_plans()
        );
    }
    group.measurement_time(Duration::from_secs(5));
    group.bench_function("tss", |b| {
        b.iter(|| {
            simulate(black_box(&tss), black_box(SEED))
                .expect("valid")
                .plans_made()
        });
    });
    group.finish();
}

criterion_group!(benches, closed_loop);
criterion_main!(benches);
