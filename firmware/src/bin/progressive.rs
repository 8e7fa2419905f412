//! The demo scene in progressive passes, from spacing 8 to 1, each pass's instructions against
//! the full frame's (see `progressive.rs`).

#![no_std]
#![no_main]

#[cfg_attr(target_arch = "arm", cortex_m_rt::entry)]
#[cfg_attr(target_arch = "riscv32", riscv_rt::entry)]
fn main() -> ! {
    fixray_firmware::harness::run_progressive()
}
