//! [`Plane`] and ray–plane intersection (section 4.3, Eq. 4.2).

use crate::check;
use crate::error::{Error, Quantity};
use crate::geometry::hit::Hit;
use crate::geometry::ray::Ray;
use crate::numbers::fx;
use crate::numbers::fx::{FAR, Fx};
use crate::numbers::reciprocal::{Mantissa, Scale, inverse};
use crate::numbers::vec3::Vec3;

/// An infinite plane through a point `p0` with unit normal `n`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Plane {
    point: Vec3,
    normal: Vec3,
    /// `[min, max]` in [`Plane::coords`], for a bounded rectangle.
    bounds: Option<[[Fx; 2]; 2]>,
}

impl Plane {
    /// A plane through `point` facing `normal` (normalised here), checked: the point within
    /// ±[`LIMIT`](crate::LIMIT), the normal not zero.
    ///
    /// ```
    /// use fixray::{Error, Plane, Quantity, Vec3};
    /// let ground = Plane::new([0.0, -4.0, 0.0], [0.0, 3.0, 0.0])?;
    /// assert_eq!(ground.normal(), Vec3::Y);
    /// assert_eq!(
    ///     Plane::new([0.0; 3], [0.0; 3]),
    ///     Err(Error::ZeroVector { quantity: Quantity::PlaneNormal })
    /// );
    /// # Ok::<(), Error>(())
    /// ```
    pub fn new(point: [f32; 3], normal: [f32; 3]) -> Result<Self, Error> {
        Plane::from_fx(
            check::f32_point(point, Quantity::PlanePoint)?,
            check::f32_point(normal, Quantity::PlaneNormal)?,
        )
    }

    /// [`Plane::new`] in fixed point, for `const` and `static` scenes: the same checks, at
    /// compile time when the values are constants.
    pub const fn from_fx(point: Vec3, normal: Vec3) -> Result<Self, Error> {
        let point = match check::point(point, Quantity::PlanePoint) {
            Ok(point) => point,
            Err(e) => return Err(e),
        };
        match check::direction(normal, Quantity::PlaneNormal) {
            Ok(normal) => Ok(Plane {
                point,
                normal,
                bounds: None,
            }),
            Err(e) => Err(e),
        }
    }

    /// The same plane cut down to the rectangle `min ≤ (u, v) ≤ max` in its own coordinates
    /// ([`Plane::coords`]); rays that meet the plane outside it miss.
    ///
    /// The corners must lie within ±[`LIMIT`](crate::LIMIT) ([`Error::OutOfRange`]) and `min`
    /// below `max` on both axes ([`Error::EmptyBounds`]).
    ///
    /// ```
    /// use fixray::{Error, Plane, Ray, Vec3};
    /// // The classic floor: y = −4 for |x| < 10 and −30 < z < −10.
    /// let floor = Plane::new([0.0, -4.0, 0.0], [0.0, 1.0, 0.0])?
    ///     .bounded([-10.0, -30.0], [10.0, -10.0])?;
    /// let down = |z: i16| Ray::new(Vec3::from_ints(0, 0, z), -Vec3::Y).unwrap();
    /// assert!(floor.intersect(&down(-20)).is_some());
    /// assert!(floor.intersect(&down(-5)).is_none());
    /// // A strip of no width encloses nothing.
    /// assert_eq!(
    ///     Plane::new([0.0; 3], [0.0, 1.0, 0.0])?.bounded([0.0, 0.0], [0.0, 1.0]),
    ///     Err(Error::EmptyBounds)
    /// );
    /// # Ok::<(), Error>(())
    /// ```
    pub fn bounded(self, min: [f32; 2], max: [f32; 2]) -> Result<Self, Error> {
        let corner = |c: [f32; 2]| -> Result<[Fx; 2], Error> {
            Ok([
                check::f32_coordinate(c[0], Quantity::PlaneBounds)?,
                check::f32_coordinate(c[1], Quantity::PlaneBounds)?,
            ])
        };
        self.bounded_fx(corner(min)?, corner(max)?)
    }

    /// [`Plane::bounded`] in fixed point, for `const` and `static` scenes.
    pub const fn bounded_fx(self, min: [Fx; 2], max: [Fx; 2]) -> Result<Self, Error> {
        let corners = [min[0], min[1], max[0], max[1]];
        let mut i = 0;
        while i < 4 {
            if let Err(e) = check::coordinate(corners[i], Quantity::PlaneBounds) {
                return Err(e);
            }
            i += 1;
        }
        if min[0].to_bits() >= max[0].to_bits() || min[1].to_bits() >= max[1].to_bits() {
            return Err(Error::EmptyBounds);
        }
        Ok(Plane {
            bounds: Some([min, max]),
            point: self.point,
            normal: self.normal,
        })
    }

