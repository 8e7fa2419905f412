//! The shadows a moved sphere casts, before and after, bounded on the screen: on a sphere by
//! its silhouette, when the cone from the light around the caster may meet it; on a plane by
//! an octagonal pyramid from the light around that cone, cut by the slab of the plane's hit
//! points, and by the plane's own rectangle when it is bounded.
//!
//! All in integers, exactly but for the square roots and quotients, each rounded the way
//! that widens the bound or with its rounding added to the margin (see `exact.rs` for why
//! nothing overflows).

use super::exact::{
    W3, add, ceil_div, cross, dot, fraction, raw, root_above, root_below, square, sub, wide,
};
use super::screen::Screen;
use super::{Area, Damage};
use crate::geometry::plane::Plane;
use crate::geometry::shape::Shape;
use crate::geometry::sphere::Sphere;
use crate::numbers::vec3::Vec3;
use crate::render::camera::Camera;
use crate::render::camera::unit_of_exact;
use crate::scene::Scene;
use crate::scene::light::Light;

impl Damage {
    /// Adds the shadows `ball` (object `index` of `scene`, or what it was) casts from `light`
    /// on the other objects that did not change: a sphere that may receive it is marked in
    /// `outlines` for its silhouette, within the bound of the shadow there (the hull of it
    /// and any it was marked with); a plane's shadow is bounded here.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn shadows<const N: usize, const L: usize>(
        &mut self,
        scene: &Scene<N, L>,
        index: usize,
        ball: &Sphere,
        light: &Light,
        camera: &Camera,
        screen: &Screen,
        changed: &impl Fn(usize) -> bool,
        outlines: &mut [Option<Area>; N],
    ) -> Option<()> {
        let caster = Caster::new(ball, light.position(), camera.eye());
        for (other, object) in scene.objects().iter().enumerate() {
            if other == index || changed(other) {
                // A changed object's pixels are in its own silhouettes already.
                continue;
            }
            match object.shape {
                Shape::Sphere(receiver) => {
                    let within = match caster.on_sphere(&receiver, screen, self) {
                        Some(None) => continue,
                        Some(Some(shadow)) => shadow,
                        None => Area {
                            left: 0,
                            top: 0,
                            right: self.cols,
                            bottom: self.rows,
                        },
                    };
                    let mark = outlines.get_mut(other)?;
                    *mark = Some(mark.map_or(within, |m| m.hull(&within)));
                }
                Shape::Plane(plane) => {
                    let shadow = caster.on_plane(&plane, screen, self);
                    let within = plane_area(&plane, camera.eye(), screen, self);
                    let area = match (shadow, within) {
                        (Some(None), _) => None,
                        (Some(Some(shadow)), Some(within)) => within.and_then(|w| w.meet(&shadow)),
                        (Some(Some(shadow)), None) => Some(shadow),
                        (None, Some(within)) => within,
                        (None, None) => return None,
                    };
                    if let Some(area) = area {
                        self.add(area);
                    }
                }
            }
        }
        Some(())
    }
}

/// How far a hit point may lie from the surface it was found on, in raw world units (2⁻¹⁰):
/// far more than a Q16.16 hit point's rounding (a few units of 2⁻¹⁶).
const ON_SURFACE: i64 = 1 << 6;

/// 1/64 of a world unit, raw: how far outside the widened sphere the light must be for a
/// cone to bound its shadow.
const CLEAR: u128 = 1 << 10;

/// `cos(π/8)` and `sin(π/8)` in Q16.16, rounded up: the directions of a regular octagon's
/// vertices, which lie then a little outside the unit circle's octagon.
const COS: i128 = 60_548;
const SIN: i128 = 25_080;

/// The longest a shadow's ray may run from the light to the plane, as a multiple of its
/// run to the octagon around the caster: farther, the shadow is not worth bounding.
const STRETCH: i128 = 64;

