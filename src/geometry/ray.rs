//! [`Ray`]: the chapter's ray `x(t) = p_r + t·u_r` (Eq. 4.1).

use crate::check;
use crate::error::{Error, Quantity};
use crate::numbers::fx::Fx;
use crate::numbers::vec3::Vec3;

/// A ray: an origination point `p_r` and a unit direction `u_r`.
///
/// Every point on the ray is `x(t) = p_r + t·u_r` for a distance `t ≥ 0` (Eq. 4.1). The
/// origin lies within ±[`LIMIT`](crate::LIMIT) and the direction is a unit vector, as
/// [`Ray::new`] and the [`Camera`](crate::Camera) make them.
///
/// A ray also keeps the direction it was made along before normalising, `w` (a camera's ray
/// points at a pixel of its screen): its hits on planes are worked out along `w`, which is
/// exact, rather than along the rounded `u_r` (see [`Plane::intersect`](crate::Plane)). Two
/// rays are equal when all three are.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Ray {
    pub(crate) origin: Vec3,
    pub(crate) dir: Vec3,
    /// The direction before normalising, `u_r` times a positive length, each component at most
    /// 2³⁰ in raw units (a camera's rays stay within its ray budget; other rays keep `u_r`).
    pub(crate) w: Vec3,
}

impl Ray {
    /// A ray from `origin` along `dir`, which is normalised here.
    ///
    /// The origin must lie within ±[`LIMIT`](crate::LIMIT); a zero direction is an error.
    ///
    /// ```
    /// use fixray::{Fx, Ray, Vec3};
    /// // The chapter's example: from (1, 1) along +x.
    /// let ray = Ray::new(Vec3::from_ints(1, 1, 0), Vec3::from_ints(5, 0, 0)).unwrap();
    /// assert_eq!(ray.dir(), Vec3::X);
    /// assert_eq!(ray.at(Fx::from_num(3)), Vec3::from_ints(4, 1, 0));
    /// ```
    pub const fn new(origin: Vec3, dir: Vec3) -> Result<Self, Error> {
        let origin = match check::point(origin, Quantity::RayOrigin) {
            Ok(origin) => origin,
            Err(e) => return Err(e),
        };
        match check::direction(dir, Quantity::RayDirection) {
            Ok(dir) => Ok(Ray {
                origin,
                dir,
                w: dir,
            }),
            Err(e) => Err(e),
        }
    }

    /// A ray from a hit point, as the renderer's shadow and mirror rays leave one: the origin
    /// may lie anywhere a first hit can (within ±(`LIMIT` + `FAR`)), the direction is
    /// normalised here. For tests that repeat the renderer's secondary rays by brute force.
    #[cfg(feature = "internals")]
    pub(crate) const fn from_hit_point(origin: Vec3, dir: Vec3) -> Result<Self, Error> {
        let bound = crate::numbers::fx::HIT_REACH;
        if !origin.within_raw(bound) {
            return Err(Error::OutOfRange {
                quantity: Quantity::RayOrigin,
                min: Fx::from_bits(-bound),
                max: Fx::from_bits(bound),
            });
        }
        match check::direction(dir, Quantity::RayDirection) {
            Ok(dir) => Ok(Ray {
                origin,
                dir,
                w: dir,
            }),
            Err(e) => Err(e),
        }
    }

    /// The origination point `p_r`.
    #[must_use]
    pub const fn origin(&self) -> Vec3 {
        self.origin
    }

    /// The unit direction `u_r`.
    #[must_use]
    pub const fn dir(&self) -> Vec3 {
        self.dir
    }

    /// A ray whose direction the caller promises is already a unit vector, as
    /// [`Vec3::try_normalize`] gives it: within a few units of 2⁻¹⁶ of length 1. Debug
    /// builds check that promise.
    #[inline]
    #[must_use]
    pub(crate) const fn new_unchecked(origin: Vec3, dir: Vec3) -> Self {
        debug_assert!(
            is_unit(dir),
            "Ray::new_unchecked: the direction is not a unit vector"
        );
        Ray {
            origin,
            dir,
            w: dir,
        }
    }

    /// A ray made along `w` (components at most 2³⁰ in raw units), whose normalised direction
    /// is `dir`, as the camera makes its rays: planes are met along `w`.
    #[inline]
    #[must_use]
    pub(crate) const fn along(origin: Vec3, dir: Vec3, w: Vec3) -> Self {
        debug_assert!(
            w.within_raw(1 << 30),
            "Ray::along: the direction is outside the ray budget"
        );
        Ray { origin, dir, w }
    }

    /// The point at distance `t` along the ray: `p_r + t·u_r`, each component saturating at
    /// the ends of Q16.16.
    #[inline]
    #[must_use]
    pub fn at(&self, t: Fx) -> Vec3 {
        self.origin + self.dir.scale(t)
    }

    /// [`Ray::at`] for a hit's distance (within ±[`FAR`](crate::FAR)) along a unit direction:
    /// the same point, for products without a saturation check.
    #[inline]
    pub(crate) fn at_hit(&self, t: Fx) -> Vec3 {
        self.origin.plus(self.dir.scale_unit(t))
    }
}

/// Whether `dir` has length 1 within the rounding of [`Vec3::try_normalize`]: each component
/// within a unit of 2⁻¹⁶ of exact puts the squared length within 2⁻¹⁴ of 1; 2⁻¹² leaves room.
pub(crate) const fn is_unit(dir: Vec3) -> bool {
    let one = 1u64 << 32; // 1 in Q32.32
    dir.length_squared_wide().abs_diff(one) <= one >> 12
}
