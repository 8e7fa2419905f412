//! Sets of up to 64 objects, bit `i` for object `i`, as the culling keeps them: a bit by its
//! index with 32-bit shifts only, since a 64-bit shift by a variable amount is a library call
//! on the Cortex-M0.

/// The set of object `i` alone, for `i` below 64.
#[inline]
pub(crate) const fn bit(i: usize) -> u64 {
    debug_assert!(i < 64, "bits::bit: no object's bit past the 64th");
    let one = 1u64 << (i & 31);
    if i < 32 { one } else { one << 32 }
}

/// Whether `set` holds object `i`, for `i` below 64.
#[inline]
pub(crate) const fn has(set: u64, i: usize) -> bool {
    debug_assert!(i < 64, "bits::has: no object's bit past the 64th");
    // A shift in each branch: a word chosen first and then shifted was folded back into a
    // 64-bit shift by a variable amount, the library call this module is here to avoid.
    if i < 32 {
        (set as u32 >> i) & 1 != 0
    } else {
        ((set >> 32) as u32 >> (i - 32)) & 1 != 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bits_are_the_shifted_ones() {
        let sets = [0, !0, 0x8000_0001_8000_0001, 0x5555_5555_aaaa_aaaa, 1 << 63];
        for i in 0..64 {
            assert_eq!(bit(i), 1u64 << i, "bit {i}");
            for set in sets {
                assert_eq!(has(set, i), set & (1 << i) != 0, "{set:x} has {i}");
            }
        }
    }
}
