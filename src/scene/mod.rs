//! [`Scene`]: planes and spheres, lights, and the chapter's `shoot` and `shade`.

pub(crate) mod background;
pub(crate) mod colour;
pub(crate) mod hit;
pub(crate) mod light;
pub(crate) mod linear;
pub(crate) mod material;

pub use background::Background;
pub use colour::Rgb;
pub use hit::SceneHit;
pub use light::Light;
pub use material::{Checker, Material, Refraction};

use crate::check;
use crate::error::{Error, Quantity};
use crate::geometry::plane::Plane;
use crate::geometry::shape::Shape;
use crate::geometry::sphere::Sphere;
use crate::numbers::fx::Fx;
use crate::numbers::vec3::Vec3;
use crate::render::accel::shadow_caches::ShadowCaches;

/// A shape and what it is made of.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Object {
    /// Its geometry.
    pub shape: Shape,
    /// How it shades.
    pub material: Material,
}

impl Object {
    /// A shape made of a material.
    #[must_use]
    pub const fn new(shape: Shape, material: Material) -> Self {
        Object { shape, material }
    }

    /// The surface colour at a hit point: the material's, or its checkerboard's on a plane.
    #[must_use]
    #[inline]
    pub fn colour_at(&self, point: Vec3) -> Rgb {
        match self.material.checker {
            Some(_) => self.checkered_at(point),
            None => self.material.colour,
        }
    }

    /// [`Object::colour_at`] for a material with a checkerboard: a function of its own, since
    /// the plain colour is the common case and every pixel's shading asks for one or the other.
    fn checkered_at(&self, point: Vec3) -> Rgb {
        match (self.material.checker, self.shape) {
            (Some(checker), Shape::Plane(plane)) => {
                checker.colour_at(self.material.colour, plane.coords(point))
            }
            _ => self.material.colour,
        }
    }

    /// What fills a scene's unused slots; never shown.
    const UNUSED: Object = Object {
        shape: Shape::Sphere(Sphere::UNIT),
        material: Material::matte(Rgb::BLACK),
    };
}

/// Up to `N` objects and `L` point lights, an ambient term and a background.
///
/// The capacities are in the type and the storage inside the value: no allocator. Shadows are
/// on and mirrors follow up to [`Scene::DEFAULT_DEPTH`] bounces unless set otherwise.
///
/// A render's stack grows with them: a row keeps 4 bytes an object for its culling, and in a
/// scene whose capacity passes 32, where the 32-bit shadow sets can no longer name every
/// object, 8 bytes an object and light for its floor's casters and about 70 bytes a light for
/// each of 8 spheres' shadowers (64 for a whole frame, [`render`](crate::render)).
///
/// ```
/// use fixray::{Light, Plane, Ray, Rgb, Scene, Sphere, Vec3};
/// let light = Light::new([-20.0, 20.0, 20.0], 0.8)?;
/// let mut scene: Scene<2> = Scene::new(light, 0.2, Rgb::new(50, 180, 205))?;
/// let ball = scene.add_sphere(Sphere::new([0.0, 0.0, -10.0], 2.0)?, Rgb::WHITE)?;
/// scene.add_plane(Plane::new([0.0, -4.0, 0.0], [0.0, 1.0, 0.0])?, Rgb::WHITE)?;
/// // A third object does not fit.
/// assert!(scene.add_plane(Plane::new([0.0; 3], [0.0, 0.0, 1.0])?, Rgb::BLACK).is_err());
///
/// let ray = Ray::new(Vec3::ZERO, -Vec3::Z)?;
/// assert_eq!(scene.shoot(&ray).map(|hit| hit.object()), Some(ball));
/// assert_eq!(scene.trace(&Ray::new(Vec3::ZERO, Vec3::Y)?), Rgb::new(50, 180, 205));
/// # Ok::<(), fixray::Error>(())
/// ```
///
/// A scene can also be a `static`, built at compile time by the `const` constructors (the
/// fixed-point forms, `from_fx`): the values are checked by the compiler, and on a
/// microcontroller the scene lies in flash, not on the stack.
///
/// ```
/// use fixray::{Background, Error, Fx, Light, Material, Object, Rgb, Scene, Shape, Sphere, Vec3};
/// const fn ok<T: Copy>(result: Result<T, Error>) -> T {
///     match result {
///         Ok(value) => value,
///         Err(_) => panic!("out of range"),
///     }
/// }
/// static SCENE: Scene<1, 1> = {
///     let light = ok(Light::from_fx(Vec3::from_ints(-20, 20, 20), Fx::ONE));
///     let ball = ok(Sphere::from_fx(Vec3::from_ints(0, 0, -10), Fx::const_from_int(2)));
///     let mut scene = match Scene::from_fx(light, Fx::ZERO, Background::plain(Rgb::BLACK)) {
///         Ok(scene) => scene,
///         Err(_) => panic!("out of range"),
///     };
///     ok(scene.add(Object::new(Shape::Sphere(ball), Material::matte(Rgb::WHITE))));
///     scene
/// };
/// assert_eq!(SCENE.objects().len(), 1);
/// ```
#[derive(Debug, Clone)]
pub struct Scene<const N: usize, const L: usize = 4> {
    /// The objects in `objects[..object_count]`; the rest are unused.
    objects: [Object; N],
    object_count: usize,
    /// The lights in `lights[..light_count]`.
    lights: [Light; L],
    light_count: usize,
    /// What the shadow rays' speed-ups keep, worked out again on every change of an object
    /// or a light: private to `render/accel/`.
    shadow_caches: ShadowCaches<N, L>,
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
    /// The most bounces [`Scene::set_depth`] allows.
    pub const MAX_DEPTH: u8 = 16;

