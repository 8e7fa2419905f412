//! Which columns of a matte run a sphere can shadow: outside them a hit's shadow ray towards
//! that light needs no test, and the run's own loop only the cosine.
//!
//! A run's hits on its plane lie, up to rounding, on one line, `P(k) = P(0) + k·Δ` for the
//! run's `k`-th column. A shadow ray from `P` towards the light `L` that a sphere blocks passes
//! within `ρ` of its centre `C` ([`blocking_radius`]: the radius widened by every rounding of
//! the test); seen along the plane's normal `n`, so does its shadow on the plane, the line from
//! `P` to the light's foot. That is `|(n × (C − L))·(P − L)| ≤ ρ·‖n‖·‖P − L‖'`, with `‖·‖'` the
//! length along the plane: the left side is affine in `k`, the right side at most its value at
//! the farther end of the run, as `‖P − L‖` is convex in `k`. So two divisions bound the
//! columns where the sphere can matter. Every rounding of the set-up widens the bound, never
//! narrows it: a column left out is one whose shadow ray the sphere cannot block.

use core::ops::Range;

use crate::geometry::plane::offset;
use crate::geometry::shape::Shape;
use crate::geometry::sphere::Sphere;
use crate::numbers::fx::Fx;
use crate::numbers::reciprocal::Scale;
use crate::numbers::vec3::Vec3;
use crate::render::accel::shadow_rows::blocking_radius;
use crate::scene::Scene;

/// How coarsely the affine side is solved: in units of 2²⁰ of its Q32.32 value, so that its
/// products with a column count stay within 64 bits.
const COARSE: u32 = 20;

/// The hits of a matte run: `eye + s·w(k)` with `w(k) = towards + k·step` and `s = scale`,
/// rounded as the run's loop rounds them, for its `len` columns; a hit only where
/// `‖w(k)‖² ≤ reach` (within [`FAR`](crate::FAR)).
pub(crate) struct RunLine {
    pub(crate) eye: Vec3,
    pub(crate) scale: Scale,
    pub(crate) reach: u64,
    pub(crate) towards: Vec3,
    pub(crate) step: Vec3,
    pub(crate) len: usize,
}

impl RunLine {
    /// The hit of column `k`, within half a unit of 2⁻¹⁶ in each component of the exact
    /// `eye + s·w(k)`, which is affine in `k`.
    fn point(&self, k: usize) -> Vec3 {
        self.eye.plus(offset(self.scale, self.towards_column(k)))
    }

    /// `w(k)`: for one of the run's columns, fewer than 2¹⁶, that column's direction.
    fn towards_column(&self, k: usize) -> Vec3 {
        self.towards.plus(self.step.steps(k as i32))
    }

    /// The columns (indices into the run) whose hits' shadow rays towards `light` the sphere
    /// `sphere` may block, on a plane whose normal is `normal`: empty where it blocks none.
    // Out of line, with the shadow sets' set-up (`row_shadowers`, `scaled`, `product`,
    // `quotient`): once a run and sphere, and in line it crowds the row's pixel loops.
    #[inline(never)]
    pub(crate) fn shadowed_by(&self, normal: Vec3, light: Vec3, sphere: &Sphere) -> Range<usize> {
        match self.seen_from(normal, light) {
            Ok(seen) => {
                let (first, end, bound) = seen.sides(sphere);
                seen.columns(first, end, bound)
            }
            Err(columns) => columns,
        }
    }

    /// What the columns' tests for every sphere share for a light at `light`, on a plane whose
    /// normal is `normal`; where they need no sphere, their answer: no column on an empty run,
    /// every column where an end lies past the reach.
    pub(crate) fn seen_from(&self, normal: Vec3, light: Vec3) -> Result<SeenFrom, Range<usize>> {
        let Some(last) = self.len.checked_sub(1) else {
            return Err(0..0);
        };
        // Where an end lies past the reach, the hits' line is not followed: points far out
        // would leave the products' budget. Within it at both ends, every column is within it
        // (‖w(k)‖² is convex in `k`), and every hit within FAR of the eye.
        let within = |k: usize| self.towards_column(k).length_squared_wide() <= self.reach;
        if !(within(0) && within(last)) {
            return Err(0..self.len);
        }
        // The run's ends, from the light.
        let (start, end) = (self.point(0) - light, self.point(last) - light);
        // The farthest a hit lies from the light: at most the farther end's exact distance
        // (convexity), which `length` truncates by under a unit and the ends' and the
        // column's roundings move by under a unit each. (Taken again over the columns found,
        // it narrows them, but costs more than it spares.)
        let far = start.length().max(end.length()).to_bits() as i64 + 3;
        Ok(SeenFrom {
            normal,
            light,
            start,
            end,
            far,
            last,
        })
    }
}

/// A run's hits seen from a light, for [`RunLine::seen_from`]'s tests: the plane's normal,
/// the light, the run's ends from it, the farthest a hit lies from it, and the run's last
/// column.
pub(crate) struct SeenFrom {
    normal: Vec3,
    light: Vec3,
    start: Vec3,
    end: Vec3,
    far: i64,
    last: usize,
}

