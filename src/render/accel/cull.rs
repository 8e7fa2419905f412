//! Which objects a row of rays, or a ray from the eye, can meet: the culling behind
//! `render_row`'s runs, and what rays from one point share.

use crate::geometry::hit::Hit;
use crate::geometry::plane::{Numerator, Plane};
use crate::geometry::ray::Ray;
use crate::geometry::shape::Shape;
use crate::geometry::sphere::Sphere;
use crate::numbers::bits;
use crate::numbers::fx::{self, FAR, Fx};
use crate::numbers::isqrt::isqrt;
use crate::numbers::vec3::Vec3;
use crate::render::accel::crowd::{ByIndex, Crowd, Names};
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
    #[cfg(feature = "internals")]
    #[must_use]
    pub fn seen_from_row(&self, camera: &crate::Camera, row: u16) -> u64 {
        self.seen_from_row_plane(camera.eye(), camera.row_plane_normal(row))
    }

    /// `Scene::seen_from_row` given the row's plane's unit normal `normal`
    /// (`Camera::row_plane_normal`), which `None` leaves every object in: the test `Runs`
    /// makes of each sphere ([`row_offset`]).
    #[cfg(feature = "internals")]
    pub(crate) fn seen_from_row_plane(&self, eye: Vec3, normal: Option<Vec3>) -> u64 {
        let Some(normal) = normal else {
            return !0;
        };
        let mut among = !0u64;
        for (index, object) in self.objects().iter().enumerate().take(64) {
            if let Shape::Sphere(sphere) = object.shape
                && row_offset(&sphere, eye, normal).is_none()
            {
                among &= !bits::bit(index);
            }
        }
        among
    }

    /// The nearest hit among the objects whose bit is set in `among` (bit `i` for object `i`;
    /// objects past the 64th are always tried). Distances first, and a sphere's hit point and
    /// normal only for the nearest (a plane's hit comes with its distance, and is kept).
    #[cfg(feature = "internals")]
    #[must_use]
    pub fn shoot_among(&self, ray: &Ray, among: u64) -> Option<SceneHit> {
        self.nearest_among(ray, [among, 0], 0, ByIndex, |_, shape, _| shape.meet(ray))
    }

    /// [`Scene::shoot_among`] for a ray from `eye.origin()`, with what all such rays share
    /// worked out once: the same hit, for less.
    ///
    /// The spheres are tried before the planes: a hit on a sphere that lies wholly before
    /// every plane ([`Eye`]'s `before_planes`) is nearer than any plane's, and then the planes
    /// need no test. A sphere whose near side lies beyond the nearest hit found so far takes
    /// one dot product ([`Sphere::hit_distance_within`]).
    #[inline]
    pub(crate) fn shoot_from_eye<C: Names>(
        &self,
        ray: &Ray,
        among: u64,
        eye: &Eye<N, C>,
    ) -> Option<SceneHit> {
        let order = [among & !eye.planes, among & eye.planes];
        self.nearest_among(
            ray,
            order,
            eye.before_planes,
            eye.names,
            |index, shape, best| match shape {
                Shape::Plane(plane) => {
                    let hit = plane.hit_from(ray, eye.numerator(index))?;
                    Some((hit.t, Some(hit)))
                }
                // A sphere whose every hit lies beyond the nearest found cannot be nearer.
                Shape::Sphere(sphere) => {
                    Some((sphere.hit_distance_within(ray, best.min(FAR))?, None))
                }
            },
        )
    }

    /// [`Scene::shoot_from_eye`] for a set of one object, `index`: its hit, if any.
    #[inline]
    pub(crate) fn shoot_one_from_eye<C: Names>(
        &self,
        ray: &Ray,
        index: usize,
        eye: &Eye<N, C>,
    ) -> Option<SceneHit> {
        let hit = match self.objects().get(index)?.shape {
            Shape::Plane(plane) => plane.hit_from(ray, eye.numerator(index))?,
            Shape::Sphere(sphere) => sphere.hit_at(ray, sphere.hit_distance(ray)?),
        };
        Some(SceneHit { hit, object: index })
    }

    /// The nearest hit among the objects of `first`, then of `then` unless the nearest of
    /// `first` is one of `enough` (bit `i` for object `i`; objects past the 64th are always
    /// tried, last; or with a row's `crowd`, bit `i` for the object it names, and its extras
    /// tried last), with `distance(index, shape, best)` giving each one's `t`, and its whole
    /// hit where that came at no extra cost (a plane's point is found before its distance).
    /// `best` is the nearest `t` found so far (`Fx::MAX` before any): a shape none of whose
    /// hits can be as near may come back `None`. Ties go to the lower index, whatever the
    /// order (see [`Scene::shoot_among`]).
    #[inline]
    fn nearest_among<C: Names>(
        &self,
        ray: &Ray,
        [first, then]: [u64; 2],
        enough: u64,
        names: C,
        distance: impl Fn(usize, &Shape, Fx) -> Option<(Fx, Option<Hit>)>,
    ) -> Option<SceneHit> {
        // Hits lie within FAR, so any hit is nearer than MAX.
        let (mut best, mut nearest, mut known) = (Fx::MAX, usize::MAX, None);
        let mut try_object = |index: usize, object: &Object, nearest: &mut usize| {
            if let Some((t, hit)) = distance(index, &object.shape, best)
                && (t < best || (t == best && index < *nearest))
            {
                (best, *nearest, known) = (t, index, hit);
            }
        };
        // A crowd's bits are all objects the row has: no mask of present ones applies.
        let present = if C::CROWD { !0 } else { self.present() };
        // Only the set bits, lowest first: culled objects cost nothing.
        let (mut rest, mut then) = (first & present, then & present);
        loop {
            while rest != 0 {
                let bit = rest.trailing_zeros() as usize;
                rest &= rest - 1;
                let index = names.object(bit);
                try_object(index, &self.objects()[index], &mut nearest);
            }
            if then == 0 || (nearest < 64 && bits::has(enough, nearest)) {
                break;
            }
            (rest, then) = (then, 0);
        }
        if C::CROWD {
            for &index in names.extras() {
                if let Some(object) = self.objects().get(index as usize) {
                    try_object(index as usize, object, &mut nearest);
                }
            }
        } else {
            for (index, object) in self.objects().iter().enumerate().skip(64) {
                try_object(index, object, &mut nearest);
            }
        }
        self.hit_of_nearest(ray, nearest, best, known)
    }
}

