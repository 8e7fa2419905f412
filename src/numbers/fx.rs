//! The one scalar of the renderer: [`Fx`], a Q16.16 fixed-point number, and the widening
//! arithmetic that keeps products exact.
//!
//! A Q16.16 value is an `i32` counting units of 2⁻¹⁶ (about 1.5 × 10⁻⁵), so it spans
//! −32 768 ≤ x < 32 768. Multiplying two of them directly would need 48 bits before the
//! result is scaled back, so every product here widens to `i64` first ("Q32.32"), and dot
//! products add their three terms at that width before a single rounding.

/// The renderer's scalar: a signed Q16.16 fixed-point number.
pub type Fx = fixed::types::I16F16;

/// The largest magnitude a coordinate, a radius or a light position may have.
///
/// Keeping inputs within ±1024 and hits within [`FAR`] leaves every intermediate of the
/// render path (differences, squared lengths, dot products) inside its integer type with room
/// to spare; see the crate docs for the budget.
pub const LIMIT: Fx = Fx::const_from_int(1024);

/// The far clip: hits farther along a ray than this are misses.
///
/// It bounds hit points to ±(1024 + 8192), so that they, and the vectors from them to a light,
/// stay well inside Q16.16.
pub const FAR: Fx = Fx::const_from_int(8192);

/// The farthest a hit point lies from the origin along any axis, in raw units: `LIMIT + FAR`
/// (the overflow budget of the crate's docs), where a secondary ray may start.
pub(crate) const HIT_REACH: i32 = LIMIT.to_bits() + FAR.to_bits();

/// Number of fractional bits in [`Fx`].
pub(crate) const FRAC: u32 = 16;

pub(crate) use crate::chip::{HIGH_WORD_QUOTIENT, NO_CLZ, NO_DIVIDE, NO_LONG_MULTIPLY};
use crate::numbers::split::{
    split_mul, split_mul_fits, split_mul_high, split_mul_u32, split_mul_unit,
};

/// The product of two Q16.16 raw values, exact, as a Q32.32 raw value.
#[inline]
#[must_use]
pub(crate) const fn wide_mul(a: i32, b: i32) -> i64 {
    if NO_LONG_MULTIPLY {
        split_mul(a, b)
    } else {
        a as i64 * b as i64
    }
}

/// `a · b` for unsigned 32-bit values, exact in 64 bits, by the cheapest means the chip has
/// (see [`wide_mul`]).
#[inline]
#[must_use]
pub(crate) const fn wide_mul_u32(a: u32, b: u32) -> u64 {
    if NO_LONG_MULTIPLY {
        split_mul_u32(a, b)
    } else {
        a as u64 * b as u64
    }
}

/// `(a · b) / 2^shift` rounded half up, for `1 ≤ shift ≤ 63`: the scaling step of
/// normalisation and of the sphere's normal, exact.
///
/// Render-path shifts are 33 or more, and then only the product's high word matters:
/// `2^(shift−1)` is a whole multiple of 2³², so adding it and dropping `shift` bits gives the
/// same as taking the high word, adding `2^(shift−33)` and dropping `shift − 32` bits — 32-bit
/// operations where a 64-bit shift by a variable amount is a library call on Cortex-M0.
#[inline]
#[must_use]
pub(crate) const fn mul_shift_round(a: i32, b: i32, shift: u32) -> i64 {
    // The one product whose high word is 2³⁰ is i32::MIN², and a shift of 63 rounds with 2³⁰:
    // that sum alone would not fit. Callers multiply by a positive reciprocal (below 2³¹).
    debug_assert!(
        shift >= 1 && shift <= 63,
        "mul_shift_round: shift outside 1..=63"
    );
    debug_assert!(
        !(shift == 63 && a == i32::MIN && b == i32::MIN),
        "mul_shift_round: i32::MIN² shifted by 63"
    );
    if shift >= 33 {
        // |high| ≤ 2³⁰, and so is the rounding term; both reach it only in the case above.
        let high = if NO_LONG_MULTIPLY {
            split_mul_high(a, b)
        } else {
            (wide_mul(a, b) >> 32) as i32
        };
        shift_round_high(high, shift)
    } else {
        shift_round(wide_mul(a, b), shift)
    }
}

