//! `run.json`, how a batch was made, and `vorrt merge`, which combines the
//! shards of one batch and refuses shards of different batches.

use super::{batch_error, output_error, prepare_out, summary_table, write_all};
use crate::args::MergeArgs;
use crate::console;
use crate::error::{CliError, ExitStatus};
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use vorrt_scenarios::batch::{self, Shard};
use vorrt_scenarios::generator::GeneratorSpec;

/// The file name of [`RunInfo`] in a batch's output folder.
pub(crate) const RUN_FILE: &str = "run.json";

/// How a batch was made: `run.json` (see `docs/evaluation.md`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct RunInfo {
    /// The version of vorrt that ran it.
    pub(crate) vorrt_version: String,
    /// The command line.
    pub(crate) command: Vec<String>,
    /// The generator, for a generated batch.
    pub(crate) generator: Option<GeneratorSpec>,
    /// The scenario folder, for a batch of files.
    pub(crate) dir: Option<PathBuf>,
    /// The batch seed.
    pub(crate) seed: u64,
    /// Scenarios in the whole batch (before sharding).
    pub(crate) count: u64,
    /// The shard, `i/n`.
    pub(crate) shard: String,
    /// Scenarios run.
    pub(crate) scenarios_run: usize,
    /// Worker threads (for a merge, the most any shard used).
    pub(crate) threads: usize,
    /// Wall time, seconds (for a merge, the sum over the shards).
    pub(crate) wall_time_s: f64,
    /// For a merge: the shards merged.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub(crate) merged_shards: Vec<String>,
    /// For a merge: the shards of the batch that were not among the inputs.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub(crate) missing_shards: Vec<String>,
}

impl RunInfo {
    /// Writes `DIR/run.json`.
    pub(crate) fn write(&self, dir: &Path) -> Result<(), CliError> {
        let path = dir.join(RUN_FILE);
        let json = serde_json::to_string_pretty(self)
            .map_err(|error| CliError::Output(format!("{}: {error}", path.display())))?;
        std::fs::write(&path, json + "\n").map_err(output_error(&path))
    }

    /// Reads `DIR/run.json`.
    fn read(dir: &Path) -> Result<Self, CliError> {
        let path = dir.join(RUN_FILE);
        let text = std::fs::read_to_string(&path).map_err(|error| {
            CliError::BadInput(format!(
                "cannot read {}: {error} (merge takes the output folders of `vorrt batch`)",
                path.display()
            ))
        })?;
        serde_json::from_str(&text)
            .map_err(|error| CliError::BadInput(format!("{}: {error}", path.display())))
    }

