//! [`SceneHit`]: the nearest hit in a scene, and which object it is on.

use crate::geometry::hit::Hit;
use crate::numbers::fx::Fx;
use crate::numbers::vec3::Vec3;

/// The nearest hit of a ray in a [`Scene`](crate::Scene): a [`Hit`] and the index of the
/// object it is on, as [`Scene::add`](crate::Scene::add) returned it.
///
/// The normal follows [`Hit`]'s convention: on the side the ray came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SceneHit {
    pub(crate) t: Fx,
    pub(crate) point: Vec3,
    pub(crate) normal: Vec3,
    pub(crate) object: usize,
}

impl SceneHit {
    /// `hit`, on object `object`.
    #[inline]
    pub(crate) const fn new(hit: Hit, object: usize) -> Self {
        SceneHit {
            t: hit.t,
            point: hit.point,
            normal: hit.normal,
            object,
        }
    }

    /// The index of the object hit.
    #[must_use]
    pub const fn object(&self) -> usize {
        self.object
    }

    /// The hit on that object's shape.
    #[must_use]
    pub const fn hit(&self) -> Hit {
        Hit {
            t: self.t,
            point: self.point,
            normal: self.normal,
        }
    }

    /// Distance along the ray, `t ≥ 0`.
    #[must_use]
    pub const fn t(&self) -> Fx {
        self.t
    }

    /// The hit point `x = p_r + t·u_r`.
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
