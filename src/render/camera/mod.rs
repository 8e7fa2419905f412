//! [`Camera`]: the chapter's pinhole camera and the general look-at camera, and the builders
//! that set them up.

use micromath::F32Ext;

use embedded_graphics::geometry::Size;

use crate::check::{self, within};
use crate::error::{CameraProblem, Error, Quantity};
use crate::geometry::ray::Ray;
use crate::numbers::fx::{self, FRAC, Fx};
use crate::numbers::isqrt::isqrt;
use crate::numbers::vec3::Vec3;

mod builder;

pub use builder::{LookAt, Orbit, Pinhole};

/// Largest screen size in pixels, per side.
pub const MAX_PIXELS: u32 = 4096;

/// The ray budget in pixels, `B`: with `F` the view distance and `R` the distance from the
/// screen's centre to its corner, both in pixels and as rounded to Q16.16, every camera has
/// `F² + R² ≤ B·F`.
///
/// Two things follow. The direction towards any point of the screen is `√(F² + r²) ≤ B`
/// pixels long (as `F ≤ B`), so its components fit Q16.16 with a bit to spare, and every
/// product and squared length made from it fits 64 bits. And every ray is good to half a
/// pixel: a Q16.16 unit direction is within about 2⁻¹⁵ radians of the exact one (its own
/// rounding and that of the camera's basis), and an angle `δ` at a point `r` pixels from the
/// screen's centre moves the ray by `δ·(F² + r²)/F` pixels on the screen, at most
/// 2⁻¹⁵ · B = ½. Narrow fields of view meet the budget at `F ≈ B`, wide ones at `F ≈ R²/B`.
const RAY_BUDGET_PX: u32 = 16_384;

/// The longest distance [`Camera::orbit`] takes: between two points within ±[`LIMIT`] (the
/// eye and the target), at most `2·1024·√3` = 3547.24005…, rounded down to Q16.16.
///
/// [`LIMIT`]: crate::LIMIT
const ORBIT_REACH: Fx = Fx::from_bits(232_471_924);

/// A camera: a viewpoint and a screen of `width × height` pixels in front of it, made by a
/// builder: [`Camera::look_at`], [`Camera::orbit`] or the chapter's [`Camera::pinhole`].
///
/// One coordinate order throughout, embedded-graphics': pixel (`x`, `y`) is column `x` from
/// the left and row `y` from the top, and sizes are [`Size`]s, width by height. The chapter
/// numbers its rows upward from the bottom, so its row `i` is display row
/// `height − 1 − i`; with that mapping the picture comes out upright.
///
/// Ray directions do not depend on the size of the screen, only on its shape, so the camera
/// stores its screen scaled to make one pixel one unit wide. The pixel-centre offsets are then
/// exact half-integers, and Q16.16 rounding of a small pixel pitch (`w/N`) never accumulates
/// across a row.
///
/// # Limits
///
/// Every constructor checks the camera it builds as rounded to Q16.16 — the view distance in
/// pixels, the pixel aspect and the basis — not the `f32` inputs. The view distance `F` and
/// the screen's half-diagonal `R` (both in pixels) must satisfy `F² + R² ≤ 16 384·F`, which
/// keeps every ray of the screen within half a pixel of the exact one and every intermediate
/// inside its integer type. In fields of view (vertical, for square pixels):
///
/// | width × height | narrowest | widest |
/// |---|---|---|
/// | 1 × 1 | 0.004° | 179.99° |
/// | 160 × 128 | 0.448° | 178.85° |
/// | 320 × 240 | 0.840° | 177.67° |
/// | 1920 × 1080 | 3.793° | 164.31° |
/// | 4096 × 4096 | 14.721° | 151.03° |
///
/// Outside them the constructors return [`Error::FieldOfViewTooNarrow`] or
/// [`Error::FieldOfViewTooWide`] with the limit for that screen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Camera {
    // The row walk of `render/accel/camera_rows.rs` reads the frame directly.
    pub(in crate::render) eye: Vec3,
    /// From the eye to the screen centre, in pixel units.
    pub(in crate::render) forward: Vec3,
    /// One pixel towards increasing column.
    pub(in crate::render) right: Vec3,
    /// One pixel towards increasing display row (down the picture).
    pub(in crate::render) down: Vec3,
    /// The view distance in pixels, as `forward` was scaled to it.
    pub(in crate::render) view: Fx,
    /// `forward` normalised, for the culling's column spans: a property of the camera, so
    /// made once here rather than for every sphere of every row.
    pub(in crate::render) view_unit: Option<Vec3>,
    /// The distance from the eye to the screen in world units, for [`Camera::pixel_centre`]:
    /// a direction in pixel units times `screen / view` is a point of the screen.
    screen: Fx,
    pub(in crate::render) cols: u16,
    rows: u16,
}

