//! Pictures of one aero2d run, as a PNG: the wake and the section at the
//! last time (equal scales in x and y, chords), and below it the force
//! histories against time (chords travelled): CL and CT together, CP alone.
//!
//! Non-finite values (NaN, infinities) and absurd ones (beyond `1e12`) are
//! skipped; empty inputs give empty axes with a default range.

use std::ops::Range;
use std::path::Path;

use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

use crate::aero2d::ldvm::{FreeVortex, History};

use super::drawing::{DrawingError, FONT};

/// Picture size, pixels.
const SIZE: (u32, u32) = (1200, 1350);
/// Height of the wake panel, pixels (the two history panels share the rest).
const WAKE_HEIGHT: u32 = 550;
/// Dot radius range for the free vortices, pixels.
const DOT_RADIUS: (f64, f64) = (1.5, 8.0);
/// At most this many whole-period marks are drawn.
const MAX_PERIOD_MARKS: f64 = 2000.0;
/// Colour of the whole-period marks.
const PERIOD_MARK: RGBColor = RGBColor(140, 140, 140);

type Panel<'a> = DrawingArea<BitMapBackend<'a>, Shift>;
type Chart<'a> = ChartContext<'a, BitMapBackend<'a>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Draws one run to `png` (overwritten).
///
/// - `history`: the time histories of the run; `cl`, `ct`, `cp` are plotted
///   against `time` (chords travelled), pairs beyond the shorter vector are
///   ignored and non-finite points (or beyond `1e12`) leave gaps.
/// - `wake`: the free vortices at the last time (chords), drawn as dots, red
///   for counter-clockwise (`gamma > 0`), blue for clockwise, with a radius
///   growing as `sqrt(|gamma|)` (relative to the 90th percentile of
///   `|gamma|`, clamped to 1.5–8 pixels).
/// - `body`: the section's points at the last time (chords), drawn as a
///   black line; may be empty.
/// - `period`: the motion's period in chords travelled (`pi / k` for the
///   reduced frequency `k = omega c / (2U)`); whole periods are marked with
///   light vertical lines. `None` (or a non-positive or non-finite value)
///   draws no marks.
///
/// Errors (font, file or backend) come back as [`DrawingError`]; nothing
/// panics on empty or non-finite inputs.
pub fn draw(
    history: &History,
    wake: &[FreeVortex],
    body: &[(f64, f64)],
    period: Option<f64>,
    png: &Path,
) -> Result<(), DrawingError> {
    let root = BitMapBackend::new(png, SIZE).into_drawing_area();
    root.fill(&WHITE)?;
    let (top, bottom) = root.split_vertically(WAKE_HEIGHT);
    draw_wake(&top, wake, body)?;
    let panels = bottom.split_evenly((2, 1));
    let forces = [
        ("CL (lift, up)", &history.cl[..], RED),
        ("CT (thrust, upstream)", &history.ct[..], BLUE),
    ];
    let caption = "Lift and thrust coefficients (on 1/2 rho U^2 c)";
    let time = &history.time;
    draw_history(&panels[0], caption, "CL, CT", time, &forces, period)?;
    let power = [("CP (input power)", &history.cp[..], MAGENTA)];
    let caption = "Input power coefficient (on 1/2 rho U^3 c)";
    draw_history(&panels[1], caption, "CP", time, &power, period)?;
    root.present()?;
    Ok(())
}

/// Whether `v` is drawn: finite and not absurdly large (which would
/// overflow the axis arithmetic).
fn shown(v: f64) -> bool {
    v.abs() <= 1e12
}

/// The range of the shown values of `values`, widened by `pad` of its span
/// on each side; `default` when there are none, widened when degenerate.
fn padded_range(values: impl Iterator<Item = f64>, default: Range<f64>, pad: f64) -> Range<f64> {
    let (lo, hi) = values
        .filter(|&v| shown(v))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| {
            (l.min(v), h.max(v))
        });
    if lo > hi {
        return default;
    }
    let span = hi - lo;
    if span <= 1e-9 * lo.abs().max(1.0) {
        let half = 0.5 * lo.abs().max(1.0);
        return lo - half..hi + half;
    }
    lo - pad * span..hi + pad * span
}

