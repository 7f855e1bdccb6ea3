//! Monte Carlo campaigns: `vorrt batch`, `vorrt generate` and `vorrt merge`,
//! with SVG histograms of the minimum distance and of the planning time.
//!
//! `batch` writes into its `--out` folder: `rows.csv` (one row per scenario,
//! [`vorrt_scenarios::BatchRow`]), `summary.json`
//! ([`vorrt_scenarios::BatchSummary`]), `run.json` (how the batch was made:
//! generator, seed, shard, wall time), `min_distance.svg`,
//! `planning_time.svg`, and `failures/` with the scenario file of every run
//! that was not a success. `merge` writes the same rows, summary and plots
//! for several shard folders together.

use crate::commands::{CliError, ExitStatus, folder_name};
use crate::font;
use clap::{Args, ValueEnum};
use plotters::prelude::*;
use serde::Serialize;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::time::Instant;
use vorrt_scenarios::batch::{
    self, BatchItem, BatchRow, BatchSummary, Shard, generate_items, load_items,
};
use vorrt_scenarios::generator::{
    GeneratorSpec, OpenSeaSpec, TargetBehaviour, TssDirection, TssSpec,
};

/// Which generator.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Kind {
    /// Open-sea encounters: targets on near-collision courses (see
    /// docs/evaluation.md).
    OpenSea,
    /// Crossings of a traffic separation scheme.
    Tss,
}

/// How the generated targets move.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum BehaviourName {
    /// Straight for their goals at constant speed (the paper's).
    Constant,
    /// Give way to ownship by COLREGs when they must (35° to starboard).
    Colregs,
    /// Course and speed wander about the nominal (5°, 0.5 kn).
    Noisy,
    /// Turn 30-90° to a random side, unannounced, before the closest approach.
    SuddenTurn,
}

/// Lane layout of a generated TSS.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum DirectionName {
    /// One lane, traffic flowing west.
    Westbound,
    /// One lane, traffic flowing east.
    Eastbound,
    /// Two lanes with a separation zone.
    TwoWay,
}

/// The generator options shared by `batch --generate` and `generate`.
#[derive(Debug, Clone, Args)]
pub struct GeneratorArgs {
    /// Open sea: number of targets per scenario (1-64).
    #[arg(long, value_name = "N")]
    pub targets: Option<usize>,
    /// TSS: traffic density, targets per nautical mile of lane [default: 1].
    #[arg(long, value_name = "PER_NM")]
    pub density: Option<f64>,
    /// TSS: lane layout.
    #[arg(long, value_enum, default_value = "westbound")]
    pub direction: DirectionName,
    /// TSS: lane width, nautical miles.
    #[arg(long, value_name = "NM", default_value_t = 1.0)]
    pub lane_width: f64,
    /// Number of scenarios in the whole batch (before sharding).
    #[arg(long, value_name = "K", default_value_t = 100)]
    pub count: u64,
    /// Batch seed: scenario k is drawn from stream k of this seed and
    /// simulated with a seed derived from (seed, k).
    #[arg(long, value_name = "S", default_value_t = 1)]
    pub seed: u64,
    /// How the targets move.
    #[arg(long, value_enum, default_value = "constant")]
    pub behaviour: BehaviourName,
    /// Only the scenarios k with k % n == i (e.g. --shard
    /// $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT).
    #[arg(long, value_name = "i/n")]
    pub shard: Option<String>,
}

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
                    CliError::BadInput("open sea needs --targets N (1 to 64)".into())
                })?;
                Ok(GeneratorSpec::OpenSea(
                    OpenSeaSpec::with_targets(targets).with_behaviour(behaviour),
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

/// `vorrt batch`.
#[derive(Debug, Clone, Args)]
pub struct BatchArgs {
    /// Generate the scenarios.
    #[arg(
        long,
        value_enum,
        value_name = "KIND",
        conflicts_with = "dir",
        required_unless_present = "dir"
    )]
    pub generate: Option<Kind>,
    /// Run the scenario files (*.ron) of this folder instead, in file-name
    /// order; each with its own `seed` if it has one.
    #[arg(long, value_name = "FOLDER")]
    pub dir: Option<PathBuf>,
    /// The generator, seed and shard options.
    #[command(flatten)]
    pub generator: GeneratorArgs,
    /// Worker threads [default: one per core].
    #[arg(long, value_name = "N")]
    pub jobs: Option<usize>,
    /// Output folder.
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
    /// Also write every run's trajectory.csv, into
    /// `DIR/runs/<index>-<scenario name>/`.
    #[arg(long)]
    pub trajectories: bool,
}

/// `vorrt generate`.
#[derive(Debug, Clone, Args)]
pub struct GenerateArgs {
    /// Which generator.
    #[arg(value_enum)]
    pub kind: Kind,
    /// The generator, seed and shard options.
    #[command(flatten)]
    pub generator: GeneratorArgs,
    /// Output folder for the .ron files.
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
}

