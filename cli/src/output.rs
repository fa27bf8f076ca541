//! Writing a triangulation: result JSON (`{"vertices": …, "triangles": …}`, as the README describes) or an SVG picture.

use std::io::{self, Write};

use serde::Serialize;

use crate::layout::Layout;

/// One output feature of `--format geojson`: triangles (indices into the vertices) and the
/// input feature's id and properties.
#[derive(Debug, Default)]
pub struct TriangleFeature<'a> {
    /// Indices into the written vertices.
    pub triangles: Vec<[u32; 3]>,
    /// The input feature's `id`.
    pub id: Option<&'a geojson::feature::Id>,
    /// The input feature's `properties`.
    pub properties: Option<&'a geojson::JsonObject>,
    /// False for a feature that is left out (a polygon of it was refused, or it has no
    /// triangles).
    pub written: bool,
}

/// Writes a GeoJSON FeatureCollection: per written feature a MultiPolygon of its triangles
/// (each a closed ring of four positions, counter-clockwise) with its id and properties,
/// or with `per_triangle` one Polygon feature per triangle, each with them.
pub fn write_geojson<W: Write>(
    mut w: W,
    vertices: &[[f64; 2]],
    z: Option<&[f64]>,
    features: &[TriangleFeature<'_>],
    per_triangle: bool,
) -> io::Result<()> {
    let ring = |t: &[u32; 3]| -> Vec<Vec<f64>> {
        let p = |i: u32| {
            let mut position = vertices.get(i as usize).map_or(vec![], |v| v.to_vec());
            position.extend(z.and_then(|z| z.get(i as usize)));
            position
        };
        vec![p(t[0]), p(t[1]), p(t[2]), p(t[0])]
    };
    let feature = |f: &TriangleFeature<'_>, value: geojson::GeometryValue| geojson::Feature {
        bbox: None,
        geometry: Some(geojson::Geometry::new(value)),
        id: f.id.cloned(),
        properties: f.properties.cloned(),
        foreign_members: None,
    };
    let mut out = Vec::new();
    for f in features.iter().filter(|f| f.written) {
        if per_triangle {
            out.extend(
                f.triangles
                    .iter()
                    .map(|t| feature(f, geojson::GeometryValue::new_polygon(vec![ring(t)]))),
            );
        } else {
            let polygons: Vec<Vec<Vec<Vec<f64>>>> =
                f.triangles.iter().map(|t| vec![ring(t)]).collect();
            out.push(feature(
                f,
                geojson::GeometryValue::new_multi_polygon(polygons),
            ));
        }
    }
    let collection = geojson::FeatureCollection {
        bbox: None,
        features: out,
        foreign_members: None,
    };
    serde_json::to_writer(&mut w, &collection)?;
    writeln!(w)
}

/// Writes the result JSON of a 3D input: `{"vertices": [[x, y, z], …], "triangles": …}`.
pub fn write_json_3d<W: Write>(
    mut w: W,
    vertices: &[[f64; 2]],
    z: &[f64],
    triangles: &[[u32; 3]],
) -> io::Result<()> {
    let vertices: Vec<[f64; 3]> = (vertices.iter().zip(z))
        .map(|(v, &z)| [v[0], v[1], z])
        .collect();
    serde_json::to_writer(
        &mut w,
        &serde_json::json!({ "vertices": vertices, "triangles": triangles }),
    )?;
    writeln!(w)
}

/// Writes Wavefront OBJ: a `v x y z` line per vertex (z 0 without `z`), then an `f a b c`
/// line per triangle (1-based indices, counter-clockwise).
pub fn write_obj<W: Write>(
    mut w: W,
    vertices: &[[f64; 2]],
    z: Option<&[f64]>,
    triangles: &[[u32; 3]],
) -> io::Result<()> {
    writeln!(
        w,
        "# polytri: {} vertices, {} triangles",
        vertices.len(),
        triangles.len()
    )?;
    for (i, v) in vertices.iter().enumerate() {
        let z = z.and_then(|z| z.get(i)).copied().unwrap_or(0.0);
        writeln!(w, "v {} {} {}", v[0], v[1], z)?;
    }
    for t in triangles {
        writeln!(w, "f {} {} {}", t[0] + 1, t[1] + 1, t[2] + 1)?;
    }
    Ok(())
}

/// A vertex added where edges cross (with `--fill-rule`), numbered after the file's.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Added {
    /// Its index in the written vertices.
    pub vertex: usize,
    /// Its coordinates (in the precision triangulated in, widened to f64).
    #[serde(skip)]
    pub position: [f64; 2],
    /// Two edges crossing there, each by the flat index of the vertex it starts at.
    pub edges: [usize; 2],
}

