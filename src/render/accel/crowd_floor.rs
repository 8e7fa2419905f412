//! [`Floor`]: in a scene of more than 32 objects, a display row's casters on its floor — for
//! each light, the objects that may shadow some column of the row's hits on one matte plane,
//! with those columns — so that a shadow ray from the floor tries only the few whose columns
//! hold its own, not the light's whole sweep (`accel/shadow_sweep.rs`).
//!
//! Past 32 objects the shadow sets (`shadow_rows`, `shadow_columns`) no longer name objects
//! and every floor pixel sends its shadow rays through the sweep. A row's hits on a plane its
//! column step is parallel to lie, up to rounding, on one line: only objects whose shadow
//! directions meet those of the line's points can shadow them, which one walk of the light's
//! sweep finds (`shadow_sweep::steps_along`); of those, a sphere far from the plane through
//! the line and the light (`Pencil`, as `shadow_rows` finds it) shadows none of them, and any
//! other only the columns `SeenFrom` finds for it (a few products, most spheres ruled out by
//! the line's two ends without a division); other planes may shadow any column. They are
//! found once a row and light, sorted by their first column, and a floor pixel's shadow
//! ray towards a light tries those whose columns hold the pixel's, each by the same cone and
//! test as [`Scene::occluded_among`]: every object that can block the ray is among them, so
//! the pixel is bit for bit the plain path's.
//!
//! Only scenes whose capacity passes 32 make one (`render_every`); the others' matte runs
//! are shaded as before, through `()`, which shades none.

use crate::geometry::plane::far_reach;
use crate::geometry::shape::Shape;
use crate::numbers::fx::{self, Fx};
use crate::numbers::vec3::Vec3;
use crate::render::accel::crowd::Names;
use crate::render::accel::cull::Eye;
use crate::render::accel::matte::{Axis, MatteRun, Walk};
use crate::render::accel::shade::blocks;
use crate::render::accel::shadow_columns::RunLine;
use crate::render::accel::shadow_rows::{Pencil, sin_between};
use crate::render::accel::shadow_sweep;
use crate::render::camera::Camera;
use crate::render::trace::{Surface, TowardsLight};
use crate::scene::hit::SceneHit;
use crate::scene::{Rgb, Scene};

/// An object that may shadow the row's columns `first..end` on the floor from a light.
#[derive(Debug, Clone, Copy)]
struct Caster {
    first: u16,
    end: u16,
    object: u32,
}

impl Caster {
    const NONE: Self = Caster {
        first: 0,
        end: 0,
        object: 0,
    };
}

/// A row's casters on its floor, for each light (see the module's notes).
pub(crate) struct Floor<const N: usize, const L: usize> {
    /// The plane whose matte runs are shaded here; `None`: none of the row's.
    plane: Option<usize>,
    /// For each light, its casters in `casters[light][..counts[light]]`, by first column.
    casters: [[Caster; N]; L],
    counts: [usize; L],
}

/// What shades a row's matte runs besides [`Scene::shade_matte_run`]: a crowd's [`Floor`], or
/// `()`, which shades none.
pub(crate) trait Floors<const N: usize, const L: usize>: Copy {
    /// Shades the matte run `run`, whose first pixel is display column `first` and whose next
    /// ones are `stride` apart, into `out`, as `Scene::shade_matte_run` does; `false`, with
    /// `out` untouched, where it does not.
    fn shade(
        self,
        scene: &Scene<N, L>,
        camera: &Camera,
        run: &MatteRun<'_>,
        place: (u16, u16),
        out: &mut [Rgb],
    ) -> bool;
}

impl<const N: usize, const L: usize> Floors<N, L> for () {
    fn shade(
        self,
        _: &Scene<N, L>,
        _: &Camera,
        _: &MatteRun<'_>,
        _: (u16, u16),
        _: &mut [Rgb],
    ) -> bool {
        false
    }
}

