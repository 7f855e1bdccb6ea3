//! Closed loop on the paper's crossing encounter: ownship gives way to a vessel from starboard (rule 15).
//!
//! Run with `cargo run --release --example crossing`; prints one row per target
//! (encounter, role, minimum distance, compliance) and the run's totals.
#![allow(clippy::print_stdout)]

mod common;

fn main() -> std::process::ExitCode {
    common::run_fixture("paper/crossing.ron")
}
