//! [`Damage`]: which pixels an edit of the scene can change, so that an animation redraws
//! only those ([`render_changes`], [`render_row_span`]) and sends only them to its display.
//!
//! The camera stays where it is between the two frames; the scene changes. The region is
//! conservative: a pixel outside it has bit for bit the same colour in both frames. It is
//! built from these rules:
//!
//! - **Nothing** when the scenes are equal.
//! - **The whole screen** when the scenes differ in anything but their objects (a light, the
//!   ambient term, the background, shadows on or off, the depth), in their number of
//!   objects, or when an object of either scene mirrors or refracts (a mirror or glass can
//!   show any other part of the scene); when a changed object is a plane or turns from one
//!   shape into the other; and whenever one of the bounds below cannot be made (a point
//!   behind or beside the eye, a shadow that reaches too far, a light inside a sphere).
//! - **A sphere whose material alone changed**: its silhouette.
//! - **A sphere that moved or changed size**: its silhouettes before and after, and the
//!   shadows it casts before and after on every other object from every light. A pixel
//!   outside both silhouettes meets the same object at the same point in both scenes, and
//!   its colour can differ only where the sphere blocks a shadow ray in one scene and not the
//!   other: where its hit point lies in the sphere's shadow. On a sphere that shadow is
//!   bounded by the receiver's silhouette; on a plane by the projection, from the light, of
//!   a box around the sphere (the central projection of a convex set lies in the hull of
//!   its corners' projections), seen through the camera.
//!
//! Silhouettes are the renderer's own culling, the rows of
//! [`Scene::seen_from_row`](crate::Scene::seen_from_row) and the columns of the camera's
//! screen span of a sphere: a pixel outside them never tries the sphere in
//! [`render_row`](crate::render_row). Shadows are bounded in `f32` once a frame, with the
//! sphere widened by more than the rounding of a shadow ray and its test, and two pixels and
//! more of margin on the screen, more than the half pixel by which a ray may miss its exact
//! direction.

use core::ops::Range;

use embedded_graphics::geometry::{Point, Size};
use embedded_graphics::primitives::Rectangle;

use crate::error::Error;
use crate::framebuffer::Framebuffer;
use crate::geometry::plane::Plane;
use crate::geometry::shape::Shape;
use crate::geometry::sphere::Sphere;
use crate::numbers::vec3::Vec3;
use crate::render::camera::Camera;
use crate::render::camera::project::{F3, ScreenMap, cross, dot, exceeds, f3};
use crate::scene::Scene;
use crate::scene::colour::Rgb;
use crate::scene::light::Light;

/// At most this many rectangles make a [`Damage`]; more are merged into bounding boxes.
pub const MAX_RECTANGLES: usize = 8;

/// A rectangle of whole pixels within the screen: columns `left..right`, rows `top..bottom`,
/// never empty.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Area {
    left: u16,
    top: u16,
    right: u16,
    bottom: u16,
}

impl Area {
    const EMPTY: Area = Area {
        left: 0,
        top: 0,
        right: 0,
        bottom: 0,
    };

    fn pixels(&self) -> u32 {
        u32::from(self.right - self.left) * u32::from(self.bottom - self.top)
    }

    fn contains(&self, other: &Area) -> bool {
        self.left <= other.left
            && self.top <= other.top
            && self.right >= other.right
            && self.bottom >= other.bottom
    }

    fn hull(&self, other: &Area) -> Area {
        Area {
            left: self.left.min(other.left),
            top: self.top.min(other.top),
            right: self.right.max(other.right),
            bottom: self.bottom.max(other.bottom),
        }
    }

    fn meet(&self, other: &Area) -> Option<Area> {
        let area = Area {
            left: self.left.max(other.left),
            top: self.top.max(other.top),
            right: self.right.min(other.right),
            bottom: self.bottom.min(other.bottom),
        };
        (area.left < area.right && area.top < area.bottom).then_some(area)
    }
}

