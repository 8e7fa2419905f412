//! The shadows a moved sphere casts, before and after, bounded on the screen: on a sphere by
//! its silhouette, on a plane by the projection from the light of octagonal prisms around
//! the caster, and by the plane's own rectangle when it is bounded.

use super::{Area, Damage};
use crate::geometry::plane::Plane;
use crate::geometry::shape::Shape;
use crate::geometry::sphere::Sphere;
use crate::numbers::vec3::Vec3;
use crate::render::camera::Camera;
use crate::render::camera::project::{
    F3, ScreenMap, add, cross, dot, exceeds, f3, length, perpendiculars, scale, sub,
};
use crate::scene::Scene;
use crate::scene::light::Light;

impl Damage {
    /// Adds the shadows `ball` (object `index` of `scene`, or what it was) casts from `light`
    /// on the other objects that did not change: a sphere that may receive it is marked in
    /// `outlines` for its silhouette; a plane's shadow is bounded here.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn shadows<const N: usize, const L: usize>(
        &mut self,
        scene: &Scene<N, L>,
        index: usize,
        ball: &Sphere,
        light: &Light,
        camera: &Camera,
        map: &ScreenMap,
        changed: &impl Fn(usize) -> bool,
        outlines: &mut [bool; N],
    ) -> Option<()> {
        let caster = Caster::new(ball, light.position(), camera.eye());
        for (other, object) in scene.objects().iter().enumerate() {
            if other == index || changed(other) {
                // A changed object's pixels are in its own silhouettes already.
                continue;
            }
            match object.shape {
                Shape::Sphere(receiver) => {
                    if caster.may_shade(&receiver) {
                        *outlines.get_mut(other)? = true;
                    }
                }
                Shape::Plane(plane) => {
                    let shadow = caster.on_plane(&plane, map, self);
                    let within = plane_area(&plane, camera.eye(), map, self);
                    let area = match (shadow, within) {
                        (Some(None), _) => None,
                        (Some(Some(shadow)), Some(within)) => within.and_then(|w| w.meet(&shadow)),
                        (Some(Some(shadow)), None) => Some(shadow),
                        (None, Some(within)) => within,
                        (None, None) => return None,
                    };
                    if let Some(area) = area {
                        self.add(area);
                    }
                }
            }
        }
        Some(())
    }
}

/// How far a hit point may lie from the surface it was found on, in world units: far more
/// than a Q16.16 hit point's rounding (a few units of 2⁻¹⁶).
const ON_SURFACE: f32 = 1.0 / 1024.0;

/// A regular octagon's vertices on the unit circle, as (cos, sin) of the odd multiples of
/// π/8. Scaled by [`OCTAGON`] its sides lie outside the unit circle, which it then holds.
const OCTAGON_VERTICES: [(f32, f32); 8] = [
    (0.923_879_5, 0.382_683_43),
    (0.382_683_43, 0.923_879_5),
    (-0.382_683_43, 0.923_879_5),
    (-0.923_879_5, 0.382_683_43),
    (-0.923_879_5, -0.382_683_43),
    (-0.382_683_43, -0.923_879_5),
    (0.382_683_43, -0.923_879_5),
    (0.923_879_5, -0.382_683_43),
];

/// `1 / cos(π/8)`, rounded up: how far out an octagon around a unit circle has its vertices.
const OCTAGON: f32 = 1.082_4;

/// Nearer the eye than this (world units, along the view) no point is projected.
pub(super) const NEAREST: f32 = 1.0 / 16.0;

/// A sphere casting shadows from a point light. Positions are offsets from the light,
/// differences taken exactly in Q16.16 and then converted, so that `f32` never subtracts
/// two large coordinates.
struct Caster {
    /// The sphere's centre.
    centre: F3,
    radius: f32,
    /// The light.
    light: Vec3,
    /// The light as an offset from the camera's eye.
    light_from_eye: F3,
    /// The part of the margin that does not grow with distance (see [`Caster::margin`]).
    reach: f32,
}

impl Caster {
    fn new(ball: &Sphere, light: Vec3, eye: Vec3) -> Self {
        let radius: f32 = ball.radius().to_num();
        Caster {
            centre: f3(ball.centre() - light),
            radius,
            light,
            light_from_eye: f3(light - eye),
            reach: 1.0 / 256.0 + libm::sqrtf(radius) / 32.0,
        }
    }

