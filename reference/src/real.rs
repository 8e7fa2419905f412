//! [`Real`]: the float type the reference model computes in, `f64` or `f32`.

use core::fmt::Debug;
use core::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub};

/// A float the reference model can run in: `f64` (the default everywhere) or `f32`.
///
/// It has only what the model needs: arithmetic and comparison, the few `libm` functions the
/// model calls, and conversions. Each `f32` operation is an `f32` one (`libm::sqrtf`,
/// `libm::tanf`, …), never a round trip through `f64`, so on a chip with a single-precision
/// FPU the `f32` model runs on it, and on one without, on the compiler's soft-float `f32`
/// routines. The functions come from `libm` on both, so a host renders the same picture as a
/// chip.
///
/// The trait is sealed: `f64` and `f32` are its only types. It is public so that code
/// generic over the model's precision (a firmware renderer, say) can name it.
pub trait Real:
    sealed::Sealed
    + Copy
    + Default
    + Debug
    + PartialEq
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + MulAssign
{
    /// 0.
    const ZERO: Self;
    /// 1.
    const ONE: Self;
    /// 2.
    const TWO: Self;

    /// The nearest value to `x` (exact for every Q16.16 number in `f64`). Meant for
    /// constants and set-up: on a chip without double precision it is a soft-float call,
    /// unless `x` is a constant the compiler folds.
    fn from_f64(x: f64) -> Self;
    /// The value as an `f64` (exact).
    fn to_f64(self) -> f64;
    /// A pixel coordinate or count, exactly.
    fn from_u16(n: u16) -> Self;
    /// The integer part as a `u8`, saturating: negative and NaN give 0, 255 and above 255.
    fn to_u8(self) -> u8;

    /// True unless infinite or NaN.
    fn is_finite(self) -> bool;
    /// `|x|`.
    fn abs(self) -> Self;
    /// `⌊x⌋`.
    fn floor(self) -> Self;
    /// The nearest integer, halfway cases away from zero.
    fn round(self) -> Self;
    /// The remainder of `x / y` with the sign of `x` (C's `fmod`).
    fn fmod(self, y: Self) -> Self;
    /// `√x`, correctly rounded.
    fn sqrt(self) -> Self;
    /// `x^n`.
    fn powi(self, n: u16) -> Self;
    /// Degrees to radians.
    fn to_radians(self) -> Self;
    /// `tan x`, `x` in radians.
    fn tan(self) -> Self;
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for f64 {}
    impl Sealed for f32 {}
}

/// `impl Real` for a float type: the same code for both, each calling its own precision's
/// `libm` functions (`$unary`: those of one argument, after the method each implements).
macro_rules! real {
    ($t:ident: $($method:ident => $unary:path),*; fmod => $fmod:path, pow => $pow:path) => {
        impl Real for $t {
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const TWO: Self = 2.0;

            #[inline]
            fn from_f64(x: f64) -> Self {
                x as $t
            }
            #[inline]
            fn to_f64(self) -> f64 {
                f64::from(self)
            }
            #[inline]
            fn from_u16(n: u16) -> Self {
                $t::from(n)
            }
            #[inline]
            fn to_u8(self) -> u8 {
                self as u8
            }
            #[inline]
            fn is_finite(self) -> bool {
                $t::is_finite(self)
            }
            #[inline]
            fn to_radians(self) -> Self {
                $t::to_radians(self)
            }
            #[inline]
            fn fmod(self, y: Self) -> Self {
                $fmod(self, y)
            }
            #[inline]
            fn powi(self, n: u16) -> Self {
                $pow(self, $t::from(n))
            }
            $(
                #[inline]
                fn $method(self) -> Self {
                    $unary(self)
                }
            )*
        }
    };
}

real!(f64:
    abs => libm::fabs, floor => libm::floor, round => libm::round, sqrt => libm::sqrt,
    tan => libm::tan; fmod => libm::fmod, pow => libm::pow);
real!(f32:
    abs => libm::fabsf, floor => libm::floorf, round => libm::roundf, sqrt => libm::sqrtf,
    tan => libm::tanf; fmod => libm::fmodf, pow => libm::powf);

#[cfg(test)]
mod tests {
    use super::*;

    /// The same checks in both precisions.
    fn behaves<F: Real>() {
        let f = F::from_f64;
        assert_eq!(f(2.5).round(), f(3.0));
        assert_eq!(f(-2.5).round(), f(-3.0));
        assert_eq!(f(-0.5).floor(), f(-1.0));
        assert_eq!(f(-3.0).fmod(F::TWO), f(-1.0));
        assert_eq!(f(9.0).sqrt(), f(3.0));
        assert_eq!(f(0.5).powi(3), f(0.125));
        assert_eq!(f(-1.5).abs(), f(1.5));
        assert!((f(45.0).to_radians().tan() - F::ONE).abs() < f(1e-6));
        assert_eq!(F::from_u16(u16::MAX).to_f64(), 65535.0);
        assert_eq!([f(-1.0), f(254.9), f(300.0)].map(F::to_u8), [0, 254, 255]);
        assert_eq!(f(f64::NAN).to_u8(), 0);
        assert!(!f(f64::INFINITY).is_finite() && F::ZERO.is_finite());
    }

    #[test]
    fn f64_and_f32_do_what_the_model_needs() {
        behaves::<f64>();
        behaves::<f32>();
    }
}
