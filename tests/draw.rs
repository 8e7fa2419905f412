//! The drawing layer: streamed renders against the framebuffer, an ASCII-art picture, driver
//! errors, the framebuffer as an embedded-graphics image and target.

use core::convert::Infallible;

use embedded_graphics::image::Image;
use embedded_graphics::mock_display::MockDisplay;
use embedded_graphics::pixelcolor::{
    Bgr555, Bgr565, Bgr666, Bgr888, BinaryColor, Gray2, Gray4, Gray8, Rgb555, Rgb565, Rgb666,
    Rgb888,
};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{PrimitiveStyle, Rectangle};
use fixray::{
    Camera, DrawError, Error, Framebuffer, FromRgb, Fx, Light, Rgb, Scene, Sphere, Vec3, Viewport,
    demo, render,
};

/// A display that records every `fill_contiguous` call and every pixel, and notices a pixel
/// drawn twice, outside the display, or an iterator of the wrong length.
struct Recorder<C> {
    size: Size,
    pixels: Vec<Option<C>>,
    calls: Vec<Rectangle>,
    faults: Vec<String>,
}

impl<C: PixelColor> Recorder<C> {
    fn new(width: u32, height: u32) -> Self {
        Recorder {
            size: Size::new(width, height),
            pixels: vec![None; (width * height) as usize],
            calls: Vec::new(),
            faults: Vec::new(),
        }
    }

    fn get(&self, x: i32, y: i32) -> Option<C> {
        self.pixels[(y as u32 * self.size.width + x as u32) as usize]
    }
}

impl<C: PixelColor> OriginDimensions for Recorder<C> {
    fn size(&self) -> Size {
        self.size
    }
}

