//! Generated cameras: a [`CameraSpec`] is a camera as the user asked for it, built through
//! fixray's constructors, with the documented rules for when fixray must refuse it.

use embedded_graphics::prelude::Size;
use fixray::{Camera, Error, Fx, Vec3};

use super::{Source, f32_around};

/// A camera as the user asked for it, before fixray checks it.
#[derive(Debug, Clone, Copy)]
pub enum CameraSpec {
    Pinhole {
        w: f32,
        h: f32,
        z_p: f32,
        rows: u32,
        cols: u32,
    },
    LookAt {
        eye: [f32; 3],
        target: [f32; 3],
        up: [f32; 3],
        fov: f32,
        cols: u32,
        rows: u32,
    },
    Orbit {
        target: [f32; 3],
        distance: f32,
        yaw: f32,
        pitch: f32,
        fov: f32,
        cols: u32,
        rows: u32,
    },
}

/// A screen size: mostly small, sometimes a single pixel, the largest allowed, or too large.
fn screen(src: &mut impl Source, hostility: u64) -> (u32, u32) {
    const SIDES: [u32; 8] = [0, 1, 2, 4096, 4097, 65_536, 1 << 31, u32::MAX];
    if src.one_in(4) {
        (12, 9) // the framebuffer size the checks render into
    } else if src.one_in(hostility) {
        (src.pick(&SIDES), src.pick(&SIDES))
    } else {
        (1 + src.below(40) as u32, 1 + src.below(30) as u32)
    }
}

/// A camera: hostile one value in `hostility`, otherwise an ordinary one.
pub fn camera_spec<S: Source>(src: &mut S, hostility: u64) -> CameraSpec {
    let (cols, rows) = screen(src, hostility);
    let fov = |s: &mut S| {
        if s.one_in(hostility) {
            s.pick(&[
                1e-6,
                0.001,
                0.5,
                1.7,
                179.0,
                179.9,
                179.999,
                180.0,
                -60.0,
                f32::NAN,
            ])
        } else {
            10.0 + s.uniform(160.0).abs().min(160.0)
        }
    };
    let point = |s: &mut S, typical| {
        [
            f32_around(s, typical, hostility),
            f32_around(s, typical, hostility),
            f32_around(s, typical, hostility),
        ]
    };
    match src.below(3) {
        0 => {
            let h = f32_around(src, 2.0, hostility).abs();
            let w = if src.one_in(2) {
                h * cols as f32 / rows.max(1) as f32
            } else {
                f32_around(src, 2.0, hostility).abs()
            };
            CameraSpec::Pinhole {
                w,
                h,
                z_p: f32_around(src, 2.0, hostility).abs(),
                rows,
                cols,
            }
        }
        1 => {
            let eye = point(src, 20.0);
            let target = if src.one_in(hostility) {
                eye
            } else {
                point(src, 20.0)
            };
            let up = if src.one_in(hostility) {
                [target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]]
            } else if src.one_in(2) {
                [0.0, 1.0, 0.0]
            } else {
                point(src, 1.0)
            };
            CameraSpec::LookAt {
                eye,
                target,
                up,
                fov: fov(src),
                cols,
                rows,
            }
        }
        _ => CameraSpec::Orbit {
            target: point(src, 20.0),
            distance: f32_around(src, 30.0, hostility),
            yaw: f32_around(src, 400.0, hostility),
            pitch: f32_around(src, 95.0, hostility),
            fov: fov(src),
            cols,
            rows,
        },
    }
}

/// Q16.16 as fixray rounds a checked `f32` input, or `None` where it must refuse it.
fn rounded(v: f32) -> Option<Fx> {
    (v.is_finite() && (-1024.0..=1024.0).contains(&v)).then(|| Fx::from_num(v))
}

pub(super) fn rounded3(v: [f32; 3]) -> Option<Vec3> {
    Some(Vec3::new(rounded(v[0])?, rounded(v[1])?, rounded(v[2])?))
}

/// Exact i128 cross product of raw Q16.16 components (units of 2⁻³²).
fn cross_i128(a: Vec3, b: Vec3) -> [i128; 3] {
    let r = |v: Fx| v.to_bits() as i128;
    [
        r(a.y) * r(b.z) - r(a.z) * r(b.y),
        r(a.z) * r(b.x) - r(a.x) * r(b.z),
        r(a.x) * r(b.y) - r(a.y) * r(b.x),
    ]
}

impl CameraSpec {
    pub fn build(&self) -> Result<Camera, Error> {
        match *self {
            CameraSpec::Pinhole {
                w,
                h,
                z_p,
                rows,
                cols,
            } => Camera::pinhole(w, h, z_p)
                .size(Size::new(cols, rows))
                .build(),
            CameraSpec::LookAt {
                eye,
                target,
                up,
                fov,
                cols,
                rows,
            } => Camera::look_at(eye, target)
                .up(up)
                .fov_degrees(fov)
                .size(Size::new(cols, rows))
                .build(),
            CameraSpec::Orbit {
                target,
                distance,
                yaw,
                pitch,
                fov,
                cols,
                rows,
            } => Camera::orbit(target, distance)
                .yaw_degrees(yaw)
                .pitch_degrees(pitch)
                .fov_degrees(fov)
                .size(Size::new(cols, rows))
                .build(),
        }
    }

    /// Why fixray must refuse this camera, by the documented rules, if it must.
    pub fn must_refuse(&self) -> Option<&'static str> {
        let screen = |cols: u32, rows: u32| {
            (cols == 0 || rows == 0 || cols > 4096 || rows > 4096).then_some("screen size")
        };
        let fov_bad = |fov: f32| !(fov.is_finite() && fov > 0.0 && fov < 180.0);
        match *self {
            CameraSpec::Pinhole {
                w,
                h,
                z_p,
                rows,
                cols,
            } => screen(cols, rows).or_else(|| {
                [w, h, z_p]
                    .iter()
                    .any(|v| !v.is_finite() || *v <= 0.0 || *v > 1024.0)
                    .then_some("screen width, height or distance not in (0, 1024]")
            }),
            CameraSpec::LookAt {
                eye,
                target,
                up,
                fov,
                cols,
                rows,
            } => screen(cols, rows).or_else(|| {
                let (Some(e), Some(t), Some(u)) = (rounded3(eye), rounded3(target), rounded3(up))
                else {
                    return Some("eye, target or up not finite or outside ±1024");
                };
                if fov_bad(fov) {
                    return Some("field of view outside (0°, 180°)");
                }
                if e == t {
                    return Some("target is the eye");
                }
                if u == Vec3::ZERO {
                    return Some("up is zero");
                }
                if cross_i128(t - e, u) == [0; 3] {
                    return Some("up is parallel to the view");
                }
                None
            }),
            CameraSpec::Orbit {
                target,
                distance,
                yaw,
                pitch,
                fov,
                cols,
                rows,
            } => screen(cols, rows).or_else(|| {
                if ![distance, yaw, pitch].iter().all(|v| v.is_finite())
                    || rounded3(target).is_none()
                {
                    return Some("orbit values or target not finite, or target outside ±1024");
                }
                if !(pitch > -90.0 && pitch < 90.0) {
                    return Some("orbit pitch outside (−90°, 90°)");
                }
                if fov_bad(fov) {
                    return Some("field of view outside (0°, 180°)");
                }
                None
            }),
        }
    }
}
