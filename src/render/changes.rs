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
//!   show any other part of the scene); when a changed plane moved or turned, an infinite
//!   one's material changed, or an object turned from one shape into the other; and
//!   whenever the shadow of a changed sphere on an infinite plane cannot be bounded: it
//!   stretches too far (a light within 1/64 of the widened sphere, an edge of the pyramid
//!   below not running down to the plane, or running more than 64 times its length to it)
//!   or reaches within 1/16 of the plane of the eye.
//! - **A sphere whose material alone changed**: its silhouette. **A bounded plane whose
//!   material alone changed**: its rectangle (an infinite one: the whole screen).
//! - **A sphere that moved or changed size**: its silhouettes before and after, and the
//!   shadows it casts before and after on every other object from every light. A pixel
//!   outside both silhouettes meets the same object at the same point in both scenes, and
//!   its colour can differ only where the sphere blocks a shadow ray in one scene and not the
//!   other: where its hit point lies in the sphere's shadow. That shadow lies in the cone
//!   from the light around the sphere, and in a pyramid around the cone, through an octagon
//!   around its section at the sphere's centre. On a sphere it is bounded by the receiver's
//!   silhouette, where the cone comes within the receiver's radius of its centre, met with
//!   the pyramid cut between the planes across its axis that hold the receiver; on a plane
//!   by the pyramid cut by the slab of the plane's hit points, and by the plane's own
//!   rectangle when it is bounded (which stands in alone where the shadow cannot be
//!   bounded). Each cut is the hull of the points where the pyramid's edges cross its
//!   faces, and so is its picture: the pixels near the screen box of those points.
//! - **Several changed spheres**: the union of what each gives.
//!
//! Silhouettes are the renderer's own culling: on each row the columns of the camera's span
//! of the ball that row's rays can meet of the sphere (`row_ball`, on the rows whose plane
//! comes near it), a pixel outside which never tries the sphere in
//! [`render_row`](crate::render_row) (the whole row where the sphere reaches the plane of
//! the eye and has no span; nothing where it lies wholly behind it); a changed sphere's are
//! met with the screen box of the cube around it, and each is kept in four bands of rows.
//!
//! All of it is integer arithmetic, once a frame, with no `f32`: points and offsets in raw
//! Q16.16 units in `i64`, which two points of the overflow-safe range and a shadow's
//! crossings (at most 64 times an edge of the pyramid from the light, below 2³⁸) keep
//! within ±2⁴⁴, and their products in `i128`, exact (the camera's cross products are below
//! 2⁴⁹ a component, so a dot product of one with an offset is below 2⁹⁶). Square roots are
//! bounded from below or above as the bound needs; the few quotients are 64-bit divisions of
//! numbers shifted down together, within 3/256 of a pixel for a position and within
//! `2⁻²³` relatively for a crossing, which widens the margin by as much. The margins: the
//! sphere casting a shadow is widened by more than the rounding of a shadow ray and of its
//! test (1/256, `√r/32` and 1/1024 of the distance to the shadow), a hit point is taken to
//! lie within 2⁻¹⁰ of its surface, the octagon around the cone's section is 1/64 and eight
//! raw units wider than it needs to be, and a screen box gets half a pixel (the most by
//! which a ray misses its exact direction), 1/256, and what 2⁻¹¹ of a world unit (a hit
//! point's rounding and the points' own) moves a picture at the box's nearest depth.
//!
//! The region is kept as at most [`MAX_RECTANGLES`] rectangles; when a ninth is needed, the
//! two of the nine whose bounding box adds the fewest pixels become that box. A renderer redraws, on each row, the hull of
//! the rectangles there ([`Damage::row_span`]): one window per row for a display driver.

mod exact;
mod redraw;
mod screen;
mod shadow;

pub use redraw::{render_changes, render_row_span};

use screen::{Screen, behind_eye};

use core::ops::Range;

use embedded_graphics::geometry::{Point, Size};
use embedded_graphics::primitives::Rectangle;

use crate::geometry::shape::Shape;
use crate::geometry::sphere::Sphere;
use crate::render::accel::cull::{row_ball, row_offset};
use crate::render::camera::Camera;
use crate::scene::Scene;

/// At most this many rectangles make a [`Damage`]; more are merged into bounding boxes.
pub const MAX_RECTANGLES: usize = 8;

/// A rectangle of whole pixels within the screen: columns `left..right`, rows `top..bottom`;
/// never empty.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Area {
    left: u16,
    top: u16,
    right: u16,
    bottom: u16,
}

