//! Reading and writing scenario files (RON).

use crate::error::ScenarioError;
use crate::recorded_tracks::RecordedTracks;
use crate::scenario::Scenario;
use ron::extensions::Extensions;
use ron::ser::PrettyConfig;
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// The file extension of scenario files.
pub const SCENARIO_EXTENSION: &str = "ron";

/// Scenario files are read and written with the `implicit_some` extension:
/// an optional field is written as its value, `goal_nm: (0.0, 3.0)`, not
/// `goal_nm: Some((0.0, 3.0))` (both are accepted).
fn options() -> ron::Options {
    ron::Options::default().with_default_extension(Extensions::IMPLICIT_SOME)
}

impl Scenario {
    /// Parses and validates a scenario. `source` names the text in error
    /// messages (a file path, or e.g. `"<generated>"`) and is kept in
    /// [`Scenario::source`].
    ///
    /// # Errors
    /// [`ScenarioError::Syntax`] when the text is not a scenario (with the
    /// line and column), [`ScenarioError::Invalid`] when a value breaks a rule.
    pub fn from_ron_str(text: &str, source: &str) -> Result<Scenario, ScenarioError> {
        let syntax = |error: ron::error::SpannedError, path: Option<String>| {
            let message = error.code.to_string();
            ScenarioError::Syntax {
                file: source.to_owned(),
                line: error.position.line,
                column: error.position.col,
                // A type error deep in the file names its field, e.g.
                // `targets[1].speed_kn: Expected float`.
                message: match path.filter(|path| !path.is_empty() && path != ".") {
                    Some(path) => format!("{path}: {message}"),
                    None => message,
                },
            }
        };
        let mut deserializer = ron::Deserializer::from_str_with_options(text, &options())
            .map_err(|error| syntax(error, None))?;
        let mut track = serde_path_to_error::Track::new();
        let parsed = Scenario::deserialize(serde_path_to_error::Deserializer::new(
            &mut deserializer,
            &mut track,
        ));
        let mut scenario = match parsed {
            Ok(scenario) => scenario,
            Err(error) => {
                let spanned = deserializer.span_error(error);
                return Err(syntax(spanned, Some(track.path().to_string())));
            }
        };
        deserializer
            .end()
            .map_err(|error| syntax(deserializer.span_error(error), None))?;
        source.clone_into(&mut scenario.source);
        scenario.validate()?;
        Ok(scenario)
    }

    /// Reads, parses and validates the scenario file at `path`, and the
    /// recorded tracks it names (`recorded_tracks`, relative to the file's
    /// folder) into [`Scenario::recorded`].
    ///
    /// # Errors
    /// [`ScenarioError::Io`] when the file or its tracks cannot be read, a
    /// [`ScenarioError::Invalid`] naming the tracks file, line and field
    /// for a bad row, or a `Recorded` target without a track; else as
    /// [`Scenario::from_ron_str`].
    pub fn load(path: &Path) -> Result<Scenario, ScenarioError> {
        let text = std::fs::read_to_string(path).map_err(|source| ScenarioError::Io {
            path: path.to_owned(),
            source,
        })?;
        let mut scenario = Self::from_ron_str(&text, &path.display().to_string())?;
        if let Some(relative) = &scenario.recorded_tracks {
            let tracks_path = path.parent().unwrap_or(Path::new("")).join(relative);
            let text =
                std::fs::read_to_string(&tracks_path).map_err(|source| ScenarioError::Io {
                    path: tracks_path.clone(),
                    source,
                })?;
            scenario.recorded = RecordedTracks::from_csv_str(
                &text,
                &tracks_path.display().to_string(),
                scenario.local_frame().as_ref(),
                |vessel| scenario.vessel_length_m(vessel),
            )?;
            scenario.check_recorded()?;
        }
        Ok(scenario)
    }

    /// The scenario as pretty-printed RON, in the format it was read from.
    /// [`Scenario::from_ron_str`] on the result gives back an equal scenario.
    /// Fields at their defaults are left out.
    ///
    /// # Errors
    /// [`ScenarioError::Syntax`] if RON cannot represent a value (it can
    /// represent every value a valid scenario holds).
    pub fn to_ron_string(&self) -> Result<String, ScenarioError> {
        let config = PrettyConfig::new()
            .struct_names(true)
            .indentor("    ".to_owned());
        let mut text =
            options()
                .to_string_pretty(self, config)
                .map_err(|error| ScenarioError::Syntax {
                    file: self.source.clone(),
                    line: 0,
                    column: 0,
                    message: format!("cannot write as RON: {error}"),
                })?;
        text.push('\n');
        Ok(text)
    }
}

