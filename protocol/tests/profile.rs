//! `Profile::validate` against `Limits`, and the JSON profile document.

mod strategies;

use fwav_protocol::document::{DocumentError, ProfileDocument};
use fwav_protocol::*;
use proptest::prelude::*;

const DEG: f32 = core::f32::consts::PI / 180.0;
const L: Limits = Limits::REFERENCE_FWAV;

/// The seed paper's initial design: 11 Hz, +-30 deg, reached in 1 s.
fn cruise() -> Segment {
    Segment::symmetric(11.0, 30.0 * DEG, 0.0, 10.0, 1.0)
}

fn one(seg: Segment) -> Profile {
    Profile::from_segments(&[seg], EndAction::Hold).unwrap()
}

fn errors(p: &Profile) -> Vec<ProfileError> {
    let mut v = Vec::new();
    p.for_each_violation(&L, |e| v.push(e));
    v
}

#[test]
fn initial_design_is_valid() {
    assert_eq!(one(cruise()).validate(&L), Ok(()));
}

#[test]
fn empty_profile_is_refused() {
    assert_eq!(Profile::default().validate(&L), Err(ProfileError::Empty));
}

#[test]
fn each_field_error_is_named() {
    let cases: Vec<(Segment, ProfileError)> = vec![
        (
            Segment {
                frequency_hz: f32::NAN,
                ..cruise()
            },
            ProfileError::NotFinite {
                segment: 0,
                field: SegmentField::Frequency,
            },
        ),
        (
            Segment {
                ramp_s: f32::INFINITY,
                ..cruise()
            },
            ProfileError::NotFinite {
                segment: 0,
                field: SegmentField::Ramp,
            },
        ),
        (
            Segment {
                duration_s: -1.0,
                ramp_s: 0.0,
                amplitude_rad: 0.0,
                ..cruise()
            },
            ProfileError::NonPositiveDuration {
                segment: 0,
                duration_s: -1.0,
            },
        ),
        (
            Segment {
                ramp_s: 11.0,
                ..cruise()
            },
            ProfileError::RampOutOfRange {
                segment: 0,
                ramp_s: 11.0,
                duration_s: 10.0,
            },
        ),
        (
            Segment {
                frequency_hz: 25.0,
                ..cruise()
            },
            ProfileError::FrequencyOutOfRange {
                segment: 0,
                frequency_hz: 25.0,
                min_hz: 1.0,
                max_hz: 20.0,
            },
        ),
        (
            Segment {
                frequency_hz: 0.0,
                ..cruise()
            },
            ProfileError::FrequencyOutOfRange {
                segment: 0,
                frequency_hz: 0.0,
                min_hz: 1.0,
                max_hz: 20.0,
            },
        ),
        (
            Segment {
                amplitude_rad: 50.0 * DEG,
                ramp_s: 5.0,
                ..cruise()
            },
            ProfileError::AmplitudeOutOfRange {
                segment: 0,
                amplitude_rad: 50.0 * DEG,
                max_rad: L.max_amplitude_rad,
            },
        ),
        (
            Segment {
                amplitude_rad: -0.1,
                ..cruise()
            },
            ProfileError::AmplitudeOutOfRange {
                segment: 0,
                amplitude_rad: -0.1,
                max_rad: L.max_amplitude_rad,
            },
        ),
        (
            Segment {
                mean_rad: -25.0 * DEG,
                amplitude_rad: 10.0 * DEG,
                ..cruise()
            },
            ProfileError::MeanOutOfRange {
                segment: 0,
                mean_rad: -25.0 * DEG,
                max_rad: L.max_mean_rad,
            },
        ),
        (
            Segment {
                mean_rad: 20.0 * DEG,
                amplitude_rad: 42.0 * DEG,
                ramp_s: 5.0,
                ..cruise()
            },
            ProfileError::ExcursionOutOfRange {
                segment: 0,
                excursion_rad: 20.0 * DEG + 42.0 * DEG,
                max_rad: L.max_excursion_rad,
            },
        ),
        (
            Segment {
                downstroke_fraction: 0.75,
                ..cruise()
            },
            ProfileError::SplitCycleOutOfRange {
                segment: 0,
                downstroke_fraction: 0.75,
                max_asymmetry: 0.2,
            },
        ),
        (
            // Smoothstep peak: 1.5 * 30 deg / 0.5 s = 90 deg/s > 60 deg/s.
            Segment {
                ramp_s: 0.5,
                ..cruise()
            },
            ProfileError::SlewTooFast {
                segment: 0,
                quantity: SlewQuantity::Amplitude,
                rate: 1.5 * 30.0 * DEG / 0.5,
                max_rate: L.max_angle_slew_rad_s,
            },
        ),
    ];
    for (seg, expected) in cases {
        assert_eq!(errors(&one(seg)), vec![expected], "{seg:?}");
    }
}

