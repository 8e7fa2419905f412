//! [`Runs`]: a display row cut into runs of columns, each with the set of objects its rays
//! can meet.

use crate::geometry::shape::Shape;
use crate::numbers::bits;
use crate::numbers::vec3::Vec3;
use crate::render::accel::crowd::{ByIndex, Crowd, Names};
use crate::render::accel::cull::{Eye, row_ball, row_offset};
use crate::render::accel::shadow_rows::row_shadowers;
use crate::render::camera::Camera;
use crate::scene::Scene;

/// The runs of one display row, left to right.
///
/// A row's rays lie in one plane through the eye (`Scene::seen_from_row_plane` drops the spheres
/// that plane misses), each remaining sphere covers a span of columns (`Camera::column_span`),
/// and a plane is missed by a whole run when every ray of it points away from the plane or
/// along it. Between the ends of spans the set of objects worth trying is constant: a run.
/// Every test is conservative, so a ray tries every object it can hit and the hits are
/// exactly [`Scene::shoot`]'s.
pub(crate) struct Runs<'a, const N: usize, const L: usize, C: Names = ByIndex> {
    scene: &'a Scene<N, L>,
    /// The objects the row's plane can meet.
    among: u64,
    /// Spheres with a span, and their spans (inclusive, possibly past the screen's edges), by
    /// object: as many as the scene holds, of which the first 64 are used.
    bounded: u64,
    spans: [(i16, i16); N],
    /// Planes, and what their hit tests share for rays from the eye.
    planes: u64,
    eye: Eye<N, C>,
    /// For each light, the objects that may shadow the row's hits on planes.
    shadowers: [u32; L],
    /// The unnormalised direction towards column 0, and one column's step.
    start: Vec3,
    step: Vec3,
    col: u16,
    cols: u16,
    /// The row's width.
    width: u16,
}

impl<'a, const N: usize, const L: usize> Runs<'a, N, L> {
    /// The runs of display row `row` of `camera`'s view of `scene`.
    // Out of line: the culling's temporaries (each sphere's ball in the row's plane and its
    // span) are needed once a row, and in line they would sit in the row's stack frame under
    // every pixel's shading; the call is one a row.
    #[inline(never)]
    pub(crate) fn new(scene: &'a Scene<N, L>, camera: &Camera, row: u16) -> Self {
        // Objects past the 64th have no bit of their own and are always tried. Bit 63 then
        // stands for them as well as for object 63, so it is never cleared: no run is taken
        // for empty while they exist, and object 63 is simply tried with them.
        let own_bits = if scene.objects().len() > 64 { 63 } else { 64 };
        let beyond = if own_bits == 63 { 1 << 63 } else { 0 };
        let start = camera.row_start(row);
        let row_normal = camera.row_plane_normal_from(start);
        let (eye, present) = (camera.eye(), scene.present());
        // The spheres the row's plane misses leave `among` (`Scene::seen_from_row_plane`'s
        // test, made here with the height it finds kept for the sphere's ball).
        let (mut among, mut bounded, mut spans, mut planes) = (!0u64, 0, [(0, 0); N], 0);
        for (index, object) in scene.objects().iter().enumerate().take(own_bits) {
            match object.shape {
                Shape::Sphere(sphere) if bits::has(present, index) => {
                    // What the row's rays can meet of the sphere, and the columns that holds.
                    let (centre, radius) = match row_normal {
                        Some(normal) => match row_offset(&sphere, eye, normal) {
                            Some(height) => row_ball(&sphere, eye, normal, height),
                            None => {
                                among &= !bits::bit(index);
                                continue;
                            }
                        },
                        None => (sphere.centre(), sphere.radius()),
                    };
                    if let (Some(span), Some(slot)) =
                        (camera.column_span(centre, radius), spans.get_mut(index))
                    {
                        *slot = span;
                        bounded |= bits::bit(index);
                    }
                }
                Shape::Plane(_) => planes |= bits::bit(index),
                Shape::Sphere(_) => {}
            }
        }
        let among = among & present | beyond;
        let shadowers = match row_normal {
            Some(row_normal) => row_shadowers(scene, camera.eye(), row_normal, planes & among),
            None => [!0; L],
        };
        // One value made last, in the caller's place: a `Runs` is a few hundred bytes, and
        // one made earlier and changed would be copied there.
        Runs {
            scene,
            among,
            bounded,
            spans,
            planes,
            shadowers,
            eye: Eye::new(scene, camera.eye(), among),
            start,
            step: camera.column_step(),
            col: 0,
            cols: camera.cols(),
            width: camera.cols(),
        }
    }

