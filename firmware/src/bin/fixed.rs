//! The demo scene by fixray's Q16.16 renderer: integer arithmetic only.

#![no_std]
#![no_main]

use fixray::{Camera, Error, Rgb, Scene, demo};
use fixray_firmware::Renderer;

struct Fixed {
    scene: Scene<8>,
    camera: Camera,
}

impl Renderer for Fixed {
    const NAME: &'static str = "fixed";
    type Error = Error;

    fn new(cols: u16, rows: u16) -> Result<Self, Error> {
        Ok(Fixed {
            scene: demo::scene(),
            camera: demo::camera(cols, rows)?,
        })
    }

    fn render_row(&self, row: u16, out: &mut [Rgb]) -> Result<(), Error> {
        fixray::render_row(&self.scene, &self.camera, row, out)
    }
}

#[cfg_attr(target_arch = "arm", cortex_m_rt::entry)]
#[cfg_attr(target_arch = "riscv32", riscv_rt::entry)]
fn main() -> ! {
    fixray_firmware::run::<Fixed>()
}
