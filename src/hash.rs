//! [`FrameHash`]: a digest of a frame's bytes, the same on the host and on every chip.

use crate::scene::colour::Rgb;

/// FNV-1a (32-bit) over a frame's bytes, fed one row at a time.
///
/// Firmware that streams rows and never holds a frame can still prove its picture equals the
/// host's: both feed the same `r, g, b` bytes in the same order and compare the digests.
///
/// ```
/// use fixray::{FrameHash, Rgb};
/// let mut whole = FrameHash::new();
/// whole.update(&[Rgb::new(1, 2, 3), Rgb::new(4, 5, 6)]);
/// let mut split = FrameHash::new();
/// split.update(&[Rgb::new(1, 2, 3)]);
/// split.update(&[Rgb::new(4, 5, 6)]);
/// assert_eq!(whole.finish(), split.finish());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FrameHash {
    state: u32,
}

impl FrameHash {
    const OFFSET_BASIS: u32 = 0x811c_9dc5;
    const PRIME: u32 = 0x0100_0193;

    /// A digest of no bytes yet.
    #[must_use]
    pub const fn new() -> Self {
        FrameHash {
            state: Self::OFFSET_BASIS,
        }
    }

    /// Feeds the bytes of `pixels`, in order.
    pub fn update(&mut self, pixels: &[Rgb]) {
        for p in pixels {
            for byte in [p.r, p.g, p.b] {
                self.state = (self.state ^ byte as u32).wrapping_mul(Self::PRIME);
            }
        }
    }

    /// The digest so far.
    #[must_use]
    pub const fn finish(&self) -> u32 {
        self.state
    }
}

impl Default for FrameHash {
    fn default() -> Self {
        Self::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn known_fnv1a_vectors() {
        // Published FNV-1a test vectors: "" and "a", "foobar" (as the bytes of two pixels).
        assert_eq!(FrameHash::new().finish(), 0x811c_9dc5);
        let mut h = FrameHash::new();
        h.update(&[Rgb::new(b'f', b'o', b'o'), Rgb::new(b'b', b'a', b'r')]);
        assert_eq!(h.finish(), 0xbf9c_f968);
    }
}
