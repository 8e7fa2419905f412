//! Which spheres can shadow a display row's hits on planes: a shadow ray from such a hit
//! tries no other sphere.
//!
//! The hits of a row on a plane lie, up to rounding, on one line: where the plane meets the
//! plane through the eye that holds the row's rays. Seen from a light, that line spans one
//! plane through the light, `Π`, and every shadow ray from those hits runs, up to rounding, in
//! `Π`. A sphere farther from `Π` than its radius casts no shadow anywhere on the row's line,
//! so the row's plane hits need not test it. On the demo's ground most rows lie in the shadow
//! of one sphere or none, where every plane hit would otherwise test the cones of all four.
//!
//! The test is worked out once a row in Q16.16, a few products and two divisions a light, with
//! margins wider than every rounding of the render path and of the set-up itself; where a
//! margin cannot be bounded (a light near the plane, a row whose plane grazes it) nothing is
//! ruled out. Shadow rays only ever skip spheres they cannot meet, so the picture is bit for
//! bit the plain path's.

use crate::geometry::plane::Plane;
use crate::geometry::shape::Shape;
use crate::geometry::sphere::Sphere;
use crate::numbers::fx::{self, FAR, Fx};
use crate::numbers::vec3::Vec3;
use crate::scene::Scene;

/// How far a hit point may lie off its plane: the documented 2⁻¹⁰, plus 2⁻¹² for the
/// rounding of the light's height above the plane.
const OFF_PLANE: Fx = Fx::from_bits((1 << 6) + (1 << 4));

/// How far, as an angle, a row's ray may stray from the row's plane as `Camera`
/// rounds that plane's normal: the ray's unit direction is within 2⁻¹⁵ of exact, the normal
/// within 2⁻¹⁴; 2⁻¹² leaves room.
const OFF_ROW_SHIFT: u32 = 12;

/// One unit of 2⁻¹⁶ per component of a rounded unit vector: within 2⁻¹⁵ of exact.
const ROUNDED_DIRECTION: Fx = Fx::from_bits(2);

/// For each light, the objects (bit `i` for object `i`) that may shadow a hit on one of the
/// planes `planes` (bit `i` for object `i`) of the display row whose plane through the eye at
/// `eye` has the unit normal `row_normal` (`Camera::row_plane_normal`): every object but the
/// spheres that lie too far from the row's `Π` for each of those planes. `!0` where nothing
/// is ruled out: shadows off, no plane, or more than 32 objects (the shadow sets' limit).
// Out of line, with the rest of the shadow sets' set-up (`scaled`, `product`, `quotient`,
// `RunLine::shadowed_by`): it runs once a row, and in line it crowds the row's pixel loops.
#[inline(never)]
pub(crate) fn row_shadowers<const N: usize, const L: usize>(
    scene: &Scene<N, L>,
    eye: Vec3,
    row_normal: Vec3,
    planes: u64,
) -> [u32; L] {
    let mut sets = [!0u32; L];
    let objects = scene.objects();
    if !scene.shadows() || planes == 0 || objects.len() > 32 {
        return sets;
    }
    // A sphere is ruled out for a light only where every plane of the row rules it out. The
    // planes go outermost: the angle between a plane and the row's is the lights' to share.
    let mut ruled_out = [!0u32; L];
    let mut rest = planes;
    let lights = scene.lights().len();
    while rest != 0 && ruled_out.iter().take(lights).any(|&r| r != 0) {
        let index = rest.trailing_zeros() as usize;
        rest &= rest - 1;
        let Some(Shape::Plane(plane)) = objects.get(index).map(|o| o.shape) else {
            ruled_out = [0; L];
            break;
        };
        let sin_row = sin_between(row_normal, &plane);
        for (out, light) in ruled_out.iter_mut().zip(scene.lights()) {
            if *out != 0 {
                let row = (row_normal, sin_row);
                *out &= far_from_row(scene, &plane, row, eye, light.position()).unwrap_or(0);
            }
        }
    }
    for (set, out) in sets.iter_mut().zip(ruled_out).take(lights) {
        *set = !out;
    }
    sets
}

