//! Closed loop on the paper's overtaking encounter (rule 13).
//!
//! Run with `cargo run --release --example overtaking`; prints one row per target
//! (encounter, role, minimum distance, compliance) and the run's totals.
#![allow(clippy::print_stdout)]

mod common;

fn main() -> std::process::ExitCode {
    common::run_fixture("paper/overtaking.ron")
}
