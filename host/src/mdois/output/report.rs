//! `report.md`: the design run for a person — how it ended, every cycle's
//! numbers (the ones of `summary.json`), the initial design against the
//! final one, and links to the pictures and ParaView files.

use std::fmt::Write as _;

use crate::mdois::profile::ActuatorCheck;
use crate::mdois::summary::Summary;

/// A number with `digits` decimals, or "–" when missing or not finite.
fn num(value: Option<f64>, digits: usize) -> String {
    match value {
        Some(v) if v.is_finite() => format!("{v:.digits$}"),
        _ => "–".to_string(),
    }
}

/// A relative change in percent with its sign.
fn percent(value: f64) -> String {
    if value.is_finite() {
        format!("{:+.1}%", 100.0 * value)
    } else {
        "–".to_string()
    }
}

/// The report of `summary`; `pictures` are the PNG files written (name,
/// caption), `cycle_files` the `wing-cycle-N.vtu` files.
pub fn markdown(summary: &Summary, pictures: &[(&str, &str)], cycle_files: &[String]) -> String {
    let mut s = String::new();
    // Writing to a String cannot fail.
    let _ = writeln!(s, "# fwav design run\n");
    ending(&mut s, summary);
    cycles(&mut s, summary);
    disciplines(&mut s, summary);
    section_models(&mut s, summary);
    initial_and_final(&mut s, summary);
    if let Some(a) = &summary.actuator {
        actuator(&mut s, a);
    }
    picture_list(&mut s, pictures);
    file_list(&mut s, cycle_files);
    s
}

/// How the run ended, and what it cost.
fn ending(s: &mut String, summary: &Summary) {
    let ran = summary.cycles.len();
    let ending = match (summary.outcome.as_str(), summary.converged_cycle) {
        ("converged", Some(c)) => format!(
            "**Converged in cycle {c}**: no design variable changed in that cycle's disciplines (kinematics within {:.1}% of each level range, layout: at most {:.1}% of the design elements changed). The final design is the one cycle {c} analysed.",
            100.0 * summary.kinematics_tolerance_of_range,
            100.0 * summary.layout_tolerance,
        ),
        ("cycle cap reached", _) => format!(
            "**Not converged: the cycle cap of {} was reached** with the design still changing in cycle {}. Cycle {} is the system analysis of that last proposal, reported as the final design; it is not a converged design.",
            summary.max_cycles, summary.max_cycles, summary.max_cycles + 1
        ),
        _ => "**Unfinished**: the run stopped before its end; `fwav design --resume DIR` continues it.".to_string(),
    };
    let _ = writeln!(
        s,
        "{ending}\n\n{ran} cycle(s) begun, {} invocation(s) of the driver, {:.1} s of stage time. The configuration is [config.toml](config.toml); every number below is in [summary.json](summary.json).\n",
        summary.runs, summary.stage_seconds
    );
}

/// The design analysed in each cycle and its 3D system analysis.
fn cycles(s: &mut String, summary: &Summary) {
    let _ = writeln!(s, "## Cycles\n");
    let _ = writeln!(
        s,
        "Design analysed in each cycle and its 3D system analysis:\n\n| cycle | frequency, Hz | amplitude, deg | mean angle, deg | stroke plane, deg | carbon mass fraction | CT | CP | efficiency | wing mass, g | time, s |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
    );
    for c in &summary.cycles {
        let k = &c.kinematics;
        let sys = c.system.as_ref();
        let _ = writeln!(
            s,
            "| {} | {:.3} | {:.2} | {:.2} | {:.2} | {:.3} | {} | {} | {} | {} | {} |",
            c.cycle,
            k.frequency,
            k.amplitude_deg(),
            k.mean_angle_deg(),
            k.stroke_plane_deg(),
            c.carbon_mass_fraction,
            num(sys.map(|s| s.ct), 4),
            num(sys.map(|s| s.cp), 4),
            num(sys.map(|s| s.efficiency), 4),
            num(sys.map(|s| 1e3 * s.wing_mass_kg), 3),
            num(sys.map(|s| s.seconds), 1),
        );
    }
}

