//! What the firmware renders: the [`Variant`]s of the scene, and the [`Renderer`]s that draw
//! them — fixray's Q16.16 renderer ([`Fixed`]) and its reference model in `f64` or `f32`
//! ([`Reference`]).
//!
//! This file uses only `fixray` and its reference model, `fixray-reference`, so the host
//! compiles it too: `examples/frame_hash.rs` includes it (`#[path]`) and hashes the very frames
//! the chips render, built by the same code, for `scripts/firmware.sh` to compare.

use core::fmt::Debug;

use fixray::{Camera, Error, Rgb, Scene, demo};
use fixray_reference::{self as reference, DCamera, DScene, Real};

/// Columns of the frame (its width).
pub const COLS: u32 = 160;
/// Rows of the frame (its height).
pub const ROWS: u32 = 128;

/// A scene and its camera, as the figures table names them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Variant {
    /// `demo::scene()` (four matte spheres, a ground plane, one light, shadows) through
    /// `demo::camera`, the chapter's pinhole camera.
    Demo,
    #[cfg(feature = "mirrors-and-glass")]
    /// `demo::classic()` (highlights, three lights, shadows, mirrors, a checkerboard floor)
    /// through `demo::classic_camera`, a look-at camera with a 60° field of view.
    Classic,
    /// The demo scene without shadow rays: against `Demo`, what its shadows cost.
    DemoNoShadow,
    #[cfg(feature = "mirrors-and-glass")]
    /// The classic scene without shadow rays: what shadows cost.
    ClassicNoShadow,
    #[cfg(feature = "mirrors-and-glass")]
    /// The classic scene with every material's `reflect` set to 0: what mirrors cost.
    ///
    /// Not `set_depth(0)`: at depth 0 a mirror still adds the sky along its mirror ray.
    ClassicNoMirror,
    #[cfg(feature = "mirrors-and-glass")]
    /// `demo::classic_opaque()`: the classic scene with its glass not refracting, what
    /// refraction costs.
    ClassicOpaque,
}

impl Variant {
    /// All of them in this build: the classic scene's only with `mirrors-and-glass`.
    pub const ALL: &[Variant] = &[
        Variant::Demo,
        Variant::DemoNoShadow,
        #[cfg(feature = "mirrors-and-glass")]
        Variant::Classic,
        #[cfg(feature = "mirrors-and-glass")]
        Variant::ClassicNoShadow,
        #[cfg(feature = "mirrors-and-glass")]
        Variant::ClassicNoMirror,
        #[cfg(feature = "mirrors-and-glass")]
        Variant::ClassicOpaque,
    ];

    /// What follows the renderer's name in the table: `fixed-classic-noshadow`, say.
    #[must_use]
    pub const fn suffix(self) -> &'static str {
        match self {
            Variant::Demo => "",
            Variant::DemoNoShadow => "-noshadow",
            #[cfg(feature = "mirrors-and-glass")]
            Variant::Classic => "-classic",
            #[cfg(feature = "mirrors-and-glass")]
            Variant::ClassicNoShadow => "-classic-noshadow",
            #[cfg(feature = "mirrors-and-glass")]
            Variant::ClassicNoMirror => "-classic-nomirror",
            #[cfg(feature = "mirrors-and-glass")]
            Variant::ClassicOpaque => "-classic-opaque",
        }
    }

    /// The fixed-point scene, a `static` the compiler built: in flash, as a user's scene on a
    /// microcontroller would be, so that drawing it takes no RAM for the scene.
    #[must_use]
    pub fn scene(self) -> &'static Scene<8> {
        const fn without_shadows(mut scene: Scene<8>) -> Scene<8> {
            scene.set_shadows(false);
            scene
        }
        static DEMO: Scene<8> = demo::scene();
        static DEMO_NOSHADOW: Scene<8> = without_shadows(demo::scene());
        #[cfg(feature = "mirrors-and-glass")]
        static CLASSIC: Scene<8> = demo::classic();
        #[cfg(feature = "mirrors-and-glass")]
        static CLASSIC_NOSHADOW: Scene<8> = without_shadows(demo::classic());
        #[cfg(feature = "mirrors-and-glass")]
        static CLASSIC_NOMIRROR: Scene<8> = demo::classic_without_mirrors();
        #[cfg(feature = "mirrors-and-glass")]
        static CLASSIC_OPAQUE: Scene<8> = demo::classic_opaque();
        match self {
            Variant::Demo => &DEMO,
            Variant::DemoNoShadow => &DEMO_NOSHADOW,
            #[cfg(feature = "mirrors-and-glass")]
            Variant::Classic => &CLASSIC,
            #[cfg(feature = "mirrors-and-glass")]
            Variant::ClassicNoShadow => &CLASSIC_NOSHADOW,
            #[cfg(feature = "mirrors-and-glass")]
            Variant::ClassicNoMirror => &CLASSIC_NOMIRROR,
            #[cfg(feature = "mirrors-and-glass")]
            Variant::ClassicOpaque => &CLASSIC_OPAQUE,
        }
    }

    /// The fixed-point camera for a `cols × rows` frame.
    pub fn camera(self, cols: u32, rows: u32) -> Result<Camera, Error> {
        match self {
            Variant::Demo | Variant::DemoNoShadow => demo::camera(cols, rows),
            #[cfg(feature = "mirrors-and-glass")]
            _ => demo::classic_camera(cols, rows),
        }
    }

    /// The same camera in the reference model, from the same `f32` constants, in `F`.
    #[must_use]
    pub fn dcamera<F: Real>(self, cols: u32, rows: u32) -> Option<DCamera<F>> {
        match self {
            Variant::Demo | Variant::DemoNoShadow => reference::demo_camera(cols, rows),
            #[cfg(feature = "mirrors-and-glass")]
            _ => reference::classic_camera(cols, rows),
        }
    }
}

