//! [`Scene`]: planes and spheres, lights, and the chapter's `shoot` and `shade`.

pub(crate) mod background;
pub(crate) mod colour;
pub(crate) mod light;
pub(crate) mod linear;
pub(crate) mod material;

pub use background::Background;
pub use colour::Rgb;
pub use light::Light;
pub use material::{Checker, Material};

use heapless::Vec;

use crate::error::Error;
use crate::geometry::hit::Hit;
use crate::geometry::plane::Plane;
use crate::geometry::ray::Ray;
use crate::geometry::shape::Shape;
use crate::geometry::sphere::Sphere;
use crate::numbers::fx::{self, Fx};
use crate::numbers::vec3::Vec3;
use crate::render::accel::cone::ShadowCone;
use crate::scene::light::unit_interval;

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
            ambient: unit_interval(ambient, "ambient light")?,
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

    /// Shoots `ray` into the scene and returns the nearest hit; on a tie the object added
    /// first wins.
    #[must_use]
    pub fn shoot(&self, ray: &Ray) -> Option<Hit> {
        self.shoot_from(&ray.bounded(), None)
    }

    /// [`Scene::shoot`], ignoring the object the ray leaves from.
    ///
    /// Spheres and planes are convex: a ray leaving one towards a light or along a mirror
    /// direction cannot meet the same surface again, so skipping it replaces the usual small
    /// offset along the normal. That is exact, where an offset in Q16.16 would have to be
    /// larger than the hit point's rounding (which grows with distance) and would detach
    /// shadows from the objects that cast them.
    pub(crate) fn shoot_from(&self, ray: &Ray, leaving: Option<usize>) -> Option<Hit> {
        // By index, not by a bit of `among`: objects past the 64th have no bit of their own.
        let leaving = leaving.unwrap_or(usize::MAX);
        self.nearest_among(ray, !0, |index, shape| {
            if index == leaving {
                None
            } else {
                shape.hit_distance_bounded(ray)
            }
        })
    }

    /// The objects that rays of display row `row` can meet, as a bit set for
    /// [`Scene::shoot_among`]: planes always, spheres only when their centre lies within
    /// their radius (plus a margin for the rounding of ray directions) of the plane that
    /// holds the row's rays. A row sees few of the spheres, and skipping the rest is the
    /// cheapest intersection test there is. [`render_row`](crate::render_row) does this; a
    /// loop of its own over a row's pixels can too:
    ///
    /// ```
    /// use fixray::demo;
    /// let (scene, camera) = (demo::scene(), demo::camera(160, 128).unwrap());
    /// let among = scene.seen_from_row(&camera, 0);
    /// // The top row looks 29.8° up; the highest sphere, (7, 5, −18) r 4, reaches 27.1°: the
    /// // row can meet only the ground plane, object 0.
    /// assert_eq!(among & 0b11111, 0b00001);
    /// let ray = camera.ray(0, 80);
    /// assert_eq!(scene.shoot_among(&ray, among), scene.shoot(&ray));
    /// ```
    #[must_use]
    pub fn seen_from_row(&self, camera: &crate::Camera, row: u16) -> u64 {
        let Some(normal) = camera.row_plane_normal(row) else {
            return !0;
        };
        let mut among = !0u64;
        for (index, object) in self.objects.iter().enumerate().take(64) {
            if let Shape::Sphere(sphere) = object.shape {
                let to_centre = sphere.centre() - camera.eye();
                // Ray directions are within a few units of 2⁻¹⁶ of the row plane: over a
                // distance D they stray by less than D · 2⁻¹², and the normal's own rounding
                // adds as much again.
                let reach = to_centre.x.abs() + to_centre.y.abs() + to_centre.z.abs();
                let margin = (reach >> 11) + Fx::from_bits(1 << 8);
                if normal.dot(to_centre).abs() > sphere.radius() + margin {
                    among &= !(1 << index);
                }
            }
        }
        among
    }

    /// The nearest hit among the objects whose bit is set in `among` (bit `i` for object `i`;
    /// objects past the 64th are always tried). Distances first; the hit point and normal
    /// only for the nearest.
    #[must_use]
    pub fn shoot_among(&self, ray: &Ray, among: u64) -> Option<Hit> {
        let ray = &ray.bounded();
        self.nearest_among(ray, among, |_, shape| shape.hit_distance_bounded(ray))
    }

    /// [`Scene::shoot_among`] for a ray from `eye.origin()`, with what all such rays share
    /// worked out once: the same hit, for less.
    pub(crate) fn shoot_from_eye(&self, ray: &Ray, among: u64, eye: &Eye<N>) -> Option<Hit> {
        self.nearest_among(ray, among, |index, shape| match shape {
            Shape::Plane(plane) => plane.hit_distance_from(ray, eye.numerator(index)),
            Shape::Sphere(sphere) => sphere.hit_distance_bounded(ray),
        })
    }

    /// The nearest hit among the objects of `among` (see [`Scene::shoot_among`]), with
    /// `distance(index, shape)` giving each one's `t`.
    #[inline]
    fn nearest_among(
        &self,
        ray: &Ray,
        among: u64,
        distance: impl Fn(usize, &Shape) -> Option<Fx>,
    ) -> Option<Hit> {
        // Hits lie within FAR, so any hit is nearer than MAX.
        let (mut best, mut nearest) = (Fx::MAX, usize::MAX);
        let mut try_object = |index: usize, object: &Object| {
            if let Some(t) = distance(index, &object.shape)
                && t < best
            {
                (best, nearest) = (t, index);
            }
        };
        // Only the set bits, lowest first: culled objects cost nothing.
        let mut rest = among & self.present;
        while rest != 0 {
            let index = rest.trailing_zeros() as usize;
            rest &= rest - 1;
            try_object(index, &self.objects[index]);
        }
        for (index, object) in self.objects.iter().enumerate().skip(64) {
            try_object(index, object);
        }
        let hit = self.objects.get(nearest)?.shape.hit_at(ray, best);
        Some(Hit {
            object: nearest,
            ..hit
        })
    }

    /// Whether anything but object `leaving` lies on `ray` closer than `√distance_squared`
    /// (a Q32.32 value): a shadow ray towards light `light`, which stops at the first
    /// occluder and skips the spheres outside its [`ShadowCone`].
    pub(crate) fn occluded(
        &self,
        ray: &Ray,
        distance_squared: u64,
        leaving: usize,
        light: usize,
    ) -> bool {
        let blocks = |object: &Object| {
            object.shape.hit_distance_bounded(ray).is_some_and(|t| {
                let t = t.to_bits() as u32;
                fx::wide_mul_u32(t, t) < distance_squared
            })
        };
        let Some(cones) = self.cones.get(light) else {
            // Not one of the scene's lights: no cones to go by.
            return (self.objects.iter().enumerate()).any(|(i, o)| i != leaving && blocks(o));
        };
        for (index, (object, cone)) in self.objects.iter().zip(cones).enumerate() {
            if index != leaving && cone.may_block(ray.dir, distance_squared) && blocks(object) {
                return true;
            }
        }
        false
    }

    /// The colour seen along `ray` when it has this first hit: the background for a miss,
    /// otherwise the lit surface plus what its mirror shows (see [`Material`]).
    ///
    /// `hit` is meant to come from [`Scene::shoot`], but it may be built by hand: a normal
    /// that is not a unit vector saturates the arithmetic instead of overflowing it, and an
    /// object index past the last shades as a miss.
    #[must_use]
    pub fn shade(&self, ray: &Ray, hit: Option<&Hit>) -> Rgb {
        self.shade_bounded(&ray.bounded(), hit.map(Hit::bounded))
    }

    /// [`Scene::shade`] for a bounded ray and hit (see `Ray::bounded`), as the render path's
    /// own are.
    pub(crate) fn shade_bounded(&self, ray: &Ray, hit: Option<Hit>) -> Rgb {
        crate::scene::linear::to_rgb(self.radiance(ray, hit))
    }

    /// `shade(shoot(ray))`: the colour of the pixel this ray passes through.
    #[must_use]
    pub fn trace(&self, ray: &Ray) -> Rgb {
        self.shade(ray, self.shoot(ray).as_ref())
    }
}

