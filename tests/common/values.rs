//! Hostile values: `f32`s, raw Q16.16 numbers, vectors, directions and colours, ordinary most
//! of the time and chosen to break careless code the rest.

use fixray::{Fx, Rgb, Vec3};

use super::Source;

/// Floats that break careless set-up code: non-finite, huge, tiny, just past the limits.
const NASTY_F32: [f32; 20] = [
    f32::NAN,
    f32::INFINITY,
    f32::NEG_INFINITY,
    f32::MAX,
    f32::MIN,
    f32::MIN_POSITIVE,
    1e-30,
    1e-6,
    -0.0,
    0.0,
    1024.0,
    -1024.0,
    1024.0001,
    -1024.0001,
    f32::EPSILON,
    179.999,
    180.0,
    89.9999,
    4096.0,
    8192.0,
];

/// An `f32` around `typical` in size, hostile one time in `hostility`.
pub fn f32_around(src: &mut impl Source, typical: f32, hostility: u64) -> f32 {
    if src.one_in(hostility) {
        src.pick(&NASTY_F32)
    } else {
        src.uniform(typical)
    }
}

/// Raw Q16.16 values that break careless arithmetic: the ends of the range, single units,
/// just past [`LIMIT`] and [`FAR`].
pub fn fx_any(src: &mut impl Source) -> Fx {
    let raw = match src.below(8) {
        0 => src.pick(&[
            i32::MIN,
            i32::MAX,
            i32::MIN + 1,
            0,
            1,
            -1,
            1 << 16,
            -(1 << 16),
            (1024 << 16) + 1,
            -(1024 << 16) - 1,
            8192 << 16,
            (8192 << 16) + 1,
        ]),
        1 => src.bits() as i32,
        2 => (src.bits() as i32) >> src.below(32),
        _ => return Fx::from_num(src.uniform(40.0)),
    };
    Fx::from_bits(raw)
}

/// A vector of [`fx_any`] components.
pub fn vec_any(src: &mut impl Source) -> Vec3 {
    if src.one_in(8) {
        // All three at an end of the range: the largest sums of products.
        let end = |s: &mut _| {
            if Source::one_in(s, 2) {
                Fx::MAX
            } else {
                Fx::MIN
            }
        };
        return Vec3::new(end(src), end(src), end(src));
    }
    Vec3::new(fx_any(src), fx_any(src), fx_any(src))
}

/// A vector of finite `f32` components around `typical` (never hostile), as fixray rounds them (the caller's `f32`
/// values are converted exactly as [`Vec3::from_f32`] does: `Fx::from_num`).
pub fn vec_within(src: &mut impl Source, typical: f32) -> Vec3 {
    fn c(s: &mut impl Source, typical: f32) -> Fx {
        Fx::from_num(s.uniform(typical).clamp(-1024.0, 1024.0))
    }
    Vec3::new(c(src, typical), c(src, typical), c(src, typical))
}

/// A direction: along an axis, tiny (a few units of 2⁻¹⁶), or random.
pub fn direction(src: &mut impl Source) -> Vec3 {
    match src.below(6) {
        0 => src.pick(&[Vec3::X, Vec3::Y, Vec3::Z, -Vec3::X, -Vec3::Y, -Vec3::Z]),
        1 => Vec3::new(
            Fx::from_bits(src.below(5) as i32 - 2),
            Fx::from_bits(src.below(5) as i32 - 2),
            Fx::from_bits(src.below(5) as i32 - 2),
        ),
        _ => vec_within(src, 1.0),
    }
}

pub(super) fn rgb(src: &mut impl Source) -> Rgb {
    let b = src.bits();
    Rgb::new(b as u8, (b >> 8) as u8, (b >> 16) as u8)
}