    /// The two world coordinates that lie across the plane: those left when the axis the
    /// normal is closest to is dropped — `(x, z)` for a floor, `(x, y)` for a wall facing ±z,
    /// `(y, z)` for a wall facing ±x. Bounds and checkerboards are measured in them.
    #[must_use]
    pub fn coords(&self, x: Vec3) -> [Fx; 2] {
        let (nx, ny, nz) = (
            self.normal.x.abs(),
            self.normal.y.abs(),
            self.normal.z.abs(),
        );
        if ny >= nx && ny >= nz {
            [x.x, x.z]
        } else if nz >= nx {
            [x.x, x.y]
        } else {
            [x.y, x.z]
        }
    }

    /// The rectangle the plane is cut to, `[min, max]` in [`Plane::coords`], if any.
    #[must_use]
    pub const fn bounds(&self) -> Option<[[Fx; 2]; 2]> {
        self.bounds
    }

    /// The point `p0` the plane passes through.
    #[must_use]
    pub const fn point(&self) -> Vec3 {
        self.point
    }

    /// The unit normal `n`.
    #[must_use]
    pub const fn normal(&self) -> Vec3 {
        self.normal
    }

    /// The perpendicular distance `d = n·(x − p0)` of a point from the plane: positive above
    /// (on the side `n` points to), negative below.
    #[must_use]
    pub fn distance(&self, x: Vec3) -> Fx {
        self.normal.dot(x - self.point)
    }

    /// Where `ray` meets the plane: `t = −n·(p_r − p0) / (n·u_r)` (Eq. 4.2).
    ///
    /// The hit is worked out along the direction the ray was made along, `w` (for a camera's
    /// ray, towards its pixel; for any other, `u_r` itself): the point is
    /// `p_r + s·w` with `s = −n·(p_r − p0) / (n·w)`, the same point as `p_r + t·u_r`, without
    /// the rounding of `u_r` in it. `s` is a quotient good to 27 bits, so the point is
    /// within a unit of 2⁻¹⁶ and `t·2⁻²⁷` of the exact one; `t` is the distance of its
    /// projection on the ray, `s·(w·u_r)/‖u_r‖`.
    ///
    /// A ray parallel to the plane (`n·w = 0`), one whose hit lies behind its origin, one
    /// whose hit lies beyond [`FAR`] and one that starts on the plane (`n·(p_r − p0) = 0`
    /// exactly: it leaves the plane or runs along it) all miss. The division happens only
    /// once the hit is known to be in front, and the point is made only once it is known to
    /// be within `FAR`, so nothing divides by zero or overflows. The normal of the hit faces
    /// the ray: planes are two-sided. A bounded plane misses outside its rectangle.
    ///
    /// ```
    /// use fixray::{Plane, Ray, Vec3};
    /// // The chapter's wall whose front face is at x = 4, and its ray from (1, 1) along +x.
    /// let wall = Plane::new([4.0, 0.0, 0.0], [-1.0, 0.0, 0.0])?;
    /// let hit = wall.intersect(&Ray::new(Vec3::from_ints(1, 1, 0), Vec3::X)?).unwrap();
    /// assert_eq!(hit.t(), 3);
    /// assert_eq!(hit.point(), Vec3::from_ints(4, 1, 0));
    /// // A ray parallel to the wall misses.
    /// assert!(wall.intersect(&Ray::new(Vec3::ZERO, Vec3::Y)?).is_none());
    /// # Ok::<(), fixray::Error>(())
    /// ```
    #[must_use]
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        self.hit_from(ray, &self.numerator(ray.origin))
    }

    /// The `t` of [`Plane::intersect`] alone, a shadow ray's question: the same steps, the
    /// hit point made only where the plane's bounds need it, the normal not at all.
    pub(crate) fn hit_distance(&self, ray: &Ray) -> Option<Fx> {
        let scale = self.reach(ray, &self.numerator(ray.origin))?;
        if self.bounds.is_some() {
            self.bounded_at(ray.origin.plus(offset(scale, ray.w)))?;
        }
        Some(distance(scale, ray.w, ray.dir))
    }

    /// `−n·(p_r − p0)`, the numerator of Eq. 4.2, exactly in Q32.32: it depends on the
    /// ray's origin alone, so rays that share one (a camera's) can share it.
    pub(crate) fn numerator(&self, origin: Vec3) -> Numerator {
        let value = -self.normal.dot_wide_exact(origin - self.point);
        Numerator {
            value,
            mantissa: if value == 0 {
                Mantissa::ZERO
            } else {
                Mantissa::new(value.unsigned_abs())
            },
        }
    }

    /// [`Plane::intersect`] given `num`, which must be `self.numerator(ray.origin)`.
    pub(crate) fn hit_from(&self, ray: &Ray, num: &Numerator) -> Option<Hit> {
        let scale = self.reach(ray, num)?;
        let point = self.bounded_at(ray.origin.plus(offset(scale, ray.w)))?;
        Some(Hit {
            t: distance(scale, ray.w, ray.dir),
            point,
            normal: self.facing(num),
        })
    }

    /// The scale `s` of the hit `p_r + s·w` of a ray from the origin of `num`, if the plane
    /// lies ahead within [`FAR`] (its bounds are the caller's to check).
    fn reach(&self, ray: &Ray, num: &Numerator) -> Option<Scale> {
        let scale = self.scale_along(num, self.normal.dot_wide_exact(ray.w))?;
        within_far(scale, ray.w.length_squared_wide()).then_some(scale)
    }

    /// `s = −n·(p_r − p0) / (n·w)` for a direction `w` with `n·w = den` (exact, in Q32.32),
    /// if the plane lies ahead: the ray is not parallel to it, does not start on it, and
    /// points towards it.
    #[inline]
    pub(crate) fn scale_along(&self, num: &Numerator, den: i64) -> Option<Scale> {
        let value = num.value;
        if den == 0 || value == 0 || (value < 0) != (den < 0) {
            return None;
        }
        Some(num.mantissa.over(den.unsigned_abs()))
    }

    /// `point` if it lies within the plane's bounds (always, for an unbounded plane).
    #[inline]
    pub(crate) fn bounded_at(&self, point: Vec3) -> Option<Vec3> {
        if let Some([min, max]) = self.bounds {
            let [u, v] = self.coords(point);
            if u < min[0] || u > max[0] || v < min[1] || v > max[1] {
                return None;
            }
        }
        Some(point)
    }

    /// The plane's normal facing rays from the origin of `num` that meet it: such a ray has
    /// `n·w` of the numerator's sign, so the normal is turned exactly when that is positive.
    #[inline]
    pub(crate) fn facing(&self, num: &Numerator) -> Vec3 {
        if num.value > 0 {
            -self.normal
        } else {
            self.normal
        }
    }
}

