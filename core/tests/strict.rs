//! Strict mode (the default) refuses bad input with an error that says what and where;
//! lenient mode never refuses it and reports what it repaired or dropped.
//!
//! Only what needs neither the corpus nor a judge: error variants, their messages, counts
//! and drop reasons. Fixtures and judged results are in `oracle/tests/strict.rs`.

use polytri::{DropReason, Error, Nesting, Options, Strategy, Triangulator};

fn strict(strategy: Strategy) -> Options {
    Options::default()
        .with_strategy(strategy)
        .with_nesting(Nesting::FirstIsOuter)
}

/// The input rounded to `f32`, as given to a `Triangulator<f32>`.
fn to_f32(vertices: &[[f64; 2]]) -> Vec<[f32; 2]> {
    vertices
        .iter()
        .map(|&[x, y]| [x as f32, y as f32])
        .collect()
}

fn tri_f64(vertices: &[[f64; 2]], starts: &[usize], opts: Options) -> Result<usize, Error> {
    let mut out = Vec::new();
    Triangulator::<f64>::new()
        .triangulate(vertices, starts, &opts, &mut out)
        .map(|_| out.len())
}

const SQUARE: [[f64; 2]; 4] = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];

#[test]
fn non_finite_coordinates_are_named() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for (vertex, axis) in [(0, 0), (2, 1), (5, 0)] {
            let mut v: Vec<[f64; 2]> = SQUARE.to_vec();
            v.extend([[1.0, 1.0], [1.0, 2.0], [2.0, 1.0]]);
            v[vertex][axis] = bad;
            let err = tri_f64(&v, &[0, 4], Options::default()).unwrap_err();
            assert_eq!(err, Error::NonFinite { vertex }, "{bad} at vertex {vertex}");
            assert!(
                err.to_string().contains(&format!("vertex {vertex}")),
                "{err}"
            );
        }
    }
    // f32 too.
    let mut v32 = to_f32(&SQUARE);
    v32[3][1] = f32::NAN;
    let mut out = Vec::new();
    let err = Triangulator::<f32>::new()
        .triangulate(&v32, &[0], &Options::default(), &mut out)
        .unwrap_err();
    assert_eq!(err, Error::NonFinite { vertex: 3 });
}

#[test]
fn coordinates_beyond_exact_signs_are_named_in_strict_mode() {
    // Beyond 2^500 products of coordinate differences overflow; below 2^-480 they lose
    // bits: the signs would not be exact. Strict mode names the vertex, in every strategy
    // and in `check`; lenient mode still returns triangles. A whole ring scaled there too.
    let square: Vec<[f64; 2]> = SQUARE.to_vec();
    for scale in [1e300, 1e-300] {
        for vertex in [None, Some(2)] {
            let mut v = square.clone();
            match vertex {
                Some(i) => v[i][1] *= scale,
                None => v.iter_mut().flatten().for_each(|c| *c *= scale),
            }
            let expected = Error::CoordinateRange {
                vertex: vertex.unwrap_or(1),
            };
            for strategy in [Strategy::Fast, Strategy::Quality, Strategy::Seidel] {
                let opts = Options::default().with_strategy(strategy);
                assert_eq!(tri_f64(&v, &[0], opts), Err(expected), "{scale}");
            }
            let mut tri = Triangulator::<f64>::new();
            assert_eq!(tri.check(&v, &[0], Nesting::Auto), Err(expected));
            assert!(expected.to_string().contains("2^500"));
            let lenient = Options::default().with_lenient(true);
            assert!(tri_f64(&v, &[0], lenient).is_ok(), "{scale} lenient");
        }
    }
    // the same square just inside the range is triangulated, as is every f32 value
    for scale in [2f64.powi(497), 2f64.powi(-480)] {
        let v: Vec<[f64; 2]> = square
            .iter()
            .map(|p| [p[0] * scale, p[1] * scale])
            .collect();
        assert_eq!(tri_f64(&v, &[0], Options::default()), Ok(2), "{scale}");
    }
    let v32: Vec<[f32; 2]> = SQUARE
        .iter()
        .map(|p| [p[0] as f32 * 1e37, p[1] as f32 * 1e37])
        .collect();
    let mut out = Vec::new();
    let mut tri32 = Triangulator::<f32>::new();
    let made = tri32.triangulate(&v32, &[0], &Options::default(), &mut out);
    assert!(made.is_ok() && out.len() == 2);
}

