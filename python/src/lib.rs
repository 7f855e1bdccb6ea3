//! Python bindings of vorrt: the `vorrt` extension module, built with `PyO3`
//! and maturin (`pip install ./python`).
//!
//! The module wraps the Rust crates, which know nothing of Python:
//! [`vorrt_scenarios::Scenario`] (load, parse, write RON),
//! [`vorrt_scenarios::simulate`] with the command line's report
//! ([`vorrt_cli::report::Report`], the content of `report.json`), the plan of
//! `vorrt plan` ([`vorrt_cli::report::PlanOutput`]) and a closed loop
//! stepped by hand ([`vorrt_scenarios::ClosedLoop`]). Reports and plans cross
//! to Python as JSON text read back with `json.loads`, so that Python sees
//! exactly the command line's fields. The API is documented in
//! `python/vorrt.pyi`.

use pyo3::create_exception;
use pyo3::exceptions::{PyException, PyRuntimeError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

mod campaign;
mod commanded;
use std::path::PathBuf;
use std::sync::{Mutex, OnceLock};
use vorrt_cli::report::{PlanOutput, Report};
use vorrt_geometry::{angle, units};
use vorrt_planner::{Planner, VesselState};
use vorrt_scenarios::{RunStatus, SimulationRecord, evaluate};

create_exception!(
    vorrt,
    ScenarioError,
    PyException,
    "A scenario could not be read or is invalid; the message names the file and the field."
);
create_exception!(
    vorrt,
    PlanningError,
    PyException,
    "The planner found no plan, or its settings are invalid."
);

fn scenario_error(error: &vorrt_scenarios::ScenarioError) -> PyErr {
    ScenarioError::new_err(error.to_string())
}

/// `json.loads(text)`.
fn json_loads(py: Python<'_>, text: &str) -> PyResult<Py<PyAny>> {
    Ok(py.import("json")?.call_method1("loads", (text,))?.unbind())
}

/// `value` as JSON text, as the command line writes it (pretty-printed).
fn to_json<T: serde::Serialize>(value: &T) -> PyResult<String> {
    serde_json::to_string_pretty(value)
        .map_err(|error| PyRuntimeError::new_err(format!("cannot write as JSON: {error}")))
}

/// A scenario: ownship, targets, planner settings (`vorrt.Scenario`).
#[pyclass(module = "vorrt", name = "Scenario", frozen)]
#[derive(Debug, Clone)]
pub struct PyScenario {
    inner: vorrt_scenarios::Scenario,
}

#[pymethods]
impl PyScenario {
    /// Reads and validates the scenario file at `path`: RON, or JSON
    /// (`.json`, or content starting with `{`).
    #[staticmethod]
    #[expect(
        clippy::needless_pass_by_value,
        reason = "PyO3 extracts a path argument as an owned PathBuf"
    )]
    fn load(path: PathBuf) -> PyResult<Self> {
        vorrt_scenarios::Scenario::load(&path)
            .map(|inner| Self { inner })
            .map_err(|error| scenario_error(&error))
    }

    /// Parses and validates a scenario from RON text; `source` names it in
    /// error messages.
    #[staticmethod]
    #[pyo3(signature = (text, source = "<string>"))]
    fn from_ron(text: &str, source: &str) -> PyResult<Self> {
        vorrt_scenarios::Scenario::from_ron_str(text, source)
            .map(|inner| Self { inner })
            .map_err(|error| scenario_error(&error))
    }

    /// The scenario as RON text (`from_ron` reads it back).
    fn to_ron(&self) -> PyResult<String> {
        self.inner
            .to_ron_string()
            .map_err(|error| scenario_error(&error))
    }

    /// Parses and validates a scenario from JSON text (the fields of the
    /// RON format, tuples as lists); `source` names it in error messages.
    #[staticmethod]
    #[pyo3(signature = (text, source = "<string>"))]
    fn from_json(text: &str, source: &str) -> PyResult<Self> {
        vorrt_scenarios::Scenario::from_json_str(text, source)
            .map(|inner| Self { inner })
            .map_err(|error| scenario_error(&error))
    }

    /// The scenario as JSON text (`from_json` reads it back).
    fn to_json(&self) -> PyResult<String> {
        self.inner
            .to_json_string()
            .map_err(|error| scenario_error(&error))
    }

    /// Validates a scenario given as a dict (what `to_dict` gives, or
    /// `json.load` of a JSON scenario file); `source` names it in errors.
    #[staticmethod]
    #[pyo3(signature = (data, source = "<dict>"))]
    fn from_dict(py: Python<'_>, data: &Bound<'_, PyAny>, source: &str) -> PyResult<Self> {
        let text: String = py
            .import("json")?
            .call_method1("dumps", (data,))
            .map_err(|error| {
                ScenarioError::new_err(format!("{source}: not a JSON-like dict: {error}"))
            })?
            .extract()?;
        Self::from_json(&text, source)
    }

    /// The scenario as a dict of plain values (the JSON form).
    fn to_dict(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        json_loads(py, &self.to_json()?)
    }

    /// The planner seed the scenario asks for, if any.
    #[getter]
    fn seed(&self) -> Option<u64> {
        self.inner.seed
    }

    /// A copy with planner seed `seed` (`None` removes it).
    #[pyo3(signature = (seed))]
    fn with_seed(&self, seed: Option<u64>) -> Self {
        let mut inner = self.inner.clone();
        inner.seed = seed;
        Self { inner }
    }

    /// Whether the scenario is geographic (latitudes and longitudes).
    #[getter]
    fn is_geographic(&self) -> bool {
        self.inner.is_geographic()
    }

    fn __eq__(&self, other: &Self) -> bool {
        self.inner == other.inner
    }

    /// The scenario's name.
    #[getter]
    fn name(&self) -> &str {
        &self.inner.name
    }

    /// The file (or source name) the scenario was read from.
    #[getter]
    fn source(&self) -> &str {
        &self.inner.source
    }

    fn __repr__(&self) -> String {
        format!(
            "Scenario(name={:?}, source={:?})",
            self.inner.name, self.inner.source
        )
    }
}

