//! Reciprocals without a division: `1/√s` to normalise vectors, and `1/d` to divide.
//!
//! A 64-bit division is a long library call on every chip fixray targets (the Cortex-M0 has no
//! divide instruction at all). Both reciprocals here start from a small table built at compile
//! time from integers, interpolated, and take one Newton step in 32 × 32 → 64-bit products:
//! [`rsqrt`] normalises a vector with three multiplications, and [`Mantissa::over`] divides
//! Eq. 4.2's numerator by its denominator with one more, as a [`Scale`] of 29 bits and more.

use crate::numbers::fx::{bit_length, top_word, wide_mul_u32};

/// A knot of a table in Q2.30, held below 2³¹ (the tables' first knots are 2), so that an
/// interpolated seed and its square stay within their 32-bit words.
const fn knot(value: u128) -> u32 {
    if value > i32::MAX as u128 {
        i32::MAX as u32
    } else {
        value as u32
    }
}

/// The seed of a Newton step for `x` in Q0.32, whose top byte is at least `first`: linear
/// interpolation between `knots[j]` and `knots[j + 1]`, for the knot `j` below `x` and the next
/// 16 bits of `x` past it. The knots fall by less than 2²⁴ from one to the next, so the step,
/// cut to 16 bits, times that fraction fits 32 bits.
#[inline]
const fn between_knots(knots: &[u32], first: u32, x: u32) -> u32 {
    let j = ((x >> 24) - first) as usize;
    let fraction = (x >> 8) & 0xffff;
    let (below, above) = (knots[j], knots[j + 1]);
    below - ((((below - above) >> 8) * fraction) >> 8)
}

// The reciprocal square root.
/// `1/√μ` at the knots `μ = (64 + j)/256`, `j` in 0..=192, in Q2.30 (the first, 2, held one
/// unit below 2³¹ so that a seed always lies below it): the seed of the Newton step,
/// interpolated between knots.
///
/// Built at compile time from an integer square root, so there is no float anywhere.
const RSQRT_KNOTS: [u32; 193] = {
    let mut knots = [0u32; 193];
    let mut j = 0;
    while j < 193 {
        // 1/√((64 + j)/256) in Q2.30: 2³⁴/√(64 + j) = √(2⁶⁸ / (64 + j)).
        knots[j] = knot(((1u128 << 68) / (64 + j as u128)).isqrt());
        j += 1;
    }
    knots
};

/// `1/√s` for `s ≥ 1`, as `(y, shift)` with `1/√s ≈ y · 2^−(30 + shift)`.
///
/// `s` is scaled by an even power of two into `μ ∈ [¼, 1)` in Q0.32; linear interpolation
/// between the 193 knots of a table gives `1/√μ` to about 2⁻¹⁵ relative, in 32-bit
/// arithmetic, and one Newton step `y ← y·(3 − μ·y²)/2` brings it to about 2⁻²⁹. `y` lies
/// in `(2³⁰, 2³¹)`. The Newton step's three products are 32 × 32 → 64 bits.
#[must_use]
pub(crate) const fn rsqrt(s: u64) -> (u32, u32) {
    // 0 has no reciprocal root, and no bit for the table to be indexed by.
    debug_assert!(s >= 1, "rsqrt: zero argument");
    // s < 2^p with p even, and s ≥ 2^(p−2).
    let bits = bit_length(s);
    let p = (bits + 1) & !1;
    let m = top_word(s, p);
    let mut y = between_knots(&RSQRT_KNOTS, 64, m); // Q2.30
    let y2 = (wide_mul_u32(y, y) >> 30) as u32; // Q2.30, below 4 · 2³⁰
    let my2 = (wide_mul_u32(m, y2) >> 32) as u32; // μ·y², near 1 in Q2.30
    let factor = (3u32 << 30).wrapping_sub(my2); // 3 − μ·y², near 2, in Q2.30
    y = (wide_mul_u32(y, factor) >> 31) as u32;
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
/// `1/δ` at the knots `δ = (128 + j)/256`, `j` in 0..=128, in Q2.30, rounded (the first, 2,
/// held one unit below 2³¹): the seed of the Newton step, interpolated between knots.
const RECIPROCAL_KNOTS: [u32; 129] = {
    let mut knots = [0u32; 129];
    let mut j = 0;
    while j < 129 {
        // 1/((128 + j)/256) in Q2.30: 2³⁸ / (128 + j).
        let d = 128 + j as u128;
        knots[j] = knot(((1u128 << 38) + d / 2) / d);
        j += 1;
    }
    knots
};

/// `1/den` for `den > 0`, as `(y, bits)` with `den < 2^bits` and `2^bits/den ≈ y · 2⁻³⁰`:
/// `den` is scaled into `δ ∈ [½, 1)`, and `y ∈ [2³⁰, 2³¹]` is `1/δ` in Q2.30 to about 2⁻²⁹.
/// Newton's step for a reciprocal approaches it from below, but the step's truncated product
/// `δ·y` can leave `y` up to 3 units above it (a test holds it below 4).
// Out of line: a division and the bound on FAR share it, in every loop that meets planes.
#[inline(never)]
pub(crate) fn inverse(den: u64) -> (u32, u32) {
    let den_bits = bit_length(den); // den < 2^den_bits
    let d = top_word(den, den_bits);
    let y = between_knots(&RECIPROCAL_KNOTS, 128, d); // 1/δ in Q2.30
    let dy = (wide_mul_u32(d, y) >> 32) as u32; // δ·y, near 1, in Q2.30
    let factor = (2u32 << 30).wrapping_sub(dy); // 2 − δ·y, near 1, in Q2.30
    ((wide_mul_u32(y, factor) >> 30) as u32, den_bits)
}

/// A positive number `m · 2^−shift` with `m` in `[2²⁹, 2³¹)`: 29 bits and more of a quotient,
/// whatever its size, for products with 32-bit values (a ray's direction, in
/// `plane.rs`). `shift` may be negative, for quotients of 2³¹ and more.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Scale {
    pub(crate) m: i32,
    pub(crate) shift: i32,
}

