//! The `fwav` program as a user runs it (the README's main command among them).

use fwav::discipline::kinematic::EVALUATIONS;

use crate::program::{fwav, fwav_command, fwav_on_terminal};

#[test]
fn readme_main_command_checks_the_initial_design() {
    let out = fwav(&["profile", "check", "host/profiles/initial-design.json"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.contains("valid"), "{stdout}");
    assert!(
        stdout.contains("11.000") && stdout.contains("30.00"),
        "{stdout}"
    );
}

#[test]
fn invalid_profile_is_refused_with_reasons() {
    let dir = std::env::temp_dir().join(format!("fwav-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("too-wide.json");
    std::fs::write(
        &path,
        r#"{"format":"fwav-profile","format_version":1,"segments":[
            {"frequency_hz": 25.0, "amplitude_deg": 50.0, "duration_s": 5.0, "ramp_s": 1.0}]}"#,
    )
    .unwrap();
    let out = fwav(&["profile", "check", path.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr.contains("frequency 25 Hz"), "{stderr}");
    assert!(stderr.contains("amplitude 50.00 deg"), "{stderr}");

    let json = fwav(&["profile", "check", "--json", path.to_str().unwrap()]);
    let report: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    assert_eq!(report["valid"], false);
    assert!(report["errors"].as_array().unwrap().len() >= 2);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn unreadable_and_malformed_files_name_the_file() {
    let out = fwav(&["profile", "check", "no/such/file.json"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot read no/such/file.json"));

    let dir = std::env::temp_dir().join(format!("fwav-cli-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("bad.json");
    std::fs::write(
        &path,
        "{\"format\": \"fwav-profile\",\n \"format_version\": 1,\n \"segmnts\": []}",
    )
    .unwrap();
    let out = fwav(&["profile", "check", path.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr.contains("bad.json") && stderr.contains("segmnts") && stderr.contains("line 3"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn protocol_info_is_json() {
    let out = fwav(&["protocol", "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["protocol_version"], fwav_protocol::PROTOCOL_VERSION);
    assert_eq!(
        v["schema_hash"],
        format!("{:016x}", fwav_protocol::SCHEMA_HASH)
    );
}

#[test]
fn aero2d_reports_thrust_beside_garrick() {
    let out = fwav(&[
        "aero2d",
        "--plunge-amplitude",
        "0.05",
        "--reduced-frequency",
        "1.0",
        "--cycles",
        "4",
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let (ct, garrick) = (
        v["mean_ct"].as_f64().unwrap(),
        v["garrick"]["mean_ct"].as_f64().unwrap(),
    );
    assert!((ct / garrick - 1.0).abs() < 0.10, "{ct} vs {garrick}");
    assert!(v["mean_ct_change_last_two_cycles"].as_f64().unwrap().abs() < 0.02);
    // Net thrust is the inviscid thrust less the skin-friction estimate.
    let (net, friction) = (
        v["mean_ct_net"].as_f64().unwrap(),
        v["mean_cd_friction"].as_f64().unwrap(),
    );
    assert!(friction > 0.0 && (net - (ct - friction)).abs() < 1e-12);

    // --plot draws a PNG.
    let png = std::env::temp_dir().join(format!("fwav-aero2d-{}.png", std::process::id()));
    // A leftover of an earlier run is never drawn over.
    std::fs::remove_file(&png).ok();
    let out = fwav(&["aero2d", "--cycles", "2", "--plot", png.to_str().unwrap()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    let _ = std::fs::remove_file(&png);

    // A deformation file that is not one is named in the error.
    let dir = std::env::temp_dir().join(format!("fwav-aero2d-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("shape.json");
    std::fs::write(
        &file,
        r#"{"format": "fwav-section-history", "format_version": 1,
            "samples": [[[0.0, 0.0], [0.5, 0.01], [0.4, 0.0]]]}"#,
    )
    .unwrap();
    let bad = fwav(&["aero2d", "--deformation", file.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&bad.stderr);
    assert_eq!(bad.status.code(), Some(1));
    assert!(
        err.contains("shape.json") && err.contains("point 2"),
        "{err}"
    );
    // So is one of another format version.
    std::fs::write(
        &file,
        r#"{"format": "fwav-section-history", "format_version": 9, "samples": []}"#,
    )
    .unwrap();
    let bad = fwav(&["aero2d", "--deformation", file.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&bad.stderr);
    assert_eq!(bad.status.code(), Some(1));
    assert!(
        err.contains("shape.json")
            && err.contains("\"format_version\" is 9, this build reads version 1"),
        "{err}"
    );

    // A thick NACA section runs the panel model; a bad name is refused.
    let out = fwav(&["aero2d", "--section", "naca0012", "--cycles", "2", "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["model"], "thick section (panel)");
    let bad = fwav(&["aero2d", "--section", "naca00x2"]);
    assert_eq!(bad.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("NACA 4-digit"));
    let bad = fwav(&["aero2d", "--reduced-frequency=-1"]);
    assert!(String::from_utf8_lossy(&bad.stderr).contains("--reduced-frequency"));
}

/// A thin-line run kept attached whose leading edge would have shed is
/// marked doubtful: past the flat plate's critical suction parameter,
/// 0.11 (`FWAV_LESP_CRITICAL`, after Ramesh, Gopalarathnam, Granlund, Ol &
/// Edwards 2014, J. Fluid Mech. 751), the attached flow is Garrick's
/// theory, not the flow a plate holds. A plunge of 0.2 c at k = 1 kept
/// attached gave CT 0.164 (Garrick 0.151), and 0.056 shedding; a mean
/// pitch of 45 deg gave CL 4.27 and exited 0.
#[test]
fn an_attached_run_past_the_critical_suction_is_doubtful() {
    let run = |extra: &[&str]| {
        let mut args = vec!["aero2d", "--cycles", "4", "--json"];
        args.extend_from_slice(extra);
        let out = fwav(&args);
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        (out, v)
    };
    for pitch in [["--plunge-amplitude", "0.2"], ["--mean-pitch-deg", "45"]] {
        let (out, v) = run(&pitch);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{pitch:?}: {stderr}");
        assert!(
            stderr.contains("leading-edge suction parameter |A0| reached")
                && stderr.contains("give --lesp-critical 0.11"),
            "{stderr}"
        );
        let warnings = v["warnings"].as_array().unwrap();
        assert!(
            warnings
                .iter()
                .any(|w| w.as_str().unwrap().contains("kept attached")),
            "{v}"
        );
    }
    // Shedding beyond it, the same plunge is not doubted.
    let (out, v) = run(&["--plunge-amplitude", "0.2", "--lesp-critical", "0.11"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(v["warnings"], serde_json::json!([]), "{v}");
    // Garrick's plunge of 0.05 c at k = 2 stays below it: attached flow
    // is the model there, and nothing is doubted.
    let (out, v) = run(&["--plunge-amplitude", "0.05", "--reduced-frequency", "2"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(v["warnings"], serde_json::json!([]), "{v}");
}

/// `fwav system-analysis` on a coarse wing: a JSON summary, the files the
/// disciplines take (the section history is read back by `fwav aero2d
/// --deformation`), the ParaView series; a bad field is named.
#[test]
fn system_analysis_writes_what_the_disciplines_take() {
    let dir = crate::program::scratch("system");
    let config = dir.join("wing.toml");
    std::fs::write(
        &config,
        "[wing]\nspan_elements = 12\nchord_elements = 6\n[analysis]\ncycles = 2\nsteps_per_cycle = 16\nchordwise_panels = 3\nspanwise_panels = 6\n[topology]\nmax_cycles = 3\nsimp_iterations = 30\n",
    )
    .unwrap();
    let out_dir = dir.join("out");
    let out = fwav(&[
        "system-analysis",
        "--config",
        config.to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let summary: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(summary["mean_ct"].as_f64().unwrap() > 0.0, "{summary}");
    assert!(summary["tip_deflection_amplitude_m"].as_f64().unwrap() > 0.0);
    // Periodic, the tip well inside the span: nothing doubtful.
    assert_eq!(summary["doubts"], serde_json::json!([]), "{summary}");
    for file in [
        "section.json",
        "pressure.json",
        "steps.csv",
        "wing.pvd",
        "wake.pvd",
        "wing-0000.vtu",
    ] {
        assert!(out_dir.join(file).exists(), "{file}");
    }
    let pressure: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out_dir.join("pressure.json")).unwrap())
            .unwrap();
    let samples = pressure["samples"].as_array().unwrap();
    assert_eq!(samples.len(), 16);
    assert_eq!(samples[0].as_array().unwrap().len(), 72);
    let section = out_dir.join("section.json");
    let aero = fwav(&[
        "aero2d",
        "--deformation",
        section.to_str().unwrap(),
        "--cycles",
        "2",
        "--lesp-critical",
        "0.11",
        "--json",
    ]);
    assert!(
        aero.status.success(),
        "{}",
        String::from_utf8_lossy(&aero.stderr)
    );

    // The structural discipline takes the pressure history.
    let topology_dir = dir.join("topology");
    let pressure_file = out_dir.join("pressure.json");
    let topology = fwav(&[
        "topology",
        "--config",
        config.to_str().unwrap(),
        "--pressure",
        pressure_file.to_str().unwrap(),
        "--out",
        topology_dir.to_str().unwrap(),
        "--json",
    ]);
    assert!(
        topology.status.success(),
        "{}",
        String::from_utf8_lossy(&topology.stderr)
    );
    let summary: serde_json::Value = serde_json::from_slice(&topology.stdout).unwrap();
    let cycles = summary["cycles"].as_array().unwrap();
    assert!(!cycles.is_empty() && cycles.len() <= 3, "{summary}");
    assert!(cycles[0]["strain_energy_j"].as_f64().unwrap() > 0.0);
    assert!(summary["converged"].is_boolean());
    for file in ["layout.vtu", "layout.png", "cycles.csv", "topology.json"] {
        assert!(topology_dir.join(file).exists(), "{file}");
    }
    // The wing's time series as ParaView opens it: `wing.pvd` lists its
    // steps' files, each there, at times that increase.
    let pvd = std::fs::read_to_string(out_dir.join("wing.pvd")).unwrap();
    let steps: Vec<(f64, String)> = pvd
        .lines()
        .filter_map(|l| {
            let field = |key: &str| {
                let start = l.find(&format!("{key}=\""))? + key.len() + 2;
                Some(l[start..start + l[start..].find('"')?].to_string())
            };
            Some((field("timestep")?.parse().ok()?, field("file")?))
        })
        .collect();
    assert!(steps.len() > 1, "{pvd}");
    assert!(steps.windows(2).all(|w| w[0].0 < w[1].0), "{pvd}");
    assert!(
        steps.iter().all(|(_, f)| out_dir.join(f).is_file()),
        "{pvd}"
    );
    let last = out_dir.join(&steps.last().unwrap().1);
    // The ParaView files as VTK's own reader reads them: the wing's
    // 12 x 6 shell elements as quadrilaterals (type 9) on its 13 x 7
    // nodes at its first and last steps, with the pressure jump on the
    // wing (finite) and the layout's fields, fractions in [0, 1].
    for (vtu, arrays) in [
        (out_dir.join(&steps[0].1), &["pressure_jump_pa"][..]),
        (last, &["pressure_jump_pa"][..]),
        (
            topology_dir.join("layout.vtu"),
            &["carbon", "simp_density", "design_domain"][..],
        ),
    ] {
        let Some(grid) = crate::vtk_reader::read_vtu(&vtu) else {
            continue;
        };
        assert_eq!(
            (grid.points, grid.cells, grid.cell_types.as_slice()),
            (13 * 7, 12 * 6, &[9][..]),
            "{}",
            vtu.display()
        );
        let names: Vec<&str> = grid.cell_arrays.iter().map(|a| a.name.as_str()).collect();
        assert_eq!(names, arrays, "{}", vtu.display());
        for a in &grid.cell_arrays {
            let [lo, hi] = a.range;
            let fraction = (0.0..=1.0).contains(&lo) && (0.0..=1.0).contains(&hi);
            assert!(
                if a.name == "pressure_jump_pa" {
                    lo.is_finite() && hi.is_finite()
                } else {
                    fraction
                },
                "{}: {a:?}",
                vtu.display()
            );
        }
    }
    // A pressure history for another mesh is refused, naming the file.
    std::fs::write(
        &pressure_file,
        r#"{"format": "fwav-pressure-history", "format_version": 1, "dt_s": 0.01, "samples": [[1.0, 2.0]]}"#,
    )
    .unwrap();
    let bad = fwav(&[
        "topology",
        "--config",
        config.to_str().unwrap(),
        "--pressure",
        pressure_file.to_str().unwrap(),
        "--out",
        dir.join("refused").to_str().unwrap(),
    ]);
    assert!(!bad.status.success());
    let stderr = String::from_utf8_lossy(&bad.stderr);
    assert!(
        stderr.contains("pressure.json") && stderr.contains("72 elements"),
        "{stderr}"
    );

    std::fs::write(&config, "[kinematics]\namplitude_deg = 120\n").unwrap();
    let bad = fwav(&["system-analysis", "--config", config.to_str().unwrap()]);
    assert!(!bad.status.success());
    let stderr = String::from_utf8_lossy(&bad.stderr);
    assert!(stderr.contains("kinematics.amplitude_deg"), "{stderr}");
    std::fs::remove_dir_all(&dir).ok();
}

/// `fwav kinematics`: the discipline on the built-in rigid section, JSON
/// out, its evaluations kept in a cache file and all reused by a rerun; a
/// bad `[design]` level set is named.
#[test]
fn kinematics_runs_the_discipline_and_reuses_its_evaluations() {
    let dir = crate::program::scratch("kinematics");
    let cache = dir.join("evaluations.json");
    let run = || {
        let out = fwav(&["kinematics", "--cache", cache.to_str().unwrap(), "--json"]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice::<serde_json::Value>(&out.stdout).unwrap()
    };
    let first = run();
    assert_eq!(first["evaluations_reused"], 0);
    assert_eq!(first["result"]["runs"].as_array().unwrap().len(), 18);
    assert_eq!(first["result"]["candidates"].as_array().unwrap().len(), 3);
    let entries = || {
        let text = std::fs::read_to_string(&cache).unwrap();
        let file: serde_json::Value = serde_json::from_str(&text).unwrap();
        file["entries"].as_object().unwrap().len() as u64
    };
    // Every distinct design evaluated once (at least the 18 rows; a
    // candidate that is an array row is not run twice), all reused by the
    // rerun, which adds nothing.
    let stored = entries();
    assert!(stored >= 18, "{stored} cached evaluations");
    let second = run();
    assert_eq!(second["evaluations_reused"].as_u64().unwrap(), stored);
    assert_eq!(entries(), stored);
    assert_eq!(first["result"]["chosen"], second["result"]["chosen"]);
    let plots = dir.join("plots");
    let out = fwav(&[
        "kinematics",
        "--cache",
        cache.to_str().unwrap(),
        "--plot",
        plots.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for png in ["main-effects.png", "pareto.png"] {
        assert!(
            std::fs::metadata(plots.join(png)).unwrap().len() > 1000,
            "{png}"
        );
    }

    let config = dir.join("bad.toml");
    std::fs::write(&config, "[design]\namplitude_deg = [40.0, 30.0, 20.0]\n").unwrap();
    let bad = fwav(&["kinematics", "--config", config.to_str().unwrap()]);
    assert!(!bad.status.success());
    let stderr = String::from_utf8_lossy(&bad.stderr);
    assert!(stderr.contains("design.amplitude_deg"), "{stderr}");
    std::fs::remove_dir_all(&dir).ok();
}

/// Two `fwav kinematics` runs at once keeping their evaluations in one
/// cache file, on different frequency levels (so neither can serve the
/// other's rows): the file ends with every evaluation of both, so a rerun
/// of each finds all it evaluates there, adds nothing and answers as
/// before. Before the cache's writes merged under a
/// lock, the run that wrote last replaced the other's results (and two
/// writes at once could leave a file mixed of both).
#[test]
fn kinematics_runs_sharing_a_cache_keep_each_others_evaluations() {
    let dir = crate::program::scratch("kinematics-shared");
    let cache = dir.join("evaluations.json");
    let configs: Vec<_> = [[9.0, 11.0, 13.0], [8.0, 10.0, 12.0]]
        .iter()
        .enumerate()
        .map(|(i, levels)| {
            let path = dir.join(format!("run{i}.toml"));
            std::fs::write(
                &path,
                format!(
                    "[design]\nsection_cycles = 3\nfrequency_hz = [{}, {}, {}]\n",
                    levels[0], levels[1], levels[2]
                ),
            )
            .unwrap();
            path
        })
        .collect();
    let run = |config: &std::path::Path, cache: &std::path::Path| {
        fwav_command(&[
            "kinematics",
            "--json",
            "--config",
            config.to_str().unwrap(),
            "--cache",
            cache.to_str().unwrap(),
        ])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("the fwav binary runs")
    };
    let answer = |child: std::process::Child| {
        let out = child.wait_with_output().unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice::<serde_json::Value>(&out.stdout).unwrap()
    };
    let entries = |path: &std::path::Path| {
        let text = std::fs::read_to_string(path).unwrap();
        let file: serde_json::Value = serde_json::from_str(&text).unwrap();
        file["entries"].clone()
    };
    let together: Vec<_> = configs.iter().map(|c| run(c, &cache)).collect();
    let answers: Vec<_> = together.into_iter().map(answer).collect();
    let kept = entries(&cache);
    assert!(kept.as_object().unwrap().len() >= 36, "{kept}");
    // Each run again: all it evaluates is in the file (nothing is added),
    // it answers as before, and it counts as reused its own evaluations,
    // not the file's (which holds the other run's too).
    for (config, first) in configs.iter().zip(&answers) {
        let again = answer(run(config, &cache));
        assert_eq!(again["result"]["chosen"], first["result"]["chosen"]);
        assert_eq!(entries(&cache), kept);
        let result = &again["result"];
        let own: std::collections::HashSet<String> = std::iter::once(&result["initial"])
            .chain(result["runs"].as_array().unwrap())
            .chain(
                result["candidates"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|c| &c["confirmation"]),
            )
            .map(|e| e["design"].to_string())
            .collect();
        assert_eq!(again["evaluations_reused"], own.len());
        assert!(own.len() < kept.as_object().unwrap().len());
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// The long runs show how far they have come on a terminal, and nothing
/// off one: `fwav kinematics` a bar of its 2D evaluations (with the
/// Navier–Stokes model a run is about half an hour), `fwav aero2d --model
/// ns` the chords travelled, each from its start. Each bar is cleared at
/// the end, and the results on standard output are the same as off a
/// terminal.
#[test]
fn long_runs_show_their_progress_on_a_terminal() {
    let dir = crate::program::scratch("progress");
    let config = dir.join("quick.toml");
    std::fs::write(&config, "[design]\nsection_cycles = 3\n").unwrap();
    let plate = crate::viscous_field::plate_at_ten_degrees_for("2", &[]);
    let kinematics = ["kinematics", "--config", config.to_str().unwrap()];
    // How far each redraw says the run is: the chords before " of", the
    // evaluations before "/21" (of EVALUATIONS).
    let chords = |redraw: &str| -> f64 {
        let head = &redraw[..redraw.find(" of 2.00").unwrap()];
        head.rsplit(' ').next().unwrap().parse().unwrap()
    };
    let total = format!("/{EVALUATIONS}");
    let evaluations = |redraw: &str| -> f64 {
        let head = &redraw[..redraw.find(&total).unwrap()];
        head.rsplit(' ').next().unwrap().parse().unwrap()
    };
    for (args, shown, done) in [
        (
            &plate[..],
            " of 2.00 chords travelled",
            &chords as &dyn Fn(&str) -> f64,
        ),
        (&kinematics[..], " 2D evaluation ", &evaluations),
    ] {
        let (out, terminal) = fwav_on_terminal(args, 100);
        assert!(out.status.success(), "{terminal}");
        // Redrawn in place: each redraw starts with a carriage return,
        // and says the run is further on (or as far).
        let progress: Vec<f64> = terminal
            .split('\r')
            .filter(|piece| piece.contains(shown))
            .map(done)
            .collect();
        assert!(
            progress.len() >= 2 && progress.windows(2).all(|w| w[0] <= w[1]),
            "{progress:?} in {terminal:?}"
        );
        assert!(progress[progress.len() - 1] > progress[0], "{progress:?}");
        // Saying so from the start, before the first step's end (a fine
        // grid's first load sample may be minutes away).
        assert_eq!(progress[0], 0.0, "{terminal:?}");
        // Cleared at the end.
        assert!(terminal.trim_end().ends_with("\x1b[2K"), "{terminal:?}");
        let off = fwav(args);
        assert!(off.status.success());
        assert!(
            off.stderr.is_empty(),
            "{}",
            String::from_utf8_lossy(&off.stderr)
        );
        let without_time = |text: &[u8]| {
            String::from_utf8_lossy(text)
                .lines()
                .filter(|l| !l.ends_with("evaluations reused"))
                .map(str::to_string)
                .collect::<Vec<_>>()
        };
        assert_eq!(without_time(&out.stdout), without_time(&off.stdout));
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `fwav actuator` on a design file and on a plant file: the margins are
/// `1 - value / limit`, the limiting one is the smallest, the verdict is
/// "every margin at least the reserve"; on the design file's wing with no
/// spring the peak current is at least the inertial one, `(J_wing + N^2
/// J_rotor) A w^2 / (N K_t)`, with the wing's inertia in closed form
/// (`mu (c_r L^3/3 - (c_r - c_t) L^3/4)` for the built-in tapered wing,
/// full carbon layer: mu = 2001.2 * 0.5e-3 + 1400.6 * 0.1e-3 kg/m^2); and a
/// bad key is refused by name.
#[test]
fn actuator_prints_margins_limiting_and_verdict() {
    let dir = std::env::temp_dir().join(format!("fwav-actuator-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let config = dir.join("fwav.toml");
    std::fs::write(
        &config,
        "[actuator]\nspring = \"fixed\"\nspring_nm_per_rad = 0.0\n",
    )
    .unwrap();
    let args = [
        "actuator",
        "--config",
        config.to_str().unwrap(),
        "--frequency-hz",
        "11",
        "--amplitude-deg",
        "30",
        "--mean-deg",
        "-5",
        "--json",
    ];
    let out = fwav(&args);
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let r: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let v = &r["verdict"];
    let reserve = v["reserve"].as_f64().unwrap();
    let mut least = f64::INFINITY;
    for q in ["torque", "current", "voltage"] {
        let m = &v[q];
        let (value, limit, margin) = (
            m["value"].as_f64().unwrap(),
            m["limit"].as_f64().unwrap(),
            m["margin"].as_f64().unwrap(),
        );
        assert!((margin - (1.0 - value / limit)).abs() < 1e-12, "{m}");
        least = least.min(margin);
    }
    assert_eq!(v["limiting"]["margin"].as_f64().unwrap(), least);
    assert_eq!(v["feasible"].as_bool().unwrap(), least >= reserve);
    // Without a spring the drive cannot fly it (the current's margin is
    // -67.5%): the verdict is printed, and the status says no.
    assert!(least < reserve, "{v}");
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("error: the actuator cannot fly 11.000 Hz")
            && stderr.contains("below the reserve of 10.0%"),
        "{stderr}"
    );
    let (cr, ct, l) = (0.075f64, 0.045f64, 0.15f64);
    let mu = 2001.2 * 0.5e-3 + 1400.6 * 0.1e-3;
    let wing = mu * (cr * l.powi(3) / 3.0 - (cr - ct) * l.powi(3) / 4.0);
    let vehicle = &r["vehicle"];
    let got = vehicle["wing_inertia_kg_m2"].as_f64().unwrap();
    assert!((got / wing - 1.0).abs() < 1e-9, "{got} vs {wing}");
    let act = &vehicle["actuator"];
    let n = act["gear_ratio"].as_f64().unwrap();
    let kt = act["motor"]["torque_constant_nm_per_a"].as_f64().unwrap();
    let j = wing + n * n * act["motor"]["rotor_inertia_kg_m2"].as_f64().unwrap();
    let w = 2.0 * std::f64::consts::PI * 11.0;
    let inertial = j * 30f64.to_radians() * w * w / (n * kt);
    let current = v["current"]["value"].as_f64().unwrap();
    assert!(current >= inertial, "{current} A < inertial {inertial} A");
    assert!(r["tuned_spring"]["peak_current_saved_a"].as_f64().unwrap() > 0.0);

    let out = fwav(&[
        "actuator",
        "--plant",
        "actuator/plant.toml",
        "--frequency-hz",
        "11",
        "--amplitude-deg",
        "30",
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for line in [
        "motor torque",
        "motor current",
        "terminal voltage",
        "limiting: ",
        "verdict: ",
    ] {
        assert!(stdout.contains(line), "{line}: {stdout}");
    }

    // A gear ratio below the flight controller's least (1): the file's
    // range is the device's since 2026-12-07 ((0, inf) before).
    std::fs::write(&config, "[actuator]\ngear_ratio = 0.5\n").unwrap();
    let out = fwav(&[
        "actuator",
        "--config",
        config.to_str().unwrap(),
        "--frequency-hz",
        "11",
        "--amplitude-deg",
        "30",
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(
        stderr.contains("actuator.gear_ratio = 0.5 is outside [1, 1000]"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