    /// How much wider than its radius the sphere is taken to be, for receiving points as far
    /// as `distance` from it and from the light.
    ///
    /// A shadow ray from a hit point runs towards the light along a Q16.16 unit direction,
    /// within about 2⁻¹⁵ radians of the exact one: at the sphere it is off the exact segment
    /// by up to `distance · 2⁻¹⁵`, here taken as `distance / 1024`. The sphere's test rounds
    /// the ray's closest approach by a few units of 2⁻¹⁶ (the fixed 1/256), and the square
    /// root that places the crossing along a grazing ray moves it by up to about
    /// `√(r · 2⁻¹³)`, which widening the sphere by `√r / 32` more than covers: a crossing
    /// the test puts before the light is then one the widened sphere has before it too.
    fn margin(&self, distance: f32) -> f32 {
        self.reach + distance / 1024.0
    }

    /// Whether a shadow of the sphere may fall on `receiver`: always when the light is in
    /// or near the widened sphere, where no cone bounds the shadow.
    fn may_shade(&self, receiver: &Sphere) -> bool {
        let to_receiver = f3(receiver.centre() - self.light);
        let reach: f32 = receiver.radius().to_num::<f32>() + ON_SURFACE;
        let apart = length(sub(to_receiver, self.centre));
        let (caster, other) = (length(self.centre), length(to_receiver));
        let widened = self.radius + self.margin(apart.max(other) + reach);
        if !exceeds(caster, widened + 1.0 / 64.0) || other <= reach {
            return true;
        }
        // Every point of the receiver nearer the light than the sphere's near side: a
        // segment from it to the light cannot reach the sphere.
        if other + reach < caster - widened {
            return false;
        }
        // Cones from the light around each: the shadow lies in the sphere's, the receiver in
        // its own. Apart by more than the two half-angles, they never meet.
        let between = libm::atan2f(
            length(cross(self.centre, to_receiver)),
            dot(self.centre, to_receiver),
        );
        let half = |r: f32, d: f32| libm::asinf((r / d).min(1.0));
        !exceeds(
            between,
            half(widened, caster) + half(reach, other) + 1.0 / 1024.0,
        )
    }

    /// The pixels of `plane` the shadow may fall on: `Some(None)` where it casts none there,
    /// `None` where it cannot be bounded (it stretches too far, or reaches behind the eye).
    ///
    /// A shadowed hit point `P` lies within [`ON_SURFACE`] of the plane (a slab), and its
    /// segment to the light meets the widened sphere at some `Q`, which lies between the
    /// slab's bottom and the light's height: `Q` is in the sphere cut to those heights, and in
    /// two octagonal prisms around it (the part in the slab and the part above). Along the
    /// ray from the light through `Q`, `P` lies between `Q` (or where the ray enters the
    /// slab, if `Q` is above it) and where it leaves the slab. Central projection from the
    /// light keeps convex hulls, so `P` lies in the hull of the prisms' vertices, each taken
    /// into the slab's faces so; and so does its pixel, in the screen box of those points,
    /// all of them ahead of the eye.
    fn on_plane(&self, plane: &Plane, map: &ScreenMap, damage: &Damage) -> Option<Option<Area>> {
        let normal = f3(plane.normal());
        // Heights above the plane, on the light's side.
        let to_light = -dot(normal, f3(plane.point() - self.light));
        if !exceeds(to_light.abs(), 1.0 / 64.0) {
            return None;
        }
        let up = if to_light > 0.0 {
            normal
        } else {
            scale(normal, -1.0)
        };
        let light_height = to_light.abs();
        let centre_height = light_height + dot(up, self.centre);
        let (across, along) = perpendiculars(up);
        // The margin grows with distance: it is worked out again until it covers the
        // farthest point it gives.
        let mut distance = 0.0f32;
        for _ in 0..4 {
            let half = self.radius + self.margin(distance);
            let low = (centre_height - half).max(-ON_SURFACE);
            let high = (centre_height + half).min(light_height);
            if low > high {
                return Some(None);
            }
            // Beyond 63/64 of the light's height the shadow stretches more than 64 times as
            // far from the light as the sphere: not worth bounding.
            if !exceeds(light_height * (63.0 / 64.0), high) {
                return None;
            }
            let mut points = [[0.0f32; 3]; 64];
            let mut count = 0;
            // The cut sphere in two: below the slab's top, a vertex is a point of the slab
            // itself; above, its ray enters the slab at the top face.
            let top = ON_SURFACE.clamp(low, high);
            for (from, to, above) in [(low, top, false), (top, high, true)] {
                if from > to {
                    continue;
                }
                // The widest cross-section of the sphere between those heights, and the
                // octagon around it: the prism on it holds that part of the sphere.
                let off = (centre_height - centre_height.clamp(from, to)).abs();
                let round = libm::sqrtf((half * half - off * off).max(0.0)) * 1.001;
                let reach = round * OCTAGON;
                for height in [from, to] {
                    for (a, b) in OCTAGON_VERTICES {
                        let corner = add(
                            add(self.centre, scale(up, height - centre_height)),
                            add(scale(across, a * reach), scale(along, b * reach)),
                        );
                        // The ray from the light through the corner is at height h at the
                        // fraction (light − h) / (light − corner) of the way along, past 1.
                        let at =
                            |h: f32| scale(corner, (light_height - h) / (light_height - height));
                        let enters = if above { at(ON_SURFACE) } else { corner };
                        for p in [enters, at(-ON_SURFACE)] {
                            if let Some(slot) = points.get_mut(count) {
                                *slot = p;
                                count += 1;
                            }
                        }
                    }
                }
            }
            let points = points.get(..count)?;
            let farthest = points.iter().fold(0.0f32, |m, &p| {
                m.max(length(p)).max(length(sub(p, self.centre)))
            });
            if !farthest.is_finite() {
                return None;
            }
            if farthest <= distance {
                return screen_area(
                    points.iter().map(|&p| add(self.light_from_eye, p)),
                    map,
                    damage,
                );
            }
            distance = farthest * 1.25 + 1.0;
        }
        None
    }
}

