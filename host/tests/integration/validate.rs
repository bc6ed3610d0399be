//! `fwav validate` as a user runs it: a fast subset of the validation
//! cases (the shell family, about a second) as JSON, the table, the case
//! list and a filter that matches nothing.

use crate::program::fwav;

/// The JSON array of the shell cases: every case has the documented keys,
/// passes, and its error is what its value and reference say.
#[test]
fn shell_cases_pass_as_json() {
    let out = fwav(&["validate", "--only", "shell/", "--json"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // Not a terminal: no progress lines.
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let cases: Vec<serde_json::Value> = serde_json::from_slice(&out.stdout).unwrap();
    let names: Vec<&str> = cases.iter().filter_map(|c| c["name"].as_str()).collect();
    assert_eq!(names.len(), cases.len());
    assert!(names.len() >= 8, "{names:?}");
    assert!(names.contains(&"shell/scordelis-lo-roof"), "{names:?}");
    for c in &cases {
        for key in [
            "name",
            "solver",
            "reference",
            "quantity",
            "units",
            "value",
            "reference_value",
            "error_kind",
            "error",
            "tolerance",
            "pass",
            "note",
            "failure",
            "run_time_s",
        ] {
            assert!(c.get(key).is_some(), "{key} missing in {c}");
        }
        assert_eq!(c["solver"], "shell");
        assert!(c["name"].as_str().unwrap().starts_with("shell/"));
        assert_eq!(c["pass"], true, "{c}");
        assert!(c["failure"].is_null());
        let (value, reference, error, tolerance) = (
            c["value"].as_f64().unwrap(),
            c["reference_value"].as_f64().unwrap(),
            c["error"].as_f64().unwrap(),
            c["tolerance"].as_f64().unwrap(),
        );
        let expected = match c["error_kind"].as_str().unwrap() {
            "relative" => value / reference - 1.0,
            "absolute" => value - reference,
            other => panic!("error kind {other}"),
        };
        assert!((error - expected).abs() < 1e-12, "{c}");
        assert!(error.abs() < tolerance, "{c}");
        assert!(!c["reference"].as_str().unwrap().is_empty());
    }
}

/// The table names each case with PASS, and the summary counts them.
#[test]
fn table_and_list() {
    let out = fwav(&["validate", "--only", "optimizers/l18"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}");
    assert!(stdout.contains("tolerance"), "{stdout}");
    assert!(
        stdout
            .lines()
            .any(|l| l.starts_with("optimizers/l18-orthogonality") && l.contains("PASS")),
        "{stdout}"
    );
    assert!(stdout.contains("1 of 1 cases passed"), "{stdout}");

    let out = fwav(&["validate", "--list"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success());
    for family in ["aero2d/", "shell/", "uvlm/", "optimizers/"] {
        assert!(
            stdout.lines().any(|l| l.starts_with(family)),
            "{family}: {stdout}"
        );
    }
}

/// A filter that matches no case is refused (exit 1) with a hint.
#[test]
fn unknown_filter_is_refused() {
    let out = fwav(&["validate", "--only", "no-such-case"]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("no-such-case") && stderr.contains("--list"),
        "{stderr}"
    );
}

/// An empty filter is refused at once: every name contains the empty
/// text, so until 2026-12-07 `--only ""` ran every case (over a minute
/// before it was stopped by hand) instead of saying what to give.
#[test]
fn an_empty_filter_is_refused() {
    for empty in ["", " "] {
        let out = fwav(&["validate", "--only", empty]);
        assert_eq!(out.status.code(), Some(1));
        assert!(out.stdout.is_empty());
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            stderr.contains("part of a case's name") && stderr.contains("--list"),
            "{stderr}"
        );
    }
}