/// `vorrt merge`.
#[derive(Debug, Clone, Args)]
pub struct MergeArgs {
    /// Shard output folders (each holding rows.csv) or rows CSV files.
    #[arg(required = true, value_name = "DIR")]
    pub inputs: Vec<PathBuf>,
    /// Output folder.
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
}

/// How a batch was made: `run.json`.
#[derive(Debug, Serialize)]
struct RunInfo {
    vorrt_version: &'static str,
    command: Vec<String>,
    generator: Option<GeneratorSpec>,
    dir: Option<PathBuf>,
    seed: u64,
    count: u64,
    shard: String,
    scenarios_run: usize,
    threads: usize,
    wall_time_s: f64,
}

fn output_error(path: &Path) -> impl FnOnce(std::io::Error) -> CliError + '_ {
    move |error| CliError::Output(format!("cannot write {}: {error}", path.display()))
}

fn batch_error(error: batch::BatchError) -> CliError {
    match error {
        batch::BatchError::Io { .. } => CliError::Output(error.to_string()),
        other => CliError::BadInput(other.to_string()),
    }
}

/// Runs `vorrt batch`.
///
/// # Errors
/// [`CliError::BadInput`] for bad options or scenarios, [`CliError::Output`]
/// when the output cannot be written.
pub fn batch_command(args: &BatchArgs) -> Result<ExitStatus, CliError> {
    let shard = args.generator.shard()?;
    let started = Instant::now();
    let (items, generator) = match (&args.generate, &args.dir) {
        (Some(kind), _) => {
            let spec = args.generator.spec(*kind)?;
            let items = generate_items(&spec, args.generator.seed, args.generator.count, shard)
                .map_err(batch_error)?;
            (items, Some(spec))
        }
        (None, Some(dir)) => (
            load_items(dir, args.generator.seed, shard).map_err(batch_error)?,
            None,
        ),
        (None, None) => {
            return Err(CliError::BadInput(
                "give --generate open-sea|tss or --dir FOLDER".into(),
            ));
        }
    };
    let pool = {
        let mut builder = rayon::ThreadPoolBuilder::new();
        if let Some(jobs) = args.jobs {
            builder = builder.num_threads(jobs.max(1));
        }
        builder
            .build()
            .map_err(|error| CliError::BadInput(format!("cannot start worker threads: {error}")))?
    };
    let threads = pool.current_num_threads();
    eprintln!(
        "running {} scenarios (shard {shard}) on {threads} threads",
        items.len()
    );
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
    let summary = write_all(&rows, &args.out)?;
    write_failures(&items, &rows, &args.out)?;
    let info = RunInfo {
        vorrt_version: env!("CARGO_PKG_VERSION"),
        command: std::env::args().collect(),
        generator,
        dir: args.dir.clone(),
        seed: args.generator.seed,
        count: args.generator.count,
        shard: shard.to_string(),
        scenarios_run: rows.len(),
        threads,
        wall_time_s,
    };
    let path = args.out.join("run.json");
    let json = serde_json::to_string_pretty(&info).unwrap_or_default();
    std::fs::write(&path, json + "\n").map_err(output_error(&path))?;
    print!("{}", summary_table(&summary));
    println!("wall time {wall_time_s:.1} s; wrote {}", args.out.display());
    Ok(ExitStatus::Success)
}

/// Runs `vorrt generate`.
///
/// # Errors
/// As [`batch_command`].
pub fn generate_command(args: &GenerateArgs) -> Result<ExitStatus, CliError> {
    let spec = args.generator.spec(args.kind)?;
    let shard = args.generator.shard()?;
    let items = generate_items(&spec, args.generator.seed, args.generator.count, shard)
        .map_err(batch_error)?;
    std::fs::create_dir_all(&args.out).map_err(output_error(&args.out))?;
    for item in &items {
        write_scenario(item, &args.out)?;
    }
    println!("wrote {} scenarios to {}", items.len(), args.out.display());
    Ok(ExitStatus::Success)
}

