//! Test support shared by polytri's integration tests: an exact validity checker that knows
//! nothing of the triangulator's internals, earcut's `deviation`, exact 90° rotations, an
//! exact edge-crossing finder, corpus loading and a panic/hang guard.
//!
//! Every geometric decision here is exact: orientations through `robust::orient2d`,
//! positions compared with `==`, areas summed as floating-point expansions (Shewchuk's
//! exact arithmetic), so a verdict never depends on round-off.
#![allow(dead_code)] // each test binary uses a different part of this module

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::mpsc;
use std::time::Duration;

use robust::{orient2d, Coord};
use serde_json::Value;

/// Rings as points: `[outer, hole, …]` or any set of rings.
pub type Rings = Vec<Vec<[f64; 2]>>;

// ------------------------------------------------------------------------------------------
// Corpus loading
// ------------------------------------------------------------------------------------------

/// The repository's `corpus/` directory.
pub fn corpus_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../corpus")
}

/// Parses a JSON file under `corpus/`.
pub fn read_json(relative: &str) -> Value {
    let path = corpus_dir().join(relative);
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("bad JSON in {}: {e}", path.display()))
}

/// Rings JSON `[[[x, y], …], …]` (extra coordinates beyond x, y are ignored).
pub fn rings_from_json(v: &Value) -> Rings {
    let rings = v.as_array().expect("rings JSON: an array of rings");
    rings
        .iter()
        .map(|ring| {
            ring.as_array()
                .expect("ring: an array of points")
                .iter()
                .map(|p| {
                    let p = p.as_array().expect("point: [x, y]");
                    [p[0].as_f64().expect("x"), p[1].as_f64().expect("y")]
                })
                .collect()
        })
        .collect()
}

/// Shapes JSON: a list of polygons, each in rings JSON.
pub fn shapes_from_json(v: &Value) -> Vec<Rings> {
    v.as_array()
        .expect("shapes JSON: an array of polygons")
        .iter()
        .map(rings_from_json)
        .collect()
}

/// Input flattened the way earcut's test does it: all points in ring order.
#[derive(Clone, Debug, Default)]
pub struct Flat {
    /// Every point of every ring, rings concatenated.
    pub vertices: Vec<[f64; 2]>,
    /// Index of each ring's first vertex (first is 0).
    pub ring_starts: Vec<usize>,
    /// Vertex indices of each ring, in order.
    pub rings: Vec<Vec<usize>>,
}

/// Concatenates rings; empty rings are skipped (ring starts must increase).
pub fn flatten(rings: &[Vec<[f64; 2]>]) -> Flat {
    let mut flat = Flat::default();
    for ring in rings.iter().filter(|r| !r.is_empty()) {
        let start = flat.vertices.len();
        flat.ring_starts.push(start);
        flat.vertices.extend_from_slice(ring);
        flat.rings.push((start..start + ring.len()).collect());
    }
    flat
}

/// Rotates every point exactly by `k` × 90° counter-clockwise, as earcut's test does.
pub fn rotate(rings: &[Vec<[f64; 2]>], k: u32) -> Rings {
    let turn = |[x, y]: [f64; 2]| -> [f64; 2] {
        match k % 4 {
            0 => [x, y],
            1 => [-y, x],
            2 => [-x, -y],
            _ => [y, -x],
        }
    };
    rings
        .iter()
        .map(|r| r.iter().copied().map(turn).collect())
        .collect()
}

/// Every ring's winding reversed (its first point kept first).
pub fn reverse_windings(rings: &[Vec<[f64; 2]>]) -> Rings {
    rings
        .iter()
        .map(|r| {
            let mut rev = r.clone();
            if rev.len() > 1 {
                rev[1..].reverse();
            }
            rev
        })
        .collect()
}

/// The input rounded to `f32`, as given to a `Triangulator<f32>`.
pub fn to_f32(vertices: &[[f64; 2]]) -> Vec<[f32; 2]> {
    vertices
        .iter()
        .map(|&[x, y]| [x as f32, y as f32])
        .collect()
}

/// `f32` vertices widened back to `f64` (exact).
pub fn widen(vertices: &[[f32; 2]]) -> Vec<[f64; 2]> {
    vertices
        .iter()
        .map(|&[x, y]| [f64::from(x), f64::from(y)])
        .collect()
}

