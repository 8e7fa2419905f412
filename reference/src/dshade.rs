//! Shading in `f64` (or `f32`): lights, shadows, highlights and mirrors, as [`DScene::radiance`].

use super::dcolour::{DColour, add_weighted, background, linear};
use super::{DHit, DObject, DRay, DScene, DVec3, Real};

impl<const N: usize, const L: usize, F: Real> DScene<N, L, F> {
    /// The light arriving along `ray`, whose first hit is `hit`, in linear units (1.0 for a
    /// channel of 255), before clamping.
    ///
    /// With `d` the direction of the ray being followed, the colour is summed as the ray
    /// bounces, starting from weight 1:
    ///
    /// 1. no hit: add `weight ·` the background along `d`, and stop;
    /// 2. a hit: add `weight ·` the surface's own light (the `local` term of
    ///    [`DMaterial`](super::DMaterial)), and stop unless the material reflects;
    /// 3. a mirror: multiply the weight by `reflect` and leave the hit point along
    ///    `r = d − 2(d·n)n` (renormalised), `n` the normal facing the ray. The mirror ray is
    ///    shot among the other objects and the sum goes on from step 1, at most
    ///    [`depth`](Self::depth) times; the mirror ray after that sees only the background.
    ///
    /// So depth 0 still adds `reflect ·` the background seen along the first mirror ray; it
    /// stops mirrors showing other objects, not mirrors altogether.
    ///
    /// A hit whose `object` is not in the scene counts as a miss.
    #[must_use]
    pub fn radiance(&self, ray: &DRay<F>, hit: Option<&DHit<F>>) -> DColour<F> {
        let mut sum = [F::ZERO; 3];
        let mut weight = F::ONE;
        let mut dir = ray.dir();
        let mut hit = hit.copied();
        let mut bounce: u8 = 0;
        loop {
            let Some((h, object)) = hit.and_then(|h| Some((h, self.objects().get(h.object)?)))
            else {
                add_weighted(&mut sum, weight, background(&self.background(), dir));
                return sum;
            };
            let n = facing(h.normal, dir);
            add_weighted(&mut sum, weight, self.local(object, &h, n, dir));
            let reflect = object.material.reflect;
            if reflect == F::ZERO {
                return sum;
            }
            weight *= reflect;
            dir = (dir - n * (F::TWO * dir.dot(n)))
                .try_normalize()
                .unwrap_or(dir);
            if bounce == self.depth() {
                add_weighted(&mut sum, weight, background(&self.background(), dir));
                return sum;
            }
            hit = self.shoot_from(&DRay::new_unchecked(h.point, dir), Some(h.object));
            bounce += 1;
        }
    }

    /// The light a surface gives off by itself at `hit`, seen along `d`, with `n` its unit
    /// normal turned towards the eye (see [`DMaterial`](super::DMaterial)):
    ///
    /// `C·(ambient + diffuse·Σ I·(n·l)) + specular·Σ I·clamp(n·h, 0, 1)^shininess`
    ///
    /// summed over the lights in front of the surface (`n·l > 0`) and, with shadows on, not
    /// hidden by another object; `C` is the colour at the point (a checkerboard's square on a
    /// plane) and `h` the unit half vector of `l` and `−d`.
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
