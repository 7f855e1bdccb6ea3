//! Monte Carlo batches: run many scenarios in closed loop in parallel
//! (rayon), one row of results per scenario, a summary of the whole batch,
//! deterministic sharding and merging of shards.
//!
//! Scenario `index` of a batch is simulated with [`run_seed`]`(batch seed,
//! index)` (or with its own `seed` field when loaded from a file that has
//! one; generated scenarios carry exactly that seed). Shard `i/n` of a batch
//! holds the scenarios with `index % n == i`, so `n` shards together hold the
//! same scenarios, run with the same seeds, as the unsharded batch; their
//! rows ([`write_csv`]) merge ([`merge_rows`]) into the same
//! [`BatchSummary`]. Only the wall-clock planning times differ from run to
//! run.
//!
//! ```
//! use vorrt_scenarios::batch::{BatchSummary, Shard, generate_items, run_batch};
//! use vorrt_scenarios::generator::{GeneratorSpec, OpenSeaSpec};
//! let spec = GeneratorSpec::OpenSea(OpenSeaSpec::with_targets(1));
//! let items = generate_items(&spec, 3, 2, Shard::ALL).unwrap();
//! let rows = run_batch(&items, &|_, _| {});
//! assert_eq!(rows.len(), 2);
//! let summary = BatchSummary::from_rows(&rows);
//! assert_eq!(summary.count, 2);
//! ```

use crate::error::ScenarioError;
use crate::evaluation::{Evaluation, evaluate};
use crate::generator::{GeneratorError, GeneratorSpec, run_seed};
use crate::io::load_dir;
use crate::scenario::Scenario;
use crate::simulation::{SimulationRecord, simulate};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// File name of the rows of a batch in its output folder.
pub const ROWS_FILE: &str = "rows.csv";
/// File name of the summary of a batch in its output folder.
pub const SUMMARY_FILE: &str = "summary.json";

/// The rules whose compliance is counted separately.
pub const RULES: [u8; 5] = [13, 14, 15, 16, 17];

/// What can go wrong running, writing or merging a batch.
#[derive(Debug, Error)]
pub enum BatchError {
    /// A scenario could not be generated.
    #[error(transparent)]
    Generator(#[from] GeneratorError),
    /// A scenario could not be loaded.
    #[error(transparent)]
    Scenario(#[from] ScenarioError),
    /// A file could not be read or written.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// What the operating system said.
        #[source]
        source: std::io::Error,
    },
    /// A rows file is not valid CSV of [`BatchRow`]s.
    #[error("{}: {message}", path.display())]
    Csv {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
    /// A bad `--shard` or merge input.
    #[error("{0}")]
    Invalid(String),
}

/// A deterministic slice of a batch, written `index/count`: the scenarios
/// whose batch index `k` has `k % count == index`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Shard {
    /// Which slice, from 0.
    pub index: u64,
    /// How many slices.
    pub count: u64,
}

impl Shard {
    /// The whole batch: shard `0/1`.
    pub const ALL: Shard = Shard { index: 0, count: 1 };

    /// Parses `i/n` (`0 <= i < n`).
    ///
    /// # Errors
    /// [`BatchError::Invalid`] naming the text.
    pub fn parse(text: &str) -> Result<Self, BatchError> {
        let bad = || BatchError::Invalid(format!("shard {text:?}: expected i/n with 0 <= i < n"));
        let (index, count) = text.split_once('/').ok_or_else(bad)?;
        let index: u64 = index.trim().parse().map_err(|_| bad())?;
        let count: u64 = count.trim().parse().map_err(|_| bad())?;
        if count == 0 || index >= count {
            return Err(bad());
        }
        Ok(Self { index, count })
    }

