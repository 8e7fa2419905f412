//! [`DVec3`]: a point or direction in `f64` (or `f32`).

use core::ops::{Add, Div, Mul, Neg, Sub};

use super::Real;

/// A point or a direction with three components, `f64` unless `F` says `f32`: the reference
/// twin of [`Vec3`](fixray::Vec3).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DVec3<F: Real = f64> {
    /// x component.
    pub x: F,
    /// y component.
    pub y: F,
    /// z component.
    pub z: F,
}

impl<F: Real> DVec3<F> {
    /// The zero vector.
    pub const ZERO: Self = DVec3::new(F::ZERO, F::ZERO, F::ZERO);
    /// The unit vector along +x.
    pub const X: Self = DVec3::new(F::ONE, F::ZERO, F::ZERO);
    /// The unit vector along +y.
    pub const Y: Self = DVec3::new(F::ZERO, F::ONE, F::ZERO);
    /// The unit vector along +z.
    pub const Z: Self = DVec3::new(F::ZERO, F::ZERO, F::ONE);

    /// A vector from its three components.
    #[inline]
    #[must_use]
    pub const fn new(x: F, y: F, z: F) -> Self {
        DVec3 { x, y, z }
    }

    /// The dot product `self · o`.
    #[inline]
    #[must_use]
    pub fn dot(self, o: Self) -> F {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// The cross product `self × o` (right-handed: `X × Y = Z`).
    #[inline]
    #[must_use]
    pub fn cross(self, o: Self) -> Self {
        DVec3::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }

    /// `‖self‖²`.
    #[inline]
    #[must_use]
    pub fn length_squared(self) -> F {
        self.dot(self)
    }

    /// `‖self‖`.
    #[inline]
    #[must_use]
    pub fn length(self) -> F {
        self.length_squared().sqrt()
    }

    /// The unit vector `self / ‖self‖`, or `None` if the length is zero or not finite.
    #[must_use]
    pub fn try_normalize(self) -> Option<Self> {
        let len = self.length();
        if len > F::ZERO && len.is_finite() {
            Some(self / len)
        } else {
            None
        }
    }

    /// The unit vector along `self`, or the zero vector when there is none.
    #[must_use]
    pub fn normalize_or_zero(self) -> Self {
        self.try_normalize().unwrap_or(Self::ZERO)
    }

    /// True when all three components are finite.
    #[inline]
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }
}

impl<F: Real> From<fixray::Vec3> for DVec3<F> {
    /// The Q16.16 vector in `F`: exact in `f64` (every Q16.16 number is an `f64`), the
    /// nearest `f32` in `f32`.
    fn from(v: fixray::Vec3) -> Self {
        let f = |x: fixray::Fx| F::from_f64(x.to_num::<f64>());
        DVec3::new(f(v.x), f(v.y), f(v.z))
    }
}

/// A fixed vector's components as `f64`, exactly: for comparing fixray's numbers with the
/// reference's.
pub trait ToF64 {
    /// The components, `[x, y, z]`.
    fn to_f64(self) -> [f64; 3];
}

impl ToF64 for fixray::Vec3 {
    fn to_f64(self) -> [f64; 3] {
        [self.x.to_num(), self.y.to_num(), self.z.to_num()]
    }
}

impl<F: Real> Add for DVec3<F> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        DVec3::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl<F: Real> Sub for DVec3<F> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        DVec3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl<F: Real> Neg for DVec3<F> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        DVec3::new(-self.x, -self.y, -self.z)
    }
}

impl<F: Real> Mul<F> for DVec3<F> {
    type Output = Self;
    #[inline]
    fn mul(self, k: F) -> Self {
        DVec3::new(self.x * k, self.y * k, self.z * k)
    }
}

impl<F: Real> Div<F> for DVec3<F> {
    type Output = Self;
    #[inline]
    fn div(self, k: F) -> Self {
        DVec3::new(self.x / k, self.y / k, self.z / k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cross_follows_the_right_hand_rule() {
        assert_eq!(<DVec3>::X.cross(DVec3::Y), DVec3::Z);
        assert_eq!(<DVec3>::Y.cross(DVec3::Z), DVec3::X);
        assert_eq!(<DVec3>::Y.cross(DVec3::X), -DVec3::Z);
    }

    #[test]
    fn normalize_divides_by_the_length() {
        let v = DVec3::new(3.0, 0.0, -4.0);
        assert_eq!(v.length(), 5.0);
        assert_eq!(v.try_normalize(), Some(DVec3::new(0.6, 0.0, -0.8)));
        assert_eq!(<DVec3>::ZERO.try_normalize(), None);
        assert_eq!(DVec3::new(f64::NAN, 0.0, 0.0).try_normalize(), None);
        assert_eq!(<DVec3>::ZERO.normalize_or_zero(), DVec3::ZERO);
    }

    #[test]
    fn converts_q16_16_exactly() {
        let f = fixray::Fx::from_num;
        let v = fixray::Vec3 {
            x: f(1.5),
            y: f(-0.25),
            z: f(1000.0),
        };
        assert_eq!(DVec3::from(v), DVec3::new(1.5, -0.25, 1000.0));
    }
}
