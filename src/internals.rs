//! Not stable API (feature `internals`, off by default): the pieces of the render path that
//! fixray's own tests, fuzz target and profiling firmware reach for, each one the renderer
//! uses as it is. Nothing here is needed to draw a scene, and any of it may change in any
//! release.

use crate::error::Error;
use crate::geometry::ray::Ray;
use crate::numbers::vec3::Vec3;

pub use crate::geometry::refract::refract;
pub use crate::numbers::isqrt::isqrt;
pub use crate::render::shoot_row_skipping;

/// The exact dot product of `a` and `b` as a Q32.32 value, saturated to `i64`: what the
/// render path's tests and set-up compare against.
#[must_use]
pub const fn dot_wide(a: Vec3, b: Vec3) -> i64 {
    a.dot_wide(b)
}

/// `‖v‖²` as an exact unsigned Q32.32 value: three squares below 2⁶² each, so it never
/// overflows.
#[must_use]
pub const fn length_squared_wide(v: Vec3) -> u64 {
    v.length_squared_wide()
}

/// A ray from a hit point, as the renderer's shadow and mirror rays leave one: the origin may
/// lie anywhere a first hit can (within ±(`LIMIT` + `FAR`)), the direction is normalised here.
/// For tests that repeat the renderer's secondary rays by brute force.
pub const fn ray_from_hit_point(origin: Vec3, dir: Vec3) -> Result<Ray, Error> {
    Ray::from_hit_point(origin, dir)
}