/// The pixels that may show points `from_eye` (offsets from the eye) and anything in their
/// convex hull, or `None` if one lies less than [`NEAREST`] ahead of the eye. Empty (inner
/// `None`) when the box misses the screen.
pub(super) fn screen_area(
    from_eye: impl Iterator<Item = F3>,
    map: &ScreenMap,
    damage: &Damage,
) -> Option<Option<Area>> {
    let (mut min, mut max) = ([f32::MAX; 2], [f32::MIN; 2]);
    let mut nearest = f32::MAX;
    for d in from_eye {
        let [u, v] = map.position(d, NEAREST)?;
        nearest = nearest.min(map.depth(d));
        (min[0], min[1]) = (min[0].min(u), min[1].min(v));
        (max[0], max[1]) = (max[0].max(u), max[1].max(v));
    }
    if !exceeds(f32::MAX, nearest) {
        return Some(None);
    }
    // Two pixels: a ray may miss its exact direction by half a pixel (see `Camera`), and
    // `f32` rounding here is a small fraction of one. A hit point's own rounding, a few
    // units of 2⁻¹⁶ (taken as 2⁻¹²), moves its picture by up to about view / depth times
    // that, and more towards the screen's edges, by (view² + offset²) / view.
    let view = map.view();
    let offset = [min[0].abs(), max[0].abs(), min[1].abs(), max[1].abs()]
        .into_iter()
        .fold(0.0f32, f32::max)
        + f32::from(damage.cols.max(damage.rows));
    let margin = 2.0 + (view + offset * offset / view) / (nearest * 4096.0) + offset / 65536.0;
    damage.area_of(min, max, margin)
}

/// The pixels that may see `plane`, if it is bounded and its rectangle lies ahead of the
/// eye: inner `None` when none can; `None` when it is unbounded or not wholly ahead.
pub(super) fn plane_area(
    plane: &Plane,
    eye: Vec3,
    map: &ScreenMap,
    damage: &Damage,
) -> Option<Option<Area>> {
    let [min, max] = plane.bounds()?;
    let normal = plane.normal();
    let (nx, ny, nz) = (normal.x.abs(), normal.y.abs(), normal.z.abs());
    // The axes `Plane::coords` measures the bounds on, and the one it drops.
    let (a, b, dropped) = if ny >= nx && ny >= nz {
        (0, 2, 1)
    } else if nz >= nx {
        (0, 1, 2)
    } else {
        (1, 2, 0)
    };
    let n = f3(normal);
    let (point, eye) = (f3(plane.point()), f3(eye));
    let slack = 1.0 / 256.0;
    let mut corners = [[0.0f32; 3]; 8];
    let mut count = 0;
    for u in [
        min[0].to_num::<f32>() - slack,
        max[0].to_num::<f32>() + slack,
    ] {
        for v in [
            min[1].to_num::<f32>() - slack,
            max[1].to_num::<f32>() + slack,
        ] {
            let mut p = [0.0f32; 3];
            p[a] = u;
            p[b] = v;
            // On the plane: n·(p − point) = 0 fixes the dropped coordinate (its normal
            // component is the largest, at least 1/√3).
            p[dropped] =
                point[dropped] - (n[a] * (u - point[a]) + n[b] * (v - point[b])) / n[dropped];
            for side in [-ON_SURFACE, ON_SURFACE] {
                if let Some(slot) = corners.get_mut(count) {
                    *slot = add(sub(p, eye), scale(n, side));
                    count += 1;
                }
            }
        }
    }
    screen_area(corners.into_iter(), map, damage)
}
