#![doc = include_str!("../README.md")]
#![forbid(missing_docs)]
// All printing goes through `console`, which never panics on a failed write.
#![deny(clippy::print_stdout, clippy::print_stderr)]

mod args;
mod batch;
mod coast;
mod commands;
mod console;
mod demo;
mod error;
mod export;
mod fixtures;
mod font;
mod import_ais;
mod judge;
pub mod library;
mod plot;
mod progress;
mod replay;
pub mod report;
mod run;

// The crates whose types `report`'s constructors take, so that this crate
// alone is enough to build a report.
pub use vorrt_planner as planner;
pub use vorrt_scenarios as scenarios;

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
    ExitCode::from(run_parsed(std::env::args_os()))
}

/// [`main_entry`] on the command line `argv` (the program name first):
/// the exit code.
fn run_parsed(argv: impl IntoIterator<Item = std::ffi::OsString>) -> u8 {
    let cli = match args::Cli::try_parse_from(argv) {
        Ok(cli) => cli,
        Err(error) => {
            // --help and --version are "errors" with exit code 0.
            let _ = error.print();
            let code = match error.exit_code() {
                0 => ExitStatus::Success,
                _ => ExitStatus::BadInput,
            };
            return code.code();
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
        Some(error) if error.kind() == ErrorKind::BrokenPipe => status.code(),
        Some(error) => {
            console::warn(&format!("error: cannot write to standard output: {error}"));
            ExitStatus::BadInput.code()
        }
        None => status.code(),
    }
}
