//! Faults and unexpected exceptions end the QEMU run with [`exit::FAULT`] instead of hanging
//! until `timeout` (the start-up crates' defaults loop forever).

use crate::exit;
use semihosting::eprintln;

#[cfg(target_arch = "arm")]
#[cortex_m_rt::exception]
unsafe fn HardFault(frame: &cortex_m_rt::ExceptionFrame) -> ! {
    eprintln!("hard fault at pc {:#010x}", frame.pc());
    exit::with(exit::FAULT)
}

#[cfg(target_arch = "arm")]
#[cortex_m_rt::exception]
unsafe fn DefaultHandler(irqn: i16) -> ! {
    eprintln!("unexpected exception or interrupt {irqn}");
    exit::with(exit::FAULT)
}

/// riscv-rt calls this for every exception without a handler of its own.
#[cfg(target_arch = "riscv32")]
#[unsafe(no_mangle)]
extern "C" fn ExceptionHandler(frame: &riscv_rt::TrapFrame) -> ! {
    let cause = riscv::register::mcause::read().bits();
    let pc = riscv::register::mepc::read();
    eprintln!(
        "exception {cause:#x} at pc {pc:#010x} (ra {:#010x})",
        frame.ra
    );
    exit::with(exit::FAULT)
}

/// riscv-rt calls this for every interrupt without a handler of its own.
#[cfg(target_arch = "riscv32")]
#[unsafe(no_mangle)]
extern "C" fn DefaultHandler() -> ! {
    eprintln!(
        "unexpected interrupt {:#x}",
        riscv::register::mcause::read().bits()
    );
    exit::with(exit::FAULT)
}