/// A sphere casting shadows from a point light. Positions are offsets from the light, raw.
struct Caster {
    /// The sphere's centre.
    centre: W3,
    /// `|centre|²`, in units of 2⁻³².
    far: u128,
    radius: u128,
    /// The light.
    light: W3,
    /// The light as an offset from the camera's eye.
    light_from_eye: W3,
    /// The part of the margin that does not grow with distance (see [`Caster::margin`]).
    reach: u128,
    /// Two unit vectors across the direction from the light to the centre, raw.
    axes: Option<([i128; 3], [i128; 3])>,
}

impl Caster {
    fn new(ball: &Sphere, light: Vec3, eye: Vec3) -> Self {
        let (light, radius) = (raw(light), ball.radius().to_bits().unsigned_abs().into());
        let centre = sub(raw(ball.centre()), light);
        Caster {
            centre,
            far: square(wide(centre)),
            radius,
            light,
            light_from_eye: sub(light, raw(eye)),
            // 1/256, and √r / 32 (√r raw is √(r_raw · 2¹⁶)).
            reach: (1 << 8) + root_above(radius << 16).div_ceil(32),
            axes: perpendiculars(centre),
        }
    }

    /// How much wider than its radius the sphere is taken to be (raw), for receiving points
    /// as far as `distance` (raw) from it and from the light.
    ///
    /// A shadow ray from a hit point runs towards the light along a Q16.16 unit direction,
    /// within about 2⁻¹⁵ radians of the exact one: at the sphere it is off the exact segment
    /// by up to `distance · 2⁻¹⁵`, here taken as `distance / 1024`. The sphere's test rounds
    /// the ray's closest approach by a few units of 2⁻¹⁶ (the fixed 1/256), and the square
    /// root that places the crossing along a grazing ray moves it by up to about
    /// `√(r · 2⁻¹³)`, which widening the sphere by `√r / 32` more than covers: a crossing
    /// the test puts before the light is then one the widened sphere has before it too.
    fn margin(&self, distance: u128) -> u128 {
        self.reach + distance.div_ceil(1024)
    }

    /// The pixels of `receiver` the shadow may fall on: `Some(None)` where it casts none on
    /// it, `None` where no bound is made (the light is in or near the widened sphere, or in
    /// the receiver, or the bound reaches behind the eye).
    ///
    /// The shadow lies in the cone from the light around the widened sphere (of radius `R`,
    /// its centre `u` from the light, `d = |u|`), whose half-angle `α` has `sin α = R / d`. A
    /// receiver centred `s` from the light, of radius `ρ` (widened by a hit point's distance
    /// from its surface), is farther from that cone than
    /// `(|s × u| · √(d² − R²) − (s · u) · R) / d²` (its distance `|s|·sin(θ − α)` when the
    /// angle `θ` between `s` and `u` exceeds `α`, and less than that distance otherwise): more
    /// than `ρ`, and no point of it is shaded. Each root is rounded down, so the left side is
    /// understated.
    ///
    /// Otherwise a shaded point `P` of the receiver lies in the pyramid of
    /// [`Caster::octagon`], and between two planes across `u`: `(P − light) · u` is at least
    /// `(d − R)·d` (the segment from `P` to the light meets the sphere, so `P` lies beyond
    /// the sphere's near side) and within `ρ·d` of `s · u` (it lies in the receiver). Every
    /// edge of the pyramid crosses both, and `P` lies in the hull of the sixteen crossings.
    fn on_sphere(
        &self,
        receiver: &Sphere,
        screen: &Screen,
        damage: &Damage,
    ) -> Option<Option<Area>> {
        let s = sub(raw(receiver.centre()), self.light);
        let rho = u128::from(receiver.radius().to_bits().unsigned_abs()) + ON_SURFACE as u128;
        let to_receiver = square(wide(s));
        let apart = root_above(square(wide(sub(s, self.centre))));
        let other = root_above(to_receiver);
        let widened = self.radius + self.margin(apart.max(other) + rho);
        let caster = root_below(self.far);
        if caster <= widened + CLEAR || root_below(to_receiver) <= rho {
            return None;
        }
        // Every point of the receiver nearer the light than the sphere's near side: a
        // segment from it to the light cannot reach the sphere.
        if other + rho < caster - widened {
            return Some(None);
        }
        let (s, u) = (wide(s), wide(self.centre));
        let across = root_below(square(cross(s, u)));
        let cos = root_below(self.far - widened * widened);
        // Below 2⁵⁶ · 2²⁸, 2⁵⁷ · 2²⁹ and 2²⁹ · 2⁵⁶: exact in i128.
        let side = (across * cos) as i128 - dot(s, u) * widened as i128;
        if side > (rho * self.far) as i128 {
            return Some(None);
        }
        let edges = self.octagon(widened)?;
        let length = root_above(self.far);
        // Below 2⁵⁸ each.
        let (middle, reach) = (dot(s, u), (rho * length) as i128);
        let near = self.far.saturating_sub(widened * length) as i128;
        let (low, high) = ((middle - reach).max(near), middle + reach);
        if high < low {
            return Some(None);
        }
        let (mut points, mut off) = ([[0i64; 3]; 16], 0);
        let mut slot = points.iter_mut();
        for edge in edges {
            let along = dot(edge, u);
            if along <= 0 {
                return None;
            }
            for level in [low, high] {
                // The crossing `level / along` of the edge's length from the light (Q32, at
                // most 2⁸: farther, no bound is made), and its rounding.
                let t = fraction(level, along)?;
                let at = fitting(edge.map(|c| (c * i128::from(t)) >> 32))?;
                off = off.max(rounding(at, edge));
                *slot.next()? = add(self.light_from_eye, at);
            }
        }
        Some(screen.area(&screen.place(points.into_iter())?, off, damage))
    }