/// A screen size as the builders take it, checked to 1..=4096 pixels a side: its width and
/// height as the camera keeps them.
#[inline]
fn check_size(size: Size) -> Result<(u16, u16), Error> {
    if size.width == 0 || size.height == 0 {
        return Err(Error::DegenerateCamera(CameraProblem::NoPixels));
    }
    if size.width > MAX_PIXELS || size.height > MAX_PIXELS {
        return Err(Error::DegenerateCamera(CameraProblem::TooManyPixels));
    }
    // At most 4096: both fit u16.
    let (cols, rows) = (size.width as u16, size.height as u16);
    check_resolution(cols, rows)?;
    Ok((cols, rows))
}

fn check_resolution(cols: u16, rows: u16) -> Result<(), Error> {
    if cols == 0 || rows == 0 {
        return Err(Error::DegenerateCamera(CameraProblem::NoPixels));
    }
    if u32::from(cols) > MAX_PIXELS || u32::from(rows) > MAX_PIXELS {
        return Err(Error::DegenerateCamera(CameraProblem::TooManyPixels));
    }
    Ok(())
}

/// A positive, finite `f32` setup length, converted to Q16.16: at most 1024, and not so small
/// that it rounds to zero (the range 2⁻¹⁶ to 1024 of [`Error::OutOfRange`]).
///
/// The range is checked here, where `value` is known to be positive, rather than by the
/// general `check::f32_within`: with constant inputs (a firmware's fixed pinhole camera) the
/// pinhole's whole set-up, ray budget included, then folds away at compile time.
fn positive(value: f32, quantity: Quantity) -> Result<Fx, Error> {
    if !value.is_finite() {
        return Err(Error::NotFinite { quantity });
    }
    let (min, max) = (Fx::DELTA, crate::LIMIT);
    if value <= 0.0 || value > 1024.0 {
        return Err(Error::OutOfRange { quantity, min, max });
    }
    // Finite and within (0, 1024]: the conversion cannot overflow, and only rounding to zero
    // can leave the range.
    within(Fx::from_num(value), min, max, quantity)
}

/// A view distance of `view` pixels, worked out in `f32` at set-up, in Q16.16.
///
/// Past the budget (or infinite, for a vanishing field of view) it is clamped to just past it,
/// and below zero to zero, so that [`Camera::checked`] refuses it with the field of view the
/// screen allows; in between it is the rounded value.
fn view_distance(view: f32) -> Fx {
    let past = (RAY_BUDGET_PX + 1) as f32;
    // NaN cannot arise from the finite, positive inputs; it would clamp to 0 and be refused.
    let clamped = if view.is_nan() {
        0.0
    } else {
        view.clamp(0.0, past)
    };
    // Finite and within [0, 16 385]: the conversion cannot overflow.
    Fx::from_num(clamped)
}

