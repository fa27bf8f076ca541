// earcut 0.4.12's `src/lib.rs` (georust/earcut, a port of mapbox/earcut), trimmed to
// what `polytri bench` needs. Not a module: `mod.rs` includes it twice (`include!`), once
// with exact predicates and once with upstream's own, which each define `area` and
// `point_in_triangle` beside it. Licences and every change: README.md beside this file.

use std::{cmp::Ordering, num::NonZeroU32, ptr};

/// The node at index `$offset` (upstream: at that byte offset, unchecked).
macro_rules! node {
    ($self:ident.$nodes:ident, $offset:expr) => {
        &$self.$nodes[$offset.get() as usize]
    };
    ($nodes:ident, $offset:expr) => {
        &$nodes[$offset.get() as usize]
    };
}

/// The node at index `$offset`, mutable.
macro_rules! node_mut {
    ($self:ident.$nodes:ident, $offset:expr) => {
        &mut $self.$nodes[$offset.get() as usize]
    };
    ($nodes:ident, $offset:expr) => {
        &mut $nodes[$offset.get() as usize]
    };
}

/// Index of a node in the nodes Vec (upstream: its byte offset).
///
/// Non-zero so `Option<NodeOffset>` keeps `Node` small.
type NodeOffset = NonZeroU32;

/// The index of a real node: index 0 is the dummy node, so real node offsets are non-zero
/// (and below 2^32: [`Earcut::earcut_slice`] takes fewer than [`MAX_VERTICES`]).
#[inline(always)]
fn node_offset(index: usize) -> NodeOffset {
    NodeOffset::MIN.saturating_add((index as u32).saturating_sub(1))
}

/// The largest polygons triangulated, in vertices, less one: far beyond any input of the
/// bench, and low enough that node indices (at most about 3 per vertex) fit `u32` and hole
/// index blocks `i32` (upstream asserts instead).
pub const MAX_VERTICES: usize = 1 << 28;

const STEINER_BIT: u32 = 1 << 31;
const INDEX_MASK: u32 = !STEINER_BIT;

struct Node {
    /// vertex index in coordinates array (lower 31 bits) + steiner flag (bit 31)
    i_steiner: u32,
    /// z-order curve value
    z: i32,
    /// vertex coordinates
    xy: [f64; 2],
    /// previous vertex nodes in a polygon ring
    prev_i: NodeOffset,
    /// next vertex nodes in a polygon ring
    next_i: NodeOffset,
    /// previous nodes in z-order
    prev_z_i: Option<NodeOffset>,
    /// next nodes in z-order
    next_z_i: Option<NodeOffset>,
}

struct LinkInfo {
    prev_i: NodeOffset,
    next_i: NodeOffset,
    prev_z_i: Option<NodeOffset>,
    next_z_i: Option<NodeOffset>,
}

const HOLE_BLOCK_SIZE: usize = 16;
// For a few short rings, index construction costs more than direct traversal.
// Limit both dimensions: even short inputs can have many holes to bridge.
const DIRECT_BRIDGE_MAX_VERTICES: usize = 4 * HOLE_BLOCK_SIZE;
const DIRECT_BRIDGE_MAX_HOLES: usize = 4;
/// Member slots per chunk, and how many blocks a freshly filled chunk takes, which
/// leaves room for merged holes to be inserted without splitting right away.
const CHUNK_CAPACITY: usize = 32;
const CHUNK_FILL: usize = 16;

/// Bounding-box blocks used while holes are merged into the outer ring.
///
/// Every indexed node records its owning block in `z`, and a block is the run
/// of consecutive ring nodes carrying its id, starting at its head. Walking a
/// block therefore stops as soon as the ring leaves it, so a hole spliced into
/// the middle of an older block is never re-walked through that block.
///
/// Blocks are grouped into chunks of consecutive blocks with a combined bbox, so
/// a bridge search can skip a whole chunk at once. Chunks are listed in ring
/// order (`chunk_order`) and keep their blocks in ring order, so scanning visits
/// edges in the same order as walking the merged ring from the outer ring's
/// head; this keeps tie-breaking in `find_hole_bridge` identical to an
/// unindexed scan. All storage is flat and reused across triangulations.
struct HoleBlockIndex {
    /// per block: bbox of its edges, first node, and the chunk holding it
    bboxes: Vec<[f64; 4]>,
    heads: Vec<NodeOffset>,
    block_chunks: Vec<u32>,
    /// per chunk: combined bbox, member count, and `CHUNK_CAPACITY` member slots;
    /// the slots are kept across triangulations and only read up to the member count
    chunk_bboxes: Vec<[f64; 4]>,
    chunk_lens: Vec<u32>,
    chunk_members: Vec<u32>,
    /// chunks in ring order
    chunk_order: Vec<u32>,
    /// blocks waiting to be placed by `insert_after`
    pending: Vec<u32>,
}

fn empty_bbox() -> [f64; 4] {
    [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ]
}

fn union_bbox(bbox: &mut [f64; 4], other: [f64; 4]) {
    bbox[0] = bbox[0].min(other[0]);
    bbox[1] = bbox[1].min(other[1]);
    bbox[2] = bbox[2].max(other[2]);
    bbox[3] = bbox[3].max(other[3]);
}

impl HoleBlockIndex {
    fn new() -> Self {
        Self {
            bboxes: Vec::new(),
            heads: Vec::new(),
            block_chunks: Vec::new(),
            chunk_bboxes: Vec::new(),
            chunk_lens: Vec::new(),
            chunk_members: Vec::new(),
            chunk_order: Vec::new(),
            pending: Vec::new(),
        }
    }

    fn reset(&mut self, max_nodes: usize, num_holes: usize) {
        self.bboxes.clear();
        self.heads.clear();
        self.block_chunks.clear();
        self.chunk_bboxes.clear();
        self.chunk_lens.clear();
        self.chunk_order.clear();

        let indexed_nodes = max_nodes.saturating_add(num_holes.saturating_mul(2));
        // one partial block per indexed segment, plus one detached tail per merge
        let max_blocks = indexed_nodes
            .div_ceil(HOLE_BLOCK_SIZE)
            .saturating_add(num_holes.saturating_mul(2))
            .saturating_add(2);
        self.bboxes.reserve(max_blocks);
        self.heads.reserve(max_blocks);
        self.block_chunks.reserve(max_blocks);
    }

    /// Index the ring run `head..stop`; `head == stop` means the whole ring.
    /// Returns the last new block; the caller places the new blocks in chunks.
    fn index_segment(
        &mut self,
        nodes: &mut [Node],
        head_i: NodeOffset,
        stop_i: NodeOffset,
    ) -> usize {
        let mut p_i = head_i;
        loop {
            let block = self.bboxes.len();
            self.heads.push(p_i);
            self.block_chunks.push(u32::MAX);

            let mut min_x = f64::INFINITY;
            let mut min_y = f64::INFINITY;
            let mut max_x = f64::NEG_INFINITY;
            let mut max_y = f64::NEG_INFINITY;
            let mut count = 0;

            loop {
                let p = node!(nodes, p_i);
                let (next_i, [x, y]) = (p.next_i, p.xy);
                let [next_x, next_y] = node!(nodes, next_i).xy;
                // (fewer blocks than nodes, which `run` keeps below 2^28: the cast is exact)
                node_mut!(nodes, p_i).z = block as i32;

                min_x = min_x.min(x).min(next_x);
                min_y = min_y.min(y).min(next_y);
                max_x = max_x.max(x).max(next_x);
                max_y = max_y.max(y).max(next_y);

                p_i = next_i;
                count += 1;
                if count == HOLE_BLOCK_SIZE || p_i == stop_i {
                    break;
                }
            }

            self.bboxes.push([min_x, min_y, max_x, max_y]);
            if p_i == stop_i {
                return block;
            }
        }
    }

