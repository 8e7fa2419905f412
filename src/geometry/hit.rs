//! [`Hit`]: where a ray met a surface.

use crate::numbers::fx::Fx;
use crate::numbers::vec3::Vec3;

/// The first point where a ray meets a shape.
///
/// The normal is the surface's unit normal on the side the ray came from (`n·u_r ≤ 0`; a
/// plane decides the side by the direction the ray was made along, `n·w < 0`, which a
/// grazing ray's rounded `u_r` may miss by its rounding): a plane is two-sided, and a sphere seen from outside has its outward normal, seen from inside
/// its inward one. Shading, shadows and mirrors all work on that side of the surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Hit {
    pub(crate) t: Fx,
    pub(crate) point: Vec3,
    pub(crate) normal: Vec3,
}

impl Hit {
    /// The hit at distance `t` on a surface of unit normal `normal` (either side) at `point`,
    /// seen along `dir`: the normal is turned to face the ray.
    #[inline]
    pub(crate) fn facing(t: Fx, point: Vec3, normal: Vec3, dir: Vec3) -> Hit {
        // Both are unit vectors: the exact sum cannot overflow.
        let normal = if normal.dot_positive(dir) {
            -normal
        } else {
            normal
        };
        Hit { t, point, normal }
    }

    /// Distance along the ray, `t ≥ 0`.
    #[must_use]
    pub const fn t(&self) -> Fx {
        self.t
    }

    /// The hit point `x = p_r + t·u_r`, up to the rounding of `u_r`: a plane is met along the
    /// direction the ray was made along (see [`Plane::intersect`](crate::Plane::intersect)),
    /// and `t` is the distance of the point's projection on the ray.
    #[must_use]
    pub const fn point(&self) -> Vec3 {
        self.point
    }

    /// The unit surface normal at the point, on the side the ray came from.
    #[must_use]
    pub const fn normal(&self) -> Vec3 {
        self.normal
    }
}
