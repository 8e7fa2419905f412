//! [`ShadowCone`]: what a light sees of a sphere, to skip shadow tests that cannot hit.

use crate::geometry::shape::Shape;
use crate::numbers::fx::Fx;
use crate::numbers::isqrt::isqrt;
use crate::numbers::vec3::Vec3;
use crate::render::accel::shadow_rows::blocking_radius;

/// The cone from a light that holds a sphere, and the sphere's nearest distance from it.
///
/// A shadow ray runs from a hit point to the light; seen from the light it leaves along some
/// direction and ends at the hit point. It can meet the sphere only if that direction lies
/// inside the cone (half-angle `α`, `sin α = r / D` for a centre `D` away) and the hit point
/// is farther from the light than the sphere's near side (`D − r`). Both are tested with a
/// dot product and a comparison, against the dozen products of a full ray–sphere test, and
/// with margins far wider than the rounding, so a sphere that blocks is never skipped.
///
/// Sixteen bytes a light and a sphere: the axis and `cos α` in Q2.14 are plenty for a test
/// whose margin is 2⁻¹⁰, and the near distance is kept squared, as the test wants it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct ShadowCone {
    /// Unit vector from the light to the sphere's centre, Q2.14.
    axis: [i16; 3],
    /// `cos α` less a margin, Q2.14; `i16::MIN` for shapes that must always be tested.
    cos: i16,
    /// `(D − r)²` with a margin taken off `D − r`, in Q32.32 like a squared length.
    near_squared: u64,
}

impl ShadowCone {
    /// Always test: planes, and spheres that hold or nearly touch the light.
    pub(crate) const ALWAYS: ShadowCone = ShadowCone {
        axis: [0; 3],
        cos: i16::MIN,
        near_squared: 0,
    };

    /// 2⁻¹⁰: far wider than the few units of 2⁻¹⁶ that directions and lengths are off.
    const MARGIN: Fx = Fx::from_bits(1 << 6);

    /// The cone of `shape` seen from a light at `light` (`const`, for `static` scenes).
    pub(crate) const fn new(light: Vec3, shape: &Shape) -> ShadowCone {
        let Shape::Sphere(sphere) = shape else {
            return ShadowCone::ALWAYS;
        };
        // Raw units throughout: `Fx`'s operators cannot run in a `const fn`. Lights and
        // spheres are checked to lie within ±1024, so the differences below cannot saturate.
        let radius = sphere.radius().to_bits() as i64;
        let to_centre = sphere.centre().saturating_sub(light);
        let distance = to_centre.length().to_bits() as i64;
        let Some(axis) = to_centre.try_normalize() else {
            return ShadowCone::ALWAYS;
        };
        let margin = ShadowCone::MARGIN.to_bits() as i64;
        if distance <= radius + margin * 4 {
            return ShadowCone::ALWAYS;
        }
        // cos α = √(D² − r²) / D.
        let root = isqrt((distance * distance - radius * radius) as u64) as i64;
        let cos = (root << 16) / distance - margin;
        let near = {
            let near = distance - radius - margin;
            if near > 0 { near as u64 } else { 0 }
        };
        ShadowCone {
            axis: [
                q14(axis.x.to_bits()),
                q14(axis.y.to_bits()),
                q14(axis.z.to_bits()),
            ],
            cos: q14(cos as i32),
            near_squared: near * near,
        }
    }

    /// Whether every point at most `√distance_squared` from the light lies nearer than the
    /// sphere's near side, so that no shadow ray from it can meet the sphere.
    pub(crate) fn starts_past(&self, distance_squared: u64) -> bool {
        self.cos != i16::MIN && distance_squared <= self.near_squared
    }

    /// Whether a shadow ray along the unit `dir` (towards the light), from a point
    /// `√distance_squared` from the light, may meet the sphere.
    pub(crate) fn may_block(&self, dir: Vec3, distance_squared: u64) -> bool {
        if self.cos == i16::MIN {
            return true;
        }
        if distance_squared <= self.near_squared {
            return false;
        }
        // Seen from the light the ray leaves along −dir: inside the cone when −dir·axis ≥ cos.
        // In Q4.28: three products of Q2.14 values, each below 2²⁹ in magnitude.
        let c = |d: Fx, a: i16| (d.to_bits() >> 2) * a as i32;
        let dot = c(dir.x, self.axis[0]) + c(dir.y, self.axis[1]) + c(dir.z, self.axis[2]);
        -dot >= (self.cos as i32) << 14
    }

    /// [`ShadowCone::may_block`] with its three tests all taken, none skipping the others:
    /// for a loop over many cones, whose answers no branch could foresee.
    pub(crate) fn may_block_all_tested(&self, dir: Vec3, distance_squared: u64) -> bool {
        let c = |d: Fx, a: i16| (d.to_bits() >> 2) * a as i32;
        let dot = c(dir.x, self.axis[0]) + c(dir.y, self.axis[1]) + c(dir.z, self.axis[2]);
        let within = -dot >= (self.cos as i32) << 14;
        (self.cos == i16::MIN) | ((distance_squared > self.near_squared) & within)
    }

