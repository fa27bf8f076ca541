//! The validity checker of `tests/common` judged on hand-made triangulations: it must accept
//! valid ones and reject every kind of broken one.

mod common;

use common::{check, check_with_roles, deviation, first_is_outer, flatten, rotate, Exact};

/// Vertices, rings as vertex indices, triangles.
type Triangulated = (Vec<[f64; 2]>, Vec<Vec<usize>>, Vec<[u32; 3]>);

/// A 10×10 square with a 4×4 square hole, and a valid triangulation of it (8 triangles).
fn square_with_hole() -> Triangulated {
    let rings = vec![
        vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]],
        vec![[3.0, 3.0], [3.0, 7.0], [7.0, 7.0], [7.0, 3.0]],
    ];
    let flat = flatten(&rings);
    // Outer 0..4 CCW, hole 4..8 given clockwise: 4 (3,3), 5 (3,7), 6 (7,7), 7 (7,3).
    let tris = vec![
        [0, 1, 7],
        [0, 7, 4],
        [1, 2, 6],
        [1, 6, 7],
        [2, 3, 5],
        [2, 5, 6],
        [3, 0, 4],
        [3, 4, 5],
    ];
    (flat.vertices, flat.rings, tris)
}

#[test]
fn accepts_a_valid_triangulation_with_a_hole() {
    let (v, r, t) = square_with_hole();
    let stats = check(&v, &r, &t).expect("valid");
    assert_eq!(stats.triangles, 8);
    assert_eq!(stats.area, 84.0);
    assert_eq!(stats.deviation, 0.0);
    assert!(stats.min_angle_deg > 0.0 && stats.min_angle_deg <= 60.0);
    // Same with the roles given.
    check_with_roles(&v, &r, &first_is_outer(2), &t).expect("valid with roles");
}

#[test]
fn rejects_a_dropped_triangle() {
    let (v, r, mut t) = square_with_hole();
    t.remove(3);
    let err = check(&v, &r, &t).unwrap_err();
    assert!(
        err.contains("boundary mismatch") || err.contains("area"),
        "{err}"
    );
}

#[test]
fn rejects_a_duplicated_triangle() {
    let (v, r, mut t) = square_with_hole();
    t.push(t[2]);
    let err = check(&v, &r, &t).unwrap_err();
    assert!(err.contains("overlap"), "{err}");
}

#[test]
fn rejects_a_flipped_triangle() {
    let (v, r, mut t) = square_with_hole();
    t[5].swap(1, 2);
    let err = check(&v, &r, &t).unwrap_err();
    assert!(err.contains("clockwise"), "{err}");
}

#[test]
fn rejects_a_degenerate_triangle() {
    let (v, r, mut t) = square_with_hole();
    t.push([0, 1, 1]);
    assert!(check(&v, &r, &t).unwrap_err().contains("degenerate"));
}

#[test]
fn rejects_an_index_out_of_range() {
    let (v, r, mut t) = square_with_hole();
    t[0][2] = 99;
    assert!(check(&v, &r, &t).unwrap_err().contains("out of range"));
}

#[test]
fn rejects_overlapping_triangles_after_a_vertex_moved() {
    // One triangle's corner moved to another vertex: still counter-clockwise, now it
    // overlaps its neighbours and leaves a gap.
    let (v, r, mut t) = square_with_hole();
    t[0] = [0, 1, 6]; // was [0, 1, 7]
    assert!(check(&v, &r, &t).is_err());
    // A vertex's position moved: the hole's corner (7,3) pulled to (8,2) — the polygon
    // changes with it, and the old triangulation no longer fits it.
    let (mut v, r, t) = square_with_hole();
    v[7] = [8.0, 2.0];
    assert!(
        check(&v, &r, &t).is_ok(),
        "moving a corner inside a convex star keeps it valid"
    );
    v[7] = [11.0, 5.0];
    assert!(
        check(&v, &r, &t).is_err(),
        "a corner moved outside the polygon"
    );
}

#[test]
fn rejects_triangles_filling_the_hole() {
    let (v, r, mut t) = square_with_hole();
    t.push([4, 7, 6]);
    t.push([4, 6, 5]);
    let err = check(&v, &r, &t).unwrap_err();
    assert!(err.contains("boundary mismatch"), "{err}");
}

#[test]
fn rejects_triangles_over_a_notch() {
    // An arrow: the notch at 3 is reflex.
    let rings = vec![vec![
        [0.0, 0.0],
        [4.0, 0.0],
        [4.0, 4.0],
        [2.0, 1.0],
        [0.0, 4.0],
    ]];
    let flat = flatten(&rings);
    let good = vec![[0, 1, 3], [1, 2, 3], [0, 3, 4]];
    check(&flat.vertices, &flat.rings, &good).expect("valid");
    // Two triangles covering the notch, which is outside the polygon.
    let bad = vec![[0, 1, 2], [0, 2, 4]];
    assert!(check(&flat.vertices, &flat.rings, &bad).is_err());
}

#[test]
fn accepts_dropped_collinear_vertices_and_repeated_points() {
    // (2,0) lies on the bottom edge and (4,4) is repeated; neither need be used.
    let rings = vec![vec![
        [0.0, 0.0],
        [2.0, 0.0],
        [4.0, 0.0],
        [4.0, 4.0],
        [4.0, 4.0],
        [0.0, 4.0],
    ]];
    let flat = flatten(&rings);
    check(&flat.vertices, &flat.rings, &[[0, 2, 3], [0, 3, 5]]).expect("collinear dropped");
    // Using the repeated index instead is the same position: also fine.
    check(&flat.vertices, &flat.rings, &[[0, 2, 4], [0, 3, 5]]).expect("repeat used");
    // Using the collinear vertex too is fine.
    check(
        &flat.vertices,
        &flat.rings,
        &[[0, 1, 5], [1, 2, 3], [1, 3, 5]],
    )
    .expect("kept");
}