/// Each cycle's disciplines: the proposed kinematics and the new layout.
fn disciplines(s: &mut String, summary: &Summary) {
    let _ = writeln!(
        s,
        "\nThe disciplines of each cycle (2D values on the mid-span section; strain energy of the analysed design under the cycle's pressure history):\n\n| cycle | chosen | proposed f, Hz | A, deg | mean, deg | stroke, deg | 2D CT | 2D efficiency | kinematics moved (of range) | strain energy, J | new mass fraction | elements changed | ESLSO cycles | unchanged | times, s (aero / struct) |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
    );
    for c in &summary.cycles {
        let (Some(a), Some(t)) = (&c.aerodynamic, &c.structural) else {
            continue;
        };
        let p = &a.proposed;
        let d = c.change.as_ref();
        let _ = writeln!(
            s,
            "| {} | {} | {:.3} | {:.2} | {:.2} | {:.2} | {} | {} | {} | {} | {:.3} | {} | {}{} | {} | {:.1} / {:.1} |",
            c.cycle,
            a.chosen.as_deref().unwrap_or("none (kept)"),
            p.frequency,
            p.amplitude_deg(),
            p.mean_angle_deg(),
            p.stroke_plane_deg(),
            num(a.proposed_2d.map(|r| r.ct), 4),
            num(a.proposed_2d.map(|r| r.efficiency), 4),
            d.map_or("–".into(), |d| format!(
                "{:.1}%",
                100.0 * d.kinematics_change_of_range
            )),
            num(Some(t.strain_energy_j), 6),
            t.mass_fraction,
            t.elements_changed,
            t.eslso_cycles,
            if t.eslso_converged { "" } else { " (cap)" },
            d.map_or("–", |d| if d.design_unchanged { "yes" } else { "no" }),
            a.seconds,
            t.seconds,
        );
    }
}

/// The section model of each cycle's 2D evaluations, and what it left
/// out (said, never silent: the Navier–Stokes model's rigid section).
fn section_models(s: &mut String, summary: &Summary) {
    let notes: Vec<(usize, &str, f64)> = summary
        .cycles
        .iter()
        .filter_map(|c| {
            let a = c.aerodynamic.as_ref()?;
            Some((
                c.cycle,
                a.section.as_ref()?.note.as_str(),
                a.adoption_margin,
            ))
        })
        .collect();
    if notes.is_empty() {
        return;
    }
    let _ = writeln!(
        s,
        "
The 2D section model of each cycle's evaluations:
"
    );
    for (cycle, note, margin) in notes {
        let _ = write!(s, "- cycle {cycle}: {note}");
        if margin > 0.0 {
            let _ = write!(
                s,
                "; a candidate had to beat the analysed design's combined objective by \
                 {margin:.3}, the scatter of two runs (the scores move with the time step, or \
                 from stroke to stroke)"
            );
        }
        let _ = writeln!(s);
    }
}

/// The initial design against the final one, once the run is over.
fn initial_and_final(s: &mut String, summary: &Summary) {
    let _ = writeln!(s, "\n## Initial and final design\n");
    match (&summary.initial, &summary.final_design, &summary.comparison) {
        (Some(i), Some(f), Some(c)) => {
            let _ = writeln!(
                s,
                "| | cycle | frequency, Hz | amplitude, deg | mean angle, deg | stroke plane, deg | carbon mass fraction | CT | CP | efficiency | wing mass, g |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
            );
            for (name, p) in [("initial", i), ("final", f)] {
                let k = &p.kinematics;
                let _ = writeln!(
                    s,
                    "| {name} | {} | {:.3} | {:.2} | {:.2} | {:.2} | {:.3} | {:.4} | {:.4} | {:.4} | {:.3} |",
                    p.cycle,
                    k.frequency,
                    k.amplitude_deg(),
                    k.mean_angle_deg(),
                    k.stroke_plane_deg(),
                    p.carbon_mass_fraction,
                    p.ct,
                    p.cp,
                    p.efficiency,
                    1e3 * p.wing_mass_kg
                );
            }
            let _ = writeln!(
                s,
                "\nChange from the initial design: CT {}, CP {}, efficiency {}, wing mass {}.",
                percent(c.ct_relative_change),
                percent(c.cp_relative_change),
                percent(c.efficiency_relative_change),
                percent(c.wing_mass_relative_change)
            );
        }
        _ => {
            let _ = writeln!(s, "Not available until the run is over.");
        }
    }
}

