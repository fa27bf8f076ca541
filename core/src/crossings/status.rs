//! A sequence edited by replacing runs: the sweep's status (see `super::sweep`).
//!
//! Small, the status is one flat `Vec`, edited by shifting its tail, which is fastest for a
//! few dozen items. Grown large, it becomes [`Blocks`]: a list of blocks of at most [`BLOCK`]
//! items each, so replacing a run shifts one block, not the whole tail. A sweep line that
//! crosses Θ(n) edges (a star) then costs O(log n + [`BLOCK`]) per event instead of O(n):
//! finding a run is a binary search over the blocks' last items, then inside one block, and
//! only a block that overflows or empties changes the list of blocks (O(n / [`BLOCK`])).
//!
//! Both are a [`Sequence`], so the sweep is written once. In [`Blocks`], positions are
//! [`Cursor`]s; a cursor is *normal* when it names an item, or is the end `(blocks, 0)`.
//! Every cursor handed out is normal.

/// Items per block, at most (few in unit tests, so that small cases span
/// many blocks).
pub(crate) const BLOCK: usize = if cfg!(test) { 8 } else { 128 };

/// A position: the `off`-th item of the `blk`-th block in sequence order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct Cursor {
    pub blk: usize,
    pub off: usize,
}

/// See the [module documentation](self).
#[derive(Debug)]
pub(crate) struct Blocks<T> {
    /// Block storage, each with capacity [`BLOCK`]; slots are reused.
    slots: Vec<Vec<T>>,
    /// The slots of the blocks, in sequence order (no block is empty).
    order: Vec<usize>,
    /// Slots not in `order`.
    free: Vec<usize>,
    /// Items while blocks are rebuilt.
    buf: Vec<T>,
    /// New slots while blocks are rebuilt.
    ids: Vec<usize>,
}

impl<T> Default for Blocks<T> {
    fn default() -> Self {
        Self {
            slots: Vec::new(),
            order: Vec::new(),
            free: Vec::new(),
            buf: Vec::new(),
            ids: Vec::new(),
        }
    }
}

/// A sequence edited by replacing runs, read through positions `Pos`.
pub(crate) trait Sequence<T> {
    type Pos: Copy + Ord;

    /// The first position whose item fails `pred`, for `pred` true on a prefix (the end
    /// when it holds for all): a binary search.
    fn search(&self, pred: impl Fn(&T) -> bool) -> Self::Pos;

    /// Like `search` over the items from `from` on. For a `Vec` it is exactly the
    /// standard `partition_point` over them, whatever `pred` does.
    fn search_from(&self, from: Self::Pos, pred: impl Fn(&T) -> bool) -> Self::Pos;

    /// The first position from `from` on whose item fails `pred`, by a linear walk.
    fn walk(&self, from: Self::Pos, pred: impl Fn(&T) -> bool) -> Self::Pos {
        let mut c = from;
        while let Some(x) = self.item(c) {
            if !pred(&x) {
                break;
            }
            c = self.after(c);
        }
        c
    }

    /// The item at `c`, if any.
    fn item(&self, c: Self::Pos) -> Option<T>;

    /// The position after `c`.
    fn after(&self, c: Self::Pos) -> Self::Pos;

    /// The position before `c`, if any.
    fn before(&self, c: Self::Pos) -> Option<Self::Pos>;

    /// Replaces the items from `lo` up to `hi` with `items`; returns the position of the
    /// first of them (of the item after them when there are none). Never allocates within
    /// the capacity reserved.
    fn replace(&mut self, lo: Self::Pos, hi: Self::Pos, items: &[T]) -> Self::Pos;
}

impl<T: Copy> Sequence<T> for Vec<T> {
    type Pos = usize;

    #[inline]
    fn search(&self, pred: impl Fn(&T) -> bool) -> usize {
        self.as_slice().partition_point(pred)
    }

    #[inline]
    fn search_from(&self, from: usize, pred: impl Fn(&T) -> bool) -> usize {
        from + self
            .as_slice()
            .get(from..)
            .unwrap_or(&[])
            .partition_point(pred)
    }

