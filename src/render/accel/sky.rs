//! [`Scene::paint_sky`]: a run of columns that can meet nothing, under a gradient sky.
//!
//! A gradient reads one component of a ray's direction, its height (`Background::along`). A
//! run that can meet nothing gets a ray a column only to have that read, so here each
//! column takes the component alone, as the unit vector's normalisation forms it
//! (`Vec3::unit_component_with_square`, bit for bit), from the direction towards its pixel,
//! stepped along the row as the rays' walk steps it: the pixels are [`Scene::trace`]'s. (A
//! plain sky needs not even that: `render_row` fills its runs.)

use crate::numbers::fx::Fx;
use crate::numbers::vec3::Vec3;
use crate::render::accel::row_rays::RowSquares;
use crate::render::camera::Camera;
use crate::scene::Scene;
use crate::scene::background::Blend;
use crate::scene::colour::Rgb;
use crate::scene::linear::rgb_of;

impl<const N: usize, const L: usize> Scene<N, L> {
    /// The background's pixels for a run of columns of display row `row` that can meet
    /// nothing, from column `first` and on every `stride`th column (a stride that keeps
    /// `out`'s columns on the screen), one for each pixel of `out`.
    pub(crate) fn paint_sky(
        &self,
        camera: &Camera,
        row: u16,
        first: u16,
        stride: u16,
        out: &mut [Rgb],
    ) {
        let step = camera.column_step().steps(stride.into());
        // Where a run's walk along the row starts (`Camera::row_start`).
        let mut towards = camera.towards(first.into(), row.into());
        let mut square = RowSquares::new(towards, step);
        // The background's blend, as `Background::along_height` forms it, with its ends
        // converted once.
        let blend = Blend::of(&self.background());
        for pixel in out.iter_mut() {
            // A zero direction makes the zero ray (`Camera::ray_along`), whose height is 0.
            let height = Vec3::unit_component_with_square(towards.y, square.now(towards));
            *pixel = rgb_of(blend.at(height.unwrap_or(Fx::ZERO)));
            towards = towards.plus(step);
            square.step();
        }
    }
}