    fn index_outer(&mut self, nodes: &mut [Node], outer_i: NodeOffset) {
        let last = self.index_segment(nodes, outer_i, outer_i);
        for block in 0..=last {
            if block % CHUNK_FILL == 0 {
                let chunk = self.new_chunk();
                self.chunk_order.push(chunk as u32);
            }
            self.push_member(self.chunk_lens.len() - 1, block as u32);
        }
    }

    /// Index a hole just merged at `bridge` (the ring run `bridge..stop`) and place its
    /// blocks right after the block that owned `bridge`, where the hole now sits in the ring.
    fn index_merged_hole(&mut self, nodes: &mut [Node], bridge_i: NodeOffset, stop_i: NodeOffset) {
        let old_block = node!(nodes, bridge_i).z;
        let first = self.bboxes.len() as u32;
        let last = self.index_segment(nodes, bridge_i, stop_i) as u32;
        let tail = self.detach_tail(nodes, old_block, stop_i).map(|b| b as u32);
        let replace = Self::live_head(&mut self.heads, nodes, old_block as usize).is_none();
        self.insert_after(old_block as usize, first..=last, tail, replace);
    }

    fn new_chunk(&mut self) -> usize {
        let chunk = self.chunk_lens.len();
        self.chunk_lens.push(0);
        self.chunk_bboxes.push(empty_bbox());
        let slots_end = (chunk + 1) * CHUNK_CAPACITY;
        if self.chunk_members.len() < slots_end {
            self.chunk_members.resize(slots_end, 0);
        }
        chunk
    }

    fn push_member(&mut self, chunk: usize, block: u32) {
        let len = self.chunk_lens[chunk] as usize;
        self.chunk_members[chunk * CHUNK_CAPACITY + len] = block;
        self.chunk_lens[chunk] += 1;
        self.block_chunks[block as usize] = chunk as u32;
        union_bbox(&mut self.chunk_bboxes[chunk], self.bboxes[block as usize]);
    }

    fn chunk_range(&self, chunk: usize) -> core::ops::Range<usize> {
        let start = chunk * CHUNK_CAPACITY;
        start..start + self.chunk_lens[chunk] as usize
    }

    /// Place the new blocks `new` followed by `tail` (in ring order) right after `block`.
    /// If its chunk overflows, the chunk keeps the blocks before the insertion point
    /// and the rest spill into new chunks that follow it in ring order.
    fn insert_after(
        &mut self,
        block: usize,
        new: core::ops::RangeInclusive<u32>,
        tail: Option<u32>,
        replace: bool,
    ) {
        let chunk = self.block_chunks[block] as usize;
        let range = self.chunk_range(chunk);
        // (every indexed block belongs to its chunk)
        let Some(position) = self.chunk_members[range.clone()]
            .iter()
            .position(|&b| b as usize == block)
        else {
            return;
        };
        let at = range.start + position + usize::from(!replace);
        let removed = usize::from(replace);
        let n = (new.end() - new.start() + 1) as usize + usize::from(tail.is_some());

        if range.len() + n - removed <= CHUNK_CAPACITY {
            self.chunk_members
                .copy_within(at + removed..range.end, at + n);
            for (slot, b) in (at..).zip(new.chain(tail)) {
                self.chunk_members[slot] = b;
                self.block_chunks[b as usize] = chunk as u32;
                union_bbox(&mut self.chunk_bboxes[chunk], self.bboxes[b as usize]);
            }
            self.chunk_lens[chunk] += (n - removed) as u32;
            return;
        }

        self.pending.clear();
        self.pending.extend(new.chain(tail));
        self.pending
            .extend_from_slice(&self.chunk_members[at + removed..range.end]);
        let kept = at - range.start;
        self.chunk_lens[chunk] = 0;
        self.chunk_bboxes[chunk] = empty_bbox();
        for k in range.start..at {
            let b = self.chunk_members[k];
            self.push_member(chunk, b);
        }

        let first_new = self.chunk_lens.len();
        let mut target = chunk;
        let mut room = CHUNK_FILL.saturating_sub(kept);
        for k in 0..self.pending.len() {
            if room == 0 {
                target = self.new_chunk();
                room = CHUNK_FILL;
            }
            let b = self.pending[k];
            self.push_member(target, b);
            room -= 1;
        }

        // (every chunk is listed in ring order)
        let order_at = self
            .chunk_order
            .iter()
            .position(|&c| c as usize == chunk)
            .map_or(self.chunk_order.len(), |at| at + 1);
        self.chunk_order.splice(
            order_at..order_at,
            first_new as u32..self.chunk_lens.len() as u32,
        );
    }

    fn grow(&mut self, block: usize, [x, y]: [f64; 2]) {
        let point = [x, y, x, y];
        union_bbox(&mut self.bboxes[block], point);
        union_bbox(
            &mut self.chunk_bboxes[self.block_chunks[block] as usize],
            point,
        );
    }

    /// First live node of the block, or `None` once none of its nodes are left.
    ///
    /// Removed nodes keep their links, so skipping forward from a removed head
    /// reaches either the block's next survivor or a node owned elsewhere. Takes
    /// only `heads`, so a scan can keep iterating a chunk's members meanwhile.
    fn live_head(heads: &mut [NodeOffset], nodes: &[Node], block: usize) -> Option<NodeOffset> {
        let mut head_i = heads[block];
        let mut prev_i = node!(nodes, head_i).prev_i;
        while node!(nodes, prev_i).next_i != head_i {
            head_i = node!(nodes, head_i).next_i;
            prev_i = node!(nodes, head_i).prev_i;
        }
        heads[block] = head_i;
        (node!(nodes, head_i).z == block as i32).then_some(head_i)
    }

    /// Merging a hole at `bridge` re-owns the bridge node, which cuts its former
    /// block in two. Give the part after the bridge (starting at `tail`) a block
    /// of its own so it stays reachable; it inherits the old bbox, which still
    /// covers all of its edges.
    fn detach_tail(
        &mut self,
        nodes: &mut [Node],
        old_block: i32,
        tail_i: NodeOffset,
    ) -> Option<usize> {
        if node!(nodes, tail_i).z != old_block {
            return None;
        }
        let block = self.bboxes.len();
        // (fewer blocks than nodes, which `run` keeps below 2^28: the cast is exact)
        let block_z = block as i32;
        self.bboxes.push(self.bboxes[old_block as usize]);
        self.heads.push(tail_i);
        self.block_chunks.push(u32::MAX);
        let mut p_i = tail_i;
        while node!(nodes, p_i).z == old_block {
            let p = node_mut!(nodes, p_i);
            p.z = block_z;
            p_i = p.next_i;
        }
        Some(block)
    }
}

impl Node {
    const PLACEHOLDER_OFFSET: NodeOffset = NodeOffset::MIN;

    fn new(i: u32, xy: [f64; 2]) -> Self {
        debug_assert!(i & STEINER_BIT == 0);
        Self {
            i_steiner: i,
            xy,
            prev_i: Self::PLACEHOLDER_OFFSET,
            next_i: Self::PLACEHOLDER_OFFSET,
            z: 0,
            prev_z_i: None,
            next_z_i: None,
        }
    }

    #[inline(always)]
    fn index(&self) -> u32 {
        self.i_steiner & INDEX_MASK
    }

    #[inline(always)]
    fn is_steiner(&self) -> bool {
        self.i_steiner & STEINER_BIT != 0
    }

    #[inline(always)]
    fn set_steiner(&mut self) {
        self.i_steiner |= STEINER_BIT;
    }

