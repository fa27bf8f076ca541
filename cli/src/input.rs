//! Reading polygons from files: rings JSON, shapes JSON, GeoJSON and WKT.
//!
//! The format is recognised from the file, not from flags: a `.wkt` name or text opening
//! with a WKT keyword is WKT, anything else JSON, and JSON is told apart by its shape (an
//! object is GeoJSON; an array is rings or shapes by how deep its first number sits).
//! Every point keeps its position in the file, so errors found later can say where.

use std::collections::BTreeMap;
use std::fmt;
use std::io::Read;
use std::path::Path;
use std::str::FromStr;

use geojson::{GeoJson, GeometryValue};
use serde::de::{self, Deserializer, IgnoredAny, SeqAccess, Visitor};
use serde::Deserialize;
use serde_json::Value;

use crate::Failure;

/// One ring: its points in file order, a repeated closing point already dropped.
pub type Ring = Vec<[f64; 2]>;

/// One polygon as the file gives it: the first ring is its outer boundary, the rest holes.
pub type Polygon = Vec<Ring>;

/// The input formats `polytri` reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// earcut's test format `[[[x, y], …], …]`: one polygon, first ring outer.
    Rings,
    /// A list of rings-format polygons `[[[[x, y], …], …], …]`.
    Shapes,
    /// GeoJSON (RFC 7946): Polygon and MultiPolygon, in Features, FeatureCollections and
    /// GeometryCollections.
    GeoJson,
    /// Well-known text: POLYGON, MULTIPOLYGON and GEOMETRYCOLLECTION, any number per file.
    Wkt,
    /// A corpus case: a JSON object whose `rings` are rings JSON, beside metadata (name,
    /// description, source, expectations) that is ignored here.
    Case,
}

impl fmt::Display for Format {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Format::Rings => "rings JSON",
            Format::Shapes => "shapes JSON",
            Format::GeoJson => "GeoJSON",
            Format::Wkt => "WKT",
            Format::Case => "corpus case JSON",
        })
    }
}

/// A GeoJSON feature's identity, for writing its triangles back with it.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Feature {
    /// The feature's `id`, if it has one.
    pub id: Option<geojson::feature::Id>,
    /// The feature's `properties`, if it has any.
    pub properties: Option<geojson::JsonObject>,
}

/// The polygons of one file, and what was skipped on the way.
#[derive(Debug, Clone, PartialEq)]
pub struct Input {
    /// The format the file was read as.
    pub format: Format,
    /// Every polygon, in file order.
    pub polygons: Vec<Polygon>,
    /// GeoJSON: the features that hold polygons, in file order (a bare geometry is one
    /// feature without id or properties). Other formats: empty.
    pub features: Vec<Feature>,
    /// GeoJSON: per polygon, the index of its feature in `features`. Other formats: empty.
    pub polygon_feature: Vec<usize>,
    /// Per polygon, the z of every point, ring by ring, when every point of it has one
    /// (rings JSON `[x, y, z]`, GeoJSON positions of three numbers); empty for WKT.
    pub z: Vec<Option<Vec<Vec<f64>>>>,
    /// Geometries that are not polygons (points, lines, features without geometry), by
    /// type name, with how many of each were skipped.
    pub skipped: BTreeMap<&'static str, usize>,
}

impl Input {
    fn new(format: Format) -> Self {
        Input {
            format,
            polygons: Vec::new(),
            features: Vec::new(),
            polygon_feature: Vec::new(),
            z: Vec::new(),
            skipped: BTreeMap::new(),
        }
    }

    fn skip(&mut self, what: &'static str) {
        *self.skipped.entry(what).or_insert(0) += 1;
    }
}

