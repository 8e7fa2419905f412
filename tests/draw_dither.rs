//! Ordered dithering holds to its documented precision: within one level per pixel, exact to
//! 1/128 of a level over an 8 × 8 block, black and white untouched; every embedded-graphics
//! colour type gets its channels in place, dithered where it has fewer bits than 8.

use embedded_graphics::pixelcolor::{
    Bgr555, Bgr565, Bgr666, Bgr888, BinaryColor, Gray2, Gray4, Gray8, Rgb555, Rgb565, Rgb666,
    Rgb888,
};
use embedded_graphics::prelude::{GrayColor, Point, RgbColor};
use fixray::draw::{BAYER_8X8, LUMA_MAX, bayer_index, dither, luma};
use fixray::{FromRgb, Rgb};

/// The 8 × 8 Bayer matrix as printed in the literature (Bayer 1973; Ulichney, "Digital
/// Halftoning", 1987).
const PUBLISHED: [[u8; 8]; 8] = [
    [0, 32, 8, 40, 2, 34, 10, 42],
    [48, 16, 56, 24, 50, 18, 58, 26],
    [12, 44, 4, 36, 14, 46, 6, 38],
    [60, 28, 52, 20, 62, 30, 54, 22],
    [3, 35, 11, 43, 1, 33, 9, 41],
    [51, 19, 59, 27, 49, 17, 57, 25],
    [15, 47, 7, 39, 13, 45, 5, 37],
    [63, 31, 55, 23, 61, 29, 53, 21],
];

fn tile() -> impl Iterator<Item = Point> {
    (0..64).map(|i| Point::new(i % 8, i / 8))
}

#[test]
fn the_matrix_is_bayers_and_tiles_the_plane() {
    assert_eq!(BAYER_8X8, PUBLISHED);
    for p in tile() {
        let index = PUBLISHED[p.y as usize][p.x as usize];
        for shift in [
            Point::new(8, 0),
            Point::new(-8, 16),
            Point::new(-800, -8),
            Point::new(i32::MIN, i32::MIN),
        ] {
            assert_eq!(bayer_index(p + shift), index, "{p:?} + {shift:?}");
        }
    }
}

#[test]
fn luma_uses_bt601_weights_in_256ths() {
    assert_eq!(luma(Rgb::WHITE), LUMA_MAX);
    assert_eq!(luma(Rgb::BLACK), 0);
    // 0.299, 0.587 and 0.114 of 256, rounded.
    assert_eq!(luma(Rgb::new(255, 0, 0)), 77 * 255);
    assert_eq!(luma(Rgb::new(0, 255, 0)), 150 * 255);
    assert_eq!(luma(Rgb::new(0, 0, 255)), 29 * 255);
    for c in 0..=255 {
        assert_eq!(luma(Rgb::new(c, c, c)), 256 * u32::from(c));
    }
}

#[test]
fn every_pixel_is_within_a_level_and_every_block_is_exact_on_average() {
    for max in [1u8, 3, 15, 255] {
        let max_wide = i64::from(max);
        let mut previous = [0u8; 64];
        for l in 0..=LUMA_MAX {
            // The exact level is v = l · max / LUMA_MAX; compare everything times LUMA_MAX.
            let exact = i64::from(l) * max_wide;
            let mut sum = 0i64;
            for (i, p) in tile().enumerate() {
                let level = dither(l, max, p);
                assert!(level <= max);
                let err = i64::from(level) * i64::from(LUMA_MAX) - exact;
                assert!(
                    err.abs() < i64::from(LUMA_MAX),
                    "luma {l}, {max} levels, {p:?}: level {level}"
                );
                assert!(
                    level >= previous[i],
                    "brighter input, darker pixel at luma {l}"
                );
                previous[i] = level;
                sum += i64::from(level);
            }
            let mean_err = sum * i64::from(LUMA_MAX) - 64 * exact;
            assert!(
                mean_err.abs() * 128 <= 64 * i64::from(LUMA_MAX),
                "luma {l}, {max} levels: block sum {sum}"
            );
        }
    }
}

