//! [`DLight`]: a point light.

use super::{DVec3, Real};

/// A point light: where it is, and how strongly it lights a surface facing it squarely.
///
/// An intensity of 1 lights a white matte surface facing it to full white; several lights add
/// up. The fixed renderer accepts 0 to 4.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DLight<F: Real = f64> {
    /// The light's position.
    pub position: DVec3<F>,
    /// The light's strength, multiplying both the diffuse and the highlight terms.
    pub intensity: F,
}

impl<F: Real> DLight<F> {
    /// A light at `position` with `intensity`.
    #[inline]
    #[must_use]
    pub const fn new(position: DVec3<F>, intensity: F) -> Self {
        DLight {
            position,
            intensity,
        }
    }

    /// Seen from `point`: the unit vector `l` towards the light and the distance to it.
    ///
    /// `None` when the light sits exactly on `point`, where `l` has no direction; such a light
    /// lights nothing there.
    #[must_use]
    pub fn seen_from(&self, point: DVec3<F>) -> Option<(DVec3<F>, F)> {
        let to_light = self.position - point;
        Some((to_light.try_normalize()?, to_light.length()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_direction_is_unit_and_the_distance_euclidean() {
        let light = DLight::new(DVec3::new(3.0, 4.0, 0.0), 1.0);
        assert_eq!(
            light.seen_from(DVec3::ZERO),
            Some((DVec3::new(0.6, 0.8, 0.0), 5.0))
        );
        let (l, distance) = light.seen_from(DVec3::new(3.0, 4.0, 12.0)).unwrap();
        assert_eq!((l, distance), (-DVec3::Z, 12.0));
    }

    #[test]
    fn a_light_on_the_point_has_no_direction() {
        let light = DLight::new(DVec3::new(1.0, 2.0, 3.0), 1.0);
        assert_eq!(light.seen_from(DVec3::new(1.0, 2.0, 3.0)), None);
    }
}
