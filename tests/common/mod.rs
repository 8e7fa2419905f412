//! Hostile inputs and the oracles that judge fixray on them, shared by `tests/hostile.rs` (a
//! seeded xorshift drives the choices) and the `cargo fuzz` target in `fuzz/` (libFuzzer's bytes
//! drive them). Both see the same generators and the same assertions; only the source of the
//! choices differs.
//!
//! Only fixray's public API is used, and every expected value is worked out here independently:
//! exact integer or `f64` arithmetic on the Q16.16 values, brute-force loops over the objects,
//! and the chapter's formulas for the camera.
#![allow(dead_code)] // each user of this module calls a different part of it

use std::collections::HashMap;

use embedded_graphics::pixelcolor::{BinaryColor, Gray8, PixelColor, Rgb565, Rgb888};
use embedded_graphics::prelude::{DrawTarget, OriginDimensions, Pixel, Point, Size};
use embedded_graphics::primitives::Rectangle;
use fixray::draw::{self, Viewport};
use fixray::{
    Background, Camera, Error, FAR, Framebuffer, Fx, LIMIT, Light, Material, Object, Plane, Ray,
    Rgb, Scene, SceneHit, Shape, Sphere, Vec3,
};

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

/// Where the choices come from.
pub trait Source {
    /// The next 64 random bits (a fuzzer's input that has run out gives zeros).
    fn bits(&mut self) -> u64;

    /// A value in `0..n` (0 when `n` is 0).
    fn below(&mut self, n: u64) -> u64 {
        if n == 0 { 0 } else { self.bits() % n }
    }

    /// True one time in `n`.
    fn one_in(&mut self, n: u64) -> bool {
        self.below(n) == 0
    }

    /// A uniform `f32` in `[-range, range]`.
    fn uniform(&mut self, range: f32) -> f32 {
        let unit = (self.bits() >> 40) as f32 / (1u32 << 24) as f32; // [0, 1)
        (2.0 * unit - 1.0) * range
    }

    /// One of `items`.
    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len() as u64) as usize]
    }
}

/// Marsaglia's xorshift64 (shifts 13, 7, 17), started from a seed: the same cases on every run.
pub struct XorShift(pub u64);

impl XorShift {
    /// A generator for case `seed`; the seed is mixed (splitmix64) so neighbouring seeds give
    /// unrelated sequences, and never leaves the state zero.
    pub fn new(seed: u64) -> Self {
        let mut z = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        XorShift((z ^ (z >> 31)) | 1)
    }
}

impl Source for XorShift {
    fn bits(&mut self) -> u64 {
        let s = &mut self.0;
        *s ^= *s << 13;
        *s ^= *s >> 7;
        *s ^= *s << 17;
        *s
    }
}

// ---------------------------------------------------------------------------------------------
// Hostile values
// ---------------------------------------------------------------------------------------------

/// Floats that break careless set-up code: non-finite, huge, tiny, just past the limits.
const NASTY_F32: [f32; 20] = [
    f32::NAN,
    f32::INFINITY,
    f32::NEG_INFINITY,
    f32::MAX,
    f32::MIN,
    f32::MIN_POSITIVE,
    1e-30,
    1e-6,
    -0.0,
    0.0,
    1024.0,
    -1024.0,
    1024.0001,
    -1024.0001,
    f32::EPSILON,
    179.999,
    180.0,
    89.9999,
    4096.0,
    8192.0,
];

/// An `f32` around `typical` in size, hostile one time in `hostility`.
pub fn f32_around(src: &mut impl Source, typical: f32, hostility: u64) -> f32 {
    if src.one_in(hostility) {
        src.pick(&NASTY_F32)
    } else {
        src.uniform(typical)
    }
}

/// Raw Q16.16 values that break careless arithmetic: the ends of the range, single units,
/// just past [`LIMIT`] and [`FAR`].
pub fn fx_any(src: &mut impl Source) -> Fx {
    let raw = match src.below(8) {
        0 => src.pick(&[
            i32::MIN,
            i32::MAX,
            i32::MIN + 1,
            0,
            1,
            -1,
            1 << 16,
            -(1 << 16),
            (1024 << 16) + 1,
            -(1024 << 16) - 1,
            8192 << 16,
            (8192 << 16) + 1,
        ]),
        1 => src.bits() as i32,
        2 => (src.bits() as i32) >> src.below(32),
        _ => return Fx::from_num(src.uniform(40.0)),
    };
    Fx::from_bits(raw)
}

/// A vector of [`fx_any`] components.
pub fn vec_any(src: &mut impl Source) -> Vec3 {
    if src.one_in(8) {
        // All three at an end of the range: the largest sums of products.
        let end = |s: &mut _| {
            if Source::one_in(s, 2) {
                Fx::MAX
            } else {
                Fx::MIN
            }
        };
        return Vec3::new(end(src), end(src), end(src));
    }
    Vec3::new(fx_any(src), fx_any(src), fx_any(src))
}

/// A vector of finite `f32` components around `typical` (never hostile), as fixray rounds them (the caller's `f32`
/// values are converted exactly as [`Vec3::from_f32`] does: `Fx::from_num`).
pub fn vec_within(src: &mut impl Source, typical: f32) -> Vec3 {
    fn c(s: &mut impl Source, typical: f32) -> Fx {
        Fx::from_num(s.uniform(typical).clamp(-1024.0, 1024.0))
    }
    Vec3::new(c(src, typical), c(src, typical), c(src, typical))
}

/// A direction: along an axis, tiny (a few units of 2⁻¹⁶), or random.
pub fn direction(src: &mut impl Source) -> Vec3 {
    match src.below(6) {
        0 => src.pick(&[Vec3::X, Vec3::Y, Vec3::Z, -Vec3::X, -Vec3::Y, -Vec3::Z]),
        1 => Vec3::new(
            Fx::from_bits(src.below(5) as i32 - 2),
            Fx::from_bits(src.below(5) as i32 - 2),
            Fx::from_bits(src.below(5) as i32 - 2),
        ),
        _ => vec_within(src, 1.0),
    }
}

fn rgb(src: &mut impl Source) -> Rgb {
    let b = src.bits();
    Rgb::new(b as u8, (b >> 8) as u8, (b >> 16) as u8)
}

// ---------------------------------------------------------------------------------------------
// Scenes
// ---------------------------------------------------------------------------------------------

/// A scene as a list of already-validated parts, so that one description can be loaded into
/// scenes of several capacities, printed as a reproducer, and rebuilt with other lights.
#[derive(Debug, Clone)]
pub struct World {
    pub objects: Vec<Object>,
    pub lights: Vec<Light>,
    pub ambient: Fx,
    pub background: Background,
    pub shadows: bool,
    pub depth: u8,
}

