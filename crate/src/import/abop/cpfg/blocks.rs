//! cpfg's statement blocks (`{x = e; if (c) {…} else …}`): assignments bind names for what
//! follows, `if`/`else` over assignments bind conditional values, and in lpfg's blocks each
//! `produce` ends a path.

use super::super::{is_identifier, Env, Importer};
use crate::syntax::PARENTHESES_AND_BRACES;

impl Importer {
    /// A statement block, in order: assignments `x = e;` (also `+=` …), which bind `x` for what
    /// follows; `if (c) … else …` over assignments, which binds each variable a branch assigns to
    /// a conditional expression `((c)?then:else)`; `{…}` groups; `printf` (dropped with a note);
    /// a statement that assigns nothing (no effect in cpfg either: dropped with a note). A loop,
    /// or anything else, is an error (the production is skipped).
    pub(in crate::import::abop) fn block(
        &mut self,
        block: &str,
        env: &mut Env,
        n: usize,
    ) -> Result<(), String> {
        self.statements(block, env, n, 0).map(|_| ())
    }

    /// The statements of `text` (see [`Importer::block`]); `depth` bounds the nesting of braces
    /// and `if`s, so that no input exhausts the stack.
    /// Returns whether every path through them ends at lpfg's `produce`.
    pub(in crate::import::abop) fn statements(
        &mut self,
        text: &str,
        env: &mut Env,
        n: usize,
        depth: usize,
    ) -> Result<bool, String> {
        if depth > 16 {
            return Err("statement blocks nest more than 16 deep".into());
        }
        let mut rest = text.trim_start();
        while !rest.is_empty() {
            let (statement, after) = next_statement(rest, 0)?;
            rest = after.trim_start();
            let statement = match statement {
                Statement::Group(inner) => {
                    if self.statements(inner, env, n, depth + 1)? {
                        return Ok(true);
                    }
                    continue;
                }
                Statement::If(condition, then, otherwise) => {
                    if self.if_statement(condition, then, otherwise, env, n, depth)? {
                        return Ok(true);
                    }
                    continue;
                }
                Statement::While(condition, body, once) => {
                    if once {
                        self.statements(body, env, n, depth + 1)?;
                    }
                    self.loop_statement(condition, body, env, depth)?;
                    continue;
                }
                Statement::Simple(s) => s.trim(),
            };
            if statement.is_empty() {
                continue;
            }
            if let Some(successor) = statement.strip_prefix("produce") {
                if self.lpfg.produced.is_some()
                    && !successor.starts_with(|c: char| c.is_ascii_alphanumeric() || c == '_')
                {
                    let successor = self.lpfg_modules(successor, env, n)?;
                    let condition = match self.lpfg.path.len() {
                        0 => None,
                        1 => Some(self.lpfg.path[0].clone()),
                        _ => Some(
                            self.lpfg
                                .path
                                .iter()
                                .map(|c| format!("({c})"))
                                .collect::<Vec<_>>()
                                .join(" && "),
                        ),
                    };
                    if let Some(produced) = &mut self.lpfg.produced {
                        produced.push((condition, successor));
                    }
                    return Ok(true);
                }
            }
            let word: String = statement
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            if ["while", "for", "do"].contains(&word.as_str()) {
                return Err(format!(
                    "the statement '{}' is a loop; Meristem has no statements",
                    one_line(statement)
                ));
            }
            self.simple_statement(statement, env, n)?;
        }
        Ok(false)
    }

    /// `if (condition) then else otherwise`: each variable a branch assigns is bound to
    /// `((condition)?then:else)`, the other branch's value being the one before the `if` (or the
    /// name itself: a parameter or a constant).
    fn if_statement(
        &mut self,
        condition: &str,
        then: &str,
        otherwise: Option<&str>,
        env: &mut Env,
        n: usize,
        depth: usize,
    ) -> Result<bool, String> {
        let c = self
            .expression(condition, env)
            .map_err(|why| format!("the condition of 'if ({})': {why}", one_line(condition)))?;
        let depth_before = self.lpfg.path.len();
        // A value drawn inside a branch stays substituted (see `draws.rs`).
        let draws = self.cpfg.draws.take();
        let result = self.branches(c, then, otherwise, env, n, depth, depth_before);
        self.cpfg.draws = draws;
        result
    }

