//! What each subcommand does.

use crate::args::{Cli, Command, PlanFormat};
use crate::error::{CliError, ExitStatus};
use crate::progress::Ticker;
use crate::report::{PlanOutput, Report, yes_no};
use crate::run::{OUTPUT_FILES, folder_name, load, run_scenario, seed_for, write_outputs};
use crate::{batch, console, demo};
use std::path::{Path, PathBuf};
use vorrt_planner::Planner;
use vorrt_scenarios::Scenario;

/// Runs the parsed command line.
///
/// # Errors
/// [`CliError`] when the command could not do its work.
pub(crate) fn run(cli: Cli) -> Result<ExitStatus, CliError> {
    match cli.command {
        Command::Simulate {
            scenario,
            seed,
            out,
            ais,
            ais_origin,
        } => simulate_command(
            &scenario,
            seed,
            out.as_deref(),
            &AisOut {
                write: ais,
                origin: ais_origin,
            },
        ),
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
        Command::Batch(args) => batch::batch_command(&args),
        Command::Generate(args) => batch::generate_command(&args),
        Command::Merge(args) => batch::merge_command(&args),
        Command::ImportAis(args) => crate::import_ais::import_ais_command(&args),
        Command::Judge(args) => crate::judge::judge_command(&args),
        Command::Coast(args) => crate::coast::coast_command(&args),
    }
}

/// The planner calls of a run in one unambiguous phrase: every call is the
/// first plan or a replan, and succeeded or failed.
pub(crate) fn planner_calls(report: &Report) -> String {
    let planning = &report.planning;
    let calls = planning.plans_made + planning.failed_plans;
    format!(
        "{calls} calls (the first plan and {} replans): {} succeeded, {} failed; {:.3} s planning",
        planning.replans,
        planning.plans_made,
        planning.failed_plans,
        planning.total_planning_time_s
    )
}

/// The summary table `simulate` prints.
#[must_use]
pub(crate) fn summary_table(report: &Report) -> String {
    use std::fmt::Write as _;
    let mut text = String::new();
    let _ = writeln!(
        text,
        "scenario {} (seed {}), d_th = {:.0} m",
        report.scenario, report.seed, report.d_th_m
    );
    report.write_target_table(&mut text);
    let _ = writeln!(text);
    let arrival = match report.arrival_time_s {
        Some(time_s) => format!("yes, at {:.1} min", time_s / 60.0),
        None => format!("no (run ended at {:.1} min)", report.duration_s / 60.0),
    };
    let _ = writeln!(text, "reached goal:   {arrival}");
    let _ = writeln!(text, "collision:      {}", yes_no(report.collision));
    report.write_safety_lines(&mut text);
    report.write_overhead_lines(&mut text);
    if let Some(rule10) = &report.rule10 {
        rule10.write_lines(&mut text);
    }
    let _ = writeln!(text, "planner:        {}", planner_calls(report));
    text
}

/// What `simulate --ais` asks for.
struct AisOut {
    /// Whether to write `run.nmea` (`--ais`).
    write: bool,
    /// `--ais-origin`, as given.
    origin: Option<String>,
}

fn simulate_command(
    path: &Path,
    seed: Option<u64>,
    out: Option<&Path>,
    ais: &AisOut,
) -> Result<ExitStatus, CliError> {
    let scenario = load(path)?;
    let seed = seed_for(&scenario, seed);
    // Before the run, so that a missing --ais-origin costs no simulation.
    let ais_frame = ais
        .write
        .then(|| crate::export::ais_frame(&scenario, ais.origin.as_deref()))
        .transpose()?;
    let dir = out.map_or_else(
        || PathBuf::from("out").join(folder_name(&scenario.name)),
        Path::to_path_buf,
    );
    let run = {
        let _ticker = Ticker::start(format!("simulating {}", scenario.source));
        let run = run_scenario(&scenario, seed)?;
        write_outputs(&scenario, &run, &dir)?;
        if let Some(frame) = &ais_frame {
            crate::export::write_ais(&scenario, &run.record, frame, &dir)?;
        }
        run
    };
    console::print(&summary_table(&run.report));
    let mut exports = if scenario.is_geographic() {
        ",trajectory.csv,trajectory.geojson,trajectory.gpx".to_owned()
    } else {
        ",trajectory.csv".to_owned()
    };
    if ais_frame.is_some() {
        exports = format!("{exports},{}", crate::export::RUN_NMEA);
    }
    console::line(&format!(
        "\nwrote {}/{{{}{exports}}}",
        dir.display(),
        OUTPUT_FILES.join(",")
    ));
    let status = run.status();
    if !run.report.reached_goal_safely {
        console::warn("the run did not reach its goal safely");
    } else if status != ExitStatus::Success {
        console::warn("the run reached its goal safely but did not obey COLREGs (findings above)");
    }
    Ok(status)
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
    // The scenario's land and no-go areas and its traffic separation
    // scheme, as the closed loop keeps them.
    let constraint = vorrt_scenarios::planning_constraint(&scenario)
        .map_err(|error| CliError::BadInput(error.to_string()))?;
    let mut planner = Planner::with_constraint(config, constraint)
        .map_err(|error| CliError::BadInput(format!("{}: {error}", scenario.source)))?;
    let outcome = {
        let _ticker = Ticker::start(format!("planning {}", scenario.source));
        planner.plan(&scenario.planning_problem(), seed)
    };
    let plan = outcome.map_err(|error| match error {
        vorrt_planner::PlannerError::NoSafePath { .. }
        | vorrt_planner::PlannerError::NodeBudgetTooSmall { .. }
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
    console::line(&text);
    Ok(ExitStatus::Success)
}

fn check_command(paths: &[PathBuf]) -> ExitStatus {
    let mut status = ExitStatus::Success;
    for path in paths {
        match Scenario::load(path) {
            Ok(_) => console::line(&format!("ok: {}", path.display())),
            Err(error) => {
                console::warn(&format!("error: {error}"));
                status = ExitStatus::BadInput;
            }
        }
    }
    status
}