/// What every ray from one point (a camera's eye) shares, worked out once a frame: each
/// plane's numerator of Eq. 4.2 ([`Plane`]'s `t = −n·(p_r − p0) / (n·u_r)` has `p_r` only in
/// its numerator).
pub(crate) struct Eye<const N: usize, C: Names = ByIndex> {
    numerators: [Numerator; N],
    /// The planes among the first 64 objects (bit `i` for object `i`), or among a crowd's.
    planes: u64,
    /// Of the spheres the rays will try, those every hit of which, as a ray from the eye
    /// finds it, is nearer than any plane's hit on that ray (bit `i` for object `i`; none in
    /// scenes of more than 64 objects): they lie wholly on the eye's side of every plane
    /// ([`before_plane`]).
    before_planes: u64,
    /// What the bits stand for.
    names: C,
}

impl<const N: usize> Eye<N> {
    /// The shared terms of rays from `origin` into `scene` that try the objects of `among`
    /// (bit `i` for object `i`).
    pub(crate) fn new<const L: usize>(scene: &Scene<N, L>, origin: Vec3, among: u64) -> Self {
        let objects = scene.objects();
        // Each plane's numerator, made where it is kept (an array of a few hundred bytes is
        // not to be copied): the other objects' are `Numerator::NONE`.
        let numerators = core::array::from_fn(|index| match objects.get(index) {
            Some(Object {
                shape: Shape::Plane(plane),
                ..
            }) => plane.numerator(origin),
            _ => Numerator::NONE,
        });
        let planes = (objects.iter().enumerate().take(64))
            .filter(|(_, object)| matches!(object.shape, Shape::Plane(_)))
            .fold(0, |planes, (index, _)| planes | bits::bit(index));
        let before_planes = if planes != 0 && among & !planes != 0 {
            spheres_before_planes(scene, planes, among & !planes, &numerators, origin)
        } else {
            0
        };
        Eye {
            numerators,
            planes,
            before_planes,
            names: ByIndex,
        }
    }
}

