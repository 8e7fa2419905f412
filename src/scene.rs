//! [`Scene`]: planes and spheres, a light, and the chapter's `shoot` and `shade`.

use heapless::Vec;

use crate::color::Rgb;
use crate::error::Error;
use crate::fx::{self, Fx};
use crate::hit::Hit;
use crate::light::{Light, unit_interval};
use crate::plane::Plane;
use crate::ray::Ray;
use crate::sphere::Sphere;

/// The geometry of an object.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// An infinite plane.
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
}

/// A shape and its material colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Object {
    /// Its geometry.
    pub shape: Shape,
    /// Its colour under full light.
    pub colour: Rgb,
}

/// Up to `N` objects, one point light, an ambient term and a background colour.
///
/// The capacity is in the type and the storage inside the value: no allocator.
///
/// ```
/// use fixray::{Fx, Light, Plane, Ray, Rgb, Scene, Sphere, Vec3};
/// let light = Light::new(Vec3::from_ints(-20, 20, 20), Fx::from_num(0.8)).unwrap();
/// let mut scene: Scene<2> = Scene::new(light, Fx::from_num(0.2), Rgb::new(50, 180, 205)).unwrap();
/// let ball = scene.add_sphere(Sphere::new(Vec3::from_ints(0, 0, -10), Fx::from_num(2)).unwrap(), Rgb::WHITE).unwrap();
/// scene.add_plane(Plane::new(Vec3::from_ints(0, -4, 0), Vec3::Y).unwrap(), Rgb::WHITE).unwrap();
/// // A third object does not fit.
/// assert!(scene.add_plane(Plane::new(Vec3::ZERO, Vec3::Z).unwrap(), Rgb::BLACK).is_err());
///
/// let hit = scene.shoot(&Ray::new(Vec3::ZERO, -Vec3::Z).unwrap()).unwrap();
/// assert_eq!(hit.object, ball);
/// assert_eq!(scene.shade(None), Rgb::new(50, 180, 205));
/// ```
#[derive(Debug, Clone)]
pub struct Scene<const N: usize> {
    objects: Vec<Object, N>,
    light: Light,
    ambient: Fx,
    background: Rgb,
}

impl<const N: usize> Scene<N> {
    /// An empty scene lit by `light`, with `ambient` (0 to 1) light everywhere and
    /// `background` where rays miss.
    pub fn new(light: Light, ambient: Fx, background: Rgb) -> Result<Self, Error> {
        Ok(Scene {
            objects: Vec::new(),
            light,
            ambient: unit_interval(ambient, "ambient light")?,
            background,
        })
    }

    /// Adds an object and returns its index, or an error when the scene is full.
    pub fn add(&mut self, object: Object) -> Result<usize, Error> {
        self.objects
            .push(object)
            .map_err(|_| Error::CapacityExceeded { capacity: N })?;
        Ok(self.objects.len() - 1)
    }

    /// Adds a sphere of the given colour.
    pub fn add_sphere(&mut self, sphere: Sphere, colour: Rgb) -> Result<usize, Error> {
        self.add(Object {
            shape: Shape::Sphere(sphere),
            colour,
        })
    }

    /// Adds a plane of the given colour.
    pub fn add_plane(&mut self, plane: Plane, colour: Rgb) -> Result<usize, Error> {
        self.add(Object {
            shape: Shape::Plane(plane),
            colour,
        })
    }

    /// The objects, in the order they were added.
    #[must_use]
    pub fn objects(&self) -> &[Object] {
        &self.objects
    }

    /// The point light.
    #[must_use]
    pub const fn light(&self) -> Light {
        self.light
    }

    /// The ambient term.
    #[must_use]
    pub const fn ambient(&self) -> Fx {
        self.ambient
    }

    /// The colour of a ray that hits nothing.
    #[must_use]
    pub const fn background(&self) -> Rgb {
        self.background
    }

    /// Shoots `ray` into the scene and returns the nearest hit; on a tie the object added
    /// first wins.
    #[must_use]
    pub fn shoot(&self, ray: &Ray) -> Option<Hit> {
        let mut nearest: Option<Hit> = None;
        for (index, object) in self.objects.iter().enumerate() {
            if let Some(hit) = object.shape.intersect(ray)
                && nearest.is_none_or(|best| hit.t < best.t)
            {
                nearest = Some(Hit {
                    object: index,
                    ..hit
                });
            }
        }
        nearest
    }

