//! The verdict on a triangulation: exact validity checks, `geo`'s second opinion, `spade`'s
//! constrained Delaunay triangulation for comparison, and quality metrics.
//!
//! Nothing here uses `polytri`'s code: the checks have their own exact predicates
//! (`exact`) and their own notion of the polygon (`region`, whose docs define when an
//! input is valid). A triangulation is valid when every check that ran passed:
//!
//! | check             | what it asks                                                        |
//! |-------------------|---------------------------------------------------------------------|
//! | `input`           | the input is a valid polygon set (see `region`)                     |
//! | `indices`         | every triangle index names an input vertex                          |
//! | `orientation`     | every triangle has positive area, counter-clockwise with y up       |
//! | `edges`           | each directed edge is used once; one without its reverse lies on the boundary, polygon on its left |
//! | `boundary`        | every boundary edge (cut at vertices on it) is covered by exactly one triangle edge |
//! | `crossings`       | no triangle edge crosses a ring edge (zero-width ones, walked both ways or of zero-area rings, bound nothing and may be crossed) |
//! | `count`           | the count any triangulation over the vertices used has (`n − 2 + 2h` per polygon) |
//! | `area`            | Σ triangle areas = the polygon's area, exactly                      |
//! | `containment`     | every triangle's centroid has winding number 1, exactly             |
//! | `geo-area`        | the same by `geo`, within floating-point noise ([`CheckOptions::geo`]) |
//! | `geo-containment` | centroids inside by `geo`'s point-in-polygon test ([`CheckOptions::geo`]) |
//! | `cdt`             | spade's CDT of the rings covers the same area; same count when it uses the same vertices ([`CheckOptions::cdt`]) |
//!
//! Checks that need geometry are skipped when the input's structure or coordinates are
//! unusable (NaN, out of the exact range, malformed ring starts); `count`, `geo-*` and
//! `cdt` run only for valid inputs.

use std::cmp::Ordering;
use std::collections::HashSet;

use serde::{Deserialize, Serialize};

use crate::input::{Input, Nesting};
use crate::metrics;

mod fill;
mod geo;
mod mesh;
pub(crate) mod region;

pub use fill::{
    check_fill, fill_area, fill_area_float, verify_fill, FillArea, EXACT_MAX_CROSSINGS,
    EXACT_MAX_EDGES, FLOAT_RELATIVE_TOLERANCE,
};

use mesh::Mesh;
use region::Region;

/// Which of the slower checks to run besides the exact ones and the metrics.
///
/// `Default` is [`CheckOptions::fast`].
#[derive(Clone, Debug, Default)]
pub struct CheckOptions {
    /// Run `geo`'s area and containment tests (floating point, an independent library;
    /// containment samples triangles on huge rings).
    pub geo: bool,
    /// Build `spade`'s constrained Delaunay triangulation and compare.
    pub cdt: bool,
}

impl CheckOptions {
    /// Exact checks and metrics only: what fuzzing wants.
    pub fn fast() -> Self {
        CheckOptions {
            geo: false,
            cdt: false,
        }
    }

    /// Everything: exact checks, geo and the CDT comparison.
    pub fn full() -> Self {
        CheckOptions {
            geo: true,
            cdt: true,
        }
    }
}

/// The outcome of one check.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Check {
    /// The check's name (see the module docs for the list).
    pub name: String,
    /// Whether it passed.
    pub passed: bool,
    /// For a failure: the first offending triangle or edge (input vertex indices) and how
    /// many more there were; for a pass, an occasional note.
    pub detail: Option<String>,
}

/// spade's constrained Delaunay triangulation of the same rings, restricted to the
/// polygon's interior.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CdtComparison {
    /// Its number of triangles.
    pub triangles: usize,
    /// Its total area.
    pub area: f64,
    /// Its smallest angle in degrees: the quality target.
    pub min_angle_deg: f64,
}

/// The verdict on a triangulation of an input.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Verdict {
    /// Every check that ran passed.
    pub valid: bool,
    /// The input itself is a valid polygon set by the oracle's exact test.
    pub input_valid: bool,
    /// Every check that ran, in order.
    pub checks: Vec<Check>,
    /// The number of triangles judged.
    pub triangles: usize,
    /// The number any triangulation of the input over the same vertices has (valid inputs).
    pub expected_triangles: Option<usize>,
    /// earcut's `|area(polygon) − Σ area(triangles)| / area(polygon)` of geo's areas, by
    /// [`polytri::deviation`] (0 when both are 0, 1 when only the polygon's is).
    pub deviation: f64,
    /// The smallest triangle angle in degrees.
    pub min_angle_deg: f64,
    /// The largest aspect ratio (longest edge × perimeter / (4√3 · area); 1 is equilateral).
    pub worst_aspect: f64,
    /// The total length of the distinct edges.
    pub total_edge_length: f64,
    /// The CDT comparison, when it ran.
    pub cdt: Option<CdtComparison>,
}