/// Whether a hit at `s·w`, `s = scale`, on a ray whose `‖w‖²` is `square` (Q32.32) lies
/// within [`FAR`]: `square ≤ far_reach(scale)`.
///
/// Most hits lie well inside: where `square < 2^b` with `b + 63 ≤ 58 + 2·shift`, the product
/// `square · m²` is below half of `2^(58 + 2·shift)` (as `m² < 2⁶²`), so `square` is below
/// half the exact reach, and so below `far_reach`, which lies within 2⁻²⁵ of it. That is
/// decided by a bit length, without the reciprocal.
#[inline]
pub(crate) fn within_far(scale: Scale, square: u64) -> bool {
    (fx::bit_length(square) as i32 + 63 <= FAR_SQUARED_BITS + 2 * scale.shift)
        || square <= far_reach(scale)
}

/// FAR² is `2^FAR_SQUARED_BITS` in Q32.32.
const FAR_SQUARED_BITS: i32 = 2 * (FAR.to_bits().trailing_zeros() as i32);

/// The largest `‖w‖²` (Q32.32) for which a hit at `s·w`, `s = scale`, counts as within
/// [`FAR`]: `(FAR/s)²`, as `2^(58 + 2·shift) / m²` (FAR is 2²⁹ raw units) with `1/m` from
/// `reciprocal::inverse` less 4 units of its 2³⁰, below the exact reciprocal. So the bound
/// lies inside the exact one by at most about 2⁻²⁶ of it, and a hit that passes has
/// `‖s·w‖ ≤ FAR`. One
/// reciprocal, a square and a shift: a whole row that shares `s` shares the bound. A scale
/// with no fractional bits (`shift ≤ 0`, `s ≥ 2²⁹`) reaches nothing: it would need `‖w‖`
/// below 2⁻¹⁶, shorter than any ray's direction. It is rarely needed per ray (see
/// [`within_far`]).
pub(crate) fn far_reach(scale: Scale) -> u64 {
    if scale.shift <= 0 {
        return 0;
    }
    // 1/m ≈ y · 2^−(30 + bits), y in [2³⁰, 2³¹]: 1/m² ≈ y² · 2^−(60 + 2·bits).
    let (y, bits) = inverse(scale.m as u64);
    let y = (y - 4) as u64; // y ≥ 2³⁰
    let y2 = y * y;
    let exponent = FAR_SQUARED_BITS + 2 * scale.shift - 60 - 2 * bits as i32;
    if exponent >= 0 {
        // y² is about 2⁶⁰ or more: a shift of 4 or more leaves u64, and 0..=3 may.
        if exponent >= 4 || y2 > u64::MAX >> exponent {
            u64::MAX
        } else {
            y2 << exponent
        }
    } else if exponent > -64 {
        y2 >> -exponent
    } else {
        0
    }
}