/// Reads and parses the file at `path` (`-` is standard input).
///
/// # Errors
///
/// A [`Failure`] naming the file and what is wrong: unreadable, not UTF-8, or not
/// parseable, with line and column where the parser knows them.
pub fn read(path: &Path) -> Result<Input, Failure> {
    let name = display_name(path);
    let bytes = if is_stdin(path) {
        let mut bytes = Vec::new();
        std::io::stdin()
            .read_to_end(&mut bytes)
            .map_err(|e| Failure(format!("{name}: cannot read standard input: {e}")))?;
        bytes
    } else {
        std::fs::read(path).map_err(|e| Failure(format!("{name}: cannot read: {e}")))?
    };
    let text = String::from_utf8(bytes).map_err(|e| {
        Failure(format!(
            "{name}: not UTF-8 text (invalid byte at offset {})",
            e.utf8_error().valid_up_to()
        ))
    })?;
    parse(&text, has_wkt_extension(path)).map_err(|e| Failure(format!("{name}: {e}")))
}

/// The name messages use for `path`.
pub fn display_name(path: &Path) -> String {
    if is_stdin(path) {
        "<stdin>".to_owned()
    } else {
        path.display().to_string()
    }
}

fn is_stdin(path: &Path) -> bool {
    path.as_os_str() == "-"
}

fn has_wkt_extension(path: &Path) -> bool {
    path.extension()
        .is_some_and(|ext| ext.eq_ignore_ascii_case("wkt"))
}

/// Parses `text`, as WKT when `wkt` is set or the text opens with a WKT keyword, else as
/// JSON of any of the supported shapes.
///
/// # Errors
///
/// A one-line description of the first problem, with its position where known.
pub fn parse(text: &str, wkt: bool) -> Result<Input, String> {
    // Editors on Windows like to start UTF-8 files with a byte-order mark.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if wkt || starts_with_wkt_keyword(text) {
        return parse_wkt(text);
    }
    // Parse once untyped to choose the shape (and to report syntax errors with their
    // position), then again typed, so that a bad coordinate is reported with its position.
    let value: Value = serde_json::from_str(text).map_err(|e| format!("invalid JSON: {e}"))?;
    match value {
        Value::Object(ref map) if map.contains_key("rings") && !map.contains_key("type") => {
            parse_case(text)
        }
        Value::Object(_) => parse_geojson(text),
        Value::Array(ref items) => match items.iter().find_map(number_depth) {
            // The first number is x of a point, inside a ring, inside a polygon: depth 3 is
            // one polygon, depth 4 a list of them. Deeper or shallower nestings go through
            // the typed parser too, which then says where the shape goes wrong.
            Some(depth) if depth >= 3 => parse_shapes(text),
            _ => parse_rings(text),
        },
        other => Err(format!(
            "expected rings [[[x, y], …], …], shapes [[[[x, y], …], …], …] or a GeoJSON object, found {}",
            json_kind(&other)
        )),
    }
}

/// How many arrays enclose the first number in `value` (0 for a number itself).
fn number_depth(value: &Value) -> Option<usize> {
    match value {
        Value::Number(_) => Some(0),
        // serde_json refuses to nest deeper than 128, so this recursion is bounded.
        Value::Array(items) => items.iter().find_map(number_depth).map(|d| d + 1),
        _ => None,
    }
}

fn json_kind(value: &Value) -> &'static str {
    match value {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// Adds a ring whose points may have z (`z[i]` for point `i`), dropping a repeated
/// closing point: the result JSON's vertices are the file's points with that one removed
/// (a ring of one point stays as it is). The closing point is one only where z repeats
/// too: a vertical wall's points repeat in x and y.
fn push_ring_z(
    polygon: &mut Polygon,
    zs: &mut Vec<Vec<Option<f64>>>,
    mut ring: Ring,
    mut z: Vec<Option<f64>>,
) {
    if ring.len() > 1 && ring.first() == ring.last() && z.first() == z.last() {
        ring.pop();
        z.pop();
    }
    polygon.push(ring);
    zs.push(z);
}

/// One polygon's z values, ring by ring: `None` when some point has no z.
fn polygon_z(z: Vec<Vec<Option<f64>>>) -> Option<Vec<Vec<f64>>> {
    z.into_iter()
        .map(|ring| ring.into_iter().collect())
        .collect()
}

// ---------------------------------------------------------------------------------------
// rings and shapes JSON

/// A JSON point `[x, y, …]`, with its z when a third coordinate is given; further
/// coordinates (m) are read and ignored.
///
/// Deserialized by hand rather than as `Vec<f64>` so a short point is refused inside
/// serde, which then reports the line and column.
struct JsonPoint([f64; 2], Option<f64>);

impl<'de> Deserialize<'de> for JsonPoint {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_seq(PointVisitor)
    }
}

