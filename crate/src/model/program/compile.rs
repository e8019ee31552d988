//! The compiler: an expression's syntax → a [`Program`]'s ops, names resolved in a [`Scope`],
//! constant operands folded, the size and depth limits checked (`E0121`, `E0127`, `E0128`).

use super::eval::{evaluate_binary, truth};
use super::{Op, Program, Scope, MAX_OPS, MAX_STACK};
use crate::diagnostics::Diagnostic;
use crate::model::curve::Curve;
use crate::syntax::{BinaryOp, ExprSyntax, Span, UnaryOp};
use crate::vocabulary::{function_named, value_named, Value};
use std::sync::Arc;

/// Deepest the compiler recurses into one expression, `#define` names expanded (`E0121`). The
/// parser bounds nesting to [`crate::syntax::MAX_EXPRESSION_DEPTH`] levels, each of which makes at
/// most eight nodes, one inside the other.
const MAX_COMPILE_DEPTH: usize = 8 * crate::syntax::MAX_EXPRESSION_DEPTH;

impl Program {
    /// Compiles `expr` in `scope`.
    pub fn compile(expr: &ExprSyntax, scope: &dyn Scope) -> Result<Program, Diagnostic> {
        let mut c = Compiler {
            ops: Vec::new(),
            spans: Vec::new(),
            scope,
            expanding: Vec::new(),
            random: false,
            root: expr.span(),
            curves: Vec::new(),
        };
        c.expr(expr, 0)?;
        c.check_size()?;
        let mut program = Program {
            ops: c.ops,
            spans: c.spans,
            span: expr.span(),
            random: c.random,
            stack_depth: 0,
            curves: c.curves,
        };
        program.stack_depth = program.max_stack();
        if program.stack_depth > MAX_STACK {
            return Err(Diagnostic::error(
                "E0127",
                expr.span(),
                format!("expression too complex: it needs more than {MAX_STACK} stack slots"),
            ));
        }
        Ok(program)
    }

    fn max_stack(&self) -> usize {
        let mut depth: isize = 0;
        let mut max = 0;
        for op in &self.ops {
            depth += match op {
                Op::Const(_) | Op::Slot(_) | Op::NumIt | Op::MaxIt | Op::Var(_) => 1,
                Op::Neg | Op::Not | Op::Truth | Op::Jump(_) | Op::Curve(_) => 0,
                Op::Bin(_) | Op::JumpIfFalse(_) => -1,
                Op::Call(f) => 1 - f.info().arity() as isize,
            };
            max = max.max(depth);
        }
        max.max(0) as usize
    }
}

struct Compiler<'a> {
    ops: Vec<Op>,
    spans: Vec<Span>,
    scope: &'a dyn Scope,
    /// `#define` names being expanded, to catch cycles.
    expanding: Vec<String>,
    random: bool,
    /// The whole expression's span, where `E0128` points.
    root: Span,
    curves: Vec<Arc<Curve>>,
}

