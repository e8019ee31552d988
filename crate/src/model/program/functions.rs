//! The built-in functions of expressions (`sin`, `clamp`, …), the random ones (`uniform`,
//! `normal`, …) drawing from the evaluation's generator.

use crate::maths;
use crate::number::Decimal;
use crate::vocabulary::Function;
use rand::RngExt;
use rand_distr::{Binomial, Distribution, Exp, Normal, Poisson, StandardNormal};
use std::fmt::Write;

/// `x` limited to 0 … 1: the growth functions' normalised age (NaN stays NaN, an error later).
fn unit(x: f64) -> f64 {
    x.clamp(0.0, 1.0)
}

/// `name(a, b, …)` with the numbers as Rust writes them ([`Decimal`]), for the messages.
fn called(name: &str, args: &[f64]) -> String {
    let mut text = format!("{name}(");
    for (k, v) in args.iter().enumerate() {
        let _ = write!(text, "{}{}", if k > 0 { ", " } else { "" }, Decimal(*v));
    }
    text.push(')');
    text
}

/// The value of `f` at the arguments `a`, or why the arguments are invalid.
pub(super) fn call<R: rand::Rng + ?Sized>(
    f: Function,
    a: &[f64],
    rng: &mut R,
) -> Result<f64, String> {
    let deg = |x: f64| x.to_radians();
    Ok(match f {
        Function::Sin => maths::sin(deg(a[0])),
        Function::Cos => maths::cos(deg(a[0])),
        Function::Tan => maths::tan(deg(a[0])),
        Function::Asin => maths::asin(a[0]).to_degrees(),
        Function::Acos => maths::acos(a[0]).to_degrees(),
        Function::Atan => maths::atan(a[0]).to_degrees(),
        Function::Atan2 => maths::atan2(a[0], a[1]).to_degrees(),
        Function::Sqrt => a[0].sqrt(),
        Function::Exp => maths::exp(a[0]),
        Function::Log => maths::ln(a[0]),
        Function::Abs => a[0].abs(),
        Function::Floor => a[0].floor(),
        Function::Ceil => a[0].ceil(),
        Function::Round => a[0].round(),
        Function::Min => a[0].min(a[1]),
        Function::Max => a[0].max(a[1]),
        Function::Clamp => a[0].max(a[1]).min(a[2]),
        Function::Sign => {
            if a[0] > 0.0 {
                1.0
            } else if a[0] < 0.0 {
                -1.0
            } else {
                0.0
            }
        }
        Function::Constant => a[0],
        Function::Linear | Function::ExponentialGrowth | Function::Logistic | Function::Sigmoid => {
            growth(f, a)?
        }
        Function::Uniform => {
            if a[0] > a[1] {
                return Err(format!(
                    "{}: the lower bound is above the upper",
                    called("uniform", &a[..2])
                ));
            }
            a[0] + (a[1] - a[0]) * rng.random::<f64>()
        }
        Function::UniformInt => {
            let (lo, hi) = (a[0].ceil(), a[1].floor());
            if lo > hi {
                return Err(format!(
                    "{}: no whole number in the range",
                    called("uniform_int", &a[..2])
                ));
            }
            (lo + (rng.random::<f64>() * (hi - lo + 1.0)).floor()).min(hi)
        }
        // rand_distr takes a negative deviation as a mirror image; like `exponential`'s negative
        // rate, it is an error here.
        Function::Normal => Normal::new(a[0], a[1])
            .ok()
            .filter(|_| a[1] >= 0.0)
            .ok_or_else(|| format!("{}: the deviation must be ≥ 0", called("normal", &a[..2])))?
            .sample(rng),
        Function::Exponential => Exp::new(a[0])
            .map_err(|_| format!("{}: the rate must be ≥ 0", called("exponential", &a[..1])))?
            .sample(rng),
        Function::Binomial => binomial(a[0], a[1], rng)?,
        Function::Poisson => poisson(a[0], rng)?,
        Function::Beta => beta(a[0], a[1], rng)?,
    })
}

/// `binomial(n, p)`: a count of successes among n trials.
fn binomial<R: rand::Rng + ?Sized>(n: f64, p: f64, rng: &mut R) -> Result<f64, String> {
    if !(0.0..=1e12).contains(&n) {
        return Err(format!(
            "{}: n must be a count from 0 to 10^12",
            called("binomial", &[n, p])
        ));
    }
    Ok(Binomial::new(n as u64, p)
        .map_err(|_| format!("{}: p must be in 0..1", called("binomial", &[n, p])))?
        .sample(rng) as f64)
}

