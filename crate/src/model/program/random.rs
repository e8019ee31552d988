//! `#random` variables: each module's deviates, drawn on first use, the variables a distribution
//! reads drawn before it.

use super::{Env, EvalError, Program};

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

/// The value of random variable `k` (`#random`): the module's deviate, drawn on first use, or a
/// fresh one when `env.fresh_vars`. A variable that reads others has them drawn first, in the order
/// [`RandomVariable::depends_on`] gives (the module's deviates, or fresh ones with it), so nothing
/// here recurses deeper than one variable.
#[inline]
pub(super) fn deviate<R: rand::Rng + ?Sized>(
    env: &mut Env<'_, R>,
    k: usize,
) -> Result<f64, EvalError> {
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
