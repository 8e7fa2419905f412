//! [`Accuracy`]: the fixed-point renderer measured against the f64 reference, pixel by pixel.
//!
//! The measuring lives with the tests, not in the reference model: the model knows nothing of
//! fixray's renderer. Included with `#[path]` by the tests and by `examples/accuracy.rs`.
#![allow(dead_code)] // each user of this module reads a different part of it

use fixray::{Camera, Rgb, Scene};
use fixray_reference::{DCamera, DRay, DScene, DVec3};

/// How far a pixel's reference colour may move, in each channel, for the pixel to be stable.
pub const STABLE_WITHIN: u8 = 4;

/// One Q16.16 step, 2⁻¹⁶: the grid fixray rounds each component of a ray's unit direction to.
const STEP: f64 = 1.0 / 65_536.0;

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
    /// Pixels that are stable in the reference (see [`stable`]).
    pub stable: u32,
    /// The largest channel difference over the stable pixels, object mismatches included.
    pub max_stable_error: u8,
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
        Self::measure_each(scene, camera, dscene, dcamera, |_| {})
    }

    /// [`Accuracy::measure`], also handing each [`Pixel`] compared to `each`, in rows from the
    /// top: for a difference image, or to find where the errors are.
    pub fn measure_each<const N: usize, const L: usize>(
        scene: &Scene<N, L>,
        camera: &Camera,
        dscene: &DScene<N, L>,
        dcamera: &DCamera,
        mut each: impl FnMut(&Pixel),
    ) -> Self {
        let mut acc = Accuracy::default();
        for row in 0..camera.height() {
            for col in 0..camera.width() {
                let ray = camera.ray(col, row);
                let hit = scene.shoot(&ray);
                let seen = scene.shade(&ray, hit.as_ref());
                let dray = dcamera.ray(col, row);
                let (dhit, dseen) = dscene.trace(&dray);
                let pixel = Pixel {
                    x: col,
                    y: row,
                    seen,
                    reference: dseen,
                    object: hit.map(|h| h.object()),
                    reference_object: dhit.map(|h| h.object),
                    stable: stable(dscene, &dray, dseen),
                };
                let same = pixel.object == pixel.reference_object;
                acc.add(&pixel);
                each(&pixel);
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

    fn add(&mut self, pixel: &Pixel) {
        let same_object = pixel.object == pixel.reference_object;
        let diffs = channel_errors(pixel.seen, pixel.reference);
        let worst = pixel.error();
        self.pixels += 1;
        self.same_object += same_object as u32;
        self.within_2 += (worst <= 2) as u32;
        self.within_4 += (worst <= 4) as u32;
        self.same_within_4 += (same_object && worst <= 4) as u32;
        if same_object {
            self.max_channel_error = self.max_channel_error.max(worst);
        }
        self.max_channel_error_any = self.max_channel_error_any.max(worst);
        if pixel.stable {
            self.stable += 1;
            self.max_stable_error = self.max_stable_error.max(worst);
        }
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

    /// Share of pixels that are stable in the reference, in percent.
    #[must_use]
    pub fn stable_percent(&self) -> f64 {
        percent(self.stable, self.pixels)
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

/// One pixel as both renderers saw it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pixel {
    /// The column, from the left.
    pub x: u32,
    /// The row, from the top.
    pub y: u32,
    /// fixray's colour.
    pub seen: Rgb,
    /// The reference's colour.
    pub reference: Rgb,
    /// The object fixray's ray hit first (its index in the scene), if any.
    pub object: Option<usize>,
    /// The object the reference's ray hit first, if any.
    pub reference_object: Option<usize>,
    /// Whether the pixel is stable in the reference (see [`stable`]).
    pub stable: bool,
}

impl Pixel {
    /// The largest of the three channels' differences.
    #[must_use]
    pub fn error(&self) -> u8 {
        channel_errors(self.seen, self.reference)
            .into_iter()
            .max()
            .unwrap_or(0)
    }
}

/// Whether the reference's colour of the pixel whose ray is `ray` (`colour`) is stable: it
/// moves by at most [`STABLE_WITHIN`] in every channel when the ray's direction moves by each
/// of the 14 [`MOVES`], 2⁻¹⁶ in one component or in all three.
///
/// The direction is what moves, not the pixel centre on the screen, because the direction is
/// what fixray rounds: its camera's ray carries its unit direction `u_r` in Q16.16, each
/// component within 2⁻¹⁷ of exact, and spheres, highlights and every mirrored or refracted
/// ray follow that rounded `u_r` (planes are met along the unrounded direction towards the
/// pixel, so for them this asks more than fixray's rounding needs). A move of 2⁻¹⁶ a
/// component is twice that rounding. The moved direction is normalised again, so a move
/// along `u_r` itself turns it less.
fn stable<const N: usize, const L: usize>(dscene: &DScene<N, L>, ray: &DRay, colour: Rgb) -> bool {
    MOVES.iter().all(|&(x, y, z)| {
        let step = DVec3::new(x, y, z) * STEP;
        // A unit vector moved by at most 2⁻¹⁶·√3 keeps a direction.
        DRay::new(ray.origin(), ray.dir() + step).is_some_and(|moved| {
            let seen = dscene.trace(&moved).1;
            channel_errors(seen, colour)
                .iter()
                .all(|&d| d <= STABLE_WITHIN)
        })
    })
}

/// The moves of a direction that [`stable`] tries, in steps of 2⁻¹⁶: each axis either way,
/// and the eight corners, where fixray's rounding of all three components can take it at
/// once. (All 26 neighbours on the grid of steps find the same stable pixels, at every size
/// `examples/accuracy.rs` measures, at twice the cost.)
const MOVES: [(f64, f64, f64); 14] = [
    (1.0, 0.0, 0.0),
    (-1.0, 0.0, 0.0),
    (0.0, 1.0, 0.0),
    (0.0, -1.0, 0.0),
    (0.0, 0.0, 1.0),
    (0.0, 0.0, -1.0),
    (1.0, 1.0, 1.0),
    (1.0, 1.0, -1.0),
    (1.0, -1.0, 1.0),
    (1.0, -1.0, -1.0),
    (-1.0, 1.0, 1.0),
    (-1.0, 1.0, -1.0),
    (-1.0, -1.0, 1.0),
    (-1.0, -1.0, -1.0),
];

/// The three channels' differences between two colours.
#[must_use]
pub fn channel_errors(a: Rgb, b: Rgb) -> [u8; 3] {
    [a.r.abs_diff(b.r), a.g.abs_diff(b.g), a.b.abs_diff(b.b)]
}

fn percent(part: u32, whole: u32) -> f64 {
    100.0 * part as f64 / whole.max(1) as f64
}
