//! A section at rest in the stream under the Navier–Stokes model: runs
//! without a period (`fwav aero2d --model ns --duration`), the start-up
//! turn that lets a symmetric flow shed, and the wall's loads
//! (`--surface`) against Blasius. The model's conventions and the
//! periodic runs are `viscous_section`'s, whose coarse plate and
//! helpers these tests share.

use std::f64::consts::PI;

use fwav::aero2d::case::{Case, SectionModel};
use fwav::aero2d::motion::Motion;
use fwav::aero2d::viscous::{ViscousSection, ViscousShape};

use crate::program::fwav;
use crate::viscous_section::{case, coarse_plate};

/// A circle of unit diameter as a point file (`dir/circle.dat`, 200
/// points from the right, counter-clockwise): chord and diameter are one.
pub(crate) fn circle_file(dir: &std::path::Path) -> std::path::PathBuf {
    let text: String = (0..200)
        .map(|i| {
            let t = 2.0 * PI * f64::from(i) / 200.0;
            format!("{} {}\n", 0.5 + 0.5 * t.cos(), 0.5 * t.sin())
        })
        .collect();
    let path = dir.join("circle.dat");
    std::fs::write(&path, text).unwrap();
    path
}

/// The start-up turn of a section at rest for a duration is given only to
/// a mirror symmetric flow (a symmetric section at zero pitch), which
/// needs it to shed; a lifting one (the plate at 10°, a cambered NACA
/// 2412) keeps its impulsive start as it is. Seen in the work the section
/// does: none without the turn (|CP| below 1e-12 of the drag), some with
/// it. The symmetry is read from the shape: the plate, a circle's points
/// and the NACA 0012 are their mirror images, the NACA 2412 and a circle
/// moved off the chord line are not.
#[test]
fn only_a_mirror_symmetric_flow_is_turned_at_the_start() {
    let work = |shape: ViscousShape, pitch_deg: f64| -> (f64, f64) {
        let still = Motion {
            mean_pitch: pitch_deg.to_radians(),
            ..Motion::plunge(1.0, 0.0)
        };
        let section = ViscousSection {
            shape,
            ..coarse_plate()
        };
        let run = Case {
            duration: Some(3.0),
            ..case(SectionModel::Viscous(section), still, 1000.0)
        }
        .run()
        .unwrap();
        let largest = |v: &[f64]| v.iter().map(|c| c.abs()).fold(0.0, f64::max);
        (largest(&run.history.cp), largest(&run.history.ct))
    };
    let (lifting, drag) = work(ViscousShape::Plate(0.12), 10.0);
    assert!(lifting < 1e-12 * drag, "{lifting:e}");
    let (symmetric, drag) = work(ViscousShape::Plate(0.12), 0.0);
    assert!(symmetric > 1e-6 * drag, "{symmetric:e}");

    let circle = |lift: f64| -> ViscousShape {
        let points: Vec<(f64, f64)> = (0..200)
            .map(|i| {
                let t = 2.0 * PI * f64::from(i) / 200.0;
                (0.5 + 0.5 * t.cos(), lift + 0.5 * t.sin())
            })
            .collect();
        ViscousShape::from_points(&points).unwrap()
    };
    let naca = |name: &str| SectionModel::named_viscous(name, 0.04).unwrap();
    assert!(ViscousShape::Plate(0.04).is_mirror_symmetric());
    assert!(circle(0.0).is_mirror_symmetric());
    assert!(naca("naca0012").is_mirror_symmetric());
    assert!(!naca("naca2412").is_mirror_symmetric());
    assert!(!circle(0.01).is_mirror_symmetric());
}