/// Refuses a view distance `view` (pixels) and pixel aspect `aspect` (the length of one row
/// step, pixels) that break the ray budget ([`RAY_BUDGET_PX`]) for `cols × rows` pixels; the
/// error names the field of view the screen allows.
///
/// All in integers, as the render path is: no floating-point library is needed for a camera
/// however it fails.
fn check_budget(view: Fx, aspect: Fx, cols: u16, rows: u16) -> Result<(), Error> {
    // 4·(F² + R²) ≤ 4·B·F in units of 2⁻³² px², exactly, with 4R² = cols² + (rows·aspect)².
    // F's raw value is below 2³¹, so 4F² < 2⁶⁴ and 4·B·F = 2³²·F < 2⁶³; the screen's term
    // saturates only where it alone exceeds 4·B·F, so the comparison stays exact.
    let f = view.to_bits().max(0) as u64;
    let height = rows as u64 * aspect.to_bits().max(0) as u64; // rows·aspect in 2⁻¹⁶ px, < 2⁴³
    let across = ((cols as u64 * cols as u64) << 32).saturating_add(height.saturating_mul(height));
    let budget = (RAY_BUDGET_PX as u64) << FRAC; // B in 2⁻¹⁶ px
    if (4 * f * f).saturating_add(across) <= (4 * budget) * f {
        return Ok(());
    }
    // The limits: F² − B·F + R² ≤ 0 between the roots (B ∓ √(B² − 4R²))/2, real only while
    // 4R² ≤ B² (2⁶⁰ in these units).
    let Some(discriminant) = (budget * budget).checked_sub(across) else {
        return Err(Error::DegenerateCamera(CameraProblem::DiagonalTooLong));
    };
    // Twice the far root, B + √(B² − 4R²), in 2⁻¹⁸ px (below 2³⁴): the discriminant is below
    // 2⁶⁰, so four more bits of root fit. Its floor moves the limits by less than 10⁻⁵
    // millidegrees, and only towards the inside of the budget.
    let far = (budget << 2) + isqrt(discriminant << 4);
    // The narrowest view sees half the height at the far root: tan(fov/2) = height / far.
    // The widest sees it at the near root, R²/(far/2) pixels:
    // tan(fov/2) = (height/2)·(far/2)/R² = height · far / 4R². With 4R² ≤ 2⁶⁰, `height` is
    // within 2³⁰ and that product below 2⁶⁴.
    let narrow = view.to_bits() >= (budget / 2) as i32;
    let (x, y) = if narrow {
        (far, height << 2)
    } else {
        (across << 2, height * far)
    };
    let fov = doubled_angle(x, y);
    // In 2⁻³² millidegrees, at most 180 000 · 2³²; rounded towards the inside of the budget.
    if narrow {
        Err(Error::FieldOfViewTooNarrow {
            min_millidegrees: fov.div_ceil(1 << 32) as u32,
        })
    } else {
        Err(Error::FieldOfViewTooWide {
            max_millidegrees: (fov >> 32) as u32,
        })
    }
}

/// `2·atan(atan_y / atan_x)` in units of 2⁻³² millidegrees, for `atan_x > 0`: a field of view
/// from the tangent of its half, the error's limit.
///
/// By CORDIC vectoring: the vector (x, y) is turned towards the x axis by ±atan(2⁻ⁱ) at step
/// `i`, each turn a shift and an add, and the turns add up to its angle. Scaled to a top bit
/// of 2⁶⁰, the vector grows by the rotations' gain (1.65) to below 2⁶³; after 40 steps the
/// angle is good to about 10⁻⁶ millidegrees.
fn doubled_angle(atan_x: u64, atan_y: u64) -> u64 {
    /// atan(2⁻ⁱ) as a doubled angle in 2⁻³² millidegrees, rounded: `atan(2⁻ⁱ)·(360 000/π)·2³²`.
    const TURNS: [i64; 16] = [
        386_547_056_640_000,
        228_192_052_044_233,
        120_570_413_306_876,
        61_203_424_403_997,
        30_720_478_360_348,
        15_375_215_050_361,
        7_689_483_619_191,
        3_844_976_450_144,
        1_922_517_559_169,
        961_262_446_472,
        480_631_681_601,
        240_315_898_096,
        120_157_956_210,
        60_078_979_000,
        30_039_489_612,
        15_019_744_820,
    ];
    /// `(360 000/π)·2³²`: past the table, atan(2⁻ⁱ) is 2⁻ⁱ to within a relative 2⁻³³.
    const RADIAN: i64 = 492_166_998_415_031;
    const STEPS: u32 = 40;
    let top = atan_x.max(atan_y);
    let (mut x, mut y) = if top.leading_zeros() >= 3 {
        let up = top.leading_zeros() - 3;
        ((atan_x << up) as i64, (atan_y << up) as i64)
    } else {
        let down = 3 - top.leading_zeros();
        ((atan_x >> down) as i64, (atan_y >> down) as i64)
    };
    let mut angle = 0i64;
    for i in 0..STEPS {
        let turn = TURNS.get(i as usize).copied().unwrap_or(RADIAN >> i);
        let (dx, dy) = (y >> i, x >> i);
        if y >= 0 {
            (x, y, angle) = (x + dx, y - dy, angle + turn);
        } else {
            (x, y, angle) = (x - dx, y + dy, angle - turn);
        }
    }
    angle.max(0) as u64
}

