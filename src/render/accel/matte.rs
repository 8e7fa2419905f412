//! [`Scene::shade_matte_run`]: a run of columns that can meet one matte plane only, on a row
//! parallel to it — a level camera over a level floor, most of a typical frame — found and
//! shaded in one loop.
//!
//! Along such a row `n·w` does not change, and so neither does the plane's scale `s` (Eq. 4.2
//! along the direction towards the pixel, `Plane::hit_from`): the division, and the bound on
//! `‖w‖²` that [`FAR`](crate::FAR) sets, are worked out once, and each hit `eye + s·w` is
//! carried along the row by exact additions ([`Offsets`]). No ray is made for a hit: shading
//! a matte surface needs neither its direction nor its distance. What the run's pixels share is
//! worked out once too: the object and its facing normal, and for each light whether a shadow
//! ray from the run can meet anything at all (on a row that no shadow can cross, none is
//! made). Each hit is then lit by the plain path's own functions (`Scene::reaches`, which
//! takes the light's direction and casts the shadow ray, and `Scene::matte_pixel`), so the
//! pixels are bit for bit [`Scene::trace`]'s.
//!
//! Most of a level floor faces along an axis, and most of its columns lie where no sphere's
//! shadow can fall (`accel/shadow_columns.rs`): there a hit needs no shadow ray, and so not
//! the light's unit vector either, only its cosine with the normal, which is one of its
//! components ([`Axis`]). Those columns are walked apart from the rest of the run, in a loop
//! of their own wherever each of them meets the plane (`Scene::lit_stretch`): under one light,
//! on an unbounded plane of one colour, a column there costs a step of its offset, the
//! cosine and the pixel's three products.

use crate::geometry::plane::{Numerator, Plane, far_reach};
use crate::numbers::fx::{self, Fx};
use crate::numbers::reciprocal::{EvenLength, Scale};
use crate::numbers::vec3::Vec3;
use crate::render::accel::row_rays::RowSquares;
use crate::render::accel::shadow_columns::RunLine;
use crate::render::camera::Camera;
use crate::render::trace::Surface;
use crate::scene::colour::Rgb;
use crate::scene::light::Light;
use crate::scene::linear::rgb_of;
use crate::scene::{Object, Scene};

/// A run of columns whose rays can meet one matte plane only, object `index` (`plane`), whose
/// numerator for rays from the eye is `num`, on a row whose column step is parallel to the
/// plane (`n·r = 0`); the run's first ray is along `towards`, and each next one `step`
/// further (a whole number of column steps).
pub(crate) struct MatteRun<'a> {
    pub(crate) plane: Plane,
    pub(crate) index: usize,
    pub(crate) num: &'a Numerator,
    pub(crate) towards: Vec3,
    pub(crate) step: Vec3,
}

