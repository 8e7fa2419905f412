//! A crowded row's pixels that no run shades: in a scene of more than 32 objects, where the shadow
//! sets no longer name objects, a pixel on a matte sphere sends its shadow rays to the few objects
//! that may shadow that sphere from each light ([`SphereShadowers`]), and a pixel on the row's
//! floor to the floor's casters of its column (`crowd_floor`), instead of each walking the light's
//! sweep (`accel/shadow_sweep.rs`).
//!
//! A shadow ray from a point of a sphere passes within `ρ` of its centre (the point itself does),
//! so seen from the light it leaves along a direction whose steps lie within the sphere's own
//! intervals along every axis ([`shadow_sweep::steps_from`]). An object that blocks it holds that
//! direction within its intervals too, so walking the sweep once for the sphere's intervals, rather
//! than once a ray for its direction, finds every object that can shadow any of its points. Of
//! those, a sphere whose near side lies past this one's far side from the light shadows none of
//! them, nor one whose cone the directions within the intervals all miss
//! (`ShadowCone::may_block_within`, the cone test's own arithmetic taken at the corners of the
//! intervals), nor one whose own chord of directions lies farther from this one's than the two
//! chords reach (`ShadowCone::may_meet_within`: the cones' margins widen a small sphere's several
//! times over, the chords only by the rounding). A pixel's shadow ray then tries the few found,
//! each by the same cone and test as [`Scene::occluded_among`]: every object that can block it is
//! among them, so the pixel is bit for bit the plain path's.
//!
//! A frame's rows share the objects found ([`render`](crate::render)), [`FRAME_SLOTS`] spheres' at
//! a time, each in the slot its index picks (about 9 KB for two lights); a row drawn alone finds
//! its own, in [`ROW_SLOTS`] (about 1 KB). Past [`KEPT`] objects for a light, or for a sphere whose
//! cone bounds nothing, the rays walk the sweep as before. Only scenes whose capacity passes 32
//! make them (`render_every`); the others' pixels are shaded through `()`, as before.

use crate::geometry::ray::Ray;
use crate::geometry::shape::Shape;
use crate::numbers::fx::{self, Fx};
use crate::render::accel::crowd_floor::Floor;
use crate::render::accel::shade::blocks;
use crate::render::accel::shadow_rows::blocking_radius;
use crate::render::accel::shadow_sweep;
use crate::render::trace::Surface;
use crate::scene::hit::SceneHit;
use crate::scene::light::Light;
use crate::scene::{Rgb, Scene};

/// The most objects kept for a sphere and a light: at most 64, a mask's bits (and a `u8`).
const KEPT: usize = 32;

/// What shades a row's pixels that no run shades: a crowd's [`SphereShadowers`], or `()`,
/// which shades each as [`Scene::pixel_among`] does.
pub(crate) trait Pixels<const N: usize, const L: usize> {
    /// The pixel of `ray`, display column `column`, whose first hit is `hit`, as
    /// [`Scene::pixel_among`] shades it.
    fn pixel(
        &mut self,
        scene: &Scene<N, L>,
        ray: (&Ray, u16),
        hit: Option<SceneHit>,
        plane_shadowers: &[u32; L],
    ) -> Rgb;
}

impl<const N: usize, const L: usize> Pixels<N, L> for () {
    fn pixel(
        &mut self,
        scene: &Scene<N, L>,
        (ray, _): (&Ray, u16),
        hit: Option<SceneHit>,
        plane_shadowers: &[u32; L],
    ) -> Rgb {
        scene.pixel_among(ray, hit, plane_shadowers)
    }
}

/// The objects that may shadow the spheres a frame's pixels met last, for each light (see the
/// module's notes): `S` spheres', each in the slot its index picks.
pub(crate) struct SphereShadowers<const L: usize, const S: usize> {
    slots: [Slot<L>; S],
}

