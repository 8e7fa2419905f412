//! [`DSphere`]: a sphere and the two-step ray-sphere intersection of section 4.4.

use super::{DHit, DRay, DVec3, FAR, Real};

/// A sphere with centre `c` and radius `r > 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DSphere<F: Real = f64> {
    centre: DVec3<F>,
    radius: F,
}

impl<F: Real> DSphere<F> {
    /// The sphere of `radius` about `centre`.
    ///
    /// `None` unless `radius` is finite and greater than zero and `centre` is finite.
    #[must_use]
    pub fn new(centre: DVec3<F>, radius: F) -> Option<Self> {
        if centre.is_finite() && radius.is_finite() && radius > F::ZERO {
            Some(DSphere { centre, radius })
        } else {
            None
        }
    }

    /// The centre `c`.
    #[inline]
    #[must_use]
    pub const fn centre(&self) -> DVec3<F> {
        self.centre
    }

    /// The radius `r`.
    #[inline]
    #[must_use]
    pub const fn radius(&self) -> F {
        self.radius
    }

    /// Where `ray` first meets the sphere, in the chapter's two steps.
    ///
    /// 1. Closest approach: `t_close = u_r·(c − p_r)`, `x_close = p_r + t_close·u_r`, and
    ///    `d² = ‖x_close − c‖²`. If `d² > r²` the ray passes the sphere by: a miss.
    /// 2. Hit: `a = √(r² − d²)` and the ray crosses the surface at `t_close ± a`.
    ///
    /// Which crossing is ahead follows from the quadratic the crossings solve,
    /// `t² − 2·t_close·t + s = 0` with `s = ‖p_r − c‖² − r²`: the product of its roots is `s`.
    /// Outside the sphere (`s > 0`) both have the sign of `t_close`, and the near one,
    /// `t_close − a`, is the hit when they are ahead. Inside (`s < 0`) they straddle the
    /// origin and the ray leaves at `t_close + a`. On the surface (`s = 0`) one root is the
    /// origin itself, which does not count: the other, `2·t_close`, is a hit only when the ray
    /// points into the sphere (`t_close > 0`), so a ray leaving the surface or running along
    /// it misses.
    ///
    /// A hit behind the origin (`t < 0`) or beyond [`FAR`] is a miss. A ray that just grazes
    /// the sphere (`d² = r²`) hits it once, at `x_close`. The hit normal `(x − c)/r` points
    /// outward, even when the ray starts inside. The hit's `object` is 0.
    #[must_use]
    pub fn intersect(&self, ray: &DRay<F>) -> Option<DHit<F>> {
        let t_close = ray.dir().dot(self.centre - ray.origin());
        let x_close = ray.at(t_close);
        let d2 = (x_close - self.centre).length_squared();
        let r2 = self.radius * self.radius;
        if d2 > r2 {
            return None;
        }
        let a = (r2 - d2).sqrt();
        let s = (ray.origin() - self.centre).length_squared() - r2;
        let t = if s > F::ZERO {
            if t_close <= F::ZERO {
                return None;
            }
            t_close - a
        } else if s < F::ZERO || t_close > F::ZERO {
            t_close + a
        } else {
            return None;
        };
        if !(F::ZERO..=F::from_f64(FAR)).contains(&t) {
            return None;
        }
        let point = ray.at(t);
        let normal = (point - self.centre) / self.radius;
        Some(DHit {
            t,
            point,
            normal,
            object: 0,
        })
    }