impl<C: PixelColor> DrawTarget for Recorder<C> {
    type Color = C;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(&mut self, pixels: I) -> Result<(), Infallible> {
        for Pixel(p, c) in pixels {
            if !self.bounding_box().contains(p) {
                self.faults.push(format!("pixel {p:?} outside the display"));
                continue;
            }
            let i = (p.y as u32 * self.size.width + p.x as u32) as usize;
            if self.pixels[i].replace(c).is_some() {
                self.faults.push(format!("pixel {p:?} drawn twice"));
            }
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = C>>(
        &mut self,
        area: &Rectangle,
        colours: I,
    ) -> Result<(), Infallible> {
        self.calls.push(*area);
        let colours: Vec<C> = colours.into_iter().collect();
        if colours.len() != (area.size.width * area.size.height) as usize {
            self.faults
                .push(format!("{} colours for {area:?}", colours.len()));
        }
        self.draw_iter(area.points().zip(colours).map(|(p, c)| Pixel(p, c)))
    }
}

/// The demo at 40 × 30: small enough to check every pixel of every format quickly.
const COLS: u32 = 40;
const ROWS: u32 = 30;

fn demo_frame() -> (Scene<8>, Camera, Framebuffer<40, 30>) {
    let (scene, camera) = (demo::scene(), demo::camera(COLS, ROWS).unwrap());
    let mut frame = Framebuffer::new();
    render(&scene, &camera, &mut frame).unwrap();
    (scene, camera, frame)
}

/// Streams the demo into a 53 × 47 display at (7, 11) with a buffer of `buffer_rows` rows and
/// checks it against the framebuffer render, converted pixel by pixel at the same display
/// points; then checks `Framebuffer::draw_at` draws the same.
fn streamed_equals_framebuffer<C: FromRgb + core::fmt::Debug>(buffer_rows: usize) {
    let (scene, camera, frame) = demo_frame();
    let origin = Point::new(7, 11);
    let mut display = Recorder::<C>::new(53, 47);
    let view = Viewport::at(&scene, &camera, origin);
    let mut buffer = vec![Rgb::BLACK; COLS as usize * buffer_rows];
    view.render(&mut buffer, &mut display).unwrap();
    assert!(display.faults.is_empty(), "{:?}", display.faults);

    // One call per band of `buffer_rows` rows (the last band shorter), top to bottom.
    let heights: Vec<u32> = display.calls.iter().map(|a| a.size.height).collect();
    let mut expected = vec![buffer_rows.min(30) as u32; 30 / buffer_rows.min(30)];
    if 30 % buffer_rows.min(30) != 0 {
        expected.push((30 % buffer_rows) as u32);
    }
    assert_eq!(heights, expected);

    for y in 0..47 {
        for x in 0..53 {
            let (fx, fy) = (x - origin.x, y - origin.y);
            let want = (0..40).contains(&fx) && (0..30).contains(&fy);
            let expected = want.then(|| {
                let shaded = frame.pixel(fx as usize, fy as usize).unwrap();
                C::from_rgb(shaded, Point::new(x, y))
            });
            assert_eq!(display.get(x, y), expected, "display pixel ({x}, {y})");
        }
    }

    let mut whole = Recorder::<C>::new(53, 47);
    frame.draw_at(origin, &mut whole).unwrap();
    assert!(whole.faults.is_empty(), "{:?}", whole.faults);
    assert_eq!(whole.calls, [view.area()]);
    assert_eq!(whole.pixels, display.pixels);
}

#[test]
fn streamed_render_equals_framebuffer_render_in_every_format() {
    for rows in [1, 4, 7, 30, 100] {
        streamed_equals_framebuffer::<Rgb888>(rows);
        streamed_equals_framebuffer::<Rgb565>(rows);
        streamed_equals_framebuffer::<Gray8>(rows);
        streamed_equals_framebuffer::<Gray4>(rows);
        streamed_equals_framebuffer::<Gray2>(rows);
        streamed_equals_framebuffer::<BinaryColor>(rows);
        streamed_equals_framebuffer::<Bgr888>(rows);
        streamed_equals_framebuffer::<Bgr565>(rows);
        streamed_equals_framebuffer::<Rgb555>(rows);
        streamed_equals_framebuffer::<Bgr555>(rows);
        streamed_equals_framebuffer::<Rgb666>(rows);
        streamed_equals_framebuffer::<Bgr666>(rows);
    }
}

#[test]
fn rgb888_is_the_shaded_colour_and_rgb565_rounds_each_channel() {
    let (scene, camera, frame) = demo_frame();
    let view = Viewport::at(&scene, &camera, Point::zero());
    let mut row = [Rgb::BLACK; 40];
    let mut exact = Recorder::<Rgb888>::new(40, 30);
    view.render(&mut row, &mut exact).unwrap();
    let mut small = Recorder::<Rgb565>::new(40, 30);
    view.render(&mut row, &mut small).unwrap();
    // Nearest of 2^bits − 1 steps: ⌊(v · max + 127) / 255⌋.
    let round = |v: u8, max: u32| ((u32::from(v) * max + 127) / 255) as u8;
    for (i, c) in frame.rows().iter().flatten().enumerate() {
        let (x, y) = (i as i32 % 40, i as i32 / 40);
        assert_eq!(exact.get(x, y), Some(Rgb888::new(c.r, c.g, c.b)));
        assert_eq!(
            small.get(x, y),
            Some(Rgb565::new(round(c.r, 31), round(c.g, 63), round(c.b, 31)))
        );
    }
}

/// A white sphere of radius 6 at (0, 0, −10), seen by a pinhole camera at the origin through a
/// 16 × 16 unit screen 8 units away, one unit a pixel, on a black background. Ambient light 1
/// makes every lit pixel pure white, so dithering cannot touch it: the picture is the
/// silhouette, and it is derivable by hand.
///
/// The ray through the pixel centre (x, y, −8) passes the sphere's centre at distance d with
/// d² / 100 = (x² + y²) / (x² + y² + 64), so it hits when d < 6, that is when x² + y² < 36:
/// a disc of radius 6 on the screen. Centres sit at half-integers, none closer than 0.5 to
/// the rim (x² + y² is 32.5 or 36.5 at the nearest), so Q16.16 cannot move a pixel.
#[test]
fn a_sphere_straight_ahead_matches_the_ascii_art() {
    let light = Light::from_fx(Vec3::from_ints(0, 0, 10), Fx::ONE).unwrap();
    let mut scene: Scene<1> = Scene::new(light, 1.0, Rgb::BLACK).unwrap();
    let sphere = Sphere::from_fx(Vec3::from_ints(0, 0, -10), Fx::from_num(6)).unwrap();
    scene.add_sphere(sphere, Rgb::WHITE).unwrap();
    let camera = Camera::pinhole(16.0, 16.0, 8.0)
        .size(Size::new(16, 16))
        .build()
        .unwrap();

    let mut display = MockDisplay::<BinaryColor>::new();
    let view = Viewport::at(&scene, &camera, Point::new(3, 2));
    let mut row = [Rgb::BLACK; 16];
    view.render(&mut row, &mut display).unwrap();

    // Screen y is 7.5 at the top row and falls by 1 a row; x runs −7.5 … 7.5. A row's lit run
    // is every |x| with x² < 36 − y². The viewport sits 3 columns right and 2 rows down, and
    // nothing outside it is drawn (spaces).
    display.assert_pattern(&[
        "                   ",
        "                   ",
        "   ................", // y = 7.5: 56.25 > 36, none
        "   ................", // y = 6.5: 42.25 > 36, none
        "   ......####......", // y = 5.5: x² < 5.75, |x| ≤ 1.5: 4 pixels
        "   ....########....", // y = 4.5: x² < 15.75, |x| ≤ 3.5: 8
        "   ...##########...", // y = 3.5: x² < 23.75, |x| ≤ 4.5: 10
        "   ...##########...", // y = 2.5: x² < 29.75, |x| ≤ 4.5 (5.5² = 30.25): 10
        "   ..############..", // y = 1.5: x² < 33.75, |x| ≤ 5.5: 12
        "   ..############..", // y = 0.5: x² < 35.75, |x| ≤ 5.5: 12
        "   ..############..", // y = −0.5: the mirror image of the rows above
        "   ..############..", // y = −1.5
        "   ...##########...", // y = −2.5
        "   ...##########...", // y = −3.5
        "   ....########....", // y = −4.5
        "   ......####......", // y = −5.5
        "   ................", // y = −6.5
        "   ................", // y = −7.5
    ]);
}

/// A display whose `fill_contiguous` fails on call number `fail_on` (counting from 0) with an
/// error carrying the call number.
struct Flaky {
    calls: usize,
    fail_on: usize,
}

#[derive(Debug, PartialEq, Eq)]
struct BusError(usize);

impl OriginDimensions for Flaky {
    fn size(&self) -> Size {
        Size::new(40, 30)
    }
}

impl DrawTarget for Flaky {
    type Color = Rgb565;
    type Error = BusError;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, _: I) -> Result<(), BusError> {
        Err(BusError(usize::MAX))
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        _: &Rectangle,
        _: I,
    ) -> Result<(), BusError> {
        let call = self.calls;
        self.calls += 1;
        if call == self.fail_on {
            Err(BusError(call))
        } else {
            Ok(())
        }
    }
}

#[test]
fn a_failing_display_hands_its_error_back_and_stops() {
    let (scene, camera) = (demo::scene(), demo::camera(COLS, ROWS).unwrap());
    let view = Viewport::at(&scene, &camera, Point::zero());
    let mut row = [Rgb::BLACK; 40];
    for fail_on in [0, 1, 17, 29] {
        let mut display = Flaky { calls: 0, fail_on };
        let result = view.render(&mut row, &mut display);
        assert_eq!(result, Err(DrawError::Display(BusError(fail_on))));
        assert_eq!(
            display.calls,
            fail_on + 1,
            "no row is sent after the failure"
        );
    }
    // The framebuffer's own drawing passes the error through too.
    let (_, _, frame) = demo_frame();
    let mut display = Flaky {
        calls: 0,
        fail_on: 0,
    };
    assert_eq!(
        frame.draw_at(Point::zero(), &mut display),
        Err(DrawError::Display(BusError(0)))
    );
}

#[test]
fn refused_requests_are_errors_and_draw_nothing() {
    let (scene, camera) = (demo::scene(), demo::camera(COLS, ROWS).unwrap());
    let view = Viewport::at(&scene, &camera, Point::zero());
    let mut display = Flaky {
        calls: 0,
        fail_on: usize::MAX,
    };
    let mut row = [Rgb::BLACK; 40];
    // Rows past the bottom of the picture: the last one asked for is named.
    assert_eq!(
        view.render_rows(25..31, &mut row, &mut display),
        Err(DrawError::Render(Error::RowOutOfRange {
            row: 30,
            rows: 30
        }))
    );
    assert_eq!(
        view.render_rows(0..u16::MAX.into(), &mut row, &mut display),
        Err(DrawError::Render(Error::RowOutOfRange {
            row: u32::from(u16::MAX) - 1,
            rows: 30
        }))
    );
    assert_eq!(
        view.render_rows(0..u32::MAX, &mut row, &mut display),
        Err(DrawError::Render(Error::RowOutOfRange {
            row: u32::MAX - 1,
            rows: 30
        }))
    );
    // A buffer shorter than one row.
    assert_eq!(
        view.render_rows(0..30, &mut row[..39], &mut display),
        Err(DrawError::Render(Error::BufferLength {
            needed: 40,
            got: 39
        }))
    );
    // An empty range is fine and draws nothing.
    assert_eq!(view.render_rows(12..12, &mut row, &mut display), Ok(()));
    assert_eq!(display.calls, 0);
}

#[test]
fn bands_cover_every_row_once_and_can_be_interleaved() {
    let (scene, camera, frame) = demo_frame();
    let view = Viewport::at(&scene, &camera, Point::zero());
    for height in [0, 1, 7, 30, 31, u32::MAX] {
        let bands: Vec<_> = view.bands(height).collect();
        assert_eq!(bands.len(), view.bands(height).len());
        let step = height.clamp(1, 30);
        assert_eq!(bands.first(), Some(&(0..step)));
        assert_eq!(bands.last().map(|r| r.end), Some(30));
        assert!(
            bands
                .windows(2)
                .all(|w| w[0].end == w[1].start && !w[1].is_empty())
        );
    }
    // Other drawing between bands, somewhere else on the display, changes nothing in the picture.
    let mut display = Recorder::<Rgb888>::new(40, 31);
    let mut band = [Rgb::BLACK; 40 * 8];
    for (i, rows) in view.bands(8).enumerate() {
        view.render_rows(rows, &mut band, &mut display).unwrap();
        Pixel(Point::new(i as i32, 30), Rgb888::RED)
            .draw(&mut display)
            .unwrap();
    }
    assert!(display.faults.is_empty(), "{:?}", display.faults);
    for (i, c) in frame.rows().iter().flatten().enumerate() {
        assert_eq!(
            display.get(i as i32 % 40, i as i32 / 40),
            Some(Rgb888::from(*c))
        );
    }
}

#[test]
fn the_framebuffer_is_an_image_and_a_draw_target() {
    let (_, _, mut frame) = demo_frame();
    // As a draw target: embedded-graphics primitives land in the frame, clipped to it.
    Rectangle::new(Point::new(35, -3), Size::new(10, 6))
        .into_styled(PrimitiveStyle::with_fill(Rgb888::new(1, 2, 3)))
        .draw(&mut frame)
        .unwrap();
    assert_eq!(frame.pixel(35, 0), Some(Rgb::new(1, 2, 3)));
    assert_eq!(frame.pixel(39, 2), Some(Rgb::new(1, 2, 3)));
    assert_ne!(frame.pixel(34, 2), Some(Rgb::new(1, 2, 3)));
    assert_ne!(frame.pixel(35, 3), Some(Rgb::new(1, 2, 3)));
    assert_eq!(
        frame.bounding_box(),
        Rectangle::new(Point::zero(), Size::new(40, 30))
    );

    // As an image: drawn at an offset, every pixel arrives where it should.
    let mut display = Recorder::<Rgb888>::new(50, 40);
    Image::new(&frame, Point::new(4, 9))
        .draw(&mut display)
        .unwrap();
    assert!(display.faults.is_empty(), "{:?}", display.faults);
    for y in 0..40 {
        for x in 0..50 {
            let inside = (4..44).contains(&x) && (9..39).contains(&y);
            let expected = inside
                .then(|| Rgb888::from(frame.pixel((x - 4) as usize, (y - 9) as usize).unwrap()));
            assert_eq!(display.get(x, y), expected, "({x}, {y})");
        }
    }

    // A sub-image: the 3 × 2 block at (10, 20) of the frame.
    let mut part = Recorder::<Rgb888>::new(3, 2);
    let sub = embedded_graphics::image::ImageDrawableExt::sub_image(
        &frame,
        &Rectangle::new(Point::new(10, 20), Size::new(3, 2)),
    );
    Image::new(&sub, Point::zero()).draw(&mut part).unwrap();
    for (x, y) in [(0, 0), (2, 0), (1, 1), (2, 1)] {
        let expected = Rgb888::from(frame.pixel(10 + x as usize, 20 + y as usize).unwrap());
        assert_eq!(part.get(x, y), Some(expected));
    }
}

/// The display pixels a `cols × rows` demo picture at `top_left` must set on a `w × h`
/// display: each pixel of the framebuffer render whose display point lies on the display,
/// converted there. Worked out from the frame alone, with no clipping code.
fn expected_on_display<C: FromRgb, const W: usize, const H: usize>(
    frame: &Framebuffer<W, H>,
    top_left: Point,
    (w, h): (i32, i32),
) -> Vec<Option<C>> {
    let mut pixels = vec![None; (w * h) as usize];
    for (y, line) in frame.rows().iter().enumerate() {
        for (x, &c) in line.iter().enumerate() {
            // In i64: a picture near the ends of i32 has points past them, on no display.
            let (dx, dy) = (
                i64::from(top_left.x) + x as i64,
                i64::from(top_left.y) + y as i64,
            );
            if (0..i64::from(w)).contains(&dx) && (0..i64::from(h)).contains(&dy) {
                let at = Point::new(dx as i32, dy as i32);
                pixels[(at.y * w + at.x) as usize] = Some(C::from_rgb(c, at));
            }
        }
    }
    pixels
}

/// Places on a 48 × 32 display that leave the 40 × 30 demo partly off it on each side and
/// corner, wholly off it, or wholly on it.
const PLACES: [Point; 13] = [
    Point::new(-7, 0),
    Point::new(15, 1),
    Point::new(4, -11),
    Point::new(3, 20),
    Point::new(-39, -29),
    Point::new(47, 31),
    Point::new(-20, 10),
    Point::new(30, -25),
    Point::new(4, 1),
    Point::new(-40, 0),
    Point::new(0, 32),
    Point::new(48, -30),
    Point::new(i32::MIN, i32::MAX),
];

#[test]
fn a_viewport_partly_off_the_display_draws_only_what_shows() {
    let (scene, camera, frame) = demo_frame();
    for at in PLACES {
        for band_rows in [1, 7, 30] {
            let view = Viewport::at(&scene, &camera, at);
            let mut display = Recorder::<Gray4>::new(48, 32);
            let mut buffer = vec![Rgb::BLACK; 40 * band_rows];
            view.render(&mut buffer, &mut display).unwrap();
            assert!(display.faults.is_empty(), "{at:?}: {:?}", display.faults);
            assert_eq!(
                display.pixels,
                expected_on_display::<Gray4, 40, 30>(&frame, at, (48, 32)),
                "{at:?}, bands of {band_rows}"
            );
            // Every call is a band of visible rows cut to the visible columns: no call holds
            // a row or a column off the display, and no two calls overlap.
            let shown = display.pixels.iter().flatten().count() as u32;
            let sent: u32 = display
                .calls
                .iter()
                .map(|a| a.size.width * a.size.height)
                .sum();
            assert_eq!(sent, shown, "{at:?}");
            assert!(
                display
                    .calls
                    .iter()
                    .all(|a| a.size.height as usize <= band_rows)
            );
        }
    }
}

#[test]
fn a_framebuffer_partly_off_the_display_draws_only_what_shows() {
    let (_, _, frame) = demo_frame();
    for at in PLACES {
        let mut display = Recorder::<BinaryColor>::new(48, 32);
        frame.draw_at(at, &mut display).unwrap();
        assert!(display.faults.is_empty(), "{at:?}: {:?}", display.faults);
        assert!(display.calls.len() <= 1);
        assert_eq!(
            display.pixels,
            expected_on_display::<BinaryColor, 40, 30>(&frame, at, (48, 32)),
            "{at:?}"
        );
    }
}

#[test]
fn a_picture_draws_what_the_viewport_renders() {
    let (scene, camera, frame) = demo_frame();
    for at in PLACES {
        let picture = Viewport::at(&scene, &camera, at)
            .picture::<Rgb565, 40>()
            .unwrap();
        let mut display = Recorder::<Rgb565>::new(48, 32);
        picture.draw(&mut display).unwrap();
        assert!(display.faults.is_empty(), "{at:?}: {:?}", display.faults);
        assert_eq!(
            display.pixels,
            expected_on_display::<Rgb565, 40, 30>(&frame, at, (48, 32)),
            "{at:?}"
        );
        // One call per visible row: a one-row buffer.
        assert!(display.calls.iter().all(|a| a.size.height == 1));
        assert_eq!(
            picture.bounding_box(),
            Rectangle::new(at, Size::new(40, 30))
        );
    }
    // A buffer wider than the camera works the same; a narrower one is refused when the
    // picture is made, naming the camera and the buffer.
    let wide = Viewport::at(&scene, &camera, Point::zero()).picture::<Rgb888, 320>();
    let mut display = Recorder::<Rgb888>::new(40, 30);
    wide.unwrap().draw(&mut display).unwrap();
    assert_eq!(
        display.pixels,
        expected_on_display::<Rgb888, 40, 30>(&frame, Point::zero(), (40, 30))
    );
    let narrow = Viewport::at(&scene, &camera, Point::zero()).picture::<Rgb888, 39>();
    assert_eq!(
        narrow.err(),
        Some(Error::BufferLength {
            needed: 40,
            got: 39
        })
    );
}

#[test]
fn a_picture_hands_the_driver_error_back_unchanged() {
    let (scene, camera) = (demo::scene(), demo::camera(COLS, ROWS).unwrap());
    let picture = Viewport::at(&scene, &camera, Point::zero())
        .picture::<Rgb565, 40>()
        .unwrap();
    for fail_on in [0, 5, 29] {
        let mut display = Flaky { calls: 0, fail_on };
        assert_eq!(picture.draw(&mut display), Err(BusError(fail_on)));
        assert_eq!(
            display.calls,
            fail_on + 1,
            "no row is sent after the failure"
        );
    }
}

#[test]
fn at_places_the_cameras_picture_at_its_corner() {
    let (scene, camera) = (demo::scene(), demo::camera(COLS, ROWS).unwrap());
    let corner = Point::new(-3, 9);
    let at = Viewport::at(&scene, &camera, corner);
    let area = Rectangle::new(corner, Size::new(40, 30));
    assert_eq!(
        (at.top_left(), at.area(), at.size()),
        (corner, area, area.size)
    );
    assert_eq!(at.bounding_box(), area);
}

#[test]
fn draw_errors_say_which_side_failed() {
    let refused: DrawError<BusError> = Error::RowOutOfRange { row: 30, rows: 30 }.into();
    assert_eq!(
        refused.to_string(),
        "row 30 is outside the picture's 30 rows"
    );
    let source = core::error::Error::source(&refused).map(|e| e.to_string());
    assert_eq!(
        source.as_deref(),
        Some("row 30 is outside the picture's 30 rows")
    );
    let driver: DrawError<BusError> = DrawError::Display(BusError(7));
    assert_eq!(driver.to_string(), "display driver error: BusError(7)");
    assert!(core::error::Error::source(&driver).is_none());
    // One error type for every call that draws, so `?` joins them.
    fn both(display: &mut Flaky) -> Result<(), DrawError<BusError>> {
        let (scene, camera, frame) = demo_frame();
        frame.draw_at(Point::zero(), display)?;
        Viewport::at(&scene, &camera, Point::zero()).render(&mut [Rgb::BLACK; 40], display)?;
        Ok(())
    }
    let mut display = Flaky {
        calls: 0,
        fail_on: 1,
    };
    assert_eq!(both(&mut display), Err(DrawError::Display(BusError(1))));
}