/// `s·w`, each component rounded to nearest, for a scale that passed [`within_far`]: every
/// component is at most FAR, and `w`'s at most 2³⁰ times `m` below 2³¹ fits 64 bits.
#[inline]
pub(crate) fn offset(scale: Scale, w: Vec3) -> Vec3 {
    let c = |c: Fx| {
        Fx::from_bits(if scale.shift >= 64 {
            0 // |c·m| < 2⁶¹: rounds to zero
        } else {
            fx::mul_shift_round(c.to_bits(), scale.m, scale.shift as u32) as i32
        })
    };
    Vec3::new(c(w.x), c(w.y), c(w.z))
}

/// The distance `t` along the ray's unit direction `u` (`dir`) to the hit at `s·w`
/// (`s = scale`): `s·(w·u)/‖u‖`, the distance to the hit's projection on the ray, which for
/// a ray made along `u` (`w = u`) is the exact distance to where `u` meets the plane, as
/// rounded here. `1/‖u‖` is `1 + (1 − u·u)/2` to 2⁻²⁸ (`u·u` is within 2⁻¹⁴ of 1); `w·u` is
/// kept in Q32.32 until the product with `s`, rounded once. Never negative.
#[inline]
pub(crate) fn distance(scale: Scale, w: Vec3, dir: Vec3) -> Fx {
    // Both exact: |w·u| < 2⁴⁷ (w within 2³⁰ a component), |1 − u·u| < 2¹⁹ in Q32.32.
    let along = w.dot_wide_exact(dir);
    let excess = (1i64 << 32) - dir.length_squared_wide() as i64;
    let along = along + (((along >> 16) * excess) >> 17);
    if along <= 0 || !(1..64).contains(&scale.shift) {
        return Fx::ZERO;
    }
    // t in raw units is along·m·2^−(shift + 16): along's high part (below 2³¹) times m, and
    // its low 16 bits times m shifted down, below 2⁶² + 2³¹ together.
    let (high, low) = ((along >> 16) as u64, (along & 0xffff) as u64);
    let m = scale.m as u64;
    let product = high * m + ((low * m) >> 16);
    let shift = scale.shift as u32;
    Fx::from_bits(((product + (1 << (shift - 1))) >> shift) as i32)
}

/// A plane's numerator of Eq. 4.2 for rays from one origin ([`Plane::numerator`]), with its
/// magnitude made ready for division by each ray's denominator.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Numerator {
    /// `−n·(p_r − p0)` in Q32.32.
    pub(crate) value: i64,
    mantissa: Mantissa,
}

impl Numerator {
    /// For objects that are not planes.
    pub(crate) const NONE: Numerator = Numerator {
        value: 0,
        mantissa: Mantissa::ZERO,
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ray(o: [f32; 3], d: [f32; 3]) -> Ray {
        Ray::new(
            crate::check::f32_point(o, Quantity::RayOrigin).unwrap(),
            crate::check::f32_point(d, Quantity::RayDirection).unwrap(),
        )
        .unwrap()
    }

    #[test]
    fn distance_sign_tells_the_side() {
        let ground = Plane::from_fx(Vec3::from_ints(0, -4, 0), Vec3::Y).unwrap();
        assert_eq!(ground.distance(Vec3::ZERO), Fx::from_num(4));
        assert_eq!(ground.distance(Vec3::from_ints(3, -6, 1)), Fx::from_num(-2));
    }

    #[test]
    fn hit_behind_the_origin_is_a_miss() {
        let ground = Plane::from_fx(Vec3::from_ints(0, -4, 0), Vec3::Y).unwrap();
        assert!(
            ground
                .intersect(&ray([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]))
                .is_none()
        );
        assert!(
            ground
                .intersect(&ray([0.0, 0.0, 0.0], [0.0, -1.0, 0.0]))
                .is_some()
        );
    }

    #[test]
    fn nearly_parallel_ray_beyond_far_is_a_miss_not_an_overflow() {
        let ground = Plane::from_fx(Vec3::from_ints(0, -4, 0), Vec3::Y).unwrap();
        // One Q16.16 unit downward: the hit would be 4 · 2¹⁶ away.
        let r = Ray::new_unchecked(Vec3::ZERO, Vec3::new(Fx::ZERO, Fx::from_bits(-1), -Fx::ONE));
        assert!(ground.intersect(&r).is_none());
    }

    #[test]
    fn the_normal_faces_the_ray() {
        let ground = Plane::from_fx(Vec3::from_ints(0, -4, 0), Vec3::Y).unwrap();
        let from_below = ray([0.0, -8.0, 0.0], [0.0, 1.0, 0.0]);
        assert_eq!(ground.intersect(&from_below).unwrap().normal, -Vec3::Y);
    }
}
