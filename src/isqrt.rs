//! The exact integer square root, kept in one place so that it can be swapped by measurement.

/// `floor(sqrt(x))` for every `u64`, exactly.
///
/// fixray takes square roots of Q32.32 values: `isqrt(v · 2³²) = floor(sqrt(v) · 2¹⁶)`, which is
/// the Q16.16 square root of `v`, truncated. The implementation is core's `u64::isqrt`, which
/// needs no floating point and no table.
///
/// ```
/// assert_eq!(fixray::isqrt(0), 0);
/// assert_eq!(fixray::isqrt(15), 3);
/// assert_eq!(fixray::isqrt(16), 4);
/// assert_eq!(fixray::isqrt(u64::MAX), u32::MAX as u64);
/// ```
#[inline]
#[must_use]
pub const fn isqrt(x: u64) -> u64 {
    x.isqrt()
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
