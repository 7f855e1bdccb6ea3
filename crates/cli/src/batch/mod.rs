//! Monte Carlo campaigns: `vorrt batch`, `vorrt generate` and `vorrt merge`,
//! with SVG histograms of the minimum distance and of the planning time.
//!
//! `batch` writes into its `--out` folder: `rows.csv` (one row per scenario,
//! [`vorrt_scenarios::BatchRow`]), `summary.json`
//! ([`vorrt_scenarios::BatchSummary`]), `run.json` (how the batch was made:
//! generator, seed, shard, wall time), `min_distance.svg`,
//! `planning_time.svg`, `failures/` with the scenario file of every run
//! that was not a success, and `findings/` with that of every run that
//! succeeded with a COLREGs finding. `merge` writes the same rows, summary and plots
//! for several shard folders together.

mod histogram;
mod merge;

use crate::args::{BatchArgs, BehaviourName, DirectionName, GenerateArgs, GeneratorArgs, Kind};
use crate::console;
use crate::error::{CliError, ExitStatus};
use crate::run::folder_name;
use histogram::write_histograms;
use merge::RunInfo;
pub(crate) use merge::merge_command;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::time::Instant;
use vorrt_scenarios::batch::{
    self, BatchItem, BatchRow, BatchSummary, Shard, generate_items, load_items,
};
use vorrt_scenarios::generator::{
    CoastalSpec, GeneratorSpec, OpenSeaSpec, TargetBehaviour, TssDirection, TssSpec,
};

impl GeneratorArgs {
    fn behaviour(&self) -> TargetBehaviour {
        let name = match self.behaviour {
            BehaviourName::Constant => "constant",
            BehaviourName::Colregs => "colregs",
            BehaviourName::Noisy => "noisy",
            BehaviourName::SuddenTurn => "sudden-turn",
        };
        TargetBehaviour::from_name(name).unwrap_or_default()
    }

    fn spec(&self, kind: Kind) -> Result<GeneratorSpec, CliError> {
        let behaviour = self.behaviour();
        match kind {
            Kind::OpenSea => {
                if self.density.is_some() {
                    return Err(CliError::BadInput(
                        "--density is for --generate tss; open sea takes --targets".into(),
                    ));
                }
                let targets = self.targets.ok_or_else(|| {
                    CliError::BadInput("open sea needs --targets N (1 to 256)".into())
                })?;
                Ok(GeneratorSpec::OpenSea(
                    OpenSeaSpec::with_targets(targets).with_behaviour(behaviour),
                ))
            }
            Kind::Coastal => {
                if self.density.is_some() {
                    return Err(CliError::BadInput(
                        "--density is for --generate tss; coastal takes --targets".into(),
                    ));
                }
                Ok(GeneratorSpec::Coastal(
                    CoastalSpec::with_targets(self.targets.unwrap_or(1)).with_behaviour(behaviour),
                ))
            }
            Kind::Tss => {
                if self.targets.is_some() {
                    return Err(CliError::BadInput(
                        "a TSS is sized by --density (targets per nm of lane), not --targets"
                            .into(),
                    ));
                }
                let mut spec =
                    TssSpec::with_density(self.density.unwrap_or(1.0)).with_behaviour(behaviour);
                spec.lane_width_nm = self.lane_width;
                spec.direction = match self.direction {
                    DirectionName::Westbound => TssDirection::Westbound,
                    DirectionName::Eastbound => TssDirection::Eastbound,
                    DirectionName::TwoWay => TssDirection::TwoWay,
                };
                Ok(GeneratorSpec::Tss(spec))
            }
        }
    }

    fn shard(&self) -> Result<Shard, CliError> {
        self.shard
            .as_deref()
            .map_or(Ok(Shard::ALL), Shard::parse)
            .map_err(|error| CliError::BadInput(error.to_string()))
    }
}

pub(crate) fn output_error(path: &Path) -> impl FnOnce(std::io::Error) -> CliError + '_ {
    move |error| CliError::Output(format!("cannot write {}: {error}", path.display()))
}

pub(crate) fn batch_error(error: batch::BatchError) -> CliError {
    match error {
        batch::BatchError::Io { .. } => CliError::Output(error.to_string()),
        other => CliError::BadInput(other.to_string()),
    }
}

