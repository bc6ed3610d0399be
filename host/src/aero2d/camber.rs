//! A deforming thin section: the camber line `eta(x, t)` (normal offset
//! from the chord, chords, positive up) as periodic samples, interpolated
//! linearly in `x` and by a periodic Catmull-Rom cubic in `t`, so that the
//! deformation rate is continuous (a rate that jumps between samples would
//! put spikes into the unsteady loads). This is how the section deformation history from
//! the system analysis (mid-span section x, y over a period) enters the 2D
//! analysis, after it is expressed in the chord frame.

use fwav_settings::Shown;

/// Why a camber history is refused.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum CamberError {
    /// Stations must rise strictly from 0 to 1.
    #[error("chord stations must rise strictly from 0 to 1 (got {0} stations)")]
    Stations(usize),
    /// Every sample needs one offset per station.
    #[error("sample {sample} has {got} offsets for {expected} stations")]
    SampleLength {
        /// Sample index.
        sample: usize,
        /// Offsets given.
        got: usize,
        /// Stations.
        expected: usize,
    },
    /// A period and at least one sample are needed.
    #[error("the period must be positive and there must be at least one sample")]
    Period,
    /// A value is not finite.
    #[error("a camber offset or station is not finite")]
    NotFinite,
    /// Section points must run from the leading edge to the trailing edge.
    #[error("sample {sample}: point {point} does not lie downstream of the one before (x must rise from the leading edge to the trailing edge)")]
    PointOrder {
        /// Sample index.
        sample: usize,
        /// Point index.
        point: usize,
    },
    /// Too few points in a sample.
    #[error("sample {sample} has {got} points; at least 2 are needed")]
    TooFewPoints {
        /// Sample index.
        sample: usize,
        /// Points given.
        got: usize,
    },
    /// A mid-line sample much longer or shorter than the chord
    /// ([`MIDLINE_STRETCH`]).
    #[error(
        "sample {sample}'s mid-line is {:.4} chords long: a section's mid-line keeps the \
         chord's length within {}% (a system analysis's within 0.25%); check the sample, cut \
         short or scaled, or the file's units (chords)",
        Shown(*.length),
        100.0 * MIDLINE_STRETCH
    )]
    MidlineLength {
        /// Sample index.
        sample: usize,
        /// Its length along the points, chords.
        length: f64,
    },
}

/// How far a mid-line sample's length may differ from the chord, as a
/// fraction of it. The membrane's mid-line is nearly inextensible: over
/// the four cycles of the Navier–Stokes design run of `docs/ns-design`
/// (2026-12-06) the system analysis's samples were 1.0000 to 1.0025
/// chords long. A sample 5 % off is not a membrane's deformation but a
/// broken file (a sample cut short, points in another unit), and the
/// models would extend or squeeze it into a section that never flew.
pub const MIDLINE_STRETCH: f64 = 0.05;

/// Checks that each of `samples` (mid-lines, chords, as
/// [`CamberHistory::from_section_points`] takes them) has at least two
/// finite points and a length along them within [`MIDLINE_STRETCH`] of
/// the chord.
///
/// # Errors
/// [`CamberError::TooFewPoints`], [`CamberError::NotFinite`],
/// [`CamberError::MidlineLength`] for the first sample that fails.
pub fn check_midlines(samples: &[Vec<(f64, f64)>]) -> Result<(), CamberError> {
    samples
        .iter()
        .enumerate()
        .try_for_each(|(i, points)| check_midline(i, points))
}

/// [`check_midlines`] for one sample, number `sample`.
fn check_midline(sample: usize, points: &[(f64, f64)]) -> Result<(), CamberError> {
    check_midline_points(sample, points)?;
    check_midline_length(sample, points)
}

/// At least two points in sample number `sample`, each finite.
fn check_midline_points(sample: usize, points: &[(f64, f64)]) -> Result<(), CamberError> {
    if points.len() < 2 {
        return Err(CamberError::TooFewPoints {
            sample,
            got: points.len(),
        });
    }
    if !points.iter().all(|(x, y)| x.is_finite() && y.is_finite()) {
        return Err(CamberError::NotFinite);
    }
    Ok(())
}

