//! The quality strategy's priority queue of ear tips, by angle at the tip.

use crate::structures::NodeId;

/// The quality strategy's queue of candidate ears, smallest first: entries packed by
/// [`ear`], so that one integer comparison orders them by angle, then node. A node has at
/// most one entry: queuing it again moves its entry (a neighbour's cut changes its angle),
/// so no outdated entries pile up to be popped and skipped. A 4-ary heap: popping from a
/// queue of a million ears touches half as many levels as a binary heap, and a node's
/// four children share a cache line.
#[derive(Debug, Default)]
pub(super) struct EarQueue {
    items: Vec<u64>,
    /// By node: the index of its entry in `items`, if `items` holds one there (stale
    /// indices are told by the node the entry names, so none are ever cleared).
    at: Vec<u32>,
}

/// A queue entry: the tip's angle rank (non-negative, so its bit pattern orders as the
/// number; the sign bit dropped, then the top 32 bits of the rest, which tells ranks
/// apart down to a relative 2⁻²¹) above the node id. Ranks closer than that tie, and
/// then the node decides, as for equal ranks.
pub(super) fn ear(rank: f64, n: NodeId) -> u64 {
    (rank.to_bits() << 1) >> 32 << 32 | u64::from(n.0)
}

/// The node of a queue entry, as an index.
pub(super) fn ear_node(item: u64) -> usize {
    item as u32 as usize
}

impl EarQueue {
    /// Empties the queue, for nodes `0..nodes`.
    pub(super) fn clear(&mut self, nodes: usize) {
        self.items.clear();
        if self.at.len() < nodes {
            self.at.resize(nodes, 0);
        }
    }

    /// Queues `item`, or moves its node's entry to it; ignores nodes past those the queue
    /// was cleared for.
    pub(super) fn set(&mut self, item: u64) {
        let Some(&i) = self.at.get(ear_node(item)) else {
            return;
        };
        let i = i as usize;
        match self.items.get(i) {
            Some(&old) if ear_node(old) == ear_node(item) => {
                if item < old {
                    self.sift_up(i, item);
                } else {
                    self.sift_down(i, item);
                }
            }
            _ => {
                self.items.push(item);
                self.sift_up(self.items.len() - 1, item);
            }
        }
    }

    /// Puts `item` at index `i`, recording where its node's entry is.
    #[inline]
    fn place(&mut self, i: usize, item: u64) {
        self.items[i] = item;
        self.at[ear_node(item)] = i as u32;
    }

    /// Moves `item`, meant for index `i`, up past the entries above it that are larger.
    fn sift_up(&mut self, mut i: usize, item: u64) {
        while i > 0 {
            let parent = (i - 1) / 4;
            let above = self.items[parent];
            if above <= item {
                break;
            }
            self.place(i, above);
            i = parent;
        }
        self.place(i, item);
    }

    /// The index of the least child of `i`, and that child; `None` for a leaf.
    #[inline]
    fn least_child(&self, i: usize) -> Option<(usize, u64)> {
        let first = 4 * i + 1;
        match self.items.get(first..first + 4) {
            // all four children: a tournament, two independent comparisons first
            Some(&[a, b, c, d]) => {
                let (one, x) = if b < a { (first + 1, b) } else { (first, a) };
                let (two, y) = if d < c {
                    (first + 3, d)
                } else {
                    (first + 2, c)
                };
                Some(if y < x { (two, y) } else { (one, x) })
            }
            _ => {
                let children = self.items.get(first..)?;
                let (k, &least) = children.iter().enumerate().min_by_key(|&(_, &c)| c)?;
                Some((first + k, least))
            }
        }
    }

    /// Moves `item`, meant for index `i`, down past the entries below it that are smaller.
    fn sift_down(&mut self, mut i: usize, item: u64) {
        while let Some((child, least)) = self.least_child(i) {
            if item <= least {
                break;
            }
            self.place(i, least);
            i = child;
        }
        self.place(i, item);
    }

    pub(super) fn pop(&mut self) -> Option<u64> {
        let last = self.items.pop()?;
        let Some(&top) = self.items.first() else {
            return Some(last);
        };
        // Floyd's bottom-up pop: move the hole at the root down to a leaf, always to the
        // least child, without comparing with `last` (which came from the end, so usually
        // belongs near the bottom), then sift `last` up from there
        let mut i = 0;
        while let Some((child, least)) = self.least_child(i) {
            self.place(i, least);
            i = child;
        }
        self.sift_up(i, last);
        Some(top)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ear_queue_pops_the_least_entry_with_one_entry_per_node() {
        let mut random = crate::testing::random(0x9e37_79b9_7f4a_7c15);
        let mut queue = EarQueue::default();
        // the model: each node's entry, if queued
        let mut model = std::collections::BTreeMap::new();
        let least = |model: &std::collections::BTreeMap<u32, u64>| model.values().min().copied();
        for round in 0..2 {
            queue.clear(40);
            model.clear();
            for _ in 0..20_000 {
                if random(3) < 2 {
                    // few distinct ranks and nodes: ties and moved entries happen
                    let node = random(40) as u32;
                    let item = ear(random(50) as f64 / 25.0, NodeId(node));
                    queue.set(item);
                    model.insert(node, item);
                } else {
                    let expected = least(&model);
                    if let Some(item) = expected {
                        model.remove(&(ear_node(item) as u32));
                    }
                    assert_eq!(queue.pop(), expected, "round {round}");
                }
            }
            while let Some(item) = least(&model) {
                model.remove(&(ear_node(item) as u32));
                assert_eq!(queue.pop(), Some(item));
            }
            assert_eq!(queue.pop(), None);
        }
    }

    #[test]
    fn ear_entries_order_by_rank_then_node() {
        let (a, b) = (NodeId(3), NodeId(70_000));
        assert!(ear(0.25, b) < ear(0.5, a));
        assert!(ear(0.5, a) < ear(0.5, b));
        assert!(ear(1.999, b) < ear(2.0, a));
        // ranks closer than 2^-21 relative tie, and the node decides
        assert!(ear(0.5 + 1e-9, a) < ear(0.5, b));
        assert_eq!(ear_node(ear(2.0, b)), b.idx());
    }
}
