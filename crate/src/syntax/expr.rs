//! The expression parser: precedence climbing over the text of one expression, with spans.
//!
//! Precedence, lowest first: `?:` (right), `||`, `&&`, `== != =`, `< <= > >=`, `+ -`, `* / %`,
//! unary `- + !`, `^` (right, binds tighter than unary minus: `-2^2` is −4), calls and parentheses.

use super::ast::{BinaryOp, ExprSyntax, Span, UnaryOp};
use crate::diagnostics::Diagnostic;

/// Expressions nested deeper than this are rejected (the parser and the compiler recurse).
pub const MAX_EXPRESSION_DEPTH: usize = 64;

/// Parses all of `text` (which starts at byte `base` of the source) as one expression.
pub fn parse_expression(text: &str, base: usize) -> Result<ExprSyntax, Diagnostic> {
    let mut p = ExprParser {
        text,
        base,
        pos: 0,
        depth: 0,
    };
    let expr = p.conditional()?;
    p.skip_ws();
    if p.pos < text.len() {
        let c = p.peek_char().unwrap_or(' ');
        return Err(p.error_here("E0120", format!("unexpected '{c}' in expression")));
    }
    Ok(expr)
}

struct ExprParser<'a> {
    text: &'a str,
    base: usize,
    pos: usize,
    depth: usize,
}

