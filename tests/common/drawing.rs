//! Drawing: a display that records every pixel ([`Recorder`]), hostile corners to draw at,
//! and the oracles for viewports and framebuffers drawn onto it.

use std::collections::HashMap;

use embedded_graphics::pixelcolor::{BinaryColor, Gray8, PixelColor, Rgb565, Rgb888};
use embedded_graphics::prelude::{DrawTarget, OriginDimensions, Pixel, Point, Size};
use embedded_graphics::primitives::Rectangle;
use fixray::draw::{self, Viewport};
use fixray::{Camera, Framebuffer, Rgb, Scene};

use super::Source;

/// A display that records every pixel drawn, in any colour type.
pub struct Recorder<C> {
    pub size: Size,
    pub pixels: HashMap<(i32, i32), C>,
}

impl<C: PixelColor> DrawTarget for Recorder<C> {
    type Color = C;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        for Pixel(at, c) in pixels {
            self.pixels.insert((at.x, at.y), c);
        }
        Ok(())
    }
}

impl<C> OriginDimensions for Recorder<C> {
    fn size(&self) -> Size {
        self.size
    }
}

/// A top-left corner: near the origin, negative, or near the ends of `i32`.
pub fn corner(src: &mut impl Source) -> Point {
    fn c(s: &mut impl Source) -> i32 {
        match s.below(4) {
            0 => s.pick(&[i32::MIN, i32::MAX, i32::MAX - 3, i32::MIN + 3, -1]),
            _ => s.below(64) as i32 - 16,
        }
    }
    Point::new(c(src), c(src))
}

/// [ASSERT: viewports draw render_row's pixels] A viewport at a hostile place, drawn in bands
/// of a hostile buffer, onto a recording display in full colour and in dithered grey and one
/// bit: every pixel on the display is the rendered row's, converted at its display position,
/// and nothing else is drawn.
pub fn check_viewport<const N: usize>(
    src: &mut impl Source,
    scene: &Scene<N>,
    camera: &Camera,
    frame: &[Vec<Rgb>],
) {
    let (cols, rows) = (camera.width(), camera.height());
    let top_left = corner(src);
    let viewport = Viewport::at(scene, camera, top_left);
    assert_eq!(camera.size(), Size::new(cols, rows), "the camera's size");
    assert_eq!(
        viewport.area(),
        Rectangle::new(top_left, Size::new(cols, rows)),
        "the viewport covers the camera's picture at its corner"
    );
    let buffer_len = match src.below(4) {
        0 => src.below(cols as u64) as usize, // less than a row: refused
        1 => cols as usize,
        _ => cols as usize * (1 + src.below(rows as u64 + 2) as usize) + src.below(3) as usize,
    };
    let mut buffer = vec![Rgb::BLACK; buffer_len];
    let bands = viewport.bands(src.pick(&[0, 1, 3, u32::MAX]));
    let mut rgb = Recorder::<Rgb888> {
        size: Size::new(u32::MAX, u32::MAX),
        pixels: HashMap::new(),
    };
    let mut grey = Recorder::<Gray8> {
        size: Size::new(64, 64),
        pixels: HashMap::new(),
    };
    let mut bits = Recorder::<BinaryColor> {
        size: Size::new(64, 64),
        pixels: HashMap::new(),
    };
    let mut covered = 0usize;
    for band in bands {
        let a = viewport.render_rows(band.clone(), &mut buffer, &mut rgb);
        let b = viewport.render_rows(band.clone(), &mut buffer, &mut grey);
        let c = viewport.render_rows(band.clone(), &mut buffer, &mut bits);
        if buffer_len < cols as usize {
            assert!(
                a.is_err() && b.is_err() && c.is_err(),
                "a buffer below one row"
            );
            return;
        }
        assert!(a.is_ok() && b.is_ok() && c.is_ok(), "band {band:?}");
        covered += band.len();
    }
    assert_eq!(covered, rows as usize, "bands cover every row once");
    // Rows past the camera's are refused, as is an empty buffer.
    assert!(
        viewport
            .render_rows(0..rows + 1, &mut buffer, &mut rgb)
            .is_err()
    );
    assert!(viewport.render_rows(0..1, &mut [], &mut rgb).is_err());
    let _ = viewport.render_rows(rows..rows / 2, &mut buffer, &mut rgb); // a backwards range
    // The viewport is clipped to each display's bounding box: a pixel is drawn exactly where
    // its point lies on the display (and below i32::MAX, where embedded-graphics' corners
    // still fit), converted at that point.
    let on = |size: Size, x: i64, y: i64| {
        let limit = |side: u32| i64::from(side).min(i64::from(i32::MAX));
        (0..limit(size.width)).contains(&x) && (0..limit(size.height)).contains(&y)
    };
    let mut shown = [0usize; 3];
    for (row, line) in frame.iter().enumerate() {
        for (col, &c) in line.iter().enumerate() {
            let x = i64::from(top_left.x) + col as i64;
            let y = i64::from(top_left.y) + row as i64;
            // A point on any display fits i32; `at` is used only then.
            let at = Point::new(x as i32, y as i32);
            if on(rgb.size, x, y) {
                shown[0] += 1;
                assert_eq!(
                    rgb.pixels.get(&(at.x, at.y)),
                    Some(&Rgb888::from(c)),
                    "{at:?}"
                );
            }
            if on(grey.size, x, y) {
                shown[1] += 1;
                let level = draw::dither(draw::luma(c), 255, at);
                assert_eq!(
                    grey.pixels.get(&(at.x, at.y)),
                    Some(&Gray8::new(level)),
                    "{at:?}"
                );
            }
            if on(bits.size, x, y) {
                shown[2] += 1;
                let lit = BinaryColor::from(draw::dither(draw::luma(c), 1, at) == 1);
                assert_eq!(bits.pixels.get(&(at.x, at.y)), Some(&lit), "{at:?}");
            }
        }
    }
    assert_eq!(
        [rgb.pixels.len(), grey.pixels.len(), bits.pixels.len()],
        shown,
        "nothing off the display or outside the area"
    );
    let _ = <Rgb565 as draw::FromRgb>::from_rgb(Rgb::WHITE, top_left);
}

