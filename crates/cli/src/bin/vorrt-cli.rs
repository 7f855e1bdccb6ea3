//! The `vorrt` command under this crate's binary name (`cargo run -p vorrt-cli`);
//! the workspace root builds the same program as `vorrt`. See `vorrt --help`.

fn main() -> std::process::ExitCode {
    vorrt_cli::main_entry()
}
