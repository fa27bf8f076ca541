//! The stage alone, on rings given as it takes them (region on the left of every edge):
//! counts, orientation, the edges' pairing and the area.

use std::collections::HashMap;

use super::{triangulate, Scratch};
use crate::geom::{orient2d, Orientation, Point};

/// Rings of positions → distinct points (shared positions merged) and index rings.
fn indexed(rings: &[Vec<[f64; 2]>]) -> (Vec<[f64; 2]>, Vec<usize>, Vec<u32>) {
    let mut points: Vec<[f64; 2]> = Vec::new();
    let mut starts = Vec::new();
    let mut ids = Vec::new();
    for ring in rings {
        starts.push(ids.len());
        for p in ring {
            let k = points.iter().position(|q| q == p).unwrap_or_else(|| {
                points.push(*p);
                points.len() - 1
            });
            ids.push(k as u32);
        }
    }
    (points, starts, ids)
}

/// Twice the signed area of a ring.
fn double_area(points: &[[f64; 2]], ring: &[u32]) -> f64 {
    let mut a = 0.0;
    for (i, &k) in ring.iter().enumerate() {
        let p = points[k as usize];
        let q = points[ring[(i + 1) % ring.len()] as usize];
        a += p[0] * q[1] - p[1] * q[0];
    }
    a
}

fn pt(points: &[[f64; 2]], k: u32) -> Point {
    let p = points[k as usize];
    Point::new(p[0], p[1])
}