/// The wall's loads of a run (`CaseRun::surface`, what `fwav aero2d
/// --surface` writes) on a plate 1 % thick at rest in the stream at zero
/// incidence, Re 15,000, after 4 chords, on 256 x 192 (7 s):
/// - the skin friction on each face over x/c in [0.3, 0.7] within 10 % of
///   Blasius' (1908) flat plate, `Cf = 0.664 / sqrt(Re x)` with x from
///   the leading edge, pointing downstream (measured 7.0 %; after 8
///   chords 5.7 %, and 5.6 % on the exponential 384 x 320, the default
///   until 2026-12-05). The default
///   plate, 4 % thick, is not Blasius' plate: the pressure gradient of
///   its round nose flattens its friction (0.79 to 1.09 of Blasius' over
///   the same stretch on the default grid);
/// - the pressure and friction integrated round the wall give the run's
///   force at its end (CD and CL within 1 % of the drag; measured 0.16 %),
///   so the file's axes, signs and scales are the forces';
/// - the pressure's level (`fwav_ns2d::Flow::wall_pressure_mean`): the
///   nose's stagnation point within 0.05 of Bernoulli's `cp = 1` (a nose
///   of radius 0.005 c is at Re 75 on its radius, where the viscous
///   excess is a few hundredths), and `|cp|` over x/c in [0.3, 0.7]
///   under 0.05, the order of the plate's thickness and of Blasius'
///   displacement thickness there (`1.72 x / sqrt(Re x)`, 0.01 c at mid
///   chord), as thin-airfoil theory has it. Measured 1.0196 and 0.038;
///   without the level (the mean round the wall's nodes, -0.058, left
///   out, as `--surface` wrote before 2026-12-04) both fail.
#[test]
fn the_wall_friction_of_a_thin_plate_in_the_stream_is_blasius() {
    let plate = ViscousSection {
        around: 256,
        radial: 192,
        far: None,
        ..ViscousSection::plate(0.01)
    };
    let still = Case {
        duration: Some(4.0),
        ..case(
            SectionModel::Viscous(plate),
            Motion::plunge(1.0, 0.0),
            15_000.0,
        )
    };
    let run = still.run().unwrap();
    let wall = run.surface.as_ref().unwrap();
    let n = wall.points.len();
    let mut worst: f64 = 0.0;
    let mut flat_cp: f64 = 0.0;
    let nose_cp = wall.cp.iter().copied().fold(f64::MIN, f64::max);
    for (k, &(x, y)) in wall.points.iter().enumerate() {
        if (0.3..=0.7).contains(&x) {
            flat_cp = flat_cp.max(wall.cp[k].abs());
            let blasius = 0.664 / (15_000.0 * x).sqrt();
            let (fx, fy) = wall.cf[k];
            assert!(fx > 0.0 && fy.abs() < 0.1 * fx, "at ({x}, {y}): {fx}, {fy}");
            worst = worst.max((fx / blasius - 1.0).abs());
        }
    }
    // Round the wall: the pressure on the inward normal, the friction
    // along the wall, each over its node's share of the arc.
    let mut force = (0.0, 0.0);
    for k in 0..n {
        let (a, b) = (wall.points[(k + n - 1) % n], wall.points[(k + 1) % n]);
        let (tx, ty) = (0.5 * (b.0 - a.0), 0.5 * (b.1 - a.1));
        let ds = tx.hypot(ty);
        force.0 += -ty * wall.cp[k] + wall.cf[k].0 * ds;
        force.1 += tx * wall.cp[k] + wall.cf[k].1 * ds;
    }
    let h = &run.history;
    let (cd, cl) = (-h.ct[h.ct.len() - 1], h.cl[h.cl.len() - 1]);
    println!(
        "thin plate at rest, Re 15,000, t = {:.2}: skin friction worst {:.1}% from Blasius over \
         x/c 0.3-0.7; wall integral CD {:.5} CL {:+.5} against the run's {cd:.5} {cl:+.5}; \
         largest cp {nose_cp:.4}, largest |cp| over x/c 0.3-0.7 {flat_cp:.4}, mean cp over \
         the nodes {:.4}",
        wall.time,
        100.0 * worst,
        force.0,
        force.1,
        wall.cp.iter().sum::<f64>() / n as f64
    );
    assert!(worst < 0.10, "{worst}");
    assert!((force.0 - cd).abs() < 0.01 * cd && (force.1 - cl).abs() < 0.01 * cd);
    assert!((nose_cp - 1.0).abs() < 0.05, "stagnation cp {nose_cp}");
    assert!(flat_cp < 0.05, "mid-chord cp {flat_cp}");
}

