//! The chapter's shoot and shade: the nearest hit along a ray, and the light that reaches the
//! eye from it — lights, shadow rays, highlights and mirror bounces, without recursion.
//!
//! This is the plain path, readable top to bottom: [`Scene::trace`] is `shade(shoot(ray))`
//! for one ray. `render_row` finds the same pixels for a whole row for less (see `accel`),
//! bit for bit.

use crate::geometry::Shape;
use crate::geometry::hit::Hit;
use crate::geometry::ray::Ray;
use crate::geometry::refract::{refract, schlick};
use crate::numbers::fx::{self, Fx};
use crate::numbers::vec3::Vec3;
use crate::render::highlight::highlight_below;
use crate::scene::cone::ShadowCone;
use crate::scene::hit::SceneHit;
use crate::scene::light::Light;
use crate::scene::linear::{Linear, channel_to_linear, powi};
use crate::scene::{Material, Object, Rgb, Scene};

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
        self.shoot_after(ray, leaving.map(Start::Off))
    }

    /// The nearest hit of a ray that starts as `start` says, or anywhere (`None`): a ray
    /// leaving an object's surface skips that object ([`Scene::shoot_from`]); one that has
    /// entered a sphere through its surface meets that sphere at the far crossing (see
    /// `Sphere::exit_distance`), the others as any ray does. On a tie the object added
    /// first wins. One loop for both, so that the secondary rays have one copy of it.
    fn shoot_after(&self, ray: &Ray, start: Option<Start>) -> Option<SceneHit> {
        self.nearest(ray, |index, shape| match (start, shape) {
            (Some(Start::Off(from)), _) if from == index => None,
            (Some(Start::Within(from)), Shape::Sphere(sphere)) if from == index => {
                Some((sphere.exit_distance(ray), None))
            }
            _ => shape.meet(ray),
        })
    }

    /// The nearest hit along `ray`, with `distance(index, shape)` the distance at which it
    /// meets object `index`, if it does, and the whole hit where that came at no extra cost
    /// (a plane's point is found before its distance): on a tie the first object wins.
    #[inline(always)]
    fn nearest(
        &self,
        ray: &Ray,
        distance: impl Fn(usize, &Shape) -> Option<(Fx, Option<Hit>)>,
    ) -> Option<SceneHit> {
        // Hits lie within FAR, so any hit is nearer than MAX.
        let (mut best, mut nearest, mut known) = (Fx::MAX, usize::MAX, None);
        for (index, object) in self.objects().iter().enumerate() {
            if let Some((t, hit)) = distance(index, &object.shape)
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
    #[inline(always)]
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
    /// A hit on a mirror or a transparent surface starts a tree of secondary rays: each hit
    /// may send on a mirror ray and a refracted ray, each weighted by the product of the
    /// weights on its path from the eye. Rays are followed to [`Scene::depth`] generations;
    /// a ray of the next generation sees the background. The tree is followed without
    /// recursion, depth first, from a list of waiting rays that holds at most one ray per
    /// generation plus one, [`Scene::MAX_DEPTH`]` + 1` = 17 in all (about 700 bytes of
    /// stack), so the stack a pixel needs does not grow with the depth. A pixel traces at
    /// most [`Scene::MAX_RAYS`] of them, first come first served in that order; the rest see
    /// the background, so its time is bounded too.
    #[must_use]
    pub fn shade(&self, ray: &Ray, hit: Option<&SceneHit>) -> Rgb {
        self.pixel_among(ray, hit.copied(), &[!0; L])
    }

    /// [`Scene::shade`] where a first hit on a plane need only try objects of
    /// `plane_shadowers[light]` for its shadow rays (see [`Scene::radiance_among`]). A surface
    /// that shows its own diffuse light alone ([`Material::is_plain_matte`]) is the pixel by
    /// itself: its channels are formed from its brightness in one product each
    /// ([`Scene::matte_pixel`]); any other sums its light and its rays' first.
    pub(crate) fn pixel_among(
        &self,
        ray: &Ray,
        hit: Option<SceneHit>,
        plane_shadowers: &[u32; L],
    ) -> Rgb {
        if let Some(h) = hit
            && let Some(object) = self.objects().get(h.object)
            && object.material.is_plain_matte()
        {
            let at = Surface {
                index: h.object,
                point: h.hit.point,
                normal: h.hit.normal,
            };
            let on_plane = matches!(object.shape, Shape::Plane(_));
            let diffuse = self.matte_diffuse(&at, on_plane, plane_shadowers);
            return self.matte_pixel(&object.material, diffuse, object.colour_at(at.point));
        }
        crate::scene::linear::rgb_of(self.radiance_among(ray, hit, plane_shadowers))
    }

    /// The light arriving along `ray`, whose first hit is `hit`, in linear units, where a first
    /// hit on a plane need only try objects of `plane_shadowers[light]` (bit `i` for object
    /// `i`) for its shadow rays: the same light, given sets that hold every object which can
    /// shadow the hit (`accel/shadow_rows.rs`).
    pub(crate) fn radiance_among(
        &self,
        ray: &Ray,
        hit: Option<SceneHit>,
        plane_shadowers: &[u32; L],
    ) -> Linear {
        let Some((h, object)) = hit.and_then(|h| Some((h, self.objects().get(h.object)?))) else {
            return self.background().along(ray.dir);
        };
        // The first surface has weight 1: its light is the sum so far, exactly.
        let (point, normal) = (h.hit.point, h.hit.normal);
        let light = self.local(
            object,
            h.object,
            point,
            normal,
            Some(ray.dir),
            plane_shadowers,
        );
        if object.material.reflect == Fx::ZERO && object.material.refraction.is_none() {
            return light;
        }
        self.secondary(light, ray.dir, &h)
    }

    /// [`Scene::radiance`] past a first surface that mirrors or refracts: `sum` is that
    /// surface's own light, and the tree of secondary rays is followed from it. Kept apart so
    /// that the common matte pixel does not pay for the list's set-up.
    #[inline(never)]
    fn secondary(&self, mut sum: Linear, dir: Vec3, first: &SceneHit) -> Linear {
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
            let (point, normal) = (h.hit.point, h.hit.normal);
            let light = self.local(object, h.object, point, normal, Some(next.dir), &[!0; L]);
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
        if generation > self.depth() || !waiting.push(next) {
            add(sum, weight, self.background().along(ray.dir));
        }
    }

    /// The surface's own light where a ray along `view` met object `index` (`object`) at
    /// `point`, its normal there `normal`: ambient and diffuse times its colour, plus white
    /// highlights, from every light whose shadow ray reaches it. Only a highlight needs the
    /// view, and a surface without one may be shaded without it (`None`). On a plane, a
    /// shadow ray towards light `i` tries only the objects of `plane_shadowers[i]`.
    fn local(
        &self,
        object: &Object,
        index: usize,
        point: Vec3,
        normal: Vec3,
        view: Option<Vec3>,
        plane_shadowers: &[u32; L],
    ) -> Linear {
        let material = &object.material;
        let on_plane = matches!(object.shape, Shape::Plane(_));
        let at = Surface {
            index,
            point,
            normal,
        };
        // A matte surface, the most common, sums the lights' diffuse terms alone: apart from
        // the highlights' loop, whose sums and view it has no use for.
        if material.specular <= Fx::ZERO {
            let diffuse = self.matte_diffuse(&at, on_plane, plane_shadowers);
            return self.lit(material, diffuse, object.colour_at(point));
        }
        let (mut diffuse, mut specular) = (Fx::ZERO, Fx::ZERO);
        let mut light_up = |light_index: usize, light: &Light| {
            let among = self.shadow_set(light_index, on_plane, plane_shadowers);
            let Some((l, cos)) = self.reaches(light_index, light, &at, among) else {
                return;
            };
            diffuse = diffuse.saturating_add(fx::mul_unit(light.intensity, cos));
            if let Some(dir) = view {
                let v = l.minus(dir); // two unit vectors: no saturation to check
                if highlight_below(normal, v, material.highlight_from) {
                    return;
                }
                // `v`'s squared length is taken again here rather than handed over from the
                // test: a square to hand over lengthens the M0's copy of the normalisation.
                let Some(half) = v.try_normalize() else {
                    return;
                };
                let s = normal.dot_units(half).max(Fx::ZERO).min(Fx::ONE);
                // Below the material's threshold the power is 0, and so is the highlight.
                if s.to_bits() >= i32::from(material.highlight_from) {
                    let power = powi(s, material.shininess);
                    specular = specular.saturating_add(fx::mul_fits(light.intensity, power));
                }
            }
        };
        match self.lights() {
            [only] => light_up(0, only),
            lights => {
                for (light_index, light) in lights.iter().enumerate() {
                    light_up(light_index, light);
                }
            }
        }
        let lit = self.lit(material, diffuse, object.colour_at(point));
        if specular <= Fx::ZERO {
            return lit; // no highlight here: nothing to add
        }
        let highlight = fx::mul(material.specular, specular);
        lit.map(|c| c.saturating_add(highlight))
    }

    /// The diffuse light a surface `at` receives (each light's intensity times its cosine,
    /// summed), from every light whose shadow ray reaches it: all a surface without a
    /// highlight needs of the lights. `on_plane` and `plane_shadowers` as for `local`.
    // In line on every chip, in the pixel's shading and the plain path's.
    #[inline(always)]
    fn matte_diffuse(&self, at: &Surface, on_plane: bool, plane_shadowers: &[u32; L]) -> Fx {
        // One light, the common case on a small screen, without a loop to set up. On the
        // Armv7-M cores and RV32 its term is written apart from the loop's, so that a sphere
        // pixel does not store what the loop's closure takes along; the Cortex-M0 shares the
        // loop's closure, as a second copy is more than its flash holds.
        if let ([only], false) = (self.lights(), fx::NO_LONG_MULTIPLY) {
            return self.diffuse_from(0, only, at, on_plane, plane_shadowers);
        }
        let of_light =
            |i: usize, light: &Light| self.diffuse_from(i, light, at, on_plane, plane_shadowers);
        match self.lights() {
            [only] => of_light(0, only),
            lights => (lights.iter().enumerate()).fold(Fx::ZERO, |sum, (i, light)| {
                sum.saturating_add(of_light(i, light))
            }),
        }
    }

    /// Light `light_index`'s (`light`'s) term of [`Scene::matte_diffuse`].
    #[inline]
    fn diffuse_from(
        &self,
        light_index: usize,
        light: &Light,
        at: &Surface,
        on_plane: bool,
        plane_shadowers: &[u32; L],
    ) -> Fx {
        let among = self.shadow_set(light_index, on_plane, plane_shadowers);
        match self.reaches(light_index, light, at, among) {
            Some((_, cos)) => fx::mul_unit(light.intensity, cos),
            None => Fx::ZERO,
        }
    }

    /// The objects a shadow ray towards light `light_index` tries from a surface (a plane's
    /// row set where `on_plane`, every object otherwise), or `None` where shadows are off.
    #[inline(always)]
    fn shadow_set(
        &self,
        light_index: usize,
        on_plane: bool,
        plane_shadowers: &[u32; L],
    ) -> Option<u32> {
        self.shadows()
            .then(|| match plane_shadowers.get(light_index) {
                Some(&set) if on_plane => set,
                _ => !0,
            })
    }

    /// The ambient and diffuse light leaving a surface of `material` and `colour` that
    /// receives `diffuse` from the lights (each light's intensity times its cosine, summed).
    #[inline(always)]
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
    #[inline(always)]
    pub(crate) fn matte_pixel(&self, material: &Material, diffuse: Fx, colour: Rgb) -> Rgb {
        let mut pixel = Rgb::BLACK;
        self.paint_matte(material, diffuse, colour, &mut pixel);
        pixel
    }

    /// [`Scene::matte_pixel`], written into `pixel` a channel at a time: formed as one value
    /// and then stored, the compiler joins the three bytes into a word and takes it apart
    /// again, a few instructions a pixel, where a loop of matte pixels stores each alone.
    #[inline(always)]
    pub(crate) fn paint_matte(
        &self,
        material: &Material,
        diffuse: Fx,
        colour: Rgb,
        pixel: &mut Rgb,
    ) {
        let k = self.brightness(material, diffuse).to_bits();
        // Up to a brightness of 1, the common case, no channel passes 255 (255·2¹⁶ + 2¹⁵ is
        // below 256·2¹⁶): nothing to hold. Above it (and below 0, which as a `u32` is above
        // too), the channels are held out of line.
        if (k as u32) > 1 << 16 {
            *pixel = bright_pixel(k, colour);
            return;
        }
        let channel = |c: u8| scaled_channel(c, k as u32) as u8;
        pixel.r = channel(colour.r);
        pixel.g = channel(colour.g);
        pixel.b = channel(colour.b);
    }

    /// A surface's brightness: the ambient term plus `diffuse`, the light it receives,
    /// weighted by the material's diffuse weight.
    #[inline(always)]
    fn brightness(&self, material: &Material, diffuse: Fx) -> Fx {
        // Several lights and a specular weight up to 16 can exceed Q16.16's range: the sums
        // saturate rather than wrap.
        // A weight of 1, every matte material's, leaves the sum as it is (the product rounds
        // to it exactly): no 64-bit product for it where that is a long sequence.
        let weighted = if material.diffuse == Fx::ONE {
            diffuse
        } else {
            fx::mul(material.diffuse, diffuse)
        };
        self.ambient().saturating_add(weighted)
    }

    /// Whether light `light_index` (`light`) reaches the surface `at`: the unit direction `l`
    /// towards it and the cosine `n·l`, or `None` where it is at the point, does not face the
    /// surface, or — with a shadow set `among` (see [`Scene::occluded`]), where shadows are
    /// on — is blocked.
    // Out of line: every lit pixel's light, for the plain path and the matte runs alike.
    #[inline(never)]
    pub(crate) fn reaches(
        &self,
        light_index: usize,
        light: &Light,
        at: &Surface,
        among: Option<u32>,
    ) -> Option<(Vec3, Fx)> {
        let Surface {
            index,
            point,
            normal,
        } = *at;
        let to_light = light.position.minus(point);
        let distance_squared = to_light.length_squared_wide();
        let l = to_light.normalize_in_line(distance_squared)?;
        let cos = normal.dot_exact(l);
        if cos <= Fx::ZERO {
            return None;
        }
        if let Some(among) = among
            && self.occluded(point, l, distance_squared, index, light_index, among)
        {
            return None;
        }
        Some((l, cos))
    }

    /// Whether anything but object `leaving` lies on the ray from `from` along the unit `dir`
    /// closer than `√distance_squared` (a Q32.32 value): a shadow ray towards light `light`,
    /// made only for the objects that come to the whole test, which stops at the first
    /// occluder, tries only the objects that can shadow object `leaving` from that light
    /// (`Scene::shadowers`) and are in `among` (bit `i` for object `i`, which must hold every
    /// object that can block the ray in scenes of up to 32 objects), and skips the spheres
    /// outside its [`ShadowCone`].
    pub(crate) fn occluded(
        &self,
        from: Vec3,
        dir: Vec3,
        distance_squared: u64,
        leaving: usize,
        light: usize,
        among: u32,
    ) -> bool {
        let blocks =
            |object: &Object| blocks_shadow_ray(&object.shape, from, dir, distance_squared);
        let Some(cones) = self.cones().get(light) else {
            // Not one of the scene's lights: no cones to go by.
            return (self.objects().iter().enumerate()).any(|(i, o)| i != leaving && blocks(o));
        };
        let objects = self.objects();
        let may_block = |index: usize, object: &Object, cone: &ShadowCone| {
            cone.may_block(dir, distance_squared) && index != leaving && blocks(object)
        };
        match self.walked(leaving, light) {
            // Only the objects that can shadow the one the ray leaves (bit `i` for object
            // `i`), most often none or one: walked by their bits.
            Some(set) => {
                let mut rest = set & among;
                while rest != 0 {
                    let index = rest.trailing_zeros() as usize;
                    rest &= rest - 1;
                    if let (Some(object), Some(cone)) = (objects.get(index), cones.get(index))
                        && may_block(index, object, cone)
                    {
                        return true;
                    }
                }
            }
            // In scenes of more than 32 objects every one is tried; the receiver is ruled out
            // before its surface could be taken for a blocker.
            _ => {
                for (index, (object, cone)) in objects.iter().zip(cones).enumerate() {
                    if may_block(index, object, cone) {
                        return true;
                    }
                }
            }
        }
        false
    }

    /// The objects (bit `i` for object `i`) that [`Scene::occluded`] walks for a shadow ray
    /// from object `leaving` towards light `light`, before they are met with its `among`:
    /// those that can shadow `leaving` from it. `None` where every object is tried: scenes
    /// of more than 32 objects, or a light that is not the scene's.
    #[inline(always)]
    pub(crate) fn walked(&self, leaving: usize, light: usize) -> Option<u32> {
        let set = self.shadowers().get(light).and_then(|s| s.get(leaving));
        set.copied().filter(|_| self.objects().len() <= 32)
    }
}

/// Whether `shape` lies on the shadow ray from `from` along the unit `dir` nearer than
/// `√distance_squared` ([`Shape::blocks`]). The ray is made here, for the few objects that come
/// to the whole test: most shadow rays end at an empty set or at the cones, where a ray made
/// first would be stored for nothing. Out of line on the Armv7-M cores, where in line it
/// took the shadow walk's registers; in line on ARMv6-M and RV32, where out of line it
/// measured slower (and on the M0 a second copy of the test, past its flash).
#[cfg_attr(all(target_arch = "arm", target_has_atomic = "32"), inline(never))]
#[cfg_attr(
    not(all(target_arch = "arm", target_has_atomic = "32")),
    inline(always)
)]
fn blocks_shadow_ray(shape: &Shape, from: Vec3, dir: Vec3, distance_squared: u64) -> bool {
    shape.blocks(&Ray::new_unchecked(from, dir), distance_squared)
}