/// Triangulates and checks: every triangle strictly counter-clockwise; every ring edge
/// used once in its direction; every other edge once each way; the count `expected`; the
/// area the rings' (within `tolerance` relative). Returns the triangles.
fn check_with(
    rings: &[Vec<[f64; 2]>],
    expected: usize,
    seed: u64,
    tolerance: f64,
) -> Vec<[u32; 3]> {
    let (points, starts, ids) = indexed(rings);
    let mut s = Scratch::default();
    let mut out = vec![[7, 7, 7]];
    triangulate(&mut s, &points, &starts, &ids, seed, &mut out).expect("triangulates");
    assert_eq!(out.len(), expected, "triangle count (seed {seed})");
    let mut edges: HashMap<(u32, u32), usize> = HashMap::new();
    let mut area = 0.0;
    for t in &out {
        let (a, b, c) = (pt(&points, t[0]), pt(&points, t[1]), pt(&points, t[2]));
        assert_eq!(
            orient2d(a, b, c),
            Orientation::CounterClockwise,
            "triangle {t:?} (seed {seed})"
        );
        area += (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        for k in 0..3 {
            *edges.entry((t[k], t[(k + 1) % 3])).or_default() += 1;
        }
    }
    let mut boundary = HashMap::new();
    let mut ring_area = 0.0;
    for (k, &start) in starts.iter().enumerate() {
        let end = starts.get(k + 1).copied().unwrap_or(ids.len());
        let ring = &ids[start..end];
        ring_area += double_area(&points, ring);
        for (i, &a) in ring.iter().enumerate() {
            boundary.insert((a, ring[(i + 1) % ring.len()]), ());
        }
    }
    for (&(a, b), &n) in &edges {
        assert_eq!(n, 1, "edge {a}→{b} used {n} times (seed {seed})");
        if !boundary.contains_key(&(a, b)) {
            assert!(
                edges.contains_key(&(b, a)),
                "edge {a}→{b} inside the region but without its twin (seed {seed})"
            );
        }
    }
    for &(a, b) in boundary.keys() {
        assert!(
            edges.contains_key(&(a, b)),
            "ring edge {a}→{b} unused (seed {seed})"
        );
    }
    assert!(
        (area - ring_area).abs() <= tolerance * ring_area.abs(),
        "area {area} vs {ring_area} (seed {seed})"
    );
    out
}

/// [`check_with`] exactly (integer coordinates) for several seeds.
fn check(rings: &[Vec<[f64; 2]>], expected: usize) {
    for seed in 0..20 {
        check_with(rings, expected, seed, 0.0);
    }
}

fn square(x: f64, y: f64, side: f64) -> Vec<[f64; 2]> {
    vec![[x, y], [x + side, y], [x + side, y + side], [x, y + side]]
}

fn reversed(mut ring: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
    ring.reverse();
    ring
}

#[test]
fn a_square() {
    check(&[square(0.0, 0.0, 1.0)], 2);
}

#[test]
fn a_triangle_and_nothing() {
    check(&[vec![[0.0, 0.0], [2.0, 1.0], [1.0, 3.0]]], 1);
    let mut s = Scratch::default();
    let mut out = vec![[1, 2, 3]];
    triangulate(&mut s, &[[0.0, 0.0]], &[], &[], 1, &mut out).expect("no rings");
    assert!(out.is_empty());
}

#[test]
fn a_square_with_a_hole() {
    check(
        &[square(0.0, 0.0, 10.0), reversed(square(3.0, 3.0, 4.0))],
        8,
    );
}

#[test]
fn two_squares_touching_at_a_corner() {
    // two pieces of 4 vertices each
    check(&[square(0.0, 0.0, 2.0), square(2.0, 2.0, 2.0)], 4);
    check(&[square(0.0, 0.0, 2.0), square(2.0, -2.0, 2.0)], 4);
}

#[test]
fn a_comb() {
    let teeth = 50;
    let mut ring = vec![[0.0, 0.0], [(2 * teeth) as f64, 0.0]];
    for k in (0..teeth).rev() {
        let x = (2 * k) as f64;
        ring.push([x + 2.0, 10.0]);
        ring.push([x + 1.0, 10.0]);
        ring.push([x + 1.0, 1.0]);
        ring.push([x, 1.0]);
    }
    // (0, 1) repeats nothing: the last tooth ends at (0, 1) above (0, 0)
    let n = ring.len();
    check(&[ring], n - 2);
}

#[test]
fn a_star_with_1000_spikes() {
    let spikes = 1000;
    let mut ring = Vec::new();
    for k in 0..2 * spikes {
        let angle = std::f64::consts::PI * k as f64 / spikes as f64;
        let r = if k % 2 == 0 {
            100.0
        } else {
            3.0 + (k % 7) as f64
        };
        ring.push([r * angle.cos(), r * angle.sin()]);
    }
    for seed in 0..3 {
        check_with(&[ring.clone()], 2 * spikes - 2, seed, 1e-12);
    }
}

#[test]
fn collinear_vertices_on_the_edges() {
    // every integer point of a 5×3 rectangle's boundary, and a hole with collinear points
    let mut ring = Vec::new();
    for x in 0..5 {
        ring.push([x as f64, 0.0]);
    }
    for y in 0..3 {
        ring.push([5.0, y as f64]);
    }
    for x in (1..=5).rev() {
        ring.push([x as f64, 3.0]);
    }
    for y in (1..=3).rev() {
        ring.push([0.0, y as f64]);
    }
    let n = ring.len();
    check(&[ring.clone()], n - 2);
    let hole = vec![
        [1.5, 1.0],
        [1.5, 2.0],
        [2.5, 2.0],
        [3.5, 2.0],
        [3.5, 1.0],
        [2.5, 1.0],
    ];
    check(&[ring, hole], n + 6 - 2 + 2);
}

#[test]
fn horizontal_and_vertical_runs() {
    // an orthogonal staircase: many points at equal heights and abscissae
    let mut ring = vec![[0.0, 0.0]];
    for k in 0..20 {
        ring.push([(k + 1) as f64, k as f64]);
        ring.push([(k + 1) as f64, (k + 1) as f64]);
    }
    ring.push([0.0, 20.0]);
    let n = ring.len();
    check(&[ring], n - 2);
}

#[test]
fn a_hole_touching_the_outer_ring_at_a_vertex() {
    // the hole's corner (0, 2) is the outer ring's vertex
    let outer = vec![[0.0, 0.0], [6.0, 0.0], [6.0, 4.0], [0.0, 4.0], [0.0, 2.0]];
    let hole = reversed(vec![[0.0, 2.0], [2.0, 1.0], [3.0, 2.0], [2.0, 3.0]]);
    // the boundary is one weakly simple ring through (0, 2) twice: 9 − 2 triangles
    check(&[outer.clone(), hole.clone()], 7);
    // and a second hole touching the first: 13 vertex occurrences, 11 triangles
    let hole2 = reversed(vec![[3.0, 2.0], [4.0, 1.0], [5.0, 2.0], [4.0, 3.0]]);
    check(&[outer, hole, hole2], 11);
}

#[test]
fn nested_islands() {
    let rings = vec![
        square(0.0, 0.0, 20.0),
        reversed(square(2.0, 2.0, 16.0)),
        square(4.0, 4.0, 12.0),
        reversed(square(6.0, 6.0, 8.0)),
        square(8.0, 8.0, 4.0),
    ];
    // two pieces with one hole each (8 − 2 + 2 each) and a square
    check(&rings, 8 + 8 + 2);
}

#[test]
fn a_lattice_of_touching_diamonds() {
    // diamonds touching at their corners, holes in a square whose sides pass through the
    // outer diamonds' corners
    let k = 6;
    let side = (2 * k) as f64;
    let mut outer = Vec::new();
    for i in 0..=2 * k {
        outer.push([i as f64, 0.0]);
    }
    for i in 1..=2 * k {
        outer.push([side, i as f64]);
    }
    for i in (0..2 * k).rev() {
        outer.push([i as f64, side]);
    }
    for i in (1..2 * k).rev() {
        outer.push([0.0, i as f64]);
    }
    let mut rings = vec![outer];
    for i in 0..k {
        for j in 0..k {
            let (cx, cy) = ((2 * i + 1) as f64, (2 * j + 1) as f64);
            rings.push(vec![
                [cx, cy - 1.0],
                [cx - 1.0, cy],
                [cx, cy + 1.0],
                [cx + 1.0, cy],
            ]);
        }
    }
    // the region falls apart into pieces between the diamonds: (k − 1)² inner diamonds
    // (2 triangles each), 4 corner triangles (1 each) and 4 (k − 1) triangles along the
    // sides with a collinear vertex (2 each)
    let expected = 2 * (k - 1) * (k - 1) + 4 + 8 * (k - 1);
    check(&rings, expected);
}

#[test]
fn deterministic_for_a_seed() {
    let rings = vec![square(0.0, 0.0, 10.0), reversed(square(3.0, 3.0, 4.0))];
    let a = check_with(&rings, 8, 42, 0.0);
    let b = check_with(&rings, 8, 42, 0.0);
    assert_eq!(a, b);
}

#[test]
fn rejects_broken_rings_without_panicking() {
    let mut s = Scratch::default();
    let mut out = Vec::new();
    let pts = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]];
    // an index out of range, a ring too short, a bad start
    assert!(triangulate(&mut s, &pts, &[0], &[0, 1, 5], 0, &mut out).is_err());
    assert!(triangulate(&mut s, &pts, &[0], &[0, 1], 0, &mut out).is_err());
    assert!(triangulate(&mut s, &pts, &[4], &[0, 1, 2], 0, &mut out).is_err());
    // clockwise (not the rings promised): no panic, whatever it answers
    let _ = triangulate(&mut s, &pts, &[0], &[0, 2, 1], 0, &mut out);
    // crossing edges (a bow tie) must not panic, whatever it answers
    let bow = [[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]];
    for seed in 0..20 {
        let _ = triangulate(&mut s, &bow, &[0], &[0, 1, 2, 3], seed, &mut out);
    }
    // and the scratch still works afterwards
    triangulate(&mut s, &pts, &[0], &[0, 1, 2], 0, &mut out).expect("a triangle");
    assert_eq!(out.len(), 1);
}

