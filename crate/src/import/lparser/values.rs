//! The turtle's length, angle and thickness as Lparser scales them: which a symbol reads, the
//! net factor of an expansion over the steps left (its law: constant or geometric), and values
//! as products of factors ([`Prod`]).

use super::{Tok, A, L, T};
use crate::import::number;

/// The component a scaling command multiplies, and by how much.
pub(super) fn factor(tok: &Tok) -> Option<(usize, f64)> {
    let (comp, default) = match tok.ch {
        '\'' => (L, 0.9),
        '"' => (L, 1.0 / 0.9),
        ':' => (A, 0.9),
        ';' => (A, 1.0 / 0.9),
        '!' => (T, 0.7),
        '?' => (T, 1.0 / 0.7),
        _ => return None,
    };
    Some((comp, tok.value.unwrap_or(default)))
}

/// The state components a command reads when it draws or turns.
pub(super) fn reads(ch: char, has_value: bool) -> [bool; 3] {
    match ch {
        'F' | 'Z' => [!has_value, false, true],
        'f' | 'z' | 'g' => [!has_value, false, false],
        '+' | '-' | '&' | '^' | '<' | '>' => [false, !has_value, false],
        _ => [false; 3],
    }
}

/// The net scaling of an expansion as a function of the steps left, r.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Net {
    Neutral,
    /// `prefix[r]` for r < prefix.len(), then `base * ratio^(r - prefix.len())`.
    Law {
        prefix: Vec<f64>,
        base: f64,
        ratio: f64,
    },
    Irregular,
}

pub(super) fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(1e-300)
}

pub(super) fn classify(s: &[f64]) -> Net {
    if s.iter().all(|&v| close(v, 1.0)) {
        return Net::Neutral;
    }
    if s.iter().any(|v| !v.is_finite()) {
        return Net::Irregular;
    }
    for k in 0..s.len().saturating_sub(8) {
        let ratio = if s[k] == 0.0 { 1.0 } else { s[k + 1] / s[k] };
        let fits = (k..s.len()).all(|r| close(s[r], s[k] * ratio.powi((r - k) as i32)));
        if fits {
            return Net::Law {
                prefix: s[..k].to_vec(),
                base: s[k],
                ratio: if close(ratio, 1.0) { 1.0 } else { ratio },
            };
        }
    }
    Net::Irregular
}

/// The Meristem expression of a net factor for a symbol written at step `NumIt` (rewritten
/// `MaxIt - NumIt` more times).
pub(super) fn net_expr(net: &Net) -> Option<String> {
    let Net::Law {
        prefix,
        base,
        ratio,
    } = net
    else {
        return None;
    };
    let k = prefix.len();
    let left = if k == 0 {
        "(MaxIt-NumIt)".to_string()
    } else {
        format!("(MaxIt-NumIt-{k})")
    };
    let tail = if *ratio == 1.0 {
        number(*base)
    } else if close(*base, 1.0) {
        format!("{}^{left}", number(*ratio))
    } else {
        format!("{}*{}^{left}", number(*base), number(*ratio))
    };
    Some(match k {
        0 => tail,
        1 => format!("(NumIt<MaxIt?{tail}:{})", number(prefix[0])),
        _ => {
            let mut chain = String::from("(");
            for (r, v) in prefix.iter().enumerate() {
                chain.push_str(&format!("MaxIt-NumIt<{}?{}:", r + 1, number(*v)));
            }
            chain.push_str(&tail);
            chain.push(')');
            chain
        }
    })
}

/// A product `coef × factors…`, for parameter expressions.
#[derive(Clone, Debug)]
pub(super) struct Prod {
    coef: f64,
    factors: Vec<String>,
}

impl Prod {
    pub(super) fn constant(v: f64) -> Self {
        Prod {
            coef: v,
            factors: Vec::new(),
        }
    }
    pub(super) fn name(name: &str) -> Self {
        Prod {
            coef: 1.0,
            factors: vec![name.to_string()],
        }
    }
    pub(super) fn times(&self, v: f64) -> Self {
        Prod {
            coef: self.coef * v,
            factors: self.factors.clone(),
        }
    }
    pub(super) fn times_expr(&mut self, e: String) {
        self.factors.push(e);
    }
    pub(super) fn is_constant(&self, v: f64) -> bool {
        self.factors.is_empty() && close(self.coef, v)
    }
    pub(super) fn render(&self) -> String {
        if self.factors.is_empty() || self.coef == 0.0 {
            return number(self.coef);
        }
        let mut counted: Vec<(&String, usize)> = Vec::new();
        for f in &self.factors {
            match counted.iter_mut().find(|(g, _)| *g == f) {
                Some((_, n)) => *n += 1,
                None => counted.push((f, 1)),
            }
        }
        let mut s = counted
            .iter()
            .map(|(f, n)| match n {
                1 => (*f).clone(),
                // `^` is right-associative: (x^y)^n needs its parentheses.
                n => format!("({f})^{n}"),
            })
            .collect::<Vec<_>>()
            .join("*");
        if !close(self.coef, 1.0) {
            s.push('*');
            s.push_str(&number(self.coef));
        }
        s
    }
}
