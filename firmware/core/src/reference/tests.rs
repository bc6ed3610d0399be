//! Tests of the reference generator.

use super::*;
use fwav_protocol::Segment;

const DEG: f32 = PI / 180.0;
const DT: f32 = 1e-4; // 10 kHz control rate
const L: Limits = Limits::REFERENCE_FWAV;

fn profile(segs: &[Segment], on_end: EndAction) -> Profile {
    let p = Profile::from_segments(segs, on_end).unwrap();
    assert_eq!(p.validate(&L), Ok(()), "test profiles are valid");
    p
}

/// Runs the generator for `t` seconds; returns (time, reference, segment).
fn run(g: &mut ReferenceGenerator, t: f32) -> std::vec::Vec<(f32, Reference, Option<usize>)> {
    let n = (t / DT) as usize;
    (0..n)
        .map(|i| {
            let r = g.waveform().evaluate(0.0, 1.0);
            let seg = g.active_segment();
            g.advance(DT);
            (i as f32 * DT, r, seg)
        })
        .collect()
}

/// 11 Hz/30 deg -> 14 Hz/20 deg with a mean change and a split cycle,
/// repeating: every kind of ramp, and the wrap-around.
fn two_segments() -> Profile {
    profile(
        &[
            Segment::symmetric(11.0, 30.0 * DEG, 0.0, 2.0, 1.0),
            Segment {
                frequency_hz: 14.0,
                amplitude_rad: 20.0 * DEG,
                mean_rad: 5.0 * DEG,
                duration_s: 2.0,
                ramp_s: 0.5,
                downstroke_fraction: 0.55,
            },
        ],
        EndAction::Repeat,
    )
}

#[test]
fn angle_and_rate_are_continuous_across_segment_changes() {
    let mut g = ReferenceGenerator::new();
    g.start(&two_segments(), &L);
    let trace = run(&mut g, 8.5);
    let changes = trace.windows(2).filter(|w| w[0].2 != w[1].2).count();
    assert!(
        changes >= 4,
        "the run crosses segment changes and the wrap-around"
    );
    let max_rate = trace.iter().map(|s| s.1.rate.abs()).fold(0.0, f32::max);
    let max_accel = trace.iter().map(|s| s.1.accel.abs()).fold(0.0, f32::max);
    for w in trace.windows(2) {
        let (a, b) = (&w[0].1, &w[1].1);
        // A step in angle or a jump in rate would exceed these bounds by
        // orders of magnitude; 5% covers the discretization.
        assert!(
            (b.angle - a.angle).abs() <= 1.05 * max_rate * DT,
            "angle step at t = {}",
            w[0].0
        );
        assert!(
            (b.rate - a.rate).abs() <= 1.05 * max_accel * DT,
            "rate jump at t = {}",
            w[0].0
        );
    }
}

#[test]
fn analytic_rate_and_acceleration_match_finite_differences() {
    let mut g = ReferenceGenerator::new();
    g.start(&two_segments(), &L);
    let trace = run(&mut g, 4.5);
    let peak_rate = 2.0 * PI * 14.0 * 30.0 * DEG; // bound on |rate|
    let peak_accel = peak_rate * 2.0 * PI * 14.0 / 0.45; // split cycle sharpens it
    let mut accel_checked = 0;
    for w in trace.windows(3) {
        let (a, b, c) = (&w[0].1, &w[1].1, &w[2].1);
        let fd_rate = (c.angle - a.angle) / (2.0 * DT);
        assert!(
            (fd_rate - b.rate).abs() < 2e-3 * peak_rate,
            "rate at t = {}",
            w[1].0
        );
        // Acceleration may jump at ramp ends and stroke reversals of a
        // split cycle (smoothstep is C1, not C2): skip those samples.
        let fd_accel = (c.rate - a.rate) / (2.0 * DT);
        let jump = (c.accel - a.accel).abs() > 1e-2 * peak_accel;
        if !jump {
            assert!(
                (fd_accel - b.accel).abs() < 5e-3 * peak_accel,
                "accel at t = {}",
                w[1].0
            );
            accel_checked += 1;
        }
    }
    assert!(accel_checked > trace.len() * 9 / 10);
}

