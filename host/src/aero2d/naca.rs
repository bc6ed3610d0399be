//! Section geometry for the panel method ([`super::panel`]): NACA 4-digit
//! sections and airfoil coordinate files.
//!
//! Points are in chords, in the section's body frame (leading edge at the
//! origin, trailing edge at (1, 0) for the NACA sections), ordered
//! **clockwise**: from the trailing edge along the lower surface to the
//! leading edge and back along the upper surface to the trailing edge (the
//! order of Katz & Plotkin, *Low-Speed Aerodynamics*, 2nd ed., 2001,
//! section 11.4). With a closed (sharp) trailing edge the first and last
//! points coincide. [`super::panel::SectionShape`] accepts either
//! orientation and puts it clockwise.
//!
//! NACA 4-digit sections (Abbott & von Doenhoff, *Theory of Wing Sections*,
//! 1959, section 6.4): thickness
//! `y_t = 5 t (0.2969 sqrt x - 0.1260 x - 0.3516 x^2 + 0.2843 x^3 + a4 x^4)`
//! with `a4 = -0.1015` in the original definition, which leaves a
//! trailing-edge thickness of `2 * 0.0105 t` (0.25% of the chord for
//! 12%); the widely used modification `a4 = -0.1036` closes it (the default
//! here, [`TrailingEdge::Closed`]: a sharp edge suits the Kutta condition of
//! a panel method; the half-thickness changes by `0.0105 t x^4`, at most
//! 0.13% of the chord for 12%, and mostly near the trailing edge).
//! Camber line `y_c = m/p^2 (2 p x - x^2)` ahead of `p`,
//! `m/(1-p)^2 (1 - 2 p + 2 p x - x^2)` behind it, the thickness laid off
//! normal to it. Stations by cosine spacing, `x = (1 - cos theta) / 2` with
//! `theta` uniform on each surface (points cluster at both edges).
//!
//! Point files ([`parse_points`]): plain text, two numbers `x y` per line
//! (spaces, tabs or a comma between them), `#` starts a comment, blank lines
//! are skipped; the first line may be a name (Selig format, as in the UIUC
//! airfoil coordinates database: name line, then the points from the
//! trailing edge over the upper surface to the leading edge and back along
//! the lower surface). The Lednicer format (a line of point counts after the
//! name, surfaces given separately) is recognised and refused.

use std::f64::consts::PI;
use std::str::FromStr;

/// Why a NACA designation or a point count is refused.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum NacaError {
    /// Not four digits (after an optional "naca" prefix).
    #[error(
        "{0:?} is not a NACA 4-digit designation (four digits, e.g. \"0012\" or \"naca2412\")"
    )]
    Designation(String),
    /// Camber without a position of maximum camber (second digit 0).
    #[error(
        "NACA {0}: a cambered section needs the position of maximum camber (second digit 1 to 9)"
    )]
    CamberPosition(String),
    /// Thickness digits 00: there is no closed contour to panel.
    #[error("NACA {0}: zero thickness (last two digits 00) has no contour to panel")]
    ZeroThickness(String),
    /// The panel count must be even (half on each surface) and at least 4.
    #[error("{0} panels: need an even number, at least 4")]
    Panels(usize),
}

/// Trailing-edge closure of a NACA 4-digit thickness distribution.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TrailingEdge {
    /// `a4 = -0.1036`: zero thickness at x = 1 (first and last points
    /// coincide). The default.
    #[default]
    Closed,
    /// `a4 = -0.1015`, the original definition: a blunt edge of thickness
    /// `0.021 t` (the panel method closes it with one panel).
    Open,
}

impl TrailingEdge {
    /// The `x^4` coefficient of the thickness polynomial.
    pub fn a4(self) -> f64 {
        match self {
            Self::Closed => -0.1036,
            Self::Open => -0.1015,
        }
    }
}

