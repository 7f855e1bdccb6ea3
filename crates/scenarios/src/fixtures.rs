//! The bundled scenarios, embedded in the library: the paper's reference
//! encounters (`paper`), the 22 Imazu problems (`imazu`), a geographic
//! scenario imported from AIS (`geo`) and coastal encounters with land
//! (`coastal`). Their files are this crate's
//! `fixtures/<group>/<file>`; they are compiled in so that a program using
//! them (`vorrt demo`) needs no checkout beside it. A test checks that every
//! `*.ron` file of those folders is in [`BUNDLED`] with the same text.
//!
//! ```
//! let fixture = vorrt_scenarios::fixtures::find("paper/crossing").expect("bundled");
//! assert_eq!(fixture.source(), "fixtures/paper/crossing.ron");
//! let scenario = fixture.load().expect("valid");
//! assert_eq!(scenario.targets.len(), 1);
//! ```

use crate::error::ScenarioError;
use crate::io::SCENARIO_EXTENSION;
use crate::scenario::Scenario;

/// One embedded scenario file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Fixture {
    /// Its folder under `fixtures/`: `paper`, `imazu` or `geo`.
    pub group: &'static str,
    /// Its file name, e.g. `crossing.ron`.
    pub file: &'static str,
    /// Its text.
    pub text: &'static str,
    /// The text of the `GeoJSON` file its `land_geojson` names (a real
    /// coastline beside it in `fixtures/<group>/`), embedded too; `None`
    /// without one.
    pub land_geojson: Option<&'static str>,
}

impl Fixture {
    /// Its name for [`find`]: `<group>/<file>`, e.g. `paper/crossing.ron`.
    #[must_use]
    pub fn name(&self) -> String {
        format!("{}/{}", self.group, self.file)
    }

    /// The name it goes by in messages and reports (and in
    /// [`Scenario::source`] after [`Fixture::load`]):
    /// `fixtures/<group>/<file>`, its path in this crate.
    #[must_use]
    pub fn source(&self) -> String {
        format!("fixtures/{}/{}", self.group, self.file)
    }

    /// The file name without `.ron`.
    #[must_use]
    pub fn stem(&self) -> &'static str {
        self.file
            .strip_suffix(SCENARIO_EXTENSION)
            .and_then(|stem| stem.strip_suffix('.'))
            .unwrap_or(self.file)
    }

    /// Parses and validates the scenario, as [`Scenario::from_ron_str`] with
    /// [`Fixture::source`] as its name.
    ///
    /// # Errors
    /// None for the bundled files (a test loads each one); the error type is
    /// that of [`Scenario::from_ron_str`].
    pub fn load(&self) -> Result<Scenario, ScenarioError> {
        match self.land_geojson {
            // Its coastline comes embedded too: inline land, no file read.
            Some(land) => Scenario::from_ron_str_with_land_geojson(self.text, &self.source(), land),
            None => Scenario::from_ron_str(self.text, &self.source()),
        }
    }
}

macro_rules! fixture {
    ($group:literal, $file:literal) => {
        Fixture {
            group: $group,
            file: $file,
            text: include_str!(concat!("../fixtures/", $group, "/", $file)),
            land_geojson: None,
        }
    };
    ($group:literal, $file:literal, $land:literal) => {
        Fixture {
            group: $group,
            file: $file,
            text: include_str!(concat!("../fixtures/", $group, "/", $file)),
            land_geojson: Some(include_str!(concat!("../fixtures/", $group, "/", $land))),
        }
    };
}

/// Every bundled scenario: the paper's encounters, the Imazu problems, then
/// the geographic ones, each group in file-name order.
pub const BUNDLED: &[Fixture] = &[
    fixture!("paper", "crossing.ron"),
    fixture!("paper", "head_on.ron"),
    fixture!("paper", "multi_vessel.ron"),
    fixture!("paper", "overtaking.ron"),
    fixture!("paper", "tss.ron"),
    fixture!("imazu", "imazu_01.ron"),
    fixture!("imazu", "imazu_02.ron"),
    fixture!("imazu", "imazu_03.ron"),
    fixture!("imazu", "imazu_04.ron"),
    fixture!("imazu", "imazu_05.ron"),
    fixture!("imazu", "imazu_06.ron"),
    fixture!("imazu", "imazu_07.ron"),
    fixture!("imazu", "imazu_08.ron"),
    fixture!("imazu", "imazu_09.ron"),
    fixture!("imazu", "imazu_10.ron"),
    fixture!("imazu", "imazu_11.ron"),
    fixture!("imazu", "imazu_12.ron"),
    fixture!("imazu", "imazu_13.ron"),
    fixture!("imazu", "imazu_14.ron"),
    fixture!("imazu", "imazu_15.ron"),
    fixture!("imazu", "imazu_16.ron"),
    fixture!("imazu", "imazu_17.ron"),
    fixture!("imazu", "imazu_18.ron"),
    fixture!("imazu", "imazu_19.ron"),
    fixture!("imazu", "imazu_20.ron"),
    fixture!("imazu", "imazu_21.ron"),
    fixture!("imazu", "imazu_22.ron"),
    fixture!("geo", "channel_ais.ron"),
    fixture!("coastal", "crossing_coast.ron"),
    fixture!(
        "coastal",
        "dover_tss_crossing.ron",
        "dover_strait_ne10m.geojson"
    ),
    fixture!("coastal", "island.ron"),
    fixture!(
        "coastal",
        "kent_coast_head_on.ron",
        "dover_strait_ne10m.geojson"
    ),
    fixture!(
        "coastal",
        "new_york_narrows_approach.ron",
        "new_york_harbor_ne10m.geojson"
    ),
];