    /// How far from the sphere's centre [`Caster::octagon`] puts its vertices (raw), or
    /// `None` when the light is within 1/64 of the sphere widened to `widened`: the disc's
    /// radius rounded up, made 1/64 and eight raw units wider, times 1.08301 (above
    /// 1/cos(π/8), so that the octagon's sides lie as far out as that).
    fn vertex(&self, widened: u128) -> Option<u128> {
        if root_below(self.far) <= widened + CLEAR {
            return None;
        }
        let cos = root_below(self.far - widened * widened);
        let disc = ceil_div(widened * root_above(self.far), cos.max(1));
        Some(ceil_div((disc + disc / 64 + 8) * 1109, 1024))
    }

    /// The edges, from the light, of a pyramid that holds the cone from the light around the
    /// sphere widened to `widened` (raw), or `None` when the light is within 1/64 of it.
    ///
    /// The cone's section across its axis at the sphere's centre is a disc of radius
    /// `R·d / √(d² − R²)`; the edges run through the vertices of an octagon around that disc,
    /// a little wider. The vertices are placed along two unit vectors across the axis, each
    /// within 2⁻¹⁵ of exact and of square to the other, and rounded to a raw unit: the
    /// octagon is made 1/64 and eight raw units wider than the disc needs, far more than that
    /// moves it. The disc is below 2³⁷ raw (`d` below 2²⁸ and `d − R` at least 2¹⁰), so each
    /// edge's component is below 2³⁸.
    fn octagon(&self, widened: u128) -> Option<[[i128; 3]; 8]> {
        let (one, two) = self.axes?;
        let vertex = self.vertex(widened)? as i128;
        let mut edges = [[0i128; 3]; 8];
        let mut slot = edges.iter_mut();
        for (a, b) in [(COS, SIN), (SIN, COS)] {
            for (a, b) in [(a, b), (-a, b), (a, -b), (-a, -b)] {
                // Below 2³⁷ · 2¹⁷ · 2¹⁷: exact; floored to raw units.
                let offset = |k: usize| ((vertex * (a * one[k] + b * two[k])) >> 32) as i64;
                *slot.next()? = wide(add(self.centre, [offset(0), offset(1), offset(2)]));
            }
        }
        Some(edges)
    }

