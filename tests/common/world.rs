//! Generated scenes: a [`World`] of objects, lights and settings scattered around a [`View`],
//! built into scenes of any capacity.

use fixray::{
    Background, Error, Fx, LIMIT, Light, Material, Object, Plane, Scene, Shape, Sphere, Vec3,
};

use super::values::rgb;
use super::{Source, direction, vec_within};

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
