//! [`Crowd`]: a row's objects in a scene that may hold more than 64, named by the row's own
//! 64 bits.
//!
//! The culling keeps its sets as 64-bit masks, a bit an object (`runs`, `cull`). In a scene of
//! up to 64 objects bit `i` is object `i`. In a larger one, each row gives its bits to the
//! objects its rays can meet (`Runs::crowded`: the planes, and the spheres near the row's plane
//! whose columns reach the screen), in order, and keeps here which object each bit stands for:
//! the runs, the planes' tests and a ray's nearest hit then work as in a small scene, each ray
//! meeting the objects near it, however many the scene holds. A row that can meet more than
//! 64 keeps the rest as extras, which every ray of the row tries. Only scenes whose capacity
//! passes 64 build one: the render path of smaller ones names objects [`ByIndex`], which
//! takes no room and compiles to the code it was before crowds.

use crate::render::accel::run_ends::RunEnds;

/// Which object each of a row's bits stands for, and the row's extras.
pub(crate) struct Crowd<const N: usize> {
    /// `objects[i]`: the object bit `i` stands for.
    objects: [u32; 64],
    /// The objects the row can meet past the 64 that have bits, in `extra[..extras]`.
    extra: [u32; N],
    extras: usize,
    /// The ends of the row's spans, by bit (`Runs::crowded`).
    ends: RunEnds,
}

impl<const N: usize> Crowd<N> {
    /// No object yet.
    pub(crate) const fn empty() -> Self {
        Crowd {
            objects: [0; 64],
            extra: [0; N],
            extras: 0,
            ends: RunEnds::empty(),
        }
    }

    /// Keeps the ends of the spans `spans[bit]` of the bits of `bounded`, sorted.
    pub(crate) fn sort_ends(&mut self, bounded: u64, spans: &[(i16, i16)]) {
        self.ends = RunEnds::new(bounded, spans);
    }

    /// Gives the next bit, `bit`, to object `index`, or, from the 65th, makes it an extra.
    pub(crate) fn add(&mut self, bit: usize, index: usize) {
        match self.objects.get_mut(bit) {
            Some(slot) => *slot = index as u32,
            None => {
                if let Some(slot) = self.extra.get_mut(self.extras) {
                    *slot = index as u32;
                    self.extras += 1;
                }
            }
        }
    }

    /// The object bit `bit` stands for.
    pub(crate) fn object(&self, bit: usize) -> usize {
        self.objects
            .get(bit)
            .map_or(usize::MAX, |&index| index as usize)
    }

    /// The objects every ray of the row tries, past those with bits.
    pub(crate) fn extras(&self) -> &[u32] {
        self.extra.get(..self.extras).unwrap_or(&[])
    }
}

/// How a row's bits name objects: [`ByIndex`] or a row's [`Crowd`].
pub(crate) trait Names: Copy {
    /// Whether the bits are a crowd's: every bit set stands for an object the scene has.
    const CROWD: bool;

    /// The object bit `bit` stands for.
    fn object(self, bit: usize) -> usize;

    /// The objects every ray of the row tries besides its set.
    fn extras(&self) -> &[u32];

    /// Whether a ray's set is all it tries, in a scene of `count` objects.
    fn alone(self, count: usize) -> bool;

    /// Of the bits with spans, those whose spans hold column `col`, and the first column past
    /// it where a span starts or ends ([`RunEnds::at`]); `None` where the ends are not kept
    /// and the spans are to be taken one by one.
    fn ends_at(self, col: i16) -> Option<(u64, i16)>;
}

/// Bit `i` is object `i`; objects past the 64th have none, and every ray tries them.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ByIndex;

impl Names for ByIndex {
    const CROWD: bool = false;

    fn object(self, bit: usize) -> usize {
        bit
    }

    fn extras(&self) -> &[u32] {
        &[]
    }

    fn alone(self, count: usize) -> bool {
        count <= 64
    }

    fn ends_at(self, _col: i16) -> Option<(u64, i16)> {
        None
    }
}

impl<const N: usize> Names for &Crowd<N> {
    const CROWD: bool = true;

    fn object(self, bit: usize) -> usize {
        Crowd::object(self, bit)
    }

    fn extras(&self) -> &[u32] {
        Crowd::extras(self)
    }

    fn alone(self, _count: usize) -> bool {
        Crowd::extras(self).is_empty()
    }

    fn ends_at(self, col: i16) -> Option<(u64, i16)> {
        Some(self.ends.at(col))
    }
}