/// [`shift_round`] from a shift of 33 up, given the product's high word `high` alone (see
/// [`mul_shift_round`]): `|high| ≤ 2³⁰`, and so is the rounding term.
#[inline]
const fn shift_round_high(high: i32, shift: u32) -> i64 {
    ((high + (1 << (shift - 33))) >> (shift - 32)) as i64
}

/// `(product + 2^(shift−1)) >> shift`, rounded half up, for `1 ≤ shift ≤ 63` and
/// `|product| ≤ 2⁶²`, short of `2⁶²` itself shifted by 63 (so that the sum fits): a product of
/// two `i32`s, or less.
#[inline]
#[must_use]
pub(crate) const fn shift_round(product: i64, shift: u32) -> i64 {
    debug_assert!(
        shift >= 1 && shift <= 63,
        "shift_round: shift outside 1..=63"
    );
    debug_assert!(
        product.unsigned_abs() <= 1 << 62 && !(shift == 63 && product == 1 << 62),
        "shift_round: the rounded sum does not fit"
    );
    if !WORD_SHIFTS {
        (product + (1 << (shift - 1))) >> shift
    } else if shift >= 33 {
        shift_round_high((product >> 32) as i32, shift)
    } else {
        shift_round_words(product, shift)
    }
}

use crate::chip::WORD_SHIFTS;

/// [`shift_round`] for `1 ≤ shift ≤ 32`, in 32-bit words: the rounding term is below 2³², so
/// it adds to the low word with a carry into the high word, which holds the sum. Compiled
/// everywhere, so the host tests check it.
#[inline]
const fn shift_round_words(product: i64, shift: u32) -> i64 {
    debug_assert!(
        shift >= 1 && shift <= 32,
        "shift_round_words: shift outside 1..=32"
    );
    let (low, carry) = (product as u32).overflowing_add(1 << (shift - 1));
    let high = ((product >> 32) as i32).wrapping_add(carry as i32);
    if shift == 32 {
        high as i64
    } else {
        let low = (high << (32 - shift)) as u32 | low >> shift;
        (((high >> shift) as i64) << 32) | low as i64
    }
}

/// `x >> k` for `k ≤ 32` where the caller knows the result fits 32 bits (`x < 2^(32 + k)`),
/// with 32-bit shifts only.
#[inline]
#[must_use]
const fn shr_to_u32(x: u64, k: u32) -> u32 {
    debug_assert!(k <= 32, "shr_to_u32: shift above 32");
    debug_assert!(
        x >> k <= u32::MAX as u64,
        "shr_to_u32: the result does not fit 32 bits"
    );
    let (high, low) = ((x >> 32) as u32, x as u32);
    if k == 0 {
        low
    } else if k >= 32 {
        high >> (k - 32)
    } else {
        (high << (32 - k)) | (low >> k)
    }
}

/// `x · 2^(32 − p)`, truncated, for `x < 2^p` and `1 ≤ p ≤ 64`: `x` moved so that its bit
/// `p − 1` lands on bit 31. The leading 32 bits of a value whose bit length is at most `p`,
/// as the reciprocal seeds of `rsqrt`, `isqrt` and division want them, with 32-bit shifts only.
#[inline]
#[must_use]
pub(crate) const fn top_word(x: u64, p: u32) -> u32 {
    debug_assert!(p >= 1 && p <= 64, "top_word: bit length outside 1..=64");
    debug_assert!(p == 64 || x >> p == 0, "top_word: x has more than p bits");
    if p >= 32 {
        shr_to_u32(x, p - 32)
    } else {
        (x as u32) << (32 - p)
    }
}