impl SeenFrom {
    /// The run's two ends from the light: every hit lies within a unit of 2⁻¹⁶ a component of
    /// the segment between them (each end and each hit within half a unit of the exact ones).
    pub(crate) const fn ends(&self) -> (Vec3, Vec3) {
        (self.start, self.end)
    }

    /// The affine side of the sphere `sphere` at the run's two ends and the bound within which
    /// it may shadow a column (coarse units): the columns are those where the line through
    /// the two sides lies within `±bound` ([`SeenFrom::columns`]), and there are none where
    /// both sides pass it on one side.
    pub(crate) fn sides(&self, sphere: &Sphere) -> (i64, i64, i64) {
        // ρ·‖n‖ and the rounding of `g` below (half a unit a component, times ‖P − L‖): `n`
        // is a unit vector to within 2⁻¹⁵, so ρ·(1 + 2⁻¹⁴) and two units cover both.
        let rho = blocking_radius(sphere.radius());
        let rho: Fx = rho + (rho >> 14) + Fx::from_bits(2);
        // `g = n × (C − L)`, rounded: `g·(P − L)` is the affine side. A hit's rounding moves it
        // by at most half a unit of `P` a component, `|g|₁ / 2` in Q32.32: the line through
        // its values at the ends is within `slack` of every column's (the ends' roundings and
        // the column's), and the coarse shifts move it by under two coarse units.
        let g = self.normal.cross(sphere.centre() - self.light);
        let slack = g.l1_raw();
        let side = |p: Vec3| g.dot_wide_exact(p) >> COARSE;
        let bound = ((rho.to_bits() as i64 * self.far + slack) >> COARSE) + 2;
        (side(self.start), side(self.end), bound)
    }

    /// The columns (indices into the run) where the line through `first` at the first and
    /// `end` at the last lies within `±bound`: those [`SeenFrom::sides`]' sphere may shadow.
    pub(crate) fn columns(&self, first: i64, end: i64, bound: i64) -> Range<usize> {
        let last = self.last;
        let Some((lo, hi)) = solve(first, end, last as i64, bound) else {
            return 0..0;
        };
        let (lo, hi) = (lo.max(0), hi.min(last as i64));
        if lo > hi {
            return 0..0;
        }
        lo as usize..hi as usize + 1
    }
}

impl<const N: usize, const L: usize> Scene<N, L> {
    /// The columns of the run `line` on plane `index`, whose normal is `normal`, outside which
    /// no shadow ray of its hits needs a test: for each light `i` whose rays try `sets[i]`
    /// (`None`: none), the columns each sphere it tries may shadow, and none where no light's
    /// rays try anything; all of them where a plane may shadow the run, the scene's sets do
    /// not name the objects, more than three spheres are tried in all, or the run is shorter
    /// than 16 pixels.
    pub(crate) fn shadowed_columns(
        &self,
        index: usize,
        normal: Vec3,
        line: &RunLine,
        sets: &[Option<u32>; L],
    ) -> Range<usize> {
        // Each sphere costs two lengths and a division a light: past three (several lights
        // over several spheres, as in the classic scene), or on a short run (a few pixels of an
        // animation's redrawn region), the columns they leave out spare less than they cost,
        // and the run is taken whole. A progressive pass's runs hold fewer pixels than the
        // row's: from 16, the pixels spared still pay.
        let mut tried = 0;
        for (i, set) in sets.iter().enumerate() {
            let Some(among) = *set else { continue };
            let Some(walked) = self.walked(index, i) else {
                return 0..line.len;
            };
            tried += (walked & among).count_ones();
        }
        if tried == 0 {
            return 0..0;
        }
        if tried > 3 || line.len < 16 {
            return 0..line.len;
        }
        let (mut lo, mut hi) = (line.len, 0);
        for (i, (light, set)) in self.lights().iter().zip(sets).enumerate() {
            let Some(among) = *set else { continue };
            let Some(mut rest) = self.walked(index, i).map(|walked| walked & among) else {
                return 0..line.len;
            };
            while rest != 0 {
                let blocker = rest.trailing_zeros() as usize;
                rest &= rest - 1;
                let columns = match self.objects().get(blocker).map(|o| o.shape) {
                    Some(Shape::Sphere(sphere)) => {
                        line.shadowed_by(normal, light.position(), &sphere)
                    }
                    _ => return 0..line.len,
                };
                if !columns.is_empty() {
                    (lo, hi) = (lo.min(columns.start), hi.max(columns.end));
                }
            }
        }
        lo.min(hi)..hi
    }
}

