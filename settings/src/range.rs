//! Allowed ranges as data — real intervals with closed, open or
//! unbounded sides, integer ranges, increasing sequences, flags and
//! choices — and the text people read for them (generated here, never
//! written by hand). Imports nothing but `std`.

use std::fmt;

use crate::shown::Shown;

/// One side of a real interval.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Bound {
    /// The value itself is allowed.
    Closed(f64),
    /// Values up to, but not including, this one.
    Open(f64),
    /// No limit on this side (finite values only: a setting is never
    /// infinite or NaN).
    Unbounded,
}

/// A real interval: finite values between two [`Bound`]s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// The lower side.
    pub low: Bound,
    /// The upper side.
    pub high: Bound,
}

impl Interval {
    /// `[low, high]`.
    pub const fn closed(low: f64, high: f64) -> Self {
        Self {
            low: Bound::Closed(low),
            high: Bound::Closed(high),
        }
    }

    /// `(low, high)`.
    pub const fn open(low: f64, high: f64) -> Self {
        Self {
            low: Bound::Open(low),
            high: Bound::Open(high),
        }
    }

    /// `(low, high]`.
    pub const fn above_up_to(low: f64, high: f64) -> Self {
        Self {
            low: Bound::Open(low),
            high: Bound::Closed(high),
        }
    }

    /// `[low, inf)`.
    pub const fn at_least(low: f64) -> Self {
        Self {
            low: Bound::Closed(low),
            high: Bound::Unbounded,
        }
    }

    /// `(low, inf)`.
    pub const fn above(low: f64) -> Self {
        Self {
            low: Bound::Open(low),
            high: Bound::Unbounded,
        }
    }

    /// `(0, inf)`.
    pub const fn positive() -> Self {
        Self::above(0.0)
    }

    /// `(-inf, inf)`: any finite value.
    pub const fn finite() -> Self {
        Self {
            low: Bound::Unbounded,
            high: Bound::Unbounded,
        }
    }

    /// Whether `value` is finite and inside (NaN and infinities never are).
    pub fn contains(&self, value: f64) -> bool {
        let above = match self.low {
            Bound::Closed(l) => value >= l,
            Bound::Open(l) => value > l,
            Bound::Unbounded => true,
        };
        let below = match self.high {
            Bound::Closed(h) => value <= h,
            Bound::Open(h) => value < h,
            Bound::Unbounded => true,
        };
        value.is_finite() && above && below
    }
}

impl fmt::Display for Interval {
    /// `[0.01, 2]`, `(0, 1]`, `[0, inf)`, `(-inf, inf)`; very small or
    /// large bounds in exponent form (`1e-12`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.low {
            Bound::Closed(l) => write!(f, "[{}", Shown(l))?,
            Bound::Open(l) => write!(f, "({}", Shown(l))?,
            Bound::Unbounded => f.write_str("(-inf")?,
        }
        match self.high {
            Bound::Closed(h) => write!(f, ", {}]", Shown(h)),
            Bound::Open(h) => write!(f, ", {})", Shown(h)),
            Bound::Unbounded => f.write_str(", inf)"),
        }
    }
}

/// An integer range, inclusive, with an optional upper end.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Integers {
    /// The smallest value allowed.
    pub min: i64,
    /// The largest value allowed, `None`: no limit.
    pub max: Option<i64>,
}

impl Integers {
    /// `min..=max`.
    pub const fn between(min: i64, max: i64) -> Self {
        Self {
            min,
            max: Some(max),
        }
    }

    /// `min` or more.
    pub const fn at_least(min: i64) -> Self {
        Self { min, max: None }
    }

    /// Whether `value` is inside.
    pub fn contains(&self, value: i64) -> bool {
        value >= self.min && self.max.is_none_or(|m| value <= m)
    }
}

impl fmt::Display for Integers {
    /// `2..=400` or `>= 4`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.max {
            Some(max) => write!(f, "{}..={max}", self.min),
            None => write!(f, ">= {}", self.min),
        }
    }
}