    fn link_info(&self) -> LinkInfo {
        LinkInfo {
            prev_i: self.prev_i,
            next_i: self.next_i,
            prev_z_i: self.prev_z_i,
            next_z_i: self.next_z_i,
        }
    }
}

/// Instance of the earcut algorithm.
pub struct Earcut {
    nodes: Vec<Node>,
    queue: Vec<(NodeOffset, f64)>,
    sort_queue: Vec<(i32, NodeOffset)>,
    sort_scratch: Vec<(i32, NodeOffset)>,
    /// halves of split polygons waiting to be triangulated, so deeply nested
    /// splits don't grow the call stack
    split_stack: Vec<NodeOffset>,
    hole_blocks: HoleBlockIndex,
}

impl Default for Earcut {
    fn default() -> Self {
        Self::new()
    }
}

impl Earcut {
    /// Creates a new instance of the earcut algorithm.
    ///
    /// You can reuse a single instance for multiple triangulations to reduce memory allocations.
    pub fn new() -> Self {
        Self {
            nodes: Vec::new(),
            queue: Vec::new(),
            sort_queue: Vec::new(),
            sort_scratch: Vec::new(),
            split_stack: Vec::new(),
            hole_blocks: HoleBlockIndex::new(),
        }
    }

    fn reset(&mut self, capacity: usize) {
        self.nodes.clear();
        self.nodes.reserve(capacity);
        self.nodes
            .push(Node::new(0, [f64::INFINITY, f64::INFINITY])); // dummy node
    }

    /// Triangulates a polygon: `data` its vertices, the outer ring's first, then each
    /// hole's, each hole starting at its entry of `hole_indices`. The triangles' vertex
    /// indices go to `triangles_out`, three per triangle (cleared first).
    ///
    /// Triangulates nothing when `hole_indices` is not non-decreasing, holds an index past
    /// the vertices, or the polygon has [`MAX_VERTICES`] vertices or more (upstream
    /// panics on the first two).
    #[inline(always)]
    pub fn earcut_slice(
        &mut self,
        data: &[[f64; 2]],
        hole_indices: &[u32],
        triangles_out: &mut Vec<u32>,
    ) {
        triangles_out.clear();
        let sorted = hole_indices.windows(2).all(|w| w[0] <= w[1]);
        let within = hole_indices
            .last()
            .is_none_or(|&h| h as usize <= data.len());
        if sorted && within && data.len() < MAX_VERTICES {
            self.run(data, hole_indices, triangles_out);
        }
    }

    #[inline]
    fn run(&mut self, data: &[[f64; 2]], hole_indices: &[u32], triangles_out: &mut Vec<u32>) {
        if data.len() < 3 {
            return;
        }

        triangles_out.reserve(data.len().saturating_mul(3));
        self.reset(data.len() / 2 * 3);

        let has_holes = !hole_indices.is_empty();
        let outer_len: usize = if has_holes {
            hole_indices[0] as usize
        } else {
            data.len()
        };

        // create nodes
        let Some(mut outer_node_i) = self.linked_list(data, 0, outer_len, true) else {
            return;
        };
        let outer_node = node!(self.nodes, outer_node_i);
        if outer_node.next_i == outer_node.prev_i {
            return;
        }
        if has_holes {
            outer_node_i = self.eliminate_holes(data, hole_indices, outer_node_i);
        }

        let mut min_x = 0.0;
        let mut min_y = 0.0;
        let mut inv_size = 0.0;

        // if the shape is not too simple, we'll use z-order curve hash later; calculate polygon bbox
        if data.len() > 80 {
            let [x0, y0] = data[0];
            let (mut mnx, mut mny, mut mxx, mut mxy) = (x0, y0, x0, y0);
            for &[x, y] in &data[1..outer_len] {
                mnx = f64::min(mnx, x);
                mny = f64::min(mny, y);
                mxx = f64::max(mxx, x);
                mxy = f64::max(mxy, y);
            }
            min_x = mnx;
            min_y = mny;
            // minX, minY and invSize are later used to transform coords into integers for z-order calculation
            inv_size = (mxx - mnx).max(mxy - mny);
            if inv_size != 0.0 {
                inv_size = 32767.0 / inv_size;
            }
        }

        self.split_stack.clear();
        let mut start_i = Some(outer_node_i);
        while let Some(ear_i) = start_i {
            earcut_linked(
                &mut self.nodes,
                ear_i,
                triangles_out,
                min_x,
                min_y,
                inv_size,
                &mut self.sort_queue,
                &mut self.sort_scratch,
                &mut self.split_stack,
            );
            start_i = self.split_stack.pop();
        }
    }

    /// create a circular doubly linked list from polygon points in the specified winding order
    fn linked_list(
        &mut self,
        data: &[[f64; 2]],
        start: usize,
        end: usize,
        clockwise: bool,
    ) -> Option<NodeOffset> {
        let data = &data[start..end];
        if data.is_empty() {
            return None;
        }

        let mut last_i: Option<NodeOffset> = None;
        let iter = data.iter().enumerate();

        if clockwise == (signed_area(data) > 0.0) {
            for (i, &xy) in iter {
                let idx = start + i;
                last_i = Some(insert_node(&mut self.nodes, idx as u32, xy, last_i));
            }
        } else {
            for (i, &xy) in iter.rev() {
                let idx = start + i;
                last_i = Some(insert_node(&mut self.nodes, idx as u32, xy, last_i));
            }
        };

        if let Some(li) = last_i {
            let last = node!(self.nodes, li);
            if equals(last, node!(self.nodes, last.next_i)) {
                let ll = last.link_info();
                let (_, next_i) = remove_node(&mut self.nodes, ll);
                last_i = Some(next_i);
            }
        }

        last_i
    }

    /// link every hole into the outer loop, producing a single-ring polygon without holes
    #[inline(never)]
    fn eliminate_holes(
        &mut self,
        data: &[[f64; 2]],
        hole_indices: &[u32],
        mut outer_node_i: NodeOffset,
    ) -> NodeOffset {
        self.queue.clear();
        for (i, hi) in hole_indices.iter().enumerate() {
            let start = (*hi) as usize;
            let end = if i < hole_indices.len() - 1 {
                hole_indices[i + 1] as usize
            } else {
                data.len()
            };
            if let Some(list_i) = self.linked_list(data, start, end, false) {
                let list = &mut node_mut!(self.nodes, list_i);
                if list_i == list.next_i {
                    list.set_steiner();
                }
                let (leftmost_i, leftmost) = get_leftmost(&self.nodes, list_i);
                self.queue.push((leftmost_i, leftmost.xy[0]));
            }
        }

        self.queue.sort_by(|(ai, ax), (bi, bx)| {
            // compareXYSlope
            match ax.partial_cmp(bx) {
                Some(Ordering::Equal) => {}
                Some(ordering) => return ordering,
                None => return Ordering::Equal,
            }
            // when the left-most point of 2 holes meet at a vertex, sort the holes counterclockwise so that when we find
            // the bridge to the outer shell is always the point that they meet at.
            let a = node!(self.nodes, *ai);
            let b = node!(self.nodes, *bi);
            match a.xy[1].partial_cmp(&b.xy[1]) {
                Some(Ordering::Equal) => {}
                Some(ordering) => return ordering,
                None => return Ordering::Equal,
            };
            let a_next = node!(self.nodes, a.next_i);
            let b_next = node!(self.nodes, b.next_i);
            let a_slope = (a_next.xy[1] - a.xy[1]) / (a_next.xy[0] - a.xy[0]);
            let b_slope = (b_next.xy[1] - b.xy[1]) / (b_next.xy[0] - b.xy[0]);
            a_slope.partial_cmp(&b_slope).unwrap_or(Ordering::Equal)
        });

        // Keep the initial ring anchor on the direct path so candidate ties
        // use the same traversal order as the indexed path.
        if data.len() <= DIRECT_BRIDGE_MAX_VERTICES && hole_indices.len() <= DIRECT_BRIDGE_MAX_HOLES
        {
            self.hole_blocks.chunk_order.clear();
            self.hole_blocks.heads.clear();
            self.hole_blocks.heads.push(outer_node_i);
        } else {
            self.hole_blocks.reset(data.len(), hole_indices.len());
            self.hole_blocks.index_outer(&mut self.nodes, outer_node_i);
        }

        // Process holes from left to right. Each merged hole extends the
        // append-only block index used by subsequent bridge searches.
        for i in 0..self.queue.len() {
            let q = self.queue[i].0;
            outer_node_i = eliminate_hole(&mut self.nodes, q, outer_node_i, &mut self.hole_blocks);
        }

        // Collapse collinear/coincident points across the whole merged ring
        // once before clipping.
        filter_points(&mut self.nodes, outer_node_i, None, None).0
    }
}

