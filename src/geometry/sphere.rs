//! [`Sphere`] and the chapter's two-step ray–sphere intersection (section 4.4).

use core::cmp::Ordering;

use crate::check;
use crate::error::{Error, Quantity};
use crate::geometry::hit::Hit;
use crate::geometry::ray::Ray;
use crate::numbers::fx::{self, FAR, FRAC, Fx};
use crate::numbers::isqrt::isqrt;
use crate::numbers::vec3::Vec3;

/// A near crossing at least this far ahead (a quarter of a unit) proves the origin outside
/// the sphere, so the exact classification of [`Sphere::crossing_near_origin`] is needed only
/// below it.
///
/// For an origin on or inside the sphere (`‖c − p_r‖ ≤ r`) the exact near crossing is at most
/// 0, and the rounded one `t_close − a` exceeds it only through a computed `a` that came out
/// too small. Then `a² ≥ t_close²·(1 − ε) − δ`: the direction's squared length is within
/// `ε ≤ 2√3·2⁻¹⁶` of 1, and rounding `x_close` moves `d²` by `δ ≤ 2⁻⁵` for radii within
/// [`LIMIT`](crate::LIMIT). With `t_close ≤ 2r ≤ 2048` the near crossing is thus at most
/// `ε·t_close/2 + δ/(2·t_close)` plus a few units of 2⁻¹⁶: below 0.12 once `t_close ≥ ¼`, and
/// below `t_close` always.
const SURELY_OUTSIDE: Fx = Fx::from_bits(1 << 14);

/// A sphere with centre `c` and radius `r > 0`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Sphere {
    centre: Vec3,
    radius: Fx,
    /// `2^(31 + inv_shift) / r` in raw units, in `(2³⁰, 2³¹)`: the normal `(x − c)/r` is a
    /// multiplication by it instead of three divisions.
    inv_radius: i32,
    inv_shift: u32,
}

impl Sphere {
    /// A sphere of centre `centre` and radius `radius`, checked: the centre within
    /// ±[`LIMIT`](crate::LIMIT), the radius positive and at most `LIMIT` (one that rounds to
    /// zero in Q16.16 is not positive).
    ///
    /// ```
    /// use fixray::{Error, Sphere};
    /// let ball = Sphere::new([-3.0, 0.0, -16.0], 2.0)?;
    /// assert_eq!(ball.radius(), 2.0);
    /// assert_eq!(Sphere::new([0.0; 3], 0.0), Err(Error::NonPositiveRadius));
    /// # Ok::<(), Error>(())
    /// ```
    pub fn new(centre: [f32; 3], radius: f32) -> Result<Self, Error> {
        let centre = check::f32_point(centre, Quantity::SphereCentre)?;
        if radius.is_finite() && radius <= 0.0 {
            return Err(Error::NonPositiveRadius);
        }
        Sphere::from_fx(
            centre,
            check::f32_coordinate(radius, Quantity::SphereRadius)?,
        )
    }

    /// [`Sphere::new`] in fixed point, for `const` and `static` scenes: the same checks, at
    /// compile time when the values are constants.
    ///
    /// ```
    /// use fixray::{Fx, Sphere, Vec3};
    /// const BALL: Result<Sphere, fixray::Error> =
    ///     Sphere::from_fx(Vec3::from_ints(-3, 0, -16), Fx::const_from_int(2));
    /// assert_eq!(BALL, Sphere::new([-3.0, 0.0, -16.0], 2.0));
    /// ```
    pub const fn from_fx(centre: Vec3, radius: Fx) -> Result<Self, Error> {
        let centre = match check::point(centre, Quantity::SphereCentre) {
            Ok(centre) => centre,
            Err(e) => return Err(e),
        };
        if radius.to_bits() <= 0 {
            return Err(Error::NonPositiveRadius);
        }
        if let Err(e) = check::coordinate(radius, Quantity::SphereRadius) {
            return Err(e);
        }
        // r in raw units lies in [2^k, 2^(k+1)); 2^(31+k)/r then lies in (2³⁰, 2³¹].
        let r = radius.to_bits() as u64;
        let k = 63 - r.leading_zeros();
        let inv = (1u64 << (31 + k)) / r;
        Ok(Sphere {
            centre,
            radius,
            inv_radius: if inv > i32::MAX as u64 {
                i32::MAX
            } else {
                inv as i32
            },
            inv_shift: k,
        })
    }

