//! An independent `f64` model of fixray's raycaster, for testing the Q16.16 renderer against.
//!
//! A crate of its own, so the compiler sees to it that it uses only fixray's public API. It
//! follows the same chapter (sections 4.1–4.4) and the same shading model as the fixed-point
//! core but shares none of its code: its types are `f64` twins named with a `D` prefix
//! ([`DVec3`], [`DRay`], [`DPlane`], [`DSphere`], [`DHit`], [`DCamera`], [`DLight`],
//! [`DMaterial`], [`DScene`]), so a mistake in one model shows up as a disagreement with the
//! other rather than being copied into both. Plain data it shares with the fixed side:
//! [`Rgb`](fixray::Rgb) colours and the [`Background`](fixray::Background) gradient's two ends.
//!
//! # In `f32`
//!
//! Every type takes its float as a last type parameter, [`Real`], which is `f64` unless named:
//! `DScene<8>` is `DScene<8, 4, f64>`, `DCamera` is `DCamera<f64>`. Naming `f32` instead
//! (`DScene<8, 4, f32>`, `DCamera<f32>`) runs the same model in single precision throughout:
//! the float baseline for chips whose FPU, like the Cortex-M4F's, has only `f32`. How far the
//! `f32` picture is from the `f64` one is measured in fixray's `tests/reference_f32.rs`.
//!
//! The pipeline is the chapter's raycasting loop:
//!
//! 1. [`DCamera::ray`] builds the ray through the *pixel centre* of a display pixel
//!    (Equation 4.1: `x(t) = p_r + t·u_r`, `t ≥ 0`);
//! 2. [`DScene::shoot`] intersects it with every object — planes (or rectangles of them) by
//!    Equation 4.2, spheres by the two-step `t_close` method — and keeps the nearest [`DHit`];
//! 3. [`DScene::radiance`] lights that hit: ambient, diffuse and a white highlight from every
//!    light that is not in shadow, a checkerboard on planes, and mirror bounces followed in a
//!    loop, with a gradient background where rays escape; [`DScene::shade`] rounds the sum
//!    ([`DColour`], 1.0 for 255) to an 8-bit pixel;
//! 4. [`render_row`] and [`render`] repeat this for every pixel, row 0 at the top.
//!
//! Everything is `no_std` and allocation-free; square roots, powers, floors and tangents come
//! from `libm` (`sqrt` in `f64`, `sqrtf` in `f32`, and so on), so the model computes the same
//! numbers under `cargo test` on a host as on a microcontroller. Colours are fixray's own [`Rgb`](fixray::Rgb), so pictures from the two
//! models compare directly.
//!
//! ```
//! use fixray_reference::{demo_camera, render, DScene};
//! use fixray::{demo, Rgb};
//!
//! // The demo scene and camera, in both models.
//! let scene = demo::scene();
//! let camera = demo::camera(8, 6)?;
//! let twin = DScene::from_scene(&scene).unwrap();
//! let twin_camera = demo_camera::<f64>(8, 6).unwrap();
//!
//! let mut frame = [Rgb::BLACK; 6 * 8];
//! render(&twin, &twin_camera, &mut frame);
//! assert_eq!(frame[0], demo::BACKGROUND); // the top-left pixel is sky
//! for (x, y) in [(0, 0), (2, 3), (7, 5)] {
//!     // Both models see the same object through each pixel.
//!     let fixed = scene.shoot(&camera.ray(x, y)).map(|hit| hit.object());
//!     let reference = twin.shoot(&twin_camera.ray(x, y)).map(|hit| hit.object);
//!     assert_eq!(fixed, reference);
//! }
//! # Ok::<(), fixray::Error>(())
//! ```

#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs, rustdoc::broken_intra_doc_links)]

mod dcamera;
mod dcolour;
mod demo;
mod dhit;
mod dlight;
mod dmaterial;
mod dobject;
mod dplane;
mod dray;
mod dscene;
mod dshade;
mod dsphere;
mod dvec3;
mod from_fixed;
mod real;
mod render;

pub use dcamera::DCamera;
pub use dcolour::DColour;
pub use demo::{classic_camera, demo_camera};
pub use dhit::DHit;
pub use dlight::DLight;
pub use dmaterial::{DChecker, DMaterial, DRefraction};
pub use dobject::{DObject, DShape};
pub use dplane::DPlane;
pub use dray::DRay;
pub use dscene::DScene;
pub use dsphere::DSphere;
pub use dvec3::{DVec3, ToF64};
pub use real::Real;
pub use render::{render, render_row, render_row_supersampled};

/// The far clip: a hit farther along the ray than this is a miss, as in the fixed renderer.
///
/// A hit exactly at `FAR` still counts.
pub const FAR: f64 = 8192.0;