/// A renderer the firmware can measure: built for a scene, then asked for one row at a time,
/// so a frame never has to fit in RAM.
pub trait Renderer: Sized {
    /// Its name in the report and the script's table, before the variant's suffix.
    const NAME: &'static str;
    /// Why it refused: `Copy`, so that the harness can report it from a borrowed `Result`.
    type Error: Debug + Copy;

    /// Sets up `variant` for a `cols × rows` frame.
    fn new(variant: Variant, cols: u32, rows: u32) -> Result<Self, Self::Error>;

    /// Renders row `row` (0 at the top) into `out`, `cols` pixels long.
    fn render_row(&self, row: u32, out: &mut [Rgb]) -> Result<(), Self::Error>;
}

/// fixray's Q16.16 renderer: integer arithmetic only.
pub struct Fixed {
    scene: &'static Scene<8>,
    camera: Camera,
}

impl Renderer for Fixed {
    const NAME: &'static str = "fixed";
    type Error = Error;

    fn new(variant: Variant, cols: u32, rows: u32) -> Result<Self, Error> {
        Ok(Fixed {
            scene: variant.scene(),
            camera: variant.camera(cols, rows)?,
        })
    }

    fn render_row(&self, row: u32, out: &mut [Rgb]) -> Result<(), Error> {
        fixray::render_row(self.scene, &self.camera, row, out)
    }
}

/// [`Fixed`] with `render_row` a call of its own, not in line in the harness's loop: its
/// symbol is where `scripts/stack_bound.py` starts the static stack bound from `render_row`
/// down. Its frames are `Fixed`'s; the measured figures are `Fixed`'s, whose row the compiler
/// may specialise for the `static` scene, as it may in a user's loop.
pub struct FixedCall(Fixed);

impl Renderer for FixedCall {
    const NAME: &'static str = "fixed";
    type Error = Error;

    fn new(variant: Variant, cols: u32, rows: u32) -> Result<Self, Error> {
        Fixed::new(variant, cols, rows).map(FixedCall)
    }

    #[inline(never)]
    fn render_row(&self, row: u32, out: &mut [Rgb]) -> Result<(), Error> {
        self.0.render_row(row, out)
    }
}

/// Runs of sky a row of [`FixedRays`] skips, at most this many.
const SKIPS: usize = 4;

/// The first stage of [`Fixed`] alone, for the profile: the rays `render_row` makes, as
/// [`Camera::row_rays`] (the rays of [`fixray::shoot_row`]) without those of the runs of sky
/// that `render_row` paints without rays, written out as the bytes of their directions so
/// that nothing is optimised away. The runs are found when it is made, not while measured.
pub struct FixedRays {
    camera: Camera,
    /// For each row, the runs of columns `render_row` makes no rays for, as `u16` (a screen is
    /// at most 4096 wide) to keep the table small on a 16 KiB chip.
    skips: [[(u16, u16); SKIPS]; ROWS as usize],
}

impl Renderer for FixedRays {
    const NAME: &'static str = "fixed-rays";
    type Error = Error;

