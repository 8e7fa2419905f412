//! The chapter's shoot and shade: the nearest hit along a ray, and the light that reaches the
//! eye from it — lights, shadow rays, highlights and mirror bounces, without recursion.
//!
//! This is the plain path, readable top to bottom: [`Scene::trace`] is `shade(shoot(ray))`
//! for one ray. `render_row` finds the same pixels for a whole row for less (see `accel`),
//! bit for bit.

use crate::geometry::ray::Ray;
use crate::numbers::fx::{self, Fx};
use crate::numbers::vec3::Vec3;
use crate::scene::hit::SceneHit;
use crate::scene::light::Light;
use crate::scene::linear::{Linear, channel_to_linear, powi};
use crate::scene::{Object, Rgb, Scene};

impl<const N: usize, const L: usize> Scene<N, L> {
    /// `shade(shoot(ray))`: the colour of the pixel this ray passes through.
    #[must_use]
    pub fn trace(&self, ray: &Ray) -> Rgb {
        self.shade(ray, self.shoot(ray).as_ref())
    }

    /// Shoots `ray` into the scene and returns the nearest hit; on a tie the object added
    /// first wins.
    #[must_use]
    pub fn shoot(&self, ray: &Ray) -> Option<SceneHit> {
        self.shoot_from(ray, None)
    }

    /// [`Scene::shoot`], ignoring the object the ray leaves from.
    ///
    /// Spheres and planes are convex: a ray leaving one towards a light or along a mirror
    /// direction cannot meet the same surface again, so skipping it replaces the usual small
    /// offset along the normal. That is exact, where an offset in Q16.16 would have to be
    /// larger than the hit point's rounding (which grows with distance) and would detach
    /// shadows from the objects that cast them.
    pub(crate) fn shoot_from(&self, ray: &Ray, leaving: Option<usize>) -> Option<SceneHit> {
        // Hits lie within FAR, so any hit is nearer than MAX; on a tie the first object wins.
        let (mut best, mut nearest) = (Fx::MAX, usize::MAX);
        for (index, object) in self.objects().iter().enumerate() {
            if Some(index) != leaving
                && let Some(t) = object.shape.hit_distance(ray)
                && t < best
            {
                (best, nearest) = (t, index);
            }
        }
        // Distances first; the hit point and normal only for the nearest.
        let hit = self.objects().get(nearest)?.shape.hit_at(ray, best);
        Some(SceneHit {
            hit,
            object: nearest,
        })
    }

    /// The colour seen along `ray` when it has this first hit (from [`Scene::shoot`]): the
    /// background for a miss, otherwise the lit surface plus what its mirror shows (see
    /// [`Material`](crate::Material)).
    #[must_use]
    pub fn shade(&self, ray: &Ray, hit: Option<&SceneHit>) -> Rgb {
        crate::scene::linear::to_rgb(self.radiance(ray, hit.copied()))
    }

    /// The light arriving along `ray`, whose first hit is `hit`, in linear units.
    ///
    /// Mirrors are followed in a loop, not by recursion: each bounce adds its surface's light
    /// times the product of the reflectivities so far, and the ray that leaves the last
    /// allowed bounce sees the background. The stack stays the same size at any depth.
    pub(crate) fn radiance(&self, ray: &Ray, hit: Option<SceneHit>) -> Linear {
        let Some((h, object)) = hit.and_then(|h| Some((h, self.objects().get(h.object)?))) else {
            return self.background().along(ray.dir);
        };
        // The first surface has weight 1: its light is the sum so far, exactly.
        let light = self.local(object, &h, ray.dir);
        if object.material.reflect == Fx::ZERO {
            return light;
        }
        self.reflections(light, ray.dir, &h, object.material.reflect)
    }

    /// [`Scene::radiance`] past a first surface that mirrors: `sum` is that surface's own
    /// light, and the bounces are followed from it. Kept apart so that the common matte pixel
    /// does not pay for the loop's set-up.
    #[inline(never)]
    fn reflections(&self, mut sum: Linear, dir: Vec3, first: &SceneHit, reflect: Fx) -> Linear {
        let mut weight = fx::mul(Fx::ONE, reflect);
        let Some(bounced) = mirror(dir, first.hit.normal) else {
            add(&mut sum, weight, self.background().along(dir));
            return sum;
        };
        let mut ray = Ray::new_unchecked(first.hit.point, bounced);
        let mut leaving = first.object;
        let mut bounce = 0;
        loop {
            if bounce == self.depth() {
                add(&mut sum, weight, self.background().along(ray.dir));
                return sum;
            }
            let hit = self.shoot_from(&ray, Some(leaving));
            bounce += 1;
            let Some((h, object)) = hit.and_then(|h| Some((h, self.objects().get(h.object)?)))
            else {
                add(&mut sum, weight, self.background().along(ray.dir));
                return sum;
            };
            add(&mut sum, weight, self.local(object, &h, ray.dir));
            let reflect = object.material.reflect;
            if reflect == Fx::ZERO {
                return sum;
            }
            weight = fx::mul(weight, reflect);
            let Some(bounced) = mirror(ray.dir, h.hit.normal) else {
                add(&mut sum, weight, self.background().along(ray.dir));
                return sum;
            };
            ray = Ray::new_unchecked(h.hit.point, bounced);
            leaving = h.object;
        }
    }