/// The view distance in pixels of a look-at camera of `rows` rows whose vertical field of
/// view is `fov_y_degrees` (strictly between 0 and 180), as its builder rounds it: the screen
/// is `2·tan(fov/2)` high one unit from the eye.
fn view_of_fov(fov_y_degrees: f32, rows: u16) -> Fx {
    let half_angle = fov_y_degrees.to_radians() / 2.0;
    let screen_h = 2.0 * libm::tanf(half_angle);
    let pitch = screen_h / rows as f32;
    view_distance(1.0 / pitch)
}

/// A look-at camera's refusal `error` with the limit it names made the one that camera
/// accepts: the widest (or narrowest) field of view in whole thousandths of a degree whose
/// view distance, as [`view_of_fov`] rounds it, passes [`check_budget`] for a screen of
/// `cols × rows` pixels whose row step is `aspect` long. Other errors are left as they are.
///
/// [`check_budget`] names its limit from the budget's continuous equation, to within 10⁻⁵
/// millidegrees; but the view distance it checks is rounded to Q16.16, which on the widest
/// views of small screens (a view distance of a few units of 2⁻¹⁶ pixels) moves the field of
/// view it stands for by up to about 3.5 millidegrees (one unit of 2⁻¹⁶ at a view distance
/// of `F` pixels turns the edge of a screen `h` rows high by `2⁻¹⁶ · h / (F² + h²/4)`
/// radians, at most `4 · 2⁻¹⁶` for one row). So the named value is a start: from it, a
/// thousandth at a time, inwards until the camera accepts it, then outwards while it still
/// does. Acceptance changes once along each way (the view distance falls as the field of view
/// widens, and `F² + R² ≤ B·F` holds between two roots), so that is the widest accepted;
/// a few steps in all, each one tangent, on a path only a refused camera takes. Each way
/// takes at most 64 steps (no screen comes near); should none inwards be accepted, the named
/// value is left.
fn accepted_limit(error: Error, aspect: Fx, cols: u16, rows: u16) -> Error {
    let accepts = |millidegrees: u32| {
        let fov = millidegrees as f32 / 1000.0;
        fov > 0.0 && fov < 180.0 && check_budget(view_of_fov(fov, rows), aspect, cols, rows).is_ok()
    };
    // From `named`, the last value accepted going `outward` (+1 or −1 a step) from the first
    // accepted going the other way.
    let edge = |named: u32, outward: i32| {
        let step = |m: u32, by: i32| m.checked_add_signed(by).filter(|&m| m <= 180_000);
        let mut m = named;
        for _ in 0..64 {
            if accepts(m) {
                for _ in 0..64 {
                    match step(m, outward).filter(|&next| accepts(next)) {
                        Some(next) => m = next,
                        None => break,
                    }
                }
                return m;
            }
            match step(m, -outward) {
                Some(inner) => m = inner,
                None => break,
            }
        }
        named
    };
    match error {
        Error::FieldOfViewTooWide { max_millidegrees } => Error::FieldOfViewTooWide {
            max_millidegrees: edge(max_millidegrees, 1),
        },
        Error::FieldOfViewTooNarrow { min_millidegrees } => Error::FieldOfViewTooNarrow {
            min_millidegrees: edge(min_millidegrees, -1),
        },
        other => other,
    }
}

/// `v`'s unit vector ([`Vec3::try_normalize`]), for the three vectors the look-at set-up
/// normalises.
fn unit(v: Vec3) -> Option<Vec3> {
    v.try_normalize()
}

/// The unit vector along the exact integer vector `v` (any scale; components within ±2⁶²),
/// or `None` for the zero vector: each component within 0.55 of a unit of 2⁻¹⁶ of exact, and
/// a further 2⁻³⁰ at most.
///
/// `v` is first brought to a largest component of 2²⁹ to 2³⁰ in magnitude, so that it fits
/// Q16.16 with room for the normalisation's squares: by a left shift if smaller (exact), or a
/// right shift rounded to nearest if larger (each component then moves by at most half a
/// unit, the whole by at most √3/2 units of a length of at least 2²⁹: a direction within
/// 2⁻²⁹ of `v`'s). [`Vec3::try_normalize`] then does the rest, to 0.55 of a unit of 2⁻¹⁶.
pub(in crate::render) fn unit_of_exact(v: [i64; 3]) -> Option<Vec3> {
    let largest = v.iter().map(|c| c.unsigned_abs()).max().unwrap_or(0);
    if largest == 0 {
        return None;
    }
    // The bit length of `largest` brought to 30: 2²⁹ ≤ largest < 2³⁰ once shifted.
    let length = 64 - largest.leading_zeros() as i32;
    let scaled = |c: i64| {
        let bits = if length <= 30 {
            c << (30 - length)
        } else {
            let down = (length - 30) as u32;
            (c + (1 << (down - 1))) >> down
        };
        // At most 2³⁰ in magnitude (a rounded-up top component), so it fits.
        Fx::from_bits(bits as i32)
    };
    Vec3::new(scaled(v[0]), scaled(v[1]), scaled(v[2])).try_normalize()
}