/// The result JSON: `{"vertices": [[x, y], …], "triangles": [[a, b, c], …]}`, and with a
/// fill rule `"added": [{"vertex": i, "edges": [a, b]}, …]`.
#[derive(Serialize)]
struct ResultJson<'a> {
    vertices: &'a [[f64; 2]],
    triangles: &'a [[u32; 3]],
    #[serde(skip_serializing_if = "Option::is_none")]
    added: Option<&'a [Added]>,
}

/// Writes the result JSON on one line, then a newline. `added` (with a fill rule: the
/// vertices added where edges cross, which `vertices` ends with) becomes an `"added"`
/// list; without one the JSON is as it always was.
///
/// Vertices are written as parsed (a non-finite one, only possible with `--lenient` from
/// WKT or the f32 conversion, becomes `null`, as JSON has no NaN).
pub fn write_json<W: Write>(
    mut w: W,
    vertices: &[[f64; 2]],
    triangles: &[[u32; 3]],
    added: Option<&[Added]>,
) -> io::Result<()> {
    serde_json::to_writer(
        &mut w,
        &ResultJson {
            vertices,
            triangles,
            added,
        },
    )
    .map_err(io::Error::from)?;
    w.write_all(b"\n")?;
    w.flush()
}

/// The canvas is this many user units across its longer side, whatever the input's scale:
/// stroke widths and dot sizes are then constants, and coordinates stay small numbers that
/// SVG renderers (often single precision) draw without jitter.
const CANVAS: f64 = 1000.0;
/// Blank border around the drawing, in canvas units.
const MARGIN: f64 = 20.0;

