//! [`Screen`]: where a point of the world lands on a camera's screen, the inverse of
//! [`Camera::ray`], worked out exactly in integers; the pixels that may show a convex set
//! of points ([`Screen::area`]); and whether a sphere lies wholly behind the eye.

use super::exact::{W3, ceil_div, cross, dot, quotient, raw, sub, wide};
use super::{Area, Damage};
use crate::geometry::sphere::Sphere;
use crate::numbers::vec3::Vec3;
use crate::render::camera::Camera;

/// Nearer the eye than this, in raw Q16.16 world units along the view (1/16), no point is
/// placed on the screen.
pub(super) const NEAREST: i128 = 1 << 12;

/// Screen positions are kept in units of 1/256 of a pixel.
const SUB: i64 = 256;

/// A camera's screen as a map from points (offsets from the eye, raw Q16.16) to pixel
/// positions.
///
/// The camera's ray for pixel (`x`, `y`) runs along `forward + kx·right + ky·down` with
/// `kx = x + ½ − cols/2` and `ky = y + ½ − rows/2`, in its rounded Q16.16 basis. Writing an
/// offset `d` from the eye in that basis, `d = a·forward + b·right + c·down`, the offset lies
/// on the exact line towards screen position `(cols/2 + b/a, rows/2 + c/a)`, where pixel
/// (`x`, `y`) spans `[x, x + 1) × [y, y + 1)`. By Cramer's rule `a`, `b` and `c` are `d`
/// dotted with `right × down`, `down × forward` and `forward × right`, over the basis's
/// determinant `forward · (right × down)`, a common positive factor that cancels in the
/// ratios. All of it is exact in `i128`: a component of `right` is at most 2¹⁶ + 1 raw, of
/// `down` at most 2¹⁸ + 4 (a pixel aspect of at most 4) and of `forward` at most 2³⁰ (the ray
/// budget), so the cross products are below 2⁴⁹ a component, and an offset within ±2⁴⁴ raw
/// dotted with one below 2⁹⁶. Only the ray's rounding (the half pixel [`Camera`] documents),
/// a hit point's, and the floor of a quotient to 1/256 of a pixel are left for margins.
pub(super) struct Screen {
    /// `right × down`, in units of 2⁻³².
    depth: [i128; 3],
    /// `down × forward`, in units of 2⁻³².
    across: [i128; 3],
    /// `forward × right`, in units of 2⁻³².
    downward: [i128; 3],
    /// `forward · (right × down)`, in units of 2⁻⁴⁸: positive for every camera the builders
    /// make (`right`, `down` and `forward` are right-handed).
    determinant: i128,
    /// The view distance, raw.
    view: i128,
    /// The screen's centre in units of [`SUB`].
    centre: [i64; 2],
    /// The screen's larger side in pixels.
    side: i128,
}

/// Points placed on the screen: the box of their positions and the nearest one's depth.
pub(super) struct Placed {
    /// Least and greatest positions (1/256 pixel), the greatest exclusive.
    low: [i64; 2],
    high: [i64; 2],
    /// The least `a` (see [`Screen`]) of the points, in units of 2⁻⁴⁸.
    nearest: i128,
}

impl Screen {
    /// The map of `camera`'s screen, or `None` if its basis is not right-handed.
    pub(super) fn new(camera: &Camera) -> Option<Self> {
        let (forward, right, down) = (
            wide(raw(camera.forward)),
            wide(raw(camera.right)),
            wide(raw(camera.down)),
        );
        let depth = cross(right, down);
        let determinant = dot(forward, depth);
        (determinant > 0).then(|| Screen {
            depth,
            across: cross(down, forward),
            downward: cross(forward, right),
            determinant,
            view: camera.view.to_bits().into(),
            centre: [
                i64::from(camera.cols()) * SUB / 2,
                i64::from(camera.rows()) * SUB / 2,
            ],
            side: camera.cols().max(camera.rows()).into(),
        })
    }

    /// How far ahead of the eye along the view `d` lies, as `a` in units of 2⁻⁴⁸: the
    /// depth in raw units is `a · view / determinant`.
    fn ahead(&self, d: W3) -> i128 {
        dot(wide(d), self.depth)
    }

    /// Places points `from_eye` (offsets from the eye, raw, each within ±2⁴⁴): `None` if
    /// one lies less than [`NEAREST`] ahead of the eye, an empty box if there are none.
    pub(super) fn place(&self, from_eye: impl Iterator<Item = W3>) -> Option<Placed> {
        let mut placed = Placed {
            low: [i64::MAX; 2],
            high: [i64::MIN; 2],
            nearest: i128::MAX,
        };
        for d in from_eye {
            let a = self.ahead(d);
            // Below 2⁸² · 2³¹ and 2¹² · 2⁶⁸ (see [`Screen`]): exact.
            if a <= 0 || a * self.view < NEAREST * self.determinant {
                return None;
            }
            let w = wide(d);
            for (axis, onto) in [self.across, self.downward].iter().enumerate() {
                // Within 3 of the exact position, or at least 2³⁰ units (2²² pixels) away
                // from the centre: then put at 2⁴⁰ units on its side, which moves it along
                // that side, and no farther than [`Screen::area`]'s margin from the screen.
                let along = dot(w, *onto) * i128::from(SUB);
                let q = quotient(along, a).unwrap_or(if along < 0 { -(1 << 40) } else { 1 << 40 });
                let q = q + self.centre[axis];
                placed.low[axis] = placed.low[axis].min(q - 3);
                placed.high[axis] = placed.high[axis].max(q + 4);
            }
            placed.nearest = placed.nearest.min(a);
        }
        Some(placed)
    }

