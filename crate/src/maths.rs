//! The core's transcendental functions: the same bits natively and in WebAssembly.
//!
//! `f64::sin`, `exp`, `ln`, `powf` and the like are not one function. Natively they call the C
//! library (glibc on Linux, another on macOS or Windows); under wasm32 they call Rust's port of
//! musl's libm (compiler-builtins). Both are accurate to within an ulp, but not to the same bits:
//! measured on 2 M random arguments, sin differs in the last bit on 3.0 % of them, exp on 9.7 %, ln
//! on 6.7 %, pow on 10.2 %. Most of the time that moves a vertex's last digit. With an environment
//! (issue 47) it moves a plant: a threshold on a bud's exposure flips, and the studio (wasm) and the
//! CLI (native) grew different trees from one grammar and one seed.
//!
//! So the core calls these. Natively they call the `libm` crate, the same port of musl's libm that
//! WebAssembly's `f64` methods run; under wasm32 they call those methods, so the first plant's
//! core carries no second copy (a `libm` of its own cost 370 B of the first load). That both are
//! the same bits is checked, not assumed: `tests/wasm_boundary.rs` folds every function here at
//! 20,000 arguments into one number, natively and under wasm32, against one constant, so a
//! toolchain whose builtins drift from the `libm` pinned in Cargo.toml fails there. Clippy
//! (`crate/clippy.toml`) forbids the `f64` methods, and glam's rotations that use them, elsewhere
//! in the core.
//!
//! glam's own rotations and angles call the platform's functions too (its `libm` feature would
//! also make its `sqrt` a software one in WebAssembly), so the few the core needs are here:
//! [`rotation`], [`angle_between`], [`signed_angle`], [`axis_angle`].
//!
//! Not here, because they are already the same everywhere: `sqrt`, `abs`, `floor`, `ceil`,
//! `round`, `mul_add` (correctly rounded by IEEE 754 on every target) and `powi` (rustc lowers it
//! to compiler-builtins' `__powidf2`, the same code on every target, or to the same multiplications).

#[cfg(not(target_arch = "wasm32"))]
use libm as imp;

/// `x` limited to `lo` … `hi`, as `f64::clamp` for `lo ≤ hi` (NaN stays NaN), but with no
/// assertion on the bounds: `f64::clamp` panics when they cross or one is NaN, and its message
/// formats them, which brings Rust's float formatting into the first plant's core (issue 22).
#[inline]
pub fn clamp(x: f64, lo: f64, hi: f64) -> f64 {
    if x < lo {
        lo
    } else if x > hi {
        hi
    } else {
        x
    }
}

/// Under wasm32 the `f64` methods are already musl's libm (compiler-builtins), named as `libm` names them.
#[cfg(target_arch = "wasm32")]
#[allow(clippy::disallowed_methods)]
mod imp {
    pub fn sin(x: f64) -> f64 {
        x.sin()
    }
    pub fn cos(x: f64) -> f64 {
        x.cos()
    }
    pub fn tan(x: f64) -> f64 {
        x.tan()
    }
    pub fn asin(x: f64) -> f64 {
        x.asin()
    }
    pub fn acos(x: f64) -> f64 {
        x.acos()
    }
    pub fn atan(x: f64) -> f64 {
        x.atan()
    }
    pub fn atan2(y: f64, x: f64) -> f64 {
        y.atan2(x)
    }
    pub fn exp(x: f64) -> f64 {
        x.exp()
    }
    pub fn log(x: f64) -> f64 {
        x.ln()
    }
    pub fn log10(x: f64) -> f64 {
        x.log10()
    }
    pub fn pow(x: f64, y: f64) -> f64 {
        x.powf(y)
    }
    pub fn cbrt(x: f64) -> f64 {
        x.cbrt()
    }
    pub fn hypot(x: f64, y: f64) -> f64 {
        x.hypot(y)
    }
}

use glam::{DQuat, DVec2, DVec3};

/// The sine of `x` radians.
pub fn sin(x: f64) -> f64 {
    imp::sin(x)
}

/// The cosine of `x` radians.
pub fn cos(x: f64) -> f64 {
    imp::cos(x)
}

/// `(sin(x), cos(x))`, each the same bits as [`sin`] and [`cos`].
pub fn sin_cos(x: f64) -> (f64, f64) {
    (imp::sin(x), imp::cos(x))
}

