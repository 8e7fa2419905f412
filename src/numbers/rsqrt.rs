//! The reciprocal square root that normalises vectors without a division.
//!
//! Normalising divides three components by a length. A 64-bit division is a long library
//! call on every chip fixray targets (Cortex-M0 has no divide instruction at all), so
//! [`rsqrt`] finds `1/√s` by table and Newton steps in 32-bit fixed point instead, and a
//! vector is normalised with three multiplications.

use crate::numbers::fx::{bit_length, top_word, wide_mul_u32};
/// `1/√μ` for `μ = (64 + i + ½)/256`, `i` in 0..192, in Q2.14: the seed of the Newton steps.
///
/// Built at compile time from an integer square root, so there is no float anywhere.
const SEEDS: [u16; 192] = {
    let mut seeds = [0u16; 192];
    let mut i = 0;
    while i < 192 {
        // 1/√((2i + 129)/512) = √(512/(2i + 129)); in Q2.14: √(512 · 2²⁸ / (2i + 129)).
        let ratio = (512u64 << 28) / (2 * i as u64 + 129);
        seeds[i] = ratio.isqrt() as u16;
        i += 1;
    }
    seeds
};

/// `1/√s` for `s ≥ 1`, as `(y, shift)` with `1/√s ≈ y · 2^−(30 + shift)`.
///
/// `s` is scaled by an even power of two into `μ ∈ [¼, 1)` in Q0.32, a 192-entry table gives
/// `1/√μ` to about 0.4 %, and two Newton steps `y ← y·(3 − μ·y²)/2` bring it to about 2⁻²⁸
/// relative. `y` lies in `(2³⁰, 2³¹)`. Every product is 32 × 32 → 64 bits.
#[must_use]
pub(crate) fn rsqrt(s: u64) -> (u32, u32) {
    // 0 has no reciprocal root, and no bit for the table to be indexed by.
    debug_assert!(s >= 1, "rsqrt: zero argument");
    // s < 2^p with p even, and s ≥ 2^(p−2).
    let bits = bit_length(s);
    let p = (bits + 1) & !1;
    let m = top_word(s, p);
    let seed = SEEDS[((m >> 24) - 64) as usize] as u32;
    let mut y = seed << 16; // Q2.30
    for _ in 0..2 {
        let y2 = (wide_mul_u32(y, y) >> 30) as u32; // Q2.30, ≤ 4.1 · 2³⁰ fits
        let my2 = (wide_mul_u32(m, y2) >> 32) as u32; // μ·y², near 1 in Q2.30
        let factor = (3u32 << 30).wrapping_sub(my2); // 3 − μ·y², near 2, in Q2.30
        y = (wide_mul_u32(y, factor) >> 31) as u32;
    }
    (y.min(i32::MAX as u32), p / 2)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn relative_error(s: u64) -> f64 {
        let (y, shift) = rsqrt(s);
        let got = y as f64 / 2f64.powi(30 + shift as i32);
        let exact = 1.0 / (s as f64).sqrt();
        (got / exact - 1.0).abs()
    }

    #[test]
    fn seeds_are_close_to_the_inverse_root() {
        for (i, &seed) in SEEDS.iter().enumerate() {
            let mu = (64.0 + i as f64 + 0.5) / 256.0;
            let exact = (1.0 / mu.sqrt()) * 16384.0;
            assert!((seed as f64 - exact).abs() <= 1.0, "{i}: {seed} vs {exact}");
        }
    }

    #[test]
    fn accurate_to_two_to_the_minus_27_everywhere() {
        let mut s: u64 = 1;
        let mut worst: f64 = 0.0;
        // Every power of two and many values between, up to the top of u64.
        while s < u64::MAX / 3 {
            for x in [s, s + s / 3, s + s / 2, s + s / 7 * 5, 2 * s - 1] {
                worst = worst.max(relative_error(x));
            }
            s *= 2;
        }
        worst = worst.max(relative_error(u64::MAX));
        assert!(worst < 2f64.powi(-27), "worst relative error {worst:e}");
    }
}
