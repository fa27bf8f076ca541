//! Line charts as SVG strings, drawn with `plotters`' SVG backend.

use plotters::prelude::*;

/// One line of a chart.
#[derive(Debug, Clone)]
pub struct Series {
    /// The legend entry.
    pub name: String,
    /// The line's colour.
    pub color: RGBColor,
    /// Dashed (used for f64) instead of solid.
    pub dashed: bool,
    /// `(decade, percent)` points, ascending in decade.
    pub points: Vec<(i32, f64)>,
}

/// What a chart shows.
#[derive(Debug, Clone)]
pub struct Chart {
    /// The caption above the plot.
    pub title: String,
    /// The x axis's label.
    pub x_desc: String,
    /// The y axis's label.
    pub y_desc: String,
    /// The x range, in decades, inclusive.
    pub x_range: (i32, i32),
    /// An x value drawn as "0" instead of a power of ten (offset 0), if any.
    pub zero_at: Option<i32>,
    /// The lines.
    pub series: Vec<Series>,
}

/// The colour of a subject's lines, by position in `Subject::ALL`; the last one for extra
/// lines (such as "input broken by rounding").
pub fn palette(k: usize) -> RGBColor {
    const COLORS: [RGBColor; 5] = [
        RGBColor(31, 119, 180),
        RGBColor(44, 160, 44),
        RGBColor(214, 39, 40),
        RGBColor(148, 103, 189),
        RGBColor(90, 90, 90),
    ];
    COLORS[k.min(COLORS.len() - 1)]
}

/// Draws `chart` as a standalone SVG document.
///
/// # Errors
///
/// plotters' drawing error as text (only possible for a degenerate range).
pub fn draw(chart: &Chart) -> Result<String, String> {
    let mut svg = String::new();
    draw_into(&mut svg, chart).map_err(|e| format!("drawing chart '{}': {e}", chart.title))?;
    Ok(svg)
}

fn draw_into(svg: &mut String, chart: &Chart) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::with_string(svg, (820, 460)).into_drawing_area();
    root.fill(&WHITE)?;
    let (lo, hi) = chart.x_range;
    let mut ctx = ChartBuilder::on(&root)
        .caption(&chart.title, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(56)
        .build_cartesian_2d(lo..hi.max(lo + 1), -2f64..102f64)?;
    let zero_at = chart.zero_at;
    let label = move |x: &i32| {
        if Some(*x) == zero_at {
            "0".to_owned()
        } else {
            format!("1e{x}")
        }
    };
    ctx.configure_mesh()
        .x_desc(chart.x_desc.as_str())
        .y_desc(chart.y_desc.as_str())
        .x_labels((hi - lo + 1).clamp(2, 20) as usize)
        .x_label_formatter(&label)
        .y_labels(11)
        .light_line_style(WHITE.mix(0.0))
        .draw()?;
    for series in &chart.series {
        let style = ShapeStyle::from(&series.color).stroke_width(2);
        let points = series.points.clone();
        let legend_style = style;
        if series.dashed {
            ctx.draw_series(DashedLineSeries::new(points.clone(), 6, 4, style))?
                .label(series.name.as_str())
                .legend(move |(x, y)| {
                    EmptyElement::at((x, y))
                        + PathElement::new(vec![(0, 0), (6, 0)], legend_style)
                        + PathElement::new(vec![(11, 0), (18, 0)], legend_style)
                });
        } else {
            ctx.draw_series(LineSeries::new(points.clone(), style))?
                .label(series.name.as_str())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], legend_style));
        }
        let dot = ShapeStyle::from(&series.color).filled();
        ctx.draw_series(points.into_iter().map(|p| Circle::new(p, 3, dot)))?;
    }
    ctx.configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.4))
        .position(SeriesLabelPosition::UpperLeft)
        .label_font(("sans-serif", 12))
        .draw()?;
    root.present()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chart_is_an_svg_with_its_legend() {
        let chart = Chart {
            title: "failures".into(),
            x_desc: "offset / scale".into(),
            y_desc: "%".into(),
            x_range: (-1, 3),
            zero_at: Some(-1),
            series: vec![
                Series {
                    name: "polytri f32".into(),
                    color: palette(0),
                    dashed: false,
                    points: vec![(-1, 0.0), (3, 50.0)],
                },
                Series {
                    name: "earcut f64".into(),
                    color: palette(2),
                    dashed: true,
                    points: vec![(0, 10.0)],
                },
            ],
        };
        let svg = draw(&chart).expect("draws");
        assert!(svg.contains("<svg"));
        assert!(svg.contains("polytri f32"));
        assert!(svg.contains("earcut f64"));
        assert!(svg.contains(">1e3<") || svg.contains("1e3"));
    }
}
