//! The short way for rings whose edges only cross each other properly (a simplified
//! border looping over itself, a bow tie): each crossing is rounded to the grid and both
//! edges are split there. Then, by even–odd, the passes through each point are relinked
//! so that they touch instead of crossing ([`relink`]): the rings then neither cross nor
//! change their even–odd region (beyond the rounding), and the usual pipeline, strict,
//! triangulates them. By the other rules (or where strict mode refuses the relinked
//! rings), the split edges go to the long way's winding sweep and tracing as they are
//! ([`wind`]), the sweep proving that they meet only at their ends. Where it finds
//! otherwise, or strict mode refuses the rings, the caller resolves the input the long
//! way ([`super::resolve`]).
//!
//! **Why the region stays.** A point's winding number is the signed count of the edges
//! a ray from it crosses, and its even–odd parity the count's parity: they depend on the
//! set of directed edges, not on how they are linked into rings. Splitting edge a–b at
//! the rounded crossing p′ replaces a–b by a–p′–b: winding numbers change only inside the
//! thin triangle a, b, p′, whose height is the rounding (less than a pixel's diagonal).
//! Relinking changes no edge. So the rings' region is the input's up to those
//! triangles, the same allowance as snap rounding's.
//!
//! **Why they do not cross.** Where a → p → b crosses c → p → d, the four directions
//! round p alternate between the two lines (a, c, b, d or a, d, b, c); the relinked passes
//! a → p → d and c → p → b each take two neighbouring directions, so they touch at p.
//! Where more edges cross at one point (or their crossings round to one point), its ways
//! in and out, by angle, are paired as parentheses pair ([`relink_round`]): no two pairs
//! interleave. That holds for exact crossings; a rounded point may upset it (or make a
//! split edge pass on the other side of a vertex) where edges come within a pixel of each
//! other. Nothing here relies on it: the pipeline's strict check decides exactly whether
//! the relinked rings cross anywhere, and its triangles are then exact for them; the
//! winding sweep proves the split edges planar before it counts.
//!
//! A crossing that rounds onto an end of one of its edges adds no vertex: that edge
//! passes through the point at its vertex, and that pass is relinked with the others; so
//! are the passes where rings meet at a vertex (a vertex inside another edge, two
//! vertices at one position, a crossing rounded onto a vertex), crossing there or not. The
//! short way declines (the long way runs) where no edges cross properly (they only
//! overlap or meet at vertices), where crossings are dense ([`DENSE`]) or where many
//! vertices lie where rings meet ([`SHARED`]).

use super::{
    bounds, find_crossings, ordered_bits, point, reach, typical_extent, unordered_bits, Edge,
    Scratch as Resolve,
};
use crate::geom::{cmp_around, in_range, on_ray, within_box, Point, SnapGrid};
use crate::report::Added;
use crate::structures::positions;
use crate::{Error, FillRule};

/// No edge or vertex.
const NONE: u32 = u32::MAX;

/// The short way declines with more crossing points than one in this many vertices
/// (measured: the crossing outlines of a world layer have one in 300 to 8,000 vertices,
/// the water fixtures one in 40 to 80; crossing star polygons and overlapping strokes,
/// one in 2 to 4, where rounding often makes relinked edges cross and strict mode
/// refuses them).
const DENSE: usize = 16;

/// The short way declines where more than one vertex in this many lies where rings meet
/// (a layer given at once, nearly every vertex on a neighbour's border): joining them
/// costs strict mode more than the long way takes, as in `strict_first`.
const SHARED: usize = 4;

/// Crossing points and vertices where rings meet that the short way takes beyond those
/// limits.
const FEW: usize = 16;

/// Pairs the crossing search may count beyond its limits on small input.
const SMALL: usize = 256;

/// The short way's buffers.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    /// Each node's successor: the input's vertices first, then the copies of the
    /// crossing points on their edges.
    next: Vec<u32>,
    /// The points (the rounded crossings and the positions where rings meet at
    /// vertices, each once), each with two edges crossing there (or [`NONE`]) and its
    /// output index.
    points: Vec<([f64; 2], u32, u32, u32)>,
    /// The points inside edges: (the edge's start vertex, the point), sorted along each
    /// edge; copy `t` is node `n + t`.
    on_edges: Vec<(u32, u32)>,
    /// The points at vertices (a crossing rounded onto an end of its edge, a vertex
    /// inside another edge or where another vertex is): (the point, the vertex).
    at_vertices: Vec<(u32, u32)>,
    /// Where edges meet at vertices ([`find_crossings`]'s contacts).
    contacts: Vec<(u32, u32)>,
    /// What happens at each point: (position, an edge split there or [`NONE`], a vertex
    /// there or [`NONE`]).
    marks: Vec<([f64; 2], u32, u32)>,
    /// Each node's neighbours once the edges are split, before relinking.
    around: Vec<[u32; 2]>,
    /// The passes by point: (point, node).
    by_point: Vec<(u32, u32)>,
    /// The ways into and out of one point (towards the node before or after a pass), by
    /// angle: (that node's position, whether it is the way in, the pass).
    ends: Vec<(Point, bool, u32)>,
    /// The ways in not yet paired with a way out ([`relink_round`]).
    open: Vec<u32>,
    seen: Vec<bool>,
    /// The table of [`repeated_positions`].
    table: Vec<u32>,
    /// The input's vertex count (nodes from it on are copies).
    n: usize,
    /// Every node's position as sorting keys, its output index and the node, sorted
    /// ([`wind`]); then each position once.
    spots: Vec<([u64; 2], u32, u32)>,
    /// Each node's position among them.
    spot: Vec<u32>,
    /// Per position: whether several nodes lie there.
    many: Vec<bool>,
}