/// What values a setting allows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Allowed {
    /// A finite real in the interval.
    Real(Interval),
    /// An integer in the range.
    Integer(Integers),
    /// A strictly increasing sequence of finite reals, each in the
    /// interval (levels, breakpoints).
    Increasing(Interval),
    /// `true` or `false`.
    Flag,
    /// One of these words.
    Choice(&'static [&'static str]),
}

impl fmt::Display for Allowed {
    /// The range as people read it, without its unit (see [`Limits`]).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Allowed::Real(i) => write!(f, "{i}"),
            Allowed::Integer(i) => write!(f, "{i}"),
            Allowed::Increasing(i) => write!(f, "increasing, each in {i}"),
            Allowed::Flag => f.write_str("true or false"),
            Allowed::Choice(words) => {
                for (n, w) in words.iter().enumerate() {
                    match n {
                        0 => {}
                        n if n + 1 == words.len() => f.write_str(" or ")?,
                        _ => f.write_str(", ")?,
                    }
                    write!(f, "\"{w}\"")?;
                }
                Ok(())
            }
        }
    }
}

/// A range with its unit: the text of an error and a template comment
/// (`[0.01, 2] m`, `1..=50`, `increasing, each in [0, 80] deg`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limits {
    /// The values allowed.
    pub allowed: Allowed,
    /// Their unit, `""` for none.
    pub unit: &'static str,
}

impl fmt::Display for Limits {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.allowed)?;
        if !self.unit.is_empty() {
            write!(f, " {}", self.unit)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each kind of side reads as written in mathematics; NaN and the
    /// infinities are never inside.
    #[test]
    fn intervals_read_and_contain() {
        assert_eq!(Interval::closed(0.01, 2.0).to_string(), "[0.01, 2]");
        assert_eq!(Interval::above_up_to(0.0, 1.0).to_string(), "(0, 1]");
        assert_eq!(Interval::at_least(0.0).to_string(), "[0, inf)");
        assert_eq!(Interval::positive().to_string(), "(0, inf)");
        assert_eq!(Interval::finite().to_string(), "(-inf, inf)");
        assert_eq!(Interval::closed(1e-12, 0.5).to_string(), "[1e-12, 0.5]");
        assert_eq!(Interval::closed(1e-4, 1e6).to_string(), "[1e-4, 1e6]");
        assert_eq!(Interval::closed(-60.0, 60.0).to_string(), "[-60, 60]");
        let unit = Interval::above_up_to(0.0, 1.0);
        assert!(!unit.contains(0.0) && unit.contains(1e-300) && unit.contains(1.0));
        assert!(!unit.contains(f64::NAN) && !unit.contains(1.0 + f64::EPSILON));
        assert!(!Interval::finite().contains(f64::INFINITY));
        assert!(!Interval::at_least(0.0).contains(f64::NEG_INFINITY));
        assert!(Interval::finite().contains(-1e300));
        let open = Interval::open(0.0, 180.0);
        assert_eq!(open.to_string(), "(0, 180)");
        assert!(!open.contains(0.0) && !open.contains(180.0) && open.contains(179.999));
    }

    #[test]
    fn integers_choices_and_units_read() {
        assert_eq!(Integers::between(1, 50).to_string(), "1..=50");
        assert_eq!(Integers::at_least(4).to_string(), ">= 4");
        assert!(Integers::at_least(4).contains(i64::MAX));
        assert!(!Integers::between(1, 50).contains(51));
        let limits = Limits {
            allowed: Allowed::Increasing(Interval::closed(0.0, 80.0)),
            unit: "deg",
        };
        assert_eq!(limits.to_string(), "increasing, each in [0, 80] deg");
        assert_eq!(
            Allowed::Choice(&["a", "b", "c"]).to_string(),
            "\"a\", \"b\" or \"c\""
        );
        assert_eq!(Allowed::Choice(&["only"]).to_string(), "\"only\"");
    }
}
