//! The exit statuses the firmware hands QEMU (through semihosting), and so the script.

/// The frame was rendered and measured.
pub const SUCCESS: i32 = 0;
/// The renderer refused its set-up or a row.
pub const RENDER_FAILED: i32 = 2;
/// The instruction counter disagreed with the loop of known length.
pub const COUNTER_WRONG: i32 = 3;
/// A fault or an unexpected exception or interrupt.
pub const FAULT: i32 = 4;
/// A probe of [`crate::codegen`] gave a wrong answer: the compiler miscompiles it here.
pub const MISCOMPILED: i32 = 5;
// A panic exits with 101, from `semihosting`'s panic handler.

/// Ends the QEMU run with `status`.
pub fn with(status: i32) -> ! {
    semihosting::process::exit(status)
}