    /// Whether the sphere of radius `radius` this is the cone of may block a shadow ray whose
    /// unit direction from the light lies within the chord `spread` of `axis` (both Q2.14,
    /// `axis` a unit vector rounded down): the ray then passes within `ρ` of the centre
    /// (`blocking_radius`), so its direction lies within the chord `c = s·(1 + s)` of this
    /// cone's axis, `s ≥ ρ/D` (as `shadow_sweep`'s spans are bounded), and the two axes lie
    /// within `spread + c` of each other. `D` is taken at least the near side's distance,
    /// `√near_squared` rounded down; the axes' rounding, a unit a component each, is 4 units
    /// of their difference at most, and 5 are allowed. `true` where `s` would pass ½.
    pub(crate) fn may_meet_within(&self, radius: Fx, axis: [i16; 3], spread: i32) -> bool {
        if self.cos == i16::MIN {
            return true;
        }
        // Below 2²⁸ raw: a distance within ±2048·√3.
        let near = isqrt(self.near_squared) as i64;
        let rho = i64::from(blocking_radius(radius).to_bits());
        if near <= 2 * rho {
            return true;
        }
        // At most 2¹³ (ρ/D below ½), rounded up.
        let s = ((rho << 14) + near - 1) / near + 1;
        let chord = s + ((s * s) >> 14) + 1;
        let difference = |k: usize| i64::from(self.axis[k]) - i64::from(axis[k]);
        let apart = difference(0).pow(2) + difference(1).pow(2) + difference(2).pow(2);
        let reach = i64::from(spread) + chord + 5;
        apart <= reach * reach
    }

    /// Whether some shadow ray may meet the sphere whose direction seen from the light, `−dir`,
    /// has components that [`ShadowCone::may_block`] forms (`−(dir_k >> 2)`, Q2.14) within
    /// `bounds[k]`: whether `−dir·axis` can reach `cos` there. A linear form's largest value
    /// over a box is at a corner, each component at the end its axis's sign picks; directions
    /// are unit vectors, which only lowers it. Exact, in 64 bits.
    pub(crate) fn may_block_within(&self, bounds: [(i32, i32); 3]) -> bool {
        if self.cos == i16::MIN {
            return true;
        }
        let largest = |(low, high): (i32, i32), a: i16| {
            let a = i64::from(a);
            (i64::from(low) * a).max(i64::from(high) * a)
        };
        let most = largest(bounds[0], self.axis[0])
            + largest(bounds[1], self.axis[1])
            + largest(bounds[2], self.axis[2]);
        most >= i64::from(self.cos) << 14
    }
}

/// A raw Q16.16 value of magnitude at most 1, in Q2.14.
const fn q14(raw: i32) -> i16 {
    (raw >> 2) as i16
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::sphere::Sphere;

    #[test]
    fn the_cone_holds_the_sphere_and_little_else() {
        let light = Vec3::from_ints(0, 100, 0);
        let ball =
            Shape::Sphere(Sphere::from_fx(Vec3::from_ints(0, 50, 0), Fx::from_num(5)).unwrap());
        let cone = ShadowCone::new(light, &ball);
        let towards_light = |from: Vec3| {
            let v = light - from;
            (v.try_normalize().unwrap(), v.length_squared_wide())
        };
        // Straight below the ball: blocked, so it must be tested.
        let (dir, d2) = towards_light(Vec3::ZERO);
        assert!(cone.may_block(dir, d2));
        // sin α = 5/50: at the floor the shadow's edge is 10 from the axis. Well outside it
        // the test is skipped; just inside it is not.
        let (dir, d2) = towards_light(Vec3::from_ints(20, 0, 0));
        assert!(!cone.may_block(dir, d2));
        let (dir, d2) = towards_light(Vec3::from_ints(9, 0, 0));
        assert!(cone.may_block(dir, d2));
        // A point between the light and the ball cannot be shadowed by it.
        let (dir, d2) = towards_light(Vec3::from_ints(0, 80, 0));
        assert!(!cone.may_block(dir, d2));
    }

    /// Random spheres seen from random lights, random unit directions from random points:
    /// the cone's test taken whole answers as the one that skips, and a box of directions
    /// around each direction is refused only where the direction's own test refuses it.
    #[test]
    fn all_tested_and_within_a_box_agree_with_the_cone_test() {
        let mut rng = crate::xorshift::XorShift(0x5eed_c0e5_0000_0002);
        let (mut held, mut tried) = (0, 0);
        for _ in 0..20_000 {
            let v = |rng: &mut crate::xorshift::XorShift, r: f32| {
                Vec3::new(
                    Fx::from_num(rng.signed(r)),
                    Fx::from_num(rng.signed(r)),
                    Fx::from_num(rng.signed(r)),
                )
            };
            let light = v(&mut rng, 30.0);
            let radius = Fx::from_num(0.05 + rng.signed(4.0).abs());
            let ball = Sphere::from_fx(v(&mut rng, 30.0), radius).unwrap();
            let cone = ShadowCone::new(light, &Shape::Sphere(ball));
            // Points near the sphere's shadow, and anywhere.
            let from = match rng.next() % 2 {
                0 => ball.centre() + (ball.centre() - light).scale(Fx::from_num(0.5)),
                _ => v(&mut rng, 30.0),
            } + v(&mut rng, 2.0);
            let to_light = light - from;
            let d2 = to_light.length_squared_wide();
            let Some(dir) = to_light.normalize_with_square(d2) else {
                continue;
            };
            let blocks = cone.may_block(dir, d2);
            assert_eq!(cone.may_block_all_tested(dir, d2), blocks);
            // A box of the components the test forms, `−(dir_k >> 2)`, around them.
            let widen = (rng.next() % 200) as i32;
            let c = |d: Fx| -(d.to_bits() >> 2);
            let around = |d: Fx| (c(d) - widen, c(d) + widen);
            let bounds = [around(dir.x), around(dir.y), around(dir.z)];
            if cone.may_block(dir, u64::MAX) {
                assert!(cone.may_block_within(bounds));
            }
            held += u64::from(blocks);
            tried += 1;
        }
        assert!(held * 50 > tried && held * 2 < tried, "{held} of {tried}");
    }
}
