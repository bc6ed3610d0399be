//! Pictures of a design run, as PNGs: the MDOIS convergence (3D thrust
//! and efficiency, the kinematic variables within their level ranges, and
//! the layout's changes and mass fraction, per cycle) and the thrust
//! history of the initial and final designs over their last flapping
//! cycle. (The Pareto front and main effects come from
//! [`crate::output::discipline_plot`].)

use std::ops::Range;
use std::path::Path;

use plotters::prelude::*;

use crate::discipline::kinematic::DesignSpace;

use crate::mdois::records::SystemRecord;
use crate::mdois::summary::Summary;
use crate::output::drawing::{DrawingError, FONT};
const COLOURS: [RGBColor; 4] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
];

/// A padded range over the finite values (a unit range when there are
/// none).
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
    let pad = 0.08 * (hi - lo).max(1e-6 * hi.abs().max(1e-9));
    (lo - pad)..(hi + pad)
}

/// One panel: `series` of (name, points) against the cycle number.
fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    title: &str,
    y_label: &str,
    cycles: Range<f64>,
    y: Range<f64>,
    series: &[(&str, Vec<(f64, f64)>)],
) -> Result<(), DrawingError>
where
    DB::ErrorType: 'static,
{
    let mut chart = ChartBuilder::on(area)
        .caption(title, (FONT, 20))
        .margin(12)
        .x_label_area_size(35)
        .y_label_area_size(60)
        .build_cartesian_2d(cycles, y)?;
    chart
        .configure_mesh()
        .x_desc("design cycle")
        .y_desc(y_label)
        .x_labels(8)
        .x_label_formatter(&|x: &f64| {
            if (x - x.round()).abs() < 1e-9 {
                format!("{x:.0}")
            } else {
                String::new()
            }
        })
        .draw()
        .map_err(|e| DrawingError::Backend(e.to_string()))?;
    for (i, (name, points)) in series.iter().enumerate() {
        let colour = COLOURS[i % COLOURS.len()];
        chart
            .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))
            .map_err(|e| DrawingError::Backend(e.to_string()))?
            .label(*name)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], colour));
        chart
            .draw_series(points.iter().map(|&p| Circle::new(p, 4, colour.filled())))
            .map_err(|e| DrawingError::Backend(e.to_string()))?;
    }
    if series.len() > 1 {
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(|e| DrawingError::Backend(e.to_string()))?;
    }
    Ok(())
}

/// Draws the convergence of `summary` over `space` to `png`.
pub fn convergence(summary: &Summary, space: &DesignSpace, png: &Path) -> Result<(), DrawingError> {
    let root = BitMapBackend::new(png, (1400, 1000)).into_drawing_area();
    root.fill(&WHITE)?;
    let areas = root.split_evenly((2, 2));
    let last = summary.cycles.len().max(1) as f64;
    let cycles = 0.8..last + 0.2;
    let with_system: Vec<_> = summary
        .cycles
        .iter()
        .filter_map(|c| c.system.as_ref().map(|s| (c.cycle as f64, s)))
        .collect();
    let ct: Vec<(f64, f64)> = with_system.iter().map(|(c, s)| (*c, s.ct)).collect();
    let eta: Vec<(f64, f64)> = with_system
        .iter()
        .map(|(c, s)| (*c, s.efficiency))
        .collect();
    panel(
        &areas[0],
        "3D mean thrust coefficient",
        "CT",
        cycles.clone(),
        span(ct.iter().map(|p| p.1)),
        &[("CT", ct.clone())],
    )?;
    panel(
        &areas[1],
        "3D propulsive efficiency",
        "CT / CP",
        cycles.clone(),
        span(eta.iter().map(|p| p.1)),
        &[("efficiency", eta.clone())],
    )?;
    // Each kinematic variable coded in its level range: -1 low, 1 high.
    let levels = [
        space.frequency_hz,
        space.amplitude_deg,
        space.mean_angle_deg,
        space.stroke_plane_deg,
    ];
    let coded = |i: usize, x: f64| {
        let l = levels[i];
        if x < l[1] {
            (x - l[1]) / (l[1] - l[0]).abs().max(1e-12)
        } else {
            (x - l[1]) / (l[2] - l[1]).abs().max(1e-12)
        }
    };
    let names = ["frequency", "amplitude", "mean angle", "stroke plane"];
    let variables: Vec<(&str, Vec<(f64, f64)>)> = names
        .iter()
        .enumerate()
        .map(|(i, &name)| {
            let points = summary
                .cycles
                .iter()
                .map(|c| (c.cycle as f64, coded(i, c.kinematics.degrees()[i])))
                .collect();
            (name, points)
        })
        .collect();
    panel(
        &areas[2],
        "kinematics analysed (-1 low level, 0 initial, 1 high)",
        "coded value",
        cycles.clone(),
        -1.15..1.15,
        &variables,
    )?;
    let changed: Vec<(f64, f64)> = summary
        .cycles
        .iter()
        .filter_map(|c| {
            c.change
                .as_ref()
                .map(|d| (c.cycle as f64, d.elements_changed_fraction))
        })
        .collect();
    let mass: Vec<(f64, f64)> = summary
        .cycles
        .iter()
        .map(|c| (c.cycle as f64, c.carbon_mass_fraction))
        .collect();
    panel(
        &areas[3],
        "carbon layout",
        "fraction of the design domain",
        cycles,
        -0.02..1.02,
        &[
            ("elements changed by the disciplines", changed),
            ("carbon mass fraction analysed", mass),
        ],
    )?;
    root.present()?;
    Ok(())
}

/// Draws the thrust coefficient over the last flapping cycle of each
/// `(label, system analysis)` against the phase `t / T` to `png`.
pub fn thrust_history(runs: &[(String, &SystemRecord)], png: &Path) -> Result<(), DrawingError> {
    let root = BitMapBackend::new(png, (1000, 600)).into_drawing_area();
    root.fill(&WHITE)?;
    let curves: Vec<(String, Vec<(f64, f64)>)> = runs
        .iter()
        .map(|(label, s)| {
            let n = s.steps_per_cycle.max(1);
            let last = &s.steps[s.steps.len().saturating_sub(n)..];
            let points = last
                .iter()
                .enumerate()
                .map(|(k, r)| ((k + 1) as f64 / n as f64, r.ct))
                .collect();
            (label.clone(), points)
        })
        .collect();
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Thrust coefficient over the last flapping cycle (3D system analysis)",
            (FONT, 22),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d(
            0.0..1.0,
            span(curves.iter().flat_map(|c| c.1.iter().map(|p| p.1))),
        )?;
    chart
        .configure_mesh()
        .x_desc("t / T (flapping angle mean + amplitude cos(2 pi t / T))")
        .y_desc("CT")
        .draw()?;
    for (i, (label, points)) in curves.into_iter().enumerate() {
        let colour = COLOURS[i % COLOURS.len()];
        chart
            .draw_series(LineSeries::new(points, colour.stroke_width(2)))?
            .label(label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], colour));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}