/// How many spheres' objects a frame's rows keep: a row meets a few dozen spheres, and the
/// rows after it most of the same.
pub(crate) const FRAME_SLOTS: usize = 64;

/// How many a row drawn alone keeps: the spheres of a row, where a frame's slots would be
/// found again for each row, and stand on the stack for nothing.
pub(crate) const ROW_SLOTS: usize = 8;

/// The objects that may shadow one sphere, for each light.
struct Slot<const L: usize> {
    /// The sphere they are for; `usize::MAX`: none yet.
    sphere: usize,
    /// For each light, the objects in `kept[light][..counts[light]]`; a count past [`KEPT`]:
    /// none kept, the sweep serves.
    kept: [[u16; KEPT]; L],
    counts: [u8; L],
}

impl<const L: usize, const S: usize> SphereShadowers<L, S> {
    /// For no sphere yet.
    pub(crate) const fn new() -> Self {
        SphereShadowers {
            slots: [const {
                Slot {
                    sphere: usize::MAX,
                    kept: [[0; KEPT]; L],
                    counts: [0; L],
                }
            }; S],
        }
    }
}

impl<const L: usize> Slot<L> {
    /// Finds the objects that may shadow sphere `sphere` of `scene` from each light.
    fn gather<const N: usize>(&mut self, scene: &Scene<N, L>, sphere: usize) {
        self.sphere = sphere;
        let objects = scene.objects();
        let caches = scene.shadow_caches();
        let lights = scene.lights().iter().enumerate();
        for ((light, kept), count) in lights.zip(&mut self.kept).zip(&mut self.counts) {
            *count = KEPT as u8 + 1;
            let (index, light) = light;
            let (Some(sweep), Some(cones), Some(object)) = (
                caches.sweep(index, objects.len()),
                caches.cones(index),
                objects.get(sphere),
            ) else {
                continue;
            };
            let Shape::Sphere(ball) = &object.shape else {
                continue;
            };
            let from = shadow_sweep::steps_from(light.position, &object.shape);
            let Some((steps, axis, spread)) = from else {
                continue;
            };
            // The sphere's points lie within `ρ` of its centre, which lies within a unit of
            // 2⁻¹⁶ of `length` from the light (lights and spheres within ±1024: no
            // saturation, and the square of at most 2²⁹ fits). Every shadow ray from them
            // starts at most `far` from the light.
            let distance = ball.centre().minus(light.position).length().to_bits();
            let far = (distance as u64) + blocking_radius(ball.radius()).to_bits() as u64 + 1;
            let far_squared = far * far;
            let within = shadow_sweep::components_within(steps);
            let mut found = 0;
            let full = shadow_sweep::any_within(sweep, steps, |other| {
                let shadows = match (cones.get(other), objects.get(other).map(|o| o.shape)) {
                    (Some(cone), Some(Shape::Sphere(ball))) => {
                        !cone.starts_past(far_squared)
                            && cone.may_block_within(within)
                            && cone.may_meet_within(ball.radius(), axis, spread)
                    }
                    (Some(_), Some(Shape::Plane(_))) => true,
                    _ => false,
                };
                if other == sphere || !shadows {
                    return false;
                }
                match kept.get_mut(found) {
                    Some(slot) => {
                        *slot = other as u16;
                        found += 1;
                        false
                    }
                    None => true,
                }
            });
            if !full {
                *count = found as u8; // at most `KEPT`
            }
        }
    }

