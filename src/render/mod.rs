//! Rendering: the [`Camera`] that makes a ray for each pixel, the chapter's shoot and shade
//! (`shade.rs` lights a hit), the rows and frames that users call ([`render_row`] and the
//! rest), progressive passes over a frame (`progressive.rs`), and `accel`, the speed-ups of the
//! row walk.
//!
//! Every acceleration in `accel` is bound by one contract: a row it renders is bit for bit the
//! row of pixels each traced on its own with [`Scene::trace`](crate::Scene::trace) of
//! [`Camera::ray`]. `tests/render_row.rs` is that contract's oracle.

pub(crate) mod accel;
pub(crate) mod camera;
pub(crate) mod changes;
pub(crate) mod highlight;
pub(crate) mod pick;
pub(crate) mod progressive;
pub(crate) mod rows;
pub(crate) mod trace;

pub use accel::row_rays::RowRays;
pub use camera::{Camera, LookAt, MAX_PIXELS, Orbit, Pinhole};
pub use changes::{Damage, MAX_RECTANGLES, render_changes, render_row_span};
pub use progressive::{Columns, MAX_SPACING, Pass, Passes, render_pass, render_pass_row};
#[cfg(feature = "internals")]
pub use rows::shoot_row_skipping;
pub use rows::{render, render_row, render_row_supersampled, shoot_row};
