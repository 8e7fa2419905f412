//! What the row walk asks of the camera: the direction towards a row's first pixel and the
//! exact step from one column to the next, a ray from such a direction, the plane that holds
//! every ray of a row, and the columns whose rays can meet a sphere. The plain path makes
//! each pixel's ray on its own ([`Camera::ray`]); these serve the runs, the culling, the
//! shadow sets of a row and the damage of an edit, each held to the plain path by the tests.

use crate::geometry::ray::Ray;
use crate::numbers::fx::{self, Fx};
use crate::numbers::isqrt::isqrt;
use crate::numbers::reciprocal::{Mantissa, Scale, inverse};
use crate::numbers::vec3::Vec3;
use crate::render::camera::{Camera, MAX_PIXELS, unit_of_exact};

impl Camera {
    /// From the eye towards the centre of pixel (`row`, 0), unnormalised: with
    /// [`Camera::column_step`] added `col` times it is exactly the direction towards pixel
    /// (`row`, `col`), since each column adds `2·right` to a numerator that is halved with
    /// rounding. A row's rays then cost three additions each, before normalising. For a row
    /// of the screen only ([`Camera::check_row`]).
    pub(crate) fn row_start(&self, row: u16) -> Vec3 {
        self.towards(0, row.into())
    }

    /// One column to the right, in the units of [`Camera::row_start`].
    pub(crate) const fn column_step(&self) -> Vec3 {
        self.right
    }

    /// The ray from the eye along `towards`, whose squared length is `square`, normalised:
    /// [`Camera::ray`] for a direction from [`Camera::row_start`].
    pub(crate) fn ray_along(&self, towards: Vec3, square: u64) -> Ray {
        let dir = towards.normalize_with_square(square);
        Ray::along(self.eye, dir.unwrap_or(Vec3::ZERO), towards)
    }

    /// The unit normal of the plane through the eye that holds every ray of display row
    /// `row` (the rays of a row differ only along `right`), or `None` if it is degenerate.
    /// Any `u16` row: off the screen, its direction towards column 0 is scaled to fit.
    ///
    /// Each component is within 0.55 of a unit of 2⁻¹⁶ of the exact unit normal of the plane
    /// the row's rays lie in, however short their directions: the culling of
    /// `Scene::seen_from_row_plane`, its row balls, the shadow sets
    /// of a row and the damage of an edit take their margins from that.
    ///
    /// The unnormalised direction towards column `x` is exactly `w + x·right`, `w` the one
    /// towards column 0 (each column adds `2·right` to a numerator halved with rounding), so
    /// every ray of the row lies in the plane through the eye along `right` and `w`, whose
    /// normal is `right × w`. That product is formed exactly here, in raw units of 2⁻³²: a
    /// component of `right` (a unit vector) is at most 2¹⁶ + 1 raw, one of `w` at most 2³⁰ + 1
    /// (the ray budget on the screen, [`Camera::shift_to_fit`] off it), so each product of two
    /// is below 2⁴⁷ and each difference below 2⁴⁸: no overflow. [`unit_of_exact`] then
    /// scales it to a top component of 2²⁹ to 2³⁰ (exact, or rounded to within 2⁻³⁰ of its
    /// length) and normalises it, the one rounding that matters.
    ///
    /// Rounding `right × w` to Q16.16 first, as this once did, is not enough: the ray budget
    /// lets the view distance fall to `R²/16 384` pixels, a `w` of about ten raw units on a
    /// one-pixel screen at 179.96°, and a cross product rounded to 2⁻¹⁶ then points
    /// hundredths of a radian off, far past the culling's margin of 2⁻¹¹ of a distance.
    pub(crate) fn row_plane_normal(&self, row: u16) -> Option<Vec3> {
        self.row_plane_normal_from(self.towards(0, row.into()))
    }

    /// [`Camera::row_plane_normal`] for the row whose [`Camera::row_start`] is `w`: a row's
    /// walk has it already.
    pub(crate) fn row_plane_normal_from(&self, w: Vec3) -> Option<Vec3> {
        let r = self.right;
        let c = |p: Fx, q: Fx, s: Fx, t: Fx| {
            fx::wide_mul(p.to_bits(), q.to_bits()) - fx::wide_mul(s.to_bits(), t.to_bits())
        };
        unit_of_exact([
            c(r.y, w.z, r.z, w.y),
            c(r.z, w.x, r.x, w.z),
            c(r.x, w.y, r.y, w.x),
        ])
    }

