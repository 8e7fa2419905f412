//! [`Shape`]: the geometry of an object, a plane or a sphere.

use crate::geometry::hit::Hit;
use crate::geometry::plane::Plane;
use crate::geometry::ray::Ray;
use crate::geometry::sphere::Sphere;
use crate::numbers::fx::{self, Fx};

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
        match self {
            Shape::Plane(p) => p.intersect(ray),
            Shape::Sphere(s) => s.intersect(ray),
        }
    }

    /// The distance `t` to the first hit alone (a sphere's without its point; a plane's from
    /// its whole hit, which costs no more): what [`Shape::blocks`] answers from, for tests.
    #[cfg(test)]
    pub(crate) fn hit_distance(&self, ray: &Ray) -> Option<Fx> {
        match self {
            Shape::Plane(p) => p.hit_distance(ray),
            Shape::Sphere(s) => s.hit_distance(ray),
        }
    }

    /// Whether `ray` meets this shape nearer than `√distance_squared` (a Q32.32 value), as
    /// [`Shape::hit_distance`] finds it: a shadow ray's question.
    pub(crate) fn blocks(&self, ray: &Ray, distance_squared: u64) -> bool {
        match self {
            Shape::Plane(p) => p.hit_distance(ray).is_some_and(|t| {
                let t = t.to_bits() as u32;
                fx::wide_mul_u32(t, t) < distance_squared
            }),
            Shape::Sphere(s) => s.blocks(ray, distance_squared),
        }
    }

    /// Where `ray` first meets this shape: its distance, and for a plane the whole hit, which
    /// costs no more (a plane's point is found before its distance). A sphere's hit is made
    /// for the nearest object only, by [`Shape::sphere_hit_at`].
    pub(crate) fn meet(&self, ray: &Ray) -> Option<(Fx, Option<Hit>)> {
        match self {
            Shape::Plane(plane) => {
                let hit = plane.intersect(ray)?;
                Some((hit.t, Some(hit)))
            }
            Shape::Sphere(sphere) => Some((sphere.hit_distance(ray)?, None)),
        }
    }

    /// The hit at distance `t` along `ray` on a sphere, whose distance came without it
    /// ([`Shape::meet`], [`Sphere::hit_distance`]); `None` for a plane, whose hit comes with
    /// its distance and is kept, never made again.
    pub(crate) fn sphere_hit_at(&self, ray: &Ray, t: Fx) -> Option<Hit> {
        match self {
            Shape::Plane(_) => None,
            Shape::Sphere(s) => Some(s.hit_at(ray, t)),
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