    /// The two branches of an `if` whose condition is `c` (see [`Importer::if_statement`]).
    #[allow(clippy::too_many_arguments)]
    fn branches(
        &mut self,
        c: String,
        then: &str,
        otherwise: Option<&str>,
        env: &mut Env,
        n: usize,
        depth: usize,
        depth_before: usize,
    ) -> Result<bool, String> {
        let mut yes = env.clone();
        self.lpfg.path.push(c.clone());
        let yes_ends = self.statements(then, &mut yes, n, depth + 1)?;
        self.lpfg.path.truncate(depth_before);
        let mut no = env.clone();
        self.lpfg.path.push(format!("!({c})"));
        let no_ends = match otherwise {
            Some(otherwise) => self.statements(otherwise, &mut no, n, depth + 1)?,
            None => false,
        };
        self.lpfg.path.truncate(depth_before);
        // lpfg: a branch that produced ends the production; what follows runs on the other.
        match (yes_ends, no_ends) {
            (true, true) => return Ok(true),
            (true, false) => {
                self.lpfg.path.push(format!("!({c})"));
                *env = no;
                return Ok(false);
            }
            (false, true) => {
                self.lpfg.path.push(c);
                *env = yes;
                return Ok(false);
            }
            (false, false) => {}
        }
        let mut names: Vec<String> = yes.keys().chain(no.keys()).cloned().collect();
        names.sort();
        names.dedup();
        for name in names {
            let before = env.get(&name).cloned();
            let pick = |side: &Env| {
                side.get(&name)
                    .cloned()
                    .or_else(|| before.clone())
                    .unwrap_or_else(|| name.clone())
            };
            let (a, b) = (pick(&yes), pick(&no));
            if a != b {
                let value = format!("(({c})?{a}:{b})");
                if value.len() > MAX_VALUE {
                    return Err(too_long());
                }
                env.insert(name, value);
            }
        }
        Ok(false)
    }

    /// One statement without braces: an assignment, `x++`, `printf(…)`, `srand(…)` or an
    /// expression that assigns nothing.
    fn simple_statement(&mut self, statement: &str, env: &mut Env, n: usize) -> Result<(), String> {
        // A C declaration with its value (`float length = …`, lpfg): an assignment.
        let statement = ["const ", "float ", "double ", "int "]
            .iter()
            .fold(statement, |s, t| {
                s.strip_prefix(t).map_or(s, str::trim_start)
            });
        let compact: String = statement.chars().filter(|c| !c.is_whitespace()).collect();
        if compact.ends_with("++") || compact.ends_with("--") {
            self.note(n, format!("the statement '{statement}' changes a variable cpfg keeps from module to module; Meristem has no variables: dropped"));
            return Ok(());
        }
        if compact.starts_with("printf(") {
            self.note(n, format!("cpfg's printf prints to the console; it is not translated (the plant is the same): '{}' dropped", one_line(statement)));
            return Ok(());
        }
        if compact.starts_with("srand(") {
            self.note(n, format!("the statement '{statement}' restarts cpfg's random generator when the production is applied; Meristem draws from its own generator, seeded once (#seed), so it is dropped"));
            return Ok(());
        }
        let Some((target, op, value)) = ["+=", "-=", "*=", "/=", "="].iter().find_map(|op| {
            statement
                .split_once(op)
                .map(|(t, v)| (t.trim(), *op, v.trim()))
        }) else {
            // An expression statement (`roll - roll/L0;`): C computes it and throws it away.
            if self.expression(statement, env).is_ok() {
                self.note(n, format!("the statement '{statement}' assigns nothing (it has no effect in cpfg either); dropped"));
                return Ok(());
            }
            return Err(format!("the statement '{statement}' is not an assignment"));
        };
        if !is_identifier(target) || value.starts_with('=') {
            return Err(format!("the statement '{statement}' is not an assignment"));
        }
        if self.cpfg.globals.is_global(target) && !env.contains_key(target) {
            self.note(n, format!("the statement '{statement}' changes cpfg's global variable {target} during the derivation; Meristem has no variables, so it is dropped and {target} keeps its start value"));
            return Ok(());
        }
        let value = self.expression(value, env)?;
        let value = match op {
            "=" => value,
            _ => {
                let old = env
                    .get(target)
                    .cloned()
                    .unwrap_or_else(|| target.to_string());
                format!("{old}{}({value})", &op[..1])
            }
        };
        if value.len() > MAX_VALUE {
            return Err(too_long());
        }
        if let Some(aux) = self.drawn(target, &value) {
            env.insert(target.to_string(), aux);
            return Ok(());
        }
        env.insert(target.to_string(), format!("({value})"));
        Ok(())
    }
}

/// The longest value a statement block may give a variable: each use of a variable copies its
/// value, so `x = x*x;` repeated would double it each time.
pub(in crate::import::abop) const MAX_VALUE: usize = 20_000;

