//! A ball rolling across the demo scene's floor: each frame redrawn only where it can have
//! changed (`fixray::Damage`) and, for comparison, in full (see `animation.rs`).

#![no_std]
#![no_main]

#[cfg_attr(target_arch = "arm", cortex_m_rt::entry)]
#[cfg_attr(target_arch = "riscv32", riscv_rt::entry)]
fn main() -> ! {
    fixray_firmware::harness::run_animation()
}
