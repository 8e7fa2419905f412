//! [`Accuracy`]: the fixed-point renderer measured against the f64 reference, pixel by pixel.
//!
//! The measuring lives with the tests, not in the reference model: the model knows nothing of
//! fixray's renderer. Included with `#[path]` by the tests and by `examples/accuracy.rs`.
#![allow(dead_code)] // each user of this module reads a different part of it

use fixray::{Camera, Rgb, Scene};
use fixray_reference::{DCamera, DScene};

/// How closely a fixed-point render matches the f64 reference, over every pixel of a frame.
///
/// Both renderers shoot the ray through each pixel centre, each with its own camera, and the
/// counts below compare what they saw.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Accuracy {
    /// Pixels compared.
    pub pixels: u32,
    /// Pixels where both saw the same object, or both saw nothing.
    pub same_object: u32,
    /// Pixels (of all) whose three channels are each within ±2 of the reference.
    pub within_2: u32,
    /// Pixels (of all) whose three channels are each within ±4 of the reference.
    pub within_4: u32,
    /// Pixels where the object agrees and all three channels are within ±4.
    pub same_within_4: u32,
    /// The largest channel difference where the object agrees.
    pub max_channel_error: u8,
    /// The largest channel difference anywhere, object mismatches included.
    pub max_channel_error_any: u8,
    /// Sum of squared channel differences over all pixels, for the PSNR.
    pub squared_error: f64,
    /// The largest |t_fixed − t_f64| where both hit the same object.
    pub max_dt: f64,
    /// The largest |t_fixed − t_f64| / t_f64 where both hit the same object.
    pub max_dt_relative: f64,
}

impl Accuracy {
    /// Renders every pixel of `camera`'s screen with both renderers and compares them.
    ///
    /// `camera` and `dcamera` must describe the same screen; the reference scene is the fixed
    /// one converted ([`DScene::from_scene`]).
    #[must_use]
    pub fn measure<const N: usize, const L: usize>(
        scene: &Scene<N, L>,
        camera: &Camera,
        dscene: &DScene<N, L>,
        dcamera: &DCamera,
    ) -> Self {
        Self::measure_each(scene, camera, dscene, dcamera, |_, _, _, _| {})
    }

    /// [`Accuracy::measure`], also handing each pixel's position and both colours (fixed,
    /// reference) to `each`: for a difference image.
    pub fn measure_each<const N: usize, const L: usize>(
        scene: &Scene<N, L>,
        camera: &Camera,
        dscene: &DScene<N, L>,
        dcamera: &DCamera,
        mut each: impl FnMut(u32, u32, Rgb, Rgb),
    ) -> Self {
        let mut acc = Accuracy::default();
        for row in 0..camera.height() {
            for col in 0..camera.width() {
                let ray = camera.ray(col, row);
                let hit = scene.shoot(&ray);
                let seen = scene.shade(&ray, hit.as_ref());
                let (dhit, dseen) = dscene.trace(&dcamera.ray(col, row));
                let same = hit.map(|h| h.object()) == dhit.map(|h| h.object);
                acc.add(seen, dseen, same);
                each(row, col, seen, dseen);
                if let (Some(h), Some(d), true) = (hit, dhit, same) {
                    let dt = (h.hit().t().to_num::<f64>() - d.t).abs();
                    acc.max_dt = acc.max_dt.max(dt);
                    if d.t > 0.0 {
                        acc.max_dt_relative = acc.max_dt_relative.max(dt / d.t);
                    }
                }
            }
        }
        acc
    }

    fn add(&mut self, seen: Rgb, reference: Rgb, same_object: bool) {
        let diffs = [
            seen.r.abs_diff(reference.r),
            seen.g.abs_diff(reference.g),
            seen.b.abs_diff(reference.b),
        ];
        let worst = diffs.iter().copied().max().unwrap_or(0);
        self.pixels += 1;
        self.same_object += same_object as u32;
        self.within_2 += (worst <= 2) as u32;
        self.within_4 += (worst <= 4) as u32;
        self.same_within_4 += (same_object && worst <= 4) as u32;
        if same_object {
            self.max_channel_error = self.max_channel_error.max(worst);
        }
        self.max_channel_error_any = self.max_channel_error_any.max(worst);
        self.squared_error += diffs.iter().map(|&d| (d as f64) * (d as f64)).sum::<f64>();
    }

    /// Share of pixels where the object agrees, in percent.
    #[must_use]
    pub fn same_object_percent(&self) -> f64 {
        percent(self.same_object, self.pixels)
    }

    /// Share of pixels within ±2 per channel, in percent.
    #[must_use]
    pub fn within_2_percent(&self) -> f64 {
        percent(self.within_2, self.pixels)
    }

    /// Share of the pixels whose object agrees that are within ±4 per channel, in percent.
    #[must_use]
    pub fn same_within_4_percent(&self) -> f64 {
        percent(self.same_within_4, self.same_object)
    }

    /// Share of pixels within ±4 per channel, in percent.
    #[must_use]
    pub fn within_4_percent(&self) -> f64 {
        percent(self.within_4, self.pixels)
    }

    /// Peak signal-to-noise ratio over all channels, in dB (infinite for identical pictures).
    #[must_use]
    pub fn psnr_db(&self) -> f64 {
        let mse = self.squared_error / (3.0 * self.pixels.max(1) as f64);
        if mse == 0.0 {
            f64::INFINITY
        } else {
            10.0 * libm::log10(255.0 * 255.0 / mse)
        }
    }
}

fn percent(part: u32, whole: u32) -> f64 {
    100.0 * part as f64 / whole.max(1) as f64
}
