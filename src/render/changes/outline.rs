//! A sphere's outline on the screen: the box of the pixels that may see it, and whether it
//! lies wholly behind the eye.

use super::{Area, Damage, shadow};
use crate::geometry::sphere::Sphere;
use crate::render::camera::Camera;
use crate::render::camera::project::{ScreenMap, add, cross, dot, exceeds, f3, length, scale, sub};

/// The pixels that may see `ball`, from its outline through `map` (tighter than the
/// culling's bounds, which take the sphere's depth range whole): inner `None` if it misses
/// the screen, `None` if no outline can be drawn (the sphere reaches the plane of the eye,
/// or holds the lines through the eye along the screen's axes).
///
/// The columns are bounded by the two planes through the eye along the camera's `down` step
/// that touch the sphere (every direction in such a plane has one column position), the
/// rows likewise along `right`: each is found in the plane across that axis, as the
/// tangents from the eye to the sphere's circle there, and placed on the screen by a point
/// where it touches the sphere. The sphere is widened by 2⁻⁸, far more than the rounding
/// of a primary ray's test; the margins of [`shadow::screen_area`] do the rest.
pub(super) fn outline(
    ball: &Sphere,
    camera: &Camera,
    map: &ScreenMap,
    damage: &Damage,
) -> Option<Option<Area>> {
    let centre = f3(ball.centre() - camera.eye());
    let radius = ball.radius().to_num::<f32>() + 1.0 / 256.0;
    if !exceeds(map.depth(centre) - radius, shadow::NEAREST) {
        return None;
    }
    let (right, down) = camera.steps();
    let mut touches = [[0.0f32; 3]; 4];
    for (pair, axis) in touches.chunks_exact_mut(2).zip([f3(down), f3(right)]) {
        let axis = scale(axis, 1.0 / length(axis));
        let along = dot(centre, axis);
        let across = sub(centre, scale(axis, along));
        let apart = length(across);
        if !exceeds(apart, radius * 1.001) {
            return None;
        }
        // In the plane across the axis: the tangents from the eye meet the circle at the
        // angle asin(r / apart) either side of the centre, cos(angle) · apart away.
        let towards = scale(across, 1.0 / apart);
        let side = cross(axis, towards);
        let sin = radius / apart;
        let cos = libm::sqrtf(1.0 - sin * sin);
        for (touch, sign) in pair.iter_mut().zip([1.0f32, -1.0]) {
            let tangent = add(scale(towards, cos), scale(side, sign * sin));
            *touch = add(scale(tangent, cos * apart), scale(axis, along));
        }
    }
    shadow::screen_area(touches.into_iter(), map, damage)
}

/// Whether every point of `ball` lies behind the eye, so no ray of the screen meets it.
pub(super) fn behind_eye(ball: &Sphere, camera: &Camera, map: &ScreenMap) -> bool {
    let depth = map.depth(f3(ball.centre() - camera.eye()));
    depth + ball.radius().to_num::<f32>() < -1.0 / 16.0
}
