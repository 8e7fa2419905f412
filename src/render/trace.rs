//! The chapter's shoot and shade: the nearest hit along a ray, and the light that reaches the
//! eye from it — lights, shadow rays, highlights, mirrors and glass, without recursion.
//!
//! This is the plain path, and the oracle every speed-up is held to: [`Scene::trace`] is
//! `shade(shoot(ray))` for one ray, with brute-force loops — every object for the nearest hit,
//! every object and every light for the shadows — and no caches. `render_row` finds the same
//! pixels for a whole row for less (`render/accel/`), bit for bit.

use crate::geometry::Shape;
use crate::geometry::hit::Hit;
use crate::geometry::ray::Ray;
use crate::geometry::refract::{refract, schlick};
use crate::numbers::fx::{self, Fx};
use crate::numbers::vec3::Vec3;
use crate::scene::hit::SceneHit;
use crate::scene::light::Light;
use crate::scene::linear::{Linear, channel_to_linear, powi, rgb_of};
use crate::scene::{Material, Object, Rgb, Scene};

impl<const N: usize, const L: usize> Scene<N, L> {
    /// `shade(shoot(ray))`: the colour of the pixel this ray passes through.
    #[must_use]
    pub fn trace(&self, ray: &Ray) -> Rgb {
        self.shade(ray, self.shoot(ray).as_ref())
    }

    /// Shoots `ray` into the scene and returns the nearest hit; on a tie the object added
    /// first wins. A hit beyond the reach every hit point keeps (±(`LIMIT` + `FAR`), which a
    /// ray from a point within `LIMIT` never passes) is a miss, as for the secondary rays.
    #[must_use]
    pub fn shoot(&self, ray: &Ray) -> Option<SceneHit> {
        self.shoot_after(ray, None)
            .filter(|h| h.hit.point.within_raw(fx::HIT_REACH))
    }

    /// The nearest hit of a ray that starts as `start` says, or anywhere (`None`).
    ///
    /// Spheres and planes are convex: a ray leaving one towards a light or along a mirror
    /// direction cannot meet the same surface again, so it skips that object
    /// ([`Start::Off`]). That replaces the usual small offset along the normal, exactly, where
    /// an offset in Q16.16 would have to be larger than the hit point's rounding (which grows
    /// with distance) and would detach shadows from the objects that cast them. A ray that has
    /// entered a sphere through its surface meets that sphere at the far crossing
    /// ([`Start::Within`], `Sphere::exit_distance`). On a tie the object added first wins.
    fn shoot_after(&self, ray: &Ray, start: Option<Start>) -> Option<SceneHit> {
        // Hits lie within FAR, so any hit is nearer than MAX.
        let (mut best, mut nearest, mut known) = (Fx::MAX, usize::MAX, None);
        for (index, object) in self.objects().iter().enumerate() {
            let met = match (start, object.shape) {
                (Some(Start::Off(from)), _) if from == index => None,
                (Some(Start::Within(from)), Shape::Sphere(sphere)) if from == index => {
                    Some((sphere.exit_distance(ray), None))
                }
                (_, shape) => shape.meet(ray),
            };
            if let Some((t, hit)) = met
                && t < best
            {
                (best, nearest, known) = (t, index, hit);
            }
        }
        self.hit_of_nearest(ray, nearest, best, known)
    }

    /// The hit on object `nearest`, found at distance `best` along `ray`: `known` where its
    /// distance came with it (a plane's), otherwise a sphere's hit point and normal, made for
    /// the nearest object only; `None` where no object was met (`nearest` is none).
    pub(crate) fn hit_of_nearest(
        &self,
        ray: &Ray,
        nearest: usize,
        best: Fx,
        known: Option<Hit>,
    ) -> Option<SceneHit> {
        let hit = match known {
            Some(hit) => hit,
            None => self
                .objects()
                .get(nearest)?
                .shape
                .sphere_hit_at(ray, best)?,
        };
        Some(SceneHit {
            hit,
            object: nearest,
        })
    }

