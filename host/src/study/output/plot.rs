//! The study's pictures: for each varied key with numeric values, one
//! PNG of the chosen outputs against it (a panel an output), the finished
//! cases only. Cases that share the other keys' values are joined by a
//! line (a grid's rows, labelled by those values); a Latin hypercube's
//! scattered cases are points.

use std::collections::BTreeMap;
use std::ops::Range;
use std::path::Path;

use plotters::prelude::*;

use crate::output::drawing::{DrawingError, FONT};
use crate::study::results::{CaseResult, Output};

use super::table::cell;

/// A key's value as a number, if it is one.
fn numeric(value: &toml::Value) -> Option<f64> {
    value
        .as_float()
        .or_else(|| value.as_integer().map(|n| n as f64))
}

/// A padded range over the values (`0..1` without any).
fn span(values: impl IntoIterator<Item = f64>) -> Range<f64> {
    let (lo, hi) = values
        .into_iter()
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| {
            (l.min(v), h.max(v))
        });
    if !(lo.is_finite() && hi.is_finite()) {
        return 0.0..1.0;
    }
    // At least 0.5% of the values' size either side: differences in the
    // optimizer's last digits (10 Hz and 10.0000015 Hz) draw flat.
    let size = hi.abs().max(lo.abs()).max(1e-12);
    let pad = (0.08 * (hi - lo)).max(0.005 * size);
    (lo - pad)..(hi + pad)
}

/// Whether `key` has numeric values in every case that sets it.
pub fn plottable(key: &str, results: &[CaseResult]) -> bool {
    let mut values = results
        .iter()
        .filter_map(|r| r.values.iter().find(|(k, _)| k == key).map(|(_, v)| v))
        .peekable();
    values.peek().is_some() && values.all(|v| numeric(v).is_some())
}

/// The finished cases' points of `output` against `key`, grouped by the
/// other keys' values (label, points sorted by `key`).
fn series(key: &str, output: Output, results: &[CaseResult]) -> Vec<(String, Vec<(f64, f64)>)> {
    let mut groups: BTreeMap<String, Vec<(f64, f64)>> = BTreeMap::new();
    for r in results {
        let (Some(design), Some(x)) = (
            r.design.as_ref(),
            r.values
                .iter()
                .find(|(k, _)| k == key)
                .and_then(|(_, v)| numeric(v)),
        ) else {
            continue;
        };
        let Some(y) = output.of(design).filter(|y| y.is_finite()) else {
            continue;
        };
        let label: Vec<String> = r
            .values
            .iter()
            .filter(|(k, _)| k != key)
            .map(|(k, v)| format!("{k} = {}", cell(v)))
            .collect();
        groups.entry(label.join(", ")).or_default().push((x, y));
    }
    groups
        .into_iter()
        .map(|(label, mut points)| {
            points.sort_by(|a, b| a.0.total_cmp(&b.0));
            (label, points)
        })
        .collect()
}

/// Draws the chosen `outputs` of the finished `results` against `key` to
/// `png`, a panel each.
pub fn against(
    key: &str,
    outputs: &[Output],
    results: &[CaseResult],
    png: &Path,
) -> Result<(), DrawingError> {
    let columns = outputs.len().clamp(1, 2);
    let rows = outputs.len().div_ceil(columns).max(1);
    let size = (700 * columns as u32, 480 * rows as u32);
    let root = BitMapBackend::new(png, size).into_drawing_area();
    root.fill(&WHITE)?;
    let areas = root.split_evenly((rows, columns));
    for (area, &output) in areas.iter().zip(outputs) {
        let groups = series(key, output, results);
        let all = || groups.iter().flat_map(|(_, p)| p.iter().copied());
        let mut chart = ChartBuilder::on(area)
            .caption(output.label(), (FONT, 20))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(span(all().map(|p| p.0)), span(all().map(|p| p.1)))?;
        chart
            .configure_mesh()
            .x_desc(key)
            .y_desc(output.name())
            .draw()
            .map_err(|e| DrawingError::Backend(e.to_string()))?;
        let joined = groups.iter().any(|(_, p)| p.len() > 1);
        for (i, (label, points)) in groups.iter().enumerate() {
            let colour = Palette99::pick(i).to_rgba();
            if joined {
                chart
                    .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))
                    .map_err(|e| DrawingError::Backend(e.to_string()))?
                    .label(label.clone())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], colour));
            }
            chart
                .draw_series(points.iter().map(|&p| Circle::new(p, 4, colour.filled())))
                .map_err(|e| DrawingError::Backend(e.to_string()))?;
        }
        if joined && groups.len() > 1 && groups.len() <= 12 {
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .draw()
                .map_err(|e| DrawingError::Backend(e.to_string()))?;
        }
    }
    root.present()?;
    Ok(())
}