#[test]
fn steady_state_is_the_commanded_sinusoid() {
    let mut g = ReferenceGenerator::new();
    g.start(
        &profile(
            &[Segment::symmetric(11.0, 30.0 * DEG, 0.0, 10.0, 1.0)],
            EndAction::Hold,
        ),
        &L,
    );
    let trace = run(&mut g, 3.0);
    let settled: std::vec::Vec<_> = trace.iter().filter(|s| s.0 >= 1.0).collect();
    let max = settled.iter().map(|s| s.1.angle).fold(f32::MIN, f32::max);
    let min = settled.iter().map(|s| s.1.angle).fold(f32::MAX, f32::min);
    assert!(
        (max - 30.0 * DEG).abs() < 1e-4 && (min + 30.0 * DEG).abs() < 1e-4,
        "{max} {min}"
    );
    // Upward zero crossings are one period apart.
    let ups: std::vec::Vec<f32> = settled
        .windows(2)
        .filter(|w| w[0].1.angle < 0.0 && w[1].1.angle >= 0.0)
        .map(|w| w[0].0 - w[0].1.angle / (w[1].1.angle - w[0].1.angle) * DT)
        .collect();
    for p in ups.windows(2) {
        assert!(
            ((p[1] - p[0]) - 1.0 / 11.0).abs() < 2e-5,
            "period {}",
            p[1] - p[0]
        );
    }
}

#[test]
fn split_cycle_downstroke_takes_its_fraction() {
    let seg = Segment {
        downstroke_fraction: 0.6,
        ..Segment::symmetric(10.0, 20.0 * DEG, 0.0, 10.0, 1.0)
    };
    let mut g = ReferenceGenerator::new();
    g.start(&profile(&[seg], EndAction::Hold), &L);
    let trace = run(&mut g, 3.0);
    // Reversals: rate changes sign. Downstroke = top (rate + to -) to bottom.
    let mut tops = vec![];
    let mut bottoms = vec![];
    for w in trace.windows(2).filter(|w| w[0].0 > 1.5) {
        if w[0].1.rate > 0.0 && w[1].1.rate <= 0.0 {
            tops.push(w[1].0);
        }
        if w[0].1.rate < 0.0 && w[1].1.rate >= 0.0 {
            bottoms.push(w[1].0);
        }
    }
    let bottom_after = bottoms.iter().find(|&&b| b > tops[0]).unwrap();
    assert!(
        ((bottom_after - tops[0]) - 0.06).abs() < 2e-4,
        "downstroke {}",
        bottom_after - tops[0]
    );
    assert!(
        ((tops[1] - bottom_after) - 0.04).abs() < 2e-4,
        "upstroke {}",
        tops[1] - bottom_after
    );
}

#[test]
fn ramps_respect_the_slew_limit() {
    let mut g = ReferenceGenerator::new();
    g.start(&two_segments(), &L);
    let mut last = g.waveform().kin;
    for _ in 0..(6.0 / DT) as usize {
        g.advance(DT);
        let now = g.waveform().kin;
        let slew = (now.amplitude_rad - last.amplitude_rad)
            .abs()
            .max((now.mean_rad - last.mean_rad).abs())
            / DT;
        assert!(slew <= L.max_angle_slew_rad_s * 1.001, "{slew}");
        let fslew = (now.frequency_hz - last.frequency_hz).abs() / DT;
        assert!(fslew <= L.max_frequency_slew_hz_s * 1.001, "{fslew}");
        last = now;
    }
}

