//! [`XorShift`]: the tests' source of many varied inputs, the same on every run.

/// Marsaglia's xorshift64 (shifts 13, 7, 17): deterministic, and every state but zero is
/// followed by another.
pub(crate) struct XorShift(pub(crate) u64);

impl XorShift {
    /// The next state, which is also the value drawn.
    pub(crate) fn next(&mut self) -> u64 {
        let s = &mut self.0;
        *s ^= *s << 13;
        *s ^= *s >> 7;
        *s ^= *s << 17;
        *s
    }

    /// A value drawn evenly from `−range..range`, from the state's top 24 bits.
    pub(crate) fn signed(&mut self, range: f32) -> f32 {
        ((self.next() >> 40) as f32 / (1u64 << 24) as f32 * 2.0 - 1.0) * range
    }
}
