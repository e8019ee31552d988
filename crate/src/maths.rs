//! The core's transcendental functions: the same bits natively and in WebAssembly.
//!
//! `f64::sin`, `exp`, `ln`, `powf` and the like are not one function. Natively they call the C
//! library (glibc on Linux, another on macOS or Windows); under wasm32 they call Rust's port of
//! musl's libm. Both are accurate to within an ulp, but not to the same bits: measured on 2 M random
//! arguments, sin differs in the last bit on 3.0 % of them, exp on 9.7 %, ln on 6.7 %, pow on
//! 10.2 %. Most of the time that moves a vertex's last digit. With an environment (issue 47) it
//! moves a plant: a threshold on a bud's exposure flips, and the studio (wasm) and the CLI
//! (native) grow different trees from one grammar and one seed.
//!
//! So the core calls these, which call the `libm` crate on every target: one implementation, the
//! same bits everywhere. `crate/clippy.toml` forbids the `f64` methods in the core (clippy's
//! `disallowed_methods`), and `tests/wasm_boundary.rs` checks a stand under wasm32 against the
//! numbers the native build writes.
//!
//! Not here, because they are already the same everywhere: `sqrt`, `abs`, `floor`, `ceil`,
//! `round`, `mul_add` (correctly rounded by IEEE 754 on every target) and `powi` (rustc lowers it
//! to compiler-builtins' `__powidf2`, the same code on every target, or to the same multiplications).

/// The sine of `x` radians.
pub fn sin(x: f64) -> f64 {
    libm::sin(x)
}

/// The cosine of `x` radians.
pub fn cos(x: f64) -> f64 {
    libm::cos(x)
}

/// `(sin(x), cos(x))`, each the same bits as [`sin`] and [`cos`].
pub fn sin_cos(x: f64) -> (f64, f64) {
    (libm::sin(x), libm::cos(x))
}

/// The tangent of `x` radians.
pub fn tan(x: f64) -> f64 {
    libm::tan(x)
}

/// The arcsine of `x`, in radians (NaN outside [-1, 1]).
pub fn asin(x: f64) -> f64 {
    libm::asin(x)
}

/// The arccosine of `x`, in radians (NaN outside [-1, 1]).
pub fn acos(x: f64) -> f64 {
    libm::acos(x)
}

/// The arctangent of `x`, in radians.
pub fn atan(x: f64) -> f64 {
    libm::atan(x)
}

/// The angle of the point (`x`, `y`) from the x axis, in radians in [-π, π] (`y.atan2(x)`).
pub fn atan2(y: f64, x: f64) -> f64 {
    libm::atan2(y, x)
}

/// e to the power `x`.
pub fn exp(x: f64) -> f64 {
    libm::exp(x)
}

/// The natural logarithm of `x`.
pub fn ln(x: f64) -> f64 {
    libm::log(x)
}

/// The base-10 logarithm of `x`.
pub fn log10(x: f64) -> f64 {
    libm::log10(x)
}

/// `x` to the power `y` (`x.powf(y)`).
pub fn powf(x: f64, y: f64) -> f64 {
    libm::pow(x, y)
}

/// The cube root of `x`.
pub fn cbrt(x: f64) -> f64 {
    libm::cbrt(x)
}

/// `√(x² + y²)` without overflow or underflow on the way.
pub fn hypot(x: f64, y: f64) -> f64 {
    libm::hypot(x, y)
}

#[cfg(test)]
#[allow(clippy::disallowed_methods)] // the platform's functions, to compare with
mod tests {
    use super::*;

    #[test]
    fn each_function_is_the_one_it_stands_for() {
        // Within an ulp or two of the platform's own: the same function, perhaps other bits.
        let close = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * b.abs().max(1.0);
        for &x in &[0.3, 1.0, 2.5, -0.7, 10.0] {
            assert!(close(sin(x), x.sin()));
            assert!(close(cos(x), x.cos()));
            assert!(close(tan(x), x.tan()));
            assert!(close(atan(x), x.atan()));
            assert!(close(exp(x), x.exp()));
            assert!(close(cbrt(x), x.cbrt()));
            assert!(close(atan2(x, 0.4), x.atan2(0.4)));
            assert!(close(hypot(x, 0.4), x.hypot(0.4)));
            assert_eq!(sin_cos(x), (sin(x), cos(x)));
        }
        for &x in &[0.3, 1.0, 2.5, 10.0] {
            assert!(close(ln(x), x.ln()));
            assert!(close(log10(x), x.log10()));
            assert!(close(powf(x, 1.7), x.powf(1.7)));
        }
        for &x in &[-0.9, 0.0, 0.5] {
            assert!(close(asin(x), x.asin()));
            assert!(close(acos(x), x.acos()));
        }
    }
}
