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
//! exact integer floors (`isqrt`) of those 64-bit values. Floats appear only at set-up
//! (camera construction, `f32` inputs), never per pixel.
//!
//! # The overflow budget
//!
//! Inputs are checked to lie within ±[`LIMIT`] (1024) and hits beyond [`FAR`] (8192) are
//! misses, so hit points stay within ±9216 and every difference, squared length (below 2⁶¹)
//! and dot product of the render path fits its integer type. Nothing in the render path wraps:
//! [`Vec3`]'s operators saturate (the render path's own additions skip that check where the
//! budget rules overflow out, and debug builds check that it does), and divisions happen only
//! where the divisor is known to be non-zero and the quotient known to fit. Out-of-range input is an [`Error`], not a wrapped
//! picture.
//!
//! Cameras keep `F² + R² ≤ 16 384·F` (view distance `F`, half-diagonal `R`, in pixels), so
//! ray directions stay within 16 384 pixels and within half a pixel of exact. Every type that
//! carries a checked value ([`Ray`], [`Hit`], [`Sphere`], [`Plane`], [`Light`], [`Material`],
//! [`Scene`], [`Camera`]) keeps its fields private, so the render path only ever meets
//! values its constructors accepted.
//!
//! # Set-up
//!
//! Values are given as `f32` (`Sphere::new([0.0, 0.0, -10.0], 2.0)`), converted and checked
//! once (the `check` module). Each constructor has a `const` fixed-point form, `from_fx`, with
//! the same checks, so that a scene can be a `static` built at compile time.
//!
//! # The pipeline, layer by layer
//!
//! The source folders are the layers, each using only the ones above it:
//! - `numbers/`: [`Fx`] and its exact products, integer square roots (`isqrt`), reciprocals
//!   (a table-seeded reciprocal square root, and a table-seeded reciprocal for division),
//!   [`Vec3`].
//! - `error.rs` and `check.rs`: the [`Error`] a refused value gets, and the set-up checks
//!   that refuse it.
//! - `geometry/`: the chapter's [`Ray`] (Eq. 4.1), [`Plane`] (Eq. 4.2) and [`Sphere`]
//!   (section 4.4), pure intersection functions returning a [`Hit`], whose normal faces the
//!   ray; [`Shape`] is either; `refract.rs`, Snell's law and Schlick's approximation.
//! - `scene/`: the [`Scene`] that holds [`Object`]s (a shape and its [`Material`], perhaps a
//!   [`Checker`]), [`Light`]s and a [`Background`], in [`Rgb`] colours; its nearest hit is a
//!   [`SceneHit`], a [`Hit`] and the object it is on. A material may mirror and, as glass,
//!   refract ([`Refraction`]).
//! - `render/`: the [`Camera`] makes a ray through each pixel centre; `trace.rs` is the
//!   chapter's shoot and shade, read top to bottom ([`Scene::trace`] = `shade(shoot(ray))`,
//!   brute-force loops over every object and light, mirror and refracted rays followed as a
//!   tree from a bounded list, without recursion): the plain path, and the oracle.
//!   [`render_row`], [`render`], [`render_row_supersampled`] and [`shoot_row`] walk rows and
//!   frames into a [`Framebuffer`] or a row buffer ([`FrameHash`] digests them); `accel/`
//!   holds every speed-up of that walk ([`RowRays`], row culling, runs of columns, matte runs,
//!   the shadow sets and cones, the first surface's shading), each bit for bit the plain
//!   path's.
//!   `changes.rs` bounds the pixels an edit of the scene can change ([`Damage`]) and
//!   redraws only those ([`render_changes`], [`render_row_span`]), for animations;
//!   `progressive.rs` draws a frame in passes, coarse grids then whole rows ([`Pass`],
//!   [`render_pass_row`], [`render_pass`]) that end exactly on it, for a moving view.
//! - [`draw`]: onto any `embedded-graphics` display at a point, clipped to it: a
//!   [`Viewport`] drawn as one [`Picture`] (an embedded-graphics `Drawable`), band by band,
//!   or pass by pass ([`Viewport::render_pass`], each block one filled rectangle),
//!   in every embedded-graphics colour type ([`FromRgb`]), Bayer-dithered where a channel has
//!   fewer than 8 bits; [`DrawError`] for anything that draws
//! - `demo` (feature `demo`): the scenes the examples, tests and firmware share (demo and
//!   classic)
//! - features: `mirrors-and-glass` (on by default) follows mirror and refracted rays; without
//!   it that code is left out and such a material is refused
//!   ([`Error::MirrorsAndGlassLeftOut`]). `demo` and `internals` are off by default.
//! - an independent f64 model of the same maths is a crate of its own, `fixray-reference`
//!   (the `reference/` folder), which sees only this public API

#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs, rustdoc::broken_intra_doc_links)]

mod check;
mod chip;
#[cfg(feature = "demo")]
pub mod demo;
pub mod draw;
mod error;
mod framebuffer;
mod geometry;
mod hash;
#[cfg(feature = "internals")]
pub mod internals;
mod numbers;
mod render;
mod scene;
#[cfg(test)]
mod xorshift;

pub use draw::{DrawError, FromRgb, Picture, Viewport};
/// A position on a display, column `x` and row `y`: embedded-graphics' own, where a
/// [`Viewport`] is drawn.
pub use embedded_graphics::geometry::Point;
/// The size type of the camera builders and [`Camera::size`]: embedded-graphics' own, width
/// by height, so a display's size can be passed as it is.
pub use embedded_graphics::geometry::Size;
pub use error::{CameraProblem, Error, Quantity};
pub use framebuffer::Framebuffer;
pub use geometry::{Hit, Plane, Ray, Shape, Sphere};
pub use hash::FrameHash;
pub use numbers::{FAR, Fx, LIMIT, Vec3};
pub use render::{
    Camera, Columns, Damage, LookAt, MAX_PIXELS, MAX_RECTANGLES, MAX_SPACING, Orbit, Pass, Passes,
    Pinhole, RowRays, render, render_changes, render_pass, render_pass_row, render_row,
    render_row_span, render_row_supersampled, shoot_row,
};
pub use scene::{Background, Checker, Light, Material, Object, Refraction, Rgb, Scene, SceneHit};

/// The README's Rust examples, compiled and run as doc tests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
