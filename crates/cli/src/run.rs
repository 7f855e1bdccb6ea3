//! One scenario's closed-loop run and the files it writes, shared by
//! `simulate`, `demo` and `batch`.

use crate::error::{CliError, ExitStatus};
use crate::plot;
use crate::report::Report;
use std::path::Path;
use vorrt_scenarios::{Evaluation, Scenario, SimulationRecord, evaluate, simulate};

/// Loads and validates a scenario file, as a [`CliError::BadInput`] on failure.
///
/// # Errors
/// The scenario error's message: it names the file, and the line or field.
pub(crate) fn load(path: &Path) -> Result<Scenario, CliError> {
    Scenario::load(path).map_err(|error| CliError::BadInput(error.to_string()))
}

/// The seed a run uses: the one given, else the scenario's, else 1.
#[must_use]
pub(crate) fn seed_for(scenario: &Scenario, seed: Option<u64>) -> u64 {
    seed.or(scenario.seed).unwrap_or(1)
}

/// A finished closed-loop run with its evaluation and report.
#[derive(Debug, Clone)]
pub(crate) struct Run {
    /// Every recorded state and planner call.
    pub(crate) record: SimulationRecord,
    /// The library's evaluation.
    pub(crate) evaluation: Evaluation,
    /// The report written to `report.json`.
    pub(crate) report: Report,
}

impl Run {
    /// How the run ends the command: 0 when it succeeded
    /// ([`Evaluation::success`]: goal reached, no collision, `d_th` kept)
    /// and the tracks were safe and compliant
    /// ([`Evaluation::safe_and_compliant`]: no COLREGs finding, as `vorrt
    /// judge` asks of the same tracks), else 1. The one exit judgement of
    /// `vorrt simulate` and of each run of `vorrt demo`.
    #[must_use]
    pub(crate) fn status(&self) -> ExitStatus {
        if self.evaluation.success() && self.evaluation.safe_and_compliant() {
            ExitStatus::Success
        } else {
            ExitStatus::Unsafe
        }
    }
}

/// Simulates `scenario` with `seed` and evaluates the run.
///
/// # Errors
/// [`CliError::BadInput`] when the scenario's planner settings are invalid.
pub(crate) fn run_scenario(scenario: &Scenario, seed: u64) -> Result<Run, CliError> {
    let record = simulate(scenario, seed).map_err(|error| CliError::BadInput(error.to_string()))?;
    let evaluation = evaluate(scenario, &record);
    let report = Report::new(scenario, &record, &evaluation);
    Ok(Run {
        record,
        evaluation,
        report,
    })
}

/// The files [`write_outputs`] writes into its folder: the report, the
/// plots ([`plot::PLOT_FILES`]) and the replay page.
pub(crate) const OUTPUT_FILES: [&str; 8] = [
    "report.json",
    plot::PLOT_FILES[0],
    plot::PLOT_FILES[1],
    plot::PLOT_FILES[2],
    plot::PLOT_FILES[3],
    plot::PLOT_FILES[4],
    plot::PLOT_FILES[5],
    crate::replay::REPLAY_HTML,
];

/// Writes `report.json`, the plots, the trajectory exports
/// ([`crate::export::write_trajectories`]) and `replay.html`
/// ([`crate::replay::write_replay`]) of `run` into `dir` (created if needed).
///
/// # Errors
/// [`CliError::Output`] when a file cannot be written.
pub(crate) fn write_outputs(scenario: &Scenario, run: &Run, dir: &Path) -> Result<(), CliError> {
    std::fs::create_dir_all(dir)
        .map_err(|error| CliError::Output(format!("cannot create {}: {error}", dir.display())))?;
    let json = serde_json::to_string_pretty(&run.report)
        .map_err(|error| CliError::Output(format!("cannot write the report as JSON: {error}")))?;
    let report_path = dir.join("report.json");
    std::fs::write(&report_path, json + "\n").map_err(|error| {
        CliError::Output(format!("cannot write {}: {error}", report_path.display()))
    })?;
    plot::write_plots(scenario, &run.record, &run.evaluation, dir).map_err(CliError::Output)?;
    crate::export::write_trajectories(scenario, &run.record, &run.report, dir)?;
    crate::replay::write_replay(scenario, &run.record, &run.evaluation, &run.report, dir)?;
    Ok(())
}

/// A file-system friendly version of a scenario name.
#[must_use]
pub(crate) fn folder_name(name: &str) -> String {
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
