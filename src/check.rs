//! The set-up checks: every value a user hands fixray is converted and range-checked here,
//! once, so that the layers below never meet a value outside their overflow budget.
//!
//! Each check names what it checks with a [`Quantity`], which the [`Error`] carries. The
//! `const` checks serve the `const` constructors (`from_fx`) of `static` scenes; the `f32`
//! ones the constructors a program calls at run time.

use crate::error::{Error, Quantity};
use crate::numbers::fx::{Fx, LIMIT};
use crate::numbers::vec3::Vec3;

/// Refuses a value outside `min ..= max` with [`Error::OutOfRange`] naming `quantity`: the
/// one range check behind every checked constructor.
pub(crate) const fn within(value: Fx, min: Fx, max: Fx, quantity: Quantity) -> Result<Fx, Error> {
    // Raw comparisons, so that `const` constructors can use it.
    if value.to_bits() < min.to_bits() || value.to_bits() > max.to_bits() {
        Err(Error::OutOfRange { quantity, min, max })
    } else {
        Ok(value)
    }
}

/// Refuses a coordinate outside ±[`LIMIT`], the overflow-safe range.
pub(crate) const fn coordinate(value: Fx, quantity: Quantity) -> Result<Fx, Error> {
    within(value, Fx::from_bits(-LIMIT.to_bits()), LIMIT, quantity)
}

/// Refuses a point with a coordinate outside ±[`LIMIT`].
pub(crate) const fn point(v: Vec3, quantity: Quantity) -> Result<Vec3, Error> {
    // `?` is not allowed in a `const fn`.
    if let Err(e) = coordinate(v.x, quantity) {
        return Err(e);
    }
    if let Err(e) = coordinate(v.y, quantity) {
        return Err(e);
    }
    if let Err(e) = coordinate(v.z, quantity) {
        return Err(e);
    }
    Ok(v)
}

/// A direction: `v` normalised, refusing the zero vector with [`Error::ZeroVector`].
pub(crate) const fn direction(v: Vec3, quantity: Quantity) -> Result<Vec3, Error> {
    match v.try_normalize() {
        Some(unit) => Ok(unit),
        None => Err(Error::ZeroVector { quantity }),
    }
}

/// Converts an `f32` to [`Fx`], refusing NaN and infinities ([`Error::NotFinite`]) and values
/// that round to outside `min ..= max` ([`Error::OutOfRange`]).
///
/// The bounds (within ±2¹⁴) apply to the rounded value, as every later check sees it: a tiny
/// positive value that rounds to zero is below a `min` of [`Fx::DELTA`].
pub(crate) fn f32_within(value: f32, min: Fx, max: Fx, quantity: Quantity) -> Result<Fx, Error> {
    if !value.is_finite() {
        return Err(Error::NotFinite { quantity });
    }
    // Values beyond ±2¹⁴ are past every range fixray checks (bounds are within ±1024) and
    // refused before they could overflow the conversion. Below that every f32 converts, and
    // the bounds are checked on the rounded value.
    const BEYOND: f32 = 16_384.0;
    if !(value > -BEYOND && value < BEYOND) {
        return Err(Error::OutOfRange { quantity, min, max });
    }
    within(Fx::from_num(value), min, max, quantity)
}

/// An `f32` coordinate, converted: finite and within ±[`LIMIT`].
pub(crate) fn f32_coordinate(value: f32, quantity: Quantity) -> Result<Fx, Error> {
    f32_within(value, -LIMIT, LIMIT, quantity)
}

/// An `f32` point, converted: each coordinate finite and within ±[`LIMIT`].
pub(crate) fn f32_point(v: [f32; 3], quantity: Quantity) -> Result<Vec3, Error> {
    Ok(Vec3::new(
        f32_coordinate(v[0], quantity)?,
        f32_coordinate(v[1], quantity)?,
        f32_coordinate(v[2], quantity)?,
    ))
}

/// `const` constructors return `Result`, and `Result::unwrap` cannot run in a `const`: this
/// is its `const` form, for fixray's own scenes, where a refused value is a compile error.
#[cfg(feature = "demo")]
pub(crate) const fn valid<T: Copy>(result: Result<T, Error>) -> T {
    match result {
        Ok(value) => value,
        Err(_) => panic!("a constant scene value is out of range"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn f32_conversion_is_checked() {
        let q = Quantity::LightPosition;
        let outside = Err(Error::OutOfRange {
            quantity: q,
            min: -LIMIT,
            max: LIMIT,
        });
        assert_eq!(
            f32_coordinate(f32::NAN, q),
            Err(Error::NotFinite { quantity: q })
        );
        assert_eq!(
            f32_coordinate(f32::NEG_INFINITY, q),
            Err(Error::NotFinite { quantity: q })
        );
        assert_eq!(f32_coordinate(1024.5, q), outside);
        // The next f32 past the limit, and one far past it that Q16.16 cannot hold.
        assert_eq!(
            f32_coordinate(f32::from_bits(1024f32.to_bits() + 1), q),
            outside
        );
        assert_eq!(f32_coordinate(-1e30, q), outside);
        assert_eq!(f32_coordinate(1024.0, q), Ok(Fx::from_num(1024)));
        assert_eq!(f32_coordinate(-1024.0, q), Ok(Fx::from_num(-1024)));
        assert_eq!(
            f32_point([1.5, -4.0, f32::NAN], q),
            Err(Error::NotFinite { quantity: q })
        );
    }

    #[test]
    fn f32_bounds_apply_to_the_rounded_value() {
        let q = Quantity::ScreenDistance;
        let positive = |v: f32| f32_within(v, Fx::DELTA, LIMIT, q);
        let below = Err(Error::OutOfRange {
            quantity: q,
            min: Fx::DELTA,
            max: LIMIT,
        });
        // 0.6 of a step rounds up to one step; 0.4 of a step rounds to zero.
        assert_eq!(positive(0.6 / 65_536.0), Ok(Fx::DELTA));
        assert_eq!(positive(0.4 / 65_536.0), below);
        assert_eq!(positive(0.0), below);
        assert_eq!(positive(-2.0), below);
        assert_eq!(positive(1e9), below);
    }

    #[test]
    fn points_and_directions_are_checked() {
        let q = Quantity::PlaneNormal;
        let far = Vec3::new(Fx::ZERO, LIMIT + Fx::DELTA, Fx::ZERO);
        assert!(point(far, q).is_err());
        assert_eq!(point(Vec3::Y, q), Ok(Vec3::Y));
        assert_eq!(
            direction(Vec3::ZERO, q),
            Err(Error::ZeroVector { quantity: q })
        );
        assert_eq!(direction(Vec3::from_ints(0, 3, 0), q), Ok(Vec3::Y));
    }
}