impl<const N: usize, const L: usize> Scene<N, L> {
    /// The colours of a [`MatteRun`]'s columns, one for each pixel of `out`, as
    /// [`Scene::trace`] gives them for the camera's rays: where the plane is met, its matte
    /// light, whose shadow rays towards light `i` try only the objects of
    /// `plane_shadowers[i]` (see `accel/shadow_rows.rs`); elsewhere the background.
    pub(crate) fn shade_matte_run(
        &self,
        camera: &Camera,
        run: &MatteRun<'_>,
        plane_shadowers: &[u32; L],
        out: &mut [Rgb],
    ) {
        let (plane, index) = (&run.plane, run.index);
        let Some(object) = self.objects().get(index) else {
            return; // not reached: the run's object is one of the scene's
        };
        let normal = plane.facing(run.num);
        let axis = Axis::of(normal);
        // For each light, the set a shadow ray from the run tries, or `None` where it can
        // meet nothing: of the objects `Scene::occluded` walks (`Scene::walked`), it tries
        // only those in the row's set.
        let mut shadow_sets = [None; L];
        if self.shadows() {
            let lights = self.lights().len();
            for (light, test) in shadow_sets.iter_mut().enumerate().take(lights) {
                let among = plane_shadowers.get(light).copied().unwrap_or(!0);
                let none = self
                    .walked(index, light)
                    .is_some_and(|set| set & among == 0);
                *test = (!none).then_some(among);
            }
        }
        let mut at = Surface {
            index,
            point: Vec3::ZERO,
            normal,
        };
        let (eye, step, towards) = (camera.eye(), run.step, run.towards);
        // Where the plane is not ahead of the row, nothing is within reach.
        let scale = plane.scale_along(run.num, plane.normal().dot_wide_exact(towards));
        let reach = scale.map_or(0, far_reach);
        let scale = scale.unwrap_or(Scale { m: 0, shift: 1 });
        let walk = |from: usize| Walk {
            towards: towards.plus(step.steps(from as i32)),
            step,
            scale,
            reach,
        };
        let material = &object.material;
        // On a plane facing along an axis, the columns where no shadow ray needs a test (all
        // but those some sphere may shadow, `shadowed_columns`) take only the cosine; the
        // others, and every column of any other plane, the light's whole unit vector and the
        // shadow ray.
        let shadowed = match axis {
            Some(_) => {
                let line = RunLine {
                    eye,
                    scale,
                    reach,
                    towards,
                    step,
                    len: out.len(),
                };
                self.shadowed_columns(index, plane.normal(), &line, &shadow_sets)
            }
            None => 0..out.len(),
        };
        let (before, rest) = out.split_at_mut(shadowed.start.min(out.len()));
        let (inside, after) = rest.split_at_mut(shadowed.len().min(rest.len()));
        let lights = self.lights();
        let mut shadowed_at = |point: Vec3| {
            at.point = point;
            let mut diffuse = Fx::ZERO;
            for (i, (light, &test)) in lights.iter().zip(&shadow_sets).enumerate() {
                if let Some((_, cos)) = self.reaches_among(i, light, &at, test) {
                    diffuse = diffuse.saturating_add(fx::mul_unit(light.intensity, cos));
                }
            }
            self.matte_pixel_within_one(material, diffuse, object.colour_at(point))
        };
        // The stretches where no shadow ray needs a test, most of a floor: within reach at both
        // ends, their own loop, which takes only the cosine; a stretch that reaches past FAR
        // (rows near the horizon) the loop of every column, whose shadow rays then find
        // nothing. Either may be empty, and is then not set up.
        if let Some(axis) = axis {
            for (from, stretch) in [(0, before), (shadowed.end, after)] {
                let walk = walk(from);
                if stretch.is_empty() {
                    continue;
                }
                if walk.within(stretch.len()) {
                    self.lit_stretch(camera, plane, object, axis, walk, stretch);
                } else {
                    self.matte_loop(camera, plane, walk, stretch, &mut shadowed_at);
                }
            }
        }
        if !inside.is_empty() {
            self.matte_loop(
                camera,
                plane,
                walk(shadowed.start),
                inside,
                &mut shadowed_at,
            );
        }
    }

    /// The walk along a stretch of a [`MatteRun`] that starts at `walk`: each column's hit on
    /// `plane`, shaded by `shade`, or the background where the plane is not met. Started at
    /// any column, it meets the same values as a walk from the run's start: the steps are
    /// exact.
    pub(crate) fn matte_loop(
        &self,
        camera: &Camera,
        plane: &Plane,
        walk: Walk,
        out: &mut [Rgb],
        shade: &mut impl FnMut(Vec3) -> Rgb,
    ) {
        let eye = camera.eye();
        let sky = self.background().plain_colour();
        let Walk {
            mut towards,
            step,
            scale,
            reach,
        } = walk;
        let mut square = RowSquares::new(towards, step);
        let mut offsets = Offsets::new(scale, towards, step);
        for pixel in out.iter_mut() {
            let hit = if square.now(towards) <= reach {
                plane.bounded_at(eye.plus(offsets.now()))
            } else {
                None
            };
            *pixel = match (hit, sky) {
                (Some(point), _) => shade(point),
                // A plain sky's colour, which `Background::along` gives whatever the ray.
                (None, Some(sky)) => sky,
                (None, None) => self.background_along(camera, towards, square.now(towards)),
            };
            towards = towards.plus(step);
            square.step();
            offsets.step();
        }
    }

