//! The exact integer square root, kept in one place so that it can be swapped by measurement.

use crate::numbers::fx::{top_word, wide_mul_u32};
use crate::numbers::reciprocal::{rsqrt, rsqrt_unit_and_mantissa};

/// `floor(sqrt(x))` for every `u64`, exactly.
///
/// fixray takes square roots of Q32.32 values: `isqrt(v · 2³²) = floor(sqrt(v) · 2¹⁶)`, which is
/// the Q16.16 square root of `v`, truncated.
///
/// The estimate is `x · (1/√x)` from the table-seeded reciprocal square root that normalises
/// vectors (to 2⁻²⁰·⁶, within 4 of the root below 2⁴⁴), with a Newton step from 2⁴⁴ up (good
/// to about 2⁻²⁸), then corrected by whole steps until `r² ≤ x < (r + 1)²` holds: a few steps
/// or none for the values the renderer meets, at most a few dozen anywhere. How it compares
/// with core's `u64::isqrt` is measured in docs/PERFORMANCE.md.
///
/// ```
/// assert_eq!(fixray::internals::isqrt(0), 0);
/// assert_eq!(fixray::internals::isqrt(15), 3);
/// assert_eq!(fixray::internals::isqrt(16), 4);
/// assert_eq!(fixray::internals::isqrt(u64::MAX), u32::MAX as u64);
/// ```
// In line, so that a sphere test takes its root below 2⁴⁴ without a call, which would move
// the test's values out of the registers it clobbers; the rest is out of line.
#[inline(always)]
#[must_use]
pub const fn isqrt(x: u64) -> u64 {
    if x < 2 {
        return x;
    }
    // Below 2⁴⁴, where every sphere test's root lies, in 32-bit words.
    if x < 1 << 44 {
        return root_below_two_to_the_44(x) as u64;
    }
    isqrt_from_two_to_the_44(x)
}

/// [`isqrt`] for `x ≥ 2⁴⁴`: the estimate's Newton step, then whole steps.
// Out of line: the Newton step, which no sphere test needs, stays out of every `isqrt` taken
// in line.
#[inline(never)]
const fn isqrt_from_two_to_the_44(x: u64) -> u64 {
    // The root is below 2³², and so, once clamped there, is the estimate.
    let estimate = estimate(x);
    let mut r = if estimate > u32::MAX as u64 {
        u32::MAX
    } else {
        estimate as u32
    };
    // The whole steps go by the residual `x − r²`: `(r + 1)² ≤ x` is `x − r² > 2r`, and a
    // step moves it by `2r + 1`. The estimate is within 8 of the root, so the residual is
    // far inside an `i64`. At `r = 2³² − 1` the residual is at most `2r`, so `r` never steps
    // past it.
    debug_assert!(
        r.abs_diff(x.isqrt() as u32) <= 1 << 8,
        "isqrt: the estimate is far from the root"
    );
    let mut residual = x.wrapping_sub(wide_mul_u32(r, r)) as i64;
    while residual < 0 {
        r -= 1; // r² > x ≥ 2: r is at least 2
        residual += 2 * r as i64 + 1; // (r + 1)² − r²
    }
    while residual > 2 * r as i64 {
        residual -= 2 * r as i64 + 1;
        r += 1;
    }
    r as u64
}

/// [`isqrt`] for `2 ≤ x < 2⁴⁴`: its estimate, below 2²² and within 4 of the root, and its
/// whole steps in 32-bit words: the residual `x − r²` lies within ±2³¹ (within about ±2²⁶ for
/// the estimate's 4), so taken modulo 2³² it is exact.
// In line in `isqrt`'s in-line part, with `root_and_mantissa`: the sphere test's root,
// taken without a call.
#[inline(always)]
const fn root_below_two_to_the_44(x: u64) -> u32 {
    let mut r = estimate(x) as u32;
    debug_assert!(
        x >= 2 && x < 1 << 44 && r.abs_diff(x.isqrt() as u32) <= 1 << 8,
        "root_below_two_to_the_44: x out of range, or the estimate far from the root"
    );
    let mut residual = (x as u32).wrapping_sub(r.wrapping_mul(r)) as i32;
    while residual < 0 {
        r -= 1; // r² > x ≥ 2: r is at least 2
        residual += (2 * r + 1) as i32; // (r + 1)² − r²
    }
    while residual > (2 * r) as i32 {
        residual -= (2 * r + 1) as i32;
        r += 1;
    }
    r
}