/// Sample number `sample`'s length along its points within
/// [`MIDLINE_STRETCH`] of the chord.
fn check_midline_length(sample: usize, points: &[(f64, f64)]) -> Result<(), CamberError> {
    let length: f64 = points
        .windows(2)
        .map(|w| f64::hypot(w[1].0 - w[0].0, w[1].1 - w[0].1))
        .sum();
    if (length - 1.0).abs() > MIDLINE_STRETCH {
        return Err(CamberError::MidlineLength { sample, length });
    }
    Ok(())
}

/// A periodic camber-line history.
#[derive(Clone, Debug, PartialEq)]
pub struct CamberHistory {
    stations: Vec<f64>,
    samples: Vec<Vec<f64>>,
    period: f64,
}

impl CamberHistory {
    /// `samples[i][j]`: offset at station `stations[j]` at time
    /// `i * period / samples.len()` (chords, time in chords travelled).
    pub fn new(
        stations: Vec<f64>,
        samples: Vec<Vec<f64>>,
        period: f64,
    ) -> Result<Self, CamberError> {
        let n = stations.len();
        let rising = stations.windows(2).all(|w| w[1] > w[0]);
        if n < 2 || !rising || stations[0] != 0.0 || stations[n - 1] != 1.0 {
            return Err(CamberError::Stations(n));
        }
        // Written so that a NaN period fails.
        let period_ok = period > 0.0;
        if !period_ok || samples.is_empty() {
            return Err(CamberError::Period);
        }
        for (i, s) in samples.iter().enumerate() {
            if s.len() != n {
                return Err(CamberError::SampleLength {
                    sample: i,
                    got: s.len(),
                    expected: n,
                });
            }
        }
        if !stations
            .iter()
            .chain(samples.iter().flatten())
            .all(|v| v.is_finite())
        {
            return Err(CamberError::NotFinite);
        }
        Ok(Self {
            stations,
            samples,
            period,
        })
    }

    /// The camber history of a deforming section given as the `(x, y)` of
    /// its mid-line points over one period (the mid-span section history of
    /// the system analysis), each sample in the section's kinematic frame:
    /// chords, the undeformed leading edge at (0, 0) and trailing edge at
    /// (1, 0), y normal to that chord; samples equally spaced over `period`
    /// (chords travelled). Each sample is resampled linearly onto `stations`
    /// equally spaced stations from 0 to 1, extending the end values
    /// linearly where the deformed line is shorter: the offsets are the
    /// camber (thin-airfoil theory keeps the normal offset; the small
    /// chordwise motion of the points is neglected, second order in the
    /// deflection). Each sample's points must rise in `x`, and its length
    /// is checked ([`check_midlines`]): a mid-line far shorter than the
    /// chord would be extended into one that never flew.
    pub fn from_section_points(
        samples: &[Vec<(f64, f64)>],
        period: f64,
        stations: usize,
    ) -> Result<Self, CamberError> {
        if stations < 2 {
            return Err(CamberError::Stations(stations));
        }
        let grid: Vec<f64> = (0..stations)
            .map(|i| i as f64 / (stations - 1) as f64)
            .collect();
        let mut offsets = Vec::with_capacity(samples.len());
        for (i, points) in samples.iter().enumerate() {
            check_midline_points(i, points)?;
            if let Some(j) = points.windows(2).position(|w| w[1].0 <= w[0].0) {
                return Err(CamberError::PointOrder {
                    sample: i,
                    point: j + 1,
                });
            }
            check_midline_length(i, points)?;
            let eta = grid
                .iter()
                .map(|&x| {
                    let k = points
                        .partition_point(|p| p.0 <= x)
                        .clamp(1, points.len() - 1);
                    let ((x0, y0), (x1, y1)) = (points[k - 1], points[k]);
                    y0 + (y1 - y0) * (x - x0) / (x1 - x0)
                })
                .collect();
            offsets.push(eta);
        }
        Self::new(grid, offsets, period)
    }

    /// A camber line that does not change.
    pub fn steady(stations: Vec<f64>, offsets: Vec<f64>) -> Result<Self, CamberError> {
        Self::new(stations, vec![offsets], 1.0)
    }