impl Compiler<'_> {
    fn emit(&mut self, op: Op, span: Span) -> usize {
        self.ops.push(op);
        self.spans.push(span);
        self.ops.len() - 1
    }

    fn patch(&mut self, at: usize) {
        let target = self.ops.len() as u32;
        match &mut self.ops[at] {
            Op::JumpIfFalse(t) | Op::Jump(t) => *t = target,
            _ => {}
        }
    }

    /// The `#define` names being expanded, `a -> b -> c` (the middle of a long chain left out).
    fn expansion(&self) -> String {
        let names = &self.expanding;
        if names.len() <= 4 {
            return names.join(" -> ");
        }
        format!(
            "{} -> {} -> … -> {}",
            names[0],
            names[1],
            names[names.len() - 1]
        )
    }

    /// `E0128` once the expression has more than [`MAX_OPS`] operations.
    fn check_size(&self) -> Result<(), Diagnostic> {
        if self.ops.len() <= MAX_OPS {
            return Ok(());
        }
        let through = if self.expanding.is_empty() {
            String::new()
        } else {
            format!(" once #define {} is expanded", self.expansion())
        };
        Err(Diagnostic::error(
            "E0128",
            self.root.clone(),
            format!(
                "expression too large: it needs more than {MAX_OPS} operations{through}; \
                 split it into smaller expressions or use fewer terms"
            ),
        ))
    }

    fn expr(&mut self, e: &ExprSyntax, depth: usize) -> Result<(), Diagnostic> {
        if depth > MAX_COMPILE_DEPTH {
            let message = if self.expanding.is_empty() {
                format!("expression nested more than {MAX_COMPILE_DEPTH} levels deep")
            } else {
                format!(
                    "expression nested more than {MAX_COMPILE_DEPTH} levels deep once #define {} is expanded",
                    self.expansion()
                )
            };
            return Err(Diagnostic::error("E0121", e.span(), message));
        }
        self.check_size()?;
        // The depth of the operands.
        let inner = depth + 1;
        match e {
            ExprSyntax::Number(v, span) => {
                self.emit(Op::Const(*v), span.clone());
            }
            ExprSyntax::Name(name, span) => self.name(name, span, depth)?,
            ExprSyntax::Unary(op, x, span) => self.unary(*op, x, span, inner)?,
            ExprSyntax::Binary(op, a, b, span) => {
                let start = self.ops.len();
                self.expr(a, inner)?;
                self.link(start, *op, b, span, inner)?;
            }
            ExprSyntax::Chain(first, links) => {
                let start = self.ops.len();
                self.expr(first, inner)?;
                for (op, b, span) in links {
                    self.check_size()?;
                    self.link(start, *op, b, span, inner)?;
                }
            }
            ExprSyntax::Conditional(c, a, b, span) => {
                self.conditional(c, span, inner, |s| s.expr(a, inner), |s| s.expr(b, inner))?
            }
            ExprSyntax::Call(name, name_span, args, span) => {
                self.call(name, name_span, args, span, inner)?
            }
        }
        Ok(())
    }

    /// `left op b`, where the ops of `left` (already compiled) start at `start`.
    fn link(
        &mut self,
        start: usize,
        op: BinaryOp,
        b: &ExprSyntax,
        span: &Span,
        depth: usize,
    ) -> Result<(), Diagnostic> {
        match op {
            // a && b  =>  a ? truth(b) : 0
            BinaryOp::And => {
                self.branch(span, |c| c.truth(b, span, depth), |c| c.constant(0.0, span))
            }
            // a || b  =>  a ? 1 : truth(b)
            BinaryOp::Or => {
                self.branch(span, |c| c.constant(1.0, span), |c| c.truth(b, span, depth))
            }
            _ => {
                self.expr(b, depth)?;
                self.binary(start, op, span);
                Ok(())
            }
        }
    }

    /// `-x` or `!x`, folded when `x` is a constant. `depth` is that of `x`.
    fn unary(
        &mut self,
        op: UnaryOp,
        x: &ExprSyntax,
        span: &Span,
        depth: usize,
    ) -> Result<(), Diagnostic> {
        let start = self.ops.len();
        self.expr(x, depth)?;
        if let [Op::Const(v)] = self.ops[start..] {
            let folded = match op {
                UnaryOp::Neg => -v,
                UnaryOp::Not => truth(v == 0.0),
            };
            *self.ops.last_mut().expect("just pushed") = Op::Const(folded);
            return Ok(());
        }
        let op = match op {
            UnaryOp::Neg => Op::Neg,
            UnaryOp::Not => Op::Not,
        };
        self.emit(op, span.clone());
        Ok(())
    }

    /// `condition ? then : otherwise`, the branches compiled by `then` and `otherwise`. `depth`
    /// is that of the condition.
    fn conditional(
        &mut self,
        condition: &ExprSyntax,
        span: &Span,
        depth: usize,
        then: impl FnOnce(&mut Self) -> Result<(), Diagnostic>,
        otherwise: impl FnOnce(&mut Self) -> Result<(), Diagnostic>,
    ) -> Result<(), Diagnostic> {
        self.expr(condition, depth)?;
        self.branch(span, then, otherwise)
    }

    /// With the condition's value on the stack: a jump past `then` when it is false, and one
    /// past `otherwise` after `then`.
    fn branch(
        &mut self,
        span: &Span,
        then: impl FnOnce(&mut Self) -> Result<(), Diagnostic>,
        otherwise: impl FnOnce(&mut Self) -> Result<(), Diagnostic>,
    ) -> Result<(), Diagnostic> {
        let jump_false = self.emit(Op::JumpIfFalse(0), span.clone());
        then(self)?;
        let jump_end = self.emit(Op::Jump(0), span.clone());
        self.patch(jump_false);
        otherwise(self)?;
        self.patch(jump_end);
        Ok(())
    }

    /// `truth(x)`: 1 when `x` is not zero, else 0.
    fn truth(&mut self, x: &ExprSyntax, span: &Span, depth: usize) -> Result<(), Diagnostic> {
        self.expr(x, depth)?;
        self.emit(Op::Truth, span.clone());
        Ok(())
    }

    /// A constant `v`.
    fn constant(&mut self, v: f64, span: &Span) -> Result<(), Diagnostic> {
        self.emit(Op::Const(v), span.clone());
        Ok(())
    }

    /// `left op right` for an operator other than `&&` and `||`, both operands compiled, the ops
    /// of `left` starting at `start`; folded when both are constants (not a division by zero, nor
    /// a result that is not finite: those stay runtime errors).
    fn binary(&mut self, start: usize, op: BinaryOp, span: &Span) {
        if let [Op::Const(x), Op::Const(y)] = self.ops[start..] {
            if let Some(v) = evaluate_binary(op, x, y).filter(|v| v.is_finite()) {
                self.ops.truncate(start);
                self.spans.truncate(start);
                self.emit(Op::Const(v), span.clone());
                return;
            }
        }
        self.emit(Op::Bin(op), span.clone());
    }

    /// A call of the function `name` with `args`, each compiled at `depth`.
    fn call(
        &mut self,
        name: &str,
        name_span: &Span,
        args: &[ExprSyntax],
        span: &Span,
        depth: usize,
    ) -> Result<(), Diagnostic> {
        let Some(info) = function_named(name) else {
            if let Some(curve) = self.scope.curve(name) {
                return self.curve_call(name, curve, args, span, depth);
            }
            return Err(self.not_a_function(name, name_span));
        };
        let (arity, f) = (info.arity(), info.function);
        if args.len() != arity {
            return Err(Diagnostic::error(
                "E0502",
                span.clone(),
                format!(
                    "{name} takes {arity} argument{}, not {}",
                    if arity == 1 { "" } else { "s" },
                    args.len()
                ),
            ));
        }
        for a in args {
            self.expr(a, depth)?;
        }
        if info.random {
            self.random = true;
        }
        self.emit(Op::Call(f), span.clone());
        Ok(())
    }

    /// A call of a `#curve` or `#table` function: one argument, folded when it is a constant.
    fn curve_call(
        &mut self,
        name: &str,
        curve: Arc<Curve>,
        args: &[ExprSyntax],
        span: &Span,
        depth: usize,
    ) -> Result<(), Diagnostic> {
        let [arg] = args else {
            return Err(Diagnostic::error(
                "E0502",
                span.clone(),
                format!("{name} takes 1 argument, not {}", args.len()),
            ));
        };
        let start = self.ops.len();
        self.expr(arg, depth)?;
        if let [Op::Const(x)] = self.ops[start..] {
            self.ops[start] = Op::Const(curve.value(x));
            return Ok(());
        }
        let index = match self.curves.iter().position(|c| Arc::ptr_eq(c, &curve)) {
            Some(i) => i,
            None => {
                self.curves.push(curve);
                self.curves.len() - 1
            }
        };
        self.emit(Op::Curve(index as u16), span.clone());
        Ok(())
    }

    /// Why a call of `name`, which names no function, is an error: it names a value, or nothing.
    fn not_a_function(&self, name: &str, name_span: &Span) -> Diagnostic {
        let is_value = value_named(name).is_some()
            || self.scope.slot(name).is_some()
            || self.scope.define(name).is_some()
            || self.scope.random_var(name).is_some();
        if is_value {
            return Diagnostic::error(
                "E0506",
                name_span.clone(),
                format!("'{name}' is a value, not a function: write it without parentheses"),
            );
        }
        Diagnostic::error(
            "E0501",
            name_span.clone(),
            format!("unknown function '{name}'"),
        )
    }

    fn name(&mut self, name: &str, span: &Span, depth: usize) -> Result<(), Diagnostic> {
        if let Some(slot) = self.scope.slot(name) {
            self.emit(Op::Slot(slot), span.clone());
        } else if let Some(value) = value_named(name).filter(|v| {
            !v.definable
                || (self.scope.random_var(name).is_none() && self.scope.define(name).is_none())
        }) {
            let op = match value.value {
                Value::NumIt => Op::NumIt,
                Value::MaxIt => Op::MaxIt,
                Value::Dt => Op::Const(self.scope.dt()),
            };
            self.emit(op, span.clone());
        } else if let Some(k) = self.scope.random_var(name) {
            self.random = true;
            self.emit(Op::Var(k), span.clone());
        } else if let Some(value) = self.scope.define_value(name) {
            self.emit(Op::Const(value), span.clone());
        } else if let Some(definition) = self.scope.define(name) {
            if self.expanding.iter().any(|n| n == name) {
                return Err(Diagnostic::error(
                    "E0503",
                    span.clone(),
                    format!(
                        "#define {name} is defined in terms of itself: {} -> {name}",
                        self.expanding
                            [self.expanding.iter().position(|n| n == name).unwrap_or(0)..]
                            .join(" -> ")
                    ),
                ));
            }
            self.expanding.push(name.to_string());
            self.expr(definition, depth + 1)?;
            self.expanding.pop();
        } else if function_named(name).is_some() || self.scope.curve(name).is_some() {
            return Err(Diagnostic::error(
                "E0504",
                span.clone(),
                format!("'{name}' is a function: call it as {name}(…)"),
            ));
        } else {
            return Err(Diagnostic::error(
                "E0505",
                span.clone(),
                format!("unknown name '{name}'"),
            ));
        }
        Ok(())
    }
}
