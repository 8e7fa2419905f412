//! [`Vec3`]: a point or direction in Q16.16.

use crate::numbers::split::{
    COARSE_MARGIN, coarse_dot, split_dot_parts, split_dot_unit, split_length_squared,
};
use core::ops::{Add, Neg, Sub};

use crate::numbers::fx::{self, Fx};
use crate::numbers::isqrt::isqrt;
use crate::numbers::reciprocal::{EvenLength, rsqrt_unit, rsqrt_unit_near};

/// A point or a direction with three Q16.16 components.
///
/// Addition, subtraction and negation saturate at the ends of the Q16.16 range instead of
/// wrapping; inside the documented range ([`LIMIT`](crate::LIMIT)) they are exact. Products
/// (`dot`, `cross`, `length`) are formed at 64 bits and rounded once.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub struct Vec3 {
    /// x component.
    pub x: Fx,
    /// y component.
    pub y: Fx,
    /// z component.
    pub z: Fx,
}

impl Vec3 {
    /// The zero vector.
    pub const ZERO: Vec3 = Vec3::new(Fx::ZERO, Fx::ZERO, Fx::ZERO);
    /// The unit vector along +x.
    pub const X: Vec3 = Vec3::new(Fx::ONE, Fx::ZERO, Fx::ZERO);
    /// The unit vector along +y.
    pub const Y: Vec3 = Vec3::new(Fx::ZERO, Fx::ONE, Fx::ZERO);
    /// The unit vector along +z.
    pub const Z: Vec3 = Vec3::new(Fx::ZERO, Fx::ZERO, Fx::ONE);

    /// A vector from three Q16.16 components.
    #[inline]
    #[must_use]
    pub const fn new(x: Fx, y: Fx, z: Fx) -> Self {
        Vec3 { x, y, z }
    }

    /// A vector from three whole numbers, for `const` scenes.
    ///
    /// ```
    /// use fixray::{Fx, Vec3};
    /// const UP: Vec3 = Vec3::from_ints(0, 1, 0);
    /// assert_eq!(UP.y, Fx::ONE);
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_ints(x: i16, y: i16, z: i16) -> Self {
        Vec3::new(
            Fx::const_from_int(x as i32),
            Fx::const_from_int(y as i32),
            Fx::const_from_int(z as i32),
        )
    }

    /// The components as `f64`, for the tests' exact comparisons.
    #[cfg(test)]
    pub(crate) fn to_f64(self) -> [f64; 3] {
        [self.x.to_num(), self.y.to_num(), self.z.to_num()]
    }

    /// `self · k`, each component rounded once.
    #[inline]
    #[must_use]
    pub const fn scale(self, k: Fx) -> Self {
        Vec3::new(fx::mul(self.x, k), fx::mul(self.y, k), fx::mul(self.z, k))
    }

    /// `self · t` for a unit vector `self` and a distance `t` (see [`fx::mul_unit`]): a
    /// point's offset along a ray.
    #[inline]
    pub(crate) const fn scale_unit(self, t: Fx) -> Self {
        Vec3::new(
            fx::mul_unit(t, self.x),
            fx::mul_unit(t, self.y),
            fx::mul_unit(t, self.z),
        )
    }

    /// `self · n` for a camera's column step `self` and a count `n` of columns within its row:
    /// the direction towards any of a row's pixels lies within the camera's bounds, and so
    /// does every whole number of steps up to it, so no product wraps (debug builds check).
    /// No saturation: its products are long sequences on the Cortex-M0.
    #[inline]
    pub(crate) fn steps(self, n: i32) -> Self {
        let t = |c: Fx| {
            debug_assert!(
                c.to_bits().checked_mul(n).is_some(),
                "Vec3::steps: out of range"
            );
            Fx::from_bits(c.to_bits().wrapping_mul(n))
        };
        Vec3::new(t(self.x), t(self.y), t(self.z))
    }

    /// The dot product as a Q32.32 raw value (`i64`, 2⁻³² units): exact wherever it fits,
    /// which it always does in the render path (each product is below 2⁶² in magnitude).
    /// Beyond that it saturates rather than wrap.
    #[inline]
    #[must_use]
    pub(crate) const fn dot_wide(self, o: Vec3) -> i64 {
        let wrapped = self.dot_wide_wrapping(o);
        // Three products of at most 2⁶² each sum to at most 3 · 2⁶² in magnitude, so a sum
        // that wrapped lies at least 2⁶² from zero: one that lies within 2⁶¹ is exact. Any
        // other goes to the exact sum, saturated, which only out-of-budget vectors need.
        if wrapped >> 61 == wrapped >> 63 {
            wrapped
        } else {
            self.dot_wide_saturated(o)
        }
    }

    /// The three products summed at 64 bits with wrapping: the exact dot product whenever it
    /// fits, and the same instructions as a plain sum.
    #[inline]
    const fn dot_wide_wrapping(self, o: Vec3) -> i64 {
        fx::wide_mul(self.x.to_bits(), o.x.to_bits())
            .wrapping_add(fx::wide_mul(self.y.to_bits(), o.y.to_bits()))
            .wrapping_add(fx::wide_mul(self.z.to_bits(), o.z.to_bits()))
    }

    /// The exact dot product, saturated to `i64`: the rare path of
    /// [`Vec3::dot_wide`] and [`Vec3::dot`], for vectors far outside the overflow budget.
    #[cold]
    const fn dot_wide_saturated(self, o: Vec3) -> i64 {
        // Each product is exact at 64 bits and at most 2⁶² in magnitude, and the sum is
        // followed through two 64-bit additions by their overflows, shorter than a 128-bit
        // sum where a word is 32 bits. The first overflows only at `2⁶² + 2⁶²`, to −2⁶³; the
        // second then only downwards, and the two cancel.
        const fn p(a: Fx, b: Fx) -> i64 {
            fx::wide_mul(a.to_bits(), b.to_bits())
        }
        let z = p(self.z, o.z);
        let (pair, first) = p(self.x, o.x).overflowing_add(p(self.y, o.y));
        let (sum, second) = pair.overflowing_add(z);
        match (first, second) {
            (false, false) | (true, true) => sum,
            (true, false) => i64::MAX,
            (false, true) if z > 0 => i64::MAX,
            (false, true) => i64::MIN,
        }
    }

