//! Reciprocals without a division: `1/√s` to normalise vectors, and `1/d` to divide.
//!
//! A 64-bit division is a long library call on every chip fixray targets (the Cortex-M0 has no
//! divide instruction at all). Both reciprocals here start from a small table built at compile
//! time from integers and take two Newton steps in 32 × 32 → 64-bit products: [`rsqrt`]
//! normalises a vector with three multiplications, and [`div_q16`] divides Eq. 4.2's numerator
//! by its denominator with one.

use crate::numbers::fx::{bit_length, top_word, wide_mul_u32};

// The reciprocal square root.
/// `1/√μ` for `μ = (64 + i + ½)/256`, `i` in 0..192, in Q2.14: the seed of the Newton steps.
///
/// Built at compile time from an integer square root, so there is no float anywhere.
const RSQRT_SEEDS: [u16; 192] = {
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
pub(crate) const fn rsqrt(s: u64) -> (u32, u32) {
    // 0 has no reciprocal root, and no bit for the table to be indexed by.
    debug_assert!(s >= 1, "rsqrt: zero argument");
    // s < 2^p with p even, and s ≥ 2^(p−2).
    let bits = bit_length(s);
    let p = (bits + 1) & !1;
    let m = top_word(s, p);
    let seed = RSQRT_SEEDS[((m >> 24) - 64) as usize] as u32;
    let mut y = seed << 16; // Q2.30
    let mut step = 0;
    while step < 2 {
        step += 1;
        let y2 = (wide_mul_u32(y, y) >> 30) as u32; // Q2.30, ≤ 4.1 · 2³⁰ fits
        let my2 = (wide_mul_u32(m, y2) >> 32) as u32; // μ·y², near 1 in Q2.30
        let factor = (3u32 << 30).wrapping_sub(my2); // 3 − μ·y², near 2, in Q2.30
        y = (wide_mul_u32(y, factor) >> 31) as u32;
    }
    (
        if y > i32::MAX as u32 {
            i32::MAX as u32
        } else {
            y
        },
        p / 2,
    )
}

// Division by a reciprocal.
/// `1/δ` for `δ = (128 + i + ½)/256`, `i` in 0..128, in Q1.15: the seed of the Newton steps.
const RECIPROCAL_SEEDS: [u16; 128] = {
    let mut seeds = [0u16; 128];
    let mut i = 0;
    while i < 128 {
        // 1/((2i + 257)/512) in Q1.15, rounded.
        seeds[i] = (((512u64 << 15) + (2 * i as u64 + 257) / 2) / (2 * i as u64 + 257)) as u16;
        i += 1;
    }
    seeds
};

/// `num · 2¹⁶ / den` for `den > 0` and a quotient below 2³² (`num < den · 2¹⁶`), within one unit plus 2⁻²⁷ of the exact quotient
/// (a distance of 8192 is off by at most 5 units of 2⁻¹⁶, a distance of 10 by at most one).
///
/// `den` is scaled into `δ ∈ [½, 1)` in Q0.32, a table gives `1/δ` to about 0.4 %, two
/// Newton steps `y ← y·(2 − δ·y)` bring it to about 2⁻²⁸ (the steps truncate), and `num`'s
/// top 32 bits are multiplied by it. Every product is 32 × 32 → 64 bits. A 64-bit division is a long library call on every chip fixray targets.
#[must_use]
pub(crate) fn div_q16(num: u64, den: u64) -> u32 {
    // A quotient of 2³² or more would not fit, and its shift below would go negative.
    debug_assert!(den > 0, "div_q16: zero divisor");
    debug_assert!(
        (num as u128) < (den as u128) << 16,
        "div_q16: the quotient does not fit 32 bits"
    );
    if num == 0 {
        return 0;
    }
    let den_bits = bit_length(den); // den < 2^den_bits
    let d = top_word(den, den_bits);
    let mut y = (RECIPROCAL_SEEDS[((d >> 24) - 128) as usize] as u32) << 15; // 1/δ in Q2.30
    for _ in 0..2 {
        let dy = (wide_mul_u32(d, y) >> 32) as u32; // δ·y, near 1, in Q2.30
        let factor = (2u32 << 30).wrapping_sub(dy); // 2 − δ·y, near 1, in Q2.30
        y = (wide_mul_u32(y, factor) >> 30) as u32;
    }
    // num ≈ n · 2^k with n its top 32 bits.
    let num_bits = bit_length(num);
    let k = num_bits.saturating_sub(32);
    let n = top_word(num, num_bits.max(32));
    // num·2¹⁶/den = n · 2^k · 2¹⁶ · y · 2⁻³⁰ / 2^den_bits
    let shift = 14 + den_bits - k;
    let q = wide_mul_u32(n, y);
    if shift >= 64 {
        return 0;
    }
    if shift >= 33 {
        // `fx::mul_shift_round`'s high-word rounding, unsigned: q < 2⁶³ may reach 2³¹ in its
        // high word, which the signed step would overflow; the sum fits a u32.
        return (((q >> 32) as u32) + (1 << (shift - 33))) >> (shift - 32);
    }
    ((q + (1 << (shift - 1))) >> shift) as u32
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
        for (i, &seed) in RSQRT_SEEDS.iter().enumerate() {
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

    #[test]
    fn within_a_unit_and_two_to_the_minus_27_of_the_exact_quotient() {
        let mut rng = crate::xorshift::XorShift(0x2545_f491_4f6c_dd1d);
        let mut next = || rng.next();
        for _ in 0..1_000_000 {
            let den = (next() >> (next() % 60)).max(1);
            // A quotient of up to 2²⁹ (t up to 8192 in Q16.16).
            let num = (((next() as u128 % (1u128 << 29)) * den as u128) >> 16) as u64;
            let exact = (num as f64) * 65536.0 / den as f64;
            let got = div_q16(num, den) as f64;
            let bound = 1.0 + exact / 2f64.powi(27);
            assert!(
                (got - exact).abs() <= bound,
                "{num} / {den}: {got} vs {exact}"
            );
        }
        assert_eq!(div_q16(3 << 32, 1 << 32), 3 << 16);
        assert_eq!(div_q16(0, 5), 0);
    }
}
