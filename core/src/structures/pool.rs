//! The node pool: every ring's vertices in one `Vec<Node>`, each ring a circular doubly
//! linked list by index. No pointers, no `unsafe`; removal only relinks.

use crate::geom::Point;

/// Index of a node in the pool.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) struct NodeId(pub u32);

impl NodeId {
    #[inline]
    pub const fn idx(self) -> usize {
        self.0 as usize
    }
}

/// One vertex occurrence. Bridging copies nodes, so one input vertex may have several.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Node {
    /// Position, widened to f64.
    pub p: Point,
    /// Index of the input vertex it stands for.
    pub vertex: u32,
    /// The ring (index into the triangulator's ring table) it was loaded into.
    pub ring: u32,
    pub prev: NodeId,
    pub next: NodeId,
    /// Unlinked from its ring.
    pub removed: bool,
    /// Clipping: the turn prev → self → next is not strictly counter-clockwise.
    pub reflex: bool,
    /// Lenient mode: the edge leaving this node crosses another edge; ears using it wait.
    pub crossed: bool,
    /// Clipping: failed the ear test, skip until a neighbour changes (paper §3.3).
    pub not_ear: bool,
    /// Bumped whenever the node's ear status may have changed (quality strategy's queue).
    pub stamp: u32,
}

impl Node {
    /// A fresh node between `prev` and `next`, with every flag clear.
    #[inline]
    fn new(p: Point, vertex: u32, ring: u32, prev: NodeId, next: NodeId) -> Self {
        Node {
            p,
            vertex,
            ring,
            prev,
            next,
            removed: false,
            reflex: false,
            crossed: false,
            not_ear: false,
            stamp: 0,
        }
    }
}

/// The pool: nodes plus list operations.
#[derive(Debug, Default)]
pub(crate) struct Pool {
    pub nodes: Vec<Node>,
}

impl Pool {
    pub fn clear(&mut self) {
        self.nodes.clear();
    }

    #[inline]
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    #[inline]
    pub fn get(&self, n: NodeId) -> &Node {
        &self.nodes[n.idx()]
    }

    #[inline]
    pub fn get_mut(&mut self, n: NodeId) -> &mut Node {
        &mut self.nodes[n.idx()]
    }

    #[inline]
    pub fn p(&self, n: NodeId) -> Point {
        self.nodes[n.idx()].p
    }

    #[inline]
    pub fn next(&self, n: NodeId) -> NodeId {
        self.nodes[n.idx()].next
    }

    #[inline]
    pub fn prev(&self, n: NodeId) -> NodeId {
        self.nodes[n.idx()].prev
    }

    /// Appends an unlinked node (its own ring of one) and returns its id.
    pub fn push(&mut self, p: Point, vertex: u32, ring: u32) -> NodeId {
        let id = NodeId(self.nodes.len() as u32);
        self.nodes.push(Node::new(p, vertex, ring, id, id));
        id
    }

    /// Appends one ring's nodes, given as positions with vertex indices, linked in order
    /// into a circular list; returns how many. (One `extend` of known length: no capacity
    /// check per node.)
    pub fn push_ring(
        &mut self,
        points: impl ExactSizeIterator<Item = (Point, u32)>,
        ring: u32,
    ) -> u32 {
        let first = self.nodes.len() as u32;
        self.nodes
            .extend((first..).zip(points).map(|(id, (p, vertex))| {
                let (prev, next) = (id.wrapping_sub(1), id.wrapping_add(1));
                Node::new(p, vertex, ring, NodeId(prev), NodeId(next))
            }));
        let count = self.nodes.len() as u32 - first;
        self.close_run(first, count);
        count
    }

    /// Links the nodes `first..first+count` (in pool order) into one circular list.
    pub fn link_run(&mut self, first: u32, count: u32) {
        if count == 0 {
            return;
        }
        let last = first + count - 1;
        let run = &mut self.nodes[first as usize..=last as usize];
        // no division per node: the ends are fixed up afterwards
        for (k, n) in (first..).zip(run.iter_mut()) {
            n.prev = NodeId(k.wrapping_sub(1));
            n.next = NodeId(k.wrapping_add(1));
        }
        self.close_run(first, count);
    }

    /// Closes the run `first..first+count`, linked in pool order, into a circle.
    fn close_run(&mut self, first: u32, count: u32) {
        if count == 0 {
            return;
        }
        let last = first + count - 1;
        self.nodes[first as usize].prev = NodeId(last);
        self.nodes[last as usize].next = NodeId(first);
    }

