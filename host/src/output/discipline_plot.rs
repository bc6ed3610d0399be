//! Pictures of the aerodynamic discipline, as PNGs: the main effects (the
//! ANOM level means of the combined objective, one panel per design
//! variable) and the net CT – net efficiency plane with the response
//! surfaces' Pareto front, the 18 array runs, the analysed design (the
//! discipline's start) and the three confirmed candidates.

use std::path::Path;

use plotters::prelude::*;

use crate::discipline::kinematic::{DesignSpace, KinematicResult};

use super::drawing::{DrawingError, FONT};

/// Pixels between the stacked names of the candidates ([`pareto`]).
const CANDIDATE_LINE: i32 = 18;

/// Draws the main effects of `result` over `space` to `png`.
pub fn main_effects(
    result: &KinematicResult,
    space: &DesignSpace,
    png: &Path,
) -> Result<(), DrawingError> {
    let root = BitMapBackend::new(png, (1400, 420)).into_drawing_area();
    root.fill(&WHITE)?;
    let names = [
        ("frequency, Hz", space.frequency_hz),
        ("amplitude, deg", space.amplitude_deg),
        ("mean angle, deg", space.mean_angle_deg),
        ("stroke plane, deg", space.stroke_plane_deg),
    ];
    let all: Vec<f64> = result.level_means.iter().flatten().copied().collect();
    let values = span(&all);
    for (panel, ((name, levels), means)) in root
        .split_evenly((1, 4))
        .iter()
        .zip(names.iter().zip(&result.level_means))
    {
        let mut chart = ChartBuilder::on(panel)
            .caption(*name, (FONT, 20))
            .margin(12)
            .x_label_area_size(35)
            .y_label_area_size(55)
            .build_cartesian_2d(levels[0]..levels[2], values.clone())?;
        chart
            .configure_mesh()
            .y_desc("mean combined objective")
            .draw()?;
        let points: Vec<(f64, f64)> = levels.iter().copied().zip(means.iter().copied()).collect();
        chart.draw_series(LineSeries::new(points.clone(), BLUE.stroke_width(2)))?;
        chart.draw_series(points.iter().map(|&p| Circle::new(p, 5, BLUE.filled())))?;
    }
    root.present()?;
    Ok(())
}

/// Draws the net CT – net efficiency plane of `result` to `png` (the
/// quantities the objective and the surfaces use).
pub fn pareto(result: &KinematicResult, png: &Path) -> Result<(), DrawingError> {
    let root = BitMapBackend::new(png, (900, 700)).into_drawing_area();
    root.fill(&WHITE)?;
    let runs: Vec<(f64, f64)> = result
        .runs
        .iter()
        .filter_map(|e| e.result.as_ref().ok().map(|r| (r.ct_net, r.efficiency_net)))
        .collect();
    let front: Vec<(f64, f64)> = result.pareto.iter().map(|p| (p.1, p.2)).collect();
    let candidates: Vec<(String, (f64, f64))> = result
        .candidates
        .iter()
        .filter_map(|c| {
            c.confirmation
                .result
                .as_ref()
                .ok()
                .map(|r| (c.method.clone(), (r.ct_net, r.efficiency_net)))
        })
        .collect();
    let initial = result
        .initial
        .result
        .as_ref()
        .ok()
        .map(|r| (r.ct_net, r.efficiency_net));
    let xs: Vec<f64> = runs
        .iter()
        .chain(&front)
        .chain(candidates.iter().map(|c| &c.1))
        .chain(&initial)
        .map(|p| p.0)
        .collect();
    let ys: Vec<f64> = runs
        .iter()
        .chain(&front)
        .chain(candidates.iter().map(|c| &c.1))
        .chain(&initial)
        .map(|p| p.1)
        .collect();
    let mut chart = ChartBuilder::on(&root)
        .caption("Thrust and efficiency of the mid-span section", (FONT, 24))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d(span(&xs), span(&ys))?;
    chart
        .configure_mesh()
        .x_desc("mean net CT (less friction)")
        .y_desc("net propulsive efficiency")
        .draw()?;
    chart
        .draw_series(
            front
                .iter()
                .map(|&p| Circle::new(p, 3, RGBColor(120, 120, 220).filled())),
        )?
        .label("Pareto front of the response surfaces")
        .legend(|(x, y)| Circle::new((x, y), 3, RGBColor(120, 120, 220).filled()));
    chart
        .draw_series(runs.iter().map(|&p| Cross::new(p, 5, BLACK)))?
        .label("L18 runs")
        .legend(|(x, y)| Cross::new((x, y), 5, BLACK));
    if let Some(p) = initial {
        chart
            .draw_series(std::iter::once(TriangleMarker::new(p, 8, GREEN.filled())))?
            .label("analysed design (the discipline's start)")
            .legend(|(x, y)| TriangleMarker::new((x, y), 8, GREEN.filled()));
    }
    // Each candidate's name a line below the last one's, right of its
    // point: candidates often land on one another (the same design found
    // by two methods), and their names then stack instead of overprinting.
    for (i, (name, p)) in candidates.iter().enumerate() {
        let line = i32::try_from(i).unwrap_or(0) * CANDIDATE_LINE;
        chart.draw_series(std::iter::once(
            EmptyElement::at(*p)
                + Circle::new((0, 0), 7, RED.filled())
                + Text::new(name.clone(), (10, line - 8), (FONT, 16).into_font()),
        ))?;
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}

/// A padded range over the finite values (a unit range when there are none).
fn span(values: &[f64]) -> std::ops::Range<f64> {
    let finite = values.iter().copied().filter(|v| v.is_finite());
    let (lo, hi) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| {
        (l.min(v), h.max(v))
    });
    if !(lo.is_finite() && hi.is_finite()) {
        return 0.0..1.0;
    }
    let pad = 0.08 * (hi - lo).max(1e-9 * hi.abs().max(1.0));
    (lo - pad)..(hi + pad)
}