#[test]
fn random_orthogonal_polygons_with_holes() {
    // a grid of cells, some removed as holes (never at the border, never touching)
    let mut next = crate::testing::random(0x5eed);
    for round in 0..30 {
        let size = 12;
        let mut rings = vec![vec![
            [0.0, 0.0],
            [size as f64, 0.0],
            [size as f64, size as f64],
            [0.0, size as f64],
        ]];
        let mut holes = 0;
        for i in (1..size - 1).step_by(2) {
            for j in (1..size - 1).step_by(2) {
                if next(3) == 0 {
                    rings.push(reversed(square(i as f64, j as f64, 1.0)));
                    holes += 1;
                }
            }
        }
        let n = 4 + 4 * holes;
        check_with(&rings, n - 2 + 2 * holes, round, 0.0);
    }
}

/// Inputs large enough for rounds in ring order after the random one (at least 256 ·
/// log₂ n segments): a star, a comb, and a square with a lattice of holes, rows of them
/// touching each other at corners.
#[test]
fn large_inputs_insert_rounds_in_ring_order() {
    let spikes = 3000;
    let star: Vec<[f64; 2]> = (0..2 * spikes)
        .map(|k| {
            let angle = std::f64::consts::PI * k as f64 / spikes as f64;
            let r = if k % 2 == 0 {
                1000.0
            } else {
                10.0 + (k % 13) as f64
            };
            [r * angle.cos(), r * angle.sin()]
        })
        .collect();
    check_with(&[star], 2 * spikes - 2, 5, 1e-12);

    let teeth = 2000;
    let mut comb = vec![[0.0, 0.0], [(2 * teeth) as f64, 0.0]];
    for k in (0..teeth).rev() {
        let x = (2 * k) as f64;
        comb.extend([[x + 2.0, 50.0], [x + 1.0, 50.0], [x + 1.0, 1.0], [x, 1.0]]);
    }
    let n = comb.len();
    check_with(&[comb], n - 2, 6, 0.0);

    // holes: diamonds around odd lattice points, every other row touching the next one
    let k: usize = 40;
    let side = (2 * k) as f64;
    let mut rings = vec![square(-1.0, -1.0, side + 2.0)];
    let mut expected = 4 - 2;
    for i in 0..k {
        for j in 0..k {
            let (cx, cy) = ((2 * i + 1) as f64, (2 * j + 1) as f64);
            let r = if j % 2 == 0 { 1.0 } else { 0.5 };
            rings.push(vec![[cx, cy - r], [cx - r, cy], [cx, cy + r], [cx + r, cy]]);
        }
    }
    // the diamonds of radius 1 in a row touch each other; counted by pieces, the region is
    // one piece whose boundary walk visits every hole vertex once and every touching
    // point twice: (4 + 4 k²) vertex occurrences, plus 2 per hole not touching any other
    // (the half-size ones), each row of touching diamonds one more hole's worth
    let rows = k.div_ceil(2);
    let small = k * (k / 2);
    expected += 4 * k * k + 2 * small + 2 * rows;
    check_with(&rings, expected, 7, 0.0);
}