/// The bundled fixture called `name`: `<group>/<file>` with or without the
/// `.ron` (`paper/crossing.ron`, `imazu/imazu_05`), optionally prefixed by
/// `fixtures/` as in [`Fixture::source`].
#[must_use]
pub fn find(name: &str) -> Option<&'static Fixture> {
    let name = name.strip_prefix("fixtures/").unwrap_or(name);
    let (group, file) = name.split_once('/')?;
    BUNDLED
        .iter()
        .find(|fixture| fixture.group == group && (fixture.file == file || fixture.stem() == file))
}

/// The bundled fixtures of one group (`paper`, `imazu` or `geo`), in
/// file-name order; none for an unknown group.
pub fn group(group: &str) -> impl Iterator<Item = &'static Fixture> {
    BUNDLED.iter().filter(move |fixture| fixture.group == group)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    /// Every scenario file of the bundled groups is embedded, with the text
    /// it has in this crate's `fixtures/`, and nothing else is.
    #[test]
    fn every_fixture_file_is_embedded() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures");
        let mut on_disk = Vec::new();
        for group in ["paper", "imazu", "geo", "coastal"] {
            let mut files: Vec<String> = std::fs::read_dir(root.join(group))
                .expect("fixture folder")
                .map(|entry| {
                    entry
                        .expect("entry")
                        .file_name()
                        .to_string_lossy()
                        .into_owned()
                })
                .filter(|name| Path::new(name).extension().is_some_and(|ext| ext == "ron"))
                .collect();
            files.sort();
            for file in files {
                let text = std::fs::read_to_string(root.join(group).join(&file)).expect("read");
                on_disk.push((group.to_owned(), file, text));
            }
        }
        let embedded: Vec<(String, String, String)> = BUNDLED
            .iter()
            .map(|f| (f.group.to_owned(), f.file.to_owned(), f.text.to_owned()))
            .collect();
        assert_eq!(embedded, on_disk);
        // The folder the crate's path helper names is the one embedded.
        assert_eq!(crate::io::bundled_fixtures_dir(), root);
    }

    /// A fixture with an embedded coastline loads the same land as its
    /// file does from disk, beside its `GeoJSON`.
    #[test]
    fn embedded_coastline_is_the_file_beside_it() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures");
        let with_land: Vec<_> = BUNDLED
            .iter()
            .filter(|f| f.land_geojson.is_some())
            .collect();
        assert_eq!(with_land.len(), 3);
        for fixture in with_land {
            let embedded = fixture.load().expect("valid");
            let from_disk =
                Scenario::load(&root.join(fixture.group).join(fixture.file)).expect("valid");
            assert!(from_disk.land_geojson.is_some() && embedded.land_geojson.is_none());
            assert!(!embedded.land.is_empty());
            assert_eq!(embedded.land, from_disk.geojson_land, "{}", fixture.name());
        }
    }

    #[test]
    fn every_embedded_fixture_is_valid() {
        for fixture in BUNDLED {
            let scenario = fixture.load().expect("valid");
            assert_eq!(scenario.source, fixture.source());
        }
    }

    #[test]
    fn find_takes_the_name_with_or_without_extension_and_prefix() {
        for fixture in BUNDLED {
            for name in [
                fixture.name(),
                fixture.source(),
                format!("{}/{}", fixture.group, fixture.stem()),
            ] {
                assert_eq!(find(&name), Some(fixture), "{name}");
            }
        }
        assert_eq!(find("paper/imazu_01"), None);
        assert_eq!(find("crossing"), None);
        assert_eq!(find("paper/"), None);
        assert_eq!(group("paper").count(), 5);
        assert_eq!(group("imazu").count(), 22);
        assert_eq!(group("geo").count(), 1);
        assert_eq!(group("coastal").count(), 5);
        assert_eq!(group("golden").count(), 0);
    }
}