impl<'a, const N: usize> Eye<N, &'a Crowd<N>> {
    /// The shared terms of rays from `origin` into `scene`, for a row whose bits `crowd` gives
    /// to objects, `planes` those of planes. Spheres before the planes are not sought: the
    /// nearest hit tries every object of a ray's set.
    pub(crate) fn crowded<const L: usize>(
        scene: &Scene<N, L>,
        origin: Vec3,
        planes: u64,
        crowd: &'a Crowd<N>,
    ) -> Self {
        let objects = scene.objects();
        let numerators = core::array::from_fn(|index| match objects.get(index) {
            Some(Object {
                shape: Shape::Plane(plane),
                ..
            }) => plane.numerator(origin),
            _ => Numerator::NONE,
        });
        Eye {
            numerators,
            planes,
            before_planes: 0,
            names: crowd,
        }
    }
}

impl<const N: usize, C: Names> Eye<N, C> {
    /// The object bit `bit` of a row's sets stands for.
    pub(crate) fn object(&self, bit: usize) -> usize {
        self.names.object(bit)
    }

    /// Whether a ray's set is all it tries, in a scene of `count` objects.
    pub(crate) fn alone(&self, count: usize) -> bool {
        self.names.alone(count)
    }

    /// The objects every ray of the row tries besides its set.
    pub(crate) fn extras(&self) -> &[u32] {
        self.names.extras()
    }

    /// [`Names::ends_at`] of what the bits stand for.
    pub(crate) fn ends_at(&self, col: i16) -> Option<(u64, i16)> {
        self.names.ends_at(col)
    }

    /// Plane `index`'s numerator of Eq. 4.2 for rays from the eye (0 for anything else).
    pub(crate) fn numerator(&self, index: usize) -> &Numerator {
        self.numerators.get(index).unwrap_or(&Numerator::NONE)
    }
}

/// The spheres among the objects `others` of `scene` that lie wholly before each of its
/// planes `planes` (bit `i` for object `i`), seen from `eye` ([`before_plane`]); none in
/// scenes of more than 64 objects. Once a row.
fn spheres_before_planes<const N: usize, const L: usize>(
    scene: &Scene<N, L>,
    planes: u64,
    others: u64,
    numerators: &[Numerator; N],
    eye: Vec3,
) -> u64 {
    let objects = scene.objects();
    if objects.len() > 64 {
        return 0;
    }
    let (mut before_planes, mut spheres) = (0, others);
    while spheres != 0 {
        let index = spheres.trailing_zeros() as usize;
        spheres &= spheres - 1;
        let Some(Shape::Sphere(sphere)) = objects.get(index).map(|o| &o.shape) else {
            continue;
        };
        let (mut rest, mut before) = (planes, true);
        while rest != 0 && before {
            let plane = rest.trailing_zeros() as usize;
            rest &= rest - 1;
            if let (Some(Shape::Plane(p)), Some(num)) =
                (objects.get(plane).map(|o| &o.shape), numerators.get(plane))
            {
                before = before_plane(sphere, p, num, eye);
            }
        }
        if before {
            before_planes |= bits::bit(index);
        }
    }
    before_planes
}

/// Whether every hit on `sphere` of a ray from `eye` ([`Sphere::hit_distance`]) is nearer
/// than that ray's hit on `plane`, if any (`Plane::hit_from`; `from_eye` is the plane's
/// numerator for rays from `eye`): true where the sphere and the eye lie on the same side of
/// the plane, the sphere's centre at least `r + m` from it and the eye at least `m`, with a
/// margin `m` of 2⁻⁸ plus 2⁻¹² of `|C − eye|₁ + r`.
///
/// Heights are taken along the plane's rounded normal `n`, as its hit test takes them. A hit
/// `t` on the sphere is either 0 (the eye itself, at least `m` from the plane) or within the
/// half chord `a` of `t_close`, and then its point along the ray's direction `u` lies within
/// `r + r·2⁻¹⁵ + t_close·2⁻¹⁴ + 2⁻¹⁵` of the centre (the roundings of `t_close`, of the
/// closest point and of `a`, and `u`'s length within 2⁻¹⁴ of 1): above the plane by more than
/// `t·2⁻¹⁴ + 2⁻¹⁴` still. The plane's hit lies along the exact direction `w` towards the
/// pixel, within 2⁻¹⁵ of `u`: the point `t` along `w` is above the plane too, so `w` crosses
/// it farther out, and the plane's distance (its projection on `u`, to 2⁻²⁷ of itself and a
/// unit) comes out larger than `t`. The margin holds several times what this needs.
fn before_plane(sphere: &Sphere, plane: &Plane, from_eye: &Numerator, eye: Vec3) -> bool {
    let centre = sphere.centre();
    let radius = sphere.radius().to_bits() as i64;
    // Raw units: eyes, centres, points and radii lie within ±1024, so nothing below overflows.
    let margin = (1 << 8) + ((centre.minus(eye).l1_raw() + radius) >> 12);
    let (eye_needs, centre_needs) = (margin << 16, (radius + margin) << 16);
    // Heights `n·(x − p0)` are the numerators' (`−n·(p_r − p0)`) negated; turned so that the
    // eye's is positive.
    let above = plane.normal().dot_wide_exact(centre - plane.point());
    let (eye_height, centre_height) = match -from_eye.value {
        height @ 0.. => (height, above),
        height => (-height, -above),
    };
    eye_height >= eye_needs && centre_height >= centre_needs
}

