//! [`Shape`]: the geometry of an object, a plane or a sphere.

use crate::geometry::hit::Hit;
use crate::geometry::plane::Plane;
use crate::geometry::ray::Ray;
use crate::geometry::sphere::Sphere;
use crate::numbers::fx::Fx;

/// The geometry of an object.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// An infinite plane, or a rectangle of one.
    Plane(Plane),
    /// A sphere.
    Sphere(Sphere),
}

impl Shape {
    /// The first hit of `ray` on this shape, if any.
    #[must_use]
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let t = self.hit_distance(ray)?;
        Some(self.hit_at(ray, t))
    }

    /// The distance `t` to the first hit alone: what finding the nearest object and testing
    /// shadow rays need.
    pub(crate) fn hit_distance(&self, ray: &Ray) -> Option<Fx> {
        match self {
            Shape::Plane(p) => p.hit_distance(ray),
            Shape::Sphere(s) => s.hit_distance(ray),
        }
    }

    /// The hit at distance `t` along `ray`: the point and normal, for the nearest object only.
    pub(crate) fn hit_at(&self, ray: &Ray, t: Fx) -> Hit {
        match self {
            Shape::Plane(p) => p.hit_at(ray, t),
            Shape::Sphere(s) => s.hit_at(ray, t),
        }
    }
}

impl From<Sphere> for Shape {
    fn from(sphere: Sphere) -> Self {
        Shape::Sphere(sphere)
    }
}

impl From<Plane> for Shape {
    fn from(plane: Plane) -> Self {
        Shape::Plane(plane)
    }
}