/// [ASSERT: the framebuffer as a display and an image] `render` into a framebuffer equals the
/// rows; drawing it anywhere, whole or in part, never panics and draws the right pixels.
pub fn check_framebuffer<const N: usize, const W: usize, const H: usize>(
    src: &mut impl Source,
    scene: &Scene<N>,
    camera: &Camera,
    frame: &[Vec<Rgb>],
) {
    use embedded_graphics::image::{GetPixel, ImageDrawable};
    let mut fb = Framebuffer::<W, H>::new();
    let result = fixray::render(scene, camera, &mut fb);
    if (camera.width() as usize, camera.height() as usize) != (W, H) {
        assert!(
            result.is_err(),
            "render into a {W}×{H} framebuffer must be refused"
        );
    } else {
        result.unwrap_or_else(|e| panic!("render refused a matching framebuffer: {e}"));
        for (row, line) in frame.iter().enumerate() {
            assert_eq!(&fb.rows()[row][..], &line[..], "render's row {row}");
        }
        let mut hash = fixray::FrameHash::new();
        for line in fb.rows() {
            hash.update(line);
        }
        let mut whole = fixray::FrameHash::new();
        whole.update(fb.rows().as_flattened());
        assert_eq!(hash.finish(), whole.finish());
        assert_eq!(fb.bytes().count(), 3 * W * H);
    }
    assert_eq!((fb.width(), fb.height()), (W, H));
    assert_eq!(fb.pixel(W, 0), None);
    assert_eq!(fb.pixel(0, usize::MAX), None);
    assert!(!fb.set_pixel(usize::MAX, 0, Rgb::WHITE));
    assert_eq!(GetPixel::pixel(&fb, Point::new(-1, 0)), None);
    let mut display = Recorder::<Rgb888> {
        size: Size::new(u32::MAX, u32::MAX),
        pixels: HashMap::new(),
    };
    let at = corner(src);
    let _ = fb.draw_at(at, &mut display);
    let _ = fb.draw_at(
        at,
        &mut Recorder::<BinaryColor> {
            size: Size::zero(),
            pixels: HashMap::new(),
        },
    );
    let _ = ImageDrawable::draw(&fb, &mut display);
    for _ in 0..4 {
        let size = Size::new(
            src.pick(&[0, 1, W as u32, u32::MAX, i32::MAX as u32]),
            src.pick(&[0, 1, H as u32, u32::MAX, i32::MAX as u32]),
        );
        let area = Rectangle::new(corner(src), size);
        let mut part = Recorder::<Rgb888> {
            size: Size::new(u32::MAX, u32::MAX),
            pixels: HashMap::new(),
        };
        ImageDrawable::draw_sub_image(&fb, &mut part, &area).expect("infallible");
        for ((x, y), c) in &part.pixels {
            let source = Point::new(area.top_left.x + x, area.top_left.y + y);
            assert_eq!(GetPixel::pixel(&fb, source), Some(*c), "sub-image {area:?}");
        }
    }
}
