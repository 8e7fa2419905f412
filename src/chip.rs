//! The instruction set fixray's arithmetic follows: the few facts about a chip family that
//! change the best exact form of a product, a shift or a bit length. `build.rs` names the
//! family (`fixray_chip`) from the target; this is the one place that reads it.
//!
//! Every path these facts choose computes the same values as the other; the host's tests run
//! each family's paths by forcing the family (`FIXRAY_CHIP=armv6m cargo test`), and
//! ARCHITECTURE.md lists them with what each saves.

/// ARMv6-M (Cortex-M0/M0+), which multiplies 32 × 32 → 32 only: there the compiler's 64-bit
/// product is a call to a full 64 × 64 multiply, and four 16-bit partial products are shorter.
pub(crate) const NO_LONG_MULTIPLY: bool = cfg!(fixray_chip = "armv6m");

/// ARMv6-M, which has no divide instruction: there a 32-bit division is a library call.
pub(crate) const NO_DIVIDE: bool = cfg!(fixray_chip = "armv6m");

/// Chips without a count-leading-zeros instruction: ARMv6-M, and RV32 without Zbb. There a bit
/// length comes from comparisons and a table.
pub(crate) const NO_CLZ: bool = cfg!(any(
    fixray_chip = "armv6m",
    all(fixray_chip = "riscv32", not(target_feature = "zbb"))
));

/// The Armv7-M cores, whose 32 × 32 → 64-bit multiply gives the product's high word in one
/// instruction: there a rounded quotient of a product by `2^shift`, `shift ≥ 33`, is taken from
/// the high word alone, and a smaller shift is moved up to 33 where the operand allows.
pub(crate) const HIGH_WORD_QUOTIENT: bool = cfg!(fixray_chip = "armv7m");

/// ARMv6-M, where a 64-bit shift by a variable amount is a library call: there a rounded shift
/// goes by 32-bit words.
pub(crate) const WORD_SHIFTS: bool = cfg!(fixray_chip = "armv6m");

#[cfg(test)]
mod tests {
    extern crate std;

    /// The family this build is for, as `build.rs` named it or `--cfg` forced it.
    const FAMILY: &str = if cfg!(fixray_chip = "armv6m") {
        "armv6m"
    } else if cfg!(fixray_chip = "armv7m") {
        "armv7m"
    } else if cfg!(fixray_chip = "riscv32") {
        "riscv32"
    } else {
        "other"
    };

    #[test]
    fn the_family_asked_for_is_the_one_in_force() {
        // CI forces each family in turn and says which in `FIXRAY_CHIP`: a build that did not
        // take it would run the host's paths again and prove nothing.
        if let Ok(want) = std::env::var("FIXRAY_CHIP") {
            assert_eq!(FAMILY, want);
        }
        assert_eq!(super::NO_LONG_MULTIPLY, FAMILY == "armv6m");
        assert_eq!(super::WORD_SHIFTS, FAMILY == "armv6m");
        assert_eq!(super::HIGH_WORD_QUOTIENT, FAMILY == "armv7m");
    }
}
