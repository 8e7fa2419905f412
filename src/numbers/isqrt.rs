//! The exact integer square root, kept in one place so that it can be swapped by measurement.

use crate::numbers::fx::{top_word, wide_mul_u32};
use crate::numbers::reciprocal::rsqrt;

/// `floor(sqrt(x))` for every `u64`, exactly.
///
/// fixray takes square roots of Q32.32 values: `isqrt(v · 2³²) = floor(sqrt(v) · 2¹⁶)`, which is
/// the Q16.16 square root of `v`, truncated.
///
/// The estimate is `x · (1/√x)` from the table-seeded reciprocal square root that normalises
/// vectors, with a Newton step (good to about 2⁻²⁸), then corrected by whole steps until
/// `r² ≤ x < (r + 1)²` holds: one step or none for the values the renderer meets, at most a
/// few dozen anywhere. Measured under QEMU in a loop on 2⁴⁰-sized arguments (the loop's own
/// cost included), it took 208 instructions on a Cortex-M4F where core's `u64::isqrt` took
/// 250, and 1 229 on a Cortex-M0 against 1 286.
///
/// ```
/// assert_eq!(fixray::isqrt(0), 0);
/// assert_eq!(fixray::isqrt(15), 3);
/// assert_eq!(fixray::isqrt(16), 4);
/// assert_eq!(fixray::isqrt(u64::MAX), u32::MAX as u64);
/// ```
#[must_use]
pub const fn isqrt(x: u64) -> u64 {
    if x < 2 {
        return x;
    }
    let (y, half) = rsqrt(x); // 1/√x ≈ y · 2^−(30 + half), with x < 2^(2·half)
    // √x = x · (1/√x). With m the top 32 bits of x, x ≈ m · 2^(2·half − 32), so
    // √x ≈ m · y · 2^(half − 62).
    let p = 2 * half;
    let m = top_word(x, p);
    let mut r = wide_mul_u32(m, y) >> (62 - half);
    while !square_at_most(r, x) {
        r -= 1;
    }
    while square_at_most(r + 1, x) {
        r += 1;
    }
    r
}

/// [`isqrt`], out of line: for the set-up work of a frame or a row (lengths, the balls that
/// bound what a row can meet), which shares one copy, while each sphere test keeps its own.
#[inline(never)]
pub(crate) const fn isqrt_once(x: u64) -> u64 {
    isqrt(x)
}

/// Whether `r² ≤ x`: `r²` by a 32 × 32 product, and from `r = 2³²` up it exceeds every `u64`.
#[inline]
const fn square_at_most(r: u64, x: u64) -> bool {
    r >> 32 == 0 && wide_mul_u32(r as u32, r as u32) <= x
}

#[cfg(test)]
mod tests {
    use super::isqrt;

    /// The defining property of the floor square root, in exact 128-bit arithmetic.
    fn is_floor_sqrt(x: u64, r: u64) -> bool {
        let (x, r) = (x as u128, r as u128);
        r * r <= x && x < (r + 1) * (r + 1)
    }

    #[test]
    fn exhaustive_below_two_to_the_twenty_two() {
        for x in 0..(1u64 << 22) {
            assert!(is_floor_sqrt(x, isqrt(x)), "isqrt({x}) = {}", isqrt(x));
        }
    }

    #[test]
    fn random_u64_of_every_size() {
        let mut rng = crate::xorshift::XorShift(0x9e37_79b9_7f4a_7c15);
        for _ in 0..1_000_000 {
            let seed = rng.next();
            let x = seed >> (seed % 64); // every bit length, not only the largest
            assert!(is_floor_sqrt(x, isqrt(x)), "isqrt({x}) = {}", isqrt(x));
        }
    }

    #[test]
    fn around_every_perfect_square_up_to_two_to_the_thirty_two() {
        // Squares and their neighbours are where an off-by-one shows.
        let mut r: u64 = 1;
        while r < (1 << 32) {
            for x in [r * r - 1, r * r, r * r + 1] {
                assert!(is_floor_sqrt(x, isqrt(x)), "isqrt({x})");
            }
            r += 9973;
        }
        let top = u32::MAX as u64;
        for x in [top * top - 1, top * top, u64::MAX] {
            assert!(is_floor_sqrt(x, isqrt(x)), "isqrt({x})");
        }
    }
}
