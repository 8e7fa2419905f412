//! [`Scene`]: planes and spheres, lights, and the chapter's `shoot` and `shade`.

pub(crate) mod background;
pub(crate) mod colour;
pub(crate) mod cone;
pub(crate) mod light;
pub(crate) mod linear;
pub(crate) mod material;

pub use background::Background;
pub use colour::Rgb;
pub use light::Light;
pub use material::{Checker, Material};

use heapless::Vec;

use crate::error::{Error, Quantity, within};
use crate::geometry::plane::Plane;
use crate::geometry::shape::Shape;
use crate::geometry::sphere::Sphere;
use crate::numbers::fx::Fx;
use crate::scene::cone::ShadowCone;

/// A shape and what it is made of.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Object {
    /// Its geometry.
    pub shape: Shape,
    /// How it shades.
    pub material: Material,
}

impl Object {
    /// The surface colour at a hit point: the material's, or its checkerboard's on a plane.
    #[must_use]
    pub fn colour_at(&self, point: crate::Vec3) -> Rgb {
        match (self.material.checker, self.shape) {
            (Some(checker), Shape::Plane(plane)) => {
                checker.colour_at(self.material.colour, plane.coords(point))
            }
            _ => self.material.colour,
        }
    }
}

/// Up to `N` objects and `L` point lights, an ambient term and a background.
///
/// The capacities are in the type and the storage inside the value: no allocator. Shadows are
/// on and mirrors follow up to [`Scene::DEFAULT_DEPTH`] bounces unless set otherwise.
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
/// let ray = Ray::new(Vec3::ZERO, Vec3::from_ints(0, 0, -1)).unwrap();
/// assert_eq!(scene.shoot(&ray).unwrap().object, ball);
/// let up = Ray::new(Vec3::ZERO, Vec3::Y).unwrap();
/// assert_eq!(scene.trace(&up), Rgb::new(50, 180, 205));
/// ```
#[derive(Debug, Clone)]
pub struct Scene<const N: usize, const L: usize = 4> {
    objects: Vec<Object, N>,
    lights: Vec<Light, L>,
    /// `cones[light][object]`: what each light sees of each sphere, to skip shadow tests.
    cones: [[ShadowCone; N]; L],
    ambient: Fx,
    background: Background,
    shadows: bool,
    depth: u8,
    /// Bit `i` set for each object `i` below 64: what [`Scene::shoot_among`] may try.
    present: u64,
}

impl<const N: usize, const L: usize> Scene<N, L> {
    /// Mirror bounces followed by default.
    pub const DEFAULT_DEPTH: u8 = 4;

    /// An empty scene lit by `light`, with `ambient` (0 to 1) light everywhere and
    /// `background` where rays escape (an [`Rgb`] or a [`Background`] gradient).
    pub fn new(
        light: Light,
        ambient: Fx,
        background: impl Into<Background>,
    ) -> Result<Self, Error> {
        let mut scene = Scene {
            objects: Vec::new(),
            cones: [[ShadowCone::ALWAYS; N]; L],
            lights: Vec::new(),
            ambient: within(ambient, Fx::ZERO, Fx::ONE, Quantity::Ambient)?,
            background: background.into(),
            shadows: true,
            depth: Self::DEFAULT_DEPTH,
            present: 0,
        };
        scene.add_light(light)?;
        Ok(scene)
    }

    /// Adds an object and returns its index, or an error when the scene is full.
    pub fn add(&mut self, object: Object) -> Result<usize, Error> {
        self.objects
            .push(object)
            .map_err(|_| Error::CapacityExceeded { capacity: N })?;
        let index = self.objects.len() - 1;
        self.present = low_bits(self.objects.len());
        for (cones, light) in self.cones.iter_mut().zip(&self.lights) {
            cones[index] = ShadowCone::new(light.position, &object.shape);
        }
        Ok(index)
    }

    /// Adds a sphere of a material (or a plain [`Rgb`], which is matte).
    pub fn add_sphere(
        &mut self,
        sphere: Sphere,
        material: impl Into<Material>,
    ) -> Result<usize, Error> {
        self.add(Object {
            shape: Shape::Sphere(sphere),
            material: material.into(),
        })
    }

    /// Adds a plane of a material (or a plain [`Rgb`], which is matte).
    pub fn add_plane(
        &mut self,
        plane: Plane,
        material: impl Into<Material>,
    ) -> Result<usize, Error> {
        self.add(Object {
            shape: Shape::Plane(plane),
            material: material.into(),
        })
    }

    /// Adds another light, or an error when `L` are already there.
    pub fn add_light(&mut self, light: Light) -> Result<usize, Error> {
        self.lights
            .push(light)
            .map_err(|_| Error::CapacityExceeded { capacity: L })?;
        let index = self.lights.len() - 1;
        for (cone, object) in self.cones[index].iter_mut().zip(&self.objects) {
            *cone = ShadowCone::new(light.position, &object.shape);
        }
        Ok(index)
    }