/// A positive dividend split into its top 32 bits, `top` in `[2³¹, 2³²)`, and its bit length
/// `bits`: it is `top · 2^(bits − 32)`, exactly when it has 32 bits or fewer, to a relative
/// 2⁻³¹ otherwise. Made once, divided by many.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Mantissa {
    top: u32,
    bits: u32,
}

impl Mantissa {
    /// Zero, which no division takes.
    pub(crate) const ZERO: Mantissa = Mantissa { top: 0, bits: 0 };

    /// `num`, which must not be 0.
    #[inline]
    pub(crate) const fn new(num: u64) -> Self {
        debug_assert!(num > 0, "Mantissa::new: zero");
        let bits = bit_length(num);
        Mantissa {
            top: top_word(num, bits),
            bits,
        }
    }

    /// `self / den` for `den > 0`, to a relative 2⁻²⁷ (its test's bound): `top · 2^(bits − 32)` times the
    /// reciprocal `y · 2^(−30 − den_bits)`, whose product `q` lies in `[2⁶¹, 2⁶³)`, of which
    /// `m` keeps the high word: `m · 2^(bits − 30 − den_bits)`.
    #[inline]
    pub(crate) fn over(self, den: u64) -> Scale {
        debug_assert!(den > 0, "Mantissa::over: zero divisor");
        let (y, den_bits) = inverse(den);
        let q = wide_mul_u32(self.top, y);
        Scale {
            m: (q >> 32) as i32,
            shift: 30 + den_bits as i32 - self.bits as i32,
        }
    }
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
    fn knots_are_the_inverse_root() {
        for (j, &knot) in RSQRT_KNOTS.iter().enumerate() {
            let mu = (64.0 + j as f64) / 256.0;
            let exact = (1.0 / mu.sqrt()) * 2f64.powi(30);
            assert!((knot as f64 - exact).abs() <= 1.0, "{j}: {knot} vs {exact}");
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
    fn accurate_to_two_to_the_minus_29_between_the_knots() {
        // Every 32-bit mantissa the table can be indexed by is equally likely here, and the
        // ends of the range are taken whole.
        let mut rng = crate::xorshift::XorShift(0x1405_7b7e_f767_814f);
        let mut worst: f64 = 0.0;
        for _ in 0..1_000_000 {
            worst = worst.max(relative_error((rng.next() >> 32).max(1 << 30)));
        }
        for x in (1u64 << 30..(1 << 30) + 4096).chain((1 << 32) - 4096..1 << 32) {
            worst = worst.max(relative_error(x));
        }
        assert!(worst < 2f64.powi(-29), "worst relative error {worst:e}");
    }

    #[test]
    fn inverse_is_less_than_four_units_above_the_exact_one() {
        let mut rng = crate::xorshift::XorShift(0x1234_5678_9abc_def1);
        let mut worst = f64::MIN;
        let mut check = |den: u64| {
            let (y, bits) = inverse(den);
            let exact = 2f64.powi(bits as i32 + 30) / den as f64;
            worst = worst.max(y as f64 - exact);
        };
        for _ in 0..1_000_000 {
            check((rng.next() >> (rng.next() % 34)).max(1));
        }
        // The scales of `plane.rs` are m in [2²⁹, 2³¹): both ends, densely.
        for den in ((1u64 << 29)..(1 << 29) + 50_000).chain((1 << 31) - 50_000..1 << 31) {
            check(den);
        }
        assert!(worst < 4.0, "y exceeds 2^(bits + 30)/den by {worst}");
        assert!(
            worst > 0.0,
            "the bound is not tight: the test checks nothing"
        );
    }

    #[test]
    fn a_scale_is_within_two_to_the_minus_27_of_the_exact_quotient() {
        let mut rng = crate::xorshift::XorShift(0x2545_f491_4f6c_dd1d);
        let mut next = || rng.next();
        let mut worst: f64 = 0.0;
        for _ in 0..1_000_000 {
            let num = (next() >> (next() % 64)).max(1);
            let den = (next() >> (next() % 64)).max(1);
            let Scale { m, shift } = Mantissa::new(num).over(den);
            assert!((1 << 29..=i32::MAX).contains(&m), "{num} / {den}: m = {m}");
            let got = m as f64 * 2f64.powi(-shift);
            let exact = num as f64 / den as f64;
            worst = worst.max((got / exact - 1.0).abs());
        }
        assert!(worst < 2f64.powi(-27), "worst relative error {worst:e}");
        assert_eq!(
            Mantissa::new(3 << 40).over(1 << 40),
            Scale {
                m: 3 << 29,
                shift: 29
            }
        );
    }
}
