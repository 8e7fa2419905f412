//! The shadow sweep: for a scene of more than 32 objects, whose shadow sets (`shadowers`) no
//! longer fit a 32-bit mask, each light's objects kept as a two-dimensional tree of the
//! directions their [`ShadowCone`]s span seen from the light, so that a shadow ray walks down
//! to the few whose cone may hold it, and tries no other.
//!
//! A shadow ray that a sphere blocks runs along a line from its hit to the light that passes
//! within `ρ` of the sphere's centre `C` (`blocking_radius`: the radius widened by every
//! rounding of the test), so seen from the light it leaves along a direction `u` at an angle
//! `θ` from the centre's, `a`, with `sin θ ≤ ρ/D` (`D` the centre's distance), and each of its
//! components within the chord `|u − a| = 2 sin(θ/2)` of `a`'s: along any axis `k` the
//! directions lie in an interval, `a_k ± chord`, and a ray whose `u_k` lies outside it, along
//! either of two axes, cannot meet the sphere.
//!
//! The tree is a k-d tree over those intervals, balanced and laid out in order (each range's
//! middle entry the root of the range): at even depths a range is sorted by the intervals'
//! starts along the axis along which the light's cones' axes spread widest, at odd depths
//! along the next widest, and each root holds its own start and its subtree's largest end
//! along its level's axis. A shadow ray seen from the light along `u` walks down only into
//! subtrees whose largest end reaches `u_k`, and right of an entry only where that entry's
//! start does; each entry it reaches is tried. One axis alone leaves every sphere of a band
//! of directions across the light's view; the two leave those near the ray's direction in
//! both. Planes and the spheres a cone cannot bound span every direction, and are always
//! tried.
//!
//! Each entry is one `u32` of the scene's shadow sets, which a scene this large does not use:
//! whether the object's cone bounds its directions (bit 31: the others sort first, and stay
//! out of the tree), the start (9 bits, from bit 22), the subtree's largest end (9 bits, from
//! bit 13), the entry's axis (2 bits, from bit 11) and the object (11 bits). Past 2 048
//! objects the sweep is not kept, and every object is tried.

use crate::geometry::shape::Shape;
use crate::numbers::vec3::Vec3;
use crate::render::accel::shadow_rows::blocking_radius;
use crate::scene::Object;

/// The most objects a sweep indexes: 11 bits.
pub(crate) const MOST: usize = 1 << INDEX_BITS;

const INDEX_BITS: u32 = 11;
const AXIS_SHIFT: u32 = 11;
const END_SHIFT: u32 = 13;
const START_SHIFT: u32 = 22;
const BOUNDED: u32 = 1 << 31;
const KEY_MASK: u32 = (1 << 9) - 1;

/// A component in Q2.14 (−1 to 1, and a little past it for rounded unit vectors) as one of
/// 512 steps of 2⁻⁸, rounded down: held to 0 below −1 and to 511 from 1 up, monotone, so a
/// value within an interval comes out within its ends' steps.
const fn step_of(q14: i32) -> u32 {
    let shifted = (q14 + (1 << 14)) >> 6;
    if shifted < 0 {
        0
    } else if shifted > KEY_MASK as i32 {
        KEY_MASK
    } else {
        shifted as u32
    }
}

/// The steps of the interval `[start, end]` (Q2.14) along which a cone's directions lie,
/// the end rounded up.
const fn steps_of((start, end): (i32, i32)) -> (u32, u32) {
    (step_of(start), step_of(end + (1 << 6) - 1))
}

/// The interval (Q2.14) of component `axis` of the unit directions a shadow ray that a
/// sphere blocks may leave a light along, from what [`bound`] finds for it: the unit vector
/// from the light to its centre and `s ≥ ρ/D`.
///
/// The chord `2 sin(θ/2) = sin θ / cos(θ/2)` is at most `s·(1 + s)` for `sin θ ≤ s ≤ ½`
/// (`1/cos(θ/2) ≤ 1.04` there); `s` is rounded up, from `D` rounded down. Four units of 2⁻¹⁴
/// cover the rest: the axis's rounding to Q2.14 (one), the ray's rounded unit direction (half
/// of one), and its rounding down to Q2.14 (one).
const fn span((centre, s): (Vec3, i32), axis: usize) -> (i32, i32) {
    let chord = s + ((s * s) >> 14) + 1 + 4;
    let a = [centre.x, centre.y, centre.z];
    let centre = a[axis].to_bits() >> 2;
    (centre - chord, centre + chord)
}