    /// The most secondary rays a pixel traces. Each mirror or glass hit can send two rays on,
    /// so a full tree `d` generations deep has `2^(d+1) − 2` of them: every tree up to depth 5
    /// fits, and past this many rays the rest see only the background, so that a scene of
    /// mirrors and glass at depth 16 costs at most this many rays a pixel, not 130 000.
    pub const MAX_RAYS: u16 = 64;

    /// An empty scene lit by `light`, with `ambient` (0 to 1) light everywhere and
    /// `background` where rays escape (an [`Rgb`] or a [`Background`] gradient).
    pub fn new(
        light: Light,
        ambient: f32,
        background: impl Into<Background>,
    ) -> Result<Self, Error> {
        let ambient = check::f32_within(ambient, Fx::ZERO, Fx::ONE, Quantity::Ambient)?;
        Scene::from_fx(light, ambient, background.into())
    }

    /// [`Scene::new`] in fixed point, for `const` and `static` scenes.
    pub const fn from_fx(light: Light, ambient: Fx, background: Background) -> Result<Self, Error> {
        if let Err(e) = check::within(ambient, Fx::ZERO, Fx::ONE, Quantity::Ambient) {
            return Err(e);
        }
        let mut scene = Scene {
            objects: [Object::UNUSED; N],
            object_count: 0,
            lights: [light; L],
            light_count: 0,
            shadow_caches: ShadowCaches::NONE,
            ambient,
            background,
            shadows: true,
            depth: Self::DEFAULT_DEPTH,
            present: 0,
        };
        match scene.add_light(light) {
            Ok(_) => Ok(scene),
            Err(e) => Err(e),
        }
    }

    /// Adds an object and returns its index, or an error when the scene is full.
    pub const fn add(&mut self, object: Object) -> Result<usize, Error> {
        let index = self.object_count;
        if index >= N {
            return Err(Error::CapacityExceeded { capacity: N });
        }
        self.objects[index] = object;
        self.object_count += 1;
        self.present = low_bits(self.object_count);
        self.refresh_object_cones(index);
        Ok(index)
    }

    /// Adds a sphere of a material (or a plain [`Rgb`], which is matte).
    pub fn add_sphere(
        &mut self,
        sphere: Sphere,
        material: impl Into<Material>,
    ) -> Result<usize, Error> {
        self.add(Object::new(Shape::Sphere(sphere), material.into()))
    }

    /// Adds a plane of a material (or a plain [`Rgb`], which is matte).
    pub fn add_plane(
        &mut self,
        plane: Plane,
        material: impl Into<Material>,
    ) -> Result<usize, Error> {
        self.add(Object::new(Shape::Plane(plane), material.into()))
    }

    /// Adds another light, or an error when `L` are already there.
    pub const fn add_light(&mut self, light: Light) -> Result<usize, Error> {
        let index = self.light_count;
        if index >= L {
            return Err(Error::CapacityExceeded { capacity: L });
        }
        self.lights[index] = light;
        self.light_count += 1;
        self.refresh_light_cones(index);
        Ok(index)
    }

    /// Works out again what the shadow rays' speed-ups keep of object `index` (which must
    /// exist).
    const fn refresh_object_cones(&mut self, index: usize) {
        let objects = self.objects.split_at(self.object_count).0;
        let lights = self.lights.split_at(self.light_count).0;
        self.shadow_caches.refresh_object(index, objects, lights);
    }

