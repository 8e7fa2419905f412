//! Shading in `f64` (or `f32`): lights, shadows, highlights, mirrors and glass, as
//! [`DScene::radiance`].

use super::dcolour::{DColour, add_weighted, background, linear};
use super::{DHit, DObject, DRay, DScene, DShape, DVec3, Real};

impl<const N: usize, const L: usize, F: Real> DScene<N, L, F> {
    /// The light arriving along `ray`, whose first hit is `hit`, in linear units (1.0 for a
    /// channel of 255), before clamping.
    ///
    /// With `d` the direction of the ray being followed and `n` the unit normal at its hit
    /// turned to face it:
    ///
    /// 1. no hit: the background along `d`;
    /// 2. a hit: the surface's own light (the `local` term of [`DMaterial`](super::DMaterial)),
    ///    plus, for a mirror, `reflect ·` what the mirror ray `r = d − 2(d·n)n` sees, and for
    ///    glass, its weight `·` what the refracted ray sees, bent by Snell's law; where no
    ///    light passes (total internal reflection) the glass's weight joins the mirror's.
    ///    With Fresnel weighting, Schlick's share `R₀ + (1 − R₀)(1 − cos θ)⁵` of the glass's
    ///    weight joins the mirror's and the rest passes, `θ` the larger of the two angles to
    ///    the normal and `R₀ = ((η − 1)/(η + 1))²`.
    ///
    /// Secondary rays start on the surface they leave. A ray going outwards from a sphere, or
    /// through or off a plane, cannot meet that convex surface again and skips it; a ray going
    /// into a sphere (refracted into it, or mirrored on its inner side) meets it where it
    /// leaves ([`DSphere::exit`](super::DSphere::exit)). Whether a sphere is hit on its inside
    /// is read from the hit: the ray is leaving it when `d` points along the outward normal.
    ///
    /// The eye's ray is generation 0 and a ray sent from a hit of generation `g` is `g + 1`;
    /// a ray past [`depth`](Self::depth) sees only the background. So depth 0 still adds
    /// `reflect ·` the background seen along the first mirror ray. Every ray of the tree is
    /// followed: fixray stops at `Scene::MAX_RAYS` secondary rays a pixel, which only trees
    /// more than 5 generations deep can reach.
    ///
    /// A hit whose `object` is not in the scene counts as a miss.
    #[must_use]
    pub fn radiance(&self, ray: &DRay<F>, hit: Option<&DHit<F>>) -> DColour<F> {
        self.seen(ray.dir(), hit.copied(), 0)
    }

    /// What a ray of `generation` going along `dir` sees at `hit`: steps 1 and 2 of
    /// [`radiance`](Self::radiance). Recursive: the depth of the recursion is the scene's
    /// depth plus one.
    // Inlined, as `local` is, so that a matte pixel runs one function: this model in `f32` is
    // the firmware's float baseline, and calls would count against it.
    #[inline(always)]
    fn seen(&self, dir: DVec3<F>, hit: Option<DHit<F>>, generation: u8) -> DColour<F> {
        let Some((h, object)) = hit.and_then(|h| Some((h, self.objects().get(h.object)?))) else {
            return background(&self.background(), dir);
        };
        let n = facing(h.normal, dir);
        let sum = self.local(object, &h, n, dir);
        if object.material.reflect == F::ZERO && object.material.refract.is_none() {
            return sum;
        }
        self.secondary(sum, dir, &h, n, generation)
    }

    /// The rest of [`seen`](Self::seen) at a mirror or glass surface: what its mirror ray and
    /// its refracted ray add to `sum`, the surface's own light. Kept apart, and never inlined,
    /// so that the recursion does not weigh on the matte surfaces most pixels show.
    #[inline(never)]
    fn secondary(
        &self,
        mut sum: DColour<F>,
        dir: DVec3<F>,
        h: &DHit<F>,
        n: DVec3<F>,
        generation: u8,
    ) -> DColour<F> {
        let Some(object) = self.objects().get(h.object) else {
            return sum;
        };
        // A sphere's normal points outward: a ray along it is leaving the sphere.
        let inside = match object.shape {
            DShape::Sphere(_) => h.normal.dot(dir) > F::ZERO,
            DShape::Plane(_) => false,
        };
        let material = &object.material;
        let mut reflect = material.reflect;
        if let Some(glass) = material.refract {
            let mut weight = glass.weight;
            let (bent, into) = match object.shape {
                // A sheet with no thickness: the ray goes on as it was.
                DShape::Plane(_) => (Some(dir), false),
                DShape::Sphere(_) if inside => (snell(dir, n, glass.index), false),
                DShape::Sphere(_) => (snell(dir, n, F::ONE / glass.index), true),
            };
            match bent {
                None => reflect += weight,
                Some(bent) => {
                    if glass.fresnel {
                        let (cos_in, cos_out) = (-n.dot(dir), -n.dot(bent));
                        let cos = if cos_in < cos_out { cos_in } else { cos_out };
                        let share = weight * schlick(glass.index, cos);
                        reflect += share;
                        weight = weight - share;
                    }
                    let along = DRay::new_unchecked(h.point, bent);
                    let seen = self.through(&along, h.object, into, generation);
                    add_weighted(&mut sum, weight, seen);
                }
            }
        }
        if reflect > F::ZERO {
            let r = (dir - n * (F::TWO * dir.dot(n)))
                .try_normalize()
                .unwrap_or(dir);
            // Mirrored on the inside of a sphere, the ray stays inside it.
            let seen = self.through(
                &DRay::new_unchecked(h.point, r),
                h.object,
                inside,
                generation,
            );
            add_weighted(&mut sum, reflect, seen);
        }
        sum
    }