    /// The colour seen along `ray` when it has this first hit (from [`Scene::shoot`]): the
    /// background for a miss, otherwise the lit surface plus what its mirror and its
    /// refraction show (see [`Material`](crate::Material)).
    ///
    /// A surface that shows its own diffuse light alone (no highlight, mirror or refraction)
    /// is the pixel by itself: its channels are formed from its brightness in one product
    /// each (`Scene::matte_pixel`). Any other sums its light and its rays' first.
    ///
    /// A hit on a mirror or a transparent surface starts a tree of secondary rays: each hit
    /// may send on a mirror ray and a refracted ray, each weighted by the product of the
    /// weights on its path from the eye. Rays are followed to [`Scene::depth`] generations;
    /// a ray of the next generation sees the background. The tree is followed without
    /// recursion, depth first, from a list of waiting rays that holds at most one ray per
    /// generation plus one, [`Scene::MAX_DEPTH`]` + 1` = 17 in all, so the stack a pixel needs
    /// does not grow with the depth. A pixel traces at most [`Scene::MAX_RAYS`] of them, first
    /// come first served in that order; the rest see the background, so its time is bounded
    /// too.
    #[must_use]
    pub fn shade(&self, ray: &Ray, hit: Option<&SceneHit>) -> Rgb {
        let Some((h, object)) = hit.and_then(|h| Some((*h, self.objects().get(h.object)?))) else {
            return rgb_of(self.background().along(ray.dir));
        };
        let at = Surface::of(&h);
        if object.material.is_plain_matte() {
            let diffuse = (self.lights().iter()).fold(Fx::ZERO, |sum, light| {
                sum.saturating_add(self.diffuse(light, &at))
            });
            return self.matte_pixel(&object.material, diffuse, object.colour_at(at.point));
        }
        let light = self.local(object, &at, ray.dir);
        let local = |object: &Object, at: &Surface, view: Vec3| self.local(object, at, view);
        rgb_of(self.followed(light, ray.dir, &h, &local))
    }

    /// The light arriving along `dir` from its first hit `first`, whose own light is
    /// `light`: that alone on a surface that neither mirrors nor refracts, and otherwise with
    /// the tree of secondary rays the surface sends on, each hit's own light from `local`
    /// (the plain path's is [`Scene::local`]; the rows' finds the same light for less).
    pub(crate) fn followed(
        &self,
        light: Linear,
        dir: Vec3,
        first: &SceneHit,
        local: &impl Fn(&Object, &Surface, Vec3) -> Linear,
    ) -> Linear {
        match self.objects().get(first.object) {
            Some(object) if object.material.sends_rays() => {
                self.secondary(light, dir, first, local)
            }
            _ => light,
        }
    }

    /// The light arriving along `dir` past a first surface `first` that mirrors or refracts:
    /// `sum` is that surface's own light, and the tree of secondary rays is followed from it,
    /// each hit's own light from `local`.
    fn secondary(
        &self,
        mut sum: Linear,
        dir: Vec3,
        first: &SceneHit,
        local: &impl Fn(&Object, &Surface, Vec3) -> Linear,
    ) -> Linear {
        let mut waiting = Waiting::new();
        let exiting = self.exits(first, None);
        self.branch(&mut sum, &mut waiting, dir, first, exiting, Fx::ONE, 0);
        let mut traced: u16 = 0;
        while let Some(next) = waiting.pop() {
            if traced == Self::MAX_RAYS {
                add(&mut sum, next.weight, self.background().along(next.dir));
                continue;
            }
            traced += 1;
            let ray = Ray::new_unchecked(next.origin, next.dir);
            // A secondary ray may travel FAR from a point that is itself FAR from the eye: its
            // hits are kept inside the budget every hit point keeps (±(LIMIT + FAR)), past
            // which they are misses, so that the next ray starts inside it too.
            let hit = self
                .shoot_after(&ray, Some(next.start))
                .filter(|h| h.hit.point.within_raw(fx::HIT_REACH));
            let Some((h, object)) = hit.and_then(|h| Some((h, self.objects().get(h.object)?)))
            else {
                add(&mut sum, next.weight, self.background().along(next.dir));
                continue;
            };
            let within = match next.start {
                Start::Within(sphere) => Some(sphere),
                Start::Off(_) => None,
            };
            let exiting = self.exits(&h, within);
            let light = local(object, &Surface::of(&h), next.dir);
            add(&mut sum, next.weight, light);
            self.branch(
                &mut sum,
                &mut waiting,
                next.dir,
                &h,
                exiting,
                next.weight,
                next.generation,
            );
        }
        sum
    }