    /// [`Runs::new`] for a scene whose capacity passes 64: the row's bits go to the objects it
    /// can meet, in order, as `crowd` keeps them (`accel/crowd.rs`), and a sphere whose
    /// columns all lie off the screen has none.
    pub(crate) fn crowded(
        scene: &'a Scene<N, L>,
        camera: &Camera,
        row: u16,
        crowd: &'a mut Crowd<N>,
    ) -> Runs<'a, N, L, &'a Crowd<N>> {
        let start = camera.row_start(row);
        let row_normal = camera.row_plane_normal_from(start);
        let eye = camera.eye();
        let cols = i32::from(camera.cols());
        let (mut among, mut bounded, mut spans, mut planes) = (0u64, 0, [(0, 0); N], 0);
        // The planes by object, for the shadow sets, which name objects.
        let mut plane_objects = 0;
        let mut bit = 0;
        for (index, object) in scene.objects().iter().enumerate() {
            let span = match object.shape {
                Shape::Sphere(sphere) => {
                    let (centre, radius) = match row_normal {
                        Some(normal) => match row_offset(&sphere, eye, normal) {
                            Some(height) => row_ball(&sphere, eye, normal, height),
                            None => continue,
                        },
                        None => (sphere.centre(), sphere.radius()),
                    };
                    match camera.column_span(centre, radius) {
                        Some((first, last)) if last < 0 || i32::from(first) >= cols => continue,
                        span => span,
                    }
                }
                Shape::Plane(_) => {
                    if index < 64 {
                        plane_objects |= bits::bit(index);
                    }
                    None
                }
            };
            crowd.add(bit, index);
            if bit < 64 {
                among |= bits::bit(bit);
                if let Shape::Plane(_) = object.shape {
                    planes |= bits::bit(bit);
                }
                if let (Some(span), Some(slot)) = (span, spans.get_mut(bit)) {
                    *slot = span;
                    bounded |= bits::bit(bit);
                }
            }
            bit += 1;
        }
        crowd.sort_ends(bounded, &spans);
        let shadowers = match row_normal {
            Some(row_normal) => row_shadowers(scene, eye, row_normal, plane_objects),
            None => [!0; L],
        };
        Runs {
            scene,
            among,
            bounded,
            spans,
            planes,
            shadowers,
            eye: Eye::crowded(scene, eye, planes, crowd),
            start,
            step: camera.column_step(),
            col: 0,
            cols: camera.cols(),
            width: camera.cols(),
        }
    }
}

impl<'a, const N: usize, const L: usize, C: Names> Runs<'a, N, L, C> {
    /// The one object a run's set `here` can meet, if it is one alone: none where objects
    /// past the 64th or a crowded row's extras are tried as well.
    pub(crate) fn only(&self, here: u64) -> Option<usize> {
        let alone =
            here.is_power_of_two() && (N <= 64 || self.eye.alone(self.scene.objects().len()));
        alone.then(|| self.eye.object(here.trailing_zeros() as usize))
    }

    /// Whether a run's set `here` meets nothing at all.
    pub(crate) fn is_empty(&self, here: u64) -> bool {
        here == 0 && self.eye.extras().is_empty()
    }

    /// For each light, the objects that may shadow a hit of the row on a plane (see
    /// `shadow_rows`); a hit on a sphere may be shadowed by any of its own set.
    pub(crate) const fn shadowers(&self) -> &[u32; L] {
        &self.shadowers
    }

    /// Limits the walk to columns `cols` (clipped to the row), wherever an earlier walk
    /// stopped: started and stopped there it finds the runs of the whole row cut at those
    /// columns, since each run is found from the column it starts at. So one set-up serves
    /// several walks along its row. In place: a `Runs` is a few hundred bytes, not to be
    /// copied.
    pub(crate) fn limit(&mut self, cols: core::ops::Range<u16>) {
        self.cols = cols.end.min(self.width);
        self.col = cols.start.min(self.cols);
    }

    /// What rays from the eye share, for [`Scene::shoot_from_eye`].
    pub(crate) const fn eye(&self) -> &Eye<N, C> {
        &self.eye
    }

    /// The unnormalised direction towards column `col` (see `Camera::row_start`): the value
    /// a walk along the row by column steps reaches, exactly.
    pub(crate) fn towards(&self, col: u16) -> Vec3 {
        self.start.plus(self.step.steps(col as i32))
    }