#[test]
fn black_and_white_are_never_dithered_and_greys_are_exact_in_gray8() {
    for p in tile().chain([Point::new(-3, 1000)]) {
        assert_eq!(BinaryColor::from_rgb(Rgb::WHITE, p), BinaryColor::On);
        assert_eq!(BinaryColor::from_rgb(Rgb::BLACK, p), BinaryColor::Off);
        assert_eq!(Gray2::from_rgb(Rgb::WHITE, p), Gray2::WHITE);
        assert_eq!(Gray4::from_rgb(Rgb::BLACK, p), Gray4::BLACK);
        for c in 0..=255 {
            assert_eq!(Gray8::from_rgb(Rgb::new(c, c, c), p), Gray8::new(c));
        }
    }
    assert_eq!(
        dither(u32::MAX, 15, Point::zero()),
        15,
        "above white counts as white"
    );
}

#[test]
fn a_one_bit_display_shows_shading_not_a_silhouette() {
    // Each grey lights round(64 · c / 255) of the 64 pixels in a block: shades, not a cut-off.
    for c in 0..=255u8 {
        let lit = tile()
            .filter(|&p| BinaryColor::from_rgb(Rgb::new(c, c, c), p).is_on())
            .count();
        let expected = (64.0 * f64::from(c) / 255.0).round() as usize;
        assert!(
            lit.abs_diff(expected) <= 1,
            "grey {c}: {lit} lit, expected {expected}"
        );
    }
    // Gray4 spreads the fraction between two levels the same way.
    let grey = Rgb::new(100, 100, 100); // 100 / 255 · 15 = 5.88 levels
    let levels: Vec<u8> = tile().map(|p| Gray4::from_rgb(grey, p).luma()).collect();
    assert!(levels.iter().all(|&l| l == 5 || l == 6));
    assert_eq!(levels.iter().filter(|&&l| l == 6).count(), 56); // 0.88 · 64 = 56.5 → 56
}

/// The RGB types of 5 and 6 bits a channel: each channel ordered-dithered to its two nearest
/// levels, in the right place in the type, exact where the level is exact.
#[test]
fn every_rgb_type_gets_its_channels_in_place() {
    let at = Point::new(5, 2);
    let (r, g, b) = (
        Rgb::new(255, 0, 0),
        Rgb::new(0, 255, 0),
        Rgb::new(0, 0, 255),
    );
    assert_eq!(
        Bgr888::from_rgb(Rgb::new(1, 2, 3), at),
        Bgr888::new(1, 2, 3)
    );
    assert_eq!(
        Rgb888::from_rgb(Rgb::new(1, 2, 3), at),
        Rgb888::new(1, 2, 3)
    );
    assert_eq!(
        [r, g, b].map(|c| Bgr565::from_rgb(c, at)),
        [Bgr565::RED, Bgr565::GREEN, Bgr565::BLUE]
    );
    assert_eq!(
        [r, g, b].map(|c| Rgb555::from_rgb(c, at)),
        [Rgb555::RED, Rgb555::GREEN, Rgb555::BLUE]
    );
    assert_eq!(
        [r, g, b].map(|c| Bgr555::from_rgb(c, at)),
        [Bgr555::RED, Bgr555::GREEN, Bgr555::BLUE]
    );
    assert_eq!(
        [r, g, b].map(|c| Rgb666::from_rgb(c, at)),
        [Rgb666::RED, Rgb666::GREEN, Rgb666::BLUE]
    );
    assert_eq!(
        [r, g, b].map(|c| Bgr666::from_rgb(c, at)),
        [Bgr666::RED, Bgr666::GREEN, Bgr666::BLUE]
    );
    // 85 and 170 are exactly 21 and 42 of 63: six bits show them undithered, everywhere.
    for p in tile() {
        let c = Rgb::new(85, 170, 255);
        assert_eq!(Rgb666::from_rgb(c, p), Rgb666::new(21, 42, 63));
        assert_eq!(Bgr666::from_rgb(c, p), Bgr666::new(21, 42, 63));
    }
}