impl<const N: usize, const L: usize> Floor<N, L> {
    /// The casters of display row `row` on its floor: the first plane of `scene` that is
    /// matte, unbounded, facing along an axis and parallel to the row's column step, whose
    /// hits on the row all lie within reach (`eye` holds its numerator for the row's rays).
    /// None where shadows are off or the scene holds at most 32 objects (the shadow sets
    /// serve it), or no plane is such.
    pub(crate) fn of_row<C: Names>(
        scene: &Scene<N, L>,
        camera: &Camera,
        row: u16,
        eye: &Eye<N, C>,
    ) -> Self {
        let mut floor = Floor {
            plane: None,
            casters: [[Caster::NONE; N]; L],
            counts: [0; L],
        };
        let objects = scene.objects();
        if !scene.shadows() || objects.len() <= 32 {
            return floor;
        }
        let step = camera.column_step();
        let found = objects.iter().enumerate().find_map(|(index, object)| {
            let Shape::Plane(plane) = object.shape else {
                return None;
            };
            let normal = plane.normal();
            let usable = object.material.is_plain_matte()
                && plane.bounds().is_none()
                && Axis::of(normal).is_some()
                && normal.dot_wide_exact(step) == 0;
            usable.then_some((index, plane))
        });
        let Some((index, plane)) = found else {
            return floor;
        };
        let towards = camera.row_start(row);
        let Some(row_normal) = camera.row_plane_normal_from(towards) else {
            return floor;
        };
        let row_plane = (row_normal, sin_between(row_normal, &plane));
        let den = plane.normal().dot_wide_exact(towards);
        let Some(scale) = plane.scale_along(eye.numerator(index), den) else {
            return floor;
        };
        let line = RunLine {
            eye: camera.eye(),
            scale,
            reach: far_reach(scale),
            towards,
            step,
            len: camera.cols().into(),
        };
        let lights = scene.lights().iter().enumerate();
        for (((light_index, light), casters), count) in
            lights.zip(&mut floor.casters).zip(&mut floor.counts)
        {
            // Past the reach at an end, or an empty row: the row is left to the matte runs.
            let Ok(seen) = line.seen_from(plane.normal(), light.position()) else {
                return floor;
            };
            let pencil = Pencil::of_row(&plane, row_plane, camera.eye(), light.position());
            let mut consider = |object: usize| {
                let Some(caster) = objects.get(object) else {
                    return;
                };
                let columns = match caster.shape {
                    _ if object == index => return,
                    Shape::Plane(_) => 0..usize::from(u16::MAX),
                    Shape::Sphere(sphere)
                        if pencil.as_ref().is_some_and(|p| p.rules_out(&sphere)) =>
                    {
                        return;
                    }
                    Shape::Sphere(sphere) => {
                        let (first, end, bound) = seen.sides(&sphere);
                        // Beyond the bound on one side at both ends: on that side throughout.
                        if first.min(end) > bound || first.max(end) < -bound {
                            return;
                        }
                        seen.columns(first, end, bound)
                    }
                };
                if let (false, Some(slot)) = (columns.is_empty(), casters.get_mut(*count)) {
                    *slot = Caster {
                        first: columns.start as u16,
                        end: columns.end as u16,
                        object: object as u32,
                    };
                    *count += 1;
                }
            };
            // The objects whose shadow directions may meet those of the row's hits, from the
            // light's sweep; every object where there is none.
            let sweep = scene.shadow_caches().sweep(light_index, objects.len());
            match (sweep, shadow_sweep::steps_along(seen.ends())) {
                (Some(sweep), Some(steps)) => {
                    shadow_sweep::any_within(sweep, steps, |object| {
                        consider(object);
                        false
                    });
                }
                _ => (0..objects.len()).for_each(consider),
            }
            if let Some(found) = casters.get_mut(..*count) {
                found.sort_unstable_by_key(|caster| caster.first);
            }
        }
        floor.plane = Some(index);
        floor
    }