    #[inline]
    fn item(&self, c: usize) -> Option<T> {
        self.as_slice().get(c).copied()
    }

    #[inline]
    fn after(&self, c: usize) -> usize {
        c + 1
    }

    #[inline]
    fn before(&self, c: usize) -> Option<usize> {
        c.checked_sub(1)
    }

    #[inline]
    fn replace(&mut self, lo: usize, hi: usize, items: &[T]) -> usize {
        splice(self, lo, hi, items);
        lo
    }
}

impl<T: Copy> Sequence<T> for Blocks<T> {
    type Pos = Cursor;

    fn search(&self, pred: impl Fn(&T) -> bool) -> Cursor {
        // the first block whose last item fails, then the first item in it that fails
        let blk = self
            .order
            .partition_point(|&s| self.slots.get(s).and_then(|b| b.last()).is_some_and(&pred));
        let off = self.block(blk).partition_point(pred);
        self.norm(Cursor { blk, off })
    }

    /// Walks: the same answer as a binary search when `pred` holds on a prefix.
    fn search_from(&self, from: Cursor, pred: impl Fn(&T) -> bool) -> Cursor {
        self.walk(from, pred)
    }

    #[inline]
    fn item(&self, c: Cursor) -> Option<T> {
        self.block(c.blk).get(c.off).copied()
    }

    #[inline]
    fn after(&self, c: Cursor) -> Cursor {
        self.norm(Cursor {
            blk: c.blk,
            off: c.off + 1,
        })
    }

    fn before(&self, c: Cursor) -> Option<Cursor> {
        if c.off > 0 {
            return Some(Cursor {
                blk: c.blk,
                off: c.off - 1,
            });
        }
        // blocks are never empty
        let blk = c.blk.checked_sub(1)?;
        let len = self.block(blk).len();
        Some(Cursor {
            blk,
            off: len.checked_sub(1)?,
        })
    }

    fn replace(&mut self, lo: Cursor, hi: Cursor, items: &[T]) -> Cursor {
        // (`hi` before `lo` would be a caller's mistake: read as an empty run)
        let (lo, hi) = (self.denorm(lo), self.denorm(hi.max(lo)));
        if let (true, Some(&s)) = (lo.blk == hi.blk, self.order.get(lo.blk)) {
            if let Some(b) = self.slots.get_mut(s) {
                let now = b.len() - (hi.off - lo.off) + items.len();
                // a block may grow up to BLOCK and shrink down to BLOCK / 4 in place
                if now <= BLOCK && now > 0 && (now >= b.len() || now >= BLOCK / 4) {
                    splice(b, lo.off, hi.off, items);
                    return self.norm(lo);
                }
            }
        }
        self.rebuild(lo, hi, items)
    }
}

impl<T: Copy> Blocks<T> {
    /// Makes `items` the sequence; `cap` is the most items it will hold, to reserve room.
    pub fn assign(&mut self, items: &[T], cap: usize) {
        self.free.append(&mut self.order);
        self.buf.clear();
        self.buf.reserve(cap);
        self.lay_out(0, 0, items, 0);
    }

    /// Moves every item into `v`, in order, leaving the sequence empty.
    pub fn drain_into(&mut self, v: &mut Vec<T>) {
        v.clear();
        for &s in &self.order {
            if let Some(b) = self.slots.get(s) {
                v.extend_from_slice(b);
            }
        }
        self.free.append(&mut self.order);
    }

    /// The number of blocks.
    #[inline]
    fn blocks(&self) -> usize {
        self.order.len()
    }

    /// The `j`-th block in sequence order (empty past the end).
    #[inline]
    fn block(&self, j: usize) -> &[T] {
        match self.order.get(j).and_then(|&s| self.slots.get(s)) {
            Some(b) => b,
            None => &[],
        }
    }

    /// `c`, moved past the end of its block to the next item (or the end).
    #[inline]
    fn norm(&self, mut c: Cursor) -> Cursor {
        while c.blk < self.blocks() && c.off >= self.block(c.blk).len() {
            c = Cursor {
                blk: c.blk + 1,
                off: 0,
            };
        }
        c
    }

