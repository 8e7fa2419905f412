//! [`DCamera`]: the pinhole camera of section 4.1, and the same camera aimed anywhere.

use super::{DRay, DVec3, Real};

/// A pinhole camera: an eye and a view screen of `width × height` pixels in front of it.
///
/// The screen is the rectangle `width × height` centred on the point `centre` (relative to
/// the eye) and spanned by the unit vectors `right` and `up`. Following the chapter, the
/// *pixel centre* of chapter row `i` (counted upward from the bottom) and column `j`, for a
/// screen of `cols × rows` pixels, is
///
/// `p = centre + right·(−width/2 + width/cols·(j + ½)) + up·(−height/2 + height/rows·(i + ½))`
///
/// and the ray through it starts at the eye with direction `p / ‖p‖`.
///
/// [`ray`](Self::ray) takes *display* coordinates (`x`, `y`) instead, as fixray's camera
/// does: column `x` is `j`, and row 0 is the top of the picture, so display row `y` is chapter
/// row `i = rows − 1 − y`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DCamera<F: Real = f64> {
    eye: DVec3<F>,
    centre: DVec3<F>,
    right: DVec3<F>,
    up: DVec3<F>,
    width: F,
    height: F,
    rows: u32,
    cols: u32,
}

/// A count of pixels in precision `F`: exact, as counts are far below 2²⁴.
fn px<F: Real>(n: u32) -> F {
    F::from_f64(f64::from(n))
}

impl<F: Real> DCamera<F> {
    /// The chapter's camera: the eye at the origin looking down −z, and a `w × h` screen at
    /// distance `z_p`, centred on `(0, 0, −z_p)`, with `cols × rows` pixels (width by
    /// height).
    ///
    /// `None` unless `w`, `h` and `z_p` are finite and positive and `cols`, `rows` non-zero.
    #[must_use]
    pub fn pinhole(w: F, h: F, z_p: F, cols: u32, rows: u32) -> Option<Self> {
        let positive = |x: F| x.is_finite() && x > F::ZERO;
        if !(positive(w) && positive(h) && positive(z_p)) || rows == 0 || cols == 0 {
            return None;
        }
        let centre = DVec3::new(F::ZERO, F::ZERO, -z_p);
        let (right, up) = (DVec3::X, DVec3::Y);
        Some(DCamera {
            eye: DVec3::ZERO,
            centre,
            right,
            up,
            width: w,
            height: h,
            rows,
            cols,
        })
    }

    /// A camera at `eye` looking at `target`, with `up` pointing roughly up the picture and a
    /// vertical field of view of `fov_y_degrees`, for `cols × rows` pixels.
    ///
    /// This is the pinhole camera turned to face `f = (target − eye)/‖target − eye‖`, with its
    /// screen at distance 1: `right = (f × up)/‖f × up‖`, `u = right × f`, height
    /// `hh = 2·tan(fov/2)` and width `ww = hh·cols/rows`, so pixels are square.
    ///
    /// `None` if the inputs are not finite, `eye == target`, `up` is parallel to the view
    /// direction, the field of view is not strictly between 0° and 180°, or `cols` or `rows`
    /// is zero.
    #[must_use]
    pub fn look_at(
        eye: DVec3<F>,
        target: DVec3<F>,
        up: DVec3<F>,
        fov_y_degrees: F,
        cols: u32,
        rows: u32,
    ) -> Option<Self> {
        let fov_ok = fov_y_degrees > F::ZERO && fov_y_degrees < F::from_f64(180.0);
        if !(eye.is_finite() && fov_ok) || rows == 0 || cols == 0 {
            return None;
        }
        let f = (target - eye).try_normalize()?;
        let right = f.cross(up).try_normalize()?;
        let u = right.cross(f);
        let half_angle = fov_y_degrees.to_radians() / F::TWO;
        let height = F::TWO * half_angle.tan();
        let width = height * px::<F>(cols) / px::<F>(rows);
        Some(DCamera {
            eye,
            centre: f,
            right,
            up: u,
            width,
            height,
            rows,
            cols,
        })
    }

    /// The picture's width in pixels (its columns).
    #[inline]
    #[must_use]
    pub const fn width(&self) -> u32 {
        self.cols
    }

    /// The picture's height in pixels (its rows).
    #[inline]
    #[must_use]
    pub const fn height(&self) -> u32 {
        self.rows
    }

    /// The eye: where every ray starts.
    #[inline]
    #[must_use]
    pub const fn eye(&self) -> DVec3<F> {
        self.eye
    }

    /// The pixel centre of display pixel (`x`, `y`) on the view screen, in world
    /// coordinates.
    ///
    /// Coordinates past the last column or row extrapolate the grid; they do not fail.
    #[must_use]
    pub fn pixel_centre(&self, x: u32, y: u32) -> DVec3<F> {
        self.eye + self.towards(x, y)
    }

    /// From the eye to the pixel centre of display pixel (`x`, `y`): the chapter's `p`.
    fn towards(&self, x: u32, y: u32) -> DVec3<F> {
        // Chapter row i counts up from the bottom; display rows count down from the top.
        let i = px::<F>(self.rows) - F::ONE - px::<F>(y);
        let j = px::<F>(x);
        let half = F::from_f64(0.5);
        let across = -self.width / F::TWO + self.width / px::<F>(self.cols) * (j + half);
        let up = -self.height / F::TWO + self.height / px::<F>(self.rows) * (i + half);
        self.centre + self.right * across + self.up * up
    }