/// The unit vector from `light` to a sphere's centre, and `s ≥ ρ/D` in Q2.14 (see
/// [`span`]); `None` for a plane or where `s` passes ½.
const fn bound(light: Vec3, shape: &Shape) -> Option<(Vec3, i32)> {
    let Shape::Sphere(sphere) = shape else {
        return None;
    };
    // Lights and spheres lie within ±1024: the difference does not saturate.
    let to_centre = sphere.centre().saturating_sub(light);
    let Some(unit) = to_centre.try_normalize() else {
        return None;
    };
    // `length` is within a unit of 2⁻¹⁶ of the distance.
    let distance = to_centre.length().to_bits() as i64 - 1;
    let rho = blocking_radius(sphere.radius()).to_bits() as i64;
    if distance <= 2 * rho {
        return None;
    }
    // At most 2¹³ (ρ/D below ½): rounded up.
    let s = ((rho << 14) + distance - 1) / distance + 1;
    Some((unit, s as i32))
}

/// The sweep of a light at `light` over `objects`, written into `sweep` (its first
/// `objects.len()` entries).
pub(crate) const fn build(light: Vec3, objects: &[Object], sweep: &mut [u32]) {
    let count = objects.len();
    // The two axes along which the cones' axes spread widest, the wider first.
    let (mut low, mut high) = ([i32::MAX; 3], [i32::MIN; 3]);
    let mut i = 0;
    while i < count {
        if let Some((unit, _)) = bound(light, &objects[i].shape) {
            let a = [unit.x, unit.y, unit.z];
            let mut k = 0;
            while k < 3 {
                let v = a[k].to_bits();
                low[k] = if v < low[k] { v } else { low[k] };
                high[k] = if v > high[k] { v } else { high[k] };
                k += 1;
            }
        }
        i += 1;
    }
    let spread = [
        high[0] as i64 - low[0] as i64,
        high[1] as i64 - low[1] as i64,
        high[2] as i64 - low[2] as i64,
    ];
    let (mut first, mut second) = (0, 1);
    if spread[1] > spread[0] {
        (first, second) = (1, 0);
    }
    if spread[2] > spread[first] {
        (first, second) = (2, first);
    } else if spread[2] > spread[second] {
        second = 2;
    }
    // Each object's index, and while the tree is built its interval's starts along both axes
    // (the first's where the start goes, the second's where the largest end goes); the
    // objects whose cones bound nothing lack the flag and sort first.
    let mut i = 0;
    while i < count {
        sweep[i] = match bound(light, &objects[i].shape) {
            Some(bounded) => {
                let along_first = steps_of(span(bounded, first)).0;
                let along_second = steps_of(span(bounded, second)).0;
                BOUNDED | along_first << START_SHIFT | along_second << END_SHIFT | i as u32
            }
            None => i as u32,
        };
        i += 1;
    }
    sort(sweep, 0, count, 0);
    let mut bounded = 0;
    while bounded < count && sweep[bounded] & BOUNDED == 0 {
        bounded += 1;
    }
    subtree(light, objects, sweep, (bounded, count), [first, second], 0);
}

