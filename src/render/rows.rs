//! The chapter's double loop: for each pixel, shoot a ray through its centre and shade it.

use core::ops::Range;

use crate::error::Error;
use crate::framebuffer::Framebuffer;
use crate::geometry::plane::Plane;
use crate::geometry::ray::Ray;
use crate::geometry::shape::Shape;
use crate::numbers::vec3::Vec3;
use crate::render::accel::crowd::{Crowd, Names};
use crate::render::accel::crowd_floor::{Floor, Floors};
use crate::render::accel::crowd_spheres::{FRAME_SLOTS, Pixels, ROW_SLOTS, SphereShadowers};
use crate::render::accel::matte::MatteRun;
use crate::render::accel::row_rays::RowRays;
use crate::render::accel::runs::Runs;
use crate::render::camera::Camera;
use crate::scene::Scene;
use crate::scene::colour::Rgb;
use crate::scene::hit::SceneHit;

/// Renders display row `y` (0 at the top) into `out`, one colour per column.
///
/// This is the streaming form: RAM for one row, so a chip that cannot hold a frame can send
/// each row to its display as it is finished. `y` must be below `camera.height()`
/// ([`Error::RowOutOfRange`]) and `out` must hold exactly `camera.width()` pixels
/// ([`Error::BufferLength`]).
///
/// ```
/// use fixray::{demo, render_row, Error, Rgb};
/// let (scene, camera) = (demo::scene(), demo::camera(16, 8).unwrap());
/// let mut row = [Rgb::BLACK; 16];
/// render_row(&scene, &camera, 7, &mut row).unwrap();
/// // The bottom row of the demo looks down at the ground plane, not the sky.
/// assert_ne!(row[0], demo::BACKGROUND);
/// // A buffer that is not one row long is refused, whether short or long.
/// let mut long = [Rgb::BLACK; 17];
/// assert_eq!(
///     render_row(&scene, &camera, 7, &mut long),
///     Err(Error::BufferLength { needed: 16, got: 17 })
/// );
/// ```
pub fn render_row<const N: usize, const L: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
    y: u32,
    out: &mut [Rgb],
) -> Result<(), Error> {
    let row = check_row(camera, y, out)?;
    render_every(scene, camera, row, &[(0..camera.cols(), 0)], out);
    Ok(())
}

/// Paints a run [`cast_row`] hands over whole into `out[cols]`, display columns from `first`
/// by `stride` of display row `row`: a matte run (by `floor` where it shades it), or a run of
/// sky (`sky`, where it is plain).
#[allow(clippy::too_many_arguments)]
fn paint_run<const N: usize, const L: usize>(
    (scene, camera, row): (&Scene<N, L>, &Camera, u16),
    (first, stride): (u16, u16),
    out: &mut [Rgb],
    cols: Range<u16>,
    run: Run<'_>,
    shadowers: &[u32; L],
    sky: Option<Rgb>,
    floor: impl Floors<N, L>,
) {
    let Some(pixels) = out.get_mut(cols.start as usize..cols.end as usize) else {
        return;
    };
    match run {
        Run::Matte(run) => {
            if !floor.shade(scene, camera, run, (first, stride), pixels) {
                scene.shade_matte_run(camera, run, shadowers, pixels);
            }
        }
        Run::Empty => match sky {
            Some(sky) => pixels.fill(sky),
            None => scene.paint_sky(camera, row, first, stride, pixels),
        },
    }
}

/// Shades the pixel [`cast_row`] hands over for `out[col]`, display column `column`, by
/// `pixels`.
fn paint_pixel<const N: usize, const L: usize>(
    (scene, pixels): (&Scene<N, L>, &mut impl Pixels<N, L>),
    out: &mut [Rgb],
    (col, column): (u16, u16),
    ray: &Ray,
    hit: Option<SceneHit>,
    shadowers: &[u32; L],
) {
    if let Some(out) = out.get_mut(col as usize) {
        *out = pixels.pixel(scene, (ray, column), hit, shadowers);
    }
}

/// [`render_row`]'s pixels for columns `cols` of a checked display row, into `out`
/// (`out[0]` is column `cols.start`): the same walk along the row, started and stopped at the
/// span's ends, so the pixels are bit for bit those of the whole row. Columns past the row or
/// past `out` are not drawn.
pub(crate) fn render_columns<const N: usize, const L: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
    row: u16,
    cols: Range<u16>,
    out: &mut [Rgb],
) {
    render_every(scene, camera, row, &[(cols, 0)], out);
}