/// main ear slicing loop which triangulates a polygon (given as a linked list)
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn earcut_linked(
    nodes: &mut Vec<Node>,
    ear_i: NodeOffset,
    triangles: &mut Vec<u32>,
    min_x: f64,
    min_y: f64,
    inv_size: f64,
    sort_queue: &mut Vec<(i32, NodeOffset)>,
    sort_scratch: &mut Vec<(i32, NodeOffset)>,
    split_stack: &mut Vec<NodeOffset>,
) {
    if inv_size != 0.0 {
        earcut_linked_impl::<true>(
            nodes,
            ear_i,
            triangles,
            min_x,
            min_y,
            inv_size,
            sort_queue,
            sort_scratch,
            split_stack,
        );
    } else {
        earcut_linked_impl::<false>(
            nodes,
            ear_i,
            triangles,
            min_x,
            min_y,
            inv_size,
            sort_queue,
            sort_scratch,
            split_stack,
        );
    }
}

#[allow(clippy::too_many_arguments)]
fn earcut_linked_impl<const HASHED: bool>(
    nodes: &mut Vec<Node>,
    ear_i: NodeOffset,
    triangles: &mut Vec<u32>,
    min_x: f64,
    min_y: f64,
    inv_size: f64,
    sort_queue: &mut Vec<(i32, NodeOffset)>,
    sort_scratch: &mut Vec<(i32, NodeOffset)>,
    split_stack: &mut Vec<NodeOffset>,
) {
    let mut ear_i = ear_i;

    // interlink polygon nodes in z-order
    if HASHED {
        index_curve(
            nodes,
            ear_i,
            min_x,
            min_y,
            inv_size,
            sort_queue,
            sort_scratch,
        );
    }

    let mut stop_i = ear_i;
    let mut cured = false;
    // a strictly convex ring has no vertex that could block an ear, so skip the point
    // checks until a candidate fails; without this, a big convex ring is cut as one fan
    // of long triangles and each hashed check scans O(n) points
    let mut convex = HASHED && is_convex(nodes, ear_i);

    // iterate through ears, slicing them one by one
    loop {
        let ear = node!(nodes, ear_i);
        if ear.prev_i == ear.next_i {
            break;
        }
        let ni = ear.next_i;

        let (is_ear, prev, next) = if HASHED && convex {
            let (a, c) = (node!(nodes, ear.prev_i), node!(nodes, ear.next_i));
            (area(a, ear, c) < 0.0, a, c)
        } else if HASHED {
            is_ear_hashed(nodes, ear, min_x, min_y, inv_size)
        } else {
            is_ear(nodes, ear)
        };
        if is_ear {
            let next_i = next.index();
            let next_node_i = ear.next_i;

            // cut off the triangle
            triangles.extend([prev.index(), ear.index(), next_i]);

            let ll = ear.link_info();
            remove_node(nodes, ll);

            (ear_i, stop_i) = (next_node_i, next_node_i);

            continue;
        }

        convex = false;
        ear_i = ni;

        // if we looped through the whole remaining polygon and can't find any more ears
        if ear_i == stop_i {
            // Filtering a point can expose another removable point or a new
            // ear, so keep clipping while filtering makes progress.
            let (filtered_i, filtered_out) = filter_points(nodes, ear_i, None, None);
            ear_i = filtered_i;
            if filtered_out {
                stop_i = ear_i;
                continue;
            }

            // Cure local self-intersections once before falling back to a
            // polygon split.
            if !cured {
                ear_i = cure_local_intersections(nodes, ear_i, triangles);
                stop_i = ear_i;
                cured = true;
                continue;
            }

            split_earcut(nodes, ear_i, split_stack);
            break;
        }
    }
}

/// check whether every vertex of a ring is strictly convex
fn is_convex(nodes: &[Node], start_i: NodeOffset) -> bool {
    let mut p_i = start_i;
    loop {
        let p = node!(nodes, p_i);
        if area(node!(nodes, p.prev_i), p, node!(nodes, p.next_i)) >= 0.0 {
            return false;
        }
        p_i = p.next_i;
        if p_i == start_i {
            return true;
        }
    }
}
/// check whether a polygon node forms a valid ear with adjacent nodes
fn is_ear<'a>(nodes: &'a [Node], ear: &'a Node) -> (bool, &'a Node, &'a Node) {
    let b = ear;
    let a = node!(nodes, b.prev_i);
    let c = node!(nodes, b.next_i);

    if area(a, b, c) >= 0.0 {
        // reflex, can't be an ear
        return (false, a, c);
    }

    // now make sure we don't have other points inside the potential ear

    // triangle bbox for z-order range
    let x0 = a.xy[0].min(b.xy[0].min(c.xy[0]));
    let y0 = a.xy[1].min(b.xy[1].min(c.xy[1]));
    let x1 = a.xy[0].max(b.xy[0].max(c.xy[0]));
    let y1 = a.xy[1].max(b.xy[1].max(c.xy[1]));

    let mut p = node!(nodes, c.next_i);
    let mut p_prev = node!(nodes, p.prev_i);
    while !ptr::eq(p, a) {
        let p_next = node!(nodes, p.next_i);
        if (p.xy[0] >= x0 && p.xy[0] <= x1 && p.xy[1] >= y0 && p.xy[1] <= y1)
            && point_in_triangle_except_first(a.xy, b.xy, c.xy, p.xy)
            && area(p_prev, p, p_next) >= 0.0
        {
            return (false, a, c);
        }
        (p_prev, p) = (p, p_next);
    }
    (true, a, c)
}

