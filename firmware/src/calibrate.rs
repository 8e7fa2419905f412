//! Proves the instruction counter: time a loop whose instruction count is known.
//!
//! [`spin`] is two instructions per iteration (decrement, branch back), written in assembly so
//! the compiler cannot reshape it. [`run`] times 10⁷ iterations and compares the counter's
//! figure with 2 × 10⁷.

use crate::counter;

/// Iterations of the loop of known length: 2 × 10⁷ instructions, so that a tick of resolution
/// (80 instructions at most) is a few parts per million of it, and so that on the micro:bit
/// it spans several SysTick wraps.
pub const ITERATIONS: u32 = 10_000_000;

/// The counter's reading against the loop's known length.
#[derive(Debug, Clone, Copy)]
pub struct Calibration {
    /// Instructions the loop executes.
    pub expected: u64,
    /// Instructions the counter saw.
    pub measured: u64,
}

impl Calibration {
    /// Allowed gap: one tick of resolution plus the few instructions around the loop (the two
    /// counter reads and the call).
    pub const TOLERANCE: u64 = counter::RESOLUTION + 64;

    /// Whether the counter agrees with the loop within [`Self::TOLERANCE`].
    #[must_use]
    pub const fn agrees(&self) -> bool {
        self.measured.abs_diff(self.expected) <= Self::TOLERANCE
    }
}

/// Times [`ITERATIONS`] of [`spin`].
#[must_use]
pub fn run() -> Calibration {
    let before = counter::ticks();
    spin(ITERATIONS);
    let ticks = counter::ticks().wrapping_sub(before);
    Calibration {
        expected: 2 * u64::from(ITERATIONS),
        measured: counter::instructions(u64::from(ticks)),
    }
}

/// Executes exactly `2 × iterations` instructions (`iterations` ≥ 1).
#[inline(never)]
pub fn spin(iterations: u32) {
    // SAFETY: the loop only counts a register down to zero.
    unsafe {
        #[cfg(target_arch = "arm")]
        core::arch::asm!(
            "2:",
            "subs {n}, {n}, #1",
            "bne 2b",
            n = inout(reg) iterations => _,
            options(nomem, nostack),
        );
        #[cfg(target_arch = "riscv32")]
        core::arch::asm!(
            "2:",
            "addi {n}, {n}, -1",
            "bnez {n}, 2b",
            n = inout(reg) iterations => _,
            options(nomem, nostack),
        );
    }
}