/// [`render_columns`] for walks along the row, each every `2^shift`th column of its `cols`
/// from its first, their pixels one after another in `out` (`out[i]` is column
/// `cols.start + i·2^shift` of the first walk, and so on): the same walk along the row, its
/// column step taken `2^shift` at a time, exactly, so the pixels are bit for bit those of the
/// whole row. The row is set up once for all its walks. `shift` at most
/// [`MAX_STRIDE_SHIFT`]; a larger one is taken as that.
pub(crate) fn render_every<const N: usize, const L: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
    row: u16,
    walks: &[(Range<u16>, u32)],
    out: &mut [Rgb],
) {
    if N > 32 {
        let spheres = &mut SphereShadowers::<L, ROW_SLOTS>::new();
        return crowded_every(scene, camera, row, walks, out, spheres);
    }
    let runs = &mut Runs::new(scene, camera, row);
    walk_every(scene, camera, row, walks, out, runs, ((), &mut ()));
}

/// [`render_every`] for a scene whose capacity passes 32, where the shadow sets no longer name
/// every object: its floor's casters found for the row, its spheres' shadowers kept in
/// `spheres`, which a frame's rows share, and past 64 its row's objects kept as a [`Crowd`].
fn crowded_every<const N: usize, const L: usize, const S: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
    row: u16,
    walks: &[(Range<u16>, u32)],
    out: &mut [Rgb],
    spheres: &mut SphereShadowers<L, S>,
) {
    if N > 64 {
        let mut crowd = Crowd::empty();
        let mut runs = Runs::crowded(scene, camera, row, &mut crowd);
        let floor = Floor::of_row(scene, camera, row, runs.eye());
        return walk_every(
            scene,
            camera,
            row,
            walks,
            out,
            &mut runs,
            (&floor, &mut (&floor, spheres)),
        );
    }
    let mut runs = Runs::new(scene, camera, row);
    let floor = Floor::of_row(scene, camera, row, runs.eye());
    walk_every(
        scene,
        camera,
        row,
        walks,
        out,
        &mut runs,
        (&floor, &mut (&floor, spheres)),
    );
}

/// [`render_every`] along the runs `runs` of display row `row`, its matte runs shaded by
/// `floor` where it shades them, and its other pixels by `pixels`.
fn walk_every<const N: usize, const L: usize, C: Names>(
    scene: &Scene<N, L>,
    camera: &Camera,
    row: u16,
    walks: &[(Range<u16>, u32)],
    out: &mut [Rgb],
    runs: &mut Runs<'_, N, L, C>,
    (floor, pixels): (impl Floors<N, L>, &mut impl Pixels<N, L>),
) {
    // Where nothing can be hit the sky needs no rays: a plain one is its colour, a gradient
    // reads one component of each ray's direction.
    let sky = scene.background().plain_colour();
    let at = (scene, camera, row);
    let mut offset = 0;
    for (cols, shift) in walks {
        // A walk of one column never steps: it is taken as that column alone, with a stride
        // of 1, which keeps the step a column's however wide the stride asked.
        let shift = (*shift).min(MAX_STRIDE_SHIFT);
        let (cols, shift) = match cols.len() > 1 << shift {
            true => (cols.clone(), shift),
            false => (cols.start..cols.end.min(cols.start.saturating_add(1)), 0),
        };
        let Some(walk_out) = out.get_mut(offset..) else {
            return;
        };
        offset += (cols.len() + (1 << shift) - 1) >> shift;
        let (start, stride) = (cols.start, 1 << shift);
        cast_row(
            scene,
            camera,
            runs,
            (cols, shift),
            (true, true),
            walk_out,
            |out, first, end, run, shadowers| {
                let place = (start + (first << shift), stride);
                paint_run(at, place, out, first..end, run, shadowers, sky, floor);
            },
            |out, col, ray, hit, shadowers| {
                let column = start + (col << shift);
                paint_pixel((scene, pixels), out, (col, column), ray, hit, shadowers)
            },
        );
    }
}

