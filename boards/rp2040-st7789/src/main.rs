//! fixray on a Raspberry Pi Pico: the demo scene on a 240 × 135 ST7789 display, rendered by
//! both of the RP2040's Cortex-M0+ cores, then the frame time in the corner, then a slow orbit
//! of the camera in progressive passes.
//!
//! The picture is cut into bands of `BAND_ROWS` rows. Core 0 renders the even bands, core 1
//! the odd ones, each with `fixray::render_row` into a band buffer of `Rgb` rows; core 0 sends
//! every band to the display in order, converted to `Rgb565` on the way. The sending is by
//! DMA (`dma_interface`): core 0 packs a band's bytes into a DMA buffer, starts the transfer
//! and goes back to rendering while the band is on the wire. It waits for the wire only when
//! the next band's address window is due before the last transfer has ended (a band spends
//! far less time on the wire than in rendering: the README has the figures).
//!
//! Core 1's two buffers travel between the cores through four one-buffer slots (one per
//! buffer for "rendered", one per buffer for "sent"), each a `critical_section::Mutex`, so
//! the hand-over is safe Rust: a buffer is always owned by exactly one core. A core waiting
//! for a slot sleeps in `wfe`; the other core's `sev` after filling one wakes it. A band is
//! packed into the DMA buffer as it is sent, so core 1 gets its buffer back at once.
//!
//! With the `single-core` feature core 0 renders every band itself and core 1 is never
//! started; the bands, the DMA interface and the driver are the same. That is the build
//! scripts/pico.sh runs in an emulator with one core and checks pixel for pixel.
//!
//! After a pause the camera circles the scene. Core 0 alone draws each new view as a
//! progressive render (`Pass`): a coarse pass of 8 × 8 blocks fills the display quickly, and
//! three finer ones sharpen it until it matches a full render of that view. The blocks go to
//! the display through the same driver: in the finer passes a row of blocks that tile their
//! band (the odd rows, half the even ones, every other row of the grid of 4) is one fill of
//! the whole band, one address window;
//! every other block, the first pass's included, is a fill of its own. None of it fills a
//! DMA buffer, so the CPU writes it. Core 1, if started, sleeps once its share of the first
//! frame is done.

#![no_std]
#![no_main]
#![deny(unsafe_code)]

#[cfg(not(feature = "single-core"))]
use core::cell::RefCell;
use core::fmt::Write;

#[cfg(not(feature = "single-core"))]
use critical_section::Mutex;
use embedded_graphics::mono_font::{MonoTextStyleBuilder, ascii::FONT_6X10};
use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use embedded_graphics::text::{Baseline, Text};
use embedded_hal::delay::DelayNs;
use fixray::{Camera, DrawError, FromRgb, Pass, Rgb, Scene, Viewport, demo, render_row};
use mipidsi::Builder;
use mipidsi::models::ST7789;
use mipidsi::options::{ColorInversion, Orientation, Rotation};
use panic_halt as _;
use rp2040_hal::dma::DMAExt;
use rp2040_hal::fugit::RateExtU32;
use rp2040_hal::gpio::{FunctionSpi, PinState};
#[cfg(not(feature = "single-core"))]
use rp2040_hal::multicore::{Multicore, Stack};
use rp2040_hal::{Sio, Timer, Watchdog, pac};

mod dma_interface;
use dma_interface::DmaInterface;

/// The second-stage boot loader for the Pico's W25Q080 flash, at the start of flash.
#[allow(unsafe_code)] // placing a static in a linker section is an unsafe attribute
#[unsafe(link_section = ".boot2")]
#[used]
static BOOT2: [u8; 256] = rp2040_boot2::BOOT_LOADER_W25Q080;

/// The Pico's crystal.
const XTAL_HZ: u32 = 12_000_000;

/// The display in landscape: the 1.14" 240 × 135 ST7789 module (Pimoroni's Pico Display Pack,
/// and the bare modules sold as "1.14 inch IPS"). For a 320 × 240 module see the README.
const WIDTH: usize = 240;
const HEIGHT: usize = 135;

