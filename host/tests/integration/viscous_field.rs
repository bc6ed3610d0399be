//! `fwav aero2d --model ns --field FILE.vtu`: the flow at the run's end
//! as a file ParaView opens, checked against the wall condition the
//! solver imposes and read back by VTK's own reader.

use crate::viscous_section::fwav;
use crate::vtk_reader::read_vtu;

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
    let dir = std::env::temp_dir().join(format!("fwav-viscous-field-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("flow.vtu");
    let args = [
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
        "0.3",
        "--ns-around",
        "128",
        "--ns-radial",
        "96",
        "--field",
        path.to_str().unwrap(),
    ];
    let out = fwav(&args);
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
    if let Some(read) = read_vtu(&path) {
        let range = |v: &[f64]| {
            [
                v.iter().copied().fold(f64::MAX, f64::min),
                v.iter().copied().fold(f64::MIN, f64::max),
            ]
        };
        assert_eq!(
            (read.points, read.cells, read.cell_types.as_slice()),
            (around * rings, around * (rings - 1), &[9][..]),
            "VTK's reader: quadrilaterals"
        );
        for (name, values) in [("vorticity", &omega), ("streamfunction", &psi)] {
            let array = read.point_array(name).expect(name);
            assert_eq!(
                (array.components, array.range),
                (1, range(values)),
                "{name}"
            );
        }
    }
    let again = fwav(&args);
    let e = String::from_utf8_lossy(&again.stderr);
    assert!(
        !again.status.success() && e.contains("--field") && e.contains("exists"),
        "{e}"
    );
    assert_eq!(std::fs::read_to_string(&path).unwrap(), text);
    std::fs::remove_dir_all(&dir).ok();
}
