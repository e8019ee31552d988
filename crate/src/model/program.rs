//! Compiled expressions: a small stack bytecode, evaluated in f64 without allocation. Names are
//! resolved when compiling (formal parameters become slots, `#define` constants are inlined), so
//! evaluation never looks at text.

use super::curve::Curve;
use crate::diagnostics::Diagnostic;
use crate::syntax::{BinaryOp, ExprSyntax, Span, UnaryOp};
use crate::vocabulary::{function_named, value_named, Function, Value};
use rand::RngExt;
use rand_distr::{Binomial, Distribution, Exp, Normal, Poisson};
use std::sync::Arc;

/// Deepest evaluation stack a compiled expression may need.
pub const MAX_STACK: usize = 64;

/// Most operations one compiled expression may have, `#define` names expanded (`E0128`): an
/// expression is evaluated for every module it rewrites, so its size multiplies every step's cost.
pub const MAX_OPS: usize = 10_000;

/// Deepest the compiler recurses into one expression, `#define` names expanded (`E0121`). The
/// parser bounds nesting to [`crate::syntax::MAX_EXPRESSION_DEPTH`] levels, each of which makes at
/// most eight nodes, one inside the other.
const MAX_COMPILE_DEPTH: usize = 8 * crate::syntax::MAX_EXPRESSION_DEPTH;

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

/// A `#random` variable: a name, the distribution each deviate is drawn from, and the variables
/// that distribution reads (directly or through others), in the order they must be drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct RandomVariable {
    pub name: String,
    pub distribution: Program,
    /// Every variable the distribution depends on, directly or not, each before those that read
    /// it; empty for a variable that reads no other (the usual case).
    pub depends_on: Vec<u16>,
}

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

    /// The constant value, when the expression has no names and draws nothing.
    pub fn constant(&self) -> Option<f64> {
        match self.ops.as_slice() {
            [Op::Const(v)] => Some(*v),
            _ => None,
        }
    }

    /// The expression as one of the shapes a template evaluates without the interpreter (a
    /// constant, a parameter, or one arithmetic operator on two of them), when it is one.
    pub fn simple(&self) -> Option<Simple> {
        let arithmetic = |op: &BinaryOp| {
            matches!(
                op,
                BinaryOp::Add | BinaryOp::Sub | BinaryOp::Mul | BinaryOp::Div
            )
        };
        Some(match self.ops.as_slice() {
            [Op::Const(v)] => Simple::Const(*v),
            [Op::Slot(s)] => Simple::Slot(*s),
            [Op::Slot(s), Op::Const(c), Op::Bin(op)] if arithmetic(op) => {
                Simple::SlotConst(*op, *s, *c)
            }
            [Op::Const(c), Op::Slot(s), Op::Bin(op)] if arithmetic(op) => {
                Simple::ConstSlot(*op, *c, *s)
            }
            [Op::Slot(a), Op::Slot(b), Op::Bin(op)] if arithmetic(op) => {
                Simple::SlotSlot(*op, *a, *b)
            }
            _ => return None,
        })
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

    /// Evaluates the expression. Division by zero, invalid arguments of random functions and
    /// results that are not finite numbers are errors, never silent NaNs.
    #[inline]
    pub fn eval<R: rand::Rng + ?Sized>(&self, env: &mut Env<'_, R>) -> Result<f64, EvalError> {
        // The commonest shapes (a constant, a parameter, a parameter and a constant) without the
        // interpreter loop; a value that is not finite takes the loop, which reports it.
        let slot = |s: &u16| env.slots.get(*s as usize).copied().unwrap_or(0.0);
        let quick = match self.ops.as_slice() {
            [Op::Const(v)] => return Ok(*v),
            [Op::Slot(s)] => Some(slot(s)),
            [Op::Slot(s), Op::Const(c), Op::Bin(op)] => quick_binary(*op, slot(s), *c),
            [Op::Const(c), Op::Slot(s), Op::Bin(op)] => quick_binary(*op, *c, slot(s)),
            _ => None,
        };
        if let Some(v) = quick.filter(|v| v.is_finite()) {
            return Ok(v);
        }
        // Most expressions need a few slots: a small stack is cheaper to set up.
        if self.stack_depth <= 8 {
            self.run::<8, R>(env)
        } else {
            self.run::<MAX_STACK, R>(env)
        }
    }

    /// The interpreter loop over the ops, with a stack of `N` values.
    fn run<const N: usize, R: rand::Rng + ?Sized>(
        &self,
        env: &mut Env<'_, R>,
    ) -> Result<f64, EvalError> {
        let mut stack = [0.0f64; N];
        let mut sp = 0usize;
        let mut pc = 0usize;
        while pc < self.ops.len() {
            let op = self.ops[pc];
            pc += 1;
            match op {
                Op::Const(v) => {
                    stack[sp] = v;
                    sp += 1;
                }
                Op::Slot(s) => {
                    stack[sp] = env.slots.get(s as usize).copied().unwrap_or(0.0);
                    sp += 1;
                }
                Op::NumIt => {
                    stack[sp] = env.num_it;
                    sp += 1;
                }
                Op::MaxIt => {
                    stack[sp] = env.max_it;
                    sp += 1;
                }
                Op::Var(k) => {
                    stack[sp] = deviate(env, k as usize)?;
                    sp += 1;
                }
                Op::Neg => stack[sp - 1] = -stack[sp - 1],
                Op::Not => stack[sp - 1] = truth(stack[sp - 1] == 0.0),
                Op::Truth => stack[sp - 1] = truth(stack[sp - 1] != 0.0),
                Op::Bin(op) => {
                    sp -= 1;
                    stack[sp - 1] = evaluate_binary(op, stack[sp - 1], stack[sp])
                        .ok_or_else(|| self.error(pc - 1, "division by zero".into()))?;
                }
                Op::Call(f) => {
                    let arity = f.info().arity();
                    sp -= arity;
                    let args = &stack[sp..sp + arity];
                    let value = call(f, args, env.rng).map_err(|m| self.error(pc - 1, m))?;
                    stack[sp] = value;
                    sp += 1;
                }
                Op::Curve(k) => stack[sp - 1] = self.curves[k as usize].value(stack[sp - 1]),
                Op::JumpIfFalse(target) => {
                    sp -= 1;
                    if stack[sp] == 0.0 {
                        pc = target as usize;
                    }
                }
                Op::Jump(target) => pc = target as usize,
            }
        }
        let value = stack[0];
        if !value.is_finite() {
            return Err(EvalError {
                message: format!("the expression gives {value}, not a finite number"),
                span: self.span.clone(),
            });
        }
        Ok(value)
    }

    fn error(&self, op: usize, message: String) -> EvalError {
        EvalError {
            message,
            span: self
                .spans
                .get(op)
                .cloned()
                .unwrap_or_else(|| self.span.clone()),
        }
    }
}