impl Area {
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
/// bounding box adds the fewest pixels to their union are merged into it. The storage is
/// inside the value.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Damage {
    areas: heapless::Vec<Area, MAX_RECTANGLES>,
    whole: bool,
    cols: u16,
    rows: u16,
}

impl Damage {
    /// No damage on `camera`'s screen: nothing to redraw.
    #[must_use]
    pub const fn none(camera: &Camera) -> Self {
        Damage {
            areas: heapless::Vec::new(),
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
    ///   or refracts; when a plane moved or turned, an infinite plane's material changed or
    ///   an object changed shape kind; and when the shadow of a changed sphere on an
    ///   infinite plane cannot be bounded (it stretches too far, as from a light inside the
    ///   sphere or barely above it, or reaches behind the eye);
    /// - a sphere whose material alone changed: its silhouette; a bounded plane whose
    ///   material alone changed: its rectangle;
    /// - a sphere that moved or changed size: its silhouettes before and after, and the
    ///   shadows it casts before and after from every light on every other object (a sphere
    ///   that may receive them: its silhouette, within the screen bound of the shadow there;
    ///   a plane: the screen bound of the shadow on it, within the plane's own rectangle if
    ///   it is bounded).
    ///
    /// Integer arithmetic, once a frame; `O(rows · objects)` for the silhouettes.
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
    pub fn is_empty(&self) -> bool {
        !self.whole && self.areas.is_empty()
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
        let whole = self.whole.then_some(Area {
            left: 0,
            top: 0,
            right: self.cols,
            bottom: self.rows,
        });
        // When whole, the kept areas (none) are not listed, the screen is.
        let kept = if self.whole { &[][..] } else { self.areas() };
        whole.into_iter().chain(kept.iter().copied()).map(|area| {
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
        &self.areas
    }

    /// Adds an area; when all places are taken, the pair of the areas (the new one
    /// included) whose bounding box adds the fewest pixels becomes that box.
    fn add(&mut self, area: Area) {
        if self.whole || self.areas().iter().any(|a| a.contains(&area)) {
            return;
        }
        // Drop the areas the new one covers.
        self.areas.retain(|a| !area.contains(a));
        let Err(area) = self.areas.push(area) else {
            return;
        };
        let mut all: heapless::Vec<Area, { MAX_RECTANGLES + 1 }> = heapless::Vec::new();
        all.extend(self.areas.iter().copied().chain([area]));
        let (mut best, mut pair) = (u32::MAX, (0, MAX_RECTANGLES));
        for i in 0..all.len() {
            for j in i + 1..all.len() {
                // The box less the union of the two: below 2 · 4096², exact in u32.
                let (a, b) = (&all[i], &all[j]);
                let overlap = a.meet(b).map_or(0, |m| m.pixels());
                let grown = (a.hull(b).pixels() + overlap) - (a.pixels() + b.pixels());
                if grown < best {
                    (best, pair) = (grown, (i, j));
                }
            }
        }
        let merged = all[pair.0].hull(&all[pair.1]);
        self.areas.clear();
        for (index, a) in all.iter().enumerate() {
            if index != pair.0 && index != pair.1 {
                // Seven of the nine: room for each.
                let _ = self.areas.push(*a);
            }
        }
        // Seven areas are left: the merged one goes in the eighth place, through `add` so
        // that the areas it now covers are dropped.
        self.add(merged);
    }

    /// The pixels whose centres lie within `margin` of the screen box `[low, high]` (all in
    /// units of 1/256 of a pixel), clipped to the screen: `None` if there are none. Each
    /// value within ±2⁴¹, so nothing here overflows.
    fn area_of(&self, low: [i64; 2], high: [i64; 2], margin: i64) -> Option<Area> {
        // Pixel x's centre is x + ½: x from ⌈(low − margin)/256 − ½⌉ to
        // ⌊(high + margin)/256 − ½⌋.
        let span = |lo: i64, hi: i64, count: u16| -> Option<(u16, u16)> {
            let first = (lo - margin - 128 + 255).div_euclid(256);
            let last = (hi + margin - 128).div_euclid(256);
            let first = first.clamp(0, count.into()) as u16;
            let end = (last + 1).clamp(0, count.into()) as u16;
            (first < end).then_some((first, end))
        };
        let (left, right) = span(low[0], high[0], self.cols)?;
        let (top, bottom) = span(low[1], high[1], self.rows)?;
        Some(Area {
            left,
            top,
            right,
            bottom,
        })
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
        let see_through =
            |scene: &Scene<N, L>| (scene.objects().iter()).any(|o| o.material.sends_rays());
        if see_through(before) || see_through(after) {
            return None;
        }
        let screen = Screen::new(camera)?;
        // Silhouettes to add: of sphere `i` as it is before, and as it is after the edit.
        let mut outline_before = [None; N];
        let mut outline_after = [None; N];
        let screen_area = Area {
            left: 0,
            top: 0,
            right: self.cols,
            bottom: self.rows,
        };
        for index in (0..after.objects().len()).filter(|&i| changed(i)) {
            let (Some(old), Some(new)) = (before.objects().get(index), after.objects().get(index))
            else {
                return None;
            };
            let (old_ball, new_ball) = match (old.shape, new.shape) {
                (Shape::Sphere(old_ball), Shape::Sphere(new_ball)) => (old_ball, new_ball),
                // A plane's new material shows only where the plane is seen, and casts the
                // same shadows: within its rectangle, if it has one.
                (Shape::Plane(old_plane), Shape::Plane(new_plane)) if old_plane == new_plane => {
                    if let Some(area) = shadow::plane_area(&new_plane, camera.eye(), &screen, self)?
                    {
                        self.add(area);
                    }
                    continue;
                }
                _ => return None,
            };
            // The sphere's cube, where it can be bounded; the culling bounds it in any case.
            let seen = |ball: &Sphere| match screen.ball_area(ball, camera.eye(), self) {
                Some(area) => area,
                None => Some(screen_area),
            };
            *outline_before.get_mut(index)? = seen(&old_ball);
            *outline_after.get_mut(index)? = seen(&new_ball);
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
                        &screen,
                        &changed,
                        &mut outline_after,
                    )?;
                }
            }
        }
        self.silhouettes(
            [(before, &outline_before), (after, &outline_after)],
            camera,
            &screen,
        )
    }

    /// Adds the silhouettes of the spheres marked in each `(scene, marked)` pair, each met
    /// with the area it is marked with: on each row, the columns of the camera's span of
    /// the ball the row's rays can meet of the sphere (`row_ball`, on the rows whose culling
    /// keeps it), what `render_row` tries it on. The rows of each silhouette are taken in
    /// [`BANDS`] bands across its mark, each the hull of its rows. `O(rows · marked)`: each
    /// row's plane is found once for both scenes.
    fn silhouettes<const N: usize, const L: usize>(
        &mut self,
        scenes: [(&Scene<N, L>, &[Option<Area>; N]); 2],
        camera: &Camera,
        screen: &Screen,
    ) -> Option<()> {
        // Spheres wholly behind the eye are not seen at all.
        let mut live = [[None; N]; 2];
        for ((scene, marked), live) in scenes.iter().zip(live.iter_mut()) {
            for ((object, mark), live) in scene.objects().iter().zip(*marked).zip(live) {
                if let Shape::Sphere(ball) = object.shape
                    && !behind_eye(&ball, camera, screen)
                {
                    *live = *mark;
                } else if mark.is_some() && !matches!(object.shape, Shape::Sphere(_)) {
                    return None;
                }
            }
        }
        let marks = live.iter().flatten().flatten();
        let (first, end) = marks.fold((u16::MAX, 0), |(first, end), m| {
            (first.min(m.top), end.max(m.bottom))
        });
        let mut bands = [[[None::<Area>; BANDS]; N]; 2];
        let (eye, cols) = (camera.eye(), camera.cols());
        let clip = |c: i16| c.clamp(0, cols as i16) as u16;
        for row in first..end {
            let normal = camera.row_plane_normal(row);
            for (((scene, _), live), bands) in scenes.iter().zip(&live).zip(bands.iter_mut()) {
                for ((index, object), (mark, bands)) in scene
                    .objects()
                    .iter()
                    .enumerate()
                    .zip(live.iter().zip(bands.iter_mut()))
                {
                    let (Some(within), Shape::Sphere(ball)) = (mark, object.shape) else {
                        continue;
                    };
                    if !(within.top..within.bottom).contains(&row) {
                        continue;
                    }
                    // Objects past the 64th, and rows without a plane, are never culled.
                    let (centre, radius) = match normal {
                        Some(normal) if index < 64 => match row_offset(&ball, eye, normal) {
                            Some(height) => row_ball(&ball, eye, normal, height),
                            None => continue,
                        },
                        _ => (ball.centre(), ball.radius()),
                    };
                    // A sphere with no span is tried on every column.
                    let (left, right) = match camera.column_span(centre, radius) {
                        Some((first, last)) => (clip(first), clip(last.saturating_add(1))),
                        None => (0, cols),
                    };
                    if left >= right {
                        continue;
                    }
                    let here = Area {
                        left,
                        top: row,
                        right,
                        bottom: row + 1,
                    };
                    let height = u32::from(within.bottom - within.top);
                    let band = (u32::from(row - within.top) * BANDS as u32 / height) as usize;
                    if let Some(band) = bands.get_mut(band) {
                        *band = Some(band.map_or(here, |b| b.hull(&here)));
                    }
                }
            }
        }
        for (bands, live) in bands.iter().zip(&live) {
            for (bands, mark) in bands.iter().zip(live) {
                for (band, mark) in bands.iter().zip(core::iter::repeat(mark)) {
                    if let (Some(band), Some(mark)) = (band, mark)
                        && let Some(area) = band.meet(mark)
                    {
                        self.add(area);
                    }
                }
            }
        }
        Some(())
    }
}

/// How many bands of rows a silhouette is kept in: the hull of each is closer to a round
/// outline than one box.
const BANDS: usize = 4;

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> Camera {
        Camera::pinhole(2.0, 2.0, 1.0)
            .size(Size::new(100, 60))
            .build()
            .unwrap()
    }