/// True when some coordinate is not an integer.
pub fn has_non_integer(vertices: &[[f64; 2]]) -> bool {
    vertices.iter().flatten().any(|c| c.fract() != 0.0)
}

/// Runs `f` on its own thread: a panic or a run longer than `timeout` becomes an `Err`
/// (a hung thread is left behind and ends with the test process).
pub fn guarded<T: Send + 'static>(
    timeout: Duration,
    f: impl FnOnce() -> T + Send + 'static,
) -> Result<T, String> {
    let (tx, rx) = mpsc::channel();
    std::thread::Builder::new()
        .stack_size(64 << 20)
        .spawn(move || {
            let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
            let _ = tx.send(r);
        })
        .expect("spawn");
    match rx.recv_timeout(timeout) {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(payload)) => {
            let msg = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "non-string panic payload".into());
            Err(format!("PANIC: {msg}"))
        }
        Err(_) => Err(format!("HANG: no result after {timeout:?}")),
    }
}

// ------------------------------------------------------------------------------------------
// Exact arithmetic: nonoverlapping floating-point expansions (Shewchuk 1997)
// ------------------------------------------------------------------------------------------

/// An exact sum of `f64` values and products, as a nonoverlapping expansion kept in
/// increasing magnitude without zeros. Exact as long as no product overflows or underflows.
#[derive(Clone, Debug, Default)]
pub struct Exact {
    c: Vec<f64>,
    scratch: Vec<f64>,
}

fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let x = a + b;
    let bv = x - a;
    let av = x - bv;
    (x, (a - av) + (b - bv))
}

fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let x = a + b;
    (x, b - (x - a))
}

impl Exact {
    /// Adds `b` exactly.
    pub fn add(&mut self, b: f64) {
        if b == 0.0 {
            return;
        }
        // Grow-Expansion with zero elimination.
        self.scratch.clear();
        let mut q = b;
        for &e in &self.c {
            let (s, h) = two_sum(q, e);
            q = s;
            if h != 0.0 {
                self.scratch.push(h);
            }
        }
        if q != 0.0 {
            self.scratch.push(q);
        }
        std::mem::swap(&mut self.c, &mut self.scratch);
        if self.c.len() > 16 {
            self.compress();
        }
    }

    /// Adds `a · b` exactly (the product split by a fused multiply-add).
    pub fn add_product(&mut self, a: f64, b: f64) {
        let p = a * b;
        let e = a.mul_add(b, -p);
        self.add(e);
        self.add(p);
    }

    /// Adds another expansion, times `sign` (±1).
    pub fn add_exact(&mut self, other: &Exact, sign: f64) {
        for &c in &other.c {
            self.add(c * sign);
        }
    }

    /// Shewchuk's Compress: same value, fewer components.
    fn compress(&mut self) {
        let e = &self.c;
        let m = e.len();
        if m < 2 {
            return;
        }
        let mut g = vec![0.0; m];
        let mut bottom = m - 1;
        let mut q = e[m - 1];
        for i in (0..m - 1).rev() {
            let (qn, low) = fast_two_sum(q, e[i]);
            if low != 0.0 {
                g[bottom] = qn;
                bottom -= 1;
                q = low;
            } else {
                q = qn;
            }
        }
        g[bottom] = q;
        let mut h = Vec::with_capacity(m);
        let mut q = g[bottom];
        for &gi in &g[bottom + 1..] {
            let (qn, low) = fast_two_sum(gi, q);
            if low != 0.0 {
                h.push(low);
            }
            q = qn;
        }
        if q != 0.0 {
            h.push(q);
        }
        self.c = h;
    }

    /// The exact sign: -1, 0 or 1.
    pub fn signum(&mut self) -> i32 {
        self.compress();
        match self.c.last() {
            None => 0,
            Some(&top) if top > 0.0 => 1,
            Some(_) => -1,
        }
    }

    /// An approximation (the components summed).
    pub fn approx(&self) -> f64 {
        self.c.iter().sum()
    }
}

/// Twice the signed area of `a b c`, exactly.
fn twice_area_exact(a: [f64; 2], b: [f64; 2], c: [f64; 2], acc: &mut Exact) {
    acc.add_product(a[0], b[1]);
    acc.add_product(-a[1], b[0]);
    acc.add_product(b[0], c[1]);
    acc.add_product(-b[1], c[0]);
    acc.add_product(c[0], a[1]);
    acc.add_product(-c[1], a[0]);
}