    /// Whether scenario `index` belongs to this shard.
    #[must_use]
    pub fn contains(&self, index: u64) -> bool {
        index % self.count == self.index
    }
}

impl std::fmt::Display for Shard {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

/// One scenario of a batch, with its place in the batch and the seed it is
/// simulated with.
#[derive(Debug, Clone, PartialEq)]
pub struct BatchItem {
    /// Position in the whole (unsharded) batch.
    pub index: u64,
    /// The simulation seed.
    pub seed: u64,
    /// The scenario.
    pub scenario: Scenario,
    /// The file it came from, if any.
    pub path: Option<PathBuf>,
}

/// Generates the scenarios `0..count` of the batch seeded with `seed` that
/// belong to `shard` (in parallel; each from its own stream, so the result
/// does not depend on the sharding).
///
/// # Errors
/// The first [`GeneratorError`] in index order.
pub fn generate_items(
    spec: &GeneratorSpec,
    seed: u64,
    count: u64,
    shard: Shard,
) -> Result<Vec<BatchItem>, BatchError> {
    let indices: Vec<u64> = (0..count).filter(|index| shard.contains(*index)).collect();
    indices
        .par_iter()
        .map(|&index| {
            Ok(BatchItem {
                index,
                seed: run_seed(seed, index),
                scenario: spec.generate(seed, index)?,
                path: None,
            })
        })
        .collect()
}

/// Loads every scenario file of `dir` (sorted by file name; see
/// [`load_dir`]) belonging to `shard`. Scenario `index` is simulated with
/// its own `seed` if it has one, else with [`run_seed`]`(seed, index)`.
///
/// # Errors
/// The first file that fails to load.
pub fn load_items(dir: &Path, seed: u64, shard: Shard) -> Result<Vec<BatchItem>, BatchError> {
    Ok(load_dir(dir)?
        .into_iter()
        .enumerate()
        .map(|(index, (path, scenario))| (index as u64, path, scenario))
        .filter(|(index, _, _)| shard.contains(*index))
        .map(|(index, path, scenario)| BatchItem {
            index,
            seed: scenario.seed.unwrap_or_else(|| run_seed(seed, index)),
            scenario,
            path: Some(path),
        })
        .collect())
}

/// The results of one scenario of a batch: one CSV row.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BatchRow {
    /// Position in the whole batch.
    pub index: u64,
    /// The scenario's name.
    pub name: String,
    /// Number of targets.
    pub targets: usize,
    /// The simulation seed.
    pub seed: u64,
    /// Whether ownship reached its goal.
    pub reached_goal: bool,
    /// Whether any hull touched another.
    pub collision: bool,
    /// Smallest distance to any target, metres.
    pub min_distance_m: f64,
    /// The clearance `d_th` of the scenario, metres.
    pub clearance_m: f64,
    /// Whether any target came closer than `d_th`.
    pub clearance_violation: bool,
    /// Whether every encounter was handled compliantly (rules 13-17).
    pub compliant: bool,
    /// Rule 13 (overtaking): `None` when it never applied, else whether every
    /// encounter it applied to scored full marks on it.
    pub rule_13: Option<bool>,
    /// Rule 14 (head-on), as `rule_13`.
    pub rule_14: Option<bool>,
    /// Rule 15 (crossing, give way), as `rule_13`.
    pub rule_15: Option<bool>,
    /// Rule 16 (action by give-way vessel), as `rule_13`.
    pub rule_16: Option<bool>,
    /// Rule 17 (action by stand-on vessel), as `rule_13`.
    pub rule_17: Option<bool>,
    /// Extra sailed length over the straight route, percent.
    pub path_overhead_pct: f64,
    /// Wall-clock planning time of the whole run, milliseconds.
    pub planning_time_ms: f64,
    /// Mean wall-clock time per planner call, milliseconds.
    pub planning_time_per_plan_ms: f64,
    /// Planner calls.
    pub plans: usize,
    /// Planner calls after the first.
    pub replans: usize,
    /// Planner calls that failed.
    pub failed_plans: usize,
    /// The target that came closest.
    pub closest_target: String,
    /// Its encounter type (`none` if risk never arose).
    pub closest_encounter: String,
    /// Every distinct finding over all targets, `;`-separated
    /// (`clearance_violated;late_action`).
    pub violations: String,
    /// Why the scenario could not be run at all (empty when it ran).
    pub error: String,
}

impl BatchRow {
    /// Whether the run counts as a success: goal reached, no collision, `d_th` kept.
    #[must_use]
    pub fn success(&self) -> bool {
        self.error.is_empty() && self.reached_goal && !self.collision && !self.clearance_violation
    }