/// Lays out the bounded entries `sweep[lo..hi]` as the subtree of depth `depth`: sorted by
/// the start along its axis (`axes[depth % 2]`), its middle entry the root, whose left and
/// right are laid out in turn, one level deeper. The root's entry then keeps its own start
/// and the subtree's largest end along its axis, and the axis; returned, the subtree's
/// largest ends along both axes.
const fn subtree(
    light: Vec3,
    objects: &[Object],
    sweep: &mut [u32],
    (lo, hi): (usize, usize),
    axes: [usize; 2],
    depth: usize,
) -> [u32; 2] {
    if lo >= hi {
        return [0, 0];
    }
    // While building, the start along the second axis stands where the largest end goes.
    let (side, shift) = match depth % 2 {
        0 => (0, START_SHIFT),
        _ => (1, END_SHIFT),
    };
    sort(sweep, lo, hi, shift);
    let mid = lo + (hi - lo) / 2;
    let entry = sweep[mid];
    let index = index_of(entry);
    let left = subtree(light, objects, sweep, (lo, mid), axes, depth + 1);
    let right = subtree(light, objects, sweep, (mid + 1, hi), axes, depth + 1);
    let mut largest = match bound(light, &objects[index].shape) {
        Some(bounded) => [
            steps_of(span(bounded, axes[0])).1,
            steps_of(span(bounded, axes[1])).1,
        ],
        None => [KEY_MASK; 2], // not reached: a bounded entry's object has a bound
    };
    let mut k = 0;
    while k < 2 {
        largest[k] = if left[k] > largest[k] {
            left[k]
        } else {
            largest[k]
        };
        largest[k] = if right[k] > largest[k] {
            right[k]
        } else {
            largest[k]
        };
        k += 1;
    }
    let start = (entry >> shift) & KEY_MASK;
    sweep[mid] = BOUNDED
        | start << START_SHIFT
        | largest[side] << END_SHIFT
        | (axes[side] as u32) << AXIS_SHIFT
        | index as u32;
    largest
}

/// The object an entry names.
const fn index_of(entry: u32) -> usize {
    (entry & ((1 << INDEX_BITS) - 1)) as usize
}

/// What `values` sort by: with `shift` 0 the whole value, else the 9 bits from `shift`.
const fn rank(value: u32, shift: u32) -> u32 {
    match shift {
        0 => value,
        _ => (value >> shift) & KEY_MASK,
    }
}

/// Sorts `values[lo..hi]` in place by [`rank`], ascending (`const`, for `static` scenes).
const fn sort(values: &mut [u32], lo: usize, hi: usize, shift: u32) {
    let count = hi - lo;
    let mut end = count;
    let mut start = count / 2;
    while start > 0 {
        start -= 1;
        sift_down(values, (lo, start, end), shift);
    }
    while end > 1 {
        end -= 1;
        let top = values[lo];
        values[lo] = values[lo + end];
        values[lo + end] = top;
        sift_down(values, (lo, 0, end), shift);
    }
}

/// Moves the heap's `root` down the heap of `end` entries from `values[lo]` to where it
/// belongs.
const fn sift_down(values: &mut [u32], (lo, mut root, end): (usize, usize, usize), shift: u32) {
    loop {
        let mut child = 2 * root + 1;
        if child >= end {
            return;
        }
        if child + 1 < end && rank(values[lo + child + 1], shift) > rank(values[lo + child], shift)
        {
            child += 1;
        }
        if rank(values[lo + root], shift) >= rank(values[lo + child], shift) {
            return;
        }
        let top = values[lo + root];
        values[lo + root] = values[lo + child];
        values[lo + child] = top;
        root = child;
    }
}

/// Whether `tries(index)` holds for some object a shadow ray along the unit `dir` (towards
/// the light) may meet, by a light's sweep `sweep` (the scene's objects, sorted): those whose
/// cone bounds nothing, then the bounded ones whose interval may hold the ray's step.
pub(crate) fn any(sweep: &[u32], dir: Vec3, tries: impl FnMut(usize) -> bool) -> bool {
    // Seen from the light the ray leaves along −dir; in Q2.14, rounded down, along each axis.
    let key_of = |c: crate::numbers::fx::Fx| step_of(-(c.to_bits() >> 2));
    let keys = [key_of(dir.x), key_of(dir.y), key_of(dir.z), 0];
    any_within(sweep, (keys, keys), tries)
}

