//! Known compiler miscompiles, probed on this chip ([`fixray_firmware::codegen`]): one line
//! per case, `codegen: probe=... args=... want=... got=... verdict=ok|WRONG`, and exit status
//! `exit::MISCOMPILED` if any case is wrong.

#![no_std]
#![no_main]

use core::hint::black_box;

use fixray_firmware::{codegen, exit};
use semihosting::println;

#[cfg_attr(target_arch = "arm", cortex_m_rt::entry)]
#[cfg_attr(target_arch = "riscv32", riscv_rt::entry)]
fn main() -> ! {
    println!(
        "board={} target={} renderer=codegen-check",
        fixray_firmware::MACHINE,
        fixray_firmware::TARGET
    );
    let mut wrong = false;
    for case in codegen::CASES {
        // Through black_box, so that the call is made with values the compiler cannot see.
        let probe = black_box(case.probe);
        let (a, b) = black_box(case.args);
        let got = probe(a, b);
        let verdict = if got == case.want { "ok" } else { "WRONG" };
        wrong |= got != case.want;
        println!(
            "codegen: probe={} args={a},{b} want={:#x} got={got:#x} verdict={verdict}",
            case.name, case.want
        );
    }
    exit::with(if wrong {
        exit::MISCOMPILED
    } else {
        exit::SUCCESS
    })
}