fn draw_wake(area: &Panel, wake: &[FreeVortex], body: &[(f64, f64)]) -> Result<(), DrawingError> {
    let title = "Wake and section at the last time \
        (red: ccw, gamma > 0; blue: cw, gamma < 0; dot size ~ |gamma|)";
    let area = area.titled(title, (FONT, 18))?;
    let vortices: Vec<&FreeVortex> = wake
        .iter()
        .filter(|v| shown(v.x) && shown(v.y) && shown(v.gamma))
        .collect();
    let section: Vec<(f64, f64)> = body
        .iter()
        .copied()
        .filter(|&(x, y)| shown(x) && shown(y))
        .collect();
    let points = || {
        vortices
            .iter()
            .map(|v| (v.x, v.y))
            .chain(section.iter().copied())
    };
    let x_data = padded_range(points().map(|p| p.0), -0.5..1.5, 0.03);
    let y_data = padded_range(points().map(|p| p.1), -0.5..0.5, 0.1);

    // Equal scales: measure the plotting area (building a chart without a
    // caption draws nothing), then widen the range that would be stretched.
    let builder = || {
        let mut b = ChartBuilder::on(&area);
        b.margin(10).x_label_area_size(40).y_label_area_size(70);
        b
    };
    let (w, h) = builder()
        .build_cartesian_2d(0.0..1.0, 0.0..1.0)?
        .plotting_area()
        .dim_in_pixel();
    let (w, h) = (f64::from(w.max(1)), f64::from(h.max(1)));
    let scale = ((x_data.end - x_data.start) / w).max((y_data.end - y_data.start) / h);
    let xc = 0.5 * (x_data.start + x_data.end);
    let yc = 0.5 * (y_data.start + y_data.end);
    let mut chart = builder().build_cartesian_2d(
        xc - 0.5 * scale * w..xc + 0.5 * scale * w,
        yc - 0.5 * scale * h..yc + 0.5 * scale * h,
    )?;
    chart
        .configure_mesh()
        .x_desc("x, chords (downstream)")
        .y_desc("y, chords (up)")
        .draw()?;

    // Dot radius relative to the 90th percentile of |gamma|, so that a strong
    // starting vortex does not shrink all the others to points.
    let mut strengths: Vec<f64> = vortices.iter().map(|v| v.gamma.abs()).collect();
    strengths.sort_by(f64::total_cmp);
    let reference = strengths
        .get(strengths.len() * 9 / 10)
        .copied()
        .filter(|g| *g > 0.0)
        .unwrap_or(1.0);
    let radius = |gamma: f64| {
        let r = DOT_RADIUS.0 + 3.5 * (gamma.abs() / reference).sqrt();
        r.clamp(DOT_RADIUS.0, DOT_RADIUS.1).round() as i32
    };
    for (label, colour, sign) in [
        ("ccw (gamma > 0)", RED, 1.0),
        ("cw (gamma < 0)", BLUE, -1.0),
    ] {
        let dots = vortices
            .iter()
            .filter(|v| v.gamma * sign > 0.0)
            .map(|v| Circle::new((v.x, v.y), radius(v.gamma), colour.mix(0.7).filled()));
        chart
            .draw_series(dots)?
            .label(label)
            .legend(move |(x, y)| Circle::new((x + 10, y), 4, colour.filled()));
    }
    chart.draw_series(LineSeries::new(section, BLACK.stroke_width(2)))?;
    key(&mut chart, "section", BLACK.stroke_width(2))?;
    legend(&mut chart)
}

/// Adds a line of `style` labelled `label` to the legend of `chart`.
fn key(chart: &mut Chart, label: &str, style: ShapeStyle) -> Result<(), DrawingError> {
    chart
        .draw_series(LineSeries::new(std::iter::empty::<(f64, f64)>(), style))?
        .label(label)
        .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], style));
    Ok(())
}

/// Draws the legend of `chart`.
fn legend(chart: &mut Chart) -> Result<(), DrawingError> {
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    Ok(())
}

