//! The reinforcement layout as a picture: the planform seen from above,
//! span to the right and the leading edge at the top, carbon elements
//! black and mylar-only elements white (the seed paper's Fig. 20 style).

use std::path::Path;

use plotters::prelude::*;

use crate::shell::mesh::ShellMesh;

use super::drawing::{DrawingError, FONT};

/// Draws `layout` (carbon or not per element of `mesh`) to `png`, about
/// `width` pixels wide, with `title` above.
pub fn planform(
    mesh: &ShellMesh,
    layout: &[bool],
    title: &str,
    width: u32,
    png: &Path,
) -> Result<(), DrawingError> {
    if layout.len() != mesh.elements.len() || mesh.nodes.is_empty() {
        return Err(DrawingError::LayoutLength {
            values: layout.len(),
            elements: mesh.elements.len(),
        });
    }
    // Span (y) across, chord (x) down.
    let (mut y0, mut y1, mut x0, mut x1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for p in &mesh.nodes {
        y0 = y0.min(p.y);
        y1 = y1.max(p.y);
        x0 = x0.min(p.x);
        x1 = x1.max(p.x);
    }
    let (span, chord) = ((y1 - y0).max(1e-12), (x1 - x0).max(1e-12));
    let margin = 40u32;
    let inner = width.saturating_sub(2 * margin).max(10);
    let height_px = (f64::from(inner) * chord / span).ceil() as u32 + 2 * margin + 20;
    let root = BitMapBackend::new(png, (width.max(10 + 2 * margin), height_px)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, (FONT, 18))
        .margin(margin / 2)
        .build_cartesian_2d(y0..y1, x1..x0)?;
    let grey = RGBColor(200, 200, 200);
    chart.draw_series(mesh.elements.iter().zip(layout).map(|(nodes, &carbon)| {
        let corners: Vec<(f64, f64)> = nodes
            .iter()
            .map(|&n| (mesh.nodes[n].y, mesh.nodes[n].x))
            .collect();
        let style = if carbon {
            BLACK.filled()
        } else {
            WHITE.filled()
        };
        Polygon::new(corners, style)
    }))?;
    // The outline, so a white wing shows on white paper.
    let outline = boundary(mesh);
    chart.draw_series(
        outline
            .into_iter()
            .map(|(a, b)| PathElement::new(vec![a, b], grey.stroke_width(1))),
    )?;
    root.present()?;
    Ok(())
}

/// Edges used by one element only, as (span, chord) point pairs.
fn boundary(mesh: &ShellMesh) -> Vec<((f64, f64), (f64, f64))> {
    let mut count = std::collections::HashMap::new();
    for nodes in &mesh.elements {
        for k in 0..4 {
            let (a, b) = (nodes[k], nodes[(k + 1) % 4]);
            *count.entry((a.min(b), a.max(b))).or_insert(0usize) += 1;
        }
    }
    let mut edges: Vec<_> = count
        .into_iter()
        .filter(|&(_, c)| c == 1)
        .map(|(e, _)| e)
        .collect();
    edges.sort_unstable();
    edges
        .into_iter()
        .map(|(a, b)| {
            let (p, q) = (mesh.nodes[a], mesh.nodes[b]);
            ((p.y, p.x), (q.y, q.x))
        })
        .collect()
}