/// `a × b` exactly, in raw units of 2⁻³², for `a` within ±2048 and `b` within ±1024 (an
/// offset between two points of the overflow-safe range, and one such point): each product
/// of two components is below 2²⁷ · 2²⁶ = 2⁵³ and each difference below 2⁵⁴.
///
/// The look-at camera's `right` is the unit vector along `(target − eye) × up`, formed so
/// from the values it was given rather than from their unit vectors rounded to Q16.16: the
/// cross product of two unit vectors `θ` apart, each off by up to 2⁻¹⁶ a component, points
/// up to about 2⁻¹⁶/sin θ off in the plane of the screen, which turns the picture about its
/// centre by several pixels at the corners of a large screen with `up` a degree off the
/// view (10.8 pixels at 4096 × 4096 with `up` 0.25° off). Formed exactly and normalised
/// once ([`unit_of_exact`]), `right` is within 0.55 of a unit of 2⁻¹⁶ a component of exact
/// whatever θ, and `down = −right × forward` (two unit vectors at right angles) within a few
/// units: the basis the ray budget's half pixel assumes.
fn exact_cross(a: Vec3, b: Vec3) -> [i64; 3] {
    let c = |p: Fx, q: Fx, s: Fx, t: Fx| {
        p.to_bits() as i64 * q.to_bits() as i64 - s.to_bits() as i64 * t.to_bits() as i64
    };
    [
        c(a.y, b.z, a.z, b.y),
        c(a.z, b.x, a.x, b.z),
        c(a.x, b.y, a.y, b.x),
    ]
}

impl Camera {
    /// The camera at `eye` looking along the unit vector `dir` at a screen `view` pixels
    /// away, with one pixel's steps `right` and `down` (`aspect` being the length of `down`,
    /// which the pinhole knows without a square root), `screen` world units from the eye:
    /// built from those rounded values and refused if they break the ray budget.
    #[allow(clippy::too_many_arguments)]
    fn checked(
        eye: Vec3,
        dir: Vec3,
        view: Fx,
        (right, down, aspect): (Vec3, Vec3, Fx),
        screen: Fx,
        cols: u16,
        rows: u16,
    ) -> Result<Self, Error> {
        debug_assert_eq!(aspect, down.length());
        check_resolution(cols, rows)?;
        check_budget(view, aspect, cols, rows)?;
        let forward = dir.scale(view);
        Ok(Camera {
            eye,
            forward,
            view_unit: forward.try_normalize(),
            right,
            down,
            view,
            screen,
            cols,
            rows,
        })
    }

    /// The pinhole camera of [`Camera::pinhole`], its size in pixels checked.
    #[inline]
    fn pinhole_checked(w: f32, h: f32, z_p: f32, cols: u16, rows: u16) -> Result<Self, Error> {
        check_resolution(cols, rows)?;
        positive(w, Quantity::ScreenWidth)?;
        positive(h, Quantity::ScreenHeight)?;
        let screen = positive(z_p, Quantity::ScreenDistance)?;
        let pitch_x = w / cols as f32;
        let pitch_y = h / rows as f32;
        positive(pitch_x, Quantity::PixelWidth)?;
        positive(pitch_y, Quantity::PixelHeight)?;
        let aspect = pitch_y / pitch_x;
        if !(0.25..=4.0).contains(&aspect) {
            return Err(Error::DegenerateCamera(CameraProblem::PixelAspect));
        }
        // Within 1/4..4, so finite: the conversion cannot overflow.
        let down = Fx::from_num(aspect);
        Camera::checked(
            Vec3::ZERO,
            Vec3::new(Fx::ZERO, Fx::ZERO, -Fx::ONE),
            view_distance(z_p / pitch_x),
            (Vec3::X, Vec3::new(Fx::ZERO, -down, Fx::ZERO), down),
            screen,
            cols,
            rows,
        )
    }