/// Loads every `*.ron` file directly inside `dir` (not in subdirectories),
/// sorted by file name.
///
/// # Errors
/// [`ScenarioError::Io`] if the directory cannot be listed; otherwise the
/// first file (in name order) that fails to load stops the loading and its
/// error is returned.
pub fn load_dir(dir: &Path) -> Result<Vec<(PathBuf, Scenario)>, ScenarioError> {
    let io_error = |source| ScenarioError::Io {
        path: dir.to_owned(),
        source,
    };
    let mut paths = Vec::new();
    for entry in std::fs::read_dir(dir).map_err(io_error)? {
        let path = entry.map_err(io_error)?.path();
        if path.is_file()
            && path
                .extension()
                .is_some_and(|extension| extension == SCENARIO_EXTENSION)
        {
            paths.push(path);
        }
    }
    paths.sort_by(|a, b| a.file_name().cmp(&b.file_name()));
    paths
        .into_iter()
        .map(|path| Scenario::load(&path).map(|scenario| (path, scenario)))
        .collect()
}

/// The bundled fixtures directory (this crate's `fixtures/`, holding
/// `paper/`, `imazu/` and `geo/`), as found from this crate's source
/// location; the same files are embedded in [`crate::fixtures`].
#[must_use]
pub fn bundled_fixtures_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::planner_settings::PlannerSettings;
    use crate::scenario::{Behaviour, Lane, SimulationSettings, VesselSpec};

    /// A scenario with every field set (and some at awkward values).
    fn everything() -> Scenario {
        let mut ownship = VesselSpec::new("own", (0.0, 0.0), 0.0, 11.5, 75.0);
        ownship.start_nm = None;
        ownship.start_m = Some((-12.5, -5556.25));
        ownship.goal_m = Some((1.0e-3, 5556.0));
        Scenario {
            name: "everything".into(),
            description: Some("all \"fields\"\nset".into()),
            ownship,
            targets: vec![
                VesselSpec::new("A", (1.0 / 3.0, 2.0), 359.999_999, 0.1, 50.0)
                    .with_goal_nm((-4.0, 2.0)),
                VesselSpec::new("B", (3.0, -2.0), 90.0, 0.0, 999.0)
                    .with_behaviour(Behaviour::ConstantVelocity),
            ],
            planner: PlannerSettings {
                clearance_m: Some(150.0),
                nodes_per_phase: Some(300),
                nearest_index: Some(vorrt_planner::NearestIndex::RTree),
                time_budget_s: Some(0.25),
                mtd_nm: Some(4.5),
                ..PlannerSettings::default()
            },
            simulation: SimulationSettings {
                time_step_s: 1.0,
                max_duration_s: Some(3600.0),
                replan_deviation_m: 25.0,
            },
            lanes: vec![Lane {
                name: "north".into(),
                from_nm: (0.0, -5.0),
                to_nm: (0.1, 5.0),
                width_nm: 0.75,
            }],
            seed: Some(u64::MAX),
            start_time: None,
            source: "everything".into(),
            recorded_tracks: None,
            recorded: crate::RecordedTracks::default(),
        }
    }

    #[test]
    fn everything_round_trips() {
        let mut scenario = everything();
        scenario.validate().expect("valid");
        let text = scenario.to_ron_string().expect("writes");
        let back = Scenario::from_ron_str(&text, "back").expect("reads back");
        assert_eq!(back, scenario, "{text}");
        assert_eq!(back.source, "back");
    }

    #[test]
    fn defaults_are_left_out_when_writing() {
        let mut scenario = everything();
        scenario.planner = PlannerSettings::default();
        scenario.simulation = SimulationSettings::default();
        scenario.lanes.clear();
        scenario.description = None;
        scenario.seed = None;
        let text = scenario.to_ron_string().expect("writes");
        for absent in ["planner", "simulation", "lanes", "description", "seed"] {
            assert!(!text.contains(absent), "{absent} in {text}");
        }
        assert!(!text.contains("Some("), "{text}");
        assert_eq!(
            Scenario::from_ron_str(&text, "back").expect("reads"),
            scenario
        );
    }

    #[test]
    fn equality_ignores_the_source() {
        let a = everything();
        let mut b = everything();
        b.source = "elsewhere".into();
        assert_eq!(a, b);
        b.seed = None;
        assert_ne!(a, b);
    }
}
