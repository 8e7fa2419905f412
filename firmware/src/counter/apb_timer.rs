//! CMSDK APB timer 0 of the MPS2 AN386 at 0x4000_0000, on the 25 MHz peripheral clock: one
//! tick per 40 instructions under `-icount shift=0`.
//!
//! It is a 32-bit down-counter, so it wraps only every 1.7 × 10¹¹ instructions.

use core::ptr;

/// The counter, as the report names it.
pub const NAME: &str = "CMSDK APB timer 0, 25 MHz";
/// 1 ns per instruction ÷ 40 ns per tick at 25 MHz.
pub const PER_TICK: (u64, u64) = (40, 1);

/// Timer 0 control: bit 0 enables it.
const CTRL: *mut u32 = 0x4000_0000 as *mut u32;
/// Timer 0 current value, counting down.
const VALUE: *mut u32 = 0x4000_0004 as *mut u32;
/// Timer 0 reload value, loaded when VALUE passes 0.
const RELOAD: *mut u32 = 0x4000_0008 as *mut u32;

/// Starts timer 0 free-running over the full 32 bits.
pub fn start() {
    // SAFETY: timer 0's registers; nothing else in the firmware uses them.
    unsafe {
        ptr::write_volatile(RELOAD, u32::MAX);
        ptr::write_volatile(VALUE, u32::MAX);
        ptr::write_volatile(CTRL, 1);
    }
}

/// Ticks since [`start`], modulo 2³².
pub fn ticks() -> u32 {
    // SAFETY: reading the current value has no side effect.
    let value = unsafe { ptr::read_volatile(VALUE) };
    u32::MAX - value
}
