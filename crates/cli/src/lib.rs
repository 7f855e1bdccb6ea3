//! # vorrt-cli
//!
//! The `vorrt` command line: run a scenario in closed loop and report on it
//! (`simulate`), plan once from the start (`plan`), validate scenario files
//! (`check`), run every bundled scenario into an HTML page (`demo`), run
//! Monte Carlo campaigns (`batch`, `generate`, `merge`), and judge any
//! planner's recorded tracks (`judge`).
//!
//! Its only public parts are [`main_entry`], the whole program, and
//! [`report`], the stable `report.json` and `plan` output schemas (see
//! `docs/report-format.md`). Inside, each module depends only on those
//! above it in this list, so there is no import circle:
//!
//! | module | what it gives |
//! |---|---|
//! | `error` | `ExitStatus` and `CliError` |
//! | `console` | the one writer of standard output and error |
//! | `args` | the command line itself (clap), with its help texts |
//! | `font`, `plot`, [`report`] | the bundled font, the plots and the report schema |
//! | `fixtures` | the bundled scenarios, embedded in the binary |
//! | `run` | one scenario's closed-loop run and its files |
//! | `progress` | progress on stderr for long runs |
//! | `export` | `trajectory.csv`, `trajectory.geojson`, `trajectory.gpx`; the plan as GeoJSON or GPX |
//! | `demo`, `batch`, `import_ais` | `vorrt demo`; `vorrt batch`, `generate` and `merge`; `import-ais`: an AIS log into a geographic scenario |
//! | `judge` | `vorrt judge`: recorded tracks judged by the project's evaluation |
//! | `commands` | what each subcommand does |
//!
//! The workspace root package's `vorrt` binary (`cargo run --release -- demo`
//! at the root; `cargo install --locked --path .`) and this crate's
//! `vorrt-cli` binary (used by its tests) both just call [`main_entry`].
#![forbid(missing_docs)]
// All printing goes through `console`, which never panics on a failed write.
#![deny(clippy::print_stdout, clippy::print_stderr)]

mod args;
mod batch;
mod commands;
mod console;
mod demo;
mod error;
mod export;
mod fixtures;
mod font;
mod import_ais;
mod judge;
mod plot;
mod progress;
pub mod report;
mod run;

use clap::Parser;
use error::ExitStatus;
use std::io::ErrorKind;
use std::process::ExitCode;

/// Parses the command line, runs the command and returns its exit code:
/// 0 success, 1 no safe path / the run did not reach its goal safely,
/// 2 bad input or usage (clap's usage errors included), or standard output
/// that could not be written. Bad input never panics: the error is printed
/// on stderr as one `error: ...` message. A closed standard output (a pipe
/// whose reader left) ends the printing quietly; the files are written all
/// the same.
#[must_use]
pub fn main_entry() -> ExitCode {
    let cli = match args::Cli::try_parse() {
        Ok(cli) => cli,
        Err(error) => {
            // --help and --version are "errors" with exit code 0.
            let _ = error.print();
            let code = match error.exit_code() {
                0 => ExitStatus::Success,
                _ => ExitStatus::BadInput,
            };
            return code.into();
        }
    };
    let status = match commands::run(cli) {
        Ok(status) => status,
        Err(error) => {
            console::warn(&format!("error: {error}"));
            error.status()
        }
    };
    match console::stdout_error() {
        Some(error) if error.kind() == ErrorKind::BrokenPipe => status.into(),
        Some(error) => {
            console::warn(&format!("error: cannot write to standard output: {error}"));
            ExitStatus::BadInput.into()
        }
        None => status.into(),
    }
}