/// The largest stride of a walk along a row, as a power of two: `2^7` column steps, each
/// component of which stays within 2²⁴ raw (a component of `right` is at most 2¹⁶ + 1).
pub(crate) const MAX_STRIDE_SHIFT: u32 = 7;

/// Shoots the ray of every pixel of display row `y` into the scene, nearest hit first, and
/// hands each to `each(x, ray, hit)` in column order: `render_row` without the shading.
///
/// A row of rays lies in one plane through the eye, and each sphere covers a span of columns,
/// so the row is first culled: only the spheres whose span holds a pixel are tried for it
/// (the spheres the row's plane can meet and [`Camera`]'s conservative screen span of a sphere). The hits
/// are exactly those of [`Scene::shoot`]. A row outside the screen is
/// [`Error::RowOutOfRange`], and nothing is shot.
///
/// ```
/// use fixray::{demo, shoot_row, Error};
/// let (scene, camera) = (demo::scene(), demo::camera(40, 32).unwrap());
/// let mut hits = 0;
/// shoot_row(&scene, &camera, 31, |x, ray, hit| {
///     assert_eq!(hit, scene.shoot(ray), "column {x}");
///     hits += hit.is_some() as u32;
/// })?;
/// assert_eq!(hits, 40); // the bottom row sees the ground everywhere
/// assert_eq!(
///     shoot_row(&scene, &camera, 32, |_, _, _| {}),
///     Err(Error::RowOutOfRange { row: 32, rows: 32 })
/// );
/// # Ok::<(), Error>(())
/// ```
pub fn shoot_row<const N: usize, const L: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
    y: u32,
    mut each: impl FnMut(u32, &Ray, Option<SceneHit>),
) -> Result<(), Error> {
    let row = camera.check_row(y)?;
    cast_row(
        scene,
        camera,
        &mut Runs::new(scene, camera, row),
        (0..camera.cols(), 0),
        (false, false),
        &mut each,
        |_, _, _, _, _| {}, // not made: `skip_empty` and `matte` are false here
        |each, col, ray, hit, _| each(col.into(), ray, hit),
    );
    Ok(())
}

/// [`shoot_row`] for a renderer whose background needs no ray (a plain colour): the columns
/// where the row can meet nothing come as whole runs, `empty(first..end)`, without rays made
/// for them; every other column as `each(x, ray, hit)`, in column order. This is what
/// [`render_row`] does over a plain sky, for a shading of one's own. A row outside the
/// screen is [`Error::RowOutOfRange`], and nothing is handed over.
///
/// ```
/// use fixray::{demo, internals::shoot_row_skipping};
/// let (scene, camera) = (demo::scene(), demo::camera(40, 32).unwrap());
/// let (mut skipped, mut shot) = (0, 0);
/// shoot_row_skipping(&scene, &camera, 0, |run| skipped += run.len(), |_, _, _| shot += 1)?;
/// assert_eq!((skipped, shot), (40, 0)); // the top row sees only sky
/// # Ok::<(), fixray::Error>(())
/// ```
#[cfg(feature = "internals")]
pub fn shoot_row_skipping<const N: usize, const L: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
    y: u32,
    empty: impl FnMut(core::ops::Range<u32>),
    each: impl FnMut(u32, &Ray, Option<SceneHit>),
) -> Result<(), Error> {
    let row = camera.check_row(y)?;
    cast_row(
        scene,
        camera,
        &mut Runs::new(scene, camera, row),
        (0..camera.cols(), 0),
        (true, false),
        &mut (empty, each),
        |(empty, _), first, end, run, _| match run {
            Run::Empty => empty(first.into()..end.into()),
            Run::Matte(_) => {} // not made: `matte` is false here
        },
        |(_, each), col, ray, hit, _| each(col.into(), ray, hit),
    );
    Ok(())
}

/// What [`cast_row`] hands over for a run of columns as a whole, without rays.
pub(crate) enum Run<'a> {
    /// A run in which no object can be hit.
    Empty,
    /// A run that can meet one matte plane only, on a row parallel to it: found and shaded
    /// whole ([`Scene::shade_matte_run`]).
    Matte(&'a MatteRun<'a>),
}