    fn at_sample(&self, i: usize, x: f64) -> (f64, f64) {
        let s = &self.stations;
        let j = s.partition_point(|&v| v <= x).clamp(1, s.len() - 1);
        let (x0, x1) = (s[j - 1], s[j]);
        let (e0, e1) = (self.samples[i][j - 1], self.samples[i][j]);
        let slope = (e1 - e0) / (x1 - x0);
        (e0 + slope * (x - x0), slope)
    }

    /// `(eta, d eta/dx, d eta/dt)` at station `x` and time `t`.
    pub fn at(&self, x: f64, t: f64) -> (f64, f64, f64) {
        let n = self.samples.len();
        if n == 1 {
            let (e, s) = self.at_sample(0, x);
            return (e, s, 0.0);
        }
        let span = PeriodicSpan::new(t, self.period, n);
        let [p0, p1, p2, p3] = span.samples.map(|j| self.at_sample(j, x));
        let (eta, rate) = span.cubic(p0.0, p1.0, p2.0, p3.0);
        let (slope, _) = span.cubic(p0.1, p1.1, p2.1, p3.1);
        (eta, slope, rate)
    }
}

/// Where time `t` falls among `n` samples equally spaced over a period:
/// the four samples of the periodic Catmull-Rom span around it, the
/// fraction `w` across the span and the sample spacing.
pub(crate) struct PeriodicSpan {
    /// Samples before, at the start, at the end and after the span.
    pub samples: [usize; 4],
    /// Fraction across the span, in [0, 1).
    pub w: f64,
    /// Sample spacing (time).
    pub dt: f64,
}

impl PeriodicSpan {
    /// The span of `t` among `n >= 1` samples over `period`.
    pub fn new(t: f64, period: f64, n: usize) -> Self {
        let dt = period / n as f64;
        let phase = (t / dt).rem_euclid(n as f64);
        let i = (phase.floor() as usize).min(n - 1);
        Self {
            samples: [i + n - 1, i, i + 1, i + 2].map(|j| j % n),
            w: phase - i as f64,
            dt,
        }
    }