/// A NACA 4-digit section `MPTT`: camber `M`% of the chord at `P`/10 of
/// the chord, thickness `TT`% (all stored as fractions of the chord).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Naca4 {
    /// Maximum camber `m`, chords (first digit / 100).
    pub camber: f64,
    /// Position of maximum camber `p`, chords (second digit / 10).
    pub camber_position: f64,
    /// Maximum thickness `t`, chords (last two digits / 100).
    pub thickness: f64,
}

impl FromStr for Naca4 {
    type Err = NacaError;

    /// Parses `"0012"`, `"naca2412"`, `"NACA 2412"`, `"naca-0006"`.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let trimmed = s.trim();
        let lower = trimmed.to_ascii_lowercase();
        let digits = lower
            .strip_prefix("naca")
            .unwrap_or(&lower)
            .trim_start_matches([' ', '-', '_']);
        let bad = || NacaError::Designation(trimmed.to_string());
        if digits.len() != 4 || !digits.bytes().all(|b| b.is_ascii_digit()) {
            return Err(bad());
        }
        let d: Vec<f64> = digits.bytes().map(|b| f64::from(b - b'0')).collect();
        let naca = Self {
            camber: d[0] / 100.0,
            camber_position: d[1] / 10.0,
            thickness: (10.0 * d[2] + d[3]) / 100.0,
        };
        if naca.camber > 0.0 && naca.camber_position == 0.0 {
            return Err(NacaError::CamberPosition(digits.to_string()));
        }
        if naca.thickness == 0.0 {
            return Err(NacaError::ZeroThickness(digits.to_string()));
        }
        Ok(naca)
    }
}

impl Naca4 {
    /// Half-thickness at station `x` (chords).
    pub fn half_thickness(&self, x: f64, edge: TrailingEdge) -> f64 {
        let sx = x.max(0.0).sqrt();
        5.0 * self.thickness
            * (0.2969 * sx + x * (-0.1260 + x * (-0.3516 + x * (0.2843 + x * edge.a4()))))
    }

    /// Camber line height and slope `(y_c, dy_c/dx)` at station `x`.
    pub fn camber_line(&self, x: f64) -> (f64, f64) {
        let (m, p) = (self.camber, self.camber_position);
        if m == 0.0 {
            (0.0, 0.0)
        } else if x < p {
            (
                m / (p * p) * (2.0 * p * x - x * x),
                2.0 * m / (p * p) * (p - x),
            )
        } else {
            let q = (1.0 - p) * (1.0 - p);
            (
                m / q * (1.0 - 2.0 * p + 2.0 * p * x - x * x),
                2.0 * m / q * (p - x),
            )
        }
    }

    /// Surface points for `panels` panels (even, at least 4; `panels / 2`
    /// on each surface, cosine spacing), clockwise from the trailing edge
    /// along the lower surface (see the module documentation): `panels + 1`
    /// points, the first and last both at the trailing edge (coincident for
    /// [`TrailingEdge::Closed`]). Chords, leading edge at (0, 0).
    pub fn points(&self, panels: usize, edge: TrailingEdge) -> Result<Vec<(f64, f64)>, NacaError> {
        if panels < 4 || panels % 2 != 0 {
            return Err(NacaError::Panels(panels));
        }
        let n = panels / 2;
        let surface = |i: usize, upper: bool| -> (f64, f64) {
            let x = 0.5 * (1.0 - (PI * i as f64 / n as f64).cos());
            let yt = self.half_thickness(x, edge);
            let (yc, slope) = self.camber_line(x);
            let (s, c) = slope.atan().sin_cos();
            let sign = if upper { 1.0 } else { -1.0 };
            (x - sign * yt * s, yc + sign * yt * c)
        };
        let mut points: Vec<(f64, f64)> = (0..=n).rev().map(|i| surface(i, false)).collect();
        points.extend((1..=n).map(|i| surface(i, true)));
        if edge == TrailingEdge::Closed {
            // Exactly coincident ends (round-off would leave ~1e-17).
            points[2 * n] = points[0];
        }
        Ok(points)
    }
}