    /// A stretch of a [`MatteRun`] on `object` (`plane`, facing along `axis`) that starts at
    /// `walk` and lies within reach at both ends, where no shadow ray needs a test:
    /// [`Scene::matte_loop`]'s pixels, without its reach test or ray, and with each light's
    /// cosine alone ([`Axis`]). Its own loop, which keeps the values the columns share in
    /// registers.
    // Out of line: its values stay off `shade_matte_run`'s stack frame, which lies under
    // every shadow ray of the run's other stretches; the call is one a stretch.
    #[inline(never)]
    fn lit_stretch(
        &self,
        camera: &Camera,
        plane: &Plane,
        object: &Object,
        axis: Axis,
        walk: Walk,
        out: &mut [Rgb],
    ) {
        let (eye, step) = (camera.eye(), walk.step);
        let material = &object.material;
        // One light on an unbounded plane of one colour, the common case on a small screen:
        // each column's direction to the light is the light's from the eye less the column's
        // offset, exactly (`light − (eye + offset)`, every value within range), and there is no
        // colour to look up and no bound to test. The row's step is parallel to the plane, so
        // along the axis the offset, and the direction's component `c`, do not change: taken
        // with their components across the axis first (`Axis::across`), a column steps two
        // offsets and squares two components.
        if let ([light], None, None) = (self.lights(), material.checker, plane.bounds()) {
            let from_eye = axis.across(light.position.minus(eye));
            let mut offsets =
                Offsets::new(walk.scale, axis.across(walk.towards), axis.across(step));
            let c = from_eye.minus(offsets.now()).z;
            let c_square = Vec3::new(Fx::ZERO, Fx::ZERO, c).length_squared_wide();
            // Neighbouring columns' squares mostly share their bit length: kept from one to
            // the next.
            let mut length = EvenLength::NONE;
            for pixel in out.iter_mut() {
                let e = from_eye.minus(offsets.now());
                let square = Vec3::new(e.x, e.y, Fx::ZERO).length_squared_wide() + c_square;
                let diffuse = match axis.cosine_near(c, square, &mut length) {
                    Some(cos) => fx::mul_unit(light.intensity, cos),
                    None => Fx::ZERO,
                };
                *pixel = self.matte_pixel_within_one(material, diffuse, material.colour);
                offsets.step_across();
            }
            return;
        }
        let mut offsets = Offsets::new(walk.scale, walk.towards, step);
        let diffuse_from =
            |light: &Light, point: Vec3| match axis.cosine(light.position.minus(point)) {
                Some(cos) => fx::mul_unit(light.intensity, cos),
                None => Fx::ZERO,
            };
        for (k, pixel) in out.iter_mut().enumerate() {
            *pixel = match plane.bounded_at(eye.plus(offsets.now())) {
                Some(point) => {
                    let diffuse = self.lights().iter().fold(Fx::ZERO, |sum, light| {
                        sum.saturating_add(diffuse_from(light, point))
                    });
                    self.matte_pixel_within_one(material, diffuse, object.colour_at(point))
                }
                None => self.background_past_bounds(camera, walk.towards, step, k),
            };
            offsets.step();
        }
    }

    /// What column `k` of a stretch that starts along `start` and steps by `step` sees past a
    /// plane's bounds.
    #[cold]
    fn background_past_bounds(&self, camera: &Camera, start: Vec3, step: Vec3, k: usize) -> Rgb {
        match self.background().plain_colour() {
            Some(sky) => sky,
            None => {
                let towards = start.plus(step.steps(k as i32));
                self.background_along(camera, towards, towards.length_squared_wide())
            }
        }
    }

    /// What the camera's ray along `towards`, whose squared length is `square`, sees of a
    /// background that is not plain: cold, since most backgrounds are plain.
    #[cold]
    fn background_along(&self, camera: &Camera, towards: Vec3, square: u64) -> Rgb {
        let ray = camera.ray_along(towards, square);
        rgb_of(self.background().along(ray.dir))
    }
}

/// Where a stretch of a run starts: the direction towards its first column, and the step to
/// the next, the plane's scale and reach, which the whole run shares.
#[derive(Clone, Copy)]
pub(crate) struct Walk {
    pub(crate) towards: Vec3,
    pub(crate) step: Vec3,
    pub(crate) scale: Scale,
    pub(crate) reach: u64,
}