    /// Where a ray that has just crossed the surface inwards (its origin on the sphere, its
    /// direction into it) leaves the sphere again: the far crossing `t_close + a`.
    ///
    /// [`intersect`](Self::intersect) would decide between the crossings by the sign of
    /// `‖p_r − c‖² − r²`, which for an origin on the surface is rounding; here the ray is
    /// known to be inside. A ray running along the surface (`d² ≥ r²` by rounding) leaves at
    /// once, at `t_close` or 0. The normal points outward, as from `intersect`.
    #[must_use]
    pub fn exit(&self, ray: &DRay<F>) -> DHit<F> {
        let t_close = ray.dir().dot(self.centre - ray.origin());
        let d2 = (ray.at(t_close) - self.centre).length_squared();
        let r2 = self.radius * self.radius;
        let a = if d2 < r2 { (r2 - d2).sqrt() } else { F::ZERO };
        let t = t_close + a;
        let t = if t > F::ZERO { t } else { F::ZERO };
        let point = ray.at(t);
        DHit {
            t,
            point,
            normal: (point - self.centre) / self.radius,
            object: 0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The unit sphere five units down the −z axis.
    fn ahead() -> DSphere {
        DSphere::new(DVec3::new(0.0, 0.0, -5.0), 1.0).unwrap()
    }

    fn down_z(x: f64, y: f64, z: f64) -> DRay {
        DRay::new(DVec3::new(x, y, z), -DVec3::Z).unwrap()
    }

    #[test]
    fn a_central_ray_hits_the_near_side() {
        // t_close = 5, d = 0, a = 1: t = 4 at (0, 0, −4), facing back at the eye.
        let hit = ahead().intersect(&down_z(0.0, 0.0, 0.0)).unwrap();
        assert_eq!(hit.t, 4.0);
        assert_eq!(hit.point, DVec3::new(0.0, 0.0, -4.0));
        assert_eq!(hit.normal, DVec3::Z);
    }

    #[test]
    fn a_tangent_ray_hits_at_x_close() {
        // d = r: a = 0 and the single hit is x_close itself.
        let hit = ahead().intersect(&down_z(0.0, 1.0, 0.0)).unwrap();
        assert_eq!(hit.t, 5.0);
        assert_eq!(hit.point, DVec3::new(0.0, 1.0, -5.0));
        assert_eq!(hit.normal, DVec3::Y);
        assert_eq!(ahead().intersect(&down_z(0.0, 1.5, 0.0)), None);
    }

    #[test]
    fn from_inside_the_ray_leaves_through_the_far_side() {
        // Origin at the centre: t_close − a = −1 < 0, so t = t_close + a = 1.
        let hit = ahead().intersect(&down_z(0.0, 0.0, -5.0)).unwrap();
        assert_eq!(hit.t, 1.0);
        assert_eq!(hit.point, DVec3::new(0.0, 0.0, -6.0));
        assert_eq!(hit.normal, -DVec3::Z, "the normal still points outward");
    }

    #[test]
    fn from_the_surface_only_a_ray_into_the_sphere_meets_it() {
        // The origin on the near pole, (0, 0, −4).
        let out = DRay::new(DVec3::new(0.0, 0.0, -4.0), DVec3::Z).unwrap();
        assert_eq!(ahead().intersect(&out), None, "pointing away");
        let along = DRay::new(DVec3::new(0.0, 0.0, -4.0), DVec3::X).unwrap();
        assert_eq!(ahead().intersect(&along), None, "along the tangent plane");
        let hit = ahead().intersect(&down_z(0.0, 0.0, -4.0)).unwrap();
        assert_eq!(hit.t, 2.0, "through the sphere to the far pole");
        // Slanted in by 45°: the chord to the surface is √2 long.
        let slant = DRay::new(DVec3::new(0.0, 0.0, -4.0), DVec3::new(1.0, 0.0, -1.0)).unwrap();
        let hit = ahead().intersect(&slant).unwrap();
        assert!((hit.t - 2f64.sqrt()).abs() < 1e-12, "{}", hit.t);
    }

    #[test]
    fn a_sphere_behind_the_origin_is_missed() {
        // t_close = −5: both crossings, −6 and −4, are behind the origin.
        let behind = DSphere::new(DVec3::new(0.0, 0.0, 5.0), 1.0).unwrap();
        assert_eq!(behind.intersect(&down_z(0.0, 0.0, 0.0)), None);
    }

    #[test]
    fn hits_beyond_far_are_misses() {
        let far = DSphere::new(DVec3::new(0.0, 0.0, -(FAR + 2.0)), 1.0).unwrap();
        assert_eq!(far.intersect(&down_z(0.0, 0.0, 0.0)), None);
        let edge = DSphere::new(DVec3::new(0.0, 0.0, -(FAR + 1.0)), 1.0).unwrap();
        assert_eq!(
            edge.intersect(&down_z(0.0, 0.0, 0.0)).map(|h| h.t),
            Some(FAR)
        );
    }

    #[test]
    fn the_radius_must_be_positive() {
        assert_eq!(DSphere::new(DVec3::ZERO, 0.0), None);
        assert_eq!(DSphere::new(DVec3::ZERO, -1.0), None);
        assert_eq!(DSphere::new(DVec3::ZERO, f64::NAN), None);
    }
}
