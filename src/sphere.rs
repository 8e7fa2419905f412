//! [`Sphere`] and the chapter's two-step ray–sphere intersection (section 4.4).

use crate::error::Error;
use crate::fx::{self, FAR, FRAC, Fx};
use crate::hit::Hit;
use crate::isqrt::isqrt;
use crate::ray::Ray;
use crate::vec3::Vec3;

/// A sphere with centre `c` and radius `r > 0`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Sphere {
    centre: Vec3,
    radius: Fx,
    /// `2^(31 + inv_shift) / r` in raw units, in `(2³⁰, 2³¹)`: the normal `(x − c)/r` is a
    /// multiplication by it instead of three divisions.
    inv_radius: i32,
    inv_shift: u32,
}

impl Sphere {
    /// A sphere, checked: the radius must be positive and at most [`LIMIT`](crate::LIMIT), the centre within
    /// ±`LIMIT`.
    ///
    /// ```
    /// use fixray::{Error, Fx, Sphere, Vec3};
    /// assert!(Sphere::new(Vec3::from_ints(-3, 0, -16), Fx::from_num(2)).is_ok());
    /// assert_eq!(
    ///     Sphere::new(Vec3::ZERO, Fx::ZERO),
    ///     Err(Error::NonPositiveRadius)
    /// );
    /// ```
    pub fn new(centre: Vec3, radius: Fx) -> Result<Self, Error> {
        let centre = centre.check_range("sphere centre")?;
        if radius <= Fx::ZERO {
            return Err(Error::NonPositiveRadius);
        }
        fx::check_range(radius, "sphere radius")?;
        Ok(Sphere::new_unchecked(centre, radius))
    }

    /// A sphere whose values the caller promises are valid (`0 < radius ≤ 1024`, centre
    /// within ±1024). For `const` scenes.
    #[must_use]
    pub const fn new_unchecked(centre: Vec3, radius: Fx) -> Self {
        // r in raw units lies in [2^k, 2^(k+1)); 2^(31+k)/r then lies in (2³⁰, 2³¹].
        let r = if radius.to_bits() > 0 {
            radius.to_bits() as u64
        } else {
            1
        };
        let k = 63 - r.leading_zeros();
        let inv = (1u64 << (31 + k)) / r;
        Sphere {
            centre,
            radius,
            inv_radius: if inv > i32::MAX as u64 {
                i32::MAX
            } else {
                inv as i32
            },
            inv_shift: k,
        }
    }

    /// The centre `c`.
    #[must_use]
    pub const fn centre(&self) -> Vec3 {
        self.centre
    }

    /// The radius `r`.
    #[must_use]
    pub const fn radius(&self) -> Fx {
        self.radius
    }