/// A compiled expression simple enough to evaluate without the interpreter ([`Program::simple`]):
/// its value is the interpreter's, bit for bit, whenever that is a finite number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Simple {
    Const(f64),
    Slot(u16),
    /// `slot op constant` (`+ - * /`).
    SlotConst(BinaryOp, u16, f64),
    ConstSlot(BinaryOp, f64, u16),
    SlotSlot(BinaryOp, u16, u16),
}

impl Simple {
    /// The highest slot the expression reads, if any.
    pub fn max_slot(self) -> Option<u16> {
        match self {
            Simple::Const(_) => None,
            Simple::Slot(s) | Simple::SlotConst(_, s, _) | Simple::ConstSlot(_, _, s) => Some(s),
            Simple::SlotSlot(_, a, b) => Some(a.max(b)),
        }
    }

    /// The value with `slots` bound (every slot read must be in `slots`). Not checked: a result
    /// that is not finite (a division by zero, an overflow) must be evaluated again by
    /// [`Program::eval`], which reports it.
    #[inline(always)]
    pub fn eval(self, slots: &[f64]) -> f64 {
        #[inline(always)]
        fn apply(op: BinaryOp, a: f64, b: f64) -> f64 {
            match op {
                BinaryOp::Add => a + b,
                BinaryOp::Sub => a - b,
                BinaryOp::Mul => a * b,
                _ => a / b,
            }
        }
        match self {
            Simple::Const(v) => v,
            Simple::Slot(s) => slots[s as usize],
            Simple::SlotConst(op, s, c) => apply(op, slots[s as usize], c),
            Simple::ConstSlot(op, c, s) => apply(op, c, slots[s as usize]),
            Simple::SlotSlot(op, a, b) => apply(op, slots[a as usize], slots[b as usize]),
        }
    }
}