/// The engine of [`shoot_row`] and [`render_row`]: the row's runs ([`Runs`]), and in each the
/// rays, by column steps ([`Camera::row_rays`]), shot at the run's objects; each is handed to
/// `each(i, ray, hit, shadowers)`, with `shadowers[i]` the objects that may shadow the row's
/// plane hits from light `i` (see `Runs::shadowers`). Only columns `cols` are cast, every
/// `2^shift`th from the first: `i` counts them.
///
/// With `skip_empty`, a run in which no object can be hit is handed over whole and without
/// rays, as `whole(first, end, Run::Empty, shadowers)`: `render_row` paints the sky so, which
/// needs no ray (a plain one is its colour, a gradient reads one component of each
/// direction: `Scene::paint_sky`). With `matte`, a run that can meet one matte plane only, on
/// a row parallel to it, is handed over whole as [`Run::Matte`], without rays: the point
/// where a ray meets a plane needs only the direction towards the pixel, not the unit one
/// (`Plane::intersect`), and shading a matte surface needs neither
/// ([`Scene::shade_matte_run`]).
///
/// Both are handed `target`, what they draw into. The runs and the pixels come to two
/// closures, not one: the pixels' is then called from the run loop alone, where the compiler
/// can take its shading in line.
#[allow(clippy::too_many_arguments)]
fn cast_row<T: ?Sized, const N: usize, const L: usize, C: Names>(
    scene: &Scene<N, L>,
    camera: &Camera,
    runs: &mut Runs<'_, N, L, C>,
    (cols, shift): (Range<u16>, u32),
    (skip_empty, matte): (bool, bool),
    target: &mut T,
    mut whole: impl FnMut(&mut T, u16, u16, Run<'_>, &[u32; L]),
    mut each: impl FnMut(&mut T, u16, &Ray, Option<SceneHit>, &[u32; L]),
) {
    let start = cols.start;
    runs.limit(cols);
    let shadowers = *runs.shadowers();
    // The walk's step, `2^shift` columns: the row's, for every run.
    let step = camera.column_step().steps(1 << shift);
    while let Some((first_col, end_col, here)) = runs.next_run() {
        let index = |c: u16| ((u32::from(c - start) + (1 << shift) - 1) >> shift) as u16;
        let (first, end) = (index(first_col), index(end_col));
        if first == end {
            continue;
        }
        let col = start + (first << shift);
        if runs.is_empty(here) && skip_empty {
            whole(target, first, end, Run::Empty, &shadowers);
            continue;
        }
        let eye = runs.eye();
        // A run that can meet one object only (the open ground, most often) asks it alone:
        // the nearest of one is that one, and the loop has no set of objects to walk.
        let one = runs.only(here);
        if let Some(index) = one
            && matte
            && let Some(plane) = matte_plane(scene, index)
            && plane.normal().dot_wide_exact(camera.column_step()) == 0
        {
            let num = eye.numerator(index);
            let towards = runs.towards(col);
            let run = MatteRun {
                plane,
                index,
                num,
                towards,
                step,
            };
            whole(target, first, end, Run::Matte(&run), &shadowers);
            continue;
        }
        let shoot = |ray: &Ray| match one {
            Some(index) => scene.shoot_one_from_eye(ray, index, eye),
            None => scene.shoot_from_eye(ray, here, eye),
        };
        cast_run(
            camera,
            runs.towards(col),
            step,
            first..end,
            shoot,
            |i, ray, hit| each(target, i, ray, hit, &shadowers),
        );
    }
}

/// Object `index` as a plane, if it is one whose surface is all there is to see: no
/// highlight, no mirror, no refraction.
fn matte_plane<const N: usize, const L: usize>(scene: &Scene<N, L>, index: usize) -> Option<Plane> {
    let object = scene.objects().get(index)?;
    let material = &object.material;
    match object.shape {
        Shape::Plane(plane) if material.is_plain_matte() => Some(plane),
        _ => None,
    }
}

/// The rays of columns `cols` of a run, the first along `towards`, each shot by `shoot` and
/// handed to `each` as [`cast_row`] does.
fn cast_run(
    camera: &Camera,
    towards: Vec3,
    step: Vec3,
    cols: Range<u16>,
    shoot: impl Fn(&Ray) -> Option<SceneHit>,
    mut each: impl FnMut(u16, &Ray, Option<SceneHit>),
) {
    let mut rays = RowRays::stepping(camera, towards, step, cols.len() as u16);
    for col in cols {
        let ray = rays.advance();
        let hit = shoot(&ray);
        each(col, &ray, hit);
    }
}

/// [`render_row`] with `n × n` supersampling: each pixel is the mean of `n²` rays through
/// a grid of sub-pixel centres ([`Camera::sample_ray`]), each channel rounded half up.
/// `n` is clamped to 1..=16; `n = 1` equals [`render_row`]. It costs `n²` times as much, so
/// it is meant for the desktop and for still frames. The row and `out` are checked as by
/// [`render_row`].
///
/// ```
/// use fixray::{demo, render_row, render_row_supersampled, Rgb};
/// let (scene, camera) = (demo::scene(), demo::camera(32, 24).unwrap());
/// let (mut plain, mut smooth) = ([Rgb::BLACK; 32], [Rgb::BLACK; 32]);
/// render_row(&scene, &camera, 12, &mut plain).unwrap();
/// render_row_supersampled(&scene, &camera, 12, 1, &mut smooth).unwrap();
/// assert_eq!(plain, smooth);
/// ```
pub fn render_row_supersampled<const N: usize, const L: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
    y: u32,
    n: u8,
    out: &mut [Rgb],
) -> Result<(), Error> {
    check_row(camera, y, out)?;
    let n = n.clamp(1, 16);
    let count = n as u32 * n as u32;
    for (x, pixel) in (0..).zip(out.iter_mut()) {
        let mut sum = [0u32; 3];
        for sy in 0..n {
            for sx in 0..n {
                let c = scene.trace(&camera.sample_ray(x, y, sx, sy, n));
                sum[0] += c.r as u32;
                sum[1] += c.g as u32;
                sum[2] += c.b as u32;
            }
        }
        let mean = |s: u32| ((s + count / 2) / count) as u8;
        *pixel = Rgb::new(mean(sum[0]), mean(sum[1]), mean(sum[2]));
    }
    Ok(())
}

