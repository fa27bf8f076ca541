//! What a fill-rule call reports about the input's vertices: every vertex no triangle uses
//! is listed as dropped, with the reason.

use polytri::{DropReason, FillRule, Options, Strategy, Triangulator};

fn dropped(
    vertices: &[[f64; 2]],
    starts: &[usize],
    strategy: Strategy,
) -> Vec<(u32, u32, DropReason)> {
    let mut tri = Triangulator::<f64>::new();
    let options = Options::new()
        .with_fill_rule(FillRule::NonZero)
        .with_strategy(strategy);
    let mut out = Vec::new();
    let report = tri
        .triangulate(vertices, starts, &options, &mut out)
        .unwrap();
    // the report and the triangles agree: dropped exactly when unused
    for v in 0..vertices.len() as u32 {
        let used = out.iter().flatten().any(|&w| w == v);
        let listed = report.dropped.iter().any(|d| d.vertex == v);
        assert_ne!(used, listed, "vertex {v} ({strategy:?})");
    }
    let mut got: Vec<_> = report
        .dropped
        .iter()
        .map(|d| (d.vertex, d.ring, d.reason))
        .collect();
    got.sort_unstable_by_key(|d| d.0);
    got
}

#[test]
fn unused_vertices_are_reported_with_a_reason() {
    // a square with a straight vertex on its bottom edge, a triangle touching its corner
    // (4, 4) from outside, and a triangle inside the square, wound the same way (nonzero:
    // it adds nothing to the region, so none of its corners is one of the region's)
    let vertices = [
        [0.0, 0.0],
        [2.0, 0.0],
        [4.0, 0.0],
        [4.0, 4.0],
        [0.0, 4.0],
        [4.0, 4.0],
        [5.0, 4.0],
        [5.0, 5.0],
        [1.0, 1.0],
        [2.0, 1.0],
        [1.0, 2.0],
    ];
    for strategy in [Strategy::Fast, Strategy::Quality, Strategy::Seidel] {
        let mut got = dropped(&vertices, &[0, 5, 8], strategy);
        if strategy == Strategy::Seidel {
            // the trapezoidation keeps straight vertices as corners (never of a flat
            // triangle); the ear clippers drop them
            assert!(!got.iter().any(|d| d.0 == 1), "{got:?}");
            got.insert(0, (1, 0, DropReason::OffBoundary));
        }
        assert_eq!(
            got,
            vec![
                (1, 0, DropReason::OffBoundary),
                (5, 1, DropReason::Coincident),
                (8, 2, DropReason::OffBoundary),
                (9, 2, DropReason::OffBoundary),
                (10, 2, DropReason::OffBoundary),
            ],
            "{strategy:?}"
        );
    }
}

#[test]
fn a_ring_cancelled_by_its_reverse_drops_every_vertex() {
    let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
    let mut vertices = square.to_vec();
    vertices.extend(square.iter().rev());
    for strategy in [Strategy::Fast, Strategy::Seidel] {
        let got = dropped(&vertices, &[0, 4], strategy);
        assert_eq!(got.len(), 8, "{strategy:?}: {got:?}");
        assert!(
            got.iter().all(|d| d.2 == DropReason::OffBoundary),
            "{got:?}"
        );
    }
}