#[test]
fn accepts_a_hole_touching_the_outer_ring() {
    // Square with a triangular hole whose corner is the outer corner (4,0), given as a
    // second input vertex at the same position. 6 positions, one hole touching: 5 triangles.
    let rings = vec![
        vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]],
        vec![[4.0, 0.0], [2.0, 1.0], [3.0, 2.0]],
    ];
    let flat = flatten(&rings);
    let t = vec![[0, 1, 5], [0, 5, 3], [5, 6, 3], [6, 2, 3], [6, 1, 2]];
    check(&flat.vertices, &flat.rings, &t).expect("touching hole");
    // The same with the other index of the shared position.
    let t2 = vec![[0, 4, 5], [0, 5, 3], [5, 6, 3], [6, 2, 3], [6, 4, 2]];
    check(&flat.vertices, &flat.rings, &t2).expect("touching hole, other index");
}

#[test]
fn finds_islands_by_containment() {
    // Outer 0..10, hole 2..8, island 4..6: area 100 - 36 + 4 = 68.
    let rings = vec![
        vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]],
        vec![[2.0, 2.0], [8.0, 2.0], [8.0, 8.0], [2.0, 8.0]],
        vec![[4.0, 4.0], [6.0, 4.0], [6.0, 6.0], [4.0, 6.0]],
    ];
    let flat = flatten(&rings);
    let roles = common::roles_by_containment(&flat.vertices, &flat.rings);
    assert_eq!(
        roles,
        vec![common::Role::Outer, common::Role::Hole, common::Role::Outer]
    );
    let t = vec![
        // frame between outer and hole
        [0, 1, 5],
        [0, 5, 4],
        [1, 2, 6],
        [1, 6, 5],
        [2, 3, 7],
        [2, 7, 6],
        [3, 0, 4],
        [3, 4, 7],
        // island
        [8, 9, 10],
        [8, 10, 11],
    ];
    let stats = check(&flat.vertices, &flat.rings, &t).expect("valid");
    assert_eq!(stats.area, 68.0);
    // Without the island's triangles: gap.
    assert!(check(&flat.vertices, &flat.rings, &t[..8]).is_err());
}

#[test]
fn is_exact_for_non_integer_coordinates() {
    // A fan over a convex polygon with decimal coordinates: the exact area identity holds.
    let ring: Vec<[f64; 2]> = (0..7)
        .map(|k| {
            let a = k as f64 * std::f64::consts::TAU / 7.0;
            [0.1 + 3.3 * a.cos(), 0.7 + 2.9 * a.sin()]
        })
        .collect();
    let flat = flatten(&[ring]);
    let t: Vec<[u32; 3]> = (1..6).map(|k| [0, k, k + 1]).collect();
    check(&flat.vertices, &flat.rings, &t).expect("exact");
}

#[test]
fn deviation_matches_earcuts_formula() {
    let (v, _, t) = square_with_hole();
    assert_eq!(deviation(&v, &[0, 4], &t), 0.0);
    // Missing one triangle of area A (of 84) → A/84.
    let missing: Vec<[u32; 3]> = t[1..].to_vec();
    let area0 = {
        let [a, b, c] = t[0].map(|i| v[i as usize]);
        ((a[0] - c[0]) * (b[1] - a[1]) - (a[0] - b[0]) * (c[1] - a[1])).abs() / 2.0
    };
    assert_eq!(deviation(&v, &[0, 4], &missing), area0 / 84.0);
    // Zero-area polygon and zero triangle area: 0 by definition.
    let flat = [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]];
    assert_eq!(deviation(&flat, &[0], &[]), 0.0);
    assert_eq!(
        deviation(&[[0.0, 0.0], [1.0, 0.0], [0.0, 0.0]], &[0], &[[0, 1, 2]]),
        0.0
    );
}

#[test]
fn rotations_are_exact_and_cyclic() {
    let rings = vec![vec![[1.5, -2.25], [3.0, 4.0], [-7.0, 0.5]]];
    assert_eq!(rotate(&rings, 1)[0][0], [2.25, 1.5]);
    assert_eq!(rotate(&rings, 2)[0][0], [-1.5, 2.25]);
    assert_eq!(rotate(&rings, 3)[0][0], [-2.25, -1.5]);
    assert_eq!(rotate(&rotate(&rings, 1), 3), rings);
}

#[test]
fn expansions_sum_exactly() {
    let mut e = Exact::default();
    e.add(1e16);
    e.add(1.0);
    e.add(-1e16);
    assert_eq!(e.signum(), 1);
    e.add(-1.0);
    assert_eq!(e.signum(), 0);
    e.add_product(0.1, 0.1);
    e.add(-(0.1 * 0.1));
    // 0.1 * 0.1 rounds; the exact product differs from the rounded one.
    assert_ne!(e.signum(), 0);
}

#[test]
fn finds_crossing_and_overlapping_edges() {
    let bowtie = flatten(&[vec![[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]]]);
    let d = common::input_defects(&bowtie.vertices, &bowtie.rings);
    assert_eq!(d.crossings.len(), 1);
    let (v, r, _) = square_with_hole();
    assert!(common::input_defects(&v, &r).is_empty());
    // A hole whose edge runs along part of the outer's bottom edge.
    let overlap = flatten(&[
        vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]],
        vec![[1.0, 0.0], [2.0, 1.0], [3.0, 0.0]],
    ]);
    let d = common::input_defects(&overlap.vertices, &overlap.rings);
    assert_eq!(d.overlaps.len(), 1, "{d:?}");
}