/// The pixels of a screen that may differ between two frames: a few rectangles, or the
/// whole screen. Made by [`Damage::between`]; redrawn by [`render_changes`].
///
/// Up to [`MAX_RECTANGLES`] rectangles are kept; when another is needed, the two whose
/// bounding box adds the fewest pixels are merged into it. The storage is inside the value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Damage {
    areas: [Area; MAX_RECTANGLES],
    count: usize,
    whole: bool,
    cols: u16,
    rows: u16,
}

impl Damage {
    /// No damage on `camera`'s screen: nothing to redraw.
    #[must_use]
    pub const fn none(camera: &Camera) -> Self {
        Damage {
            areas: [Area::EMPTY; MAX_RECTANGLES],
            count: 0,
            whole: false,
            cols: camera.cols(),
            rows: camera.rows(),
        }
    }

    /// The whole of `camera`'s screen.
    #[must_use]
    pub const fn whole(camera: &Camera) -> Self {
        let mut damage = Damage::none(camera);
        damage.whole = true;
        damage
    }

    /// The pixels that may differ between `before` and `after` seen through `camera`: a
    /// conservative region, which never leaves out a pixel whose colour changed.
    ///
    /// The rules (the module's documentation gives the reasons):
    /// - nothing when the scenes are equal;
    /// - the whole screen when a light, the ambient term, the background, shadows on or off,
    ///   the depth or the number of objects differ; when an object of either scene mirrors
    ///   or refracts; when a changed object is a plane or changes shape kind; and when a
    ///   bound cannot be made (a sphere reaching behind the eye, a light inside a moved
    ///   sphere, a shadow on a plane that reaches too far or behind the eye);
    /// - a sphere whose material alone changed: its silhouette;
    /// - a sphere that moved or changed size: its silhouettes before and after, and the
    ///   shadows it casts before and after from every light on every other object (a sphere
    ///   that may receive them: its silhouette; a plane: the screen bound of the shadow on
    ///   it, within the plane's own rectangle if it is bounded).
    ///
    /// Set-up arithmetic in `f32`, once a frame; `O(rows · objects)` for the silhouettes.
    ///
    /// ```
    /// use fixray::{demo, render, render_changes, Damage, Framebuffer, Rgb, Sphere};
    /// let camera = demo::camera(80, 64)?;
    /// let mut scene = demo::scene();
    /// let ball = scene.add_sphere(Sphere::new([0.0, -3.0, -10.0], 1.0)?, Rgb::WHITE)?;
    /// let mut frame = Framebuffer::<80, 64>::new();
    /// render(&scene, &camera, &mut frame)?;
    ///
    /// // Roll the ball along the ground: only what it covered, covers and shades changes.
    /// let before = scene.clone();
    /// scene.set_shape(ball, Sphere::new([0.5, -3.0, -10.0], 1.0)?.into())?;
    /// let damage = Damage::between(&before, &scene, &camera);
    /// assert!(!damage.is_whole() && damage.pixel_count() < 80 * 64 / 4);
    /// render_changes(&scene, &camera, &damage, &mut frame)?;
    ///
    /// let mut full = Framebuffer::<80, 64>::new();
    /// render(&scene, &camera, &mut full)?;
    /// assert_eq!(frame, full);
    /// // Equal scenes: nothing to redraw.
    /// assert!(Damage::between(&scene, &scene, &camera).is_empty());
    /// # Ok::<(), fixray::Error>(())
    /// ```
    #[must_use]
    pub fn between<const N: usize, const L: usize>(
        before: &Scene<N, L>,
        after: &Scene<N, L>,
        camera: &Camera,
    ) -> Damage {
        let mut damage = Damage::none(camera);
        match damage.bound(before, after, camera) {
            Some(()) => damage,
            None => Damage::whole(camera),
        }
    }

    /// Whether nothing needs redrawing.
    #[must_use]
    pub const fn is_empty(&self) -> bool {
        !self.whole && self.count == 0
    }

    /// Whether the whole screen needs redrawing.
    #[must_use]
    pub const fn is_whole(&self) -> bool {
        self.whole
    }

