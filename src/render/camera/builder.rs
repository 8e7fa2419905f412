//! The camera builders: [`Camera::pinhole`], [`Camera::look_at`] and [`Camera::orbit`] start
//! one, its setters fill in what is not the default, and `build` checks it all at once.

use embedded_graphics::geometry::Size;

use crate::error::Error;
use crate::render::camera::{Camera, check_size};

impl Camera {
    /// The chapter's pinhole camera: the viewpoint at the origin looking down −z, a view
    /// screen `screen_w × screen_h` (world units) at distance `distance`; split into pixels by
    /// [`Pinhole::size`] and made by [`Pinhole::build`].
    ///
    /// With a screen of `M` rows and `N` columns, pixel `(i, j)` of the chapter (row `i`
    /// counted upward from the bottom, column `j`) has its centre at
    /// `p_ij = c − (w/2, h/2) + (w/N·(j + ½), h/M·(i + ½))` with `c = (0, 0, −distance)`: it is
    /// display pixel `(x, y) = (j, M − 1 − i)`.
    ///
    /// `screen_w`, `screen_h` and `distance` must lie in (0, 1024] and the pixel pitches
    /// `screen_w/width` and `screen_h/height` must round to at least 2⁻¹⁶ (else
    /// [`Error::OutOfRange`]); pixels may be at most four times taller than wide or wider
    /// than tall. The view distance `distance·width/screen_w` in pixels is held to the ray
    /// budget of [`Camera`]'s limits: a screen that subtends too narrow or too wide a field of
    /// view for its number of pixels is refused with the limit.
    ///
    /// ```
    /// use embedded_graphics::geometry::Size;
    /// use fixray::{Camera, Error, Quantity, Vec3};
    /// // The chapter's M = 3 by N = 5 screen, 5 × 3 units wide and high, one unit away.
    /// let cam = Camera::pinhole(5.0, 3.0, 1.0).size(Size::new(5, 3)).build()?;
    /// // Chapter pixel (0, 0) is bottom left: column 0, display row 2.
    /// assert_eq!(cam.pixel_centre(0, 2), Vec3::from_ints(-2, -1, -1));
    /// // A screen a millionth of a pixel from the eye has no view.
    /// assert!(matches!(
    ///     Camera::pinhole(1.0, 1.0, 1e-6).size(Size::new(1, 1)).build(),
    ///     Err(Error::OutOfRange { quantity: Quantity::ScreenDistance, .. })
    /// ));
    /// # Ok::<(), Error>(())
    /// ```
    pub const fn pinhole(screen_w: f32, screen_h: f32, distance: f32) -> Pinhole {
        Pinhole {
            screen_w,
            screen_h,
            distance,
            size: Size::zero(),
        }
    }

