//! Where the closed loop's planning time goes on generated open-sea runs:
//! every planner call, grouped by trigger (a retry or another trigger), by
//! whether a fully compliant plan was in force before the call, and by what
//! came of it (the level of the plan found, or a failure); with the calls'
//! wall time and the samples drawn over all the levels tried
//! (`PlanEvent::samples_drawn`, the same on every machine).
//!
//! Then, for retries: which search found the fully compliant plans of the
//! retries that found one (the manoeuvre search from the root, whose plan
//! has one node, or a tree); and how often a retry finds a fully compliant plan after
//! `k` failed calls in a row with the same encounters in force, and right
//! after the encounters changed (the case for or against backing off;
//! `docs/performance.md`, "2026-11-30: cheaper retries, a grid nearest-node index").
//!
//! Run with `cargo run --release --example fallback_calls -- BEHAVIOUR COUNT
//! [TARGETS] [SEED]` (as `vorrt batch --generate open-sea --behaviour
//! BEHAVIOUR --count COUNT --targets TARGETS --seed SEED`; defaults 8 and 11).
#![allow(clippy::print_stdout)]

use std::collections::BTreeMap;
use std::process::ExitCode;
use vorrt::colregs::{EncounterLatch, update_latch};
use vorrt::planner::Compliance;
use vorrt::scenarios::batch::generate_items;
use vorrt::scenarios::{
    GeneratorSpec, OpenSeaSpec, PlanTrigger, Shard, SimulationRecord, TargetBehaviour, simulate,
};

/// The encounters in force at each planner call, latched again from the
/// recorded states as the closed loop latches them.
fn encounters_at_calls(record: &SimulationRecord) -> Vec<Vec<Option<EncounterLatch>>> {
    let rules = record.config.rules;
    let mut latches: Vec<Option<EncounterLatch>> = vec![None; record.targets.len()];
    let mut at_calls = Vec::new();
    for (step, &time_s) in record.times_s.iter().enumerate() {
        for (target, latch) in latches.iter_mut().enumerate() {
            *latch = update_latch(
                *latch,
                &record.ownship[step],
                &record.targets[target][step],
                time_s,
                &rules,
            );
        }
        while at_calls.len() < record.plans.len()
            && record.plans[at_calls.len()].time_s <= time_s + 1e-9
        {
            at_calls.push(latches.clone());
        }
    }
    at_calls
}

/// The planner calls of every run, tallied.
#[derive(Default)]
struct Tally {
    /// (calls, seconds, samples) per group: trigger, plan in force, outcome.
    groups: BTreeMap<String, (usize, f64, u64)>,
    /// (retries, fully compliant plans found) per (encounters changed since
    /// the last failure, failures before, at most 8).
    streaks: BTreeMap<(bool, usize), (usize, usize)>,
    /// Fully compliant plans found by retries: (by the manoeuvre search, by a tree).
    found_by: (usize, usize),
}

impl Tally {
    /// Adds every planner call of one run.
    fn add_run(&mut self, record: &SimulationRecord) {
        let encounters = encounters_at_calls(record);
        let mut compliant_before = true;
        let mut failures = 0usize;
        let mut last_failure: Option<&Vec<Option<EncounterLatch>>> = None;
        for (event, now) in record.plans.iter().zip(&encounters) {
            let retry = event.trigger == PlanTrigger::Retry;
            let outcome = if event.succeeded {
                format!("{:?}", event.compliance)
            } else {
                "no plan".to_owned()
            };
            let key = format!(
                "{:<5} | {:<5} | {outcome}",
                if retry { "retry" } else { "other" },
                compliant_before
            );
            let group = self.groups.entry(key).or_default();
            group.0 += 1;
            group.1 += event.statistics.elapsed_s;
            group.2 += event.samples_drawn;
            let full = event.succeeded && event.compliance == Compliance::Full;
            let changed = last_failure.is_some_and(|before| before != now);
            if changed {
                failures = 0;
            }
            if retry && full {
                if event.statistics.nodes <= 1 {
                    self.found_by.0 += 1;
                } else {
                    self.found_by.1 += 1;
                }
            }
            if retry {
                let streak = self.streaks.entry((changed, failures.min(8))).or_default();
                streak.0 += 1;
                streak.1 += usize::from(full);
            }
            if full {
                failures = 0;
                last_failure = None;
            } else {
                failures += 1;
                last_failure = Some(now);
            }
            compliant_before = full;
        }
    }

    /// Prints the groups, the searches that found retries' plans, and the
    /// retries by streak, for `runs` runs.
    fn print(&self, runs: usize) {
        let total_s: f64 = self.groups.values().map(|group| group.1).sum();
        let total_samples: u64 = self.groups.values().map(|group| group.2).sum();
        println!(
            "trigger | fully compliant plan before | outcome, calls, planning s (share), samples drawn (share)"
        );
        for (key, (calls, seconds, samples)) in &self.groups {
            #[expect(clippy::cast_precision_loss, reason = "sample counts, far below 2^52")]
            let sample_share = *samples as f64 / total_samples as f64;
            println!(
                "{key:<30} {calls:>6} {seconds:>8.2} s ({:>4.1} %) {samples:>10} ({:>4.1} %)",
                100.0 * seconds / total_s,
                100.0 * sample_share
            );
        }
        println!("total {total_s:.2} s, {total_samples} samples, {runs} runs");
        println!(
            "fully compliant plans found by retries: {} by the manoeuvre search, {} by a tree",
            self.found_by.0, self.found_by.1
        );
        println!(
            "retries: encounters changed since the last failure | failures before (8 = 8 or more) | retries | fully compliant plans found"
        );
        for ((changed, failures), (retries, found)) in &self.streaks {
            #[expect(clippy::cast_precision_loss, reason = "retry counts, far below 2^52")]
            let found_share = *found as f64 / *retries as f64;
            println!(
                "{changed:<5} | {failures} | {retries:>5} | {found:>4} ({:.0} %)",
                100.0 * found_share
            );
        }
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(behaviour), Some(count)) = (
        args.first()
            .and_then(|name| TargetBehaviour::from_name(name).ok()),
        args.get(1).and_then(|count| count.parse::<u64>().ok()),
    ) else {
        eprintln!("usage: fallback_calls BEHAVIOUR COUNT [TARGETS] [SEED]");
        return ExitCode::from(2);
    };
    let targets = args.get(2).and_then(|n| n.parse().ok()).unwrap_or(8);
    let seed = args.get(3).and_then(|n| n.parse().ok()).unwrap_or(11);
    let spec = GeneratorSpec::OpenSea(OpenSeaSpec::with_targets(targets).with_behaviour(behaviour));
    let items = match generate_items(&spec, seed, count, Shard::ALL) {
        Ok(items) => items,
        Err(error) => {
            eprintln!("{error}");
            return ExitCode::from(2);
        }
    };
    let mut tally = Tally::default();
    for item in &items {
        if let Ok(record) = simulate(&item.scenario, item.seed) {
            tally.add_run(&record);
        }
    }
    tally.print(items.len());
    ExitCode::SUCCESS
}
