//! Ray by ray: the fixed-point intersections against the f64 reference, over random geometry.
//!
//! Both models get the same inputs: the reference is handed the fixed values converted exactly
//! to f64 (it renormalises the Q16.16 unit vectors in f64). The bounds tested here are the
//! ones the README states:
//!
//! - Hit or miss agree, except for rays within [`GRAZE`] of touching a sphere (|d − r|), rays
//!   within [`GRAZE`] of parallel to a plane's surface at the far clip, and hits within
//!   [`GRAZE`] of t = 0 (an origin on the surface).
//! - Where both hit a plane: |t_fixed − t_f64| ≤ 2⁻¹⁶·(1 + t).
//! - Where both hit a sphere: |t_fixed − t_f64| ≤ 2⁻¹⁶·(1 + t + r²/a), where
//!   a = √(r² − d²) is the half chord: the error of the square root grows towards the rim.
//!
//! Measured over 2 million random rays in ±100 units, the largest |Δt| was 0.81 of the sphere
//! bound and 0.84 of the plane bound.
//!
//! Refraction, against Snell's law worked out here in f64:
//!
//! - `refract` finds total internal reflection exactly where Snell's law does, except within
//!   [`CRITICAL`] of the critical angle (|k| ≤ 10⁻³, `k = cos² θ₂`), and each component of a
//!   refracted direction is within 2⁻¹⁶·(4 + 2·ratio²/√k) of the exact one (the square root's
//!   error grows towards the critical angle). Measured over 2 million random cases the largest
//!   error was 0.9 of that bound.
//! - A ray through a black glass sphere in front of a black-to-white sky comes out where the
//!   chain of refractions and total internal reflections worked out in f64 sends it, for
//!   indices ¼ to 4 and eyes inside and outside the sphere: its grey is within ±1 plus the
//!   most the f64 answer moves when the sphere is moved (along each axis and diagonal) or
//!   resized by the hit points' error bound, 2⁻¹⁶·(4 + 2·path + 20·r) (a bundle of rays through glass fans out, and the
//!   renderer's rounding is that of an exact render of a sphere that close). Hits that error
//!   could turn from refraction to total internal reflection are not judged: within 0.05 plus
//!   the normal's error (the bound over r) of grazing, or with |k| within 10⁻³ plus what that
//!   error moves k by.

use fixray::internals::refract;
use fixray::{
    Background, FAR, Fx, Light, Material, Object, Plane, Ray, Rgb, Scene, Shape, Sphere, Vec3,
};
use fixray_reference::{DPlane, DRay, DSphere, DVec3};
use proptest::prelude::*;

/// World units: the margin around tangency and t = 0 where hit or miss may differ.
const GRAZE: f64 = 1e-3;
/// One unit of Q16.16.
const ULP: f64 = 1.0 / 65536.0;
/// How close to the critical angle (in `k = cos² θ₂`) refraction and total internal
/// reflection may be told apart differently.
const CRITICAL: f64 = 1e-3;

fn coord(range: f64) -> impl Strategy<Value = Fx> {
    (-range..range).prop_map(Fx::from_num)
}