    /// The look-at camera of [`Camera::look_at`], its size in pixels checked.
    fn look_at_checked(
        eye: [f32; 3],
        target: [f32; 3],
        up: [f32; 3],
        fov_y_degrees: f32,
        cols: u16,
        rows: u16,
    ) -> Result<Self, Error> {
        check_resolution(cols, rows)?;
        let eye = check::f32_point(eye, Quantity::CameraEye)?;
        let target = check::f32_point(target, Quantity::CameraTarget)?;
        let up = check::f32_point(up, Quantity::CameraUp)?;
        if !fov_y_degrees.is_finite() {
            return Err(Error::NotFinite {
                quantity: Quantity::FieldOfView,
            });
        }
        if !(fov_y_degrees > 0.0 && fov_y_degrees < 180.0) {
            return Err(Error::DegenerateCamera(CameraProblem::FieldOfView));
        }
        let view = target - eye;
        let forward = unit(view).ok_or(Error::DegenerateCamera(CameraProblem::TargetIsEye))?;
        let unit_up = unit(up).ok_or(Error::DegenerateCamera(CameraProblem::UpIsZero))?;
        // Unit vectors closer than about 0.2° to parallel do not define a picture's up: a
        // length below 2⁻⁸. Compared as the exact square (below 2⁻¹⁶), which is the same test
        // since `length` is the floor of the root, and needs no square root.
        if forward.cross(unit_up).length_squared_wide() < 1 << (2 * (FRAC - 8)) {
            return Err(Error::DegenerateCamera(CameraProblem::UpAlongView));
        }
        let right = unit_of_exact(exact_cross(view, up)).unwrap_or(Vec3::X);
        let down = -right.cross(forward);
        let aspect = down.length();
        Camera::checked(
            eye,
            forward,
            view_of_fov(fov_y_degrees, rows),
            (right, down, aspect),
            Fx::ONE,
            cols,
            rows,
        )
        .map_err(|error| accepted_limit(error, aspect, cols, rows))
    }

    /// The orbiting camera of [`Camera::orbit`], its size in pixels checked.
    #[allow(clippy::too_many_arguments)]
    fn orbit_checked(
        target: [f32; 3],
        distance: f32,
        yaw_degrees: f32,
        pitch_degrees: f32,
        fov_y_degrees: f32,
        cols: u16,
        rows: u16,
    ) -> Result<Self, Error> {
        for (value, quantity) in [
            (distance, Quantity::OrbitDistance),
            (yaw_degrees, Quantity::OrbitYaw),
            (pitch_degrees, Quantity::OrbitPitch),
        ] {
            if !value.is_finite() {
                return Err(Error::NotFinite { quantity });
            }
        }
        // A distance that is not positive would put the eye on the far side of the target, or
        // on it; one past the longest distance within the overflow-safe cube, outside it.
        check::f32_within(distance, Fx::DELTA, ORBIT_REACH, Quantity::OrbitDistance)?;
        if !(pitch_degrees > -90.0 && pitch_degrees < 90.0) {
            return Err(Error::DegenerateCamera(CameraProblem::OrbitPitch));
        }
        let (yaw, pitch) = (yaw_degrees.to_radians(), pitch_degrees.to_radians());
        let flat = distance * F32Ext::cos(pitch);
        let eye = [
            target[0] + flat * F32Ext::sin(yaw),
            target[1] + distance * F32Ext::sin(pitch),
            target[2] + flat * F32Ext::cos(yaw),
        ];
        Camera::look_at_checked(eye, target, [0.0, 1.0, 0.0], fov_y_degrees, cols, rows)
    }

    /// The screen's size in pixels: width (columns) by height (rows).
    #[must_use]
    pub const fn size(&self) -> Size {
        Size::new(self.cols as u32, self.rows as u32)
    }

    /// The screen's width in pixels (its columns).
    #[must_use]
    pub const fn width(&self) -> u32 {
        self.cols as u32
    }

    /// The screen's height in pixels (its rows).
    #[must_use]
    pub const fn height(&self) -> u32 {
        self.rows as u32
    }

