//! [`DPlane`]: a plane, or a rectangle of one, and the ray-plane intersection of Equation 4.2.

use super::{DHit, DRay, DVec3, FAR, Real};

/// A plane through the point `p_0` with unit normal `n` (section 4.3), infinite or cut down
/// to a rectangle.
///
/// The plane is two-sided: it can be hit from either side, and the normal of a hit is `n` or
/// `-n`, whichever faces back along the ray.
///
/// Positions across the plane are measured in two of the world coordinates, `(u, v)`: the two
/// left when the axis `n` is closest to is dropped (see [`coords`](Self::coords)). A rectangle
/// and a checkerboard are both given in them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DPlane<F: Real = f64> {
    point: DVec3<F>,
    normal: DVec3<F>,
    /// `[min, max]` in `(u, v)`, for a rectangle.
    bounds: Option<[[F; 2]; 2]>,
}

impl<F: Real> DPlane<F> {
    /// The plane through `point` perpendicular to `normal`, which is normalised here.
    ///
    /// Normalising in `f64` means a plane built from the fixed renderer's (nearly unit) Q16.16
    /// normal gets the exact unit normal in that direction. `None` if `normal` has no
    /// direction or `point` is not finite.
    #[must_use]
    pub fn new(point: DVec3<F>, normal: DVec3<F>) -> Option<Self> {
        if !point.is_finite() {
            return None;
        }
        let normal = normal.try_normalize()?;
        Some(DPlane {
            point,
            normal,
            bounds: None,
        })
    }

    /// The same plane cut down to the rectangle `min ≤ (u, v) ≤ max`, edges included: a ray
    /// meeting the plane outside it misses.
    ///
    /// `None` unless all four numbers are finite and `min` is below `max` on both axes.
    #[must_use]
    pub fn bounded(self, min: [F; 2], max: [F; 2]) -> Option<Self> {
        let finite = min.iter().chain(&max).all(|c| c.is_finite());
        if !finite || min[0] >= max[0] || min[1] >= max[1] {
            return None;
        }
        Some(DPlane {
            bounds: Some([min, max]),
            ..self
        })
    }

    /// The rectangle `[min, max]` in `(u, v)`, or `None` for an infinite plane.
    #[inline]
    #[must_use]
    pub const fn bounds(&self) -> Option<[[F; 2]; 2]> {
        self.bounds
    }

    /// The coordinates `(u, v)` of `x` across the plane: the world axis the normal is most
    /// nearly parallel to is dropped, keeping the other two in order.
    ///
    /// | normal closest to | `(u, v)` |
    /// |---|---|
    /// | y (a floor or ceiling) | `(x, z)` |
    /// | z (a wall facing ±z) | `(x, y)` |
    /// | x (a wall facing ±x) | `(y, z)` |
    ///
    /// A tie goes to y, then z: a normal at 45° between y and x or z counts as a floor, one
    /// at 45° between z and x as a ±z wall.
    #[must_use]
    pub fn coords(&self, x: DVec3<F>) -> [F; 2] {
        let n = self.normal;
        let [ax, ay, az] = [n.x.abs(), n.y.abs(), n.z.abs()];
        if ay >= ax && ay >= az {
            [x.x, x.z]
        } else if az >= ax {
            [x.x, x.y]
        } else {
            [x.y, x.z]
        }
    }

    /// True when `x`'s `(u, v)` lies in the rectangle, edges included; always for an infinite
    /// plane.
    fn contains(&self, x: DVec3<F>) -> bool {
        let Some([min, max]) = self.bounds else {
            return true;
        };
        let [u, v] = self.coords(x);
        (min[0]..=max[0]).contains(&u) && (min[1]..=max[1]).contains(&v)
    }

    /// The point `p_0` the plane was built through.
    #[inline]
    #[must_use]
    pub const fn point(&self) -> DVec3<F> {
        self.point
    }

    /// The unit normal `n`.
    #[inline]
    #[must_use]
    pub const fn normal(&self) -> DVec3<F> {
        self.normal
    }

    /// The signed distance `d = n · (x − p_0)` of `x` from the plane: positive on the side `n`
    /// points to, negative on the other, zero on the plane.
    #[inline]
    #[must_use]
    pub fn distance(&self, x: DVec3<F>) -> F {
        self.normal.dot(x - self.point)
    }