fn point(range: f64) -> impl Strategy<Value = Vec3> {
    (coord(range), coord(range), coord(range)).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

fn direction() -> impl Strategy<Value = Vec3> {
    point(1.0).prop_filter("a direction", |v| v.length() > Fx::from_num(0.01))
}

fn d(v: Vec3) -> DVec3 {
    DVec3::from(v)
}

fn rays(range: f64) -> impl Strategy<Value = (Ray, DRay)> {
    (point(range), direction()).prop_map(|(o, u)| {
        let ray = Ray::new(o, u).unwrap();
        let dray = DRay::new(d(ray.origin()), d(ray.dir())).unwrap();
        (ray, dray)
    })
}

/// The |Δt| bound for planes.
fn t_bound(t: f64) -> f64 {
    ULP * (1.0 + t)
}

/// The |Δt| bound for spheres, with half chord `a`.
fn sphere_t_bound(t: f64, r: f64, a: f64) -> f64 {
    ULP * (1.0 + t + r * r / a)
}

fn unit(v: DVec3) -> DVec3 {
    v / v.length()
}

/// Snell's law in f64: `None` for total internal reflection, else the refracted direction and
/// `k = cos² θ₂`; `n` faces `d`.
fn snell(d: DVec3, n: DVec3, ratio: f64) -> (Option<DVec3>, f64) {
    let cos = -n.dot(d);
    let k = 1.0 - ratio * ratio * (1.0 - cos * cos);
    let bent = (k >= 0.0).then(|| d * ratio + n * (ratio * cos - libm::sqrt(k)));
    (bent, k)
}

/// What a ray `(o, d)` does in a black glass sphere of index `eta`, followed as the renderer's
/// tree (without Fresnel, all the light takes one branch): the direction it leaves with, or
/// `None` where a hit is too close to grazing or to the critical angle to call.
///
/// `wobble` is how far the renderer's normals may be from the exact ones: hits within it of
/// grazing, or whose `k` it could move across zero, are not called either.
fn through_glass(
    o: DVec3,
    d: DVec3,
    c: DVec3,
    r: f64,
    eta: f64,
    depth: u8,
    wobble: f64,
) -> Option<DVec3> {
    let (mut o, mut d) = (o, d);
    let mut inside = (o - c).length() < r;
    for generation in 1..=depth + 1 {
        // The next crossing: the far one from inside, the near one ahead from outside.
        let to_c = c - o;
        let t_close = d.dot(to_c);
        let d2 = to_c.length_squared() - t_close * t_close;
        if !inside && (t_close <= 0.0 || d2 >= r * r) {
            return Some(d); // leaves for the sky
        }
        let a = libm::sqrt((r * r - d2).max(0.0));
        let t = if inside { t_close + a } else { t_close - a };
        let p = o + d * t;
        let outward = unit(p - c);
        let n = if inside { -outward } else { outward };
        let cos = -n.dot(d);
        if cos < 0.05 + wobble {
            return None; // grazing
        }
        let ratio = if inside { eta } else { 1.0 / eta };
        let (bent, k) = snell(d, n, ratio);
        // dk/dcos = 2·ratio²·cos, and cos moves by at most twice the normal's error.
        if k.abs() <= CRITICAL + 4.0 * ratio * ratio * wobble {
            return None;
        }
        // The ray of this generation past the depth sees the sky along its direction.
        let next = match bent {
            Some(b) => {
                inside = !inside;
                unit(b)
            }
            None => unit(d - n * (2.0 * d.dot(n))),
        };
        if generation > depth {
            return Some(next);
        }
        (o, d) = (p, next);
    }
    Some(d)
}

/// Cases per property: `PROPTEST_CASES` if set (CI sets many, in a release build), else
/// enough for a quick debug `cargo test`.
fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(if cfg!(debug_assertions) {
            2_000
        } else {
            20_000
        })
}

