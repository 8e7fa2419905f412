//! Peak stack by painting: fill the free stack with a pattern, run, find the deepest word the
//! pattern no longer holds.
//!
//! The stack grows down from the top of RAM towards the end of the statics. [`paint`] fills
//! that gap up to the current stack pointer; [`peak`] scans it from the bottom. Exceptions
//! taken meanwhile (SysTick on the micro:bit and the LM3S6965) push onto the same stack and are counted, as
//! they should be.

use crate::memory;

/// The pattern: an unlikely word (cortex-m-rt paints with it too).
pub const PAINT: u32 = 0xCCCC_CCCC;

/// Fills the free stack, from the end of the statics up to the stack pointer, with [`PAINT`].
///
/// Everything deeper than the caller's frame after this is measured. The loop is
/// assembly because it must read the stack pointer after its own function has pushed
/// whatever it pushes; in Rust the compiler may read `sp` first and paint over its own
/// return address.
#[inline(never)]
pub fn paint() {
    let limit = memory::stack_limit();
    // SAFETY: writes only the words from the end of the statics up to the stack pointer,
    // where nothing is live.
    unsafe {
        #[cfg(target_arch = "arm")]
        core::arch::asm!(
            // r0: the word to paint, r1: the stack pointer, r2: the pattern. Low registers,
            // as Thumb-1 `stm` needs on the Cortex-M0.
            "mov r1, sp",
            "2:",
            "cmp r0, r1",
            "bhs 3f",
            "stm r0!, {{r2}}",
            "b 2b",
            "3:",
            inout("r0") limit => _,
            out("r1") _,
            in("r2") PAINT,
            options(nostack),
        );
        #[cfg(target_arch = "riscv32")]
        core::arch::asm!(
            "mv {end}, sp",
            "2:",
            "bgeu {word}, {end}, 3f",
            "sw {paint}, 0({word})",
            "addi {word}, {word}, 4",
            "j 2b",
            "3:",
            word = inout(reg) limit => _,
            end = out(reg) _,
            paint = in(reg) PAINT,
            options(nostack),
        );
    }
}

/// The deepest the stack has been since [`paint`], in bytes below the top of the stack.
#[must_use]
pub fn peak() -> usize {
    let top = memory::stack_top();
    let mut word = memory::stack_limit() as *const u32;
    // SAFETY: reads stay within RAM, between the end of the statics and the top of the stack.
    while (word as usize) < top && unsafe { word.read_volatile() } == PAINT {
        word = word.wrapping_add(1);
    }
    top - word as usize
}