/// `1/√x` as `(y, half)` (see `rsqrt`) and `x`'s top 32 bits at the bit length `2·half`, for
/// [`estimate`]: below 2⁴⁴ the table's seed alone (2⁻²⁰·⁶ of it) leaves the estimate within 4
/// of the root, a few whole steps, where the Newton step would cost three 64-bit products;
/// the sphere tests' roots are there. The seed is taken in line with the mantissa it looked up
/// (`rsqrt_unit_and_mantissa`): a call would move the sphere test's values out of the registers it
/// clobbers, and the mantissa need not be found again (on the Cortex-M0 and RV32, which have
/// no count-leading-zeros instruction, a second bit length).
// In line, as the sphere test's root is: a call would move the test's values out of the
// registers it clobbers.
#[inline(always)]
const fn root_and_mantissa(x: u64) -> (u32, u32, u32) {
    if x < 1 << 44 {
        return rsqrt_unit_and_mantissa(x);
    }
    let (y, half) = rsqrt(x);
    (y, half, top_word(x, 2 * half))
}

/// `√x` for `x ≥ 2`, to within 4 below 2⁴⁴ and 8 above (the tests find 2 and 3): [`isqrt`]'s
/// start.
#[inline]
const fn estimate(x: u64) -> u64 {
    // 1/√x ≈ y · 2^−(30 + half), with x < 2^(2·half).
    // √x = x · (1/√x). With m the top 32 bits of x, x ≈ m · 2^(2·half − 32), so
    // √x ≈ m · y · 2^(half − 62).
    let (y, half, m) = root_and_mantissa(x);
    let product = wide_mul_u32(m, y);
    if half <= 30 {
        // A shift of 32 or more, of the high word alone: no 64-bit shift by a variable
        // amount, a library call on the Cortex-M0. Every x below 2⁶⁰ is here.
        ((product >> 32) as u32 >> (30 - half)) as u64
    } else {
        product >> (62 - half)
    }
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
    fn the_estimate_is_within_four_of_the_root_below_two_to_the_44() {
        // The correction steps make the root exact whatever the estimate; its accuracy is what
        // keeps them few. Every bit length, each end of it, and random values between.
        let mut rng = crate::xorshift::XorShift(0x2545_f491_4f6c_dd1d);
        let (mut worst_low, mut worst_high) = (0u64, 0u64);
        for bits in 2..64 {
            let (low, high) = (1u64 << (bits - 1), (1u64 << bits) - 1);
            let random = (0..20_000).map(|_| low | (rng.next() & (high >> 1)));
            for x in [low, high].into_iter().chain(random) {
                let off = super::estimate(x).abs_diff(x.isqrt());
                if x < 1 << 44 {
                    worst_low = worst_low.max(off);
                } else {
                    worst_high = worst_high.max(off);
                }
            }
        }
        assert!(worst_low <= 4, "{worst_low} steps below 2⁴⁴");
        assert!(worst_high <= 8, "{worst_high} steps from 2⁴⁴ up");
    }

    #[test]
    fn every_neighbour_of_a_square_below_and_about_two_to_the_44() {
        // Below 2⁴⁴ the whole steps go by a residual from the low words alone: every root up
        // to 2²² at both ends of its interval, `r²` and `r² + 2r`, and their neighbours, where
        // a step taken one short or one too far shows; then both sides of 2⁴⁴ itself.
        let check = |x: u64| {
            let r = isqrt(x);
            assert!(is_floor_sqrt(x, r), "isqrt({x}) = {r}");
        };
        for r in 1u64..=1 << 22 {
            for x in [r * r - 1, r * r, r * r + 2 * r, r * r + 2 * r + 1] {
                check(x);
            }
        }
        for x in ((1u64 << 44) - 1000)..((1 << 44) + 1000) {
            check(x);
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
