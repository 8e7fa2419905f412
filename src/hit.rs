//! [`Hit`]: where a ray met a surface.

use crate::fx::Fx;
use crate::vec3::Vec3;

/// The first point where a ray meets a surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Hit {
    /// Distance along the ray, `t ≥ 0`.
    pub t: Fx,
    /// The hit point `x = p_r + t·u_r`.
    pub point: Vec3,
    /// The unit surface normal at `point`, on the side the ray came from for planes and
    /// pointing outward for spheres.
    pub normal: Vec3,
    /// Index of the object in its [`Scene`](crate::Scene); the pure intersection functions
    /// leave it 0 and [`Scene::shoot`](crate::Scene::shoot) fills it in.
    pub object: usize,
}