    /// What a secondary ray sent by a hit of `generation` on object `from` sees: the
    /// background past the depth, else what it meets. `into` says it goes into the sphere
    /// `from` (and meets it again where it leaves); otherwise it skips `from`.
    fn through(&self, ray: &DRay<F>, from: usize, into: bool, generation: u8) -> DColour<F> {
        let generation = generation.saturating_add(1);
        if generation > self.depth() {
            return background(&self.background(), ray.dir());
        }
        let hit = if into {
            self.shoot_inside(ray, from)
        } else {
            self.shoot_from(ray, Some(from))
        };
        self.seen(ray.dir(), hit, generation)
    }

    /// The light a surface gives off by itself at `hit`, seen along `d`, with `n` its unit
    /// normal turned towards the eye (see [`DMaterial`](super::DMaterial)):
    ///
    /// `C·(ambient + diffuse·Σ I·(n·l)) + specular·Σ I·clamp(n·h, 0, 1)^shininess`
    ///
    /// summed over the lights in front of the surface (`n·l > 0`) and, with shadows on, not
    /// hidden by another object; `C` is the colour at the point (a checkerboard's square on a
    /// plane) and `h` the unit half vector of `l` and `−d`.
    #[inline(always)]
    fn local(&self, object: &DObject<F>, hit: &DHit<F>, n: DVec3<F>, d: DVec3<F>) -> DColour<F> {
        let material = &object.material;
        let (mut diffuse, mut specular) = (F::ZERO, F::ZERO);
        for light in self.lights() {
            let Some((l, distance)) = light.seen_from(hit.point) else {
                continue;
            };
            let cos = n.dot(l);
            if cos <= F::ZERO {
                continue;
            }
            if self.shadows()
                && self.occluded(&DRay::new_unchecked(hit.point, l), distance, hit.object)
            {
                continue;
            }
            diffuse += light.intensity * cos;
            if material.specular > F::ZERO
                && let Some(h) = (l - d).try_normalize()
            {
                let s = unit_clamp(n.dot(h));
                specular += light.intensity * s.powi(material.shininess);
            }
        }
        let k = self.ambient() + material.diffuse * diffuse;
        let highlight = material.specular * specular;
        linear::<F>(object.colour_at(hit.point)).map(|c| c * k + highlight)
    }

    /// Whether the shadow ray from object `leaving`'s surface towards a light `distance` away
    /// is stopped by another object short of the light. The twin of fixray's (crate-private)
    /// `Scene::occluded`, without its shadow cones: every other object is tried.
    fn occluded(&self, shadow: &DRay<F>, distance: F, leaving: usize) -> bool {
        self.objects()
            .iter()
            .enumerate()
            .filter(|&(index, _)| index != leaving)
            .any(|(_, object)| {
                object
                    .shape
                    .intersect(shadow)
                    .is_some_and(|h| h.t < distance)
            })
    }
}

/// `normal`, or its opposite, whichever faces back along `dir`: a sphere seen from inside is
/// lit on its inner side.
fn facing<F: Real>(normal: DVec3<F>, dir: DVec3<F>) -> DVec3<F> {
    if normal.dot(dir) <= F::ZERO {
        normal
    } else {
        -normal
    }
}

/// The direction a unit ray `d` takes through a surface with unit normal `n` facing it, from
/// index `η₁` into `η₂` with `ratio = η₁/η₂`, or `None` where no light passes.
///
/// Split `d` into its part along the normal, `−cos θ₁·n`, and its part in the surface,
/// `t = d + cos θ₁·n` of length `sin θ₁`. Snell's law scales the part in the surface by the
/// ratio, `t₂ = ratio·t` with `‖t₂‖ = sin θ₂`, and the unit direction beyond is
/// `t₂ − √(1 − ‖t₂‖²)·n`: no light passes when `‖t₂‖ > 1`.
pub(crate) fn snell<F: Real>(d: DVec3<F>, n: DVec3<F>, ratio: F) -> Option<DVec3<F>> {
    let cos = -n.dot(d);
    let along_surface = (d + n * cos) * ratio;
    let sin2 = along_surface.length_squared();
    if sin2 > F::ONE {
        return None;
    }
    (along_surface - n * (F::ONE - sin2).sqrt()).try_normalize()
}

/// Schlick's share of light reflected at an angle with cosine `cos` to the normal, on a
/// surface between indices 1 and `index`.
fn schlick<F: Real>(index: F, cos: F) -> F {
    let r0 = (index - F::ONE) / (index + F::ONE);
    let r0 = r0 * r0;
    let x = F::ONE - unit_clamp(cos);
    r0 + (F::ONE - r0) * x.powi(5)
}

/// `x` clamped to `[0, 1]`, NaN to 0: `fmin(1, fmax(0, x))`.
fn unit_clamp<F: Real>(x: F) -> F {
    if x > F::ONE {
        F::ONE
    } else if x > F::ZERO {
        x
    } else {
        F::ZERO
    }
}

#[cfg(test)]
mod tests;