/// The columns `k` in `0..=last` (a superset, by one column each way) where the affine value
/// through `first` at 0 and `end` at `last` is within `±bound`, or `None` where there are none.
fn solve(first: i64, end: i64, last: i64, bound: i64) -> Option<(i64, i64)> {
    // |first + k·(end − first)/last| ≤ bound, times `last`; the sign of the slope turned
    // positive, as only the value's size matters.
    let (first, slope) = match end - first {
        slope if slope < 0 => (-first, -slope),
        slope => (first, slope),
    };
    if slope == 0 || last == 0 {
        return (first.abs() <= bound).then_some((0, last));
    }
    // Truncated quotients are within one of the exact ones: one column more each way.
    let from = (-bound - first) * last / slope - 1;
    let to = (bound - first) * last / slope + 1;
    (from <= to).then_some((from, to))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::plane::{Plane, far_reach};
    use crate::geometry::ray::Ray;
    use crate::{Camera, Size};

    /// Random worlds: a floor, a ceiling or a wall facing along an axis, eight spheres, a light
    /// anywhere on its lit side (some close to it), cameras anywhere on that side looking
    /// anywhere, their up along the plane's normal so that their rows run parallel to it. For
    /// every column whose hit a sphere's shadow ray may reach, the sphere's columns must hold
    /// it; and they must leave most columns out.
    #[test]
    fn a_column_left_out_is_never_shadowed_by_the_sphere() {
        let mut rng = crate::xorshift::XorShift(0x5eed_c011_0000_0002);
        let (mut tried, mut kept, mut blocked) = (0u64, 0u64, 0u64);
        for world in 0..240 {
            let mut draw = |range: f32| rng.signed(range);
            let sign = if world % 2 == 0 { 1.0 } else { -1.0 };
            let mut along = [0.0f32; 3];
            along[world % 3] = sign;
            // A point `height` above the plane (along its normal), elsewhere anywhere.
            let above = |height: f32, draw: &mut dyn FnMut(f32) -> f32| {
                let mut p = [draw(12.0), draw(12.0), draw(12.0) - 8.0];
                p[world % 3] = sign * (height - 2.0);
                p
            };
            let plane = Plane::new(above(0.0, &mut draw), along).unwrap();
            let height = if world % 4 == 0 {
                draw(0.6).abs() + 0.05
            } else {
                draw(12.0).abs() + 0.5
            };
            let light = crate::Light::new(above(height, &mut draw), 1.0)
                .unwrap()
                .position();
            let balls: [Sphere; 8] = core::array::from_fn(|_| {
                let centre = above(draw(6.0).abs(), &mut draw);
                Sphere::new(centre, draw(1.0).abs() * 2.0 + 0.1).unwrap()
            });
            let eye = above(draw(6.0).abs() + 0.5, &mut draw);
            let target = above(draw(3.0), &mut draw);
            let Ok(camera) = Camera::look_at(eye, target)
                .up(along)
                .fov_degrees(draw(1.0).abs() * 120.0 + 10.0)
                .size(Size::new(48, 36))
                .build()
            else {
                continue;
            };
            let (eye, step) = (camera.eye(), camera.column_step());
            if plane.normal().dot_wide_exact(step) != 0 {
                continue; // rows not parallel to the plane: no matte runs
            }
            let num = plane.numerator(eye);
            for row in 0..camera.rows() {
                let towards = camera.row_start(row);
                let den = plane.normal().dot_wide_exact(towards);
                let Some(scale) = plane.scale_along(&num, den) else {
                    continue;
                };
                let (reach, len) = (far_reach(scale), camera.cols().into());
                let line = RunLine {
                    eye,
                    scale,
                    reach,
                    towards,
                    step,
                    len,
                };
                for ball in &balls {
                    let columns = line.shadowed_by(plane.normal(), light, ball);
                    kept += columns.len() as u64;
                    for k in 0..len {
                        if line.towards_column(k).length_squared_wide() > reach {
                            continue;
                        }
                        let point = line.point(k);
                        let to_light = light - point;
                        let d2 = to_light.length_squared_wide();
                        let Some(l) = to_light.normalize_with_square(d2) else {
                            continue;
                        };
                        let ray = Ray::new_unchecked(point, l);
                        tried += 1;
                        if Shape::Sphere(*ball).blocks(&ray, d2) {
                            blocked += 1;
                            assert!(
                                columns.contains(&k),
                                "world {world}, row {row}: column {k} is shadowed, \
                                 outside {columns:?}"
                            );
                        }
                    }
                }
            }
        }
        // The sample holds shadows, and the columns kept are few.
        assert!(blocked > 5_000, "shadowed: {blocked} of {tried}");
        assert!(kept * 4 < tried, "kept {kept} of {tried}");
    }

    #[test]
    fn solve_brackets_every_column_within_the_bound() {
        let mut rng = crate::xorshift::XorShift(0x5eed_c011_0000_0001);
        for _ in 0..20_000 {
            let mut draw = |bits: u32| (rng.next() as i64) >> (64 - bits);
            let last = draw(9).abs() % 200;
            let (first, end) = (draw(31), draw(31));
            let bound = draw(29).abs();
            let got = solve(first, end, last, bound);
            for k in 0..=last {
                // The affine value, exactly: |first·last + k·(end − first)| ≤ bound·last.
                let within = if last == 0 {
                    first.abs() <= bound
                } else {
                    (first * last + k * (end - first)).abs() <= bound * last
                };
                if within {
                    let (from, to) = got.expect("a column within the bound, none found");
                    assert!(from <= k && k <= to, "{first} {end} {last} {bound}: {k}");
                }
            }
        }
    }
}