impl ExprParser<'_> {
    fn skip_ws(&mut self) {
        while let Some(c) = self.peek_char() {
            if !c.is_whitespace() {
                break;
            }
            self.pos += c.len_utf8();
        }
    }

    fn peek_char(&self) -> Option<char> {
        self.text[self.pos..].chars().next()
    }

    fn eat(&mut self, token: &str) -> bool {
        self.skip_ws();
        if self.text[self.pos..].starts_with(token) {
            self.pos += token.len();
            true
        } else {
            false
        }
    }

    fn span_from(&self, start: usize) -> Span {
        self.base + start..self.base + self.pos
    }

    fn error_here(&self, code: &'static str, message: String) -> Diagnostic {
        let len = self.peek_char().map_or(0, char::len_utf8);
        Diagnostic::error(
            code,
            self.base + self.pos..self.base + self.pos + len,
            message,
        )
    }

    fn enter(&mut self) -> Result<(), Diagnostic> {
        self.depth += 1;
        if self.depth > MAX_EXPRESSION_DEPTH {
            return Err(self.error_here(
                "E0121",
                format!("expression nested more than {MAX_EXPRESSION_DEPTH} levels deep"),
            ));
        }
        Ok(())
    }

    fn conditional(&mut self) -> Result<ExprSyntax, Diagnostic> {
        self.enter()?;
        self.skip_ws();
        let start = self.pos;
        let cond = self.binary(0)?;
        let result = if self.eat("?") {
            let then = self.conditional()?;
            if !self.eat(":") {
                return Err(
                    self.error_here("E0122", "expected ':' of a conditional 'c ? a : b'".into())
                );
            }
            let otherwise = self.conditional()?;
            ExprSyntax::Conditional(
                Box::new(cond),
                Box::new(then),
                Box::new(otherwise),
                self.span_from(start),
            )
        } else {
            cond
        };
        self.depth -= 1;
        Ok(result)
    }

    /// Binary operators of precedence level `level` and above.
    fn binary(&mut self, level: usize) -> Result<ExprSyntax, Diagnostic> {
        const LEVELS: &[&[(&str, BinaryOp)]] = &[
            &[("||", BinaryOp::Or)],
            &[("&&", BinaryOp::And)],
            &[
                ("==", BinaryOp::Eq),
                ("!=", BinaryOp::Ne),
                ("=", BinaryOp::Eq),
            ],
            &[
                ("<=", BinaryOp::Le),
                (">=", BinaryOp::Ge),
                ("<", BinaryOp::Lt),
                (">", BinaryOp::Gt),
            ],
            &[("+", BinaryOp::Add), ("-", BinaryOp::Sub)],
            &[
                ("*", BinaryOp::Mul),
                ("/", BinaryOp::Div),
                ("%", BinaryOp::Rem),
            ],
        ];
        if level == LEVELS.len() {
            return self.unary();
        }
        self.skip_ws();
        let start = self.pos;
        let first = self.binary(level + 1)?;
        let mut links = Vec::new();
        'outer: loop {
            for &(token, op) in LEVELS[level] {
                if self.eat(token) {
                    let rhs = self.binary(level + 1)?;
                    links.push((op, rhs, self.span_from(start)));
                    continue 'outer;
                }
            }
            break;
        }
        if links.is_empty() {
            return Ok(first);
        }
        Ok(ExprSyntax::Chain(Box::new(first), links))
    }

    fn unary(&mut self) -> Result<ExprSyntax, Diagnostic> {
        self.skip_ws();
        let start = self.pos;
        let op =
            if self.text[self.pos..].starts_with('!') && !self.text[self.pos..].starts_with("!=") {
                Some(UnaryOp::Not)
            } else if self.text[self.pos..].starts_with('-') {
                Some(UnaryOp::Neg)
            } else if self.text[self.pos..].starts_with('+') {
                self.pos += 1;
                return self.unary();
            } else {
                None
            };
        match op {
            Some(op) => {
                self.pos += 1;
                self.enter()?;
                let operand = self.unary()?;
                self.depth -= 1;
                Ok(ExprSyntax::Unary(
                    op,
                    Box::new(operand),
                    self.span_from(start),
                ))
            }
            None => self.power(),
        }
    }

    fn power(&mut self) -> Result<ExprSyntax, Diagnostic> {
        self.skip_ws();
        let start = self.pos;
        let base = self.primary()?;
        if self.eat("^") {
            self.enter()?;
            let exponent = self.unary()?; // right associative: 2^3^2 = 2^9; 2^-1 allowed
            self.depth -= 1;
            return Ok(ExprSyntax::Binary(
                BinaryOp::Pow,
                Box::new(base),
                Box::new(exponent),
                self.span_from(start),
            ));
        }
        Ok(base)
    }

    fn primary(&mut self) -> Result<ExprSyntax, Diagnostic> {
        self.skip_ws();
        let start = self.pos;
        let rest = &self.text[self.pos..];
        let Some(c) = rest.chars().next() else {
            return Err(self.error_here(
                "E0123",
                "expected a number, a name or '(' but the expression ends".into(),
            ));
        };
        if c == '(' {
            self.pos += 1;
            let inner = self.conditional()?;
            if !self.eat(")") {
                return Err(self.error_here("E0124", "expected ')'".into()));
            }
            return Ok(inner);
        }
        if c.is_ascii_digit() || (c == '.' && rest[1..].starts_with(|d: char| d.is_ascii_digit())) {
            let len = number_length(rest);
            let literal = &rest[..len];
            self.pos += len;
            let value = crate::number::parse_f64(literal).ok_or_else(|| {
                Diagnostic::error(
                    "E0125",
                    self.span_from(start),
                    format!("'{literal}' is not a number"),
                )
            })?;
            if !value.is_finite() {
                return Err(Diagnostic::error(
                    "E0126",
                    self.span_from(start),
                    format!("the number {literal} is too large for a 64-bit float"),
                ));
            }
            return Ok(ExprSyntax::Number(value, self.span_from(start)));
        }
        if c.is_alphabetic() || c == '_' {
            let len = rest
                .find(|c: char| !(c.is_alphanumeric() || c == '_'))
                .unwrap_or(rest.len());
            let name = rest[..len].to_string();
            self.pos += len;
            let name_span = self.span_from(start);
            if self.eat("(") {
                let mut args = Vec::new();
                if !self.eat(")") {
                    loop {
                        args.push(self.conditional()?);
                        if self.eat(")") {
                            break;
                        }
                        if !self.eat(",") {
                            return Err(self.error_here(
                                "E0124",
                                format!("expected ',' or ')' in the call of {name}"),
                            ));
                        }
                    }
                }
                return Ok(ExprSyntax::Call(
                    name,
                    name_span,
                    args,
                    self.span_from(start),
                ));
            }
            return Ok(ExprSyntax::Name(name, name_span));
        }
        Err(self.error_here("E0120", format!("unexpected '{c}' in expression")))
    }
}