    fn new(variant: Variant, cols: u32, rows: u32) -> Result<Self, Error> {
        let (scene, camera) = (variant.scene(), variant.camera(cols, rows)?);
        let width = u16::try_from(cols).map_err(|_| Error::CapacityExceeded { capacity: 4096 })?;
        let mut skips = [[(width, width); SKIPS]; ROWS as usize];
        let too_many = Error::CapacityExceeded { capacity: SKIPS };
        for (row, runs) in (0..rows).zip(skips.iter_mut()) {
            let mut count = 0;
            fixray::internals::shoot_row_skipping(
                scene,
                &camera,
                row,
                |run| {
                    if let Some(slot) = runs.get_mut(count) {
                        // Runs lie within the row, which fits u16.
                        *slot = (run.start as u16, run.end as u16);
                    }
                    count += 1;
                },
                |_, _, _| {},
            )?;
            if count > SKIPS {
                return Err(too_many);
            }
        }
        if rows > ROWS {
            return Err(too_many);
        }
        Ok(FixedRays { camera, skips })
    }

    fn render_row(&self, row: u32, out: &mut [Rgb]) -> Result<(), Error> {
        let mut rays = self.camera.row_rays(row)?;
        let mut col = 0u32;
        let skips = self.skips.get(row as usize).into_iter().flatten();
        let width = self.camera.width();
        let runs = skips.map(|&(first, end)| (u32::from(first), u32::from(end)));
        for (first, end) in runs.chain([(width, width)]) {
            while col < first {
                let Some(ray) = rays.next() else { break };
                if let Some(pixel) = out.get_mut(col as usize) {
                    let dir = ray.dir();
                    *pixel = Rgb::new(
                        dir.x.to_bits() as u8,
                        dir.y.to_bits() as u8,
                        dir.z.to_bits() as u8,
                    );
                }
                col += 1;
            }
            if end > first {
                // Past the run: `nth` passes all but its last ray unmade, and makes that one.
                rays.nth((end - first - 1) as usize);
                col = end;
            }
        }
        Ok(())
    }
}

/// The first two stages of [`Fixed`], for the profile: the rays and their nearest hits as
/// `render_row` makes them ([`fixray::shoot_row_skipping`], culling and runs of sky included),
/// written out as the hit's object and distance.
pub struct FixedShoot {
    scene: &'static Scene<8>,
    camera: Camera,
}

impl Renderer for FixedShoot {
    const NAME: &'static str = "fixed-shoot";
    type Error = Error;

    fn new(variant: Variant, cols: u32, rows: u32) -> Result<Self, Error> {
        Ok(FixedShoot {
            scene: variant.scene(),
            camera: variant.camera(cols, rows)?,
        })
    }

    fn render_row(&self, row: u32, out: &mut [Rgb]) -> Result<(), Error> {
        let (scene, camera) = (self.scene, &self.camera);
        let mut empty = [(0u32, 0u32); SKIPS];
        let mut count = 0;
        fixray::internals::shoot_row_skipping(
            scene,
            camera,
            row,
            |run| {
                if let Some(slot) = empty.get_mut(count) {
                    *slot = (run.start, run.end);
                }
                count += 1;
            },
            |col, _, hit| {
                if let (Some(pixel), Some(hit)) = (out.get_mut(col as usize), hit) {
                    let t = hit.hit().t().to_bits();
                    *pixel = Rgb::new(hit.object() as u8, (t >> 8) as u8, t as u8);
                } else if let Some(pixel) = out.get_mut(col as usize) {
                    *pixel = Rgb::BLACK;
                }
            },
        )?;
        for &(first, end) in empty.iter().take(count) {
            if let Some(run) = out.get_mut(first as usize..end as usize) {
                run.fill(Rgb::WHITE);
            }
        }
        Ok(())
    }
}

/// fixray's reference model in `F`: `f64`, or `f32` as the float baseline. On the Cortex-M0
/// and RV32IMC both are the compiler's soft-float routines; on the Cortex-M4F `f32` is the
/// FPU's (but for `libm`'s `sqrtf`, `tanf`, `roundf`, `floorf`, `fmodf` and `powf`, which are
/// software on every chip) and `f64` soft-float.
pub struct Reference<F: Real> {
    scene: DScene<8, 4, F>,
    camera: DCamera<F>,
}

impl<F: Real> Renderer for Reference<F> {
    // `Real` is `f64` or `f32` only: told apart by size.
    const NAME: &'static str = if size_of::<F>() == size_of::<f64>() {
        "reference-f64"
    } else {
        "reference-f32"
    };
    type Error = &'static str;

    fn new(variant: Variant, cols: u32, rows: u32) -> Result<Self, Self::Error> {
        Ok(Reference {
            scene: DScene::from_scene(variant.scene()).ok_or("the scene has no reference twin")?,
            camera: variant.dcamera(cols, rows).ok_or("a degenerate camera")?,
        })
    }

    fn render_row(&self, row: u32, out: &mut [Rgb]) -> Result<(), Self::Error> {
        reference::render_row(&self.scene, &self.camera, row, out);
        Ok(())
    }
}
