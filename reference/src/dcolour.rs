//! Colours while they are being summed: one float a channel, 1.0 standing for 255.

use super::{DVec3, Real};
use fixray::{Background, Rgb};

/// A colour in linear units: red, green, blue, each 1.0 for a channel of 255.
///
/// Light adds up in these units (several lights, a highlight, a mirror image) and may pass
/// 1.0 on the way; only the final pixel is clamped and rounded, by
/// [`DScene::shade`](super::DScene::shade).
pub type DColour<F = f64> = [F; 3];

/// An 8-bit colour in linear units: `c/255`.
#[must_use]
pub(super) fn linear<F: Real>(c: Rgb) -> DColour<F> {
    [c.r, c.g, c.b].map(|c| F::from_u16(u16::from(c)) / F::from_f64(255.0))
}

/// The pixel for a summed colour: each channel `clamp(round(x·255), 0, 255)`, rounding half
/// away from zero (which is half up for the non-negative values shading produces). NaN, which
/// no valid scene produces, gives 0.
#[must_use]
pub(super) fn to_rgb<F: Real>(c: DColour<F>) -> Rgb {
    let channel = |x: F| {
        let x = (x * F::from_f64(255.0)).round();
        // Written as comparisons so that NaN, which fails both, becomes 0.
        if x >= F::from_f64(255.0) {
            255
        } else if x > F::ZERO {
            x.to_u8()
        } else {
            0
        }
    };
    Rgb::new(channel(c[0]), channel(c[1]), channel(c[2]))
}

/// What a ray escaping along the unit direction `dir` sees: `bottom` straight down, `top`
/// straight up, and in between `bottom + (top − bottom)·s` with `s = (dir.y + 1)/2`.
#[must_use]
pub(super) fn background<F: Real>(sky: &Background, dir: DVec3<F>) -> DColour<F> {
    let s = (dir.y + F::ONE) / F::TWO;
    let (bottom, top) = (linear::<F>(sky.bottom), linear::<F>(sky.top));
    [0, 1, 2].map(|i| bottom[i] + (top[i] - bottom[i]) * s)
}

/// `sum + weight·c`, channel by channel.
pub(super) fn add_weighted<F: Real>(sum: &mut DColour<F>, weight: F, c: DColour<F>) {
    for (s, c) in sum.iter_mut().zip(c) {
        *s += weight * c;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_channel_survives_the_round_trip() {
        for c in 0..=255u8 {
            let grey = Rgb::new(c, c, c);
            assert_eq!(to_rgb(linear::<f64>(grey)), grey);
        }
    }

    #[test]
    fn pixels_round_half_up_and_clamp() {
        // 0.5/255 and 1.5/255 are halfway: up to 1 and 2. Out of range clamps.
        assert_eq!(
            to_rgb([0.5 / 255.0, 1.5 / 255.0, 1.2 / 255.0]),
            Rgb::new(1, 2, 1)
        );
        assert_eq!(to_rgb([-0.3, 7.0, f64::NAN]), Rgb::new(0, 255, 0));
    }

    #[test]
    fn the_gradient_runs_from_bottom_to_top() {
        let sky = Background {
            top: Rgb::new(255, 0, 100),
            bottom: Rgb::new(55, 200, 100),
        };
        assert_eq!(to_rgb(background(&sky, <DVec3>::Y)), sky.top);
        assert_eq!(to_rgb(background(&sky, -<DVec3>::Y)), sky.bottom);
        // Level rays see the mean: (255 + 55)/2 = 155, (0 + 200)/2 = 100.
        assert_eq!(
            to_rgb(background(&sky, <DVec3>::X)),
            Rgb::new(155, 100, 100)
        );
        // 30° up: s = (0.5 + 1)/2 = 0.75, so red is 55 + 200·0.75 = 205.
        let up30 = DVec3::new(libm::sqrt(0.75), 0.5, 0.0);
        assert_eq!(to_rgb(background(&sky, up30)), Rgb::new(205, 50, 100));
    }
}