    /// Whether `hit` is on the inside of a sphere, so that a ray refracted there leaves it:
    /// known when the ray travelled inside that sphere (`within`), and otherwise read from the
    /// hit (an eye or a ray starting inside a sphere meets its far side).
    fn exits(&self, hit: &SceneHit, within: Option<usize>) -> bool {
        match self.objects().get(hit.object).map(|object| object.shape) {
            Some(Shape::Sphere(sphere)) => {
                within == Some(hit.object) || sphere.reached_from_inside(&hit.hit)
            }
            _ => false,
        }
    }

    /// The secondary rays from `hit`, reached along `dir` by a ray of weight `weight` and
    /// generation `generation`: the mirror ray and the refracted ray its material sends on.
    /// `exiting` says the hit is on the inside of a sphere (see [`Scene::exits`]).
    ///
    /// Entering a sphere, a ray bends by `1/index` and goes on inside it; leaving, by
    /// `index`. Where Snell's law has no solution the refracted weight joins the mirror's,
    /// and with Fresnel weighting Schlick's share of it does. A plane is a sheet with no
    /// thickness: its refracted ray goes on undeviated.
    #[allow(clippy::too_many_arguments)]
    fn branch(
        &self,
        sum: &mut Linear,
        waiting: &mut Waiting,
        dir: Vec3,
        hit: &SceneHit,
        exiting: bool,
        weight: Fx,
        generation: u8,
    ) {
        let Some(object) = self.objects().get(hit.object) else {
            return;
        };
        let (normal, point, index) = (hit.hit.normal, hit.hit.point, hit.object);
        let child = generation.saturating_add(1);
        let mut reflect = object.material.reflect;
        if let Some(refraction) = object.material.refraction {
            let mut through = refraction.weight();
            let refracted = match object.shape {
                Shape::Plane(_) => Some((dir, Start::Off(index))),
                Shape::Sphere(_) if exiting => {
                    refract(dir, normal, refraction.index()).map(|d| (d, Start::Off(index)))
                }
                Shape::Sphere(_) => {
                    refract(dir, normal, refraction.inverse).map(|d| (d, Start::Within(index)))
                }
            };
            match refracted {
                // Total internal reflection: all the refracted light is mirrored.
                None => reflect = reflect.saturating_add(through),
                Some((bent, start)) => {
                    if refraction.fresnel() {
                        // Schlick's cosine is that of the larger angle, on the side of the
                        // lower index (the normal faces the arriving ray, and the bent ray
                        // goes on through the surface).
                        let cos = (-normal.dot(dir)).min(-normal.dot(bent));
                        let share = fx::mul_fits(through, schlick(refraction.r0, cos));
                        reflect = reflect.saturating_add(share);
                        through -= share;
                    }
                    let ray = Ray::new_unchecked(point, bent);
                    self.send(sum, waiting, ray, start, fx::mul(weight, through), child);
                }
            }
        }
        if reflect == Fx::ZERO {
            return;
        }
        let weight = fx::mul(weight, reflect);
        let Some(bounced) = mirror(dir, normal) else {
            add(sum, weight, self.background().along(dir));
            return;
        };
        // A ray mirrored inside a sphere stays inside it.
        let start = if exiting {
            Start::Within(index)
        } else {
            Start::Off(index)
        };
        self.send(
            sum,
            waiting,
            Ray::new_unchecked(point, bounced),
            start,
            weight,
            child,
        );
    }

