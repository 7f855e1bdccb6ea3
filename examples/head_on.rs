//! Closed loop on the paper's head-on encounter (rule 14).
//!
//! Run with `cargo run --release --example head_on`; prints one row per target
//! (encounter, role, minimum distance, compliance) and the run's totals.
#![allow(clippy::print_stdout)]

mod common;

fn main() -> std::process::ExitCode {
    common::run_fixture("paper/head_on.ron")
}
