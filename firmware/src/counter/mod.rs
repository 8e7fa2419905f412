//! The board's instruction counter.
//!
//! Under `-icount shift=0` QEMU's virtual clock is the instruction count in nanoseconds, so
//! every timer of the board is an instruction counter with a fixed number of instructions per
//! tick. Each board module provides `NAME`, `PER_TICK` (instructions per tick as a fraction),
//! `start()` and `ticks()`: a free-running 32-bit tick count. Measure with
//! `ticks().wrapping_sub(earlier)`, which is right while an interval stays under 2³² ticks
//! (over 4 × 10⁹ instructions on every board).

#[cfg(any(board = "microbit", board = "lm3s6965evb"))]
mod systick;
#[cfg(any(board = "microbit", board = "lm3s6965evb"))]
use systick as board;

#[cfg(board = "mps2_an386")]
mod apb_timer;
#[cfg(board = "mps2_an386")]
use apb_timer as board;

#[cfg(board = "virt")]
mod instret;
#[cfg(board = "virt")]
use instret as board;

pub use board::{NAME, start, ticks};

/// Instructions per tick, as `(numerator, denominator)`.
pub const PER_TICK: (u64, u64) = board::PER_TICK;

/// Instructions per tick rounded up: the counter's resolution.
pub const RESOLUTION: u64 = PER_TICK.0.div_ceil(PER_TICK.1);

/// The instructions `ticks` ticks stand for.
#[must_use]
pub const fn instructions(ticks: u64) -> u64 {
    ticks * PER_TICK.0 / PER_TICK.1
}
