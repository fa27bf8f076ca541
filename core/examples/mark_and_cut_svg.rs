//! Draws which thread marked which ear when mark-and-cut clips one polygon:
//! `cargo run --release -p polytri --features threads --example mark_and_cut_svg --`
//! `RINGS.json OUT.svg [CHUNK]`
//!
//! The polygon (a rings JSON file: its first ring outer, the rest holes) is clipped on two
//! threads with mark-and-cut lowered to start at once, in chunks of CHUNK nodes (default
//! 256), so that a small polygon shows several chunks. Triangles are coloured by the pool
//! thread that marked their ear (blue, orange), lighter in later rounds; grey ones were cut
//! by the sequential walk that finishes.

use std::fmt::Write as _;

use polytri::{Nesting, Options, Triangulator};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let (Some(input), Some(output)) = (args.get(1), args.get(2)) else {
        return Err("usage: mark_and_cut_svg RINGS.json OUT.svg [CHUNK]".into());
    };
    let chunk: usize = args.get(3).map_or(Ok(256), |c| c.parse())?;
    let rings: Vec<Vec<[f64; 2]>> = serde_json::from_str(&std::fs::read_to_string(input)?)?;
    let (mut vertices, mut starts) = (Vec::new(), Vec::new());
    for ring in &rings {
        starts.push(vertices.len());
        vertices.extend_from_slice(ring);
    }
    let mut tri = Triangulator::<f64>::new();
    tri.set_mark_and_cut(0, chunk);
    let options = Options::new()
        .with_nesting(Nesting::FirstIsOuter)
        .with_threads(2);
    let mut out = Vec::new();
    // a few calls first, so that both threads are awake and share the chunks (on a first
    // call to a small polygon, the thread that takes the round's work often marks every
    // chunk before the other wakes)
    for _ in 0..20 {
        tri.triangulate(&vertices, &starts, &options, &mut out)?;
    }
    let log = tri.mark_and_cut_log().to_vec();
    if log.is_empty() {
        return Err("no mark-and-cut round ran (is the `threads` feature on?)".into());
    }
    let rounds = log.iter().map(|e| e[3]).max().unwrap_or(0) + 1;

    // each triangle's colour: by the thread that marked it, lighter in later rounds
    let mut colour = vec![String::from("#d0d0d0"); out.len()];
    for &[first, end, thread, round] in &log {
        let hue = if thread % 2 == 0 { 210 } else { 30 };
        let light = 35 + 30 * round / rounds.max(1);
        for c in &mut colour[first as usize..end as usize] {
            *c = format!("hsl({hue},75%,{light}%)");
        }
    }

    let (mut x0, mut y0, mut x1, mut y1) = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
    for &[x, y] in &vertices {
        (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
    }
    let size = 1200.0;
    let scale = size / (x1 - x0).max(y1 - y0).max(f64::MIN_POSITIVE);
    let at = |v: u32| {
        let [x, y] = vertices[v as usize];
        ((x - x0) * scale, (y1 - y) * scale)
    };
    let (w, h) = ((x1 - x0) * scale, (y1 - y0) * scale);
    let mut svg = String::new();
    writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="-4 -32 {:.0} {:.0}" width="{:.0}" height="{:.0}">"#,
        w + 8.0,
        h + 36.0,
        w + 8.0,
        h + 36.0
    )?;
    writeln!(
        svg,
        r#"<text x="0" y="-8" font-family="sans-serif" font-size="20">{} triangles; ears marked by thread 0 (blue) and 1 (orange) in {rounds} rounds, lighter later; grey: the sequential walk</text>"#,
        out.len()
    )?;
    // one path per colour, a closed sub-path per triangle
    let mut paths: Vec<(&String, String)> = Vec::new();
    for (t, c) in out.iter().zip(&colour) {
        let [a, b, d] = t.map(at);
        let k = match paths.iter().position(|(pc, _)| *pc == c) {
            Some(k) => k,
            None => {
                paths.push((c, String::new()));
                paths.len() - 1
            }
        };
        write!(
            paths[k].1,
            "M{:.0} {:.0}L{:.0} {:.0}L{:.0} {:.0}Z",
            a.0, a.1, b.0, b.1, d.0, d.1
        )?;
    }
    for (c, d) in &paths {
        writeln!(svg, r#"<path fill="{c}" d="{d}"/>"#)?;
    }
    svg.push_str("</svg>\n");
    std::fs::write(output, svg)?;
    eprintln!(
        "{output}: {} triangles, {} of them marked in {rounds} rounds",
        out.len(),
        log.iter().map(|e| e[1] - e[0]).sum::<u32>()
    );
    Ok(())
}
