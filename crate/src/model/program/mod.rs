//! Compiled expressions: a small stack bytecode, evaluated in f64 without allocation. Names are
//! resolved when compiling (formal parameters become slots, `#define` constants are inlined), so
//! evaluation never looks at text.
//!
//! This file holds the bytecode (`Op`), the [`Program`] and what an evaluation reads ([`Env`],
//! [`Scope`] for compiling). `compile.rs`: the compiler (syntax → ops, constants folded, limits
//! checked). `eval.rs`: the interpreter loop and [`Simple`], the shapes evaluated without it.
//! `functions.rs`: the built-in functions, random ones included. `random.rs`: `#random` variables
//! and their deviates.

mod compile;
mod eval;
mod functions;
mod random;

pub use eval::Simple;
pub use random::RandomVariable;

use super::curve::Curve;
use crate::diagnostics::Diagnostic;
use crate::syntax::{BinaryOp, ExprSyntax, Span};
use crate::vocabulary::Function;
use std::sync::Arc;

/// Deepest evaluation stack a compiled expression may need.
pub const MAX_STACK: usize = 64;

/// Most operations one compiled expression may have, `#define` names expanded (`E0128`): an
/// expression is evaluated for every module it rewrites, so its size multiplies every step's cost.
pub const MAX_OPS: usize = 10_000;

#[derive(Clone, Copy, Debug, PartialEq)]
enum Op {
    Const(f64),
    Slot(u16),
    NumIt,
    MaxIt,
    /// A random variable (`#random`): in a condition, the module's deviate; elsewhere, fresh.
    Var(u16),
    Neg,
    Not,
    /// Turns the top of the stack into 1 or 0.
    Truth,
    Bin(BinaryOp),
    Call(Function),
    /// A `#curve` or `#table` function of the top of the stack: an index into `Program::curves`.
    Curve(u16),
    /// Jump to the op index when the popped value is false (zero).
    JumpIfFalse(u32),
    Jump(u32),
}

/// A compiled expression.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    ops: Vec<Op>,
    /// For each op, the span of the source it came from (for runtime diagnostics).
    spans: Vec<Span>,
    /// The whole expression's span.
    pub span: Span,
    /// True when the expression draws random numbers (its value differs between evaluations).
    pub random: bool,
    /// The deepest the evaluation stack gets.
    stack_depth: usize,
    /// The `#curve` and `#table` functions the expression calls.
    curves: Vec<Arc<Curve>>,
}

/// What names mean while compiling one expression.
pub trait Scope {
    /// The slot of a formal parameter.
    fn slot(&self, name: &str) -> Option<u16>;
    /// The expression of a `#define` constant.
    fn define(&self, name: &str) -> Option<&ExprSyntax>;
    /// The value of a `#define` whose expression is a constant, computed once when the grammar
    /// is read (`None` for one that must be expanded where it is used).
    fn define_value(&self, _name: &str) -> Option<f64> {
        None
    }
    /// The index of a `#random` variable.
    fn random_var(&self, name: &str) -> Option<u16>;
    /// A `#curve` or `#table` function.
    fn curve(&self, _name: &str) -> Option<Arc<Curve>> {
        None
    }
    /// The value of `dt`: `#dt`, 1 by default.
    fn dt(&self) -> f64 {
        1.0
    }
}

/// Why an evaluation failed; turned into a diagnostic at the op's span.
#[derive(Clone, Debug, PartialEq)]
pub struct EvalError {
    pub message: String,
    pub span: Span,
}

impl EvalError {
    pub fn into_diagnostic(self, context: &str) -> Diagnostic {
        Diagnostic::error("E0500", self.span, format!("{}{context}", self.message))
    }
}

/// The values an evaluation reads, besides its own constants.
pub struct Env<'a, R: rand::Rng + ?Sized> {
    pub slots: &'a [f64],
    pub num_it: f64,
    pub max_it: f64,
    /// Per-module deviates of `#random` variables, drawn on first use (`None` until then); when
    /// `fresh_vars` is true every use draws anew instead.
    pub vars: &'a mut [Option<f64>],
    pub fresh_vars: bool,
    /// The `#random` variables: their distributions and what each depends on.
    pub variables: &'a [RandomVariable],
    pub rng: &'a mut R,
}

impl Program {
    /// A program that gives `value`, written at `span`.
    pub fn constant_at(value: f64, span: Span) -> Program {
        Program {
            ops: vec![Op::Const(value)],
            spans: vec![span.clone()],
            span,
            random: false,
            stack_depth: 1,
            curves: Vec::new(),
        }
    }