    /// The pixel whose first hit `hit` is on the floor at display column `column`, as
    /// [`Scene::pixel_among`] shades it, its shadow rays trying the casters; `None` for a hit
    /// elsewhere.
    pub(crate) fn pixel(&self, scene: &Scene<N, L>, hit: &SceneHit, column: usize) -> Option<Rgb> {
        let object = scene.objects().get(hit.object)?;
        if self.plane != Some(hit.object) {
            return None;
        }
        let at = Surface::of(hit);
        let mut diffuse = Fx::ZERO;
        for (i, light) in scene.lights().iter().enumerate() {
            let Some(towards) = scene.towards_light(light, &at) else {
                continue;
            };
            if !self.blocked(scene, i, column, &at, &towards) {
                diffuse = diffuse.saturating_add(fx::mul_unit(light.intensity, towards.cos));
            }
        }
        let colour = object.colour_at(at.point);
        Some(scene.matte_pixel_within_one(&object.material, diffuse, colour))
    }

    /// Whether a shadow ray from the floor at `at`, display column `column`, `towards` light
    /// `light`, is blocked: [`Scene::occluded_among`]'s answer, from the light's casters whose
    /// columns hold `column`.
    fn blocked(
        &self,
        scene: &Scene<N, L>,
        light: usize,
        column: usize,
        at: &Surface,
        towards: &TowardsLight,
    ) -> bool {
        let (from, dir, distance_squared) = (at.point, towards.l, towards.distance_squared);
        let Some(cones) = scene.shadow_caches().cones(light) else {
            // Not one of the scene's lights: no cones to go by.
            return scene.occluded(from, dir, distance_squared, at.index);
        };
        let casters = self.casters.get(light).zip(self.counts.get(light));
        let casters = casters.and_then(|(casters, &count)| casters.get(..count));
        let objects = scene.objects();
        for caster in casters.unwrap_or(&[]) {
            if usize::from(caster.first) > column {
                break;
            }
            let index = caster.object as usize;
            if column >= usize::from(caster.end) || index == at.index {
                continue;
            }
            let (Some(object), Some(cone)) = (objects.get(index), cones.get(index)) else {
                continue;
            };
            if cone.may_block(dir, distance_squared) && blocks(object, from, dir, distance_squared)
            {
                return true;
            }
        }
        false
    }
}

