//! Closed loop on the paper's four-vessel encounter: give way in a crossing and a head-on, stand on for a third.
//!
//! Run with `cargo run --release --example multi_vessel`; prints one row per target
//! (encounter, role, minimum distance, compliance) and the run's totals.
#![allow(clippy::print_stdout)]

mod common;

fn main() -> std::process::ExitCode {
    common::run_fixture("paper/multi_vessel.ron")
}