/// The height of `sphere`'s centre above the row's plane (through `eye`, with the unit normal
/// `normal`: see `Camera::row_plane_normal`), `n·(C − eye)` rounded to nearest, where the
/// sphere may meet a ray of the row, for [`row_ball`]; `None` where it cannot: the test of
/// `Scene::seen_from_row_plane` and `Runs`, which the damage of an edit repeats exactly.
pub(crate) fn row_offset(sphere: &Sphere, eye: Vec3, normal: Vec3) -> Option<Fx> {
    let to_centre = sphere.centre() - eye;
    let margin = Fx::from_bits(stray(to_centre.l1_raw()) as i32);
    let height = normal.dot_units(to_centre);
    (height.abs() <= sphere.radius() + margin).then_some(height)
}

/// How far, in raw units, a row's rays may lie from the row's plane at a distance of at most
/// `reach` raw units from the eye (an `|x| + |y| + |z|`, at least the distance): ray
/// directions are within a few units of 2⁻¹⁶ of the row plane, so over a distance D they
/// stray by less than D · 2⁻¹², and the normal's own rounding adds as much again. Both hold
/// however short the rays' unnormalised directions are: every one of them lies exactly in
/// the plane, and `Camera::row_plane_normal` forms its normal exactly before rounding it (to
/// 0.55 of a unit a component) — a normal rounded from a product with a direction a few
/// raw units long, as the widest views of one-pixel screens have, would not be.
const fn stray(reach: i64) -> i64 {
    (reach >> 11) + (1 << 8)
}

