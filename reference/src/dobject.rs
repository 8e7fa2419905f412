//! [`DShape`] and [`DObject`]: what a scene is made of.

use super::{DHit, DMaterial, DPlane, DRay, DSphere, DVec3, Real};
use fixray::Rgb;

/// One of the shapes a ray can be shot at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DShape<F: Real = f64> {
    /// A two-sided plane, infinite or cut to a rectangle.
    Plane(DPlane<F>),
    /// A sphere.
    Sphere(DSphere<F>),
}

impl<F: Real> DShape<F> {
    /// Where `ray` first meets the shape, if it does within `0 ≤ t ≤ FAR`; the hit's `object`
    /// is 0.
    #[inline]
    #[must_use]
    pub fn intersect(&self, ray: &DRay<F>) -> Option<DHit<F>> {
        match self {
            DShape::Plane(plane) => plane.intersect(ray),
            DShape::Sphere(sphere) => sphere.intersect(ray),
        }
    }
}

impl<F: Real> From<DPlane<F>> for DShape<F> {
    fn from(plane: DPlane<F>) -> Self {
        DShape::Plane(plane)
    }
}

impl<F: Real> From<DSphere<F>> for DShape<F> {
    fn from(sphere: DSphere<F>) -> Self {
        DShape::Sphere(sphere)
    }
}

/// A shape and the material of its surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DObject<F: Real = f64> {
    /// The geometry.
    pub shape: DShape<F>,
    /// How the surface shades.
    pub material: DMaterial<F>,
}

impl<F: Real> DObject<F> {
    /// An object from its shape and material.
    #[inline]
    #[must_use]
    pub const fn new(shape: DShape<F>, material: DMaterial<F>) -> Self {
        DObject { shape, material }
    }

    /// A matte object of one colour.
    #[inline]
    #[must_use]
    pub const fn matte(shape: DShape<F>, colour: Rgb) -> Self {
        DObject::new(shape, DMaterial::matte(colour))
    }

    /// The surface colour at `point`: the checkerboard's square there on a plane that has
    /// one, otherwise the material's colour (spheres ignore a checkerboard).
    #[must_use]
    pub fn colour_at(&self, point: DVec3<F>) -> Rgb {
        let colour = self.material.colour;
        match (self.shape, self.material.checker) {
            (DShape::Plane(plane), Some(checker)) => checker.colour_at(colour, plane.coords(point)),
            _ => colour,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::DChecker;

    const RED: Rgb = Rgb::new(255, 0, 0);
    const BLUE: Rgb = Rgb::new(0, 0, 255);

    fn checked(shape: DShape) -> DObject {
        let checker = Some(DChecker {
            size: 1.0,
            other: BLUE,
        });
        DObject::new(
            shape,
            DMaterial {
                checker,
                ..DMaterial::matte(RED)
            },
        )
    }

    #[test]
    fn a_wall_is_checked_in_x_and_y() {
        // A wall facing +z: (u, v) = (x, y), and z does not matter.
        let wall = checked(DPlane::new(DVec3::ZERO, DVec3::Z).unwrap().into());
        assert_eq!(wall.colour_at(DVec3::new(0.5, 0.5, 0.0)), RED);
        assert_eq!(wall.colour_at(DVec3::new(1.5, 0.5, 0.0)), BLUE);
        assert_eq!(wall.colour_at(DVec3::new(0.5, 1.5, 9.0)), BLUE);
    }

    #[test]
    fn a_sphere_keeps_its_plain_colour() {
        let ball = checked(DSphere::new(DVec3::ZERO, 1.0).unwrap().into());
        for point in [DVec3::X, DVec3::Y, DVec3::new(0.0, 0.0, -1.0)] {
            assert_eq!(ball.colour_at(point), RED);
        }
    }
}
