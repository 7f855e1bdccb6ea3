//! Arbitrary bytes that parse as a scenario are planned with a small time
//! budget and small node counts: the planner must return (a plan or an
//! error), never panic and never hang (libFuzzer's `-timeout` catches a hang).
#![no_main]

use libfuzzer_sys::fuzz_target;
use vorrt_planner::Planner;
use vorrt_scenarios::Scenario;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let Ok(scenario) = Scenario::from_ron_str(&text, "fuzz.ron") else {
        return;
    };
    let Ok(mut config) = scenario.planner_config() else {
        return;
    };
    config.nodes_per_phase = config.nodes_per_phase.min(40);
    config.samples_per_phase = config.samples_per_phase.clamp(config.nodes_per_phase, 400);
    config.max_restarts = config.max_restarts.min(1);
    config.time_budget_s = Some(0.25);
    let Ok(mut planner) = Planner::new(config) else {
        return;
    };
    let problem = scenario.planning_problem();
    let _ = planner.plan(&problem, scenario.seed.unwrap_or(0));
});