/// One panel of histories against `time`; each series is `(label, values,
/// colour)`; points not shown leave gaps.
fn draw_history(
    area: &Panel,
    caption: &str,
    y_desc: &str,
    time: &[f64],
    series: &[(&str, &[f64], RGBColor)],
    period: Option<f64>,
) -> Result<(), DrawingError> {
    let pairs =
        |values: &[f64]| -> Vec<(f64, f64)> { time.iter().copied().zip(values.to_vec()).collect() };
    let finite = |&(t, v): &(f64, f64)| shown(t) && shown(v);
    let t_range = padded_range(time.iter().copied(), 0.0..1.0, 0.0);
    let values = series.iter().flat_map(|s| pairs(s.1)).filter(finite);
    let y_range = padded_range(values.map(|p| p.1), -1.0..1.0, 0.05);
    let mut chart = ChartBuilder::on(area)
        .caption(caption, (FONT, 18))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(t_range.clone(), y_range.clone())?;
    chart
        .configure_mesh()
        .light_line_style(WHITE)
        .x_desc("time, chords travelled (U t / c)")
        .y_desc(y_desc)
        .draw()?;

    let period = period.filter(|p| p.is_finite() && *p > 0.0);
    if let Some(p) = period {
        let (first, last) = ((t_range.start / p).ceil(), (t_range.end / p).floor());
        if last - first < MAX_PERIOD_MARKS {
            for k in first as i64..=last as i64 {
                let t = k as f64 * p;
                let mark = [(t, y_range.start), (t, y_range.end)];
                chart.draw_series(DashedLineSeries::new(mark, 6, 4, PERIOD_MARK.into()))?;
            }
        }
    }
    for &(label, values, colour) in series {
        // One line per run of shown points, so that NaNs leave gaps.
        for run in pairs(values).split(|p| !finite(p)) {
            let line = run.iter().copied();
            chart.draw_series(LineSeries::new(line, colour.stroke_width(2)))?;
        }
        key(&mut chart, label, colour.stroke_width(2))?;
    }
    if period.is_some() {
        key(&mut chart, "whole periods", PERIOD_MARK.into())?;
    }
    legend(&mut chart)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Draws into a unique temporary file and checks the PNG signature.
    fn assert_draws(h: &History, wake: &[FreeVortex], body: &[(f64, f64)], period: Option<f64>) {
        static COUNT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
        let n = COUNT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let png = std::env::temp_dir().join(format!("fwav-plot-{}-{n}.png", std::process::id()));
        draw(h, wake, body, period, &png).expect("drawn");
        let bytes = std::fs::read(&png).expect("png written");
        std::fs::remove_file(&png).ok();
        assert!(bytes.len() > 8, "png too short: {} bytes", bytes.len());
        assert_eq!(bytes[..8], [0x89, b'P', b'N', b'G', 0x0d, 0x0a, 0x1a, 0x0a]);
    }

    /// A plunge-like history and a sinuous wake with a strong starting vortex.
    fn synthetic(n: usize) -> (History, Vec<FreeVortex>, Vec<(f64, f64)>) {
        let mut h = History::default();
        for t in (0..n).map(|i| 0.05 * i as f64) {
            h.time.push(t);
            h.cl.push((1.2 * t).sin());
            h.ct.push(0.2 + 0.1 * (2.4 * t).cos());
            h.cp.push(0.5 - 0.3 * (2.4 * t).sin());
        }
        let gamma = |s: f64| 0.05 * s.cos() * if s == 0.0 { 10.0 } else { 1.0 };
        let wake = (0..60).map(|i| 0.3 * i as f64);
        let wake = wake.map(|s| FreeVortex {
            x: 1.0 + s / 3.0,
            y: 0.2 * s.sin(),
            gamma: gamma(s),
        });
        (
            h,
            wake.collect(),
            vec![(0.0, 0.05), (0.5, 0.0), (1.0, -0.05)],
        )
    }

    #[test]
    fn draws_a_png() {
        let (history, wake, body) = synthetic(200);
        assert_draws(&history, &wake, &body, Some(2.6));
    }

    #[test]
    fn empty_inputs_and_nans_draw() {
        assert_draws(&History::default(), &[], &[], None);

        let (mut h, mut wake, mut body) = synthetic(50);
        h.cl[10] = f64::NAN;
        h.ct.iter_mut().for_each(|v| *v = f64::NAN);
        h.cp[0] = f64::INFINITY;
        h.time[20] = f64::NAN;
        wake[3].gamma = f64::NAN;
        wake[4].x = f64::NAN;
        body.push((f64::NAN, 0.0));
        assert_draws(&h, &wake, &body, Some(f64::NAN));

        // One point, one vortex, a period far below the time span.
        let (h, wake, _) = synthetic(1);
        assert_draws(&h, &wake[..1], &[], Some(1e-9));

        // Huge but finite values are skipped too.
        let (mut h, mut wake, body) = synthetic(20);
        (h.cl[3], h.cl[4], wake[5].gamma, wake[6].y) = (f64::MAX, -1e300, f64::MAX, -f64::MAX);
        assert_draws(&h, &wake, &body, Some(1.0));
    }
}
