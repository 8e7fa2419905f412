//! The first surface's light for the rows: [`Scene::shade`] with each shadow ray trying only
//! the objects that can block it, and a highlight formed only where it is not 0.
//!
//! A shadow ray towards light `i` from object `j` tries only the objects that can shadow `j`
//! from `i` (`accel/shadowers.rs`), and of those, on a plane, only the ones that can shadow
//! the row's hits on it (`accel/shadow_rows.rs`); it skips a sphere whose cone from the light
//! it lies outside (`accel/shadow_cone.rs`). Every set holds each object that can block the ray, and
//! a cone each ray that can meet its sphere, so the answer is the brute-force one. A highlight
//! whose cosine must come out below the material's least lit one (`render/highlight.rs`), or
//! does, is 0 without its half vector or its power. So a pixel here is bit for bit the plain path's.

use crate::geometry::Shape;
use crate::geometry::ray::Ray;
use crate::numbers::fx::{self, Fx};
use crate::numbers::vec3::Vec3;
use crate::render::accel::shadow_sweep;
use crate::render::highlight::lit_cosine;
use crate::render::trace::{Surface, highlight_normal, scaled_channel};
use crate::scene::hit::SceneHit;
use crate::scene::light::Light;
use crate::scene::linear::{Linear, powi, rgb_of};
use crate::scene::{Material, Object, Rgb, Scene};

impl<const N: usize, const L: usize> Scene<N, L> {
    /// [`Scene::shade`] for a ray from the eye whose first hit is `hit`, where a hit on a plane
    /// need only try the objects of `plane_shadowers[light]` (bit `i` for object `i`) for its
    /// shadow rays towards each light.
    // In line, in the row walk's loop over a run's rays (its one caller): called, it takes
    // the hit by value through memory and walks the lights out of line, about a tenth more
    // instructions a frame on every chip.
    pub(crate) fn pixel_among(
        &self,
        ray: &Ray,
        hit: Option<SceneHit>,
        plane_shadowers: &[u32; L],
    ) -> Rgb {
        let Some((h, object)) = hit.and_then(|h| Some((h, self.objects().get(h.object)?))) else {
            return self.shade(ray, None);
        };
        let at = Surface::of(&h);
        let sets = match object.shape {
            Shape::Plane(_) => plane_shadowers,
            Shape::Sphere(_) => &[!0; L],
        };
        let material = &object.material;
        if material.is_plain_matte() {
            let diffuse = (self.lights().iter().enumerate()).fold(Fx::ZERO, |sum, (i, light)| {
                match self.reaches_among(i, light, &at, self.shadow_set(i, sets)) {
                    Some((_, cos)) => sum.saturating_add(fx::mul_unit(light.intensity, cos)),
                    None => sum,
                }
            });
            return self.matte_pixel_within_one(material, diffuse, object.colour_at(at.point));
        }
        let light = self.local_among(object, &at, ray.dir, sets);
        if !material.sends_rays() {
            return rgb_of(light);
        }
        self.beyond(light, ray.dir, &h)
    }

    /// The pixel whose first surface `first`, met along `dir`, mirrors or refracts and has its
    /// own light `light`: the plain path's tree of secondary rays, each hit lit as
    /// [`Scene::local_among`] lights it.
    // Out of line: the tree's list of waiting rays (17 of them) stays off the row's stack
    // frame, which every pixel's call goes through, and takes stack only while a mirror or
    // glass pixel is followed.
    #[inline(never)]
    fn beyond(&self, light: Linear, dir: Vec3, first: &SceneHit) -> Rgb {
        let local = |object: &Object, at: &Surface, view: Vec3| {
            self.local_among(object, at, view, &[!0; L])
        };
        rgb_of(self.followed(light, dir, first, &local))
    }

    /// `Scene::local`: the light of `object` at `at` seen along `view`, whose shadow ray
    /// towards light `i` tries only the objects of `sets[i]`, and whose highlights are formed
    /// only where they are not 0.
    fn local_among(&self, object: &Object, at: &Surface, view: Vec3, sets: &[u32; L]) -> Linear {
        let material = &object.material;
        let (mut diffuse, mut specular) = (Fx::ZERO, Fx::ZERO);
        let normal = highlight_normal(material, at.normal);
        for (i, light) in self.lights().iter().enumerate() {
            let Some((l, cos)) = self.reaches_among(i, light, at, self.shadow_set(i, sets)) else {
                continue;
            };
            diffuse = diffuse.saturating_add(fx::mul_unit(light.intensity, cos));
            if material.specular > Fx::ZERO {
                let term = highlight_if_lit(material, light, normal, l, view);
                specular = specular.saturating_add(term);
            }
        }
        let lit = self.lit(material, diffuse, object.colour_at(at.point));
        self.with_highlight(lit, material, specular)
    }

    /// [`Scene::reaches`] for light `light_index` (`light`), whose shadow ray tries only the
    /// objects of `among` (see [`Scene::occluded_among`]), and none where `among` is `None`
    /// (shadows off, or nothing that can block it).
    // Out of line: every lit pixel's light goes through it, for the first surface and the
    // matte runs alike, and in line it crowds their loops.
    #[inline(never)]
    pub(crate) fn reaches_among(
        &self,
        light_index: usize,
        light: &Light,
        at: &Surface,
        among: Option<u32>,
    ) -> Option<(Vec3, Fx)> {
        let towards = self.towards_light(light, at)?;
        if let Some(among) = among
            && self.occluded_among(
                at.point,
                towards.l,
                towards.distance_squared,
                at.index,
                light_index,
                among,
            )
        {
            return None;
        }
        Some((towards.l, towards.cos))
    }

