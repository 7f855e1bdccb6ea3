//! The bundled scenarios, embedded in the binary: `vorrt demo` runs them
//! from any folder, with no checkout beside it (`cargo install --locked
//! --path .`, then the checkout may go). `fixtures/` stays their source; a
//! test checks that every `*.ron` file of `fixtures/paper` and
//! `fixtures/imazu` and `fixtures/geo` is in [`BUNDLED`] with the same text.

use crate::error::CliError;
use vorrt_scenarios::Scenario;

/// One embedded scenario file.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Fixture {
    /// Its folder under `fixtures/`, the demo's group.
    pub(crate) group: &'static str,
    /// Its file name.
    pub(crate) file: &'static str,
    /// Its text.
    pub(crate) text: &'static str,
}

impl Fixture {
    /// The name it goes by in messages and reports:
    /// `fixtures/<group>/<file>`, as in the repository.
    pub(crate) fn source(&self) -> String {
        format!("fixtures/{}/{}", self.group, self.file)
    }

    /// The file name without `.ron`.
    pub(crate) fn stem(&self) -> &'static str {
        self.file.strip_suffix(".ron").unwrap_or(self.file)
    }

    /// Parses and validates the scenario.
    pub(crate) fn load(&self) -> Result<Scenario, CliError> {
        Scenario::from_ron_str(self.text, &self.source())
            .map_err(|error| CliError::BadInput(error.to_string()))
    }
}

macro_rules! fixture {
    ($group:literal, $file:literal) => {
        Fixture {
            group: $group,
            file: $file,
            text: include_str!(concat!("../../../fixtures/", $group, "/", $file)),
        }
    };
}

/// Every bundled scenario: the paper's encounters, the Imazu problems, then
/// the geographic ones, each group in file-name order.
pub(crate) const BUNDLED: &[Fixture] = &[
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
];

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    /// Every scenario file of the bundled groups is embedded, with the text
    /// it has in `fixtures/`, and nothing else is.
    #[test]
    fn every_fixture_file_is_embedded() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures");
        let mut on_disk = Vec::new();
        for group in ["paper", "imazu", "geo"] {
            let mut files: Vec<String> = std::fs::read_dir(root.join(group))
                .expect("fixture folder")
                .map(|entry| {
                    entry
                        .expect("entry")
                        .file_name()
                        .to_string_lossy()
                        .into_owned()
                })
                .filter(|name| name.ends_with(".ron"))
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
    }

    #[test]
    fn every_embedded_fixture_is_valid() {
        for fixture in BUNDLED {
            let scenario = fixture.load().expect("valid");
            assert_eq!(scenario.source, fixture.source());
        }
    }
}
