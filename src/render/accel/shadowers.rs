//! Which objects can shadow which: for each light and each receiving object, the set of
//! others a shadow ray from it may meet, so that a shadow ray tries no other.

use crate::geometry::plane::Plane;
use crate::geometry::shape::Shape;
use crate::geometry::sphere::Sphere;
use crate::numbers::isqrt::isqrt;
use crate::numbers::vec3::Vec3;
use crate::scene::Object;

/// How far a hit point may lie from the surface it was found on, raw: 2⁻¹⁰, far more than
/// the few units of 2⁻¹⁶ a rounded hit point is off it.
const ON_SURFACE: i64 = 1 << 6;

/// One in Q2.30, the unit of the angle tests below.
const ONE: i128 = 1 << 30;

/// The objects of `objects` (bit `i` for object `i`, below 32) that a shadow ray towards a
/// light at `light` from a hit on object `receiver` may meet, the receiver excluded.
///
/// Spheres and planes are convex and a shadow ray leaves its surface towards the light, so
/// the receiver never shadows itself. Another sphere is left out when it cannot come between
/// any point of a receiving sphere and the light ([`sphere_may_shade`]); a plane when the
/// receiving sphere lies wholly on the light's side of it, below the light
/// ([`plane_may_shade`]). Every other pair is kept, so a plane receives every object's shadow.
/// Each test allows for the rounding of shadow rays, far more widely than it needs.
pub(crate) const fn shadowers(light: Vec3, receiver: usize, objects: &[Object]) -> u32 {
    let mut set = 0u32;
    let mut other = 0;
    while other < objects.len() && other < 32 {
        if other != receiver {
            let may = match (&objects[receiver].shape, &objects[other].shape) {
                (Shape::Sphere(receiving), Shape::Sphere(casting)) => {
                    sphere_may_shade(light, casting, receiving)
                }
                (Shape::Sphere(receiving), Shape::Plane(casting)) => {
                    plane_may_shade(light, casting, receiving)
                }
                (Shape::Plane(_), _) => true,
            };
            if may {
                set |= 1 << other;
            }
        }
        other += 1;
    }
    set
}

/// How much wider than its radius a casting sphere is taken to be, raw, for shadow rays up to
/// `length` (raw) long: as the damage of an edit widens it (`render/changes/shadow.rs`). A
/// shadow ray runs along a rounded unit direction, off the exact segment by less than its
/// length over 1024; the sphere's test rounds the closest approach by a few units of 2⁻¹⁶
/// (the 2⁻⁸) and places a grazing crossing within `√(r · 2⁻¹³)` (the `√r / 32`).
const fn widening(radius: i64, length: i64) -> i64 {
    (isqrt((radius as u64) << 16) as i64) / 32 + (1 << 8) + length / 1024
}

/// Whether sphere `casting` may shade some point of sphere `receiving` from a light at
/// `light`: the cones from the light around each meet, and some point of the receiver lies
/// beyond the caster's near side.
const fn sphere_may_shade(light: Vec3, casting: &Sphere, receiving: &Sphere) -> bool {
    let to_casting = casting.centre().saturating_sub(light);
    let to_receiving = receiving.centre().saturating_sub(light);
    let (d_cast, d_receive) = (
        to_casting.length().to_bits() as i64 + 1,
        to_receiving.length().to_bits() as i64 + 1,
    );
    let r_receive = receiving.radius().to_bits() as i64 + ON_SURFACE;
    let far = d_receive + r_receive;
    let r_cast =
        casting.radius().to_bits() as i64 + widening(casting.radius().to_bits() as i64, far);
    // A light in or next to either: no cone bounds the shadow.
    if d_cast <= r_cast + (1 << 10) || d_receive <= r_receive + (1 << 10) {
        return true;
    }
    // Every point of the receiver nearer the light than the caster's near side.
    if far < d_cast - r_cast {
        return false;
    }
    // The cones' half-angles α (sin α = r / d) and the angle θ between their axes, in Q2.30:
    // they meet when θ ≤ α_cast + α_receive, that is cos θ ≥ cos(α_cast + α_receive).
    let (sin_c, sin_r) = (
        (r_cast as i128 * ONE) / d_cast as i128,
        (r_receive as i128 * ONE) / d_receive as i128,
    );
    let (cos_c, cos_r) = (root_of_one_less(sin_c), root_of_one_less(sin_r));
    let cos_sum = (cos_c * cos_r - sin_c * sin_r) / ONE;
    // cos θ = (a·b) / (|a| |b|): the dot product in Q32.32, the lengths in Q16.16 (rounded
    // up, so that its magnitude is rounded down, and the margin below covers the rest).
    let dot = to_casting.dot_wide(to_receiving) as i128;
    let cos_theta = dot * ONE / (d_cast as i128 * d_receive as i128);
    // 2⁻¹⁰ of margin, far above the rounding of the lengths and quotients.
    cos_theta + (1 << 20) >= cos_sum || sin_c >= ONE || sin_r >= ONE
}

/// `√(1 − s²)` for `0 ≤ s` in Q2.30 (0 where `s ≥ 1`).
const fn root_of_one_less(s: i128) -> i128 {
    let rest = ONE * ONE - s * s;
    if rest <= 0 {
        0
    } else {
        isqrt(rest as u64) as i128
    }
}

/// Whether plane `casting` may shade some point of sphere `receiving` from a light at
/// `light`.
///
/// A segment from a point of the sphere to the light crosses the plane only when its ends lie
/// on either side. With heights measured from the plane towards the light, a sphere wholly
/// above the plane (by [`ON_SURFACE`]) and below the light cannot be shaded by it; the
/// margin below the light allows for a shadow ray's rounded direction, which may descend a
/// little where it should run level.
const fn plane_may_shade(light: Vec3, casting: &Plane, receiving: &Sphere) -> bool {
    let normal = casting.normal();
    let light_height = normal.dot_wide(light.saturating_sub(casting.point())) >> 16;
    let up = if light_height >= 0 { 1 } else { -1 };
    let light_height = light_height.abs();
    let centre_height =
        up * (normal.dot_wide(receiving.centre().saturating_sub(casting.point())) >> 16);
    let radius = receiving.radius().to_bits() as i64 + ON_SURFACE + 2;
    let length = light.saturating_sub(receiving.centre()).length().to_bits() as i64 + radius;
    let above = centre_height - radius > ON_SURFACE;
    let below_light = centre_height + radius + length / 1024 + ON_SURFACE < light_height;
    !(above && below_light)
}
