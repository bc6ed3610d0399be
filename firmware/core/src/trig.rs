//! Sine and cosine in single precision, for the control step.
//!
//! The STM32F405's FPU does single precision only, and libm's `sincosf`
//! reduces its argument and evaluates its kernels in `f64`, which the
//! microcontroller computes in software: about 1,300 instructions a call,
//! measured on the emulated Cortex-M4F (`firmware/qemu`'s step-cost
//! benchmark), with two calls in every control step. [`sincos`] stays in
//! `f32`: about 60 instructions.
//!
//! Method: `x = k pi/2 + r` with `k = round(2x/pi)` and `|r| <= pi/4`
//! (slightly more when `2x/pi` rounds the other way), `r` computed with
//! `pi/2` split into a head of 16 significant bits, so that `k * head` is
//! exact for `|k| <= 128`, and the rest (Cody & Waite's reduction); `sin r`
//! and `cos r` by their Taylor series through `r^9` and `r^10` (the first
//! terms left out are below `2e-9` for `|r| <= pi/4`), in Horner form; the
//! quadrant `k mod 4` swaps and negates. Within `1.5e-7` of the exact
//! values for `|x| <= 200` (tested against `f64`); beyond, and for
//! non-finite `x`, it is libm's `sincosf`.

use core::f32::consts::FRAC_2_PI;

/// `pi/2` to 16 significant bits (`0x3FC9_0F00`).
const PIO2_HEAD: f32 = f32::from_bits(0x3FC9_0F00);
/// `pi/2 - PIO2_HEAD`, rounded to `f32`.
const PIO2_TAIL: f32 = (core::f64::consts::FRAC_PI_2 - PIO2_HEAD as f64) as f32;
/// Largest `|x|` reduced here (`|k| <= 128`).
const REDUCED_LIMIT: f32 = 200.0;

/// `(sin x, cos x)`, `x` in radians (see the module docs for accuracy).
pub fn sincos(x: f32) -> (f32, f32) {
    // NaN and infinities fail `is_finite`; both go to libm.
    if !x.is_finite() || libm::fabsf(x) > REDUCED_LIMIT {
        return libm::sincosf(x);
    }
    let k = libm::roundf(x * FRAC_2_PI);
    let r = (x - k * PIO2_HEAD) - k * PIO2_TAIL;
    let (s, c) = (sin_taylor(r), cos_taylor(r));
    match (k as i32) & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// `sin r` for `|r| <~ pi/4`: `r - r^3/3! + r^5/5! - r^7/7! + r^9/9!`.
fn sin_taylor(r: f32) -> f32 {
    let z = r * r;
    let p = 1.0 / 362_880.0;
    let p = p * z - 1.0 / 5_040.0;
    let p = p * z + 1.0 / 120.0;
    let p = p * z - 1.0 / 6.0;
    r + r * z * p
}

/// `cos r` for `|r| <~ pi/4`: `1 - r^2/2! + r^4/4! - ... + r^10/10!`.
fn cos_taylor(r: f32) -> f32 {
    let z = r * r;
    let p = -1.0 / 3_628_800.0;
    let p = p * z + 1.0 / 40_320.0;
    let p = p * z - 1.0 / 720.0;
    let p = p * z + 1.0 / 24.0;
    let p = p * z - 0.5;
    1.0 + z * p
}

#[cfg(test)]
mod tests {
    use super::*;

    fn worst_error(from: f32, to: f32, samples: u32) -> f64 {
        let mut worst = 0.0f64;
        for i in 0..=samples {
            let x = from + (to - from) * (i as f32 / samples as f32);
            let (s, c) = sincos(x);
            let exact = f64::from(x);
            worst = worst
                .max((f64::from(s) - exact.sin()).abs())
                .max((f64::from(c) - exact.cos()).abs());
        }
        worst
    }

    /// Against `f64` over the range the controller uses (`theta` in
    /// `[pi/2, 5pi/2)`) and the whole reduced range, densely.
    #[test]
    fn sincos_is_within_1_5e_7_of_the_exact_values() {
        let controller = worst_error(0.0, 8.0, 400_000);
        let reduced = worst_error(-REDUCED_LIMIT, REDUCED_LIMIT, 2_000_000);
        assert!(controller < 1.5e-7, "{controller:e}");
        assert!(reduced < 1.5e-7, "{reduced:e}");
    }

    /// Quadrant boundaries (where `2x/pi` is near a half-integer and `k`
    /// may round either way) and the reduction's exactness near multiples
    /// of `pi/2`.
    #[test]
    fn boundaries_and_multiples_of_pi_over_2() {
        for k in -127..=127 {
            for frac in [-0.5f64, -0.25, 0.0, 0.25, 0.5] {
                let x64 = (f64::from(k) + frac) * core::f64::consts::FRAC_PI_2;
                for x in [x64 as f32, f32::from_bits((x64 as f32).to_bits() + 1)] {
                    let (s, c) = sincos(x);
                    let e = f64::from(x);
                    assert!((f64::from(s) - e.sin()).abs() < 1.5e-7, "sin {x}");
                    assert!((f64::from(c) - e.cos()).abs() < 1.5e-7, "cos {x}");
                }
            }
        }
    }

    /// Outside the reduced range and for non-finite input it is libm's.
    #[test]
    fn large_and_non_finite_arguments_are_libms() {
        for x in [
            1e3f32,
            -5e4,
            3e30,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ] {
            let (s, c) = sincos(x);
            let (ls, lc) = libm::sincosf(x);
            assert!(
                s.to_bits() == ls.to_bits() || (s.is_nan() && ls.is_nan()),
                "{x}"
            );
            assert!(
                c.to_bits() == lc.to_bits() || (c.is_nan() && lc.is_nan()),
                "{x}"
            );
        }
        assert_eq!(sincos(0.0), (0.0, 1.0));
    }
}
