//! # vorrt-cli
//!
//! The `vorrt` command line: run a scenario in closed loop and report on it
//! (`simulate`), plan once from the start (`plan`), validate scenario files
//! (`check`), and run every bundled scenario into an HTML page (`demo`).
//!
//! | module | what it gives |
//! |---|---|
//! | [`args`] | the command line itself (clap), with its help texts |
//! | [`commands`] | what each subcommand does, and [`ExitStatus`] |
//! | [`report`] | the stable `report.json` and `plan` output schemas (see `docs/report-format.md`) |
//! | [`plot`] | trajectory and distance plots, SVG and PNG |
//! | [`demo`] | every bundled scenario in parallel, and `index.html` |
//! | [`batch`] | Monte Carlo campaigns: `batch`, `generate`, `merge`, histograms |
//! | [`export`] | `trajectory.csv`, `trajectory.geojson`, `trajectory.gpx`; the plan as GeoJSON or GPX |
//! | [`import_ais`] | `import-ais`: an AIS log into a geographic scenario |
//! | [`font`] | the bundled DejaVu Sans font for PNG text |
//!
//! [`main_entry`] is the whole program: the workspace root package's `vorrt`
//! binary (`cargo run --release -- demo` at the root; `cargo install --path .`)
//! and this crate's `vorrt-cli` binary (used by its tests) both just call it.
#![forbid(missing_docs)]
// Printing results for a person is this crate's job.
#![allow(clippy::print_stdout, clippy::print_stderr)]

pub mod args;
pub mod batch;
pub mod commands;
pub mod demo;
pub mod export;
pub mod font;
pub mod import_ais;
pub mod plot;
pub mod report;

pub use commands::{CliError, ExitStatus};

use clap::Parser;
use std::process::ExitCode;

/// Parses the command line, runs the command and returns its exit code:
/// 0 success, 1 no safe path / the run did not reach its goal safely,
/// 2 bad input or usage (clap's usage errors included). Bad input never
/// panics: the error is printed on stderr as one `error: ...` message.
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
    match commands::run(cli) {
        Ok(status) => status.into(),
        Err(error) => {
            eprintln!("error: {error}");
            error.status().into()
        }
    }
}