    /// The dot product as an exact Q32.32 value, without [`Vec3::dot_wide`]'s range check,
    /// for the render path's vectors: one of them a unit vector (components within ±2, raw
    /// values within ±2¹⁷), as ray directions and surface normals are, or both inside the
    /// budget (components below 2¹⁴, raw values below 2³⁰), as hit points and vectors to
    /// lights are. The sum then lies below 2⁵⁰, or 2⁶², and plain addition cannot overflow.
    #[inline]
    #[must_use]
    pub(crate) const fn dot_wide_exact(self, o: Vec3) -> i64 {
        debug_assert!(
            self.within_raw(1 << 17)
                || o.within_raw(1 << 17)
                || (self.within_raw((1 << 30) - 1) && o.within_raw((1 << 30) - 1)),
            "dot_wide_exact: neither vector a unit one, nor both inside the overflow budget"
        );
        sparse_mul(self.x, o.x) + sparse_mul(self.y, o.y) + sparse_mul(self.z, o.z)
    }

    /// `self + o` for the render path's points and offsets, which lie within the overflow
    /// budget (below 2¹⁵ in magnitude, sums included): no saturation check, which the `+`
    /// operator makes on every component (debug builds check that none is needed).
    #[inline]
    pub(crate) const fn plus(self, o: Vec3) -> Vec3 {
        const fn add(a: Fx, b: Fx) -> Fx {
            debug_assert!(a.checked_add(b).is_some(), "Vec3::plus: out of range");
            Fx::from_bits(a.to_bits().wrapping_add(b.to_bits()))
        }
        Vec3::new(add(self.x, o.x), add(self.y, o.y), add(self.z, o.z))
    }

    /// `self − o`, as [`Vec3::plus`].
    #[inline]
    pub(crate) const fn minus(self, o: Vec3) -> Vec3 {
        const fn sub(a: Fx, b: Fx) -> Fx {
            debug_assert!(a.checked_sub(b).is_some(), "Vec3::minus: out of range");
            Fx::from_bits(a.to_bits().wrapping_sub(b.to_bits()))
        }
        Vec3::new(sub(self.x, o.x), sub(self.y, o.y), sub(self.z, o.z))
    }

    /// `self − o`, each component saturating: `-` in a `const fn`.
    #[inline]
    pub(crate) const fn saturating_sub(self, o: Vec3) -> Vec3 {
        Vec3::new(
            self.x.saturating_sub(o.x),
            self.y.saturating_sub(o.y),
            self.z.saturating_sub(o.z),
        )
    }

    /// Whether every raw component lies within `±bound`.
    pub(crate) const fn within_raw(self, bound: i32) -> bool {
        const fn within(c: Fx, bound: i32) -> bool {
            c.to_bits() >= -bound && c.to_bits() <= bound
        }
        within(self.x, bound) && within(self.y, bound) && within(self.z, bound)
    }

    /// [`Vec3::dot_wide_exact`] rounded once to Q16.16: the render path's dot product of a
    /// unit vector `self` (a ray's direction, a surface normal) and a vector within the
    /// budget (components below 2¹⁴). Its magnitude is then below `√3 · 2¹⁴` and fits
    /// Q16.16: no saturation check (debug builds check the bounds).
    #[inline]
    #[must_use]
    pub(crate) const fn dot_exact(self, o: Vec3) -> Fx {
        debug_assert!(
            self.within_raw(1 << 17) && o.within_raw((1 << 30) - 1),
            "dot_exact: not a unit vector and one within the budget"
        );
        if fx::NO_LONG_MULTIPLY {
            return Fx::from_bits(split_dot_unit(self, o));
        }
        let rounded = (self.dot_wide_exact(o) + (1 << (fx::FRAC - 1))) >> fx::FRAC;
        debug_assert!(rounded as i32 as i64 == rounded, "dot_exact: out of range");
        Fx::from_bits(rounded as i32)
    }

    /// The dot product, formed at 64 bits and rounded once to Q16.16 (saturating).
    ///
    /// The three products are summed with wrapping, which is exact whenever the rounded
    /// result fits Q16.16: a sum that wrapped lies at least 2⁶² from zero and cannot round
    /// into range. Only a result out of range takes the slow path, to find its sign from the
    /// additions' overflows, so saturation costs nothing on the way through.
    #[inline]
    #[must_use]
    pub const fn dot(self, o: Vec3) -> Fx {
        match fx::narrow_fitting(self.dot_wide_wrapping(o)) {
            Some(dot) => dot,
            None => fx::narrow(self.dot_wide_saturated(o)),
        }
    }

    /// [`Vec3::dot`] of a unit-sized `self` (within 2¹⁷ raw: a normal, a ray's direction, a
    /// step along a row) and an `o` within 2²⁸ raw (another such vector, a difference of
    /// points within `LIMIT`). Where a 64-bit product is a long sequence, from the split
    /// products of [`Vec3::dot_exact`], the same value: the dot product then lies within
    /// 3·2²⁹ raw, and fits.
    // In line: a highlight's cosine and a mirror ray's direction take it at each pixel that
    // has one, where a call would move their values out of the registers it clobbers.
    #[inline(always)]
    pub(crate) const fn dot_units(self, o: Vec3) -> Fx {
        self.dot_by::<{ fx::NO_LONG_MULTIPLY }>(o)
    }