    /// Where `ray` meets the plane, by Equation 4.2: `t = −n·(p_r − p_0) / (n·u_r)`.
    ///
    /// A ray parallel to the plane (`n·u_r = 0`) misses, even one lying in it; so does a hit
    /// behind the origin (`t < 0`) or beyond [`FAR`], and on a rectangle one whose hit point
    /// lies outside it. A ray starting on the plane (`n·(p_r − p_0) = 0`) misses too: it
    /// leaves the plane at once, or runs along it. The hit's `object` is 0.
    #[must_use]
    pub fn intersect(&self, ray: &DRay<F>) -> Option<DHit<F>> {
        let den = self.normal.dot(ray.dir());
        let height = self.distance(ray.origin());
        if den == F::ZERO || height == F::ZERO {
            return None;
        }
        let t = -height / den;
        if !(F::ZERO..=F::from_f64(FAR)).contains(&t) {
            return None;
        }
        let point = ray.at(t);
        if !self.contains(point) {
            return None;
        }
        // The ray travels against the normal that faces it: n if n·u_r < 0, else −n.
        let normal = if den < F::ZERO {
            self.normal
        } else {
            -self.normal
        };
        Some(DHit {
            t,
            point,
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
    fn behind_misses_and_so_does_a_ray_from_the_plane() {
        let r = ray(DVec3::new(1.0, 1.0, 0.0), DVec3::X);
        assert_eq!(wall(0.0, DVec3::X).intersect(&r), None);
        // From a point of the wall, out through it, back from it or along it: no hit.
        for toward in [DVec3::X, -DVec3::X, DVec3::Y, DVec3::new(1.0, 1.0, 0.0)] {
            let on = ray(DVec3::new(4.0, 1.0, 0.0), toward);
            assert_eq!(wall(4.0, DVec3::X).intersect(&on), None, "{toward:?}");
        }
        // Just off it, the wall is met at once.
        let near = ray(DVec3::new(4.0 - 1e-9, 1.0, 0.0), DVec3::X);
        assert!(wall(4.0, DVec3::X).intersect(&near).is_some());
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
        assert_eq!(DPlane::new(<DVec3>::ZERO, DVec3::ZERO), None);
    }

    #[test]
    fn coordinates_drop_the_axis_the_normal_is_closest_to() {
        let x = DVec3::new(1.0, 2.0, 3.0);
        let plane = |n: DVec3| DPlane::new(DVec3::ZERO, n).unwrap();
        assert_eq!(plane(DVec3::Y).coords(x), [1.0, 3.0]);
        assert_eq!(plane(-DVec3::Z).coords(x), [1.0, 2.0]);
        assert_eq!(plane(DVec3::X).coords(x), [2.0, 3.0]);
        // Mostly x, a little y: still a wall facing x.
        assert_eq!(plane(DVec3::new(-3.0, 1.0, 1.0)).coords(x), [2.0, 3.0]);
        // 45° ties: y beats x and z, z beats x.
        assert_eq!(plane(DVec3::new(1.0, 1.0, 0.0)).coords(x), [1.0, 3.0]);
        assert_eq!(plane(DVec3::new(0.0, -1.0, 1.0)).coords(x), [1.0, 3.0]);
        assert_eq!(plane(DVec3::new(1.0, 0.0, -1.0)).coords(x), [1.0, 2.0]);
    }

    #[test]
    fn a_rectangle_misses_outside_and_hits_on_its_edges() {
        // The floor y = −4 for −10 ≤ x ≤ 10 and −30 ≤ z ≤ −10.
        let floor = DPlane::new(DVec3::new(0.0, -4.0, 0.0), DVec3::Y)
            .unwrap()
            .bounded([-10.0, -30.0], [10.0, -10.0])
            .unwrap();
        assert_eq!(floor.bounds(), Some([[-10.0, -30.0], [10.0, -10.0]]));
        let down = |x: f64, z: f64| ray(DVec3::new(x, 0.0, z), -DVec3::Y);
        assert_eq!(floor.intersect(&down(0.0, -20.0)).map(|h| h.t), Some(4.0));
        assert_eq!(floor.intersect(&down(0.0, -5.0)), None);
        assert_eq!(floor.intersect(&down(10.5, -20.0)), None);
        assert_eq!(floor.intersect(&down(-10.0, -30.0)).map(|h| h.t), Some(4.0));
        assert_eq!(floor.intersect(&down(10.0, -10.0)).map(|h| h.t), Some(4.0));
    }

    #[test]
    fn an_empty_or_inverted_rectangle_is_refused() {
        let floor = DPlane::new(DVec3::ZERO, DVec3::Y).unwrap();
        assert_eq!(floor.bounds(), None);
        assert_eq!(floor.bounded([0.0, 0.0], [0.0, 1.0]), None);
        assert_eq!(floor.bounded([0.0, 2.0], [1.0, 1.0]), None);
        assert_eq!(floor.bounded([f64::NAN, 0.0], [1.0, 1.0]), None);
    }
}
