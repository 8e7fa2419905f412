//! Hostile inputs and the oracles that judge fixray on them, shared by `tests/hostile.rs` (a
//! seeded xorshift drives the choices) and the `cargo fuzz` target in `fuzz/` (libFuzzer's bytes
//! drive them). Both see the same generators and the same assertions; only the source of the
//! choices differs.
//!
//! Only fixray's public API is used, and every expected value is worked out here independently:
//! exact integer or `f64` arithmetic on the Q16.16 values, brute-force loops over the objects,
//! and the chapter's formulas for the camera.
//!
//! One concept a file, declared and re-exported here so that users name everything
//! `common::…`:
//! - `random`: [`Source`], where the choices come from, and the seeded [`XorShift`];
//! - `values`: hostile `f32`s, Q16.16 numbers, vectors and directions;
//! - `world`: generated scenes ([`World`] around a [`View`]);
//! - `camera_spec`: generated cameras ([`CameraSpec`]) and when fixray must refuse them;
//! - `exact`: `f64` arithmetic on Q16.16 values, and the chapter's camera in `f64`;
//! - `check_camera`, `check_hit`, `check_row`, `check_progressive`: the oracles for cameras,
//!   hits, rows and progressive passes;
//! - `drawing`: a recording display ([`Recorder`]) and the oracles for drawing;
//! - `case`: one random [`Case`] and every check run on it.
//!
//! `accuracy.rs` sits here too but is not declared: it measures fixray against the
//! `fixray-reference` model, which the fuzz crate does not depend on, so its users
//! (`tests/accuracy.rs`, `tests/edges.rs`, `examples/accuracy.rs`) include it alone with
//! `#[path]`.
#![allow(dead_code)] // each user of this module calls a different part of it

mod camera_spec;
mod case;
mod check_camera;
mod check_hit;
mod check_progressive;
mod check_row;
mod drawing;
mod exact;
mod random;
mod values;
mod world;

// Each user names a different part of the module, as with dead code above.
#[allow(unused_imports)]
pub use self::{
    camera_spec::{CameraSpec, camera_spec},
    case::{Case, case, run_case},
    check_camera::{check_camera_spec, check_rays, check_rays_past_the_screen},
    check_hit::{check_hit, check_surface_through_origin},
    check_progressive::check_progressive,
    check_row::{check_row, check_shadows, check_supersampled, occluded},
    drawing::{Recorder, check_framebuffer, check_viewport, corner},
    exact::{ToF64, ULP, UNIT_TOLERANCE, length},
    random::{Source, XorShift},
    values::{direction, f32_around, fx_any, vec_any, vec_within},
    world::{ClampLimit, View, World, world},
};