/// Pairs the ways in and out of one point (`ends`, by angle round it, as many in as out)
/// so that no two pairs interleave — each way in with a way out as parentheses pair, read
/// from just after the lowest running count — and links each pair's passes: the pass of
/// a way in goes on where the pass of its way out went (`around`: each node's neighbours
/// before relinking). Pairs that do not interleave touch at the point without crossing.
fn relink_round(
    next: &mut [u32],
    ends: &[(Point, bool, u32)],
    around: &[[u32; 2]],
    open: &mut Vec<u32>,
) {
    let (mut count, mut lowest, mut from) = (0i64, 0i64, 0);
    for (k, &(_, way_in, _)) in ends.iter().enumerate() {
        count += if way_in { 1 } else { -1 };
        if count < lowest {
            (lowest, from) = (count, k + 1);
        }
    }
    open.clear();
    for k in 0..ends.len() {
        let (_, way_in, t) = ends[(from + k) % ends.len()];
        if way_in {
            open.push(t);
        } else if let Some(u) = open.pop() {
            next[u as usize] = around[t as usize][1];
        }
    }
}

/// Rings of the input's vertices and its rounded crossings whose even–odd region is the
/// input's (see the module docs), into `r.rings`, `r.ring_starts` and `r.map` (each
/// ring position's output index: an input vertex's own, or an added vertex's, pushed to
/// `added`). `Ok(false)` where the short way declines; `r`'s rings are empty then and
/// `added` is as it was.
///
/// With `rule`, the rings are instead those bounding the rule's region of the split
/// edges, as the long way traces them ([`rewind`]).
pub(crate) fn uncross(
    r: &mut Resolve,
    vertices: &[[f64; 2]],
    ring_starts: &[usize],
    grid: SnapGrid,
    added: &mut Vec<Added>,
    rule: Option<FillRule>,
) -> Result<bool, Error> {
    let mut s = core::mem::take(&mut r.uncross);
    let before = added.len();
    let made = split(
        r,
        &mut s,
        vertices,
        ring_starts,
        grid,
        added,
        rule.is_some(),
    );
    let made = made.map(|split| {
        split
            && match rule {
                None => {
                    relink(r, &mut s);
                    true
                }
                Some(rule) => wind(r, &mut s, rule),
            }
    });
    if made == Ok(false) {
        added.truncate(before);
    }
    r.uncross = s;
    made
}

/// After [`uncross`] relinked the rings (no rule) and strict mode refused them (edges
/// along each other, or rounding that made relinked edges cross): the rings bounding
/// `rule`'s region of the same split edges instead, into `r` as the long way leaves its
/// rings (`hot`, `hot_out`, `vertex_hot`, the rings and `map`). False where the split
/// edges meet other than at their ends; then only the long way can round them.
///
/// The region is the rule's region of the input up to the rounding, for every rule, by
/// the argument of the module docs: splitting moves the edges only within thin triangles,
/// and a point's winding number depends on the directed edges, not on their linking.
/// The sweep that counts the winding numbers ([`super::winding`]) proves the split edges
/// planar first.
pub(crate) fn rewind(r: &mut Resolve, rule: FillRule) -> bool {
    let mut s = core::mem::take(&mut r.uncross);
    let made = wind(r, &mut s, rule);
    r.uncross = s;
    made
}

/// How many of the points `hot` repeat a point before them (found in an open-addressing
/// table of indices by position), counted up to one past `most`.
fn repeated_positions(table: &mut Vec<u32>, hot: &[[f64; 2]], most: usize) -> usize {
    positions::reset_table(table, hot.len());
    let mut repeated = 0;
    for (v, &p) in hot.iter().enumerate() {
        let slot = positions::slot(table, p, |w| hot[w as usize]);
        if table[slot] == positions::EMPTY {
            table[slot] = v as u32;
        } else {
            repeated += 1;
            if repeated > most {
                return repeated;
            }
        }
    }
    repeated
}