    /// Where `ray` first meets the sphere, by the chapter's two steps.
    ///
    /// 1. The closest approach: `t_close = u_r·(c − p_r)`, `x_close = p_r + t_close·u_r`,
    ///    `d = ‖x_close − c‖`. If `d > r` there is no hit.
    /// 2. Otherwise `a = √(r² − d²)` and the nearest hit is at `t_close − a`.
    ///
    /// What the chapter leaves open: a ray whose origin is inside the sphere has
    /// `t_close − a < 0` and leaves through `t_close + a`; a sphere wholly behind the origin
    /// (both negative) is a miss, as is a hit beyond [`FAR`]; a tangent ray (`d = r`) hits at
    /// `x_close`. `d²` and `r²` are compared exactly at 64 bits.
    ///
    /// ```
    /// use fixray::{Fx, Ray, Sphere, Vec3};
    /// let ball = Sphere::new(Vec3::from_ints(0, 0, -10), Fx::from_num(2)).unwrap();
    /// let ray = Ray::new(Vec3::ZERO, -Vec3::Z).unwrap();
    /// let hit = ball.intersect(&ray).unwrap();
    /// assert_eq!(hit.t, Fx::from_num(8));
    /// assert_eq!(hit.normal, Vec3::Z);
    /// ```
    #[must_use]
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let t = self.hit_distance(ray)?;
        Some(self.hit_at(ray, t))
    }

    /// The `t` of [`Sphere::intersect`] alone, without the hit point and normal: what the
    /// scene needs to find the nearest object and to test shadow rays.
    #[must_use]
    pub fn hit_distance(&self, ray: &Ray) -> Option<Fx> {
        let to_centre = self.centre - ray.origin;
        let t_close = ray.dir.dot_exact(to_centre);
        if t_close < -self.radius {
            return None; // wholly behind the origin
        }
        if t_close > FAR + self.radius {
            return None; // every hit would lie beyond t_close − r > FAR
        }
        // x_close − c = t_close·u_r − (c − p_r)
        let d2 = (ray.dir.scale_unit(t_close) - to_centre).length_squared_wide();
        let r2 = fx::wide_mul(self.radius.to_bits(), self.radius.to_bits()).unsigned_abs();
        if d2 > r2 {
            return None;
        }
        // r² − d² ≤ r² ≤ 2²⁰·2³², so a fits Q16.16.
        let a = Fx::from_bits(isqrt(r2 - d2) as i32);
        let mut t = t_close - a;
        if t < Fx::ZERO {
            t = t_close + a; // the origin is inside the sphere
        }
        if t < Fx::ZERO || t > FAR {
            return None;
        }
        Some(t)
    }

    /// The hit at distance `t` along `ray`: its point and outward normal.
    #[must_use]
    pub fn hit_at(&self, ray: &Ray, t: Fx) -> Hit {
        let point = ray.at_hit(t);
        Hit {
            t,
            point,
            normal: self.normal_at(point),
            object: 0,
        }
    }

    /// The outward unit normal `(x − c) / r` at a point `x` on the surface, as a
    /// multiplication by the reciprocal radius kept since construction.
    #[must_use]
    pub fn normal_at(&self, x: Vec3) -> Vec3 {
        let shift = FRAC - 1 + self.inv_shift; // (v·2^(31+k)/r) / 2^(15+k) = v·2¹⁶/r
        let scale = |c: Fx| {
            let q = fx::mul_shift_round(c.to_bits(), self.inv_radius, shift);
            // A point within rounding of the surface gives |q| ≤ 2¹⁶ plus a few units.
            Fx::from_bits(q.clamp(-(1 << FRAC), 1 << FRAC) as i32)
        };
        let v = x - self.centre;
        Vec3::new(scale(v.x), scale(v.y), scale(v.z))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ball() -> Sphere {
        Sphere::new(Vec3::from_ints(0, 0, -10), Fx::from_num(2)).unwrap()
    }

    fn ray(o: Vec3, d: Vec3) -> Ray {
        Ray::new(o, d).unwrap()
    }

    #[test]
    fn origin_inside_leaves_through_the_far_side() {
        let hit = ball()
            .intersect(&ray(Vec3::from_ints(0, 0, -10), -Vec3::Z))
            .unwrap();
        assert_eq!(hit.t, Fx::from_num(2));
        assert_eq!(hit.point, Vec3::from_ints(0, 0, -12));
    }

    #[test]
    fn sphere_behind_the_origin_is_a_miss() {
        assert!(ball().intersect(&ray(Vec3::ZERO, Vec3::Z)).is_none());
    }

    #[test]
    fn tangent_ray_hits_at_closest_approach() {
        let hit = ball()
            .intersect(&ray(Vec3::from_ints(2, 0, 0), -Vec3::Z))
            .unwrap();
        assert_eq!(hit.t, Fx::from_num(10));
        assert_eq!(hit.normal, Vec3::X);
    }

    #[test]
    fn ray_passing_outside_is_a_miss() {
        let beside = Vec3::new(Fx::from_num(2) + Fx::from_bits(1), Fx::ZERO, Fx::ZERO);
        assert!(ball().intersect(&ray(beside, -Vec3::Z)).is_none());
    }

    #[test]
    fn invalid_spheres_are_refused() {
        assert_eq!(
            Sphere::new(Vec3::ZERO, Fx::from_num(-1)),
            Err(Error::NonPositiveRadius)
        );
        assert!(matches!(
            Sphere::new(Vec3::from_ints(0, 2000, 0), Fx::ONE),
            Err(Error::OutOfRange {
                what: "sphere centre",
                ..
            })
        ));
        assert!(matches!(
            Sphere::new(Vec3::ZERO, Fx::from_num(1500)),
            Err(Error::OutOfRange {
                what: "sphere radius",
                ..
            })
        ));
    }
}