/// Twice the signed area of a ring (positive counter-clockwise, y up), exactly.
pub fn ring_area_exact(vertices: &[[f64; 2]], ring: &[usize]) -> Exact {
    let mut acc = Exact::default();
    for (k, &i) in ring.iter().enumerate() {
        let j = ring[(k + ring.len() - 1) % ring.len()];
        let (p, q) = (vertices[j], vertices[i]);
        acc.add_product(p[0], q[1]);
        acc.add_product(-p[1], q[0]);
    }
    acc
}

// ------------------------------------------------------------------------------------------
// Predicates
// ------------------------------------------------------------------------------------------

fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    orient2d(
        Coord { x: a[0], y: a[1] },
        Coord { x: b[0], y: b[1] },
        Coord { x: c[0], y: c[1] },
    )
}

/// `p` lies on the closed segment `a b` (exact).
fn on_segment(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> bool {
    orient(a, b, p) == 0.0
        && a[0].min(b[0]) <= p[0]
        && p[0] <= a[0].max(b[0])
        && a[1].min(b[1]) <= p[1]
        && p[1] <= a[1].max(b[1])
}

/// `p` lies in the relative interior of segment `a b`, `a ≠ b` (exact).
fn strictly_inside_segment(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> bool {
    if orient(a, b, p) != 0.0 {
        return false;
    }
    if a[0] != b[0] {
        a[0].min(b[0]) < p[0] && p[0] < a[0].max(b[0])
    } else {
        a[1].min(b[1]) < p[1] && p[1] < a[1].max(b[1])
    }
}

/// Where `p` is relative to a closed ring: `Some(true)` inside, `Some(false)` outside,
/// `None` on its boundary. Exact crossing-number test.
pub fn point_in_ring(vertices: &[[f64; 2]], ring: &[usize], p: [f64; 2]) -> Option<bool> {
    let mut inside = false;
    for (k, &i) in ring.iter().enumerate() {
        let a = vertices[i];
        let b = vertices[ring[(k + 1) % ring.len()]];
        if on_segment(a, b, p) {
            return None;
        }
        if (a[1] > p[1]) != (b[1] > p[1]) {
            let o = orient(a, b, p);
            if (b[1] > a[1] && o > 0.0) || (b[1] < a[1] && o < 0.0) {
                inside = !inside;
            }
        }
    }
    Some(inside)
}

// ------------------------------------------------------------------------------------------
// Ring roles
// ------------------------------------------------------------------------------------------

/// Whether a ring bounds its polygon from outside or is a hole.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// An outer boundary (containment depth even).
    Outer,
    /// A hole (depth odd).
    Hole,
}

/// earcut's convention: ring 0 outer, the rest holes.
pub fn first_is_outer(rings: usize) -> Vec<Role> {
    (0..rings)
        .map(|k| if k == 0 { Role::Outer } else { Role::Hole })
        .collect()
}

/// Shapes' convention: in each shape, the first ring outer and the rest holes.
pub fn shape_roles(shapes: &[Rings]) -> Vec<Role> {
    shapes
        .iter()
        .flat_map(|s| first_is_outer(s.iter().filter(|r| !r.is_empty()).count()))
        .collect()
}

fn bbox(vertices: &[[f64; 2]], ring: &[usize]) -> [f64; 4] {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for &i in ring {
        let [x, y] = vertices[i];
        b = [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)];
    }
    b
}

