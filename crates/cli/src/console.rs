//! The one writer of the console: everything the command line prints goes
//! through [`print`] (standard output) or [`warn`] (standard error), never
//! through `println!`, which panics when the output cannot be written.
//!
//! A failed write to standard output does not stop the command: its files
//! are still written. The first error is kept, later output is dropped, and
//! [`stdout_error`] hands it to `main_entry`, which ends quietly on a closed
//! pipe (as Unix tools do: `vorrt demo | head -3`) and otherwise says what
//! failed and exits 2 (`vorrt plan x.ron > /dev/full`).

use std::io::{self, Write};
use std::sync::{Mutex, PoisonError};

/// The first error writing to standard output, if any.
static STDOUT_ERROR: Mutex<Option<io::Error>> = Mutex::new(None);

/// Writes `text` to standard output as it is (add the line ends) and
/// flushes it. After the first failure, does nothing.
pub(crate) fn print(text: &str) {
    // The lock also keeps lines from parallel runs whole.
    let mut failed = STDOUT_ERROR.lock().unwrap_or_else(PoisonError::into_inner);
    if failed.is_some() {
        return;
    }
    let mut stdout = io::stdout().lock();
    if let Err(error) = stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush())
    {
        *failed = Some(error);
    }
}

/// [`print`] with a line end.
pub(crate) fn line(text: &str) {
    print(&format!("{text}\n"));
}

/// Writes `text` and a line end to standard error. Errors are ignored:
/// there is nowhere left to report them.
pub(crate) fn warn(text: &str) {
    let mut stderr = io::stderr().lock();
    let _ = writeln!(stderr, "{text}");
}

/// Takes the error of the first failed write to standard output.
pub(crate) fn stdout_error() -> Option<io::Error> {
    STDOUT_ERROR
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .take()
}