    /// The compliance with `rule` (13-17), as in the row.
    #[must_use]
    pub fn rule(&self, rule: u8) -> Option<bool> {
        match rule {
            13 => self.rule_13,
            14 => self.rule_14,
            15 => self.rule_15,
            16 => self.rule_16,
            17 => self.rule_17,
            _ => None,
        }
    }

    /// The row of a run that could not be made.
    fn failed(item: &BatchItem, error: String) -> Self {
        Self {
            index: item.index,
            name: item.scenario.name.clone(),
            targets: item.scenario.targets.len(),
            seed: item.seed,
            reached_goal: false,
            collision: false,
            min_distance_m: f64::NAN,
            clearance_m: f64::NAN,
            clearance_violation: false,
            compliant: false,
            rule_13: None,
            rule_14: None,
            rule_15: None,
            rule_16: None,
            rule_17: None,
            path_overhead_pct: f64::NAN,
            planning_time_ms: 0.0,
            planning_time_per_plan_ms: 0.0,
            plans: 0,
            replans: 0,
            failed_plans: 0,
            closest_target: String::new(),
            closest_encounter: String::new(),
            violations: String::new(),
            error,
        }
    }

    /// The row of an evaluated run.
    #[must_use]
    pub fn from_evaluation(item: &BatchItem, evaluation: &Evaluation) -> Self {
        let rule = |rule: u8| -> Option<bool> {
            let scores: Vec<f64> = evaluation
                .targets
                .iter()
                .filter_map(|target| target.assessment.as_ref())
                .filter_map(|assessment| {
                    assessment
                        .scores
                        .applicable()
                        .into_iter()
                        .find(|(number, _)| *number == rule)
                        .map(|(_, score)| score)
                })
                .collect();
            (!scores.is_empty()).then(|| scores.iter().all(|score| *score >= 1.0))
        };
        let closest = evaluation
            .targets
            .iter()
            .min_by(|a, b| a.min_distance_m.total_cmp(&b.min_distance_m));
        let mut findings = BTreeSet::new();
        for target in &evaluation.targets {
            match &target.assessment {
                Some(assessment) => {
                    findings.extend(assessment.violations.iter().map(|v| v.name()));
                }
                None if !target.clearance_kept => {
                    findings.insert("clearance_violated");
                }
                None => {}
            }
        }
        let plans = evaluation.plans_made + evaluation.failed_plans;
        let planning_time_ms = 1000.0 * evaluation.planning_time_s;
        Self {
            index: item.index,
            name: evaluation.scenario.clone(),
            targets: evaluation.targets.len(),
            seed: evaluation.seed,
            reached_goal: evaluation.reached_goal,
            collision: evaluation.collision,
            min_distance_m: evaluation.min_distance_m,
            clearance_m: evaluation.clearance_m,
            clearance_violation: !evaluation.clearance_kept,
            compliant: evaluation.compliant,
            rule_13: rule(13),
            rule_14: rule(14),
            rule_15: rule(15),
            rule_16: rule(16),
            rule_17: rule(17),
            path_overhead_pct: evaluation.path_overhead_pct,
            planning_time_ms,
            planning_time_per_plan_ms: if plans > 0 {
                planning_time_ms / plans as f64
            } else {
                0.0
            },
            plans,
            replans: evaluation.replans,
            failed_plans: evaluation.failed_plans,
            closest_target: closest.map(|t| t.name.clone()).unwrap_or_default(),
            closest_encounter: closest
                .map(|t| t.encounter.name().to_owned())
                .unwrap_or_default(),
            violations: findings.into_iter().collect::<Vec<_>>().join(";"),
            error: String::new(),
        }
    }
}

/// Simulates and evaluates one scenario.
#[must_use]
pub fn run_item(item: &BatchItem) -> BatchRow {
    run_item_with(item, &|_, _| {})
}

/// As [`run_item`], handing the run's record to `on_record` first (to export
/// its trajectories).
pub fn run_item_with(item: &BatchItem, on_record: &RecordSink<'_>) -> BatchRow {
    match simulate(&item.scenario, item.seed) {
        Ok(record) => {
            on_record(item, &record);
            BatchRow::from_evaluation(item, &evaluate(&item.scenario, &record))
        }
        Err(error) => BatchRow::failed(item, error.to_string()),
    }
}

/// What [`run_batch_with`] hands every run's record to.
pub type RecordSink<'a> = dyn Fn(&BatchItem, &SimulationRecord) + Sync + 'a;

/// Runs every item in parallel on rayon's current pool; `progress` is called
/// after each run with the number done so far and its row. The rows come
/// back in the items' order.
pub fn run_batch(
    items: &[BatchItem],
    progress: &(dyn Fn(usize, &BatchRow) + Sync),
) -> Vec<BatchRow> {
    run_batch_with(items, progress, &|_, _| {})
}

/// As [`run_batch`], handing every run's record to `on_record` (from the
/// worker that ran it).
pub fn run_batch_with(
    items: &[BatchItem],
    progress: &(dyn Fn(usize, &BatchRow) + Sync),
    on_record: &RecordSink<'_>,
) -> Vec<BatchRow> {
    let done = std::sync::atomic::AtomicUsize::new(0);
    items
        .par_iter()
        .map(|item| {
            let row = run_item_with(item, on_record);
            let count = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(count, &row);
            row
        })
        .collect()
}

/// Percentiles of a distribution (nearest rank over the finite values).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Percentiles {
    /// How many finite values there were.
    pub count: usize,
    /// Smallest.
    pub min: Option<f64>,
    /// 1st percentile.
    pub p1: Option<f64>,
    /// 10th percentile.
    pub p10: Option<f64>,
    /// Median.
    pub p50: Option<f64>,
    /// 90th percentile.
    pub p90: Option<f64>,
    /// 99th percentile.
    pub p99: Option<f64>,
    /// Largest.
    pub max: Option<f64>,
    /// Mean.
    pub mean: Option<f64>,
}

