//! [`DVec3`]: a point or direction in `f64`.

use core::ops::{Add, Div, Mul, Neg, Sub};

/// A point or a direction with three `f64` components, the reference twin of
/// [`Vec3`](crate::Vec3).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DVec3 {
    /// x component.
    pub x: f64,
    /// y component.
    pub y: f64,
    /// z component.
    pub z: f64,
}

impl DVec3 {
    /// The zero vector.
    pub const ZERO: DVec3 = DVec3::new(0.0, 0.0, 0.0);
    /// The unit vector along +x.
    pub const X: DVec3 = DVec3::new(1.0, 0.0, 0.0);
    /// The unit vector along +y.
    pub const Y: DVec3 = DVec3::new(0.0, 1.0, 0.0);
    /// The unit vector along +z.
    pub const Z: DVec3 = DVec3::new(0.0, 0.0, 1.0);

    /// A vector from its three components.
    #[inline]
    #[must_use]
    pub const fn new(x: f64, y: f64, z: f64) -> Self {
        DVec3 { x, y, z }
    }

    /// The dot product `self · o`.
    #[inline]
    #[must_use]
    pub const fn dot(self, o: DVec3) -> f64 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// The cross product `self × o` (right-handed: `X × Y = Z`).
    #[inline]
    #[must_use]
    pub const fn cross(self, o: DVec3) -> DVec3 {
        DVec3::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }

    /// `‖self‖²`.
    #[inline]
    #[must_use]
    pub const fn length_squared(self) -> f64 {
        self.dot(self)
    }

    /// `‖self‖`.
    #[inline]
    #[must_use]
    pub fn length(self) -> f64 {
        libm::sqrt(self.length_squared())
    }

    /// The unit vector `self / ‖self‖`, or `None` if the length is zero or not finite.
    #[must_use]
    pub fn try_normalize(self) -> Option<DVec3> {
        let len = self.length();
        if len > 0.0 && len.is_finite() {
            Some(self / len)
        } else {
            None
        }
    }

    /// The unit vector along `self`, or the zero vector when there is none.
    #[must_use]
    pub fn normalize_or_zero(self) -> DVec3 {
        self.try_normalize().unwrap_or(DVec3::ZERO)
    }

    /// True when all three components are finite.
    #[inline]
    #[must_use]
    pub const fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }
}

impl From<crate::Vec3> for DVec3 {
    /// The exact `f64` value of a Q16.16 vector (every Q16.16 number is an `f64`).
    fn from(v: crate::Vec3) -> DVec3 {
        DVec3::new(
            v.x.to_num::<f64>(),
            v.y.to_num::<f64>(),
            v.z.to_num::<f64>(),
        )
    }
}

impl Add for DVec3 {
    type Output = DVec3;
    #[inline]
    fn add(self, o: DVec3) -> DVec3 {
        DVec3::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl Sub for DVec3 {
    type Output = DVec3;
    #[inline]
    fn sub(self, o: DVec3) -> DVec3 {
        DVec3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl Neg for DVec3 {
    type Output = DVec3;
    #[inline]
    fn neg(self) -> DVec3 {
        DVec3::new(-self.x, -self.y, -self.z)
    }
}

impl Mul<f64> for DVec3 {
    type Output = DVec3;
    #[inline]
    fn mul(self, k: f64) -> DVec3 {
        DVec3::new(self.x * k, self.y * k, self.z * k)
    }
}

impl Div<f64> for DVec3 {
    type Output = DVec3;
    #[inline]
    fn div(self, k: f64) -> DVec3 {
        DVec3::new(self.x / k, self.y / k, self.z / k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cross_follows_the_right_hand_rule() {
        assert_eq!(DVec3::X.cross(DVec3::Y), DVec3::Z);
        assert_eq!(DVec3::Y.cross(DVec3::Z), DVec3::X);
        assert_eq!(DVec3::Y.cross(DVec3::X), -DVec3::Z);
    }

    #[test]
    fn normalize_divides_by_the_length() {
        let v = DVec3::new(3.0, 0.0, -4.0);
        assert_eq!(v.length(), 5.0);
        assert_eq!(v.try_normalize(), Some(DVec3::new(0.6, 0.0, -0.8)));
        assert_eq!(DVec3::ZERO.try_normalize(), None);
        assert_eq!(DVec3::new(f64::NAN, 0.0, 0.0).try_normalize(), None);
        assert_eq!(DVec3::ZERO.normalize_or_zero(), DVec3::ZERO);
    }

    #[test]
    fn converts_q16_16_exactly() {
        let f = crate::Fx::from_num;
        let v = crate::Vec3 {
            x: f(1.5),
            y: f(-0.25),
            z: f(1000.0),
        };
        assert_eq!(DVec3::from(v), DVec3::new(1.5, -0.25, 1000.0));
    }
}
