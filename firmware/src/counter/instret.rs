//! `minstret`, the RISC-V hart's retired-instruction counter. Under `-icount` QEMU derives
//! it from the instruction count, so it is exact: one tick per instruction.

/// The counter, as the report names it.
pub const NAME: &str = "minstret";
/// One tick per instruction.
pub const PER_TICK: (u64, u64) = (1, 1);

/// Nothing to start: `minstret` always counts.
pub fn start() {}

/// Instructions retired, modulo 2³².
pub fn ticks() -> u32 {
    // Truncation intended: the low word, measured with wrapping differences.
    riscv::register::minstret::read() as u32
}
