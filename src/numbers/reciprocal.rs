//! Reciprocals without a division: `1/√s` to normalise vectors, and `1/d` to divide.
//!
//! A 64-bit division is a long library call on every chip fixray targets (the Cortex-M0 has no
//! divide instruction at all). Both reciprocals here start from a small table built at compile
//! time from integers. [`rsqrt_unit`] interpolates its table quadratically, to about 2⁻²⁰ in
//! 32-bit products, which is all a unit vector needs (normalising then takes three
//! multiplications); [`rsqrt`] adds one Newton step in 32 × 32 → 64-bit products, to 2⁻²⁹,
//! for the integer square root. [`Mantissa::over`] divides Eq. 4.2's numerator by its
//! denominator with a linearly interpolated seed and one Newton step, as a [`Scale`] of 29
//! bits and more.

use crate::numbers::fx::{self, bit_length, top_word, wide_mul_u32};

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
/// cut to 16 bits, times that fraction fits 32 bits. An `x` below the table (not reached: the
/// callers' `x` is a mantissa with its top bit set) takes its first knot, not a panic.
#[inline]
const fn between_knots(knots: &[u32], first: u32, x: u32) -> u32 {
    let j = (x >> 24).saturating_sub(first) as usize;
    let fraction = (x >> 8) & 0xffff;
    if j + 1 >= knots.len() {
        return knots[0];
    }
    let (below, above) = (knots[j], knots[j + 1]);
    below - ((((below - above) >> 8) * fraction) >> 8)
}

// The reciprocal square root.
/// `1/√μ` at the knots `μ = (64 + j)/256`, `j` in 0..=193 (the last past 1, for the
/// quadratic through the last interval's three knots), in Q2.30 (the first, 2, held one unit
/// below 2³¹ so that a seed always lies below it), interpolated by [`rsqrt_unit`].
///
/// Built at compile time from an integer square root, so there is no float anywhere.
const RSQRT_KNOTS: [u32; 194] = {
    let mut knots = [0u32; 194];
    let mut j = 0;
    while j < 194 {
        // 1/√((64 + j)/256) in Q2.30: 2³⁴/√(64 + j) = √(2⁶⁸ / (64 + j)).
        knots[j] = knot(((1u128 << 68) / (64 + j as u128)).isqrt());
        j += 1;
    }
    knots
};

/// [`RSQRT_KNOTS`] indexed by a mantissa's top byte itself (64 to 255, and the two knots past
/// the last), the first 64 entries unused: where the byte indexes the table directly, no
/// index needs checking against its length (a mantissa's top byte is at most 255), for 256
/// bytes of flash.
const RSQRT_BY_BYTE: [u32; 258] = {
    let mut knots = [0u32; 258];
    let mut j = 0;
    while j < 194 {
        knots[64 + j] = RSQRT_KNOTS[j];
        j += 1;
    }
    knots
};

/// The three knots from the one below a mantissa whose top byte is `byte` (64 to 255).
const fn knots_from(byte: usize) -> (u32, u32, u32) {
    let t = &RSQRT_BY_BYTE;
    (t[byte], t[byte + 1], t[byte + 2])
}

/// `1/√s` for `s ≥ 1`, as `(y, shift)` with `1/√s ≈ y · 2^−(30 + shift)`, to about 2⁻²⁰:
/// what a unit vector needs (`Vec3::normalize_with_square`), whose components it leaves
/// within a tenth of a unit of 2⁻¹⁶ of the exact quotient before rounding.
///
/// `s` is scaled by an even power of two into `μ ∈ [¼, 1)`, a 32-bit mantissa `m` in Q0.32,
/// and `1/√μ` is interpolated quadratically between three knots of a table of 194, in 32-bit
/// products: no Newton step. `y` lies in `(2³⁰, 2³¹)`.
#[must_use]
pub(crate) const fn rsqrt_unit(s: u64) -> (u32, u32) {
    let (y, half, _) = rsqrt_unit_and_mantissa(s);
    (y, half)
}

/// [`rsqrt_unit`], in line wherever it is called, and the mantissa `m` it looked up (`s`'s
/// top 32 bits at an even bit length, `μ` in Q0.32): for the few callers that take a root a
/// pixel with many values live (a light's direction, the sphere test's integer root, whose
/// estimate multiplies the root by that mantissa), where a call would move those values out
/// of the registers it clobbers. A floor's columns take it through [`rsqrt_unit_near`].
// In line: a light's direction at each lit pixel and a sphere test's root take it, where a
// call would move their values out of the registers it clobbers.
#[inline(always)]
#[must_use]
pub(crate) const fn rsqrt_unit_and_mantissa(s: u64) -> (u32, u32, u32) {
    // 0 has no reciprocal root, and no bit for the table to be indexed by.
    debug_assert!(s >= 1, "rsqrt: zero argument");
    // μ = m · 2⁻³², s scaled by 2^(32 − p) with p even and s ≥ 2^(p−2); half = p / 2.
    let (m, half) = fx::even_top_word(s);
    (interpolated(m), half, m)
}

