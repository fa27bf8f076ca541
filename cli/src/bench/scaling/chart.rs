//! The scaling plot: median time against vertices on log-log axes, a line per
//! implementation, drawn with `plotters`' SVG backend.

use plotters::prelude::*;

/// The growth the speed goal allows (README, "Speed"): drawn as a dashed reference line.
const GOAL_EXPONENT: f64 = 1.15;

/// One implementation's measurements.
#[derive(Debug, Clone)]
pub(super) struct Line {
    /// The legend entry.
    pub name: String,
    /// The implementation's name, which picks its colour.
    pub implementation: String,
    /// `(vertices, milliseconds)`, ascending in vertices.
    pub points: Vec<(f64, f64)>,
}

/// The colour and stroke width of an implementation's line: polytri's in blues and greens,
/// drawn thicker, the peers' in warm colours; stable whichever subset is plotted.
fn style(implementation: &str) -> ShapeStyle {
    let (color, width) = match implementation {
        "polytri-fast" => (RGBColor(31, 119, 180), 3),
        "polytri-lenient" => (RGBColor(23, 190, 207), 2),
        "polytri-quality" => (RGBColor(44, 160, 44), 3),
        "polytri-check" => (RGBColor(127, 127, 127), 2),
        "earcut" => (RGBColor(214, 39, 40), 2),
        "earcutr" => (RGBColor(255, 127, 14), 2),
        "i-triangle" => (RGBColor(148, 103, 189), 2),
        "lyon" => (RGBColor(140, 86, 75), 2),
        "spade" => (RGBColor(227, 119, 194), 2),
        _ => (RGBColor(188, 189, 34), 2),
    };
    ShapeStyle::from(&color).stroke_width(width)
}

/// Draws `lines` under `title` as a standalone SVG document.
///
/// # Errors
///
/// plotters' drawing error as text, or a message when no line has a point.
pub(super) fn draw(title: &str, lines: &[Line]) -> Result<String, String> {
    let mut svg = String::new();
    draw_into(&mut svg, title, lines).map_err(|e| format!("drawing the plot '{title}': {e}"))?;
    Ok(svg)
}

/// The smallest and largest of `values`, widened by `factor` each way (a log axis needs
/// room around its extreme points); `None` when empty.
fn log_range(values: impl Iterator<Item = f64>, factor: f64) -> Option<(f64, f64)> {
    let (lo, hi) = values
        .filter(|v| *v > 0.0 && v.is_finite())
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    (lo <= hi).then(|| (lo / factor, hi * factor))
}

/// A tick label: powers of ten as 10ⁿ, other values with up to three significant digits.
fn tick(x: f64) -> String {
    let exponent = x.log10().round();
    if (x / 10f64.powf(exponent) - 1.0).abs() < 1e-9 && exponent.abs() >= 3.0 {
        let superscript: String = format!("{}", exponent as i64)
            .chars()
            .map(|c| match c {
                '-' => '⁻',
                d => ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'][d as usize - '0' as usize],
            })
            .collect();
        format!("10{superscript}")
    } else {
        let text = format!("{x:.3}");
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    }
}

fn draw_into(
    svg: &mut String,
    title: &str,
    lines: &[Line],
) -> Result<(), Box<dyn std::error::Error>> {
    let all = || lines.iter().flat_map(|l| l.points.iter().copied());
    let ((x_lo, x_hi), (y_lo, y_hi)) = log_range(all().map(|p| p.0), 1.3)
        .zip(log_range(all().map(|p| p.1), 2.0))
        .ok_or("no measurements to plot")?;
    let root = SVGBackend::with_string(svg, (820, 540)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut ctx = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 17))
        .margin(14)
        .x_label_area_size(44)
        .y_label_area_size(64)
        .build_cartesian_2d((x_lo..x_hi).log_scale(), (y_lo..y_hi).log_scale())?;
    ctx.configure_mesh()
        .x_desc("vertices")
        .y_desc("median time per run (ms)")
        .x_label_formatter(&|x| tick(*x))
        .y_label_formatter(&|y| tick(*y))
        .light_line_style(WHITE.mix(0.0))
        .draw()?;
    for line in lines.iter().filter(|l| !l.points.is_empty()) {
        let style = style(&line.implementation);
        ctx.draw_series(LineSeries::new(line.points.clone(), style))?
            .label(line.name.as_str())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], style));
        let dot = ShapeStyle::from(&style.color).filled();
        ctx.draw_series(line.points.iter().map(|&p| Circle::new(p, 3, dot)))?;
    }
    if let Some(reference) = goal_line(lines, x_hi / 1.3) {
        let grey = ShapeStyle::from(&BLACK.mix(0.45)).stroke_width(1);
        ctx.draw_series(DashedLineSeries::new(reference, 6, 4, grey))?
            .label(format!(
                "n^{GOAL_EXPONENT} from polytri-fast's first point (goal)"
            ))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], grey));
    }
    ctx.configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.4))
        .position(SeriesLabelPosition::LowerRight)
        .label_font(("sans-serif", 12))
        .draw()?;
    root.present()?;
    Ok(())
}

/// The goal's growth, `time ∝ n^1.15`, from polytri-fast's smallest size (or the first
/// line's) to `x_end`.
fn goal_line(lines: &[Line], x_end: f64) -> Option<Vec<(f64, f64)>> {
    let start = lines
        .iter()
        .find(|l| l.implementation == "polytri-fast" && !l.points.is_empty())
        .or_else(|| lines.iter().find(|l| !l.points.is_empty()))?
        .points[0];
    (x_end > start.0).then(|| {
        vec![
            start,
            (x_end, start.1 * (x_end / start.0).powf(GOAL_EXPONENT)),
        ]
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plot_is_an_svg_with_its_legend_and_axes() {
        let line = |implementation: &str, factor: f64| Line {
            name: format!("{implementation} (n^1.00)"),
            implementation: implementation.to_owned(),
            points: vec![
                (1e3, 0.1 * factor),
                (1e4, 1.0 * factor),
                (1e5, 10.0 * factor),
            ],
        };
        let svg =
            draw("circles", &[line("polytri-fast", 1.0), line("earcut", 3.0)]).expect("draws");
        assert!(svg.starts_with("<svg"), "{}", &svg[..80]);
        for text in [
            "polytri-fast (n^1.00)",
            "earcut (n^1.00)",
            "vertices",
            "10⁴",
            "(goal)",
        ] {
            assert!(svg.contains(text), "no {text:?} in the plot");
        }
        assert!(draw("empty", &[]).is_err());
    }

    #[test]
    fn ticks_read_as_powers_of_ten() {
        assert_eq!(tick(1e6), "10⁶");
        assert_eq!(tick(1e-3), "10⁻³");
        assert_eq!(tick(10.0), "10");
        assert_eq!(tick(0.25), "0.25");
    }
}
