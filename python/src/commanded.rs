//! A run with ownship steered from Python (`vorrt.CommandedRun`), the
//! engine of the Gymnasium environment `vorrt.gym`: course and speed
//! commands in, the states of every vessel out, and the one evaluation's
//! report of the run so far.

use crate::{PyScenario, json_loads, scenario_error, seed_for, status_key, to_json, vessel_dict};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use std::sync::Mutex;
use vorrt_cli::report::Report;
use vorrt_geometry::units;
use vorrt_scenarios::{COMMANDED_GOAL_TOLERANCE_M, CommandedRun, evaluate};

/// A run whose ownship makes the course and speed it is given each step;
/// the targets move by their behaviours (`vorrt.CommandedRun`).
#[pyclass(module = "vorrt", name = "CommandedRun", frozen)]
#[derive(Debug)]
pub struct PyCommandedRun {
    scenario: vorrt_scenarios::Scenario,
    run: Mutex<CommandedRun>,
}

impl PyCommandedRun {
    fn with_run<T>(&self, action: impl FnOnce(&mut CommandedRun) -> PyResult<T>) -> PyResult<T> {
        let mut run = self
            .run
            .lock()
            .map_err(|_| pyo3::exceptions::PyRuntimeError::new_err("the run was poisoned"))?;
        action(&mut run)
    }
}

#[pymethods]
impl PyCommandedRun {
    /// A run of `scenario` at time 0, its targets seeded with `seed` (the
    /// scenario's, else 1, when `None`); ownship has arrived within
    /// `goal_tolerance_m` of its goal.
    #[new]
    #[pyo3(signature = (scenario, seed = None, goal_tolerance_m = COMMANDED_GOAL_TOLERANCE_M))]
    fn new(scenario: &PyScenario, seed: Option<u64>, goal_tolerance_m: f64) -> PyResult<Self> {
        let scenario = scenario.inner.clone();
        let seed = seed_for(&scenario, seed);
        let run = CommandedRun::new(&scenario, seed, goal_tolerance_m)
            .map_err(|error| scenario_error(&error))?;
        Ok(Self {
            scenario,
            run: Mutex::new(run),
        })
    }

    /// Sails one time step making `course_deg` (clockwise from north) and
    /// `speed_kn`; gives the status after it (`running`, `reached_goal`,
    /// `out_of_time`). Raises `ValueError` for a command out of range or a
    /// finished run.
    fn step(&self, py: Python<'_>, course_deg: f64, speed_kn: f64) -> PyResult<&'static str> {
        py.detach(|| {
            self.with_run(|run| {
                run.step(course_deg.to_radians(), units::knots_to_mps(speed_kn))
                    .map(status_key)
                    .map_err(|error| PyValueError::new_err(error.to_string()))
            })
        })
    }

    /// The present moment: `time_s`, `status`, `goal_east_m`,
    /// `goal_north_m`, `ownship` and `targets` (dicts as in
    /// `ClosedLoop.state`).
    fn state(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        self.with_run(|run| {
            let dict = PyDict::new(py);
            dict.set_item("time_s", run.time_s())?;
            dict.set_item("status", status_key(run.status()))?;
            dict.set_item("goal_east_m", run.goal_m().x)?;
            dict.set_item("goal_north_m", run.goal_m().y)?;
            dict.set_item(
                "ownship",
                vessel_dict(py, &self.scenario.ownship.name, &run.ownship())?,
            )?;
            let targets = PyList::empty(py);
            for (spec, target) in self.scenario.targets.iter().zip(run.targets()) {
                targets.append(vessel_dict(py, &spec.name, target)?)?;
            }
            dict.set_item("targets", targets)?;
            Ok(dict.into_any().unbind())
        })
    }

    /// The run so far judged by the one evaluation, as `report.json`'s
    /// dict (the planner fields are zero: no planner ran).
    fn report(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        let text = py.detach(|| {
            self.with_run(|run| {
                let record = run.record();
                let evaluation = evaluate(&self.scenario, record);
                to_json(&Report::new(&self.scenario, record, &evaluation))
            })
        })?;
        json_loads(py, &text)
    }

    /// `trajectory.csv` of the run so far.
    fn trajectory_csv(&self) -> PyResult<String> {
        self.with_run(|run| {
            vorrt_cli::library::trajectory_csv(&self.scenario, run.record())
                .map_err(pyo3::exceptions::PyRuntimeError::new_err)
        })
    }
}

/// Adds the class to the extension module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyCommandedRun>()
}