impl Verdict {
    /// `"name: detail"` for every failed check.
    pub fn failures(&self) -> Vec<String> {
        self.checks
            .iter()
            .filter(|c| !c.passed)
            .map(|c| format!("{}: {}", c.name, c.detail.as_deref().unwrap_or("failed")))
            .collect()
    }

    /// The check called `name`, if it ran.
    pub fn check(&self, name: &str) -> Option<&Check> {
        self.checks.iter().find(|c| c.name == name)
    }
}

/// Collects the failures of one check: the first spelled out, the rest counted.
#[derive(Debug, Default)]
pub(crate) struct Failures {
    first: Option<String>,
    count: usize,
}

impl Failures {
    /// Records one failure; `what` is only called for the first.
    pub(crate) fn note(&mut self, what: impl FnOnce() -> String) {
        if self.first.is_none() {
            self.first = Some(what());
        }
        self.count += 1;
    }

    pub(crate) fn check(self, name: &str) -> Check {
        let detail = self.first.map(|first| match self.count {
            1 => first,
            n => format!("{first} (and {} more)", n - 1),
        });
        Check {
            name: name.to_owned(),
            passed: self.count == 0,
            detail,
        }
    }
}

/// Judges `triangles` (indices into `input.vertices`) as a triangulation of `input`, with
/// every check ([`CheckOptions::full`]).
///
/// ```
/// use polytri_oracle::{check, Input, Nesting};
/// let square = Input::new(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], vec![0], Nesting::Auto);
/// assert!(check(&square, &[[0, 1, 2], [0, 2, 3]]).valid);
/// let verdict = check(&square, &[[0, 1, 2]]);
/// assert!(!verdict.valid);
/// assert!(verdict.failures().iter().any(|f| f.starts_with("boundary:")));
/// ```
pub fn check(input: &Input, triangles: &[[u32; 3]]) -> Verdict {
    check_with(input, triangles, &CheckOptions::full())
}

/// Verifies any program's triangulation of a polygon with holes: `triangles` (index
/// triples into `vertices`) against the rings `vertices` and `ring_starts` describe, with
/// holes decided by `nesting` as polytri decides them. The verdict names each failed
/// check and the first triangle or edge it failed on; `verdict.valid` is the answer.
///
/// This is polytri's second product: an independent judge with its own exact arithmetic,
/// for polytri's results and for any other triangulator's.
///
/// ```
/// use polytri::{Nesting, Options, Triangulator};
/// // a square with a square hole
/// let vertices = [
///     [0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0],
///     [3.0, 3.0], [3.0, 7.0], [7.0, 7.0], [7.0, 3.0],
/// ];
/// let ring_starts = [0, 4];
/// let mut triangles = Vec::new();
/// Triangulator::<f64>::new()
///     .triangulate(&vertices, &ring_starts, &Options::default(), &mut triangles)
///     .expect("a valid polygon");
/// let verdict = polytri_oracle::verify(&vertices, &ring_starts, Nesting::Auto, &triangles);
/// assert!(verdict.valid);
///
/// // turn one triangle round: the verdict names it
/// triangles[1].swap(1, 2);
/// let verdict = polytri_oracle::verify(&vertices, &ring_starts, Nesting::Auto, &triangles);
/// assert!(!verdict.valid);
/// let failures = verdict.failures();
/// assert!(failures[0].starts_with("orientation: triangle 1 "), "{failures:?}");
/// ```
pub fn verify<T: polytri::Coord>(
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    nesting: polytri::Nesting,
    triangles: &[[u32; 3]],
) -> Verdict {
    let vertices = vertices
        .iter()
        .map(|v| [v[0].to_f64(), v[1].to_f64()])
        .collect();
    let nesting = match nesting {
        polytri::Nesting::FirstIsOuter => Nesting::FirstIsOuter,
        _ => Nesting::Auto,
    };
    check(
        &Input::new(vertices, ring_starts.to_vec(), nesting),
        triangles,
    )
}