/// Creates the output folder and checks that files can be written into it,
/// before any scenario runs.
///
/// # Errors
/// [`CliError::Output`] naming the folder.
pub(crate) fn prepare_out(dir: &Path) -> Result<(), CliError> {
    let cannot = |error: std::io::Error| {
        CliError::Output(format!(
            "cannot write into the output folder {}: {error}",
            dir.display()
        ))
    };
    std::fs::create_dir_all(dir).map_err(cannot)?;
    let probe = dir.join(".vorrt-write-check");
    std::fs::write(&probe, b"").map_err(cannot)?;
    std::fs::remove_file(&probe).map_err(cannot)
}

/// The scenarios of a batch or of `generate`, refused when there are none.
pub(crate) fn items_of(
    args: &GeneratorArgs,
    kind: Option<Kind>,
    dir: Option<&Path>,
) -> Result<(Vec<BatchItem>, Option<GeneratorSpec>), CliError> {
    let shard = args.shard()?;
    let (items, generator) = match (kind, dir) {
        (Some(kind), _) => {
            let spec = args.spec(kind)?;
            let items = generate_items(&spec, args.seed, args.count, shard).map_err(batch_error)?;
            (items, Some(spec))
        }
        (None, Some(dir)) => (
            load_items(dir, args.seed, shard).map_err(batch_error)?,
            None,
        ),
        (None, None) => {
            return Err(CliError::BadInput(
                "give --generate open-sea|coastal|tss or --dir FOLDER".into(),
            ));
        }
    };
    if items.is_empty() {
        let what = match dir {
            Some(dir) if kind.is_none() => {
                format!("{} holds no scenario files (*.ron, *.json)", dir.display())
            }
            _ => format!("--count {} makes no scenario", args.count),
        };
        return Err(CliError::BadInput(if shard == Shard::ALL {
            what
        } else {
            format!("shard {shard} holds no scenario: {what} for it")
        }));
    }
    Ok((items, generator))
}

/// Runs `vorrt batch`.
///
/// # Errors
/// [`CliError::BadInput`] for bad options or scenarios, [`CliError::Output`]
/// when the output cannot be written.
pub(crate) fn batch_command(args: &BatchArgs) -> Result<ExitStatus, CliError> {
    let started = Instant::now();
    let (items, generator) = items_of(&args.generator, args.generate, args.dir.as_deref())?;
    prepare_out(&args.out)?;
    for folder in [FAILURES, FINDINGS] {
        clean_saved(&args.out, folder)?;
    }
    let shard = args.generator.shard()?;
    let pool = {
        let mut builder = rayon::ThreadPoolBuilder::new();
        if let Some(jobs) = args.jobs {
            builder = builder.num_threads(jobs);
        }
        builder
            .build()
            .map_err(|error| CliError::BadInput(format!("cannot start worker threads: {error}")))?
    };
    let threads = pool.current_num_threads();
    console::warn(&format!(
        "running {} scenarios (shard {shard}) on {threads} threads",
        items.len()
    ));
    let progress = Progress::new(items.len());
    let export_error = std::sync::Mutex::new(None);
    let export = |item: &BatchItem, record: &vorrt_scenarios::SimulationRecord| {
        if args.trajectories
            && let Err(error) = write_run_trajectory(item, record, &args.out)
            && let Ok(mut first) = export_error.lock()
        {
            first.get_or_insert(error);
        }
    };
    let rows = pool.install(|| {
        batch::run_batch_with(&items, &|done, row| progress.report(done, row), &export)
    });
    if let Some(error) = export_error.into_inner().ok().flatten() {
        return Err(error);
    }
    progress.finish();
    let wall_time_s = started.elapsed().as_secs_f64();
    // The scenario files of the failures first: they matter most.
    write_saved(&items, &rows, &args.out)?;
    let summary = write_all(&rows, &args.out)?;
    let info = RunInfo {
        vorrt_version: env!("CARGO_PKG_VERSION").to_owned(),
        command: std::env::args().collect(),
        generator,
        dir: args.dir.clone(),
        seed: args.generator.seed,
        count: args.generator.count,
        shard: shard.to_string(),
        scenarios_run: rows.len(),
        threads,
        wall_time_s,
        merged_shards: Vec::new(),
        missing_shards: Vec::new(),
    };
    info.write(&args.out)?;
    console::print(&summary_table(&summary));
    console::line(&format!(
        "wall time {wall_time_s:.1} s; wrote {}",
        args.out.display()
    ));
    Ok(ExitStatus::Success)
}

/// Runs `vorrt generate`.
///
/// # Errors
/// As [`batch_command`].
pub(crate) fn generate_command(args: &GenerateArgs) -> Result<ExitStatus, CliError> {
    let (items, _) = items_of(&args.generator, Some(args.kind), None)?;
    prepare_out(&args.out)?;
    for item in &items {
        write_scenario(
            item,
            &args.out,
            &format!("{}.ron", folder_name(&item.scenario.name)),
        )?;
    }
    console::line(&format!(
        "wrote {} scenarios to {}",
        items.len(),
        args.out.display()
    ));
    Ok(ExitStatus::Success)
}

