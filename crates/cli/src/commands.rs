//! What each subcommand does.

use crate::args::{Cli, Command, PlanFormat};
use crate::report::{PlanOutput, Report};
use crate::{demo, plot};
use std::fmt;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use vorrt_planner::Planner;
use vorrt_scenarios::{Evaluation, Scenario, SimulationRecord, evaluate, simulate};

/// How a command ended, as the process's exit code.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExitStatus {
    /// 0: success.
    Success,
    /// 1: the planner found no safe path, or a run did not reach its goal safely.
    Unsafe,
    /// 2: bad input or usage.
    BadInput,
}

impl ExitStatus {
    /// The numeric exit code.
    #[must_use]
    pub fn code(self) -> u8 {
        match self {
            Self::Success => 0,
            Self::Unsafe => 1,
            Self::BadInput => 2,
        }
    }
}

impl From<ExitStatus> for ExitCode {
    fn from(status: ExitStatus) -> Self {
        ExitCode::from(status.code())
    }
}

/// Why a command failed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CliError {
    /// A scenario could not be read or is invalid, or an option is wrong (exit 2).
    BadInput(String),
    /// An output file or folder could not be written (exit 2).
    Output(String),
    /// The planner found no safe path (exit 1).
    NoSafePath(String),
}

impl CliError {
    /// The exit status this error ends the program with.
    #[must_use]
    pub fn status(&self) -> ExitStatus {
        match self {
            Self::BadInput(_) | Self::Output(_) => ExitStatus::BadInput,
            Self::NoSafePath(_) => ExitStatus::Unsafe,
        }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::BadInput(message) | Self::Output(message) | Self::NoSafePath(message) => {
                f.write_str(message)
            }
        }
    }
}

impl std::error::Error for CliError {}

/// Runs the parsed command line.
///
/// # Errors
/// [`CliError`] when the command could not do its work.
pub fn run(cli: Cli) -> Result<ExitStatus, CliError> {
    match cli.command {
        Command::Simulate {
            scenario,
            seed,
            out,
        } => simulate_command(&scenario, seed, out.as_deref()),
        Command::Plan {
            scenario,
            seed,
            format,
        } => plan_command(&scenario, seed, format),
        Command::Check { scenarios } => Ok(check_command(&scenarios)),
        Command::Demo {
            out,
            seed,
            fixtures,
            only,
        } => demo::run(&demo::DemoOptions {
            out,
            seed,
            fixtures,
            only,
        }),
        Command::Batch(args) => crate::batch::batch_command(&args),
        Command::Generate(args) => crate::batch::generate_command(&args),
        Command::Merge(args) => crate::batch::merge_command(&args),
        Command::ImportAis(args) => crate::import_ais::import_ais_command(&args),
    }
}

/// Loads and validates a scenario file, as a [`CliError::BadInput`] on failure.
///
/// # Errors
/// The scenario error's message: it names the file, and the line or field.
pub fn load(path: &Path) -> Result<Scenario, CliError> {
    Scenario::load(path).map_err(|error| CliError::BadInput(error.to_string()))
}

/// The seed a run uses: the one given, else the scenario's, else 1.
#[must_use]
pub fn seed_for(scenario: &Scenario, seed: Option<u64>) -> u64 {
    seed.or(scenario.seed).unwrap_or(1)
}

/// A finished closed-loop run with its evaluation and report.
#[derive(Debug, Clone)]
pub struct Run {
    /// Every recorded state and planner call.
    pub record: SimulationRecord,
    /// The library's evaluation.
    pub evaluation: Evaluation,
    /// The report written to `report.json`.
    pub report: Report,
}

/// Simulates `scenario` with `seed` and evaluates the run.
///
/// # Errors
/// [`CliError::BadInput`] when the scenario's planner settings are invalid.
pub fn run_scenario(scenario: &Scenario, seed: u64) -> Result<Run, CliError> {
    let record = simulate(scenario, seed).map_err(|error| CliError::BadInput(error.to_string()))?;
    let evaluation = evaluate(scenario, &record);
    let report = Report::new(scenario, &record, &evaluation);
    Ok(Run {
        record,
        evaluation,
        report,
    })
}

/// The files [`write_outputs`] writes into its folder.
pub const OUTPUT_FILES: [&str; 5] = [
    "report.json",
    "trajectories.svg",
    "trajectories.png",
    "distance.svg",
    "distance.png",
];

/// Writes `report.json`, the four plots and the trajectory exports
/// ([`crate::export::write_trajectories`]) of `run` into `dir` (created if needed).
///
/// # Errors
/// [`CliError::Output`] when a file cannot be written.
pub fn write_outputs(scenario: &Scenario, run: &Run, dir: &Path) -> Result<(), CliError> {
    std::fs::create_dir_all(dir)
        .map_err(|error| CliError::Output(format!("cannot create {}: {error}", dir.display())))?;
    let json = serde_json::to_string_pretty(&run.report)
        .map_err(|error| CliError::Output(format!("cannot write the report as JSON: {error}")))?;
    let report_path = dir.join("report.json");
    std::fs::write(&report_path, json + "\n").map_err(|error| {
        CliError::Output(format!("cannot write {}: {error}", report_path.display()))
    })?;
    plot::write_plots(scenario, &run.record, &run.evaluation, dir).map_err(CliError::Output)?;
    crate::export::write_trajectories(scenario, run, dir)?;
    Ok(())
}

/// A file-system friendly version of a scenario name.
#[must_use]
pub fn folder_name(name: &str) -> String {
    let cleaned: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect();
    if cleaned.is_empty() {
        "scenario".to_owned()
    } else {
        cleaned
    }
}