/// Where a ring turns back along its last edge (a spike, which the crossing search
/// does not compare with its neighbour), the nearer of the two far ends lies on the other
/// edge: a contact, so that the two edges split into pieces that run between the same
/// points ([`wind`] then merges them).
fn spike_contacts(r: &Resolve, s: &mut Scratch) {
    let (hot, next) = (&r.hot, &s.next);
    for a in 0..next.len() {
        let b = next[a] as usize;
        let c = next[b] as usize;
        if b == a || c == a {
            continue;
        }
        let [pa, pb, pc] = [a, b, c].map(|v| point(hot[v]));
        // (back along a → b: c on the ray from b through a)
        if !on_ray(pb, pa, pc) {
            continue;
        }
        if pa == pc {
            s.contacts.push((a as u32, NONE));
            s.contacts.push((c as u32, NONE));
        } else if within_box(pa, pb, pc) {
            s.contacts.push((c as u32, a as u32));
        } else {
            s.contacts.push((a as u32, b as u32));
        }
    }
}

/// [`uncross`] up to the split edges (`s.around`, each node's neighbours), with its
/// buffers apart from the stage's: false where the short way declines. With `spikes`,
/// the edges of spikes are split where they run along each other
/// ([`spike_contacts`]).
fn split(
    r: &mut Resolve,
    s: &mut Scratch,
    vertices: &[[f64; 2]],
    ring_starts: &[usize],
    grid: SnapGrid,
    added: &mut Vec<Added>,
    spikes: bool,
) -> Result<bool, Error> {
    r.rings.clear();
    r.ring_ids.clear();
    r.ring_starts.clear();
    r.map.clear();
    let n = vertices.len();
    s.n = n;
    let in_grid = |p: &[f64; 2]| in_range(p[0]) && in_range(p[1]);
    if n == 0 || u32::try_from(n).is_err() || !vertices.iter().all(in_grid) {
        return Ok(false);
    }
    // every vertex its own point; a vertex repeating the position of the one before it
    // on its ring (a closing point, say) is left out (its successor itself), and the
    // rings link the others
    r.hot.clear();
    r.hot
        .extend(vertices.iter().map(|p| [p[0] + 0.0, p[1] + 0.0]));
    // (a layer given at once: most vertices on a neighbour's border, found before any
    // search)
    let shared = n / SHARED + FEW;
    if repeated_positions(&mut s.table, &r.hot, shared) > shared {
        return Ok(false);
    }
    s.next.clear();
    s.next.extend(0..n as u32);
    r.edges.clear();
    for (k, &start) in ring_starts.iter().enumerate() {
        let end = ring_starts.get(k + 1).copied().unwrap_or(n).min(n);
        let Some(first) = (start..end).next() else {
            continue;
        };
        let mut last = first;
        for i in start + 1..end {
            if r.hot[i] != r.hot[last] {
                s.next[last] = i as u32;
                last = i;
            }
        }
        // (the ring's last kept vertex at its first one's position: left out too)
        if last != first && r.hot[last] == r.hot[first] {
            let mut before = first;
            while s.next[before] as usize != last {
                before = s.next[before] as usize;
            }
            s.next[last] = last as u32;
            last = before;
        }
        s.next[last] = first as u32;
        let mut v = first;
        loop {
            let w = s.next[v] as usize;
            if w != v {
                let (v, w) = (v as u32, w as u32);
                r.edges.push(Edge {
                    from: v,
                    a: v,
                    b: w,
                    count: 1,
                });
            }
            if w == first {
                break;
            }
            v = w;
        }
    }
    if ring_starts.first() != Some(&0) || r.edges.is_empty() {
        return Ok(false);
    }
    r.typical = typical_extent(&r.edges, &r.hot);
    let (lo, hi) = bounds(&r.hot);
    s.contacts.clear();
    let reach = reach(grid, lo, hi);
    // (a few always: small input costs little either way)
    let dense = n / DENSE + FEW;
    // (the search counts a pair in every cell the two edges share: on small input,
    // long edges share most cells)
    let most = [4 * dense + SMALL, shared / 2 + SMALL, 2 * dense];
    if !find_crossings(r, lo, hi, grid, reach, Some(&mut s.contacts), most) {
        return Ok(false);
    }
    if r.crossings.is_empty() {
        return Ok(false);
    }
    if spikes {
        spike_contacts(r, s);
    }
    let order = |x: &[f64; 2], y: &[f64; 2]| x[0].total_cmp(&y[0]).then(x[1].total_cmp(&y[1]));
    r.crossings.sort_unstable_by(|x, y| order(&x.0, &y.0));
    let hot = &r.hot;
    // the points: the rounded crossings and the positions where edges meet at vertices,
    // each once (several edges may pass through one); at each, the edges passing through
    // it inside are split there, and the vertices there are passes through it too
    s.marks.clear();
    for &(p, e, f) in &r.crossings {
        for e in [e, f] {
            let end = s.next[e as usize];
            if p == hot[e as usize] {
                s.marks.push((p, NONE, e));
            } else if p == hot[end as usize] {
                s.marks.push((p, NONE, end));
            } else {
                s.marks.push((p, e, NONE));
            }
        }
    }
    for &(v, e) in &s.contacts {
        let p = hot[v as usize];
        s.marks.push((p, NONE, v));
        if e != NONE {
            s.marks.push((p, e, NONE));
        }
    }
    s.marks
        .sort_unstable_by(|x, y| order(&x.0, &y.0).then((x.1, x.2).cmp(&(y.1, y.2))));
    s.marks.dedup();
    s.points.clear();
    s.on_edges.clear();
    s.at_vertices.clear();
    let mut crossing = r.crossings.iter().peekable();
    for &(p, e, v) in &s.marks {
        if s.points.last().map(|q| q.0) != Some(p) {
            // (an added vertex names two edges crossing there, if any do)
            while crossing.next_if(|c| order(&c.0, &p).is_lt()).is_some() {}
            let edges = crossing
                .peek()
                .filter(|c| c.0 == p)
                .map_or((NONE, NONE), |c| (c.1, c.2));
            s.points.push((p, edges.0, edges.1, NONE));
        }
        let at = (s.points.len() - 1) as u32;
        if e != NONE {
            s.on_edges.push((e, at));
        } else {
            s.at_vertices.push((at, v));
        }
    }
    // (many points: where crossings are dense, rounding often makes relinked edges cross,
    // and the long way would run after all; where rings meet at many vertices, joining
    // them costs strict mode more than the long way takes)
    if s.points.len() > dense || s.at_vertices.len() > shared {
        return Ok(false);
    }
    // the points on each edge, in order from its start: the points met on a segment
    // have monotone coordinates, so ordering by (±x, ±y) as the edge runs orders them
    // along it (each point once per edge)
    if u32::try_from(n + s.on_edges.len()).is_err() {
        return Ok(false);
    }
    let (points, next) = (&s.points, &s.next);
    s.on_edges.sort_unstable_by(|&(e, c), &(f, d)| {
        e.cmp(&f).then_with(|| {
            let (a, b) = (hot[e as usize], hot[next[e as usize] as usize]);
            let (p, q) = (points[c as usize].0, points[d as usize].0);
            let along = |p: [f64; 2]| {
                let sx = if b[0] >= a[0] { p[0] } else { -p[0] };
                let sy = if b[1] >= a[1] { p[1] } else { -p[1] };
                [sx, sy]
            };
            order(&along(p), &along(q))
        })
    });
    s.on_edges.dedup();
    // split the edges: edge i → j becomes i → copies → j
    let base = n as u32;
    s.next.resize(n + s.on_edges.len(), 0);
    let mut t = 0;
    while t < s.on_edges.len() {
        let e = s.on_edges[t].0;
        let end = s.next[e as usize];
        let mut at = e;
        while t < s.on_edges.len() && s.on_edges[t].0 == e {
            let copy = base + t as u32;
            s.next[at as usize] = copy;
            (at, t) = (copy, t + 1);
        }
        s.next[at as usize] = end;
    }
    // every node's neighbours before relinking
    s.around.clear();
    s.around.resize(s.next.len(), [0; 2]);
    for (v, &w) in s.next.iter().enumerate() {
        s.around[v][1] = w;
        s.around[w as usize][0] = v as u32;
    }
    // each point's output index: the input vertex there (the lowest), or an added
    // vertex
    for &(at, v) in s.at_vertices.iter().rev() {
        s.points[at as usize].3 = v;
    }
    for point in &mut s.points {
        if point.3 == NONE {
            let vertex = n + added.len();
            let vertex =
                u32::try_from(vertex).map_err(|_| Error::TooManyVertices { count: vertex })?;
            added.push(Added {
                vertex,
                position: point.0,
                edges: [point.1, point.2],
            });
            point.3 = vertex;
        }
    }
    Ok(true)
}