    /// The general camera: at `eye`, looking at `target`. [`LookAt::up`] gives the upward
    /// direction of the picture (+y unless set), [`LookAt::fov_degrees`] the vertical field
    /// of view (60° unless set), [`LookAt::size`] the screen in pixels, and
    /// [`LookAt::build`] makes it.
    ///
    /// Pixels are square. The screen sits one unit in front of the eye, `2·tan(fov/2)` high,
    /// `height / (2·tan(fov/2))` pixels away. Degenerate input — `target == eye`, `up` zero
    /// or parallel to the view, a field of view outside (0°, 180°), no pixels — is an error.
    ///
    /// The field of view must also suit the number of rows (see [`Camera`]'s limits): at
    /// least about `2·atan(height / 32 768)`: 0.84° at 320 × 240, 3.8° at 1920 × 1080, 14.7°
    /// at 4096 × 4096 ([`Error::FieldOfViewTooNarrow`], which names the smallest allowed in
    /// thousandths of a degree), and not so wide that the view distance drops below about
    /// `R²/16 384` pixels for a screen `R` pixels from centre to corner
    /// ([`Error::FieldOfViewTooWide`]). Within them every ray is within half a pixel of the
    /// exact one; `docs/ACCURACY_FOV.md` has the measured agreement with an f64 renderer
    /// across fields of view.
    ///
    /// The tangent is libm's `tanf`, correctly rounded to within an ulp. (micromath's `tan`
    /// is 0.07 % off at 60° and 0.19 % at 45°; measured against the f64 reference, that
    /// error alone moved silhouettes enough to drop object agreement on the demo scene from
    /// 100 % to 99.97 % and raise the largest channel error from 1 to 4.)
    ///
    /// ```
    /// use embedded_graphics::geometry::Size;
    /// use fixray::{Camera, Error};
    /// let size = Size::new(160, 128);
    /// let cam = Camera::look_at([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]).size(size).build();
    /// assert!(cam.is_ok());
    /// // Looking straight up, the default up (+y) gives the picture no up.
    /// let bad = Camera::look_at([0.0; 3], [0.0, 5.0, 0.0]).size(size).build();
    /// assert!(matches!(bad, Err(Error::DegenerateCamera { .. })));
    /// let fine = Camera::look_at([0.0; 3], [0.0, 5.0, 0.0]).up([0.0, 0.0, -1.0]).size(size);
    /// assert!(fine.build().is_ok());
    /// // A telephoto view of half a degree needs fewer rows than 240.
    /// let narrow = Camera::look_at([0.0; 3], [0.0, 0.0, -1.0])
    ///     .fov_degrees(0.5)
    ///     .size(Size::new(320, 240))
    ///     .build();
    /// assert_eq!(narrow, Err(Error::FieldOfViewTooNarrow { min_millidegrees: 840 }));
    /// ```
    pub const fn look_at(eye: [f32; 3], target: [f32; 3]) -> LookAt {
        LookAt {
            eye,
            target,
            up: [0.0, 1.0, 0.0],
            fov_degrees: DEFAULT_FOV_DEGREES,
            size: Size::zero(),
        }
    }

    /// A look-at camera circling `target` at `distance`: [`Orbit::yaw_degrees`] turns it
    /// about the vertical (+y) axis, 0° (unless set) placing the eye on the +z side, and
    /// [`Orbit::pitch_degrees`] raises it above the horizon (strictly between −90° and 90°;
    /// 0° unless set). Up is +y; the field of view and size are set as for
    /// [`Camera::look_at`]. The distance must be positive, and no longer than two points
    /// within ±[`LIMIT`](crate::LIMIT) can be apart (`2·1024·√3`, about 3547.24): else
    /// [`Error::OutOfRange`] names [`Quantity::OrbitDistance`](crate::Quantity::OrbitDistance).
    ///
    /// The eye's position uses micromath's `sin` and `cos` (about 10⁻³ absolute error), which
    /// moves the eye slightly along its orbit but never off the view it aims at: the view
    /// direction is still exactly `target − eye`.
    ///
    /// ```
    /// use embedded_graphics::geometry::Size;
    /// use fixray::{Camera, Fx};
    /// let cam = Camera::orbit([0.0, 0.0, -16.0], 16.0).size(Size::new(160, 128)).build()?;
    /// // Yaw 0, pitch 0: the eye sits on the +z side, at the origin.
    /// assert!(cam.eye().x.abs() < Fx::from_num(0.05) && cam.eye().z.abs() < Fx::from_num(0.05));
    /// let overhead = Camera::orbit([0.0; 3], 10.0).pitch_degrees(90.0);
    /// assert!(overhead.size(Size::new(160, 128)).build().is_err());
    /// // A negative distance is refused, not turned into an orbit on the far side.
    /// let behind = Camera::orbit([0.0; 3], -10.0).size(Size::new(160, 128)).build();
    /// assert!(matches!(
    ///     behind,
    ///     Err(fixray::Error::OutOfRange { quantity: fixray::Quantity::OrbitDistance, .. })
    /// ));
    /// # Ok::<(), fixray::Error>(())
    /// ```
    pub const fn orbit(target: [f32; 3], distance: f32) -> Orbit {
        Orbit {
            target,
            distance,
            yaw_degrees: 0.0,
            pitch_degrees: 0.0,
            fov_degrees: DEFAULT_FOV_DEGREES,
            size: Size::zero(),
        }
    }
}

/// The vertical field of view of [`Camera::look_at`] and [`Camera::orbit`] unless set.
const DEFAULT_FOV_DEGREES: f32 = 60.0;