/// Runs `vorrt merge`.
///
/// # Errors
/// [`CliError::BadInput`] when an input cannot be read or two inputs hold the
/// same scenario; [`CliError::Output`] when the output cannot be written.
pub fn merge_command(args: &MergeArgs) -> Result<ExitStatus, CliError> {
    let rows = batch::read_shards(&args.inputs).map_err(batch_error)?;
    let summary = write_all(&rows, &args.out)?;
    print!("{}", summary_table(&summary));
    println!(
        "merged {} inputs into {}",
        args.inputs.len(),
        args.out.display()
    );
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

fn write_scenario(item: &BatchItem, dir: &Path) -> Result<PathBuf, CliError> {
    let text = item
        .scenario
        .to_ron_string()
        .map_err(|error| CliError::Output(error.to_string()))?;
    let path = dir.join(format!("{}.ron", folder_name(&item.scenario.name)));
    std::fs::write(&path, text).map_err(output_error(&path))?;
    Ok(path)
}

/// Writes the scenario of every run that was not a success into
/// `DIR/failures/` (nothing, and no folder, when all succeeded).
fn write_failures(items: &[BatchItem], rows: &[BatchRow], dir: &Path) -> Result<(), CliError> {
    let failed: Vec<&BatchItem> = items
        .iter()
        .zip(rows)
        .filter(|(_, row)| !row.success())
        .map(|(item, _)| item)
        .collect();
    if failed.is_empty() {
        return Ok(());
    }
    let folder = dir.join("failures");
    std::fs::create_dir_all(&folder).map_err(output_error(&folder))?;
    for item in failed {
        let mut item = item.clone();
        // The file carries the seed it was run with, so `vorrt simulate`
        // repeats the run.
        item.scenario.seed = Some(item.seed);
        write_scenario(&item, &folder)?;
    }
    Ok(())
}

/// Rows, summary and plots.
fn write_all(rows: &[BatchRow], dir: &Path) -> Result<BatchSummary, CliError> {
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
        } else if row.success() {
            format!("ok, min {:.0} m", row.min_distance_m)
        } else {
            format!(
                "FAIL (goal {}, min {:.0} m, collision {})",
                if row.reached_goal {
                    "reached"
                } else {
                    "not reached"
                },
                row.min_distance_m,
                row.collision
            )
        };
        match &self.bar {
            Some(bar) => {
                bar.set_position(done as u64);
                if !row.success() {
                    bar.println(format!("{}: {outcome}", row.name));
                }
            }
            None => eprintln!("[{done}/{}] {}: {outcome}", self.total, row.name),
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
pub fn summary_table(summary: &BatchSummary) -> String {
    use std::fmt::Write as _;
    let mut text = String::new();
    let _ = writeln!(text, "scenarios            {}", summary.count);
    if summary.errors > 0 {
        let _ = writeln!(text, "could not run        {}", summary.errors);
    }
    let _ = writeln!(
        text,
        "success              {}",
        percent(summary.success_rate)
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
    let _ = writeln!(
        text,
        "compliant            {}",
        percent(summary.compliance_rate)
    );
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
    text
}

/// Writes `min_distance.svg` and `planning_time.svg`.
///
/// # Errors
/// A message when a file cannot be drawn or written.
pub fn write_histograms(rows: &[BatchRow], dir: &Path) -> Result<(), String> {
    font::register();
    let clearance = rows
        .iter()
        .map(|row| row.clearance_m)
        .find(|value| value.is_finite());
    let distances: Vec<f64> = rows
        .iter()
        .map(|row| row.min_distance_m)
        .filter(|value| value.is_finite())
        .collect();
    histogram(
        &dir.join("min_distance.svg"),
        "Minimum distance to any target per run",
        "minimum distance (m)",
        &distances,
        clearance,
    )?;
    let times: Vec<f64> = rows
        .iter()
        .filter(|row| row.error.is_empty())
        .map(|row| row.planning_time_ms)
        .collect();
    histogram(
        &dir.join("planning_time.svg"),
        "Planning time per run (all planner calls)",
        "planning time (ms)",
        &times,
        None,
    )
}

const BINS: usize = 40;

fn histogram(
    path: &Path,
    title: &str,
    x_label: &str,
    values: &[f64],
    marker: Option<f64>,
) -> Result<(), String> {
    let text = |error: &dyn std::fmt::Display| format!("{}: {error}", path.display());
    let high = values.iter().copied().fold(0.0, f64::max).max(1.0) * 1.0001;
    let high = marker.map_or(high, |m| high.max(m * 1.1));
    let width = high / BINS as f64;
    let mut counts = [0u32; BINS];
    for value in values {
        let bin = ((value / width).floor().max(0.0) as usize).min(BINS - 1);
        counts[bin] += 1;
    }
    let top = counts.iter().copied().max().unwrap_or(0).max(1);
    let root = SVGBackend::new(path, (900, 520)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| text(&e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!("{title} ({} runs)", values.len()),
            (font::FAMILY, 20),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..high, 0u32..(top + top / 10 + 1))
        .map_err(|e| text(&e))?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc("runs")
        .label_style((font::FAMILY, 14))
        .draw()
        .map_err(|e| text(&e))?;
    chart
        .draw_series(
            counts
                .iter()
                .enumerate()
                .filter(|(_, c)| **c > 0)
                .map(|(bin, count)| {
                    let x0 = bin as f64 * width;
                    Rectangle::new([(x0, 0), (x0 + width, *count)], BLUE.mix(0.6).filled())
                }),
        )
        .map_err(|e| text(&e))?;
    if let Some(marker) = marker {
        chart
            .draw_series(std::iter::once(PathElement::new(
                vec![(marker, 0), (marker, top + top / 10 + 1)],
                RED.stroke_width(2),
            )))
            .map_err(|e| text(&e))?
            .label(format!("d_th = {marker:.0} m"))
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], RED.stroke_width(2)));
        chart
            .configure_series_labels()
            .label_font((font::FAMILY, 14))
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(|e| text(&e))?;
    }
    root.present().map_err(|e| text(&e))
}