/// Why a point file is refused (lines are numbered from 1).
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum PointsError {
    /// A value on a line is not a number.
    #[error("line {line}: {text:?} is not a number")]
    NotANumber {
        /// Line number.
        line: usize,
        /// The offending field.
        text: String,
    },
    /// A point line does not have exactly two columns.
    #[error("line {line}: {found} columns; a point line has two (x y)")]
    Columns {
        /// Line number.
        line: usize,
        /// Columns found.
        found: usize,
    },
    /// A coordinate is infinite or NaN.
    #[error("line {line}: coordinate is not finite")]
    NotFinite {
        /// Line number.
        line: usize,
    },
    /// The Lednicer format (point counts after the name) is not supported.
    #[error("line {line}: looks like the point counts of a Lednicer-format file; give the points in one clockwise or Selig-order loop instead")]
    Lednicer {
        /// Line number.
        line: usize,
    },
    /// Fewer than three points.
    #[error("{0} points; at least 3 are needed")]
    TooFewPoints(usize),
    /// The points span far more or less than a chord: a file in other
    /// units (millimetres, metres, inches).
    #[error(
        "the points span {span:.4} (the larger of their extents in x and in y), but a section \
         file is in chords, spanning about 1 (from {} to {}): divide the coordinates by the \
         chord in the file's units",
        CHORD_SPAN.start(),
        CHORD_SPAN.end()
    )]
    NotInChords {
        /// The larger of the points' extents in x and y, in the file's
        /// units.
        span: f64,
    },
    /// The file could not be read.
    #[error("cannot read {path}: {message}")]
    Io {
        /// The file.
        path: String,
        /// The system's message.
        message: String,
    },
}

/// The contents of a point file.
#[derive(Clone, Debug, PartialEq)]
pub struct AirfoilPoints {
    /// The name line, if the file had one.
    pub name: Option<String>,
    /// The points `(x, y)`, chords, in file order.
    pub points: Vec<(f64, f64)>,
}

/// Splits a line into its fields (whitespace and commas separate them).
fn fields(line: &str) -> Vec<&str> {
    line.split(|c: char| c.is_whitespace() || c == ',')
        .filter(|f| !f.is_empty())
        .collect()
}

/// Parses a point file (see the module documentation for the format).
pub fn parse_points(text: &str) -> Result<AirfoilPoints, PointsError> {
    let mut name = None;
    let mut points = Vec::new();
    let mut first_content = true;
    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        let content = raw.split('#').next().unwrap_or("").trim();
        if content.is_empty() {
            continue;
        }
        let parsed: Result<Vec<f64>, &str> = fields(content)
            .into_iter()
            .map(|f| f.parse::<f64>().map_err(|_| f))
            .collect();
        let is_first = std::mem::replace(&mut first_content, false);
        let values = match parsed {
            // A Selig name line.
            Err(_) if is_first => {
                name = Some(content.to_string());
                continue;
            }
            Err(text) => {
                return Err(PointsError::NotANumber {
                    line,
                    text: text.to_string(),
                })
            }
            Ok(values) => values,
        };
        let [x, y] = values[..] else {
            return Err(PointsError::Columns {
                line,
                found: values.len(),
            });
        };
        if !x.is_finite() || !y.is_finite() {
            return Err(PointsError::NotFinite { line });
        }
        // Lednicer: "17. 17." counts (whole numbers > 1) as the first point.
        if points.is_empty() && x >= 2.0 && y >= 2.0 && x.fract() == 0.0 && y.fract() == 0.0 {
            return Err(PointsError::Lednicer { line });
        }
        points.push((x, y));
    }
    if points.len() < 3 {
        return Err(PointsError::TooFewPoints(points.len()));
    }
    let span = span(&points);
    if !CHORD_SPAN.contains(&span) {
        return Err(PointsError::NotInChords { span });
    }
    Ok(AirfoilPoints { name, points })
}