    /// Lays the nodes out again in the order the rings through `starts` visit them, each
    /// ring from its start, then every other node in pool order; `starts` and `renamed`
    /// (each node's new id by old id, as scratch) follow. Links, flags and positions move
    /// with the nodes. A walk along a ring then reads memory in order, which matters once
    /// the pool outgrows the caches.
    pub fn lay_out(
        &mut self,
        starts: &mut [NodeId],
        renamed: &mut Vec<u32>,
        spare: &mut Vec<Node>,
    ) {
        const UNSET: u32 = u32::MAX;
        renamed.clear();
        renamed.resize(self.nodes.len(), UNSET);
        spare.clear();
        for &start in starts.iter() {
            let mut n = start;
            // bounded, in case a start was unlinked
            for _ in 0..self.nodes.len() {
                let Some(id) = renamed.get_mut(n.idx()) else {
                    break;
                };
                if *id != UNSET {
                    break;
                }
                *id = spare.len() as u32;
                spare.push(self.nodes[n.idx()]);
                n = self.nodes[n.idx()].next;
            }
        }
        for (node, id) in self.nodes.iter().zip(renamed.iter_mut()) {
            if *id == UNSET {
                *id = spare.len() as u32;
                spare.push(*node);
            }
        }
        let rename = |n: NodeId| NodeId(renamed[n.idx()]);
        for node in spare.iter_mut() {
            (node.prev, node.next) = (rename(node.prev), rename(node.next));
        }
        for start in starts.iter_mut() {
            *start = rename(*start);
        }
        core::mem::swap(&mut self.nodes, spare);
    }

    /// Unlinks `n` from its ring; its neighbours become adjacent and may be ears again.
    pub fn remove(&mut self, n: NodeId) {
        let (prev, next) = (self.prev(n), self.next(n));
        self.get_mut(prev).next = next;
        self.get_mut(next).prev = prev;
        self.touch(prev);
        self.touch(next);
        self.get_mut(n).removed = true;
    }

    /// Marks a node's ear status as unknown (a neighbour changed).
    #[inline]
    pub fn touch(&mut self, n: NodeId) {
        let node = self.get_mut(n);
        node.not_ear = false;
        node.stamp = node.stamp.wrapping_add(1);
    }

    /// Inserts a new node right after `after`, on `after`'s ring.
    pub fn insert_after(&mut self, after: NodeId, p: Point, vertex: u32) -> NodeId {
        let ring = self.get(after).ring;
        let id = self.push(p, vertex, ring);
        let next = self.next(after);
        let n = self.get_mut(id);
        n.prev = after;
        n.next = next;
        self.get_mut(after).next = id;
        self.get_mut(next).prev = id;
        id
    }

    /// Inserts a copy of `n` (same position and vertex) right after `after`.
    fn copy_after(&mut self, n: NodeId, after: NodeId) -> NodeId {
        let node = *self.get(n);
        let id = self.insert_after(after, node.p, node.vertex);
        self.get_mut(id).ring = node.ring;
        id
    }

    /// Connects `a` and `b` by a diagonal, splitting their ring in two — or, when `a` and
    /// `b` are on different rings, merging them into one through a two-way bridge.
    /// Returns the copy of `b` that now ends the second ring (earcut's `splitPolygon`).
    ///
    /// Before: `… ap → a → an …` and `… bp → b → bn …`.
    /// After:  `… ap → a → b → bn …` and `… bp → b2 → a2 → an …`.
    pub fn split(&mut self, a: NodeId, b: NodeId) -> NodeId {
        let an = self.next(a);
        let bp = self.prev(b);
        let a2 = self.copy_after(a, a); // a → a2 → an
        let b2 = self.copy_after(b, bp); // bp → b2 → b
                                         // a2 takes over a's edge; the two bridge edges cross nothing
        self.get_mut(a).crossed = false;
        self.get_mut(b2).crossed = false;
        // a → b, b2 → a2
        self.get_mut(a).next = b;
        self.get_mut(b).prev = a;
        self.get_mut(b2).next = a2;
        self.get_mut(a2).prev = b2;
        self.get_mut(a2).next = an;
        self.get_mut(an).prev = a2;
        for n in [a, b, a2, b2] {
            self.touch(n);
        }
        b2
    }

    /// Reverses the direction of the ring through `start`.
    pub fn reverse(&mut self, start: NodeId) {
        let mut n = start;
        loop {
            let node = self.get_mut(n);
            core::mem::swap(&mut node.prev, &mut node.next);
            n = node.prev; // the old next
            if n == start {
                break;
            }
        }
    }

    /// [`Pool::reverse`] for a ring whose nodes are exactly the live ones of `range`: the
    /// same relinking, in pool order rather than along the links.
    pub fn reverse_live_in(&mut self, range: core::ops::Range<usize>) {
        for node in &mut self.nodes[range] {
            if !node.removed {
                core::mem::swap(&mut node.prev, &mut node.next);
            }
        }
    }

