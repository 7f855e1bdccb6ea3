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

mod row;
mod summary;

pub use row::BatchRow;
pub use summary::{BatchSummary, Percentiles, RuleRate};

use crate::error::ScenarioError;
use crate::evaluation::evaluate;
use crate::generator::{GeneratorError, GeneratorSpec, run_seed};
use crate::io::load_dir;
use crate::scenario::Scenario;
use crate::simulation::{SimulationRecord, simulate};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
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

    /// The batch indices below `count` that belong to this shard, without
    /// walking the others.
    pub fn indices(&self, count: u64) -> impl Iterator<Item = u64> + use<> {
        let step = usize::try_from(self.count).unwrap_or(usize::MAX);
        (self.index..count).step_by(step)
    }

    /// How many of the batch indices below `count` belong to this shard.
    #[must_use]
    pub fn len_of(&self, count: u64) -> u64 {
        if count <= self.index {
            0
        } else {
            (count - self.index).div_ceil(self.count)
        }
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

/// The most scenarios one run of a batch (one shard) may hold: more would
/// take days and more memory than a machine has; use more shards.
pub const MAX_SHARD_SCENARIOS: u64 = 1_000_000;

/// Generates the scenarios `0..count` of the batch seeded with `seed` that
/// belong to `shard` (in parallel; each from its own stream, so the result
/// does not depend on the sharding). Only the shard's own indices are
/// visited, so a huge `count` split into as many shards is cheap.
///
/// # Errors
/// [`BatchError::Invalid`] when the shard would hold more than
/// [`MAX_SHARD_SCENARIOS`]; else the first [`GeneratorError`] in index order.
pub fn generate_items(
    spec: &GeneratorSpec,
    seed: u64,
    count: u64,
    shard: Shard,
) -> Result<Vec<BatchItem>, BatchError> {
    let size = shard.len_of(count);
    if size > MAX_SHARD_SCENARIOS {
        return Err(BatchError::Invalid(format!(
            "shard {shard} of {count} scenarios holds {size}, more than the {MAX_SHARD_SCENARIOS} one run may hold: split the batch into more shards"
        )));
    }
    let indices: Vec<u64> = shard.indices(count).collect();
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
        for shard in &shards {
            let walked: Vec<u64> = (0..31).filter(|k| shard.contains(*k)).collect();
            assert_eq!(shard.indices(31).collect::<Vec<_>>(), walked);
            assert_eq!(shard.len_of(31), walked.len() as u64);
        }
        let huge = Shard {
            index: 5,
            count: u64::MAX,
        };
        assert_eq!(huge.indices(u64::MAX).collect::<Vec<_>>(), vec![5]);
        assert_eq!(huge.len_of(3), 0);
    }
}
