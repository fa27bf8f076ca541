//! Layer 4, the context: the state the stages share — the node pool, the ring table, what
//! was dropped and repaired, where rings touch, which edges cross, and an index of the
//! edges that knows whether it is current. Each stage's scratch buffers are its own (see
//! the stage modules); the triangulator owns them and lends them to the stage it runs.

mod edge_index;
mod winding;

pub(crate) use edge_index::EdgeIndex;
pub(crate) use winding::{lowest_net_arrives, net_boundary_counter_clockwise, NetEdge};

use crate::crossings::sweep::Crossing;
use crate::report::{Added, DropReason, Dropped, Repair, RepairKind};
use crate::structures::{NodeId, Pool};

/// One ring after loading. Rings are indexed in load order, which is input order.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Ring {
    /// Position in the caller's `ring_starts`.
    pub input: u32,
    /// A live node of the ring.
    pub start: NodeId,
    /// Live nodes in the ring.
    pub len: u32,
    /// Rightmost node (ties: lowest y); the paper's M for holes.
    pub rightmost: NodeId,
    /// Containment depth: even for outer boundaries, odd for holes.
    pub depth: u32,
    /// Still part of the input (not degenerate, not skipped).
    pub alive: bool,
    /// Part of an outer boundary's ring by now: an outer ring, or a hole bridged into one.
    pub merged: bool,
    /// The outer ring whose polygon this ring belongs to once bridged (itself for outers).
    pub component: u32,
}

/// Where a ring's nodes lie in the pool as loaded: together, in input order.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LoadedRing {
    /// The ring's first node.
    pub first: u32,
    /// How many nodes it was loaded with.
    pub len: u32,
}

impl LoadedRing {
    /// The node after `i` (one of the ring's) as loaded: the next one, or the first after
    /// the last.
    pub fn next(self, i: u32) -> u32 {
        if i + 1 == self.first + self.len {
            self.first
        } else {
            i + 1
        }
    }

    /// The ring's nodes as loaded, in input order.
    pub fn nodes(self) -> core::ops::Range<u32> {
        self.first..self.first + self.len
    }
}

/// What the stages share: the node pool, the ring table, what was dropped and repaired,
/// and what one stage found for the next. Stages are functions over this context and
/// their own scratch.
#[derive(Debug, Default)]
pub(crate) struct Context {
    /// Every ring's nodes, linked in circular lists by index.
    pub pool: Pool,
    /// The rings, in input order (then the lobes `lobes` splits off).
    pub rings: Vec<Ring>,
    /// Input vertices left out, and why (for the `Report`).
    pub dropped: Vec<Dropped>,
    /// What lenient mode repaired (for the `Report`).
    pub repairs: Vec<Repair>,
    /// Lenient mode: repair instead of refusing.
    pub lenient: bool,
    /// Strict mode, for a caller that only asks whether the input passes (a fill rule's
    /// first try): `clean` refuses at the first crossing its proof meets, whichever it
    /// is, without the sweep that finds the one strict mode names, and does not search
    /// the edges as loaded for a crossing a dropped spike hid (`hidden_unchecked` says
    /// where it did not). Cleared by `reset`.
    pub probe: bool,
    /// With `probe`: the filter dropped a spike's tip or a ring of no area, and `clean`
    /// did not look for a crossing of the edges as loaded that the drop hid (the filtered
    /// rings' own check passed or not, as it says). Cleared by `reset`.
    pub hidden_unchecked: bool,
    /// `clean` keeps straight vertices: a first try dropped one where edges then crossed.
    /// Set for the rest of the call (every lenient rerun included).
    pub keep_collinear: bool,
    /// Per ring as loaded: where its nodes lie (set by `clean`, read by `nest`, `lobes`).
    pub as_loaded: Vec<LoadedRing>,
    /// The crossing edges `clean`'s sweep found (lenient mode; strict mode refuses them).
    pub crossings: Vec<Crossing>,
    /// Nodes at positions held by several nodes, sorted by position (set by `clean`, read
    /// by `lobes`, `nest` and `touch`).
    pub shared: Vec<NodeId>,
    /// Lenient mode: some ring touching itself was split into its lobes (by `lobes`).
    pub split_lobes: bool,
    /// Lenient mode: `lobes` leaves every ring whole, for the rest of the call (splitting
    /// them made two rings double each other, see `rings_doubled`).
    pub keep_lobes: bool,
    /// Lenient mode: two rings lie on each other with equal depths, each inside the
    /// other, so that the region there counts twice (strict mode refuses them as
    /// `Error::RingsOverlap`; set by `nest`).
    pub rings_doubled: bool,
    /// Lenient mode: a ring lies on another's boundary, inside it, where strict mode
    /// refuses it as `Error::RingsOverlap`: two rings each inside the other (which
    /// lenient mode makes cancel), or depths that do not make one the other's hole; or
    /// (`Nesting::Auto`, no edges crossing) rings cross at a vertex they share, where
    /// strict mode refuses them as `Error::RingsCrossAtVertex` (set by `nest`).
    pub rings_overlap: bool,
    /// The input rings `lobes` split (their lobes are the rings after `as_loaded`'s).
    pub lobe_rings: Vec<u32>,
    /// The live edges in a grid, built by `nest` and reused by `bridge`.
    pub edge_index: EdgeIndex,
    /// With a fill rule: the vertices added where edges cross (for the `Report`).
    pub added: Vec<Added>,
}

impl Context {
    /// Empties the context for a new run (buffers kept).
    pub(crate) fn reset(&mut self, lenient: bool) {
        self.pool.clear();
        self.rings.clear();
        self.dropped.clear();
        self.repairs.clear();
        self.lenient = lenient;
        self.probe = false;
        self.hidden_unchecked = false;
        self.split_lobes = false;
        self.rings_doubled = false;
        self.rings_overlap = false;
        self.edge_index.invalidate();
    }

    /// Records a lenient-mode repair.
    pub fn repair(&mut self, kind: RepairKind, ring: u32, vertex: u32) {
        self.repairs.push(Repair { kind, ring, vertex });
    }

    /// Takes a ring out of the triangulation (lenient mode), reporting its vertices.
    pub fn skip_ring(&mut self, r: usize) {
        let ring = self.rings[r];
        if !ring.alive {
            return;
        }
        self.rings[r].alive = false;
        let first = self.pool.get(ring.start).vertex;
        self.repair(RepairKind::HoleOutside, ring.input, first);
        for n in self.pool.ring(ring.start) {
            let vertex = self.pool.get(n).vertex;
            self.dropped.push(Dropped {
                vertex,
                ring: ring.input,
                reason: DropReason::RingSkipped,
            });
        }
    }

    /// The end of the run of `shared` from `i` on whose nodes share one position.
    pub fn same_position_end(&self, i: usize) -> usize {
        let p = self.pool.p(self.shared[i]);
        let mut j = i + 1;
        while j < self.shared.len() && self.pool.p(self.shared[j]) == p {
            j += 1;
        }
        j
    }

    /// Whether ring `r` is a lobe, or what is left of a ring split into lobes.
    pub fn is_lobe(&self, r: usize) -> bool {
        self.split_lobes && (r >= self.as_loaded.len() || self.lobe_rings.contains(&(r as u32)))
    }
}