    /// The ray shot through the pixel centre of display pixel (`x`, `y`).
    #[must_use]
    pub fn ray(&self, x: u32, y: u32) -> DRay<F> {
        let p = self.towards(x, y);
        // The screen is never at the eye (its centre is a non-zero distance straight ahead),
        // so p has a direction.
        DRay::new_unchecked(self.eye, p.normalize_or_zero())
    }

    /// The ray through sample (`sx`, `sy`) of an `n × n` grid of sub-pixel centres in pixel
    /// (`x`, `y`), for supersampling: the sample sits `(2sx + 1)/(2n)` of a pixel right of
    /// the pixel's left edge and `(2sy + 1)/(2n)` below its top edge. `n = 1` is the pixel
    /// centre.
    #[must_use]
    pub fn sample_ray(&self, x: u32, y: u32, sx: u8, sy: u8, n: u8) -> DRay<F> {
        let n = F::from_u16(u16::from(n.max(1)));
        let offset = |s: u8| (F::TWO * F::from_u16(u16::from(s)) + F::ONE) / (F::TWO * n);
        // Positions in pixels from the top left; the chapter's y grows upward.
        let across = px::<F>(x) + offset(sx);
        let down = px::<F>(y) + offset(sy);
        let right = -self.width / F::TWO + self.width / px::<F>(self.cols) * across;
        let up =
            -self.height / F::TWO + self.height / px::<F>(self.rows) * (px::<F>(self.rows) - down);
        let p = self.centre + self.right * right + self.up * up;
        DRay::new_unchecked(self.eye, p.normalize_or_zero())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: DVec3, b: DVec3) -> bool {
        (a - b).length() < 1e-12
    }

    #[test]
    fn the_chapter_grid_has_its_middle_pixel_on_the_axis() {
        // M = 3 rows by N = 5 columns on a 5 × 3 screen at z_p = 1: 1 × 1 pixels.
        let cam = DCamera::pinhole(5.0, 3.0, 1.0, 5, 3).unwrap();
        assert_eq!(cam.pixel_centre(2, 1), DVec3::new(0.0, 0.0, -1.0));
        assert_eq!(cam.ray(2, 1).dir(), -DVec3::Z);
        assert_eq!(cam.ray(2, 1).origin(), DVec3::ZERO);
    }

    #[test]
    fn display_row_0_is_the_top_and_col_0_the_left() {
        let cam = DCamera::pinhole(5.0, 3.0, 1.0, 5, 3).unwrap();
        assert_eq!(cam.pixel_centre(0, 0), DVec3::new(-2.0, 1.0, -1.0));
        assert_eq!(cam.pixel_centre(4, 2), DVec3::new(2.0, -1.0, -1.0));
        let d = cam.ray(0, 0).dir();
        assert!(close(d, DVec3::new(-2.0, 1.0, -1.0) / libm::sqrt(6.0)));
    }

    #[test]
    fn look_at_down_minus_z_is_the_pinhole_camera() {
        // hh = 2·tan(45°) = 2 at distance 1, ww = 2 · 4/2 = 4.
        let cam = DCamera::look_at(DVec3::ZERO, -DVec3::Z, DVec3::Y, 90.0, 4, 2).unwrap();
        let pin = DCamera::pinhole(4.0, 2.0, 1.0, 4, 2).unwrap();
        for row in 0..2 {
            for col in 0..4 {
                assert!(
                    close(cam.ray(col, row).dir(), pin.ray(col, row).dir()),
                    "{row},{col}"
                );
            }
        }
    }

    #[test]
    fn look_at_starts_rays_at_the_eye_and_aims_at_the_target() {
        let eye = DVec3::new(0.0, 2.0, 5.0);
        let target = DVec3::new(0.0, 2.0, -5.0);
        let cam = DCamera::look_at(eye, target, DVec3::Y, 60.0, 3, 3).unwrap();
        assert_eq!(cam.ray(1, 1).origin(), eye);
        assert!(close(cam.ray(1, 1).dir(), -DVec3::Z));
        assert!(close(cam.pixel_centre(1, 1), DVec3::new(0.0, 2.0, 4.0)));
        assert!(cam.ray(1, 0).dir().y > 0.0, "row 0 looks up");
        assert!(cam.ray(0, 1).dir().x < 0.0, "col 0 looks left");
    }

    #[test]
    fn degenerate_cameras_are_refused() {
        assert_eq!(DCamera::pinhole(0.0, 1.0, 1.0, 2, 2), None);
        assert_eq!(DCamera::pinhole(1.0, 1.0, f64::NAN, 2, 2), None);
        assert_eq!(DCamera::pinhole(1.0, 1.0, 1.0, 2, 0), None);
        let (o, y) = (DVec3::ZERO, DVec3::Y);
        assert_eq!(DCamera::look_at(o, o, y, 60.0, 2, 2), None);
        assert_eq!(DCamera::look_at(o, y, y, 60.0, 2, 2), None);
        assert_eq!(DCamera::look_at(o, -DVec3::Z, y, 180.0, 2, 2), None);
        assert_eq!(DCamera::look_at(o, -DVec3::Z, y, 60.0, 2, 0), None);
    }
}
