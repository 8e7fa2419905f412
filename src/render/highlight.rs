//! Which highlights are 0 before their cosine is formed.
//!
//! A highlight is `Σ I·(n·h)^shininess` over the lights, `h` the unit vector halfway between a
//! light's direction and the view's. Its power is 0 below the material's least lit cosine
//! (`least_lit_base`, exact), and for a shininess of 50 and more that is most of a surface:
//! there neither the power nor the cosine's reciprocal root need be formed. The test here
//! says so only where the cosine the plain path forms is surely below it, so the highlights
//! are bit for bit those formed in full.

use crate::numbers::fx::{self, Fx};
use crate::numbers::vec3::Vec3;

/// The cosine `n·h` of a highlight, for `h` the unit vector along `v` (a light's unit
/// direction less the view's), as [`highlight`](crate::render::trace::highlight) forms it
/// ([`Vec3::cosine_to`]); or `None` where that cosine must come out below `from` (raw
/// Q16.16, the material's least lit cosine), so that the highlight is 0 and the root need not
/// be taken, or where `v` is zero. Exact where it says so, conservative elsewhere: the
/// cosines it gives are bit for bit the plain path's, and those it rules out are below `from`.
pub(crate) fn lit_cosine(normal: Vec3, v: Vec3, from: u16) -> Option<Fx> {
    let (n, square) = (normal.dot_wide_exact(v), v.length_squared_wide());
    if surely_below(n, square, from) {
        return None;
    }
    Vec3::cosine_from(n, square)
}

