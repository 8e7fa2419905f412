//! [`ShadowCaches`]: what the shadow rays' speed-ups keep in a [`Scene`](crate::Scene), worked
//! out again whenever an object or a light changes, so that a render reads them and never
//! builds them.
//!
//! The scene holds one and calls [`ShadowCaches::refresh_object`] or
//! [`ShadowCaches::refresh_light`] on every change; nothing else of the scene knows what is
//! in it. Both are `const fn`, so a `static` scene's caches are built by the compiler.

use crate::render::accel::shadow_cone::ShadowCone;
use crate::render::accel::shadow_sweep;
use crate::render::accel::shadowers::shadowers;
use crate::scene::{Light, Object};

/// Each light's [`ShadowCone`] around each object, and the objects that can shadow each
/// object from each light ([`shadowers`]), or in a scene of more than 32 objects each light's
/// shadow sweep (`shadow_sweep`).
#[derive(Debug, Clone)]
pub(crate) struct ShadowCaches<const N: usize, const L: usize> {
    /// `cones[light][object]`: what each light sees of each sphere.
    cones: [[ShadowCone; N]; L],
    /// `shadowers[light][object]`: the objects a shadow ray towards each light from a hit on
    /// each object may meet (bit `i` for object `i`, below 32); past 32 objects, the light's
    /// sweep.
    shadowers: [[u32; N]; L],
}

impl<const N: usize, const L: usize> ShadowCaches<N, L> {
    /// For a scene of no object: every cone tested, every object a possible shadower.
    pub(crate) const NONE: Self = ShadowCaches {
        cones: [[ShadowCone::ALWAYS; N]; L],
        shadowers: [[!0; N]; L],
    };

    /// Works out again every light's cone around object `index` of `objects` (which must be
    /// one of them), and which objects can shadow which, since that depends on it.
    pub(crate) const fn refresh_object(
        &mut self,
        index: usize,
        objects: &[Object],
        lights: &[Light],
    ) {
        let mut light = 0;
        while light < lights.len() {
            self.cones[light][index] =
                ShadowCone::new(lights[light].position, &objects[index].shape);
            self.refresh_shadowers(light, objects, lights);
            light += 1;
        }
    }

    /// Works out again light `index`'s cone around every object, and which objects can
    /// shadow which from it (the light must be one of `lights`).
    pub(crate) const fn refresh_light(
        &mut self,
        index: usize,
        objects: &[Object],
        lights: &[Light],
    ) {
        let mut object = 0;
        while object < objects.len() {
            self.cones[index][object] =
                ShadowCone::new(lights[index].position, &objects[object].shape);
            object += 1;
        }
        self.refresh_shadowers(index, objects, lights);
    }

    /// Works out again which objects can shadow each object from light `light`, or past 32
    /// objects the light's sweep.
    const fn refresh_shadowers(&mut self, light: usize, objects: &[Object], lights: &[Light]) {
        if objects.len() > 32 {
            if objects.len() <= shadow_sweep::MOST {
                let position = lights[light].position;
                shadow_sweep::build(position, objects, &mut self.shadowers[light]);
            }
            return;
        }
        let position = lights[light].position;
        let mut object = 0;
        while object < objects.len() {
            self.shadowers[light][object] = shadowers(position, object, objects);
            object += 1;
        }
    }

    /// Light `light`'s cones, by object; `None` for a light the scene does not have.
    pub(crate) fn cones(&self, light: usize) -> Option<&[ShadowCone; N]> {
        self.cones.get(light)
    }

    /// Light `light`'s sweep of a scene of `count` objects, more than 32 and at most
    /// `shadow_sweep::MOST`; `None` for other scenes or a light out of range.
    pub(crate) fn sweep(&self, light: usize, count: usize) -> Option<&[u32]> {
        if count <= 32 || count > shadow_sweep::MOST {
            return None;
        }
        self.shadowers.get(light)?.get(..count)
    }

    /// The objects (below 32) a shadow ray towards light `light` from a hit on object
    /// `receiver` may meet; `None` for a light or an object out of range.
    pub(crate) fn shadowers(&self, light: usize, receiver: usize) -> Option<u32> {
        self.shadowers.get(light)?.get(receiver).copied()
    }
}