#[test]
fn stop_ramps_to_rest_at_the_slew_limit() {
    let mut g = ReferenceGenerator::new();
    g.start(
        &profile(
            &[Segment::symmetric(11.0, 30.0 * DEG, 0.0, 10.0, 1.0)],
            EndAction::Hold,
        ),
        &L,
    );
    run(&mut g, 2.0);
    g.stop();
    assert_eq!(g.mode(), Mode::Stopping);
    let expected = 1.5 * 30.0 * DEG / L.max_angle_slew_rad_s; // 0.75 s
    let trace = run(&mut g, expected + 0.01);
    assert_eq!(g.mode(), Mode::Idle);
    assert!(trace.iter().rev().take(10).all(|s| s.1.angle.abs() < 1e-3));
    let amp_mid = trace[trace.len() / 4].1.angle.abs();
    assert!(amp_mid <= 30.0 * DEG);
}

#[test]
fn failsafe_stop_takes_one_wingbeat() {
    let mut g = ReferenceGenerator::new();
    g.start(
        &profile(
            &[Segment::symmetric(11.0, 30.0 * DEG, 0.0, 10.0, 1.0)],
            EndAction::Hold,
        ),
        &L,
    );
    run(&mut g, 2.0);
    g.stop_within_one_wingbeat();
    let trace = run(&mut g, 1.0 / 11.0 + 2.0 * DT);
    assert_eq!(g.mode(), Mode::Idle);
    let max_rate = trace.iter().map(|s| s.1.rate.abs()).fold(0.0, f32::max);
    for w in trace.windows(2) {
        assert!((w[1].1.angle - w[0].1.angle).abs() <= 1.05 * max_rate * DT);
    }
}

#[test]
fn end_actions() {
    let seg = Segment::symmetric(11.0, 20.0 * DEG, 0.0, 1.0, 0.5);
    let mut g = ReferenceGenerator::new();
    g.start(&profile(&[seg], EndAction::Hold), &L);
    run(&mut g, 3.0);
    assert_eq!(g.active_segment(), Some(0), "held");

    g.start(&profile(&[seg], EndAction::Stop), &L);
    run(&mut g, 1.0 + 0.5 + 0.01);
    assert_eq!(g.mode(), Mode::Idle, "stopped after the end");

    let other = Segment {
        amplitude_rad: 10.0 * DEG,
        ..seg
    };
    g.start(&profile(&[seg, other], EndAction::Repeat), &L);
    let trace = run(&mut g, 2.5);
    let order: std::vec::Vec<Option<usize>> = trace
        .windows(2)
        .filter(|w| w[0].2 != w[1].2)
        .map(|w| w[1].2)
        .collect();
    assert_eq!(order, vec![Some(1), Some(0)]);
}

#[test]
fn phase_wrap_is_in_range() {
    for x in [-1e-9f32, -0.5, 0.0, 0.999_999_9, 1.0, 7.25, -3.75] {
        let w = wrap(x);
        assert!((0.0..1.0).contains(&w), "{x} -> {w}");
    }
}

/// After ~2000 s an f32 clock no longer advances by 100 us steps; segment
/// and ramp clocks are f64, so a long segment still ends on time.
#[test]
fn long_segments_end_on_time() {
    let long = Segment::symmetric(11.0, 20.0 * DEG, 0.0, 3000.0, 1.0);
    let next = Segment::symmetric(11.0, 10.0 * DEG, 0.0, 10.0, 1.0);
    let mut g = ReferenceGenerator::new();
    g.start(&profile(&[long, next], EndAction::Hold), &L);
    // Jump to 50 ms before the end of the long segment (the ramp is done).
    g.in_segment = 2999.95;
    g.ramp.elapsed = 2999.95;
    run(&mut g, 0.049);
    assert_eq!(g.active_segment(), Some(0));
    run(&mut g, 0.002);
    assert_eq!(
        g.active_segment(),
        Some(1),
        "switched within a step of 3000 s"
    );
    let f32_clock = 2999.95f32 + 1e-4;
    assert_eq!(
        f32_clock, 2999.95f32,
        "(an f32 clock would have stalled here)"
    );
}