/// [`Scene::matte_pixel`] for a brightness `k` (raw Q16.16) above 1: each channel held at
/// 255 (and at 0 for a `k` below 0, which no surface has). Out of line, and shared by the
/// three places that form matte pixels: where the ambient term and the lights' intensities
/// sum to 1 or less (with a diffuse weight of 1), no surface is above 1, and a brighter one
/// pays a call.
#[cold]
#[inline(never)]
fn bright_pixel(k: i32, colour: Rgb) -> Rgb {
    // From 256 up every channel but 0 is 255, so k is held there: c·k then fits 32 bits.
    let k = k.clamp(0, 1 << 24) as u32;
    let channel = |c: u8| scaled_channel(c, k).min(255) as u8;
    Rgb::new(channel(colour.r), channel(colour.g), channel(colour.b))
}

/// An 8-bit channel `c` times a brightness `k` (raw Q16.16, at most 2²⁴), rounded half up:
/// [`Scene::matte_pixel`]'s one product, not yet held at 255.
#[inline(always)]
const fn scaled_channel(c: u8, k: u32) -> u32 {
    (c as u32 * k + (1 << 15)) >> 16
}

/// A point on the surface of object `index`, whose unit normal there is `normal` (facing the
/// side that is lit and seen).
#[derive(Clone, Copy)]
pub(crate) struct Surface {
    pub(crate) index: usize,
    pub(crate) point: Vec3,
    pub(crate) normal: Vec3,
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
struct Waiting {
    rays: [Option<Pending>; WAITING],
    len: usize,
}

/// The capacity of [`Waiting`].
const WAITING: usize = Scene::<1, 1>::MAX_DEPTH as usize + 1;

impl Waiting {
    fn new() -> Self {
        Waiting {
            rays: [None; WAITING],
            len: 0,
        }
    }

    /// Adds a ray; `false` if the list is full, which the bound above rules out.
    fn push(&mut self, ray: Pending) -> bool {
        let Some(slot) = self.rays.get_mut(self.len) else {
            return false;
        };
        *slot = Some(ray);
        self.len += 1;
        true
    }

    fn pop(&mut self) -> Option<Pending> {
        self.len = self.len.checked_sub(1)?;
        self.rays.get_mut(self.len)?.take()
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
    let along = normal.scale(dir.dot_units(normal).saturating_mul_int(2));
    (dir - along).try_normalize()
}