impl Walk {
    /// Whether a stretch of `len` columns from this walk's start lies within reach at both
    /// ends, and so at every column: `‖w‖²` is a convex quadratic along the stretch, exact in
    /// integers.
    pub(crate) fn within(&self, len: usize) -> bool {
        let last = self
            .towards
            .plus(self.step.steps(len.saturating_sub(1) as i32));
        [self.towards, last]
            .iter()
            .all(|end| end.length_squared_wide() <= self.reach)
    }
}

/// A facing normal along a coordinate axis, `±1` in one component and 0 in the others, as a
/// level floor's or an upright wall's is: its dot product with a unit vector is that vector's
/// component, rounded as [`Vec3::dot_exact`] rounds it (exactly), so where no shadow ray needs
/// the light's whole unit vector, the cosine needs one component of it.
#[derive(Clone, Copy)]
pub(crate) struct Axis {
    /// 0, 1 or 2 for x, y or z.
    index: u8,
    negative: bool,
}

impl Axis {
    /// The axis a unit normal lies along, or `None` where it lies along none.
    pub(crate) fn of(normal: Vec3) -> Option<Axis> {
        let one = Fx::ONE.to_bits().unsigned_abs();
        let c = [normal.x, normal.y, normal.z].map(Fx::to_bits);
        let index = match c {
            [_, 0, 0] => 0,
            [0, _, 0] => 1,
            [0, 0, _] => 2,
            _ => return None,
        };
        let value = c[index];
        (value.unsigned_abs() == one).then_some(Axis {
            index: index as u8,
            negative: value < 0,
        })
    }

    /// What `Scene::reaches` gives as the cosine of `to_light` (from the hit to the light) on a
    /// surface facing along the axis, without a shadow ray: `None` where it is not positive.
    fn cosine(self, to_light: Vec3) -> Option<Fx> {
        self.cosine_of(self.across(to_light).z, to_light.length_squared_wide())
    }

    /// [`Axis::cosine`] of a vector whose component along the axis is `c` and whose squared
    /// length is `square`.
    fn cosine_of(self, c: Fx, square: u64) -> Option<Fx> {
        self.facing(Vec3::unit_component_with_square(c, square)?)
    }

    /// [`Axis::cosine_of`] with the reciprocal root in line, for one of a run of squares that
    /// mostly share their bit length, kept in `length`.
    fn cosine_near(self, c: Fx, square: u64, length: &mut EvenLength) -> Option<Fx> {
        self.facing(Vec3::unit_component_near(c, square, length)?)
    }

    /// The cosine with the facing normal of a unit vector whose component along the axis is
    /// `c`: `None` where it is not positive.
    fn facing(self, c: Fx) -> Option<Fx> {
        let cos = if self.negative { -c } else { c };
        (cos > Fx::ZERO).then_some(cos)
    }

    /// `v` with its two components across the axis first and the one along it last (as `z`).
    fn across(self, v: Vec3) -> Vec3 {
        match self.index {
            0 => Vec3::new(v.y, v.z, v.x),
            1 => Vec3::new(v.z, v.x, v.y),
            _ => v,
        }
    }
}

/// `s·w` along a row, `w` stepping by `r`: `plane::offset(scale, w)` for each column, carried
/// without a shift. Each component is the rounded quotient `⌊q / 2^shift⌋` of
/// `q = w·m + 2^(shift−1)` (the product exact: `w` within the ray budget, `m` below 2³¹, so
/// below 2⁶¹), held as that quotient and its remainder, the remainder in the top `shift` bits
/// of a 64-bit word. A column adds the step `r·m` split the same way: the remainders' sum
/// carries out of the word exactly when it reaches `2^shift`, and the carry goes into the
/// quotient. The quotients are the offsets, as `offset` rounds them, at every column; a
/// component along which the row does not move (`r`'s is 0: two of three for a camera
/// looking along an axis) is left as it is.
struct Offsets {
    offset: [i32; 3],
    remainder: [u64; 3],
    step_quotient: [i32; 3],
    step_remainder: [u64; 3],
}

