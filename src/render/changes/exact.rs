//! Exact integer vectors for the damage's set-up: points and offsets in raw Q16.16 units
//! (2⁻¹⁶) held in `i64`, their products in `i128`, square roots bounded from below and
//! from above, and quotients by 64-bit divisions. Nothing rounds but the roots and the
//! quotients, and each says which way, or by how much.
//!
//! Every offset the damage forms lies within ±2⁴⁴ raw: two points of the overflow-safe
//! range are at most 2²⁸ raw apart, and a corner of a shadow at most 64 times as far from
//! its light as a vertex of the octagon around the caster, below 2³⁸ (see `shadow.rs`). A
//! dot product of such an offset with one of the camera's cross products (below 2⁴⁹ a
//! component) is then below 2⁹⁶: far inside `i128`.

use crate::numbers::isqrt::isqrt;
use crate::numbers::vec3::Vec3;

/// Three raw Q16.16 components, exactly.
pub(super) type W3 = [i64; 3];

/// `v`'s raw components.
pub(super) fn raw(v: Vec3) -> W3 {
    [
        v.x.to_bits().into(),
        v.y.to_bits().into(),
        v.z.to_bits().into(),
    ]
}

pub(super) fn sub(a: W3, b: W3) -> W3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(super) fn add(a: W3, b: W3) -> W3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `a · b` exactly, in the product of the two's units.
pub(super) fn dot(a: [i128; 3], b: [i128; 3]) -> i128 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `a` widened, for [`dot`] and [`cross`].
pub(super) fn wide(a: W3) -> [i128; 3] {
    [a[0].into(), a[1].into(), a[2].into()]
}

/// `a × b` exactly, in the product of the two's units.
pub(super) fn cross(a: [i128; 3], b: [i128; 3]) -> [i128; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `|a|²` exactly.
pub(super) fn square(a: [i128; 3]) -> u128 {
    a.iter().map(|c| c.unsigned_abs() * c.unsigned_abs()).sum()
}

/// `⌊√x⌋`, or less: a lower bound of the root. Below 2⁶⁴ it is exact; above, the root of
/// `x` shifted down by `2k` bits, shifted up by `k`, which only loses the low bits.
pub(super) fn root_below(x: u128) -> u128 {
    let k = (128 - x.leading_zeros()).saturating_sub(64).div_ceil(2);
    u128::from(isqrt((x >> (2 * k)) as u64)) << k
}

/// An upper bound of `√x`: with `s = ⌊√(x / 4ᵏ)⌋`, `x < 4ᵏ·(⌊x / 4ᵏ⌋ + 1) ≤ 4ᵏ·(s + 1)²`.
pub(super) fn root_above(x: u128) -> u128 {
    let k = (128 - x.leading_zeros()).saturating_sub(64).div_ceil(2);
    (u128::from(isqrt((x >> (2 * k)) as u64)) + 1) << k
}

/// `n / d` for `d > 0`, within 3 of it, or `None` when its magnitude may reach 2³⁰: a
/// 64-bit division in place of a 128-bit one (a long library call on every chip here).
///
/// Both are shifted down by `s` bits, so that `d' = ⌊d / 2ˢ⌋` has 32 bits (or `s = 0` and
/// the division is exact); with `n' = ⌊n / 2ˢ⌋` and `q = n' / d'`,
/// `|n'/d' − n/d| ≤ (|q| + 2) / d'`, below 2 while `|n'|` is below 2⁶² (then `|q|` is below
/// 2³¹), and the floor adds 1.
pub(super) fn quotient(n: i128, d: i128) -> Option<i64> {
    let s = (128 - d.leading_zeros()).saturating_sub(32);
    let (n, d) = (n >> s, d >> s);
    if n.unsigned_abs() >= 1 << 62 || d <= 0 {
        return None;
    }
    Some((n as i64).div_euclid(d as i64))
}

/// `n / d` for `d > 0` and `0 ≤ n < 2⁸·d`, in Q32 (below 2⁴⁰), within `(n/d + 2) · 2⁻²³`
/// of it; `None` where `n` is out of that range. A 64-bit division in place of a 128-bit
/// one.
///
/// Both are shifted down by `s` bits, so that `d' = ⌊d / 2ˢ⌋` has 24 bits (or `s = 0`, and
/// only the last floor rounds); with `n' = ⌊n / 2ˢ⌋`, `n'/d'` lies within
/// `(n/d + 1) · 2⁻²³` of `n/d`, and `n'` below 2³² (as `n'/d'` is below 2⁸), so
/// `⌊n' · 2³² / d'⌋` is a 64-bit quotient, 2⁻³² more at most.
pub(super) fn fraction(n: i128, d: i128) -> Option<u64> {
    if n < 0 || d <= 0 {
        return None;
    }
    let s = (128 - d.leading_zeros()).saturating_sub(24);
    let (n, d) = ((n >> s) as u128, (d >> s) as u128);
    if n >= 1 << 32 || n >= d << 8 {
        return None;
    }
    Some(((n as u64) << 32) / d as u64)
}

/// `⌈a / b⌉` for `b > 0`, `a ≥ 0`.
pub(super) fn ceil_div(a: u128, b: u128) -> u128 {
    a.div_ceil(b.max(1))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quotients_are_within_three_of_the_exact_ones() {
        let mut x: u128 = 7;
        let mut next = |bits: u32| {
            x = x
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (x >> 1) as i128 >> (127 - bits)
        };
        let mut made = 0;
        for step in 0..20_000u32 {
            let d = next(1 + step % 100).abs().max(1);
            let n = next(step % 126);
            let exact = n.div_euclid(d);
            match quotient(n, d) {
                Some(q) => {
                    assert!((i128::from(q) - exact).abs() <= 3, "{n} / {d}: {q} {exact}");
                    made += 1;
                }
                None => assert!(exact.abs() >= (1 << 30) - 1, "{n} / {d}: {exact}"),
            }
        }
        assert!(made > 10_000);
    }

    #[test]
    fn fractions_are_within_their_bound() {
        let mut x: u128 = 11;
        let mut next = |bits: u32| {
            x = x
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            ((x >> 1) as i128 >> (127 - bits)).abs()
        };
        let mut made = 0;
        for step in 0..20_000u32 {
            let d = next(1 + step % 100).max(1);
            let n = next(step % 110);
            let exact = n as f64 / d as f64;
            match fraction(n, d) {
                Some(t) => {
                    let t = t as f64 / 2f64.powi(32);
                    assert!(
                        (t - exact).abs() <= (exact + 2.0) / 2f64.powi(23),
                        "{n} / {d}: {t}"
                    );
                    made += 1;
                }
                None => assert!(exact >= 255.0 || exact >= (1u64 << 32) as f64, "{n} / {d}"),
            }
        }
        assert!(made > 1_000, "{made}");
    }

    #[test]
    fn roots_bound_the_exact_root_from_both_sides() {
        let mut x: u128 = 1;
        for step in 0..4000u128 {
            x = x.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(step) >> (step % 120);
            let (low, high) = (root_below(x), root_above(x));
            assert!(low * low <= x, "{x}");
            assert!(high.checked_mul(high).is_none_or(|h| h > x), "{x}");
            // Tight to a relative 2⁻³¹ or better.
            assert!(high - low <= (low >> 31) + 2, "{x}: {low} {high}");
        }
        assert_eq!(root_below(u128::MAX), (1 << 64) - (1 << 32));
        assert_eq!(root_below(99), 9);
        assert_eq!(root_above(99), 10);
    }
}