/// A statement of a cpfg block, as [`next_statement`] reads it.
#[derive(Debug, PartialEq)]
enum Statement<'a> {
    /// `{ … }`: the text inside the braces.
    Group(&'a str),
    /// `if (condition) then [else otherwise]`.
    If(&'a str, &'a str, Option<&'a str>),
    /// `while (condition) body` (false), `do body while (condition);` (true: the body runs
    /// once first).
    While(&'a str, &'a str, bool),
    /// Anything else, up to its `;`.
    Simple(&'a str),
}

/// `while (condition) {body}` at the start of `text` (after `while`): the condition, the body
/// and the text after it.
fn while_loop(text: &str) -> Result<(&str, &str, &str), String> {
    let after = text.trim_start();
    if !after.starts_with('(') {
        return Err("'while' without '('".into());
    }
    let close = PARENTHESES_AND_BRACES
        .closing(after, 0)
        .ok_or("a '(' is never closed")?;
    let condition = &after[1..close];
    let rest = after[close + 1..].trim_start();
    if !rest.starts_with('{') {
        return Err("a loop's body must be in braces (cpfg's rule)".into());
    }
    let end = PARENTHESES_AND_BRACES
        .closing(rest, 0)
        .ok_or("a '{' block is never closed")?;
    Ok((condition, &rest[1..end], &rest[end + 1..]))
}

/// Whether `text` starts with the keyword `word` (not a longer name).
fn starts_with_word(text: &str, word: &str) -> bool {
    text.starts_with(word)
        && !text[word.len()..]
            .chars()
            .next()
            .is_some_and(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// The first statement of `text` (which starts with no space) and the text after it.
fn next_statement(text: &str, depth: usize) -> Result<(Statement<'_>, &str), String> {
    if depth > 16 {
        return Err("statements nest more than 16 deep".into());
    }
    if text.starts_with('{') {
        let close = PARENTHESES_AND_BRACES
            .closing(text, 0)
            .ok_or("a '{' block is never closed")?;
        return Ok((Statement::Group(&text[1..close]), &text[close + 1..]));
    }
    if starts_with_word(text, "while") {
        let (condition, body, rest) = while_loop(&text[5..])?;
        return Ok((Statement::While(condition, body, false), rest));
    }
    if starts_with_word(text, "do") {
        let after = text[2..].trim_start();
        if !after.starts_with('{') {
            return Err("a loop's body must be in braces (cpfg's rule)".into());
        }
        let end = PARENTHESES_AND_BRACES
            .closing(after, 0)
            .ok_or("a '{' block is never closed")?;
        let rest = after[end + 1..].trim_start();
        if !starts_with_word(rest, "while") {
            return Err("'do {…}' without 'while'".into());
        }
        let (condition, rest) =
            match PARENTHESES_AND_BRACES.closing(rest, rest.find('(').unwrap_or(0)) {
                Some(close) if rest.find('(').is_some() => {
                    let open = rest.find('(').unwrap_or(0);
                    (&rest[open + 1..close], rest[close + 1..].trim_start())
                }
                _ => return Err("'while' without '('".into()),
            };
        let rest = rest.strip_prefix(';').unwrap_or(rest);
        return Ok((Statement::While(condition, &after[1..end], true), rest));
    }
    if starts_with_word(text, "if") {
        let open = text.find(|c: char| !c.is_whitespace() && c != 'i' && c != 'f');
        let open = open
            .filter(|&o| text[o..].starts_with('('))
            .ok_or("'if' without '('")?;
        let close = PARENTHESES_AND_BRACES
            .closing(text, open)
            .ok_or("a '(' is never closed")?;
        let condition = &text[open + 1..close];
        let after = text[close + 1..].trim_start();
        let (then, rest) = next_statement(after, depth + 1)?;
        let then_text = &after[..after.len() - rest.len()];
        let then_text = match then {
            Statement::Group(inner) => inner,
            _ => then_text,
        };
        let rest = rest.trim_start();
        if starts_with_word(rest, "else") {
            let after = rest[4..].trim_start();
            let (otherwise, rest) = next_statement(after, depth + 1)?;
            let otherwise_text = match otherwise {
                Statement::Group(inner) => inner,
                _ => &after[..after.len() - rest.len()],
            };
            return Ok((
                Statement::If(condition, then_text, Some(otherwise_text)),
                rest,
            ));
        }
        return Ok((Statement::If(condition, then_text, None), rest));
    }
    let end = PARENTHESES_AND_BRACES
        .depths(text)
        .find(|&(_, c, depth)| c == ';' && depth <= 0);
    Ok(match end {
        Some((i, _, _)) => (Statement::Simple(&text[..i]), &text[i + 1..]),
        None => (Statement::Simple(text), ""),
    })
}

/// `text` on one line, its runs of white space one space.
fn one_line(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

fn too_long() -> String {
    format!("the statement block's values grow longer than {MAX_VALUE} characters")
}