/// `fwav aero2d --model ns --duration`, a run without a period, on a
/// circle given as a point file:
/// - the sudden start at Re 550 (256 x 192, 1.5 diameters, 3 s): the
///   drag history of `--history` within 5% of Koumoutsakos & Leonard
///   (1995, fig. 18; `ns2d/tests/data`) over U t/R in [0.5, 3], as the
///   solver's own validated case (measured 2.2%, with the start-up turn
///   that breaks the symmetry: 2.0% without it, which moves the drag by
///   at most 0.18% there);
/// - the wake at Re 100 (128 x 128, 150 diameters, 2 s): the lift sheds
///   at Strouhal 0.164-0.165 and the mean drag is 1.33-1.35 (Liu, Zheng &
///   Sung 1998; Park, Kwon & Choi 1998), each within the 3% of
///   the band, over the run's second half (measured 0.1653 and 1.331;
///   the exponential 384 x 320, the default until 2026-12-05, 30 s:
///   0.1654 and 1.329). Its lift swing,
///   0.322 here and 0.289 on the default grid at the default Courant
///   number 3 (0.314 at 1), is not asserted: the band's 0.33-0.34 is
///   `fwav-ns2d`'s to meet at its validated step (0.323,
///   `the_cylinder_wake_at_re_100_sheds_as_published`); the default
///   step was chosen on the FWAV plate's thrust;
/// - `--surface` writes the wall's loads at the end, a row a node;
/// - `--duration` is refused for the inviscid models, out of range, and
///   with `--cycles`; `--surface` and `--field` for the inviscid models,
///   and a `--field` not named `.vtu`.
#[test]
fn aero2d_runs_a_body_at_rest_for_a_duration() {
    let dir = crate::program::scratch("ns-duration");
    let circle = circle_file(&dir);
    let circle = circle.to_str().unwrap();
    let csv = dir.join("start.csv");
    let wall = dir.join("wall.csv");
    let base = [
        "aero2d",
        "--model",
        "ns",
        "--section",
        circle,
        "--plunge-amplitude",
        "0",
    ];
    let mut start = base.to_vec();
    start.extend_from_slice(&[
        "--reynolds",
        "550",
        "--duration",
        "1.5",
        "--ns-around",
        "256",
    ]);
    start.extend_from_slice(&["--ns-radial", "192", "--history", csv.to_str().unwrap()]);
    start.extend_from_slice(&["--surface", wall.to_str().unwrap()]);
    let out = fwav(&start);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("at rest") && text.contains("1.5 chords travelled"),
        "{text}"
    );
    let history = std::fs::read_to_string(&csv).unwrap();
    // U t / R = 2 U t / c; CD = -CT.
    let drag: Vec<(f64, f64)> = history
        .lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            (2.0 * v[0], -v[2])
        })
        .collect();
    let reference = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../ns2d/tests/data/koumoutsakos_leonard_1995_re550.dat"
    ))
    .unwrap();
    let (error, at) = fwav_ns2d::ReferenceCurve::parse(&reference)
        .unwrap()
        .worst_deviation(&drag, (0.5, 3.0), f64::abs);
    println!(
        "sudden start, Re 550: worst {:.2}% at U t/R = {at:.2}",
        100.0 * error
    );
    assert!(error < 0.05, "{error} at {at}");
    // The wall file: a comment with the time, the header, a row a node.
    let text = std::fs::read_to_string(&wall).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert!(
        lines[0].starts_with("# wall loads at U t / c = 1.5"),
        "{}",
        lines[0]
    );
    assert_eq!(lines[1], "s,x,y,cp,cf_x,cf_y");
    assert_eq!(lines.len(), 2 + 256);
    assert!(lines[2..].iter().all(|l| l
        .split(',')
        .all(|x| x.parse::<f64>().is_ok_and(f64::is_finite))));

    let mut wake = base.to_vec();
    wake.extend_from_slice(&[
        "--reynolds",
        "100",
        "--duration",
        "150",
        "--ns-around",
        "128",
    ]);
    wake.extend_from_slice(&["--ns-radial", "128", "--json"]);
    let out = fwav(&wake);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON on stdout");
    let strouhal = v["shedding"]["strouhal"].as_f64().unwrap();
    let drag = v["window"]["mean_cd"].as_f64().unwrap();
    println!(
        "wake, Re 100: Strouhal {strouhal:.4}, CD {drag:.3}, CL +- {:.3}",
        v["window"]["cl_swing"].as_f64().unwrap()
    );
    assert!(strouhal > 0.164 * 0.97 && strouhal < 0.165 * 1.03, "{v}");
    assert!(drag > 1.33 * 0.97 && drag < 1.35 * 1.03, "{v}");
    assert_eq!(v["at_rest"], true);
    assert!(v["window"]["mean_cp"].as_f64().unwrap().abs() < 1e-3, "{v}");

    for (bad, says) in [
        (&["aero2d", "--duration", "3"][..], "applies to --model ns"),
        (
            &["aero2d", "--surface", "wall.csv"][..],
            "apply to --model ns only",
        ),
        (
            &["aero2d", "--field", "flow.vtu"][..],
            "apply to --model ns only",
        ),
        (
            &["aero2d", "--model", "ns", "--duration", "-1"][..],
            "(0, 1000]",
        ),
        (
            &["aero2d", "--model", "ns", "--field", "flow.vtk"][..],
            "name it FILE.vtu",
        ),
        (
            &[
                "aero2d",
                "--model",
                "ns",
                "--duration",
                "3",
                "--cycles",
                "4",
            ][..],
            "cannot be used",
        ),
    ] {
        let out = fwav(bad);
        let e = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success() && e.contains(says), "{bad:?}: {e}");
    }
    std::fs::remove_dir_all(&dir).ok();
}