/// Whether the cosine formed from `n = n·v` (exact, raw units) and `square = ‖v‖²` (Q32.32)
/// must come out below `from`.
///
/// It comes out within 0.541 of a unit of 2⁻¹⁶ of `N/√S` ([`Vec3::cosine_from`]), so below
/// `from` wherever `N < (from − 1)·√S`. That is `N ≤ 0`, or `N² < (from − 1)²·S`, compared
/// with `N` divided by 4 (rounded up) and `S` by 16 (down) so that both sides are 32 × 32-bit
/// products below 2⁶².
fn surely_below(n: i64, square: u64, from: u16) -> bool {
    let t = i32::from(from) - 1;
    if t <= 0 {
        return false;
    }
    if n <= 0 {
        return true;
    }
    // A light's and a view's unit vectors keep `n` within 2³³ and `‖v‖²` within 2³⁴ (and a
    // little); anything larger is not ruled out.
    let (quarter, sixteenth) = ((n + 3) >> 2, square >> 4);
    if quarter > u32::MAX as i64 || sixteenth > u32::MAX as u64 {
        return false;
    }
    let t2 = t as u32 * t as u32; // t < 2¹⁶: the square fits 32 bits
    fx::wide_mul_u32(quarter as u32, quarter as u32) < fx::wide_mul_u32(t2, sixteenth as u32)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::linear::least_lit_base;
    use crate::xorshift::XorShift;

    fn unit(rng: &mut XorShift) -> Vec3 {
        loop {
            let v = Vec3::new(
                Fx::from_num(rng.signed(1.0)),
                Fx::from_num(rng.signed(1.0)),
                Fx::from_num(rng.signed(1.0)),
            );
            if let Some(u) = v.try_normalize() {
                return u;
            }
        }
    }

    /// The cosine as `Scene::local` forms it, clamped, in raw units: 0 where `v` is zero.
    fn cosine(normal: Vec3, v: Vec3) -> i32 {
        normal
            .cosine_to(v)
            .map_or(0, |s| s.max(Fx::ZERO).min(Fx::ONE).to_bits())
    }

    #[test]
    fn a_highlight_said_to_be_below_its_threshold_is() {
        let mut rng = XorShift(0x51ed_2701_a3b4_c5d6);
        let thresholds = [1u16, 2, 3, 10, 50, 125, 1425, 4096].map(least_lit_base);
        let (mut well_below, mut caught) = (0u32, 0u32);
        for round in 0..400_000 {
            let normal = match round % 4 {
                0 => Vec3::new(Fx::ZERO, Fx::ONE, Fx::ZERO), // a level floor's
                _ => unit(&mut rng),
            };
            let (l, dir) = (unit(&mut rng), unit(&mut rng));
            let v = l - dir;
            let from = thresholds[round % thresholds.len()];
            let s = cosine(normal, v);
            if lit_cosine(normal, v, from).is_none() {
                assert!(s < i32::from(from), "{normal:?} {v:?}: {s} against {from}");
            }
            if s + 8 < i32::from(from) && v.length_squared_wide() > 1 << 28 {
                well_below += 1;
                caught += u32::from(lit_cosine(normal, v, from).is_none());
            }
        }
        // Tight as well as safe: every highlight 8 units and more below its threshold is
        // caught, for a half vector not from nearly opposite directions (`‖v‖ > ¼`).
        assert!(well_below > 100_000, "{well_below}");
        assert_eq!(caught, well_below);
    }

    #[test]
    fn highlights_at_their_threshold_are_not_ruled_out() {
        // Half vectors at cosines within a few units of each threshold, from views and lights
        // that form them: the reflection of the view about the plane across h.
        let mut rng = XorShift(0x0dd5_eed5_1234_abcd);
        let mut near = 0;
        for n in [10u16, 50, 125, 1425, 4096] {
            let from = least_lit_base(n);
            for _ in 0..20_000 {
                let normal = unit(&mut rng);
                let c = (f64::from(from) + f64::from(rng.signed(6.0))) / 65536.0;
                let c = c.min(1.0);
                // h = c·n + √(1 − c²)·p, p a unit vector across n.
                let (nx, ny, nz) = (
                    normal.x.to_num::<f64>(),
                    normal.y.to_num::<f64>(),
                    normal.z.to_num::<f64>(),
                );
                let r = unit(&mut rng);
                let (rx, ry, rz) = (
                    r.x.to_num::<f64>(),
                    r.y.to_num::<f64>(),
                    r.z.to_num::<f64>(),
                );
                let d = rx * nx + ry * ny + rz * nz;
                let (px, py, pz) = (rx - d * nx, ry - d * ny, rz - d * nz);
                let pl = (px * px + py * py + pz * pz).sqrt();
                if pl < 1e-3 {
                    continue;
                }
                let sine = (1.0 - c * c).max(0.0).sqrt();
                let h = [
                    c * nx + sine * px / pl,
                    c * ny + sine * py / pl,
                    c * nz + sine * pz / pl,
                ];
                // A view with dir·h < 0, and l = dir − 2(dir·h)h.
                let w = unit(&mut rng);
                let mut dir = [w.x, w.y, w.z].map(|x| x.to_num::<f64>());
                let mut dh = dir[0] * h[0] + dir[1] * h[1] + dir[2] * h[2];
                if dh > 0.0 {
                    dir = dir.map(|x| -x);
                    dh = -dh;
                }
                let l = [0, 1, 2].map(|i| dir[i] - 2.0 * dh * h[i]);
                let fixed = |a: [f64; 3]| {
                    Vec3::new(Fx::from_num(a[0]), Fx::from_num(a[1]), Fx::from_num(a[2]))
                        .try_normalize()
                };
                let (Some(l), Some(dir)) = (fixed(l), fixed(dir)) else {
                    continue;
                };
                let v = l - dir;
                let s = cosine(normal, v);
                if lit_cosine(normal, v, from).is_none() {
                    assert!(s < i32::from(from), "{normal:?} {v:?}: {s} against {from}");
                }
                near += usize::from((s - i32::from(from)).abs() <= 2);
            }
        }
        assert!(
            near > 10_000,
            "{near} cosines within 2 units of a threshold"
        );
    }
}