/// Ring `inner` lies inside ring `outer` (decided at the first vertex of `inner` not on
/// `outer`'s boundary, else at the first edge midpoint not on it).
fn ring_inside(vertices: &[[f64; 2]], inner: &[usize], outer: &[usize]) -> bool {
    for &i in inner {
        if let Some(inside) = point_in_ring(vertices, outer, vertices[i]) {
            return inside;
        }
    }
    for (k, &i) in inner.iter().enumerate() {
        let (a, b) = (vertices[i], vertices[inner[(k + 1) % inner.len()]]);
        let mid = [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
        if let Some(inside) = point_in_ring(vertices, outer, mid) {
            return inside;
        }
    }
    false
}

/// Roles by exact containment depth (even: outer), what `Nesting::Auto` promises.
/// Rings enclosing no area are given `Role::Hole`; they contribute nothing either way.
pub fn roles_by_containment(vertices: &[[f64; 2]], rings: &[Vec<usize>]) -> Vec<Role> {
    let areas: Vec<i32> = rings
        .iter()
        .map(|r| ring_area_exact(vertices, r).signum())
        .collect();
    let boxes: Vec<[f64; 4]> = rings.iter().map(|r| bbox(vertices, r)).collect();
    (0..rings.len())
        .map(|r| {
            if areas[r] == 0 {
                return Role::Hole;
            }
            let depth = (0..rings.len())
                .filter(|&q| {
                    q != r
                        && areas[q] != 0
                        && boxes[q][0] <= boxes[r][0]
                        && boxes[q][1] <= boxes[r][1]
                        && boxes[q][2] >= boxes[r][2]
                        && boxes[q][3] >= boxes[r][3]
                        && ring_inside(vertices, &rings[r], &rings[q])
                })
                .count();
            if depth % 2 == 0 {
                Role::Outer
            } else {
                Role::Hole
            }
        })
        .collect()
}

// ------------------------------------------------------------------------------------------
// The validity checker
// ------------------------------------------------------------------------------------------

/// What a valid triangulation measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stats {
    /// Number of triangles.
    pub triangles: usize,
    /// The polygon's area (outer rings minus holes), rounded from the exact value.
    pub area: f64,
    /// earcut's relative area deviation with these roles (for `first_is_outer` roles it is
    /// exactly earcut's `deviation`).
    pub deviation: f64,
    /// Smallest interior angle of any triangle, in degrees.
    pub min_angle_deg: f64,
    /// Triangle boundary edges with a vertex of some triangle strictly inside them (allowed
    /// where separate polygons touch; informational).
    pub t_junctions: usize,
}

/// Checks `triangles` against the rings, with roles found by exact containment.
pub fn check(
    vertices: &[[f64; 2]],
    rings: &[Vec<usize>],
    triangles: &[[u32; 3]],
) -> Result<Stats, String> {
    let roles = roles_by_containment(vertices, rings);
    check_with_roles(vertices, rings, &roles, triangles)
}

