//! The arithmetic of shading: colours in linear Q16.16 units, and powers for highlights.

use crate::numbers::fx::{self, Fx};
use crate::scene::colour::Rgb;

/// A colour being summed up, one Q16.16 value a channel, 1.0 standing for 255.
pub(crate) type Linear = [Fx; 3];

/// A channel of 0..=255 as 0..=1, rounded to nearest.
///
/// `c · 2¹⁶ / 255 = c · 257 + c/255`, and `c/255` rounds to 1 exactly when `c ≥ 128`, that is
/// `c >> 7`: no division, and no comparison.
#[inline]
pub(crate) const fn channel_to_linear(c: u8) -> Fx {
    Fx::from_bits(c as i32 * 257 + (c >> 7) as i32)
}

/// A summed channel back to 0..=255: times 255, rounded half up, clamped.
#[inline]
pub(crate) const fn linear_to_channel(x: Fx) -> u8 {
    // From 1.0 up everything is 255, and below it the product fits 32 bits.
    let x = x.to_bits();
    if x <= 0 {
        0
    } else if x >= 1 << 16 {
        255
    } else {
        ((x * 255 + 0x8000) >> 16) as u8
    }
}

/// An [`Rgb`] from summed channels. (A surface whose light is the pixel by itself skips the
/// sum: `Scene::matte_pixel`.)
pub(crate) fn rgb_of(c: Linear) -> Rgb {
    Rgb::new(
        linear_to_channel(c[0]),
        linear_to_channel(c[1]),
        linear_to_channel(c[2]),
    )
}

/// `base^exponent` for `0 ≤ base ≤ 1`, by repeated squaring in Q1.31.
///
/// Squaring doubles a relative error, so a power formed in Q16.16 would be off by up to
/// `exponent · 2⁻¹⁷` (1 % for the mirror's 1425). Carried at 31 fractional bits in `u64` the
/// chain's error stays below `exponent · 2⁻³¹`, and the result is rounded once to Q16.16.
///
/// Each product rounds half up a product of non-negative values, which grows with either of
/// them, so the power grows with `base` (never falls): below [`least_lit_base`] it is 0.
#[must_use]
pub(crate) const fn powi(base: Fx, exponent: u16) -> Fx {
    const ONE: u64 = 1 << 31;
    // Both at most 2³¹, so each fits 32 bits and the product 64: the chip's 32 × 32 → 64-bit
    // product (`fx::wide_mul_u32`), not a 64 × 64 one (a library call on the Cortex-M0).
    const fn mul(a: u64, b: u64) -> u64 {
        (fx::wide_mul_u32(a as u32, b as u32) + (1 << 30)) >> 31
    }
    let raw = base.to_bits();
    let clamped = if raw < 0 {
        0
    } else if raw > 1 << 16 {
        1 << 16
    } else {
        raw
    };
    let (mut result, mut square, mut e) = (ONE, (clamped as u64) << 15, exponent);
    while e > 0 {
        if e & 1 == 1 {
            result = mul(result, square);
        }
        e >>= 1;
        if e > 0 {
            square = mul(square, square);
        }
    }
    Fx::from_bits(((result + (1 << 14)) >> 15) as i32)
}

/// The least base, in raw Q16.16 units, whose [`powi`] to `exponent` is not 0: a highlight
/// whose `n·h` lies below it adds nothing, and needs no power taken. Below 2¹⁶ for every
/// exponent up to 4096 (`(1 − 2⁻¹⁶)^4096` is about 0.94), so it fits a `u16`.
///
/// `powi` grows with its base, so a binary search finds it: seventeen powers, once a
/// material.
#[must_use]
pub(crate) const fn least_lit_base(exponent: u16) -> u16 {
    // powi(low) is 0, powi(high) is not: 0 to 0 is 1 only for the exponent 0, which no
    // material has, and 1 to any power is 1.
    let (mut low, mut high) = (0i32, 1i32 << 16);
    if exponent == 0 {
        return 0;
    }
    while high - low > 1 {
        let middle = low + (high - low) / 2;
        if powi(Fx::from_bits(middle), exponent).to_bits() > 0 {
            high = middle;
        } else {
            low = middle;
        }
    }
    if high > u16::MAX as i32 {
        u16::MAX
    } else {
        high as u16
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn channels_convert_as_the_rounded_quotient() {
        for c in 0..=255i32 {
            let exact = (c * 65536 + 127) / 255;
            assert_eq!(channel_to_linear(c as u8).to_bits(), exact, "{c}");
        }
    }

    #[test]
    fn channels_survive_the_round_trip() {
        for c in 0..=255u8 {
            assert_eq!(linear_to_channel(channel_to_linear(c)), c);
        }
        assert_eq!(linear_to_channel(Fx::from_num(-0.5)), 0);
        assert_eq!(linear_to_channel(Fx::from_num(7)), 255);
    }

    #[test]
    fn powers_by_squaring() {
        let half = Fx::from_num(0.5);
        assert_eq!(powi(half, 0), Fx::ONE);
        assert_eq!(powi(half, 1), half);
        assert_eq!(powi(half, 10), Fx::from_num(1.0 / 1024.0));
        assert_eq!(powi(Fx::ONE, 4096), Fx::ONE);
        // The quantised 0.99 to the 50th, and 0.999 to the 1425th: within a unit of 2⁻¹⁶.
        for (b, n) in [(0.99, 50u16), (0.999, 1425), (0.5, 3)] {
            let base = Fx::from_num(b);
            let p = powi(base, n).to_num::<f64>();
            let exact = (0..n).fold(1.0, |acc, _| acc * base.to_num::<f64>());
            assert!(
                (p - exact).abs() <= 1.0 / 65536.0,
                "{b}^{n}: {p} vs {exact}"
            );
        }
    }

    #[test]
    fn below_the_least_lit_base_every_power_is_zero_and_from_it_none_is() {
        // Every base, for exponents across the range: the threshold splits them exactly.
        for n in [1u16, 2, 3, 7, 10, 50, 125, 1000, 1425, 4096] {
            let least = least_lit_base(n) as i32;
            for raw in 0..=1i32 << 16 {
                let lit = powi(Fx::from_bits(raw), n) > Fx::ZERO;
                assert_eq!(lit, raw >= least, "{raw} to the {n}: least {least}");
            }
        }
        // Every exponent, at the threshold and one unit below it.
        for n in 1..=4096u16 {
            let least = least_lit_base(n) as i32;
            assert!(powi(Fx::from_bits(least), n) > Fx::ZERO, "{n}");
            assert_eq!(powi(Fx::from_bits(least - 1), n), Fx::ZERO, "{n}");
        }
        // The highlights of the classic scene's materials start near the cosines
        // 2^(−17/n) suggests.
        assert_eq!(least_lit_base(1), 1);
        let cosine = |n: u16| least_lit_base(n) as f64 / 65536.0;
        for n in [10u16, 50, 125, 1425] {
            let estimate = 2f64.powf(-17.0 / f64::from(n));
            assert!((cosine(n) - estimate).abs() < 0.01, "{n}: {}", cosine(n));
        }
    }
}
