//! `fwav aero2d --model ns --field FILE.vtu`: the flow at the run's end
//! as a file ParaView opens, checked against the wall condition the
//! solver imposes and read back by VTK's own reader.

use std::path::Path;

use fwav::aero2d::case::{Case, CaseError, SectionModel};
use fwav::aero2d::motion::Motion;
use fwav::aero2d::viscous::{FlowField, FrameSink, ViscousError, ViscousSection};

use crate::program::{fwav, fwav_command};
use crate::viscous_section::{case, coarse_plate};
use crate::vtk_reader::read_vtu;

/// VTK's reader (where Python's `vtk` is installed: [`read_vtu`]) finds
/// in the flow field `path` the grid's `around × rings` nodes and its
/// quadrilaterals (type 9), the vorticity and the streamfunction with
/// one component each and the ranges of `omega` and `psi` (as this test
/// read them from the file), and a three-component velocity.
fn vtk_reads_the_field(path: &Path, (around, rings): (usize, usize), omega: &[f64], psi: &[f64]) {
    let Some(read) = read_vtu(path) else { return };
    let file = path.display();
    assert_eq!(
        (read.points, read.cells, read.cell_types.as_slice()),
        (around * rings, around * (rings - 1), &[9][..]),
        "VTK's reader on {file}: quadrilaterals"
    );
    for (name, values) in [("vorticity", omega), ("streamfunction", psi)] {
        let range = [
            values.iter().copied().fold(f64::MAX, f64::min),
            values.iter().copied().fold(f64::MIN, f64::max),
        ];
        let array = read.point_array(name).expect(name);
        assert_eq!(
            (array.components, array.range),
            (1, range),
            "{file}: {name}"
        );
    }
    let velocity = read.point_array("velocity").expect("velocity");
    assert_eq!(velocity.components, 3, "{file}: velocity (u, v, 0)");
}

/// `fwav aero2d` with `extra` on the flat plate at 10° started in a
/// stream, NS, Re 200, 0.3 chords travelled, 128 × 96 nodes (about a
/// second).
fn plate_at_ten_degrees(extra: &[&str]) -> std::process::Output {
    fwav(&plate_at_ten_degrees_for("0.3", extra))
}

/// The arguments of [`plate_at_ten_degrees`], run for `duration` chords.
pub(crate) fn plate_at_ten_degrees_for<'a>(duration: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec![
        "aero2d",
        "--model",
        "ns",
        "--section",
        "flat",
        "--plunge-amplitude",
        "0",
        "--mean-pitch-deg",
        "10",
        "--reynolds",
        "200",
        "--duration",
        duration,
        "--ns-around",
        "128",
        "--ns-radial",
        "96",
    ];
    args.extend_from_slice(extra);
    args
}

/// The values of the `.vtu` array named `name` (the points' when
/// `None`: three a point), as written.
fn data_array(text: &str, name: Option<&str>) -> Vec<f64> {
    let start = match name {
        Some(name) => text
            .find(&format!("Name=\"{name}\""))
            .unwrap_or_else(|| panic!("no array {name}")),
        None => text.find("<Points>").expect("no points"),
    };
    let open = start + text[start..].find('>').unwrap() + 1;
    let open = if name.is_none() {
        // `<Points>` then its `<DataArray ...>`.
        open + text[open..].find('>').unwrap() + 1
    } else {
        open
    };
    let close = open + text[open..].find("</DataArray>").unwrap();
    text[open..close]
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect()
}