/// Rows per band: small bands keep the two cores' shares even (27 bands, 14 and 13) and the
/// buffers small (3 × 3 600 bytes of `Rgb`, 2 × 2 400 of `Rgb565` for the DMA). A band is one
/// DMA transfer only if every band is full, so the band divides the height.
const BAND_ROWS: usize = 5;
const BANDS: usize = HEIGHT / BAND_ROWS;
const _: () = assert!(
    HEIGHT.is_multiple_of(BAND_ROWS),
    "a band's rows must divide the height"
);

/// A band's bytes on the wire: two per `Rgb565` pixel.
const BAND_BYTES: usize = WIDTH * BAND_ROWS * 2;

/// A band of rendered rows, fixray's 3-byte colours.
type Band = [Rgb; WIDTH * BAND_ROWS];

/// The scene is built by the compiler and sits in flash; both cores read it.
static SCENE: Scene<8> = demo::scene();

/// The first frame and its time stay on the display this long, so the time can be read.
const PAUSE_MS: u32 = 2000;

/// The circle the eye follows, the same as the ESP32-C3 program's: centred near the middle of
/// the demo's spheres and 15 units from it, so that at yaw 0 and pitch 0 the eye is where the
/// demo camera is, looking the same way; raised 10° to look down on the floor a little, and
/// turned 3° further for each view.
const TARGET: [f32; 3] = [0.0, 0.0, -15.0];
const DISTANCE: f32 = 15.0;
const PITCH_DEGREES: f32 = 10.0;
const YAW_STEP_DEGREES: u32 = 3;

/// The coarsest pass's block side: it traces one pixel in 64, so a whole, blocky view shows
/// after a small fraction of a frame's work.
const COARSEST: u16 = 8;

/// Core 1's stack: 16 KiB (a render takes well under 8 KiB on a Cortex-M0).
#[cfg(not(feature = "single-core"))]
static CORE1_STACK: Stack<4096> = Stack::new();

/// A place one core leaves one of core 1's buffers for the other core to take.
#[cfg(not(feature = "single-core"))]
type Slot = Mutex<RefCell<Option<&'static mut Band>>>;

/// Core 1's band buffers, rendered and waiting to be sent; slot `i % 2` for its `i`-th band.
#[cfg(not(feature = "single-core"))]
static RENDERED: [Slot; 2] = [const { Mutex::new(RefCell::new(None)) }; 2];
/// The same buffers, sent and free again.
#[cfg(not(feature = "single-core"))]
static SENT: [Slot; 2] = [const { Mutex::new(RefCell::new(None)) }; 2];