/// The sine of the angle between a row's plane, whose unit normal is `row_normal`, and
/// `plane`, `|row_normal × n|`, less its rounding.
pub(crate) fn sin_between(row_normal: Vec3, plane: &Plane) -> Fx {
    row_normal.cross(plane.normal()).length() - Fx::from_bits(1 << 3)
}

/// The spheres (bit `i` for object `i`) that cannot shadow any hit of the row whose plane
/// has the unit normal `row_normal` on `plane` from a light at `light`, or `None` where the
/// margins cannot be bounded. `sin_row` is [`sin_between`] the two planes.
fn far_from_row<const N: usize, const L: usize>(
    scene: &Scene<N, L>,
    plane: &Plane,
    row: (Vec3, Fx),
    eye: Vec3,
    light: Vec3,
) -> Option<u32> {
    let pencil = Pencil::of_row(plane, row, eye, light)?;
    let mut ruled_out = 0u32;
    for (index, object) in scene.objects().iter().enumerate().take(32) {
        if let Shape::Sphere(sphere) = object.shape
            && pencil.rules_out(&sphere)
        {
            ruled_out |= 1 << index;
        }
    }
    Some(ruled_out)
}

/// `Π` seen from a light (see the module's notes): its unit normal, the light, and the widest
/// angle by which a shadow ray from a hit of the row may stray from it.
pub(crate) struct Pencil {
    pi: Vec3,
    light: Vec3,
    angle: Fx,
}

impl Pencil {
    /// The pencil of the row whose plane has the unit normal `row_normal` on `plane`, seen
    /// from a light at `light`, or `None` where the margins cannot be bounded. `sin_row` is
    /// [`sin_between`] the two planes.
    pub(crate) fn of_row(
        plane: &Plane,
        (row_normal, sin_row): (Vec3, Fx),
        eye: Vec3,
        light: Vec3,
    ) -> Option<Self> {
        let normal = plane.normal();
        // The light's height above the plane: shadow rays from it are at least `reach` long.
        // Lights, eyes and planes' points lie within ±LIMIT: no difference here saturates.
        let height = normal.dot_units(light - plane.point());
        let reach = height.abs() - OFF_PLANE;
        if reach < Fx::from_bits(1 << 14) || sin_row < Fx::from_bits(1 << 10) {
            return None; // a light within ¼ of the plane, or a row's plane within 1/64 of it
        }
        // Π's normal: the plane of the pencil through the row's line on `plane` that holds the
        // light, `height · m − (m·(light − eye)) · n`. Its rounding, from `m`'s 2⁻¹⁴ and the
        // products', is below `error`.
        let to_light = light - eye;
        let across = row_normal.dot_units(to_light);
        let pi = scaled(row_normal, height) - scaled(normal, across);
        let error =
            Fx::from_bits(((height.abs().to_bits() as i64 + to_light.l1_raw()) >> 14) as i32 + 12);
        let size = pi.length();
        let pi = pi.try_normalize()?;
        // A hit lies within OFF_PLANE of `plane` and within `t / 2¹²` of the row's plane, `t` its
        // distance from the eye: within `(OFF_PLANE + t / 2¹²) / sin_row` of their line, which
        // lies in Π. Seen from the light, at least `reach` away, with `t` at most `reach` plus
        // `|light − eye|` more than that, the direction to the hit is off Π by at most `off`; Π's
        // rounded normal, by `tilt`. `|light − eye|` is taken at most the sum of its components'
        // sizes, which needs no root (each below 2¹², from coordinates within ±LIMIT).
        let from_eye = Fx::from_bits(to_light.l1_raw().min(i32::MAX as i64 >> 2) as i32);
        let off = quotient(
            OFF_PLANE + ((reach.saturating_add(from_eye)) >> OFF_ROW_SHIFT),
            product(reach, sin_row),
        )?;
        let tilt = quotient(error * 2, size)? + ROUNDED_DIRECTION;
        let angle = off.saturating_add(tilt);
        if angle >= Fx::ONE {
            return None;
        }
        Some(Pencil { pi, light, angle })
    }