#[test]
fn malformed_ring_starts_are_refused() {
    let mut v: Vec<[f64; 2]> = SQUARE.to_vec();
    v.extend([[1.0, 1.0], [1.0, 2.0], [2.0, 1.0]]);
    let o = Options::default();
    assert_eq!(
        tri_f64(&v, &[1, 4], o),
        Err(Error::FirstRingStart { start: Some(1) })
    );
    assert_eq!(
        tri_f64(&v, &[], o),
        Err(Error::FirstRingStart { start: None })
    );
    assert_eq!(
        tri_f64(&v, &[0, 4, 4], o),
        Err(Error::RingStartsNotIncreasing {
            ring: 2,
            start: 4,
            previous: 4
        })
    );
    assert_eq!(
        tri_f64(&v, &[0, 5, 3], o),
        Err(Error::RingStartsNotIncreasing {
            ring: 2,
            start: 3,
            previous: 5
        })
    );
    assert_eq!(
        tri_f64(&v, &[0, 9], o),
        Err(Error::RingStartOutOfRange {
            ring: 1,
            start: 9,
            len: 7
        })
    );
    assert_eq!(
        tri_f64(&v, &[0, 7], o),
        Err(Error::RingStartOutOfRange {
            ring: 1,
            start: 7,
            len: 7
        })
    );
    for e in [
        Error::FirstRingStart { start: Some(1) },
        Error::RingStartsNotIncreasing {
            ring: 2,
            start: 3,
            previous: 5,
        },
        Error::RingStartOutOfRange {
            ring: 1,
            start: 9,
            len: 7,
        },
    ] {
        assert!(!e.to_string().is_empty());
    }
}

#[test]
fn empty_input_gives_no_triangles() {
    for strategy in [Strategy::Fast, Strategy::Quality] {
        for lenient in [false, true] {
            let o = Options::default()
                .with_strategy(strategy)
                .with_lenient(lenient);
            assert_eq!(tri_f64(&[], &[], o), Ok(0));
            let mut out = vec![[9u32, 9, 9]];
            Triangulator::<f32>::new()
                .triangulate(&[], &[], &o, &mut out)
                .expect("empty f32");
            assert!(out.is_empty(), "out is cleared");
        }
    }
}

