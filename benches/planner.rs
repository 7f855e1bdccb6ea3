//! Benchmarks of one call to `Planner::plan`: the paper's five scenarios
//! (each with the default turn-rate-limited plan and, as `<name>_instant`,
//! with the paper's instantaneous turns), scaling with the number of targets and with the tree size, and the two
//! nearest-node indexes.
//!
//! Run with `cargo bench --bench planner`; see `docs/performance.md`.

// criterion_group! and criterion_main! generate undocumented public functions.
#![allow(missing_docs)]

mod support;

use criterion::{Criterion, black_box, criterion_group, criterion_main};
use std::time::Duration;
use support::{
    GENERATOR_SEED, SEED, blocked_goal_config, blocked_goal_problem, fixture_problem,
    generated_problem,
};
use vorrt::planner::{NearestIndex, Planner, PlannerConfig, PlanningProblem, Turning};

/// Plans once outside the measurement and says on stderr what the search
/// did, so that a time can be read together with the work behind it.
fn describe(id: &str, problem: &PlanningProblem, config: &PlannerConfig) {
    let mut planner = Planner::new(*config).expect("valid configuration");
    match planner.plan(problem, SEED) {
        Ok(plan) => eprintln!(
            "{id}: ok, {} waypoints, {} nodes, {} samples, {} restarts",
            plan.waypoints.len(),
            plan.statistics.nodes,
            plan.statistics.samples,
            plan.statistics.restarts
        ),
        Err(error) => eprintln!("{id}: failed: {error}"),
    }
}

/// One plan per iteration. The planner is built once and reused, as a
/// closed loop reuses it; its result (plan or error) is consumed.
fn bench_plan(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    group_name: &str,
    id: &str,
    problem: &PlanningProblem,
    config: &PlannerConfig,
) {
    describe(&format!("{group_name}/{id}"), problem, config);
    let mut planner = Planner::new(*config).expect("valid configuration");
    group.bench_function(id, |b| {
        b.iter(|| {
            let result = planner.plan(black_box(problem), black_box(SEED));
            black_box(result.map(|plan| plan.waypoints.len()).ok())
        });
    });
}

fn paper_scenarios(c: &mut Criterion) {
    const GROUP: &str = "plan";
    let mut group = c.benchmark_group(GROUP);
    group.measurement_time(Duration::from_secs(3));
    for name in ["crossing", "head_on", "overtaking", "multi_vessel", "tss"] {
        let (problem, config) = fixture_problem("paper", name);
        bench_plan(&mut group, GROUP, name, &problem, &config);
        // The paper's instantaneous turns: the tree's branch is the plan, no
        // simplification into legs and arcs. The difference to the id above
        // is the cost of the turn-rate-limited plan.
        let instant = PlannerConfig {
            turning: Turning::Instant,
            ..config
        };
        bench_plan(
            &mut group,
            GROUP,
            &format!("{name}_instant"),
            &problem,
            &instant,
        );
    }
    group.finish();
}

fn target_scaling(c: &mut Criterion) {
    const GROUP: &str = "plan_scaling/targets";
    let mut group = c.benchmark_group(GROUP);
    group.sample_size(20);
    group.measurement_time(Duration::from_secs(3));
    // The paper fixtures' budget: 600 accepted nodes per phase.
    let config = PlannerConfig {
        nodes_per_phase: 600,
        ..PlannerConfig::default()
    };
    for targets in [1usize, 2, 4, 8, 16, 32, 64] {
        let problem = generated_problem(targets, GENERATOR_SEED);
        bench_plan(&mut group, GROUP, &targets.to_string(), &problem, &config);
    }
    group.finish();
}

fn tree_scaling(c: &mut Criterion) {
    const GROUP: &str = "plan_scaling/nodes_per_phase";
    let mut group = c.benchmark_group(GROUP);
    group.sample_size(20);
    group.measurement_time(Duration::from_secs(3));
    // The goal is blocked, so both phases grow to the full quota: a tree of
    // 2 × nodes_per_phase + 1 nodes, then NoSafePath.
    let problem = blocked_goal_problem(GENERATOR_SEED);
    for nodes in [200usize, 400, 800, 1600] {
        bench_plan(
            &mut group,
            GROUP,
            &nodes.to_string(),
            &problem,
            &blocked_goal_config(nodes),
        );
    }
    group.finish();
}

fn nearest_index(c: &mut Criterion) {
    const GROUP: &str = "nearest_index";
    let mut group = c.benchmark_group(GROUP);
    group.sample_size(20);
    group.measurement_time(Duration::from_secs(3));
    let indexes = [
        ("linear", NearestIndex::Linear),
        ("rtree", NearestIndex::RTree),
        ("grid", NearestIndex::Grid),
    ];
    // A real problem: the traffic separation scheme, as its fixture sets it.
    let (tss, tss_config) = fixture_problem("paper", "tss");
    for (name, index) in indexes {
        let config = PlannerConfig {
            nearest_index: index,
            ..tss_config
        };
        bench_plan(&mut group, GROUP, &format!("tss/{name}"), &tss, &config);
    }
    // A large tree: 3201 nodes grown toward a blocked goal.
    let blocked = blocked_goal_problem(GENERATOR_SEED);
    for (name, index) in indexes {
        let config = PlannerConfig {
            nearest_index: index,
            ..blocked_goal_config(1600)
        };
        bench_plan(
            &mut group,
            GROUP,
            &format!("blocked_1600/{name}"),
            &blocked,
            &config,
        );
    }
    group.finish();
}

criterion_group!(
    benches,
    paper_scenarios,
    target_scaling,
    tree_scaling,
    nearest_index
);
criterion_main!(benches);
