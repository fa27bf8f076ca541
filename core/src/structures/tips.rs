//! The fast walk's candidate tips: the nodes of the ring being clipped by their position
//! in it, and a set of positions holding at least those the walk still has to look at
//! (live, not marked "not an ear"), so that a step to the next one costs O(log₆₄ n) however
//! many marked tips lie in between. Without it, a ring whose ears all lie behind the walk
//! (a comb's spine, fanned from a corner) costs a lap over marked tips per cut.
//!
//! Clipping only removes nodes from a ring, so the ring order of the live nodes stays that
//! of the positions handed out when the walk starts.

use crate::structures::NodeId;

/// Levels of the bit set: 64⁶ = 2³⁶ positions, more than there are node ids.
const LEVELS: usize = 6;

/// Ring positions with a set of them (see the module docs).
#[derive(Debug, Default)]
pub(crate) struct Tips {
    /// The node at each position.
    at: Vec<NodeId>,
    /// Each node's position, by node id; valid only where `at` holds the node there.
    pos: Vec<u32>,
    /// `bits[0]` has a bit per position, set for members; `bits[k + 1]` a bit per word of
    /// `bits[k]`, set where that word is not zero.
    bits: [Vec<u64>; LEVELS],
    /// Levels in use: up to the first one of a single word (0 for no positions).
    depth: usize,
}

impl Tips {
    /// Forgets the positions; `nodes_total` bounds the node ids that will be pushed.
    pub fn clear(&mut self, nodes_total: usize) {
        self.at.clear();
        if self.pos.len() < nodes_total {
            self.pos.resize(nodes_total, 0);
        }
        for level in &mut self.bits {
            level.clear();
        }
        self.depth = 0;
    }

    /// Gives `n` the next position, not a member yet; call [`Tips::fill`] after the last.
    pub fn push(&mut self, n: NodeId) {
        if let Some(slot) = self.pos.get_mut(n.idx()) {
            *slot = self.at.len() as u32;
            self.at.push(n);
        }
    }

    /// Number of positions.
    pub fn len(&self) -> usize {
        self.at.len()
    }

    /// Makes exactly the nodes for which `member` holds members.
    pub fn fill(&mut self, mut member: impl FnMut(NodeId) -> bool) {
        let mut words = self.at.len().div_ceil(64);
        self.depth = 0;
        while words > 0 && self.depth < LEVELS {
            self.bits[self.depth].clear();
            self.bits[self.depth].resize(words, 0);
            self.depth += 1;
            if words == 1 {
                break;
            }
            words = words.div_ceil(64);
        }
        for (i, &n) in self.at.iter().enumerate() {
            if member(n) {
                self.bits[0][i / 64] |= 1 << (i % 64);
            }
        }
        for k in 1..self.depth {
            let (below, level) = self.bits.split_at_mut(k);
            for (i, &word) in below[k - 1].iter().enumerate() {
                if word != 0 {
                    level[0][i / 64] |= 1 << (i % 64);
                }
            }
        }
    }

    /// The position of `n`, if it has one.
    #[inline]
    pub fn position(&self, n: NodeId) -> Option<usize> {
        let p = *self.pos.get(n.idx())? as usize;
        (self.at.get(p) == Some(&n)).then_some(p)
    }

    /// The node at position `p` (which must be one).
    #[inline]
    pub fn node(&self, p: usize) -> NodeId {
        self.at[p]
    }

    /// Makes `n` a member (if it has a position).
    pub fn insert(&mut self, n: NodeId) {
        let Some(mut i) = self.position(n) else {
            return;
        };
        for level in &mut self.bits[..self.depth] {
            let word = &mut level[i / 64];
            let was = *word;
            *word |= 1 << (i % 64);
            if was != 0 {
                break;
            }
            i /= 64;
        }
    }

    /// Makes `n` no member (if it has a position).
    pub fn remove(&mut self, n: NodeId) {
        let Some(mut i) = self.position(n) else {
            return;
        };
        for level in &mut self.bits[..self.depth] {
            let word = &mut level[i / 64];
            *word &= !(1 << (i % 64));
            if *word != 0 {
                break;
            }
            i /= 64;
        }
    }

    /// The first member at position `p` or after it (not wrapping round).
    fn first_from(&self, p: usize) -> Option<usize> {
        let mut i = p;
        let mut k = 0;
        // up until a word has a member at or after `i`...
        loop {
            if k == self.depth {
                return None;
            }
            let word = *self.bits[k].get(i / 64)? & (!0u64 << (i % 64));
            if word != 0 {
                i = i / 64 * 64 + word.trailing_zeros() as usize;
                break;
            }
            i = i / 64 + 1;
            k += 1;
        }
        // ...then down to its first member
        while k > 0 {
            k -= 1;
            i = i * 64 + self.bits[k][i].trailing_zeros() as usize;
        }
        Some(i)
    }

    /// The first member after position `p` in ring order, wrapping round (`p` itself only
    /// when it is the sole member).
    pub fn next_after(&self, p: usize) -> Option<usize> {
        self.first_from(p + 1).or_else(|| self.first_from(0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn next_after_visits_exactly_the_members() {
        let mut random = crate::testing::random(0x2545_f491_4f6c_dd1d);
        let mut tips = Tips::default();
        // sizes around the word and level boundaries
        for len in [1, 2, 63, 64, 65, 300, 4095, 4096, 4097, 20_000] {
            // positions in a shuffled order of node ids, as a ring after bridging has them
            let mut ids: Vec<u32> = (0..len as u32).collect();
            for i in (1..ids.len()).rev() {
                ids.swap(i, random(i as u64 + 1) as usize);
            }
            tips.clear(len + 5);
            for &id in &ids {
                tips.push(NodeId(id));
            }
            assert_eq!(tips.len(), len);
            let density = 1 + random(20);
            let mut member: Vec<bool> = (0..len).map(|_| random(density) == 0).collect();
            let mut position = vec![0; len];
            for (p, &id) in ids.iter().enumerate() {
                position[id as usize] = p;
            }
            tips.fill(|n| member[position[n.idx()]]);
            for _ in 0..2_000 {
                let p = random(len as u64) as usize;
                let n = NodeId(ids[p]);
                assert_eq!(tips.position(n), Some(p));
                assert_eq!(tips.node(p), n);
                match random(3) {
                    0 => {
                        tips.insert(n);
                        member[p] = true;
                    }
                    1 => {
                        tips.remove(n);
                        member[p] = false;
                    }
                    _ => {}
                }
                let q = random(len as u64) as usize;
                let expected = (1..=len).map(|d| (q + d) % len).find(|&m| member[m]);
                assert_eq!(tips.next_after(q), expected, "len {len}, from {q}");
            }
            // nodes without a position change nothing
            tips.insert(NodeId(len as u32 + 3));
            tips.remove(NodeId(len as u32 + 100));
            assert_eq!(tips.position(NodeId(len as u32 + 3)), None);
        }
    }
}
