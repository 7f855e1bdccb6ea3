//! The `vorrt` command (the `cli` feature, on by default): `cargo run --release -- demo`
//! at the workspace root. See `vorrt --help` and the `vorrt-cli` crate.

fn main() -> std::process::ExitCode {
    vorrt_cli::main_entry()
}