fn is_ear_hashed<'a>(
    nodes: &'a [Node],
    ear: &'a Node,
    min_x: f64,
    min_y: f64,
    inv_size: f64,
) -> (bool, &'a Node, &'a Node) {
    let b = ear;
    let a = node!(nodes, b.prev_i);
    let c = node!(nodes, b.next_i);

    if area(a, b, c) >= 0.0 {
        // reflex, can't be an ear
        return (false, a, c);
    }

    // Cache vertex coordinates in stack locals so the inner loops don't
    // reload them through the (potentially aliased) node references.
    let a_xy = a.xy;
    let b_xy = b.xy;
    let c_xy = c.xy;

    // triangle bbox
    let xy_min = [
        a_xy[0].min(b_xy[0].min(c_xy[0])),
        a_xy[1].min(b_xy[1].min(c_xy[1])),
    ];
    let xy_max = [
        a_xy[0].max(b_xy[0].max(c_xy[0])),
        a_xy[1].max(b_xy[1].max(c_xy[1])),
    ];

    // z-order range for the current triangle bbox;
    let min_z = z_order(xy_min, min_x, min_y, inv_size);
    let max_z = z_order(xy_max, min_x, min_y, inv_size);

    // Walk both z-order directions interleaved: the two pointer chases are
    // independent, so the CPU keeps two loads in flight instead of one on
    // this latency-bound traversal. Any hit returns immediately, so the visit
    // order does not change the result.
    //
    // `point_in_triangle_except_first` already rejects points coinciding with
    // `a`, so only the shared `c` vertex needs an identity check (matches the
    // C++ reference).
    let mut o_n = ear.next_z_i.map(|i| node!(nodes, i));
    let mut o_p = ear.prev_z_i.map(|i| node!(nodes, i));
    while let (Some(n), Some(p)) = (o_n, o_p) {
        if n.z > max_z || p.z < min_z {
            break;
        }
        if !ptr::eq(n, c)
            && point_in_triangle_except_first(a_xy, b_xy, c_xy, n.xy)
            && area(node!(nodes, n.prev_i), n, node!(nodes, n.next_i)) >= 0.0
        {
            return (false, a, c);
        }
        if !ptr::eq(p, c)
            && point_in_triangle_except_first(a_xy, b_xy, c_xy, p.xy)
            && area(node!(nodes, p.prev_i), p, node!(nodes, p.next_i)) >= 0.0
        {
            return (false, a, c);
        }
        o_n = n.next_z_i.map(|i| node!(nodes, i));
        o_p = p.prev_z_i.map(|i| node!(nodes, i));
    }

    // drain the remaining increasing z-order side
    while let Some(n) = o_n {
        if n.z > max_z {
            break;
        };
        if !ptr::eq(n, c)
            && point_in_triangle_except_first(a_xy, b_xy, c_xy, n.xy)
            && area(node!(nodes, n.prev_i), n, node!(nodes, n.next_i)) >= 0.0
        {
            return (false, a, c);
        }
        o_n = n.next_z_i.map(|i| node!(nodes, i));
    }

    // drain the remaining decreasing z-order side
    while let Some(p) = o_p {
        if p.z < min_z {
            break;
        };
        if !ptr::eq(p, c)
            && point_in_triangle_except_first(a_xy, b_xy, c_xy, p.xy)
            && area(node!(nodes, p.prev_i), p, node!(nodes, p.next_i)) >= 0.0
        {
            return (false, a, c);
        }
        o_p = p.prev_z_i.map(|i| node!(nodes, i));
    }

    (true, a, c)
}

/// go through all polygon nodes and cure small local self-intersections
fn cure_local_intersections(
    nodes: &mut [Node],
    mut start_i: NodeOffset,
    triangles: &mut Vec<u32>,
) -> NodeOffset {
    let mut p_i = start_i;
    let mut cured = false;
    loop {
        let p = node!(nodes, p_i);
        let p_next_i = p.next_i;
        let p_next = node!(nodes, p_next_i);
        let b_i = p_next.next_i;
        let a = node!(nodes, p.prev_i);
        let b = node!(nodes, b_i);

        if !equals(a, b)
            && intersects(a, p, p_next, b, false)
            && locally_inside(nodes, a, b)
            && locally_inside(nodes, b, a)
        {
            triangles.extend([a.index(), p.index(), b.index()]);

            let b_next_i = b.next_i;
            remove_node(nodes, p.link_info());
            let pnl = node!(nodes, p_next_i).link_info();
            remove_node(nodes, pnl);

            (p_i, start_i) = (b_next_i, b_i);
            cured = true;
        } else {
            p_i = p.next_i;
        }

        if p_i == start_i {
            return if cured {
                filter_points(nodes, p_i, None, None).0
            } else {
                p_i
            };
        }
    }
}

/// try splitting polygon into two; both halves are queued on `split_stack` to be
/// triangulated independently, `a` on top so it is triangulated first
fn split_earcut(nodes: &mut Vec<Node>, start_i: NodeOffset, split_stack: &mut Vec<NodeOffset>) {
    // look for a valid diagonal that divides the polygon into two
    let mut ai = start_i;
    let mut a = node!(nodes, ai);
    loop {
        let a_next = node!(nodes, a.next_i);
        let a_prev = node!(nodes, a.prev_i);
        let mut bi = a_next.next_i;

        while bi != a.prev_i {
            let b = node!(nodes, bi);
            if a.index() != b.index() && is_valid_diagonal(nodes, a, b, a_next, a_prev) {
                // split the polygon in two by the diagonal
                let mut ci = split_polygon(nodes, ai, bi);

                // filter colinear points around the cuts
                let end_i = Some(node!(nodes, ai).next_i);
                ai = filter_points(nodes, ai, end_i, None).0;
                let end_i = Some(node!(nodes, ci).next_i);
                ci = filter_points(nodes, ci, end_i, None).0;

                // queue both halves for earcut, a on top so it's triangulated first
                split_stack.extend([ci, ai]);
                return;
            }
            bi = b.next_i;
        }

        ai = a.next_i;
        if ai == start_i {
            return;
        }
        a = a_next;
    }
}

/// interlink polygon nodes in z-order
fn index_curve(
    nodes: &mut [Node],
    start_i: NodeOffset,
    min_x: f64,
    min_y: f64,
    inv_size: f64,
    order: &mut Vec<(i32, NodeOffset)>,
    scratch: &mut Vec<(i32, NodeOffset)>,
) {
    order.clear();
    let mut p_i = start_i;
    let mut p = node_mut!(nodes, p_i);

    loop {
        // `z` temporarily holds the hole block id during hole elimination.
        p.z = z_order(p.xy, min_x, min_y, inv_size);
        order.push((p.z, p_i));
        p_i = p.next_i;
        p = node_mut!(nodes, p_i);
        if p_i == start_i {
            break;
        }
    }

    sort_by_z(order, scratch);

    for idx in 0..order.len() {
        let prev_z_i = if idx > 0 {
            Some(order[idx - 1].1)
        } else {
            None
        };
        let next_z_i = order.get(idx + 1).map(|&(_, i)| i);
        let p = node_mut!(nodes, order[idx].1);
        p.prev_z_i = prev_z_i;
        p.next_z_i = next_z_i;
    }
}

/// Sort a large z-order queue with four stable byte-wise radix passes.
fn sort_by_z(order: &mut [(i32, NodeOffset)], scratch: &mut Vec<(i32, NodeOffset)>) {
    const RADIX_MIN_LEN: usize = 512;
    let n = order.len();
    if n < RADIX_MIN_LEN {
        order.sort_unstable_by_key(|&(z, _)| z);
        return;
    }

    #[inline(always)]
    fn scatter(
        src: &[(i32, NodeOffset)],
        dst: &mut [(i32, NodeOffset)],
        shift: u32,
        offsets: &mut [u32; 256],
    ) {
        for &item in src {
            let bucket = (item.0 as u32 >> shift & 0xff) as usize;
            dst[offsets[bucket] as usize] = item;
            offsets[bucket] += 1;
        }
    }

    let mut counts = [[0u32; 256]; 4];
    for &(z, _) in order.iter() {
        let key = z as u32;
        counts[0][(key & 0xff) as usize] += 1;
        counts[1][(key >> 8 & 0xff) as usize] += 1;
        counts[2][(key >> 16 & 0xff) as usize] += 1;
        counts[3][(key >> 24 & 0xff) as usize] += 1;
    }

    scratch.resize(n, order[0]);
    let mut in_order = true;
    for (pass, counts) in counts.iter().enumerate() {
        if counts.iter().any(|&count| count as usize == n) {
            continue;
        }
        let mut offsets = [0u32; 256];
        let mut sum = 0;
        for (offset, &count) in offsets.iter_mut().zip(counts.iter()) {
            *offset = sum;
            sum += count;
        }
        let shift = pass as u32 * 8;
        if in_order {
            scatter(order, scratch, shift, &mut offsets);
        } else {
            scatter(scratch, order, shift, &mut offsets);
        }
        in_order = !in_order;
    }
    if !in_order {
        order.copy_from_slice(scratch);
    }
}