/// Lenient mode accepts what strict mode refuses, drops what it cannot use, and says so.
#[test]
fn lenient_repairs_bad_input() {
    let lenient = Options::default().with_lenient(true);
    // A NaN vertex in a pentagon: dropped as NonFinite, the rest triangulated.
    let v = [
        [0.0, 0.0],
        [4.0, 0.0],
        [f64::NAN, 2.0],
        [4.0, 4.0],
        [0.0, 4.0],
    ];
    let mut tri = Triangulator::<f64>::new();
    let mut out = Vec::new();
    let report = tri
        .triangulate(&v, &[0], &lenient, &mut out)
        .expect("lenient NaN");
    assert!(
        report
            .dropped
            .iter()
            .any(|d| d.vertex == 2 && d.reason == DropReason::NonFinite),
        "NaN vertex reported: {:?}",
        report.dropped
    );
    assert!(out.iter().flatten().all(|&i| i != 2), "NaN vertex unused");
    assert_eq!(out.len(), 2);

    // Malformed ring starts: a result anyway, and a RingStartIgnored repair.
    let mut v: Vec<[f64; 2]> = SQUARE.to_vec();
    v.extend([[1.0, 1.0], [1.0, 2.0], [2.0, 1.0]]);
    for starts in [&[0, 4, 4][..], &[0, 9], &[0, 5, 3]] {
        let report = tri.triangulate(&v, starts, &lenient, &mut out);
        let report = report.unwrap_or_else(|e| panic!("lenient {starts:?}: {e}"));
        assert!(
            report
                .repairs
                .iter()
                .any(|r| r.kind == polytri::RepairKind::RingStartIgnored),
            "{starts:?}: {:?}",
            report.repairs
        );
    }

    // A bow-tie: strict refuses, lenient repairs.
    let bow = [[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]];
    assert!(matches!(
        tri_f64(&bow, &[0], Options::default()),
        Err(Error::EdgesCross { .. })
    ));
    let report = tri
        .triangulate(&bow, &[0], &lenient, &mut out)
        .expect("lenient bow-tie");
    assert!(!report.is_clean(), "bow-tie repaired");

    // Repeated and collinear vertices are dropped with their reasons, strict or not.
    let v = [
        [0.0, 0.0],
        [2.0, 0.0],
        [4.0, 0.0],
        [4.0, 4.0],
        [4.0, 4.0],
        [0.0, 4.0],
        [0.0, 0.0],
    ];
    for o in [Options::default(), lenient] {
        let report = tri.triangulate(&v, &[0], &o, &mut out).expect("repeats");
        let mut reasons: Vec<(u32, DropReason)> = report
            .dropped
            .iter()
            .map(|d| (d.vertex, d.reason))
            .collect();
        reasons.sort_by_key(|r| r.0);
        assert_eq!(out.len(), 2, "{reasons:?}");
        assert!(reasons.contains(&(1, DropReason::Collinear)), "{reasons:?}");
        assert!(
            reasons
                .iter()
                .any(|&(v, r)| (v == 3 || v == 4) && r == DropReason::Repeated),
            "{reasons:?}"
        );
        assert!(
            reasons
                .iter()
                .any(|&(v, r)| (v == 0 || v == 6) && r == DropReason::Repeated),
            "{reasons:?}"
        );
    }

    // A ring of fewer than three distinct points encloses nothing.
    let v = [[0.0, 0.0], [1.0, 1.0], [0.0, 0.0]];
    let report = tri
        .triangulate(&v, &[0], &lenient, &mut out)
        .expect("degenerate ring");
    assert!(out.is_empty());
    assert_eq!(report.dropped.len(), 3, "{:?}", report.dropped);
}

/// A figure eight whose lobes meet along a wall the ring runs down and later up again
/// (x = -1, y from -1 to 0): the upper lobe turns counter-clockwise, the lower one
/// clockwise. No edges cross, yet no region is bounded consistently. Found by the
/// `raw_rings` fuzz target, where strict mode reported an internal error.
#[test]
fn lobes_winding_opposite_ways_along_a_wall_are_refused() {
    let ring = [
        [-1.0, 1.0],
        [-1.0, -1.0],
        [0.0, -2.0],
        [-1.0, -5.0],
        [-1.0, 0.0],
        [0.0, 0.0],
    ];
    for rotation in 0..4 {
        let turned: Vec<[f64; 2]> = ring
            .iter()
            .map(|&p| (0..rotation).fold(p, |[x, y], _| [-y, x]))
            .collect();
        for strategy in [Strategy::Fast, Strategy::Quality] {
            let err = match tri_f64(&turned, &[0], strict(strategy)) {
                Ok(n) => panic!("rotation {rotation}, {strategy:?}: Ok with {n} triangles"),
                Err(e) => e,
            };
            let Error::LobesWindOpposite { ring: 0, vertex } = err else {
                panic!("rotation {rotation}, {strategy:?}: {err:?}");
            };
            assert!(vertex < ring.len(), "{err}");
            assert!(err.to_string().contains("winds both ways"), "{err}");
            let mut out = Vec::new();
            let err32 = Triangulator::<f32>::new()
                .triangulate(&to_f32(&turned), &[0], &strict(strategy), &mut out)
                .unwrap_err();
            assert!(
                matches!(err32, Error::LobesWindOpposite { ring: 0, .. }),
                "{err32:?}"
            );
            // Lenient mode makes the best of it: a result, never an error.
            let lenient = strict(strategy).with_lenient(true);
            assert!(tri_f64(&turned, &[0], lenient).is_ok());
        }
    }
}