struct PointVisitor;

impl<'de> Visitor<'de> for PointVisitor {
    type Value = JsonPoint;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a point [x, y]")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<JsonPoint, A::Error> {
        let x: f64 = seq
            .next_element()?
            .ok_or_else(|| de::Error::invalid_length(0, &self))?;
        let y: f64 = seq
            .next_element()?
            .ok_or_else(|| de::Error::invalid_length(1, &self))?;
        // a third coordinate that is a number is z; null or anything else is no z
        let z = (seq.next_element::<Value>()?).and_then(|v| v.as_f64());
        while seq.next_element::<IgnoredAny>()?.is_some() {}
        Ok(JsonPoint([x, y], z))
    }
}

type JsonRings = Vec<Vec<JsonPoint>>;

fn json_polygon(input: &mut Input, rings: JsonRings) {
    let mut polygon = Polygon::with_capacity(rings.len());
    let mut z = Vec::with_capacity(rings.len());
    for ring in rings {
        let ring_z = ring.iter().map(|p| p.1).collect();
        push_ring_z(
            &mut polygon,
            &mut z,
            ring.into_iter().map(|p| p.0).collect(),
            ring_z,
        );
    }
    input.z.push(polygon_z(z));
    input.polygons.push(polygon);
}

fn parse_rings(text: &str) -> Result<Input, String> {
    let rings: JsonRings =
        serde_json::from_str(text).map_err(|e| format!("invalid rings JSON: {e}"))?;
    let mut input = Input::new(Format::Rings);
    json_polygon(&mut input, rings);
    Ok(input)
}

fn parse_shapes(text: &str) -> Result<Input, String> {
    let shapes: Vec<JsonRings> =
        serde_json::from_str(text).map_err(|e| format!("invalid shapes JSON: {e}"))?;
    let mut input = Input::new(Format::Shapes);
    for rings in shapes {
        json_polygon(&mut input, rings);
    }
    Ok(input)
}

fn parse_case(text: &str) -> Result<Input, String> {
    #[derive(Deserialize)]
    struct Case {
        rings: JsonRings,
    }
    let case: Case =
        serde_json::from_str(text).map_err(|e| format!("invalid corpus case JSON: {e}"))?;
    let mut input = Input::new(Format::Case);
    json_polygon(&mut input, case.rings);
    Ok(input)
}

// ---------------------------------------------------------------------------------------
// GeoJSON

fn parse_geojson(text: &str) -> Result<Input, String> {
    let geojson: GeoJson =
        serde_json::from_str(text).map_err(|e| format!("invalid GeoJSON: {e}"))?;
    let mut input = Input::new(Format::GeoJson);
    match geojson {
        GeoJson::Geometry(geometry) => {
            input.features.push(Feature::default());
            geojson_geometry(&mut input, geometry.value)?;
        }
        GeoJson::Feature(feature) => geojson_feature(&mut input, feature)?,
        GeoJson::FeatureCollection(collection) => {
            for feature in collection.features {
                geojson_feature(&mut input, feature)?;
            }
        }
    }
    Ok(input)
}

