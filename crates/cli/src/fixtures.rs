//! The bundled scenarios, embedded in the binary: `vorrt demo` runs them
//! from any folder, with no checkout beside it (`cargo install --locked
//! --path .`, then the checkout may go). They are `vorrt_scenarios::fixtures`
//! (files in that crate's `fixtures/`, where its test checks that every one
//! is embedded); this module only turns their errors into the CLI's.

use crate::error::CliError;
use vorrt_scenarios::Scenario;
pub(crate) use vorrt_scenarios::fixtures::{BUNDLED, Fixture};

/// Parses and validates a bundled scenario; a failure is bad input, as for a
/// scenario file given on the command line.
pub(crate) fn load(fixture: &Fixture) -> Result<Scenario, CliError> {
    fixture
        .load()
        .map_err(|error| CliError::BadInput(error.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The demo's reports name an embedded scenario as
    /// `fixtures/<group>/<file>` (`first_hour.rs` checks one end to end).
    #[test]
    fn every_embedded_fixture_loads_under_its_source_name() {
        for fixture in BUNDLED {
            let scenario = load(fixture).expect("valid");
            assert_eq!(
                scenario.source,
                format!("fixtures/{}/{}", fixture.group, fixture.file)
            );
        }
    }
}