/// The seed a run uses, as the command line: the one given, else the
/// scenario's, else 1.
fn seed_for(scenario: &vorrt_scenarios::Scenario, seed: Option<u64>) -> u64 {
    seed.or(scenario.seed).unwrap_or(1)
}

/// A finished closed-loop run (`vorrt.Run`). Its report's JSON, the dict
/// and `trajectory.csv` are made when first asked for: a campaign that
/// reads one field of each run pays for no more (`docs/performance.md`).
#[pyclass(module = "vorrt", name = "Run", frozen)]
#[derive(Debug)]
pub struct PyRun {
    /// Whether ownship reached its goal.
    #[pyo3(get)]
    reached_goal: bool,
    scenario: vorrt_scenarios::Scenario,
    record: SimulationRecord,
    report: Report,
    report_json: OnceLock<String>,
    report_dict: OnceLock<Py<PyAny>>,
}

impl PyRun {
    fn json(&self) -> PyResult<&str> {
        if let Some(text) = self.report_json.get() {
            return Ok(text);
        }
        let text = to_json(&self.report)?;
        Ok(self.report_json.get_or_init(|| text))
    }
}

#[pymethods]
impl PyRun {
    /// `report.json` as the command line writes it (pretty JSON, no final
    /// line end).
    fn report_json(&self) -> PyResult<&str> {
        self.json()
    }

    /// The content of the command line's `report.json`, as a dict (the
    /// same dict on every access).
    #[getter]
    fn report(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        if let Some(dict) = self.report_dict.get() {
            return Ok(dict.clone_ref(py));
        }
        let dict = json_loads(py, self.json()?)?;
        Ok(self.report_dict.get_or_init(|| dict).clone_ref(py))
    }

    /// `trajectory.csv` as `vorrt simulate` writes it, byte for byte.
    fn trajectory_csv(&self, py: Python<'_>) -> PyResult<String> {
        py.detach(|| vorrt_cli::library::trajectory_csv(&self.scenario, &self.record))
            .map_err(PyRuntimeError::new_err)
    }

    /// The columns of `trajectory.csv`: a pandas `DataFrame`, or a dict of
    /// numpy arrays without pandas (built on each access).
    #[getter]
    fn tracks(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        let text = self.trajectory_csv(py)?;
        Ok(py
            .import("vorrt._tables")?
            .call_method1("table_from_csv", (text,))?
            .unbind())
    }