    /// The surface's own light at a hit: ambient and diffuse times its colour, plus white
    /// highlights, from every light whose shadow ray reaches it.
    fn local(&self, object: &Object, hit: &SceneHit, dir: Vec3) -> Linear {
        let (material, normal) = (&object.material, hit.hit.normal);
        let (mut diffuse, mut specular) = (Fx::ZERO, Fx::ZERO);
        let mut light_up = |index: usize, light: &Light| {
            let to_light = light.position - hit.hit.point;
            let distance_squared = to_light.length_squared_wide();
            let Some(l) = to_light.normalize_with_square(distance_squared) else {
                return;
            };
            let cos = normal.dot_exact(l);
            if cos <= Fx::ZERO {
                return;
            }
            if self.shadows() {
                let shadow_ray = Ray::new_unchecked(hit.hit.point, l);
                if self.occluded(&shadow_ray, distance_squared, hit.object, index) {
                    return;
                }
            }
            diffuse = diffuse.saturating_add(fx::mul_unit(light.intensity, cos));
            if material.specular > Fx::ZERO
                && let Some(half) = (l - dir).try_normalize()
            {
                let s = normal.dot(half).max(Fx::ZERO).min(Fx::ONE);
                specular = specular
                    .saturating_add(fx::mul_fits(light.intensity, powi(s, material.shininess)));
            }
        };
        // One light, the common case on a small screen, without a loop to set up.
        match self.lights() {
            [only] => light_up(0, only),
            lights => {
                for (index, light) in lights.iter().enumerate() {
                    light_up(index, light);
                }
            }
        }
        // Several lights and a specular weight up to 16 can exceed Q16.16's range: the sums
        // saturate rather than wrap.
        let k = self
            .ambient()
            .saturating_add(fx::mul(material.diffuse, diffuse));
        let highlight = if specular > Fx::ZERO {
            fx::mul(material.specular, specular)
        } else {
            Fx::ZERO
        };
        let colour = object.colour_at(hit.hit.point);
        // A channel is at most 1: its product with k needs no saturation.
        let channel = |c: u8| fx::mul_fits(k, channel_to_linear(c)).saturating_add(highlight);
        [channel(colour.r), channel(colour.g), channel(colour.b)]
    }

    /// Whether anything but object `leaving` lies on `ray` closer than `√distance_squared`
    /// (a Q32.32 value): a shadow ray towards light `light`, which stops at the first
    /// occluder and skips the spheres outside its [`ShadowCone`].
    pub(crate) fn occluded(
        &self,
        ray: &Ray,
        distance_squared: u64,
        leaving: usize,
        light: usize,
    ) -> bool {
        let blocks = |object: &Object| {
            object.shape.hit_distance(ray).is_some_and(|t| {
                let t = t.to_bits() as u32;
                fx::wide_mul_u32(t, t) < distance_squared
            })
        };
        let Some(cones) = self.cones().get(light) else {
            // Not one of the scene's lights: no cones to go by.
            return (self.objects().iter().enumerate()).any(|(i, o)| i != leaving && blocks(o));
        };
        for (index, (object, cone)) in self.objects().iter().zip(cones).enumerate() {
            if index != leaving && cone.may_block(ray.dir, distance_squared) && blocks(object) {
                return true;
            }
        }
        false
    }
}

/// `sum += weight · c`; the first surface a ray meets has weight 1, and no product.
fn add(sum: &mut Linear, weight: Fx, c: Linear) {
    for (s, c) in sum.iter_mut().zip(c) {
        *s = s.saturating_add(if weight == Fx::ONE {
            c
        } else {
            fx::mul(weight, c)
        });
    }
}

/// The mirror direction `d − 2(d·n)n`, renormalised; `None` where it has no direction.
///
/// For unit `d` and `n` it is never zero (it has the length of `d`); should rounding ever make
/// it so, the mirror sees the background, as an escaping ray does.
fn mirror(dir: Vec3, normal: Vec3) -> Option<Vec3> {
    let along = normal.scale(dir.dot(normal).saturating_mul_int(2));
    (dir - along).try_normalize()
}
