//! Names the board each target runs on (as `cfg(board = "...")`) and hands the linker that
//! board's memory layout as `memory.x`.

use std::{env, fs, path::PathBuf};

/// Target triple, board (the file `memory/{board}.x` and the cfg value), QEMU machine.
const BOARDS: [(&str, &str, &str); 4] = [
    ("thumbv6m-none-eabi", "microbit", "microbit"),
    ("thumbv7m-none-eabi", "lm3s6965evb", "lm3s6965evb"),
    ("thumbv7em-none-eabihf", "mps2_an386", "mps2-an386"),
    ("riscv32imc-unknown-none-elf", "virt", "virt"),
];

fn main() {
    println!(
        r#"cargo::rustc-check-cfg=cfg(board, values("microbit", "lm3s6965evb", "mps2_an386", "virt"))"#
    );
    println!("cargo::rerun-if-changed=build.rs");
    let target = env::var("TARGET").expect("cargo sets TARGET");
    // Any other target (a host `cargo check`, say) gets no board; src/lib.rs then refuses it.
    let Some(&(_, board, machine)) = BOARDS.iter().find(|(t, _, _)| *t == target) else {
        return;
    };
    let layout = format!("memory/{board}.x");
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    fs::copy(&layout, out.join("memory.x")).expect("copy the board's memory layout");
    println!("cargo::rerun-if-changed={layout}");
    println!("cargo::rustc-link-search={}", out.display());
    println!(r#"cargo::rustc-cfg=board="{board}""#);
    println!("cargo::rustc-env=FIRMWARE_TARGET={target}");
    println!("cargo::rustc-env=FIRMWARE_MACHINE={machine}");
}