/// `(top_word(x, p), p / 2)` for `x ≥ 1` and `p` its bit length rounded up to even
/// (`2^(p−2) ≤ x < 2^p`): the mantissa of a reciprocal square root's argument, and half its
/// exponent.
///
/// Found from the word that holds the leading bit: its `n` leading zeros (of 64) move `x`'s
/// leading bit to the top of the word, and one more shift down where `n` is odd makes the
/// length even. Two cases, against `top_word`'s three after the bit length.
#[inline]
#[must_use]
pub(crate) const fn even_top_word(x: u64) -> (u32, u32) {
    debug_assert!(x >= 1, "even_top_word: zero");
    let (high, low) = ((x >> 32) as u32, x as u32);
    let (top, n) = if high != 0 {
        let n = leading_zeros_u32(high);
        // `low >> (32 − n)` in two shifts, each below 32 for every n in 0..=31.
        ((high << n) | ((low >> 1) >> (31 - n)), n)
    } else {
        let n = leading_zeros_u32(low);
        (low << n, 32 + n)
    };
    (top >> (n & 1), 32 - (n >> 1))
}

/// `x.leading_zeros()`, from [`bit_length_u32`] where there is no instruction for it.
#[inline]
const fn leading_zeros_u32(x: u32) -> u32 {
    if NO_CLZ {
        32 - bit_length_u32(x)
    } else {
        x.leading_zeros()
    }
}

/// The number of bits `x` needs, `64 − x.leading_zeros()` (0 for 0).
///
/// Cortex-M0 and RV32IMC have no count-leading-zeros instruction, and the library call that
/// stands in for one is long; two comparisons and a 256-entry table are far shorter.
/// Elsewhere it is the instruction.
#[inline]
#[must_use]
pub(crate) const fn bit_length(x: u64) -> u32 {
    if !NO_CLZ {
        return 64 - x.leading_zeros();
    }
    let high = (x >> 32) as u32;
    if high != 0 {
        32 + bit_length_u32(high)
    } else {
        bit_length_u32(x as u32)
    }
}

/// [`bit_length`] of a 32-bit value by halving the range twice and a table for the last
/// eight bits (256 bytes of flash). Compiled everywhere, so the host tests check it.
#[inline]
const fn bit_length_u32(mut x: u32) -> u32 {
    const BYTE: [u8; 256] = {
        let mut table = [0u8; 256];
        let mut i = 1;
        while i < 256 {
            table[i] = (32 - (i as u32).leading_zeros()) as u8;
            i += 1;
        }
        table
    };
    let mut n = 0;
    if x >= 1 << 16 {
        n += 16;
        x >>= 16;
    }
    if x >= 1 << 8 {
        n += 8;
        x >>= 8;
    }
    n + BYTE[x as usize & 0xff] as u32
}

/// A Q32.32 raw value rounded (half up) back to Q16.16, saturating at the ends of the range.
#[inline]
#[must_use]
pub(crate) const fn narrow(wide: i64) -> Fx {
    match narrow_fitting(wide) {
        Some(x) => x,
        // The sign of `wide`, not of the rounded value: the rounding term wraps the largest
        // values (from i64::MAX − 2¹⁵ + 1 up) round to negative ones.
        None if wide < 0 => Fx::MIN,
        None => Fx::MAX,
    }
}

/// [`narrow`] where the rounded value fits Q16.16, `None` where it does not.
///
/// The rounding term is added with wrapping: the only sums that wrap start within 2¹⁵ of
/// `i64::MAX` and land within 2¹⁵ of `i64::MIN`, whose rounded value (about −2⁴⁷) does not
/// fit either, so they come back `None` like every other value out of range. Wrapping costs
/// nothing here, where a saturating add would cost a check on every product.
#[inline]
#[must_use]
pub(crate) const fn narrow_fitting(wide: i64) -> Option<Fx> {
    let rounded = wide.wrapping_add(1 << (FRAC - 1)) >> FRAC;
    let low = rounded as i32;
    // It fits when its high word is the sign extension of the low one: one comparison of
    // 32-bit words, where two 64-bit comparisons would cost several instructions each.
    if (rounded >> 32) as i32 == low >> 31 {
        Some(Fx::from_bits(low))
    } else {
        None
    }
}

/// `a * b` in Q16.16 with the product formed at 64 bits and rounded once.
#[inline]
#[must_use]
pub const fn mul(a: Fx, b: Fx) -> Fx {
    narrow(wide_mul(a.to_bits(), b.to_bits()))
}