    /// [`Vec3::dot_units`], from the split products where `SPLIT`: both forms are compiled
    /// everywhere, so the host tests check the Cortex-M0's.
    const fn dot_by<const SPLIT: bool>(self, o: Vec3) -> Fx {
        if SPLIT && self.within_raw(1 << 17) && o.within_raw(1 << 28) {
            return Fx::from_bits(split_dot_unit(self, o));
        }
        self.dot(o)
    }

    /// Whether `self · o > 0`, exactly, for two unit vectors (components below 2¹⁷ raw): on
    /// the side a surface's normal faces. Where a 64-bit product is a long sequence, from
    /// three 32-bit products of the components' top bits where they decide it (`coarse_dot`:
    /// all but pairs near perpendicular, a sphere's silhouette), otherwise from the split
    /// products of the exact dot product (`split_dot_parts`), a third of the cost.
    #[inline]
    pub(crate) const fn dot_positive(self, o: Vec3) -> bool {
        debug_assert!(
            self.within_raw(1 << 17) && o.within_raw(1 << 17),
            "dot_positive: not two unit vectors"
        );
        if fx::NO_LONG_MULTIPLY {
            // Most pairs are decided by their components' top bits alone (`coarse_dot`); only
            // those within a few hundredths of perpendicular take the exact sum.
            let coarse = coarse_dot(self, o);
            if coarse.unsigned_abs() > COARSE_MARGIN {
                return coarse > 0;
            }
            let (high, low) = split_dot_parts(self, o);
            ((high as i64) << 16) + low as i64 > 0
        } else {
            self.dot_wide_exact(o) > 0
        }
    }

    /// The cross product, each component formed at 64 bits and rounded once.
    #[inline]
    #[must_use]
    pub const fn cross(self, o: Vec3) -> Vec3 {
        /// `p·q − r·s`, formed at 64 bits and rounded once.
        const fn c(p: Fx, q: Fx, r: Fx, s: Fx) -> Fx {
            fx::narrow(
                fx::wide_mul(p.to_bits(), q.to_bits()) - fx::wide_mul(r.to_bits(), s.to_bits()),
            )
        }
        let (a, b) = (self, o);
        Vec3::new(
            c(a.y, b.z, a.z, b.y),
            c(a.z, b.x, a.x, b.z),
            c(a.x, b.y, a.y, b.x),
        )
    }

    /// ‖self‖² as an exact unsigned Q32.32 raw value: three squares below 2⁶² each, so it
    /// never overflows.
    #[inline]
    #[must_use]
    pub(crate) const fn length_squared_wide(self) -> u64 {
        if fx::NO_LONG_MULTIPLY {
            return split_length_squared(self);
        }
        const fn sq(c: Fx) -> u64 {
            // A square of an i32 is at most 2⁶², so the signed 32 × 32 → 64 product holds it.
            fx::wide_mul(c.to_bits(), c.to_bits()) as u64
        }
        sq(self.x) + sq(self.y) + sq(self.z)
    }

    /// ‖self‖, truncated to Q16.16: `isqrt` of the exact Q32.32 square.
    #[must_use]
    pub const fn length(self) -> Fx {
        let root = isqrt(self.length_squared_wide());
        // The root is below √3 · 2³¹; above i32::MAX it saturates.
        if root > i32::MAX as u64 {
            Fx::MAX
        } else {
            Fx::from_bits(root as i32)
        }
    }

    /// The unit vector along `self`, or `None` for the zero vector.
    ///
    /// The exact squared length goes through a table-interpolated reciprocal square root (good
    /// to about 2⁻²⁰ whatever the size of `self`), and each component is multiplied by it and
    /// rounded to nearest: every component is within 0.55 of a unit of 2⁻¹⁶ of the exact unit
    /// vector, even for vectors a few units of 2⁻¹⁶ long, and no division is needed.
    ///
    /// ```
    /// use fixray::{Fx, Vec3};
    /// let tiny = Vec3::new(Fx::ZERO, Fx::from_bits(3), Fx::from_bits(-4));
    /// assert_eq!(tiny.try_normalize(), Some(Vec3::new(Fx::ZERO, Fx::from_num(0.6), Fx::from_num(-0.8))));
    /// ```
    #[must_use]
    pub const fn try_normalize(self) -> Option<Vec3> {
        self.normalize_with_square(self.length_squared_wide())
    }

    /// `self·v / ‖v‖`, the cosine between a unit vector `self` (a normal) and any `v` shorter
    /// than 4, or `None` for the zero `v`: formed from the exact dot product and one
    /// reciprocal root, not from `v` made a unit vector first, whose three rounded components
    /// would put the cosine up to 0.95 of a unit of 2⁻¹⁶ off before its own rounding.
    ///
    /// Within 0.541 of a unit of the exact `N/√S` (`N = self·v`, `S = ‖v‖²`) whatever the
    /// length of `v`; see [`Vec3::cosine_from`].
    pub(crate) const fn cosine_to(self, v: Vec3) -> Option<Fx> {
        Vec3::cosine_from(self.dot_wide_exact(v), v.length_squared_wide())
    }

    /// [`Vec3::cosine_to`] from its exact dot product `dot` (raw units squared) and `v`'s
    /// squared length `square` (Q32.32), for a caller that has them already.
    ///
    /// The root is `1/√S ≈ y·2^−(30 + half)` with `S < 2^(2·half)` (`rsqrt_unit`), so `|N| <
    /// 2^(16 + half)` (and a little, for a normal up to 2⁻¹⁵ long): moved by `half − 14` bits to
    /// below 2³¹, the cosine is that times `y` over 2⁴⁴ whatever the length — the product's
    /// high word alone on every core. Moving `N` down drops less than `2^(half − 14)` raw
    /// units, under 2⁻¹³ of a unit of the cosine since `√S ≥ 2^(half − 1)`; the root's error
    /// (2⁻²⁰·⁶ relative) under 0.04 of a unit on a cosine up to 1; and the final rounding half
    /// a unit: within 0.541 in all.
    pub(crate) const fn cosine_from(dot: i64, square: u64) -> Option<Fx> {
        if square == 0 {
            return None;
        }
        let (y, half) = rsqrt_unit(square);
        let n = match half as i32 - 14 {
            k @ 0.. => dot >> k,
            k => dot << -k,
        };
        Some(Fx::from_bits(
            fx::mul_shift_round(n as i32, y as i32, 44) as i32
        ))
    }