#[test]
fn instant_step_is_infinitely_fast() {
    let p = one(Segment {
        ramp_s: 0.0,
        ..cruise()
    });
    match p.validate(&L) {
        Err(ProfileError::SlewTooFast {
            quantity: SlewQuantity::Amplitude,
            rate,
            ..
        }) => {
            assert!(rate.is_infinite())
        }
        other => panic!("{other:?}"),
    }
    // A step of nothing needs no ramp.
    let still = Segment {
        amplitude_rad: 0.0,
        ramp_s: 0.0,
        ..cruise()
    };
    assert_eq!(one(still).validate(&L), Ok(()));
}

#[test]
fn slew_between_segments_and_on_repeat() {
    // Peak rates of the smoothstep (1.5 x average), worked by hand.
    // 11 -> 16 Hz in 0.25 s: 1.5 * 5 / 0.25 = 30 Hz/s > 10 Hz/s.
    let fast = Segment {
        frequency_hz: 16.0,
        ramp_s: 0.25,
        ..cruise()
    };
    let p = Profile::from_segments(&[cruise(), fast], EndAction::Hold).unwrap();
    assert_eq!(
        p.validate(&L),
        Err(ProfileError::SlewTooFast {
            segment: 1,
            quantity: SlewQuantity::Frequency,
            rate: 30.0,
            max_rate: 10.0
        })
    );
    // 11 -> 18 Hz in 1.5 s: 7 Hz/s, fine forwards; 30 deg in 1 s: 45 deg/s.
    let second = Segment {
        frequency_hz: 18.0,
        ramp_s: 1.5,
        ..cruise()
    };
    let hold = Profile::from_segments(&[cruise(), second], EndAction::Hold).unwrap();
    assert_eq!(hold.validate(&L), Ok(()));
    // With Repeat the wrap-around 18 -> 11 Hz uses segment 0's 1 s ramp:
    // 1.5 * 7 / 1 = 10.5 Hz/s > 10 Hz/s. Only the wrap-around is too fast.
    let repeat = Profile {
        on_end: EndAction::Repeat,
        ..hold
    };
    assert_eq!(
        repeat.validate(&L),
        Err(ProfileError::SlewTooFast {
            segment: 0,
            quantity: SlewQuantity::Frequency,
            rate: 10.5,
            max_rate: 10.0
        })
    );
    // 17 Hz wraps at 1.5 * 6 / 1 = 9 Hz/s: valid.
    let slower = Segment {
        frequency_hz: 17.0,
        ..second
    };
    let ok = Profile::from_segments(&[cruise(), slower], EndAction::Repeat).unwrap();
    assert_eq!(ok.validate(&L), Ok(()));
}

#[test]
fn nan_limits_refuse_everything() {
    let broken = Limits {
        max_amplitude_rad: f32::NAN,
        ..L
    };
    assert!(matches!(
        one(cruise()).validate(&broken),
        Err(ProfileError::AmplitudeOutOfRange { .. })
    ));
}

#[test]
fn every_violation_is_listed() {
    let bad = Segment {
        frequency_hz: 30.0,
        amplitude_rad: 80.0 * DEG,
        ramp_s: 0.0,
        ..cruise()
    };
    let p = Profile::from_segments(&[cruise(), bad], EndAction::Hold).unwrap();
    let e = errors(&p);
    assert!(e.len() >= 4, "{e:?}");
    assert!(e
        .iter()
        .all(|e| !matches!(e, ProfileError::NotFinite { .. })));
    assert_eq!(p.validate(&L), Err(e[0]));
}

#[test]
fn messages_are_in_degrees() {
    let e = ProfileError::AmplitudeOutOfRange {
        segment: 2,
        amplitude_rad: 50.0 * DEG,
        max_rad: 45.0 * DEG,
    };
    assert_eq!(
        e.to_string(),
        "segment 2: amplitude 50.00 deg is outside 0..=45.00 deg"
    );
}