    /// The settings every shard of one batch shares, by name, as text.
    fn identity(&self) -> Result<[(&'static str, String); 5], CliError> {
        let shard = self.shard()?;
        Ok([
            (
                "generator (kind, targets, behaviour, ...)",
                serde_json::to_string(&self.generator).unwrap_or_default(),
            ),
            (
                "dir",
                self.dir
                    .as_ref()
                    .map_or_else(String::new, |dir| dir.display().to_string()),
            ),
            ("seed", self.seed.to_string()),
            ("count", self.count.to_string()),
            ("number of shards", shard.count.to_string()),
        ])
    }

    fn shard(&self) -> Result<Shard, CliError> {
        Shard::parse(&self.shard).map_err(|error| CliError::BadInput(format!("run.json: {error}")))
    }
}

/// The run.json of the merge of `infos` (one per input, in input order),
/// after checking that they are shards of one batch.
///
/// # Errors
/// [`CliError::BadInput`] naming the two inputs and the setting in which
/// they differ.
fn merged_info(inputs: &[PathBuf], infos: &[RunInfo]) -> Result<RunInfo, CliError> {
    let first = &infos[0];
    let identity = first.identity()?;
    for (input, info) in inputs.iter().zip(infos).skip(1) {
        for ((name, expected), (_, found)) in identity.iter().zip(info.identity()?) {
            if *expected != found {
                return Err(CliError::BadInput(format!(
                    "{} and {} are not shards of one batch: their {name} differ ({expected} vs {found}) in {RUN_FILE}",
                    inputs[0].display(),
                    input.display()
                )));
            }
        }
    }
    let count = first.shard()?.count;
    let mut merged = BTreeSet::new();
    for (input, info) in inputs.iter().zip(infos) {
        if !merged.insert(info.shard()?.index) {
            return Err(CliError::BadInput(format!(
                "{} is shard {} again: give each shard once",
                input.display(),
                info.shard
            )));
        }
    }
    let missing: Vec<String> = (0..count)
        .filter(|index| !merged.contains(index))
        .take(1000)
        .map(|index| format!("{index}/{count}"))
        .collect();
    Ok(RunInfo {
        vorrt_version: env!("CARGO_PKG_VERSION").to_owned(),
        command: std::env::args().collect(),
        generator: first.generator,
        dir: first.dir.clone(),
        seed: first.seed,
        count: first.count,
        shard: if missing.is_empty() {
            Shard::ALL.to_string()
        } else {
            "partial".to_owned()
        },
        scenarios_run: infos.iter().map(|info| info.scenarios_run).sum(),
        threads: infos.iter().map(|info| info.threads).max().unwrap_or(0),
        wall_time_s: infos.iter().map(|info| info.wall_time_s).sum(),
        merged_shards: infos.iter().map(|info| info.shard.clone()).collect(),
        missing_shards: missing,
    })
}

/// Refuses an output folder that is one of the inputs: the merge would
/// overwrite that shard's rows with the merged ones.
///
/// # Errors
/// [`CliError::BadInput`] naming the input.
fn refuse_out_among_inputs(inputs: &[PathBuf], out: &Path) -> Result<(), CliError> {
    // A folder that does not exist yet is no input; one that does is
    // compared by its canonical path (`a/../shard` is `shard`).
    let Ok(out_canonical) = out.canonicalize() else {
        return Ok(());
    };
    match inputs.iter().find(|input| {
        input
            .canonicalize()
            .is_ok_and(|input| input == out_canonical)
    }) {
        Some(input) => Err(CliError::BadInput(format!(
            "--out {} is the input {}: the merge would overwrite that shard; give another folder",
            out.display(),
            input.display()
        ))),
        None => Ok(()),
    }
}

/// Runs `vorrt merge`: checks that the inputs are shards of one batch
/// (their `run.json` agree on generator, folder, seed, count and number of
/// shards, each shard once) and that every shard is there (unless
/// `--allow-missing`, which warns instead), and writes the merged rows,
/// summary, plots and `run.json`.
///
/// # Errors
/// [`CliError::BadInput`] when an input cannot be read or does not belong,
/// when `--out` is an input, or when a shard is missing without
/// `--allow-missing`; [`CliError::Output`] when the output cannot be written.
pub(crate) fn merge_command(args: &MergeArgs) -> Result<ExitStatus, CliError> {
    refuse_out_among_inputs(&args.inputs, &args.out)?;
    let infos = args
        .inputs
        .iter()
        .map(|input| RunInfo::read(input))
        .collect::<Result<Vec<_>, _>>()?;
    let info = merged_info(&args.inputs, &infos)?;
    if !info.missing_shards.is_empty() && !args.allow_missing {
        return Err(CliError::BadInput(format!(
            "shards missing from the merge: {} (give every shard of the batch, or --allow-missing to merge a part of it)",
            info.missing_shards.join(", ")
        )));
    }
    let rows = batch::read_shards(&args.inputs).map_err(batch_error)?;
    prepare_out(&args.out)?;
    let summary = write_all(&rows, &args.out)?;
    info.write(&args.out)?;
    if !info.missing_shards.is_empty() {
        console::warn(&format!(
            "warning: shards missing from the merge: {} (the merged rows hold {} of the batch's {} scenarios)",
            info.missing_shards.join(", "),
            rows.len(),
            info.count
        ));
    }
    console::print(&summary_table(&summary));
    console::line(&format!(
        "merged {} shards into {}",
        args.inputs.len(),
        args.out.display()
    ));
    Ok(ExitStatus::Success)
}
