//! The contour's checks: each bad input refused with what is wrong.

use super::*;

fn square(n_side: usize) -> Vec<(f64, f64)> {
    let mut p = Vec::new();
    for k in 0..n_side {
        p.push((k as f64 / n_side as f64, 0.0));
    }
    for k in 0..n_side {
        p.push((1.0, k as f64 / n_side as f64));
    }
    for k in 0..n_side {
        p.push((1.0 - k as f64 / n_side as f64, 1.0));
    }
    for k in 0..n_side {
        p.push((0.0, 1.0 - k as f64 / n_side as f64));
    }
    p
}

/// Either orientation, with or without the closing duplicate: the same
/// counterclockwise contour.
#[test]
fn orientation_and_closing_point_are_normalised() {
    let ccw = square(3);
    let mut cw = ccw.clone();
    cw.reverse();
    let mut closed = ccw.clone();
    closed.push(ccw[0]);
    let a = Contour::from_points(&ccw).unwrap();
    let b = Contour::from_points(&cw).unwrap();
    let c = Contour::from_points(&closed).unwrap();
    assert_eq!(a.len(), 12);
    assert_eq!(c, a);
    assert!((a.area() - 1.0).abs() < 1e-15 && (b.area() - 1.0).abs() < 1e-15);
    assert!((a.perimeter() - 4.0).abs() < 1e-15);
}

/// A figure-eight (a lemniscate of Gerono, traced once) crosses itself
/// at the origin: the two segments through it are named.
#[test]
fn a_figure_eight_is_refused_with_its_crossing() {
    let n = 64;
    let points: Vec<(f64, f64)> = (0..n)
        .map(|k| {
            let t = std::f64::consts::TAU * (f64::from(k) + 0.5) / f64::from(n);
            (t.cos(), t.sin() * t.cos())
        })
        .collect();
    let err = Contour::from_points(&points).unwrap_err();
    let NsError::ContourCrossing {
        first,
        second,
        x,
        y,
        ..
    } = err
    else {
        panic!("{err:?}");
    };
    // The curve passes the origin at t = π/2 (between points 15 and 16)
    // and t = 3π/2 (points 47 and 48).
    assert_eq!((first, second), (15, 47));
    assert!(x.abs() < 1e-12 && y.abs() < 1e-12, "({x}, {y})");
    assert!(
        err.to_string().contains("segment 15 (points 15->16)"),
        "{err}"
    );
}

/// A bow-tie: four corners in the wrong order.
#[test]
fn a_bow_tie_is_refused_with_its_crossing() {
    let mut points = Vec::new();
    let corners = [(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.0, 1.0)];
    for i in 0..4 {
        let (p, q) = (corners[i], corners[(i + 1) % 4]);
        for k in 0..3 {
            let t = f64::from(k) / 3.0;
            points.push((p.0 + t * (q.0 - p.0), p.1 + t * (q.1 - p.1)));
        }
    }
    let err = Contour::from_points(&points).unwrap_err();
    let NsError::ContourCrossing { x, y, .. } = err else {
        panic!("{err:?}");
    };
    assert!(
        (x - 0.5).abs() < 1e-12 && (y - 0.5).abs() < 1e-12,
        "({x}, {y})"
    );
}

#[test]
fn a_nan_point_is_refused_by_index() {
    let mut points = square(3);
    points[5].1 = f64::NAN;
    let err = Contour::from_points(&points).unwrap_err();
    assert!(
        matches!(err, NsError::ContourPointNotFinite { index: 5, .. }),
        "{err:?}"
    );
    points[5].1 = f64::INFINITY;
    assert!(Contour::from_points(&points).is_err());
}

#[test]
fn too_few_repeated_and_flat_contours_are_refused() {
    let err = Contour::from_points(&square(1)).unwrap_err();
    assert_eq!(err, NsError::ContourTooFewPoints { count: 4 });
    let mut points = square(3);
    points.insert(4, points[4]);
    let err = Contour::from_points(&points).unwrap_err();
    assert!(
        matches!(
            err,
            NsError::ContourRepeatedPoint {
                index: 4,
                next: 5,
                ..
            }
        ),
        "{err:?}"
    );
    // Out along a line and back: the way back overlaps the way out.
    let line: Vec<(f64, f64)> = (0..5)
        .map(|k| (f64::from(k), 0.0))
        .chain((1..5).map(|k| (4.5 - f64::from(k), 0.0)))
        .collect();
    let err = Contour::from_points(&line).unwrap_err();
    assert!(matches!(err, NsError::ContourCrossing { .. }), "{err:?}");
}

/// A spike: a point that goes out and comes straight back.
#[test]
fn a_spike_is_refused() {
    let mut points = square(3);
    points.insert(2, (1.0 / 3.0, -1.0));
    points.insert(3, (1.0 / 3.0, -0.5));
    let err = Contour::from_points(&points).unwrap_err();
    assert!(
        matches!(
            err,
            NsError::ContourCrossing {
                first: 1,
                second: 2,
                ..
            }
        ),
        "{err:?}"
    );
}

/// The distance to the polygon is the distance to its nearest segment.
#[test]
fn distance_to_the_polygon() {
    let c = Contour::from_points(&square(4)).unwrap();
    assert!((c.distance_to(Complex64::new(0.5, 0.2)) - 0.2).abs() < 1e-15);
    assert!((c.distance_to(Complex64::new(2.0, 2.0)) - 2f64.sqrt()).abs() < 1e-15);
}

/// A unit square encloses its middle, not a point beside it; a path
/// across one side crosses it, one inside does not.
#[test]
fn inside_a_square() {
    // A contour takes at least 8 points: the corners and the sides' middles.
    let points = [
        (0.0, 0.0),
        (0.5, 0.0),
        (1.0, 0.0),
        (1.0, 0.5),
        (1.0, 1.0),
        (0.5, 1.0),
        (0.0, 1.0),
        (0.0, 0.5),
    ];
    let square = Contour::from_points(&points).unwrap();
    assert!(square.encloses(Complex64::new(0.5, 0.5)));
    assert!(!square.encloses(Complex64::new(1.5, 0.5)));
    let across = [Complex64::new(0.5, 0.3), Complex64::new(1.5, 0.3)];
    let within = [Complex64::new(0.2, 0.3), Complex64::new(0.8, 0.3)];
    assert!(square.crossed_by(&across));
    assert!(!square.crossed_by(&within));
}
