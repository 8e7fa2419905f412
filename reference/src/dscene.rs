//! [`DScene`]: the objects, the lights, and the chapter's `shoot`.

use super::{DHit, DLight, DObject, DRay, DShape, Real};
use fixray::{Background, Rgb};

/// A scene of up to `N` objects and `L` point lights, with an ambient term, a background,
/// shadows on or off and a limit on mirror bounces, all in fixed storage.
///
/// Usually built from the fixed renderer's scene with [`DScene::from_scene`], so that both
/// models draw the same thing. Shading is in [`DScene::radiance`].
#[derive(Debug, Clone)]
pub struct DScene<const N: usize, const L: usize = 4, F: Real = f64> {
    objects: heapless::Vec<DObject<F>, N>,
    lights: heapless::Vec<DLight<F>, L>,
    ambient: F,
    background: Background,
    shadows: bool,
    depth: u8,
}

impl<const N: usize, const L: usize, F: Real> DScene<N, L, F> {
    /// Mirror bounces followed by a new scene, as in the fixed renderer.
    pub const DEFAULT_DEPTH: u8 = 4;

    /// An empty, unlit scene: every ray shows `background`, and objects added get only
    /// `ambient` until lights are added. Shadows are on and mirrors follow up to
    /// [`DEFAULT_DEPTH`](Self::DEFAULT_DEPTH) bounces.
    #[must_use]
    pub const fn new(ambient: F, background: Background) -> Self {
        DScene {
            objects: heapless::Vec::new(),
            lights: heapless::Vec::new(),
            ambient,
            background,
            shadows: true,
            depth: Self::DEFAULT_DEPTH,
        }
    }

    /// Adds an object after those already in the scene; a full scene hands it back, like
    /// `heapless::Vec::push`.
    pub fn push(&mut self, object: DObject<F>) -> Result<(), DObject<F>> {
        self.objects.push(object)
    }

    /// Adds a light; a scene already holding `L` hands it back.
    pub fn push_light(&mut self, light: DLight<F>) -> Result<(), DLight<F>> {
        self.lights.push(light)
    }

    /// Turns shadow rays on or off.
    pub fn set_shadows(&mut self, on: bool) {
        self.shadows = on;
    }

    /// Sets how many mirror bounces are followed (see [`DScene::radiance`]).
    ///
    /// Unlike the fixed renderer, which caps this at 16 to bound its running time, any `u8`
    /// is kept.
    pub fn set_depth(&mut self, bounces: u8) {
        self.depth = bounces;
    }

    /// The objects, in the order they were added; a hit's `object` indexes this slice.
    #[inline]
    #[must_use]
    pub fn objects(&self) -> &[DObject<F>] {
        &self.objects
    }

    /// The lights, in the order they were added.
    #[inline]
    #[must_use]
    pub fn lights(&self) -> &[DLight<F>] {
        &self.lights
    }

    /// The ambient brightness every surface gets, lit or not.
    #[inline]
    #[must_use]
    pub const fn ambient(&self) -> F {
        self.ambient
    }

    /// What rays that hit nothing see.
    #[inline]
    #[must_use]
    pub const fn background(&self) -> Background {
        self.background
    }

    /// Whether lights are tested for shadows.
    #[inline]
    #[must_use]
    pub const fn shadows(&self) -> bool {
        self.shadows
    }

    /// How many mirror bounces are followed.
    #[inline]
    #[must_use]
    pub const fn depth(&self) -> u8 {
        self.depth
    }

    /// Shoots `ray` into the scene and returns the first hit: the one with the smallest `t`.
    ///
    /// On a tie the object added earlier wins. The hit's `object` is the index of the object
    /// in [`objects`](Self::objects).
    #[must_use]
    pub fn shoot(&self, ray: &DRay<F>) -> Option<DHit<F>> {
        self.shoot_from(ray, None)
    }

    /// [`shoot`](Self::shoot) among every object but `leaving`: the object a mirror ray
    /// leaves from. The twin of fixray's (crate-private) `Scene::shoot_from`.
    ///
    /// Planes and spheres are convex, so a ray leaving one outward cannot meet it again;
    /// leaving it out replaces nudging the origin off the surface.
    pub(super) fn shoot_from(&self, ray: &DRay<F>, leaving: Option<usize>) -> Option<DHit<F>> {
        self.nearest(|index, shape| {
            if Some(index) == leaving {
                None
            } else {
                shape.intersect(ray)
            }
        })
    }

    /// The hit with the smallest `t` among `hit(index, shape)` over the objects, its `object`
    /// set to the index; on a tie the object added earlier wins.
    fn nearest(&self, hit: impl Fn(usize, &DShape<F>) -> Option<DHit<F>>) -> Option<DHit<F>> {
        self.objects
            .iter()
            .enumerate()
            .filter_map(|(index, object)| {
                Some(DHit {
                    object: index,
                    ..hit(index, &object.shape)?
                })
            })
            // `min_by` would keep the last of equals; the earlier object must win a tie.
            .fold(None, |nearest: Option<DHit<F>>, hit| match nearest {
                Some(best) if best.t <= hit.t => Some(best),
                _ => Some(hit),
            })
    }