/// Writes `trajectory.csv` of one batch run into `DIR/runs/<index>-<name>/`.
fn write_run_trajectory(
    item: &BatchItem,
    record: &vorrt_scenarios::SimulationRecord,
    out: &Path,
) -> Result<(), CliError> {
    let dir = out.join("runs").join(format!(
        "{}-{}",
        item.index,
        folder_name(&item.scenario.name)
    ));
    std::fs::create_dir_all(&dir).map_err(output_error(&dir))?;
    let text = crate::export::trajectory_csv(&item.scenario, record)?;
    let path = dir.join(crate::export::TRAJECTORY_CSV);
    std::fs::write(&path, text).map_err(output_error(&path))
}

fn write_scenario(item: &BatchItem, dir: &Path, file: &str) -> Result<PathBuf, CliError> {
    let text = item
        .scenario
        .to_ron_string()
        .map_err(|error| CliError::Output(error.to_string()))?;
    let path = dir.join(file);
    std::fs::write(&path, text).map_err(output_error(&path))?;
    Ok(path)
}

/// The folder of the failures' scenario files: runs that were not a
/// success ([`BatchRow::success`]).
const FAILURES: &str = "failures";

/// The folder of the scenario files of runs that succeeded but broke
/// COLREGs (a finding: not [`BatchRow::compliant`]).
const FINDINGS: &str = "findings";

/// The file name of a saved run's scenario in `failures/` or `findings/`:
/// its batch index (unique within a batch, and across its shards) and its name.
fn failure_file(item: &BatchItem) -> String {
    format!("{:06}-{}.ron", item.index, folder_name(&item.scenario.name))
}

/// Where a run's scenario is saved: `failures/` when it was not a success,
/// `findings/` when it succeeded with a COLREGs finding, nowhere when it
/// succeeded and complied.
fn saved_folder(row: &BatchRow) -> Option<&'static str> {
    if !row.success() {
        Some(FAILURES)
    } else if !row.compliant {
        Some(FINDINGS)
    } else {
        None
    }
}

/// Removes the `*.ron` files a previous batch left in `DIR/<folder>/`, so
/// that the folder holds only this batch's runs (documented in
/// `docs/evaluation.md`).
fn clean_saved(dir: &Path, folder: &str) -> Result<(), CliError> {
    let folder = dir.join(folder);
    let Ok(entries) = std::fs::read_dir(&folder) else {
        return Ok(());
    };
    for entry in entries.filter_map(Result::ok) {
        let path = entry.path();
        if path.is_file() && path.extension().is_some_and(|extension| extension == "ron") {
            std::fs::remove_file(&path).map_err(|error| {
                CliError::Output(format!(
                    "cannot remove the old saved run {}: {error}",
                    path.display()
                ))
            })?;
        }
    }
    Ok(())
}

/// Writes the scenario of every run that was not a success, or had a
/// COLREGs finding, into `DIR/failures/` or `DIR/findings/`
/// ([`saved_folder`]) as [`failure_file`] (nothing, and no folder, when
/// there is none of its kind).
fn write_saved(items: &[BatchItem], rows: &[BatchRow], dir: &Path) -> Result<(), CliError> {
    for (item, row) in items.iter().zip(rows) {
        let Some(folder) = saved_folder(row) else {
            continue;
        };
        let folder = dir.join(folder);
        std::fs::create_dir_all(&folder).map_err(output_error(&folder))?;
        let mut item = item.clone();
        // The file carries the seed it was run with, so `vorrt simulate`
        // repeats the run.
        item.scenario.seed = Some(item.seed);
        write_scenario(&item, &folder, &failure_file(&item))?;
    }
    Ok(())
}

/// Rows, summary and plots.
pub(crate) fn write_all(rows: &[BatchRow], dir: &Path) -> Result<BatchSummary, CliError> {
    let summary = batch::write_outputs(rows, dir).map_err(batch_error)?;
    write_histograms(rows, dir).map_err(CliError::Output)?;
    Ok(summary)
}

/// Progress on stderr: a bar on a terminal, one line per run otherwise.
struct Progress {
    bar: Option<indicatif::ProgressBar>,
    total: usize,
}

