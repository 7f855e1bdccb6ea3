//! Progress on stderr while one long run goes on: a spinner with the
//! elapsed time on a terminal, else a plain line every few seconds
//! (`VORRT_PROGRESS_EVERY_S`, default 5), so that a long simulation is never
//! silent. Short runs print nothing.

use crate::console;
use std::io::IsTerminal;
use std::sync::mpsc::{self, RecvTimeoutError, Sender};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// Seconds between plain progress lines, unless `VORRT_PROGRESS_EVERY_S` says otherwise.
const DEFAULT_EVERY_S: f64 = 5.0;

/// Shows that something is running until it is dropped.
pub(crate) struct Ticker {
    bar: Option<indicatif::ProgressBar>,
    stop: Option<Sender<()>>,
    thread: Option<JoinHandle<()>>,
}

impl Ticker {
    /// Starts showing `message` with the time elapsed.
    pub(crate) fn start(message: String) -> Self {
        if std::io::stderr().is_terminal() {
            let bar = indicatif::ProgressBar::new_spinner();
            if let Ok(style) =
                indicatif::ProgressStyle::with_template("{spinner} {msg} ({elapsed})")
            {
                bar.set_style(style);
            }
            bar.set_message(message);
            bar.enable_steady_tick(Duration::from_millis(200));
            return Self {
                bar: Some(bar),
                stop: None,
                thread: None,
            };
        }
        let every = std::env::var("VORRT_PROGRESS_EVERY_S")
            .ok()
            .and_then(|text| text.parse::<f64>().ok())
            .filter(|seconds| seconds.is_finite() && *seconds > 0.0 && *seconds < 1e6)
            .unwrap_or(DEFAULT_EVERY_S);
        let (stop, stopped) = mpsc::channel::<()>();
        let started = Instant::now();
        let thread = std::thread::spawn(move || {
            while let Err(RecvTimeoutError::Timeout) =
                stopped.recv_timeout(Duration::from_secs_f64(every))
            {
                console::warn(&format!(
                    "{message}: still running after {:.0} s",
                    started.elapsed().as_secs_f64()
                ));
            }
        });
        Self {
            bar: None,
            stop: Some(stop),
            thread: Some(thread),
        }
    }
}

impl Drop for Ticker {
    fn drop(&mut self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
        // Dropping the sender wakes the thread, which then ends.
        self.stop.take();
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}