    fn square(x: u16, y: u16) -> Area {
        Area {
            left: x,
            top: y,
            right: x + 5,
            bottom: y + 5,
        }
    }

    #[test]
    fn a_ninth_rectangle_merges_the_pair_that_grows_least() {
        let mut damage = Damage::none(&camera());
        // Nine squares along a row, the last two closest together.
        for x in [0, 11, 22, 33, 44, 55, 66, 77, 83] {
            damage.add(square(x, 0));
        }
        assert_eq!(damage.areas().len(), MAX_RECTANGLES);
        for x in [0, 11, 22, 33, 44, 55, 66, 77, 83] {
            assert!(damage.areas().iter().any(|a| a.contains(&square(x, 0))));
        }
        assert!(damage.areas().contains(&Area {
            left: 77,
            top: 0,
            right: 88,
            bottom: 5
        }));
        // A covered area adds nothing; one covering others replaces them.
        let before = damage.clone();
        damage.add(square(78, 0));
        assert_eq!(damage, before);
        damage.add(Area {
            left: 0,
            top: 0,
            right: 30,
            bottom: 10,
        });
        assert_eq!(damage.areas().len(), 6);
    }

    #[test]
    fn a_row_span_is_the_hull_of_the_rectangles_on_it() {
        let mut damage = Damage::none(&camera());
        damage.add(square(10, 10));
        damage.add(square(40, 12));
        assert_eq!(damage.row_span(9), None);
        assert_eq!(damage.row_span(10), Some(10..15));
        assert_eq!(damage.row_span(13), Some(10..45));
        assert_eq!(damage.row_span(16), Some(40..45));
        assert_eq!(damage.row_span(60), None);
        assert_eq!(damage.pixel_count(), 2 * 5 + 3 * 35 + 2 * 5);
        let rectangles = damage.rectangles().count();
        assert_eq!(rectangles, 2);
    }

    #[test]
    fn screen_boxes_become_pixels_whose_centres_lie_within_the_margin() {
        let damage = Damage::none(&camera());
        let at = |x: f64| (x * 256.0) as i64;
        // Centres x + ½ within [10.2 − 1, 20.7 + 1]: columns 9 to 21; rows likewise.
        let area = damage.area_of([at(10.2), at(5.0)], [at(20.7), at(6.0)], 256);
        assert_eq!(
            area,
            Some(Area {
                left: 9,
                top: 4,
                right: 22,
                bottom: 7
            })
        );
        // A centre exactly on the margin's edge is in: column 9's centre is 9.5, and
        // 10.5 − 1 = 9.5.
        let edge = damage.area_of([at(10.5), 0], [at(10.5), 0], 256);
        assert_eq!(edge.map(|a| (a.left, a.right)), Some((9, 12)));
        // Off the screen, clipped; far off, clipped to the screen.
        assert_eq!(
            damage.area_of([at(-50.0), at(-9.0)], [at(-20.0), at(-5.0)], 512),
            None
        );
        let far = damage.area_of([-(1 << 41), 0], [1 << 41, 256], 512);
        assert_eq!(far.map(|a| (a.left, a.right)), Some((0, 100)));
    }
}