/// The position of node `v` (an input vertex, or a copy of a point) once split.
fn position(r: &Resolve, s: &Scratch, v: u32) -> [f64; 2] {
    if (v as usize) < s.n {
        r.hot[v as usize]
    } else {
        s.points[s.on_edges[v as usize - s.n].1 as usize].0
    }
}

/// The output index of node `v`: an input vertex's own, or its point's.
fn output(s: &Scratch, v: u32) -> u32 {
    if (v as usize) < s.n {
        v
    } else {
        s.points[s.on_edges[v as usize - s.n].1 as usize].3
    }
}

/// The even–odd rings of the split edges: at each point, the passes through it (copies
/// and vertices) relinked so that they touch; then the cycles, into `r.rings`,
/// `r.ring_starts` and `r.map`.
fn relink(r: &mut Resolve, s: &mut Scratch) {
    s.by_point.clear();
    let base = s.n as u32;
    let copies = (0..s.on_edges.len() as u32).map(|t| (s.on_edges[t as usize].1, base + t));
    s.by_point
        .extend(copies.chain(s.at_vertices.iter().copied()));
    s.by_point.sort_unstable();
    for group in s.by_point.chunk_by(|x, y| x.0 == y.0) {
        let o = point(s.points[group[0].0 as usize].0);
        // each pass's way in and way out, by angle round the point
        s.ends.clear();
        for &(_, v) in group {
            let [before, after] = s.around[v as usize];
            s.ends.push((point(position(r, s, before)), true, v));
            s.ends.push((point(position(r, s, after)), false, v));
        }
        s.ends.sort_by(|x, y| cmp_around(o, x.0, y.0));
        relink_round(&mut s.next, &s.ends, &s.around, &mut s.open);
    }
    // the rings: the cycles of the successors, from every node not yet on one
    let nodes = s.next.len();
    s.seen.clear();
    s.seen.resize(nodes, false);
    for start in 0..nodes {
        // (a vertex left out is its own successor)
        if s.seen[start] || s.next[start] as usize == start {
            continue;
        }
        r.ring_starts.push(r.rings.len());
        let mut v = start;
        while !s.seen[v] {
            s.seen[v] = true;
            r.rings.push(position(r, s, v as u32));
            r.map.push(output(s, v as u32));
            v = s.next[v] as usize;
        }
    }
}