/// Where the generated camera looks from and to: objects are scattered around that view.
#[derive(Debug, Clone, Copy)]
pub struct View {
    pub eye: Vec3,
    pub forward: Vec3,
}

/// A material through the public constructors: matte, a checked `Material::new`, a mirror,
/// a checkerboard.
fn material(src: &mut impl Source) -> Material {
    let colour = rgb(src);
    fn weight(s: &mut impl Source, max: f32) -> Fx {
        Fx::from_num(s.uniform(max).abs())
    }
    let m = match src.below(4) {
        0 => Material::matte(colour),
        1 => Material::from_fx(
            colour,
            weight(src, 2.0),
            weight(src, 16.0),
            1 + src.below(4096) as u16,
            Fx::ZERO,
        )
        .expect("weights drawn inside their documented ranges"),
        _ => Material::from_fx(
            colour,
            weight(src, 2.0),
            weight(src, 16.0),
            1 + src.below(4096) as u16,
            if src.one_in(3) {
                Fx::ONE
            } else {
                weight(src, 1.0)
            },
        )
        .expect("weights drawn inside their documented ranges"),
    };
    let m = if src.one_in(4) {
        let size = src.pick(&[Fx::from_bits(1), Fx::from_num(0.5), Fx::from_num(2), LIMIT]);
        m.with_checker_fx(size, rgb(src))
            .expect("checker size drawn inside its documented range")
    } else {
        m
    };
    if src.one_in(4) {
        // Glass: indices across the whole range, the ends too, and any weight up to 1.
        let index = match src.below(4) {
            0 => Fx::from_num(0.25),
            1 => Fx::from_num(4),
            _ => Fx::from_num(0.25 + src.uniform(3.75).abs()),
        };
        let through = weight(src, 1.0).max(Fx::from_bits(1));
        let glass = m
            .with_refraction_fx(index, through)
            .expect("index and weight drawn inside their documented ranges");
        if src.one_in(2) {
            glass.with_fresnel()
        } else {
            glass
        }
    } else {
        m
    }
}

/// A sphere near the view (or anywhere, one time in eight), of a radius from 2⁻¹⁶ to 1024.
fn sphere(src: &mut impl Source, view: View) -> Sphere {
    let radius = match src.below(8) {
        0 => Fx::from_bits(1 + src.below(64) as i32),
        1 => LIMIT,
        2 => Fx::from_num(src.uniform(200.0).abs()).max(Fx::from_bits(1)),
        _ => Fx::from_num(0.05 + src.uniform(4.0).abs()),
    };
    let centre = if src.one_in(8) {
        vec_within(src, 1024.0)
    } else {
        let along = Fx::from_num(2.0 + src.uniform(40.0).abs());
        let spread = vec_within(src, 10.0);
        (view.eye + view.forward.scale(along) + spread).clamp_limit()
    };
    Sphere::from_fx(centre, radius).expect("centre and radius drawn inside the limits")
}

/// A plane through a point near the view, possibly bounded.
fn plane(src: &mut impl Source, view: View) -> Plane {
    let point = (view.eye + vec_within(src, 20.0)).clamp_limit();
    let normal = loop {
        let n = direction(src);
        if n != Vec3::ZERO {
            break n;
        }
    };
    let plane = Plane::from_fx(point, normal).expect("point inside the limits, normal non-zero");
    if src.one_in(3) {
        let (a, b) = (
            Fx::from_num(src.uniform(30.0)),
            Fx::from_num(src.uniform(30.0)),
        );
        let (c, d) = (
            Fx::from_num(src.uniform(30.0)),
            Fx::from_num(src.uniform(30.0)),
        );
        let lo = [a.min(b), c.min(d)];
        let hi = [a.max(b) + Fx::from_bits(1), c.max(d) + Fx::from_bits(1)];
        plane
            .bounded_fx(lo, hi)
            .expect("bounds inside the limits, min below max")
    } else {
        plane
    }
}

/// Clamping into ±LIMIT, for generated points pushed outward by an offset, and for hostile
/// points moved to the nearest one a constructor accepts.
pub trait ClampLimit {
    fn clamp_limit(self) -> Self;
}

impl ClampLimit for Vec3 {
    fn clamp_limit(self) -> Vec3 {
        let c = |v: Fx| v.clamp(-LIMIT, LIMIT);
        Vec3::new(c(self.x), c(self.y), c(self.z))
    }
}

/// A world of `count` objects around `view`. Past the 64th object the interesting ones sit:
/// with `crowded`, the first 63 or 64 are small spheres out of sight (behind the eye), so the
/// objects in view and the mirrors are those past the 64th. One time in six the eye is put on
/// a surface: a plane through it, or a sphere whose surface passes through it.
pub fn world(src: &mut impl Source, view: View, count: usize, crowded: bool) -> World {
    let mut objects = Vec::with_capacity(count);
    if crowded {
        let hidden = 63 + src.below(2) as usize;
        for i in 0..hidden.min(count) {
            let behind = view.eye - view.forward.scale(Fx::from_num(30 + (i % 7) as i32));
            let centre = (behind + vec_within(src, 5.0)).clamp_limit();
            let s = Sphere::from_fx(centre, Fx::from_num(0.25)).expect("inside the limits");
            objects.push(Object {
                shape: Shape::Sphere(s),
                material: material(src),
            });
        }
    }
    if src.one_in(6) {
        let shape = if src.one_in(2) {
            Shape::Plane(Plane::from_fx(view.eye, direction_non_zero(src)).expect("valid"))
        } else {
            // An axis-aligned offset of exactly r: the eye lies exactly on the surface.
            let r = Fx::from_num(0.5 + src.uniform(50.0).abs());
            let axis = src.pick(&[Vec3::X, Vec3::Y, Vec3::Z, -Vec3::X, -Vec3::Y, -Vec3::Z]);
            let centre = view.eye + axis.scale(r);
            match Sphere::from_fx(centre, r) {
                Ok(s) => Shape::Sphere(s),
                Err(_) => Shape::Plane(Plane::from_fx(view.eye, axis).expect("valid")),
            }
        };
        objects.push(Object {
            shape,
            material: material(src),
        });
    }
    while objects.len() < count {
        let shape = if src.one_in(4) {
            Shape::Plane(plane(src, view))
        } else {
            Shape::Sphere(sphere(src, view))
        };
        objects.push(Object {
            shape,
            material: material(src),
        });
    }
    let lights = (0..1 + src.below(4))
        .map(|_| {
            let position = (view.eye + vec_within(src, 60.0)).clamp_limit();
            let intensity = Fx::from_num(src.uniform(4.0).abs());
            Light::from_fx(position, intensity).expect("inside the limits")
        })
        .collect();
    let background = if src.one_in(2) {
        Background::plain(rgb(src))
    } else {
        Background {
            top: rgb(src),
            bottom: rgb(src),
        }
    };
    World {
        objects,
        lights,
        ambient: Fx::from_num(src.uniform(1.0).abs()),
        background,
        shadows: !src.one_in(4),
        depth: src.pick(&[0, 1, 4, 16, 255]),
    }
}