/// Judges `triangles` as a triangulation of `input`, running the checks `opts` asks for.
/// Never panics, whatever the input or the triangles hold.
pub fn check_with(input: &Input, triangles: &[[u32; 3]], opts: &CheckOptions) -> Verdict {
    let region = Region::build(input);
    let mut verdict = Verdict {
        valid: false,
        input_valid: region.problems.is_empty(),
        checks: Vec::new(),
        triangles: triangles.len(),
        expected_triangles: None,
        deviation: 0.0,
        min_angle_deg: 0.0,
        worst_aspect: 0.0,
        total_edge_length: 0.0,
        cdt: None,
    };
    let mut input_fails = Failures::default();
    for p in &region.problems {
        input_fails.note(|| p.clone());
    }
    input_fails.count = region.problem_count;
    verdict.checks.push(input_fails.check("input"));

    let n = region.pts.len();
    let mut bad_index = Failures::default();
    let mut good = Vec::with_capacity(triangles.len());
    for (k, t) in triangles.iter().enumerate() {
        match t.iter().find(|&&i| i as usize >= n) {
            Some(&i) => bad_index.note(|| {
                format!(
                    "triangle {k} ({}, {}, {}) names vertex {i}, but there are {n}",
                    t[0], t[1], t[2]
                )
            }),
            None => good.push((k, t.map(|i| region.rep[i as usize]))),
        }
    }
    verdict.checks.push(bad_index.check("indices"));

    if region.usable {
        judge_geometry(&mut verdict, input, &region, good, opts);
    }
    verdict.valid = verdict.checks.iter().all(|c| c.passed);
    verdict
}

/// Every check that needs coordinates.
fn judge_geometry(
    verdict: &mut Verdict,
    input: &Input,
    region: &Region,
    good: Vec<(usize, [u32; 3])>,
    opts: &CheckOptions,
) {
    let mesh = Mesh::new(region, good);
    verdict.checks.push(mesh.orientation());
    let (edges, chain) = mesh.edges();
    verdict.checks.push(edges);
    verdict.checks.push(mesh.boundary(&chain));
    verdict.checks.push(mesh.crossings());
    if verdict.input_valid {
        let mut fails = Failures::default();
        match mesh.expected_count() {
            Ok(expected) => {
                verdict.expected_triangles = Some(expected);
                if expected != verdict.triangles {
                    fails.note(|| {
                        format!("{} triangles, but a triangulation over the {} vertices used has {expected}", verdict.triangles, mesh.used().len())
                    });
                }
            }
            Err(sum) => fails.note(|| {
                format!("the polygon's angles at the vertices used sum to {sum}·π, not a whole multiple of π: the triangles leave out or repeat part of a vertex's neighbourhood")
            }),
        }
        verdict.checks.push(fails.check("count"));
    }
    verdict.checks.push(mesh.area());
    verdict.checks.push(mesh.containment());

    let pts = &region.pts;
    let corners: Vec<[([f64; 2], u32); 3]> = mesh
        .tris
        .iter()
        .map(|&(_, t)| t.map(|v| (pts[v as usize], v)))
        .collect();
    let quality = metrics::measure(&corners);
    verdict.min_angle_deg = quality.min_angle_deg;
    verdict.worst_aspect = quality.worst_aspect;
    verdict.total_edge_length = quality.total_edge_length;

    let rings = geo::GeoRings::new(input, region);
    let polygon_area = rings.area();
    let triangle_area = geo::triangle_area(pts, &mesh.tris);
    verdict.deviation = polytri::deviation(polygon_area, triangle_area);
    if !verdict.input_valid {
        return;
    }
    if opts.geo {
        let scale = pts
            .iter()
            .fold(0.0, |m: f64, p| m.max(p[0].abs()).max(p[1].abs()));
        let terms = pts.len() + 3 * mesh.tris.len();
        verdict
            .checks
            .push(geo::area_check(polygon_area, triangle_area, terms, scale));
        verdict
            .checks
            .push(geo::containment(&rings, region, pts, &mesh.tris));
    }
    if opts.cdt {
        compare_cdt(verdict, region, &mesh);
    }
}

