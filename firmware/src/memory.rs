//! Flash and RAM use, read from the symbols the start-up crate's linker script defines.
//!
//! Both scripts (cortex-m-rt's and riscv-rt's) lay memory out the same way: flash holds code,
//! read-only data and the initial values of `.data`, ending at `__sidata + (__edata -
//! __sdata)`; RAM holds `.data`, `.bss` and `.uninit` from `__sdata` up, then the stack, which
//! grows down from `_stack_start` at the top of RAM.

/// Bytes used, as the linker laid them out.
#[derive(Debug, Clone, Copy)]
pub struct Usage {
    /// The flash image: code, read-only data and `.data`'s initial values.
    pub flash: usize,
    /// Static RAM: `.data`, `.bss` and `.uninit`.
    pub static_ram: usize,
}

// Only their addresses are used, never their contents.
unsafe extern "C" {
    /// Start of the flash image (cortex-m-rt: the vector table; riscv-rt: `.text`).
    #[cfg_attr(target_arch = "arm", link_name = "__vector_table")]
    #[cfg_attr(target_arch = "riscv32", link_name = "__stext")]
    static FLASH_START: u32;
    /// Start of `.data` in RAM.
    static __sdata: u32;
    /// End of `.data` in RAM.
    static __edata: u32;
    /// Where `.data`'s initial values are, in flash.
    static __sidata: u32;
    /// End of the statics, the lowest address the stack may reach.
    #[cfg_attr(target_arch = "arm", link_name = "_stack_end")]
    #[cfg_attr(target_arch = "riscv32", link_name = "__estack")]
    static STACK_LIMIT: u32;
    /// The initial stack pointer, at the top of RAM.
    static _stack_start: u32;
}

/// The flash image and static RAM of this firmware.
#[must_use]
pub fn usage() -> Usage {
    let data = (&raw const __edata).addr() - (&raw const __sdata).addr();
    Usage {
        flash: (&raw const __sidata).addr() + data - (&raw const FLASH_START).addr(),
        static_ram: stack_limit() - (&raw const __sdata).addr(),
    }
}

/// The lowest address the stack may grow down to: the end of the statics.
#[must_use]
pub fn stack_limit() -> usize {
    (&raw const STACK_LIMIT).addr()
}

/// The top of the stack, where it starts.
#[must_use]
pub fn stack_top() -> usize {
    (&raw const _stack_start).addr()
}