fn direction_non_zero(src: &mut impl Source) -> Vec3 {
    loop {
        let d = direction(src);
        if d != Vec3::ZERO {
            return d;
        }
    }
}

impl World {
    /// The scene of capacity `N`, or `None` when the objects do not fit, which must then be
    /// the capacity error (checked here).
    pub fn build<const N: usize>(&self) -> Option<Scene<N>> {
        self.build_with_lights::<N>(&self.lights, self.shadows)
    }

    /// The same objects lit by `lights` instead (a light of no intensity when there are none:
    /// a scene needs one, and it adds nothing).
    pub fn build_with_lights<const N: usize>(
        &self,
        lights: &[Light],
        shadows: bool,
    ) -> Option<Scene<N>> {
        let dark = Light::from_fx(Vec3::ZERO, Fx::ZERO).expect("valid");
        let first = lights.first().copied().unwrap_or(dark);
        let mut scene = Scene::<N>::from_fx(first, self.ambient, self.background)
            .expect("ambient drawn within 0..=1");
        for light in lights.iter().skip(1) {
            scene.add_light(*light).expect("at most four lights");
        }
        // Capacity: exactly N objects fit, the next is refused.
        for (i, object) in self.objects.iter().enumerate() {
            match scene.add(*object) {
                Ok(index) => assert_eq!(index, i, "add returns the object's index"),
                Err(e) => {
                    assert!(i >= N, "object {i} refused by a scene of capacity {N}: {e}");
                    assert_eq!(e, Error::CapacityExceeded { capacity: N });
                    return None;
                }
            }
        }
        scene.set_shadows(shadows);
        scene.set_depth(self.depth);
        assert_eq!(scene.depth(), self.depth.min(16), "depth is capped at 16");
        assert_eq!(scene.objects(), &self.objects[..]);
        if lights.is_empty() {
            assert_eq!(scene.lights(), &[dark]);
        } else {
            assert_eq!(scene.lights(), lights);
        }
        Some(scene)
    }
}

// ---------------------------------------------------------------------------------------------
// Cameras
// ---------------------------------------------------------------------------------------------

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