    /// [`Scene::occluded`] for a shadow ray towards light `light`, made only for the objects
    /// that come to the whole test: it tries only the objects that can shadow object
    /// `leaving` from that light (`Scene::shadowers`) and are in `among` (bit `i` for object
    /// `i`, which must hold every object that can block the ray in scenes of up to 32
    /// objects), and skips the spheres outside their [`ShadowCone`](crate::render::accel::shadow_cone::ShadowCone).
    pub(crate) fn occluded_among(
        &self,
        from: Vec3,
        dir: Vec3,
        distance_squared: u64,
        leaving: usize,
        light: usize,
        among: u32,
    ) -> bool {
        let Some(cones) = self.shadow_caches().cones(light) else {
            // Not one of the scene's lights: no cones to go by.
            return self.occluded(from, dir, distance_squared, leaving);
        };
        let objects = self.objects();
        let may_block = |index: usize| {
            let (Some(object), Some(cone)) = (objects.get(index), cones.get(index)) else {
                return false;
            };
            index != leaving
                && cone.may_block(dir, distance_squared)
                && blocks(object, from, dir, distance_squared)
        };
        match self.walked(leaving, light) {
            // Only the objects that can shadow the one the ray leaves, most often none or one:
            // walked by their bits.
            Some(set) => {
                let mut rest = set & among;
                while rest != 0 {
                    let index = rest.trailing_zeros() as usize;
                    rest &= rest - 1;
                    if may_block(index) {
                        return true;
                    }
                }
                false
            }
            // In scenes of more than 32 objects, those the light's sweep leaves.
            None => match self.shadow_caches().sweep(light, objects.len()) {
                Some(sweep) if N > 32 => shadow_sweep::any(sweep, dir, may_block),
                _ => (0..objects.len()).any(may_block),
            },
        }
    }

    /// The objects (bit `i` for object `i`) that [`Scene::occluded_among`] walks for a shadow
    /// ray from object `leaving` towards light `light`, before they are met with its `among`:
    /// those that can shadow `leaving` from it. `None` where every object is tried: scenes
    /// of more than 32 objects, or a light that is not the scene's.
    pub(crate) fn walked(&self, leaving: usize, light: usize) -> Option<u32> {
        let set = self.shadow_caches().shadowers(light, leaving);
        set.filter(|_| self.objects().len() <= 32)
    }

    /// The objects a shadow ray towards light `light_index` tries, `sets[light_index]`, or
    /// `None` where shadows are off.
    fn shadow_set(&self, light_index: usize, sets: &[u32; L]) -> Option<u32> {
        self.shadows()
            .then(|| sets.get(light_index).copied().unwrap_or(!0))
    }

    /// [`Scene::matte_pixel`] for the loops of matte pixels: up to a brightness of 1, the
    /// common case, no channel passes 255 (255·2¹⁶ + 2¹⁵ is below 256·2¹⁶), so there is
    /// nothing to hold.
    // In line: the last step of every matte pixel, in the loops of matte runs, where a call
    // would move the loop's values out of the registers it clobbers.
    #[inline(always)]
    pub(crate) fn matte_pixel_within_one(
        &self,
        material: &Material,
        diffuse: Fx,
        colour: Rgb,
    ) -> Rgb {
        let k = self.brightness(material, diffuse).to_bits();
        // Above 1 (and below 0, which as a `u32` is above too) the plain form holds them.
        if (k as u32) > 1 << 16 {
            return self.matte_pixel(material, diffuse, colour);
        }
        let channel = |c: u8| scaled_channel(c, k as u32) as u8;
        Rgb::new(channel(colour.r), channel(colour.g), channel(colour.b))
    }
}

/// [`highlight`], 0 without its root or its power where its cosine must come out below the
/// material's least lit one ([`lit_cosine`]) or does, where the power is 0.
fn highlight_if_lit(material: &Material, light: &Light, normal: Vec3, l: Vec3, view: Vec3) -> Fx {
    let v = l.minus(view); // two unit vectors: no saturation to check
    let Some(s) = lit_cosine(normal, v, material.highlight_from) else {
        return Fx::ZERO;
    };
    let s = s.max(Fx::ZERO).min(Fx::ONE);
    if s.to_bits() < i32::from(material.highlight_from) {
        return Fx::ZERO;
    }
    fx::mul_fits(light.intensity, powi(s, material.shininess))
}

/// Whether `object` lies on the shadow ray from `from` along the unit `dir` nearer than
/// `√distance_squared`. The ray is made here, for the few objects that come to the whole test:
/// most shadow rays end at an empty set or at the cones, where a ray made first would be
/// stored for nothing.
pub(crate) fn blocks(object: &Object, from: Vec3, dir: Vec3, distance_squared: u64) -> bool {
    object
        .shape
        .blocks(&Ray::new_unchecked(from, dir), distance_squared)
}