    /// Works out again what the shadow rays' speed-ups keep of light `index` (which must
    /// exist).
    const fn refresh_light_cones(&mut self, index: usize) {
        let objects = self.objects.split_at(self.object_count).0;
        let lights = self.lights.split_at(self.light_count).0;
        self.shadow_caches.refresh_light(index, objects, lights);
    }

    /// Replaces object `index` (its shape, its material or both), keeping its place: the
    /// scene between two frames of an animation. Every light's shadow cone of it is worked out
    /// again, so the next render is exactly that of a scene built with the new object.
    ///
    /// ```
    /// use fixray::{Error, Light, Rgb, Scene, Shape, Sphere};
    /// let light = Light::new([0.0, 20.0, 0.0], 1.0)?;
    /// let mut scene: Scene<2> = Scene::new(light, 0.2, Rgb::BLACK)?;
    /// let ball = scene.add_sphere(Sphere::new([0.0, 0.0, -10.0], 1.0)?, Rgb::WHITE)?;
    /// let moved = Sphere::new([3.0, 0.0, -10.0], 1.0)?;
    /// scene.set_shape(ball, moved.into())?;
    /// assert_eq!(scene.objects()[ball].shape, Shape::Sphere(moved));
    /// assert_eq!(scene.set_shape(5, Shape::Sphere(moved)), Err(Error::NoSuchObject { index: 5, count: 1 }));
    /// # Ok::<(), fixray::Error>(())
    /// ```
    pub fn set_object(&mut self, index: usize, object: Object) -> Result<(), Error> {
        let count = self.object_count;
        let slot = self.objects[..count]
            .get_mut(index)
            .ok_or(Error::NoSuchObject { index, count })?;
        *slot = object;
        self.refresh_object_cones(index);
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
        let count = self.object_count;
        let object = self.objects[..count]
            .get_mut(index)
            .ok_or(Error::NoSuchObject { index, count })?;
        object.material = material.into();
        Ok(())
    }

    /// The material of object `index`.
    fn material_of(&self, index: usize) -> Result<Material, Error> {
        let count = self.object_count;
        self.objects()
            .get(index)
            .map(|object| object.material)
            .ok_or(Error::NoSuchObject { index, count })
    }

    /// Moves, brightens or dims light `index`; its shadow cones are worked out again.
    pub fn set_light(&mut self, index: usize, light: Light) -> Result<(), Error> {
        let count = self.light_count;
        let slot = self.lights[..count]
            .get_mut(index)
            .ok_or(Error::NoSuchLight { index, count })?;
        *slot = light;
        self.refresh_light_cones(index);
        Ok(())
    }

    /// Sets the ambient light, 0 to 1.
    pub fn set_ambient(&mut self, ambient: f32) -> Result<(), Error> {
        self.ambient = check::f32_within(ambient, Fx::ZERO, Fx::ONE, Quantity::Ambient)?;
        Ok(())
    }

    /// Sets what escaping rays see: an [`Rgb`] or a [`Background`] gradient.
    pub fn set_background(&mut self, background: impl Into<Background>) {
        self.background = background.into();
    }

    /// Turns shadow rays on or off (on by default).
    pub const fn set_shadows(&mut self, on: bool) {
        self.shadows = on;
    }

    /// Sets how many generations of secondary rays (mirror and refracted rays) are followed,
    /// at most [`Scene::MAX_DEPTH`]. A ray of the generation past the last sees only the
    /// background, so at 0 mirrors and glass show the sky but no objects.
    pub fn set_depth(&mut self, bounces: u8) {
        self.depth = bounces.min(Self::MAX_DEPTH);
    }

    /// The objects, in the order they were added.
    #[must_use]
    pub fn objects(&self) -> &[Object] {
        // `add` keeps the count within N; `min` says so to the compiler, which then drops the
        // slice's bounds check from a call the render path makes for every ray.
        &self.objects[..self.object_count.min(N)]
    }

    /// The lights, in the order they were added.
    #[must_use]
    pub fn lights(&self) -> &[Light] {
        &self.lights[..self.light_count.min(L)]
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

    /// What the shadow rays' speed-ups keep (`render/accel/shadow_caches.rs`).
    pub(crate) const fn shadow_caches(&self) -> &ShadowCaches<N, L> {
        &self.shadow_caches
    }
}

/// A mask of the lowest `n` bits (all 64 for `n ≥ 64`).
const fn low_bits(n: usize) -> u64 {
    if n >= 64 { !0 } else { (1u64 << n) - 1 }
}

#[cfg(test)]
mod tests;