/// The directions in which every shadow ray from a point of a sphere `shape` leaves a light at
/// `light`: those of a ray that passes within `ρ` of the centre, which a ray from a point of
/// the sphere does (`ρ` exceeds the radius by 2⁻⁸ and more, and a hit lies within a few units
/// of 2⁻¹⁶ of the surface). Their steps along each axis, the intervals [`span`] bounds; the
/// unit vector towards the centre, rounded down to Q2.14; and the chord within which they lie
/// of the exact one, `s·(1 + s)` (Q2.14, see [`span`]). `None` for a plane, or a sphere whose
/// cone bounds nothing.
pub(crate) fn steps_from(light: Vec3, shape: &Shape) -> Option<(Keys, [i16; 3], i32)> {
    let bounded = bound(light, shape)?;
    let (mut low, mut high) = ([0; 4], [0; 4]);
    for axis in 0..3 {
        (low[axis], high[axis]) = steps_of(span(bounded, axis));
    }
    let (unit, s) = bounded;
    let q14 = |c: crate::numbers::fx::Fx| (c.to_bits() >> 2) as i16;
    let chord = s + ((s * s) >> 14) + 1;
    Some(((low, high), [q14(unit.x), q14(unit.y), q14(unit.z)], chord))
}

/// The steps, along each axis, of the directions from a light to every point within a unit
/// of 2⁻¹⁶ a component of the segment between `ends` (seen from the light), of a shadow ray
/// from such a point: `None` where an end lies within a unit of the light (by `|·|₁`), or the
/// ends' unit vectors lie a quarter turn apart or more.
///
/// The directions to the segment's points lie on the great circle's arc between its ends'
/// unit vectors `a` and `b`, whose every point lies within `1 − cos(θ/2) ≤ c²/4` of the chord,
/// `c = |a − b|`: along each axis, between the ends' components widened by that. `a` and `b`
/// rounded to Q2.14 are a unit a component off, so `c` is taken 4 units more. A point a unit
/// of 2⁻¹⁶ a component off the segment, at least `1/√3` from the light, turns the direction by
/// under 3·2⁻¹⁶, a unit; 8 are allowed, and the ray's own rounding, as for [`span`], 4 more.
pub(crate) fn steps_along((start, end): (Vec3, Vec3)) -> Option<Keys> {
    let near = |v: Vec3| v.l1_raw() < 1 << 16;
    if near(start) || near(end) {
        return None;
    }
    let (a, b) = (start.try_normalize()?, end.try_normalize()?);
    let q14 = |v: Vec3| [v.x, v.y, v.z].map(|c| i64::from(c.to_bits() >> 2));
    let (a, b) = (q14(a), q14(b));
    let squared = (0..3).map(|k| (a[k] - b[k]).pow(2)).sum::<i64>();
    // A chord of √2 is a quarter turn: past it the bound is not kept.
    if squared >= 2 << 28 {
        return None;
    }
    let chord = crate::numbers::isqrt::isqrt(squared as u64) as i64 + 1 + 4;
    let sag = ((chord * chord) >> 16) + 1;
    let (mut low, mut high) = ([0; 4], [0; 4]);
    for k in 0..3 {
        let widen = sag + 8 + 4;
        let start = (a[k].min(b[k]) - widen) as i32;
        let end = (a[k].max(b[k]) + widen) as i32;
        (low[k], high[k]) = steps_of((start, end));
    }
    Some((low, high))
}

/// The lowest and highest steps of some directions along each axis (the fourth unused).
pub(crate) type Keys = ([u32; 4], [u32; 4]);

/// The components `−(dir_k >> 2)` (Q2.14) that a shadow ray along the unit `dir` whose steps
/// [`any`] finds within `(low, high)` can have along each axis: a step `s` holds those from
/// `64·s − 2¹⁴` to 63 past it, and the ends hold the little past ±1 that a rounded unit
/// vector's components reach (4 covers it).
pub(crate) fn components_within((low, high): Keys) -> [(i32, i32); 3] {
    let start = |step: u32| (step as i32) * 64 - (1 << 14) - 4;
    let end = |step: u32| (step as i32) * 64 - (1 << 14) + 63 + 4;
    [
        (start(low[0]), end(high[0])),
        (start(low[1]), end(high[1])),
        (start(low[2]), end(high[2])),
    ]
}