/// find the leftmost node of a polygon ring
fn get_leftmost(nodes: &[Node], start_i: NodeOffset) -> (NodeOffset, &Node) {
    let mut p_i = start_i;
    let mut p = node!(nodes, p_i);
    let mut leftmost_i = start_i;
    let mut leftmost = p;

    loop {
        if p.xy[0] < leftmost.xy[0] || (p.xy[0] == leftmost.xy[0] && p.xy[1] < leftmost.xy[1]) {
            (leftmost_i, leftmost) = (p_i, p);
        }
        p_i = p.next_i;
        if p_i == start_i {
            return (leftmost_i, leftmost);
        }
        p = node!(nodes, p_i);
    }
}

/// check if a diagonal between two polygon nodes is valid (lies in polygon interior)
fn is_valid_diagonal(nodes: &[Node], a: &Node, b: &Node, a_next: &Node, a_prev: &Node) -> bool {
    if a_next.index() == b.index() || a_prev.index() == b.index() {
        return false;
    }

    let b_next = node!(nodes, b.next_i);
    let b_prev = node!(nodes, b.prev_i);

    let zero_length_valid =
        equals(a, b) && area(a_prev, a, a_next) > 0.0 && area(b_prev, b, b_next) > 0.0;

    (zero_length_valid
        || (locally_inside(nodes, a, b)
            && locally_inside(nodes, b, a)
            // does not create opposite-facing sectors
            && (area(a_prev, a, b_prev) != 0.0 || area(a, b_prev, b) != 0.0)))
        && !intersects_polygon(nodes, a, b)
        && (zero_length_valid || middle_inside(nodes, a, b))
}

/// check if two segments intersect; optionally include collinear boundary touches
fn intersects(p1: &Node, q1: &Node, p2: &Node, q2: &Node, include_boundary: bool) -> bool {
    let o1 = area(p1, q1, p2);
    let o2 = area(p1, q1, q2);
    let o3 = area(p2, q2, p1);
    let o4 = area(p2, q2, q1);
    let proper = ((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0))
        && ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0));
    proper
        || include_boundary
            && ((o3 == 0.0 && on_segment(p2, p1, q2))
                || (o4 == 0.0 && on_segment(p2, q1, q2))
                || (o2 == 0.0 && on_segment(p1, q2, q1))
                || (o1 == 0.0 && on_segment(p1, p2, q1)))
}

/// check if a polygon diagonal intersects any polygon segments
fn intersects_polygon(nodes: &[Node], a: &Node, b: &Node) -> bool {
    let ai = a.index();
    let bi = b.index();
    let x0 = a.xy[0].min(b.xy[0]);
    let y0 = a.xy[1].min(b.xy[1]);
    let x1 = a.xy[0].max(b.xy[0]);
    let y1 = a.xy[1].max(b.xy[1]);
    let mut p = a;
    loop {
        let p_next = node!(nodes, p.next_i);
        let pi = p.index();
        let pni = p_next.index();
        let px0 = p.xy[0].min(p_next.xy[0]);
        let py0 = p.xy[1].min(p_next.xy[1]);
        let px1 = p.xy[0].max(p_next.xy[0]);
        let py1 = p.xy[1].max(p_next.xy[1]);
        if (((pi != ai) && (pi != bi)) && ((pni != ai) && (pni != bi)))
            && px0 <= x1
            && px1 >= x0
            && py0 <= y1
            && py1 >= y0
            && intersects(p, p_next, a, b, true)
        {
            return true;
        }
        p = p_next;
        if ptr::eq(p, a) {
            return false;
        }
    }
}

/// check if the middle point of a polygon diagonal is inside the polygon
fn middle_inside(nodes: &[Node], a: &Node, b: &Node) -> bool {
    let mut p = a;
    let mut inside = false;
    let two = 1.0 + 1.0;
    let (px, py) = ((a.xy[0] + b.xy[0]) / two, (a.xy[1] + b.xy[1]) / two);
    loop {
        let p_next = node!(nodes, p.next_i);
        inside ^= (p.xy[1] > py) != (p_next.xy[1] > py)
            && p_next.xy[1] != p.xy[1]
            && (px
                < (p_next.xy[0] - p.xy[0]) * (py - p.xy[1]) / (p_next.xy[1] - p.xy[1]) + p.xy[0]);
        p = p_next;
        if ptr::eq(p, a) {
            return inside;
        }
    }
}

/// find a bridge between vertices that connects hole with an outer ring and and link it
fn eliminate_hole(
    nodes: &mut Vec<Node>,
    hole_i: NodeOffset,
    outer_node_i: NodeOffset,
    blocks: &mut HoleBlockIndex,
) -> NodeOffset {
    let Some(bridge_i) = find_hole_bridge(nodes, node!(nodes, hole_i), outer_node_i, blocks) else {
        return outer_node_i;
    };
    let bridge_reverse_i = split_polygon(nodes, bridge_i, hole_i);

    // Index the merged hole and its two slit edges before filtering. Removed
    // collinear nodes leave conservative bboxes behind, so they cannot cause
    // a false skip in later searches.
    if blocks.chunk_order.is_empty() {
        return heal_bridge(nodes, bridge_i, bridge_reverse_i, hole_i, None);
    }

    let bridge2_i = node!(nodes, bridge_reverse_i).next_i;
    let stop_i = node!(nodes, bridge2_i).next_i;
    blocks.index_merged_hole(nodes, bridge_i, stop_i);

    heal_bridge(nodes, bridge_i, bridge_reverse_i, hole_i, Some(blocks))
}

/// heal collinear/coincident points around the two new slit edges of a merged hole
fn heal_bridge(
    nodes: &mut [Node],
    bridge_i: NodeOffset,
    bridge_reverse_i: NodeOffset,
    hole_i: NodeOffset,
    mut blocks: Option<&mut HoleBlockIndex>,
) -> NodeOffset {
    // leave bridge2 alone: dropping it as collinear would leave bridge lying on the
    // healed edge, where a later hole could bridge into it from outside its sector
    let start_i = node!(nodes, bridge_reverse_i).prev_i;
    filter_points(
        nodes,
        start_i,
        Some(bridge_reverse_i),
        blocks.as_deref_mut(),
    );

    // likewise, if bridge lies strictly between its prev and hole, healing would drop it
    // and leave bridge2 on the healed edge; skip the heal then (a spike at bridge, e.g.
    // a hole touching an outer edge, still needs it)
    let bridge = node!(nodes, bridge_i);
    let a = node!(nodes, bridge.prev_i);
    let hole = node!(nodes, hole_i);
    if area(a, bridge, hole) == 0.0
        && (a.xy[0] - bridge.xy[0]) * (hole.xy[0] - bridge.xy[0])
            + (a.xy[1] - bridge.xy[1]) * (hole.xy[1] - bridge.xy[1])
            < 0.0
    {
        return bridge_i;
    }

    let end_i = Some(bridge.next_i);
    filter_points(nodes, bridge_i, end_i, blocks).0
}

/// check if a polygon diagonal is locally inside the polygon
fn locally_inside(nodes: &[Node], a: &Node, b: &Node) -> bool {
    let a_prev = node!(nodes, a.prev_i);
    let a_next = node!(nodes, a.next_i);
    if area(a_prev, a, a_next) < 0.0 {
        area(a, b, a_next) >= 0.0 && area(a, a_prev, b) >= 0.0
    } else {
        area(a, b, a_prev) < 0.0 || area(a, a_next, b) < 0.0
    }
}