    /// The `#random` variables the expression reads, each with where it is written.
    pub fn variables(&self) -> impl Iterator<Item = (u16, &Span)> + '_ {
        self.ops
            .iter()
            .zip(&self.spans)
            .filter_map(|(op, span)| match op {
                Op::Var(k) => Some((*k, span)),
                _ => None,
            })
    }

    /// True when the expression reads `MaxIt` (the number of steps of the derivation).
    pub fn reads_max_it(&self) -> bool {
        self.ops.contains(&Op::MaxIt)
    }

    /// The constant value, when the expression has no names and draws nothing.
    pub fn constant(&self) -> Option<f64> {
        match self.ops.as_slice() {
            [Op::Const(v)] => Some(*v),
            _ => None,
        }
    }

    /// True when the expression reads `NumIt` or `MaxIt` (its value depends on the step).
    pub fn reads_step(&self) -> bool {
        self.ops
            .iter()
            .any(|op| matches!(op, Op::NumIt | Op::MaxIt))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::parse_expression;

    struct TestScope;
    impl Scope for TestScope {
        fn slot(&self, name: &str) -> Option<u16> {
            ["x", "y", "z"]
                .iter()
                .position(|n| *n == name)
                .map(|i| i as u16)
        }
        fn define(&self, _: &str) -> Option<&ExprSyntax> {
            None
        }
        fn random_var(&self, _: &str) -> Option<u16> {
            None
        }
    }

    fn eval(text: &str, slots: &[f64]) -> Result<f64, String> {
        let e = parse_expression(text, 0).map_err(|d| d.message)?;
        let p = Program::compile(&e, &TestScope).map_err(|d| d.message)?;
        let mut rng = rand_pcg::Pcg64Mcg::new(7);
        let mut env = Env {
            slots,
            num_it: 3.0,
            max_it: 5.0,
            vars: &mut [],
            fresh_vars: true,
            variables: &[],
            rng: &mut rng,
        };
        p.eval(&mut env).map_err(|e| e.message)
    }

    #[test]
    fn arithmetic_logic_and_functions() {
        assert_eq!(eval("1 + 2 * 3", &[]), Ok(7.0));
        assert_eq!(eval("x/y", &[1.0, 4.0]), Ok(0.25));
        assert_eq!(eval("x + y + z > 10 && x = 4", &[4.0, 5.0, 6.0]), Ok(1.0));
        assert_eq!(eval("x < 1 || y", &[2.0, 0.0]), Ok(0.0));
        assert_eq!(eval("x < 1 ? 10 : 20", &[2.0]), Ok(20.0));
        assert_eq!(eval("7 % 4 + 2^3", &[]), Ok(11.0));
        assert!((eval("sin(30)", &[]).unwrap() - 0.5).abs() < 1e-12);
        assert!((eval("atan2(1, 1)", &[]).unwrap() - 45.0).abs() < 1e-12);
        assert_eq!(
            eval("clamp(5, 0, 2) + sign(-3) + NumIt * MaxIt", &[]),
            Ok(16.0)
        );
        assert_eq!(eval("!0 + !5", &[]), Ok(1.0));
    }

    #[test]
    fn runtime_errors_are_reported_not_nan() {
        assert_eq!(
            eval("x / (y - 1)", &[1.0, 1.0]),
            Err("division by zero".into())
        );
        assert!(eval("sqrt(x)", &[-1.0])
            .unwrap_err()
            .contains("not a finite number"));
        assert_eq!(eval("1 / 0", &[]), Err("division by zero".into()));
        assert!(eval("uniform(2, 1)", &[])
            .unwrap_err()
            .contains("lower bound"));
    }

    #[test]
    fn compile_errors_name_the_problem() {
        assert_eq!(eval("q + 1", &[]), Err("unknown name 'q'".into()));
        assert_eq!(
            eval("sin(1, 2)", &[]),
            Err("sin takes 1 argument, not 2".into())
        );
        assert_eq!(eval("frob(1)", &[]), Err("unknown function 'frob'".into()));
        assert_eq!(
            eval("sin + 1", &[]),
            Err("'sin' is a function: call it as sin(…)".into())
        );
    }

    #[test]
    fn random_functions_stay_in_range() {
        for _ in 0..100 {
            let v = eval("uniform(2, 3)", &[]).unwrap();
            assert!((2.0..3.0).contains(&v));
            let k = eval("uniform_int(1, 3)", &[]).unwrap();
            assert!([1.0, 2.0, 3.0].contains(&k));
        }
    }
}
