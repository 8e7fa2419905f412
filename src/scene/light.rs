//! [`Light`]: a point light.

use crate::error::{Error, Quantity, within};
use crate::numbers::fx::Fx;
use crate::numbers::vec3::Vec3;

/// A point light at `position` with an `intensity` between 0 and 4 (1 lights a white surface
/// facing it fully; several lights add up).
///
/// [`Light::new`] checks both. The fields are public, so a light built by hand may hold any
/// value: shading saturates instead of wrapping, and shadows from a light outside ±1024 are
/// tested against every object instead of being culled.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Light {
    /// Where the light is.
    pub position: Vec3,
    /// How strongly it lights a surface facing it, 0 to 4.
    pub intensity: Fx,
}

impl Light {
    /// A light, checked: position within ±[`LIMIT`](crate::LIMIT), intensity within 0..=4.
    pub fn new(position: Vec3, intensity: Fx) -> Result<Self, Error> {
        let position = position.check_range(Quantity::LightPosition)?;
        let intensity = within(
            intensity,
            Fx::ZERO,
            Fx::const_from_int(4),
            Quantity::LightIntensity,
        )?;
        Ok(Light {
            position,
            intensity,
        })
    }

    /// A light whose values the caller promises are valid (those [`Light::new`] checks). For
    /// `const` scenes. Debug builds check the promise.
    #[must_use]
    pub const fn new_unchecked(position: Vec3, intensity: Fx) -> Self {
        debug_assert!(
            position.within_raw(crate::LIMIT.to_bits()),
            "Light::new_unchecked: position outside ±1024"
        );
        debug_assert!(
            intensity.to_bits() >= 0 && intensity.to_bits() <= 4 << 16,
            "Light::new_unchecked: intensity outside 0 to 4"
        );
        Light {
            position,
            intensity,
        }
    }
}
