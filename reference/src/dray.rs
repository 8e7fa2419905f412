//! [`DRay`]: the chapter's ray, Equation 4.1.

use super::{DVec3, Real};

/// A ray: an origination point `p_r` and a unit direction `u_r`.
///
/// The points on the ray are `x(t) = p_r + t·u_r` for `t ≥ 0` (Equation 4.1). Because `u_r`
/// is a unit vector, `t` is the distance from `p_r` to `x(t)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DRay<F: Real = f64> {
    origin: DVec3<F>,
    dir: DVec3<F>,
}

impl<F: Real> DRay<F> {
    /// The ray from `origin` in the direction of `toward`, which is normalised here.
    ///
    /// `None` if `toward` has no direction (zero or not finite) or `origin` is not finite.
    #[must_use]
    pub fn new(origin: DVec3<F>, toward: DVec3<F>) -> Option<Self> {
        if !origin.is_finite() {
            return None;
        }
        let dir = toward.try_normalize()?;
        Some(DRay { origin, dir })
    }

    /// The ray from `origin` along `dir`, which the caller promises is a unit vector.
    #[inline]
    #[must_use]
    pub const fn new_unchecked(origin: DVec3<F>, dir: DVec3<F>) -> Self {
        DRay { origin, dir }
    }

    /// The origination point `p_r`.
    #[inline]
    #[must_use]
    pub const fn origin(&self) -> DVec3<F> {
        self.origin
    }

    /// The unit direction `u_r`.
    #[inline]
    #[must_use]
    pub const fn dir(&self) -> DVec3<F> {
        self.dir
    }

    /// The point `x(t) = p_r + t·u_r` at distance `t` along the ray (Equation 4.1).
    #[inline]
    #[must_use]
    pub fn at(&self, t: F) -> DVec3<F> {
        self.origin + self.dir * t
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_chapter_example_reaches_the_wall_at_t_3() {
        // p_r = (1, 1), u_r parallel to the x axis: the wall face x = 4 is at t = 3.
        let ray = DRay::new(DVec3::new(1.0, 1.0, 0.0), DVec3::X).unwrap();
        assert_eq!(ray.at(3.0), DVec3::new(4.0, 1.0, 0.0));
        assert_eq!(ray.at(0.0), ray.origin());
    }

    #[test]
    fn the_direction_is_made_unit() {
        let ray = DRay::new(DVec3::ZERO, DVec3::new(0.0, 0.0, -7.0)).unwrap();
        assert_eq!(ray.dir(), -DVec3::Z);
        assert_eq!(DRay::new(<DVec3>::ZERO, DVec3::ZERO), None);
        assert_eq!(
            DRay::new(DVec3::new(f64::INFINITY, 0.0, 0.0), DVec3::X),
            None
        );
    }
}