/// David Eberly's algorithm for finding a bridge between hole and outer polygon
fn find_hole_bridge(
    nodes: &[Node],
    hole: &Node,
    outer_node_i: NodeOffset,
    blocks: &mut HoleBlockIndex,
) -> Option<NodeOffset> {
    if blocks.chunk_order.is_empty() {
        let mut head_i = blocks.heads[0];
        loop {
            let prev_i = node!(nodes, head_i).prev_i;
            if node!(nodes, prev_i).next_i == head_i {
                break;
            }
            head_i = node!(nodes, head_i).next_i;
        }
        blocks.heads[0] = head_i;
        return find_hole_bridge_linear(nodes, hole, outer_node_i, head_i);
    }

    let mut qx = f64::NEG_INFINITY;
    let mut m_i: Option<NodeOffset> = None;
    let [hx, hy] = hole.xy;

    // find a segment intersected by a ray from the hole's leftmost point to the left;
    // segment's endpoint with lesser x will be potential connection point
    // unless they intersect at a vertex, then choose the vertex
    if equals(hole, node!(nodes, outer_node_i)) {
        return Some(outer_node_i);
    }

    let single_chunk = blocks.chunk_order.len() == 1;
    for ci in 0..blocks.chunk_order.len() {
        let chunk = blocks.chunk_order[ci] as usize;
        let [min_x, min_y, max_x, max_y] = blocks.chunk_bboxes[chunk];
        if !single_chunk && (hy < min_y || hy > max_y || min_x > hx || max_x <= qx) {
            continue;
        }
        let members = blocks.chunk_range(chunk);
        for &block in &blocks.chunk_members[members] {
            let block = block as usize;
            let [min_x, min_y, max_x, max_y] = blocks.bboxes[block];
            if hy < min_y || hy > max_y || min_x > hx || max_x <= qx {
                continue;
            }

            let Some(head_i) = HoleBlockIndex::live_head(&mut blocks.heads, nodes, block) else {
                continue;
            };
            // walking `next` from a live node only visits live nodes
            let mut p_i = head_i;
            loop {
                let p = node!(nodes, p_i);
                let next_i = p.next_i;
                let p_next = node!(nodes, next_i);
                if equals(hole, p_next) {
                    return Some(next_i);
                }
                if hy <= p.xy[1] && hy >= p_next.xy[1] && p_next.xy[1] != p.xy[1] {
                    let x = p.xy[0]
                        + (hy - p.xy[1]) * (p_next.xy[0] - p.xy[0]) / (p_next.xy[1] - p.xy[1]);
                    if x <= hx && x > qx {
                        qx = x;
                        m_i = Some(if p.xy[0] < p_next.xy[0] { p_i } else { next_i });
                        if x == hx {
                            return m_i;
                        }
                    }
                }
                p_i = next_i;
                if p_i == head_i || p_next.z != p.z {
                    break;
                }
            }
        }
    }

    let mut m_i = m_i?;

    // look for points inside the triangle of hole point, segment intersection and endpoint;
    // if there are no points found, we have a valid connection;
    // otherwise choose the point of the minimum angle with the ray as connection point

    let mut m = node!(nodes, m_i);
    let mxmy = m.xy;
    let mut tan_min = f64::INFINITY;
    let triangle_min_y = hy.min(mxmy[1]);
    let triangle_max_y = hy.max(mxmy[1]);

    let (tri_a, tri_c) = if hy < mxmy[1] {
        ([hx, hy], [qx, hy])
    } else {
        ([qx, hy], [hx, hy])
    };

    let single_chunk = blocks.chunk_order.len() == 1;
    for ci in 0..blocks.chunk_order.len() {
        let chunk = blocks.chunk_order[ci] as usize;
        let [min_x, min_y, max_x, max_y] = blocks.chunk_bboxes[chunk];
        if !single_chunk
            && (max_x < mxmy[0] || min_x > hx || max_y < triangle_min_y || min_y > triangle_max_y)
        {
            continue;
        }
        let members = blocks.chunk_range(chunk);
        for &block in &blocks.chunk_members[members] {
            let block = block as usize;
            let [min_x, min_y, max_x, max_y] = blocks.bboxes[block];
            if max_x < mxmy[0] || min_x > hx || max_y < triangle_min_y || min_y > triangle_max_y {
                continue;
            }

            let Some(head_i) = HoleBlockIndex::live_head(&mut blocks.heads, nodes, block) else {
                continue;
            };
            let mut p_i = head_i;
            loop {
                let p = node!(nodes, p_i);
                if p.z as usize != block {
                    break;
                }
                let next_i = p.next_i;
                if hx >= p.xy[0]
                    && p.xy[0] >= mxmy[0]
                    && hx != p.xy[0]
                    && point_in_triangle(tri_a, mxmy, tri_c, p.xy)
                {
                    let tan = (hy - p.xy[1]).abs() / (hx - p.xy[0]);
                    let p_next = node!(nodes, next_i);
                    if (locally_inside(nodes, p, hole)
                        || (p.xy[1] == hy && p_next.xy[1] == hy && p_next.xy[0] > hx))
                        && (tan < tan_min
                            || (tan == tan_min
                                && (p.xy[0] > m.xy[0]
                                    || (p.xy[0] == m.xy[0]
                                        && sector_contains_sector(nodes, m, p)))))
                    {
                        (m_i, m) = (p_i, p);
                        tan_min = tan;
                    }
                }
                p_i = next_i;
                if p_i == head_i {
                    break;
                }
            }
        }
    }

    Some(m_i)
}

// Direct ring traversal, derived from this module's bridge search.
fn find_hole_bridge_linear(
    nodes: &[Node],
    hole: &Node,
    outer_node_i: NodeOffset,
    head_i: NodeOffset,
) -> Option<NodeOffset> {
    let mut qx = f64::NEG_INFINITY;
    let mut m_i: Option<NodeOffset> = None;
    let [hx, hy] = hole.xy;

    // find a segment intersected by a ray from the hole's leftmost point to the left;
    // segment's endpoint with lesser x will be potential connection point
    // unless they intersect at a vertex, then choose the vertex
    if equals(hole, node!(nodes, outer_node_i)) {
        return Some(outer_node_i);
    }

    let mut p_i = head_i;
    loop {
        let p = node!(nodes, p_i);
        let next_i = p.next_i;
        let p_next = node!(nodes, next_i);
        if equals(hole, p_next) {
            return Some(next_i);
        }
        if hy <= p.xy[1] && hy >= p_next.xy[1] && p_next.xy[1] != p.xy[1] {
            let x = p.xy[0] + (hy - p.xy[1]) * (p_next.xy[0] - p.xy[0]) / (p_next.xy[1] - p.xy[1]);
            if x <= hx && x > qx {
                qx = x;
                m_i = Some(if p.xy[0] < p_next.xy[0] { p_i } else { next_i });
                if x == hx {
                    return m_i;
                }
            }
        }
        p_i = next_i;
        if p_i == head_i {
            break;
        }
    }

    let mut m_i = m_i?;

    // look for points inside the triangle of hole point, segment intersection and endpoint;
    // if there are no points found, we have a valid connection;
    // otherwise choose the point of the minimum angle with the ray as connection point

    let mut m = node!(nodes, m_i);
    let mxmy = m.xy;
    let mut tan_min = f64::INFINITY;

    let (tri_a, tri_c) = if hy < mxmy[1] {
        ([hx, hy], [qx, hy])
    } else {
        ([qx, hy], [hx, hy])
    };

    let mut p_i = head_i;
    loop {
        let p = node!(nodes, p_i);
        let next_i = p.next_i;
        if hx >= p.xy[0]
            && p.xy[0] >= mxmy[0]
            && hx != p.xy[0]
            && point_in_triangle(tri_a, mxmy, tri_c, p.xy)
        {
            let tan = (hy - p.xy[1]).abs() / (hx - p.xy[0]);
            let p_next = node!(nodes, next_i);
            if (locally_inside(nodes, p, hole)
                || (p.xy[1] == hy && p_next.xy[1] == hy && p_next.xy[0] > hx))
                && (tan < tan_min
                    || (tan == tan_min
                        && (p.xy[0] > m.xy[0]
                            || (p.xy[0] == m.xy[0] && sector_contains_sector(nodes, m, p)))))
            {
                (m_i, m) = (p_i, p);
                tan_min = tan;
            }
        }
        p_i = next_i;
        if p_i == head_i {
            break;
        }
    }

    Some(m_i)
}