proptest! {
    // A few in a hundred grazing rays are set aside (`prop_assume!`): the budget grows with
    // the cases.
    #![proptest_config(ProptestConfig {
        cases: cases(),
        max_global_rejects: cases() / 10 + 1024,
        ..ProptestConfig::default()
    })]

    #[test]
    fn spheres_agree_with_the_reference(
        (ray, dray) in rays(100.0),
        centre in point(100.0),
        radius in (0.25f64..50.0).prop_map(Fx::from_num),
    ) {
        let sphere = Sphere::from_fx(centre, radius).unwrap();
        let dsphere = DSphere::new(d(centre), radius.to_num()).unwrap();
        let (hit, dhit) = (sphere.intersect(&ray), dsphere.intersect(&dray));
        // How far the ray passes from the rim, and the reference's t.
        let to_centre = d(centre) - dray.origin();
        let t_close = dray.dir().dot(to_centre);
        let miss_distance = (dray.at(t_close) - d(centre)).length() - radius.to_num::<f64>();
        let grazing = miss_distance.abs() <= GRAZE;
        match (hit, dhit) {
            (Some(h), Some(dh)) => {
                let r = radius.to_num::<f64>();
                let a = libm::sqrt((r * r - (miss_distance + r).powi(2)).max(0.0));
                let dt = (h.t().to_num::<f64>() - dh.t).abs();
                prop_assert!(dt <= sphere_t_bound(dh.t, r, a), "|Δt| = {dt} at t = {}, a = {a}", dh.t);
            }
            (None, None) => {}
            (h, dh) => {
                let near_origin = dh.is_some_and(|x| x.t <= GRAZE) || h.is_some_and(|x| x.t().to_num::<f64>() <= GRAZE)
                    || (to_centre.length() - radius.to_num::<f64>()).abs() <= GRAZE;
                prop_assert!(grazing || near_origin, "fixed {h:?}, reference {dh:?}, |d − r| = {miss_distance}");
            }
        }
    }

    #[test]
    fn planes_agree_with_the_reference(
        (ray, dray) in rays(100.0),
        through in point(100.0),
        normal in direction(),
    ) {
        let plane = Plane::from_fx(through, normal).unwrap();
        let dplane = DPlane::new(d(plane.point()), d(plane.normal())).unwrap();
        let (hit, dhit) = (plane.intersect(&ray), dplane.intersect(&dray));
        match (hit, dhit) {
            (Some(h), Some(dh)) => {
                let dt = (h.t().to_num::<f64>() - dh.t).abs();
                prop_assert!(dt <= t_bound(dh.t), "|Δt| = {dt} at t = {}", dh.t);
                prop_assert_eq!(d(h.normal()).dot(dh.normal) > 0.0, true, "normals face the same way");
            }
            (None, None) => {}
            (h, dh) => {
                // Disagreement is allowed only at the ends of the t range.
                let far = FAR.to_num::<f64>();
                let t = dh.map(|x| x.t).or(h.map(|x| x.t().to_num::<f64>())).unwrap();
                let at_an_end = t <= GRAZE || (t - far).abs() <= t_bound(far);
                let on_surface = dplane.distance(dray.origin()).abs() <= GRAZE;
                prop_assert!(at_an_end || on_surface, "fixed {h:?}, reference {dh:?}");
            }
        }
    }

    /// Rays aimed to pass within ±0.01 of a sphere's rim: hit or miss may differ only within
    /// GRAZE of it.
    #[test]
    fn grazing_rays_disagree_only_within_the_margin(
        origin in point(100.0),
        centre in point(100.0),
        radius in (0.25f64..50.0).prop_map(Fx::from_num),
        side in direction(),
        offset in -0.01f64..0.01,
    ) {
        let r = radius.to_num::<f64>();
        let to_centre = d(centre) - d(origin);
        // A point at distance r + offset from the centre, across the line of sight.
        let across = to_centre.cross(d(side));
        prop_assume!(across.length() > 1e-3 && to_centre.length() > r + 0.1);
        let aim = d(centre) + across / across.length() * (r + offset);
        let to_aim = aim - d(origin);
        prop_assume!([to_aim.x, to_aim.y, to_aim.z].iter().all(|c| c.abs() <= 1024.0));
        let dir = Vec3::new(Fx::from_num(to_aim.x as f32), Fx::from_num(to_aim.y as f32), Fx::from_num(to_aim.z as f32));
        let ray = Ray::new(origin, dir).unwrap();
        let dray = DRay::new(d(ray.origin()), d(ray.dir())).unwrap();
        let sphere = Sphere::from_fx(centre, radius).unwrap();
        let dsphere = DSphere::new(d(centre), r).unwrap();
        let t_close = dray.dir().dot(to_centre);
        let miss_distance = (dray.at(t_close) - d(centre)).length() - r;
        let agree = sphere.intersect(&ray).is_some() == dsphere.intersect(&dray).is_some();
        prop_assert!(agree || miss_distance.abs() <= GRAZE, "disagree at |d − r| = {miss_distance}");
    }

    /// Anywhere in the documented range, intersections never panic or overflow, and any hit
    /// lies on its surface within the stated bound.
    #[test]
    fn the_whole_range_is_overflow_free(
        (ray, _) in rays(1024.0),
        centre in point(1024.0),
        radius in (0.01f64..1024.0).prop_map(Fx::from_num),
        normal in direction(),
    ) {
        let sphere = Sphere::from_fx(centre, radius).unwrap();
        if let Some(h) = sphere.intersect(&ray) {
            let r = radius.to_num::<f64>();
            let off = (d(h.point()) - d(centre)).length() - r;
            // The point x = p_r + t·u_r carries t's error (the sphere bound, with the half
            // chord a of the ray's own direction), and the direction's rounding times t.
            let dray = DRay::new_unchecked(d(ray.origin()), d(ray.dir()));
            let t_close = dray.dir().dot(d(centre) - dray.origin());
            let d2 = (dray.at(t_close) - d(centre)).length_squared();
            let a = libm::sqrt((r * r - d2).max(0.0));
            let bound = sphere_t_bound(h.t().to_num(), r, a) + ULP * (1.0 + h.t().to_num::<f64>());
            prop_assert!(off.abs() <= bound, "{off} off the surface, bound {bound}");
        }
        let plane = Plane::from_fx(centre, normal).unwrap();
        if let Some(h) = plane.intersect(&ray) {
            prop_assert!(h.t() >= Fx::ZERO && h.t() <= FAR);
            let dplane = DPlane::new(d(plane.point()), d(plane.normal())).unwrap();
            let off = dplane.distance(d(h.point()));
            let bound = ULP * (2.0 + 2.0 * h.t().to_num::<f64>());
            prop_assert!(off.abs() <= bound, "{off} off the plane, bound {bound}");
        }
    }

    #[test]
    fn refraction_follows_snells_law(
        dir in direction(),
        normal in direction(),
        ratio in 0.25f64..4.0,
    ) {
        let dir = dir.try_normalize().unwrap();
        let mut normal = normal.try_normalize().unwrap();
        if normal.dot(dir) > Fx::ZERO {
            normal = -normal;
        }
        let ratio = Fx::from_num(ratio);
        let rr = ratio.to_num::<f64>();
        let (want, k) = snell(unit(d(dir)), unit(d(normal)), rr);
        match (refract(dir, normal, ratio), want) {
            (Some(got), Some(want)) => {
                let bound = ULP * (4.0 + 2.0 * rr * rr / libm::sqrt(k));
                let error = d(got) - want;
                let worst = error.x.abs().max(error.y.abs()).max(error.z.abs());
                prop_assert!(worst <= bound, "{worst} off at k = {k}, ratio {rr}, bound {bound}");
            }
            (None, None) => {}
            (got, _) => prop_assert!(k.abs() <= CRITICAL, "fixed {got:?} at k = {k}"),
        }
    }

    #[test]
    fn rays_through_a_glass_sphere_leave_where_snell_sends_them(
        centre in point(20.0),
        radius in 0.5f64..10.0,
        eta in 0.25f64..4.0,
        eye in point(40.0),
        aim in point(1.0),
        depth in 0u8..6,
    ) {
        let (radius, eta) = (Fx::from_num(radius), Fx::from_num(eta));
        let glass = Material::new(Rgb::BLACK, 0.0, 0.0, 1, 0.0)
            .unwrap()
            .with_refraction_fx(eta, Fx::ONE)
            .unwrap();
        let sky = Background { top: Rgb::WHITE, bottom: Rgb::BLACK };
        let mut scene: Scene<1> = Scene::new(Light::new([0.0, 900.0, 0.0], 1.0).unwrap(), 0.0, sky).unwrap();
        let sphere = Sphere::from_fx(centre, radius).unwrap();
        scene.add(Object::new(Shape::Sphere(sphere), glass)).unwrap();
        scene.set_depth(depth);
        // Aimed at a point within the sphere, from anywhere (inside too).
        let target = centre + aim.scale(radius);
        prop_assume!((target - eye).length() > Fx::from_num(0.01));
        let ray = Ray::new(eye, target - eye).unwrap();
        let (o, u, c, r, e) =
            (d(ray.origin()), unit(d(ray.dir())), d(centre), radius.to_num::<f64>(), eta.to_num::<f64>());
        // The hit points' error bound, and what it does to a normal.
        let path = (o - c).length() + 2.0 * r * f64::from(depth + 1);
        let shift = ULP * (4.0 + 2.0 * path + 20.0 * r);
        let wobble = shift / r;
        let leaves = through_glass(o, u, c, r, e, depth, wobble);
        prop_assume!(leaves.is_some());
        let want_y = leaves.unwrap().y;
        // How much the answer moves when the sphere moves by that bound: the renderer's
        // rounding is that of an exact render of a sphere this close.
        let mut spread: f64 = 0.0;
        // The 26 neighbours of the centre a step `shift` away along each axis, and the radius
        // `shift` larger and smaller.
        let steps = [-shift, 0.0, shift];
        let mut moves = vec![(DVec3::ZERO, shift), (DVec3::ZERO, -shift)];
        for x in steps {
            for y in steps {
                for z in steps {
                    if (x, y, z) != (0.0, 0.0, 0.0) {
                        moves.push((DVec3::new(x, y, z), 0.0));
                    }
                }
            }
        }
        for (dc, dr) in moves {
            let moved = through_glass(o, u, c + dc, r + dr, e, depth, 0.0);
            prop_assume!(moved.is_some());
            spread = spread.max((moved.unwrap().y - want_y).abs());
        }
        let want = 255.0 * (want_y + 1.0) / 2.0;
        let tolerance = 1.0 + 127.5 * spread;
        let got = scene.trace(&ray);
        prop_assert!((f64::from(got.r) - want).abs() <= tolerance, "grey {} for {want:.2} ± {tolerance:.2}", got.r);
    }
}