fn geojson_feature(input: &mut Input, feature: geojson::Feature) -> Result<(), String> {
    match feature.geometry {
        Some(geometry) => {
            input.features.push(Feature {
                id: feature.id,
                properties: feature.properties,
            });
            geojson_geometry(input, geometry.value)
        }
        None => {
            input.skip("Feature without geometry");
            Ok(())
        }
    }
}

fn geojson_geometry(input: &mut Input, value: GeometryValue) -> Result<(), String> {
    match value {
        GeometryValue::Polygon { coordinates } => geojson_polygon(input, coordinates),
        GeometryValue::MultiPolygon { coordinates } => coordinates
            .into_iter()
            .try_for_each(|polygon| geojson_polygon(input, polygon)),
        GeometryValue::GeometryCollection { geometries } => {
            // Bounded recursion: the JSON parser refuses nesting deeper than 128.
            geometries
                .into_iter()
                .try_for_each(|g| geojson_geometry(input, g.value))
        }
        other => {
            input.skip(other.type_name());
            Ok(())
        }
    }
}

fn geojson_polygon(input: &mut Input, rings: geojson::PolygonType) -> Result<(), String> {
    let index = input.polygons.len();
    let mut polygon = Polygon::with_capacity(rings.len());
    let mut z = Vec::with_capacity(rings.len());
    for (r, ring) in rings.into_iter().enumerate() {
        let mut points = Ring::with_capacity(ring.len());
        let ring_z = ring.iter().map(|p| p.as_slice().get(2).copied()).collect();
        for (v, position) in ring.iter().enumerate() {
            match position.as_slice() {
                [x, y, ..] => points.push([*x, *y]),
                _ => {
                    return Err(format!(
                        "polygon {index}, ring {r}, position {v}: a position needs at least 2 coordinates"
                    ))
                }
            }
        }
        push_ring_z(&mut polygon, &mut z, points, ring_z);
    }
    input.z.push(polygon_z(z));
    input.polygons.push(polygon);
    // (every polygon is read within a feature, pushed before its geometry)
    input
        .polygon_feature
        .push(input.features.len().saturating_sub(1));
    Ok(())
}

// ---------------------------------------------------------------------------------------
// WKT

/// The WKT geometry keywords, longest first so `MULTIPOLYGON` is not read as `MULTIPOINT`.
const WKT_KEYWORDS: [&str; 8] = [
    "GEOMETRYCOLLECTION",
    "MULTILINESTRING",
    "MULTIPOLYGON",
    "MULTIPOINT",
    "LINESTRING",
    "LINEARRING",
    "POLYGON",
    "POINT",
];

/// Nesting deeper than this is refused before the `wkt` crate, whose recursive parser
/// would otherwise overflow the stack on hostile input.
const WKT_MAX_DEPTH: usize = 64;

fn starts_with_wkt_keyword(text: &str) -> bool {
    let text = strip_srid(text.trim_start());
    let word: String = text
        .chars()
        .take_while(char::is_ascii_alphabetic)
        .map(|c| c.to_ascii_uppercase())
        .collect();
    // `POLYGONZ` and friends are single words too.
    WKT_KEYWORDS.iter().any(|k| {
        word.strip_prefix(k)
            .is_some_and(|rest| ["", "Z", "M", "ZM"].contains(&rest))
    })
}

/// Drops PostGIS's EWKT prefix `SRID=4326;`: the reference system does not matter here.
fn strip_srid(text: &str) -> &str {
    let is_srid = text
        .get(..5)
        .is_some_and(|head| head.eq_ignore_ascii_case("SRID="));
    match text.find(';') {
        Some(end) if is_srid => text[end + 1..].trim_start(),
        _ => text,
    }
}

/// One top-level geometry of a WKT file, and the line and column (1-based) it starts at.
struct WktPiece<'a> {
    line: usize,
    column: usize,
    text: &'a str,
}