/// whether sector in vertex m contains sector in vertex p in the same coordinates
fn sector_contains_sector(nodes: &[Node], m: &Node, p: &Node) -> bool {
    area(node!(nodes, m.prev_i), m, node!(nodes, p.prev_i)) < 0.0
        && area(node!(nodes, p.next_i), m, node!(nodes, m.next_i)) < 0.0
}

/// eliminate colinear or duplicate points
fn filter_points(
    nodes: &mut [Node],
    start_i: NodeOffset,
    end_i: Option<NodeOffset>,
    mut blocks: Option<&mut HoleBlockIndex>,
) -> (NodeOffset, bool) {
    let full = end_i.is_none();
    let mut end_i = end_i.unwrap_or(start_i);
    let mut filtered_out = false;

    let mut p_i = start_i;
    loop {
        let p = node!(nodes, p_i);
        let p_next = node!(nodes, p.next_i);
        let mut again = false;
        if p_i != p.next_i
            && !p.is_steiner()
            && (equals(p, p_next) || area(node!(nodes, p.prev_i), p, p_next) == 0.0)
        {
            if full || p_i == end_i {
                end_i = p.prev_i;
            }
            filtered_out = true;
            if let Some(blocks) = blocks.as_deref_mut() {
                let prev = node!(nodes, p.prev_i);
                blocks.grow(prev.z as usize, p_next.xy);
            }
            let (prev_i, _) = remove_node(nodes, p.link_info());
            p_i = prev_i;
            again = true;
        } else if full || p_i != end_i {
            p_i = p.next_i;
            again = !full;
        }

        if !again && p_i == end_i {
            return (end_i, filtered_out);
        }
    }
}

/// link two polygon vertices with a bridge; if the vertices belong to the same ring, it splits polygon into two;
/// if one belongs to the outer ring and another to a hole, it merges it into a single ring
fn split_polygon(nodes: &mut Vec<Node>, a_i: NodeOffset, b_i: NodeOffset) -> NodeOffset {
    debug_assert!(!nodes.is_empty());
    let a2_i = node_offset(nodes.len());
    let b2_i = node_offset(nodes.len() + 1);

    let a = node_mut!(nodes, a_i);
    let mut a2 = Node::new(a.index(), a.xy);
    let an_i = a.next_i;
    a.next_i = b_i;
    a2.prev_i = b2_i;
    a2.next_i = an_i;

    let b = node_mut!(nodes, b_i);
    let mut b2 = Node::new(b.index(), b.xy);
    let bp_i = b.prev_i;
    b.prev_i = a_i;
    b2.next_i = a2_i;
    b2.prev_i = bp_i;

    node_mut!(nodes, an_i).prev_i = a2_i;
    node_mut!(nodes, bp_i).next_i = b2_i;

    nodes.extend([a2, b2]);

    b2_i
}

/// create a node and optionally link it with previous one (in a circular doubly linked list)
fn insert_node(
    nodes: &mut Vec<Node>,
    i: u32,
    xy: [f64; 2],
    last: Option<NodeOffset>,
) -> NodeOffset {
    let mut p = Node::new(i, xy);
    let p_i = node_offset(nodes.len());
    match last {
        Some(last_i) => {
            let last = node_mut!(nodes, last_i);
            let last_next_i = last.next_i;
            (p.next_i, last.next_i) = (last_next_i, p_i);
            p.prev_i = last_i;
            node_mut!(nodes, last_next_i).prev_i = p_i;
        }
        None => {
            (p.prev_i, p.next_i) = (p_i, p_i);
        }
    }
    nodes.push(p);
    p_i
}

fn remove_node(nodes: &mut [Node], pl: LinkInfo) -> (NodeOffset, NodeOffset) {
    // Each `node_mut!` is its own statement, so the `&mut` never outlives it.
    // That means the z-neighbor writes are sound even when a z-neighbor
    // coincides with the ring neighbor (sequential, non-overlapping borrows),
    // so no equality branch is needed (matches the C++ reference).
    node_mut!(nodes, pl.prev_i).next_i = pl.next_i;
    node_mut!(nodes, pl.next_i).prev_i = pl.prev_i;
    if let Some(prev_z_i) = pl.prev_z_i {
        node_mut!(nodes, prev_z_i).next_z_i = pl.next_z_i;
    }
    if let Some(next_z_i) = pl.next_z_i {
        node_mut!(nodes, next_z_i).prev_z_i = pl.prev_z_i;
    }

    (pl.prev_i, pl.next_i)
}

/// signed area of a polygon ring (twice the geometric area)
fn signed_area(data: &[[f64; 2]]) -> f64 {
    debug_assert!(!data.is_empty());
    let [mut bx, mut by] = data[data.len() - 1];
    let mut sum = 0.0;
    for &[ax, ay] in data {
        sum += (bx - ax) * (ay + by);
        (bx, by) = (ax, ay);
    }
    sum
}

/// z-order of a point given coords and inverse of the longer side of data bbox
fn z_order(xy: [f64; 2], min_x: f64, min_y: f64, inv_size: f64) -> i32 {
    // coords are transformed into non-negative 15-bit integer range
    let x_scaled = (xy[0] - min_x) * inv_size;
    let y_scaled = (xy[1] - min_y) * inv_size;
    let mut x = x_scaled as u32;
    let mut y = y_scaled as u32;

    x = (x | (x << 8)) & 0x00FF00FF;
    x = (x | (x << 4)) & 0x0F0F0F0F;
    x = (x | (x << 2)) & 0x33333333;
    x = (x | (x << 1)) & 0x55555555;

    y = (y | (y << 8)) & 0x00FF00FF;
    y = (y | (y << 4)) & 0x0F0F0F0F;
    y = (y | (y << 2)) & 0x33333333;
    y = (y | (y << 1)) & 0x55555555;

    (x | (y << 1)) as i32
}

fn point_in_triangle_except_first(a: [f64; 2], b: [f64; 2], c: [f64; 2], p: [f64; 2]) -> bool {
    !(a[0] == p[0] && a[1] == p[1]) && point_in_triangle(a, b, c, p)
}

/// check if two points are equal
fn equals(p1: &Node, p2: &Node) -> bool {
    p1.xy == p2.xy
}

/// for collinear points p, q, r, check if point q lies on segment pr
fn on_segment(p: &Node, q: &Node, r: &Node) -> bool {
    ((q.xy[0] <= p.xy[0].max(r.xy[0])) & (q.xy[1] <= p.xy[1].max(r.xy[1])))
        && ((q.xy[0] >= p.xy[0].min(r.xy[0])) & (q.xy[1] >= p.xy[1].min(r.xy[1])))
}
