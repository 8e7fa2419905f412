//! [`RunEnds`]: a crowded row's span ends sorted by column, so that the walk along the row
//! finds each run from the ends it passes, not from every span.
//!
//! `Runs::next_run` finds a run from the column it starts at: the spans holding that column
//! are in, the others out, and the run ends at the nearest span end past it. Done span by
//! span, that is a pass over the row's 64 bits for every run, and a crowded row has many
//! runs. Here each span is an entry at its first column and a leave at the column after its
//! last, sorted once a row; a walk from left to right then takes each in turn, and the run
//! from a column is the set the entries and leaves up to it leave in, ending at the next one.
//! The sets and ends are those of the span by span pass exactly, for any column asked.

use core::cell::Cell;

/// A row's span ends by column, and where the walk along them stands.
pub(crate) struct RunEnds {
    /// Each end as `(column + 2¹⁵) << 8 | enters << 6 | bit`, sorted: the column, whether bit
    /// `bit`'s span starts there (or ends before it), and the bit.
    ends: [u32; 128],
    len: usize,
    /// The ends `ends[..passed]` have been taken, into `inside`, the bits whose spans they
    /// leave holding the column `at`; every one lies at or before `at`.
    passed: Cell<usize>,
    inside: Cell<u64>,
    at: Cell<i16>,
}

/// Set in an end where its span starts.
const ENTERS: u32 = 1 << 6;

impl RunEnds {
    /// No span.
    pub(crate) const fn empty() -> Self {
        RunEnds {
            ends: [0; 128],
            len: 0,
            passed: Cell::new(0),
            inside: Cell::new(0),
            at: Cell::new(i16::MIN),
        }
    }

    /// The ends of the spans `spans[bit]` of the bits of `bounded` (inclusive columns), sorted.
    /// A span whose last column comes before its first holds none, and ends at its first.
    pub(crate) fn new(bounded: u64, spans: &[(i16, i16)]) -> Self {
        let mut ends = RunEnds::empty();
        let mut rest = bounded;
        while rest != 0 {
            let bit = rest.trailing_zeros();
            rest &= rest - 1;
            let Some(&(first, last)) = spans.get(bit as usize) else {
                continue; // not reached: a bit of `bounded` has a span
            };
            match first <= last {
                true => {
                    ends.push(first, ENTERS | bit);
                    ends.push(last.saturating_add(1), bit);
                }
                false => ends.push(first, bit),
            }
        }
        if let Some(found) = ends.ends.get_mut(..ends.len) {
            found.sort_unstable();
        }
        ends
    }

    fn push(&mut self, column: i16, what: u32) {
        if let Some(slot) = self.ends.get_mut(self.len) {
            *slot = ((i32::from(column) + (1 << 15)) as u32) << 8 | what;
            self.len += 1;
        }
    }

    /// Of the bits with spans, those whose spans hold column `col`, and the first column past
    /// `col` where a span starts or ends (`i16::MAX` if none): taken on from the last column
    /// asked if `col` is not before it, else from the row's start.
    pub(crate) fn at(&self, col: i16) -> (u64, i16) {
        let (mut passed, mut inside) = match self.at.get() <= col {
            true => (self.passed.get(), self.inside.get()),
            false => (0, 0),
        };
        let ends = self.ends.get(..self.len).unwrap_or(&[]);
        let mut next = i16::MAX;
        while let Some(&end) = ends.get(passed) {
            let column = ((end >> 8) as i32 - (1 << 15)) as i16;
            if column > col {
                next = column;
                break;
            }
            let bit = 1u64 << (end & 63);
            inside = match end & ENTERS {
                0 => inside & !bit,
                _ => inside | bit,
            };
            passed += 1;
        }
        self.passed.set(passed);
        self.inside.set(inside);
        self.at.set(col);
        (inside, next)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The span by span pass of `Runs::next_run`: the bits whose spans hold `col`, and the
    /// nearest span end past it.
    fn span_by_span(bounded: u64, spans: &[(i16, i16)], col: i16) -> (u64, i16) {
        let (mut inside, mut until) = (0, i16::MAX);
        for (bit, &(first, last)) in spans.iter().enumerate() {
            if (bounded >> bit) & 1 == 0 {
                continue;
            }
            if col < first {
                until = until.min(first);
            } else if col <= last {
                inside |= 1 << bit;
                until = until.min(last.saturating_add(1));
            }
        }
        (inside, until)
    }

    #[test]
    fn every_column_asked_in_any_order_finds_the_spans_that_hold_it() {
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut draw = |range: i32| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 33) as i32 % range
        };
        for _ in 0..200 {
            let count = draw(65) as usize;
            let spans: [(i16, i16); 64] = core::array::from_fn(|_| {
                let first = draw(400) - 150;
                // Some spans empty (last before first), some reaching the largest column.
                let last = match draw(20) {
                    0 => first - 1 - draw(5),
                    1 => i32::from(i16::MAX),
                    _ => first + draw(60),
                };
                (first as i16, last as i16)
            });
            let bounded = match count {
                64 => !0,
                _ => ((1u64 << count) - 1) & !(draw(1 << 30) as u64),
            };
            let ends = RunEnds::new(bounded, &spans);
            // A walk from left to right, then columns in any order.
            let mut col = 0i16;
            while col < 200 {
                let (inside, next) = ends.at(col);
                assert_eq!((inside, next), span_by_span(bounded, &spans, col), "{col}");
                assert!(next > col);
                col = next.min(200);
            }
            for _ in 0..50 {
                let col = draw(250) as i16;
                assert_eq!(ends.at(col), span_by_span(bounded, &spans, col), "{col}");
            }
        }
    }

    #[test]
    fn a_row_without_spans_has_no_ends() {
        let ends = RunEnds::new(0, &[(0, 5); 4]);
        assert_eq!(ends.at(3), (0, i16::MAX));
    }
}
