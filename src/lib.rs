//! fixray: a raycaster in Q16.16 fixed point for microcontrollers without a floating-point
//! unit, and for every other place `embedded-graphics` draws.
//!
//! It follows the raycasting chapter it was built from (sections 4.1–4.4): a pinhole camera
//! shoots one ray through the centre of each pixel ([`Camera`], [`Ray`]), the ray is
//! intersected with planes (Eq. 4.2, [`Plane`]) and spheres (the two-step `t_close` test,
//! [`Sphere`]), the nearest hit wins ([`Scene::shoot`]) and is lit ([`Scene::shade`]). The
//! render path uses no floats, no allocator and no panics.
//!
//! ```
//! use fixray::{demo, render, Framebuffer};
//! let scene = demo::scene();
//! let camera = demo::camera(40, 32)?;
//! let mut frame = Framebuffer::<40, 32>::new();
//! render(&scene, &camera, &mut frame)?;
//! // Top row: sky. Bottom row: the ground plane.
//! assert_eq!(frame.pixel(0, 0), Some(demo::BACKGROUND));
//! assert_ne!(frame.pixel(0, 31), Some(demo::BACKGROUND));
//! # Ok::<(), fixray::Error>(())
//! ```
//!
//! # Numbers
//!
//! One scalar, [`Fx`] (Q16.16: 16 integer bits, 16 fractional, a step of 2⁻¹⁶ ≈ 1.5 × 10⁻⁵).
//! Products and dot products are formed exactly at 64 bits and rounded once; square roots are
//! exact integer floors ([`isqrt`]) of those 64-bit values. Floats appear only at set-up
//! (camera construction, `f32` inputs), never per pixel.
//!
//! # The overflow budget
//!
//! Inputs are checked to lie within ±[`LIMIT`] (1024) and hits beyond [`FAR`] (8192) are
//! misses, so hit points stay within ±9216 and every difference, squared length (below 2⁶¹)
//! and dot product of the render path fits its integer type. Nothing in the render path wraps:
//! [`Vec3`] arithmetic saturates, and divisions happen only where the divisor is known to be
//! non-zero and the quotient known to fit. Out-of-range input is an [`Error`], not a wrapped
//! picture.
//!
//! Cameras keep `F² + R² ≤ 16 384·F` (view distance `F`, half-diagonal `R`, in pixels), so
//! ray directions stay within 16 384 pixels and within half a pixel of exact. [`Ray`], [`Hit`],
//! [`Material`] and [`Light`] have public fields, so a caller can build one outside these
//! checks: the public functions that take them bound each direction and normal component to
//! ±2 and saturate weights, which keeps every product in range (the picture is then not the
//! documented one, but nothing panics or wraps).
//!
//! # Modules
//! - numbers: [`Fx`], [`mul`], [`isqrt`], [`Vec3`]
//! - geometry: [`Ray`], [`Plane`], [`Sphere`], [`Hit`]
//! - viewing: [`Camera`], and [`RowRays`], a row of its rays for a few additions each
//! - the world: [`Scene`], [`Object`], [`Shape`], [`Material`], [`Checker`], [`Light`],
//!   [`Background`], [`Rgb`]
//! - output: [`render`], [`render_row`], [`render_row_supersampled`], [`shoot_row`],
//!   [`shoot_row_skipping`],
//!   [`Framebuffer`], [`FrameHash`]
//! - [`draw`]: onto any `embedded-graphics` display at a point, clipped to it: a
//!   [`Viewport`] drawn as one [`Picture`] (an embedded-graphics `Drawable`) or band by band,
//!   in every embedded-graphics colour type ([`FromRgb`]), Bayer-dithered where a channel has
//!   fewer than 8 bits; [`DrawError`] for anything that draws
//! - [`demo`]: the scenes the examples, tests and firmware share (demo and classic)
//! - `reference` (feature `reference`): an independent f64 model of the same maths

#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs, rustdoc::broken_intra_doc_links)]

mod background;
mod camera;
mod color;
mod cone;
pub mod demo;
mod divide;
pub mod draw;
mod error;
mod framebuffer;
mod fx;
mod hash;
mod hit;
mod isqrt;
mod light;
mod lighting;
mod material;
mod plane;
mod ray;
mod render;
mod row_rays;
mod rsqrt;
mod runs;
mod scene;
mod shading;
mod sphere;
mod vec3;
#[cfg(test)]
mod xorshift;

#[cfg(feature = "reference")]
pub mod reference;

pub use background::Background;
pub use camera::{Camera, MAX_PIXELS};
pub use color::Rgb;
pub use draw::{DrawError, FromRgb, Picture, Viewport};
pub use error::Error;
pub use framebuffer::Framebuffer;
pub use fx::{FAR, Fx, LIMIT, fx_from_f32, mul};
pub use hash::FrameHash;
pub use hit::Hit;
pub use isqrt::isqrt;
pub use light::Light;
pub use material::{Checker, Material};
pub use plane::Plane;
pub use ray::Ray;
pub use render::{render, render_row, render_row_supersampled, shoot_row, shoot_row_skipping};
pub use row_rays::RowRays;
pub use scene::{Object, Scene, Shape};
pub use sphere::Sphere;
pub use vec3::Vec3;

/// The README's Rust examples, compiled and run as doc tests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