    /// The colour seen along a ray with this hit: the background for a miss, otherwise the
    /// object's colour times `ambient + intensity · max(0, n·l)` (Lambert), where `l` is the
    /// unit vector from the hit point to the light. Channels are rounded and clamped to 255.
    #[must_use]
    pub fn shade(&self, hit: Option<&Hit>) -> Rgb {
        let Some((hit, object)) = hit.and_then(|h| Some((h, self.objects.get(h.object)?))) else {
            return self.background;
        };
        let diffuse = (self.light.position - hit.point)
            .try_normalize()
            .map_or(Fx::ZERO, |l| hit.normal.dot(l).max(Fx::ZERO));
        let k = self.ambient + fx::mul(self.light.intensity, diffuse);
        // k ≤ 2, so k · 255 stays far inside u32.
        let channel = |c: u8| ((c as u32 * k.to_bits() as u32 + 0x8000) >> 16).min(255) as u8;
        Rgb::new(
            channel(object.colour.r),
            channel(object.colour.g),
            channel(object.colour.b),
        )
    }

    /// `shade(shoot(ray))`: the colour of the pixel this ray passes through.
    #[must_use]
    pub fn trace(&self, ray: &Ray) -> Rgb {
        self.shade(self.shoot(ray).as_ref())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vec3::Vec3;

    fn lit_from_above() -> Scene<4> {
        let light = Light::new(Vec3::from_ints(0, 100, 0), Fx::from_num(0.75)).unwrap();
        Scene::new(light, Fx::from_num(0.25), Rgb::new(1, 2, 3)).unwrap()
    }

    #[test]
    fn nearest_object_wins_whatever_the_order() {
        let mut scene = lit_from_above();
        let far = Sphere::new(Vec3::from_ints(0, 0, -20), Fx::from_num(2)).unwrap();
        let near = Sphere::new(Vec3::from_ints(0, 0, -10), Fx::from_num(2)).unwrap();
        scene.add_sphere(far, Rgb::WHITE).unwrap();
        let near_index = scene.add_sphere(near, Rgb::WHITE).unwrap();
        let hit = scene
            .shoot(&Ray::new(Vec3::ZERO, -Vec3::Z).unwrap())
            .unwrap();
        assert_eq!((hit.object, hit.t), (near_index, Fx::from_num(8)));
    }

    #[test]
    fn lambert_shading_follows_the_angle_to_the_light() {
        let mut scene = lit_from_above();
        let ground = Plane::new(Vec3::from_ints(0, -4, 0), Vec3::Y).unwrap();
        scene.add_plane(ground, Rgb::new(200, 100, 0)).unwrap();
        // Straight below the light: n·l = 1, so k = 0.25 + 0.75 = 1.
        let below = scene.shoot(&Ray::new(Vec3::ZERO, -Vec3::Y).unwrap());
        assert_eq!(scene.shade(below.as_ref()), Rgb::new(200, 100, 0));
        // A wall lit from behind gets only the ambient quarter.
        let behind = Light::new(Vec3::from_ints(0, 0, -100), Fx::from_num(0.75)).unwrap();
        let mut dark: Scene<1> = Scene::new(behind, Fx::from_num(0.25), Rgb::BLACK).unwrap();
        let wall = Plane::new(Vec3::from_ints(0, 0, -5), Vec3::Z).unwrap();
        dark.add_plane(wall, Rgb::new(200, 100, 0)).unwrap();
        assert_eq!(
            dark.trace(&Ray::new(Vec3::ZERO, -Vec3::Z).unwrap()),
            Rgb::new(50, 25, 0)
        );
    }

    #[test]
    fn misses_show_the_background() {
        let scene = lit_from_above();
        assert_eq!(
            scene.trace(&Ray::new(Vec3::ZERO, Vec3::X).unwrap()),
            Rgb::new(1, 2, 3)
        );
    }

    #[test]
    fn ambient_outside_zero_to_one_is_refused() {
        let light = Light::new(Vec3::ZERO, Fx::ONE).unwrap();
        assert!(matches!(
            Scene::<1>::new(light, Fx::from_num(1.5), Rgb::BLACK),
            Err(Error::OutOfRange {
                what: "ambient light",
                ..
            })
        ));
    }
}