impl<const N: usize, const L: usize> Floors<N, L> for &Floor<N, L> {
    fn shade(
        self,
        scene: &Scene<N, L>,
        camera: &Camera,
        run: &MatteRun<'_>,
        (first, stride): (u16, u16),
        out: &mut [Rgb],
    ) -> bool {
        let plane = &run.plane;
        let (Some(object), true) = (
            scene.objects().get(run.index),
            self.plane == Some(run.index),
        ) else {
            return false;
        };
        let den = plane.normal().dot_wide_exact(run.towards);
        let Some(scale) = plane.scale_along(run.num, den) else {
            return false;
        };
        let walk = Walk {
            towards: run.towards,
            step: run.step,
            scale,
            reach: far_reach(scale),
        };
        // Within reach at both ends, every column of an unbounded plane meets it, and the
        // loop's `n`-th call is the run's `n`-th column.
        if !walk.within(out.len()) {
            return false;
        }
        let mut at = Surface {
            index: run.index,
            point: Vec3::ZERO,
            normal: plane.facing(run.num),
        };
        let (material, lights) = (&object.material, scene.lights());
        let mut column = usize::from(first);
        let mut shade = |point: Vec3| {
            at.point = point;
            let mut diffuse = Fx::ZERO;
            for (i, light) in lights.iter().enumerate() {
                let Some(towards) = scene.towards_light(light, &at) else {
                    continue;
                };
                if !self.blocked(scene, i, column, &at, &towards) {
                    diffuse = diffuse.saturating_add(fx::mul_unit(light.intensity, towards.cos));
                }
            }
            column += usize::from(stride);
            scene.matte_pixel_within_one(material, diffuse, object.colour_at(point))
        };
        scene.matte_loop(camera, plane, walk, out, &mut shade);
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::ray::Ray;
    use crate::render::accel::crowd::Crowd;
    use crate::render::accel::runs::Runs;
    use crate::{Light, Plane, Size, Sphere};

    /// Random crowds of 40 to 120 spheres on, above and around a floor, with a wall now and
    /// then, under one or two lights anywhere above it, seen from level cameras anywhere: for
    /// every pixel whose first hit is the floor, each object that blocks its shadow ray
    /// towards a light is one of that light's casters whose columns hold the pixel's; and
    /// the casters a pixel's ray tries are few.
    #[test]
    fn every_object_that_shadows_a_floor_pixel_is_a_caster_of_its_column() {
        let mut rng = crate::xorshift::XorShift(0x5eed_f100_0c0d_0001);
        let (mut floor_rays, mut blocked, mut kept, mut objects_seen) = (0u64, 0u64, 0u64, 0u64);
        for world in 0..16 {
            let light = |rng: &mut crate::xorshift::XorShift| {
                let at = [
                    rng.signed(30.0),
                    rng.signed(14.0).abs() + 0.5,
                    rng.signed(30.0),
                ];
                Light::new(at, 0.5).unwrap()
            };
            let mut scene: Scene<121, 2> = Scene::new(light(&mut rng), 0.1, Rgb::BLACK).unwrap();
            if world % 2 == 0 {
                scene.add_light(light(&mut rng)).unwrap();
            }
            let floor = Plane::new([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
            scene.add_plane(floor, Rgb::WHITE).unwrap();
            let count = 40 + (rng.next() % 81) as usize;
            while scene.objects().len() < count {
                if rng.next().is_multiple_of(40) {
                    let wall = Plane::new([0.0, 0.0, -40.0], [rng.signed(0.5), 0.0, 1.0]);
                    scene.add_plane(wall.unwrap(), Rgb::WHITE).unwrap();
                    continue;
                }
                let radius = 0.1 + rng.signed(1.5).abs();
                let centre = [
                    rng.signed(25.0),
                    radius + rng.signed(3.0),
                    rng.signed(25.0) - 15.0,
                ];
                let ball = Sphere::new(centre, radius).unwrap();
                scene.add_sphere(ball, Rgb::WHITE).unwrap();
            }
            let eye = [
                rng.signed(10.0),
                rng.signed(8.0).abs() + 0.5,
                rng.signed(10.0) + 10.0,
            ];
            let target = [rng.signed(10.0), rng.signed(2.0), rng.signed(10.0) - 20.0];
            let Ok(camera) = Camera::look_at(eye, target)
                .fov_degrees(rng.signed(1.0).abs() * 100.0 + 20.0)
                .size(Size::new(48, 36))
                .build()
            else {
                continue;
            };
            for row in 0..camera.rows() {
                let mut crowd = Crowd::empty();
                let runs = Runs::crowded(&scene, &camera, row, &mut crowd);
                let floor = Floor::of_row(&scene, &camera, row, runs.eye());
                if floor.plane != Some(0) {
                    continue;
                }
                for col in 0..camera.cols() {
                    let ray = camera.ray(col.into(), row.into());
                    let Some(hit) = scene.shoot(&ray).filter(|hit| hit.object == 0) else {
                        continue;
                    };
                    let point = hit.hit.point;
                    for (i, light) in scene.lights().iter().enumerate() {
                        let to_light = light.position() - point;
                        let d2 = to_light.length_squared_wide();
                        let Some(l) = to_light.normalize_with_square(d2) else {
                            continue;
                        };
                        let shadow = Ray::new_unchecked(point, l);
                        let casters = &floor.casters[i][..floor.counts[i]];
                        let holds = |c: &&Caster| c.first <= col && col < c.end;
                        floor_rays += 1;
                        kept += casters.iter().filter(holds).count() as u64;
                        objects_seen += scene.objects().len() as u64;
                        for (index, object) in scene.objects().iter().enumerate().skip(1) {
                            if object.shape.blocks(&shadow, d2) {
                                blocked += 1;
                                let found = casters
                                    .iter()
                                    .filter(holds)
                                    .any(|c| c.object as usize == index);
                                assert!(found, "world {world}, row {row}, column {col}: {index}");
                            }
                        }
                    }
                }
            }
        }
        // The sample holds shadows, and a floor pixel's ray tries few of the objects.
        assert!(
            blocked * 20 > floor_rays,
            "{blocked} blocked of {floor_rays}"
        );
        assert!(kept * 10 < objects_seen, "{kept} tried of {objects_seen}");
    }
}
