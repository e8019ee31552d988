//! Expressions (cpfg's C, L-Py's Python) in Meristem's terms: numbers, names bound by statement
//! blocks, calls (each dialect's functions, L-Py's trigonometry in radians), operators.

use super::cpfg::blocks::MAX_VALUE;
use super::cpfg::cpp;
use super::{split_top, Env, Flavour, Importer};
use crate::syntax::PARENTHESES;

/// The longest text one read of a cpfg array may give (its values in a choice by index).
const MAX_ARRAY_READ: usize = 100_000;

/// `180 / π`: L-Py's trigonometry is Python's, in radians; Meristem's is in degrees.
pub(in crate::import::abop) const DEGREES: &str = "57.2957795131";

/// The index after the number that starts at `chars[start]` (digits, letters and dots, and a
/// sign after an exponent's `e`).
pub(in crate::import::abop) fn number_end(chars: &[char], start: usize) -> usize {
    let mut i = start;
    while i < chars.len()
        && (chars[i].is_ascii_alphanumeric()
            || chars[i] == '.'
            || ((chars[i] == '-' || chars[i] == '+') && matches!(chars[i - 1], 'e' | 'E')))
    {
        i += 1;
    }
    i
}

/// The byte index of `word` standing alone (not part of a longer name), outside parentheses.
pub(in crate::import::abop) fn find_word(text: &str, word: &str) -> Option<usize> {
    let bytes = text.as_bytes();
    PARENTHESES.find_top_level(text, |i, _| {
        if !text[i..].starts_with(word) {
            return false;
        }
        let before = i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_');
        let end = i + word.len();
        let after =
            end >= bytes.len() || !(bytes[end].is_ascii_alphanumeric() || bytes[end] == b'_');
        before && after
    })
}

impl Importer {
    /// Translates an expression (cpfg's C, L-Py's Python) with `env`'s names substituted.
    pub(in crate::import::abop) fn expression(
        &mut self,
        text: &str,
        env: &Env,
    ) -> Result<String, String> {
        let text = text.trim();
        if self.flavour == Flavour::Lpy {
            // Python's conditional expression `a if c else b`.
            if let (Some(i), Some(e)) = (find_word(text, "if"), find_word(text, "else")) {
                if i < e {
                    let a = self.expression(&text[..i], env)?;
                    let c = self.expression(&text[i + 2..e], env)?;
                    let b = self.expression(&text[e + 4..], env)?;
                    return Ok(format!("({c}?{a}:{b})"));
                }
            }
        }
        let chars: Vec<char> = text.chars().collect();
        let mut out = String::new();
        let mut i = 0;
        while i < chars.len() {
            let c = chars[i];
            if c == '\'' || c == '"' {
                return Err("a string is not a number".into());
            }
            i = if c.is_ascii_digit()
                || (c == '.' && chars.get(i + 1).is_some_and(char::is_ascii_digit))
            {
                let end = number_end(&chars, i);
                out.extend(&chars[i..end]);
                end
            } else if c.is_ascii_alphabetic() || c == '_' {
                self.word(&chars, i, env, &mut out)?
            } else {
                self.operator(&chars, i, &mut out)?
            };
        }
        Ok(out)
    }

