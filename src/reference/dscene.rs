//! [`DScene`]: the objects, the light, and the chapter's `shoot` and `shade`.

use super::{DHit, DLight, DObject, DRay};
use crate::Rgb;

/// A scene of up to `N` objects lit by one point light, in fixed storage.
///
/// Usually built from the fixed renderer's scene with
/// [`DScene::from_scene`](DScene::from_scene), so that both models draw the same thing.
#[derive(Debug, Clone)]
pub struct DScene<const N: usize> {
    objects: heapless::Vec<DObject, N>,
    light: DLight,
    ambient: f64,
    background: Rgb,
}

impl<const N: usize> DScene<N> {
    /// An empty scene: nothing in it, so every ray shows `background`.
    #[must_use]
    pub const fn new(light: DLight, ambient: f64, background: Rgb) -> Self {
        DScene {
            objects: heapless::Vec::new(),
            light,
            ambient,
            background,
        }
    }

    /// Adds an object after those already in the scene; a full scene hands it back.
    pub fn push(&mut self, object: DObject) -> Result<(), DObject> {
        self.objects.push(object)
    }

    /// The objects, in the order they were added; a hit's `object` indexes this slice.
    #[inline]
    #[must_use]
    pub fn objects(&self) -> &[DObject] {
        &self.objects
    }

    /// The point light.
    #[inline]
    #[must_use]
    pub const fn light(&self) -> DLight {
        self.light
    }

    /// The ambient brightness added to every lit surface.
    #[inline]
    #[must_use]
    pub const fn ambient(&self) -> f64 {
        self.ambient
    }

    /// The colour of a pixel whose ray hits nothing.
    #[inline]
    #[must_use]
    pub const fn background(&self) -> Rgb {
        self.background
    }

    /// Shoots `ray` into the scene and returns the first hit: the one with the smallest `t`.
    ///
    /// On a tie the object added earlier wins. The hit's `object` is the index of the object
    /// in [`objects`](Self::objects).
    #[must_use]
    pub fn shoot(&self, ray: &DRay) -> Option<DHit> {
        let mut nearest: Option<DHit> = None;
        for (index, object) in self.objects.iter().enumerate() {
            let Some(hit) = object.shape.intersect(ray) else {
                continue;
            };
            if nearest.is_none_or(|best| hit.t < best.t) {
                nearest = Some(DHit {
                    object: index,
                    ..hit
                });
            }
        }
        nearest
    }

    /// The colour a pixel shows for the result of [`shoot`](Self::shoot).
    ///
    /// A miss shows the background. A hit shows its object's colour scaled by
    /// `ambient + intensity · max(0, n · l)` (see [`DLight::shade`]). A hit whose `object` is
    /// not in this scene is treated as a miss.
    #[must_use]
    pub fn shade(&self, hit: Option<&DHit>) -> Rgb {
        let Some(hit) = hit else {
            return self.background;
        };
        match self.objects.get(hit.object) {
            Some(object) => self.light.shade(self.ambient, object.colour, hit),
            None => self.background,
        }
    }

    /// [`shoot`](Self::shoot) then [`shade`](Self::shade): the hit, if any, and the pixel's
    /// colour.
    #[must_use]
    pub fn trace(&self, ray: &DRay) -> (Option<DHit>, Rgb) {
        let hit = self.shoot(ray);
        let colour = self.shade(hit.as_ref());
        (hit, colour)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::{DPlane, DSphere, DVec3};

    const RED: Rgb = Rgb::new(200, 0, 0);
    const GREEN: Rgb = Rgb::new(0, 200, 0);
    const SKY: Rgb = Rgb::new(10, 20, 30);

    fn sphere(z: f64, colour: Rgb) -> DObject {
        let shape = DSphere::new(DVec3::new(0.0, 0.0, z), 1.0).unwrap();
        DObject::new(shape.into(), colour)
    }

    fn scene(objects: &[DObject]) -> DScene<4> {
        // A light at the eye, so a surface facing the eye gets k = 0.5 + 0.5 · 1 = 1.
        let mut s = DScene::new(DLight::new(DVec3::ZERO, 0.5), 0.5, SKY);
        for o in objects {
            s.push(*o).unwrap();
        }
        s
    }

    fn down_z() -> DRay {
        DRay::new(DVec3::ZERO, -DVec3::Z).unwrap()
    }

    #[test]
    fn shoot_keeps_the_nearest_hit() {
        let s = scene(&[sphere(-10.0, GREEN), sphere(-5.0, RED)]);
        let hit = s.shoot(&down_z()).unwrap();
        assert_eq!((hit.t, hit.object), (4.0, 1));
        assert_eq!(s.trace(&down_z()), (Some(hit), RED));
    }

    #[test]
    fn on_a_tie_the_earlier_object_wins() {
        let s = scene(&[sphere(-5.0, GREEN), sphere(-5.0, RED)]);
        assert_eq!(s.shoot(&down_z()).map(|h| h.object), Some(0));
        assert_eq!(s.trace(&down_z()).1, GREEN);
    }

    #[test]
    fn a_miss_shows_the_background() {
        let s = scene(&[sphere(5.0, RED)]);
        assert_eq!(s.trace(&down_z()), (None, SKY));
        let empty = scene(&[]);
        assert_eq!(empty.trace(&down_z()), (None, SKY));
    }

    #[test]
    fn a_full_scene_hands_the_object_back() {
        let mut s: DScene<1> = DScene::new(DLight::new(DVec3::ZERO, 1.0), 0.0, SKY);
        let floor = DPlane::new(DVec3::new(0.0, -1.0, 0.0), DVec3::Y).unwrap();
        assert_eq!(s.push(DObject::new(floor.into(), RED)), Ok(()));
        let extra = DObject::new(floor.into(), GREEN);
        assert_eq!(s.push(extra), Err(extra));
        assert_eq!(s.objects().len(), 1);
    }

    #[test]
    fn a_foreign_hit_shades_as_background() {
        let s = scene(&[sphere(-5.0, RED)]);
        let mut hit = s.shoot(&down_z()).unwrap();
        hit.object = 3;
        assert_eq!(s.shade(Some(&hit)), SKY);
    }
}
