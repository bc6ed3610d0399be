//! Numerical conformal maps of section contours against analytic maps.

use fwav_ns2d::{Contour, SectionMap};
use realfft::num_complex::Complex64;
use std::f64::consts::TAU;

fn ellipse_points(semi_x: f64, semi_y: f64, centre: (f64, f64), n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|k| {
            let t = TAU * k as f64 / n as f64;
            (centre.0 + semi_x * t.cos(), centre.1 + semi_y * t.sin())
        })
        .collect()
}

#[test]
fn explore_ellipse() {
    for (a_, b_) in [(2.0, 0.5), (1.0, 0.04)] {
        for n in [64, 128, 256, 512, 1024] {
            let c = Contour::from_points(&ellipse_points(a_, b_, (0.0, 0.0), n)).unwrap();
            let t0 = std::time::Instant::now();
            let map = SectionMap::from_contour(&c, 32);
            let el = t0.elapsed();
            match map {
                Ok(map) => {
                    let (a, z0, b) = map.coefficients();
                    let ea = (a - 0.5 * (a_ + b_)).norm();
                    let eb = (b[0] - 0.5 * (a_ - b_)).norm();
                    let rest = b[1..].iter().map(|x| x.norm()).fold(0.0, f64::max);
                    println!("{a_}:{b_} n {n}: a err {ea:.2e} b1 err {eb:.2e} z0 {:.2e} rest {rest:.2e} {el:?}", z0.norm());
                }
                Err(e) => println!("{a_}:{b_} n {n}: {e}"),
            }
        }
    }
}
