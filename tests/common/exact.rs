//! Exact `f64` arithmetic on Q16.16 values: the conversion ([`ToF64`]), one unit ([`ULP`]),
//! lengths and the tolerance of a unit vector, and the chapter's camera worked out in `f64`
//! ([`CameraSpec::exact_ray`]) for the oracles to judge fixray's rays by.

use fixray::{Camera, Vec3};

use super::CameraSpec;
use super::camera_spec::rounded3;

/// A vector's components as `f64`, exactly (every Q16.16 number is an `f64`). The fuzz target
/// shares this module and has no reference model, so the conversion is here.
pub trait ToF64 {
    fn to_f64(self) -> [f64; 3];
}

impl ToF64 for Vec3 {
    fn to_f64(self) -> [f64; 3] {
        [self.x.to_num(), self.y.to_num(), self.z.to_num()]
    }
}

/// One unit of Q16.16.
pub const ULP: f64 = 1.0 / 65536.0;

impl CameraSpec {
    /// The chapter's exact camera in `f64` for the rounded inputs fixray accepted: the
    /// direction of the ray through pixel (`x`, `y`) continuing the screen plane past its
    /// edges, the view distance in pixels, and the sine of the angle between the view and up
    /// (1 for the pinhole, whose basis is exact).
    pub fn exact_ray(&self, camera: &Camera, x: f64, y: f64) -> ([f64; 3], f64, f64) {
        let (cols, rows) = (camera.width() as f64, camera.height() as f64);
        let (x, y) = (x + 0.5 - cols / 2.0, y + 0.5 - rows / 2.0);
        match *self {
            CameraSpec::Pinhole { w, h, z_p, .. } => {
                let (pw, ph) = (w as f64 / cols, h as f64 / rows);
                let d = [x * pw, -y * ph, -(z_p as f64)];
                (unit(d), z_p as f64 / pw, 1.0)
            }
            CameraSpec::LookAt {
                target, up, fov, ..
            } => look_at_ray(camera.eye(), target, up, fov, rows, x, y),
            CameraSpec::Orbit { target, fov, .. } => {
                look_at_ray(camera.eye(), target, [0.0, 1.0, 0.0], fov, rows, x, y)
            }
        }
    }
}

fn look_at_ray(
    eye: Vec3,
    target: [f32; 3],
    up: [f32; 3],
    fov: f32,
    rows: f64,
    x: f64,
    y: f64,
) -> ([f64; 3], f64, f64) {
    let e = eye.to_f64();
    let t = rounded3(target).expect("accepted").to_f64();
    let u = unit(rounded3(up).expect("accepted").to_f64());
    let forward = unit(sub(t, e));
    let side = cross(forward, u);
    let right = unit(side);
    let true_up = cross(right, forward);
    let f = rows / (2.0 * (fov as f64).to_radians().mul_add(0.5, 0.0).tan());
    let d = [0, 1, 2].map(|i| f * forward[i] + x * right[i] - y * true_up[i]);
    (unit(d), f, norm(side))
}

pub(super) fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(super) fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub(super) fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

pub(super) fn unit(a: [f64; 3]) -> [f64; 3] {
    let n = norm(a);
    [a[0] / n, a[1] / n, a[2] / n]
}

/// The exact length of a Q16.16 vector.
pub fn length(v: Vec3) -> f64 {
    norm(v.to_f64())
}

/// How far a normalised Q16.16 vector may be from unit length: `try_normalize` puts each
/// component within one unit of 2⁻¹⁶ of the exact unit vector (its documented bound), so the
/// length is within √3 units of 1.
pub const UNIT_TOLERANCE: f64 = 1.732_050_808 * ULP;
