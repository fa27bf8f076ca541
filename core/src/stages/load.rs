//! Stage 1, *load*: every ring's vertices become nodes of one pool, each ring a circular
//! doubly linked list. Input is checked here: finite coordinates, sane ring starts.

use crate::context::{Context, Ring};
use crate::geom::Coord;
use crate::geom::{orient_exact, Point};
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
        orient_exact(p.x) && orient_exact(p.y)
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
/// a new ring, linked in order: lenient mode drops the others, strict mode refuses them;
/// and coordinates too large or too small for exact signs ([`orient_exact`]) strict mode
/// refuses too, while lenient mode keeps them (best effort: its signs may be wrong).
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
        let exact = orient_exact(p.x) && orient_exact(p.y);
        if !exact && !cx.lenient {
            return Err(Error::CoordinateRange { vertex: i });
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::DropReason;

    fn loaded(
        vertices: &[[f64; 2]],
        starts: &[usize],
        lenient: bool,
    ) -> (Context, Result<(), Error>) {
        let mut cx = Context::default();
        cx.reset(lenient);
        let result = load(&mut cx, vertices, starts);
        (cx, result)
    }

    const SQUARE_AND_HOLE: [[f64; 2]; 7] = [
        [0.0, 0.0],
        [4.0, 0.0],
        [4.0, 4.0],
        [0.0, 4.0],
        [1.0, 1.0],
        [2.0, 2.0],
        [1.0, 2.0],
    ];

    #[test]
    fn rings_become_circular_lists_in_input_order() {
        let (cx, result) = loaded(&SQUARE_AND_HOLE, &[0, 4], false);
        assert_eq!(result, Ok(()));
        assert_eq!(cx.rings.len(), 2);
        for (r, (first, len)) in [(0u32, 4u32), (4, 3)].into_iter().enumerate() {
            let ring = cx.rings[r];
            assert_eq!((ring.input, ring.len), (r as u32, len));
            let vertices: Vec<u32> = cx
                .pool
                .ring(ring.start)
                .map(|n| cx.pool.get(n).vertex)
                .collect();
            assert_eq!(vertices, (first..first + len).collect::<Vec<_>>());
            for n in cx.pool.ring(ring.start) {
                assert_eq!(cx.pool.prev(cx.pool.next(n)), n);
                assert_eq!(cx.pool.get(n).ring, r as u32);
            }
        }
    }

    #[test]
    fn bad_ring_starts_are_refused_where_they_are() {
        let v = &SQUARE_AND_HOLE;
        assert_eq!(
            loaded(v, &[1, 4], false).1,
            Err(Error::FirstRingStart { start: Some(1) })
        );
        assert_eq!(
            loaded(v, &[], false).1,
            Err(Error::FirstRingStart { start: None })
        );
        assert_eq!(
            loaded(v, &[0, 4, 3], false).1,
            Err(Error::RingStartsNotIncreasing {
                ring: 2,
                start: 3,
                previous: 4
            })
        );
        assert_eq!(
            loaded(v, &[0, 9], false).1,
            Err(Error::RingStartOutOfRange {
                ring: 1,
                start: 9,
                len: 7
            })
        );
        // lenient mode skips the bad start and says so
        let (cx, result) = loaded(v, &[0, 9, 4], true);
        assert_eq!(result, Ok(()));
        assert_eq!(cx.rings.len(), 2);
        assert!(cx
            .repairs
            .iter()
            .any(|r| r.kind == RepairKind::RingStartIgnored && r.ring == 1));
    }

    #[test]
    fn non_finite_coordinates_are_refused_or_dropped() {
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let mut v = SQUARE_AND_HOLE;
            v[5][1] = bad;
            assert_eq!(
                loaded(&v, &[0, 4], false).1,
                Err(Error::NonFinite { vertex: 5 })
            );
            let (cx, result) = loaded(&v, &[0, 4], true);
            assert_eq!(result, Ok(()));
            let dropped: Vec<_> = cx
                .dropped
                .iter()
                .filter(|d| d.reason == DropReason::NonFinite)
                .collect();
            assert_eq!(dropped.len(), 1);
            assert_eq!((dropped[0].vertex, dropped[0].ring), (5, 1));
            assert!(cx
                .pool
                .nodes
                .iter()
                .all(|n| n.p.x.is_finite() && n.p.y.is_finite()));
        }
    }

    #[test]
    fn coordinates_beyond_exact_signs_are_refused_or_kept() {
        let (max, min) = (crate::geom::ORIENT_MAX, crate::geom::ORIENT_MIN);
        for bad in [1e300, -1e200, max, 1e-300, -min / 2.0, f64::MIN_POSITIVE] {
            let mut v = SQUARE_AND_HOLE;
            v[5][1] = bad;
            let (_, result) = loaded(&v, &[0, 4], false);
            assert_eq!(result, Err(Error::CoordinateRange { vertex: 5 }), "{bad}");
            // lenient mode keeps the vertex (best effort)
            let (cx, result) = loaded(&v, &[0, 4], true);
            assert_eq!(result, Ok(()));
            assert_eq!(cx.pool.len(), 7);
            assert!(cx.dropped.is_empty());
        }
        // the ends of the range, and zero, are fine
        let below_max = max * (1.0 - f64::EPSILON / 2.0);
        for good in [below_max, -below_max, min, -min, 0.0, -0.0] {
            let mut v = SQUARE_AND_HOLE;
            v[5][0] = good;
            assert_eq!(loaded(&v, &[0, 4], false).1, Ok(()), "{good}");
        }
        // a non-finite vertex before an out-of-range one is named first
        let mut v = SQUARE_AND_HOLE;
        (v[2][0], v[5][0]) = (f64::NAN, 1e300);
        assert_eq!(
            loaded(&v, &[0, 4], false).1,
            Err(Error::NonFinite { vertex: 2 })
        );
    }

    #[test]
    fn no_vertices_load_nothing() {
        let (cx, result) = loaded(&[], &[], false);
        assert_eq!(result, Ok(()));
        assert!(cx.rings.is_empty() && cx.pool.len() == 0);
        // an f32 input is widened exactly
        let mut cx = Context::default();
        let v32 = [[0.1f32, 0.2], [1.0, 0.0], [0.0, 1.0]];
        assert_eq!(load(&mut cx, &v32, &[0]), Ok(()));
        assert_eq!(cx.pool.p(cx.rings[0].start).x, f64::from(0.1f32));
    }
}