    /// `|x| + |y| + |z|` in raw units (2⁻¹⁶), exactly: at least the length, at most √3 times
    /// it, for bounds that need no square root.
    #[inline]
    pub(crate) const fn l1_raw(self) -> i64 {
        self.x.to_bits().unsigned_abs() as i64
            + self.y.to_bits().unsigned_abs() as i64
            + self.z.to_bits().unsigned_abs() as i64
    }

    /// [`Vec3::try_normalize`] given `square`, which must be `self.length_squared_wide()`:
    /// for callers that have it already, or can keep it up to date for less.
    #[inline]
    pub(crate) const fn normalize_with_square(self, square: u64) -> Option<Vec3> {
        self.normalize_by(square)
    }

    /// [`Vec3::normalize_with_square`]'s work.
    // In line: a ray's and a light's direction are normalised at each pixel, where a call
    // would move the caller's values out of the registers it clobbers.
    #[inline(always)]
    const fn normalize_by(self, square: u64) -> Option<Vec3> {
        debug_assert!(
            square == self.length_squared_wide(),
            "normalize_with_square: square is not the vector's squared length"
        );
        let Some((y, shift)) = unit_scale(square) else {
            return None;
        };
        Some(Vec3::new(
            unit_part(self.x, y, shift),
            unit_part(self.y, y, shift),
            unit_part(self.z, y, shift),
        ))
    }

    /// The component along `c` of the unit vector along a vector whose component `c` is and
    /// whose squared length is `square`: [`Vec3::normalize_with_square`]'s, bit for bit,
    /// without the other two, where the unit vector is only dotted with an axis.
    #[inline]
    pub(crate) const fn unit_component_with_square(c: Fx, square: u64) -> Option<Fx> {
        match unit_scale(square) {
            Some((y, shift)) => Some(unit_part(c, y, shift)),
            None => None,
        }
    }

    /// [`Vec3::unit_component_with_square`] with the reciprocal root in line, for a loop that
    /// takes one a column, whose squares mostly share their even bit length: kept from one to
    /// the next in `length` ([`rsqrt_unit_near`]).
    // In line: a floor's cosine at each column of a lit stretch, where a call would move the
    // loop's values out of the registers it clobbers.
    #[inline(always)]
    pub(crate) fn unit_component_near(c: Fx, square: u64, length: &mut EvenLength) -> Option<Fx> {
        if square == 0 {
            return None;
        }
        let (y, half) = rsqrt_unit_near(square, length);
        let (y, shift) = unit_factor(y, half);
        Some(unit_part(c, y, shift))
    }

    /// The unit vector along `self`, or the zero vector when `self` is zero.
    #[must_use]
    pub fn normalize_or_zero(self) -> Vec3 {
        self.try_normalize().unwrap_or(Vec3::ZERO)
    }
}

/// `1/‖v‖` for a vector `v` whose squared length is `square`, as a factor `y` and a shift
/// (`y · 2^−shift · 2¹⁶`), or `None` for the zero vector: what each of a unit vector's
/// components is multiplied by ([`unit_part`]).
const fn unit_scale(square: u64) -> Option<(u32, u32)> {
    if square == 0 {
        return None;
    }
    let (y, half) = rsqrt_unit(square);
    Some(unit_factor(y, half))
}

/// [`unit_scale`]'s factor and shift from a reciprocal root `1/√s ≈ y · 2^−(30 + half)` of the
/// squared length `s`: `1/‖v‖` in units of 2⁻¹⁶ is `y · 2^−(30 + half) · 2¹⁶`.
// In line: one addition, which a call would cost several times over.
#[inline(always)]
const fn unit_factor(y: u32, half: u32) -> (u32, u32) {
    (y, 14 + half)
}

/// The unit vector's component along `c` (a component of `v`), from [`unit_scale`]'s
/// factor: `|c| ≤ ‖v‖` and `y·‖v‖ ≈ 2^(30 + shift − 14)`, so it is at most 2¹⁶ and a bit.
///
/// A vector shorter than 4 (a sum of unit vectors, as a highlight's half vector is, or a
/// mirrored or refracted direction) has a shift of 32 or less, where the rounding would take
/// the product's low word too. Where the high word is one instruction
/// ([`fx::HIGH_WORD_QUOTIENT`]), `c` is moved up to a shift of 33 instead, the same quotient
/// exactly from the product's high word alone: `|c| < 2^(shift − 14)`, so moved up by
/// `33 − shift` bits it stays below 2¹⁹.
#[inline]
const fn unit_part(c: Fx, y: u32, shift: u32) -> Fx {
    // Its own call with the shift a constant, which the rounding is folded with: a shift
    // chosen between the two would be a variable again.
    if fx::HIGH_WORD_QUOTIENT && shift < 33 {
        let moved = c.to_bits() << (33 - shift);
        return Fx::from_bits(fx::mul_shift_round(moved, y as i32, 33) as i32);
    }
    Fx::from_bits(fx::mul_shift_round(c.to_bits(), y as i32, shift) as i32)
}

/// The exact product of two raw values, as [`fx::wide_mul`]; where a 64-bit product is a
/// long sequence ([`fx::NO_LONG_MULTIPLY`]), a zero first factor skips it. Floors and walls
/// have normals with two zero components, and their dot products put the normal first.
#[inline]
const fn sparse_mul(a: Fx, b: Fx) -> i64 {
    if fx::NO_LONG_MULTIPLY && a.to_bits() == 0 {
        0
    } else {
        fx::wide_mul(a.to_bits(), b.to_bits())
    }
}