/// Length of the number literal at the start of `s`: digits, one '.', an exponent.
fn number_length(s: &str) -> usize {
    let b = s.as_bytes();
    let mut i = 0;
    while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'.') {
        i += 1;
    }
    if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        let mut j = i + 1;
        if j < b.len() && (b[j] == b'+' || b[j] == b'-') {
            j += 1;
        }
        if j < b.len() && b[j].is_ascii_digit() {
            while j < b.len() && b[j].is_ascii_digit() {
                j += 1;
            }
            i = j;
        }
    }
    i
}

#[cfg(test)]
mod tests {
    use super::*;

    fn show(e: &ExprSyntax) -> String {
        match e {
            ExprSyntax::Number(v, _) => format!("{v}"),
            ExprSyntax::Name(n, _) => n.clone(),
            ExprSyntax::Unary(op, x, _) => format!("({op:?} {})", show(x)),
            ExprSyntax::Binary(op, a, b, _) => format!("({op:?} {} {})", show(a), show(b)),
            ExprSyntax::Chain(first, links) => links.iter().fold(show(first), |a, (op, b, _)| {
                format!("({op:?} {a} {})", show(b))
            }),
            ExprSyntax::Conditional(c, a, b, _) => {
                format!("(? {} {} {})", show(c), show(a), show(b))
            }
            ExprSyntax::Call(n, _, args, _) => {
                format!(
                    "{n}({})",
                    args.iter().map(show).collect::<Vec<_>>().join(",")
                )
            }
        }
    }

    fn parsed(s: &str) -> String {
        show(&parse_expression(s, 0).unwrap_or_else(|d| panic!("{s}: {}", d.message)))
    }

    #[test]
    fn precedence_and_associativity() {
        assert_eq!(parsed("1 + 2 * 3"), "(Add 1 (Mul 2 3))");
        assert_eq!(parsed("-2^2"), "(Neg (Pow 2 2))");
        assert_eq!(parsed("2^3^2"), "(Pow 2 (Pow 3 2))");
        assert_eq!(parsed("a-b-c"), "(Sub (Sub a b) c)");
        assert_eq!(
            parsed("x+y+z > 10 && !(p = .5)"),
            "(And (Gt (Add (Add x y) z) 10) (Not (Eq p 0.5)))"
        );
        assert_eq!(parsed("c ? a : b ? d : e"), "(? c a (? b d e))");
        assert_eq!(
            parsed("max(1, min(x, 2e-3)) % 4"),
            "(Rem max(1,min(x,0.002)) 4)"
        );
        assert_eq!(parsed("(p*q)^0.5"), "(Pow (Mul p q) 0.5)");
    }

    #[test]
    fn errors_point_at_the_problem() {
        let e = parse_expression("x + * 2", 10).unwrap_err();
        assert_eq!((e.code, e.span.start), ("E0120", 14));
        let e = parse_expression("1e999", 0).unwrap_err();
        assert_eq!(e.code, "E0126");
        let e =
            parse_expression(&format!("{}1{}", "(".repeat(100), ")".repeat(100)), 0).unwrap_err();
        assert_eq!(e.code, "E0121");
        let e = parse_expression("sin(x", 0).unwrap_err();
        assert_eq!(e.code, "E0124");
        assert_eq!(parse_expression("", 0).unwrap_err().code, "E0123");
    }
}