    /// Iterates the ring through `start`, beginning there.
    pub fn ring(&self, start: NodeId) -> RingIter<'_> {
        RingIter {
            pool: self,
            start,
            cur: Some(start),
        }
    }
}

/// Iterator over a ring's node ids.
pub(crate) struct RingIter<'a> {
    pool: &'a Pool,
    start: NodeId,
    cur: Option<NodeId>,
}

impl Iterator for RingIter<'_> {
    type Item = NodeId;
    fn next(&mut self) -> Option<NodeId> {
        let cur = self.cur?;
        let next = self.pool.next(cur);
        self.cur = if next == self.start { None } else { Some(next) };
        Some(cur)
    }
}

#[cfg(test)]
impl Pool {
    /// A pool holding the rings of (x, y), each linked into a cycle, and one start node
    /// per ring (for unit tests of the stages).
    pub(crate) fn from_rings<R: AsRef<[(f64, f64)]>>(rings: &[R]) -> (Pool, Vec<NodeId>) {
        let mut pool = Pool::default();
        let mut starts = Vec::new();
        for (r, ring) in rings.iter().enumerate() {
            let first = pool.len() as u32;
            for (i, &(x, y)) in ring.as_ref().iter().enumerate() {
                pool.push(Point::new(x, y), i as u32, r as u32);
            }
            pool.link_run(first, ring.as_ref().len() as u32);
            starts.push(NodeId(first));
        }
        (pool, starts)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(pool: &mut Pool) -> NodeId {
        for (i, (x, y)) in [(0., 0.), (1., 0.), (1., 1.), (0., 1.)]
            .into_iter()
            .enumerate()
        {
            pool.push(Point::new(x, y), i as u32, 0);
        }
        pool.link_run(0, 4);
        NodeId(0)
    }

    fn vertices(pool: &Pool, start: NodeId) -> Vec<u32> {
        pool.ring(start).map(|n| pool.get(n).vertex).collect()
    }

    #[test]
    fn lay_out_puts_rings_in_walk_order() {
        let (mut pool, mut starts) = Pool::from_rings(&[
            vec![(0., 0.), (4., 0.), (4., 4.), (0., 4.)],
            vec![(1., 1.), (2., 1.), (2., 2.)],
            vec![(3., 3.), (3.5, 3.), (3.5, 3.5)],
        ]);
        // the first ring visited out of pool order, with a node removed; the second ring
        // is not listed (it keeps its nodes, after the listed rings')
        pool.remove(NodeId(1));
        pool.reverse(starts[0]);
        let listed = [starts[2], starts[0]];
        let before: Vec<Vec<u32>> = listed.iter().map(|&s| vertices(&pool, s)).collect();
        let mut laid = listed;
        let (mut renamed, mut spare) = (Vec::new(), Vec::new());
        pool.lay_out(&mut laid, &mut renamed, &mut spare);
        let after: Vec<Vec<u32>> = laid.iter().map(|&s| vertices(&pool, s)).collect();
        assert_eq!(after, before);
        // consecutive ids along each ring, the listed rings first
        let ids: Vec<u32> = laid
            .iter()
            .flat_map(|&s| pool.ring(s).map(|n| n.0))
            .collect();
        assert_eq!(ids, (0..6).collect::<Vec<u32>>());
        // every node is still there, links consistent, the removed one still removed
        assert_eq!(pool.len(), 10);
        for (i, node) in pool.nodes.iter().enumerate() {
            if !node.removed {
                assert_eq!(pool.get(node.next).prev, NodeId(i as u32));
            }
        }
        assert!(pool.get(NodeId(renamed[1])).removed);
        starts[1] = NodeId(renamed[starts[1].idx()]);
        assert_eq!(vertices(&pool, starts[1]), [0, 1, 2]);
    }

    #[test]
    fn link_remove_reverse() {
        let mut pool = Pool::default();
        let s = square(&mut pool);
        assert_eq!(vertices(&pool, s), [0, 1, 2, 3]);
        pool.remove(NodeId(2));
        assert_eq!(vertices(&pool, s), [0, 1, 3]);
        pool.reverse(s);
        assert_eq!(vertices(&pool, s), [0, 3, 1]);
    }

    #[test]
    fn split_makes_two_rings() {
        let mut pool = Pool::default();
        let s = square(&mut pool);
        let b2 = pool.split(NodeId(0), NodeId(2));
        assert_eq!(vertices(&pool, s), [0, 2, 3]);
        assert_eq!(vertices(&pool, b2), [2, 0, 1]);
    }
}
