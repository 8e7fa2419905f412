//! Names the chip family fixray is compiled for, as one `cfg`, `fixray_chip`, from the target
//! (`src/chip.rs` turns it into the few facts about an instruction set the arithmetic
//! follows). Nothing else in the crate asks which chip it is on.
//!
//! A family's paths can be forced on any machine, so that the host's tests run them, by the
//! environment (which rebuilds fixray alone) or by a `cfg` (which rebuilds every crate):
//!
//! ```text
//! FIXRAY_CHIP=armv6m cargo test
//! RUSTFLAGS='--cfg fixray_chip="armv6m"' cargo test
//! ```

use std::env;

/// The families, and the target names that make each: the first prefix that matches wins.
const FAMILIES: &[(&str, &str)] = &[
    // ARMv6-M (Cortex-M0/M0+): no 32 × 32 → 64 multiply, no divide, no count-leading-zeros.
    ("thumbv6m", "armv6m"),
    // ARMv7-M and ARMv7E-M (Cortex-M3, M4, M4F, M7) and ARMv8-M mainline: all three.
    ("thumbv7m", "armv7m"),
    ("thumbv7em", "armv7m"),
    ("thumbv8m.main", "armv7m"),
    // RV32 without the bit-manipulation extension: no count-leading-zeros.
    ("riscv32", "riscv32"),
];

fn main() {
    println!(
        "cargo::rustc-check-cfg=cfg(fixray_chip, values(\"armv6m\", \"armv7m\", \"riscv32\", \"other\"))"
    );
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rerun-if-env-changed=FIXRAY_CHIP");
    // A family forced with `--cfg fixray_chip=...` is the one in force.
    if env::var_os("CARGO_CFG_FIXRAY_CHIP").is_some() {
        return;
    }
    // One forced through the environment, if it names a family.
    if let Ok(forced) = env::var("FIXRAY_CHIP") {
        let names = ["armv6m", "armv7m", "riscv32", "other"];
        assert!(
            names.contains(&forced.as_str()),
            "FIXRAY_CHIP={forced} is not a chip family: one of {names:?}"
        );
        println!("cargo::rustc-cfg=fixray_chip=\"{forced}\"");
        return;
    }
    let target = env::var("TARGET").unwrap_or_default();
    let family = FAMILIES
        .iter()
        .find(|(prefix, _)| target.starts_with(prefix))
        .map_or("other", |&(_, family)| family);
    println!("cargo::rustc-cfg=fixray_chip=\"{family}\"");
}