/// `a · b` rounded to nearest, for a product known to fit: `0 ≤ b ≤ 1` (raw `b ≤ 2¹⁶`), so
/// `|a · b| ≤ |a|`. Shading's colour channels and highlight powers are such factors by
/// construction. It skips [`mul`]'s saturation check, which costs about as much as the
/// product itself.
#[inline]
#[must_use]
pub(crate) const fn mul_fits(a: Fx, b: Fx) -> Fx {
    // With 0 ≤ b ≤ 1 the rounded product lies between 0 and a. A negative b could not hold
    // that: i32::MIN · −1 does not fit.
    debug_assert!(
        b.to_bits() >= 0 && b.to_bits() <= 1 << FRAC,
        "mul_fits: factor outside 0..=1"
    );
    let (a, b) = (a.to_bits(), b.to_bits());
    Fx::from_bits(if NO_LONG_MULTIPLY {
        split_mul_fits(a, b)
    } else {
        ((a as i64 * b as i64 + (1 << (FRAC - 1))) >> FRAC) as i32
    })
}

/// `t · u` rounded to nearest, for a distance `t` and `u` a component of a unit vector.
///
/// Hit distances lie within [`FAR`] (and distances along rays within a few times it), and
/// a unit vector's components within 1 plus its rounding, far inside the bounds
/// `|t| < 2¹⁴`, `|u| < 2` within which the product fits without a saturation check. Every
/// [`Ray`](crate::Ray)'s direction is normalised by its constructor and every distance
/// comes from the render path's own hit tests, so the bounds hold by construction; debug
/// builds check them.
#[inline]
#[must_use]
pub(crate) const fn mul_unit(t: Fx, u: Fx) -> Fx {
    let (t, u) = (t.to_bits(), u.to_bits());
    debug_assert!(
        t >= -(1 << 30) && t < 1 << 30 && u >= -(1 << 17) && u < 1 << 17,
        "mul_unit: a factor outside its bound"
    );
    // |t · u| < 2⁴⁷: the rounded quotient by 2¹⁶ fits 32 bits.
    Fx::from_bits(if NO_LONG_MULTIPLY {
        split_mul_unit(t, u)
    } else {
        ((t as i64 * u as i64 + (1 << (FRAC - 1))) >> FRAC) as i32
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mul_rounds_to_nearest() {
        // 3 × 2⁻¹⁶ times 0.5 is 1.5 × 2⁻¹⁶, which rounds half up to 2 × 2⁻¹⁶.
        let a = Fx::from_bits(3);
        assert_eq!(mul(a, Fx::from_num(0.5)).to_bits(), 2);
        assert_eq!(mul(Fx::from_num(-2.5), Fx::from_num(4)), Fx::from_num(-10));
    }

    /// A unit component from any raw value: its low 17 bits, signed.
    fn b_sample(a: i32) -> i32 {
        (a << 15) >> 15
    }

    #[test]
    fn split_products_are_exact() {
        let edges = [
            0,
            1,
            -1,
            0xFFFF,
            -0xFFFF,
            0x1_0000,
            -0x1_0000,
            i32::MAX,
            i32::MIN,
        ];
        let mut rng = crate::xorshift::XorShift(0x0123_4567_89ab_cdef);
        let mut values = edges.to_vec();
        for _ in 0..300 {
            let seed = rng.next();
            values.push((seed as i32) >> (seed >> 59)); // every magnitude
        }
        for &a in &values {
            for &b in &values {
                assert_eq!(split_mul(a, b), a as i64 * b as i64, "{a} × {b}");
                let high = ((a as i64 * b as i64) >> 32) as i32;
                assert_eq!(split_mul_high(a, b), high, "{a} × {b}");
                let (ua, ub) = (a as u32, b as u32);
                assert_eq!(split_mul_u32(ua, ub), ua as u64 * ub as u64, "{ua} × {ub}");
            }
            // Distances and unit components within `mul_unit`'s bounds.
            let t = a >> 2;
            for u in [
                0,
                1,
                -1,
                0xffff,
                -0xffff,
                1 << 16,
                -(1 << 16),
                (1 << 17) - 1,
                -(1 << 17),
            ]
            .into_iter()
            .chain([b_sample(a), -b_sample(a)])
            {
                let exact = ((t as i64 * u as i64 + (1 << 15)) >> 16) as i32;
                assert_eq!(split_mul_unit(t, u), exact, "{t} × {u}");
            }
            // Every factor of 0..=1 for the bounded product: the rounded 64-bit one.
            for b in (0..=1 << 16).step_by(7).chain([0xffff, 0x8000, 1 << 16]) {
                let exact = ((a as i64 * b as i64 + (1 << 15)) >> 16) as i32;
                assert_eq!(split_mul_unit(a, b), exact, "{a} × {b}");
            }
        }
    }

    /// `(product + 2^(shift−1)) >> shift` in exact 128-bit arithmetic.
    fn rounded(product: i64, shift: u32) -> i128 {
        (product as i128 + (1i128 << (shift - 1))) >> shift
    }

    #[test]
    fn products_by_a_factor_of_at_most_one_split_as_they_round() {
        let mut rng = crate::xorshift::XorShift(0xd1b5_4a32_d192_ed03);
        let ends = [
            i32::MIN,
            -65537,
            -65536,
            -1,
            0,
            1,
            32767,
            65535,
            65536,
            65537,
            i32::MAX,
        ];
        let factors = [0, 1, 32767, 32768, 32769, 65535, 65536];
        let random = (0..100_000).map(|i| {
            let a = (rng.next() as i64 >> (32 + i % 32)) as i32;
            (a, (rng.next() % 65537) as i32)
        });
        let pairs = ends.iter().flat_map(|&a| factors.map(|b| (a, b)));
        for (a, b) in pairs.chain(random) {
            let exact = ((a as i64 * b as i64 + (1 << 15)) >> 16) as i32;
            assert_eq!(split_mul_fits(a, b), exact, "{a} × {b}");
        }
    }

    #[test]
    fn the_even_top_word_is_the_top_word_at_the_even_bit_length() {
        // Every bit length, odd and even, each end of it, and random values between; with the
        // leading bit in either word and at every place in it.
        let mut rng = crate::xorshift::XorShift(0x2545_f491_4f6c_dd1d);
        for bits in 1..=64u32 {
            let (low, high) = (1u64 << (bits - 1), u64::MAX >> (64 - bits));
            let random = (0..2_000).map(|_| low | (rng.next() & (high >> 1)));
            for x in [low, high, low + 1].into_iter().chain(random) {
                // The plain reading: x·2^(32 − p), truncated, in 128 bits.
                let p = bits + (bits & 1);
                let plain = ((x as u128) << 64 >> (32 + p)) as u32;
                assert_eq!(even_top_word(x), (plain, p / 2), "{x:#x}");
                assert_eq!(top_word(x, p), plain, "{x:#x}");
            }
        }
    }

    #[test]
    fn bit_lengths_and_shifts_agree_with_the_plain_operations() {
        let mut rng = crate::xorshift::XorShift(0x9e37_79b9_7f4a_7c15);
        for i in 0..20_000u32 {
            let seed = rng.next();
            let x = seed >> (i % 64);
            assert_eq!(bit_length(x), 64 - x.leading_zeros(), "{x}");
            assert_eq!(bit_length_u32(x as u32), 32 - (x as u32).leading_zeros());
            let k = i % 33;
            let fits = x & (u64::MAX >> (32 - k));
            assert_eq!(shr_to_u32(fits, k), (fits >> k) as u32, "{fits} >> {k}");
            let (a, b, shift) = (seed as i32, (seed >> 32) as i32, 1 + i % 63);
            let product = a as i64 * b as i64;
            let exact = rounded(product, shift);
            assert_eq!(
                mul_shift_round(a, b, shift) as i128,
                exact,
                "{a} × {b} >> {shift}"
            );
            assert_eq!(
                shift_round(product, shift) as i128,
                exact,
                "{product} >> {shift}"
            );
            let words = 1 + i % 32;
            let exact = rounded(product, words);
            assert_eq!(
                shift_round_words(product, words) as i128,
                exact,
                "{product} >> {words}"
            );
        }
        assert_eq!(bit_length(0), 0);
        assert_eq!(bit_length(u64::MAX), 64);
        let ends = [i32::MIN, i32::MIN + 1, -65536, -1, 0, 1, 65535, i32::MAX];
        for (a, b, shift) in (ends.iter().flat_map(|&a| ends.map(|b| (a, b))))
            .flat_map(|(a, b)| (1..=32).map(move |shift| (a, b, shift)))
        {
            let product = a as i64 * b as i64;
            let exact = rounded(product, shift);
            assert_eq!(
                shift_round_words(product, shift) as i128,
                exact,
                "{a} × {b} >> {shift}"
            );
        }
    }

    #[test]
    fn bounded_products_equal_the_saturating_one_within_their_bounds() {
        let mut rng = crate::xorshift::XorShift(0x5851_f42d_4c95_7f2d);
        for _ in 0..20_000 {
            let seed = rng.next();
            let a = Fx::from_bits((seed as i32) >> 2); // |a| < 2¹³
            let u = Fx::from_bits(((seed >> 32) as i32) >> 15); // |u| ≤ 1
            assert_eq!(mul_fits(a, u.abs()), mul(a, u.abs()));
            assert_eq!(mul_unit(a, u), mul(a, u));
        }
        // At the corners of the bounds the product still fits.
        let (t, u) = (Fx::from_bits((1 << 30) - 1), Fx::from_bits((1 << 17) - 1));
        assert_eq!(mul_unit(t, u), mul(t, u));
        assert_eq!(mul_unit(-t, u), mul(-t, u));
        assert_eq!(
            mul_unit(Fx::from_bits(-(1 << 30)), -u),
            mul(Fx::from_bits(-(1 << 30)), -u)
        );
    }

    #[test]
    #[cfg(debug_assertions)]
    #[should_panic(expected = "mul_unit: a factor outside its bound")]
    fn a_product_outside_the_bounds_is_caught_in_debug_builds() {
        let _ = mul_unit(Fx::MAX, Fx::ONE);
    }

    #[test]
    fn mul_saturates_instead_of_wrapping() {
        assert_eq!(mul(Fx::from_num(200), Fx::from_num(200)), Fx::MAX);
        assert_eq!(mul(Fx::from_num(-200), Fx::from_num(200)), Fx::MIN);
        assert_eq!(mul(Fx::MAX, Fx::MAX), Fx::MAX);
        assert_eq!(mul(Fx::MIN, Fx::MIN), Fx::MAX);
        assert_eq!(mul(Fx::MIN, Fx::MAX), Fx::MIN);
        assert_eq!(mul(Fx::MIN, -Fx::ONE), Fx::MAX);
    }

    #[test]
    fn narrow_saturates_at_both_ends_of_i64() {
        // The rounding term would carry these past i64::MAX.
        for wide in [i64::MAX, i64::MAX - (1 << 15) + 1, i64::MAX - (1 << 15)] {
            assert_eq!(narrow(wide), Fx::MAX, "{wide}");
        }
        for wide in [i64::MIN, i64::MIN + 1, -(1 << 48)] {
            assert_eq!(narrow(wide), Fx::MIN, "{wide}");
        }
        // The last values that round into range, and the first that do not.
        let top = (i32::MAX as i64) << 16;
        assert_eq!(narrow(top + (1 << 15) - 1), Fx::MAX);
        assert_eq!(narrow(top + (1 << 15)), Fx::MAX);
        assert_eq!(narrow_fitting(top + (1 << 15)), None);
        assert_eq!(narrow_fitting(top + (1 << 15) - 1), Some(Fx::MAX));
        let bottom = (i32::MIN as i64) << 16;
        assert_eq!(narrow_fitting(bottom - (1 << 15)), Some(Fx::MIN));
        assert_eq!(narrow_fitting(bottom - (1 << 15) - 1), None);
        assert_eq!(narrow(bottom - (1 << 15) - 1), Fx::MIN);
        // Everywhere else, the rounded quotient, exactly.
        let mut rng = crate::xorshift::XorShift(0x1234_5678_9abc_def1);
        for i in 0..20_000u32 {
            let wide = (rng.next() as i64) >> (i % 64);
            let exact = (wide as i128 + (1 << 15)) >> 16;
            let want = exact.clamp(i32::MIN as i128, i32::MAX as i128) as i32;
            assert_eq!(narrow(wide).to_bits(), want, "{wide}");
        }
    }
}
