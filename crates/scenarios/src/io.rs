//! Reading and writing scenario files: RON, or JSON (the same fields, by
//! the same serde derives), chosen by the file's extension, else by its
//! content (decision 34).

use crate::error::ScenarioError;
use crate::recorded_tracks::RecordedTracks;
use crate::scenario::Scenario;
use ron::extensions::Extensions;
use ron::ser::PrettyConfig;
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// The file extension of scenario files.
pub const SCENARIO_EXTENSION: &str = "ron";

/// The file extension of scenario files written as JSON.
pub const JSON_SCENARIO_EXTENSION: &str = "json";

/// The formats a scenario file can be written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ScenarioFormat {
    /// RON, the format of the bundled fixtures (`docs/scenario-format.md`).
    Ron,
    /// JSON with the same field names: what `serde_json` makes of the
    /// scenario's serde derives (tuples as arrays, `None` as `null`).
    Json,
}

impl ScenarioFormat {
    /// The format of the file at `path` holding `text`: `.json` is JSON,
    /// `.ron` RON, any other extension JSON when the text starts with `{`,
    /// else RON. The second value says whether it was guessed from the
    /// content.
    #[must_use]
    pub fn detect(path: &Path, text: &str) -> (Self, bool) {
        let extension = path
            .extension()
            .map(|extension| extension.to_string_lossy().to_ascii_lowercase());
        match extension.as_deref() {
            Some(JSON_SCENARIO_EXTENSION) => (Self::Json, false),
            Some(SCENARIO_EXTENSION) => (Self::Ron, false),
            _ if text.trim_start().starts_with('{') => (Self::Json, true),
            _ => (Self::Ron, true),
        }
    }