/// A pinhole camera being set up: [`Camera::pinhole`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[must_use = "a camera builder does nothing until `build` is called"]
pub struct Pinhole {
    screen_w: f32,
    screen_h: f32,
    distance: f32,
    size: Size,
}

impl Pinhole {
    /// The screen's size in pixels, width by height: 1 to 4096 a side.
    pub const fn size(mut self, size: Size) -> Self {
        self.size = size;
        self
    }

    /// The camera, or why it cannot be made: a size with no pixels (the size was never set)
    /// or wider or taller than 4096 is [`Error::DegenerateCamera`]; see [`Camera::pinhole`]
    /// for the rest.
    #[inline]
    pub fn build(self) -> Result<Camera, Error> {
        let (cols, rows) = check_size(self.size)?;
        Camera::pinhole_checked(self.screen_w, self.screen_h, self.distance, cols, rows)
    }
}

/// A look-at camera being set up: [`Camera::look_at`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[must_use = "a camera builder does nothing until `build` is called"]
pub struct LookAt {
    eye: [f32; 3],
    target: [f32; 3],
    up: [f32; 3],
    fov_degrees: f32,
    size: Size,
}

impl LookAt {
    /// The upward direction of the picture (any length but zero, not along the view): +y
    /// unless set.
    pub const fn up(mut self, up: [f32; 3]) -> Self {
        self.up = up;
        self
    }

    /// The vertical field of view in degrees, strictly between 0 and 180 and within the
    /// limits of [`Camera`] for the size: 60 unless set.
    pub const fn fov_degrees(mut self, degrees: f32) -> Self {
        self.fov_degrees = degrees;
        self
    }

    /// The screen's size in pixels, width by height: 1 to 4096 a side.
    pub const fn size(mut self, size: Size) -> Self {
        self.size = size;
        self
    }

    /// The camera, or why it cannot be made: a size with no pixels (the size was never set)
    /// or wider or taller than 4096 is [`Error::DegenerateCamera`]; see [`Camera::look_at`]
    /// for the rest.
    #[inline]
    pub fn build(self) -> Result<Camera, Error> {
        let (cols, rows) = check_size(self.size)?;
        Camera::look_at_checked(self.eye, self.target, self.up, self.fov_degrees, cols, rows)
    }
}

/// An orbiting camera being set up: [`Camera::orbit`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[must_use = "a camera builder does nothing until `build` is called"]
pub struct Orbit {
    target: [f32; 3],
    distance: f32,
    yaw_degrees: f32,
    pitch_degrees: f32,
    fov_degrees: f32,
    size: Size,
}

impl Orbit {
    /// The turn about the vertical (+y) axis through the target, in degrees: 0 (unless set)
    /// puts the eye on the target's +z side, 90 on its +x side.
    pub const fn yaw_degrees(mut self, degrees: f32) -> Self {
        self.yaw_degrees = degrees;
        self
    }

    /// The height above the target's horizon, in degrees, strictly between −90 and 90: 0
    /// unless set.
    pub const fn pitch_degrees(mut self, degrees: f32) -> Self {
        self.pitch_degrees = degrees;
        self
    }

    /// The vertical field of view in degrees, as [`LookAt::fov_degrees`]: 60 unless set.
    pub const fn fov_degrees(mut self, degrees: f32) -> Self {
        self.fov_degrees = degrees;
        self
    }

    /// The screen's size in pixels, width by height: 1 to 4096 a side.
    pub const fn size(mut self, size: Size) -> Self {
        self.size = size;
        self
    }

    /// The camera, or why it cannot be made: a size with no pixels (the size was never set)
    /// or wider or taller than 4096 is [`Error::DegenerateCamera`]; see [`Camera::orbit`]
    /// and [`Camera::look_at`] for the rest.
    pub fn build(self) -> Result<Camera, Error> {
        let (cols, rows) = check_size(self.size)?;
        Camera::orbit_checked(
            self.target,
            self.distance,
            self.yaw_degrees,
            self.pitch_degrees,
            self.fov_degrees,
            cols,
            rows,
        )
    }
}