    /// Whether the sphere `sphere` lies too far from `Π` to shadow any hit of the row.
    pub(crate) fn rules_out(&self, sphere: &Sphere) -> bool {
        let wide = blocking_radius(sphere.radius());
        let to_centre = sphere.centre() - self.light;
        // At least the distance to the centre; within ±2048 · 3.
        let distance = Fx::from_bits(to_centre.l1_raw() as i32);
        // The shadow ray passes within `wide` of the centre at a point at most
        // `distance + wide` from the light, which is within `(distance + wide) · angle` of Π.
        let limit = wide
            .saturating_add(product(distance + wide, self.angle))
            .saturating_add(Fx::from_bits(1 << 8));
        self.pi.dot_units(to_centre).abs() > limit
    }
}

/// How near a sphere of radius `radius` the exact line from a hit to a light passes where a
/// shadow ray along it is blocked: the radius widened by the test's rounding, as
/// `shadowers.rs` allows for it (√r/32 ≤ (r + 1)/64), and by the ray's rounded direction, off
/// the exact one by 2⁻¹⁵ over at most FAR + r, which the test's closest point lies within.
// In raw units, for the `const` shadow sweep: radii lie within 2048, and nothing overflows.
pub(crate) const fn blocking_radius(radius: Fx) -> Fx {
    let (r, far) = (radius.to_bits(), FAR.to_bits());
    Fx::from_bits(r + ((r + (1 << 16)) >> 6) + (1 << 8) + ((far + r) >> 15))
}

/// `v.scale(s)`: once a row and light, twice.
// Out of line, as `row_shadowers` is: set-up that in line crowds the row's pixel loops.
#[inline(never)]
fn scaled(v: Vec3, s: Fx) -> Vec3 {
    v.scale(s)
}

/// `a.saturating_mul(b)`: twice a row and light. The exact product floored to Q16.16 and held
/// within range, as `saturating_mul` forms it, by the chip's cheapest exact product
/// (`fx::wide_mul`): on the Cortex-M0 the library's is four calls of a long routine.
// Out of line, as `row_shadowers` is: set-up that in line crowds the row's pixel loops.
#[inline(never)]
fn product(a: Fx, b: Fx) -> Fx {
    let floored = fx::wide_mul(a.to_bits(), b.to_bits()) >> 16;
    Fx::from_bits(floored.clamp(i32::MIN as i64, i32::MAX as i64) as i32)
}

