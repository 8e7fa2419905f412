//! Products in 16-bit halves, for ARMv6-M (Cortex-M0/M0+), which multiplies 32 × 32 → 32 bits
//! only: there the compiler's 64-bit product is a call to a full 64 × 64 multiply, and these
//! exact forms, built from 32-bit products, are shorter. Each gives the same value as the
//! plain product it replaces (`fx::wide_mul`, `Vec3::dot_exact`, `Vec3::length_squared_wide`,
//! ...), which is chosen where [`NO_LONG_MULTIPLY`](crate::chip::NO_LONG_MULTIPLY) says so.
//! They are compiled on every chip, so the host's tests check them against the plain forms,
//! and forcing the family (`fixray_chip="armv6m"`) runs the whole renderer through them.

use crate::numbers::fx::{FRAC, Fx};
use crate::numbers::vec3::Vec3;

/// [`wide_mul`] where there is [`NO_LONG_MULTIPLY`]: four 16-bit partial products are exact
/// in 32 bits (`|a_hi · b_lo| < 2³¹`, since `|a_hi| ≤ 2¹⁵` and `b_lo < 2¹⁶`). Compiled
/// everywhere, so the host tests check it.
pub(crate) const fn split_mul(a: i32, b: i32) -> i64 {
    let (a_lo, a_hi) = (a & 0xFFFF, a >> 16);
    let (b_lo, b_hi) = (b & 0xFFFF, b >> 16);
    let low = (a_lo as u32 * b_lo as u32) as i64;
    let middle = (a_hi * b_lo) as i64 + (a_lo * b_hi) as i64;
    (((a_hi * b_hi) as i64) << 32) + (middle << 16) + low
}

/// [`wide_mul_u32`] by four 16-bit partial products; see [`split_mul`].
pub(crate) const fn split_mul_u32(a: u32, b: u32) -> u64 {
    let (a_lo, a_hi) = (a & 0xFFFF, a >> 16);
    let (b_lo, b_hi) = (b & 0xFFFF, b >> 16);
    let middle = (a_hi * b_lo) as u64 + (a_lo * b_hi) as u64;
    (((a_hi * b_hi) as u64) << 32) + (middle << 16) + (a_lo * b_lo) as u64
}

/// `⌊a · b / 2³²⌋`, the high word of [`split_mul`]'s product, in 32-bit operations: with the
/// middle products `m = m_hi·2¹⁶ + m_lo` split again, the sum below the high word,
/// `m1_lo + m2_lo + ⌊lo/2¹⁶⌋`, is below 3·2¹⁶, and only its carry reaches the high word. On
/// the Cortex-M0 the 64-bit shift and sums of the whole product are most of its cost.
/// Compiled everywhere, so the host tests check it.
pub(crate) const fn split_mul_high(a: i32, b: i32) -> i32 {
    let (a_lo, a_hi) = (a & 0xFFFF, a >> 16);
    let (b_lo, b_hi) = (b & 0xFFFF, b >> 16);
    // |a_hi|, |b_hi| ≤ 2¹⁵ and the low halves below 2¹⁶: each product fits its type.
    let (m1, m2) = (a_hi * b_lo, a_lo * b_hi);
    let low = (a_lo as u32 * b_lo as u32) >> 16;
    let carry = ((m1 & 0xFFFF) as u32 + (m2 & 0xFFFF) as u32 + low) >> 16;
    a_hi * b_hi + (m1 >> 16) + (m2 >> 16) + carry as i32
}

/// [`mul_fits`] where there is [`NO_LONG_MULTIPLY`]. The product fits 32 bits, so
/// [`split_mul_unit`]'s sum modulo 2³² is exact; and for `0 ≤ a < 1`, the brightness of a
/// surface lit by one light, `a · b` and the rounding term stay below 2³² − 2¹⁵: one 32-bit
/// product. Compiled everywhere, so the host tests check it.
pub(crate) const fn split_mul_fits(a: i32, b: i32) -> i32 {
    if a >= 0 && a < 1 << FRAC {
        ((a as u32 * b as u32 + (1 << (FRAC - 1))) >> FRAC) as i32
    } else {
        split_mul_unit(a, b)
    }
}

/// `t · u` in two parts of 32-bit products, for a factor `u` below 2¹⁷ in magnitude: with
/// `u = u_hi·2¹⁶ + u_lo` and `t = t_hi·2¹⁶ + t_lo` (`u_lo`, `t_lo` in 0..2¹⁶),
/// `t·u = 2¹⁶·(t·u_hi + t_hi·u_lo) + t_lo·u_lo`. The first part comes modulo 2³² (exact
/// whenever what it goes into fits 32 bits), the second, below 2³², exactly.
pub(crate) const fn split_by_unit(t: i32, u: i32) -> (i32, u32) {
    let (u_hi, u_lo) = (u >> FRAC, (u & 0xffff) as u32);
    let (t_hi, t_lo) = (t >> FRAC, (t & 0xffff) as u32);
    let high = t
        .wrapping_mul(u_hi)
        .wrapping_add(t_hi.wrapping_mul(u_lo as i32));
    (high, t_lo * u_lo)
}