/// Bgr565 rounds as Rgb565 does: the same panel wired BGR shows the same picture.
#[test]
fn bgr565_is_rgb565_with_the_channels_swapped() {
    let round = |v: u8, max: u32| ((u32::from(v) * max + 127) / 255) as u8;
    for v in (0..=255u8).step_by(5) {
        let c = Rgb::new(v, 255 - v, v / 3);
        let (rgb, bgr) = (
            Rgb565::from_rgb(c, Point::zero()),
            Bgr565::from_rgb(c, Point::zero()),
        );
        assert_eq!((bgr.r(), bgr.g(), bgr.b()), (rgb.r(), rgb.g(), rgb.b()));
        assert_eq!(
            (bgr.r(), bgr.g(), bgr.b()),
            (round(c.r, 31), round(c.g, 63), round(c.b, 31))
        );
    }
}

/// Over an 8 × 8 tile a channel between two levels takes only those two, in the proportion
/// of its fraction, and a grey stays grey because the channels share the pixel's threshold.
#[test]
fn few_bit_rgb_channels_are_dithered_between_their_two_levels() {
    fn check<C: FromRgb + RgbColor>(value: u8) {
        let c = Rgb::new(value, value, value);
        let exact = |max: u8| f64::from(value) * f64::from(max) / 255.0;
        let pixels: Vec<C> = tile().map(|p| C::from_rgb(c, p)).collect();
        for (max, levels) in [
            (C::MAX_R, pixels.iter().map(|p| p.r()).collect::<Vec<_>>()),
            (C::MAX_G, pixels.iter().map(|p| p.g()).collect()),
            (C::MAX_B, pixels.iter().map(|p| p.b()).collect()),
        ] {
            let (low, frac) = (exact(max).floor(), exact(max).fract());
            let high = levels
                .iter()
                .filter(|&&l| f64::from(l) == low + 1.0)
                .count();
            assert!(
                levels
                    .iter()
                    .all(|&l| f64::from(l) == low || f64::from(l) == low + 1.0),
                "{value} of {max}: {levels:?}"
            );
            assert!(
                (high as f64 - 64.0 * frac).abs() <= 1.0,
                "{value} of {max}: {high} of 64 high, fraction {frac}"
            );
        }
        if C::MAX_R == C::MAX_G && C::MAX_G == C::MAX_B {
            assert!(pixels.iter().all(|p| p.r() == p.g() && p.g() == p.b()));
        }
    }
    for value in [1, 37, 100, 128, 200, 254] {
        check::<Rgb555>(value);
        check::<Bgr555>(value);
        check::<Rgb666>(value);
        check::<Bgr666>(value);
    }
}

/// A mid grey on a four-level display shows levels 1 and 2 in a checkered pattern, about half
/// each, rather than one flat level.
#[test]
fn a_mid_grey_on_gray2_shows_both_neighbouring_levels() {
    let grey = Rgb::new(128, 128, 128); // 128 / 255 · 3 = 1.506 levels
    let levels: Vec<u8> = tile().map(|p| Gray2::from_rgb(grey, p).luma()).collect();
    assert!(levels.iter().all(|&l| l == 1 || l == 2), "{levels:?}");
    let twos = levels.iter().filter(|&&l| l == 2).count();
    assert!((31..=33).contains(&twos), "{twos} of 64 at level 2");
    // Neighbours differ: in the top row of the tile the levels alternate.
    assert!(
        levels[..8].windows(2).all(|w| w[0] != w[1]),
        "{:?}",
        &levels[..8]
    );
}
