//! The reference twins of [`fixray::demo`]'s cameras, built from the same `f32` constants.

use super::{DCamera, DVec3, Real};
use fixray::demo;

/// The twin of [`demo::camera`]: the chapter's pinhole camera with a screen
/// `SCREEN_HEIGHT · width / height` wide and [`demo::SCREEN_HEIGHT`] high at
/// [`demo::SCREEN_DISTANCE`], `width × height` pixels, in precision `F`. `None` for a screen
/// without pixels.
#[must_use]
pub fn demo_camera<F: Real>(width: u32, height: u32) -> Option<DCamera<F>> {
    let h = F::from_f64(f64::from(demo::SCREEN_HEIGHT));
    let w = h * F::from_f64(f64::from(width)) / F::from_f64(f64::from(height));
    let z_p = F::from_f64(f64::from(demo::SCREEN_DISTANCE));
    DCamera::pinhole(w, h, z_p, width, height)
}

/// The twin of [`demo::classic_camera`]: the look-at camera at the origin looking down −z with
/// a [`demo::CLASSIC_FOV_DEGREES`] vertical field of view, `width × height` pixels, in
/// precision `F`.
#[must_use]
pub fn classic_camera<F: Real>(width: u32, height: u32) -> Option<DCamera<F>> {
    let fov = F::from_f64(f64::from(demo::CLASSIC_FOV_DEGREES));
    DCamera::look_at(DVec3::ZERO, -DVec3::Z, DVec3::Y, fov, width, height)
}
