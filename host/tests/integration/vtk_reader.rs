//! Not a test group: the ParaView files the programs write, read by
//! VTK's own XML reader (Python's `vtk`, the library ParaView reads them
//! with), for the tests that write them.
//!
//! Where Python's `vtk` is not installed the reading is skipped, saying
//! so; on CI (`CI=true`), where `.ci/run` installs it, that fails.

use std::path::Path;
use std::process::Command;

/// What VTK's reader finds in a `.vtu`: its points and cells, the cells'
/// VTK types, and each point and cell array's name, components and
/// range (of its first component).
#[derive(Debug, serde::Deserialize)]
pub struct VtkGrid {
    pub points: usize,
    pub cells: usize,
    pub cell_types: Vec<u8>,
    pub point_arrays: Vec<VtkArray>,
    pub cell_arrays: Vec<VtkArray>,
}

/// One array of a [`VtkGrid`].
#[derive(Debug, serde::Deserialize)]
pub struct VtkArray {
    pub name: String,
    pub components: usize,
    pub range: [f64; 2],
}

impl VtkGrid {
    /// The point array `name`, if there is one.
    pub fn point_array(&self, name: &str) -> Option<&VtkArray> {
        self.point_arrays.iter().find(|a| a.name == name)
    }
}

const SCRIPT: &str = r#"
import json, sys, vtk
r = vtk.vtkXMLUnstructuredGridReader()
r.SetFileName(sys.argv[1])
r.Update()
if r.GetErrorCode() != 0:
    sys.exit("VTK's reader reported error %d" % r.GetErrorCode())
g = r.GetOutput()
def arrays(data):
    out = []
    for i in range(data.GetNumberOfArrays()):
        a = data.GetArray(i)
        lo, hi = a.GetRange(0)
        out.append({"name": a.GetName(), "components": a.GetNumberOfComponents(), "range": [lo, hi]})
    return out
types = sorted({g.GetCellType(i) for i in range(g.GetNumberOfCells())})
print(json.dumps({"points": g.GetNumberOfPoints(), "cells": g.GetNumberOfCells(),
    "cell_types": types, "point_arrays": arrays(g.GetPointData()),
    "cell_arrays": arrays(g.GetCellData())}))
"#;

/// `path` as VTK's reader reads it; `None` (saying so) where Python's
/// `vtk` is not installed. Panics where the reader fails on the file.
pub fn read_vtu(path: &Path) -> Option<VtkGrid> {
    let out = Command::new("python3")
        .args(["-c", SCRIPT, path.to_str().expect("a UTF-8 path")])
        .output();
    let missing = match &out {
        Ok(out) => String::from_utf8_lossy(&out.stderr).contains("No module named 'vtk'"),
        Err(_) => true,
    };
    if missing {
        assert!(
            !std::env::var("CI").is_ok_and(|v| v == "true"),
            "Python's vtk is not installed on CI: .ci/run installs it (pip install vtk)"
        );
        println!(
            "skipped VTK's reader on {}: Python's vtk not found; install it (pip install vtk) \
             to read the file as ParaView does",
            path.display()
        );
        return None;
    }
    let out = out.expect("python3 ran");
    assert!(
        out.status.success(),
        "VTK's reader on {}: {}",
        path.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    Some(serde_json::from_slice(&out.stdout).expect("the reader's JSON"))
}
