//! What expressions may call and read: functions (LANGUAGE.md sections 4 and 5) and the values
//! `NumIt` and `MaxIt`.

use super::params::text;
use serde::Serialize;

/// A function of expressions (trigonometry in degrees).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Function {
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Atan2,
    Sqrt,
    Exp,
    Log,
    Abs,
    Floor,
    Ceil,
    Round,
    Min,
    Max,
    Clamp,
    Sign,
    Uniform,
    Normal,
    Exponential,
    UniformInt,
    Binomial,
    Poisson,
    Beta,
    Constant,
    Linear,
    ExponentialGrowth,
    Logistic,
    Sigmoid,
}

impl Function {
    /// Its row of [`FUNCTIONS`] (the table lists the functions in the enum's order).
    pub fn info(self) -> &'static FunctionInfo {
        &FUNCTIONS[self as usize]
    }
}

/// One row of the function table.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct FunctionInfo {
    pub name: &'static str,
    #[serde(skip)]
    pub function: Function,
    /// Its parameters' names; a call has exactly this many arguments.
    pub params: &'static [&'static str],
    /// True for the random functions: a fresh deviate at each evaluation.
    pub random: bool,
    pub doc: &'static str,
}

impl FunctionInfo {
    pub fn arity(&self) -> usize {
        self.params.len()
    }

    /// The function as a random one: a fresh deviate at each evaluation.
    const fn random(self) -> FunctionInfo {
        FunctionInfo {
            random: true,
            ..self
        }
    }
}

const fn f(
    name: &'static str,
    function: Function,
    params: &'static [&'static str],
    doc: &'static str,
) -> FunctionInfo {
    FunctionInfo {
        name,
        function,
        params,
        random: false,
        doc: text(doc),
    }
}

use Function as F;

/// Every function, in the order of LANGUAGE.md sections 4 and 5. Names are matched in any case
/// (Green writes `UNIFORM(0, 1)`).
#[rustfmt::skip]
pub const FUNCTIONS: &[FunctionInfo] = &[
    f("sin", F::Sin, &["x"], "Sine of x degrees."),
    f("cos", F::Cos, &["x"], "Cosine of x degrees."),
    f("tan", F::Tan, &["x"], "Tangent of x degrees."),
    f("asin", F::Asin, &["x"], "Arc sine of x, in degrees."),
    f("acos", F::Acos, &["x"], "Arc cosine of x, in degrees."),
    f("atan", F::Atan, &["x"], "Arc tangent of x, in degrees."),
    f("atan2", F::Atan2, &["y", "x"], "The angle of the point (x, y), in degrees."),
    f("sqrt", F::Sqrt, &["x"], "Square root of x (x ≥ 0)."),
    f("exp", F::Exp, &["x"], "e to the power x."),
    f("log", F::Log, &["x"], "Natural logarithm of x (x > 0)."),
    f("abs", F::Abs, &["x"], "Absolute value of x."),
    f("floor", F::Floor, &["x"], "The largest whole number ≤ x."),
    f("ceil", F::Ceil, &["x"], "The smallest whole number ≥ x."),
    f("round", F::Round, &["x"], "x rounded to the nearest whole number (halves away from 0)."),
    f("min", F::Min, &["a", "b"], "The smaller of a and b."),
    f("max", F::Max, &["a", "b"], "The larger of a and b."),
    f("clamp", F::Clamp, &["x", "lo", "hi"], "x limited to lo … hi."),
    f("sign", F::Sign, &["x"], "−1, 0 or 1 by the sign of x."),
    f("uniform", F::Uniform, &["a", "b"], "A random number from a (included) to b (excluded).").random(),
    f("normal", F::Normal, &["mean", "sd"], "A random number of the normal distribution.").random(),
    f("exponential", F::Exponential, &["mean"], "A random number of the exponential distribution.").random(),
    f("uniform_int", F::UniformInt, &["a", "b"], "A random whole number from a to b, both included.").random(),
    f("binomial", F::Binomial, &["n", "p"], "A random number of successes in n trials of probability p.").random(),
    f("poisson", F::Poisson, &["mean"], "A random number of the Poisson distribution.").random(),
    f("betavariate", F::Beta, &["a", "b"], "A random number of the beta distribution of shapes a, b > 0, from 0 to 1 (Python's random.betavariate, cpfg's bran).").random(),
    f("constant", F::Constant, &["x"], "x itself (Green's CONSTANT distribution)."),
    f("linear", F::Linear, &["x", "a", "b"], "Growth function: from a at x = 0 to b at x = 1 in a straight line, a before and b after (x: age / terminal age)."),
    f("exponential_growth", F::ExponentialGrowth, &["x", "a", "b"], "Growth function: from a at x = 0 to b at x = 1 multiplying by the same factor in equal times, a·(b/a)^x (a, b > 0)."),
    f("logistic", F::Logistic, &["x", "a", "b", "k"], "Growth function: the logistic curve of steepness k > 0 centred at x = 1/2, scaled to run from a at x = 0 to b at x = 1."),
    f("sigmoid", F::Sigmoid, &["x", "a", "b"], "Growth function: from a at x = 0 to b at x = 1 along the smooth S x²(3 − 2x), starting and ending at rest."),
];

/// The row of a function name, in any case.
pub fn function_named(name: &str) -> Option<&'static FunctionInfo> {
    FUNCTIONS.iter().find(|f| f.name.eq_ignore_ascii_case(name))
}

/// A value an expression reads without a parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Value {
    /// The step being derived (1 for the first).
    NumIt,
    /// The number of steps of the derivation.
    MaxIt,
    /// The time one derivation step covers (`#dt`, default 1).
    Dt,
}

/// One row of the value table.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct ValueInfo {
    pub name: &'static str,
    pub value: Value,
    /// True when a grammar's own `#define` or `#random` of this name replaces it (cpfg models
    /// define `dt` themselves).
    pub definable: bool,
    pub doc: &'static str,
}

/// The values expressions read.
pub const VALUES: &[ValueInfo] = &[
    ValueInfo {
        name: "NumIt",
        value: Value::NumIt,
        definable: false,
        doc: text("The step being derived: 1 in the first step (0 in the axiom)."),
    },
    ValueInfo {
        name: "MaxIt",
        value: Value::MaxIt,
        definable: false,
        doc: text("The number of steps of this derivation."),
    },
    ValueInfo {
        name: "dt",
        value: Value::Dt,
        definable: true,
        doc: text("The time one derivation step covers: #dt, 1 by default (L-Py's dt); a grammar's own #define dt replaces it."),
    },
];

/// The row of a value name (exact case).
pub fn value_named(name: &str) -> Option<&'static ValueInfo> {
    VALUES.iter().find(|v| v.name == name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_follows_the_enum() {
        for (i, row) in FUNCTIONS.iter().enumerate() {
            assert_eq!(row.function as usize, i, "{}", row.name);
            assert_eq!(row.function.info().name, row.name);
        }
        assert_eq!(function_named("UNIFORM").map(|f| f.random), Some(true));
        assert!(
            value_named("numit").is_none(),
            "values are matched in exact case"
        );
    }
}