/// Splits WKT text into its top-level geometries, so a file may hold several (one per line
/// is common) and trailing text is not silently ignored, as the `wkt` crate would.
fn split_wkt(text: &str) -> Result<Vec<WktPiece<'_>>, String> {
    let mut pieces = Vec::new();
    let (mut line, mut column) = (1, 1);
    let mut start: Option<(usize, usize, usize)> = None; // byte offset, line, column
    let mut depth = 0usize;
    let mut word_start: Option<usize> = None;
    for (i, c) in text.char_indices() {
        if c.is_ascii_alphabetic() {
            word_start.get_or_insert(i);
        } else if let Some(w) = word_start.take() {
            // `POLYGON EMPTY` ends a geometry without parentheses.
            if depth == 0 && text[w..i].eq_ignore_ascii_case("EMPTY") {
                if let Some((s, line, column)) = start.take() {
                    pieces.push(WktPiece {
                        line,
                        column,
                        text: &text[s..i],
                    });
                }
            }
        }
        // Whitespace and separators between geometries belong to none of them; anything
        // else opens a piece, so stray text reaches the parser and is refused.
        if start.is_none() && depth == 0 && !c.is_whitespace() && !matches!(c, ';' | ',' | ')') {
            start = Some((i, line, column));
        }
        match c {
            '(' => {
                depth += 1;
                if depth > WKT_MAX_DEPTH {
                    return Err(format!(
                        "WKT nested deeper than {WKT_MAX_DEPTH} levels at line {line}"
                    ));
                }
            }
            ')' => {
                depth = depth.checked_sub(1).ok_or_else(|| {
                    format!("invalid WKT: unmatched ')' at line {line}, column {column}")
                })?;
                if depth == 0 {
                    if let Some((s, line, column)) = start.take() {
                        pieces.push(WktPiece {
                            line,
                            column,
                            text: &text[s..=i],
                        });
                    }
                }
            }
            _ => {}
        }
        if c == '\n' {
            line += 1;
            column = 1;
        } else {
            column += 1;
        }
    }
    if let Some(w) = word_start {
        if depth == 0 && text[w..].eq_ignore_ascii_case("EMPTY") {
            if let Some((s, line, column)) = start.take() {
                pieces.push(WktPiece {
                    line,
                    column,
                    text: &text[s..],
                });
            }
        }
    }
    if let Some((s, line, column)) = start {
        // Unterminated: let the parser say what is missing.
        pieces.push(WktPiece {
            line,
            column,
            text: &text[s..],
        });
    }
    Ok(pieces)
}

fn parse_wkt(text: &str) -> Result<Input, String> {
    let mut input = Input::new(Format::Wkt);
    for piece in split_wkt(text)? {
        let body = strip_srid(piece.text);
        let geometry = wkt::Wkt::<f64>::from_str(body).map_err(|e| {
            // The `wkt` crate says what it missed but not where; a word where a number
            // belongs (`nan`, `x`) is the common case and can be pinned down here.
            explain_wkt_error(&piece).unwrap_or_else(|| {
                let head: String = body.chars().take(24).collect();
                format!(
                    "invalid WKT in the geometry at line {} (`{head}…`): {e}",
                    piece.line
                )
            })
        })?;
        wkt_geometry(&mut input, &geometry);
    }
    Ok(input)
}