    /// [`Scene::reaches_among`] for a shadow ray from `at`, a point of the sphere the objects
    /// are for, towards light `index`: its cosine, or `None` where it is blocked or unlit.
    fn reaches<const N: usize>(
        &self,
        scene: &Scene<N, L>,
        index: usize,
        light: &Light,
        at: &Surface,
    ) -> Option<Fx> {
        let (kept, cones) = match (self.counts.get(index), self.kept.get(index)) {
            (Some(&count), Some(kept)) if usize::from(count) <= KEPT => (
                kept.get(..usize::from(count)),
                scene.shadow_caches().cones(index),
            ),
            _ => (None, None),
        };
        let (Some(kept), Some(cones)) = (kept, cones) else {
            return scene
                .reaches_among(index, light, at, Some(!0))
                .map(|(_, cos)| cos);
        };
        let towards = scene.towards_light(light, at)?;
        let (l, distance_squared) = (towards.l, towards.distance_squared);
        // The cones first, all of them, into a mask (bit `k` for `kept[k]`): few rays lie in
        // any, and which is past foreseeing; then the whole test for those whose cone holds it.
        let mut held = 0u64;
        for (k, &other) in kept.iter().enumerate() {
            let cone = cones.get(usize::from(other));
            let holds = cone.is_some_and(|cone| cone.may_block_all_tested(l, distance_squared));
            held |= u64::from(holds) << k;
        }
        let objects = scene.objects();
        while held != 0 {
            let k = held.trailing_zeros() as usize;
            held &= held - 1;
            let object = kept
                .get(k)
                .and_then(|&other| objects.get(usize::from(other)));
            if object.is_some_and(|object| blocks(object, at.point, l, distance_squared)) {
                return None;
            }
        }
        Some(towards.cos)
    }
}