/// The value of random variable `k` (`#random`): the module's deviate, drawn on first use, or a
/// fresh one when `env.fresh_vars`. A variable that reads others has them drawn first, in the order
/// [`RandomVariable::depends_on`] gives (the module's deviates, or fresh ones with it), so nothing
/// here recurses deeper than one variable.
#[inline]
fn deviate<R: rand::Rng + ?Sized>(env: &mut Env<'_, R>, k: usize) -> Result<f64, EvalError> {
    if !env.fresh_vars {
        if let Some(v) = env.vars.get(k).copied().flatten() {
            return Ok(v);
        }
    }
    let Some(variable) = env.variables.get(k) else {
        return Err(EvalError {
            message: "a #random variable that was never defined".into(),
            span: 0..0,
        });
    };
    let variables = env.variables;
    if variable.depends_on.is_empty() {
        let v = draw(
            variable,
            variables,
            &mut [],
            env.num_it,
            env.max_it,
            env.rng,
        )?;
        if !env.fresh_vars {
            if let Some(slot) = env.vars.get_mut(k) {
                *slot = Some(v);
            }
        }
        return Ok(v);
    }
    let mut fresh = Vec::new();
    let drawn: &mut [Option<f64>] = if env.fresh_vars {
        fresh.resize(variables.len(), None);
        &mut fresh
    } else {
        &mut *env.vars
    };
    for &j in &variable.depends_on {
        let j = j as usize;
        if drawn.get(j).copied().flatten().is_none() {
            let v = draw(
                &variables[j],
                variables,
                drawn,
                env.num_it,
                env.max_it,
                env.rng,
            )?;
            drawn[j] = Some(v);
        }
    }
    let v = draw(variable, variables, drawn, env.num_it, env.max_it, env.rng)?;
    if let Some(slot) = drawn.get_mut(k) {
        *slot = Some(v);
    }
    Ok(v)
}

/// One deviate of `variable`, the variables it reads taken from `drawn`.
fn draw<R: rand::Rng + ?Sized>(
    variable: &RandomVariable,
    variables: &[RandomVariable],
    drawn: &mut [Option<f64>],
    num_it: f64,
    max_it: f64,
    rng: &mut R,
) -> Result<f64, EvalError> {
    let mut inner = Env {
        slots: &[],
        num_it,
        max_it,
        vars: drawn,
        fresh_vars: false,
        variables,
        rng,
    };
    variable.distribution.eval(&mut inner)
}

/// `a op b`, or `None` for a division (or remainder) by zero.
#[inline(always)]
fn evaluate_binary(op: BinaryOp, a: f64, b: f64) -> Option<f64> {
    Some(match op {
        BinaryOp::Add => a + b,
        BinaryOp::Sub => a - b,
        BinaryOp::Mul => a * b,
        BinaryOp::Div | BinaryOp::Rem if b == 0.0 => return None,
        BinaryOp::Div => a / b,
        BinaryOp::Rem => a % b,
        BinaryOp::Pow => a.powf(b),
        BinaryOp::Lt => truth(a < b),
        BinaryOp::Le => truth(a <= b),
        BinaryOp::Gt => truth(a > b),
        BinaryOp::Ge => truth(a >= b),
        BinaryOp::Eq => truth(a == b),
        BinaryOp::Ne => truth(a != b),
        BinaryOp::And | BinaryOp::Or => unreachable_logic(a, b, op),
    })
}

/// `a op b` for the operators that cannot fail (before the finite check), as the loop computes it.
#[inline(always)]
fn quick_binary(op: BinaryOp, a: f64, b: f64) -> Option<f64> {
    match op {
        BinaryOp::Add => Some(a + b),
        BinaryOp::Sub => Some(a - b),
        BinaryOp::Mul => Some(a * b),
        _ => None,
    }
}

/// `&&` and `||` compile to jumps, so they never reach `Op::Bin`; this keeps the match total.
fn unreachable_logic(a: f64, b: f64, op: BinaryOp) -> f64 {
    match op {
        BinaryOp::And => truth(a != 0.0 && b != 0.0),
        _ => truth(a != 0.0 || b != 0.0),
    }
}

fn truth(b: bool) -> f64 {
    if b {
        1.0
    } else {
        0.0
    }
}

fn call<R: rand::Rng + ?Sized>(f: Function, a: &[f64], rng: &mut R) -> Result<f64, String> {
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
            _ => self.binary(start, op, b, span, depth),
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

    /// `left op b` for an operator other than `&&` and `||`, where the ops of `left` start at
    /// `start`; folded when both operands are constants (not a division by zero, nor a result
    /// that is not finite: those stay runtime errors). `depth` is that of `b`.
    fn binary(
        &mut self,
        start: usize,
        op: BinaryOp,
        b: &ExprSyntax,
        span: &Span,
        depth: usize,
    ) -> Result<(), Diagnostic> {
        self.expr(b, depth)?;
        if let [Op::Const(x), Op::Const(y)] = self.ops[start..] {
            if let Some(v) = evaluate_binary(op, x, y).filter(|v| v.is_finite()) {
                self.ops.truncate(start);
                self.spans.truncate(start);
                self.emit(Op::Const(v), span.clone());
                return Ok(());
            }
        }
        self.emit(Op::Bin(op), span.clone());
        Ok(())
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
        } else if let Some(value) = value_named(name) {
            let op = match value.value {
                Value::NumIt => Op::NumIt,
                Value::MaxIt => Op::MaxIt,
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