/// Checks that `triangles` triangulate exactly the region bounded by `rings`.
///
/// Rules (all exact):
/// 1. every index is in range and every triangle strictly counter-clockwise;
/// 2. vertices are identified by position (each maps to the smallest index at its
///    position); no directed edge is used by two triangles (they would overlap);
/// 3. the triangles' boundary — their directed edges after opposite pairs cancel — equals
///    the polygon's oriented boundary (outer rings counter-clockwise, holes clockwise,
///    opposite pieces cancelling) once every segment of both is split at all input
///    positions lying inside it. This lets dropped collinear vertices, touching rings and
///    shared edges through, and with 1 it implies that the triangles cover every point of
///    the polygon exactly once and nothing outside it;
/// 4. the exact sum of the triangles' areas equals the exact polygon area
///    Σ|outer| − Σ|hole|.
pub fn check_with_roles(
    vertices: &[[f64; 2]],
    rings: &[Vec<usize>],
    roles: &[Role],
    triangles: &[[u32; 3]],
) -> Result<Stats, String> {
    assert_eq!(rings.len(), roles.len(), "one role per ring");
    let n = vertices.len();
    let canon = Canon::new(vertices);

    // 1. Indices and orientation.
    for (t, tri) in triangles.iter().enumerate() {
        if let Some(&bad) = tri.iter().find(|&&i| i as usize >= n) {
            return Err(format!(
                "triangle {t} {tri:?}: index {bad} out of range (n = {n})"
            ));
        }
        let [a, b, c] = tri.map(|i| vertices[i as usize]);
        let o = orient(a, b, c);
        if o <= 0.0 {
            let what = if o == 0.0 {
                "degenerate (zero area)"
            } else {
                "clockwise"
            };
            return Err(format!(
                "triangle {t} {tri:?} = {a:?} {b:?} {c:?} is {what}"
            ));
        }
    }

    // 2. Directed edges by position; none used twice.
    let mut directed: HashMap<(u32, u32), usize> = HashMap::with_capacity(triangles.len() * 3);
    let mut used = vec![false; canon.positions.len()];
    for (t, tri) in triangles.iter().enumerate() {
        let c = tri.map(|i| canon.id[i as usize]);
        for k in 0..3 {
            used[c[k] as usize] = true;
            let e = (c[k], c[(k + 1) % 3]);
            if let Some(other) = directed.insert(e, t) {
                return Err(format!(
                    "triangles {other} {:?} and {t} {tri:?} both lie left of edge {:?} -> {:?}: they overlap",
                    triangles[other], canon.positions[e.0 as usize], canon.positions[e.1 as usize]
                ));
            }
        }
    }

    // 3. Boundary chains.
    let grid = Grid::new(&canon.positions);
    let mut t_junctions = 0;
    let mut tri_chain = Chain::default();
    for &(a, b) in directed.keys() {
        if !directed.contains_key(&(b, a)) {
            let inner = grid.points_inside(&canon.positions, a, b);
            if inner.iter().any(|&p| used[p as usize]) {
                t_junctions += 1;
            }
            tri_chain.add_split(a, b, &inner, 1);
        }
    }
    let mut ring_chain = Chain::default();
    let mut polygon_area = Exact::default();
    for (r, ring) in rings.iter().enumerate() {
        let area = ring_area_exact(vertices, ring);
        let sign = area.clone().signum();
        // Orient so the interior lies left: outer counter-clockwise, hole clockwise.
        let forward = match roles[r] {
            Role::Outer => sign >= 0,
            Role::Hole => sign <= 0,
        };
        let role_sign = if roles[r] == Role::Outer { 1.0 } else { -1.0 };
        polygon_area.add_exact(&area, role_sign * if sign < 0 { -1.0 } else { 1.0 });
        for (k, &i) in ring.iter().enumerate() {
            let j = ring[(k + 1) % ring.len()];
            let (mut a, mut b) = (canon.id[i], canon.id[j]);
            if a == b {
                continue;
            }
            if !forward {
                std::mem::swap(&mut a, &mut b);
            }
            let inner = grid.points_inside(&canon.positions, a, b);
            ring_chain.add_split(a, b, &inner, 1);
        }
    }
    compare_chains(&canon.positions, &tri_chain, &ring_chain)?;

    // 4. Exact area.
    let mut tri_area = Exact::default();
    for tri in triangles {
        let [a, b, c] = tri.map(|i| vertices[i as usize]);
        twice_area_exact(a, b, c, &mut tri_area);
    }
    let mut diff = tri_area.clone();
    diff.add_exact(&polygon_area, -1.0);
    if diff.signum() != 0 {
        return Err(format!(
            "area mismatch: triangles sum to {} but the polygon has {} (exact difference {:e})",
            tri_area.approx() / 2.0,
            polygon_area.approx() / 2.0,
            diff.approx() / 2.0
        ));
    }

    Ok(Stats {
        triangles: triangles.len(),
        area: polygon_area.approx() / 2.0,
        deviation: deviation_with_roles(vertices, rings, roles, triangles),
        min_angle_deg: min_angle_deg(vertices, triangles),
        t_junctions,
    })
}

/// Vertices identified by position: `id[i]` is the position of vertex `i`, numbered in
/// order of the smallest vertex index at each position.
struct Canon {
    id: Vec<u32>,
    positions: Vec<[f64; 2]>,
}

impl Canon {
    fn new(vertices: &[[f64; 2]]) -> Self {
        let mut by_bits: HashMap<(u64, u64), u32> = HashMap::with_capacity(vertices.len());
        let mut positions = Vec::new();
        let id = vertices
            .iter()
            .map(|&[x, y]| {
                // + 0.0 turns -0.0 into 0.0: equal positions, equal keys.
                let key = ((x + 0.0).to_bits(), (y + 0.0).to_bits());
                *by_bits.entry(key).or_insert_with(|| {
                    positions.push([x, y]);
                    (positions.len() - 1) as u32
                })
            })
            .collect();
        Canon { id, positions }
    }
}

/// A uniform grid over positions, to find the positions lying on a segment.
struct Grid {
    min: [f64; 2],
    scale: [f64; 2],
    cells: usize,
    starts: Vec<u32>,
    items: Vec<u32>,
}