/// [`rsqrt_unit_and_mantissa`] for one of a run of arguments that mostly share their even bit
/// length, which `length` keeps from one to the next ([`EvenLength`]): the same values.
// In line: a floor's cosine at each column of a lit stretch takes it, where a call would
// move the loop's values out of the registers it clobbers.
#[inline(always)]
#[must_use]
pub(crate) fn rsqrt_unit_near(s: u64, length: &mut EvenLength) -> (u32, u32) {
    debug_assert!(s >= 1, "rsqrt: zero argument");
    let (m, half) = length.even_top_word(s);
    (interpolated(m), half)
}

/// `1/√μ` in Q2.30 for `μ = m · 2⁻³²` in `[¼, 1)`: the table's quadratic interpolation.
pub(super) const fn interpolated(m: u32) -> u32 {
    // Knot j below μ, and t, the next 16 bits, the way to knot j + 1 in units of 2⁻¹⁶.
    let t = (m >> 8) & 0xffff;
    let (k0, k1, k2) = knots_from((m >> 24) as usize);
    let linear = k0 - ((((k0 - k1) >> 8) * t) >> 8);
    // The second difference, below 2¹⁹ (1/√μ is convex), times t(1 − t)/2, below 2¹³: the
    // product fits 32 bits. The sums may wrap on the way, and come back exactly.
    let bend = k0.wrapping_add(k2).wrapping_sub(k1.wrapping_mul(2));
    linear.wrapping_sub((((t * (65536 - t)) >> 17) * bend) >> 16)
}

/// The even bit length `p` of the last of a run of reciprocal roots' arguments, where it is 34
/// to 62, with the shifts that take the mantissa of an argument of that length: a floor's
/// squared distances to a light, column after column, mostly share it. An argument `s` has it
/// exactly when its high word lies in `[2^(p−34), 2^(p−32))`, one comparison, and its mantissa
/// `s >> (p − 32)` is then two shifts of its words: where the chip counts no leading zeros,
/// that is far shorter than finding the length afresh. The bounds and shifts are kept beside
/// the half length rather than derived from it, so that a column whose square has the kept
/// length takes no arithmetic for them.
#[derive(Clone, Copy)]
pub(crate) struct EvenLength {
    /// `2^(p−34)` and `3·2^(p−34)`: `high − base < span` holds for the length's high words.
    base: u32,
    span: u32,
    /// `64 − p` and `p − 32`, each 2 to 30.
    up: u32,
    down: u32,
    half: u32,
}

impl EvenLength {
    /// No length kept: the first argument finds its own.
    pub(crate) const NONE: EvenLength = EvenLength {
        base: 0,
        span: 0,
        up: 0,
        down: 0,
        half: 0,
    };

    /// [`fx::even_top_word`]`(x)` for `x ≥ 1`, through the kept length where `x` has it, and
    /// keeping `x`'s otherwise.
    pub(crate) fn even_top_word(&mut self, x: u64) -> (u32, u32) {
        // Where the leading zeros are one instruction, finding the length is shorter than
        // keeping it.
        if !fx::NO_CLZ {
            return fx::even_top_word(x);
        }
        self.kept_or_found(x)
    }

    /// [`EvenLength::even_top_word`] through the kept length, whatever the chip: compiled
    /// everywhere, so that the host tests check it.
    pub(super) fn kept_or_found(&mut self, x: u64) -> (u32, u32) {
        let (high, low) = ((x >> 32) as u32, x as u32);
        if high.wrapping_sub(self.base) < self.span {
            return ((high << self.up) | (low >> self.down), self.half);
        }
        let (top, half) = fx::even_top_word(x);
        if (17..=31).contains(&half) {
            let p = 2 * half;
            *self = EvenLength {
                base: 1 << (p - 34),
                span: 3 << (p - 34),
                up: 64 - p,
                down: p - 32,
                half,
            };
        }
        (top, half)
    }
}

