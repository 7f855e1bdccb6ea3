//! How a command ends: [`ExitStatus`] and [`CliError`].

use std::fmt;
use std::process::ExitCode;

/// How a command ended, as the process's exit code.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum ExitStatus {
    /// 0: success.
    Success,
    /// 1: the planner found no safe path, or a run did not reach its goal safely.
    Unsafe,
    /// 2: bad input or usage.
    BadInput,
}

impl ExitStatus {
    /// The numeric exit code.
    #[must_use]
    pub(crate) fn code(self) -> u8 {
        match self {
            Self::Success => 0,
            Self::Unsafe => 1,
            Self::BadInput => 2,
        }
    }
}

impl From<ExitStatus> for ExitCode {
    fn from(status: ExitStatus) -> Self {
        ExitCode::from(status.code())
    }
}

/// Why a command failed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum CliError {
    /// A scenario could not be read or is invalid, or an option is wrong (exit 2).
    BadInput(String),
    /// An output file or folder could not be written (exit 2).
    Output(String),
    /// The planner found no safe path (exit 1).
    NoSafePath(String),
}

impl CliError {
    /// The exit status this error ends the program with.
    #[must_use]
    pub(crate) fn status(&self) -> ExitStatus {
        match self {
            Self::BadInput(_) | Self::Output(_) => ExitStatus::BadInput,
            Self::NoSafePath(_) => ExitStatus::Unsafe,
        }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::BadInput(message) | Self::Output(message) | Self::NoSafePath(message) => {
                f.write_str(message)
            }
        }
    }
}

impl std::error::Error for CliError {}