impl Add for Vec3 {
    type Output = Vec3;
    #[inline]
    fn add(self, o: Vec3) -> Vec3 {
        Vec3::new(
            self.x.saturating_add(o.x),
            self.y.saturating_add(o.y),
            self.z.saturating_add(o.z),
        )
    }
}

impl Sub for Vec3 {
    type Output = Vec3;
    #[inline]
    fn sub(self, o: Vec3) -> Vec3 {
        self.saturating_sub(o)
    }
}

impl Neg for Vec3 {
    type Output = Vec3;
    #[inline]
    fn neg(self) -> Vec3 {
        Vec3::new(
            self.x.saturating_neg(),
            self.y.saturating_neg(),
            self.z.saturating_neg(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cosine_is_within_its_bound_of_the_exact_quotient() {
        let mut rng = crate::xorshift::XorShift(0x2545_f491_4f6c_dd1d);
        let raw = |v: Vec3| [v.x, v.y, v.z].map(|c| f64::from(c.to_bits()));
        let mut worst: f64 = 0.0;
        for i in 0..300_000 {
            let mut c = |bits: u32| Fx::from_bits((rng.next() as i32) >> (32 - bits));
            let normal = Vec3::new(c(18), c(18), c(18)).normalize_or_zero();
            // Half vectors of every length below 4 (sums of two unit vectors reach 2), short
            // ones a third of the time.
            let bits = if i % 3 == 0 {
                1 + (i / 3 % 17) as u32
            } else {
                18
            };
            let v = Vec3::new(c(bits), c(bits), c(bits));
            let Some(s) = normal.cosine_to(v) else {
                assert_eq!(v, Vec3::ZERO);
                continue;
            };
            let (n, w) = (raw(normal), raw(v));
            let dot = n[0] * w[0] + n[1] * w[1] + n[2] * w[2];
            let length = (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
            let exact = dot / length;
            let off = (f64::from(s.to_bits()) - exact).abs();
            assert!(
                off <= 0.541,
                "{normal:?} {v:?}: {off} past 0.541 at length {length}"
            );
            worst = worst.max(off);
        }
        // The bound is near tight: the rounding alone reaches half a unit.
        assert!(worst > 0.49, "{worst}");
    }

    #[test]
    fn a_coarse_dot_past_its_margin_has_the_exact_dot_products_sign() {
        let mut rng = crate::xorshift::XorShift(0x5851_f42d_4c95_7f2d);
        // Components built from their top bits and low byte, the extremes (±2⁹, 255) most
        // often, where the low bytes' share is largest; and random unit vectors.
        let part = |rng: &mut crate::xorshift::XorShift| {
            let r = rng.next();
            let top = match r % 4 {
                0 => -512,
                1 => 511,
                _ => (r >> 8) as i32 % 513,
            };
            let low = if r & 0x30 == 0 {
                (r >> 40) as i32 & 0xff
            } else {
                255
            };
            (top * 256 + low).clamp(-(1 << 17), 1 << 17)
        };
        // The rest `R` is largest with every component at `−2⁹·2⁸ + 255` in both vectors:
        // −200 345 085, within 6 units of 2¹⁶ of the bound, which the margin must cover.
        let corner = Fx::from_bits(-512 * 256 + 255);
        let corner = Vec3::new(corner, corner, corner);
        let rest = |u: Vec3, v: Vec3| u.dot_wide_exact(v) - ((coarse_dot(u, v) as i64) << 16);
        assert_eq!(rest(corner, corner), -200_345_085);
        let (mut decided, mut undecided) = (0, 0);
        for i in 0..400_000 {
            let (u, v) = if i % 2 == 0 {
                let mut c = || Fx::from_bits(part(&mut rng));
                (Vec3::new(c(), c(), c()), Vec3::new(c(), c(), c()))
            } else {
                let mut c = || Fx::from_bits((rng.next() as i32) >> 12);
                let u = Vec3::new(c(), c(), c()).normalize_or_zero();
                // v near perpendicular to u half the time.
                let w = Vec3::new(c(), c(), c()).normalize_or_zero();
                let v = if i % 4 == 1 {
                    (w - u.scale(u.dot(w))).normalize_or_zero()
                } else {
                    w
                };
                (u, v)
            };
            let coarse = coarse_dot(u, v);
            assert!(
                rest(u, v).abs() < (COARSE_MARGIN as i64 + 1) << 16,
                "{u:?} · {v:?}"
            );
            if coarse.unsigned_abs() > COARSE_MARGIN {
                assert_eq!(coarse > 0, u.dot_wide_exact(v) > 0, "{u:?} · {v:?}");
                decided += 1;
            } else {
                undecided += 1;
            }
        }
        assert!(rest(corner, corner).abs() < (COARSE_MARGIN as i64 + 1) << 16);
        assert!(
            decided > 100_000 && undecided > 10_000,
            "{decided} / {undecided}"
        );
    }

    #[test]
    fn split_squared_lengths_are_the_exact_sums() {
        let mut rng = crate::xorshift::XorShift(0x94d0_49bb_1331_11eb);
        let ends = [
            i32::MIN,
            i32::MIN + 1,
            -65537,
            -65536,
            -1,
            0,
            1,
            65535,
            65536,
            i32::MAX,
        ];
        let exact = |v: Vec3| {
            [v.x, v.y, v.z]
                .map(|c| (c.to_bits() as i128).pow(2))
                .iter()
                .sum::<i128>()
        };
        let corners = ends.iter().flat_map(|&x| ends.iter().map(move |&y| (x, y)));
        let corners = corners.flat_map(|(x, y)| ends.iter().map(move |&z| [x, y, z]));
        let random = (0..100_000).map(|i| {
            // Every magnitude, either sign: a signed 64-bit draw shifted arithmetically.
            [0, 1, 2].map(|_| (rng.next() as i64 >> (32 + i % 32)) as i32)
        });
        for [x, y, z] in corners.chain(random) {
            let v = Vec3::new(Fx::from_bits(x), Fx::from_bits(y), Fx::from_bits(z));
            assert_eq!(split_length_squared(v) as i128, exact(v), "{x} {y} {z}");
        }
    }

    #[test]
    fn a_unit_component_alone_is_the_unit_vectors() {
        let mut rng = crate::xorshift::XorShift(0x0c0a_1e55_0000_0001);
        // One kept length for every vector, as a loop keeps it (and the kept form alone,
        // which the host would not take otherwise, beside it).
        let (mut length, mut kept) = (EvenLength::NONE, EvenLength::NONE);
        for i in 0..200_000u32 {
            // Every magnitude within the budget, zero components and the zero vector too.
            let mut next = |bits: u32| ((rng.next() as i64) >> (64 - bits)) as i32 >> (i % 31);
            let v = Vec3::new(
                Fx::from_bits(next(31)),
                Fx::from_bits(if i % 7 == 0 { 0 } else { next(31) }),
                Fx::from_bits(next(31)),
            );
            let square = v.length_squared_wide();
            let unit = v.normalize_with_square(square);
            // Taken again, the root is the same.
            assert_eq!(v.normalize_with_square(square), unit, "{v:?}");
            for (c, u) in [
                (v.x, unit.map(|u| u.x)),
                (v.y, unit.map(|u| u.y)),
                (v.z, unit.map(|u| u.z)),
            ] {
                assert_eq!(Vec3::unit_component_with_square(c, square), u, "{v:?}");
                assert_eq!(
                    Vec3::unit_component_near(c, square, &mut length),
                    u,
                    "{v:?}"
                );
                let by_kept = (square != 0).then(|| {
                    let (m, half) = kept.kept_or_found(square);
                    let (y, shift) = unit_factor(crate::numbers::reciprocal::interpolated(m), half);
                    unit_part(c, y, shift)
                });
                assert_eq!(by_kept, u, "{v:?}");
            }
        }
    }

    #[test]
    fn a_unit_part_moved_up_to_a_shift_of_33_is_the_plain_quotient() {
        // Vectors of every length from a raw unit to 2³ (shifts 15 to 33), their components
        // of either sign and at the length itself: the unit part is the quotient of the
        // plain shift. Fails with a component moved a bit too far or not far enough.
        let mut rng = crate::xorshift::XorShift(0x5eed_0fc0_ffee_0001);
        let mut moved = 0;
        for i in 0..200_000u32 {
            let mut next = |bits: u32| ((rng.next() as i64) >> (64 - bits)) as i32;
            let v = match i % 5 {
                0 => Vec3::new(Fx::from_bits(next(20) >> (i % 19)), Fx::ZERO, Fx::ZERO),
                _ => Vec3::new(
                    Fx::from_bits(next(20) >> (i % 19)),
                    Fx::from_bits(next(20) >> (i % 13)),
                    Fx::from_bits(next(20) >> (i % 7)),
                ),
            };
            let Some((y, shift)) = unit_scale(v.length_squared_wide()) else {
                continue;
            };
            moved += u32::from(shift < 33);
            for c in [v.x, v.y, v.z] {
                let plain = fx::mul_shift_round(c.to_bits(), y as i32, shift) as i32;
                assert_eq!(unit_part(c, y, shift).to_bits(), plain, "{v:?}");
            }
        }
        assert!(
            moved > 100_000,
            "only {moved} vectors with a shift below 33"
        );
    }

    #[test]
    fn the_split_dot_product_is_the_dot_product_within_dot_onces_bounds() {
        // `dot_units` on the Cortex-M0 takes the split products for a `self` within 2¹⁷ raw
        // and an `o` within 2²⁸: the same value as `dot`, which never saturates there. The
        // bounds themselves, both signs, and random values within them.
        let mut rng = crate::xorshift::XorShift(0x6a09_e667_f3bc_c908);
        let ends = [1 << 17, -(1 << 17), 0, 1];
        let far = [1 << 28, -(1 << 28), 0, -1];
        for i in 0..100_000u32 {
            let mut next = |bits: u32| ((rng.next() as i64) >> (64 - bits)) as i32;
            let (a, b) = (i as usize % 4, (i as usize / 4) % 4);
            let u = Vec3::new(
                Fx::from_bits(if i < 64 {
                    ends[a]
                } else {
                    next(18).clamp(-(1 << 17), 1 << 17)
                }),
                Fx::from_bits(if i < 64 {
                    ends[b]
                } else {
                    next(18).clamp(-(1 << 17), 1 << 17)
                }),
                Fx::from_bits(next(18).clamp(-(1 << 17), 1 << 17) >> (i % 7)),
            );
            let v = Vec3::new(
                Fx::from_bits(if i < 64 {
                    far[a]
                } else {
                    next(29).clamp(-(1 << 28), 1 << 28)
                }),
                Fx::from_bits(if i < 64 { far[b] } else { next(29) >> (i % 23) }),
                Fx::from_bits(next(29).clamp(-(1 << 28), 1 << 28)),
            );
            assert!(u.within_raw(1 << 17) && v.within_raw(1 << 28));
            assert_eq!(
                super::split_dot_unit(u, v),
                u.dot(v).to_bits(),
                "{u:?} · {v:?}"
            );
            assert_eq!(u.dot_by::<true>(v), u.dot(v), "{u:?} · {v:?}");
        }
        // Past the bound `dot` saturates, and so must `dot_units`: the bound is where the split
        // products stop being the answer.
        let unit = Vec3::new(
            Fx::from_bits(1 << 17),
            Fx::from_bits(1 << 17),
            Fx::from_bits(1 << 17),
        );
        for raw in [(1 << 29) + 1, (1 << 30) - 1, i32::MAX] {
            let long = Vec3::new(Fx::from_bits(raw), Fx::from_bits(raw), Fx::from_bits(raw));
            assert_eq!(unit.dot_by::<true>(long), Fx::MAX);
            assert_eq!(unit.dot_by::<true>(-long), Fx::MIN);
        }
    }

    #[test]
    fn the_split_dot_product_of_a_unit_vector_is_exact() {
        let mut rng = crate::xorshift::XorShift(0x3c6e_f372_fe94_f82b);
        let mut tested = 0;
        for i in 0..200_000u32 {
            let mut next = |bits: u32| ((rng.next() as i64) >> (64 - bits)) as i32;
            // A unit-sized vector (raw below 2¹⁷) and one within the budget (below 2³⁰),
            // of every magnitude.
            let u = Vec3::new(
                Fx::from_bits(next(18) >> (i % 5)),
                Fx::from_bits(next(18)),
                Fx::from_bits(next(18) >> (i % 3)),
            );
            let v = Vec3::new(
                Fx::from_bits(next(31) >> (i % 29)),
                Fx::from_bits(next(31) >> (i % 17)),
                Fx::from_bits(next(31)),
            );
            let exact: i128 = [(u.x, v.x), (u.y, v.y), (u.z, v.z)]
                .iter()
                .map(|(a, b)| a.to_bits() as i128 * b.to_bits() as i128)
                .sum();
            let rounded = (exact + (1 << 15)) >> 16;
            // Two unit-sized vectors: the parts are the exact product, whose sign
            // `dot_positive` reads.
            let w = Vec3::new(
                Fx::from_bits(v.x.to_bits() >> 13),
                Fx::from_bits(v.y.to_bits() >> 13),
                Fx::from_bits(v.z.to_bits() >> 13),
            );
            let (high, low) = super::split_dot_parts(u, w);
            let whole = ((high as i64) << 16) + low as i64;
            assert_eq!(whole, u.dot_wide_exact(w), "{u:?} · {w:?}");
            if rounded as i32 as i128 == rounded {
                assert_eq!(
                    super::split_dot_unit(u, v) as i128,
                    rounded,
                    "{u:?} · {v:?}"
                );
                tested += 1;
            }
        }
        assert!(tested > 100_000, "too few cases in range: {tested}");
    }

    fn v(x: f32, y: f32, z: f32) -> Vec3 {
        Vec3::new(Fx::from_num(x), Fx::from_num(y), Fx::from_num(z))
    }

    #[test]
    fn long_vectors_square_without_overflow() {
        // 200² = 40 000 does not fit Q16.16, but the wide square does, and so does its root.
        let a = v(200.0, 0.0, 0.0);
        assert_eq!(a.length_squared_wide(), 40_000u64 << 32);
        assert_eq!(a.length(), Fx::from_num(200));
        let b = v(1000.0, -1000.0, 1000.0);
        assert_eq!(b.dot_wide(b), 3_000_000i64 << 32);
    }

    #[test]
    fn dot_keeps_the_bits_a_narrow_product_would_lose() {
        // (2⁻¹⁶ · 2⁻¹⁶) summed 3 × 2¹⁶ times would vanish if each product were rounded first.
        let tiny = Vec3::new(Fx::from_bits(1), Fx::from_bits(1), Fx::from_bits(1));
        assert_eq!(tiny.dot_wide(tiny), 3);
    }

    #[test]
    fn cross_follows_the_right_hand_rule() {
        assert_eq!(Vec3::X.cross(Vec3::Y), Vec3::Z);
        assert_eq!(Vec3::Y.cross(Vec3::X), -Vec3::Z);
    }

    #[test]
    fn normalize_gives_unit_length() {
        let n = v(3.0, 4.0, 0.0).try_normalize().unwrap();
        assert_eq!(n, v(0.6, 0.8, 0.0));
        assert_eq!(Vec3::ZERO.try_normalize(), None);
        assert_eq!(Vec3::ZERO.normalize_or_zero(), Vec3::ZERO);
    }

    #[test]
    fn normalize_is_within_one_unit_of_exact() {
        let mut rng = crate::xorshift::XorShift(0x2545_f491_4f6c_dd1d);
        let mut next = || {
            let seed = rng.next();
            // Components of every magnitude, from a few units of 2⁻¹⁶ to Q16.16's limit.
            let magnitude = (seed >> 59) as u32; // 0..32
            (seed as i64 as i32) >> (31 - magnitude.min(31))
        };
        for _ in 0..100_000 {
            let v = Vec3::new(
                Fx::from_bits(next()),
                Fx::from_bits(next()),
                Fx::from_bits(next()),
            );
            let Some(n) = v.try_normalize() else {
                assert_eq!(v, Vec3::ZERO);
                continue;
            };
            let [x, y, z] = v.to_f64();
            let len = (x * x + y * y + z * z).sqrt();
            for (got, c) in [(n.x, x), (n.y, y), (n.z, z)] {
                let exact = c / len * 65536.0;
                assert!(
                    (got.to_bits() as f64 - exact).abs() <= 1.0,
                    "{v:?}: {got} vs {exact}"
                );
            }
        }
    }

    #[test]
    fn extreme_vectors_neither_wrap_nor_panic() {
        let big = Vec3::new(Fx::MAX, Fx::MIN, Fx::MAX);
        assert_eq!(
            big.length_squared_wide(),
            3 * (1u64 << 62) - 2 * (1u64 << 32) + 2
        );
        assert_eq!(big.dot_wide(big), i64::MAX);
        assert_eq!(big.length(), Fx::MAX);
        let n = big.try_normalize().unwrap();
        let third = Fx::from_num(0.57735);
        assert!((n.x - third).abs() < Fx::from_num(0.0001), "{n:?}");
    }

    /// The extremes of Q16.16, each vector of them, and a few ordinary ones.
    fn extreme_vectors() -> [Vec3; 192] {
        let values = [
            Fx::MIN,
            Fx::MIN + Fx::from_bits(1),
            -Fx::ONE,
            Fx::ZERO,
            Fx::from_bits(1),
            Fx::ONE,
            Fx::MAX - Fx::from_bits(1),
            Fx::MAX,
        ];
        let mut out = [Vec3::ZERO; 192];
        let mut slots = out.iter_mut();
        for &x in &values {
            for &y in &values {
                for &z in &[Fx::MIN, Fx::ZERO, Fx::MAX] {
                    *slots.next().unwrap() = Vec3::new(x, y, z);
                }
            }
        }
        out
    }

    fn exact_dot(a: Vec3, b: Vec3) -> i128 {
        let p = |u: Fx, v: Fx| u.to_bits() as i128 * v.to_bits() as i128;
        p(a.x, b.x) + p(a.y, b.y) + p(a.z, b.z)
    }

    #[test]
    fn dot_saturates_at_the_extremes() {
        let top = Vec3::new(Fx::MAX, Fx::MAX, Fx::MAX);
        let bottom = Vec3::new(Fx::MIN, Fx::MIN, Fx::MIN);
        assert_eq!(top.dot(top), Fx::MAX);
        assert_eq!(bottom.dot(bottom), Fx::MAX);
        assert_eq!(top.dot(bottom), Fx::MIN);
        assert_eq!(bottom.dot_wide(bottom), i64::MAX);
        assert_eq!(top.dot_wide(bottom), i64::MIN);
        // MAX² + MIN² + MIN·MAX = 2⁶² + 2⁶² − 2³¹·… fits: exact, not saturated.
        let mixed = Vec3::new(Fx::MAX, Fx::MIN, Fx::MIN);
        let other = Vec3::new(Fx::MAX, Fx::MIN, Fx::MAX);
        assert_eq!(mixed.dot_wide(other) as i128, exact_dot(mixed, other));
        for &a in &extreme_vectors() {
            for &b in &extreme_vectors() {
                let exact = exact_dot(a, b);
                let wide = exact.clamp(i64::MIN as i128, i64::MAX as i128) as i64;
                assert_eq!(a.dot_wide(b), wide, "{a:?} · {b:?}");
                let rounded = (exact + (1 << 15)) >> 16;
                let narrow = rounded.clamp(i32::MIN as i128, i32::MAX as i128) as i32;
                assert_eq!(a.dot(b).to_bits(), narrow, "{a:?} · {b:?}");
            }
        }
    }

    #[test]
    fn products_at_the_extremes_saturate_to_the_exact_value() {
        let clamp32 = |v: i128| v.clamp(i32::MIN as i128, i32::MAX as i128) as i32;
        let round = |v: i128| (v + (1 << 15)) >> 16;
        for &a in &extreme_vectors() {
            for &b in &extreme_vectors() {
                let c = a.cross(b);
                let p = |u: Fx, v: Fx| u.to_bits() as i128 * v.to_bits() as i128;
                let want = [
                    p(a.y, b.z) - p(a.z, b.y),
                    p(a.z, b.x) - p(a.x, b.z),
                    p(a.x, b.y) - p(a.y, b.x),
                ]
                .map(|v| clamp32(round(v)));
                assert_eq!([c.x, c.y, c.z].map(Fx::to_bits), want, "{a:?} × {b:?}");
                let s = a.scale(b.x);
                let want = [a.x, a.y, a.z].map(|u| clamp32(round(p(u, b.x))));
                assert_eq!([s.x, s.y, s.z].map(Fx::to_bits), want, "{a:?} · {}", b.x);
                let sum = a + b;
                let want = [(a.x, b.x), (a.y, b.y), (a.z, b.z)]
                    .map(|(u, v)| clamp32(u.to_bits() as i128 + v.to_bits() as i128));
                assert_eq!([sum.x, sum.y, sum.z].map(Fx::to_bits), want);
                let diff = a - b;
                let want = [(a.x, b.x), (a.y, b.y), (a.z, b.z)]
                    .map(|(u, v)| clamp32(u.to_bits() as i128 - v.to_bits() as i128));
                assert_eq!([diff.x, diff.y, diff.z].map(Fx::to_bits), want);
            }
            let n = -a;
            let want = [a.x, a.y, a.z].map(|u| clamp32(-(u.to_bits() as i128)));
            assert_eq!([n.x, n.y, n.z].map(Fx::to_bits), want, "−{a:?}");
        }
        // −MIN is one past MAX.
        assert_eq!(
            -Vec3::new(Fx::MIN, Fx::MIN, Fx::MIN),
            Vec3::new(Fx::MAX, Fx::MAX, Fx::MAX)
        );
    }

    #[test]
    fn lengths_and_normals_of_extreme_vectors() {
        for &a in &extreme_vectors() {
            let [x, y, z] = [a.x, a.y, a.z].map(|c| c.to_bits() as f64);
            let exact = (x * x + y * y + z * z).sqrt();
            let want = (exact.floor() as i64).min(i32::MAX as i64) as i32;
            // The exact integer square root of the exact square, saturated.
            assert!((a.length().to_bits() - want).abs() <= 1, "‖{a:?}‖");
            assert!(a.length() >= Fx::ZERO);
            let Some(n) = a.try_normalize() else {
                assert_eq!(a, Vec3::ZERO);
                continue;
            };
            for (got, c) in [(n.x, x), (n.y, y), (n.z, z)] {
                let want = c / exact * 65536.0;
                assert!((got.to_bits() as f64 - want).abs() <= 1.0, "{a:?}: {n:?}");
            }
            assert_eq!(a.normalize_or_zero(), n);
        }
    }

    #[test]
    fn add_saturates() {
        let big = Vec3::new(Fx::MAX, Fx::MIN, Fx::ZERO);
        let sum = big + big;
        assert_eq!((sum.x, sum.y), (Fx::MAX, Fx::MIN));
    }
}
