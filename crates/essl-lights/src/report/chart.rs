//! The chart: RMS error against milliseconds per frame, log–log, one labelled point per
//! variant, coloured by group, the Pareto front drawn as a staircase and its points ringed;
//! each specialised/uber pair joined by a thin line (same picture, different cost). Emulated
//! variants (a `mediump` error from the CPU's binary16 emulation beside lavapipe's 32-bit time)
//! are hollow triangles with their own legend entry, and are never on the front.

use plotters::prelude::*;

use super::{Group, ProgramKind, Report};
use crate::error::LightsError;

fn colour(g: Group) -> RGBColor {
    match g {
        Group::Shading => RGBColor(31, 119, 180),
        Group::SmallSpot => RGBColor(214, 39, 40),
        Group::Edge => RGBColor(255, 127, 14),
        Group::Precision => RGBColor(148, 103, 189),
        Group::Projector => RGBColor(44, 160, 44),
        Group::Program => RGBColor(127, 127, 127),
    }
}

/// The smallest RMS the log axis shows (a perfect variant sits on the axis).
const RMS_FLOOR: f64 = 0.02;

/// An emulated variant's marker: a hollow triangle centred on the point, in pixels.
fn triangle(cx: i32, cy: i32) -> Vec<(i32, i32)> {
    vec![
        (cx, cy - 7),
        (cx + 6, cy + 4),
        (cx - 6, cy + 4),
        (cx, cy - 7),
    ]
}

fn plot_err<E: std::fmt::Display>(e: E) -> LightsError {
    LightsError::Io {
        path: "report.svg".into(),
        message: e.to_string(),
    }
}

/// A point of the chart: milliseconds per frame, RMS error (floored), the variant.
type Point<'r> = (f64, f64, &'r super::VariantResult);

/// The chart's drawing context: log–log axes on an SVG string.
type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<LogCoord<f64>, LogCoord<f64>>>;

/// The range of the points: (x0, x1, y0, y1), a default when there are none.
fn bounds(pts: &[Point]) -> (f64, f64, f64, f64) {
    if pts.is_empty() {
        return (0.1, 10.0, RMS_FLOOR, 10.0);
    }
    let (mut x0, mut x1) = (f64::INFINITY, 0.0f64);
    let (mut y0, mut y1) = (f64::INFINITY, 0.0f64);
    for &(x, y, _) in pts {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    (x0, x1, y0, y1)
}

/// Joins each specialised/uber pair: same picture, different cost.
fn draw_pairs(chart: &mut Chart, report: &Report, size: u32) -> Result<(), LightsError> {
    for w in report.results.windows(2) {
        if w[0].variant.program == ProgramKind::Specialised
            && w[1].variant.program == ProgramKind::Uber
            && w[0].variant.lit == w[1].variant.lit
        {
            let a = (w[0].ms(size), w[0].error.rms.max(RMS_FLOOR));
            let b = (w[1].ms(size), w[1].error.rms.max(RMS_FLOOR));
            if let ((Some(ax), ay), (Some(bx), by)) = (a, b) {
                chart
                    .draw_series(LineSeries::new(
                        [(ax, ay), (bx, by)],
                        RGBColor(190, 190, 190).stroke_width(1),
                    ))
                    .map_err(plot_err)?;
            }
        }
    }
    Ok(())
}

/// The Pareto front: a staircase through the non-dominated points (to `x_end`), and a ring
/// around each of them.
fn draw_front(chart: &mut Chart, pts: &[Point], x_end: f64) -> Result<(), LightsError> {
    let mut front: Vec<(f64, f64)> = pts
        .iter()
        .filter(|p| p.2.pareto)
        .map(|p| (p.0, p.1))
        .collect();
    front.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut stairs = Vec::new();
    for (i, &(x, y)) in front.iter().enumerate() {
        if i > 0 {
            stairs.push((x, front[i - 1].1));
        }
        stairs.push((x, y));
    }
    if let Some(&(_, y)) = front.last() {
        stairs.push((x_end, y));
    }
    chart
        .draw_series(DashedLineSeries::new(stairs, 6, 4, BLACK.stroke_width(2)))
        .map_err(plot_err)?
        .label("Pareto front (ringed points)")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2)));
    chart
        .draw_series(
            pts.iter()
                .filter(|p| p.2.pareto)
                .map(|p| Circle::new((p.0, p.1), 9, BLACK.stroke_width(2))),
        )
        .map_err(plot_err)?;
    Ok(())
}