    /// The columns of display row `row` that may change, as one span (the hull of the
    /// rectangles on that row, within the screen), or `None` if none of it may (or the row is
    /// off the screen).
    #[must_use]
    pub fn row_span(&self, row: u32) -> Option<Range<u32>> {
        if row >= u32::from(self.rows) {
            return None;
        }
        if self.whole {
            return Some(0..u32::from(self.cols));
        }
        let mut span: Option<Range<u32>> = None;
        for area in self.areas() {
            if (u32::from(area.top)..u32::from(area.bottom)).contains(&row) {
                let (left, right) = (u32::from(area.left), u32::from(area.right));
                span = Some(match span {
                    Some(s) => s.start.min(left)..s.end.max(right),
                    None => left..right,
                });
            }
        }
        span
    }

    /// The rectangles, within the screen, as embedded-graphics draws them (the whole screen
    /// as one when [`Damage::is_whole`]). They may overlap.
    pub fn rectangles(&self) -> impl Iterator<Item = Rectangle> + '_ {
        let whole = Area {
            left: 0,
            top: 0,
            right: self.cols,
            bottom: self.rows,
        };
        let areas: &[Area] = if self.whole {
            core::slice::from_ref(&self.areas[0])
        } else {
            self.areas()
        };
        areas.iter().map(move |area| {
            let area = if self.whole { &whole } else { area };
            Rectangle::new(
                Point::new(i32::from(area.left), i32::from(area.top)),
                Size::new(
                    u32::from(area.right - area.left),
                    u32::from(area.bottom - area.top),
                ),
            )
        })
    }

    /// The pixels [`render_changes`] redraws: the sum over rows of [`Damage::row_span`]'s
    /// lengths. Compared with the pixels that did change, it measures the region's slack.
    #[must_use]
    pub fn pixel_count(&self) -> u32 {
        (0..u32::from(self.rows))
            .filter_map(|row| self.row_span(row))
            .map(|span| span.len() as u32)
            .sum()
    }

    /// The screen's size, as the camera the damage was made for has it.
    #[must_use]
    pub const fn size(&self) -> Size {
        Size::new(self.cols as u32, self.rows as u32)
    }

    fn areas(&self) -> &[Area] {
        &self.areas[..self.count.min(MAX_RECTANGLES)]
    }

    /// Adds an area; when all places are taken, the pair of the areas (the new one
    /// included) whose bounding box adds the fewest pixels becomes that box.
    fn add(&mut self, area: Area) {
        if self.whole || self.areas().iter().any(|a| a.contains(&area)) {
            return;
        }
        // Drop the areas the new one covers.
        let mut kept = 0;
        for i in 0..self.count.min(MAX_RECTANGLES) {
            if !area.contains(&self.areas[i]) {
                self.areas[kept] = self.areas[i];
                kept += 1;
            }
        }
        self.count = kept;
        if let Some(slot) = self.areas.get_mut(self.count) {
            *slot = area;
            self.count += 1;
            return;
        }
        let mut all = [area; MAX_RECTANGLES + 1];
        all[..MAX_RECTANGLES].copy_from_slice(&self.areas);
        let (mut best, mut pair) = (u32::MAX, (0, MAX_RECTANGLES));
        for i in 0..all.len() {
            for j in i + 1..all.len() {
                let grown = all[i].hull(&all[j]).pixels() - all[i].pixels().min(all[j].pixels());
                if grown < best {
                    (best, pair) = (grown, (i, j));
                }
            }
        }
        let merged = all[pair.0].hull(&all[pair.1]);
        self.count = 0;
        for (index, a) in all.iter().enumerate() {
            if index != pair.0 && index != pair.1 {
                self.areas[self.count] = *a;
                self.count += 1;
            }
        }
        // Seven areas are left: the merged one goes in the eighth place, through `add` so
        // that the areas it now covers are dropped.
        self.add(merged);
    }

    /// The pixels whose centres lie within `margin` pixels of the screen box
    /// `[u0, u1] × [v0, v1]`, clipped to the screen; `None` if the box is not finite.
    fn area_of(&self, [u0, v0]: [f32; 2], [u1, v1]: [f32; 2], margin: f32) -> Option<Option<Area>> {
        if !(u0.is_finite() && u1.is_finite() && v0.is_finite() && v1.is_finite()) {
            return None;
        }
        // Pixel x's centre is x + ½: x from ⌈u0 − margin − ½⌉ to ⌊u1 + margin − ½⌋.
        let span = |lo: f32, hi: f32, count: u16| -> Option<(u16, u16)> {
            let limit = f32::from(count) + 1.0;
            let first = libm::ceilf((lo - margin - 0.5).clamp(-1.0, limit));
            let last = libm::floorf((hi + margin - 0.5).clamp(-1.0, limit));
            let first = first.max(0.0) as u16;
            let end = ((last + 1.0).max(0.0) as u16).min(count);
            (first < end).then_some((first, end))
        };
        let Some((left, right)) = span(u0, u1, self.cols) else {
            return Some(None);
        };
        let Some((top, bottom)) = span(v0, v1, self.rows) else {
            return Some(None);
        };
        Some(Some(Area {
            left,
            top,
            right,
            bottom,
        }))
    }

    /// Works out the region into `self`, or `None` where only the whole screen will do.
    fn bound<const N: usize, const L: usize>(
        &mut self,
        before: &Scene<N, L>,
        after: &Scene<N, L>,
        camera: &Camera,
    ) -> Option<()> {
        let same_setting = before.lights() == after.lights()
            && before.ambient() == after.ambient()
            && before.background() == after.background()
            && before.shadows() == after.shadows()
            && before.depth() == after.depth()
            && before.objects().len() == after.objects().len();
        if !same_setting {
            return None;
        }
        let changed = |index: usize| before.objects().get(index) != after.objects().get(index);
        if !(0..after.objects().len()).any(changed) {
            return Some(());
        }
        let see_through = |scene: &Scene<N, L>| {
            (scene.objects().iter()).any(|o| {
                o.material.reflect() != crate::Fx::ZERO || o.material.refraction().is_some()
            })
        };
        if see_through(before) || see_through(after) {
            return None;
        }
        let map = ScreenMap::new(camera);
        // Silhouettes to add: of sphere `i` as it is before, and as it is after the edit.
        let mut outline_before = [false; N];
        let mut outline_after = [false; N];
        for index in (0..after.objects().len()).filter(|&i| changed(i)) {
            let (Some(old), Some(new)) = (before.objects().get(index), after.objects().get(index))
            else {
                return None;
            };
            let (Shape::Sphere(old_ball), Shape::Sphere(new_ball)) = (old.shape, new.shape) else {
                return None;
            };
            *outline_before.get_mut(index)? = true;
            *outline_after.get_mut(index)? = true;
            if old_ball == new_ball || !after.shadows() {
                continue;
            }
            for light in after.lights() {
                for ball in [old_ball, new_ball] {
                    self.shadows(
                        after,
                        index,
                        &ball,
                        light,
                        camera,
                        &map,
                        &changed,
                        &mut outline_after,
                    )?;
                }
            }
        }
        self.silhouettes(before, camera, &map, &outline_before)?;
        self.silhouettes(after, camera, &map, &outline_after)
    }

    /// Adds the silhouettes of the spheres of `scene` marked in `marked`: the columns of
    /// the camera's span of each, by the rows whose culling keeps it.
    fn silhouettes<const N: usize, const L: usize>(
        &mut self,
        scene: &Scene<N, L>,
        camera: &Camera,
        map: &ScreenMap,
        marked: &[bool; N],
    ) -> Option<()> {
        if !marked.iter().any(|&m| m) {
            return Some(());
        }
        // First and last row (inclusive) on which each marked sphere survives culling.
        let mut rows = [(u16::MAX, 0u16); N];
        for row in 0..camera.rows() {
            let among = scene.seen_from_row(camera, row);
            for (index, range) in rows.iter_mut().enumerate() {
                // Objects past the 64th are never culled.
                if index >= 64 || among & (1 << index) != 0 {
                    *range = (range.0.min(row), range.1.max(row));
                }
            }
        }
        for (index, object) in scene.objects().iter().enumerate() {
            let (Some(true), Some(&(top, last))) = (marked.get(index).copied(), rows.get(index))
            else {
                continue;
            };
            let Shape::Sphere(ball) = object.shape else {
                return None;
            };
            if top > last || behind_eye(&ball, camera, map) {
                continue;
            }
            let (first, end) = camera.column_span(ball.centre(), ball.radius())?;
            let clip = |c: i16| c.clamp(0, camera.cols() as i16) as u16;
            let (left, right) = (clip(first), clip(end.saturating_add(1)));
            if left < right {
                self.add(Area {
                    left,
                    top,
                    right,
                    bottom: last + 1,
                });
            }
        }
        Some(())
    }

    /// Adds the shadows `ball` (object `index` of `scene`, or what it was) casts from `light`
    /// on the other objects that did not change: a sphere that may receive it is marked in
    /// `outlines` for its silhouette; a plane's shadow is bounded here.
    #[allow(clippy::too_many_arguments)]
    fn shadows<const N: usize, const L: usize>(
        &mut self,
        scene: &Scene<N, L>,
        index: usize,
        ball: &Sphere,
        light: &Light,
        camera: &Camera,
        map: &ScreenMap,
        changed: &impl Fn(usize) -> bool,
        outlines: &mut [bool; N],
    ) -> Option<()> {
        let caster = Caster::new(ball, light.position(), camera.eye());
        for (other, object) in scene.objects().iter().enumerate() {
            if other == index || changed(other) {
                // A changed object's pixels are in its own silhouettes already.
                continue;
            }
            match object.shape {
                Shape::Sphere(receiver) => {
                    if caster.may_shade(&receiver) {
                        *outlines.get_mut(other)? = true;
                    }
                }
                Shape::Plane(plane) => {
                    let shadow = caster.on_plane(&plane, map, self);
                    let within = plane_area(&plane, camera.eye(), map, self);
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

/// Renders columns `cols` of display row `row` into `out`, one colour per column: the
/// pixels [`render_row`](crate::render_row) gives them, bit for bit, for a display that is
/// sent only the part of a row that changed ([`Damage::row_span`]).
///
/// Each pixel is traced on its own ([`Camera::ray`], [`Scene::shoot_among`] with the row's
/// culling, [`Scene::shade`]). A row off the screen is [`Error::RowOutOfRange`], columns
/// past its right edge (or a range that ends before it starts) [`Error::ColumnOutOfRange`],
/// and a buffer that is not `cols.len()` long [`Error::BufferLength`].
///
/// ```
/// use fixray::{demo, render_row, render_row_span, Rgb};
/// let (scene, camera) = (demo::scene(), demo::camera(32, 24)?);
/// let mut row = [Rgb::BLACK; 32];
/// render_row(&scene, &camera, 20, &mut row)?;
/// let mut part = [Rgb::BLACK; 8];
/// render_row_span(&scene, &camera, 20, 10..18, &mut part)?;
/// assert_eq!(part, row[10..18]);
/// assert!(render_row_span(&scene, &camera, 20, 30..33, &mut [Rgb::BLACK; 3]).is_err());
/// # Ok::<(), fixray::Error>(())
/// ```
pub fn render_row_span<const N: usize, const L: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
    row: u32,
    cols: Range<u32>,
    out: &mut [Rgb],
) -> Result<(), Error> {
    let line = camera.check_row(row)?;
    if cols.start > cols.end {
        return Err(Error::ColumnOutOfRange {
            col: cols.start,
            cols: camera.width(),
        });
    }
    if cols.end > camera.width() {
        return Err(Error::ColumnOutOfRange {
            col: cols.end - 1,
            cols: camera.width(),
        });
    }
    let needed = cols.len();
    if out.len() != needed {
        return Err(Error::BufferLength {
            needed,
            got: out.len(),
        });
    }
    let among = scene.seen_from_row(camera, line);
    for (x, pixel) in cols.zip(out.iter_mut()) {
        let ray = camera.ray(x, row);
        *pixel = scene.shade(&ray, scene.shoot_among(&ray, among).as_ref());
    }
    Ok(())
}

/// Redraws into `frame` the pixels `damage` holds ([`Damage::row_span`] of each row), as
/// [`render`](crate::render) would draw them for `scene`: a frame of the scene before an
/// edit, so redrawn with the damage of that edit, is the frame of the edited scene, bit for
/// bit.
///
/// The frame must have the camera's size, and the damage must have been made for a camera
/// of that size: otherwise [`Error::SizeMismatch`], and nothing is drawn. See
/// [`Damage::between`] for an example.
pub fn render_changes<const N: usize, const L: usize, const W: usize, const H: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
    damage: &Damage,
    frame: &mut Framebuffer<W, H>,
) -> Result<(), Error> {
    let camera_size = (camera.cols(), camera.rows());
    if (camera_size.0 as usize, camera_size.1 as usize) != (W, H) {
        return Err(Error::SizeMismatch {
            camera: camera_size,
            target: (
                W.min(u16::MAX as usize) as u16,
                H.min(u16::MAX as usize) as u16,
            ),
        });
    }
    if (damage.cols, damage.rows) != camera_size {
        return Err(Error::SizeMismatch {
            camera: camera_size,
            target: (damage.cols, damage.rows),
        });
    }
    for (y, pixels) in (0..).zip(frame.rows_mut().iter_mut()) {
        if let Some(span) = damage.row_span(y)
            && let Some(out) = pixels.get_mut(span.start as usize..span.end as usize)
        {
            render_row_span(scene, camera, y, span, out)?;
        }
    }
    Ok(())
}

/// Whether every point of `ball` lies behind the eye, so no ray of the screen meets it.
fn behind_eye(ball: &Sphere, camera: &Camera, map: &ScreenMap) -> bool {
    let depth = map.depth(f3(ball.centre() - camera.eye()));
    depth + ball.radius().to_num::<f32>() < -1.0 / 16.0
}

/// How far a hit point may lie from the surface it was found on, in world units: far more
/// than a Q16.16 hit point's rounding (a few units of 2⁻¹⁶).
const ON_SURFACE: f32 = 1.0 / 1024.0;

/// Nearer the eye than this (world units, along the view) no point is projected.
const NEAREST: f32 = 1.0 / 16.0;

/// A sphere casting shadows from a point light. Positions are offsets from the light,
/// differences taken exactly in Q16.16 and then converted, so that `f32` never subtracts
/// two large coordinates.
struct Caster {
    /// The sphere's centre.
    centre: F3,
    radius: f32,
    /// The light.
    light: Vec3,
    /// The light as an offset from the camera's eye.
    light_from_eye: F3,
    /// The part of the margin that does not grow with distance (see [`Caster::margin`]).
    reach: f32,
}

impl Caster {
    fn new(ball: &Sphere, light: Vec3, eye: Vec3) -> Self {
        let radius: f32 = ball.radius().to_num();
        Caster {
            centre: f3(ball.centre() - light),
            radius,
            light,
            light_from_eye: f3(light - eye),
            reach: 1.0 / 256.0 + libm::sqrtf(radius) / 32.0,
        }
    }

    /// How much wider than its radius the sphere is taken to be, for receiving points as far
    /// as `distance` from it and from the light.
    ///
    /// A shadow ray from a hit point runs towards the light along a Q16.16 unit direction,
    /// within about 2⁻¹⁵ radians of the exact one: at the sphere it is off the exact segment
    /// by up to `distance · 2⁻¹⁵`, here taken as `distance / 1024`. The sphere's test rounds
    /// the ray's closest approach by a few units of 2⁻¹⁶ (the fixed 1/256), and the square
    /// root that places the crossing along a grazing ray moves it by up to about
    /// `√(r · 2⁻¹³)`, which widening the sphere by `√r / 32` more than covers: a crossing
    /// the test puts before the light is then one the widened sphere has before it too.
    fn margin(&self, distance: f32) -> f32 {
        self.reach + distance / 1024.0
    }

    /// Whether a shadow of the sphere may fall on `receiver`: always when the light is in
    /// or near the widened sphere, where no cone bounds the shadow.
    fn may_shade(&self, receiver: &Sphere) -> bool {
        let to_receiver = f3(receiver.centre() - self.light);
        let reach: f32 = receiver.radius().to_num::<f32>() + ON_SURFACE;
        let apart = length(sub(to_receiver, self.centre));
        let (caster, other) = (length(self.centre), length(to_receiver));
        let widened = self.radius + self.margin(apart.max(other) + reach);
        if !exceeds(caster, widened + 1.0 / 64.0) || other <= reach {
            return true;
        }
        // Every point of the receiver nearer the light than the sphere's near side: a
        // segment from it to the light cannot reach the sphere.
        if other + reach < caster - widened {
            return false;
        }
        // Cones from the light around each: the shadow lies in the sphere's, the receiver in
        // its own. Apart by more than the two half-angles, they never meet.
        let between = libm::atan2f(
            length(cross(self.centre, to_receiver)),
            dot(self.centre, to_receiver),
        );
        let half = |r: f32, d: f32| libm::asinf((r / d).min(1.0));
        !exceeds(
            between,
            half(widened, caster) + half(reach, other) + 1.0 / 1024.0,
        )
    }

    /// The pixels of `plane` the shadow may fall on: `Some(None)` where it casts none there,
    /// `None` where it cannot be bounded (it stretches too far, or reaches behind the eye).
    ///
    /// A shadowed hit point `P` lies within [`ON_SURFACE`] of the plane (a slab), and its
    /// segment to the light meets the widened sphere at some `Q`, which lies between the
    /// slab's bottom and the light's height: `Q` is in the box around the sphere cut to those
    /// heights. Along the ray from the light through `Q`, `P` lies between `Q` (or where the
    /// ray enters the slab, if `Q` is above it) and where it leaves the slab. Central
    /// projection from the light keeps convex hulls, so `P` lies in the hull of the cut
    /// box's corners, each taken into the slab's faces so; and so does its pixel, in the
    /// screen box of those points, all of them ahead of the eye.
    fn on_plane(&self, plane: &Plane, map: &ScreenMap, damage: &Damage) -> Option<Option<Area>> {
        let normal = f3(plane.normal());
        // Heights above the plane, on the light's side.
        let to_light = -dot(normal, f3(plane.point() - self.light));
        if !exceeds(to_light.abs(), 1.0 / 64.0) {
            return None;
        }
        let up = if to_light > 0.0 {
            normal
        } else {
            scale(normal, -1.0)
        };
        let light_height = to_light.abs();
        let centre_height = light_height + dot(up, self.centre);
        let (across, along) = perpendiculars(up);
        // The margin grows with distance: it is worked out again until it covers the
        // farthest point it gives.
        let mut distance = 0.0f32;
        for _ in 0..4 {
            let half = self.radius + self.margin(distance);
            let low = (centre_height - half).max(-ON_SURFACE);
            let high = (centre_height + half).min(light_height);
            if low > high {
                return Some(None);
            }
            // Beyond 63/64 of the light's height the shadow stretches more than 64 times as
            // far from the light as the sphere: not worth bounding.
            if !exceeds(light_height * (63.0 / 64.0), high) {
                return None;
            }
            let mut points = [[0.0f32; 3]; 32];
            let mut count = 0;
            // The cut box in two: below the slab's top, a corner is a point of the slab
            // itself; above, its ray enters the slab at the top face.
            let top = ON_SURFACE.clamp(low, high);
            for (from, to, above) in [(low, top, false), (top, high, true)] {
                if from > to {
                    continue;
                }
                for height in [from, to] {
                    for (a, b) in [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)] {
                        let corner = add(
                            add(self.centre, scale(up, height - centre_height)),
                            add(scale(across, a * half), scale(along, b * half)),
                        );
                        // The ray from the light through the corner is at height h at the
                        // fraction (light − h) / (light − corner) of the way along, past 1.
                        let at =
                            |h: f32| scale(corner, (light_height - h) / (light_height - height));
                        let enters = if above { at(ON_SURFACE) } else { corner };
                        for p in [enters, at(-ON_SURFACE)] {
                            if let Some(slot) = points.get_mut(count) {
                                *slot = p;
                                count += 1;
                            }
                        }
                    }
                }
            }
            let points = points.get(..count)?;
            let farthest = points.iter().fold(0.0f32, |m, &p| {
                m.max(length(p)).max(length(sub(p, self.centre)))
            });
            if !farthest.is_finite() {
                return None;
            }
            if farthest <= distance {
                return screen_area(
                    points.iter().map(|&p| add(self.light_from_eye, p)),
                    map,
                    damage,
                );
            }
            distance = farthest * 1.25 + 1.0;
        }
        None
    }
}

/// The pixels that may show points `from_eye` (offsets from the eye) and anything in their
/// convex hull, or `None` if one lies less than [`NEAREST`] ahead of the eye. Empty (inner
/// `None`) when the box misses the screen.
fn screen_area(
    from_eye: impl Iterator<Item = F3>,
    map: &ScreenMap,
    damage: &Damage,
) -> Option<Option<Area>> {
    let (mut min, mut max) = ([f32::MAX; 2], [f32::MIN; 2]);
    let mut nearest = f32::MAX;
    for d in from_eye {
        let [u, v] = map.position(d, NEAREST)?;
        nearest = nearest.min(map.depth(d));
        (min[0], min[1]) = (min[0].min(u), min[1].min(v));
        (max[0], max[1]) = (max[0].max(u), max[1].max(v));
    }
    if !exceeds(f32::MAX, nearest) {
        return Some(None);
    }
    // Two pixels: a ray may miss its exact direction by half a pixel (see `Camera`), and
    // `f32` rounding here is a small fraction of one. A hit point's own rounding, a few
    // units of 2⁻¹⁶ (taken as 2⁻¹²), moves its picture by up to about view / depth times
    // that, and more towards the screen's edges, by (view² + offset²) / view.
    let view = map.view();
    let offset = [min[0].abs(), max[0].abs(), min[1].abs(), max[1].abs()]
        .into_iter()
        .fold(0.0f32, f32::max)
        + f32::from(damage.cols.max(damage.rows));
    let margin = 2.0 + (view + offset * offset / view) / (nearest * 4096.0) + offset / 65536.0;
    damage.area_of(min, max, margin)
}

/// The pixels that may see `plane`, if it is bounded and its rectangle lies ahead of the
/// eye: inner `None` when none can; `None` when it is unbounded or not wholly ahead.
fn plane_area(plane: &Plane, eye: Vec3, map: &ScreenMap, damage: &Damage) -> Option<Option<Area>> {
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
    let n = f3(normal);
    let (point, eye) = (f3(plane.point()), f3(eye));
    let slack = 1.0 / 256.0;
    let mut corners = [[0.0f32; 3]; 8];
    let mut count = 0;
    for u in [
        min[0].to_num::<f32>() - slack,
        max[0].to_num::<f32>() + slack,
    ] {
        for v in [
            min[1].to_num::<f32>() - slack,
            max[1].to_num::<f32>() + slack,
        ] {
            let mut p = [0.0f32; 3];
            p[a] = u;
            p[b] = v;
            // On the plane: n·(p − point) = 0 fixes the dropped coordinate (its normal
            // component is the largest, at least 1/√3).
            p[dropped] =
                point[dropped] - (n[a] * (u - point[a]) + n[b] * (v - point[b])) / n[dropped];
            for side in [-ON_SURFACE, ON_SURFACE] {
                if let Some(slot) = corners.get_mut(count) {
                    *slot = add(sub(p, eye), scale(n, side));
                    count += 1;
                }
            }
        }
    }
    screen_area(corners.into_iter(), map, damage)
}

fn sub(a: F3, b: F3) -> F3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn add(a: F3, b: F3) -> F3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn scale(a: F3, k: f32) -> F3 {
    [a[0] * k, a[1] * k, a[2] * k]
}

fn length(a: F3) -> f32 {
    libm::sqrtf(dot(a, a))
}

/// Two unit vectors perpendicular to the unit `n` and to each other.
fn perpendiculars(n: F3) -> (F3, F3) {
    let other = if n[0].abs() < 0.6 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let a = cross(n, other);
    let a = scale(a, 1.0 / length(a));
    (a, cross(n, a))
}
