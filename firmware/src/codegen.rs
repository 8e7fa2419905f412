//! Probes for known compiler miscompiles, run on each chip by the `codegen_check` binary.
//!
//! Each probe is a small function the compiler is known to have got wrong on some target,
//! kept out of line so that it is compiled the same way wherever it is called from, with the
//! answer it must give worked out by the compiler's constant evaluator (rustc's, not LLVM's
//! code generator). `scripts/firmware.sh` runs them on every chip and reports a wrong answer.
//!
//! # `mul_by_3_shl_31`: LLVM's RV32 multiply by a hoisted constant whose low word is 2³¹
//!
//! It drew a wrong frame once: with one function of fixray moved out of line, the `fixed_rays`
//! firmware on RV32IMC found no sphere above the horizon while setting up its runs of sky. `Camera::row_plane_normal`'s cross product, inlined into the set-up, came
//! out as (0, 0, ±1): its y component, `right.z·t.x − right.x·t.z`, was compiled as the
//! constant 0. The set-up multiplies two 64-bit values by `0xFFFF_FFB0_8000_0000`; LLVM's
//! constant hoisting (`consthoist`, a code generator pass) makes that constant opaque, the
//! RV32 back end splits the 64-bit product into 32-bit pieces, and a 32-bit multiply by an
//! opaque `0x8000_0000` is compiled to nothing (the result is the other operand, or
//! undefined at `-O0`). rustc 1.95.0 (LLVM 22.1.2); `llc -disable-constant-hoisting`, or
//! `opt-level = "z"`, compiles it correctly. The LLVM IR that shows it, for `llc
//! -mtriple=riscv32 -mattr=+m`:
//!
//! ```text
//! define i32 @g(i32 %x) {
//!   %c = bitcast i32 -2147483648 to i32   ; what consthoist makes of a constant
//!   %m = mul i32 %x, %c
//!   ret i32 %m                            ; compiled to a bare `ret`
//! }
//! ```
//!
//! In Rust the smallest form found is this probe: two 64-bit products by `3 << 31`
//! (`0x1_8000_0000`), one constant used twice so that it is hoisted. At `opt-level` 1, 2, 3
//! and `"s"` on `riscv32imc-unknown-none-elf` it compiles to a bare `ret`: it returns `a`.

/// `3 · 2³¹`: a 64-bit constant whose low word is `0x8000_0000`.
const THREE_SHL_31: i64 = 3 << 31;

/// `a·C ^ b·C` with `C` = [`THREE_SHL_31`], in wrapping 64-bit arithmetic.
#[inline(never)]
#[must_use]
pub fn mul_by_3_shl_31(a: i64, b: i64) -> i64 {
    a.wrapping_mul(THREE_SHL_31) ^ b.wrapping_mul(THREE_SHL_31)
}

/// The same, evaluated by rustc at compile time: the answer the probe must give.
const fn mul_by_3_shl_31_const(a: i64, b: i64) -> i64 {
    a.wrapping_mul(THREE_SHL_31) ^ b.wrapping_mul(THREE_SHL_31)
}

/// A probe's inputs and the answer it must give.
#[derive(Debug, Clone, Copy)]
pub struct Case {
    /// The probe's name, as `codegen_check` prints it.
    pub name: &'static str,
    /// Its two arguments.
    pub args: (i64, i64),
    /// What it must return.
    pub want: i64,
    /// The probe.
    pub probe: fn(i64, i64) -> i64,
}

/// Every case: inputs where a miscompiled probe gives a different answer.
pub const CASES: [Case; 3] = [
    case("mul_by_3_shl_31", (1, 0)),
    case("mul_by_3_shl_31", (1, 2)),
    case("mul_by_3_shl_31", (-0x1234_5678_9abc, 0x7fff_ffff)),
];

const fn case(name: &'static str, args: (i64, i64)) -> Case {
    Case {
        name,
        args,
        want: mul_by_3_shl_31_const(args.0, args.1),
        probe: mul_by_3_shl_31,
    }
}