    /// Replaces object `index` (its shape, its material or both), keeping its place: the
    /// scene between two frames of an animation. Every light's shadow cone of it is worked out
    /// again, so the next render is exactly that of a scene built with the new object.
    ///
    /// ```
    /// use fixray::{Fx, Light, Rgb, Scene, Shape, Sphere, Vec3, Error};
    /// let light = Light::new(Vec3::from_ints(0, 20, 0), Fx::ONE)?;
    /// let mut scene: Scene<2> = Scene::new(light, Fx::from_num(0.2), Rgb::BLACK)?;
    /// let ball = scene.add_sphere(Sphere::new(Vec3::from_ints(0, 0, -10), Fx::ONE)?, Rgb::WHITE)?;
    /// let moved = Sphere::new(Vec3::from_ints(3, 0, -10), Fx::ONE)?;
    /// scene.set_shape(ball, Shape::Sphere(moved))?;
    /// assert_eq!(scene.objects()[ball].shape, Shape::Sphere(moved));
    /// assert_eq!(scene.set_shape(5, Shape::Sphere(moved)), Err(Error::NoSuchObject { index: 5, count: 1 }));
    /// # Ok::<(), fixray::Error>(())
    /// ```
    pub fn set_object(&mut self, index: usize, object: Object) -> Result<(), Error> {
        let count = self.objects.len();
        let slot = self
            .objects
            .get_mut(index)
            .ok_or(Error::NoSuchObject { index, count })?;
        *slot = object;
        for (cones, light) in self.cones.iter_mut().zip(&self.lights) {
            cones[index] = ShadowCone::new(light.position, &object.shape);
        }
        Ok(())
    }

    /// Moves or replaces the shape of object `index`, keeping its material (see
    /// [`Scene::set_object`]).
    pub fn set_shape(&mut self, index: usize, shape: Shape) -> Result<(), Error> {
        let material = self.material_of(index)?;
        self.set_object(index, Object { shape, material })
    }

    /// Changes what object `index` is made of, keeping its shape.
    pub fn set_material(
        &mut self,
        index: usize,
        material: impl Into<Material>,
    ) -> Result<(), Error> {
        let count = self.objects.len();
        let object = self
            .objects
            .get_mut(index)
            .ok_or(Error::NoSuchObject { index, count })?;
        object.material = material.into();
        Ok(())
    }

    /// The material of object `index`.
    fn material_of(&self, index: usize) -> Result<Material, Error> {
        let count = self.objects.len();
        self.objects
            .get(index)
            .map(|object| object.material)
            .ok_or(Error::NoSuchObject { index, count })
    }

    /// Moves, brightens or dims light `index`; its shadow cones are worked out again.
    pub fn set_light(&mut self, index: usize, light: Light) -> Result<(), Error> {
        let count = self.lights.len();
        let slot = self
            .lights
            .get_mut(index)
            .ok_or(Error::NoSuchLight { index, count })?;
        *slot = light;
        for (cone, object) in self.cones[index].iter_mut().zip(&self.objects) {
            *cone = ShadowCone::new(light.position, &object.shape);
        }
        Ok(())
    }

    /// Sets the ambient light, 0 to 1.
    pub fn set_ambient(&mut self, ambient: Fx) -> Result<(), Error> {
        self.ambient = within(ambient, Fx::ZERO, Fx::ONE, Quantity::Ambient)?;
        Ok(())
    }

    /// Sets what escaping rays see: an [`Rgb`] or a [`Background`] gradient.
    pub fn set_background(&mut self, background: impl Into<Background>) {
        self.background = background.into();
    }

    /// Turns shadow rays on or off (on by default).
    pub fn set_shadows(&mut self, on: bool) {
        self.shadows = on;
    }

    /// Sets how many mirror bounces are followed, at most 16. The ray leaving the last one sees
    /// only the background, so at 0 mirrors show the sky but no objects.
    pub fn set_depth(&mut self, bounces: u8) {
        self.depth = bounces.min(16);
    }

    /// The objects, in the order they were added.
    #[must_use]
    pub fn objects(&self) -> &[Object] {
        &self.objects
    }

    /// The lights, in the order they were added.
    #[must_use]
    pub fn lights(&self) -> &[Light] {
        &self.lights
    }

    /// The ambient term.
    #[must_use]
    pub const fn ambient(&self) -> Fx {
        self.ambient
    }

    /// What escaping rays see.
    #[must_use]
    pub const fn background(&self) -> Background {
        self.background
    }

    /// Whether shadow rays are cast.
    #[must_use]
    pub const fn shadows(&self) -> bool {
        self.shadows
    }

    /// How many mirror bounces are followed.
    #[must_use]
    pub const fn depth(&self) -> u8 {
        self.depth
    }

    /// Bit `i` set for each object `i` below 64.
    pub(crate) const fn present(&self) -> u64 {
        self.present
    }

    /// `cones[light][object]`: each light's view of each object, for shadow rays to skip
    /// what cannot block them.
    pub(crate) const fn cones(&self) -> &[[ShadowCone; N]; L] {
        &self.cones
    }
}

/// A mask of the lowest `n` bits (all 64 for `n ≥ 64`).
const fn low_bits(n: usize) -> u64 {
    if n >= 64 { !0 } else { (1u64 << n) - 1 }
}

#[cfg(test)]
mod tests;
