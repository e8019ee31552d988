//! Evaluation: the interpreter loop over a [`Program`]'s ops, its quick paths, and [`Simple`], the
//! shapes a template evaluates without the interpreter.

use super::functions::call;
use super::random::deviate;
use super::{Env, EvalError, Op, Program, MAX_STACK};
use crate::maths;
use crate::syntax::BinaryOp;

impl Program {
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
                message: format!(
                    "the expression gives {}, not a finite number",
                    crate::number::Decimal(value)
                ),
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

/// `a op b`, or `None` for a division (or remainder) by zero.
#[inline(always)]
pub(super) fn evaluate_binary(op: BinaryOp, a: f64, b: f64) -> Option<f64> {
    Some(match op {
        BinaryOp::Add => a + b,
        BinaryOp::Sub => a - b,
        BinaryOp::Mul => a * b,
        BinaryOp::Div | BinaryOp::Rem if b == 0.0 => return None,
        BinaryOp::Div => a / b,
        BinaryOp::Rem => a % b,
        BinaryOp::Pow => maths::powf(a, b),
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

pub(super) fn truth(b: bool) -> f64 {
    if b {
        1.0
    } else {
        0.0
    }
}
