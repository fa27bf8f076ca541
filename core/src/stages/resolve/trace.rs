//! The region's boundary edges linked into simple rings.
//!
//! At each vertex the region's inside and outside alternate between consecutive boundary
//! edges, so every arriving edge is followed, clockwise, by a leaving one bounding the same
//! inside corner: linking each arriving edge to it walks the region's faces and never
//! crosses a walk over itself or another. A walk that comes back to a vertex it passed is
//! cut there into two rings, so every ring is simple; the rings meet only at vertices.

use core::cmp::Ordering;

use crate::geom::{orient2d, Orientation, Point};
use crate::Error;

/// The tracer's buffers and its rings.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    /// Leaving edges by vertex, in compressed rows.
    first: Vec<u32>,
    leaving: Vec<u32>,
    /// Arriving edges by vertex, in compressed rows.
    first_in: Vec<u32>,
    arriving: Vec<u32>,
    /// The edge each edge is followed by.
    next: Vec<u32>,
    seen: Vec<bool>,
    /// Where a vertex is on the current walk (`u32::MAX`: not on it).
    on_walk: Vec<u32>,
    walk: Vec<u32>,
    around: Vec<(u32, bool)>,
    /// The rings, as vertices, in compressed rows.
    ring_starts: Vec<usize>,
    ring_vertices: Vec<u32>,
}

impl Scratch {
    /// The rings traced, each as its vertices in order.
    pub fn rings(&self) -> impl Iterator<Item = &[u32]> + '_ {
        (0..self.ring_starts.len()).map(move |k| {
            let end = self
                .ring_starts
                .get(k + 1)
                .copied()
                .unwrap_or(self.ring_vertices.len());
            &self.ring_vertices[self.ring_starts[k]..end]
        })
    }
}

/// Links `edges` (directed, the region on their left) into simple rings.
pub(crate) fn rings(s: &mut Scratch, hot: &[[f64; 2]], edges: &[(u32, u32)]) -> Result<(), Error> {
    let n = hot.len();
    let broken = Error::Internal { stage: "resolve" };
    super::rows(&mut s.first, &mut s.leaving, n, edges.iter().map(|e| e.0));
    super::rows(
        &mut s.first_in,
        &mut s.arriving,
        n,
        edges.iter().map(|e| e.1),
    );
    s.next.clear();
    s.next.resize(edges.len(), u32::MAX);
    for v in 0..n {
        let out = &s.leaving[s.first[v] as usize..s.first[v + 1] as usize];
        let inc = &s.arriving[s.first_in[v] as usize..s.first_in[v + 1] as usize];
        if out.len() != inc.len() {
            return Err(broken);
        }
        if out.len() == 1 {
            s.next[inc[0] as usize] = out[0];
            continue;
        }
        if out.is_empty() {
            continue;
        }
        // every edge at v by the direction it leaves v in, counter-clockwise from +x
        let c = Point::new(hot[v][0], hot[v][1]);
        let far = |e: u32, leaving: bool| {
            let (a, b) = edges[e as usize];
            let p = hot[if leaving { b } else { a } as usize];
            Point::new(p[0], p[1])
        };
        s.around.clear();
        s.around.extend(out.iter().map(|&e| (e, true)));
        s.around.extend(inc.iter().map(|&e| (e, false)));
        let half = |p: Point| !(p.y > c.y || (p.y == c.y && p.x > c.x));
        s.around.sort_unstable_by(|&(e, l), &(f, m)| {
            let (p, q) = (far(e, l), far(f, m));
            half(p).cmp(&half(q)).then_with(|| match orient2d(c, p, q) {
                Orientation::CounterClockwise => Ordering::Less,
                Orientation::Clockwise => Ordering::Greater,
                Orientation::Collinear => Ordering::Equal,
            })
        });
        // an arriving edge is followed by the edge just clockwise of it
        let k = s.around.len();
        for i in 0..k {
            let (e, leaving) = s.around[i];
            if !leaving {
                let (f, f_leaves) = s.around[(i + k - 1) % k];
                if !f_leaves {
                    return Err(broken);
                }
                s.next[e as usize] = f;
            }
        }
    }
    s.seen.clear();
    s.seen.resize(edges.len(), false);
    s.on_walk.clear();
    s.on_walk.resize(n, u32::MAX);
    s.ring_starts.clear();
    s.ring_vertices.clear();
    for e0 in 0..edges.len() {
        if s.seen[e0] {
            continue;
        }
        s.walk.clear();
        let mut e = e0;
        loop {
            if s.seen.get(e) != Some(&false) {
                return Err(broken);
            }
            s.seen[e] = true;
            let v = edges[e].0;
            let at = s.on_walk[v as usize];
            if at != u32::MAX {
                // back at v: the loop since v's last visit is a ring
                cut(s, at as usize);
            }
            s.on_walk[v as usize] = s.walk.len() as u32;
            s.walk.push(v);
            e = s.next[e] as usize;
            if e == e0 {
                break;
            }
        }
        cut(s, 0);
    }
    Ok(())
}

/// Makes the walk from position `at` on a ring of its own.
fn cut(s: &mut Scratch, at: usize) {
    s.ring_starts.push(s.ring_vertices.len());
    for &v in &s.walk[at..] {
        s.on_walk[v as usize] = u32::MAX;
        s.ring_vertices.push(v);
    }
    s.walk.truncate(at);
}