proptest! {
    /// Validation is total: any profile, any limits, no panic; and a profile
    /// that passes has only finite, in-range values.
    #[test]
    fn validation_never_panics(p in strategies::profile(false), l in strategies::limits(false)) {
        if p.validate(&l).is_ok() {
            for s in &p.segments {
                prop_assert!(s.frequency_hz.is_finite() && s.frequency_hz > 0.0);
                prop_assert!(s.amplitude_rad >= 0.0 && s.amplitude_rad <= l.max_amplitude_rad);
                prop_assert!(s.downstroke_fraction > 0.0 && s.downstroke_fraction < 1.0);
                prop_assert!(s.duration_s > 0.0 && s.ramp_s <= s.duration_s);
            }
        }
    }
}

const EXAMPLE: &str = r#"{
  "format": "fwav-profile",
  "format_version": 1,
  "description": "initial design",
  "on_end": "repeat",
  "segments": [
    { "frequency_hz": 11.0, "amplitude_deg": 30.0, "duration_s": 10.0, "ramp_s": 1.0 },
    { "frequency_hz": 12.0, "amplitude_deg": 25.0, "mean_deg": 5.0, "duration_s": 5.0, "ramp_s": 1.0, "downstroke_fraction": 0.55 }
  ]
}"#;

#[test]
fn document_converts_degrees_and_defaults() {
    let doc = ProfileDocument::from_json(EXAMPLE).unwrap();
    let p = doc.to_profile().unwrap();
    assert_eq!(p.on_end, EndAction::Repeat);
    assert_eq!(p.segments.len(), 2);
    let s = p.segments[0];
    assert!(
        (s.amplitude_rad - core::f32::consts::FRAC_PI_6).abs() < 1e-7,
        "30 deg = pi/6 rad"
    );
    assert_eq!((s.mean_rad, s.downstroke_fraction), (0.0, 0.5));
    assert!((p.segments[1].mean_rad - 5.0 * DEG).abs() < 1e-7);
    assert_eq!(p.validate(&L), Ok(()));
    // And back: degrees come out clean.
    let back = ProfileDocument::from_profile(&p, "initial design");
    assert_eq!(back, doc);
    assert_eq!(
        ProfileDocument::from_json(&back.to_json_pretty()).unwrap(),
        doc
    );
}

#[test]
fn document_errors_name_the_problem() {
    let typo = EXAMPLE.replace("amplitude_deg\": 30.0", "amplitude_degs\": 30.0");
    let e = ProfileDocument::from_json(&typo).unwrap_err().to_string();
    assert!(e.contains("amplitude_degs") && e.contains("line 7"), "{e}");

    let missing = EXAMPLE.replace("\"duration_s\": 10.0, ", "");
    let e = ProfileDocument::from_json(&missing)
        .unwrap_err()
        .to_string();
    assert!(e.contains("duration_s"), "{e}");

    let wrong = EXAMPLE.replace("fwav-profile", "something-else");
    assert!(matches!(
        ProfileDocument::from_json(&wrong),
        Err(DocumentError::WrongFormat { .. })
    ));

    let future = EXAMPLE.replace("\"format_version\": 1", "\"format_version\": 2");
    let e = ProfileDocument::from_json(&future).unwrap_err();
    assert!(
        matches!(e, DocumentError::UnsupportedVersion { found: 2 }),
        "{e}"
    );

    let mut doc = ProfileDocument::from_json(EXAMPLE).unwrap();
    doc.segments = vec![doc.segments[0]; MAX_SEGMENTS + 1];
    assert!(matches!(
        doc.to_profile(),
        Err(DocumentError::TooManySegments { count: 17 })
    ));
}

#[test]
fn params_table_is_consistent() {
    for (i, p) in PARAMS.iter().enumerate() {
        assert_eq!(p.id as usize, i, "PARAMS is in wire-id order");
        assert_eq!(ParamId::from_name(p.name), Some(p.id));
        assert!(
            p.min() <= p.default && p.default <= p.max(),
            "{} default in range",
            p.name
        );
        assert!(p.id.accepts(p.default) && !p.id.accepts(f32::NAN));
    }
    assert!(PARAMS.len() <= MAX_PARAMS);
}

#[test]
fn handshake_check() {
    assert_eq!(Hello::check_peer(&Hello::THIS), Ok(()));
    let older = Hello {
        protocol_version: PROTOCOL_VERSION,
        schema_hash: SCHEMA_HASH ^ 1,
    };
    let e = Hello::check_peer(&older).unwrap_err();
    let text = e.to_string();
    assert!(
        text.contains(&format!("{:016x}", SCHEMA_HASH))
            && text.contains(&format!("{:016x}", SCHEMA_HASH ^ 1)),
        "{text}"
    );
}