    /// `r²` in Q32.32, exactly: every ray test compares with it.
    const fn radius_squared(&self) -> u64 {
        fx::wide_mul(self.radius.to_bits(), self.radius.to_bits()) as u64
    }

    /// The unit sphere at the origin.
    pub(crate) const UNIT: Sphere = match Sphere::from_fx(Vec3::ZERO, Fx::ONE) {
        Ok(sphere) => sphere,
        Err(_) => panic!("the unit sphere is valid"),
    };

    /// The centre `c`.
    #[must_use]
    pub const fn centre(&self) -> Vec3 {
        self.centre
    }

    /// The radius `r`.
    #[must_use]
    pub const fn radius(&self) -> Fx {
        self.radius
    }

    /// Where `ray` first meets the sphere, by the chapter's two steps.
    ///
    /// 1. The closest approach: `t_close = u_r·(c − p_r)`, `x_close = p_r + t_close·u_r`,
    ///    `d = ‖x_close − c‖`. If `d > r` there is no hit.
    /// 2. Otherwise `a = √(r² − d²)` and the nearest hit is at `t_close − a`.
    ///
    /// What the chapter leaves open, decided by where the origin lies, `‖c − p_r‖²` against
    /// `r²` compared exactly at 64 bits:
    /// - outside: the hit is `t_close − a` for a ray pointing towards the centre
    ///   (`t_close > 0`); otherwise both crossings are behind the origin and it is a miss;
    /// - inside: the ray leaves through `t_close + a`;
    /// - on the surface: the ray meets the sphere again only if it points into it
    ///   (`u_r·(c − p_r) > 0`, exactly), at `t_close + a`; one pointing away from the sphere
    ///   or along it misses, so an eye on a surface does not see that surface at `t = 0`.
    ///
    /// A hit beyond [`FAR`] is a miss; a tangent ray (`d = r`) hits at `x_close`. `d²` and
    /// `r²` are compared exactly at 64 bits.
    ///
    /// ```
    /// use fixray::{Fx, Ray, Sphere, Vec3};
    /// let ball = Sphere::new([0.0, 0.0, -10.0], 2.0)?;
    /// let hit = ball.intersect(&Ray::new(Vec3::ZERO, -Vec3::Z)?).unwrap();
    /// assert_eq!(hit.t(), 8);
    /// assert_eq!(hit.normal(), Vec3::Z);
    /// // From inside, the ray leaves through the far side, whose normal faces back at it.
    /// let inside = ball.intersect(&Ray::new(Vec3::from_ints(0, 0, -10), -Vec3::Z)?).unwrap();
    /// assert_eq!((inside.t(), inside.normal()), (Fx::from_num(2), Vec3::Z));
    /// # Ok::<(), fixray::Error>(())
    /// ```
    #[must_use]
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let t = self.hit_distance(ray)?;
        Some(self.hit_at(ray, t))
    }

    /// The `t` of [`Sphere::intersect`] alone, without the hit point and normal: what the
    /// scene needs to find the nearest object and to test shadow rays.
    // In line, as `hit_distance_within` is: a call here would put one back in front of the
    // sphere test.
    #[inline(always)]
    pub(crate) fn hit_distance(&self, ray: &Ray) -> Option<Fx> {
        self.hit_distance_within(ray, FAR)
    }

    /// [`Sphere::hit_distance`] where it is at most `bound` (at most [`FAR`]) away, `None`
    /// where every hit would lie beyond: a hit is never nearer than `t_close − r`, since the
    /// root `a` of at most `r²` is at most `r`, so past `t_close − r > bound` nothing is left
    /// to find. With `bound` the nearest hit found so far, a sphere behind it is left after
    /// one dot product.
    // In line: the sphere test of the nearest-hit loops, where a call would move their values
    // out of the registers it clobbers.
    #[inline(always)]
    pub(crate) fn hit_distance_within(&self, ray: &Ray, bound: Fx) -> Option<Fx> {
        debug_assert!(bound <= FAR, "hit_distance_within: a bound past FAR");
        let to_centre = self.centre.minus(ray.origin);
        let t_close = ray.dir.dot_exact(to_centre);
        if t_close < -self.radius {
            return None; // wholly behind the origin
        }
        if t_close - self.radius > bound {
            return None; // every hit would lie beyond t_close − r > bound
        }
        let d2 = closest_squared(ray, to_centre, t_close);
        let r2 = self.radius_squared();
        if d2 > r2 {
            return None;
        }
        // r² − d² ≤ r² ≤ 2²⁰·2³², so a fits Q16.16.
        let a = Fx::from_bits(isqrt(r2 - d2) as i32);
        let near = t_close - a;
        let t = if near >= SURELY_OUTSIDE {
            near
        } else {
            self.crossing_near_origin(ray, to_centre, r2, t_close, a)?
        };
        if t > FAR {
            return None;
        }
        Some(t)
    }

    /// Whether `ray` meets the sphere nearer than `√distance_squared` (a Q32.32 value):
    /// exactly `hit_distance(ray).is_some_and(|t| t² < distance_squared)`, a shadow ray's
    /// question. Without the square root where the answer does not need it: when the closest
    /// approach lies more than a radius (and [`SURELY_OUTSIDE`]) ahead of the origin and
    /// within [`FAR`], a hit is at `t_close − a` with `0 ≤ a ≤ r` (`a` is a root of at most
    /// `r²`), so every hit is near enough if `t_close` is, and none if `t_close − r` is not.
    pub(crate) fn blocks(&self, ray: &Ray, distance_squared: u64) -> bool {
        let square = |t: Fx| fx::wide_mul_u32(t.to_bits() as u32, t.to_bits() as u32);
        let to_centre = self.centre.minus(ray.origin);
        let t_close = ray.dir.dot_exact(to_centre);
        let nearest = t_close - self.radius;
        if nearest >= SURELY_OUTSIDE && t_close <= FAR {
            if square(nearest) >= distance_squared {
                return false;
            }
            if square(t_close) < distance_squared {
                return closest_squared(ray, to_centre, t_close) <= self.radius_squared();
            }
        }
        self.hit_distance(ray)
            .is_some_and(|t| square(t) < distance_squared)
    }

    /// Where a ray that has just entered the sphere through its surface leaves it: the far
    /// crossing `t_close + a`, whatever the near one comes to.
    ///
    /// A refracted ray starts at a hit point rounded to Q16.16, which may lie a little
    /// outside the sphere, where [`Sphere::hit_distance`] would find the near crossing at
    /// about 0: the ray would meet the surface it has just crossed. Knowing that it entered
    /// (it was refracted inwards there), the far crossing is the one it meets, exactly, with
    /// no offset. Rounding may take a ray that grazes the surface past it (`d > r`); it then
    /// leaves at its closest approach, and never behind its origin.
    pub(crate) fn exit_distance(&self, ray: &Ray) -> Fx {
        let to_centre = self.centre.minus(ray.origin);
        let t_close = ray.dir.dot_exact(to_centre);
        // The origin lies near the surface, so |t_close| ≤ r + a little and a ≤ r: the sum
        // is far inside FAR and Q16.16.
        let d2 = ray
            .dir
            .scale_unit(t_close)
            .minus(to_centre)
            .length_squared_wide();
        let r2 = self.radius_squared();
        let a = Fx::from_bits(isqrt(r2.saturating_sub(d2)) as i32);
        (t_close + a).max(Fx::ZERO)
    }

    /// Whether `hit`, a hit on this sphere, was reached from inside it: its normal, which
    /// faces the ray, points towards the centre's side of the surface.
    pub(crate) fn reached_from_inside(&self, hit: &Hit) -> bool {
        // A hit point lies within the budget and a centre within LIMIT, and the normal is a
        // unit vector: the difference needs no saturation check, nor the dot product a
        // range check (`Vec3::dot_wide`'s). A secondary ray's question, a call away.
        hit.normal.dot_wide_exact(hit.point.minus(self.centre)) < 0
    }

    /// The crossing ahead of a ray whose near crossing `t_close − a` came out below
    /// [`SURELY_OUTSIDE`]: the origin is classified exactly as outside, on or inside the
    /// sphere (see [`Sphere::intersect`]).
    #[cold]
    fn crossing_near_origin(
        &self,
        ray: &Ray,
        to_centre: Vec3,
        r2: u64,
        t_close: Fx,
        a: Fx,
    ) -> Option<Fx> {
        match to_centre.length_squared_wide().cmp(&r2) {
            // Both crossings are behind an outside origin unless the ray points towards the
            // centre; then the near one is ahead, at 0 when rounding takes it below.
            Ordering::Greater => (t_close > Fx::ZERO).then(|| (t_close - a).max(Fx::ZERO)),
            // On the surface one crossing is the origin itself: the other is ahead only for a
            // ray pointing into the sphere, and `t_close` may round a small positive to 0.
            Ordering::Equal => {
                (ray.dir.dot_wide(to_centre) > 0).then(|| (t_close + a).max(Fx::ZERO))
            }
            Ordering::Less => Some((t_close + a).max(Fx::ZERO)),
        }
    }

    /// The hit at distance `t` along `ray`: its point, and its normal facing the ray.
    // In line: a call would hand the hit, its point and its normal, back through memory.
    #[inline(always)]
    pub(crate) fn hit_at(&self, ray: &Ray, t: Fx) -> Hit {
        let point = ray.at_hit(t);
        Hit::facing(t, point, self.outward_normal(point), ray.dir)
    }

    /// The outward unit normal `(x − c) / r` at a point `x` on the surface, as a
    /// multiplication by the reciprocal radius kept since construction.
    pub(crate) fn outward_normal(&self, x: Vec3) -> Vec3 {
        // A point near the surface lies within the radius and a little of the centre: no
        // saturation to check.
        let v = x.minus(self.centre);
        let shift = FRAC - 1 + self.inv_shift; // (v·2^(31+k)/r) / 2^(15+k) = v·2¹⁶/r
        let (v, shift) = if fx::HIGH_WORD_QUOTIENT && shift < 33 {
            (lifted(v, self.inv_shift), 33)
        } else {
            (v, shift)
        };
        let scale = |c: Fx| {
            let q = fx::mul_shift_round(c.to_bits(), self.inv_radius, shift);
            // A point within rounding of the surface gives |q| ≤ 2¹⁶ plus a few units, and a
            // hit point is within 2¹⁴ raw units of it (up to FAR along a unit direction good
            // to 2⁻¹⁶), so for any radius of a raw unit or more |q| stays below 2³¹: held at
            // ±1 as a 32-bit value, which costs less than holding the 64-bit one.
            debug_assert!(
                q.unsigned_abs() < 1 << 31,
                "outward_normal: the point is far from the surface"
            );
            Fx::from_bits((q as i32).clamp(-(1 << FRAC), 1 << FRAC))
        };
        Vec3::new(scale(v.x), scale(v.y), scale(v.z))
    }
}