/// Refuses a row outside the screen ([`Error::RowOutOfRange`]), then a row buffer that is
/// not exactly one row long ([`Error::BufferLength`]). The row comes back as the render path
/// counts rows.
fn check_row(camera: &Camera, y: u32, out: &[Rgb]) -> Result<u16, Error> {
    let row = camera.check_row(y)?;
    let needed = usize::from(camera.cols());
    if out.len() != needed {
        return Err(Error::BufferLength {
            needed,
            got: out.len(),
        });
    }
    Ok(row)
}

/// Renders the whole frame into `frame`, whose size must equal the camera's.
///
/// ```
/// use fixray::{demo, render, Framebuffer};
/// let mut frame = Framebuffer::<32, 24>::new();
/// render(&demo::scene(), &demo::camera(32, 24).unwrap(), &mut frame).unwrap();
/// // The wrong size is an error, not a panic.
/// assert!(render(&demo::scene(), &demo::camera(16, 16).unwrap(), &mut frame).is_err());
/// ```
pub fn render<const N: usize, const L: usize, const W: usize, const H: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
    frame: &mut Framebuffer<W, H>,
) -> Result<(), Error> {
    check_size::<W, H>(camera)?;
    if N > 32 {
        // The rows share what they find of the spheres' shadowers.
        let spheres = &mut SphereShadowers::<L, FRAME_SLOTS>::new();
        for (y, pixels) in (0..).zip(frame.rows_mut().iter_mut()) {
            let row = check_row(camera, y, pixels)?;
            crowded_every(
                scene,
                camera,
                row,
                &[(0..camera.cols(), 0)],
                pixels,
                spheres,
            );
        }
        return Ok(());
    }
    for (y, pixels) in (0..).zip(frame.rows_mut().iter_mut()) {
        render_row(scene, camera, y, pixels)?;
    }
    Ok(())
}

/// Refuses a frame of `W × H` pixels for a camera of another size ([`Error::SizeMismatch`]).
pub(crate) fn check_size<const W: usize, const H: usize>(camera: &Camera) -> Result<(), Error> {
    if (camera.cols() as usize, camera.rows() as usize) != (W, H) {
        return Err(Error::SizeMismatch {
            camera: (camera.cols(), camera.rows()),
            target: (
                W.min(u16::MAX as usize) as u16,
                H.min(u16::MAX as usize) as u16,
            ),
        });
    }
    Ok(())
}
