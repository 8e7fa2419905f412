//! The speed-ups of the render path, each bit-identical to the plain path it replaces:
//!
//! - `camera_rows`: what the row walk asks of the camera (a row's first direction and column
//!   step, the plane of a row's rays, a sphere's span of columns);
//! - `crowd`: a row's objects named by its 64 bits, in scenes that may hold more;
//! - `crowd_floor`: in scenes of more than 32 objects, the objects that may shadow each column
//!   of a row's floor from each light, for its shadow rays to try;
//! - `crowd_spheres`: in those, the objects that may shadow the sphere a row's pixels
//!   last met, from each light, for its shadow rays to try;
//! - `row_rays`: a row's rays by exact column steps, their squared lengths carried along;
//! - `runs`: a row cut into runs of columns that can meet the same objects (culling by the
//!   row's plane, each sphere's column span, and planes every ray of a run points away from);
//! - `run_ends`: a crowded row's span ends sorted by column, which its runs are found from;
//! - `shadow_rows`: the spheres that can shadow a row's hits on planes, from each light;
//! - `shadow_columns`: the columns of a run on a plane that a sphere can shadow;
//! - `matte`: a run that can meet one matte plane only, on a row parallel to it, found by
//!   additions and shaded in one loop, without rays;
//! - `sky`: a run that can meet nothing, under a gradient sky, from one component of each
//!   ray's direction, without rays;
//! - `shade`: a first hit's light, each shadow ray trying only the objects the sets below
//!   leave, and a highlight formed only where it is not 0;
//! - `shadow_cone`: each light's cone around each sphere, which a shadow ray outside it cannot
//!   meet;
//! - `shadowers`: for each light and object, the objects that can shadow it;
//! - `shadow_sweep`: past 32 objects, each light's objects sorted by the directions their
//!   shadows take, for a shadow ray to find those it may meet;
//! - `shadow_caches`: the two kept in the scene, worked out again whenever an object or a
//!   light changes (the scene knows no more of them than that).

pub(crate) mod camera_rows;
pub(crate) mod crowd;
pub(crate) mod crowd_floor;
pub(crate) mod crowd_spheres;
pub(crate) mod cull;
pub(crate) mod matte;
pub(crate) mod row_rays;
pub(crate) mod run_ends;
pub(crate) mod runs;
pub(crate) mod shade;
pub(crate) mod shadow_caches;
pub(crate) mod shadow_columns;
pub(crate) mod shadow_cone;
pub(crate) mod shadow_rows;
pub(crate) mod shadow_sweep;
pub(crate) mod shadowers;
pub(crate) mod sky;