/// `t · u / 2¹⁶` rounded to nearest where a 64-bit product is a long sequence, from
/// [`split_by_unit`]: `t·u_hi + t_hi·u_lo + ⌊(t_lo·u_lo + 2¹⁵)/2¹⁶⌋` (the low sum stays below
/// 2³²). Exact whenever the result fits 32 bits: within `mul_unit`'s bounds (only the corner
/// `t = −2³⁰`, `u = −2¹⁷` would reach 2³¹; no distance or unit vector comes near) and for
/// `mul_fits`. Compiled everywhere, so the host tests check it.
pub(crate) const fn split_mul_unit(t: i32, u: i32) -> i32 {
    let (high, low) = split_by_unit(t, u);
    high.wrapping_add(((low + (1 << (FRAC - 1))) >> FRAC) as i32)
}

/// [`Vec3::length_squared_wide`] where a 64-bit product is a long sequence: with each
/// component `c = h·2¹⁶ + l` (`h` signed, `l` in 0..2¹⁶), `Σ c² = 2³²·Σ h² + 2¹⁷·Σ h·l + Σ l²`,
/// nine 16-bit products and the three sums gathered once, where three whole squares would each
/// be assembled in 64 bits. `Σ h² ≤ 3·2³⁰` fits a `u32`. Compiled everywhere, so the host
/// tests check it.
pub(crate) const fn split_length_squared(v: Vec3) -> u64 {
    let (x, y, z) = (square_parts(v.x), square_parts(v.y), square_parts(v.z));
    let high = x.0 + y.0 + z.0;
    let middle = x.1 + y.1 + z.1;
    let low = x.2 + y.2 + z.2;
    // The sum is below 2⁶⁴, and the middle term may be negative: summed modulo 2⁶⁴, exactly.
    ((high as u64) << 32)
        .wrapping_add((middle << 17) as u64)
        .wrapping_add(low)
}

/// `c = h·2¹⁶ + l`'s `h²`, `h·l` and `l²`, each exact in 32 bits (`|h| ≤ 2¹⁵`, `l < 2¹⁶`):
/// [`split_length_squared`]'s terms.
pub(crate) const fn square_parts(c: Fx) -> (u32, i64, u64) {
    let c = c.to_bits();
    let (h, l) = (c >> 16, c & 0xFFFF);
    ((h * h) as u32, (h * l) as i64, (l as u32 * l as u32) as u64)
}

/// [`Vec3::dot_exact`] of raw values where a 64-bit product is a long sequence: each product
/// of a unit component in two parts ([`fx::split_by_unit`]), `Σ u·v + 2¹⁵ = 2¹⁶·Σ high +
/// Σ low + 2¹⁵`, and only the low sum, below 2³⁴, needs 64 bits. The high parts are summed
/// modulo 2³², exact since the rounded dot product fits 32 bits (`dot_exact`'s bounds).
/// Compiled everywhere, so the host tests check it.
pub(crate) const fn split_dot_unit(u: Vec3, v: Vec3) -> i32 {
    let (high, low) = split_dot_parts(u, v);
    high.wrapping_add(((low + (1 << 15)) >> 16) as i32)
}

/// [`split_dot_unit`]'s two sums, `Σ u·v = 2¹⁶·high + low`: `low` exactly (below 3·2³²),
/// `high` modulo 2³², so exactly wherever it fits 32 bits (for two unit vectors it is below
/// 2¹⁸).
pub(crate) const fn split_dot_parts(u: Vec3, v: Vec3) -> (i32, u64) {
    const fn parts(u: Fx, v: Fx) -> (i32, u64) {
        let (high, low) = split_by_unit(v.to_bits(), u.to_bits());
        (high, low as u64)
    }
    let (x, y, z) = (parts(u.x, v.x), parts(u.y, v.y), parts(u.z, v.z));
    (x.0.wrapping_add(y.0).wrapping_add(z.0), x.1 + y.1 + z.1)
}

/// `S = Σ a·a'` for two vectors whose components lie within ±2¹⁷ raw, each component
/// `c = 2⁸·a + α` cut to its top bits `a = c >> 8` (in −2⁹..=2⁹) and `α` in 0..2⁸: three
/// 32-bit products. The exact dot product is `2¹⁶·S + R`, where each component adds to `R`
/// `2⁸·(a·α' + α·a') + α·α'`, in −66 846 720..=66 911 745 (`|a·α' + α·a'| ≤ 2·2⁹·255`), so
/// `|R| < 200 735 236 < 3063·2¹⁶`: for `|S| >` [`COARSE_MARGIN`] the dot product has the sign
/// of `S`. For unit vectors that leaves undecided only pairs within about 0.047 of
/// perpendicular. Compiled everywhere, so the host tests check it.
pub(crate) const fn coarse_dot(u: Vec3, v: Vec3) -> i32 {
    const fn top(c: Fx) -> i32 {
        c.to_bits() >> 8
    }
    top(u.x) * top(v.x) + top(u.y) * top(v.y) + top(u.z) * top(v.z)
}

/// What [`coarse_dot`]'s sum must pass for its sign to be the exact dot product's: at least
/// 3 062, taken as 3·2¹⁰.
pub(crate) const COARSE_MARGIN: u32 = 3 << 10;