/// The difference `v` from the centre of a sphere of radius below 4 (`k ≤ 17`, a shift of
/// 32 or less, where the rounding would take the product's low word too), moved up by
/// `18 − k` bits: divided by `2³³` it gives the same quotient, exactly, from the product's
/// high word alone, one instruction on the chips of [`fx::HIGH_WORD_QUOTIENT`]. A component
/// beyond `2^(k+2)`, more than twice the radius, is held at ±1 either way; held at `2^(k+2)`
/// first, it fits 32 bits once moved (2²⁰).
fn lifted(v: Vec3, k: u32) -> Vec3 {
    let bound = 1i32 << (k + 2);
    let lift = |c: Fx| Fx::from_bits(c.to_bits().max(-bound).min(bound) << (18 - k));
    Vec3::new(lift(v.x), lift(v.y), lift(v.z))
}

/// `d²`, the squared distance from the centre of the point `t_close` along `ray`, whose
/// origin is `to_centre` from the centre: `x_close − c = t_close·u_r − (c − p_r)`.
fn closest_squared(ray: &Ray, to_centre: Vec3, t_close: Fx) -> u64 {
    ray.dir
        .scale_unit(t_close)
        .minus(to_centre)
        .length_squared_wide()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numbers::fx::LIMIT;

    fn ball() -> Sphere {
        Sphere::from_fx(Vec3::from_ints(0, 0, -10), Fx::from_num(2)).unwrap()
    }

    fn ray(o: Vec3, d: Vec3) -> Ray {
        Ray::new(o, d).unwrap()
    }

    /// A random ball (radius 0.05 to 30, centre within ±200) and a ray at it from far off,
    /// from near its surface or from inside (by `case`), aimed within 1.5 radii of its centre;
    /// `None` where the ray's direction came out zero.
    fn random_ball_and_ray(
        rng: &mut crate::xorshift::XorShift,
        case: usize,
    ) -> Option<(Sphere, Ray)> {
        let r = 0.05 + rng.signed(1.0).abs() * 30.0;
        let centre = [rng.signed(200.0), rng.signed(200.0), rng.signed(200.0)];
        let ball = Sphere::new(centre, r).unwrap();
        let reach = [r * 0.5, r * 1.001, r * 3.0, 400.0][case % 4];
        let mut near = |spread: f32| {
            let [x, y, z] = centre.map(|c| Fx::from_num(c + rng.signed(spread)));
            Vec3::new(x, y, z)
        };
        let origin = near(reach);
        let aim = near(r * 1.5);
        Some((ball, Ray::new(origin, aim - origin).ok()?))
    }

    #[test]
    fn origin_inside_leaves_through_the_far_side() {
        let hit = ball()
            .intersect(&ray(Vec3::from_ints(0, 0, -10), -Vec3::Z))
            .unwrap();
        assert_eq!(hit.t, Fx::from_num(2));
        assert_eq!(hit.point, Vec3::from_ints(0, 0, -12));
    }

    #[test]
    fn blocks_answers_as_the_hit_distance_does() {
        // Random balls and rays, from far off, from near the surface and from inside, against
        // squared distances at and about the hit's own, the closest approach's and the near
        // side's: `blocks` must give the answer `hit_distance` gives, everywhere.
        let mut rng = crate::xorshift::XorShift(0xb10c_5ed0_5eed_0001);
        let (mut cases, mut blocked) = (0u32, 0u32);
        for case in 0..20_000 {
            let Some((ball, ray)) = random_ball_and_ray(&mut rng, case) else {
                continue;
            };
            let origin = ray.origin;
            let square = |t: Fx| {
                let t = t.to_bits().max(0) as u64;
                t * t
            };
            let to_centre = ball.centre - origin;
            let t_close = ray.dir.dot_exact(to_centre);
            let hit = ball.hit_distance(&ray);
            let around = |t: Option<Fx>| {
                let t2 = t.map_or(0, square);
                [t2.saturating_sub(1), t2, t2 + 1]
            };
            let ends = [0, 1, u64::MAX, (rng.signed(1.0).abs() * 1e15) as u64];
            let [a, b, c] = [hit, Some(t_close), Some(t_close - ball.radius)].map(around);
            for limit in ends.into_iter().chain(a).chain(b).chain(c) {
                let expected = hit.is_some_and(|t| square(t) < limit);
                assert_eq!(
                    ball.blocks(&ray, limit),
                    expected,
                    "case {case}: {ball:?}, {ray:?}, limit {limit}"
                );
                cases += 1;
                blocked += expected as u32;
            }
        }
        assert!(
            cases > 150_000 && blocked > 20_000,
            "{cases} cases, {blocked} blocked"
        );
    }

    #[test]
    fn a_sphere_is_left_within_a_bound_only_where_its_hit_lies_beyond() {
        // Random balls and rays, from far off, near the surface and inside, against bounds at
        // and about the hit, the closest approach and the near side: within a bound, the test
        // gives the hit `hit_distance` gives, or nothing where that hit is farther than the
        // bound. Fails with the near side taken as `t_close`; taken a unit lower it is still
        // right but leaves a third as many spheres early, and the count fails.
        let mut rng = crate::xorshift::XorShift(0x0b0d_5eed_0000_0013);
        let (mut left, mut found) = (0u32, 0u32);
        for case in 0..20_000 {
            let Some((ball, ray)) = random_ball_and_ray(&mut rng, case) else {
                continue;
            };
            let origin = ray.origin;
            let t_close = ray.dir.dot_exact(ball.centre - origin);
            let hit = ball.hit_distance(&ray);
            let around = |t: Fx| [t - Fx::DELTA, t, t + Fx::DELTA];
            let [a, b, c] = [hit.unwrap_or(FAR), t_close, t_close - ball.radius].map(around);
            let ends = [Fx::ZERO, FAR, Fx::from_num(rng.signed(200.0).abs())];
            for bound in ends.into_iter().chain(a).chain(b).chain(c) {
                let bound = bound.clamp(-FAR, FAR);
                let within = ball.hit_distance_within(&ray, bound);
                match (within, hit) {
                    (Some(t), _) => assert_eq!(Some(t), hit, "case {case}: {ball:?}, {ray:?}"),
                    (None, Some(t)) => {
                        assert!(t > bound, "case {case}: {ball:?}, {ray:?}, bound {bound}");
                        left += 1;
                    }
                    (None, None) => {}
                }
                found += u32::from(within.is_some());
            }
        }
        assert!(
            left > 10_000 && found > 20_000,
            "{left} left, {found} found"
        );
        // Through the centre the hit is the near side itself, `t_close − r`: a bound there
        // is not beyond it, and the hit is found (a nearest hit found so far at the same
        // distance may still lose the tie to a lower index).
        let through = ray(Vec3::ZERO, -Vec3::Z);
        let eight = Fx::from_num(8);
        assert_eq!(ball().hit_distance_within(&through, eight), Some(eight));
        assert_eq!(
            ball().hit_distance_within(&through, eight - Fx::DELTA),
            None
        );
    }

    #[test]
    fn from_the_surface_only_a_ray_into_the_sphere_meets_it() {
        let pole = Vec3::from_ints(0, 0, -8); // the near pole of the ball
        assert_eq!(ball().hit_distance(&ray(pole, Vec3::Z)), None, "away");
        assert_eq!(ball().hit_distance(&ray(pole, Vec3::X)), None, "along");
        assert_eq!(
            ball().hit_distance(&ray(pole, -Vec3::Z)),
            Some(Fx::from_num(4)),
            "through to the far pole"
        );
        // The eye on the top of a large sphere: rays upward miss it, rays downward cross it.
        let big = Sphere::from_fx(Vec3::from_ints(0, -50, 0), Fx::from_num(50)).unwrap();
        for k in 1..=64 {
            let up = ray(
                Vec3::ZERO,
                Vec3::new(Fx::from_bits(k * 97), Fx::from_bits(k), -Fx::ONE),
            );
            assert_eq!(big.hit_distance(&up), None, "upward {k}");
        }
        // Steeper downward rays, whose chord is long against the rounding of d² (δ ≤ 2⁻¹⁰
        // for r = 50): t_close + a is then within δ/(2·t_close) + 2⁻¹⁶·100 of the chord, below
        // 2⁻⁸.
        for k in 1..=32 {
            let up = ray(
                Vec3::ZERO,
                Vec3::new(Fx::from_bits(k * 97), Fx::from_bits(k * 512), -Fx::ONE),
            );
            let down = Ray::new_unchecked(Vec3::ZERO, Vec3::new(up.dir.x, -up.dir.y, up.dir.z));
            let t = big
                .hit_distance(&down)
                .expect("downward rays cross the sphere");
            // The chord from the pole: 2·r·sin(elevation) = 100·|u_y|.
            let chord = Fx::from_num(100) * -down.dir.y;
            assert!(
                (t - chord).abs() <= Fx::from_bits(256),
                "downward {k}: {t} vs {chord}"
            );
        }
    }

    #[test]
    fn the_near_crossing_is_taken_without_classifying_only_from_outside() {
        // Origins on, just inside and just outside many spheres, in many directions: where
        // `hit_distance` takes its shortcut the exact classification agrees with it.
        let mut rng = crate::xorshift::XorShift(0x5eed_0f5a);
        for _ in 0..20_000 {
            let radius = Fx::from_bits((rng.next() % (1024 << 16)) as i32 + 1);
            let centre = Vec3::from_ints(0, 0, 0);
            let sphere = Sphere::from_fx(centre, radius).unwrap();
            // A point at the radius along an axis, or at (3/5, 4/5) of it, nudged by a few
            // units either way: on, just inside or just outside the surface.
            let nudge = Fx::from_bits((rng.next() % 9) as i32 - 4);
            let origin = if rng.next().is_multiple_of(2) {
                Vec3::new(Fx::ZERO, radius + nudge, Fx::ZERO)
            } else {
                let fifth = radius / 5;
                Vec3::new(fifth * 3, fifth * 4 + nudge, Fx::ZERO)
            };
            let dir = Vec3::new(
                Fx::from_bits(rng.next() as i32 >> 12),
                Fx::from_bits(rng.next() as i32 >> 12),
                Fx::from_bits(rng.next() as i32 >> 12),
            );
            let Some(dir) = dir.try_normalize() else {
                continue;
            };
            let ray = Ray::new_unchecked(origin, dir);
            let to_centre = centre - origin;
            let t_close = dir.dot_exact(to_centre);
            let d2 = (dir.scale_unit(t_close) - to_centre).length_squared_wide();
            let r2 = fx::wide_mul(radius.to_bits(), radius.to_bits()) as u64;
            // The same steps with every origin classified exactly.
            let classified = if d2 > r2 || t_close < -radius {
                None
            } else {
                let a = Fx::from_bits(isqrt(r2 - d2) as i32);
                sphere
                    .crossing_near_origin(&ray, to_centre, r2, t_close, a)
                    .filter(|&t| t <= FAR)
            };
            assert_eq!(
                sphere.hit_distance(&ray),
                classified,
                "r {radius}, origin {origin:?}, dir {dir:?}"
            );
        }
    }

    #[test]
    fn sphere_behind_the_origin_is_a_miss() {
        assert!(ball().intersect(&ray(Vec3::ZERO, Vec3::Z)).is_none());
    }

    #[test]
    fn tangent_ray_hits_at_closest_approach() {
        let hit = ball()
            .intersect(&ray(Vec3::from_ints(2, 0, 0), -Vec3::Z))
            .unwrap();
        assert_eq!(hit.t, Fx::from_num(10));
        assert_eq!(hit.normal, Vec3::X);
    }

    #[test]
    fn ray_passing_outside_is_a_miss() {
        let beside = Vec3::new(Fx::from_num(2) + Fx::from_bits(1), Fx::ZERO, Fx::ZERO);
        assert!(ball().intersect(&ray(beside, -Vec3::Z)).is_none());
    }

    #[test]
    fn invalid_spheres_are_refused() {
        assert_eq!(
            Sphere::from_fx(Vec3::ZERO, Fx::from_num(-1)),
            Err(Error::NonPositiveRadius)
        );
        assert_eq!(
            Sphere::from_fx(Vec3::from_ints(0, 2000, 0), Fx::ONE),
            Err(Error::OutOfRange {
                quantity: Quantity::SphereCentre,
                min: -LIMIT,
                max: LIMIT,
            })
        );
        assert_eq!(
            Sphere::from_fx(Vec3::ZERO, Fx::from_num(1500)),
            Err(Error::OutOfRange {
                quantity: Quantity::SphereRadius,
                min: -LIMIT,
                max: LIMIT,
            })
        );
    }

    #[test]
    fn a_lifted_difference_gives_the_normal_components_of_the_plain_quotient() {
        // Every radius below 4 (k ≤ 17) at both ends of its octave and between, and
        // components from 0 to the ends of i32: the lifted quotient, held at ±1, is the
        // plain one. Fails with the lift one off or the bound at 2^k.
        let mut random = crate::xorshift::XorShift(0x9E37_79B9_7F4A_7C15);
        let held = |q: i64| q.clamp(-(1 << FRAC), 1 << FRAC);
        for k in 0..18u32 {
            let octave = [1i32 << k, (1 << k) + 1, (3 << k) / 2, (2 << k) - 1];
            for r in octave.into_iter().filter(|r| r >> k == 1) {
                let sphere = Sphere::from_fx(Vec3::ZERO, Fx::from_bits(r)).unwrap();
                assert_eq!(sphere.inv_shift, k);
                let (inv, shift) = (sphere.inv_radius, FRAC - 1 + sphere.inv_shift);
                let edges = [0, 1, r - 1, r, r + 1, 2 * r, i32::MAX, i32::MIN + 1];
                let draws = (0..4000).map(|_| (random.next() as i32) >> (random.next() % 32));
                for c in edges.into_iter().chain(edges.map(|c| -c)).chain(draws) {
                    let c = c.max(-i32::MAX);
                    let v = Vec3::new(Fx::from_bits(c), Fx::ZERO, Fx::ZERO);
                    let lifted = lifted(v, sphere.inv_shift);
                    assert_eq!(
                        held(fx::mul_shift_round(lifted.x.to_bits(), inv, 33)),
                        held(fx::mul_shift_round(c, inv, shift)),
                        "radius {r} raw, component {c}"
                    );
                }
            }
        }
    }
}