impl Percentiles {
    /// Of `values` (NaN and infinite values left out).
    #[must_use]
    pub fn of(values: impl IntoIterator<Item = f64>) -> Self {
        let mut sorted: Vec<f64> = values.into_iter().filter(|v| v.is_finite()).collect();
        sorted.sort_by(f64::total_cmp);
        let rank = |p: f64| -> Option<f64> {
            if sorted.is_empty() {
                return None;
            }
            let position = ((p / 100.0) * sorted.len() as f64).ceil() as usize;
            Some(sorted[position.clamp(1, sorted.len()) - 1])
        };
        Self {
            count: sorted.len(),
            min: sorted.first().copied(),
            p1: rank(1.0),
            p10: rank(10.0),
            p50: rank(50.0),
            p90: rank(90.0),
            p99: rank(99.0),
            max: sorted.last().copied(),
            mean: (!sorted.is_empty()).then(|| sorted.iter().sum::<f64>() / sorted.len() as f64),
        }
    }
}

/// Compliance with one rule over a batch.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RuleRate {
    /// The rule (13-17).
    pub rule: u8,
    /// Runs in which it applied.
    pub applicable: usize,
    /// Of those, runs in which every encounter scored full marks on it.
    pub compliant: usize,
    /// `compliant / applicable` (`None` when it never applied).
    pub rate: Option<f64>,
}