/// Whether `tries(index)` holds for some object that a shadow ray leaving the light along a
/// direction whose steps lie within `(low, high)` may meet, by a light's sweep `sweep`: those
/// whose cone bounds nothing, then the bounded ones whose intervals may meet those steps
/// along the tree's axes.
pub(crate) fn any_within(
    sweep: &[u32],
    (low, high): Keys,
    mut tries: impl FnMut(usize) -> bool,
) -> bool {
    // The entries whose cones bound nothing, first, each tried as it is found: a scan, not a
    // search, as there are few (the planes, most often) or else every object is tried anyway.
    let mut bounded = 0;
    for &entry in sweep {
        if entry & BOUNDED != 0 {
            break;
        }
        if tries(index_of(entry)) {
            return true;
        }
        bounded += 1;
    }
    let tree = sweep.get(bounded..).unwrap_or(&[]);
    // The ranges still to walk: a tree of at most 2¹¹ entries is 12 levels deep, and each
    // range taken leaves at most one more waiting than it found.
    let mut ranges = [(0u16, 0u16); 16];
    let (mut waiting, mut ranges_len) = (0..tree.len() as u16, 0);
    loop {
        let (lo, hi) = (waiting.start as usize, waiting.end as usize);
        let next = if lo < hi {
            let mid = lo + (hi - lo) / 2;
            let entry = tree.get(mid).copied().unwrap_or(0);
            let axis = ((entry >> AXIS_SHIFT) & 3) as usize;
            if (entry >> END_SHIFT) & KEY_MASK < low[axis] {
                None
            } else if (entry >> START_SHIFT) & KEY_MASK > high[axis] {
                // Every entry right of this one starts past the steps too.
                Some(lo as u16..mid as u16)
            } else {
                if tries(index_of(entry)) {
                    return true;
                }
                match ranges.get_mut(ranges_len) {
                    Some(slot) => {
                        *slot = (mid as u16 + 1, hi as u16);
                        ranges_len += 1;
                    }
                    // Not reached (see above); were it, the range is tried whole.
                    None => {
                        let rest = tree.get(mid + 1..hi).unwrap_or(&[]);
                        if rest.iter().any(|&entry| tries(index_of(entry))) {
                            return true;
                        }
                    }
                }
                Some(lo as u16..mid as u16)
            }
        } else {
            None
        };
        waiting = match next {
            Some(range) => range,
            None if ranges_len > 0 => {
                ranges_len -= 1;
                let (lo, hi) = ranges.get(ranges_len).copied().unwrap_or((0, 0));
                lo..hi
            }
            None => return false,
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::ray::Ray;
    use crate::scene::{Light, Rgb, Scene};
    use crate::{Plane, Sphere};

    /// Random scenes of 33 to 150 objects (spheres of every size, some holding or touching a
    /// light, and planes), shadow rays from random points towards each light: the sweep leads
    /// to every object that blocks a ray.
    #[test]
    fn the_sweep_leads_to_every_object_that_blocks_a_shadow_ray() {
        let mut rng = crate::xorshift::XorShift(0x5eed_5eeb_0000_0033);
        let (mut blocked, mut tried, mut rays) = (0u64, 0u64, 0u64);
        for world in 0..40 {
            let light = |rng: &mut crate::xorshift::XorShift| {
                let at = [rng.signed(30.0), rng.signed(30.0), rng.signed(30.0)];
                Light::new(at, 0.5).unwrap()
            };
            let mut scene: Scene<150, 3> = Scene::new(light(&mut rng), 0.1, Rgb::BLACK).unwrap();
            scene.add_light(light(&mut rng)).unwrap();
            let count = 33 + (rng.next() % 118) as usize;
            while scene.objects().len() < count {
                if rng.next().is_multiple_of(20) {
                    let normal = [rng.signed(1.0), rng.signed(1.0), rng.signed(1.0)];
                    let at = [rng.signed(20.0), rng.signed(20.0), rng.signed(20.0)];
                    if let Ok(plane) = Plane::new(at, normal) {
                        scene.add_plane(plane, Rgb::WHITE).unwrap();
                    }
                    continue;
                }
                let centre = [rng.signed(25.0), rng.signed(25.0), rng.signed(25.0)];
                let radius = 0.05 + rng.signed(1.0).abs() * if world % 3 == 0 { 12.0 } else { 2.0 };
                scene
                    .add_sphere(Sphere::new(centre, radius).unwrap(), Rgb::WHITE)
                    .unwrap();
            }
            let objects = scene.objects();
            for (light_index, light) in scene.lights().iter().enumerate() {
                let sweep = scene.shadow_caches().sweep(light_index, count).unwrap();
                for _ in 0..400 {
                    let from = Vec3::from_ints(0, 0, 0)
                        + Vec3::new(
                            crate::Fx::from_num(rng.signed(30.0)),
                            crate::Fx::from_num(rng.signed(30.0)),
                            crate::Fx::from_num(rng.signed(30.0)),
                        );
                    let to_light = light.position() - from;
                    let Some(dir) = to_light.try_normalize() else {
                        continue;
                    };
                    let d2 = to_light.length_squared_wide();
                    let ray = Ray::new_unchecked(from, dir);
                    let blocks = |i: usize| objects[i].shape.blocks(&ray, d2);
                    // Every object the sweep leads to, and then every one that blocks.
                    let mut visited = [false; 150];
                    let none = any(sweep, dir, |i| {
                        visited[i] = true;
                        false
                    });
                    assert!(!none);
                    for i in (0..count).filter(|&i| blocks(i)) {
                        assert!(visited[i], "world {world}, light {light_index}: object {i}");
                        blocked += 1;
                    }
                    rays += 1;
                    tried += visited.iter().filter(|&&v| v).count() as u64;
                }
            }
        }
        // Rays meet blockers often enough for the test to mean something, and the sweep
        // leads to far fewer objects than the scenes hold (91 on average).
        assert!(blocked > rays, "{blocked} blockers of {rays} rays");
        assert!(tried * 3 < rays * 91, "{tried} tried for {rays} rays");
    }

    /// Random segments seen from random lights, shadow rays from random points within a unit
    /// of 2⁻¹⁶ of them: each ray's steps lie within those `steps_along` finds, along each axis.
    #[test]
    fn a_segments_steps_hold_every_shadow_ray_from_near_it() {
        let mut rng = crate::xorshift::XorShift(0x5eed_5e9e_0000_0002);
        let (mut rays, mut bounded) = (0, 0);
        for _ in 0..4_000 {
            let v = |rng: &mut crate::xorshift::XorShift, r: f32| {
                Vec3::new(
                    crate::Fx::from_num(rng.signed(r)),
                    crate::Fx::from_num(rng.signed(r)),
                    crate::Fx::from_num(rng.signed(r)),
                )
            };
            let light = v(&mut rng, 30.0);
            let (a, b) = (v(&mut rng, 30.0), v(&mut rng, 30.0));
            let Some((low, high)) = steps_along((a - light, b - light)) else {
                continue;
            };
            bounded += 1;
            for _ in 0..20 {
                let t = (rng.next() % 1025) as i64;
                let mut along = |p: crate::Fx, q: crate::Fx| {
                    let (p, q) = (i64::from(p.to_bits()), i64::from(q.to_bits()));
                    let jitter = (rng.next() % 3) as i64 - 1;
                    crate::Fx::from_bits((p + (q - p) * t / 1024 + jitter) as i32)
                };
                let point = Vec3::new(along(a.x, b.x), along(a.y, b.y), along(a.z, b.z));
                let Some(dir) = (light - point).try_normalize() else {
                    continue;
                };
                let key = |c: crate::Fx| step_of(-(c.to_bits() >> 2));
                for (k, c) in [dir.x, dir.y, dir.z].into_iter().enumerate() {
                    assert!(low[k] <= key(c) && key(c) <= high[k], "axis {k}");
                }
                rays += 1;
            }
        }
        assert!(
            bounded > 2_000 && rays > 40_000,
            "{bounded} segments, {rays} rays"
        );
    }
}
