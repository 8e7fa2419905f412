//! Which objects a row of rays, or a ray from the eye, can meet: the culling behind
//! `render_row`'s runs, and what rays from one point share.

use crate::geometry::hit::Hit;
use crate::geometry::plane::Numerator;
use crate::geometry::ray::Ray;
use crate::geometry::shape::Shape;
use crate::geometry::sphere::Sphere;
use crate::numbers::fx::Fx;
use crate::numbers::vec3::Vec3;
use crate::scene::hit::SceneHit;
use crate::scene::{Object, Scene};

impl<const N: usize, const L: usize> Scene<N, L> {
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
    /// let ray = camera.ray(80, 0);
    /// assert_eq!(scene.shoot_among(&ray, among), scene.shoot(&ray));
    /// ```
    // Not stable API: for fixray's profiling firmware and tests, hidden from the docs.
    #[doc(hidden)]
    #[must_use]
    pub fn seen_from_row(&self, camera: &crate::Camera, row: u16) -> u64 {
        self.seen_from_row_plane(camera.eye(), camera.row_plane_normal(row))
    }

    /// [`Scene::seen_from_row`] given the row's plane's unit normal `normal`
    /// (`Camera::row_plane_normal`), which `None` leaves every object in.
    pub(crate) fn seen_from_row_plane(&self, eye: Vec3, normal: Option<Vec3>) -> u64 {
        let Some(normal) = normal else {
            return !0;
        };
        let mut among = !0u64;
        for (index, object) in self.objects().iter().enumerate().take(64) {
            if let Shape::Sphere(sphere) = object.shape
                && !near_row_plane(&sphere, eye, normal)
            {
                among &= !(1 << index);
            }
        }
        among
    }

    /// The nearest hit among the objects whose bit is set in `among` (bit `i` for object `i`;
    /// objects past the 64th are always tried). Distances first, and a sphere's hit point and
    /// normal only for the nearest (a plane's hit comes with its distance, and is kept).
    // Not stable API: for fixray's profiling firmware and tests, hidden from the docs.
    #[doc(hidden)]
    #[must_use]
    pub fn shoot_among(&self, ray: &Ray, among: u64) -> Option<SceneHit> {
        self.nearest_among(ray, among, |_, shape| shape.meet(ray))
    }

    /// [`Scene::shoot_among`] for a ray from `eye.origin()`, with what all such rays share
    /// worked out once: the same hit, for less.
    pub(crate) fn shoot_from_eye(&self, ray: &Ray, among: u64, eye: &Eye<N>) -> Option<SceneHit> {
        self.nearest_among(ray, among, |index, shape| match shape {
            Shape::Plane(plane) => {
                let num = eye.numerator(index);
                let hit = plane.hit_from(ray, num)?;
                Some((hit.t, Some(hit)))
            }
            Shape::Sphere(sphere) => Some((sphere.hit_distance(ray)?, None)),
        })
    }

    /// [`Scene::shoot_from_eye`] for a set of one object, `index`: its hit, if any.
    #[inline]
    pub(crate) fn shoot_one_from_eye(
        &self,
        ray: &Ray,
        index: usize,
        eye: &Eye<N>,
    ) -> Option<SceneHit> {
        let hit = match self.objects().get(index)?.shape {
            Shape::Plane(plane) => plane.hit_from(ray, eye.numerator(index))?,
            Shape::Sphere(sphere) => sphere.hit_at(ray, sphere.hit_distance(ray)?),
        };
        Some(SceneHit { hit, object: index })
    }

    /// The nearest hit among the objects of `among` (see [`Scene::shoot_among`]), with
    /// `distance(index, shape)` giving each one's `t`, and its whole hit where that came at no
    /// extra cost (a plane's point is found before its distance).
    #[inline]
    fn nearest_among(
        &self,
        ray: &Ray,
        among: u64,
        distance: impl Fn(usize, &Shape) -> Option<(Fx, Option<Hit>)>,
    ) -> Option<SceneHit> {
        // Hits lie within FAR, so any hit is nearer than MAX.
        let (mut best, mut nearest, mut known) = (Fx::MAX, usize::MAX, None);
        let mut try_object = |index: usize, object: &Object| {
            if let Some((t, hit)) = distance(index, &object.shape)
                && t < best
            {
                (best, nearest, known) = (t, index, hit);
            }
        };
        // Only the set bits, lowest first: culled objects cost nothing.
        let mut rest = among & self.present();
        while rest != 0 {
            let index = rest.trailing_zeros() as usize;
            rest &= rest - 1;
            try_object(index, &self.objects()[index]);
        }
        for (index, object) in self.objects().iter().enumerate().skip(64) {
            try_object(index, object);
        }
        let hit = match known {
            Some(hit) => hit,
            None => self
                .objects()
                .get(nearest)?
                .shape
                .sphere_hit_at(ray, best)?,
        };
        Some(SceneHit {
            hit,
            object: nearest,
        })
    }
}

/// What every ray from one point (a camera's eye) shares, worked out once a frame: each
/// plane's numerator of Eq. 4.2 ([`Plane`]'s `t = −n·(p_r − p0) / (n·u_r)` has `p_r` only in
/// its numerator).
pub(crate) struct Eye<const N: usize> {
    numerators: [Numerator; N],
}

impl<const N: usize> Eye<N> {
    /// The shared terms of rays from `origin` into `scene`.
    pub(crate) fn new<const L: usize>(scene: &Scene<N, L>, origin: Vec3) -> Self {
        let mut numerators = [Numerator::NONE; N];
        for (num, object) in numerators.iter_mut().zip(scene.objects()) {
            if let Shape::Plane(plane) = object.shape {
                *num = plane.numerator(origin);
            }
        }
        Eye { numerators }
    }

    /// Plane `index`'s numerator of Eq. 4.2 for rays from the eye (0 for anything else).
    pub(crate) fn numerator(&self, index: usize) -> &Numerator {
        self.numerators.get(index).unwrap_or(&Numerator::NONE)
    }
}

/// Whether `sphere` may meet a ray of the row whose plane through `eye` has the unit normal
/// `normal` (see `Camera::row_plane_normal`): [`Scene::seen_from_row`]'s test for one sphere,
/// which the damage of an edit repeats exactly.
#[inline(always)]
pub(crate) fn near_row_plane(sphere: &Sphere, eye: Vec3, normal: Vec3) -> bool {
    let to_centre = sphere.centre() - eye;
    // Ray directions are within a few units of 2⁻¹⁶ of the row plane: over a distance D they
    // stray by less than D · 2⁻¹², and the normal's own rounding adds as much again.
    let reach = to_centre.x.abs() + to_centre.y.abs() + to_centre.z.abs();
    let margin = (reach >> 11) + Fx::from_bits(1 << 8);
    normal.dot(to_centre).abs() <= sphere.radius() + margin
}