    /// The pixels of `plane` the shadow may fall on: `Some(None)` where it casts none there,
    /// `None` where it cannot be bounded (it stretches too far, or reaches behind the eye).
    ///
    /// A shadowed hit point `P` lies within [`ON_SURFACE`] of the plane (a slab), and its
    /// segment to the light meets the widened sphere: it lies in the cone from the light
    /// around that sphere, and in the pyramid of [`Caster::octagon`] around the cone. When
    /// every edge of the pyramid runs down to the slab (and crosses it within [`STRETCH`]
    /// times its length), the pyramid meets the slab in the hull of the sixteen points where
    /// its edges cross the slab's faces, and `P` lies in that hull; so does its pixel, in
    /// [`Screen::area`] of those points.
    fn on_plane(&self, plane: &Plane, screen: &Screen, damage: &Damage) -> Option<Option<Area>> {
        let normal = wide(raw(plane.normal()));
        // Heights above the plane along its normal, in units of 2⁻³², on the light's side.
        let to_light = dot(normal, wide(sub(self.light, raw(plane.point()))));
        if to_light.unsigned_abs() < 1 << 26 {
            return None;
        }
        let up = if to_light > 0 {
            normal
        } else {
            normal.map(|c| -c)
        };
        let light_height = to_light.abs();
        // The slab's half-thickness in heights, with room for the normal's length (within
        // 2⁻¹⁵ of one).
        let slab = (i128::from(ON_SURFACE) << 16) + (1 << 8);
        let centre_height = light_height + dot(up, wide(self.centre));
        // The margin grows with distance: it is worked out again until it covers the
        // farthest point it gives.
        let mut distance = root_above(self.far) * 2;
        for _ in 0..4 {
            let widened = self.radius + self.margin(distance);
            // The widened sphere below the slab, or above both the light and the slab: no
            // segment from the slab to the light meets it.
            let half = (widened << 16) + (widened << 2);
            let half = half as i128;
            if centre_height + half < -slab || centre_height - half > light_height.max(slab) {
                return Some(None);
            }
            // An edge crosses the plane `t = H / fall` of its length from the light, at most
            // STRETCH ([`fraction`], with its rounding). It crosses the slab's faces within
            // `slab / fall` of its length of there, at most `slab · (|u| + vertex) / fall`
            // raw units away: [`Screen::area`] takes the eight crossings of the plane with
            // that and their rounding as their reach.
            let edges = self.octagon(widened)?;
            let (mut points, mut farthest, mut least) = ([[0i64; 3]; 8], 0u128, i128::MAX);
            let mut off = 0;
            for (edge, point) in edges.iter().zip(points.iter_mut()) {
                let fall = -dot(up, *edge);
                if fall <= 0 || light_height + slab > STRETCH * fall {
                    return None;
                }
                least = least.min(fall);
                let t = fraction(light_height, fall)?;
                let along = fitting(edge.map(|c| (c * i128::from(t)) >> 32))?;
                off = off.max(rounding(along, *edge));
                farthest = farthest
                    .max(square(wide(along)))
                    .max(square(wide(sub(along, self.centre))));
                *point = add(self.light_from_eye, along);
            }
            // The edges are at most |u| + the octagon's vertex long (below 2²⁹ + 2³⁸), the
            // slab below 2²³: the product below 2⁶².
            let reach = root_above(self.far) + self.vertex(widened)? + 2;
            let apart = ceil_div(slab as u128 * reach, least as u128) + off;
            let farthest = root_above(farthest) + apart;
            if farthest <= distance {
                return Some(screen.area(&screen.place(points.into_iter())?, apart, damage));
            }
            distance = farthest + farthest / 4 + (1 << 16);
        }
        None
    }
}

/// How far (raw) a crossing `at = t · edge` found with a `t` from [`fraction`] may lie from
/// the exact one: each component within `|edge_k| · (t + 2) · 2⁻²³` and the floor's unit,
/// so all within `(|at|₁ + 2·|edge|₁) · 2⁻²³ + 4`, `|at|₁` standing for `t·|edge|₁` to
/// within far less than the 4. Below 2⁴⁵: `at` within ±2⁴³, `edge` ±2³⁸.
fn rounding(at: W3, edge: [i128; 3]) -> u128 {
    let at: u128 = at.iter().map(|c| u128::from(c.unsigned_abs())).sum();
    let edge: u128 = edge.iter().map(|c| c.unsigned_abs()).sum();
    ((at + 2 * edge) >> 23) + 4
}

