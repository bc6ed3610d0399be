//! Times `SectionMap::from_contour` (release): NACA 0012 and a 2 % flat
//! plate at 256 and 1024 points, 64 terms; the best of 20 fits.
//!
//! `cargo run -p fwav-ns2d --release --example fit_timing`

use fwav_ns2d::{Contour, SectionMap};
use std::time::Instant;

fn main() -> Result<(), fwav_ns2d::NsError> {
    for points in [256, 1024] {
        let cases = [
            ("NACA 0012", Contour::naca4("0012", points, 0.005)?),
            ("2 % plate", Contour::flat_plate(1.0, 0.02, points)?),
        ];
        for (name, contour) in cases {
            let mut best = f64::INFINITY;
            for _ in 0..20 {
                let start = Instant::now();
                let map = SectionMap::from_contour(&contour, 64)?;
                best = best.min(start.elapsed().as_secs_f64());
                std::hint::black_box(map);
            }
            println!("{name:10} {points:5} points: {:.3} ms", best * 1e3);
        }
    }
    Ok(())
}