/// An input as the stage takes it: distinct points, ring starts, rings of indices.
type StageInput = (Vec<[f64; 2]>, Vec<usize>, Vec<u32>);

/// Reads one input of a timing file (see [`timing`]) from `lines`, if any is left: distinct
/// points, the first ring counter-clockwise and the others clockwise.
fn read_input<'a>(lines: &mut impl Iterator<Item = &'a str>) -> Option<(StageInput, usize)> {
    let head: Vec<usize> = lines
        .next()?
        .split(' ')
        .map(|x| x.parse().expect("a count"))
        .collect();
    let starts: Vec<usize> = (0..head[1])
        .map(|_| lines.next().expect("a start").parse().expect("a start"))
        .collect();
    let vertices: Vec<[f64; 2]> = (0..head[0])
        .map(|_| {
            let line = lines.next().expect("a vertex");
            let mut it = line
                .split(' ')
                .map(|x| x.parse::<f64>().expect("a coordinate"));
            [it.next().expect("x"), it.next().expect("y")]
        })
        .collect();
    let mut order: Vec<usize> = (0..vertices.len()).collect();
    order.sort_by(|&a, &b| vertices[a].partial_cmp(&vertices[b]).expect("finite"));
    let mut points: Vec<[f64; 2]> = Vec::new();
    let mut index = vec![0u32; vertices.len()];
    for &k in &order {
        if points.last() != Some(&vertices[k]) {
            points.push(vertices[k]);
        }
        index[k] = (points.len() - 1) as u32;
    }
    let mut ids = Vec::new();
    for (r, &start) in starts.iter().enumerate() {
        let end = starts.get(r + 1).copied().unwrap_or(vertices.len());
        let mut ring: Vec<u32> = index[start..end].to_vec();
        let ccw = double_area(&points, &ring) > 0.0;
        if ccw != (r == 0) {
            ring.reverse();
        }
        ids.extend(ring);
    }
    Some(((points, starts, ids), vertices.len()))
}

/// Times the stage alone on inputs dumped to text files in the folder
/// `SEIDEL_TIMING_DIR`: per input a line `vertex-count ring-count`, one line per ring
/// start, one `x y` line per vertex, the first ring outer and the others its holes (as the
/// scaling series and, one input per shape, glyph pages give them); a file may hold
/// several inputs, timed together as one run. `SEIDEL_TIMING_DIR=… cargo test --release
/// -p polytri --lib seidel::tests::timing -- --ignored --nocapture`.
#[test]
#[ignore = "a measurement, run by hand on dumped inputs"]
fn timing() {
    let Ok(dir) = std::env::var("SEIDEL_TIMING_DIR") else {
        return;
    };
    let min_runs: usize = std::env::var("SEIDEL_TIMING_RUNS")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(3);
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("a folder")
        .map(|e| e.expect("an entry").path())
        .collect();
    files.sort();
    for path in files {
        let text = std::fs::read_to_string(&path).expect("a file");
        let mut lines = text.lines();
        let mut inputs = Vec::new();
        let mut vertices = 0;
        while let Some((input, n)) = read_input(&mut lines) {
            inputs.push(input);
            vertices += n;
        }
        let mut s = Scratch::default();
        let mut out = Vec::new();
        let (mut best, mut total, mut runs) = (f64::INFINITY, 0.0, 0);
        let mut triangles = 0;
        while runs < min_runs || (total < 2.0 && runs < 30) {
            let began = std::time::Instant::now();
            triangles = 0;
            for (points, starts, ids) in &inputs {
                triangulate(&mut s, points, starts, ids, 0x005e_1de1_2024, &mut out).expect("ok");
                triangles += out.len();
            }
            let t = began.elapsed().as_secs_f64();
            best = best.min(t);
            total += t;
            runs += 1;
        }
        println!(
            "{:28} {:>9} vertices {:>9} triangles  best {:9.2} ms",
            path.file_name().and_then(|n| n.to_str()).unwrap_or("?"),
            vertices,
            triangles,
            best * 1e3
        );
    }
}