    /// Queues a secondary ray of generation `generation`, or adds the background it sees when
    /// that is past the scene's depth. A ray of weight 0 would add nothing and is dropped.
    fn send(
        &self,
        sum: &mut Linear,
        waiting: &mut Waiting,
        ray: Ray,
        start: Start,
        weight: Fx,
        generation: u8,
    ) {
        if weight == Fx::ZERO {
            return;
        }
        let next = Pending {
            origin: ray.origin,
            dir: ray.dir,
            start,
            weight,
            generation,
        };
        if generation > self.depth() || waiting.push(next).is_err() {
            add(sum, weight, self.background().along(ray.dir));
        }
    }

    /// The surface's own light where a ray along `view` met `object` at `at`: ambient and
    /// diffuse times its colour, plus white highlights, from every light whose shadow ray
    /// reaches it.
    fn local(&self, object: &Object, at: &Surface, view: Vec3) -> Linear {
        let material = &object.material;
        let (mut diffuse, mut specular) = (Fx::ZERO, Fx::ZERO);
        let normal = highlight_normal(material, at.normal);
        for light in self.lights() {
            let Some((l, cos)) = self.reaches(light, at) else {
                continue;
            };
            diffuse = diffuse.saturating_add(fx::mul_unit(light.intensity, cos));
            if material.specular > Fx::ZERO {
                specular = specular.saturating_add(highlight(material, light, normal, l, view));
            }
        }
        self.with_highlight(
            self.lit(material, diffuse, object.colour_at(at.point)),
            material,
            specular,
        )
    }

    /// `lit` plus the white highlight of `specular` (each light's intensity times its power,
    /// summed), weighted by the material's specular weight.
    pub(crate) fn with_highlight(&self, lit: Linear, material: &Material, specular: Fx) -> Linear {
        if specular <= Fx::ZERO {
            return lit;
        }
        let highlight = fx::mul(material.specular, specular);
        lit.map(|c| c.saturating_add(highlight))
    }

    /// `light`'s diffuse term at the surface `at`: its intensity times its cosine where it
    /// reaches the surface ([`Scene::reaches`]), 0 where it does not.
    fn diffuse(&self, light: &Light, at: &Surface) -> Fx {
        match self.reaches(light, at) {
            Some((_, cos)) => fx::mul_unit(light.intensity, cos),
            None => Fx::ZERO,
        }
    }

    /// Whether `light` reaches the surface `at`: the unit direction `l` towards it and the
    /// cosine `n·l`, or `None` where it is at the point, does not face the surface, or — where
    /// shadows are on — another object lies between ([`Scene::occluded`]).
    fn reaches(&self, light: &Light, at: &Surface) -> Option<(Vec3, Fx)> {
        let towards = self.towards_light(light, at)?;
        if self.shadows() && self.occluded(at.point, towards.l, towards.distance_squared, at.index)
        {
            return None;
        }
        Some((towards.l, towards.cos))
    }

    /// The direction from the surface `at` to `light`, where the light faces it: its unit
    /// vector, the cosine with the normal (above 0) and the squared distance (Q32.32) a shadow
    /// ray must cross. `None` where the light is at the point or behind the surface.
    pub(crate) fn towards_light(&self, light: &Light, at: &Surface) -> Option<TowardsLight> {
        let to_light = light.position.minus(at.point);
        let distance_squared = to_light.length_squared_wide();
        let l = to_light.normalize_with_square(distance_squared)?;
        let cos = at.normal.dot_exact(l);
        (cos > Fx::ZERO).then_some(TowardsLight {
            l,
            cos,
            distance_squared,
        })
    }

