//! SysTick on the core clock: on the micro:bit's Cortex-M0 at 16 MHz, one tick per 62.5
//! instructions under `-icount shift=0`; on the LM3S6965's Cortex-M3 at the 12.5 MHz the chip
//! starts on (QEMU's system control: a 200 MHz source divided by `RCC.SYSDIV + 1`, 16 at
//! reset), one tick per 80.
//!
//! SysTick is 24 bits wide: it would wrap every 1.05 × 10⁹ instructions on the micro:bit,
//! fewer than a soft-float frame takes, and a larger `shift` only makes each instruction longer
//! and the wrap sooner. So the counter is extended in software: the SysTick exception counts
//! periods of [`PERIOD`] ticks. The period is short on purpose, so that the loop of known
//! length (2 × 10⁷ instructions) crosses several wraps and the calibration checks this
//! bookkeeping too; an exception every 4 × 10⁶ instructions or so costs about a dozen of them.

use core::ptr;
use core::sync::atomic::{AtomicU32, Ordering, compiler_fence};

/// The counter, as the report names it.
#[cfg(board = "microbit")]
pub const NAME: &str = "SysTick, 16 MHz core clock";
/// 1 ns per instruction ÷ 62.5 ns per tick at 16 MHz.
#[cfg(board = "microbit")]
pub const PER_TICK: (u64, u64) = (125, 2);

/// The counter, as the report names it.
#[cfg(board = "lm3s6965evb")]
pub const NAME: &str = "SysTick, 12.5 MHz core clock";
/// 1 ns per instruction ÷ 80 ns per tick at 12.5 MHz.
#[cfg(board = "lm3s6965evb")]
pub const PER_TICK: (u64, u64) = (80, 1);

/// SysTick control and status: ENABLE, TICKINT, CLKSOURCE (the core clock) are bits 0–2.
const SYST_CSR: *mut u32 = 0xE000_E010 as *mut u32;
/// SysTick reload value.
const SYST_RVR: *mut u32 = 0xE000_E014 as *mut u32;
/// SysTick current value.
const SYST_CVR: *mut u32 = 0xE000_E018 as *mut u32;

/// Ticks per SysTick period (the counter runs `PERIOD - 1` down to 0).
const PERIOD: u32 = 1 << 16;

/// Periods completed: SysTick reached 0 this many times.
static WRAPS: AtomicU32 = AtomicU32::new(0);

/// Starts SysTick on the core clock with its exception enabled.
pub fn start() {
    // SAFETY: the SysTick registers of the core; nothing else in the firmware uses them.
    unsafe {
        ptr::write_volatile(SYST_RVR, PERIOD - 1);
        ptr::write_volatile(SYST_CVR, 0);
        ptr::write_volatile(SYST_CSR, 0b111);
    }
}

/// Ticks since [`start`], modulo 2³².
pub fn ticks() -> u32 {
    loop {
        let wraps = WRAPS.load(Ordering::Relaxed);
        compiler_fence(Ordering::SeqCst);
        // SAFETY: reading SysTick's current value has no side effect.
        let value = unsafe { ptr::read_volatile(SYST_CVR) };
        compiler_fence(Ordering::SeqCst);
        // A wrap between the two reads would pair `value` with the wrong count: read again.
        if WRAPS.load(Ordering::Relaxed) == wraps {
            // The count reaches 0 as a period ends (and the exception counts it), then
            // reloads to PERIOD - 1 and counts down: within a period, 0 comes first.
            return wraps
                .wrapping_mul(PERIOD)
                .wrapping_add(PERIOD.wrapping_sub(value) % PERIOD);
        }
    }
}

#[cortex_m_rt::exception]
fn SysTick() {
    // Only this handler writes WRAPS, and thread mode only reads it: no lost update.
    WRAPS.store(
        WRAPS.load(Ordering::Relaxed).wrapping_add(1),
        Ordering::Relaxed,
    );
}