    /// The next run: its first column, the column after its last, and the objects to try.
    pub(crate) fn next_run(&mut self) -> Option<(u16, u16, u64)> {
        if self.col >= self.cols {
            return None;
        }
        let col = self.col as i16;
        let (mut here, mut until) = (self.among, self.cols as i16);
        // A crowded row keeps its spans' ends sorted: the same set and end from the ends the
        // walk passes, not from every span.
        let ends = self.eye.ends_at(col);
        let mut rest = match ends {
            Some((inside, next)) => {
                here &= inside | !self.bounded;
                until = until.min(next);
                0
            }
            None => self.bounded,
        };
        while rest != 0 {
            let index = rest.trailing_zeros();
            rest &= rest - 1;
            let Some(&(first, last)) = self.spans.get(index as usize) else {
                continue; // not reached: a bit of `bounded` is an object's, which has a span
            };
            if col < first {
                here &= !bits::bit(index as usize);
                until = until.min(first);
            } else if col > last {
                here &= !bits::bit(index as usize);
            } else {
                until = until.min(last.saturating_add(1));
            }
        }
        let until = until.max(col + 1) as u16;
        let mut planes = here & self.planes;
        if planes != 0 {
            let (first, last) = (self.towards(self.col), self.towards(until - 1));
            while planes != 0 {
                let index = planes.trailing_zeros() as usize;
                planes &= planes - 1;
                let object_index = self.eye.object(index);
                if let Some(object) = self.scene.objects().get(object_index)
                    && let Shape::Plane(plane) = object.shape
                    && misses_all(
                        plane.normal(),
                        self.eye.numerator(object_index).value,
                        first,
                        last,
                    )
                {
                    here &= !bits::bit(index);
                }
            }
        }
        let run = (self.col, until, here);
        self.col = until;
        Some(run)
    }
}

/// Whether every ray of a run, whose unnormalised directions run linearly from `first` to
/// `last`, misses a plane of unit normal `normal` and Eq. 4.2 numerator `numerator` by
/// pointing away from it or along it.
///
/// A ray from the eye along `w` meets the plane only where the numerator is not zero and
/// `n·w` has its sign (`Plane::hit_from`, which takes both exactly). `n·w` is linear along
/// the run, so where neither end has that sign no column between them has.
fn misses_all(normal: Vec3, numerator: i64, first: Vec3, last: Vec3) -> bool {
    let (a, b) = (normal.dot_wide_exact(first), normal.dot_wide_exact(last));
    match numerator {
        0 => true, // the eye on the plane: every ray leaves it or runs along it
        ..0 => a.min(b) >= 0,
        _ => a.max(b) <= 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::demo;

    #[test]
    fn the_sky_rows_of_the_demo_try_nothing() {
        let (scene, camera) = (demo::scene(), demo::camera(160, 128).unwrap());
        let mut runs = Runs::new(&scene, &camera, 0);
        let mut count = 0;
        while let Some((_, _, here)) = runs.next_run() {
            assert_eq!(here, 0);
            count += 1;
        }
        assert_eq!(count, 1);
    }

    #[test]
    fn a_row_that_meets_more_than_64_objects_tries_the_rest_as_extras() {
        // A floor, a hundred small balls in a row across the view at the eye's height, and
        // one above them: the middle rows can meet the floor and every ball, 101 objects.
        use crate::{Plane, Rgb, Sphere, render_row};
        let light = crate::Light::new([0.0, 20.0, 10.0], 0.8).unwrap();
        let mut scene: Scene<110, 1> = Scene::new(light, 0.1, Rgb::BLACK).unwrap();
        let floor = Plane::new([0.0, -1.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
        scene.add_plane(floor, Rgb::WHITE).unwrap();
        for i in 0..100 {
            let ball = Sphere::new([(i as f32 - 49.5) * 0.3, 0.0, -20.0], 0.14).unwrap();
            scene.add_sphere(ball, Rgb::new(200, i as u8, 40)).unwrap();
        }
        let high = Sphere::new([0.0, 3.0, -20.0], 1.0).unwrap();
        scene.add_sphere(high, Rgb::new(40, 40, 200)).unwrap();
        let camera = Camera::look_at([0.0, 0.0, 0.0], [0.0, 0.0, -20.0])
            .size(crate::Size::new(96, 31))
            .build()
            .unwrap();
        let mut crowd = Crowd::empty();
        let runs = Runs::crowded(&scene, &camera, 15, &mut crowd);
        assert_eq!(runs.eye().extras().len(), 101 - 64);
        let mut out = [Rgb::BLACK; 96];
        for row in 0..31 {
            render_row(&scene, &camera, row, &mut out).unwrap();
            for (col, pixel) in (0..).zip(&out) {
                let traced = scene.trace(&camera.ray(col, row));
                assert_eq!(*pixel, traced, "row {row}, column {col}");
            }
        }
    }
}