fn rounded3(v: [f32; 3]) -> Option<Vec3> {
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

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

fn unit(a: [f64; 3]) -> [f64; 3] {
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

// ---------------------------------------------------------------------------------------------
// Oracles
// ---------------------------------------------------------------------------------------------

/// Constructors: `Err` exactly where the documented rules say so; the accepted camera's rays
/// are unit vectors close to the chapter's exact camera on the screen (and, with
/// `past_edges`, past its edges too: see [`check_rays_past_the_screen`]).
pub fn check_camera_spec(spec: &CameraSpec, past_edges: bool) -> Option<Camera> {
    let built = spec.build();
    // [ASSERT: Err for invalid input] The documented refusals are refusals.
    if let Some(why) = spec.must_refuse() {
        assert!(
            built.is_err(),
            "{spec:?} must be refused ({why}), got {built:?}"
        );
        return None;
    }
    let camera = built.ok()?;
    let (cols, rows) = (camera.width(), camera.height());
    check_rays(
        spec,
        &camera,
        &[
            (0, 0),
            (cols - 1, rows - 1),
            (cols / 2, rows / 2),
            (cols - 1, 0),
        ],
    );
    if past_edges {
        check_rays_past_the_screen(spec, &camera);
    }
    Some(camera)
}

/// [ASSERT: rays past the screen continue it] The docs promise that columns and rows outside
/// the screen, up to the last `u32`, continue the screen plane without wrapping: the rays
/// there are checked like those on it, and `row_rays` of rows past the screen refused.
/// (Separate from the rest, and run last in a case, so that a failure here does not hide the
/// others.)
pub fn check_rays_past_the_screen(spec: &CameraSpec, camera: &Camera) {
    let (cols, rows) = (camera.width(), camera.height());
    let mut pixels = Vec::new();
    for far in [
        cols,
        cols.saturating_add(1),
        cols.saturating_mul(2),
        40000,
        u32::from(u16::MAX),
        u32::MAX,
    ] {
        pixels.push((far, rows / 2));
        pixels.push((cols / 2, far));
    }
    pixels.push((u32::MAX, u32::MAX));
    check_rays(spec, camera, &pixels);
    for y in [rows, u32::from(u16::MAX) + 1, u32::MAX] {
        assert!(camera.row_rays(y).is_err(), "row_rays({y}) past the screen");
    }
}

/// [ASSERT: accepted cameras are usable] Every ray checked is a unit vector, and points where
/// the chapter's camera (in `f64`, from the same rounded inputs) points, on the screen and past
/// its edges.
///
/// The angle allowed, `2⁻¹⁶ · (6 + 2/f + 9/sin θ)` radians with `f` the view distance in
/// pixels and `θ` the angle between the view and up: the view direction and up are unit
/// vectors to one unit of 2⁻¹⁶ a component (√3 units of angle each), their cross product is
/// rounded to half a unit a component, so `right` is off by at most `(2·√3 + √3/2)/sin θ`
/// units of angle before it is normalised (√3 more) and the true up, their cross product, by
/// as much again: below `9/sin θ` for both (the pinhole's basis is exact: `sin θ = 1` and the
/// term a bound to spare). The ray's Q16.16 direction towards the pixel is rounded to half a
/// unit a component (√3/2 units over a length of at least `f` pixels), the view distance in
/// pixels to half a unit (half a unit over `f`), and the normalisation adds √3 units: with
/// the view direction's √3, below `6 + 2/f`.
pub fn check_rays(spec: &CameraSpec, camera: &Camera, pixels: &[(u32, u32)]) {
    let (cols, rows) = (camera.width(), camera.height());
    for &(col, row) in pixels {
        let ray = camera.ray(col, row);
        let (exact, f, sin) = spec.exact_ray(camera, col as f64, row as f64);
        let got = ray.dir().to_f64();
        assert_eq!(
            ray.origin(),
            camera.eye(),
            "ray({col}, {row}) leaves from the eye"
        );
        let len = norm(got);
        assert!(
            (len - 1.0).abs() <= UNIT_TOLERANCE,
            "ray({col}, {row}) of {spec:?}: |dir| = {len} (dir {:?})",
            ray.dir()
        );
        // Where the pixel-unit direction's components may not fit Q16.16 (beyond 2¹⁵ pixels),
        // only the side of the view is promised: the ray must not wrap to the other side.
        let (x, y) = (
            col as f64 + 0.5 - cols as f64 / 2.0,
            row as f64 + 0.5 - rows as f64 / 2.0,
        );
        let fits = (f * f + x * x + y * y).sqrt() < 16384.0;
        if fits {
            let angle = dot(unit(got), exact).clamp(-1.0, 1.0).acos();
            let allowed = ULP * (6.0 + 2.0 / f + 9.0 / sin);
            assert!(
                angle <= allowed,
                "ray({col}, {row}) of {spec:?} is {angle} rad off the exact camera's \
                 (allowed {allowed}; dir {:?}, exact {exact:?})",
                ray.dir()
            );
        } else {
            assert!(
                dot(got, exact) > 0.0,
                "ray({col}, {row}) of {spec:?} looks away from the exact camera's ray: \
                 dir {:?}, exact {exact:?}",
                ray.dir()
            );
        }
        // The supersampling ray at n = 1 (or 0, clamped to 1) is the pixel's ray.
        assert_eq!(camera.sample_ray(col, row, 0, 0, 1), ray, "sample_ray n=1");
        assert_eq!(camera.sample_ray(col, row, 0, 0, 0), ray, "sample_ray n=0");
        let _ = camera.pixel_centre(col, row);
    }
    // [ASSERT: RowRays is Camera::ray] for the last row of the screen.
    let row = rows - 1;
    let rays = camera.row_rays(row).expect("the last row is on the screen");
    for (col, ray) in (0..).zip(rays) {
        if col % 97 == 0 || col + 1 == cols {
            assert_eq!(ray, camera.ray(col, row), "row_rays({row}) column {col}");
        }
    }
    assert_eq!(
        camera.row_rays(row).expect("on the screen").len(),
        cols as usize,
        "a ray per column"
    );
}

/// [ASSERT: hits lie in [0, FAR] with a unit normal, and are the nearest] One hit of
/// `Scene::shoot` against every object tried by brute force.
///
/// Unit normal, the tolerance: a plane's normal is its own, normalised at construction, so
/// within [`UNIT_TOLERANCE`] (√3 units of 2⁻¹⁶) of unit length, turned to face the ray. A
/// sphere's is `(x − c)/r`, turned likewise, at
/// the rounded hit point `x`: each component within one unit of the exact quotient (a product
/// by a reciprocal good to 2⁻³⁰, rounded to nearest), and `‖x − c‖` itself off `r` by the hit
/// point's distance from the surface: half a unit a component for rounding `x` (√3/2), the
/// hit distance's error projected on the normal (at most 2⁻¹⁶·(1 + t + r), the bound
/// `tests/rays.rs` holds `t` to, times `a/r ≤ 1`), and the ray direction's own length error
/// (within 2√3 units of 2⁻¹⁶ of 1 in its square) over the distance travelled, at most
/// `3.5·t` units. Divided by `r`, the relative error of the normal's length is at most
/// `2⁻¹⁶ · (√3 + 2 + (1 + 4.5·t)/r)`.
pub fn check_hit<const N: usize>(scene: &Scene<N>, ray: &Ray, hit: Option<SceneHit>) {
    // The nearest hit by brute force; ties go to the object added first.
    let mut best: Option<(Fx, usize)> = None;
    for (i, object) in scene.objects().iter().enumerate() {
        if let Some(t) = object.shape.intersect(ray).map(|h| h.t())
            && best.is_none_or(|(b, _)| t < b)
        {
            best = Some((t, i));
        }
    }
    let Some(hit) = hit else {
        assert_eq!(
            best, None,
            "shoot missed, but object {best:?} is hit by {ray:?}"
        );
        return;
    };
    assert_eq!(
        Some((hit.hit().t(), hit.object())),
        best,
        "shoot's hit is not the nearest for {ray:?}"
    );
    assert!(
        hit.hit().t() >= Fx::ZERO && hit.hit().t() <= FAR,
        "hit distance {} outside [0, FAR] for {ray:?}",
        hit.hit().t()
    );
    let object = &scene.objects()[hit.object()];
    if let Shape::Plane(plane) = object.shape {
        check_plane_point(&plane, ray, &hit.hit());
    } else {
        let expect = ray.at(hit.hit().t());
        for (p, q) in [
            (hit.hit().point().x, expect.x),
            (hit.hit().point().y, expect.y),
            (hit.hit().point().z, expect.z),
        ] {
            assert!(
                (p.to_bits() as i64 - q.to_bits() as i64).abs() <= 1,
                "hit point {:?} is not origin + t·dir = {expect:?}",
                hit.hit().point()
            );
        }
    }
    let n = hit.hit().normal().to_f64();
    match object.shape {
        Shape::Plane(plane) => {
            assert!(
                hit.hit().normal() == plane.normal() || hit.hit().normal() == -plane.normal(),
                "plane hit normal {:?} is not ±{:?}",
                hit.hit().normal(),
                plane.normal()
            );
            let len = norm(n);
            assert!(
                (len - 1.0).abs() <= UNIT_TOLERANCE,
                "plane normal length {len} for {ray:?}"
            );
            let d = ray.dir().to_f64();
            assert!(
                n[0] * d[0] + n[1] * d[1] + n[2] * d[2] < 0.0,
                "plane normal {:?} does not face {ray:?}",
                hit.hit().normal()
            );
        }
        Shape::Sphere(sphere) => {
            let r = sphere.radius().to_num::<f64>();
            let v = sub(hit.hit().point().to_f64(), sphere.centre().to_f64());
            // The normal faces the ray: outward from outside, inward from inside. Where the
            // ray grazes the surface the side is a matter of rounding; the normal given says
            // which, and must be (x − c)/r on that side.
            let d = ray.dir().to_f64();
            let along = v[0] * d[0] + v[1] * d[1] + v[2] * d[2];
            let side = if along.abs() > 1e-3 * r {
                -along.signum()
            } else {
                n[0] * v[0] + n[1] * v[1] + n[2] * v[2]
            }
            .signum();
            for axis in 0..3 {
                let exact = side * (v[axis] / r).clamp(-1.0, 1.0);
                assert!(
                    (n[axis] - exact).abs() <= ULP,
                    "sphere normal {:?} is not ±(x − c)/r = {:?} on the ray's side within one unit",
                    hit.hit().normal(),
                    v.map(|c| side * c / r)
                );
            }
            let t = hit.hit().t().to_num::<f64>();
            let allowed = ULP * (1.732_050_808 + 2.0 + (1.0 + 4.5 * t) / r);
            let len = norm(n);
            assert!(
                (len - 1.0).abs() <= allowed,
                "sphere normal length {len} (allowed 1 ± {allowed}) at t = {t}, r = {r}, \
                 for {ray:?} on {sphere:?}"
            );
        }
    }
}

/// [ASSERT: a plane's hit point is where the ray meets it] A plane is met along the direction
/// the ray was made along (`w`, exact), not along its rounded unit direction: the point must
/// be the exact `p_r + w·s`, `s = −n·(p_r − p0)/(n·w)`, worked out in f64 from the Q16.16
/// values, to within a unit of 2⁻¹⁶ and `t·2⁻²⁷` (`s` is good to about 2⁻²⁸, and
/// `‖w·s‖ = t`). `w` is not public; it is the ray's unit direction scaled to the exact
/// distance, which the test recovers as `(x − p_r)` for the exact `x`, so the exact point
/// is the one on the plane along `u_r` nudged by the direction's rounding: within
/// `t·√3·2⁻¹⁶` of `p_r + t·u_r`. Both are asserted: on the plane, and along the ray. And
/// `t` is the distance to the point along `u_r`, to a unit and the same rounding.
fn check_plane_point(plane: &fixray::Plane, ray: &Ray, hit: &fixray::Hit) {
    let (x, o) = (hit.point().to_f64(), ray.origin().to_f64());
    let n = plane.normal().to_f64();
    let p0 = plane.point().to_f64();
    let t = hit.t().to_num::<f64>();
    let unit = ULP;
    // On the plane: n·(x − p0) = 0 up to the point's rounding and s's.
    let off_plane = (0..3).map(|a| n[a] * (x[a] - p0[a])).sum::<f64>();
    let allowed = unit * (1.0 + t / 2048.0) * 1.8;
    assert!(
        off_plane.abs() <= allowed,
        "plane hit {x:?} lies {off_plane} off the plane (allowed {allowed}) for {ray:?}"
    );
    // Along the ray: within its direction's rounding of p_r + t·u_r.
    let expect = ray.at(hit.t()).to_f64();
    let along = unit * (1.0 + t * 1.74 + t / 2048.0);
    for a in 0..3 {
        assert!(
            (x[a] - expect[a]).abs() <= along,
            "plane hit {x:?} is not along the ray: p_r + t·u_r = {expect:?} (allowed {along}) \
             for {ray:?}"
        );
    }
    // t is the distance to the point along u_r: `s·(w·u)/‖u‖`, rounded (half a unit), against
    // the rounded point's `(x − p_r)·u_r` (each component of x within half a unit: up to
    // `0.5·‖u‖₁ ≤ 0.87` units), and `1/‖u‖` is within `1.74·2⁻¹⁶` of 1 (`1.74·t` units).
    let d = ray.dir().to_f64();
    let dist = (0..3).map(|a| (x[a] - o[a]) * d[a]).sum::<f64>();
    assert!(
        (dist - t).abs() <= unit * (1.4 + t * 1.75),
        "plane hit distance {t} is not (x − p_r)·u_r = {dist} for {ray:?}"
    );
}

/// [ASSERT: a surface through the ray's origin] A ray that starts exactly on a surface and
/// points away from it or along it must miss it (a plane: any direction; a sphere: unless it
/// points inward, when it leaves through the far side at t > 0). Exact integer tests on the
/// Q16.16 values decide "exactly on".
pub fn check_surface_through_origin<const N: usize>(scene: &Scene<N>, ray: &Ray) {
    let r = |v: Fx| v.to_bits() as i128;
    let dot = |a: Vec3, b: Vec3| r(a.x) * r(b.x) + r(a.y) * r(b.y) + r(a.z) * r(b.z);
    for (i, object) in scene.objects().iter().enumerate() {
        let t = object.shape.intersect(ray).map(|h| h.t());
        match object.shape {
            Shape::Plane(plane) => {
                if dot(plane.normal(), ray.origin() - plane.point()) == 0 {
                    assert_eq!(
                        t, None,
                        "object {i}, a plane through the ray's origin, is hit by {ray:?}"
                    );
                }
            }
            Shape::Sphere(sphere) => {
                let v = ray.origin() - sphere.centre();
                if dot(v, v) == r(sphere.radius()) * r(sphere.radius()) && dot(ray.dir(), v) >= 0 {
                    assert_eq!(
                        t, None,
                        "object {i}, a sphere through the ray's origin, is hit by {ray:?} \
                         leaving it"
                    );
                }
            }
        }
    }
}

/// [ASSERT: render_row equals per-pixel trace; shoot_row and shoot_row_skipping equal shoot]
/// One row, every entry point: the rendered pixels, the rows of hits and the skipped runs
/// against the per-pixel ray of the camera, traced one by one. Also every hit (check_hit) and
/// the surface-through-origin rule. Rows past the screen are refused by `render_row` and
/// `render_row_supersampled`.
pub fn check_row<const N: usize>(scene: &Scene<N>, camera: &Camera, row: u32) -> Vec<Rgb> {
    let cols = camera.width() as usize;
    let mut out = vec![Rgb::BLACK; cols];
    let rendered = fixray::render_row(scene, camera, row, &mut out);
    // [ASSERT: Err for rows out of range and wrong buffers]
    let mut short = vec![Rgb::BLACK; cols - 1];
    assert!(
        fixray::render_row(scene, camera, row, &mut short).is_err(),
        "short buffer"
    );
    let mut long = vec![Rgb::BLACK; cols + 1];
    assert!(
        fixray::render_row(scene, camera, row, &mut long).is_err(),
        "long buffer"
    );
    let mut hits = Vec::with_capacity(cols);
    let shot_row = fixray::shoot_row(scene, camera, row, |col, ray, hit| {
        hits.push((col, *ray, hit))
    });
    let mut skipped = Vec::new();
    let mut seen = Vec::new();
    let skipped_row = fixray::shoot_row_skipping(
        scene,
        camera,
        row,
        |run| skipped.push(run),
        |col, ray, hit| seen.push((col, *ray, hit)),
    );
    if row >= camera.height() {
        assert!(
            rendered.is_err(),
            "render_row({row}) past the screen must be refused"
        );
        assert!(
            fixray::render_row_supersampled(scene, camera, row, 2, &mut out).is_err(),
            "render_row_supersampled({row}) past the screen must be refused"
        );
        // Every row entry point refuses the row the same way, and hands nothing over.
        let refused = fixray::Error::RowOutOfRange {
            row,
            rows: camera.height(),
        };
        assert_eq!(rendered, Err(refused), "render_row({row})");
        assert_eq!(shot_row, Err(refused), "shoot_row({row})");
        assert_eq!(skipped_row, Err(refused), "shoot_row_skipping({row})");
        assert!(hits.is_empty() && seen.is_empty() && skipped.is_empty());
        assert!(camera.row_rays(row).is_err(), "row_rays({row})");
        return Vec::new();
    }
    shot_row.unwrap_or_else(|e| panic!("shoot_row({row}) refused a row on the screen: {e}"));
    skipped_row
        .unwrap_or_else(|e| panic!("shoot_row_skipping({row}) refused a row on the screen: {e}"));
    rendered.unwrap_or_else(|e| panic!("render_row({row}) refused a row on the screen: {e}"));
    assert_eq!(hits.len(), cols, "shoot_row hands over every column");
    for (col, (c, ray, hit)) in hits.iter().enumerate() {
        assert_eq!(*c as usize, col, "shoot_row in column order");
        let own = camera.ray(*c, row);
        assert_eq!(*ray, own, "shoot_row's ray is the camera's, column {col}");
        let shot = scene.shoot(&own);
        assert_eq!(
            *hit, shot,
            "shoot_row's hit is shoot's, row {row} column {col}"
        );
        check_hit(scene, &own, shot);
        check_surface_through_origin(scene, &own);
        let traced = scene.trace(&own);
        assert_eq!(
            scene.shade(&own, shot.as_ref()),
            traced,
            "trace is shade(shoot)"
        );
        assert_eq!(
            out[col], traced,
            "render_row({row}) differs from trace at column {col}"
        );
    }
    // shoot_row_skipping: every column once, in order; skipped runs meet nothing.
    let mut next = 0u32;
    let (mut s, mut e) = (skipped.iter().peekable(), seen.iter().peekable());
    while (next as usize) < cols {
        if let Some(run) = s.peek()
            && run.start == next
        {
            assert!(run.end > run.start, "an empty skipped run");
            for col in (*run).clone() {
                let ray = camera.ray(col, row);
                assert_eq!(
                    scene.shoot(&ray),
                    None,
                    "shoot_row_skipping skipped column {col} of row {row}, which hits"
                );
            }
            next = run.end;
            s.next();
        } else if let Some((col, ray, hit)) = e.peek()
            && *col == next
        {
            assert_eq!(*ray, camera.ray(*col, row));
            assert_eq!(*hit, scene.shoot(ray));
            next += 1;
            e.next();
        } else {
            panic!("shoot_row_skipping left out column {next} of row {row}");
        }
    }
    assert!(
        s.next().is_none() && e.next().is_none(),
        "columns past the row"
    );
    out
}

/// [ASSERT: supersampling] `n` of 0 and 1 give `render_row`; larger `n` the rounded mean of the
/// traced sample rays (n clamped to 16).
pub fn check_supersampled<const N: usize>(
    scene: &Scene<N>,
    camera: &Camera,
    row: u32,
    n: u8,
    plain: &[Rgb],
) {
    let mut out = vec![Rgb::BLACK; camera.width() as usize];
    fixray::render_row_supersampled(scene, camera, row, n, &mut out)
        .unwrap_or_else(|e| panic!("render_row_supersampled({row}, {n}): {e}"));
    if n <= 1 {
        assert_eq!(out, plain, "supersampling by {n} is render_row");
        return;
    }
    let n = n.min(16);
    for (col, pixel) in (0..).zip(out.iter()) {
        let mut sum = [0u32; 3];
        for sy in 0..n {
            for sx in 0..n {
                let ray = camera.sample_ray(col, row, sx, sy, n);
                let length = length(ray.dir());
                assert!((length - 1.0).abs() <= UNIT_TOLERANCE, "sample ray {ray:?}");
                let c = scene.trace(&ray);
                sum = [
                    sum[0] + c.r as u32,
                    sum[1] + c.g as u32,
                    sum[2] + c.b as u32,
                ];
            }
        }
        let count = n as u32 * n as u32;
        let mean = sum.map(|s| ((s + count / 2) / count) as u8);
        assert_eq!(
            *pixel,
            Rgb::new(mean[0], mean[1], mean[2]),
            "column {col}, n {n}"
        );
    }
}

/// [ASSERT: shadows equal a brute-force occlusion test] For each pixel whose first hit is a
/// surface that does not mirror (the pixel is then that surface's own light), the light
/// reaching it is decided here by brute force: a shadow ray from the hit point towards each
/// light, the light's direction normalised from its exact squared distance, testing every
/// object but the one the ray leaves, occluded when some hit distance `t` has `t² < distance²`
/// (both exact, in Q32.32). The pixel with shadows on must then equal the pixel of the same
/// scene lit only by the lights found unoccluded, with shadows off.
///
/// Mirrors and glass are left out: their secondary rays start from points the public API does
/// not give (they are private to the shading), so the same brute force cannot follow them.
pub fn check_shadows<const N: usize>(world: &World, camera: &Camera, row: u32) {
    if row >= camera.height() {
        return;
    }
    let Some(scene) = world.build_with_lights::<N>(&world.lights, true) else {
        return;
    };
    let mut lit_only: HashMap<u32, Scene<N>> = HashMap::new();
    for col in 0..camera.width() {
        let ray = camera.ray(col, row);
        let Some(hit) = scene.shoot(&ray) else {
            continue;
        };
        let material = scene.objects()[hit.object()].material;
        if material.reflect() != Fx::ZERO || material.refraction().is_some() {
            continue;
        }
        let mut mask = 0u32;
        for (li, light) in scene.lights().iter().enumerate() {
            if !occluded(&scene, &hit, light) {
                mask |= 1 << li;
            }
        }
        let unshadowed = lit_only.entry(mask).or_insert_with(|| {
            let lights: Vec<Light> = (scene.lights().iter().enumerate())
                .filter(|(i, _)| mask & (1 << i) != 0)
                .map(|(_, l)| *l)
                .collect();
            world
                .build_with_lights::<N>(&lights, false)
                .expect("the same objects fit")
        });
        assert_eq!(
            scene.trace(&ray),
            unshadowed.trace(&ray),
            "row {row} column {col}: shadows differ from the brute-force test \
             (lights reaching the hit: {mask:#b}; hit {hit:?})"
        );
    }
}

/// Whether anything but the object `hit` is on lies between it and `light`, by brute force.
pub fn occluded<const N: usize>(scene: &Scene<N>, hit: &SceneHit, light: &Light) -> bool {
    let to_light = light.position() - hit.hit().point();
    let distance_squared = to_light.length_squared_wide();
    // The shadow ray's direction is `to_light` normalised, as the renderer's is; its origin is
    // a hit point, which may lie past ±LIMIT (up to LIMIT + FAR).
    let Ok(shadow) = Ray::from_hit_point(hit.hit().point(), to_light) else {
        return false; // a light at the hit point: it lights nothing there either way
    };
    scene.objects().iter().enumerate().any(|(i, object)| {
        i != hit.object()
            && object.shape.intersect(&shadow).is_some_and(|hit| {
                let t = hit.t().to_bits() as u32 as u64;
                t * t < distance_squared
            })
    })
}

// ---------------------------------------------------------------------------------------------
// Drawing
// ---------------------------------------------------------------------------------------------

/// A display that records every pixel drawn, in any colour type.
pub struct Recorder<C> {
    pub size: Size,
    pub pixels: HashMap<(i32, i32), C>,
}

impl<C: PixelColor> DrawTarget for Recorder<C> {
    type Color = C;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        for Pixel(at, c) in pixels {
            self.pixels.insert((at.x, at.y), c);
        }
        Ok(())
    }
}

impl<C> OriginDimensions for Recorder<C> {
    fn size(&self) -> Size {
        self.size
    }
}

/// A top-left corner: near the origin, negative, or near the ends of `i32`.
pub fn corner(src: &mut impl Source) -> Point {
    fn c(s: &mut impl Source) -> i32 {
        match s.below(4) {
            0 => s.pick(&[i32::MIN, i32::MAX, i32::MAX - 3, i32::MIN + 3, -1]),
            _ => s.below(64) as i32 - 16,
        }
    }
    Point::new(c(src), c(src))
}

/// [ASSERT: viewports draw render_row's pixels] A viewport at a hostile place, drawn in bands
/// of a hostile buffer, onto a recording display in full colour and in dithered grey and one
/// bit: every pixel on the display is the rendered row's, converted at its display position,
/// and nothing else is drawn.
pub fn check_viewport<const N: usize>(
    src: &mut impl Source,
    scene: &Scene<N>,
    camera: &Camera,
    frame: &[Vec<Rgb>],
) {
    let (cols, rows) = (camera.width(), camera.height());
    let top_left = corner(src);
    let viewport = Viewport::at(scene, camera, top_left);
    assert_eq!(camera.size(), Size::new(cols, rows), "the camera's size");
    assert_eq!(
        viewport.area(),
        Rectangle::new(top_left, Size::new(cols, rows)),
        "the viewport covers the camera's picture at its corner"
    );
    let buffer_len = match src.below(4) {
        0 => src.below(cols as u64) as usize, // less than a row: refused
        1 => cols as usize,
        _ => cols as usize * (1 + src.below(rows as u64 + 2) as usize) + src.below(3) as usize,
    };
    let mut buffer = vec![Rgb::BLACK; buffer_len];
    let bands = viewport.bands(src.pick(&[0, 1, 3, u32::MAX]));
    let mut rgb = Recorder::<Rgb888> {
        size: Size::new(u32::MAX, u32::MAX),
        pixels: HashMap::new(),
    };
    let mut grey = Recorder::<Gray8> {
        size: Size::new(64, 64),
        pixels: HashMap::new(),
    };
    let mut bits = Recorder::<BinaryColor> {
        size: Size::new(64, 64),
        pixels: HashMap::new(),
    };
    let mut covered = 0usize;
    for band in bands {
        let a = viewport.render_rows(band.clone(), &mut buffer, &mut rgb);
        let b = viewport.render_rows(band.clone(), &mut buffer, &mut grey);
        let c = viewport.render_rows(band.clone(), &mut buffer, &mut bits);
        if buffer_len < cols as usize {
            assert!(
                a.is_err() && b.is_err() && c.is_err(),
                "a buffer below one row"
            );
            return;
        }
        assert!(a.is_ok() && b.is_ok() && c.is_ok(), "band {band:?}");
        covered += band.len();
    }
    assert_eq!(covered, rows as usize, "bands cover every row once");
    // Rows past the camera's are refused, as is an empty buffer.
    assert!(
        viewport
            .render_rows(0..rows + 1, &mut buffer, &mut rgb)
            .is_err()
    );
    assert!(viewport.render_rows(0..1, &mut [], &mut rgb).is_err());
    let _ = viewport.render_rows(rows..rows / 2, &mut buffer, &mut rgb); // a backwards range
    // The viewport is clipped to each display's bounding box: a pixel is drawn exactly where
    // its point lies on the display (and below i32::MAX, where embedded-graphics' corners
    // still fit), converted at that point.
    let on = |size: Size, x: i64, y: i64| {
        let limit = |side: u32| i64::from(side).min(i64::from(i32::MAX));
        (0..limit(size.width)).contains(&x) && (0..limit(size.height)).contains(&y)
    };
    let mut shown = [0usize; 3];
    for (row, line) in frame.iter().enumerate() {
        for (col, &c) in line.iter().enumerate() {
            let x = i64::from(top_left.x) + col as i64;
            let y = i64::from(top_left.y) + row as i64;
            // A point on any display fits i32; `at` is used only then.
            let at = Point::new(x as i32, y as i32);
            if on(rgb.size, x, y) {
                shown[0] += 1;
                assert_eq!(
                    rgb.pixels.get(&(at.x, at.y)),
                    Some(&Rgb888::from(c)),
                    "{at:?}"
                );
            }
            if on(grey.size, x, y) {
                shown[1] += 1;
                let level = draw::dither(draw::luma(c), 255, at);
                assert_eq!(
                    grey.pixels.get(&(at.x, at.y)),
                    Some(&Gray8::new(level)),
                    "{at:?}"
                );
            }
            if on(bits.size, x, y) {
                shown[2] += 1;
                let lit = BinaryColor::from(draw::dither(draw::luma(c), 1, at) == 1);
                assert_eq!(bits.pixels.get(&(at.x, at.y)), Some(&lit), "{at:?}");
            }
        }
    }
    assert_eq!(
        [rgb.pixels.len(), grey.pixels.len(), bits.pixels.len()],
        shown,
        "nothing off the display or outside the area"
    );
    let _ = <Rgb565 as draw::FromRgb>::from_rgb(Rgb::WHITE, top_left);
}

/// [ASSERT: the framebuffer as a display and an image] `render` into a framebuffer equals the
/// rows; drawing it anywhere, whole or in part, never panics and draws the right pixels.
pub fn check_framebuffer<const N: usize, const W: usize, const H: usize>(
    src: &mut impl Source,
    scene: &Scene<N>,
    camera: &Camera,
    frame: &[Vec<Rgb>],
) {
    use embedded_graphics::image::{GetPixel, ImageDrawable};
    let mut fb = Framebuffer::<W, H>::new();
    let result = fixray::render(scene, camera, &mut fb);
    if (camera.width() as usize, camera.height() as usize) != (W, H) {
        assert!(
            result.is_err(),
            "render into a {W}×{H} framebuffer must be refused"
        );
    } else {
        result.unwrap_or_else(|e| panic!("render refused a matching framebuffer: {e}"));
        for (row, line) in frame.iter().enumerate() {
            assert_eq!(&fb.rows()[row][..], &line[..], "render's row {row}");
        }
        let mut hash = fixray::FrameHash::new();
        for line in fb.rows() {
            hash.update(line);
        }
        let mut whole = fixray::FrameHash::new();
        whole.update(fb.rows().as_flattened());
        assert_eq!(hash.finish(), whole.finish());
        assert_eq!(fb.bytes().count(), 3 * W * H);
    }
    assert_eq!((fb.width(), fb.height()), (W, H));
    assert_eq!(fb.pixel(W, 0), None);
    assert_eq!(fb.pixel(0, usize::MAX), None);
    assert!(!fb.set_pixel(usize::MAX, 0, Rgb::WHITE));
    assert_eq!(GetPixel::pixel(&fb, Point::new(-1, 0)), None);
    let mut display = Recorder::<Rgb888> {
        size: Size::new(u32::MAX, u32::MAX),
        pixels: HashMap::new(),
    };
    let at = corner(src);
    let _ = fb.draw_at(at, &mut display);
    let _ = fb.draw_at(
        at,
        &mut Recorder::<BinaryColor> {
            size: Size::zero(),
            pixels: HashMap::new(),
        },
    );
    let _ = ImageDrawable::draw(&fb, &mut display);
    for _ in 0..4 {
        let size = Size::new(
            src.pick(&[0, 1, W as u32, u32::MAX, i32::MAX as u32]),
            src.pick(&[0, 1, H as u32, u32::MAX, i32::MAX as u32]),
        );
        let area = Rectangle::new(corner(src), size);
        let mut part = Recorder::<Rgb888> {
            size: Size::new(u32::MAX, u32::MAX),
            pixels: HashMap::new(),
        };
        ImageDrawable::draw_sub_image(&fb, &mut part, &area).expect("infallible");
        for ((x, y), c) in &part.pixels {
            let source = Point::new(area.top_left.x + x, area.top_left.y + y);
            assert_eq!(GetPixel::pixel(&fb, source), Some(*c), "sub-image {area:?}");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// One whole case
// ---------------------------------------------------------------------------------------------

/// Everything one case draws: a world, a camera, rows, and how hard to push.
#[derive(Debug, Clone)]
pub struct Case {
    pub capacity: usize,
    pub world: World,
    pub camera: CameraSpec,
    pub rows: Vec<u32>,
    pub supersample: u8,
}

/// A case: a camera (hostile one value in six), a world of up to 12 objects in a scene of 8, or
/// 66 to 140 in scenes of 70 and 130 where the objects in view come past the 64th.
pub fn case(src: &mut impl Source) -> Case {
    let camera = camera_spec(src, 6);
    let view = match camera {
        CameraSpec::LookAt { eye, target, .. } => match (rounded3(eye), rounded3(target)) {
            (Some(e), Some(t)) => View {
                eye: e,
                forward: (t - e).try_normalize().unwrap_or(-Vec3::Z),
            },
            _ => View {
                eye: Vec3::ZERO,
                forward: -Vec3::Z,
            },
        },
        _ => View {
            eye: Vec3::ZERO,
            forward: -Vec3::Z,
        },
    };
    let (capacity, count, crowded) = match src.below(6) {
        0 => (70, 66 + src.below(5) as usize, true),
        1 => (130, 66 + src.below(75) as usize, true),
        _ => (8, 1 + src.below(12) as usize, false),
    };
    let world = world(src, view, count, crowded);
    let rows = (0..2 + src.below(3))
        .map(|_| {
            if src.one_in(6) {
                src.pick(&[30, 40000, u32::from(u16::MAX) + 1, u32::MAX])
            } else {
                src.below(30) as u32
            }
        })
        .collect();
    Case {
        capacity,
        world,
        camera,
        rows,
        supersample: src.pick(&[0, 1, 2, 3, 17, 255]),
    }
}

/// Runs every check of one case.
pub fn run_case(src: &mut impl Source, case: &Case) {
    let Some(camera) = check_camera_spec(&case.camera, false) else {
        return;
    };
    match case.capacity {
        70 => run_scene::<70>(src, case, &camera),
        130 => run_scene::<130>(src, case, &camera),
        _ => run_scene::<8>(src, case, &camera),
    }
    check_rays_past_the_screen(&case.camera, &camera);
}

fn run_scene<const N: usize>(src: &mut impl Source, case: &Case, camera: &Camera) {
    let Some(scene) = case.world.build::<N>() else {
        return;
    };
    // Big screens are checked on one row, small ones whole: a few seconds in a debug build.
    let (cols, rows) = (camera.width() as usize, camera.height() as usize);
    let small = cols * rows <= 40 * 30;
    let mut checked_rows: Vec<u32> = case.rows.clone();
    if small {
        checked_rows.extend(0..camera.height());
    }
    let mut frame = vec![Vec::new(); if small { rows } else { 0 }];
    for &row in &checked_rows {
        let line = check_row(&scene, camera, row);
        if (row as usize) < frame.len() {
            frame[row as usize] = line.clone();
        }
        if (row as usize) < rows && cols <= 64 && case.rows.contains(&row) {
            let n = if cols <= 8 {
                case.supersample
            } else {
                case.supersample.min(3)
            };
            check_supersampled(&scene, camera, row, n, &line);
        }
        if case.rows.contains(&row) && cols <= 64 {
            check_shadows::<N>(&case.world, camera, row);
        }
    }
    if small {
        check_viewport(src, &scene, camera, &frame);
        check_framebuffer::<N, 12, 9>(src, &scene, camera, &frame);
    }
}