/// The points, labelled: a filled dot per measured variant, one legend entry per group, and
/// a hollow triangle per emulated variant.
fn draw_points(
    chart: &mut Chart,
    pts: &[Point],
    offsets: &[(i32, i32)],
) -> Result<(), LightsError> {
    for g in Group::ALL {
        let c = colour(g);
        let members: Vec<_> = pts
            .iter()
            .zip(offsets)
            .filter(|(p, _)| p.2.variant.group == g && !p.2.emulated())
            .collect();
        if members.is_empty() {
            continue;
        }
        chart
            .draw_series(members.iter().map(|(p, o)| {
                EmptyElement::at((p.0, p.1))
                    + Circle::new((0, 0), 5, c.filled())
                    + Text::new(
                        p.2.variant.label.clone(),
                        **o,
                        ("sans-serif", 12).into_font().color(&c),
                    )
            }))
            .map_err(plot_err)?
            .label(g.title())
            .legend(move |(x, y)| Circle::new((x + 10, y), 5, c.filled()));
    }
    let emulated: Vec<_> = pts
        .iter()
        .zip(offsets)
        .filter(|(p, _)| p.2.emulated())
        .collect();
    if !emulated.is_empty() {
        let grey = RGBColor(90, 90, 90);
        chart
            .draw_series(emulated.iter().map(|(p, o)| {
                let c = colour(p.2.variant.group);
                EmptyElement::at((p.0, p.1))
                    + PathElement::new(triangle(0, 0), c.stroke_width(2))
                    + Text::new(
                        p.2.variant.label.clone(),
                        **o,
                        ("sans-serif", 12).into_font().color(&c),
                    )
            }))
            .map_err(plot_err)?
            .label("emulated: binary16 error, fp32 lavapipe time (off the front)")
            .legend(move |(x, y)| PathElement::new(triangle(x + 10, y), grey.stroke_width(2)));
    }
    Ok(())
}

/// The chart as SVG text.
pub fn svg(report: &Report) -> Result<String, LightsError> {
    let size = report
        .settings
        .time_sizes
        .iter()
        .copied()
        .max()
        .unwrap_or(256);
    let pts: Vec<Point> = report
        .results
        .iter()
        .filter_map(|r| Some((r.ms(size)?, r.error.rms.max(RMS_FLOOR), r)))
        .filter(|p| p.0.is_finite() && p.0 > 0.0)
        .collect();
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, (1280, 860)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let (x0, x1, y0, y1) = bounds(&pts);
        let caption = format!(
            "RMS error against time per frame at {size}² — essl-gl on {}",
            report.machine.renderer
        );
        let mut chart = ChartBuilder::on(&root)
            .caption(caption, ("sans-serif", 20))
            .margin(24)
            .x_label_area_size(56)
            .y_label_area_size(72)
            .build_cartesian_2d(
                (x0 / 1.3..x1 * 1.6).log_scale(),
                (y0 / 1.6..y1 * 2.0).log_scale(),
            )
            .map_err(plot_err)?;
        chart
            .configure_mesh()
            .x_desc(format!(
                "ms per frame at {size}² (median of rounds; clear + draw + 1-pixel readPixels; log scale)"
            ))
            .y_desc("RMS error vs float64 reference, 1/255 units (log scale)")
            .axis_desc_style(("sans-serif", 15))
            .label_style(("sans-serif", 13))
            .light_line_style(RGBColor(235, 235, 235))
            .draw()
            .map_err(plot_err)?;
        draw_pairs(&mut chart, report, size)?;
        draw_front(&mut chart, &pts, x1 * 1.6)?;
        // Labels placed greedily where they overlap no earlier label (estimated text boxes).
        let offsets = place_labels(&pts, |x, y| chart.backend_coord(&(x, y)));
        draw_points(&mut chart, &pts, &offsets)?;
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .label_font(("sans-serif", 13))
            .background_style(WHITE.mix(0.9))
            .border_style(RGBColor(160, 160, 160))
            .draw()
            .map_err(plot_err)?;
        root.present().map_err(plot_err)?;
    }
    Ok(out)
}

/// The label offset of each point (pixels from the point to the text's top left): the first of
/// a few candidate positions whose estimated box overlaps no label placed before and no other
/// point's marker.
fn place_labels(
    pts: &[(f64, f64, &super::VariantResult)],
    to_px: impl Fn(f64, f64) -> (i32, i32),
) -> Vec<(i32, i32)> {
    const H: i32 = 13;
    let px: Vec<(i32, i32)> = pts.iter().map(|p| to_px(p.0, p.1)).collect();
    let mut boxes: Vec<(i32, i32, i32, i32)> = Vec::new();
    let mut out = Vec::with_capacity(pts.len());
    for (i, p) in pts.iter().enumerate() {
        let w = (p.2.variant.label.chars().count() as f64 * 6.6).ceil() as i32;
        let candidates = [
            (7, -15),
            (7, 3),
            (-w - 7, -15),
            (-w - 7, 3),
            (7, -29),
            (7, 17),
            (-w / 2, -31),
            (-w / 2, 11),
            (7, -43),
            (7, 31),
        ];
        let (cx, cy) = px[i];
        let free = |o: &(i32, i32)| {
            let b = (cx + o.0, cy + o.1, cx + o.0 + w, cy + o.1 + H);
            let overlaps_label = boxes
                .iter()
                .any(|q| b.0 < q.2 && q.0 < b.2 && b.1 < q.3 && q.1 < b.3);
            let overlaps_point = px.iter().enumerate().any(|(j, &(x, y))| {
                j != i && b.0 < x + 5 && x - 5 < b.2 && b.1 < y + 5 && y - 5 < b.3
            });
            !overlaps_label && !overlaps_point
        };
        let o = candidates
            .iter()
            .copied()
            .find(free)
            .unwrap_or(candidates[0]);
        boxes.push((cx + o.0, cy + o.1, cx + o.0 + w, cy + o.1 + H));
        out.push(o);
    }
    out
}