impl Grid {
    fn new(points: &[[f64; 2]]) -> Self {
        let cells = ((points.len() as f64).sqrt().ceil() as usize).clamp(1, 1024);
        let mut min = [f64::INFINITY; 2];
        let mut max = [f64::NEG_INFINITY; 2];
        for p in points {
            for k in 0..2 {
                min[k] = min[k].min(p[k]);
                max[k] = max[k].max(p[k]);
            }
        }
        let scale = [0, 1].map(|k| {
            let w = max[k] - min[k];
            if w > 0.0 {
                cells as f64 / w
            } else {
                0.0
            }
        });
        let mut g = Grid {
            min,
            scale,
            cells,
            starts: vec![0; cells * cells + 1],
            items: vec![],
        };
        let keys: Vec<usize> = points.iter().map(|&p| g.cell_of(p)).collect();
        for &k in &keys {
            g.starts[k + 1] += 1;
        }
        for k in 0..cells * cells {
            g.starts[k + 1] += g.starts[k];
        }
        let mut fill = g.starts.clone();
        g.items = vec![0; points.len()];
        for (i, &k) in keys.iter().enumerate() {
            g.items[fill[k] as usize] = i as u32;
            fill[k] += 1;
        }
        g
    }

    /// Cell coordinate along axis `k`; monotone in the coordinate, so a point inside a box
    /// lands in the box's cell range.
    fn axis(&self, k: usize, v: f64) -> usize {
        (((v - self.min[k]) * self.scale[k]).floor().max(0.0) as usize).min(self.cells - 1)
    }

    fn cell_of(&self, p: [f64; 2]) -> usize {
        self.axis(1, p[1]) * self.cells + self.axis(0, p[0])
    }

    /// Positions strictly inside segment `a b`, sorted from `a` to `b`.
    fn points_inside(&self, pos: &[[f64; 2]], a: u32, b: u32) -> Vec<u32> {
        let (pa, pb) = (pos[a as usize], pos[b as usize]);
        let (x0, x1) = (
            self.axis(0, pa[0].min(pb[0])),
            self.axis(0, pa[0].max(pb[0])),
        );
        let (y0, y1) = (
            self.axis(1, pa[1].min(pb[1])),
            self.axis(1, pa[1].max(pb[1])),
        );
        let mut found = Vec::new();
        let mut test = |i: u32| {
            if i != a && i != b && strictly_inside_segment(pa, pb, pos[i as usize]) {
                found.push(i);
            }
        };
        if (x1 - x0 + 1) * (y1 - y0 + 1) > pos.len() {
            (0..pos.len() as u32).for_each(&mut test);
        } else {
            for cy in y0..=y1 {
                for cx in x0..=x1 {
                    let cell = cy * self.cells + cx;
                    let range = self.starts[cell] as usize..self.starts[cell + 1] as usize;
                    self.items[range].iter().copied().for_each(&mut test);
                }
            }
        }
        // Order along the segment by the coordinate that varies (exact comparisons).
        let k = if pa[0] != pb[0] { 0 } else { 1 };
        found.sort_by(|&i, &j| {
            let (u, v) = (pos[i as usize][k], pos[j as usize][k]);
            if pb[k] > pa[k] {
                u.partial_cmp(&v).unwrap()
            } else {
                v.partial_cmp(&u).unwrap()
            }
        });
        found
    }
}

/// A 1-chain: signed multiplicities of elementary segments, keyed `(low id, high id)`,
/// positive when running from the lower id to the higher.
#[derive(Default)]
struct Chain(HashMap<(u32, u32), i64>);

impl Chain {
    fn add(&mut self, a: u32, b: u32, w: i64) {
        let (key, w) = if a < b { ((a, b), w) } else { ((b, a), -w) };
        let v = self.0.entry(key).or_insert(0);
        *v += w;
        if *v == 0 {
            self.0.remove(&key);
        }
    }

    /// Adds `a → b` split at the sorted interior points `inner`.
    fn add_split(&mut self, a: u32, b: u32, inner: &[u32], w: i64) {
        let mut from = a;
        for &p in inner {
            self.add(from, p, w);
            from = p;
        }
        self.add(from, b, w);
    }
}

fn compare_chains(pos: &[[f64; 2]], tris: &Chain, rings: &Chain) -> Result<(), String> {
    let mut problems = Vec::new();
    let mut keys: Vec<&(u32, u32)> = tris.0.keys().chain(rings.0.keys()).collect();
    keys.sort();
    keys.dedup();
    for &(a, b) in keys {
        let t = tris.0.get(&(a, b)).copied().unwrap_or(0);
        let r = rings.0.get(&(a, b)).copied().unwrap_or(0);
        if t == r {
            continue;
        }
        let (pa, pb) = (pos[a as usize], pos[b as usize]);
        let why = if t == 0 {
            "polygon boundary not covered by any triangle (gap)".to_string()
        } else if r == 0 {
            "triangle boundary edge not on the polygon boundary (overlap, gap or outside)"
                .to_string()
        } else if t == -r {
            "triangles lie on the wrong side of this boundary edge".to_string()
        } else {
            format!("triangle boundary multiplicity {t}, polygon boundary {r}")
        };
        problems.push(format!("segment {pa:?} -> {pb:?}: {why}"));
    }
    if problems.is_empty() {
        return Ok(());
    }
    let total = problems.len();
    problems.truncate(6);
    Err(format!(
        "boundary mismatch on {total} segment(s): {}",
        problems.join("; ")
    ))
}