    /// Columns (pixels across): [`Camera::width`] as the render path counts them.
    pub(crate) const fn cols(&self) -> u16 {
        self.cols
    }

    /// Rows (pixels down): [`Camera::height`] as the render path counts them.
    pub(crate) const fn rows(&self) -> u16 {
        self.rows
    }

    /// The viewpoint.
    #[must_use]
    pub const fn eye(&self) -> Vec3 {
        self.eye
    }

    /// Refuses a display row outside the screen: the one check of every function that takes
    /// a row of the picture ([`render_row`](crate::render_row), [`shoot_row`](crate::shoot_row),
    /// [`Camera::row_rays`], …).
    ///
    /// A row of the screen comes back as the render path counts rows.
    pub(crate) fn check_row(&self, y: u32) -> Result<u16, Error> {
        match u16::try_from(y) {
            Ok(row) if row < self.rows => Ok(row),
            _ => Err(Error::RowOutOfRange {
                row: y,
                rows: u32::from(self.rows),
            }),
        }
    }

    /// Refuses a pixel outside the screen: a column past the right edge
    /// ([`Error::ColumnOutOfRange`]) or a row past the bottom ([`Error::RowOutOfRange`]).
    pub(crate) fn check_pixel(&self, x: u32, y: u32) -> Result<(), Error> {
        match u16::try_from(x) {
            Ok(col) if col < self.cols => {}
            _ => {
                return Err(Error::ColumnOutOfRange {
                    col: x,
                    cols: u32::from(self.cols),
                });
            }
        }
        self.check_row(y).map(|_| ())
    }

    /// From the eye towards the centre of pixel (`x`, `y`), in pixel units, unnormalised.
    pub(crate) fn towards(&self, x: u32, y: u32) -> Vec3 {
        self.towards_sample(x, y, 0, 0, 1)
    }

    /// `2n` times the direction from the eye towards sample (`sx`, `sy`) of an `n × n` grid of
    /// sub-pixel centres in pixel (`x`, `y`), as raw Q16.16 values (exact), and `2n`.
    fn towards_wide(&self, x: u32, y: u32, sx: u8, sy: u8, n: u8) -> ([i64; 3], i64) {
        // Offsets from the screen centre in units of 1/(2n) pixel:
        // 2n·(x + (2·sx + 1)/(2n)) − n·cols.
        let n = n.max(1) as i64;
        let denom = 2 * n;
        let kx = denom * x as i64 + 2 * sx as i64 + 1 - n * self.cols as i64;
        let ky = denom * y as i64 + 2 * sy as i64 + 1 - n * self.rows as i64;
        // |kx|, |ky| < 2³⁸ for any u32 column or row and n ≤ 16. `right` is a unit vector in
        // pixel units (raw components within 2¹⁶), `down` at most 4 pixels long (raw 2¹⁸) and
        // `forward` at most 16 384 (raw 2³⁰), so each sum is below 2⁵⁷.
        // On the screen (and for a few thousand pixels about it) the offsets fit 32 bits: the
        // products of two `i32`s, as the work of a row takes them (`fx::wide_mul`).
        let small = kx == kx as i32 as i64 && ky == ky as i32 as i64;
        let times = |a: Fx, k: i64| {
            if small {
                fx::wide_mul(a.to_bits(), k as i32)
            } else {
                a.to_bits() as i64 * k
            }
        };
        let c = |f: Fx, r: Fx, d: Fx| f.to_bits() as i64 * denom + times(r, kx) + times(d, ky);
        (
            [
                c(self.forward.x, self.right.x, self.down.x),
                c(self.forward.y, self.right.y, self.down.y),
                c(self.forward.z, self.right.z, self.down.z),
            ],
            denom,
        )
    }

