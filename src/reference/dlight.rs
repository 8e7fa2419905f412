//! [`DLight`] and the shading model: one point light plus an ambient term.

use super::{DHit, DVec3};
use crate::Rgb;

/// A point light: where it is, and how strongly it lights a surface facing it squarely.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DLight {
    /// The light's position.
    pub position: DVec3,
    /// The weight of the diffuse term in the brightness.
    pub intensity: f64,
}

impl DLight {
    /// A light at `position` with `intensity`.
    #[inline]
    #[must_use]
    pub const fn new(position: DVec3, intensity: f64) -> Self {
        DLight {
            position,
            intensity,
        }
    }

    /// The diffuse (Lambert) factor at a hit: `max(0, n · l)`, where `l` is the unit vector
    /// from the hit point towards the light.
    ///
    /// A surface facing away from the light gets 0, and so does a light sitting exactly on the
    /// hit point, where `l` has no direction.
    #[must_use]
    pub fn diffuse(&self, hit: &DHit) -> f64 {
        if self.position == hit.point {
            return 0.0;
        }
        let l = (self.position - hit.point).normalize_or_zero();
        libm::fmax(0.0, hit.normal.dot(l))
    }

    /// The brightness `k = ambient + intensity · diffuse` that scales a surface colour at a hit.
    #[must_use]
    pub fn brightness(&self, ambient: f64, hit: &DHit) -> f64 {
        ambient + self.intensity * self.diffuse(hit)
    }

    /// The colour `colour` shows at `hit`: each channel `c` becomes `min(255, round(c · k))`
    /// with `k` the [`brightness`](Self::brightness).
    ///
    /// `k` is non-negative for a sensible scene, so `round` (half away from zero) rounds half
    /// up; a negative product would become 0.
    #[must_use]
    pub fn shade(&self, ambient: f64, colour: Rgb, hit: &DHit) -> Rgb {
        let k = self.brightness(ambient, hit);
        // `as u8` saturates, so a negative (or NaN) product becomes 0.
        let channel = |c: u8| libm::fmin(255.0, libm::round(f64::from(c) * k)) as u8;
        Rgb::new(channel(colour.r), channel(colour.g), channel(colour.b))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A hit at the origin on a surface facing +y.
    fn floor_hit() -> DHit {
        DHit {
            t: 1.0,
            point: DVec3::ZERO,
            normal: DVec3::Y,
            object: 0,
        }
    }

    #[test]
    fn diffuse_is_the_cosine_of_the_light_angle() {
        let overhead = DLight::new(DVec3::new(0.0, 10.0, 0.0), 1.0);
        assert_eq!(overhead.diffuse(&floor_hit()), 1.0);
        let slanted = DLight::new(DVec3::new(3.0, 4.0, 0.0), 1.0);
        assert!((slanted.diffuse(&floor_hit()) - 0.8).abs() < 1e-15);
        let below = DLight::new(DVec3::new(0.0, -10.0, 0.0), 1.0);
        assert_eq!(below.diffuse(&floor_hit()), 0.0);
        let on_the_point = DLight::new(DVec3::ZERO, 1.0);
        assert_eq!(on_the_point.diffuse(&floor_hit()), 0.0);
    }

    #[test]
    fn shading_scales_rounds_and_clamps_each_channel() {
        let light = DLight::new(DVec3::new(0.0, 10.0, 0.0), 0.5);
        // k = 0.25 + 0.5 · 1 = 0.75: 200 → 150, 3 → 2.25 → 2, 2 → 1.5 → 2 (half up).
        let lit = light.shade(0.25, Rgb::new(200, 3, 2), &floor_hit());
        assert_eq!(lit, Rgb::new(150, 2, 2));
        // k = 1.5: 200 → 300, clamped to 255.
        let bright = DLight::new(DVec3::new(0.0, 10.0, 0.0), 1.0);
        assert_eq!(
            bright.shade(0.5, Rgb::new(200, 100, 0), &floor_hit()),
            Rgb::new(255, 150, 0)
        );
    }

    #[test]
    fn a_surface_facing_away_gets_only_ambient() {
        let below = DLight::new(DVec3::new(0.0, -10.0, 0.0), 1.0);
        assert_eq!(
            below.shade(0.1, Rgb::new(100, 50, 255), &floor_hit()),
            Rgb::new(10, 5, 26)
        );
    }
}
