#!/usr/bin/env python3
"""How far polytri's even-odd triangles are from shapely's reading of invalid polygons.

For every polygon of a GeoJSON layer (each Polygon, each member of a MultiPolygon), polytri
triangulates it with `--fill-rule even-odd`, and the union of its triangles is compared
with `shapely.make_valid` of the polygon (GEOS's "linework" method, which reads the rings
by the even-odd rule). Printed: the polygons, how many shapely calls invalid, and the area
of the symmetric difference over the layer's area — in total and for the invalid polygons
alone — for `--fill-rule even-odd` and, for comparison, `--lenient`.

    pip install shapely
    cargo build --release
    python3 docs/gis/even_odd_check.py LAYER.geojson [--polytri target/release/polytri]
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile

try:
    import shapely
    from shapely.geometry import shape
    from shapely.ops import unary_union
except ImportError:
    sys.exit("needs shapely: pip install shapely")


def polygons(layer):
    """Every polygon of the layer as (name, GeoJSON Polygon geometry)."""
    out = []
    for i, feature in enumerate(layer["features"]):
        geometry = feature.get("geometry")
        if not geometry:
            continue
        name = str(feature.get("id", i))
        if geometry["type"] == "Polygon":
            out.append((name, geometry))
        elif geometry["type"] == "MultiPolygon":
            for k, rings in enumerate(geometry["coordinates"]):
                out.append((f"{name}#{k}", {"type": "Polygon", "coordinates": rings}))
    return out


def triangulate(polytri, polys, flags):
    """polytri's triangles per polygon, as shapely geometries (None where there are none)."""
    with tempfile.TemporaryDirectory() as tmp:
        src = os.path.join(tmp, "in.geojson")
        dst = os.path.join(tmp, "out.geojson")
        features = [
            {"type": "Feature", "id": k, "properties": {}, "geometry": g}
            for k, (_, g) in enumerate(polys)
        ]
        with open(src, "w") as f:
            json.dump({"type": "FeatureCollection", "features": features}, f)
        run = subprocess.run(
            [polytri, "triangulate", src, "-o", dst, "--keep-going", *flags],
            capture_output=True,
            text=True,
        )
        if not os.path.exists(dst):
            sys.exit(f"polytri wrote nothing: {run.stderr}")
        with open(dst) as f:
            result = json.load(f)
    got = [None] * len(polys)
    for feature in result["features"]:
        k = feature.get("id")
        if isinstance(k, int) and 0 <= k < len(polys) and feature.get("geometry"):
            got[k] = shape(feature["geometry"])
    return got


def compare(polys, got):
    total = diff = bad_total = bad_diff = 0.0
    failed = 0
    for (_, g), tri in zip(polys, got):
        raw = shape(g)
        valid = shapely.make_valid(raw)
        area = valid.area
        if tri is None:
            # no triangles: right only where the polygon has no area
            failed += area > 0
            d = area
        else:
            d = unary_union(list(getattr(tri, "geoms", [tri]))).symmetric_difference(valid).area
        total += area
        diff += d
        if not raw.is_valid:
            bad_total += area
            bad_diff += d
    return diff / total if total else 0.0, bad_diff / bad_total if bad_total else 0.0, failed


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("layer")
    ap.add_argument("--polytri", default="target/release/polytri")
    args = ap.parse_args()
    with open(args.layer) as f:
        polys = polygons(json.load(f))
    invalid = sum(not shape(g).is_valid for _, g in polys)
    print(f"{args.layer}: {len(polys)} polygons, {invalid} invalid by shapely")
    print("| polytri | symmetric difference / area | on the invalid polygons | polygons with area but no triangles |")
    print("|---|--:|--:|--:|")
    for label, flags in [("--fill-rule even-odd", ["--fill-rule", "even-odd"]), ("--lenient", ["--lenient"])]:
        whole, bad, failed = compare(polys, triangulate(args.polytri, polys, flags))
        print(f"| `{label}` | {whole:.2e} | {bad:.2e} | {failed} |")


if __name__ == "__main__":
    main()