    /// The pixels that may show a point of the convex hull of `placed`'s points, if that
    /// point is a hit point a ray of the screen found (so within the rounding of a hit
    /// point of the exact one): inner `None` when none of the screen may.
    ///
    /// A ray may miss its pixel's exact direction by half a pixel. A point `e` world units
    /// off the exact ray at depth `z`, seen `r` pixels from the screen's centre, moves its
    /// picture by at most `e · (view² + r²) / (view · (z − e))` pixels; `r` is below the
    /// screen's larger side and `z` at least the nearest point's depth (depth is linear,
    /// so no point of the hull is nearer than its nearest vertex). Taking `e` as 2⁻¹¹ covers
    /// a hit point's rounding (a few units of 2⁻¹⁶) and that of the points the damage
    /// makes (at most two raw units each); a caller whose points stand for others up to
    /// `apart` raw units away adds that. The margin is half a pixel, that, and 1/256.
    pub(super) fn area(&self, placed: &Placed, apart: u128, damage: &Damage) -> Option<Area> {
        if placed.nearest == i128::MAX {
            return None;
        }
        // The nearest depth in raw units, floored: at least NEAREST, so not zero.
        let nearest = (placed.nearest * self.view / self.determinant).max(1);
        // e · (view² + side²·2³²) / (view · nearest · 2⁸) in units of 1/256 of a pixel, `e`
        // in raw units and rounded up: the view is below 2³¹ raw, the side at most 2¹², so
        // the spread is below 2⁶³; `e` is held below 2⁴⁰.
        let view = self.view.unsigned_abs().max(1);
        let spread = view * view + (self.side.unsigned_abs().pow(2) << 32);
        let e = (1 << 5) + apart.min(1 << 40);
        // The angle between a point and one `e` from it, both at least `z` away, is at
        // most `e / (z − e)`: `z − e` stands for `z`, where `e` is below half of it.
        let nearest = nearest.unsigned_abs();
        if nearest <= 2 * e {
            return damage.area_of([0, 0], [0, 0], 1 << 21);
        }
        let hit = ceil_div(e * spread, (view * (nearest - e)) << 8);
        // A margin of more than 2¹³ pixels is the whole screen from any point within 2¹²
        // pixels of it; one below that keeps a point put off at 2⁴⁰ units (see
        // [`Screen::place`]) as far from the screen as it was, more than 2²¹ pixels.
        if hit >= 1 << 21 {
            return damage.area_of([0, 0], [0, 0], 1 << 21);
        }
        damage.area_of(placed.low, placed.high, SUB / 2 + 1 + hit as i64)
    }
}

impl Screen {
    /// The pixels whose rays may meet `ball`: those of the cube around it, widened by 2⁻⁸
    /// (far more than the rounding of a primary ray's test), seen from `eye`: a hit point
    /// lies in the sphere, to within that rounding, and so in the cube. `Some(None)` when
    /// none can; `None` when the cube reaches within [`NEAREST`] of the plane of the eye.
    pub(super) fn ball_area(
        &self,
        ball: &Sphere,
        eye: Vec3,
        damage: &Damage,
    ) -> Option<Option<Area>> {
        let centre = sub(raw(ball.centre()), raw(eye));
        let r = i64::from(ball.radius().to_bits()) + (1 << 8);
        let corner = |k: usize| {
            let side = |bit: usize| if k >> bit & 1 == 0 { -r } else { r };
            [
                centre[0] + side(0),
                centre[1] + side(1),
                centre[2] + side(2),
            ]
        };
        Some(self.area(&self.place((0..8).map(corner))?, 0, damage))
    }
}

/// Whether every point of `ball` lies farther than 1/16 behind the plane of the eye, so no
/// ray of the screen meets it: every ray runs along `forward + kx·right + ky·down`, whose
/// component along `right × down` is the determinant, positive, so every point a ray
/// reaches has `(p − eye) · (right × down) ≥ 0`, to within a hit test's rounding. Exact in
/// `i128`; false when a square would not fit.
pub(super) fn behind_eye(ball: &Sphere, camera: &Camera, screen: &Screen) -> bool {
    let along = screen.ahead(sub(raw(ball.centre()), raw(camera.eye())));
    let reach = u128::from(ball.radius().to_bits().unsigned_abs()) + (1 << 12);
    let normal = super::exact::square(screen.depth);
    let (Some(far), Some(round)) = (
        along.unsigned_abs().checked_mul(along.unsigned_abs()),
        (reach * reach).checked_mul(normal),
    ) else {
        return false;
    };
    along < 0 && far > round
}