/// The flat plate at 10° started in a stream (Re 200, 0.3 chords, 128 ×
/// 96 nodes): `--field` writes every node (12,288) and cell (95 rings of
/// cells, 12,160 quadrilaterals).
///
/// Its values are where the solver puts them. The streamfunction is the
/// fluid's velocity's relative to the air at rest far away, so on the
/// wall it is that of a wall translating at `-U` without turning,
/// `ψ = -U y + const` (`u = ∂ψ/∂y`): `ψ + y` is the same at every wall
/// node, in the file's axes, the section pitched (measured spread 8e-17;
/// `ψ - y` spreads by 0.41, twice the wall's height). On the outer ring
/// `ψ = 0`. The wall is the plate pitched 10° nose up in the file's
/// axes: its leftmost node (on the leading edge's rounded end, whose
/// centre is 0.02 c in from the edge) lies above its rightmost by the
/// rise of the ends' centres, `0.96 sin 10°` = 0.1667 (measured 0.1661;
/// held to 0.002, a tenth of the ends' radius: the extreme nodes lie
/// near, not at, the ends' extreme points). VTK's reader finds
/// the same counts, quadrilaterals (type 9) and ranges.
///
/// A file that exists is refused before the run, naming it.
#[test]
fn aero2d_writes_the_flow_field_for_paraview() {
    let dir = crate::program::scratch("viscous-field");
    let path = dir.join("flow.vtu");
    let field = ["--field", path.to_str().unwrap()];
    let out = plate_at_ten_degrees(&field);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&path).unwrap();
    let (around, rings) = (128, 96);
    assert!(text.contains(&format!(
        "NumberOfPoints=\"{}\" NumberOfCells=\"{}\"",
        around * rings,
        around * (rings - 1)
    )));
    let points = data_array(&text, None);
    let psi = data_array(&text, Some("streamfunction"));
    let omega = data_array(&text, Some("vorticity"));
    assert_eq!(points.len(), 3 * around * rings);
    assert_eq!((psi.len(), omega.len()), (around * rings, around * rings));
    assert!(omega.iter().chain(&psi).all(|v| v.is_finite()));
    // The wall ring: ψ + y constant.
    let wall: Vec<f64> = (0..around).map(|k| psi[k] + points[3 * k + 1]).collect();
    let spread =
        wall.iter().fold(f64::MIN, |m, v| m.max(*v)) - wall.iter().fold(f64::MAX, |m, v| m.min(*v));
    assert!(spread < 1e-12, "psi + y on the wall spreads by {spread:e}");
    assert!(psi[around * (rings - 1)..].iter().all(|&p| p == 0.0));
    // Pitched nose up: the wall's leftmost node (the leading edge's end)
    // above its rightmost (the trailing edge's) by the ends' centres'
    // rise.
    let x = |k: usize| points[3 * k];
    let leading = (0..around).min_by(|&a, &b| x(a).total_cmp(&x(b))).unwrap();
    let trailing = (0..around).max_by(|&a, &b| x(a).total_cmp(&x(b))).unwrap();
    let rise = points[3 * leading + 1] - points[3 * trailing + 1];
    let centres = 0.96 * 10f64.to_radians().sin();
    assert!(
        (rise - centres).abs() < 0.002,
        "the leading edge's end {rise} above the trailing edge's, not {centres}"
    );
    vtk_reads_the_field(&path, (around, rings), &omega, &psi);
    let again = plate_at_ten_degrees(&field);
    let e = String::from_utf8_lossy(&again.stderr);
    assert!(
        !again.status.success() && e.contains("--field") && e.contains("exists"),
        "{e}"
    );
    assert_eq!(std::fs::read_to_string(&path).unwrap(), text);
    std::fs::remove_dir_all(&dir).ok();
}

/// The arrays of a binary `.vtu` with an appended raw section (as
/// `--field-series` writes them: a 64-bit length before each array),
/// by name (the points' as `Points`), as `f64`, read by this test
/// itself from the offsets its XML gives.
fn binary_arrays(bytes: &[u8]) -> std::collections::HashMap<String, Vec<f64>> {
    let marker = b"<AppendedData encoding=\"raw\">\n_";
    let start = bytes
        .windows(marker.len())
        .position(|w| w == marker)
        .expect("an appended section")
        + marker.len();
    let xml = std::str::from_utf8(&bytes[..start]).unwrap();
    assert!(xml.contains("header_type=\"UInt64\"") && xml.contains("byte_order=\"LittleEndian\""));
    let attribute = |tag: &str, key: &str| {
        tag.split(&format!("{key}=\""))
            .nth(1)
            .map(|rest| rest[..rest.find('"').unwrap()].to_string())
    };
    let mut arrays = std::collections::HashMap::new();
    for tag in xml.split("<DataArray").skip(1) {
        let tag = &tag[..tag.find("/>").unwrap()];
        let name = attribute(tag, "Name").unwrap_or_else(|| "Points".to_string());
        let offset: usize = attribute(tag, "offset").unwrap().parse().unwrap();
        let at = start + offset;
        let length = u64::from_le_bytes(bytes[at..at + 8].try_into().unwrap()) as usize;
        let data = &bytes[at + 8..at + 8 + length];
        let values: Vec<f64> = match attribute(tag, "type").unwrap().as_str() {
            "Float32" => data
                .chunks_exact(4)
                .map(|c| f64::from(f32::from_le_bytes(c.try_into().unwrap())))
                .collect(),
            "Int32" => data
                .chunks_exact(4)
                .map(|c| f64::from(i32::from_le_bytes(c.try_into().unwrap())))
                .collect(),
            "UInt8" => data.iter().map(|&b| f64::from(b)).collect(),
            other => panic!("unexpected type {other}"),
        };
        arrays.insert(name, values);
    }
    arrays
}

