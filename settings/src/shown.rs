//! A real number as a message shows a value someone gave.
//!
//! Rust's `{}` writes an `f64` in full decimal, so a mistyped `1e300`
//! came back in an error as a line of 301 digits, and `1e-300` as 300
//! zeros. [`Shown`] writes the same shortest round-trip form as `{}`
//! where that is short (`-3`, `0.25`, `15000`), and powers of ten
//! (`1e300`, `2.5e-9`) where it is not. The formatter's flags apply to
//! either as to an `f64`: a width and alignment with their fill
//! (`{:>10.3}`), `+`, and zero padding. A precision is the digits after
//! the point, of the number or of its mantissa (`{:.2}` of 1e300 is
//! `1.00e300`).
//!
//! ```
//! use fwav_settings::Shown;
//!
//! assert_eq!(Shown(15000.0).to_string(), "15000");
//! assert_eq!(Shown(1e300).to_string(), "1e300");
//! assert_eq!(Shown(-2.5e-9).to_string(), "-2.5e-9");
//! assert_eq!(format!("{:.3}", Shown(0.25)), "0.250");
//! assert_eq!(format!("{:>10.3}", Shown(1e300)), " 1.000e300");
//! assert_eq!(format!("{:>9.3}", Shown(11.0)), "   11.000");
//! assert_eq!(Shown(f64::NAN).to_string(), "NaN");
//! ```

use std::fmt;

/// A real number shown in plain decimals when its magnitude is in
/// `[1e-3, 1e6)` (or it is 0, infinite or NaN), in powers of ten
/// otherwise. See the module docs. The declared ranges' bounds are shown
/// so too (`[100, 1e8]`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shown(pub f64);

/// The magnitudes written in plain decimals: six digits before the point
/// at most, and no more than two zeros after it before the first digit.
const PLAIN: std::ops::Range<f64> = 1e-3..1e6;

impl Shown {
    /// A computed `x` rounded to `digits` significant digits (at least 1),
    /// then shown as any: `0.012067370231250001` to 6 is `0.0120674`. A
    /// value the user typed is shown as typed, with [`Shown`] itself.
    pub fn rounded(x: f64, digits: usize) -> Self {
        if !x.is_finite() || x == 0.0 {
            return Self(x);
        }
        let p = digits.max(1) - 1;
        Self(format!("{x:.p$e}").parse().unwrap_or(x))
    }

    /// A least value a message suggests (`set x to at least ...`), `x`
    /// rounded up to `decimals` places, so that the value as printed
    /// passes: a speed of 0.122522 m/s is suggested as 0.123, where
    /// `{:.3}` wrote 0.123 for 0.12249 too, below what it must be.
    pub fn at_least(x: f64, decimals: i32) -> Self {
        let scale = 10f64.powi(decimals);
        Self((x * scale).ceil() / scale)
    }

    /// A most value a message suggests, `x` rounded down to `decimals`
    /// places ([`Self::at_least`]'s other side).
    pub fn at_most(x: f64, decimals: i32) -> Self {
        let scale = 10f64.powi(decimals);
        Self((x * scale).floor() / scale)
    }

    /// Whether the number is written in plain decimals: its magnitude in
    /// `[1e-3, 1e6)`, or 0, infinite or NaN.
    pub fn is_plain(self) -> bool {
        let x = self.0;
        x == 0.0 || !x.is_finite() || PLAIN.contains(&x.abs())
    }
}

impl fmt::Display for Shown {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        let plain = self.is_plain();
        let mut text = match (plain, f.precision()) {
            (true, None) => format!("{x}"),
            (true, Some(p)) => format!("{x:.p$}"),
            (false, None) => format!("{x:e}"),
            (false, Some(p)) => format!("{x:.p$e}"),
        };
        if f.sign_plus() && !text.starts_with('-') && !x.is_nan() {
            text.insert(0, '+');
        }
        let width = f.width().unwrap_or(0);
        let length = text.chars().count();
        if length >= width {
            return f.write_str(&text);
        }
        let pad = width - length;
        if f.sign_aware_zero_pad() && x.is_finite() {
            let sign = usize::from(text.starts_with(['+', '-']));
            text.insert_str(sign, &"0".repeat(pad));
            return f.write_str(&text);
        }
        let fill = |n: usize| f.fill().to_string().repeat(n);
        let (before, after) = match f.align() {
            Some(fmt::Alignment::Left) => (0, pad),
            Some(fmt::Alignment::Center) => (pad / 2, pad - pad / 2),
            Some(fmt::Alignment::Right) | None => (pad, 0),
        };
        write!(f, "{}{text}{}", fill(before), fill(after))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A suggested bound passes as printed.
    #[test]
    fn suggested_bounds_pass_as_printed() {
        assert_eq!(Shown::at_least(0.122_522, 3).to_string(), "0.123");
        assert_eq!(Shown::at_least(0.122_49, 3).to_string(), "0.123");
        assert_eq!(Shown::at_most(10.610_3, 2).to_string(), "10.61");
        assert_eq!(Shown::at_most(10.619_9, 2).to_string(), "10.61");
        assert_eq!(Shown::at_least(2.0, 2).to_string(), "2");
    }

    /// Every magnitude at the edges of the plain range, and the values a
    /// message meets.
    #[test]
    fn long_numbers_are_written_in_powers_of_ten() {
        for (x, text) in [
            (0.0, "0"),
            (-0.0, "-0"),
            (1e-3, "0.001"),
            (9.99e-4, "9.99e-4"),
            (999_999.0, "999999"),
            (1e6, "1e6"),
            (1e308, "1e308"),
            (-1e-300, "-1e-300"),
            (f64::INFINITY, "inf"),
            (f64::NEG_INFINITY, "-inf"),
            (0.1 + 0.2, "0.30000000000000004"),
        ] {
            assert_eq!(Shown(x).to_string(), text, "{x:e}");
        }
        assert_eq!(format!("{:<8.1}|", Shown(2.0)), "2.0     |");
        assert_eq!(format!("{:.2}", Shown(1e300)), "1.00e300");
        // The formatter's sign, fill and zero padding, as f64's own.
        assert_eq!(format!("{:+.3}", Shown(0.5)), "+0.500");
        assert_eq!(format!("{:+}", Shown(-2e9)), "-2e9");
        assert_eq!(format!("{:*>8}", Shown(1.5)), "*****1.5");
        assert_eq!(format!("{:^7}", Shown(1.5)), "  1.5  ");
        assert_eq!(format!("{:08.3}", Shown(-1.5)), "-001.500");
        assert_eq!(format!("{:+08.1}", Shown(2e9)), "+002.0e9");
        for x in [0.25, -3.0, 123.5] {
            for text in [
                (format!("{:+08.2}", Shown(x)), format!("{x:+08.2}")),
                (format!("{:*<9.1}", Shown(x)), format!("{x:*<9.1}")),
            ] {
                assert_eq!(text.0, text.1);
            }
        }
        // A computed value to significant digits.
        assert_eq!(
            Shown::rounded(0.012067370231250001, 6).to_string(),
            "0.0120674"
        );
        assert_eq!(Shown::rounded(1.0000284, 6).to_string(), "1.00003");
        assert_eq!(Shown::rounded(-2.5e300, 3).to_string(), "-2.5e300");
        assert_eq!(Shown::rounded(f64::NAN, 3).to_string(), "NaN");
        // Every number shown parses back to the value (the shortest
        // round-trip form, in either notation).
        for x in [1e300, 2.5e-9, 123456.789, 1e-3, 3e7] {
            assert_eq!(Shown(x).to_string().parse::<f64>().unwrap(), x);
        }
    }
}