    /// The format's name in messages: `RON` or `JSON`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Ron => "RON",
            Self::Json => "JSON",
        }
    }
}

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
        Self::parse_ron(text, source, None)
    }

    /// As [`Scenario::from_ron_str`], with the text of the `GeoJSON` file
    /// its `land_geojson` names given instead of read from disk: its
    /// polygons become inline `land` areas (`land_geojson` is then `None`).
    /// This is how the bundled fixtures with real coastlines load with no
    /// file beside them ([`crate::fixtures::Fixture::load`]).
    ///
    /// # Errors
    /// As [`Scenario::from_ron_str`]; field `land_geojson` when the
    /// `GeoJSON` text holds no valid land.
    pub fn from_ron_str_with_land_geojson(
        text: &str,
        source: &str,
        land_geojson: &str,
    ) -> Result<Scenario, ScenarioError> {
        let mut scenario = Self::deserialize_ron(text, source)?;
        let areas = crate::geojson_land::parse_land_geojson(land_geojson).map_err(|problem| {
            ScenarioError::Invalid {
                file: source.to_owned(),
                field: "land_geojson".into(),
                problem,
            }
        })?;
        scenario.land.extend(areas);
        scenario.land_geojson = None;
        scenario.validate()?;
        Ok(scenario)
    }

    /// As [`Scenario::from_ron_str`], resolving a relative `land_geojson`
    /// from `base_dir` (`None`: the current directory).
    fn parse_ron(
        text: &str,
        source: &str,
        base_dir: Option<&Path>,
    ) -> Result<Scenario, ScenarioError> {
        let mut scenario = Self::deserialize_ron(text, source)?;
        scenario.base_dir = base_dir.map(Path::to_path_buf);
        scenario.validate()?;
        Ok(scenario)
    }

    /// The scenario of RON `text`, not yet validated.
    fn deserialize_ron(text: &str, source: &str) -> Result<Scenario, ScenarioError> {
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
        Ok(scenario)
    }

    /// Parses and validates a scenario written as JSON (the fields of
    /// [`Scenario::from_ron_str`], tuples as arrays); `source` names the
    /// text in error messages.
    ///
    /// # Errors
    /// [`ScenarioError::Syntax`] when the text is not a scenario (with the
    /// line, the column and the field), [`ScenarioError::Invalid`] when a
    /// value breaks a rule.
    pub fn from_json_str(text: &str, source: &str) -> Result<Scenario, ScenarioError> {
        Self::parse_json(text, source, None)
    }

    /// As [`Scenario::from_json_str`], resolving a relative `land_geojson`
    /// from `base_dir` (`None`: the current directory).
    fn parse_json(
        text: &str,
        source: &str,
        base_dir: Option<&Path>,
    ) -> Result<Scenario, ScenarioError> {
        let syntax = |path: String, error: &serde_json::Error| {
            // The position is in the message's prefix already.
            let text = error.to_string();
            let suffix = format!(" at line {} column {}", error.line(), error.column());
            let text = text.strip_suffix(&suffix).unwrap_or(&text);
            ScenarioError::Syntax {
                file: source.to_owned(),
                line: error.line(),
                column: error.column(),
                // As in RON: a type error deep in the file names its field.
                message: if path.is_empty() || path == "." {
                    text.to_owned()
                } else {
                    format!("{path}: {text}")
                },
            }
        };
        let mut deserializer = serde_json::Deserializer::from_str(text);
        let mut scenario: Scenario = serde_path_to_error::deserialize(&mut deserializer)
            .map_err(|error| syntax(error.path().to_string(), error.inner()))?;
        deserializer
            .end()
            .map_err(|error| syntax(String::new(), &error))?;
        source.clone_into(&mut scenario.source);
        scenario.base_dir = base_dir.map(Path::to_path_buf);
        scenario.validate()?;
        Ok(scenario)
    }

    /// Reads, parses and validates the scenario file at `path`, RON or JSON
    /// as [`ScenarioFormat::detect`] says (when the format was guessed from
    /// the content, a syntax error says which format was tried), and the
    /// recorded tracks it names (`recorded_tracks`, relative to the file's
    /// folder) into [`Scenario::recorded`].
    ///
    /// # Errors
    /// [`ScenarioError::Io`] when the file or its tracks cannot be read, a
    /// [`ScenarioError::Invalid`] naming the tracks file, line and field
    /// for a bad row, or a `Recorded` target without a track; else as
    /// [`Scenario::from_ron_str`] or [`Scenario::from_json_str`].
    pub fn load(path: &Path) -> Result<Scenario, ScenarioError> {
        let text = std::fs::read_to_string(path).map_err(|source| ScenarioError::Io {
            path: path.to_owned(),
            source,
        })?;
        let source = path.display().to_string();
        let (format, guessed) = ScenarioFormat::detect(path, &text);
        let loaded = match format {
            ScenarioFormat::Ron => Self::parse_ron(&text, &source, path.parent()),
            ScenarioFormat::Json => Self::parse_json(&text, &source, path.parent()),
        };
        let mut scenario = loaded.map_err(|error| match error {
            ScenarioError::Syntax {
                file,
                line,
                column,
                message,
            } => ScenarioError::Syntax {
                file,
                line,
                column,
                message: if guessed {
                    format!(
                        "{message} (read as {}, guessed from the content: name the file .ron or .json to choose)",
                        format.name()
                    )
                } else {
                    format!("{message} (read as {}, from the extension)", format.name())
                },
            },
            other => other,
        })?;
        scenario.read_recorded_tracks(path)?;
        Ok(scenario)
    }

    /// Reads the tracks file `recorded_tracks` names, beside the scenario
    /// file at `path`, into [`Scenario::recorded`] (decision 40).
    fn read_recorded_tracks(&mut self, path: &Path) -> Result<(), ScenarioError> {
        let Some(relative) = &self.recorded_tracks else {
            return Ok(());
        };
        let tracks_path = path.parent().unwrap_or(Path::new("")).join(relative);
        let text = std::fs::read_to_string(&tracks_path).map_err(|source| ScenarioError::Io {
            path: tracks_path.clone(),
            source,
        })?;
        self.recorded = RecordedTracks::from_csv_str(
            &text,
            &tracks_path.display().to_string(),
            self.local_frame().as_ref(),
            |vessel| self.vessel_length_m(vessel),
        )?;
        self.check_recorded()
    }

    /// The scenario as pretty-printed JSON (four-space indent, a final line
    /// end); [`Scenario::from_json_str`] on the result gives back an equal
    /// scenario.
    ///
    /// # Errors
    /// [`ScenarioError::Syntax`] if JSON cannot represent a value (a
    /// non-finite number: a valid scenario holds none).
    pub fn to_json_string(&self) -> Result<String, ScenarioError> {
        let mut text =
            serde_json::to_string_pretty(self).map_err(|error| ScenarioError::Syntax {
                file: self.source.clone(),
                line: 0,
                column: 0,
                message: format!("cannot write as JSON: {error}"),
            })?;
        text.push('\n');
        Ok(text)
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

/// Loads every `*.ron` and `*.json` file directly inside `dir` (not in
/// subdirectories), sorted by file name.
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
            && path.extension().is_some_and(|extension| {
                extension == SCENARIO_EXTENSION || extension == JSON_SCENARIO_EXTENSION
            })
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
            lanes: vec![Lane::new_nm("north", (0.0, -5.0), (0.1, 5.0), 0.75)],
            separation_zones: vec![crate::scheme::SeparationZoneSpec::new_nm(
                "west of it",
                vec![(-1.0, -5.0), (-0.5, -5.0), (-0.5, 5.0), (-1.0, 5.0)],
            )],
            rule10: crate::scheme::Rule10Settings {
                crossing_tolerance_deg: Some(10.0),
                flow_tolerance_deg: None,
            },
            land: Vec::new(),
            no_go: Vec::new(),
            land_geojson: None,
            land_clearance_m: None,
            geojson_land: Vec::new(),
            base_dir: None,
            seed: Some(u64::MAX),
            start_time: None,
            source: "everything".into(),
            recorded_tracks: None,
            recorded: crate::RecordedTracks::default(),
        }
    }

    #[test]
    fn everything_round_trips_as_json() {
        let mut scenario = everything();
        scenario.validate().expect("valid");
        let text = scenario.to_json_string().expect("writes");
        let back = Scenario::from_json_str(&text, "back.json").expect("reads back");
        assert_eq!(back, scenario, "{text}");
        assert_eq!(back.source, "back.json");
    }

    #[test]
    fn json_errors_name_the_line_and_the_field() {
        let text = everything().to_json_string().expect("writes");
        let bad = text.replacen("11.5", "\"fast\"", 1);
        let error = Scenario::from_json_str(&bad, "bad.json").expect_err("a string speed");
        let message = error.to_string();
        assert!(
            message.starts_with("bad.json:") && message.contains("ownship.speed_kn"),
            "{message}"
        );
    }

    #[test]
    fn detect_goes_by_extension_then_content() {
        let detect = |path: &str, text: &str| ScenarioFormat::detect(Path::new(path), text);
        assert_eq!(detect("a.JSON", "Scenario("), (ScenarioFormat::Json, false));
        assert_eq!(detect("a.ron", "{"), (ScenarioFormat::Ron, false));
        assert_eq!(
            detect("a.txt", "  {\"name\": 1}"),
            (ScenarioFormat::Json, true)
        );
        assert_eq!(detect("a", "Scenario("), (ScenarioFormat::Ron, true));
        assert_eq!(ScenarioFormat::Json.name(), "JSON");
        assert_eq!(ScenarioFormat::Ron.name(), "RON");
    }

    #[test]
    fn load_picks_the_format_and_says_which_failed() {
        let dir = std::env::temp_dir().join(format!("vorrt-io-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let mut scenario = everything();
        scenario.validate().expect("valid");
        let json = scenario.to_json_string().expect("json");
        let ron = scenario.to_ron_string().expect("ron");
        for (file, text) in [
            ("a.json", &json),
            ("b.ron", &ron),
            ("c.txt", &json),
            ("d", &ron),
        ] {
            let path = dir.join(file);
            std::fs::write(&path, text).expect("write");
            assert_eq!(Scenario::load(&path).expect(file), scenario, "{file}");
        }
        assert_eq!(
            load_dir(&dir).expect("dir").len(),
            2,
            "the .ron and .json files"
        );
        let path = dir.join("e.scenario");
        std::fs::write(&path, json.replacen("11.5", "true", 1)).expect("write");
        let message = Scenario::load(&path).expect_err("bad").to_string();
        assert!(
            message.contains("read as JSON, guessed from the content"),
            "{message}"
        );
        let path = dir.join("f.json");
        std::fs::write(&path, &ron).expect("write");
        let message = Scenario::load(&path)
            .expect_err("RON in a .json")
            .to_string();
        assert!(
            message.contains("read as JSON, from the extension"),
            "{message}"
        );
        std::fs::remove_dir_all(&dir).expect("clean");
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
        scenario.separation_zones.clear();
        scenario.rule10 = crate::scheme::Rule10Settings::default();
        let text = scenario.to_ron_string().expect("writes");
        for absent in [
            "planner",
            "simulation",
            "lanes",
            "separation_zones",
            "rule10",
            "description",
            "seed",
        ] {
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