/// The summary of a batch (`summary.json`): a function of its rows alone, so
/// merged shards give the same summary as the unsharded batch.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BatchSummary {
    /// Scenarios in the batch.
    pub count: usize,
    /// Scenarios that could not be run at all.
    pub errors: usize,
    /// Fraction that reached the goal.
    pub reached_goal_rate: f64,
    /// Fraction that reached the goal with no collision and `d_th` kept
    /// ([`BatchRow::success`]).
    pub success_rate: f64,
    /// Fraction with a collision (hulls touching).
    pub collision_rate: f64,
    /// Fraction in which some target came closer than `d_th`.
    pub clearance_violation_rate: f64,
    /// Fraction in which every encounter was handled compliantly.
    pub compliance_rate: f64,
    /// Compliance per rule, 13 to 17.
    pub rules: Vec<RuleRate>,
    /// Smallest distance to any target per run, metres.
    pub min_distance_m: Percentiles,
    /// Path overhead per run, percent.
    pub path_overhead_pct: Percentiles,
    /// Planning time per run, milliseconds.
    pub planning_time_ms: Percentiles,
    /// Mean planning time per planner call per run, milliseconds.
    pub planning_time_per_plan_ms: Percentiles,
    /// Replans per run.
    pub replans: Percentiles,
    /// Failed planner calls over the batch.
    pub failed_plans: usize,
    /// Runs with at least one failed planner call.
    pub runs_with_failed_plans: usize,
}

impl BatchSummary {
    /// Summarises `rows` (in any order).
    #[must_use]
    pub fn from_rows(rows: &[BatchRow]) -> Self {
        let mut rows: Vec<&BatchRow> = rows.iter().collect();
        rows.sort_by_key(|row| row.index);
        let count = rows.len();
        let rate = |predicate: &dyn Fn(&BatchRow) -> bool| {
            if count == 0 {
                0.0
            } else {
                rows.iter().filter(|row| predicate(row)).count() as f64 / count as f64
            }
        };
        let rules = RULES
            .iter()
            .map(|&rule| {
                let applicable = rows.iter().filter(|row| row.rule(rule).is_some()).count();
                let compliant = rows
                    .iter()
                    .filter(|row| row.rule(rule) == Some(true))
                    .count();
                RuleRate {
                    rule,
                    applicable,
                    compliant,
                    rate: (applicable > 0).then(|| compliant as f64 / applicable as f64),
                }
            })
            .collect();
        let ran: Vec<&&BatchRow> = rows.iter().filter(|row| row.error.is_empty()).collect();
        Self {
            count,
            errors: count - ran.len(),
            reached_goal_rate: rate(&|row| row.reached_goal),
            success_rate: rate(&|row| row.success()),
            collision_rate: rate(&|row| row.collision),
            clearance_violation_rate: rate(&|row| row.clearance_violation),
            compliance_rate: rate(&|row| row.error.is_empty() && row.compliant),
            rules,
            min_distance_m: Percentiles::of(ran.iter().map(|row| row.min_distance_m)),
            path_overhead_pct: Percentiles::of(ran.iter().map(|row| row.path_overhead_pct)),
            planning_time_ms: Percentiles::of(ran.iter().map(|row| row.planning_time_ms)),
            planning_time_per_plan_ms: Percentiles::of(
                ran.iter().map(|row| row.planning_time_per_plan_ms),
            ),
            replans: Percentiles::of(ran.iter().map(|row| row.replans as f64)),
            failed_plans: rows.iter().map(|row| row.failed_plans).sum(),
            runs_with_failed_plans: rows.iter().filter(|row| row.failed_plans > 0).count(),
        }
    }

    /// The summary as pretty JSON.
    #[must_use]
    pub fn to_json(&self) -> String {
        // Serialising plain numbers, strings and options cannot fail.
        serde_json::to_string_pretty(self).unwrap_or_default()
    }
}

fn io_error(path: &Path) -> impl FnOnce(std::io::Error) -> BatchError + '_ {
    move |source| BatchError::Io {
        path: path.to_owned(),
        source,
    }
}

fn csv_error(path: &Path) -> impl FnOnce(csv::Error) -> BatchError + '_ {
    move |error| BatchError::Csv {
        path: path.to_owned(),
        message: error.to_string(),
    }
}

/// Writes `rows` as CSV with a header line (floats in their shortest exact
/// form, so reading them back gives the same numbers).
///
/// # Errors
/// [`BatchError::Io`] / [`BatchError::Csv`] naming the file.
pub fn write_csv(rows: &[BatchRow], path: &Path) -> Result<(), BatchError> {
    let mut writer = csv::Writer::from_path(path).map_err(csv_error(path))?;
    for row in rows {
        writer.serialize(row).map_err(csv_error(path))?;
    }
    writer.flush().map_err(io_error(path))
}