/// [`rewind`] with the stage's buffers apart.
fn wind(r: &mut Resolve, s: &mut Scratch, rule: FillRule) -> bool {
    // every linked node's position once (sorted: x, then y), named by the lowest output
    // index there (an input vertex's before an added one's); a vertex left out (a
    // repeat, or a ring of one position) is no point of the edges
    let nodes = s.around.len();
    let key = |p: [f64; 2]| [ordered_bits(p[0]), ordered_bits(p[1])];
    s.spots.clear();
    for v in (0..nodes as u32).filter(|&v| s.around[v as usize][1] != v) {
        s.spots.push((key(position(r, s, v)), output(s, v), v));
    }
    s.spots.sort_unstable();
    s.spot.clear();
    s.spot.resize(nodes, NONE);
    s.many.clear();
    let mut last = None;
    let mut points = 0;
    for k in 0..s.spots.len() {
        let (key, out, v) = s.spots[k];
        if last != Some(key) {
            last = Some(key);
            s.spots[points] = (key, out, v);
            s.many.push(false);
            points += 1;
        } else {
            s.many[points - 1] = true;
        }
        s.spot[v as usize] = (points - 1) as u32;
    }
    s.spots.truncate(points);
    // the split edges between distinct points, merged where several join two points:
    // only an edge whose ends are both held by several nodes, or lie on a spike's two
    // sides, can have a twin (at an end held by one node, the edge's only company is the
    // pass's other edge), so only those are sorted
    r.fragments.clear();
    r.split.clear();
    for v in 0..nodes {
        let [u, w] = s.around[v].map(|x| x as usize);
        let (a, b) = (s.spot[v], s.spot[w]);
        if w == v || a == b {
            continue;
        }
        let x = s.around[w][1] as usize;
        let twin_at_a = s.many[a as usize] || s.spot[u] == b;
        let twin_at_b = s.many[b as usize] || s.spot[x] == a;
        let e = Edge {
            from: NONE,
            a,
            b,
            count: 1,
        };
        if twin_at_a && twin_at_b {
            r.split.push(e);
        } else {
            r.fragments.push(e);
        }
    }
    super::merge_fragments(&mut r.split);
    r.fragments.extend_from_slice(&r.split);
    // (each input vertex's point, a vertex left out the one at its position, if any)
    r.vertex_hot.clear();
    for v in 0..s.n {
        let at = match s.spot[v] {
            NONE => (s.spots.binary_search_by(|spot| spot.0.cmp(&key(r.hot[v]))))
                .map_or(NONE, |k| k as u32),
            spot => spot,
        };
        r.vertex_hot.push(at);
    }
    // the points (the input's positions read: `r.hot` takes them)
    r.hot.clear();
    r.hot
        .extend(s.spots.iter().map(|(key, _, _)| key.map(unordered_bits)));
    r.hot_out.clear();
    r.hot_out.extend(s.spots.iter().map(|&(_, out, _)| out));
    r.rings.clear();
    r.ring_ids.clear();
    r.ring_starts.clear();
    r.map.clear();
    if !super::winding::boundary(&mut r.winding, &r.hot, &r.fragments, rule, true) {
        return false;
    }
    // (planar edges, each directed with the region on its left: the tracer links them)
    let traced = super::trace::rings(&mut r.trace, &r.hot, &r.winding.boundary);
    debug_assert!(traced.is_ok(), "the winding sweep proved the edges planar");
    traced.is_ok() && {
        super::take_traced(r);
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::FillRule;

    type Rings = Vec<Vec<[f64; 2]>>;

    /// The relinked rings of `rings`, and the vertices added.
    fn relinked(rings: &[Vec<[f64; 2]>]) -> Option<(Rings, Vec<Added>)> {
        uncrossed(rings, None)
    }

    /// [`uncross`]'s rings of `rings` (relinked, or by `rule`), and the vertices added.
    fn uncrossed(rings: &[Vec<[f64; 2]>], rule: Option<FillRule>) -> Option<(Rings, Vec<Added>)> {
        let (vertices, starts) = flat(rings);
        let mut r = Resolve::default();
        let mut added = Vec::new();
        let grid = SnapGrid { f32: false };
        if !uncross(&mut r, &vertices, &starts, grid, &mut added, rule).unwrap() {
            assert!(added.is_empty() && r.rings.is_empty());
            return None;
        }
        Some((rings_of(&r, &vertices, &added), added))
    }

    /// `r`'s rings as lists of positions, each checked against its output index.
    fn rings_of(r: &Resolve, vertices: &[[f64; 2]], added: &[Added]) -> Rings {
        let ends = r.ring_starts.iter().skip(1).copied().chain([r.rings.len()]);
        let out = (r.ring_starts.iter().zip(ends))
            .map(|(&a, b)| r.rings[a..b].to_vec())
            .collect();
        // each position's output index: an input vertex's own, or an added one's
        for (p, &id) in r.rings.iter().zip(&r.map) {
            let at = if (id as usize) < vertices.len() {
                vertices[id as usize]
            } else {
                added[id as usize - vertices.len()].position
            };
            assert_eq!(*p, at);
        }
        out
    }

    fn flat(rings: &[Vec<[f64; 2]>]) -> (Vec<[f64; 2]>, Vec<usize>) {
        let rings: Vec<&[[f64; 2]]> = rings.iter().map(Vec::as_slice).collect();
        crate::testing::flatten(&rings)
    }

    /// The even–odd area of `rings` and the vertices added, the long way
    /// ([`super::super::resolve`]).
    fn even_odd(rings: &[Vec<[f64; 2]>]) -> (f64, usize) {
        long_way(rings, FillRule::EvenOdd)
    }

    /// The area of `rule`'s region of `rings` and the vertices added, the long way.
    fn long_way(rings: &[Vec<[f64; 2]>], rule: FillRule) -> (f64, usize) {
        let (vertices, starts) = flat(rings);
        let mut r = Resolve::default();
        let mut added = Vec::new();
        let grid = SnapGrid { f32: false };
        super::super::resolve(&mut r, &vertices, &starts, rule, grid, false, &mut added).unwrap();
        (signed_area(&rings_of(&r, &vertices, &added)), added.len())
    }

    /// The sum of the rings' signed areas (shoelace).
    fn signed_area(rings: &[Vec<[f64; 2]>]) -> f64 {
        let mut twice = 0.0;
        for ring in rings {
            for (j, p) in ring.iter().enumerate() {
                let q = ring[(j + 1) % ring.len()];
                twice += p[0] * q[1] - p[1] * q[0];
            }
        }
        twice / 2.0
    }

    /// Strict mode's check passes on `rings` (no crossing, also not at a vertex they
    /// share).
    fn assert_valid(rings: &[Vec<[f64; 2]>], name: &str) {
        let (vertices, starts) = flat(rings);
        let checked =
            crate::Triangulator::<f64>::new().check(&vertices, &starts, crate::Nesting::Auto);
        assert_eq!(checked, Ok(()), "{name}: {rings:?}");
    }

    fn square(x: f64, y: f64, side: f64) -> Vec<[f64; 2]> {
        vec![[x, y], [x + side, y], [x + side, y + side], [x, y + side]]
    }

    /// Inputs whose crossings are exact (no rounding), each with its number of
    /// crossing points.
    fn exact_crossings() -> Vec<(&'static str, Rings, usize)> {
        let bow_tie = vec![[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]];
        // a ring crossing itself twice, the way a simplified border does
        let loop_over = vec![
            [0.0, 0.0],
            [8.0, 0.0],
            [8.0, 4.0],
            [2.0, -2.0],
            [4.0, 6.0],
            [0.0, 4.0],
        ];
        // three edges through the origin
        let asterisk = vec![
            [-2.0, -1.0],
            [2.0, 1.0],
            [2.0, -1.0],
            [-2.0, 1.0],
            [0.0, 2.0],
            [0.0, -2.0],
        ];
        // a triangle crossing a band's edge at its vertex (2, 0), and inside the edge at
        // (3, 0); a ring touching a square's corner (4, 4) and crossing two of its sides
        let through_vertex = vec![[1.0, -1.0], [2.0, 0.0], [3.0, 1.0], [3.0, -1.0]];
        let at_corner = vec![[2.0, 5.0], [4.0, 4.0], [6.0, 5.0], [5.0, 1.0]];
        vec![
            ("three edges through one point", vec![asterisk], 1),
            (
                "a ring crossing an edge at its vertex",
                vec![square(0.0, 0.0, 4.0), through_vertex],
                1,
            ),
            (
                "a ring through another's corner",
                vec![square(0.0, 0.0, 4.0), at_corner],
                2,
            ),
            ("bow tie", vec![bow_tie], 1),
            (
                "overlapping squares",
                vec![square(0.0, 0.0, 2.0), square(1.0, 1.0, 2.0)],
                2,
            ),
            (
                "a hole across its outer ring",
                vec![square(0.0, 0.0, 4.0), square(3.0, 1.0, 2.0)],
                2,
            ),
            ("a ring looping over itself", vec![loop_over], 2),
            // rings running the same way round a shared part (winding 2 there), and
            // opposite ways (winding 0 there)
            (
                "overlapping squares, one reversed",
                vec![square(0.0, 0.0, 2.0), reversed(square(1.0, 1.0, 2.0))],
                2,
            ),
            (
                "a square crossing a ring wound twice",
                vec![
                    [square(0.0, 0.0, 4.0), square(0.0, 0.0, 4.0)].concat(),
                    square(3.0, 1.0, 2.0),
                ],
                2,
            ),
        ]
    }

    fn reversed(mut ring: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
        ring.reverse();
        ring
    }

    /// Crossings whose points are exact (no rounding): the relinked rings cross nowhere
    /// (the long way adds no vertex to them) and have the input's even–odd region.
    #[test]
    fn relinked_rings_touch_where_the_input_crossed_and_keep_its_region() {
        for (name, rings, crossings) in exact_crossings() {
            if name == "a square crossing a ring wound twice" {
                // (the ring wound twice touches itself at every vertex: see below)
                continue;
            }
            let (area, long_way_added) = even_odd(&rings);
            assert_eq!(long_way_added, crossings, "{name}");
            let (relinked, added) = relinked(&rings).unwrap_or_else(|| panic!("{name}: declined"));
            assert_eq!(added.len(), crossings, "{name}");
            let (relinked_area, again) = even_odd(&relinked);
            assert_eq!(again, 0, "{name}: the relinked rings cross");
            assert_valid(&relinked, name);
            assert!(
                (relinked_area - area).abs() < 1e-12,
                "{name}: {relinked_area} against {area}"
            );
            assert!(
                relinked.iter().all(|r| r.len() >= 3),
                "{name}: {relinked:?}"
            );
        }
    }

    /// By every rule, the rings of the split edges bound the rule's region as the long
    /// way does (equal areas: the crossings are exact), pass strict mode's check, and
    /// add the crossing points; after the even–odd relinking, [`rewind`] gives the same
    /// rings from the same split edges.
    #[test]
    fn every_rule_bounds_its_region_of_the_split_edges() {
        let mut cases = exact_crossings();
        cases.push(("pentagram", vec![super::super::tests::pentagram()], 5));
        for (name, rings, crossings) in cases {
            for rule in FillRule::ALL {
                let (area, _) = long_way(&rings, rule);
                let (bounds, added) = uncrossed(&rings, Some(rule))
                    .unwrap_or_else(|| panic!("{name}, {rule:?}: declined"));
                assert_eq!(added.len(), crossings, "{name}, {rule:?}");
                let tolerance = if name == "pentagram" { 1e-9 } else { 1e-12 };
                let bounded = signed_area(&bounds);
                assert!(
                    (bounded - area).abs() <= tolerance * area.abs().max(1.0),
                    "{name}, {rule:?}: {bounded} against {area}"
                );
                if !bounds.is_empty() {
                    assert_valid(&bounds, name);
                }
            }
            // the even–odd rings again, after relinking, from the same split edges
            let (vertices, starts) = flat(&rings);
            let mut r = Resolve::default();
            let mut added = Vec::new();
            let grid = SnapGrid { f32: false };
            assert!(uncross(&mut r, &vertices, &starts, grid, &mut added, None).unwrap());
            assert!(rewind(&mut r, FillRule::EvenOdd), "{name}");
            let again = signed_area(&rings_of(&r, &vertices, &added));
            let (area, _) = even_odd(&rings);
            assert!((again - area).abs() <= 1e-9 * area.abs(), "{name}");
        }
    }

    /// A crossing rounded past a vertex: a split edge then crosses edges that no edge
    /// crossed before, which the sweep counting winding numbers finds: by every rule, the
    /// short way declines (the long way's snap rounding takes such input).
    #[test]
    fn split_edges_that_rounding_made_cross_are_declined() {
        // a–b and c–d cross at p, rounded to p′ below a–b; w lies strictly between a–b
        // and a → p′ (found by exact search among the points near p′), the apex of a
        // thin triangle hanging below it, between a–b and c–d, which it meets nowhere
        let (a, b, c, d) = ([0.0, 0.0], [3.0, 1.1], [1.0, -1.0], [1.3, 1.0]);
        let w = [1.216931216931212, 0.4462081128747778];
        let hanging = vec![w, [w[0] - 0.01, w[1] - 0.01], [w[0] - 0.005, w[1] - 0.01]];
        let rings = vec![vec![a, b, d, c], hanging];
        for rule in FillRule::ALL {
            assert!(uncrossed(&rings, Some(rule)).is_none(), "{rule:?}");
        }
        // relinked, they cross: strict mode refuses them
        let (relinked, added) = relinked(&rings).expect("relinked");
        assert_eq!(added.len(), 1);
        let (vertices, starts) = flat(&relinked);
        let checked =
            crate::Triangulator::<f64>::new().check(&vertices, &starts, crate::Nesting::Auto);
        assert!(checked.is_err());
    }

    #[test]
    fn a_pentagram_becomes_five_points_round_a_pentagon() {
        let star = super::super::tests::pentagram();
        let (relinked, added) = relinked(core::slice::from_ref(&star)).expect("relinked");
        assert_eq!(added.len(), 5);
        let mut sizes: Vec<usize> = relinked.iter().map(Vec::len).collect();
        sizes.sort_unstable();
        // each edge crossed twice: the centre, a pentagon of crossings alone, and the
        // star's outline round it, touching it at every crossing
        assert_eq!(sizes, [5, 10]);
        let (area, _) = even_odd(&[star]);
        let (relinked_area, again) = even_odd(&relinked);
        assert_eq!(again, 0);
        assert_valid(&relinked, "pentagram");
        // (rounded crossings: the regions differ within a pixel of each)
        assert!(
            (relinked_area - area).abs() < 1e-9 * area.abs(),
            "{relinked_area} {area}"
        );
    }

    /// Edges from a vertex cross another edge within rounding of that vertex: the
    /// crossings round onto it, nothing is added, and the other edge passes through the
    /// vertex instead.
    #[test]
    fn crossings_rounded_onto_a_vertex_go_through_it() {
        // the bottom edge of the band runs from (0, 1) to (2, 1 − 2⁻⁵³): at x = 1 it is
        // 2⁻⁵⁴ below the triangle's top vertex (1, 1), and both of the triangle's edges
        // there cross it, at points that round to (1, 1)
        let low = 1.0 - f64::EPSILON / 2.0;
        let band = vec![[0.0, 1.0], [2.0, low], [2.0, 3.0], [0.0, 3.0]];
        let triangle = vec![[1.0, 1.0], [1.0, 0.0], [0.5, 0.5]];
        let rings = [band, triangle];
        let (relinked, added) = relinked(&rings).expect("relinked");
        assert!(added.is_empty(), "{added:?}");
        assert_eq!(relinked.iter().map(Vec::len).sum::<usize>(), 8);
        assert_valid(&relinked, "rounded onto a vertex");
        let (area, _) = even_odd(&rings);
        let (relinked_area, _) = even_odd(&relinked);
        assert!(
            (relinked_area - area).abs() < 1e-12,
            "{relinked_area} against {area}"
        );
    }

    /// The table finds every repeat, round coordinates (whose low bits are all zero)
    /// included, and stops counting one past the limit.
    #[test]
    fn repeated_positions_counts_the_repeats() {
        let mut below = crate::testing::random(7);
        for (cells, scale) in [(8u64, 1.0), (1000, 0.5), (40, 1e-3)] {
            let hot: Vec<[f64; 2]> = (0..500)
                .map(|_| [below(cells) as f64 * scale, below(cells) as f64 * scale])
                .collect();
            let mut sorted = hot.clone();
            sorted.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
            sorted.dedup();
            let repeats = hot.len() - sorted.len();
            let mut table = Vec::new();
            assert_eq!(repeated_positions(&mut table, &hot, usize::MAX), repeats);
            if repeats > 3 {
                assert_eq!(repeated_positions(&mut table, &hot, 3), 4);
            }
        }
        assert_eq!(repeated_positions(&mut Vec::new(), &[], 0), 0);
    }

    #[test]
    fn declines_where_nothing_crosses_properly() {
        // apart; touching at a corner; overlapping along an edge
        let apart = [square(0.0, 0.0, 1.0), square(2.0, 0.0, 1.0)];
        let corner = [square(0.0, 0.0, 1.0), square(1.0, 1.0, 1.0)];
        let along = [square(0.0, 0.0, 2.0), square(2.0, 0.0, 2.0)];
        for rings in [&apart[..], &corner, &along, &[]] {
            assert!(relinked(rings).is_none(), "{rings:?}");
        }
    }
}