/// The drawing's style. `non-scaling-stroke` keeps lines thin when zooming into a large
/// mesh; where it is not supported, the widths are still right at the default size,
/// because the canvas is about as many units as the picture is pixels.
const STYLE: &str = "\
.tri{fill:#cfe0f7;fill-opacity:.75;stroke:#4a6fa5;stroke-width:.5;stroke-linejoin:round;vector-effect:non-scaling-stroke}
.outer{fill:none;stroke:#111;stroke-width:1.8;stroke-linejoin:round;vector-effect:non-scaling-stroke}
.hole{fill:none;stroke:#c0392b;stroke-width:1.8;stroke-dasharray:6 3;stroke-linejoin:round;vector-effect:non-scaling-stroke}
.dropped{fill:#e67e22}
.added{fill:#e00;stroke:#fff;stroke-width:.5;vector-effect:non-scaling-stroke}";

/// Maps input coordinates (y up, any scale) to canvas coordinates (y down, 0..CANVAS).
struct Frame {
    min_x: f64,
    max_y: f64,
    /// Canvas units per half input unit: half, so spans between ±f64::MAX do not overflow.
    scale: f64,
    width: f64,
    height: f64,
}

impl Frame {
    fn fit(vertices: &[[f64; 2]]) -> Frame {
        let finite = vertices
            .iter()
            .filter(|v| v[0].is_finite() && v[1].is_finite());
        let (mut min_x, mut min_y, mut max_x, mut max_y) = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
        for v in finite {
            min_x = min_x.min(v[0]);
            max_x = max_x.max(v[0]);
            min_y = min_y.min(v[1]);
            max_y = max_y.max(v[1]);
        }
        if min_x > max_x {
            // Nothing to draw: an empty unit frame.
            (min_x, min_y, max_x, max_y) = (0.0, 0.0, 1.0, 1.0);
        }
        let half_w = max_x / 2.0 - min_x / 2.0;
        let half_h = max_y / 2.0 - min_y / 2.0;
        let half_span = half_w.max(half_h);
        // A single point or a zero-area line still gets a finite scale.
        let scale = if half_span > 0.0 {
            CANVAS / half_span
        } else {
            1.0
        };
        Frame {
            min_x,
            max_y,
            scale,
            width: half_w * scale,
            height: half_h * scale,
        }
    }

    fn map(&self, v: [f64; 2]) -> Option<(f64, f64)> {
        let x = (v[0] / 2.0 - self.min_x / 2.0) * self.scale;
        let y = (self.max_y / 2.0 - v[1] / 2.0) * self.scale;
        (x.is_finite() && y.is_finite()).then_some((x, y))
    }
}

/// A number with at most two decimals and no trailing zeros: 1/100 of a canvas unit is
/// 1/100,000 of the drawing, finer than any screen.
fn num(value: f64) -> String {
    let s = format!("{value:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_owned()
    } else {
        s.to_owned()
    }
}

/// Writes an SVG picture: the triangles (light fill, thin strokes), the file's rings on
/// top (outer boundaries solid, holes dashed red), dropped vertices as orange dots, and
/// the vertices `added` where edges cross (with a fill rule; triangles index them after
/// the layout's) as small red dots.
///
/// Points that are not finite are left out of the picture.
pub fn write_svg<W: Write>(
    mut w: W,
    layout: &Layout,
    added: &[[f64; 2]],
    triangles: &[[u32; 3]],
    groups: Option<&[usize]>,
    dropped: &[usize],
) -> io::Result<()> {
    let frame = Frame::fit(&layout.vertices);
    let n = layout.vertices.len();
    let point = |i: usize| {
        let v = if i < n {
            layout.vertices.get(i)
        } else {
            added.get(i - n)
        };
        v.and_then(|&v| frame.map(v))
    };
    let (w_box, h_box) = (frame.width + 2.0 * MARGIN, frame.height + 2.0 * MARGIN);
    writeln!(
        w,
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="{} {} {} {}" width="{}" height="{}">"#,
        num(-MARGIN),
        num(-MARGIN),
        num(w_box),
        num(h_box),
        num(w_box),
        num(h_box)
    )?;
    writeln!(w, "<title>polytri: {} triangles</title>", triangles.len())?;
    writeln!(w, "<style>\n{STYLE}\n</style>")?;

    writeln!(w, r#"<g class="triangles">"#)?;
    for (k, t) in triangles.iter().enumerate() {
        // one colour per group (a county of a layer): hues a golden angle apart
        let colour = groups.and_then(|g| g.get(k)).map(|&g| {
            let hue = (g as f64 * 137.508) % 360.0;
            format!(r#" style="fill:hsl({hue:.0},55%,72%)""#)
        });
        let colour = colour.as_deref().unwrap_or("");
        let corners = [
            point(t[0] as usize),
            point(t[1] as usize),
            point(t[2] as usize),
        ];
        if let [Some(a), Some(b), Some(c)] = corners {
            writeln!(
                w,
                r#"<polygon class="tri"{colour} points="{},{} {},{} {},{}"/>"#,
                num(a.0),
                num(a.1),
                num(b.0),
                num(b.1),
                num(c.0),
                num(c.1)
            )?;
        }
    }
    writeln!(w, "</g>")?;

    writeln!(w, r#"<g class="rings">"#)?;
    for (ring, origin) in layout.ring_origins.iter().enumerate() {
        let mut d = String::new();
        for (k, (x, y)) in layout.ring_vertices(ring).filter_map(point).enumerate() {
            d.push_str(if k == 0 { "M" } else { " L" });
            d.push_str(&num(x));
            d.push(' ');
            d.push_str(&num(y));
        }
        if !d.is_empty() {
            let class = if origin.is_hole() { "hole" } else { "outer" };
            writeln!(w, r#"<path class="{class}" d="{d} Z"/>"#)?;
        }
    }
    writeln!(w, "</g>")?;

    if !dropped.is_empty() {
        writeln!(w, r#"<g class="dropped">"#)?;
        for (x, y) in dropped.iter().filter_map(|&i| point(i)) {
            writeln!(w, r#"<circle cx="{}" cy="{}" r="3"/>"#, num(x), num(y))?;
        }
        writeln!(w, "</g>")?;
    }
    if !added.is_empty() {
        writeln!(w, r#"<g class="added">"#)?;
        for (x, y) in (n..n + added.len()).filter_map(point) {
            writeln!(w, r#"<circle cx="{}" cy="{}" r="2.5"/>"#, num(x), num(y))?;
        }
        writeln!(w, "</g>")?;
    }
    writeln!(w, "</svg>")?;
    w.flush()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_has_the_documented_shape() {
        let mut out = Vec::new();
        write_json(
            &mut out,
            &[[0.0, 0.0], [1.5, 0.0], [1.0, f64::NAN]],
            &[[0, 1, 2]],
            None,
        )
        .expect("in memory");
        let text = String::from_utf8(out).expect("utf-8");
        assert_eq!(
            text,
            "{\"vertices\":[[0.0,0.0],[1.5,0.0],[1.0,null]],\"triangles\":[[0,1,2]]}\n"
        );
        // with a fill rule: the added vertices listed after the triangles
        let mut out = Vec::new();
        let added = Added {
            vertex: 4,
            position: [1.0, 1.0],
            edges: [0, 2],
        };
        let bow_tie = [[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0], [1.0, 1.0]];
        write_json(&mut out, &bow_tie, &[[0, 4, 3]], Some(&[added])).expect("in memory");
        let text = String::from_utf8(out).expect("utf-8");
        assert!(
            text.ends_with("\"triangles\":[[0,4,3]],\"added\":[{\"vertex\":4,\"edges\":[0,2]}]}\n"),
            "{text}"
        );
    }

    #[test]
    fn numbers_are_short() {
        assert_eq!(num(12.0), "12");
        assert_eq!(num(12.5), "12.5");
        assert_eq!(num(0.123_456), "0.12");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(-20.0), "-20");
    }

    #[test]
    fn frame_flips_y_and_fits_any_scale() {
        for scale in [1e-9, 1.0, 1e9, 1e300] {
            let frame = Frame::fit(&[[0.0, 0.0], [2.0 * scale, scale]]);
            let (x0, y0) = frame.map([0.0, 0.0]).expect("finite");
            let (x1, y1) = frame.map([2.0 * scale, scale]).expect("finite");
            assert!(
                (x0 - 0.0).abs() < 1e-9 && (y0 - 500.0).abs() < 1e-6,
                "{scale}: {x0} {y0}"
            );
            assert!(
                (x1 - 1000.0).abs() < 1e-6 && y1.abs() < 1e-6,
                "{scale}: {x1} {y1}"
            );
        }
        let frame = Frame::fit(&[[-f64::MAX, -f64::MAX], [f64::MAX, f64::MAX]]);
        assert!(frame.map([f64::MAX, 0.0]).is_some());
        let frame = Frame::fit(&[[3.0, 3.0], [f64::NAN, 1.0]]);
        assert!(frame.scale.is_finite());
        assert!(Frame::fit(&[]).scale.is_finite());
    }

    #[test]
    fn svg_draws_triangles_rings_and_dropped_points() {
        let polygons = vec![vec![
            vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]],
            vec![[3.0, 3.0], [3.0, 7.0], [7.0, 7.0], [7.0, 3.0]],
        ]];
        let layout = Layout::new(&polygons);
        let mut out = Vec::new();
        write_svg(&mut out, &layout, &[], &[[0, 1, 4], [9, 9, 9]], None, &[5]).expect("in memory");
        let text = String::from_utf8(out).expect("utf-8");
        assert!(text.starts_with("<svg "), "{text}");
        assert!(text.trim_end().ends_with("</svg>"));
        // The out-of-range triangle is left out, not a panic.
        assert_eq!(text.matches("<polygon ").count(), 1);
        assert_eq!(text.matches(r#"<path class="outer""#).count(), 1);
        assert_eq!(text.matches(r#"<path class="hole""#).count(), 1);
        assert_eq!(text.matches("<circle ").count(), 1);
        // y is flipped: input (0, 0) is the canvas's bottom left.
        assert!(
            text.contains(r#"d="M0 1000 L1000 1000 L1000 0 L0 0 Z""#),
            "{text}"
        );
    }

    #[test]
    fn svg_marks_added_vertices() {
        let bow_tie = vec![[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]];
        let layout = Layout::new(&[vec![bow_tie]]);
        let mut out = Vec::new();
        write_svg(
            &mut out,
            &layout,
            &[[1.0, 1.0]],
            &[[0, 4, 3], [4, 1, 2]],
            None,
            &[],
        )
        .expect("in memory");
        let text = String::from_utf8(out).expect("utf-8");
        // both triangles drawn through the added vertex, which is one red dot
        assert_eq!(text.matches("<polygon ").count(), 2, "{text}");
        assert!(
            text.contains("<g class=\"added\">\n<circle cx=\"500\" cy=\"500\" r=\"2.5\"/>"),
            "{text}"
        );
    }

    #[test]
    fn svg_colours_each_group() {
        let square = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let layout = Layout::new(&[vec![square]]);
        let fill = |groups: Option<&[usize]>| {
            let mut out = Vec::new();
            write_svg(&mut out, &layout, &[], &[[0, 1, 2], [0, 2, 3]], groups, &[])
                .expect("in memory");
            let text = String::from_utf8(out).expect("utf-8");
            let fills: Vec<String> = text
                .split("fill:hsl(")
                .skip(1)
                .map(|f| f[..f.find(')').unwrap_or(0)].to_owned())
                .collect();
            fills
        };
        let two = fill(Some(&[0, 1]));
        assert_eq!(two.len(), 2);
        assert_ne!(two[0], two[1]);
        let one = fill(Some(&[3, 3]));
        assert_eq!(one[0], one[1]);
        assert!(fill(None).is_empty());
    }
}