/// Reads rows written by [`write_csv`].
///
/// # Errors
/// [`BatchError::Io`] / [`BatchError::Csv`] naming the file and the record.
pub fn read_csv(path: &Path) -> Result<Vec<BatchRow>, BatchError> {
    let mut reader = csv::Reader::from_path(path).map_err(csv_error(path))?;
    reader
        .deserialize()
        .map(|row| row.map_err(csv_error(path)))
        .collect()
}

/// Combines the rows of several shards: sorted by index, every index once.
///
/// # Errors
/// [`BatchError::Invalid`] when an index appears twice (the same shard
/// given twice, or batches that do not belong together).
pub fn merge_rows(shards: Vec<Vec<BatchRow>>) -> Result<Vec<BatchRow>, BatchError> {
    let mut rows: Vec<BatchRow> = shards.into_iter().flatten().collect();
    rows.sort_by_key(|row| row.index);
    if let Some(pair) = rows.windows(2).find(|pair| pair[0].index == pair[1].index) {
        return Err(BatchError::Invalid(format!(
            "scenario index {} appears twice ({} and {}): are two inputs the same shard?",
            pair[0].index, pair[0].name, pair[1].name
        )));
    }
    Ok(rows)
}

/// Writes `DIR/rows.csv` and `DIR/summary.json` (creating `DIR`) and returns
/// the summary.
///
/// # Errors
/// [`BatchError::Io`] / [`BatchError::Csv`] naming the file.
pub fn write_outputs(rows: &[BatchRow], dir: &Path) -> Result<BatchSummary, BatchError> {
    std::fs::create_dir_all(dir).map_err(io_error(dir))?;
    write_csv(rows, &dir.join(ROWS_FILE))?;
    let summary = BatchSummary::from_rows(rows);
    let path = dir.join(SUMMARY_FILE);
    std::fs::write(&path, summary.to_json() + "\n").map_err(io_error(&path))?;
    Ok(summary)
}

/// Reads the rows of shard outputs: each input is a folder holding
/// `rows.csv` or a CSV file itself.
///
/// # Errors
/// As [`read_csv`] and [`merge_rows`].
pub fn read_shards(inputs: &[PathBuf]) -> Result<Vec<BatchRow>, BatchError> {
    let shards = inputs
        .iter()
        .map(|input| {
            let path = if input.is_dir() {
                input.join(ROWS_FILE)
            } else {
                input.clone()
            };
            read_csv(&path)
        })
        .collect::<Result<Vec<_>, _>>()?;
    merge_rows(shards)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_parse_and_partition() {
        assert_eq!(Shard::parse("1/3").unwrap(), Shard { index: 1, count: 3 });
        for bad in ["3/3", "1", "a/2", "0/0", "-1/2"] {
            assert!(Shard::parse(bad).is_err(), "{bad}");
        }
        let shards: Vec<Shard> = (0..3).map(|index| Shard { index, count: 3 }).collect();
        for index in 0..30 {
            assert_eq!(shards.iter().filter(|s| s.contains(index)).count(), 1);
        }
        assert_eq!(Shard::ALL.to_string(), "0/1");
    }

    #[test]
    fn percentiles_by_nearest_rank() {
        let p = Percentiles::of((1..=100).map(f64::from).chain([f64::NAN, f64::INFINITY]));
        assert_eq!(p.count, 100);
        assert_eq!(p.p50, Some(50.0));
        assert_eq!(p.p90, Some(90.0));
        assert_eq!(p.p99, Some(99.0));
        assert_eq!(p.p1, Some(1.0));
        assert_eq!(p.max, Some(100.0));
        assert_eq!(p.mean, Some(50.5));
        assert_eq!(Percentiles::of([]).p50, None);
        assert_eq!(Percentiles::of([7.0]).p1, Some(7.0));
    }
}
