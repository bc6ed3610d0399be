//! The sections of the Navier–Stokes model behind `fwav aero2d --model
//! ns` (`fwav::aero2d::viscous::ViscousShape`) and their conformal maps:
//! a point file's sharp trailing edge opened without losing the chord, a
//! thick NACA section's blunt edge mapped, and a section whose map
//! smooths a corner warned of. The maps' own accuracy is `fwav-ns2d`'s
//! to show (`ns2d/tests/section_maps.rs`).

use fwav::aero2d::case::SectionModel;
use fwav::aero2d::viscous::{ViscousSection, ViscousShape, MAP_DEVIATION_WARNING};

use crate::program::fwav;

/// A sharp trailing edge, as coordinate files have it (the SD7003 of
/// `tests/data/sd7003.dat`, closed by a last point 1e-5 chords from the
/// first, and the NACA 0012 by name), is opened to 0.005 c and closed by
/// an arc tangent to both sides: the sections keep their chord, from the
/// leading edge at 0 to `1 + (δ/2)(1/cos φ - tan φ)` for sides meeting the
/// edge at `±φ` (between 1.002 and 1.0025 c for these edges, of a few
/// degrees), where a corner would have no conformal map (the map's Newton
/// method did not converge on the file as given). The semicircle of
/// before 2026-12-07 ended them at 1.0025 c.
#[test]
fn a_sharp_trailing_edge_keeps_the_chord() {
    let file = fwav::aero2d::naca::parse_points(include_str!("../data/sd7003.dat")).unwrap();
    let from_name = SectionModel::named_viscous("naca0012", 0.04).unwrap();
    for (what, shape) in [
        ("sd7003", ViscousShape::from_points(&file.points).unwrap()),
        ("naca0012", from_name),
    ] {
        let ViscousShape::Contour(points) = shape else {
            panic!("{what}: a contour expected")
        };
        let (low, high) = points
            .iter()
            .fold((f64::MAX, f64::MIN), |(l, h), p| (l.min(p.0), h.max(p.0)));
        assert!(
            low.abs() < 1e-3 && high > 1.002 && high <= 1.0025 + 1e-12,
            "{what}: {low} {high}"
        );
    }
}

/// A thick NACA section's sharp trailing edge, a wedge of about 52° (NACA 0040)
/// to 88° (NACA 0080), made blunt, has a conformal map at the model's
/// default resolution (192 Laurent terms): the map's Newton method did
/// not converge for NACA 0040 to 0080 while the back was a semicircle,
/// whose joins with the sides turned by half the wedge ("the conformal
/// map of the section did not converge in 60 Newton steps ...: the
/// contour is too thin or too sharp ...; ... or thicken it"). NACA 0030
/// (a 20° join) did.
#[test]
fn a_thick_sections_blunt_edge_has_a_map() {
    for code in ["naca0040", "naca0060", "naca0080", "naca6440"] {
        let ViscousShape::Contour(points) = SectionModel::named_viscous(code, 0.04).unwrap() else {
            panic!("{code}: a contour expected")
        };
        let contour = fwav_ns2d::Contour::from_points(&points).unwrap();
        let terms = ViscousSection::plate(ViscousSection::DEFAULT_THICKNESS).around / 2;
        if let Err(e) = fwav_ns2d::SectionMap::from_contour(&contour, terms) {
            panic!("{code}: {e}");
        }
    }
}

/// A NACA lower surface's corner at `x = p` (37° on 9112) has no smooth
/// conformal map, and the series the grid is built on smooths it: the
/// map's own figure of how far its section lies from the contour
/// ([`ViscousSection::map_deviation`]; `ns2d/tests/section_maps.rs`
/// checks it against the measured distance) exceeds
/// [`MAP_DEVIATION_WARNING`] on NACA 9112 at 128 terms (1.3e-3 c), and
/// `fwav aero2d --model ns` warns of it, naming the section and the
/// distance, and gives the figure in `--json`. NACA 0012 and the plate,
/// smooth, stay below (no warning), and the ellipse, mapped exactly, has
/// no such figure.
#[test]
fn a_section_its_map_smooths_is_warned_of() {
    let with = |shape: ViscousShape| ViscousSection {
        around: 256,
        ..ViscousSection::new(shape)
    };
    let named = |code: &str| with(SectionModel::named_viscous(code, 0.04).unwrap());
    let corner = named("naca9112").map_deviation().unwrap().unwrap();
    assert!(corner > MAP_DEVIATION_WARNING, "{corner:.2e}");
    for smooth in [named("naca0012"), with(ViscousShape::Plate(0.04))] {
        let deviation = smooth.map_deviation().unwrap().unwrap();
        assert!(deviation < 0.2 * MAP_DEVIATION_WARNING, "{deviation:.2e}");
    }
    assert_eq!(
        with(ViscousShape::Ellipse(0.1)).map_deviation().unwrap(),
        None
    );
    for (code, warned) in [("naca9112", true), ("naca0012", false)] {
        let args = [
            "aero2d",
            "--model",
            "ns",
            "--section",
            code,
            "--ns-around",
            "256",
            "--ns-radial",
            "48",
            "--reynolds",
            "1000",
            "--duration",
            "0.04",
            "--json",
        ];
        let out = fwav(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            out.status.code().is_some_and(|c| c != 1),
            "{code}: {stderr}"
        );
        let warning = format!("warning: --section {code}: the grid's section departs from");
        assert_eq!(stderr.contains(&warning), warned, "{code}: {stderr}");
        if warned {
            assert!(stderr.contains("by about 1.3e-3 chords"), "{stderr}");
        }
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON on stdout");
        let figure = v["section_map_deviation_chords"]
            .as_f64()
            .expect("the figure");
        assert_eq!(
            figure > MAP_DEVIATION_WARNING,
            warned,
            "{code}: {figure:.2e}"
        );
    }
}