    /// Whether any object but `leaving` lies on the shadow ray from `from` along the unit
    /// `dir` nearer than `√distance_squared` (a Q32.32 value): every object is tried.
    pub(crate) fn occluded(
        &self,
        from: Vec3,
        dir: Vec3,
        distance_squared: u64,
        leaving: usize,
    ) -> bool {
        let ray = Ray::new_unchecked(from, dir);
        (self.objects().iter().enumerate())
            .any(|(i, object)| i != leaving && object.shape.blocks(&ray, distance_squared))
    }

    /// The ambient and diffuse light leaving a surface of `material` and `colour` that
    /// receives `diffuse` from the lights (each light's intensity times its cosine, summed).
    pub(crate) fn lit(&self, material: &Material, diffuse: Fx, colour: Rgb) -> Linear {
        let k = self.brightness(material, diffuse);
        // A channel is at most 1: its product with k needs no saturation.
        let lit = |c: u8| fx::mul_fits(k, channel_to_linear(c));
        [lit(colour.r), lit(colour.g), lit(colour.b)]
    }

    /// The pixel of a surface of `material` and `colour` that shows [`Scene::lit`]'s light
    /// alone: each channel `c·k` rounded half up and clamped to 255, for its brightness `k`
    /// — one rounding of the exact product, as the f64 reference forms it, where light that is
    /// summed goes through linear units and rounds three times (`c/255`, the product, and
    /// back to 0..=255).
    pub(crate) fn matte_pixel(&self, material: &Material, diffuse: Fx, colour: Rgb) -> Rgb {
        // From 256 up every channel but 0 is 255, so k is held there (and at 0 below 0, which
        // no surface has): c·k then fits 32 bits.
        let k = self
            .brightness(material, diffuse)
            .to_bits()
            .clamp(0, 1 << 24) as u32;
        let channel = |c: u8| scaled_channel(c, k).min(255) as u8;
        Rgb::new(channel(colour.r), channel(colour.g), channel(colour.b))
    }

    /// A surface's brightness: the ambient term plus `diffuse`, the light it receives,
    /// weighted by the material's diffuse weight.
    pub(crate) fn brightness(&self, material: &Material, diffuse: Fx) -> Fx {
        // Several lights and a specular weight up to 16 can exceed Q16.16's range: the sums
        // saturate rather than wrap. A weight of 1, every matte material's, leaves the sum as
        // it is (the product rounds to it exactly).
        let weighted = if material.diffuse == Fx::ONE {
            diffuse
        } else {
            fx::mul(material.diffuse, diffuse)
        };
        self.ambient().saturating_add(weighted)
    }
}

/// The normal a highlight of `material` is formed with: `normal` made a unit vector again
/// where the material has a highlight. A sphere's normal `(x − c)/r` is as long as its hit
/// point lies far from the centre, off the radius by some units of 2⁻¹⁶, and near its peak a
/// highlight of weight `w` and shininess `k` moves by about `255·w·k` levels for each unit
/// its cosine is off (the classic scene's mirror, thousands). The light's diffuse cosine, and
/// every surface without a highlight, keep the normal as it is.
pub(crate) fn highlight_normal(material: &Material, normal: Vec3) -> Vec3 {
    if material.specular <= Fx::ZERO {
        return normal;
    }
    // `‖n‖² = 1 + e` (Q32.32). Near 1, one step of Newton's for `1/‖n‖` from 1, `1 − e/2`,
    // leaves `3e²/8`: below 2⁻²⁹ for `|e| < 2⁻¹⁴`, and each component is rounded once. A
    // normal farther off (a hit on a tiny sphere) is normalised in full.
    let e = normal.length_squared_wide() as i64 - (1 << 32);
    if e.unsigned_abs() >= 1 << 18 {
        return normal.try_normalize().unwrap_or(normal);
    }
    // |c| ≤ 2¹⁷ and |e/2| < 2¹⁷: the product fits, and so does the corrected component.
    let half = (e / 2) as i32;
    let c = |c: Fx| Fx::from_bits(c.to_bits() - fx::mul_shift_round(c.to_bits(), half, 32) as i32);
    Vec3::new(c(normal.x), c(normal.y), c(normal.z))
}

