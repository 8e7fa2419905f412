//! [`ScreenMap`]: where a point of the world lands on a camera's screen, the inverse of
//! [`Camera::ray`], for set-up work that bounds regions of the picture (the damage of an
//! edit). In `f32`, once a frame; never per pixel.

use super::Camera;
use crate::numbers::vec3::Vec3;

/// Three `f32` components: a point or direction at set-up.
pub(crate) type F3 = [f32; 3];

/// `v`'s components as `f32`.
pub(crate) fn f3(v: Vec3) -> F3 {
    [v.x.to_num(), v.y.to_num(), v.z.to_num()]
}

/// `a > b`, spelt so that a caller's `!exceeds(a, b)` reads "not surely above": true for
/// NaN, which every bound here treats as unbounded.
pub(crate) fn exceeds(a: f32, b: f32) -> bool {
    a > b
}

pub(crate) fn dot(a: F3, b: F3) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(crate) fn cross(a: F3, b: F3) -> F3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub(crate) fn sub(a: F3, b: F3) -> F3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(crate) fn add(a: F3, b: F3) -> F3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub(crate) fn scale(a: F3, k: f32) -> F3 {
    [a[0] * k, a[1] * k, a[2] * k]
}

pub(crate) fn length(a: F3) -> f32 {
    libm::sqrtf(dot(a, a))
}

/// Two unit vectors perpendicular to the unit `n` and to each other.
pub(crate) fn perpendiculars(n: F3) -> (F3, F3) {
    let other = if n[0].abs() < 0.6 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let a = cross(n, other);
    let a = scale(a, 1.0 / length(a));
    (a, cross(n, a))
}

/// A camera's screen as a map from points (given as offsets from the eye) to pixel
/// positions.
///
/// The camera's ray for pixel (`x`, `y`) runs along `forward + kx·right + ky·down` with
/// `kx = x + ½ − cols/2` and `ky = y + ½ − rows/2`, in its rounded Q16.16 basis. Writing an
/// offset `d` from the eye in that basis, `d = a·forward + b·right + c·down`, the offset lies
/// on the exact line towards screen position `(cols/2 + b/a, rows/2 + c/a)`, where pixel
/// (`x`, `y`) spans `[x, x + 1) × [y, y + 1)` and its centre is at `(x + ½, y + ½)`. By
/// Cramer's rule `a`, `b` and `c` are dot products of `d` with three fixed vectors, up to a
/// common positive factor that cancels in the ratios. Using the rounded basis itself, the
/// basis's rounding is no error here: only the rounding of each ray's direction (the half
/// pixel [`Camera`] documents) and of this `f32` arithmetic are left for margins.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ScreenMap {
    /// `right × down`: `d` dotted with it is `a` times the basis's determinant.
    depth: F3,
    /// `down × forward`: gives `b` times the determinant.
    across: F3,
    /// `forward × right`: gives `c` times the determinant.
    downward: F3,
    /// `a` times the determinant at a depth of one world unit along the view.
    per_unit_depth: f32,
    /// The screen's centre, in pixels.
    centre: [f32; 2],
    /// The view distance in pixels.
    view: f32,
}

impl ScreenMap {
    /// The map of `camera`'s screen.
    pub(crate) fn new(camera: &Camera) -> Self {
        let (forward, right, down) = (f3(camera.forward), f3(camera.right), f3(camera.down));
        let depth = cross(right, down);
        let view: f32 = camera.view.to_num();
        // forward = view · (unit view direction), so a point one world unit deep has
        // a = 1/view. The determinant forward·(right × down) is about view · aspect > 0 for
        // every camera the builders make (right, down and forward are right-handed).
        let determinant = dot(forward, depth);
        ScreenMap {
            depth,
            across: cross(down, forward),
            downward: cross(forward, right),
            per_unit_depth: determinant / view.max(f32::MIN_POSITIVE),
            centre: [camera.cols as f32 / 2.0, camera.rows as f32 / 2.0],
            view,
        }
    }

    /// How far ahead of the eye an offset `d` lies along the view, in world units.
    pub(crate) fn depth(&self, d: F3) -> f32 {
        dot(d, self.depth) / self.per_unit_depth
    }

    /// The screen position `[u, v]` in pixels of a point `d` from the eye, or `None` if it
    /// lies less than `min_depth` ahead of the eye (or the arithmetic is not finite).
    pub(crate) fn position(&self, d: F3, min_depth: f32) -> Option<[f32; 2]> {
        let a = dot(d, self.depth);
        if !exceeds(a, 0.0) || !exceeds(a, min_depth * self.per_unit_depth) {
            return None;
        }
        let u = self.centre[0] + dot(d, self.across) / a;
        let v = self.centre[1] + dot(d, self.downward) / a;
        (u.is_finite() && v.is_finite()).then_some([u, v])
    }

    /// The view distance in pixels: a world-space error `e` at depth `z` moves a point's
    /// screen position by at most about `e · view / z` pixels near the screen's centre.
    pub(crate) fn view(&self) -> f32 {
        self.view
    }
}