impl Offsets {
    fn new(scale: Scale, start: Vec3, step: Vec3) -> Self {
        // Past 63 every offset rounds to 0, and stays there (`offset` says why).
        let (m, shift) = match scale.shift {
            shift @ 1..64 => (scale.m, shift as u32),
            _ => (0, 1),
        };
        let p = |c: Fx| fx::wide_mul(c.to_bits(), m);
        let [x, y, z] =
            [start.x, start.y, start.z].map(|c| split(p(c) + (1 << (shift - 1)), shift));
        let [sx, sy, sz] = [step.x, step.y, step.z].map(|c| split(p(c), shift));
        Offsets {
            offset: [x.0, y.0, z.0],
            remainder: [x.1, y.1, z.1],
            step_quotient: [sx.0, sy.0, sz.0],
            step_remainder: [sx.1, sy.1, sz.1],
        }
    }

    /// `offset(scale, w)` for the current `w`.
    #[inline]
    fn now(&self) -> Vec3 {
        let [x, y, z] = self.offset.map(Fx::from_bits);
        Vec3::new(x, y, z)
    }

    #[inline]
    fn step(&mut self) {
        for i in 0..3 {
            if self.step_quotient[i] != 0 || self.step_remainder[i] != 0 {
                self.step_component(i);
            }
        }
    }

    /// [`Offsets::step`] for a walk that does not move along `z`: the other two alone.
    #[inline]
    fn step_across(&mut self) {
        debug_assert!(
            self.step_quotient[2] == 0 && self.step_remainder[2] == 0,
            "Offsets::step_across: the walk moves along z"
        );
        self.step_component(0);
        self.step_component(1);
    }

    /// Component `i` on to the next column: the remainders' sum carries out of the word
    /// exactly when it reaches `2^shift`, and the carry goes into the quotient.
    fn step_component(&mut self, i: usize) {
        let (sum, carry) = self.remainder[i].overflowing_add(self.step_remainder[i]);
        self.remainder[i] = sum;
        self.offset[i] = self.offset[i]
            .wrapping_add(self.step_quotient[i])
            .wrapping_add(carry as i32);
    }
}

/// `v`'s quotient by `2^shift`, floored (its low 32 bits), and its remainder, moved to the top
/// of a word, for `shift` in 1..64.
fn split(v: i64, shift: u32) -> (i32, u64) {
    ((v >> shift) as i32, (v as u64) << (64 - shift))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::xorshift::XorShift;

    /// `w·m` rounded half up by `2^shift`, in exact 128-bit arithmetic: `plane::offset`'s value
    /// for a component `w`, and 0 past a shift of 63.
    fn exact(w: i32, m: i32, shift: i32) -> i32 {
        if !(1..64).contains(&shift) {
            return 0;
        }
        let q = (w as i128 * m as i128 + (1i128 << (shift - 1))) >> shift;
        q as i32
    }

    #[test]
    fn carried_offsets_are_each_columns_rounded_product() {
        let mut rng = XorShift(0x2545_f491_4f6c_dd1d);
        // Starts within 2²⁹ and steps within 2²⁰ a component keep 300 columns within 2³⁰,
        // the ray budget's bound, so every product stays below 2⁶¹ as `Offsets` assumes.
        let component = |rng: &mut XorShift, bits: u32| match rng.next() % 8 {
            0 => 0,
            1 => 1 << bits,
            2 => -(1 << bits),
            _ => (rng.next() as i32) >> (32 - bits - 1),
        };
        for round in 0..4000 {
            let shift = round % 68 - 2; // −2 to 65: outside 1..64 too
            let m = (1 << 29) + (rng.next() % (3 << 29)) as i32; // in [2²⁹, 2³¹)
            let scale = Scale { m, shift };
            let start = [0; 3].map(|_| component(&mut rng, 29));
            let step = [0; 3].map(|_| component(&mut rng, 20));
            let v = |c: [i32; 3]| {
                Vec3::new(
                    Fx::from_bits(c[0]),
                    Fx::from_bits(c[1]),
                    Fx::from_bits(c[2]),
                )
            };
            let mut offsets = Offsets::new(scale, v(start), v(step));
            for column in 0..300 {
                let w = [0, 1, 2].map(|i| start[i] + column * step[i]);
                let want = w.map(|c| exact(c, m, shift));
                let got = offsets.now();
                assert_eq!(
                    [got.x, got.y, got.z].map(Fx::to_bits),
                    want,
                    "scale {scale:?}, start {start:?}, step {step:?}, column {column}"
                );
                offsets.step();
            }
        }
    }
}
