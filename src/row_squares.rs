//! [`RowSquares`]: the squared lengths of a row's ray directions, by additions alone.

use crate::vec3::Vec3;

/// `‖w + k·r‖²` for `k = 0, 1, 2, …`, exactly, in Q32.32 like [`Vec3::length_squared_wide`].
///
/// The directions towards a row's pixels are `w + k·r` (see `Camera::row_start`). Their
/// squared lengths obey `‖w + (k+1)r‖² = ‖w + k·r‖² + 2·(w + k·r)·r + ‖r‖²`, and the middle
/// term grows by `‖r‖²` a column, so after a few products for the first pixel each further
/// one costs two 64-bit additions instead of three squares. Integers throughout, so the
/// values are exactly the squares the pixels' directions have: the normalised rays are the
/// same bits as [`Camera::ray`](crate::Camera::ray)'s.
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

    /// `‖w + k·r‖²` for the current `k`.
    pub(crate) const fn now(&self) -> u64 {
        self.square
    }

    /// On to `k + 1`.
    pub(crate) fn step(&mut self) {
        self.square = self.square.wrapping_add_signed(self.increment);
        self.increment += self.growth;
    }
}
