//! The `simulator` example run as a user runs it, for the tests that check it
//! (`tests/draw_simulator.rs`, `tests/simulator_progressive.rs`). Not declared in `mod.rs`: the
//! fuzz crate has no example to run, so its users include it alone with `#[path]`.

use std::path::Path;
use std::process::{Command, Output};

/// `cargo run --example simulator -- ARGS`, in this test's own profile so nothing is rebuilt.
pub fn simulator(args: &[&str]) -> Output {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let mut command = Command::new(cargo);
    command.args([
        "run",
        "--quiet",
        "--example",
        "simulator",
        "--manifest-path",
    ]);
    command.arg(Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.toml"));
    if !cfg!(debug_assertions) {
        command.arg("--release");
    }
    command.arg("--").args(args);
    command.output().expect("cargo runs")
}