/// A quadrilateral with a wall from B down to C and a triangle C D E inside it turning the
/// same way, one ring (precision fuzz target, seed 8282): the winding number in the
/// triangle is 2. Strict mode refuses it in every rotation and start; the same lobe turned
/// the other way is a hole, which it triangulates (quadrilateral minus triangle).
#[test]
fn a_lobe_inside_its_ring_turning_the_same_way_is_refused() {
    let (a, b, c, d, e, f, g) = (
        [6.0, 13.0],
        [2.0, 10.0],
        [2.0, 9.0],
        [4.0, 8.0],
        [3.0, 9.0],
        [1.0, 9.0],
        [2.0, 0.0],
    );
    let same_way = [a, b, c, d, e, c, b, f, g];
    let other_way = [a, b, c, e, d, c, b, f, g];
    for rotation in 0..4 {
        let turn = |ring: &[[f64; 2]]| -> Vec<[f64; 2]> {
            ring.iter()
                .map(|&p| (0..rotation).fold(p, |[x, y], _| [-y, x]))
                .collect()
        };
        for start in 0..same_way.len() {
            let mut twice = turn(&same_way);
            twice.rotate_left(start);
            let mut hole = turn(&other_way);
            hole.rotate_left(start);
            for strategy in [Strategy::Fast, Strategy::Quality] {
                let what = format!("rotation {rotation}, start {start}, {strategy:?}");
                match tri_f64(&twice, &[0], strict(strategy)) {
                    Err(Error::RingWindsTwice { ring: 0, vertex }) => {
                        assert!(vertex < twice.len(), "{what}")
                    }
                    other => panic!("{what}: {other:?}"),
                }
                // 4 + 3 corners and one hole: 4 + 3 + 2 - 2 triangles
                assert_eq!(tri_f64(&hole, &[0], strict(strategy)), Ok(7), "{what}");
            }
        }
    }
}

#[test]
fn a_refused_call_leaves_no_triangles_behind() {
    let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
    let bow_tie = [[0.0, 0.0], [4.0, 4.0], [4.0, 0.0], [0.0, 4.0]];
    for strategy in [Strategy::Fast, Strategy::Quality, Strategy::Seidel] {
        let mut tri = Triangulator::<f64>::new();
        let mut out = Vec::new();
        let opts = strict(strategy);
        tri.triangulate(&square, &[0], &opts, &mut out).unwrap();
        assert_eq!(out.len(), 2, "{strategy:?}");
        assert!(tri.triangulate(&bow_tie, &[0], &opts, &mut out).is_err());
        assert!(out.is_empty(), "{strategy:?}: {out:?}");
    }
}

/// Two outer rings overlapping in a triangle T along their edges, and T given twice more
/// (found by the `raw_rings` fuzz target): strict mode refuses the two copies of T as
/// overlapping, while reading both as holes of the two outer rings covers each point
/// once (T has winding 2 − 2 = 0). Containment cannot order rings lying on each other;
/// lenient mode reads them by even–odd then, with no vertex added (no edges cross), and
/// says so. The region: the two outer triangles less T, 78 + 90 (before: T covered twice
/// more, 312).
#[test]
fn lenient_reads_rings_lying_on_each_other_by_even_odd() {
    let t = [[-12.0, -12.0], [-12.0, 0.0], [0.0, 0.0]];
    let rings: [&[[f64; 2]]; 4] = [
        &t,
        &[[13.0, 0.0], [-12.0, -12.0], [-12.0, 0.0]],
        &t,
        &[[-12.0, -12.0], [-12.0, 15.0], [0.0, 0.0]],
    ];
    let mut vertices = Vec::new();
    let mut starts = Vec::new();
    for r in rings {
        starts.push(vertices.len());
        vertices.extend_from_slice(r);
    }
    let auto = Options::default().with_nesting(Nesting::Auto);
    assert!(matches!(
        tri_f64(&vertices, &starts, auto),
        Err(Error::RingsOverlap { .. })
    ));
    for strategy in [Strategy::Fast, Strategy::Quality] {
        let mut out = Vec::new();
        let mut tri = Triangulator::<f64>::new();
        let opts = auto.with_strategy(strategy).with_lenient(true);
        let report = tri
            .triangulate(&vertices, &starts, &opts, &mut out)
            .unwrap();
        assert!(report.added.is_empty());
        assert!(report
            .repairs
            .iter()
            .any(|r| r.kind == polytri::RepairKind::ReadEvenOdd));
        let area: f64 = (out.iter())
            .map(|t| {
                let [a, b, c] = t.map(|i| vertices[i as usize]);
                ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2.0
            })
            .sum();
        assert_eq!((out.len(), area), (2, 168.0), "{strategy:?}");
    }
}
