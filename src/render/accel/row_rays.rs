//! [`RowRays`]: the rays of a display row, in column order, for a few additions each before
//! normalising; and [`RowSquares`], the squared lengths that make that possible.

use crate::error::Error;
use crate::geometry::ray::Ray;
use crate::numbers::vec3::Vec3;
use crate::render::camera::Camera;

/// The rays through the pixels of one display row, left to right: [`Camera::row_rays`].
///
/// Each is the very ray [`Camera::ray`] gives for its pixel, bit for bit, but found for less:
/// the direction towards the next pixel is this one's plus one column step, and its squared
/// length needs no products on the Cortex-M0 (it is carried along the row by additions), so
/// a ray costs one normalisation and little besides.
///
/// ```
/// use fixray::demo;
/// let camera = demo::camera(160, 128).unwrap();
/// for (col, ray) in (0..).zip(camera.row_rays(40)?) {
///     assert_eq!(ray, camera.ray(col, 40));
/// }
/// assert_eq!(camera.row_rays(40)?.count(), 160);
/// assert_eq!(camera.row_rays(40)?.nth(100), Some(camera.ray(100, 40)));
/// assert!(camera.row_rays(128).is_err()); // past the bottom row
/// # Ok::<(), fixray::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct RowRays<'a> {
    camera: &'a Camera,
    towards: Vec3,
    step: Vec3,
    squares: RowSquares,
    left: u16,
}

// Here rather than in `camera.rs`, so that the camera knows nothing of its accelerations.
impl Camera {
    /// The rays of display row `y` (0 at the top), left to right: [`Camera::ray`] for each
    /// column, found for less (see [`RowRays`]). A row outside the screen is
    /// [`Error::RowOutOfRange`].
    pub fn row_rays(&self, y: u32) -> Result<RowRays<'_>, Error> {
        let row = self.check_row(y)?;
        Ok(RowRays::new(self, row))
    }
}

impl<'a> RowRays<'a> {
    /// The rays of display row `row`, which must be a row of the screen (the ray budget keeps
    /// its directions, and the squares carried along it, in range).
    pub(crate) fn new(camera: &'a Camera, row: u16) -> Self {
        let step = camera.column_step();
        RowRays::stepping(camera, camera.row_start(row), step, camera.cols())
    }

    /// The next ray, and on to the column after it: [`Iterator::next`] where the caller counts
    /// the columns (a run of them, on the screen).
    pub(crate) fn advance(&mut self) -> Ray {
        let ray = self
            .camera
            .ray_along(self.towards, self.squares.now(self.towards));
        self.towards = self.towards.plus(self.step);
        self.squares.step();
        ray
    }

    /// `count` rays from the eye, the first along `towards` (a direction from
    /// [`Camera::row_start`] stepped along its row), each further one `step` further (a
    /// whole number of column steps): the rays of a run of columns, which must lie on the
    /// screen.
    pub(crate) fn stepping(camera: &'a Camera, towards: Vec3, step: Vec3, count: u16) -> Self {
        RowRays {
            camera,
            towards,
            step,
            squares: RowSquares::new(towards, step),
            left: count,
        }
    }
}

impl Iterator for RowRays<'_> {
    type Item = Ray;

    #[inline]
    fn next(&mut self) -> Option<Ray> {
        self.left = self.left.checked_sub(1)?;
        Some(self.advance())
    }

    /// Skips `n` rays without making them: a few products, however many are skipped.
    fn nth(&mut self, n: usize) -> Option<Ray> {
        let n = n.min(self.left as usize) as u16;
        if n > 0 {
            self.towards = self.towards.plus(self.step.steps(n as i32));
            self.squares = RowSquares::new(self.towards, self.step);
            self.left -= n;
        }
        self.next()
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        (self.left as usize, Some(self.left as usize))
    }
}

impl ExactSizeIterator for RowRays<'_> {}

/// `‖w + k·r‖²` for `k = 0, 1, 2, …`, exactly, in Q32.32 like [`Vec3::length_squared_wide`].
///
/// The directions towards a row's pixels are `w + k·r` (see `Camera::row_start`). Their
/// squared lengths obey `‖w + (k+1)r‖² = ‖w + k·r‖² + 2·(w + k·r)·r + ‖r‖²`, and the middle
/// term grows by `‖r‖²` a column, so after a few products for the first pixel each further
/// one costs two 64-bit additions instead of three squares. Integers throughout, so the
/// values are exactly the squares the pixels' directions have: the normalised rays are the
/// same bits as [`Camera::ray`](crate::Camera::ray)'s.
#[derive(Debug, Clone)]
pub(crate) struct RowSquares {
    square: u64,
    /// `2·(w + k·r)·r + ‖r‖²`: what the next step adds. Negative while the row nears the
    /// point closest to the eye.
    increment: i64,
    /// `2·‖r‖²`.
    growth: i64,
}

impl RowSquares {
    /// Starting at `start` (`w`) and stepping by `step` (`r`); both within the camera's
    /// bounds (components below 2¹⁵), so each product and sum fits 64 bits.
    pub(crate) fn new(start: Vec3, step: Vec3) -> Self {
        let r2 = step.length_squared_wide() as i64;
        RowSquares {
            square: start.length_squared_wide(),
            increment: 2 * start.dot_wide_exact(step) + r2,
            growth: 2 * r2,
        }
    }

    /// `‖w + k·r‖²` for the current `k`, where `towards` is `w + k·r`.
    ///
    /// Where the chip multiplies 32 × 32 → 64 bits in one instruction the three squares cost
    /// less than carrying the sums along a row (which the compiler keeps on the stack), so
    /// they are taken afresh; Cortex-M0 keeps the sums. Either way the value is the same.
    #[inline]
    pub(crate) fn now(&self, towards: Vec3) -> u64 {
        if crate::numbers::fx::NO_LONG_MULTIPLY {
            self.square
        } else {
            towards.length_squared_wide()
        }
    }

    /// The carried sum itself, whatever the chip.
    #[cfg(test)]
    pub(crate) const fn carried(&self) -> u64 {
        self.square
    }

    /// On to `k + 1`.
    pub(crate) fn step(&mut self) {
        self.square = self.square.wrapping_add_signed(self.increment);
        self.increment += self.growth;
    }
}