    /// From the eye towards sample (`sx`, `sy`) of an `n × n` grid of sub-pixel centres in
    /// pixel (`x`, `y`), in pixel units, unnormalised. `n = 1` is the pixel centre.
    ///
    /// On the screen it is the exact direction rounded (half up) to Q16.16: the ray budget
    /// keeps it within 16 384 pixels. Off the screen it may be longer than Q16.16 holds, and
    /// is then scaled down by a power of two until it is at most 16 384 pixels long per
    /// component, and rounded: the same direction, to about 2⁻³⁰.
    fn towards_sample(&self, x: u32, y: u32, sx: u8, sy: u8, n: u8) -> Vec3 {
        let (wide, denom) = self.towards_wide(x, y, sx, sy, n);
        let shift = if x < u32::from(self.cols) && y < u32::from(self.rows) {
            0
        } else {
            Camera::shift_to_fit(&wide, denom)
        };
        // Divide by 2n·2^shift, rounding half up; the quotient is below 2³⁰ + 1 in magnitude.
        // Floors compose, so it is a shift by 1 + shift and then a division by n, which the
        // pixel centres (n = 1) skip.
        let n = denom / 2;
        let c = |w: i64| {
            let halved = (w + (n << shift)) >> (shift + 1);
            Fx::from_bits(if n == 1 { halved } else { halved.div_euclid(n) } as i32)
        };
        Vec3::new(c(wide[0]), c(wide[1]), c(wide[2]))
    }

    /// The smallest `k` for which `2n`-fold components `wide` divided by `2n·2^k` are at most
    /// 2³⁰ in raw magnitude (16 384 pixels); at most 26, as they are below 2⁵⁷.
    #[cold]
    fn shift_to_fit(wide: &[i64; 3], denom: i64) -> u32 {
        let largest = wide.iter().map(|w| w.unsigned_abs()).max().unwrap_or(0);
        let limit = (denom as u64) << 30;
        let mut shift = 0;
        while largest >> shift > limit {
            shift += 1;
        }
        shift
    }

    /// The centre of pixel (`x`, `y`) on the view screen, in world units (column `x` from
    /// the left, row `y` from the top), rounded once to Q16.16.
    ///
    /// It lies on the pixel's ray ([`Camera::ray`]): the camera's own direction towards the
    /// pixel, in pixel units, scaled by the screen's distance over the view distance. Both
    /// are as rounded to Q16.16, so the point carries the view distance's rounding, a
    /// relative 2⁻¹⁷/F for a view distance of F pixels. Columns and rows outside the screen
    /// (every `u32` is allowed) continue its plane; a coordinate beyond the Q16.16 range
    /// saturates (at −32 768 or just below 32 768), the others are unaffected.
    #[must_use]
    pub fn pixel_centre(&self, x: u32, y: u32) -> Vec3 {
        let (wide, denom) = self.towards_wide(x, y, 0, 0, 1);
        // World = pixels · screen / view. Below 2⁵⁷ · 2³¹: the product fits i128, and the
        // divisor is positive (the view distance is at least one Q16.16 step).
        let divisor = denom as i128 * self.view.to_bits() as i128;
        let c = |w: i64| {
            let point =
                (w as i128 * self.screen.to_bits() as i128 + divisor / 2).div_euclid(divisor);
            Fx::from_bits(point.clamp(i32::MIN as i128, i32::MAX as i128) as i32)
        };
        self.eye + Vec3::new(c(wide[0]), c(wide[1]), c(wide[2]))
    }

    /// The ray from the viewpoint through the centre of pixel (`x`, `y`), column `x` from
    /// the left and row `y` from the top: `u_r = p / ‖p‖`.
    ///
    /// Every `u32` column and row is allowed: those outside the screen (right of it or below
    /// it) continue its plane without wrapping (their directions are exact to about 2⁻³⁰
    /// before normalising, like the screen's own).
    #[must_use]
    pub fn ray(&self, x: u32, y: u32) -> Ray {
        // The ray budget keeps the screen at least a Q16.16 step in front of the eye, and
        // pixel centres off the screen are farther from the eye, so p is never zero.
        let towards = self.towards(x, y);
        Ray::along(self.eye, towards.normalize_or_zero(), towards)
    }

    /// The ray through sample (`sx`, `sy`) of an `n × n` grid of sub-pixel centres in pixel
    /// (`x`, `y`), for supersampling: sample `(s, t)` sits at
    /// `(x + (2s + 1)/(2n), y + (2t + 1)/(2n))`. `n` is clamped to 1..=16; `n = 1` is
    /// [`Camera::ray`]. Like it, every `u32` column and row is allowed.
    #[must_use]
    pub fn sample_ray(&self, x: u32, y: u32, sx: u8, sy: u8, n: u8) -> Ray {
        let towards = self.towards_sample(x, y, sx, sy, n.clamp(1, 16));
        Ray::along(self.eye, towards.normalize_or_zero(), towards)
    }
}

#[cfg(test)]
mod tests;