    /// The first position.
    #[cfg(test)]
    fn start(&self) -> Cursor {
        self.norm(Cursor { blk: 0, off: 0 })
    }

    /// The items from `from` on, in sequence order.
    #[cfg(test)]
    fn iter_from(&self, from: Cursor) -> impl Iterator<Item = T> + '_ {
        (from.blk..self.blocks()).flat_map(move |j| {
            let b = self.block(j);
            let skip = if j == from.blk { from.off } else { 0 };
            b.get(skip..).unwrap_or(&[]).iter().copied()
        })
    }

    /// `c` as a position inside a block: the end becomes the end of the last block.
    fn denorm(&self, c: Cursor) -> Cursor {
        match self.blocks().checked_sub(1) {
            Some(last) if c.blk > last => Cursor {
                blk: last,
                off: self.block(last).len(),
            },
            _ => c,
        }
    }

    /// Replaces the items from `lo` up to `hi` (inside blocks) with `items` by laying
    /// the blocks around them out afresh, together with small neighbours.
    fn rebuild(&mut self, lo: Cursor, hi: Cursor, items: &[T]) -> Cursor {
        let n = self.order.len();
        let small = |j: usize| self.block(j).len() < BLOCK / 2;
        let first = match lo.blk.checked_sub(1) {
            Some(j) if small(j) => j,
            _ => lo.blk,
        };
        let last = if hi.blk + 1 < n && small(hi.blk + 1) {
            hi.blk + 1
        } else {
            hi.blk
        };
        let mut buf = core::mem::take(&mut self.buf);
        buf.clear();
        for j in first..lo.blk {
            buf.extend_from_slice(self.block(j));
        }
        buf.extend_from_slice(self.block(lo.blk).get(..lo.off).unwrap_or(&[]));
        let before = buf.len();
        buf.extend_from_slice(items);
        buf.extend_from_slice(self.block(hi.blk).get(hi.off..).unwrap_or(&[]));
        for j in hi.blk + 1..=last {
            buf.extend_from_slice(self.block(j));
        }
        let gone = if n == 0 {
            0
        } else {
            last.min(n - 1) + 1 - first
        };
        let at = self.lay_out(first, gone, &buf, before);
        self.buf = buf;
        at
    }

    /// Replaces the blocks `first..first + gone` with blocks holding `items`, filled to
    /// about three quarters; returns the position of `items[before]`.
    fn lay_out(&mut self, first: usize, gone: usize, items: &[T], before: usize) -> Cursor {
        if let Some(old) = self.order.get(first..first + gone) {
            self.free.extend_from_slice(old);
        }
        let k = items.len().div_ceil(BLOCK * 3 / 4);
        self.ids.clear();
        let mut at = None;
        for i in 0..k {
            let (a, b) = (items.len() * i / k, items.len() * (i + 1) / k);
            let s = match self.free.pop() {
                Some(s) => s,
                None => {
                    self.slots.push(Vec::with_capacity(BLOCK));
                    // room to free every slot at once, so that the next sweep's `clear`
                    // does not allocate
                    self.free.reserve(self.slots.len());
                    self.slots.len() - 1
                }
            };
            if let Some(block) = self.slots.get_mut(s) {
                block.clear();
                block.extend_from_slice(items.get(a..b).unwrap_or(&[]));
            }
            if at.is_none() && before < b {
                at = Some(Cursor {
                    blk: first + i,
                    off: before - a,
                });
            }
            self.ids.push(s);
        }
        let end = (first + gone).min(self.order.len());
        splice(&mut self.order, first.min(end), end, &self.ids);
        at.unwrap_or_else(|| {
            self.norm(Cursor {
                blk: first + k,
                off: 0,
            })
        })
    }
}

