//! Numbers: the one scalar, [`Fx`] (Q16.16), its exact 64-bit products, integer square roots,
//! reciprocals, and the three-vector [`Vec3`] built on them.
//!
//! Everything above this layer computes with these and nothing else: no floats after set-up.

pub(crate) mod bits;
pub(crate) mod fx;
pub(crate) mod isqrt;
pub(crate) mod reciprocal;
pub(crate) mod split;
pub(crate) mod vec3;

pub use fx::{FAR, Fx, LIMIT};
pub use vec3::Vec3;