/// `v` as raw components, if each lies within ±2⁴³ (so that [`Screen::place`] may take
/// it, added to a point's offset from the eye).
fn fitting(v: [i128; 3]) -> Option<W3> {
    let fits = |c: i128| (c.unsigned_abs() < 1 << 43).then_some(c as i64);
    Some([fits(v[0])?, fits(v[1])?, fits(v[2])?])
}

/// Two unit vectors across `axis` (raw) and across each other, each component within 0.55
/// of a raw unit of exact (`unit_of_exact`): the first across `axis` and the coordinate axis
/// it least runs along, the second across `axis` and the first. Raw in `i128`.
fn perpendiculars(axis: W3) -> Option<([i128; 3], [i128; 3])> {
    let [x, y, z] = axis.map(i64::unsigned_abs);
    let other = if x <= y && x <= z {
        [1, 0, 0]
    } else if y <= z {
        [0, 1, 0]
    } else {
        [0, 0, 1]
    };
    let narrow = |v: [i128; 3]| v.map(|c| c as i64);
    // Below 2²⁷ · 2¹⁷ a component: exact in i64.
    let one = unit_of_exact(narrow(cross(wide(axis), other)))?;
    let one = wide(raw(one));
    let two = wide(raw(unit_of_exact(narrow(cross(wide(axis), one)))?));
    Some((one, two))
}

/// The pixels that may see `plane`, if it is bounded and its rectangle lies ahead of the
/// eye: inner `None` when none can; `None` when it is unbounded or not wholly ahead.
pub(super) fn plane_area(
    plane: &Plane,
    eye: Vec3,
    screen: &Screen,
    damage: &Damage,
) -> Option<Option<Area>> {
    let [min, max] = plane.bounds()?;
    let normal = plane.normal();
    let (nx, ny, nz) = (normal.x.abs(), normal.y.abs(), normal.z.abs());
    // The axes `Plane::coords` measures the bounds on, and the one it drops.
    let (a, b, dropped) = if ny >= nx && ny >= nz {
        (0, 2, 1)
    } else if nz >= nx {
        (0, 1, 2)
    } else {
        (1, 2, 0)
    };
    let (n, point, eye) = (raw(normal), raw(plane.point()), raw(eye));
    // 1/256 around the rectangle, raw.
    let slack = 1 << 8;
    let mut corners = [[0i64; 3]; 8];
    let mut slot = corners.iter_mut();
    for u in [
        i64::from(min[0].to_bits()) - slack,
        i64::from(max[0].to_bits()) + slack,
    ] {
        for v in [
            i64::from(min[1].to_bits()) - slack,
            i64::from(max[1].to_bits()) + slack,
        ] {
            let mut p = [0i64; 3];
            p[a] = u;
            p[b] = v;
            // On the plane: n·(p − point) = 0 fixes the dropped coordinate (its normal
            // component is the largest, at least 2¹⁶/√3 raw), to within a raw unit. Each
            // product is below 2¹⁷ · 2²⁸.
            let num = n[a] * (u - point[a]) + n[b] * (v - point[b]);
            let (num, across) = match n[dropped] {
                0 => return None,
                d if d < 0 => (-num, -d),
                d => (num, d),
            };
            p[dropped] = point[dropped] - num.div_euclid(across);
            for side in [-ON_SURFACE, ON_SURFACE] {
                // side · n, to within half a raw unit.
                let lift = n.map(|c| (c * side + (1 << 15)) >> 16);
                *slot.next()? = sub(add(p, lift), eye);
            }
        }
    }
    Some(screen.area(&screen.place(corners.into_iter())?, 0, damage))
}