/// The spans a section file's points may have, in chords: wide enough for
/// a section turned or reaching past its chord (a circle of unit radius
/// spans 2), narrow enough to refuse a file in other units, whose
/// coefficients would be off by the square of the factor or worse
/// (before, a NACA 0012 in millimetres was refused by the Navier–Stokes
/// model for its Reynolds number, and "blew up" in the panel method).
pub const CHORD_SPAN: std::ops::RangeInclusive<f64> = 0.5..=2.0;

/// The larger of the extents of `points` in x and in y: the chord of a
/// section along x, the diameter of a circle, 0.71 for a plate turned by
/// 45°. Cost `O(n)`.
fn span(points: &[(f64, f64)]) -> f64 {
    let extent = |coordinate: fn(&(f64, f64)) -> f64| {
        let (low, high) = points
            .iter()
            .map(coordinate)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| {
                (l.min(v), h.max(v))
            });
        high - low
    };
    extent(|p| p.0).max(extent(|p| p.1))
}

/// Reads and parses a point file.
pub fn read_points(path: &std::path::Path) -> Result<AirfoilPoints, PointsError> {
    let text = std::fs::read_to_string(path).map_err(|e| PointsError::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    })?;
    parse_points(&text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn designations_parse() {
        let n: Naca4 = "naca2412".parse().unwrap();
        assert_eq!((n.camber, n.camber_position), (0.02, 0.4));
        assert!((n.thickness - 0.12).abs() < 1e-15);
        assert!("NACA 0012".parse::<Naca4>().is_ok());
        assert!(" naca-0006 ".parse::<Naca4>().is_ok());
        for bad in ["", "12", "00120", "naca", "x012", "0.12", "nac0012"] {
            assert!(
                matches!(bad.parse::<Naca4>(), Err(NacaError::Designation(_))),
                "{bad}"
            );
        }
        assert_eq!(
            "2012".parse::<Naca4>(),
            Err(NacaError::CamberPosition("2012".into()))
        );
        assert_eq!(
            "0000".parse::<Naca4>(),
            Err(NacaError::ZeroThickness("0000".into()))
        );
    }

    /// Abbott & von Doenhoff's ordinates of the NACA 0012 (Theory of Wing
    /// Sections, appendix I, original open trailing edge): y = 6.002% at
    /// x = 0.3 and 0.126% at x = 1 (5 t 0.0021); the closed edge has 0 at
    /// x = 1 and is thinner by `0.0105 t x^4` elsewhere.
    #[test]
    fn thickness_matches_the_tables() {
        let n: Naca4 = "0012".parse().unwrap();
        assert!((n.half_thickness(0.3, TrailingEdge::Open) - 0.06002).abs() < 5e-5);
        assert!((n.half_thickness(1.0, TrailingEdge::Open) - 0.00126).abs() < 1e-5);
        assert!(n.half_thickness(1.0, TrailingEdge::Closed).abs() < 1e-15);
        for i in 0..=100 {
            let x = i as f64 / 100.0;
            let d =
                n.half_thickness(x, TrailingEdge::Open) - n.half_thickness(x, TrailingEdge::Closed);
            assert!((d - 0.0105 * 0.12 * x.powi(4)).abs() < 1e-12);
        }
    }

    #[test]
    fn points_run_clockwise_from_the_trailing_edge() {
        let n: Naca4 = "2412".parse().unwrap();
        let p = n.points(40, TrailingEdge::Closed).unwrap();
        assert_eq!(p.len(), 41);
        assert_eq!(p[0], p[40]);
        assert!((p[0].0 - 1.0).abs() < 1e-12 && p[20] == (0.0, 0.0));
        // Lower surface first: below the camber line.
        assert!(p[10].1 < n.camber_line(p[10].0).0 && p[30].1 > n.camber_line(p[30].0).0);
        // Clockwise: negative shoelace area, about the section area.
        let area: f64 = p
            .windows(2)
            .map(|w| w[0].0 * w[1].1 - w[1].0 * w[0].1)
            .sum::<f64>()
            / 2.0;
        assert!(area < -0.08 && area > -0.09, "{area}");
        let open = n.points(40, TrailingEdge::Open).unwrap();
        assert!(open[40].1 - open[0].1 > 0.002);
        assert_eq!(
            n.points(41, TrailingEdge::Closed),
            Err(NacaError::Panels(41))
        );
        assert_eq!(n.points(2, TrailingEdge::Closed), Err(NacaError::Panels(2)));
    }

    /// A section in millimetres (the NACA 0012 on a 75 mm chord) or
    /// metres is refused with its span; one in chords, a circle of unit
    /// radius too, is read.
    #[test]
    fn point_files_in_other_units_are_refused() {
        let n: Naca4 = "0012".parse().unwrap();
        let points = n.points(40, TrailingEdge::Closed).unwrap();
        let file = |scale: f64| {
            points
                .iter()
                .map(|(x, y)| format!("{} {}\n", scale * x, scale * y))
                .collect::<String>()
        };
        assert_eq!(parse_points(&file(1.0)).unwrap().points.len(), 41);
        for scale in [75.0, 0.075] {
            let e = parse_points(&file(scale)).unwrap_err();
            let PointsError::NotInChords { span } = e else {
                panic!("{e:?}")
            };
            assert!((span - scale).abs() < 1e-9 * scale, "{span}");
            assert!(e.to_string().contains("divide the coordinates"), "{e}");
        }
        let circle: String = (0..64)
            .map(|i| {
                let t = std::f64::consts::TAU * f64::from(i) / 64.0;
                format!("{} {}\n", t.cos(), t.sin())
            })
            .collect();
        assert!(parse_points(&circle).is_ok());
    }

    #[test]
    fn point_files_parse_or_name_the_bad_line() {
        let text = "SD7003 (Selig)\n 1.0 0.0\n0.5, 0.05 # upper\n\n# comment\n0.0 0.0\n0.5\t-0.03\n1.0 0.0\n";
        let a = parse_points(text).unwrap();
        assert_eq!(a.name.as_deref(), Some("SD7003 (Selig)"));
        assert_eq!(a.points.len(), 5);
        assert_eq!(a.points[1], (0.5, 0.05));
        assert!(parse_points("1 0\n0 0\n1 0.1\n").unwrap().name.is_none());
        assert_eq!(
            parse_points("name\n1 0\n0.5 abc\n"),
            Err(PointsError::NotANumber {
                line: 3,
                text: "abc".into()
            })
        );
        assert_eq!(
            parse_points("1 0\n0.5 0.1 0.2\n0 0\n"),
            Err(PointsError::Columns { line: 2, found: 3 })
        );
        assert_eq!(
            parse_points("1 0\n0.5 NaN\n0 0\n"),
            Err(PointsError::NotFinite { line: 2 })
        );
        assert_eq!(
            parse_points("NACA 0012\n 66. 66.\n0 0\n"),
            Err(PointsError::Lednicer { line: 2 })
        );
        assert_eq!(
            parse_points("name\n1 0\n0 0\n"),
            Err(PointsError::TooFewPoints(2))
        );
        assert_eq!(parse_points(""), Err(PointsError::TooFewPoints(0)));
        // A second name-like line is an error, not a name.
        assert!(matches!(
            parse_points("name\nother\n1 0\n0 0\n0.5 0.1\n"),
            Err(PointsError::NotANumber { line: 2, .. })
        ));
        assert!(matches!(
            read_points(std::path::Path::new("/nonexistent/x.dat")),
            Err(PointsError::Io { .. })
        ));
    }
}