/// Finds the first word inside parentheses that is not a WKT keyword: in valid WKT only
/// numbers, keywords (in collections) and `Z`/`M`/`ZM`/`EMPTY` appear there.
fn explain_wkt_error(piece: &WktPiece<'_>) -> Option<String> {
    let (mut line, mut column, mut depth) = (piece.line, piece.column, 0usize);
    let mut chars = piece.text.char_indices().peekable();
    while let Some((i, c)) = chars.next() {
        match c {
            '(' => depth += 1,
            ')' => depth = depth.saturating_sub(1),
            _ if c.is_ascii_alphabetic() && depth > 0 => {
                let mut end = i + c.len_utf8();
                while let Some(&(j, next)) = chars.peek() {
                    if next.is_whitespace() || matches!(next, '(' | ')' | ',') {
                        break;
                    }
                    end = j + next.len_utf8();
                    chars.next();
                }
                let word = &piece.text[i..end];
                let upper = word.to_ascii_uppercase();
                let keyword = ["Z", "M", "ZM", "EMPTY"].contains(&upper.as_str())
                    || starts_with_wkt_keyword(word);
                if !keyword {
                    return Some(format!("invalid WKT at line {line}, column {column}: `{word}` where a number belongs"));
                }
                column += word.chars().count();
                continue;
            }
            _ => {}
        }
        if c == '\n' {
            line += 1;
            column = 1;
        } else {
            column += 1;
        }
    }
    None
}

fn wkt_geometry(input: &mut Input, geometry: &wkt::Wkt<f64>) {
    match geometry {
        wkt::Wkt::Polygon(polygon) => wkt_polygon(input, polygon),
        wkt::Wkt::MultiPolygon(multi) => {
            for polygon in multi.polygons() {
                wkt_polygon(input, polygon);
            }
        }
        wkt::Wkt::GeometryCollection(collection) => {
            // Bounded recursion: split_wkt refused nesting deeper than WKT_MAX_DEPTH.
            for g in collection.geometries() {
                wkt_geometry(input, g);
            }
        }
        wkt::Wkt::Point(_) => input.skip("Point"),
        wkt::Wkt::LineString(_) => input.skip("LineString"),
        wkt::Wkt::MultiPoint(_) => input.skip("MultiPoint"),
        wkt::Wkt::MultiLineString(_) => input.skip("MultiLineString"),
    }
}

