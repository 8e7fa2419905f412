//! Snell's law for a unit direction at a surface, and Schlick's approximation of the share
//! that Fresnel's equations reflect.

use crate::numbers::fx::{self, FRAC, Fx};
use crate::numbers::isqrt::isqrt;
use crate::numbers::vec3::Vec3;

/// The direction of a ray refracted at a surface, or `None` where Snell's law has no solution
/// (total internal reflection).
///
/// `dir` is the unit direction of the arriving ray, `normal` the surface's unit normal facing
/// it (`normal·dir ≤ 0`) and `ratio` the refractive index on the arriving side over the one
/// beyond (`η₁/η₂`, at most 4). With `cos θ₁ = −normal·dir`, Snell's law
/// `sin θ₂ = ratio · sin θ₁` gives `cos² θ₂ = k = 1 − ratio²·(1 − cos² θ₁)`; for `k < 0` no
/// ray passes. Otherwise the refracted direction is `ratio·dir + (ratio·cos θ₁ − √k)·normal`,
/// a unit vector for exact inputs, renormalised here against rounding.
///
/// ```
/// use fixray::{Fx, Vec3, internals::refract};
/// // Straight through at normal incidence, for any ratio.
/// assert_eq!(refract(-Vec3::Z, Vec3::Z, Fx::from_num(0.5)), Some(-Vec3::Z));
/// // From glass into air at 45°: sin θ₂ = 1.5 · 0.707 > 1, totally reflected.
/// let d = Vec3::new(Fx::from_num(0.7071), Fx::ZERO, Fx::from_num(-0.7071));
/// assert_eq!(refract(d, Vec3::Z, Fx::from_num(1.5)), None);
/// ```
#[must_use]
pub fn refract(dir: Vec3, normal: Vec3, ratio: Fx) -> Option<Vec3> {
    // cos θ₁ in [0, 1]; rounding may leave it a step outside.
    let cos_in = (-normal.dot(dir)).max(Fx::ZERO).min(Fx::ONE);
    let sin2_in = Fx::ONE - fx::mul_fits(cos_in, cos_in);
    // ratio ≤ 4, so ratio² ≤ 16 and ratio²·sin² θ₁ ≤ 16: no product leaves Q16.16.
    let k = Fx::ONE - fx::mul(fx::mul(ratio, ratio), sin2_in);
    if k < Fx::ZERO {
        return None;
    }
    // √k for k in [0, 1], in Q16.16: the integer root of k·2¹⁶ in raw units.
    let root = Fx::from_bits(isqrt((k.to_bits() as u64) << FRAC) as i32);
    let along_normal = fx::mul(ratio, cos_in) - root;
    (dir.scale(ratio) + normal.scale(along_normal)).try_normalize()
}

/// Schlick's approximation of the share of light a surface reflects:
/// `R₀ + (1 − R₀)(1 − cos θ)⁵` with `R₀ = ((η − 1)/(η + 1))²`, for `cos θ` in `[0, 1]` the
/// cosine of the larger of the two angles (the one on the lower-index side) and `r0` its
/// `R₀`. The result lies in `[R₀, 1]`.
pub(crate) fn schlick(r0: Fx, cos: Fx) -> Fx {
    let x = Fx::ONE - cos.max(Fx::ZERO).min(Fx::ONE);
    let x2 = fx::mul_fits(x, x);
    let x5 = fx::mul_fits(fx::mul_fits(x2, x2), x);
    r0 + fx::mul_fits(Fx::ONE - r0, x5)
}
