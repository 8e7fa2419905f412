//! [`DShape`] and [`DObject`]: what a scene is made of.

use super::{DHit, DPlane, DRay, DSphere};
use crate::Rgb;

/// One of the shapes a ray can be shot at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DShape {
    /// An infinite, two-sided plane.
    Plane(DPlane),
    /// A sphere.
    Sphere(DSphere),
}

impl DShape {
    /// Where `ray` first meets the shape, if it does within `0 ≤ t ≤ FAR`; the hit's `object`
    /// is 0.
    #[inline]
    #[must_use]
    pub fn intersect(&self, ray: &DRay) -> Option<DHit> {
        match self {
            DShape::Plane(plane) => plane.intersect(ray),
            DShape::Sphere(sphere) => sphere.intersect(ray),
        }
    }
}

impl From<DPlane> for DShape {
    fn from(plane: DPlane) -> DShape {
        DShape::Plane(plane)
    }
}

impl From<DSphere> for DShape {
    fn from(sphere: DSphere) -> DShape {
        DShape::Sphere(sphere)
    }
}

/// A shape with the colour its surface reflects.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DObject {
    /// The geometry.
    pub shape: DShape,
    /// The surface colour, before shading.
    pub colour: Rgb,
}

impl DObject {
    /// An object from its shape and colour.
    #[inline]
    #[must_use]
    pub const fn new(shape: DShape, colour: Rgb) -> Self {
        DObject { shape, colour }
    }
}
