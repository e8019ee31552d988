//! The built-in functions of expressions (`sin`, `clamp`, …), the random ones (`uniform`,
//! `normal`, …) drawing from the evaluation's generator.

use crate::vocabulary::Function;
use rand::RngExt;
use rand_distr::{Binomial, Distribution, Exp, Normal, Poisson};

/// The value of `f` at the arguments `a`, or why the arguments are invalid.
pub(super) fn call<R: rand::Rng + ?Sized>(
    f: Function,
    a: &[f64],
    rng: &mut R,
) -> Result<f64, String> {
    let deg = |x: f64| x.to_radians();
    Ok(match f {
        Function::Sin => deg(a[0]).sin(),
        Function::Cos => deg(a[0]).cos(),
        Function::Tan => deg(a[0]).tan(),
        Function::Asin => a[0].asin().to_degrees(),
        Function::Acos => a[0].acos().to_degrees(),
        Function::Atan => a[0].atan().to_degrees(),
        Function::Atan2 => a[0].atan2(a[1]).to_degrees(),
        Function::Sqrt => a[0].sqrt(),
        Function::Exp => a[0].exp(),
        Function::Log => a[0].ln(),
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
        Function::Uniform => {
            if a[0] > a[1] {
                return Err(format!(
                    "uniform({}, {}): the lower bound is above the upper",
                    a[0], a[1]
                ));
            }
            a[0] + (a[1] - a[0]) * rng.random::<f64>()
        }
        Function::UniformInt => {
            let (lo, hi) = (a[0].ceil(), a[1].floor());
            if lo > hi {
                return Err(format!(
                    "uniform_int({}, {}): no whole number in the range",
                    a[0], a[1]
                ));
            }
            (lo + (rng.random::<f64>() * (hi - lo + 1.0)).floor()).min(hi)
        }
        Function::Normal => Normal::new(a[0], a[1])
            .map_err(|_| format!("normal({}, {}): the deviation must be ≥ 0", a[0], a[1]))?
            .sample(rng),
        Function::Exponential => Exp::new(a[0])
            .map_err(|_| format!("exponential({}): the rate must be ≥ 0", a[0]))?
            .sample(rng),
        Function::Binomial => {
            if !(a[0] >= 0.0 && a[0] <= 1e12) {
                return Err(format!(
                    "binomial({}, {}): n must be a count from 0 to 10^12",
                    a[0], a[1]
                ));
            }
            Binomial::new(a[0] as u64, a[1])
                .map_err(|_| format!("binomial({}, {}): p must be in 0..1", a[0], a[1]))?
                .sample(rng) as f64
        }
        Function::Poisson => Poisson::new(a[0])
            .map_err(|_| format!("poisson({}): the mean must be > 0", a[0]))?
            .sample(rng),
    })
}