impl Progress {
    fn new(total: usize) -> Self {
        let bar = std::io::stderr().is_terminal().then(|| {
            let bar = indicatif::ProgressBar::new(total as u64);
            if let Ok(style) = indicatif::ProgressStyle::with_template(
                "{elapsed_precise} [{bar:40}] {pos}/{len} (eta {eta}) {msg}",
            ) {
                bar.set_style(style.progress_chars("=> "));
            }
            bar
        });
        Self { bar, total }
    }

    fn report(&self, done: usize, row: &BatchRow) {
        let outcome = if !row.error.is_empty() {
            format!("error: {}", row.error)
        } else if !row.success() {
            format!(
                "unsafe (goal {}, min {:.0} m, collision {})",
                if row.reached_goal {
                    "reached"
                } else {
                    "not reached"
                },
                row.min_distance_m,
                row.collision
            )
        } else if !row.compliant {
            format!(
                "findings: {}, min {:.0} m",
                if row.violations.is_empty() {
                    "not judged"
                } else {
                    &row.violations
                },
                row.min_distance_m
            )
        } else {
            format!("compliant, min {:.0} m", row.min_distance_m)
        };
        match &self.bar {
            Some(bar) => {
                bar.set_position(done as u64);
                if saved_folder(row).is_some() {
                    bar.println(format!("{}: {outcome}", row.name));
                }
            }
            None => console::warn(&format!("[{done}/{}] {}: {outcome}", self.total, row.name)),
        }
    }

    fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

fn percent(rate: f64) -> String {
    format!("{:.1} %", 100.0 * rate)
}

fn number(value: Option<f64>, digits: usize) -> String {
    value.map_or_else(|| "-".to_owned(), |value| format!("{value:.digits$}"))
}

/// The summary as a small text table.
#[must_use]
pub(crate) fn summary_table(summary: &BatchSummary) -> String {
    use std::fmt::Write as _;
    let mut text = String::new();
    let _ = writeln!(text, "scenarios            {}", summary.count);
    if summary.errors > 0 {
        let _ = writeln!(text, "could not run        {}", summary.errors);
    }
    // Success leaves compliance out: the two side by side.
    let _ = writeln!(
        text,
        "success              {}   compliant {}",
        percent(summary.success_rate),
        percent(summary.compliance_rate)
    );
    let _ = writeln!(
        text,
        "reached goal         {}",
        percent(summary.reached_goal_rate)
    );
    let _ = writeln!(
        text,
        "collision            {}",
        percent(summary.collision_rate)
    );
    let _ = writeln!(
        text,
        "clearance violated   {}",
        percent(summary.clearance_violation_rate)
    );
    let _ = writeln!(text, "COLREGs by rule");
    for rule in &summary.rules {
        let _ = writeln!(
            text,
            "  rule {}              {} of {} runs",
            rule.rule,
            rule.rate.map_or_else(|| "-".to_owned(), percent),
            rule.applicable
        );
    }
    let p = &summary.min_distance_m;
    let _ = writeln!(
        text,
        "min distance m       min {} p1 {} p10 {} p50 {}",
        number(p.min, 0),
        number(p.p1, 0),
        number(p.p10, 0),
        number(p.p50, 0)
    );
    for (name, p, digits) in [
        ("path overhead %    ", &summary.path_overhead_pct, 1),
        ("time overhead %    ", &summary.time_overhead_pct, 1),
        ("planning ms/run    ", &summary.planning_time_ms, 0),
        ("planning ms/plan   ", &summary.planning_time_per_plan_ms, 1),
        ("replans/run        ", &summary.replans, 0),
    ] {
        let _ = writeln!(
            text,
            "{name}  p50 {} p90 {} p99 {} max {}",
            number(p.p50, digits),
            number(p.p90, digits),
            number(p.p99, digits),
            number(p.max, digits)
        );
    }
    let _ = writeln!(
        text,
        "failed plans         {} in {} runs",
        summary.failed_plans, summary.runs_with_failed_plans
    );
    if summary.lane_crossings > 0 || summary.runs_with_rule10_findings > 0 {
        let p = &summary.crossing_off_perpendicular_deg;
        let _ = writeln!(
            text,
            "rule 10              {} lane crossings, {} square; off perpendicular ° p50 {} p99 {} max {}",
            summary.lane_crossings,
            summary
                .lane_crossing_square_rate
                .map_or_else(|| "-".to_owned(), percent),
            number(p.p50, 1),
            number(p.p99, 1),
            number(p.max, 1)
        );
        let _ = writeln!(
            text,
            "rule 10 findings     in {} runs; separation zone entered in {} runs",
            summary.runs_with_rule10_findings, summary.runs_with_separation_zone_entry
        );
    }
    text
}