#[rp2040_hal::entry]
fn main() -> ! {
    let mut pac = pac::Peripherals::take().unwrap();
    let mut watchdog = Watchdog::new(pac.WATCHDOG);
    // 125 MHz system clock from the 12 MHz crystal; the peripheral clock (SPI) is the same.
    let clocks = rp2040_hal::clocks::init_clocks_and_plls(
        XTAL_HZ,
        pac.XOSC,
        pac.CLOCKS,
        pac.PLL_SYS,
        pac.PLL_USB,
        &mut pac.RESETS,
        &mut watchdog,
    )
    .ok()
    .unwrap();
    let sio = Sio::new(pac.SIO);
    let pins = rp2040_hal::gpio::Pins::new(
        pac.IO_BANK0,
        pac.PADS_BANK0,
        sio.gpio_bank0,
        &mut pac.RESETS,
    );
    let mut timer = Timer::new(pac.TIMER, &mut pac.RESETS, &clocks);

    // The display on SPI0, wired as on the Pico Display Pack (README: the wiring table).
    let sck = pins.gpio18.into_function::<FunctionSpi>();
    let mosi = pins.gpio19.into_function::<FunctionSpi>();
    let cs = pins.gpio17.into_push_pull_output_in_state(PinState::High);
    let dc = pins.gpio16.into_push_pull_output();
    let _backlight = pins.gpio20.into_push_pull_output_in_state(PinState::High);
    let spi = rp2040_hal::spi::Spi::<_, _, _, 8>::new(pac.SPI0, (mosi, sck)).init(
        &mut pac.RESETS,
        125.MHz(),
        // The ST7789's fastest write clock (16 ns a bit); halve it for long jumper wires.
        62_500.kHz(),
        embedded_hal::spi::MODE_0,
    );
    let dma = pac.DMA.split(&mut pac.RESETS);
    let wire = [
        cortex_m::singleton!(: [u8; BAND_BYTES] = [0; BAND_BYTES]).unwrap(),
        cortex_m::singleton!(: [u8; BAND_BYTES] = [0; BAND_BYTES]).unwrap(),
    ];
    let interface = DmaInterface::new(dma.ch0, spi, dc, cs, wire);
    // The panel's controller is 240 × 320; this module shows 135 × 240 of it from column 52,
    // row 40, and is turned a quarter for landscape. IPS panels need their colours inverted.
    let mut display = Builder::new(ST7789, interface)
        .display_size(135, 240)
        .display_offset(52, 40)
        .orientation(Orientation::new().rotate(Rotation::Deg90))
        .invert_colors(ColorInversion::Inverted)
        .init(&mut timer)
        .unwrap();

    // The camera is the display's size. `Camera` is `Copy`: core 1 gets its own.
    let camera = demo::camera(WIDTH as u32, HEIGHT as u32).unwrap();
    let own = cortex_m::singleton!(: Band = [Rgb::BLACK; WIDTH * BAND_ROWS]).unwrap();

    #[cfg(not(feature = "single-core"))]
    let start = {
        let core1_buffers = [
            cortex_m::singleton!(: Band = [Rgb::BLACK; WIDTH * BAND_ROWS]).unwrap(),
            cortex_m::singleton!(: Band = [Rgb::BLACK; WIDTH * BAND_ROWS]).unwrap(),
        ];
        let start = timer.get_counter();
        let mut fifo = sio.fifo;
        let mut multicore = Multicore::new(&mut pac.PSM, &mut pac.PPB, &mut fifo);
        let cores = multicore.cores();
        cores[1]
            .spawn(CORE1_STACK.take().unwrap(), move || {
                core1(&camera, core1_buffers)
            })
            .unwrap();

        for band in 0..BANDS {
            if band % 2 == 0 {
                render_band(&camera, band, own);
                send_band(&mut display, band, own).unwrap();
            } else {
                // Core 1's (band / 2)-th band.
                let slot = (band / 2) % 2;
                let buffer = take(&RENDERED[slot]);
                send_band(&mut display, band, buffer).unwrap();
                put(&SENT[slot], buffer);
            }
        }
        start
    };

    // Core 0 renders every band and sends it through the same DMA interface and driver: the
    // build an emulator with one core can run (scripts/pico.sh), and the measure of what the
    // second core saves.
    #[cfg(feature = "single-core")]
    let start = {
        let start = timer.get_counter();
        for band in 0..BANDS {
            render_band(&camera, band, own);
            send_band(&mut display, band, own).unwrap();
        }
        start
    };
    let elapsed = timer.get_counter() - start;

    // The frame time, rendering and sending included, over the sky in the top left corner.
    // A line of text formatted without an allocator.
    let mut text = heapless::String::<32>::new();
    let cores = if cfg!(feature = "single-core") {
        "1 core"
    } else {
        "2 cores"
    };
    let _ = write!(text, "{} ms, {cores}", elapsed.to_millis());
    let style = MonoTextStyleBuilder::new()
        .font(&FONT_6X10)
        .text_color(Rgb565::BLACK)
        .background_color(Rgb565::from_rgb(demo::BACKGROUND, Point::zero()))
        .build();
    Text::with_baseline(text.as_str(), Point::new(2, 2), style, Baseline::Top)
        .draw(&mut display)
        .unwrap();

    // Polling the timer, as the driver's start-up delays do: no interrupt to set up. The
    // emulator's run (scripts/pico/run.mjs) ends at this pause's first read of the timer, with
    // the frame and its text sent.
    timer.delay_ms(PAUSE_MS);
    // Core 0's band buffer is free now: the passes use its first row. `orbit` returns only
    // when the display fails; the core then sleeps, the display left as it is.
    let _failed = orbit(&mut display, own);

    loop {
        cortex_m::asm::wfi();
    }
}

/// Orbits the camera about the scene, `YAW_STEP_DEGREES` a view, each view drawn in
/// progressive passes. It returns only the error that stopped a view's drawing.
fn orbit<D: DrawTarget<Color = Rgb565>>(display: &mut D, row: &mut [Rgb]) -> DrawError<D::Error> {
    let mut yaw = 0;
    loop {
        yaw = (yaw + YAW_STEP_DEGREES) % 360;
        // A camera the builder refuses is skipped: the display keeps the view before.
        let Ok(camera) = orbit_camera(yaw) else {
            continue;
        };
        if let Err(error) = draw_view(&camera, row, display) {
            return error;
        }
    }
}

