//! [`DHit`]: where a ray meets an object.

use super::{DVec3, Real};

/// The result of shooting a ray at an object: what was hit, where, and which way it faces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DHit<F: Real = f64> {
    /// The ray parameter of the hit, `0 ≤ t ≤ FAR`: its distance from the ray origin.
    pub t: F,
    /// The hit point `x = p_r + t·u_r`.
    pub point: DVec3<F>,
    /// The unit surface normal at the hit: outward for a sphere, facing the ray for a plane.
    pub normal: DVec3<F>,
    /// The index of the object hit in its scene (0 for a shape shot on its own).
    pub object: usize,
}