    /// Translates the name at `chars[start]` into `out`: a call with its arguments, a name bound
    /// in `env`, one of Python's words, or the name itself. Returns the index after it.
    pub(in crate::import::abop) fn word(
        &mut self,
        chars: &[char],
        start: usize,
        env: &Env,
        out: &mut String,
    ) -> Result<usize, String> {
        let mut i = start;
        while i < chars.len()
            && (chars[i].is_ascii_alphanumeric() || chars[i] == '_' || chars[i] == '.')
        {
            i += 1;
        }
        let mut word: String = chars[start..i].iter().collect();
        if self.flavour == Flavour::Lpy {
            for prefix in ["math.", "random.", "np.", "numpy."] {
                if let Some(w) = word.strip_prefix(prefix) {
                    word = w.to_string();
                }
            }
        }
        if word.contains('.') {
            return Err(format!("'{word}' is Python, not a number expression"));
        }
        let mut j = i;
        while j < chars.len() && chars[j] == ' ' {
            j += 1;
        }
        if chars.get(j) == Some(&'[') && self.flavour == Flavour::Cpfg {
            return self.array_read(chars, j, &word, env, out);
        }
        if chars.get(j) == Some(&'(') {
            let close = PARENTHESES
                .closing_char(chars, j)
                .ok_or("a '(' is never closed")?;
            let inner: String = chars[j + 1..close].iter().collect();
            let mut args = Vec::new();
            for arg in split_top(&inner, ',') {
                if !arg.trim().is_empty() {
                    args.push(self.expression(arg, env)?);
                }
            }
            out.push_str(&self.call(&word, &args)?);
            return Ok(close + 1);
        }
        if let Some(value) = env.get(&word) {
            out.push_str(value);
            return Ok(i);
        }
        let replacement = match (self.flavour, word.as_str()) {
            (Flavour::Lpy, "and") => "&&".to_string(),
            (Flavour::Lpy, "or") => "||".to_string(),
            (Flavour::Lpy, "not") => "!".to_string(),
            (Flavour::Lpy, "True") => "1".to_string(),
            (Flavour::Lpy, "False") => "0".to_string(),
            (Flavour::Lpy, "pi") => "3.14159265359".to_string(),
            (Flavour::Lpy, "None") => return Err("None is not a number".into()),
            _ => word,
        };
        if replacement.chars().all(|c| c.is_ascii_alphabetic())
            && !out.is_empty()
            && out.ends_with(|c: char| c.is_ascii_alphanumeric())
        {
            out.push(' ');
        }
        out.push_str(&replacement);
        Ok(i)
    }

    /// cpfg's `name[i]`, `name[i][j]`… at `chars[j]` (the first `[`), with as many indices as
    /// the array has dimensions, into `out`. Returns the index after it.
    pub(in crate::import::abop) fn array_read(
        &mut self,
        chars: &[char],
        j: usize,
        word: &str,
        env: &Env,
        out: &mut String,
    ) -> Result<usize, String> {
        let wanted = self.array_dimensions(word).unwrap_or(1);
        let mut indices = Vec::new();
        let mut at = j;
        while indices.len() < wanted && chars.get(at) == Some(&'[') {
            let close = chars[at..]
                .iter()
                .position(|&c| c == ']')
                .map(|k| at + k)
                .ok_or("a '[' is never closed")?;
            let inner: String = chars[at + 1..close].iter().collect();
            indices.push(self.expression(&inner, env)?);
            at = close + 1;
            while chars.get(at) == Some(&' ') && indices.len() < wanted {
                at += 1;
            }
        }
        let value = self.array_value(word, &indices).ok_or_else(|| {
            format!("'{word}[…]' reads an array that cpfg's Start: or Define: block does not give as one list of values")
        })?;
        // The choice repeats the index once for each value (issue 50, 6).
        if value.len() > MAX_ARRAY_READ {
            return Err(format!(
                "'{word}[…]' read here grows longer than {MAX_ARRAY_READ} characters"
            ));
        }
        out.push_str(&value);
        Ok(at)
    }

    /// Translates the operator or punctuation at `chars[i]` into `out` (Python's `**` is `^`;
    /// what has no meaning in an expression is an error). Returns the index after it.
    pub(in crate::import::abop) fn operator(
        &self,
        chars: &[char],
        i: usize,
        out: &mut String,
    ) -> Result<usize, String> {
        let c = chars[i];
        let two: String = chars[i..(i + 2).min(chars.len())].iter().collect();
        match (self.flavour, two.as_str(), c) {
            (Flavour::Lpy, "**", _) => {
                out.push('^');
                Ok(i + 2)
            }
            (Flavour::Lpy, "//", _) => Err("Python's floor division // is not translated".into()),
            (Flavour::Lpy, _, '^') => Err("Python's ^ is a bitwise or, not a power".into()),
            (_, _, '[' | ']' | '{' | '}' | ';' | '`' | '$' | '@' | '#') => {
                Err(format!("'{c}' in an expression"))
            }
            _ => {
                out.push(c);
                Ok(i + 1)
            }
        }
    }

