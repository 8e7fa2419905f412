//! [`DPlane`]: an infinite plane and the ray-plane intersection of Equation 4.2.

use super::{DHit, DRay, DVec3, FAR};

/// An infinite plane through the point `p_0` with unit normal `n` (section 4.3).
///
/// The plane is two-sided: it can be hit from either side, and the normal of a hit is `n` or
/// `-n`, whichever faces back along the ray.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DPlane {
    point: DVec3,
    normal: DVec3,
}

impl DPlane {
    /// The plane through `point` perpendicular to `normal`, which is normalised here.
    ///
    /// Normalising in `f64` means a plane built from the fixed renderer's (nearly unit) Q16.16
    /// normal gets the exact unit normal in that direction. `None` if `normal` has no
    /// direction or `point` is not finite.
    #[must_use]
    pub fn new(point: DVec3, normal: DVec3) -> Option<DPlane> {
        if !point.is_finite() {
            return None;
        }
        let normal = normal.try_normalize()?;
        Some(DPlane { point, normal })
    }

    /// The point `p_0` the plane was built through.
    #[inline]
    #[must_use]
    pub const fn point(&self) -> DVec3 {
        self.point
    }

    /// The unit normal `n`.
    #[inline]
    #[must_use]
    pub const fn normal(&self) -> DVec3 {
        self.normal
    }

    /// The signed distance `d = n · (x − p_0)` of `x` from the plane: positive on the side `n`
    /// points to, negative on the other, zero on the plane.
    #[inline]
    #[must_use]
    pub fn distance(&self, x: DVec3) -> f64 {
        self.normal.dot(x - self.point)
    }

    /// Where `ray` meets the plane, by Equation 4.2: `t = −n·(p_r − p_0) / (n·u_r)`.
    ///
    /// A ray parallel to the plane (`n·u_r = 0`) misses, even one lying in it; so does a hit
    /// behind the origin (`t < 0`) or beyond [`FAR`]. A ray starting on the plane hits it at
    /// `t = 0`. The hit's `object` is 0.
    #[must_use]
    pub fn intersect(&self, ray: &DRay) -> Option<DHit> {
        let den = self.normal.dot(ray.dir());
        if den == 0.0 {
            return None;
        }
        let t = -self.distance(ray.origin()) / den;
        if !(0.0..=FAR).contains(&t) {
            return None;
        }
        // The ray travels against the normal that faces it: n if n·u_r < 0, else −n.
        let normal = if den < 0.0 { self.normal } else { -self.normal };
        Some(DHit {
            t,
            point: ray.at(t),
            normal,
            object: 0,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ray(origin: DVec3, toward: DVec3) -> DRay {
        DRay::new(origin, toward).unwrap()
    }

    fn wall(x: f64, normal: DVec3) -> DPlane {
        DPlane::new(DVec3::new(x, 0.0, 0.0), normal).unwrap()
    }

    #[test]
    fn the_chapter_wall_is_hit_at_t_3() {
        // Ray from (1, 1) along +x, wall face at x = 4: t = 3, x = (4, 1).
        let r = ray(DVec3::new(1.0, 1.0, 0.0), DVec3::X);
        for n in [DVec3::X, -DVec3::X] {
            let hit = wall(4.0, n).intersect(&r).unwrap();
            assert_eq!(hit.t, 3.0);
            assert_eq!(hit.point, DVec3::new(4.0, 1.0, 0.0));
            // Whichever way the plane was built, the hit normal faces the ray.
            assert_eq!(hit.normal, -DVec3::X);
        }
    }

    #[test]
    fn a_ray_parallel_to_the_plane_misses() {
        let r = ray(DVec3::new(1.0, 1.0, 0.0), DVec3::Y);
        assert_eq!(wall(4.0, DVec3::X).intersect(&r), None);
        // Even when it lies in the plane.
        let r = ray(DVec3::new(4.0, 1.0, 0.0), DVec3::Y);
        assert_eq!(wall(4.0, DVec3::X).intersect(&r), None);
    }

    #[test]
    fn behind_misses_and_on_the_plane_hits_at_zero() {
        let r = ray(DVec3::new(1.0, 1.0, 0.0), DVec3::X);
        assert_eq!(wall(0.0, DVec3::X).intersect(&r), None);
        let on = ray(DVec3::new(4.0, 1.0, 0.0), DVec3::X);
        assert_eq!(wall(4.0, DVec3::X).intersect(&on).map(|h| h.t), Some(0.0));
    }

    #[test]
    fn hits_beyond_far_are_misses() {
        let r = ray(DVec3::ZERO, DVec3::X);
        assert_eq!(wall(FAR, DVec3::X).intersect(&r).map(|h| h.t), Some(FAR));
        assert_eq!(wall(FAR + 1.0, DVec3::X).intersect(&r), None);
    }

    #[test]
    fn the_normal_is_made_unit() {
        let p = DPlane::new(DVec3::ZERO, DVec3::new(0.0, 2.0, 0.0)).unwrap();
        assert_eq!(p.normal(), DVec3::Y);
        assert_eq!(p.distance(DVec3::new(5.0, -3.0, 1.0)), -3.0);
        assert_eq!(DPlane::new(DVec3::ZERO, DVec3::ZERO), None);
    }
}