/// `num / den` for positive `den`, rounded up, or `None` from 1 up: an angle that wide rules
/// nothing out. Once a row and light: a plain division.
// Out of line, as `row_shadowers` is: set-up that in line crowds the row's pixel loops.
#[inline(never)]
fn quotient(num: Fx, den: Fx) -> Option<Fx> {
    let (num, den) = (num.to_bits(), den.to_bits());
    if num < 0 || den <= 0 || num >= den {
        return None;
    }
    // At most 2¹⁶, as num < den.
    Some(Fx::from_bits(
        (((num as u64) << 16).div_ceil(den as u64)) as i32,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_product_is_the_saturating_one() {
        let mut rng = crate::xorshift::XorShift(0x3c6e_f372_fe94_f82b);
        let ends = [
            i32::MIN,
            i32::MIN + 1,
            -65536,
            -1,
            0,
            1,
            65535,
            65536,
            i32::MAX,
        ];
        let pairs = ends.iter().flat_map(|&a| ends.map(|b| (a, b)));
        let random = (0..200_000).map(|i| {
            let s = rng.next();
            ((s as i32) >> (i % 31), ((s >> 32) as i32) >> (i / 31 % 31))
        });
        for (a, b) in pairs.chain(random) {
            let (a, b) = (Fx::from_bits(a), Fx::from_bits(b));
            assert_eq!(product(a, b), a.saturating_mul(b), "{a:?} × {b:?}");
        }
    }
    use crate::geometry::ray::Ray;
    use crate::geometry::sphere::Sphere;
    use crate::scene::colour::Rgb;
    use crate::scene::light::Light;
    use crate::{Camera, Size, demo};

    /// The sets of display row `row`.
    fn sets_of_row<const N: usize, const L: usize>(
        scene: &Scene<N, L>,
        camera: &Camera,
        row: u16,
        planes: u64,
    ) -> [u32; L] {
        let normal = camera.row_plane_normal(row).unwrap();
        row_shadowers(scene, camera.eye(), normal, planes)
    }

    #[test]
    fn the_demo_rows_away_from_the_shadows_test_no_sphere() {
        let (scene, camera) = (demo::scene(), demo::camera(160, 128).unwrap());
        let spheres = 0b11110;
        // The bottom rows see the ground in front of every ball and its shadow.
        for row in 104..128 {
            let sets = sets_of_row(&scene, &camera, row, 1);
            assert_eq!(sets[0] & spheres, 0, "row {row}");
        }
        // Above them, the rows where the plain path finds the ground shadowed keep the spheres
        // that shadow it, and in all they keep few.
        let mut kept = 0;
        for row in 0..104 {
            let set = sets_of_row(&scene, &camera, row, 1)[0];
            kept += (set & spheres).count_ones();
            for col in 0..160 {
                let ray = camera.ray(col, row.into());
                let Some(hit) = scene.shoot(&ray).filter(|hit| hit.object == 0) else {
                    continue;
                };
                let to_light = scene.lights()[0].position - hit.hit.point;
                let d2 = to_light.length_squared_wide();
                let shadow = Ray::new_unchecked(hit.hit.point, to_light.try_normalize().unwrap());
                for ball in 1..5 {
                    let only = 1 << ball;
                    if scene.occluded_among(shadow.origin(), shadow.dir(), d2, 0, 0, only) {
                        assert_ne!(set & only, 0, "row {row}, column {col}, ball {ball}");
                    }
                }
            }
        }
        // Rows 64 to 103 see the floor: 160 spheres in all without the sets, 66 with them.
        assert!(kept <= 80, "rows 0 to 103 keep {kept} spheres");
    }

    #[test]
    fn nothing_is_ruled_out_without_shadows_or_past_32_objects() {
        let (mut scene, camera) = (demo::scene(), demo::camera(160, 128).unwrap());
        assert_ne!(sets_of_row(&scene, &camera, 120, 1), [!0; 4]);
        scene.set_shadows(false);
        assert_eq!(sets_of_row(&scene, &camera, 120, 1), [!0; 4]);
        // Shadow sets hold 32 objects: a 33rd leaves every row's set whole.
        let light = Light::new([0.0, 20.0, 0.0], 1.0).unwrap();
        let mut crowd: Scene<33, 1> = Scene::new(light, 0.1, Rgb::BLACK).unwrap();
        let floor = Plane::new([0.0, -4.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
        crowd.add_plane(floor, Rgb::WHITE).unwrap();
        for i in 0..32 {
            let ball = Sphere::new([i as f32 - 16.0, 0.0, -40.0], 0.4).unwrap();
            crowd.add_sphere(ball, Rgb::WHITE).unwrap();
            let set = sets_of_row(&crowd, &camera, 127, 1)[0];
            assert_eq!(set == !0, i == 31, "{} objects", i + 2);
        }
    }

    /// Random worlds: a floor (level or tilted), a wall, eight spheres, one or two lights
    /// anywhere above the floor (some close to it), cameras looking anywhere with any field of
    /// view. For every pixel whose first hit is a plane, a sphere that its row rules out must
    /// not block the shadow ray that `Scene::local` would send to any light.
    #[test]
    fn a_sphere_ruled_out_never_blocks_a_shadow_ray_of_the_row() {
        let mut rng = crate::xorshift::XorShift(0x05ee_d0f5_ad00_0001);
        let mut next = move |range: f64| {
            let seed = rng.next();
            ((seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0) * range
        };
        let (mut tried, mut ruled_out, mut blocked) = (0u64, 0u64, 0u64);
        for world in 0..120 {
            let light = |next: &mut dyn FnMut(f64) -> f64| {
                let height = if world % 4 == 0 {
                    next(0.6).abs()
                } else {
                    next(12.0).abs()
                };
                Light::new(
                    [
                        next(12.0) as f32,
                        (height - 1.7) as f32,
                        next(12.0) as f32 - 6.0,
                    ],
                    0.8,
                )
                .unwrap()
            };
            let mut scene: Scene<11, 2> = Scene::new(light(&mut next), 0.1, Rgb::BLACK).unwrap();
            if world % 2 == 0 {
                scene.add_light(light(&mut next)).unwrap();
            }
            let tilt = if world % 3 == 0 {
                next(0.4) as f32
            } else {
                0.0
            };
            let floor = Plane::new([0.0, -2.0, 0.0], [tilt, 1.0, next(0.2) as f32 * tilt]).unwrap();
            scene.add_plane(floor, Rgb::WHITE).unwrap();
            let wall = Plane::new([0.0, 0.0, -20.0], [next(0.5) as f32, 0.0, 1.0]).unwrap();
            scene.add_plane(wall, Rgb::WHITE).unwrap();
            for _ in 0..8 {
                let centre = [next(8.0) as f32, next(3.0) as f32, next(8.0) as f32 - 8.0];
                let ball = Sphere::new(centre, (next(1.0).abs() * 2.0 + 0.1) as f32).unwrap();
                scene.add_sphere(ball, Rgb::WHITE).unwrap();
            }
            let eye = [
                next(10.0) as f32,
                next(6.0) as f32 + 3.0,
                next(6.0) as f32 + 8.0,
            ];
            let target = [
                next(6.0) as f32,
                next(3.0) as f32 - 2.0,
                next(6.0) as f32 - 8.0,
            ];
            let Ok(camera) = Camera::look_at(eye, target)
                .fov_degrees((next(1.0).abs() * 120.0 + 10.0) as f32)
                .size(Size::new(48, 36))
                .build()
            else {
                continue;
            };
            let planes = 0b11;
            for row in 0..camera.rows() {
                let sets = sets_of_row(&scene, &camera, row, planes);
                for col in 0..camera.cols() {
                    let ray = camera.ray(col.into(), row.into());
                    let Some(hit) = scene.shoot(&ray) else {
                        continue;
                    };
                    if hit.object > 1 {
                        continue; // a sphere: its shadow rays try its whole set
                    }
                    let point = hit.hit.point;
                    for (light, set) in scene.lights().iter().zip(sets) {
                        let to_light = light.position - point;
                        let d2 = to_light.length_squared_wide();
                        let Some(l) = to_light.normalize_with_square(d2) else {
                            continue;
                        };
                        let shadow = Ray::new_unchecked(point, l);
                        for (index, object) in scene.objects().iter().enumerate().skip(2) {
                            let blocks = object.shape.hit_distance(&shadow).is_some_and(|t| {
                                let t = t.to_bits() as u32;
                                crate::numbers::fx::wide_mul_u32(t, t) < d2
                            });
                            tried += 1;
                            blocked += blocks as u64;
                            if set & (1 << index) == 0 {
                                ruled_out += 1;
                                assert!(
                                    !blocks,
                                    "world {world}, row {row}, column {col}: object {index} \
                                     shadows {point:?} but was ruled out"
                                );
                            }
                        }
                    }
                }
            }
        }
        // The sample holds shadows, and the rows rule out most spheres.
        assert!(blocked > 20_000, "shadowed: {blocked} of {tried}");
        assert!(ruled_out * 2 > tried, "ruled out {ruled_out} of {tried}");
    }
}