    /// The COLREGs findings of the one evaluation: a list of dicts with
    /// `target` (a name, or `None` for findings on ownship's track) and
    /// `finding`.
    #[getter]
    fn findings(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        let report = self.report(py)?;
        Ok(py
            .import("vorrt._tables")?
            .call_method1("findings", (report,))?
            .unbind())
    }

    fn __repr__(&self) -> String {
        format!("Run(reached_goal={})", self.reached_goal)
    }
}

/// The run of `record`: evaluated and reported as `report.json` says.
fn finished_run(
    py: Python<'_>,
    scenario: &vorrt_scenarios::Scenario,
    record: SimulationRecord,
) -> PyRun {
    let report = py.detach(|| {
        let evaluation = evaluate(scenario, &record);
        Report::new(scenario, &record, &evaluation)
    });
    PyRun {
        reached_goal: record.reached_goal,
        scenario: scenario.clone(),
        record,
        report,
        report_json: OnceLock::new(),
        report_dict: OnceLock::new(),
    }
}

fn course_deg(state: &VesselState) -> f64 {
    angle::normalize_2pi(state.course_rad).to_degrees()
}

/// Simulates `scenario` in closed loop with planner seed `seed` (the
/// scenario's seed, else 1, when `None`) and evaluates the run.
#[pyfunction]
#[pyo3(signature = (scenario, seed = None))]
fn simulate(py: Python<'_>, scenario: &PyScenario, seed: Option<u64>) -> PyResult<PyRun> {
    let scenario = &scenario.inner;
    let seed = seed_for(scenario, seed);
    let record = py
        .detach(|| vorrt_scenarios::simulate(scenario, seed))
        .map_err(|error| scenario_error(&error))?;
    Ok(finished_run(py, scenario, record))
}

/// The plan of `vorrt plan FILE --seed SEED` as JSON text, exactly as the
/// command line prints it (without its final line end).
#[pyfunction]
#[pyo3(signature = (scenario, seed = None))]
fn plan_json(py: Python<'_>, scenario: &PyScenario, seed: Option<u64>) -> PyResult<String> {
    let scenario = &scenario.inner;
    let seed = seed_for(scenario, seed);
    py.detach(|| {
        let config = scenario
            .planner_config()
            .map_err(|error| scenario_error(&error))?;
        let d_th_m = config.clearance_m;
        // Land, no-go areas and the traffic separation scheme, as
        // `vorrt plan` and the closed loop keep them.
        let constraint = vorrt_scenarios::planning_constraint(scenario)
            .map_err(|error| scenario_error(&error))?;
        let mut planner = Planner::with_constraint(config, constraint)
            .map_err(|error| PlanningError::new_err(format!("{}: {error}", scenario.source)))?;
        let plan = planner
            .plan(&scenario.planning_problem(), seed)
            .map_err(|error| PlanningError::new_err(format!("{}: {error}", scenario.source)))?;
        to_json(&PlanOutput::new(scenario, seed, d_th_m, &plan))
    })
}

/// The plan of `vorrt plan FILE --seed SEED`, as a dict.
#[pyfunction]
#[pyo3(signature = (scenario, seed = None))]
fn plan(py: Python<'_>, scenario: &PyScenario, seed: Option<u64>) -> PyResult<Py<PyAny>> {
    let text = plan_json(py, scenario, seed)?;
    json_loads(py, &text)
}

fn status_key(status: RunStatus) -> &'static str {
    match status {
        RunStatus::Running => "running",
        RunStatus::ReachedGoal => "reached_goal",
        RunStatus::OutOfTime => "out_of_time",
    }
}

fn vessel_dict<'py>(
    py: Python<'py>,
    name: &str,
    state: &VesselState,
) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    dict.set_item("name", name)?;
    dict.set_item("east_m", state.position_m.x)?;
    dict.set_item("north_m", state.position_m.y)?;
    dict.set_item("course_deg", course_deg(state))?;
    dict.set_item("speed_kn", units::mps_to_knots(state.speed_mps))?;
    dict.set_item("length_m", state.length_m)?;
    Ok(dict)
}

/// A closed-loop run held at its present moment, stepped by hand
/// (`vorrt.ClosedLoop`).
#[pyclass(module = "vorrt", name = "ClosedLoop", frozen)]
#[derive(Debug)]
pub struct PyClosedLoop {
    scenario: vorrt_scenarios::Scenario,
    /// `None` once finished.
    run: Mutex<Option<vorrt_scenarios::ClosedLoop>>,
}