/// Builds spade's CDT and compares it with the region and the triangulation.
fn compare_cdt(verdict: &mut Verdict, region: &Region, mesh: &Mesh<'_>) {
    let mut fails = Failures::default();
    match crate::cdt::interior_faces(region) {
        Err(why) => fails.note(|| why),
        Ok(faces) => {
            let mut area2 = crate::cdt::twice_area(&faces);
            let area = area2.value() / 2.0;
            area2.add_exact(&region.area2, -1.0);
            if area2.sign() != Ordering::Equal {
                fails.note(|| {
                    format!(
                        "spade's triangles cover {area:e}, the polygon has {:e}",
                        region.area2.value() / 2.0
                    )
                });
            }
            let cdt_used: HashSet<u32> = faces.iter().flat_map(|f| f.map(|c| c.1)).collect();
            let used = mesh.used();
            let same_vertices = cdt_used == used;
            if same_vertices && faces.len() != verdict.triangles {
                fails.note(|| {
                    format!(
                        "spade has {} triangles over the same vertices, the triangulation {}",
                        faces.len(),
                        verdict.triangles
                    )
                });
            }
            let quality = metrics::measure(&faces);
            verdict.cdt = Some(CdtComparison {
                triangles: faces.len(),
                area,
                min_angle_deg: quality.min_angle_deg,
            });
            if !same_vertices && fails.count == 0 {
                let note = format!(
                    "counts not compared: spade uses {} vertices, the triangulation {}",
                    cdt_used.len(),
                    used.len()
                );
                let mut check = fails.check("cdt");
                check.detail = Some(note);
                verdict.checks.push(check);
                return;
            }
        }
    }
    verdict.checks.push(fails.check("cdt"));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::Nesting;

    fn square_with_hole() -> Input {
        Input::from_rings(
            &[
                vec![[0.0, 0.0], [3.0, 0.0], [3.0, 3.0], [0.0, 3.0]],
                vec![[1.0, 1.0], [1.0, 2.0], [2.0, 2.0], [2.0, 1.0]],
            ],
            Nesting::Auto,
        )
    }

    /// A hand-made triangulation of the square with a hole: 8 triangles.
    const FRAME: [[u32; 3]; 8] = [
        [0, 1, 7],
        [0, 7, 4],
        [1, 2, 6],
        [1, 6, 7],
        [2, 3, 5],
        [2, 5, 6],
        [3, 0, 4],
        [3, 4, 5],
    ];

    #[test]
    fn accepts_a_frame_and_reports_metrics() {
        let v = check(&square_with_hole(), &FRAME);
        assert!(v.valid, "{:?}", v.failures());
        assert_eq!(v.expected_triangles, Some(8));
        assert_eq!(v.deviation, 0.0);
        // The sharpest corner: triangle 1 at vertex 0, 45° − atan(1/2).
        let sharpest = 45.0 - 0.5f64.atan().to_degrees();
        assert!(
            (v.min_angle_deg - sharpest).abs() < 1e-9,
            "{}",
            v.min_angle_deg
        );
        let cdt = v.cdt.clone().expect("cdt ran");
        assert_eq!((cdt.triangles, cdt.area), (8, 8.0));
        let json = serde_json::to_string(&v).expect("serialises");
        let back: Verdict = serde_json::from_str(&json).expect("round trip");
        assert_eq!(back.checks, v.checks);
    }

    #[test]
    fn names_the_failing_checks() {
        let input = square_with_hole();
        let fails = |tris: &[[u32; 3]]| -> Vec<String> {
            check(&input, tris)
                .checks
                .into_iter()
                .filter(|c| !c.passed)
                .map(|c| c.name)
                .collect()
        };
        assert_eq!(
            fails(&FRAME[1..]),
            ["edges", "boundary", "count", "area", "geo-area", "cdt"]
        );
        let mut flipped = FRAME;
        flipped[3] = [1, 7, 6];
        assert!(fails(&flipped).contains(&"orientation".to_owned()));
        let mut out_of_range = FRAME.to_vec();
        out_of_range.push([0, 1, 99]);
        assert!(fails(&out_of_range).contains(&"indices".to_owned()));
        // Covering the hole: triangles inside it are not contained.
        let mut covering = FRAME.to_vec();
        covering.extend([[4, 7, 6], [4, 6, 5]]);
        let names = fails(&covering);
        assert!(names.contains(&"containment".to_owned()), "{names:?}");
    }

    #[test]
    fn garbage_gives_verdicts_not_panics() {
        let nan = Input::new(
            vec![[f64::NAN, 0.0], [1.0, 0.0], [0.0, 1.0]],
            vec![0],
            Nesting::Auto,
        );
        let v = check(&nan, &[[0, 1, 2], [7, 8, 9]]);
        assert!(!v.valid && !v.input_valid);
        assert!(serde_json::to_string(&v).is_ok());
        let empty = check(&Input::default(), &[]);
        assert!(empty.valid, "{:?}", empty.failures());
        assert_eq!(empty.expected_triangles, Some(0));
        let v = check(&Input::default(), &[[0, 0, 0]]);
        assert!(!v.valid);
    }
}
