//! Closed loop on the paper's traffic separation scheme: ownship crosses a westbound lane of 16 vessels, `d_th` = 100 m.
//!
//! Run with `cargo run --release --example tss`; prints one row per target
//! (encounter, role, minimum distance, compliance) and the run's totals.
#![allow(clippy::print_stdout)]

mod common;

fn main() -> std::process::ExitCode {
    common::run_fixture("paper/tss.ron")
}
