//! Clipping a placed picture to a display, so hidden pixels are neither traced nor sent.

use core::ops::Range;

use embedded_graphics::prelude::{Point, Size};
use embedded_graphics::primitives::Rectangle;

/// The columns and rows of a picture of `size` pixels, its top left pixel at display point
/// `top_left`, that lie on `bounds` (a display's bounding box), counted from the picture's
/// top left: `(columns, rows)`, either empty when nothing shows.
///
/// The sums are in `i64`, so no place or size overflows. A pixel is kept only below
/// `i32::MAX` on both axes: a rectangle reaching `i32::MAX` has a far corner embedded-graphics
/// cannot compute, and no display has a pixel there.
pub(crate) fn visible(top_left: Point, size: Size, bounds: &Rectangle) -> (Range<u32>, Range<u32>) {
    let axis = |at: i32, len: u32, start: i32, extent: u32| {
        let (at, start) = (i64::from(at), i64::from(start));
        let first = at.max(start);
        let end = (at + i64::from(len))
            .min(start + i64::from(extent))
            .min(i64::from(i32::MAX));
        // Both ends within 0 ..= len of `at`, so the differences fit u32.
        let (first, end) = (
            (first - at).clamp(0, len.into()),
            (end - at).clamp(0, len.into()),
        );
        if first < end {
            first as u32..end as u32
        } else {
            0..0
        }
    };
    (
        axis(top_left.x, size.width, bounds.top_left.x, bounds.size.width),
        axis(
            top_left.y,
            size.height,
            bounds.top_left.y,
            bounds.size.height,
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn display(w: u32, h: u32) -> Rectangle {
        Rectangle::new(Point::zero(), Size::new(w, h))
    }

    #[test]
    fn a_picture_larger_than_the_display_keeps_the_display() {
        // 400 × 300 at the origin of 320 × 240: 320 columns and 240 rows show.
        let (cols, rows) = visible(Point::zero(), Size::new(400, 300), &display(320, 240));
        assert_eq!((cols, rows), (0..320, 0..240));
    }

    #[test]
    fn each_side_is_cut_where_it_leaves_the_display() {
        let size = Size::new(10, 8);
        let d = display(20, 16);
        assert_eq!(visible(Point::new(-3, -5), size, &d), (3..10, 5..8));
        assert_eq!(visible(Point::new(15, 12), size, &d), (0..5, 0..4));
        assert_eq!(visible(Point::new(4, 4), size, &d), (0..10, 0..8));
        // Off the display on any side: nothing, not a wrapped range.
        for at in [
            Point::new(-10, 0),
            Point::new(20, 0),
            Point::new(0, -8),
            Point::new(0, 16),
        ] {
            let (cols, rows) = visible(at, size, &d);
            assert!(cols.is_empty() || rows.is_empty(), "{at:?}");
        }
        // A display that does not start at the origin.
        let offset = Rectangle::new(Point::new(-100, 50), Size::new(30, 30));
        assert_eq!(visible(Point::new(-95, 45), size, &offset), (0..10, 5..8));
    }

    #[test]
    fn the_ends_of_i32_do_not_overflow() {
        let huge = Rectangle::new(
            Point::new(i32::MIN, i32::MIN),
            Size::new(u32::MAX, u32::MAX),
        );
        let size = Size::new(u32::MAX, 8);
        assert_eq!(
            visible(Point::new(i32::MAX - 4, i32::MIN), size, &huge),
            (0..4, 0..8)
        );
        assert_eq!(visible(Point::new(i32::MAX, 0), size, &huge), (0..0, 0..8));
        assert_eq!(
            visible(
                Point::new(i32::MIN, 0),
                Size::new(4, 4),
                &display(u32::MAX, u32::MAX)
            ),
            (0..0, 0..4)
        );
    }
}
