//! fixray on an ESP32-C3: the demo scene on a 240 × 135 ST7789 display through esp-hal's SPI
//! and mipidsi, then the frame time in the corner and on the serial console.
//!
//! The ESP32-C3 has one RV32IMC core and no FPU, the chip fixray is made for. The picture is
//! drawn by fixray's `Viewport` with a buffer of `BAND_ROWS` rows: it renders a band with
//! `render_row`, then sends it in one `fill_contiguous` (one address window on the display),
//! converted to `Rgb565`.
//!
//! Then the camera orbits the scene slowly, each view drawn in progressive passes (`Pass`):
//! every 8th pixel of every 8th row first, in 8 × 8 blocks, at once, then finer passes down
//! to single pixels, which end on the very picture `render` draws. The times to the first
//! picture and to the whole go to the serial console.

#![no_std]
#![no_main]
#![deny(unsafe_code)]

use core::fmt::Write;

use embedded_graphics::mono_font::{MonoTextStyleBuilder, ascii::FONT_6X10};
use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::text::{Baseline, Text};
use embedded_hal_bus::spi::ExclusiveDevice;
use esp_backtrace as _;
use esp_hal::clock::CpuClock;
use esp_hal::delay::Delay;
use esp_hal::gpio::{Level, Output, OutputConfig};
use esp_hal::spi::Mode;
use esp_hal::spi::master::{Config, Spi};
use esp_hal::time::{Instant, Rate};
use fixray::{Camera, FromRgb, Pass, Rgb, Scene, Viewport, demo};
use mipidsi::Builder;
use mipidsi::interface::SpiInterface;
use mipidsi::models::ST7789;
use mipidsi::options::{ColorInversion, Orientation, Rotation};

esp_bootloader_esp_idf::esp_app_desc!();

/// The display in landscape: the 1.14" 240 × 135 ST7789 module (sold as "1.14 inch IPS").
/// For a 320 × 240 module see the README.
const WIDTH: usize = 240;
const HEIGHT: usize = 135;

/// Rows per band: 16 rows are 11.5 KB of `Rgb` on the stack, and 9 bus transfers a frame.
const BAND_ROWS: usize = 16;

/// The scene is built by the compiler and sits in flash.
static SCENE: Scene<8> = demo::scene();

/// The orbit: about the middle of the demo's spheres, at the distance from which, at yaw 0
/// and pitch 0, it sees what the demo camera sees; a little above the floor, a few degrees a
/// view.
const TARGET: [f32; 3] = [0.0, 0.0, -15.0];
const DISTANCE: f32 = 15.0;
const PITCH_DEGREES: f32 = 10.0;
const YAW_STEP_DEGREES: u32 = 3;

/// The first pass's spacing: 1/64 of the pixels, a picture at once.
const COARSEST: u16 = 8;

#[esp_hal::main]
fn main() -> ! {
    // The fastest clock, 160 MHz: the frame time scales with it.
    let peripherals = esp_hal::init(esp_hal::Config::default().with_cpu_clock(CpuClock::max()));
    let mut delay = Delay::new();

    // The display on SPI2 (README: the wiring table). 40 MHz is the fastest the GPIO matrix
    // carries; the ST7789 takes up to 62.5 MHz.
    let spi = Spi::new(
        peripherals.SPI2,
        Config::default()
            .with_frequency(Rate::from_mhz(40))
            .with_mode(Mode::_0),
    )
    .unwrap()
    .with_sck(peripherals.GPIO6)
    .with_mosi(peripherals.GPIO7);
    let cs = Output::new(peripherals.GPIO10, Level::High, OutputConfig::default());
    let dc = Output::new(peripherals.GPIO4, Level::Low, OutputConfig::default());
    let _backlight = Output::new(peripherals.GPIO5, Level::High, OutputConfig::default());
    let spi = ExclusiveDevice::new_no_delay(spi, cs).unwrap();
    let mut spi_buffer = [0u8; 512];
    let interface = SpiInterface::new(spi, dc, &mut spi_buffer);
    // The panel's controller is 240 × 320; this module shows 135 × 240 of it from column 52,
    // row 40, and is turned a quarter for landscape. IPS panels need their colours inverted.
    let mut display = Builder::new(ST7789, interface)
        .display_size(135, 240)
        .display_offset(52, 40)
        .orientation(Orientation::new().rotate(Rotation::Deg90))
        .invert_colors(ColorInversion::Inverted)
        .init(&mut delay)
        .unwrap();

    // The camera is the display's size, the picture at its top left corner.
    let camera = demo::camera(WIDTH as u32, HEIGHT as u32).unwrap();
    let view = Viewport::at(&SCENE, &camera, Point::zero());
    let mut band = [Rgb::BLACK; WIDTH * BAND_ROWS];

    let start = Instant::now();
    view.render(&mut band, &mut display).unwrap();
    let elapsed = start.elapsed().as_millis();

    esp_println::println!("fixray: demo scene, {WIDTH} x {HEIGHT}, {elapsed} ms");
    // The frame time, rendering and sending included, over the sky in the top left corner.
    // A line of text formatted without an allocator.
    let mut text = heapless::String::<32>::new();
    let _ = write!(text, "{elapsed} ms");
    let style = MonoTextStyleBuilder::new()
        .font(&FONT_6X10)
        .text_color(Rgb565::BLACK)
        .background_color(Rgb565::from_rgb(demo::BACKGROUND, Point::zero()))
        .build();
    Text::with_baseline(text.as_str(), Point::new(2, 2), style, Baseline::Top)
        .draw(&mut display)
        .unwrap();

    delay.delay_millis(2000);

    // The orbit. Only the camera's set-up uses floats (soft-float here, once a view); the
    // passes are fixed point throughout.
    let mut yaw = 0;
    loop {
        yaw = (yaw + YAW_STEP_DEGREES) % 360;
        let Ok(camera) = Camera::orbit(TARGET, DISTANCE)
            .yaw_degrees(yaw as f32)
            .pitch_degrees(PITCH_DEGREES)
            .size(Size::new(WIDTH as u32, HEIGHT as u32))
            .build()
        else {
            continue;
        };
        let view = Viewport::at(&SCENE, &camera, Point::zero());
        let start = Instant::now();
        let mut first = 0;
        for pass in Pass::sequence(COARSEST).unwrap() {
            view.render_pass(pass, &mut band, &mut display).unwrap();
            if pass.is_first() {
                first = start.elapsed().as_millis();
            }
        }
        let whole = start.elapsed().as_millis();
        esp_println::println!(
            "fixray: orbit at {yaw} degrees, first picture {first} ms, whole {whole} ms"
        );
    }
}