/// A crowded row's pixels: those on its floor by the row's [`Floor`], those on a sphere by the
/// frame's [`SphereShadowers`].
impl<const N: usize, const L: usize, const S: usize> Pixels<N, L>
    for (&Floor<N, L>, &mut SphereShadowers<L, S>)
{
    fn pixel(
        &mut self,
        scene: &Scene<N, L>,
        (ray, column): (&Ray, u16),
        hit: Option<SceneHit>,
        plane_shadowers: &[u32; L],
    ) -> Rgb {
        let (floor, spheres) = self;
        if let Some(pixel) = hit.and_then(|h| floor.pixel(scene, &h, column.into())) {
            return pixel;
        }
        let found = hit.and_then(|h| Some((h, scene.objects().get(h.object)?)));
        // A matte sphere's; the others' light, with highlights and secondary rays, as the
        // plain path's acceleration forms it.
        let Some((h, object)) = found.filter(|(_, object)| {
            matches!(object.shape, Shape::Sphere(_))
                && object.material.is_plain_matte()
                && scene.shadows()
                && scene.objects().len() > 32
        }) else {
            return scene.pixel_among(ray, hit, plane_shadowers);
        };
        let Some(slot) = spheres.slots.get_mut(h.object % S) else {
            return scene.pixel_among(ray, hit, plane_shadowers);
        };
        if slot.sphere != h.object {
            slot.gather(scene, h.object);
        }
        let at = Surface::of(&h);
        let lights = scene.lights().iter().enumerate();
        let diffuse = lights.fold(Fx::ZERO, |sum, (index, light)| {
            match slot.reaches(scene, index, light, &at) {
                Some(cos) => sum.saturating_add(fx::mul_unit(light.intensity, cos)),
                None => sum,
            }
        });
        let material = &object.material;
        scene.matte_pixel_within_one(material, diffuse, object.colour_at(at.point))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Camera, Light, Plane, Size, Sphere};

    /// Random crowds of 40 to 200 spheres of every size on and above a floor, some near a
    /// light, under one or two lights anywhere, seen from cameras anywhere: for every pixel
    /// whose first hit is a sphere, each object that blocks its shadow ray towards a light is
    /// among those its sphere's slot keeps for that light, or the slot keeps none and the
    /// sweep serves; and a slot keeps few of the objects.
    #[test]
    fn every_object_that_shadows_a_point_of_a_sphere_is_kept_for_it() {
        let mut rng = crate::xorshift::XorShift(0x5eed_5a0e_0000_0001);
        let (mut rays, mut blocked, mut kept, mut objects_seen, mut swept) = (0u64, 0, 0, 0, 0);
        for world in 0..24 {
            let light = |rng: &mut crate::xorshift::XorShift| {
                let at = [rng.signed(30.0), rng.signed(20.0), rng.signed(30.0)];
                Light::new(at, 0.5).unwrap()
            };
            let first = light(&mut rng);
            let mut scene: Scene<201, 2> = Scene::new(first, 0.1, Rgb::BLACK).unwrap();
            if world % 2 == 0 {
                scene.add_light(light(&mut rng)).unwrap();
            }
            let floor = Plane::new([0.0, -3.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
            scene.add_plane(floor, Rgb::WHITE).unwrap();
            let count = 40 + (rng.next() % 161) as usize;
            while scene.objects().len() < count {
                let radius = 0.05 + rng.signed(1.0).abs() * if world % 4 == 0 { 6.0 } else { 1.5 };
                let near_light = rng.next().is_multiple_of(15);
                let centre = match near_light {
                    true => {
                        let at = scene.lights()[0].position();
                        let off = |c: Fx, rng: &mut crate::xorshift::XorShift| {
                            c.to_num::<f32>() + rng.signed(radius * 3.0)
                        };
                        [
                            off(at.x, &mut rng),
                            off(at.y, &mut rng),
                            off(at.z, &mut rng),
                        ]
                    }
                    false => [rng.signed(25.0), rng.signed(6.0), rng.signed(25.0) - 10.0],
                };
                let ball = Sphere::new(centre, radius).unwrap();
                scene.add_sphere(ball, Rgb::WHITE).unwrap();
            }
            let eye = [rng.signed(15.0), rng.signed(10.0), rng.signed(10.0) + 20.0];
            let target = [rng.signed(10.0), rng.signed(3.0), rng.signed(10.0) - 10.0];
            let Ok(camera) = Camera::look_at(eye, target)
                .fov_degrees(rng.signed(1.0).abs() * 90.0 + 30.0)
                .size(Size::new(40, 30))
                .build()
            else {
                continue;
            };
            let mut shadowers = SphereShadowers::<2, FRAME_SLOTS>::new();
            for (row, col) in (0..30).flat_map(|row| (0..40).map(move |col| (row, col))) {
                let ray = camera.ray(col, row);
                let Some(hit) = scene.shoot(&ray) else {
                    continue;
                };
                if !matches!(scene.objects()[hit.object].shape, Shape::Sphere(_)) {
                    continue;
                }
                let slot = &mut shadowers.slots[hit.object % FRAME_SLOTS];
                if slot.sphere != hit.object {
                    slot.gather(&scene, hit.object);
                }
                let point = hit.hit.point;
                for (i, light) in scene.lights().iter().enumerate() {
                    let to_light = light.position() - point;
                    let d2 = to_light.length_squared_wide();
                    let Some(l) = to_light.normalize_with_square(d2) else {
                        continue;
                    };
                    let shadow = Ray::new_unchecked(point, l);
                    rays += 1;
                    let Some(list) = slot.kept[i].get(..usize::from(slot.counts[i])) else {
                        swept += 1;
                        continue;
                    };
                    objects_seen += scene.objects().len() as u64;
                    kept += list.len() as u64;
                    for (index, object) in scene.objects().iter().enumerate() {
                        if index != hit.object && object.shape.blocks(&shadow, d2) {
                            blocked += 1;
                            let found = list.iter().any(|&k| usize::from(k) == index);
                            assert!(found, "world {world}, row {row}, column {col}: {index}");
                        }
                    }
                }
            }
        }
        // The sample holds shadows, a ray tries few of the objects, and most rays try the kept
        // ones (a slot keeps none for about a third here: spheres near a light, whose cones
        // bound nothing, and the worlds of large spheres, which overlap past `KEPT`).
        assert!(blocked * 20 > rays - swept, "{blocked} blocked of {rays}");
        assert!(kept * 5 < objects_seen, "{kept} tried of {objects_seen}");
        assert!(swept * 2 < rays, "{swept} of {rays} rays swept");
    }
}
