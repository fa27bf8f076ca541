//! Stage 1, *load*: every ring's vertices become nodes of one pool, each ring a circular
//! doubly linked list. Input is checked here: finite coordinates, sane ring starts.

use crate::context::{Context, Ring};
use crate::geom::Coord;
use crate::geom::Point;
use crate::report::{DropReason, Dropped, RepairKind};
use crate::structures::NodeId;
use crate::Error;

/// Loads the input into `cx.pool` and `cx.rings`.
pub(crate) fn load<T: Coord>(
    cx: &mut Context,
    vertices: &[[T; 2]],
    ring_starts: &[usize],
) -> Result<(), Error> {
    if vertices.len() > u32::MAX as usize - 1 {
        return Err(Error::TooManyVertices {
            count: vertices.len(),
        });
    }
    if vertices.is_empty() {
        return Ok(());
    }
    check_first_start(cx, ring_starts)?;
    let mut ring = 0;
    while ring < ring_starts.len() {
        let start = ring_starts[ring];
        // the next start that is usable; in lenient mode bad ones are skipped
        let mut k = ring + 1;
        let end = loop {
            match ring_starts.get(k) {
                None => break vertices.len(),
                Some(&s) if s > start && s < vertices.len() => break s,
                Some(&s) => {
                    if !cx.lenient {
                        return Err(if s >= vertices.len() {
                            Error::RingStartOutOfRange {
                                ring: k,
                                start: s,
                                len: vertices.len(),
                            }
                        } else {
                            Error::RingStartsNotIncreasing {
                                ring: k,
                                start: s,
                                previous: start,
                            }
                        });
                    }
                    cx.repair(
                        RepairKind::RingStartIgnored,
                        k as u32,
                        s.min(u32::MAX as usize) as u32,
                    );
                    k += 1;
                }
            }
        };
        load_ring(cx, vertices, start, end, ring as u32)?;
        ring = k;
    }
    Ok(())
}

/// The first ring must start at vertex 0; lenient mode pretends it does.
fn check_first_start(cx: &mut Context, ring_starts: &[usize]) -> Result<(), Error> {
    match ring_starts.first() {
        Some(0) => Ok(()),
        other if cx.lenient => {
            let s = other.copied().unwrap_or(0);
            cx.repair(
                RepairKind::RingStartIgnored,
                0,
                s.min(u32::MAX as usize) as u32,
            );
            Ok(())
        }
        other => Err(Error::FirstRingStart {
            start: other.copied(),
        }),
    }
}

/// Loads vertices `start..end` as ring number `input` (its position in `ring_starts`).
/// The ring whose first start is not 0 in lenient mode also covers the vertices before it.
fn load_ring<T: Coord>(
    cx: &mut Context,
    vertices: &[[T; 2]],
    start: usize,
    end: usize,
    input: u32,
) -> Result<(), Error> {
    let start = if input == 0 { 0 } else { start };
    let ring = cx.rings.len() as u32;
    let first = cx.pool.len() as u32;
    let run = vertices.get(start..end).unwrap_or_default();
    let count = if run.iter().all(|v| {
        let p = position(v);
        p.x.is_finite() && p.y.is_finite()
    }) {
        // the usual case: every vertex is a node, in one go
        let nodes = run.iter().enumerate();
        cx.pool
            .push_ring(nodes.map(|(k, v)| (position(v), (start + k) as u32)), ring)
    } else {
        load_finite(cx, run, start, input)?;
        cx.pool.len() as u32 - first
    };
    if count == 0 {
        return Ok(());
    }
    cx.rings.push(Ring {
        input,
        start: NodeId(first),
        len: count,
        rightmost: NodeId(first),
        depth: 0,
        alive: true,
        merged: false,
        component: ring,
    });
    Ok(())
}

/// Loads the finite vertices of `run`, the first of which is vertex `start`, as nodes of
/// a new ring, linked in order: lenient mode drops the others, strict mode refuses them.
fn load_finite<T: Coord>(
    cx: &mut Context,
    run: &[[T; 2]],
    start: usize,
    input: u32,
) -> Result<(), Error> {
    let ring = cx.rings.len() as u32;
    let first = cx.pool.len() as u32;
    for (k, v) in run.iter().enumerate() {
        let i = start + k;
        let p = position(v);
        if !(p.x.is_finite() && p.y.is_finite()) {
            if !cx.lenient {
                return Err(Error::NonFinite { vertex: i });
            }
            cx.dropped.push(Dropped {
                vertex: i as u32,
                ring: input,
                reason: DropReason::NonFinite,
            });
            continue;
        }
        cx.pool.push(p, i as u32, ring);
    }
    cx.pool.link_run(first, cx.pool.len() as u32 - first);
    Ok(())
}

/// A vertex as a position. `+ 0.0` turns -0.0 into +0.0, so equal positions compare equal
/// bit for bit too.
#[inline]
fn position<T: Coord>(v: &[T; 2]) -> Point {
    Point::new(v[0].to_f64() + 0.0, v[1].to_f64() + 0.0)
}