/// The orbit's camera at `yaw` degrees, the display's size. This is the view's only float
/// work (rp2040-hal hands `f32` arithmetic to the boot ROM's routines); tracing is fixed point.
fn orbit_camera(yaw: u32) -> Result<Camera, fixray::Error> {
    Camera::orbit(TARGET, DISTANCE)
        .yaw_degrees(yaw as f32)
        .pitch_degrees(PITCH_DEGREES)
        .size(Size::new(WIDTH as u32, HEIGHT as u32))
        .build()
}

/// Draws the scene as `camera` sees it, pass by pass from spacing `COARSEST` down to 1: the
/// first pass covers the display in blocks, the last leaves a full render's picture. `row`
/// is scratch space for one row of the picture.
fn draw_view<D: DrawTarget<Color = Rgb565>>(
    camera: &Camera,
    row: &mut [Rgb],
    display: &mut D,
) -> Result<(), DrawError<D::Error>> {
    let view = Viewport::at(&SCENE, camera, Point::zero());
    for pass in Pass::sequence(COARSEST)? {
        view.render_pass(pass, row, display)?;
    }
    Ok(())
}

/// Core 1: renders the odd bands, alternating between its two buffers, and leaves each for
/// core 0 to send.
#[cfg(not(feature = "single-core"))]
fn core1(camera: &Camera, buffers: [&'static mut Band; 2]) -> ! {
    let mut fresh = buffers.map(Some);
    for (i, band) in (1..BANDS).step_by(2).enumerate() {
        let slot = i % 2;
        // Each buffer is fresh the first time; after that, wait until core 0 has sent it.
        let buffer = fresh[slot].take().unwrap_or_else(|| take(&SENT[slot]));
        render_band(camera, band, buffer);
        put(&RENDERED[slot], buffer);
    }
    loop {
        cortex_m::asm::wfi();
    }
}

/// Renders band `band` into `buffer`, row by row.
fn render_band(camera: &Camera, band: usize, buffer: &mut Band) {
    let first = band * BAND_ROWS;
    for (r, row) in buffer.chunks_exact_mut(WIDTH).enumerate() {
        // The row is on the camera's screen and the buffer a row long: this cannot fail.
        render_row(&SCENE, camera, (first + r) as u32, row).unwrap();
    }
}

/// Sends the rendered rows of band `band` to its place on the display, converted to `Rgb565`
/// as fixray's `Viewport` converts them (rounded per channel), in one address window.
fn send_band<D: DrawTarget<Color = Rgb565>>(
    display: &mut D,
    band: usize,
    pixels: &[Rgb],
) -> Result<(), D::Error> {
    let top = (band * BAND_ROWS) as i32;
    let area = Rectangle::new(
        Point::new(0, top),
        Size::new(WIDTH as u32, BAND_ROWS as u32),
    );
    let colours = pixels.iter().enumerate().map(|(i, &pixel)| {
        let at = Point::new((i % WIDTH) as i32, top + (i / WIDTH) as i32);
        Rgb565::from_rgb(pixel, at)
    });
    display.fill_contiguous(&area, colours)
}

/// Leaves `buffer` in `slot` and wakes the other core.
#[cfg(not(feature = "single-core"))]
fn put(slot: &Slot, buffer: &'static mut Band) {
    let previous = critical_section::with(|cs| slot.borrow_ref_mut(cs).replace(buffer));
    // Each slot is emptied before the protocol fills it again.
    debug_assert!(previous.is_none());
    cortex_m::asm::sev();
}

/// Takes the buffer in `slot`, sleeping until there is one.
#[cfg(not(feature = "single-core"))]
fn take(slot: &Slot) -> &'static mut Band {
    loop {
        if let Some(buffer) = critical_section::with(|cs| slot.borrow_ref_mut(cs).take()) {
            return buffer;
        }
        // An event sent since the check above makes this return at once: no wake-up is lost.
        cortex_m::asm::wfe();
    }
}
