//! fixray's demo and classic scenes on four microcontrollers under QEMU, rendered and
//! measured.
//!
//! Each binary renders one scene ([`Variant`]) with one [`Renderer`] — [`Fixed`], the Q16.16
//! renderer, or [`Reference`], the reference model in `f64` or `f32` — at [`COLS`] × [`ROWS`],
//! one row at a time, so it fits the 16 KiB of a Cortex-M0. One scene a binary keeps each
//! row of the table to what that scene alone needs in flash and RAM:
//!
//! | binary | renders |
//! |---|---|
//! | `fixed`, `fixed_classic` | the demo and the classic scene in Q16.16 |
//! | `fixed_classic_noshadow`, `fixed_classic_nomirror`, `fixed_classic_opaque` | the classic scene without shadow rays, without mirrors, with its glass opaque (no refraction) |
//! | `reference`, `reference_classic` | both scenes by the `f64` reference (soft-float everywhere) |
//! | `reference_f32`, `reference_f32_classic` | both scenes by the reference in `f32` (the Cortex-M4F's FPU) |
//! | `animate` | a ball rolling across the demo floor, each frame redrawn where it changed and in full ([`animation`]) |
//! | `draw` | both scenes through `Viewport::render` and a `Picture` onto an `Rgb565` display: the drawing layer's stack |
//! | `fixed_call` | the demo as `fixed` draws it, with `render_row` a call of its own: the static stack bound from it down ([`FixedCall`]) |
//!
//! It prints over semihosting what `scripts/firmware.sh` turns into a table: the
//! [`fixray::FrameHash`] of the frame (the host computes the same one, with the same
//! [`renderer`] code), the instructions the rows took, the flash image, the static RAM and the
//! peak stack. It then exits QEMU with status 0, or with a non-zero [`exit`] code on any
//! failure; a panic exits with 101 (semihosting's panic handler).
//!
//! | target | board (QEMU machine) | instruction counter |
//! |---|---|---|
//! | `thumbv6m-none-eabi` | micro:bit, Cortex-M0 (`microbit`) | SysTick on the 16 MHz core clock |
//! | `thumbv7m-none-eabi` | LM3S6965EVB, Cortex-M3 (`lm3s6965evb`) | SysTick on the 12.5 MHz core clock |
//! | `thumbv7em-none-eabihf` | MPS2 AN386, Cortex-M4F (`mps2-an386`) | CMSDK APB timer 0, 25 MHz |
//! | `riscv32imc-unknown-none-elf` | RV32, ESP32-C3 class (`virt`) | `minstret` |
//!
//! QEMU runs with `-icount shift=0`: its virtual clock advances exactly one nanosecond per
//! guest instruction, so a timer of `f` MHz ticks once every `1000 / f` instructions. That
//! counts instructions, not cycles. Before each frame the [`calibrate`] module times a loop of
//! known length and refuses to go on if the counter disagrees.
//!
//! The modules, one concept each: [`counter`] (the board's instruction counter),
//! [`calibrate`] (the loop of known length), [`stack`] (paint and measure the stack),
//! [`memory`] (flash and static RAM from the linker's symbols), [`fault`] (faults exit QEMU
//! non-zero), [`exit`] (the exit statuses), [`renderer`] (what is rendered: the scenes and the
//! [`Renderer`]s), [`harness`] (the measured frames), [`codegen`] (probes of known compiler
//! miscompiles, run by the `codegen_check` binary), and [`main!`] (a binary's entry point).
//! `build.rs` picks each board's memory layout from `memory/`.
//!
//! Run one firmware from this directory with, for example,
//! `cargo run --release --target thumbv6m-none-eabi --bin fixed_classic`: the runners in
//! `.cargo/config.toml` start QEMU. `scripts/firmware.sh` runs them all.
//!
//! One more binary, `oled` (feature `oled`, the LM3S6965EVB only), is no measurement: it draws
//! the demo scene through `fixray::Viewport` onto the board's emulated 128 × 64 OLED with the
//! [`oled`] module's SSD0323 driver, for `scripts/oled.sh` to capture and compare with the
//! host's render.

#![no_std]

#[cfg(not(any(
    board = "microbit",
    board = "lm3s6965evb",
    board = "mps2_an386",
    board = "virt"
)))]
compile_error!(
    "fixray-firmware builds for thumbv6m-none-eabi, thumbv7m-none-eabi, thumbv7em-none-eabihf \
     or riscv32imc-unknown-none-elf only (pass --target)"
);

pub mod animation;
pub mod calibrate;
pub mod codegen;
pub mod counter;
pub mod exit;
pub mod fault;
pub mod harness;
pub mod memory;
#[cfg(board = "lm3s6965evb")]
pub mod oled;
pub mod progressive;
pub mod renderer;
pub mod stack;

pub use harness::run;
pub use renderer::{
    COLS, Fixed, FixedCall, FixedRays, FixedShoot, ROWS, Reference, Renderer, Variant,
};

/// The entry point of a firmware binary: [`run`] with the renderer `$renderer` on the scene
/// [`Variant`]`::$variant`, started by the board's start-up crate (`cortex-m-rt` or
/// `riscv-rt`).
///
/// ```ignore
/// fixray_firmware::main!(fixray_firmware::Fixed, Classic);
/// ```
#[macro_export]
macro_rules! main {
    ($renderer:ty, $variant:ident) => {
        #[cfg_attr(target_arch = "arm", cortex_m_rt::entry)]
        #[cfg_attr(target_arch = "riscv32", riscv_rt::entry)]
        fn main() -> ! {
            $crate::run::<$renderer>($crate::Variant::$variant)
        }
    };
}

/// The target triple this firmware was built for.
pub const TARGET: &str = env!("FIRMWARE_TARGET");
/// The QEMU machine (`-machine`) this firmware runs on.
pub const MACHINE: &str = env!("FIRMWARE_MACHINE");