/// The tangent of `x` radians.
pub fn tan(x: f64) -> f64 {
    imp::tan(x)
}

/// The arcsine of `x`, in radians (NaN outside [-1, 1]).
pub fn asin(x: f64) -> f64 {
    imp::asin(x)
}

/// The arccosine of `x`, in radians (NaN outside [-1, 1]).
pub fn acos(x: f64) -> f64 {
    imp::acos(x)
}

/// The arctangent of `x`, in radians.
pub fn atan(x: f64) -> f64 {
    imp::atan(x)
}

/// The angle of the point (`x`, `y`) from the x axis, in radians in [-π, π] (`y.atan2(x)`).
pub fn atan2(y: f64, x: f64) -> f64 {
    imp::atan2(y, x)
}

/// e to the power `x`.
pub fn exp(x: f64) -> f64 {
    imp::exp(x)
}

/// The natural logarithm of `x`.
pub fn ln(x: f64) -> f64 {
    imp::log(x)
}

/// The base-10 logarithm of `x`.
pub fn log10(x: f64) -> f64 {
    imp::log10(x)
}

/// `x` to the power `y` (`x.powf(y)`).
pub fn powf(x: f64, y: f64) -> f64 {
    imp::pow(x, y)
}

/// The cube root of `x`.
pub fn cbrt(x: f64) -> f64 {
    imp::cbrt(x)
}

/// `√(x² + y²)` without overflow or underflow on the way.
pub fn hypot(x: f64, y: f64) -> f64 {
    imp::hypot(x, y)
}

/// The rotation by `angle` radians about the unit vector `axis` (glam's `DQuat::from_axis_angle`).
pub fn rotation(axis: DVec3, angle: f64) -> DQuat {
    let (s, c) = sin_cos(angle * 0.5);
    let v = axis * s;
    DQuat::from_xyzw(v.x, v.y, v.z, c)
}

/// The angle between two non-zero vectors, in radians in [0, π] (glam's `DVec3::angle_between`).
pub fn angle_between(a: DVec3, b: DVec3) -> f64 {
    let cos = a.dot(b) / (a.length_squared() * b.length_squared()).sqrt();
    acos(cos.clamp(-1.0, 1.0))
}

/// The angle that turns `a` towards `b` in the plane, in radians in [-π, π], positive
/// anticlockwise (glam's `DVec2::angle_to`).
pub fn signed_angle(a: DVec2, b: DVec2) -> f64 {
    let cos = a.dot(b) / (a.length_squared() * b.length_squared()).sqrt();
    acos(cos.clamp(-1.0, 1.0)) * a.perp_dot(b).signum()
}

/// The axis and angle (radians) of a unit quaternion; (X, 0) for no rotation (glam's
/// `DQuat::to_axis_angle`).
pub fn axis_angle(q: DQuat) -> (DVec3, f64) {
    let v = DVec3::new(q.x, q.y, q.z);
    let length = v.length();
    if length >= 1e-8 {
        (v / length, 2.0 * atan2(length, q.w))
    } else {
        (DVec3::X, 0.0)
    }
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
        let (a, b) = (DVec3::new(1.0, 2.0, 0.5), DVec3::new(-0.3, 1.0, 2.0));
        assert!(close(angle_between(a, b), a.angle_between(b)));
        let (p, q) = (DVec2::new(1.0, 0.2), DVec2::new(-0.4, 1.0));
        assert!(close(signed_angle(p, q), p.angle_to(q)));
        assert!(close(signed_angle(q, p), q.angle_to(p)));
        let axis = DVec3::new(0.0, 0.6, 0.8);
        let r = rotation(axis, 1.2);
        let g = DQuat::from_axis_angle(axis, 1.2);
        assert!(
            (r.x - g.x).abs() + (r.y - g.y).abs() + (r.z - g.z).abs() + (r.w - g.w).abs() < 1e-15
        );
        let ((u, t), (v, w)) = (axis_angle(r), g.to_axis_angle());
        assert!(close(t, w) && (u - v).length() < 1e-12);
        assert_eq!(axis_angle(DQuat::IDENTITY), (DVec3::X, 0.0));
        for &x in &[-0.9, 0.0, 0.5] {
            assert!(close(asin(x), x.asin()));
            assert!(close(acos(x), x.acos()));
        }
    }
}