/// Replaces `v[lo..hi]` with `items`, shifting the tail. Within `v`'s capacity it never
/// allocates.
pub(crate) fn splice<T: Copy>(v: &mut Vec<T>, lo: usize, hi: usize, items: &[T]) {
    let (m, len) = (items.len(), v.len());
    let hi = hi.min(len);
    let lo = lo.min(hi);
    let r = hi - lo;
    if let (true, Some(&fill)) = (m > r, items.first()) {
        v.resize(len + (m - r), fill);
        v.copy_within(hi..len, hi + (m - r));
    } else if m < r {
        v.copy_within(hi..len, lo + m);
        v.truncate(len - (r - m));
    }
    if let Some(dst) = v.get_mut(lo..lo + m) {
        dst.copy_from_slice(items);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::random;

    /// The whole sequence, in order.
    fn items(b: &Blocks<u32>) -> Vec<u32> {
        b.iter_from(b.start()).collect()
    }

    /// The cursor of logical index `i` (the end for `len`).
    fn cursor(b: &Blocks<u32>, i: usize) -> Cursor {
        let mut c = b.start();
        for _ in 0..i {
            c = b.after(c);
        }
        c
    }

    /// Checks the items and the blocks: none empty or overfull, no two small neighbours.
    fn check(b: &Blocks<u32>, model: &[u32]) {
        assert_eq!(items(b), model);
        let lens: Vec<usize> = (0..b.blocks()).map(|j| b.block(j).len()).collect();
        assert!(lens.iter().all(|&l| l > 0 && l <= BLOCK), "{lens:?}");
        for w in lens.windows(2) {
            assert!(w[0] >= BLOCK / 4 || w[1] >= BLOCK / 4, "{lens:?}");
        }
    }

    #[test]
    fn random_run_replacements_match_a_vec() {
        for seed in 1..40u64 {
            let mut rand = random(seed * 7919);
            let mut b = Blocks::default();
            let mut model: Vec<u32> = Vec::new();
            let mut next = 0u32;
            let grow = 1 + rand(4);
            for step in 0..1500 {
                if step % 97 == 0 {
                    // through a flat `Vec` and back
                    let mut flat = Vec::new();
                    b.drain_into(&mut flat);
                    assert_eq!(flat, model);
                    check(&b, &[]);
                    b.assign(&flat, flat.len());
                    check(&b, &model);
                }
                let len = model.len() as u64;
                let lo = rand(len + 1) as usize;
                let hi = lo + rand((len - lo as u64).min(6) + 1) as usize;
                let m = rand(3 + grow) as usize + if rand(50) == 0 { 30 } else { 0 };
                let new: Vec<u32> = (0..m as u32).map(|k| next + k).collect();
                next += m as u32;
                let at = b.replace(cursor(&b, lo), cursor(&b, hi), &new);
                let at_vec = model.replace(lo, hi, &new);
                assert_eq!(at, cursor(&b, at_vec), "seed {seed} step {step}");
                check(&b, &model);
                // the neighbours of the new run, as the sweep reads them
                let below = b.before(at).and_then(|c| b.item(c));
                assert_eq!(below, model.before(lo).and_then(|i| model.item(i)));
                let after: Vec<u32> = b.iter_from(at).take(m + 1).collect();
                let want: Vec<u32> = model[lo..].iter().copied().take(m + 1).collect();
                assert_eq!(after, want);
            }
        }
    }

    #[test]
    fn searches_match_a_vec() {
        let mut rand = random(99);
        for _ in 0..200 {
            let len = rand(700) as usize;
            let mut model: Vec<u32> = (0..len as u32).map(|_| rand(1000) as u32).collect();
            model.sort_unstable();
            let mut b = Blocks::default();
            b.assign(&model, len);
            check(&b, &model);
            for _ in 0..20 {
                let t = rand(1100) as u32;
                let below = |x: &u32| *x < t;
                let want = model.search(below);
                assert_eq!(b.search(below), cursor(&b, want));
                let from = rand(len as u64 + 1) as usize;
                let want = model.search_from(from, below);
                assert_eq!(model.walk(from, below), want);
                let c = cursor(&b, from);
                assert_eq!(b.search_from(c, below), cursor(&b, want));
                assert_eq!(b.walk(c, below), cursor(&b, want));
            }
        }
    }
}