/// The same run as [`aero2d_writes_the_flow_field_for_paraview`] with
/// `--field-series DIR --field-frames 3` and `--field`: `flow.pvd` lists
/// three binary `.vtu`s at 0.1, 0.2 and 0.3 chords travelled (each at
/// the end of the first step that reaches it: within one load sample,
/// 0.3/2000, after), the last at the run's end. Each frame, read by this
/// test from its offsets, has the grid's counts and quadrilaterals and
/// the wall condition `ψ + y` constant round the wall (to single
/// precision, a few units of its last place: held to 1e-7, measured
/// 1.5e-8, against `ψ - y`'s 0.41); the last frame is `--field`'s flow
/// to single precision (within `2^-24` of the largest value: held to
/// 1e-7 of it). VTK's reader reads every frame with the same counts and
/// ranges.
///
/// Refused before the run: the same directory again (it holds the
/// series, left as it was), `--field-frames` without `--field-series`
/// or out of its range (1 to 500), `--field-series` for an inviscid
/// model.
#[test]
fn aero2d_writes_the_flow_as_a_series_paraview_plays() {
    let dir = crate::program::scratch("viscous-series");
    let series = dir.join("series");
    let last = dir.join("last.vtu");
    let (around, rings) = (128, 96);
    let run = plate_at_ten_degrees;
    let series_args = [
        "--field-series",
        series.to_str().unwrap(),
        "--field-frames",
        "3",
    ];
    let mut args = series_args.to_vec();
    args.extend(["--field", last.to_str().unwrap()]);
    let out = run(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let pvd = std::fs::read_to_string(series.join("flow.pvd")).unwrap();
    let entries: Vec<(f64, String)> = pvd
        .lines()
        .filter(|l| l.starts_with("<DataSet"))
        .map(|l| {
            let value = |key: &str| {
                let rest = l.split(&format!("{key}=\"")).nth(1).unwrap();
                rest[..rest.find('"').unwrap()].to_string()
            };
            (value("timestep").parse().unwrap(), value("file"))
        })
        .collect();
    assert_eq!(entries.len(), 3, "{pvd}");
    let sample = 0.3 / 2000.0;
    for (i, (t, file)) in entries.iter().enumerate() {
        let due = 0.1 * (i + 1) as f64;
        assert!(
            *t >= due - 1e-9 && *t <= due + sample,
            "frame {i} at {t}, due at {due}"
        );
        assert_eq!(file, &format!("flow-{i:04}.vtu"));
    }
    let final_text = std::fs::read_to_string(&last).unwrap();
    for (i, (_, file)) in entries.iter().enumerate() {
        let path = series.join(file);
        let arrays = binary_arrays(&std::fs::read(&path).unwrap());
        let (points, psi, omega) = (
            &arrays["Points"],
            &arrays["streamfunction"],
            &arrays["vorticity"],
        );
        assert_eq!(points.len(), 3 * around * rings);
        assert_eq!((psi.len(), omega.len()), (around * rings, around * rings));
        assert_eq!(arrays["connectivity"].len(), 4 * around * (rings - 1));
        assert_eq!(arrays["connectivity"][..4], [0.0, 1.0, 129.0, 128.0]);
        assert!(arrays["types"].iter().all(|&t| t == 9.0));
        assert!(omega.iter().chain(psi).all(|v| v.is_finite()));
        let wall: Vec<f64> = (0..around).map(|k| psi[k] + points[3 * k + 1]).collect();
        let spread = wall.iter().copied().fold(f64::MIN, f64::max)
            - wall.iter().copied().fold(f64::MAX, f64::min);
        assert!(spread < 1e-7, "frame {i}: psi + y spreads by {spread:e}");
        if i == entries.len() - 1 {
            for (name, values) in [
                ("vorticity", omega),
                ("streamfunction", psi),
                ("velocity", &arrays["velocity"]),
            ] {
                let exact = data_array(&final_text, Some(name));
                let largest = exact.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
                let off = exact
                    .iter()
                    .zip(values)
                    .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
                assert!(
                    off <= 1e-7 * largest,
                    "{name}: the last frame {off:e} from --field's (largest {largest:e})"
                );
            }
        }
        vtk_reads_the_field(&path, (around, rings), omega, psi);
    }
    // Refused before the run, nothing written.
    let again = run(&series_args);
    let e = String::from_utf8_lossy(&again.stderr);
    assert!(
        !again.status.success() && e.contains("--field-series") && e.contains("not an empty"),
        "{e}"
    );
    assert_eq!(
        std::fs::read_to_string(series.join("flow.pvd")).unwrap(),
        pvd
    );
    let fresh = dir.join("fresh");
    for (extra, says) in [
        (vec!["--field-frames", "3"], "give that too"),
        (
            vec![
                "--field-series",
                fresh.to_str().unwrap(),
                "--field-frames",
                "0",
            ],
            "between 1 and 500",
        ),
        (
            vec![
                "--field-series",
                fresh.to_str().unwrap(),
                "--field-frames",
                "501",
            ],
            "between 1 and 500",
        ),
    ] {
        let refused = run(&extra);
        let e = String::from_utf8_lossy(&refused.stderr);
        assert!(!refused.status.success() && e.contains(says), "{e}");
    }
    let inviscid = fwav(&[
        "aero2d",
        "--section",
        "flat",
        "--field-series",
        fresh.to_str().unwrap(),
    ]);
    let e = String::from_utf8_lossy(&inviscid.stderr);
    assert!(
        !inviscid.status.success() && e.contains("--model ns only"),
        "{e}"
    );
    assert!(!fresh.exists());
    std::fs::remove_dir_all(&dir).ok();
}

/// `--field`'s velocity against potential flow: a circle of unit
/// diameter started impulsively in a stream (Re 3000, 128 × 96 nodes),
/// after 0.05 chords travelled. Its vorticity is still a thin layer, so
/// outside it the fluid moves as round a circle translating at `-U`
/// through still fluid, a dipole, `u - iv = -U A² / (z - z₀)²` (Batchelor
/// 1967, *An Introduction to Fluid Dynamics*, ch. 6), of the circle's
/// radius grown by the layer's displacement thickness: that of the wall
/// started impulsively, Rayleigh's (Stokes' first) problem, `δ* = 2
/// √(νt/π)` (Schlichting & Gersten, *Boundary-Layer Theory*; it does not
/// depend on the outer speed), 0.0046 c here.
///
/// From 1.1 to 10 radii from the centre the velocity is within 0.006 U
/// of that dipole (measured 0.0039 at 1.1–1.3 radii, 0.0004 beyond 4;
/// the same on 256 × 192), and 0.012 U or more from the bare circle's
/// (measured 0.0169): the check sees the boundary layer's displacement.
#[test]
fn the_fields_velocity_is_the_displaced_circles_potential_flow() {
    let dir = crate::program::scratch("viscous-velocity");
    let circle = crate::viscous_stream::circle_file(&dir);
    let path = dir.join("flow.vtu");
    let (reynolds, time) = (3000.0_f64, 0.05_f64);
    let out = fwav(&[
        "aero2d",
        "--model",
        "ns",
        "--section",
        circle.to_str().unwrap(),
        "--plunge-amplitude",
        "0",
        "--reynolds",
        "3000",
        "--duration",
        "0.05",
        "--ns-around",
        "128",
        "--ns-radial",
        "96",
        "--field",
        path.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&path).unwrap();
    let points = data_array(&text, None);
    let velocity = data_array(&text, Some("velocity"));
    assert_eq!(velocity.len(), points.len());
    let around = 128;
    let centre = (0..around).fold((0.0, 0.0), |(x, y), k| {
        (
            x + points[3 * k] / around as f64,
            y + points[3 * k + 1] / around as f64,
        )
    });
    let radius = 0.5;
    let displacement = 2.0 * (time / reynolds / std::f64::consts::PI).sqrt();
    // The largest distance from the dipole of radius `a`, over the nodes
    // 1.1 to 10 radii out.
    let off_dipole = |a: f64| {
        (0..points.len() / 3)
            .filter_map(|n| {
                let (x, y) = (points[3 * n] - centre.0, points[3 * n + 1] - centre.1);
                let r2 = x * x + y * y;
                let r = r2.sqrt();
                (r > 1.1 * radius && r < 10.0 * radius).then(|| {
                    // u - iv = -a² / z²: z² = (x² - y²) + 2ixy.
                    let (re, im) = (x * x - y * y, 2.0 * x * y);
                    let scale = -a * a / (r2 * r2);
                    let (u, v) = (scale * re, scale * im);
                    (velocity[3 * n] - u).hypot(velocity[3 * n + 1] - v)
                })
            })
            .fold(0.0_f64, f64::max)
    };
    let displaced = off_dipole(radius + displacement);
    let bare = off_dipole(radius);
    assert!(
        displaced < 0.006,
        "{displaced} from the displaced circle's dipole"
    );
    assert!(
        bare > 0.012,
        "{bare} from the bare circle's: no displacement seen"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// A sink that takes `left` frames, then fails as a full disk would.
struct FillsUp {
    left: usize,
}

impl FrameSink for FillsUp {
    fn take(&mut self, _: &FlowField) -> Result<(), Box<dyn std::error::Error + Send + Sync>> {
        if self.left == 0 {
            return Err("no space left on the device".into());
        }
        self.left -= 1;
        Ok(())
    }
}

/// A run hands its sink each frame as it reaches it, not at its end
/// (what lets `--field-series` write each at once and keep a failed run's
/// frames): four frames of 0.2 chords travelled, at 0.05, 0.1, 0.15 and
/// 0.2 (each within one load sample, 0.2/2000, after), the last the run's
/// end flow itself; and a sink that fails on the third frame stops the
/// run there with the frame's time and the sink's reason (`FillsUp`).
#[test]
fn a_run_hands_its_frames_on_as_it_goes() {
    let section = ViscousSection {
        field_frames: 4,
        ..coarse_plate()
    };
    let still = Motion {
        mean_pitch: 10f64.to_radians(),
        ..Motion::plunge(1.0, 0.0)
    };
    let case = Case {
        duration: Some(0.2),
        ..case(SectionModel::Viscous(section), still, 200.0)
    };
    let mut frames: Vec<FlowField> = Vec::new();
    let run = case.run_into(&mut frames).unwrap();
    let times: Vec<f64> = frames.iter().map(|f| f.time).collect();
    assert_eq!(frames.len(), 4, "{times:?}");
    for (i, t) in times.iter().enumerate() {
        let due = 0.05 * (i + 1) as f64;
        assert!(*t >= due - 1e-9 && *t <= due + 0.2 / 2000.0, "{times:?}");
    }
    assert_eq!(frames.last(), run.field.as_ref());
    let e = case.run_into(&mut FillsUp { left: 2 }).unwrap_err();
    match &e {
        CaseError::Viscous(ViscousError::Frame { time, .. }) => {
            assert!((time - times[2]).abs() < 1e-12, "stopped at {time}");
        }
        other => panic!("{other:?}"),
    }
    let message = e.to_string();
    assert!(
        message.contains("could not be kept") && message.contains("no space left"),
        "{message}"
    );
}

/// A run that fails after writing frames keeps them, leaves alone what it
/// did not write, and says where its frames are. The plate of
/// [`plate_at_ten_degrees`] is run for 6 chords with two frames (at 3 and
/// 6 chords, about a second and a half apart here); as soon as the first
/// is on disk the test puts a file where the second goes, as a person or
/// another run might. The run stops there with an error naming that file
/// and the series of the one frame written, and the file is as it was.
#[test]
fn a_run_stopped_after_its_first_frame_says_where_the_frames_are() {
    let dir = crate::program::scratch("series-stopped");
    let series = dir.join("series");
    let series_arg = series.to_str().unwrap();
    let mut child = fwav_command(&plate_at_ten_degrees_for(
        "6",
        &["--field-series", series_arg, "--field-frames", "2"],
    ))
    .stdout(std::process::Stdio::piped())
    .stderr(std::process::Stdio::piped())
    .spawn()
    .expect("the fwav binary runs");
    let first = series.join("flow-0000.vtu");
    let second = series.join("flow-0001.vtu");
    let started = std::time::Instant::now();
    while !first.exists() {
        if let Some(status) = child.try_wait().unwrap() {
            panic!("the run ended ({status}) before its first frame");
        }
        if started.elapsed().as_secs() > 300 {
            child.kill().ok();
            panic!("no first frame in 300 s");
        }
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    std::fs::write(&second, "not the run's").unwrap();
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{stderr}");
    let pvd = series.join("flow.pvd");
    assert!(
        stderr.contains(&format!(
            "the --field-series frames written so far, 1, are in {}",
            pvd.display()
        )),
        "{stderr}"
    );
    assert!(
        stderr.contains(&format!(
            "{} exists, and is left as it is",
            second.display()
        )),
        "{stderr}"
    );
    assert_eq!(std::fs::read_to_string(&second).unwrap(), "not the run's");
    let collection = std::fs::read_to_string(&pvd).unwrap();
    assert!(
        collection.contains("flow-0000.vtu") && !collection.contains("flow-0001.vtu"),
        "{collection}"
    );
    assert!(std::fs::metadata(&first).unwrap().len() > 100_000);
    std::fs::remove_dir_all(&dir).ok();
}