/// rand_distr's largest Poisson mean (`Poisson::MAX_LAMBDA`) as `{:e}` writes it: a constant text,
/// so that the first plant's core carries no float-to-exponent formatting (issue 22; a test checks
/// it against the number).
const MAX_POISSON_MEAN_TEXT: &str = "1.844e19";

/// `poisson(mean)`: a count. A mean of 0 is legitimate, the count always 0 (rand_distr refuses
/// it; issue 50, 12).
fn poisson<R: rand::Rng + ?Sized>(mean: f64, rng: &mut R) -> Result<f64, String> {
    if mean == 0.0 {
        return Ok(0.0);
    }
    Ok(Poisson::new(mean)
        .map_err(|_| {
            format!(
                "{}: the mean must be from 0 to {MAX_POISSON_MEAN_TEXT}",
                called("poisson", &[mean])
            )
        })?
        .sample(rng))
}

/// `betavariate(a, b)`: X / (X + Y) of two gamma draws of shapes `a` and `b`.
fn beta<R: rand::Rng + ?Sized>(a: f64, b: f64, rng: &mut R) -> Result<f64, String> {
    if !(a > 0.0 && b > 0.0 && a.is_finite() && b.is_finite()) {
        return Err(format!(
            "{}: the shapes must be > 0",
            called("betavariate", &[a, b])
        ));
    }
    let (x, y) = (gamma(a, rng), gamma(b, rng));
    Ok(if x + y > 0.0 {
        x / (x + y)
    } else {
        // Both shapes so small that both draws underflowed: the mass is at 0 and 1.
        f64::from(u8::from(rng.random::<f64>() * (a + b) < a))
    })
}

/// A draw of the gamma distribution of shape `k` > 0 (scale 1), by Marsaglia and Tsang's method
/// (2000), with `u^(1/k)` for shapes under 1: betavariate's X / (X + Y). Written here rather than
/// taken from rand_distr's Beta, whose two algorithms the first plant's core has no room for.
fn gamma<R: rand::Rng + ?Sized>(k: f64, rng: &mut R) -> f64 {
    if k < 1.0 {
        let u: f64 = rng.random();
        return gamma(k + 1.0, rng) * maths::powf(u, 1.0 / k);
    }
    let d = k - 1.0 / 3.0;
    let c = 1.0 / (9.0 * d).sqrt();
    loop {
        let x: f64 = StandardNormal.sample(rng);
        let v = 1.0 + c * x;
        if v <= 0.0 {
            continue;
        }
        let v = v * v * v;
        let u: f64 = rng.random();
        if u > 0.0 && maths::ln(u) < 0.5 * x * x + d - d * v + d * maths::ln(v) {
            return d * v;
        }
    }
}

/// The growth functions (ABOP section 6.2) at `a[0]`, the age as a fraction of the terminal age,
/// limited to 0 … 1: from `a[1]` at 0 to `a[2]` at 1.
fn growth(f: Function, a: &[f64]) -> Result<f64, String> {
    Ok(match f {
        Function::Linear => a[1] + (a[2] - a[1]) * unit(a[0]),
        Function::ExponentialGrowth => {
            if !(a[1] > 0.0 && a[2] > 0.0) {
                return Err(format!(
                    "{}: a and b must be above 0",
                    called("exponential_growth", &a[..3])
                ));
            }
            a[1] * maths::powf(a[2] / a[1], unit(a[0]))
        }
        Function::Logistic => {
            if a[3].is_nan() || a[3] <= 0.0 {
                return Err(format!(
                    "{}: the steepness k must be above 0",
                    called("logistic", &a[..4])
                ));
            }
            let curve = |x: f64| 1.0 / (1.0 + maths::exp(-a[3] * (x - 0.5)));
            let (lo, hi) = (curve(0.0), curve(1.0));
            a[1] + (a[2] - a[1]) * (curve(unit(a[0])) - lo) / (hi - lo)
        }
        Function::Sigmoid => {
            let x = unit(a[0]);
            a[1] + (a[2] - a[1]) * x * x * (3.0 - 2.0 * x)
        }
        _ => a[0],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_poisson_limit_text_is_the_limit() {
        assert_eq!(
            format!("{:e}", Poisson::<f64>::MAX_LAMBDA),
            MAX_POISSON_MEAN_TEXT
        );
    }
}
