//! [`Light`]: a point light.

use crate::check;
use crate::error::{Error, Quantity};
use crate::numbers::fx::Fx;
use crate::numbers::vec3::Vec3;

/// A point light at a position within ±[`LIMIT`](crate::LIMIT), with an intensity between
/// 0 and 4 (1 lights a white surface facing it fully; several lights add up).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Light {
    pub(crate) position: Vec3,
    pub(crate) intensity: Fx,
}

impl Light {
    /// A light at `position` of `intensity`, both checked.
    ///
    /// ```
    /// use fixray::{Error, Fx, Light, Quantity};
    /// let sun = Light::new([-20.0, 20.0, 20.0], 0.8)?;
    /// assert_eq!(sun.intensity(), Fx::from_num(0.8));
    /// assert_eq!(
    ///     Light::new([0.0; 3], 5.0),
    ///     Err(Error::OutOfRange { quantity: Quantity::LightIntensity, min: Fx::ZERO, max: Fx::from_num(4) })
    /// );
    /// # Ok::<(), Error>(())
    /// ```
    pub fn new(position: [f32; 3], intensity: f32) -> Result<Self, Error> {
        Light::from_fx(
            check::f32_point(position, Quantity::LightPosition)?,
            check::f32_within(intensity, Fx::ZERO, MAX_INTENSITY, Quantity::LightIntensity)?,
        )
    }

    /// [`Light::new`] in fixed point, for `const` and `static` scenes: the same checks, at
    /// compile time when the values are constants.
    pub const fn from_fx(position: Vec3, intensity: Fx) -> Result<Self, Error> {
        let position = match check::point(position, Quantity::LightPosition) {
            Ok(position) => position,
            Err(e) => return Err(e),
        };
        match check::within(intensity, Fx::ZERO, MAX_INTENSITY, Quantity::LightIntensity) {
            Ok(intensity) => Ok(Light {
                position,
                intensity,
            }),
            Err(e) => Err(e),
        }
    }

    /// Where the light is.
    #[must_use]
    pub const fn position(&self) -> Vec3 {
        self.position
    }

    /// How strongly it lights a surface facing it, 0 to 4.
    #[must_use]
    pub const fn intensity(&self) -> Fx {
        self.intensity
    }
}

/// The brightest light: four lights' worth of white, so that a few of them still sum within
/// the shading's budget.
const MAX_INTENSITY: Fx = Fx::const_from_int(4);