/// What every ray from one point (a camera's eye) shares, worked out once a frame: each
/// plane's numerator of Eq. 4.2 ([`Plane`]'s `t = −n·(p_r − p0) / (n·u_r)` has `p_r` only in
/// its numerator).
pub(crate) struct Eye<const N: usize> {
    numerators: [i64; N],
}

impl<const N: usize> Eye<N> {
    /// The shared terms of rays from `origin` into `scene`.
    pub(crate) fn new<const L: usize>(scene: &Scene<N, L>, origin: Vec3) -> Self {
        let mut numerators = [0; N];
        for (num, object) in numerators.iter_mut().zip(scene.objects()) {
            if let Shape::Plane(plane) = object.shape {
                *num = plane.numerator(origin);
            }
        }
        Eye { numerators }
    }

    /// Plane `index`'s numerator of Eq. 4.2 for rays from the eye (0 for anything else).
    pub(crate) fn numerator(&self, index: usize) -> i64 {
        self.numerators.get(index).copied().unwrap_or(0)
    }
}

/// A mask of the lowest `n` bits (all 64 for `n ≥ 64`).
const fn low_bits(n: usize) -> u64 {
    if n >= 64 { !0 } else { (1u64 << n) - 1 }
}

#[cfg(test)]
mod tests;