    /// The columns whose rays can meet a sphere of `radius` at `centre`, as a conservative
    /// inclusive range (it may extend past the screen), or `None` when the sphere reaches
    /// within 1/16 of the plane of the eye and no range is certain.
    ///
    /// Every ray of column `j` lies in the plane through the eye along `down` and
    /// `forward + a·right`, with `a = j + ½ − cols/2`; the sphere meets that plane where, in
    /// the frame of `right` and the unit view (its centre at `x` across and `z` ahead), the
    /// line `x' = (a/f)·z'` passes within `r` of `(x, z)`: between the two tangents from the
    /// eye to the disc, whose slopes are `(x·z ± r·√k) / (z² − r²)` with `k = x² + z² − r²`
    /// (`f` the view distance in pixels). So the span is exact but for its margins: the radius
    /// is widened by 2⁻¹² of the centre's `|x| + |y| + |z|` from the eye, which covers the
    /// rounding of the frame, of the rays and of the hit tests (each about 2⁻¹⁶ of the
    /// distance), and by 2⁻⁷ for the sums' own units; one column each side covers the slopes'
    /// rounding and the half column of `cols/2`.
    pub(crate) fn column_span(&self, centre: Vec3, radius: Fx) -> Option<(i16, i16)> {
        let to_centre = centre - self.eye;
        let view = self.view_unit?;
        // In units of 2⁻⁸, each value below 2²¹ and each product of two below 2⁴²: the centre
        // and the eye lie within ±1024, a ball's radius within 2048. Flooring `x` and `z` moves
        // the centre by less than √2 units, which the radius, rounded up, grows by 2 to cover.
        let (x, z) = (self.right.dot_units(to_centre), view.dot_units(to_centre));
        let (x, z) = (x.to_bits() >> 8, z.to_bits() >> 8);
        let widened = radius.to_bits() + (to_centre.l1_raw() >> 12) as i32;
        let r = ((widened + 255) >> 8) + 2;
        if z - r < 1 << 4 {
            return None;
        }
        let product = fx::wide_mul;
        let below = product(z - r, z + r);
        // √k rounded up, so that the tangents' spread is not understated.
        let root = isqrt((product(x, x) + below) as u64) as i32 + 1;
        let (middle, spread) = (product(x, z), product(r, root));
        // The slopes in Q16.16 from one reciprocal of their divisor, not two divisions (64-bit
        // ones are long library calls on every chip): each quotient within a relative 2⁻²⁷
        // ([`Mantissa::over`]) and floored, so within `|e|·2⁻²⁷ + 1` raw of the exact slope
        // `e`, less than `|s|·2⁻²⁶ + 1` of the found one `s`; moved `⌊|s|·2⁻²⁶⌋ + 2` outwards,
        // the low one down and the high one up, the span holds the exact slopes' whatever the
        // rounding. The quotient of a numerator below 2⁴³ and a divisor of at least 2⁸ is
        // below 2³⁵, and in Q16.16 fits.
        if below <= 0 {
            return None; // not reached: `z − r` is at least 16
        }
        let reciprocal = inverse(below as u64);
        let slope = |num: i64, outwards: i64| {
            let size = match num.unsigned_abs() {
                0 => 0,
                size => {
                    let Scale { m, shift } = Mantissa::new(size).times(reciprocal);
                    match 16 - shift {
                        up @ 0.. => i64::from(m) << up.min(31),
                        down => i64::from(m) >> (-down).min(63),
                    }
                }
            };
            let size = if num < 0 { -size } else { size };
            size + outwards * ((size.abs() >> 26) + 2)
        };
        let (low, high) = (slope(middle - spread, -1), slope(middle + spread, 1));
        // f · slope in whole pixels (Q16.16 × Q16.16 / 2³²), floored, in two exact parts:
        // `f` is below 2³¹ and the slope's low word below 2³², its high word below 2³¹.
        let distance = self.view.to_bits();
        let column = |s: i64| {
            let low = (distance as u64 * s as u32 as u64) >> 32;
            let offset = product(distance, (s >> 32) as i32) + low as i64;
            (offset + self.cols as i64 / 2).clamp(-8, MAX_PIXELS as i64 + 8) as i16
        };
        Some((column(low) - 1, column(high) + 1))
    }

    /// The columns of display row `row` whose rays meet `sphere`, by brute force: what the
    /// tests hold [`Camera::column_span`]'s spans to.
    #[cfg(test)]
    pub(crate) fn columns_meeting<'a>(
        &'a self,
        sphere: &'a crate::Sphere,
        row: u16,
    ) -> impl Iterator<Item = i16> + 'a {
        (0..self.cols())
            .filter(move |&col| {
                sphere
                    .hit_distance(&self.ray(col.into(), row.into()))
                    .is_some()
            })
            .map(|col| col as i16)
    }
}
