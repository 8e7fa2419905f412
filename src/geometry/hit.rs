//! [`Hit`]: where a ray met a surface.

use crate::numbers::fx::Fx;
use crate::numbers::vec3::Vec3;

/// The first point where a ray meets a surface.
///
/// The fields are public: a hit built by hand, with a normal that is not a unit vector or an
/// object index past the scene's last, may be handed to
/// [`Scene::shade`](crate::Scene::shade), which saturates instead of overflowing (and shades
/// an index past the last object as a miss).
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

impl Hit {
    /// This hit with each component of its normal clamped to ±2 (see `Ray::bounded`): what
    /// [`Scene::shade`](crate::Scene::shade) works on when a caller built the hit by hand.
    #[inline]
    #[must_use]
    pub(crate) const fn bounded(&self) -> Hit {
        Hit {
            normal: self.normal.clamp_raw(crate::geometry::ray::BOUND),
            ..*self
        }
    }
}
