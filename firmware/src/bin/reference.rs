//! The demo scene by fixray's f64 reference model: `libm` and the compiler's soft-float
//! routines on every one of these chips (the Cortex-M4F's FPU does single precision only).

#![no_std]
#![no_main]

use fixray::reference::{self, DCamera, DScene};
use fixray::{Rgb, demo};
use fixray_firmware::Renderer;

struct Reference {
    scene: DScene<8>,
    camera: DCamera,
}

impl Renderer for Reference {
    const NAME: &'static str = "reference-f64";
    type Error = &'static str;

    fn new(cols: u16, rows: u16) -> Result<Self, Self::Error> {
        let scene = DScene::from_scene(&demo::scene()).ok_or("the demo scene has no f64 twin")?;
        // The demo camera in f64: the same screen as `demo::camera`, from the same constants.
        let h = f64::from(demo::SCREEN_HEIGHT);
        let w = h * f64::from(cols) / f64::from(rows);
        let z_p = f64::from(demo::SCREEN_DISTANCE);
        let camera = DCamera::pinhole(w, h, z_p, rows, cols).ok_or("a degenerate camera")?;
        Ok(Reference { scene, camera })
    }

    fn render_row(&self, row: u16, out: &mut [Rgb]) -> Result<(), Self::Error> {
        reference::render_row(&self.scene, &self.camera, row, out);
        Ok(())
    }
}

#[cfg_attr(target_arch = "arm", cortex_m_rt::entry)]
#[cfg_attr(target_arch = "riscv32", riscv_rt::entry)]
fn main() -> ! {
    fixray_firmware::run::<Reference>()
}