impl PyClosedLoop {
    fn with_run<T>(
        &self,
        action: impl FnOnce(&mut vorrt_scenarios::ClosedLoop) -> PyResult<T>,
    ) -> PyResult<T> {
        let mut guard = self
            .run
            .lock()
            .map_err(|_| PyRuntimeError::new_err("the closed loop was poisoned"))?;
        let run = guard
            .as_mut()
            .ok_or_else(|| PyRuntimeError::new_err("the closed loop has been finished"))?;
        action(run)
    }
}

#[pymethods]
impl PyClosedLoop {
    /// A run of `scenario` with planner seed `seed` (the scenario's, else 1,
    /// when `None`), at time 0.
    #[new]
    #[pyo3(signature = (scenario, seed = None))]
    fn new(py: Python<'_>, scenario: &PyScenario, seed: Option<u64>) -> PyResult<Self> {
        let scenario = scenario.inner.clone();
        let seed = seed_for(&scenario, seed);
        let run = py
            .detach(|| vorrt_scenarios::ClosedLoop::new(&scenario, seed))
            .map_err(|error| scenario_error(&error))?;
        Ok(Self {
            scenario,
            run: Mutex::new(Some(run)),
        })
    }

    /// One time step; `False` when the run had already finished.
    fn step(&self, py: Python<'_>) -> PyResult<bool> {
        py.detach(|| self.with_run(|run| Ok(run.step().is_some())))
    }

    /// The run at its present moment: `time_s`, `step`, `status`
    /// (`running`, `reached_goal`, `out_of_time`), `ownship`, `targets`,
    /// `evasive` and the plan in force's `plan_waypoints`.
    fn state(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        self.with_run(|run| {
            let state = run.state();
            let dict = PyDict::new(py);
            dict.set_item("time_s", state.time_s)?;
            dict.set_item("step", state.step)?;
            dict.set_item("status", status_key(state.status))?;
            dict.set_item(
                "ownship",
                vessel_dict(py, &self.scenario.ownship.name, &state.ownship)?,
            )?;
            let targets = PyList::empty(py);
            for (name, target) in state.target_names.iter().zip(state.targets) {
                targets.append(vessel_dict(py, name, target)?)?;
            }
            dict.set_item("targets", targets)?;
            dict.set_item("evasive", state.evasive)?;
            let waypoints = PyList::empty(py);
            for waypoint in state.plan.map_or(&[][..], |plan| &plan.waypoints) {
                let point = PyDict::new(py);
                point.set_item("time_s", waypoint.time_s)?;
                point.set_item("east_m", waypoint.position_m.x)?;
                point.set_item("north_m", waypoint.position_m.y)?;
                point.set_item(
                    "course_deg",
                    waypoint.course_rad.to_degrees().rem_euclid(360.0),
                )?;
                waypoints.append(point)?;
            }
            dict.set_item("plan_waypoints", waypoints)?;
            Ok(dict.into_any().unbind())
        })
    }

    /// Whether the run has finished (goal reached or time out).
    fn is_finished(&self) -> PyResult<bool> {
        self.with_run(|run| Ok(run.is_finished()))
    }

    /// Ends the run here and gives it as a `Run` (a run stopped before it
    /// finished has not reached its goal). The loop cannot be used after.
    fn finish(&self, py: Python<'_>) -> PyResult<PyRun> {
        let run = self
            .run
            .lock()
            .map_err(|_| PyRuntimeError::new_err("the closed loop was poisoned"))?
            .take()
            .ok_or_else(|| PyRuntimeError::new_err("the closed loop has been finished"))?;
        let record = run.finish();
        Ok(finished_run(py, &self.scenario, record))
    }
}

/// The `vorrt._vorrt` extension module (re-exported by the `vorrt`
/// package).
#[pymodule]
#[pyo3(name = "_vorrt")]
fn vorrt(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add_class::<PyScenario>()?;
    m.add_class::<PyRun>()?;
    m.add_class::<PyClosedLoop>()?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(plan, m)?)?;
    m.add_function(wrap_pyfunction!(plan_json, m)?)?;
    campaign::register(m)?;
    commanded::register(m)?;
    m.add("ScenarioError", py.get_type::<ScenarioError>())?;
    m.add("PlanningError", py.get_type::<PlanningError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