fn yes_no(value: bool) -> &'static str {
    if value { "yes" } else { "no" }
}

/// The summary table `simulate` prints.
#[must_use]
pub fn summary_table(report: &Report) -> String {
    use std::fmt::Write as _;
    let mut text = String::new();
    let _ = writeln!(
        text,
        "scenario {} (seed {}), d_th = {:.0} m",
        report.scenario, report.seed, report.d_th_m
    );
    let name_width = report
        .targets
        .iter()
        .map(|target| target.name.chars().count())
        .chain([6])
        .max()
        .unwrap_or(6);
    let _ = writeln!(
        text,
        "\n{:<name_width$}  {:<17}  {:<8}  {:>10}  {:>10}  {:<9}  {:>5}",
        "target", "encounter", "role", "min dist m", "at min", "compliant", "score"
    );
    for target in &report.targets {
        let _ = writeln!(
            text,
            "{:<name_width$}  {:<17}  {:<8}  {:>10.1}  {:>6.1} min  {:<9}  {:>5.2}",
            target.name,
            target.encounter,
            target.role,
            target.min_distance_m,
            target.time_of_min_s / 60.0,
            yes_no(target.compliant),
            target.score
        );
        for violation in &target.violations {
            let _ = writeln!(text, "{:<name_width$}    - {violation}", "");
        }
    }
    if report.targets.is_empty() {
        let _ = writeln!(text, "(no targets)");
    }
    let _ = writeln!(text);
    let arrival = match report.arrival_time_s {
        Some(time_s) => format!("yes, at {:.1} min", time_s / 60.0),
        None => format!("no (run ended at {:.1} min)", report.duration_s / 60.0),
    };
    let _ = writeln!(text, "reached goal:   {arrival}");
    let _ = writeln!(text, "collision:      {}", yes_no(report.collision));
    let minimum = match report.min_distance_m {
        Some(distance) => format!(
            "{distance:.1} m vs d_th {:.0} m: {}",
            report.d_th_m,
            if report.clearance_kept {
                "kept"
            } else {
                "BROKEN"
            }
        ),
        None => "- (no targets)".to_owned(),
    };
    let _ = writeln!(text, "min distance:   {minimum}");
    let _ = writeln!(
        text,
        "COLREGs:        {}",
        if report.compliant {
            "compliant"
        } else {
            "violated"
        }
    );
    let _ = writeln!(
        text,
        "path:           {:.0} m sailed vs {:.0} m straight: overhead {:.1} %",
        report.path_length_m, report.straight_length_m, report.path_overhead_pct
    );
    let _ = writeln!(
        text,
        "planner:        {} plans made, {} replans, {} failed; {:.3} s planning",
        report.planning.plans_made,
        report.planning.replans,
        report.planning.failed_plans,
        report.planning.total_planning_time_s
    );
    text
}

fn simulate_command(
    path: &Path,
    seed: Option<u64>,
    out: Option<&Path>,
) -> Result<ExitStatus, CliError> {
    let scenario = load(path)?;
    let seed = seed_for(&scenario, seed);
    let run = run_scenario(&scenario, seed)?;
    let dir = out.map_or_else(
        || PathBuf::from("out").join(folder_name(&scenario.name)),
        Path::to_path_buf,
    );
    write_outputs(&scenario, &run, &dir)?;
    print!("{}", summary_table(&run.report));
    let exports = if scenario.is_geographic() {
        ",trajectory.csv,trajectory.geojson,trajectory.gpx"
    } else {
        ",trajectory.csv"
    };
    println!(
        "\nwrote {}/{{{}{exports}}}",
        dir.display(),
        OUTPUT_FILES.join(",")
    );
    if run.report.reached_goal_safely {
        Ok(ExitStatus::Success)
    } else {
        eprintln!("the run did not reach its goal safely");
        Ok(ExitStatus::Unsafe)
    }
}

fn plan_command(
    path: &Path,
    seed: Option<u64>,
    format: PlanFormat,
) -> Result<ExitStatus, CliError> {
    let scenario = load(path)?;
    let seed = seed_for(&scenario, seed);
    let config = scenario
        .planner_config()
        .map_err(|error| CliError::BadInput(error.to_string()))?;
    let d_th_m = config.clearance_m;
    let mut planner = Planner::new(config)
        .map_err(|error| CliError::BadInput(format!("{}: {error}", scenario.source)))?;
    let plan = planner
        .plan(&scenario.planning_problem(), seed)
        .map_err(|error| match error {
            vorrt_planner::PlannerError::NoSafePath { .. }
            | vorrt_planner::PlannerError::BudgetExhausted { .. } => {
                CliError::NoSafePath(format!("{}: {error}", scenario.source))
            }
            _ => CliError::BadInput(format!("{}: {error}", scenario.source)),
        })?;
    let text = match format {
        PlanFormat::Json => {
            let output = PlanOutput::new(&scenario, seed, d_th_m, &plan);
            serde_json::to_string_pretty(&output).map_err(|error| {
                CliError::Output(format!("cannot write the plan as JSON: {error}"))
            })?
        }
        PlanFormat::Geojson => crate::export::plan_geojson(&scenario, seed, &plan)?,
        PlanFormat::Gpx => crate::export::plan_gpx(&scenario, &plan)?,
    };
    println!("{text}");
    Ok(ExitStatus::Success)
}

fn check_command(paths: &[PathBuf]) -> ExitStatus {
    let mut status = ExitStatus::Success;
    for path in paths {
        match Scenario::load(path) {
            Ok(_) => println!("ok: {}", path.display()),
            Err(error) => {
                eprintln!("error: {error}");
                status = ExitStatus::BadInput;
            }
        }
    }
    status
}