    /// A function call in Meristem's terms.
    pub(in crate::import::abop) fn call(
        &mut self,
        name: &str,
        args: &[String],
    ) -> Result<String, String> {
        if let Some((_, params, body)) = self.lpy.helpers.iter().find(|(h, _, _)| h == name) {
            if params.len() != args.len() {
                return Err(format!(
                    "{name}(…) takes {} arguments, not {}",
                    params.len(),
                    args.len()
                ));
            }
            let args: Vec<String> = args.iter().map(|a| format!("({a})")).collect();
            let inlined = cpp::substitute(body, params, &args);
            // A function that uses its argument twice doubles with each call nested in the
            // next (issue 50, 5: `f(x) = x+x` nested 28 deep asked for 4 GB).
            if inlined.len() > MAX_VALUE {
                return Err(format!(
                    "{name}(…) inlined here grows longer than {MAX_VALUE} characters"
                ));
            }
            return Ok(format!("({inlined})"));
        }
        let a = |k: usize| args.get(k).cloned().unwrap_or_default();
        let all = args.join(",");
        Ok(match (self.flavour, name) {
            (Flavour::Lpy, "sin" | "cos" | "tan") => format!("{name}(({})*{DEGREES})", a(0)),
            (Flavour::Lpy, "asin" | "acos" | "atan" | "atan2") => {
                format!("({name}({all})/{DEGREES})")
            }
            (Flavour::Lpy, "radians") => format!("(({})/{DEGREES})", a(0)),
            (Flavour::Lpy, "degrees") => format!("(({})*{DEGREES})", a(0)),
            (Flavour::Lpy, "random") if args.is_empty() => "uniform(0,1)".into(),
            // L-Py counts the steps from 0; Meristem's NumIt from 1.
            (Flavour::Lpy, "getIterationNb") if args.is_empty() => "(NumIt-1)".into(),
            (Flavour::Lpy, "randint") => format!("uniform_int({all})"),
            (Flavour::Lpy, "gauss" | "normalvariate") => format!("normal({all})"),
            (Flavour::Lpy, "expovariate") => format!("exponential({all})"),
            (Flavour::Lpy, "float") => format!("({})", a(0)),
            (Flavour::Lpy, "int") | (Flavour::Cpfg, "trunc") => {
                format!("(({0})<0?ceil({0}):floor({0}))", a(0))
            }
            (Flavour::Lpy, "pow") => format!("(({})^({}))", a(0), a(1)),
            (Flavour::Cpfg, "func") => return self.func(args),
            (Flavour::Cpfg, "tfunc") => return self.tfunc(args),
            (Flavour::Cpfg, "val") => return self.val(args),
            (Flavour::Cpfg, "ran") => format!("uniform(0,{})", a(0)),
            (Flavour::Cpfg, "nran") => format!("normal({all})"),
            (Flavour::Cpfg, "bran") => format!("betavariate({all})"),
            (Flavour::Cpfg, "curveX") => return self.contour(name, Some(0), args),
            (Flavour::Cpfg, "curveY") => return self.contour(name, Some(1), args),
            (Flavour::Cpfg, "curveZ") => return self.contour(name, Some(2), args),
            (Flavour::Cpfg, "curveGAL") => return self.contour(name, None, args),
            (Flavour::Cpfg, "biran") => format!("binomial({all})"),
            (_, "fabs") => format!("abs({all})"),
            _ => format!("{name}({all})"),
        })
    }
}
