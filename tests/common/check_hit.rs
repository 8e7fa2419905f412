//! Oracles for hits: `Scene::shoot` against every object by brute force, a plane's hit point
//! worked out exactly, and rays that start on a surface.

use fixray::{FAR, Fx, Ray, Scene, SceneHit, Shape, Vec3};

use super::exact::{norm, sub};
use super::{ToF64, ULP, UNIT_TOLERANCE};

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