/// `1/√s` for `s ≥ 1`, as [`rsqrt_unit`], to about 2⁻²⁹: its seed and one Newton step
/// `y ← y·(3 − μ·y²)/2`, whose three products are 32 × 32 → 64 bits. For the integer square
/// root, whose estimate it corrects by whole steps.
#[must_use]
pub(crate) const fn rsqrt(s: u64) -> (u32, u32) {
    let (mut y, half) = rsqrt_unit(s);
    let m = top_word(s, 2 * half); // μ in Q0.32, as the seed had it
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
        half,
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
        self.times(inverse(den))
    }

    /// [`Mantissa::over`] given the divisor's [`inverse`]: several dividends over one divisor
    /// share it.
    #[inline]
    pub(crate) fn times(self, (y, den_bits): (u32, u32)) -> Scale {
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

    /// The kept even length gives `even_top_word`'s mantissa and half length for every
    /// argument, kept or not: at both sides of every even length's ends (where a length kept
    /// one too wide or too narrow, or a shift one off, shows), and along runs of random
    /// arguments of nearby sizes, as a floor's squares come.
    #[test]
    fn a_kept_even_length_finds_the_mantissa_the_length_gives() {
        let mut rng = crate::xorshift::XorShift(0x9e37_79b9_7f4a_7c15);
        let mut length = EvenLength::NONE;
        let check = |x: u64, length: &mut EvenLength| {
            assert_eq!(length.kept_or_found(x), fx::even_top_word(x), "{x:#x}");
        };
        for p in (2..=64).step_by(2) {
            let (low, high) = (
                1u64 << (p - 2),
                if p == 64 { u64::MAX } else { (1 << p) - 1 },
            );
            for x in [low, low + 1, high - 1, high, high / 3 + 1] {
                // From this length, from the next narrower and wider, and from none.
                for before in [
                    Some(x),
                    Some((x >> 2).max(1)),
                    Some(x.saturating_mul(4)),
                    None,
                ] {
                    match before {
                        Some(before) => check(before, &mut length),
                        None => length = EvenLength::NONE,
                    }
                    check(x, &mut length);
                    check(low - 1 + (low == 1) as u64, &mut length);
                    check(high.saturating_add(1), &mut length);
                }
            }
        }
        for _ in 0..20_000 {
            let bits = 1 + rng.next() % 64;
            let x = (rng.next() >> (64 - bits)).max(1);
            for step in [1u64, 1 << 20, 1 << 40] {
                for k in 0..8 {
                    check(x.saturating_add(k * step), &mut length);
                }
            }
        }
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
    fn the_knots_by_byte_are_the_knots() {
        // Both ways to the knots, the Cortex-M0's and the others', for every top byte a
        // mantissa of `μ ∈ [¼, 1)` has.
        for byte in 64..256 {
            let j = byte - 64;
            let knots = (RSQRT_KNOTS[j], RSQRT_KNOTS[j + 1], RSQRT_KNOTS[j + 2]);
            let by_byte = (
                RSQRT_BY_BYTE[byte],
                RSQRT_BY_BYTE[byte + 1],
                RSQRT_BY_BYTE[byte + 2],
            );
            assert_eq!(by_byte, knots, "top byte {byte}");
            assert_eq!(knots_from(byte), knots, "top byte {byte}");
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
    fn the_seed_alone_is_accurate_to_two_to_the_minus_20() {
        // Every knot's interval on a fine grid, each mantissa at several scales (the even
        // powers of two it is scaled by), and random arguments across the whole range.
        let error = |s: u64| {
            let (y, shift) = rsqrt_unit(s);
            // The in-line form gives the same root, and its mantissa is `s`'s top word at the
            // root's bit length.
            assert_eq!(
                rsqrt_unit_and_mantissa(s),
                (y, shift, top_word(s, 2 * shift)),
                "{s}"
            );
            let got = y as f64 / 2f64.powi(30 + shift as i32);
            (got * (s as f64).sqrt() - 1.0).abs()
        };
        let mut worst: f64 = 0.0;
        for m in ((1u64 << 30)..(1 << 32)).step_by(4099) {
            for scale in [0, 2, 30, 62] {
                let s = m << scale >> 30;
                if s > 0 {
                    worst = worst.max(error(s));
                }
            }
            worst = worst.max(error(m));
        }
        let mut rng = crate::xorshift::XorShift(0x2bad_5eed_0f1e_e7ed);
        for _ in 0..200_000 {
            let s = rng.next() >> (rng.next() % 64);
            worst = worst.max(error(s.max(1)));
        }
        assert!(worst < 2f64.powi(-20), "worst relative error {worst:e}");
        // The seed's error is the whole of it: a step of Newton's brings it below 2⁻²⁹.
        assert!(worst > 2f64.powi(-22), "worst relative error {worst:e}");
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