fn wkt_polygon(input: &mut Input, polygon: &wkt::types::Polygon<f64>) {
    let mut rings = Polygon::with_capacity(polygon.rings().len());
    let mut z = Vec::with_capacity(polygon.rings().len());
    for ring in polygon.rings() {
        let points = ring.coords().iter().map(|c| [c.x, c.y]).collect();
        let ring_z = ring.coords().iter().map(|c| c.z).collect();
        push_ring_z(&mut rings, &mut z, points, ring_z);
    }
    input.z.push(polygon_z(z));
    input.polygons.push(rings);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(x: f64, y: f64, size: f64) -> Ring {
        vec![[x, y], [x + size, y], [x + size, y + size], [x, y + size]]
    }

    #[test]
    fn rings_json_is_one_polygon() {
        let input = parse(
            "[[[0,0],[10,0],[10,10],[0,10]],[[2,2],[2,4],[4,4],[4,2]]]",
            false,
        )
        .expect("valid rings");
        assert_eq!(input.format, Format::Rings);
        assert_eq!(input.polygons.len(), 1);
        assert_eq!(input.polygons[0].len(), 2);
        assert_eq!(input.polygons[0][0], square(0.0, 0.0, 10.0));
    }

    #[test]
    fn shapes_json_is_a_list_of_polygons() {
        let text = "[[[[0,0],[1,0],[1,1],[0,1]]], [[[5,5],[6,5],[6,6],[5,6]]]]";
        let input = parse(text, false).expect("valid shapes");
        assert_eq!(input.format, Format::Shapes);
        assert_eq!(
            input.polygons,
            vec![vec![square(0.0, 0.0, 1.0)], vec![square(5.0, 5.0, 1.0)]]
        );
    }

    #[test]
    fn shapes_are_recognised_behind_an_empty_polygon() {
        let input = parse("[[], [[[0,0],[1,0],[1,1]]]]", false).expect("valid shapes");
        assert_eq!(input.format, Format::Shapes);
        assert_eq!(input.polygons.len(), 2);
    }

    #[test]
    fn extra_coordinates_are_ignored() {
        let input = parse("[[[0,0,7],[1,0,7,8],[1,1,null]]]", false).expect("z and m ignored");
        assert_eq!(
            input.polygons[0][0],
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]
        );
    }

    #[test]
    fn closing_point_is_dropped() {
        let input = parse("[[[0,0],[1,0],[1,1],[0,0]]]", false).expect("valid rings");
        assert_eq!(
            input.polygons[0][0],
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]
        );
        // Only a repeat of the first point counts as closing.
        let input = parse("[[[0,0],[1,0],[1,1],[1,1]]]", false).expect("valid rings");
        assert_eq!(input.polygons[0][0].len(), 4);
    }

    #[test]
    fn json_errors_carry_line_and_column() {
        let err = parse("[[[0,0],\n[1,0],[1,1]", false).expect_err("truncated");
        assert!(err.contains("line 2"), "{err}");
        let err = parse("[[[0,0],\n[1,\"x\"],[1,1]]]", false).expect_err("string coordinate");
        assert!(err.contains("line 2 column"), "{err}");
        let err = parse("[[[0,0],[1],[1,1]]]", false).expect_err("short point");
        assert!(err.contains("column"), "{err}");
    }

    #[test]
    fn scalar_json_is_refused() {
        let err = parse("42", false).expect_err("not a polygon");
        assert!(err.contains("found a number"), "{err}");
        assert!(parse("", false).is_err());
    }

    #[test]
    fn geojson_polygon_and_multipolygon() {
        let text = r#"{"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4],[0,4],[0,0]],[[1,1],[1,2],[2,2],[1,1]]]}"#;
        let input = parse(text, false).expect("valid GeoJSON");
        assert_eq!(input.format, Format::GeoJson);
        assert_eq!(input.polygons[0][0], square(0.0, 0.0, 4.0));
        assert_eq!(input.polygons[0][1].len(), 3);

        let text = r#"{"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[1,1],[0,0]]],[[[5,5],[6,5],[6,6],[5,5]]]]}"#;
        assert_eq!(parse(text, false).expect("valid GeoJSON").polygons.len(), 2);
    }

    #[test]
    fn geojson_features_collections_and_skipped_types() {
        let text = r#"{"type":"FeatureCollection","features":[
            {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0,1],[1,0,1],[1,1,1]]]}},
            {"type":"Feature","properties":null,"geometry":null},
            {"type":"Feature","properties":{},"geometry":{"type":"GeometryCollection","geometries":[
                {"type":"Point","coordinates":[0,0]},
                {"type":"LineString","coordinates":[[0,0],[1,1]]},
                {"type":"Polygon","coordinates":[[[2,2],[3,2],[3,3]]]}]}}]}"#;
        let input = parse(text, false).expect("valid GeoJSON");
        assert_eq!(input.polygons.len(), 2);
        assert_eq!(
            input.polygons[0][0],
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]
        );
        assert_eq!(input.skipped.get("Point"), Some(&1));
        assert_eq!(input.skipped.get("LineString"), Some(&1));
        assert_eq!(input.skipped.get("Feature without geometry"), Some(&1));
    }

    #[test]
    fn geojson_with_a_string_coordinate_is_refused() {
        let text = r#"{"type":"Polygon","coordinates":[[[0,0],[1,"NaN"],[1,1]]]}"#;
        let err = parse(text, false).expect_err("string coordinate");
        assert!(err.starts_with("invalid GeoJSON"), "{err}");
    }

    #[test]
    fn wkt_polygon_multipolygon_and_collection() {
        let input = parse(
            "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 1 1))",
            false,
        )
        .expect("valid WKT");
        assert_eq!(input.format, Format::Wkt);
        assert_eq!(input.polygons[0][0], square(0.0, 0.0, 4.0));
        assert_eq!(input.polygons[0][1].len(), 3);

        let input = parse("multipolygon (((0 0, 1 0, 1 1)), ((5 5, 6 5, 6 6)))", false)
            .expect("lower case WKT");
        assert_eq!(input.polygons.len(), 2);

        let input = parse(
            "GEOMETRYCOLLECTION (POINT (1 2), POLYGON Z ((0 0 9, 1 0 9, 1 1 9, 0 0 9)), LINESTRING (0 0, 1 1))",
            false,
        )
        .expect("collection");
        assert_eq!(
            input.polygons,
            vec![vec![vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]]]
        );
        assert_eq!(input.skipped.len(), 2);
    }

    #[test]
    fn wkt_files_may_hold_several_geometries() {
        let text =
            "SRID=4326;POLYGON ((0 0, 1 0, 1 1))\nPOLYGON EMPTY\nPOLYGON ((5 5, 6 5, 6 6))\n";
        let input = parse(text, false).expect("three geometries");
        assert_eq!(input.polygons.len(), 3);
        assert!(input.polygons[1].is_empty());
    }

    #[test]
    fn wkt_errors_name_the_line() {
        let err = parse(
            "POLYGON ((0 0, 1 0, 1 1))\nPOLYGON ((0 0, nan 0, 1 1))",
            false,
        )
        .expect_err("nan is not a WKT number");
        assert!(
            err.contains("line 2, column 16: `nan` where a number belongs"),
            "{err}"
        );
        let err = parse("POLYGON ((0 0, 1 0, 1 1)", false).expect_err("unclosed");
        assert!(err.contains("geometry at line 1"), "{err}");
        let err = parse("POLYGON EMPTY; POLYGON ((0 0, 1 0, x 1))", false).expect_err("x");
        assert!(err.contains("line 1, column 36"), "{err}");
        assert!(parse("POLYGON ((0 0, 1 0, 1 1)) trailing", false).is_err());
        assert!(parse("POLYGON ((0 0, 1 0, 1 1)) (1 2)", false).is_err());
        assert!(parse("(0 0, 1 0, 1 1)", true).is_err());
        assert!(parse("POLYGON ((0 0, 1 0, 1 1)))", false).is_err());
        assert!(parse("POLYGON ((0 0, 1 0, 1 1)", false).is_err());
        let deep = format!("GEOMETRYCOLLECTION {}", "(".repeat(1000));
        assert!(parse(&deep, false).is_err());
    }

    #[test]
    fn corpus_cases_are_read_by_their_rings() {
        let text = r#"{"name": "two squares", "expect": {"triangles": 8},
            "rings": [[[0,0],[10,0],[10,10],[0,10]], [[3,3],[3,7],[7,7],[7,3]]]}"#;
        let input = parse(text, false).unwrap();
        assert_eq!(input.format, Format::Case);
        assert_eq!(input.polygons.len(), 1);
        assert_eq!(input.polygons[0].len(), 2);
        assert_eq!(input.polygons[0][1][3], [7.0, 3.0]);
        let err = parse(r#"{"rings": [[[0, "x"]]]}"#, false).unwrap_err();
        assert!(err.starts_with("invalid corpus case JSON"), "{err}");
    }

    #[test]
    fn format_is_detected_from_content_or_extension() {
        assert!(starts_with_wkt_keyword("  polygon((0 0, 1 0, 1 1))"));
        assert!(starts_with_wkt_keyword("POLYGONZ((0 0 0, 1 0 0, 1 1 0))"));
        assert!(starts_with_wkt_keyword("SRID=3857; MULTIPOLYGON EMPTY"));
        assert!(!starts_with_wkt_keyword("[[[0, 0]]]"));
        assert!(!starts_with_wkt_keyword("POLYGONAL"));
        assert!(has_wkt_extension(Path::new("a/b.WKT")));
        assert!(!has_wkt_extension(Path::new("a/b.json")));
        // With the extension, text that is not WKT is a WKT error, not a JSON one.
        let err = parse("[[[0,0],[1,0],[1,1]]]", true).expect_err("not WKT");
        assert!(err.contains("WKT"), "{err}");
    }
}
