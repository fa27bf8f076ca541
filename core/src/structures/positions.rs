//! Positions found by their exact coordinates: an open-addressing table (linear probing)
//! of indices into a caller's list of positions.

/// An empty slot.
pub(crate) const EMPTY: u32 = u32::MAX;

/// Empties `table` and sizes it for `count` positions: a power of two, at least twice
/// `count`, so that a probe always ends at an empty slot.
pub(crate) fn reset_table(table: &mut Vec<u32>, count: usize) {
    table.clear();
    table.resize((2 * count).next_power_of_two().max(2), EMPTY);
}

/// The slot of `table` (sized by [`reset_table`]) whose entry lies at `p` (`at(entry)`
/// says where an entry lies), or the empty slot where an entry at `p` would go. Equal
/// positions (−0.0 read as +0.0 by the caller) have equal bits, so they meet.
#[inline]
pub(crate) fn slot(table: &[u32], p: [f64; 2], at: impl Fn(u32) -> [f64; 2]) -> usize {
    let bits = table.len().trailing_zeros();
    // (the bits of both coordinates mixed, the product's top bits taken: its low bits
    // see only the factors' low bits, which round coordinates leave zero)
    let mix = (p[0].to_bits() ^ p[1].to_bits().rotate_left(29)).wrapping_mul(0x9e37_79b9_7f4a_7c15);
    let mut i = (mix >> (64 - bits)) as usize;
    loop {
        let k = table[i];
        if k == EMPTY || at(k) == p {
            return i;
        }
        i = (i + 1) & (table.len() - 1);
    }
}
