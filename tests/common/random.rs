//! Randomness: where a case's choices come from ([`Source`]), and the seeded generator
//! `tests/hostile.rs` uses ([`XorShift`]); the fuzz target supplies its own `Source`.

/// Where the choices come from.
pub trait Source {
    /// The next 64 random bits (a fuzzer's input that has run out gives zeros).
    fn bits(&mut self) -> u64;

    /// A value in `0..n` (0 when `n` is 0).
    fn below(&mut self, n: u64) -> u64 {
        if n == 0 { 0 } else { self.bits() % n }
    }

    /// True one time in `n`.
    fn one_in(&mut self, n: u64) -> bool {
        self.below(n) == 0
    }

    /// A uniform `f32` in `[-range, range]`.
    fn uniform(&mut self, range: f32) -> f32 {
        let unit = (self.bits() >> 40) as f32 / (1u32 << 24) as f32; // [0, 1)
        (2.0 * unit - 1.0) * range
    }

    /// One of `items`.
    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len() as u64) as usize]
    }
}

/// Marsaglia's xorshift64 (shifts 13, 7, 17), started from a seed: the same cases on every run.
pub struct XorShift(pub u64);

impl XorShift {
    /// A generator for case `seed`; the seed is mixed (splitmix64) so neighbouring seeds give
    /// unrelated sequences, and never leaves the state zero.
    pub fn new(seed: u64) -> Self {
        let mut z = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        XorShift((z ^ (z >> 31)) | 1)
    }
}

impl Source for XorShift {
    fn bits(&mut self) -> u64 {
        let s = &mut self.0;
        *s ^= *s << 13;
        *s ^= *s >> 7;
        *s ^= *s << 17;
        *s
    }
}