    /// Catmull-Rom through `b` (w = 0) and `c` (w = 1), C1 across samples:
    /// value and rate in time.
    pub fn cubic(&self, a: f64, b: f64, c: f64, d: f64) -> (f64, f64) {
        let w = self.w;
        let (c1, c2, c3) = (
            0.5 * (c - a),
            a - 2.5 * b + 2.0 * c - 0.5 * d,
            0.5 * (d - a) + 1.5 * (b - c),
        );
        (
            b + w * (c1 + w * (c2 + w * c3)),
            (c1 + w * (2.0 * c2 + 3.0 * w * c3)) / self.dt,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sinusoidal history sampled 64 times a period is reproduced, with its
    /// rate, to the accuracy of a cubic.
    #[test]
    fn periodic_cubic_reproduces_a_sinusoid_and_its_rate() {
        let (period, n) = (2.0, 64);
        let stations = vec![0.0, 1.0];
        let shape = |t: f64| 0.01 * (2.0 * std::f64::consts::PI * t / period).sin();
        let samples = (0..n)
            .map(|i| vec![0.0, shape(i as f64 * period / n as f64)])
            .collect();
        let c = CamberHistory::new(stations, samples, period).unwrap();
        let omega = 2.0 * std::f64::consts::PI / period;
        let h = period / n as f64;
        // At the nodes the Catmull-Rom rate is the central difference, whose
        // truncation error is A omega^3 h^2 / 6 (5.0e-5 here); in between the
        // cubic is closer.
        let rate_bound = 0.01 * omega.powi(3) * h * h / 6.0 * 1.05;
        for k in 0..200 {
            let t = k as f64 * 0.0137;
            let (eta, slope, rate) = c.at(1.0, t);
            assert!((eta - shape(t)).abs() < 1e-6, "{t}");
            assert!((slope - shape(t)).abs() < 1e-6, "{t}"); // eta(1) - eta(0) over 1
            assert!(
                (rate - 0.01 * omega * (omega * t).cos()).abs() < rate_bound,
                "{t}: {rate}"
            );
        }
    }

    /// A history given as section points gives back the camber of those
    /// points at the stations, and refuses points out of order.
    #[test]
    fn section_points_become_camber() {
        let line = |a: f64| -> Vec<(f64, f64)> {
            (0..=10)
                .map(|i| {
                    let x = i as f64 / 10.0;
                    (x, a * x * x)
                })
                .collect()
        };
        let c = CamberHistory::from_section_points(&[line(0.02), line(-0.02)], 2.0, 21).unwrap();
        let (eta, slope, _) = c.at(0.5, 0.0);
        // Exact at a given point; the slope is that of the station interval
        // [0.5, 0.55], where 0.55 lies halfway between the points at 0.5 and
        // 0.6: (0.02 (0.25 + 0.36) / 2 - 0.005) / 0.05 = 0.022.
        assert!((eta - 0.005).abs() < 1e-12, "{eta}");
        assert!((slope - 0.022).abs() < 1e-9, "{slope}");
        assert!((c.at(0.5, 1.0).0 + 0.005).abs() < 1e-12);
        let mut bad = line(0.0);
        bad.swap(3, 4);
        assert_eq!(
            CamberHistory::from_section_points(&[bad], 1.0, 11),
            Err(CamberError::PointOrder {
                sample: 0,
                point: 4
            })
        );
        assert_eq!(
            CamberHistory::from_section_points(&[vec![(0.0, 0.0)]], 1.0, 11),
            Err(CamberError::TooFewPoints { sample: 0, got: 1 })
        );
    }

    /// A mid-line sample far from the chord's length (cut short, or in
    /// another unit) is refused naming it; a bent one of the chord's
    /// length, and one stretched by less than [`MIDLINE_STRETCH`], are
    /// taken.
    #[test]
    fn a_midline_of_another_length_is_refused() {
        let line = |scale: f64, camber: f64| -> Vec<(f64, f64)> {
            (0..=20)
                .map(|i| {
                    let x = i as f64 / 20.0;
                    (scale * x, camber * (std::f64::consts::PI * x).sin())
                })
                .collect()
        };
        // Camber 0.05: 1.0062 chords along the points.
        assert_eq!(check_midlines(&[line(1.0, 0.05), line(1.04, 0.0)]), Ok(()));
        for (samples, sample, length) in [
            (vec![line(1.0, 0.0), line(0.077, 0.0)], 1, 0.077),
            (vec![line(75.0, 0.0)], 0, 75.0),
            (
                vec![line(1.0, 0.0), line(1.0, 0.0), line(0.94, 0.0)],
                2,
                0.94,
            ),
        ] {
            match check_midlines(&samples) {
                Err(CamberError::MidlineLength {
                    sample: s,
                    length: l,
                }) => {
                    assert_eq!(s, sample);
                    assert!((l - length).abs() < 1e-12, "{l}");
                }
                other => panic!("{other:?}"),
            }
            assert!(CamberHistory::from_section_points(&samples, 1.0, 11).is_err());
        }
        // The length as a reader takes it in: four decimals, or a power of
        // ten where they would print 300 digits (a coordinate of 1e300,
        // tried by hand on 2026-12-07).
        for (length, shown) in [
            (0.8335, "is 0.8335 chords"),
            (2e300, "is 2.0000e300 chords"),
        ] {
            let e = CamberError::MidlineLength { sample: 0, length };
            assert!(e.to_string().contains(shown), "{e}");
        }
    }

    #[test]
    fn bad_histories_are_refused() {
        assert_eq!(
            CamberHistory::steady(vec![0.0, 0.5], vec![0.0, 0.0]),
            Err(CamberError::Stations(2))
        );
        assert!(matches!(
            CamberHistory::new(vec![0.0, 1.0], vec![vec![0.0]], 1.0),
            Err(CamberError::SampleLength {
                sample: 0,
                got: 1,
                expected: 2
            })
        ));
        assert_eq!(
            CamberHistory::new(vec![0.0, 1.0], vec![vec![0.0, f64::NAN]], 1.0),
            Err(CamberError::NotFinite)
        );
        assert_eq!(
            CamberHistory::new(vec![0.0, 1.0], vec![vec![0.0, 0.0]], 0.0),
            Err(CamberError::Period)
        );
    }
}