/// A ball that holds every point of `sphere` which a ray of the row whose plane through `eye`
/// has the unit normal `normal` can meet, as `(centre, radius)`: smaller than the sphere on
/// every row but those through its middle, so its columns (`Camera::column_span`) are fewer.
/// `height` is the centre's height above the plane as [`row_offset`] finds it.
///
/// The row's rays stray from their plane by less than `margin` at the sphere (as
/// [`row_offset`] bounds it, here out to the sphere's far side). The points of the sphere
/// that close to the plane lie in a ball about the centre `C'` of the circle the plane cuts
/// from it: a point `P = C + q + h·n` (`q` across `n`, `|q|² + h² ≤ r²`) at `|d + h| ≤ margin`
/// from the plane, `d = n·(C − eye)`, lies `|q|² + (d + h)² ≤ r² − (|d| − margin)² + margin²`
/// from `C' = C − d·n` squared. Its radius is rounded up, and widened by `r·2⁻¹⁰` for the
/// rounding of `n` and of `C'`, far more than either; where that is not smaller than `r`, the
/// sphere itself is the ball.
// In raw integers: once a row for each sphere near it, and short.
pub(crate) fn row_ball(sphere: &Sphere, eye: Vec3, normal: Vec3, height: Fx) -> (Vec3, Fx) {
    let (centre, r) = (sphere.centre(), sphere.radius());
    let to_centre = centre.minus(eye);
    // Raw units (2⁻¹⁶): centres, eyes and radii lie within ±1024, so every square below is
    // under 2⁵⁵ and every sum fits.
    let radius = r.to_bits() as i64;
    let margin = stray(to_centre.l1_raw() + radius);
    // n·(C − eye), rounded to nearest: half a unit off at most, which the margin covers.
    let d = height.to_bits() as i64;
    let off = (d.abs() - margin).max(0);
    // Each factor below 2²⁸ (radii, distances and margins of points within ±1024): the
    // products of two `i32`s, as the work of a row takes them (`fx::wide_mul`).
    let square = |v: i64| {
        debug_assert!(v.unsigned_abs() < 1 << 28, "row_ball: a length past 2²⁸");
        fx::wide_mul(v as i32, v as i32)
    };
    let squared = (square(radius) - square(off)).max(0) + square(margin);
    let widened = isqrt(squared as u64) as i64 + 1 + (radius >> 10) + (1 << 6);
    if widened >= radius {
        return (centre, r);
    }
    // C' = C − d·n, each component rounded down.
    let across = |c: Fx, n: Fx| {
        Fx::from_bits((c.to_bits() as i64 - (fx::wide_mul(n.to_bits(), d as i32) >> 16)) as i32)
    };
    let circle = Vec3::new(
        across(centre.x, normal.x),
        across(centre.y, normal.y),
        across(centre.z, normal.z),
    );
    (circle, Fx::from_bits(widened as i32))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Camera;
    use embedded_graphics::geometry::Size;

    #[test]
    fn the_demo_balls_lie_before_its_ground_seen_from_above_it_only() {
        let mut scene = crate::demo::scene();
        let camera = crate::demo::camera(160, 128).unwrap();
        let eye = Eye::new(&scene, camera.eye(), !0);
        assert_eq!((eye.planes, eye.before_planes), (0b1, 0b11110));
        // A ball through the ground (y = −4) is not; nor is one lifted off it by 2⁻⁹ only,
        // within the margin. From below the ground, none is.
        let rgb = crate::Rgb::new(1, 2, 3);
        for y in [-4.5, -3.0 + 1.0 / 512.0] {
            scene
                .add_sphere(Sphere::new([0.0, y, -10.0], 1.0).unwrap(), rgb)
                .unwrap();
        }
        let eye = Eye::new(&scene, camera.eye(), !0);
        assert_eq!(eye.before_planes, 0b11110);
        let below = Eye::new(&scene, Vec3::from_ints(0, -6, 0), !0);
        assert_eq!(below.before_planes, 0);
    }

    #[test]
    fn a_row_meets_a_sphere_only_in_the_columns_of_its_ball() {
        // Random spheres seen by random cameras, up vectors and fields of view: every column of
        // every row whose ray meets a sphere lies in the span of the row's ball, and on most
        // rows that span is narrower than the sphere's own.
        let mut rng = crate::xorshift::XorShift(0x5eed_0fba_1150_a11e);
        let mut next = |range: f32| rng.signed(range);
        let (mut rows, mut narrower, mut hits) = (0, 0, 0);
        for case in 0..300 {
            let eye = [next(40.0), next(40.0), next(40.0)];
            let target = [next(40.0), next(40.0), next(40.0)];
            let up = [next(1.0), 1.0 + next(0.5), next(1.0)];
            let size = Size::new(
                8 + (next(1.0).abs() * 90.0) as u32,
                8 + (next(1.0).abs() * 70.0) as u32,
            );
            let Ok(camera) = Camera::look_at(eye, target)
                .up(up)
                .fov_degrees(20.0 + next(1.0).abs() * 120.0)
                .size(size)
                .build()
            else {
                continue;
            };
            let centre = [
                target[0] + next(10.0),
                target[1] + next(10.0),
                target[2] + next(10.0),
            ];
            let Ok(sphere) = Sphere::new(centre, 0.05 + next(1.0).abs() * 12.0) else {
                continue;
            };
            let whole = camera.column_span(sphere.centre(), sphere.radius());
            for row in 0..camera.rows() {
                let Some(normal) = camera.row_plane_normal(row) else {
                    continue;
                };
                let Some(height) = row_offset(&sphere, camera.eye(), normal) else {
                    continue;
                };
                let (centre, radius) = row_ball(&sphere, camera.eye(), normal, height);
                let Some((first, last)) = camera.column_span(centre, radius) else {
                    continue;
                };
                rows += 1;
                if let Some((a, b)) = whole {
                    narrower += (last - first < b - a) as u32;
                }
                for col in camera.columns_meeting(&sphere, row) {
                    hits += 1;
                    assert!(
                        (first..=last).contains(&col),
                        "case {case}, row {row}: column {col} outside {first}..={last}"
                    );
                }
            }
        }
        assert!(rows > 2000 && hits > 20_000, "{rows} rows, {hits} hits");
        assert!(narrower * 2 > rows, "{narrower} of {rows} rows narrower");
    }
}