fn min_angle_deg(vertices: &[[f64; 2]], triangles: &[[u32; 3]]) -> f64 {
    let mut min = f64::INFINITY;
    for tri in triangles {
        let p = tri.map(|i| vertices[i as usize]);
        for k in 0..3 {
            let (a, b, c) = (p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
            let (u, v) = ([b[0] - a[0], b[1] - a[1]], [c[0] - a[0], c[1] - a[1]]);
            let cross = (u[0] * v[1] - u[1] * v[0]).abs();
            let dot = u[0] * v[0] + u[1] * v[1];
            min = min.min(cross.atan2(dot).to_degrees());
        }
    }
    min
}

// ------------------------------------------------------------------------------------------
// earcut's deviation
// ------------------------------------------------------------------------------------------

/// earcut's trapezoid shoelace: Σ (xj − xi)(yi + yj), j the vertex before i.
fn earcut_signed_area(vertices: &[[f64; 2]], ring: impl Iterator<Item = usize> + Clone) -> f64 {
    let Some(last) = ring.clone().last() else {
        return 0.0;
    };
    let mut j = last;
    let mut sum = 0.0;
    for i in ring {
        sum += (vertices[j][0] - vertices[i][0]) * (vertices[i][1] + vertices[j][1]);
        j = i;
    }
    sum
}

fn earcut_triangles_area(vertices: &[[f64; 2]], triangles: &[[u32; 3]]) -> f64 {
    let mut sum = 0.0;
    for t in triangles {
        let [a, b, c] = t.map(|i| vertices[i as usize]);
        sum += ((a[0] - c[0]) * (b[1] - a[1]) - (a[0] - b[0]) * (c[1] - a[1])).abs();
    }
    sum
}

fn relative(polygon_area: f64, triangles_area: f64) -> f64 {
    if polygon_area == 0.0 && triangles_area == 0.0 {
        0.0
    } else {
        ((triangles_area - polygon_area) / polygon_area).abs()
    }
}

/// earcut's `deviation(data, holeIndices, 2, triangles)`, operation for operation:
/// `|T − P| / |P|` with P = |S(ring 0)| − Σ |S(hole)|, T = Σ |cross| over triangles.
pub fn deviation(vertices: &[[f64; 2]], ring_starts: &[usize], triangles: &[[u32; 3]]) -> f64 {
    let n = vertices.len();
    let end = |k: usize| ring_starts.get(k + 1).copied().unwrap_or(n);
    let outer_end = if ring_starts.len() > 1 {
        ring_starts[1]
    } else {
        n
    };
    let mut polygon_area = earcut_signed_area(vertices, 0..outer_end).abs();
    for (k, &start) in ring_starts.iter().enumerate().skip(1) {
        polygon_area -= earcut_signed_area(vertices, start..end(k)).abs();
    }
    relative(polygon_area, earcut_triangles_area(vertices, triangles))
}

/// The same measure for any roles: P = Σ |S(outer)| − Σ |S(hole)|.
pub fn deviation_with_roles(
    vertices: &[[f64; 2]],
    rings: &[Vec<usize>],
    roles: &[Role],
    triangles: &[[u32; 3]],
) -> f64 {
    let mut polygon_area = 0.0;
    for (ring, role) in rings.iter().zip(roles) {
        let s = earcut_signed_area(vertices, ring.iter().copied()).abs();
        match role {
            Role::Outer => polygon_area += s,
            Role::Hole => polygon_area -= s,
        }
    }
    relative(polygon_area, earcut_triangles_area(vertices, triangles))
}

// ------------------------------------------------------------------------------------------
// Edge crossings of the input
// ------------------------------------------------------------------------------------------

/// What [`input_defects`] found.
#[derive(Clone, Debug, Default)]
pub struct Defects {
    /// Edge pairs whose interiors cross at one point: `(vertex a, vertex b)`, each the
    /// input vertex an edge starts at.
    pub crossings: Vec<(usize, usize)>,
    /// Collinear edge pairs overlapping along a segment without being the same segment.
    pub overlaps: Vec<(usize, usize)>,
}

impl Defects {
    /// Neither crossings nor partial overlaps.
    pub fn is_empty(&self) -> bool {
        self.crossings.is_empty() && self.overlaps.is_empty()
    }
}

/// Edges of the rings (consecutive distinct positions) as `(start vertex, end vertex)`.
pub fn ring_edges(vertices: &[[f64; 2]], rings: &[Vec<usize>]) -> Vec<(usize, usize)> {
    let mut edges = Vec::new();
    for ring in rings {
        for (k, &i) in ring.iter().enumerate() {
            let j = ring[(k + 1) % ring.len()];
            if vertices[i] != vertices[j] {
                edges.push((i, j));
            }
        }
    }
    edges
}

/// Segments `a b` and `c d` cross at a single point interior to both (exact).
pub fn segments_cross(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    let (o1, o2) = (orient(a, b, c), orient(a, b, d));
    let (o3, o4) = (orient(c, d, a), orient(c, d, b));
    o1 * o2 < 0.0 && o3 * o4 < 0.0
}

/// Collinear segments sharing a piece of positive length, other than being identical.
fn segments_overlap(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    if orient(a, b, c) != 0.0 || orient(a, b, d) != 0.0 {
        return false;
    }
    if (a == c && b == d) || (a == d && b == c) {
        return false;
    }
    let k = if a[0] != b[0] { 0 } else { 1 };
    let (lo1, hi1) = (a[k].min(b[k]), a[k].max(b[k]));
    let (lo2, hi2) = (c[k].min(d[k]), c[k].max(d[k]));
    lo1.max(lo2) < hi1.min(hi2)
}

/// Every proper crossing and partial overlap between ring edges (exact, grid-bucketed).
pub fn input_defects(vertices: &[[f64; 2]], rings: &[Vec<usize>]) -> Defects {
    let edges = ring_edges(vertices, rings);
    let mut defects = Defects::default();
    if edges.is_empty() {
        return defects;
    }
    let pts: Vec<[f64; 2]> = edges.iter().map(|&(i, _)| vertices[i]).collect();
    let grid = Grid::new(&pts);
    // Re-bucket edges by their bounding boxes.
    let mut buckets: Vec<Vec<u32>> = vec![Vec::new(); grid.cells * grid.cells];
    let cell_range = |g: &Grid, a: [f64; 2], b: [f64; 2]| {
        (
            g.axis(0, a[0].min(b[0])),
            g.axis(0, a[0].max(b[0])),
            g.axis(1, a[1].min(b[1])),
            g.axis(1, a[1].max(b[1])),
        )
    };
    for (e, &(i, j)) in edges.iter().enumerate() {
        let (x0, x1, y0, y1) = cell_range(&grid, vertices[i], vertices[j]);
        for cy in y0..=y1 {
            for cx in x0..=x1 {
                buckets[cy * grid.cells + cx].push(e as u32);
            }
        }
    }
    for (cell, list) in buckets.iter().enumerate() {
        for (k, &e) in list.iter().enumerate() {
            let (a, b) = (vertices[edges[e as usize].0], vertices[edges[e as usize].1]);
            for &f in &list[k + 1..] {
                let (c, d) = (vertices[edges[f as usize].0], vertices[edges[f as usize].1]);
                // Test each pair once: in the cell holding the low corner of the boxes'
                // intersection.
                let low = [
                    a[0].min(b[0]).max(c[0].min(d[0])),
                    a[1].min(b[1]).max(c[1].min(d[1])),
                ];
                let hi = [
                    a[0].max(b[0]).min(c[0].max(d[0])),
                    a[1].max(b[1]).min(c[1].max(d[1])),
                ];
                if low[0] > hi[0] || low[1] > hi[1] || grid.cell_of(low) != cell {
                    continue;
                }
                let pair = (edges[e as usize].0, edges[f as usize].0);
                if segments_cross(a, b, c, d) {
                    defects.crossings.push(pair);
                } else if segments_overlap(a, b, c, d) {
                    defects.overlaps.push(pair);
                }
            }
        }
    }
    defects
}