/// The actuator check of the final kinematics.
fn actuator(s: &mut String, a: &ActuatorCheck) {
    let _ = writeln!(s, "\n## Actuator\n");
    let margins: Vec<String> = a
        .margins
        .iter()
        .map(|m| {
            format!(
                "{} {:.4} {} of {:.4} {} (margin {:.1}%)",
                m.quantity,
                m.value,
                m.unit,
                m.limit,
                m.unit,
                100.0 * m.margin
            )
        })
        .collect();
    let vehicle = format!(
        "the designed vehicle ([plant.toml](plant.toml): wing {:.2} g, inertia {:.4e} kg m^2, aerodynamic damping {:.4e} N m s^2 from the final system analysis, spring {:.4} N m/rad, on the design file's [actuator])",
        1e3 * a.wing_mass_kg,
        a.wing_inertia_kg_m2,
        a.aero_damping_nms2,
        a.spring_nm_per_rad
    );
    let verdict = if a.feasible {
        format!(
            "The final design's kinematics, which [kinematics.json](kinematics.json) flies ({} Hz, {} deg amplitude, {} deg mean), are **feasible** on {vehicle}: every margin at least {:.0}%, limiting: {}.",
            a.frequency_hz,
            a.amplitude_deg,
            a.mean_angle_deg,
            100.0 * a.reserve,
            a.limiting.quantity,
        )
    } else {
        format!(
            "The final design's kinematics, which [kinematics.json](kinematics.json) flies ({} Hz, {} deg amplitude, {} deg mean), are **not feasible** with the {:.0}% reserve on {vehicle} (limiting: {}, {:.4} {} against {:.4} {}); the discipline judged them on the previous cycle's damping.",
            a.frequency_hz,
            a.amplitude_deg,
            a.mean_angle_deg,
            100.0 * a.reserve,
            a.limiting.quantity,
            a.limiting.value,
            a.limiting.unit,
            a.limiting.limit,
            a.limiting.unit,
        )
    };
    let _ = writeln!(
        s,
        "{verdict}\n\nMargins of the final design: {}.",
        margins.join("; ")
    );
}

/// The pictures written, with their captions.
fn picture_list(s: &mut String, pictures: &[(&str, &str)]) {
    if !pictures.is_empty() {
        let _ = writeln!(s, "\n## Pictures\n");
        for (file, caption) in pictures {
            let _ = writeln!(s, "{caption}\n\n![{caption}]({file})\n");
        }
    }
}

/// Links to the ParaView files and the stages' files.
fn file_list(s: &mut String, cycle_files: &[String]) {
    let _ = writeln!(s, "## Files\n");
    let _ = writeln!(
        s,
        "- [topology.vtu](topology.vtu): the final layout on the wing mesh (ParaView; `carbon` 1/0, `simp_density`, `design_domain`)."
    );
    for f in cycle_files {
        let _ = writeln!(
            s,
            "- [{f}]({f}): the layout after that cycle (`carbon`, `carbon_analysed`, `simp_density`, `mean_pressure_jump_pa`)."
        );
    }
    let _ = writeln!(
        s,
        "- `cycle-N/`: each stage's files (`system.json`, `section.json`, `pressure.json`, `steps.csv`, `kinematics.json`, `topology.json`); [state.json](state.json) says which are finished."
    );
}
