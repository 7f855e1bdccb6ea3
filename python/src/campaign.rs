//! Campaigns and judgements from Python: the generators of `vorrt batch
//! --generate`, `vorrt judge` on tracks given as CSV text, and the whole
//! command line in-process (`vorrt batch`, `vorrt merge`, ...), each the
//! command line's own function ([`vorrt_cli::library`]).

use crate::{PyScenario, ScenarioError};
use pyo3::prelude::*;
use std::ffi::OsString;
use vorrt_cli::library::{self, GenerateOptions, JudgeOptions};

/// The scenarios `vorrt batch --generate KIND` runs, each carrying the seed
/// the batch simulates it with, so `simulate(scenario)` repeats its row.
#[pyfunction]
#[pyo3(signature = (
    kind, *, targets = None, count = 1, seed = 1, behaviour = "constant",
    density_per_nm = None, direction = "westbound", lane_width_nm = 1.0, shard = None
))]
#[expect(
    clippy::too_many_arguments,
    reason = "the generator's keyword arguments, as `vorrt generate`'s options"
)]
fn generate(
    py: Python<'_>,
    kind: &str,
    targets: Option<usize>,
    count: u64,
    seed: u64,
    behaviour: &str,
    density_per_nm: Option<f64>,
    direction: &str,
    lane_width_nm: f64,
    shard: Option<String>,
) -> PyResult<Vec<PyScenario>> {
    let options = GenerateOptions {
        targets,
        density_per_nm,
        direction: direction.to_owned(),
        lane_width_nm,
        count,
        seed,
        behaviour: behaviour.to_owned(),
        shard,
    };
    let items = py
        .detach(|| library::generate(kind, &options))
        .map_err(ScenarioError::new_err)?;
    Ok(items
        .into_iter()
        .map(|item| {
            let mut inner = item.scenario;
            inner.seed = Some(item.seed);
            PyScenario { inner }
        })
        .collect())
}

/// `judgement.json` of `vorrt judge` for tracks given as the CSV text of
/// `trajectory.csv` (the `vorrt.judge` wrapper turns a `DataFrame` into it).
#[pyfunction]
#[pyo3(signature = (
    text, scenario = None, *, source = "<tracks>", ownship = None, d_th_m = None,
    step_s = None, max_gap_s = None, goal_tolerance_m = None, length_m = None,
    max_turn_rate_deg_s = None, max_speed_kn = None
))]
#[expect(
    clippy::too_many_arguments,
    reason = "`vorrt judge`'s options as keyword arguments"
)]
fn judge_csv(
    py: Python<'_>,
    text: &str,
    scenario: Option<&PyScenario>,
    source: &str,
    ownship: Option<String>,
    d_th_m: Option<f64>,
    step_s: Option<f64>,
    max_gap_s: Option<f64>,
    goal_tolerance_m: Option<f64>,
    length_m: Option<f64>,
    max_turn_rate_deg_s: Option<f64>,
    max_speed_kn: Option<f64>,
) -> PyResult<String> {
    let defaults = JudgeOptions::default();
    let options = JudgeOptions {
        ownship,
        d_th_m,
        step_s,
        max_gap_s: max_gap_s.unwrap_or(defaults.max_gap_s),
        goal_tolerance_m: goal_tolerance_m.unwrap_or(defaults.goal_tolerance_m),
        length_m: length_m.unwrap_or(defaults.length_m),
        max_turn_rate_deg_s,
        max_speed_kn: max_speed_kn.unwrap_or(defaults.max_speed_kn),
        sea_room_m: defaults.sea_room_m,
    };
    for (name, value) in [
        ("max_gap_s", Some(options.max_gap_s)),
        ("goal_tolerance_m", Some(options.goal_tolerance_m)),
        ("length_m", Some(options.length_m)),
        ("d_th_m", options.d_th_m),
        ("step_s", options.step_s),
        ("max_turn_rate_deg_s", options.max_turn_rate_deg_s),
        ("max_speed_kn", Some(options.max_speed_kn)),
    ] {
        if let Some(value) = value
            && !(value.is_finite() && value > 0.0)
        {
            return Err(pyo3::exceptions::PyValueError::new_err(format!(
                "{name} is {value}, expected a finite number greater than 0"
            )));
        }
    }
    let scenario = scenario.map(|scenario| scenario.inner.clone());
    py.detach(|| library::judge_csv(source, text, scenario, &options))
        .map_err(ScenarioError::new_err)
}

/// Runs the command line `vorrt ARGS...` in this process and gives its
/// exit code (what it prints goes to this process's output).
#[pyfunction]
fn main(py: Python<'_>, args: Vec<String>) -> i32 {
    let args: Vec<OsString> = args.into_iter().map(OsString::from).collect();
    i32::from(py.detach(|| library::run_command_line(args)))
}

/// Adds this module's functions to the extension module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(generate, m)?)?;
    m.add_function(wrap_pyfunction!(judge_csv, m)?)?;
    m.add_function(wrap_pyfunction!(main, m)?)?;
    Ok(())
}