/// The highlight `light` adds where it reaches a surface of `material` whose normal is
/// `normal`, along the unit `l`, seen along `view`: its intensity times `(n·h)^shininess`, `h`
/// the unit vector halfway between `l` and the view's reverse — `n·h` formed as `n·v/‖v‖` for
/// `v = l − view` ([`Vec3::cosine_to`]), one rounding from the exact dot product.
pub(crate) fn highlight(
    material: &Material,
    light: &Light,
    normal: Vec3,
    l: Vec3,
    view: Vec3,
) -> Fx {
    let v = l.minus(view); // two unit vectors: no saturation to check
    let Some(s) = normal.cosine_to(v) else {
        return Fx::ZERO;
    };
    let s = s.max(Fx::ZERO).min(Fx::ONE);
    fx::mul_fits(light.intensity, powi(s, material.shininess))
}

/// An 8-bit channel `c` times a brightness `k` (raw Q16.16, at most 2²⁴), rounded half up:
/// [`Scene::matte_pixel`]'s one product, not yet held at 255.
pub(crate) const fn scaled_channel(c: u8, k: u32) -> u32 {
    (c as u32 * k + (1 << 15)) >> 16
}

/// The way from a surface to a light that faces it ([`Scene::towards_light`]).
#[derive(Clone, Copy)]
pub(crate) struct TowardsLight {
    /// The unit vector towards the light.
    pub(crate) l: Vec3,
    /// `n·l`, above 0.
    pub(crate) cos: Fx,
    /// The squared distance to the light, Q32.32.
    pub(crate) distance_squared: u64,
}

/// A point on the surface of object `index`, whose unit normal there is `normal` (facing the
/// side that is lit and seen).
#[derive(Clone, Copy)]
pub(crate) struct Surface {
    pub(crate) index: usize,
    pub(crate) point: Vec3,
    pub(crate) normal: Vec3,
}

impl Surface {
    /// The surface a hit is on.
    pub(crate) const fn of(hit: &SceneHit) -> Self {
        Surface {
            index: hit.object,
            point: hit.hit.point,
            normal: hit.hit.normal,
        }
    }
}

/// Where a secondary ray starts, which decides how it meets the surface it leaves.
#[derive(Clone, Copy)]
enum Start {
    /// Leaving object `i`'s surface outwards, or through a plane: spheres and planes are
    /// convex, so it cannot meet `i` again and skips it.
    Off(usize),
    /// Inside sphere `i`, having crossed its surface inwards: it meets `i` at the far crossing.
    Within(usize),
}

/// A secondary ray waiting to be followed.
#[derive(Clone, Copy)]
struct Pending {
    /// The ray, from `origin` along the unit `dir` (a secondary ray is made along its unit
    /// direction, so that is all it needs).
    origin: Vec3,
    dir: Vec3,
    start: Start,
    /// The product of the weights on its path from the eye.
    weight: Fx,
    /// 1 for a ray leaving the first surface, one more for each surface since.
    generation: u8,
}

/// The rays waiting to be followed, last in first out.
///
/// Followed depth first, the tree leaves at most one ray waiting for each generation below
/// the one being followed, and two of that one: taking a ray of generation `g` adds at most
/// two of `g + 1`, and rays past the scene's depth are never queued. With generations 1 to
/// [`Scene::MAX_DEPTH`] that is at most `MAX_DEPTH + 1`.
type Waiting = heapless::Vec<Pending, { Scene::<1, 1>::MAX_DEPTH as usize + 1 }>;

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
    let along = normal.scale(dir.dot_units(normal).saturating_mul_int(2));
    (dir - along).try_normalize()
}