    /// [`shoot`](Self::shoot) for a ray that has just crossed the surface of object `inside`,
    /// a sphere, inwards (or been mirrored on its inner side): that sphere is met where the
    /// ray leaves it ([`DSphere::exit`](super::DSphere::exit)), every other object as usual.
    /// If `inside` is not a sphere it is skipped, as by [`shoot_from`](Self::shoot_from).
    pub(super) fn shoot_inside(&self, ray: &DRay<F>, inside: usize) -> Option<DHit<F>> {
        self.nearest(|index, shape| match shape {
            DShape::Sphere(sphere) if index == inside => Some(sphere.exit(ray)),
            _ if index == inside => None,
            shape => shape.intersect(ray),
        })
    }

    /// The colour of the pixel whose ray is `ray` and whose first hit is `hit` (the result of
    /// [`shoot`](Self::shoot)): [`radiance`](Self::radiance), clamped and rounded to 8 bits.
    #[must_use]
    pub fn shade(&self, ray: &DRay<F>, hit: Option<&DHit<F>>) -> Rgb {
        super::dcolour::to_rgb(self.radiance(ray, hit))
    }

    /// [`shoot`](Self::shoot) then [`shade`](Self::shade): the first hit, if any, and the
    /// pixel's colour.
    #[must_use]
    pub fn trace(&self, ray: &DRay<F>) -> (Option<DHit<F>>, Rgb) {
        let hit = self.shoot(ray);
        let colour = self.shade(ray, hit.as_ref());
        (hit, colour)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{DPlane, DSphere, DVec3};

    const RED: Rgb = Rgb::new(200, 0, 0);
    const GREEN: Rgb = Rgb::new(0, 200, 0);
    const SKY: Rgb = Rgb::new(10, 20, 30);

    fn sphere(z: f64, colour: Rgb) -> DObject {
        let shape = DSphere::new(DVec3::new(0.0, 0.0, z), 1.0).unwrap();
        DObject::matte(shape.into(), colour)
    }

    /// Ambient 1 and no lights: every surface shows exactly its colour.
    fn scene(objects: &[DObject]) -> DScene<4> {
        let mut s = DScene::new(1.0, Background::plain(SKY));
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
        let s = scene(&[sphere(-5.0, GREEN), sphere(-5.0, RED), sphere(-5.0, SKY)]);
        assert_eq!(s.shoot(&down_z()).map(|h| h.object), Some(0));
        assert_eq!(s.trace(&down_z()).1, GREEN);
        assert_eq!(s.shoot_from(&down_z(), Some(0)).map(|h| h.object), Some(1));
    }

    #[test]
    fn a_miss_shows_the_background() {
        let s = scene(&[sphere(5.0, RED)]);
        assert_eq!(s.trace(&down_z()), (None, SKY));
        let empty = scene(&[]);
        assert_eq!(empty.trace(&down_z()), (None, SKY));
    }

    #[test]
    fn a_rectangle_lets_rays_past_its_edges() {
        // A red square −1 ≤ x, y ≤ 1 at z = −3 in front of a green ball.
        let square = DPlane::new(DVec3::new(0.0, 0.0, -3.0), DVec3::Z)
            .unwrap()
            .bounded([-1.0, -1.0], [1.0, 1.0])
            .unwrap();
        let ball = DSphere::new(DVec3::new(2.0, 0.0, -10.0), 1.0).unwrap();
        let s = scene(&[
            DObject::matte(square.into(), RED),
            DObject::matte(ball.into(), GREEN),
        ]);
        assert_eq!(s.trace(&down_z()).1, RED);
        // Towards the ball's centre the ray meets z = −3 at x = 0.6: still the square.
        let to_ball = DRay::new(DVec3::ZERO, DVec3::new(2.0, 0.0, -10.0)).unwrap();
        assert_eq!(s.trace(&to_ball).1, RED);
        // From x = 2 the plane is met at x = 2, outside the square: the ball behind shows.
        let beside = DRay::new(DVec3::new(2.0, 0.0, 0.0), -DVec3::Z).unwrap();
        assert_eq!(s.trace(&beside).0.map(|h| (h.object, h.t)), Some((1, 9.0)));
    }

    #[test]
    fn full_scenes_hand_the_extra_back() {
        let mut s: DScene<1, 1> = DScene::new(0.0, SKY.into());
        let floor = DPlane::new(DVec3::new(0.0, -1.0, 0.0), DVec3::Y).unwrap();
        assert_eq!(s.push(DObject::matte(floor.into(), RED)), Ok(()));
        let extra = DObject::matte(floor.into(), GREEN);
        assert_eq!(s.push(extra), Err(extra));
        assert_eq!(s.objects().len(), 1);
        let light = DLight::new(DVec3::ZERO, 1.0);
        assert_eq!(s.push_light(light), Ok(()));
        assert_eq!(s.push_light(light), Err(light));
        assert_eq!(s.lights(), [light]);
    }

    #[test]
    fn a_foreign_hit_shades_as_background() {
        let s = scene(&[sphere(-5.0, RED)]);
        let mut hit = s.shoot(&down_z()).unwrap();
        hit.object = 3;
        assert_eq!(s.shade(&down_z(), Some(&hit)), SKY);
    }
}
