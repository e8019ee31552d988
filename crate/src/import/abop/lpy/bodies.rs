//! L-Py production bodies: local assignments put where they are used, `if`/`elif`/`else`
//! branches ending in `produce`, each branch one Meristem production in order.

use super::super::cpfg::cpp;
use super::super::{is_identifier, Env, Importer, Line};
use super::{flags, produce};
use crate::import::abop::cpfg::blocks::MAX_VALUE;

/// The condition of a branch nested in the `if` headers `open` (with its own, if any): the
/// conditions joined by `&&`.
pub(in crate::import::abop) fn nested(
    open: &[(usize, Option<String>)],
    own: Option<String>,
) -> Option<String> {
    let parts: Vec<String> = open
        .iter()
        .filter_map(|(_, c)| c.clone())
        .chain(own)
        .collect();
    match parts.len() {
        0 => None,
        1 => parts.into_iter().next(),
        _ => Some(
            parts
                .iter()
                .map(|c| format!("({c})"))
                .collect::<Vec<_>>()
                .join(" && "),
        ),
    }
}

/// The local assignments that open an L-Py body, before its first `if` or `produce`
/// (`p1 = min(1,(2*k+1)/k**2)`, `a += 0.1`), taken from `lines`: their names and values, which
/// are put where the names are used, as cpfg's statement blocks are. An `if`/`elif`/`else` whose
/// branches only assign (`if x == 1:` / `auxin = max_level` / `else:` / `auxin = min_level`)
/// gives each name it assigns a conditional value, `((c)?(a):(b))`. A random draw used in more
/// than one place stays (it would be drawn again in each), and the body is then skipped with its
/// note.
pub(in crate::import::abop) fn python_locals(lines: &mut Vec<&Line>) -> (Vec<String>, Vec<String>) {
    let mut names: Vec<String> = Vec::new();
    let mut values: Vec<String> = Vec::new();
    while let Some(line) = lines.first() {
        if let Some((taken, assigned)) = python_if_assignments(lines, &names, &values) {
            // Each use copies a value: a value that grows too long is not taken (see MAX_VALUE).
            if assigned.iter().any(|(_, v)| v.len() > MAX_VALUE) {
                break;
            }
            for (name, value) in assigned {
                bind(&mut names, &mut values, name, value);
            }
            lines.drain(..taken);
            continue;
        }
        let Some((name, value)) = python_local(&line.code) else {
            break;
        };
        let value = format!("({})", cpp::substitute(&value, &names, &values));
        let rest: String = lines[1..].iter().map(|l| format!("{}\n", l.code)).collect();
        let uses = rest.match_indices(&name).filter(|(i, _)| {
            let before = rest[..*i].chars().next_back();
            let after = rest[i + name.len()..].chars().next();
            !before.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_')
                && !after.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_')
        });
        let random = ["random", "uniform", "gauss", "randint", "normal"]
            .iter()
            .any(|r| value.contains(r));
        if random && uses.count() > 1 || value.len() > MAX_VALUE {
            // Put in each place it is used, a random draw would be drawn again each time.
            break;
        }
        bind(&mut names, &mut values, name, value);
        lines.remove(0);
    }
    (names, values)
}

/// Binds `name` to `value` (already in terms of the earlier names): a name bound again takes
/// the new value in its place.
pub(in crate::import::abop) fn bind(
    names: &mut Vec<String>,
    values: &mut Vec<String>,
    name: String,
    value: String,
) {
    match names.iter().position(|n| *n == name) {
        Some(k) => values[k] = value,
        None => {
            names.push(name);
            values.push(value);
        }
    }
}

/// A branch of an L-Py `if`: its condition (`None` for else) and what it assigns.
pub(in crate::import::abop) type Branch = (Option<String>, Vec<(String, String)>);

/// An `if c:` at `lines[0]` followed by `elif c:`/`else:` at the same indentation, whose
/// branches hold only local assignments: how many lines it takes, and each name it assigns with
/// its conditional value (the value before the `if`, or the name itself, where a branch does not
/// assign it). `None` when `lines[0]` opens no such `if`.
pub(in crate::import::abop) fn python_if_assignments(
    lines: &[&Line],
    names: &[String],
    values: &[String],
) -> Option<(usize, Vec<(String, String)>)> {
    let head = lines.first()?;
    let indent = head.indent;
    let mut branches: Vec<Branch> = Vec::new();
    let mut k = 0;
    while let Some(line) = lines.get(k) {
        let code = line.code.as_str();
        let condition = if k == 0 {
            ["if ", "if("]
                .iter()
                .any(|p| code.starts_with(p))
                .then(|| &code[2..])?
        } else if line.indent == indent
            && ["elif ", "elif(", "else"]
                .iter()
                .any(|p| code.starts_with(p))
        {
            // `elif c:` and `else:` alike: four letters, then the condition (none for else).
            &code[4..]
        } else {
            break;
        };
        let condition = condition.trim().strip_suffix(':')?.trim();
        if branches.last().is_some_and(|(c, _)| c.is_none()) {
            break;
        }
        let mut assigned = Vec::new();
        k += 1;
        while let Some(inner) = lines.get(k).filter(|l| l.indent > indent) {
            let (name, value) = python_local(&inner.code)?;
            let earlier: Vec<String> = assigned
                .iter()
                .map(|(n, _): &(String, String)| n.clone())
                .collect();
            let earlier_values: Vec<String> = assigned.iter().map(|(_, v)| v.clone()).collect();
            let value = cpp::substitute(
                &cpp::substitute(&value, &earlier, &earlier_values),
                names,
                values,
            );
            assigned.push((name, format!("({value})")));
            k += 1;
        }
        if assigned.is_empty() {
            return None;
        }
        let condition = (!condition.is_empty())
            .then(|| format!("({})", cpp::substitute(condition, names, values)));
        branches.push((condition, assigned));
    }
    Some((k, conditional_values(&branches, names, values)))
}

/// Each name the branches of an `if` assign, with its conditional value: `((c)?(own):(rest))`,
/// a branch that does not assign it taking the value before the `if` (or the name itself).
pub(in crate::import::abop) fn conditional_values(
    branches: &[Branch],
    names: &[String],
    values: &[String],
) -> Vec<(String, String)> {
    let mut all: Vec<String> = branches
        .iter()
        .flat_map(|(_, a)| a.iter().map(|(n, _)| n.clone()))
        .collect();
    all.sort();
    all.dedup();
    all.into_iter()
        .map(|name| {
            let before = names
                .iter()
                .position(|n| *n == name)
                .map_or_else(|| name.clone(), |k| values[k].clone());
            let mut value = before.clone();
            for (condition, assigned) in branches.iter().rev() {
                let own = assigned
                    .iter()
                    .rev()
                    .find(|(n, _)| *n == name)
                    .map_or_else(|| before.clone(), |(_, v)| v.clone());
                value = match condition {
                    Some(c) => format!("({c}?{own}:{value})"),
                    None => own,
                };
            }
            (name, value)
        })
        .collect()
}

/// A Python local assignment `name = value` or `name += value` (and `-=`, `*=`, `/=`; not `==`):
/// the name and the value (`name + (value)` for `+=`).
pub(in crate::import::abop) fn python_local(code: &str) -> Option<(String, String)> {
    let (name, value) = code.split_once('=')?;
    let value = value.trim();
    let (name, op) = match name.trim_end().strip_suffix(['+', '-', '*', '/']) {
        Some(n) => (n.trim(), name.trim_end().chars().last()),
        None => (name.trim(), None),
    };
    if !is_identifier(name)
        || value.is_empty()
        || value.starts_with('=')
        || ["global", "produce", "nproduce", "return"].contains(&name)
    {
        return None;
    }
    Some(match op {
        Some(op) => (name.to_string(), format!("{name} {op} ({value})")),
        None => (name.to_string(), value.to_string()),
    })
}

/// `text` (a successor) with each name replaced by its value inside parentheses (the modules'
/// parameters), never in the module names themselves.
pub(in crate::import::abop) fn in_parentheses(
    text: &str,
    names: &[String],
    values: &[String],
) -> String {
    if names.is_empty() {
        return text.to_string();
    }
    let mut out = String::new();
    let mut depth = 0usize;
    let mut inside = String::new();
    for c in text.chars() {
        match c {
            '(' => {
                if depth == 0 {
                    out.push('(');
                } else {
                    inside.push('(');
                }
                depth += 1;
            }
            ')' if depth > 0 => {
                depth -= 1;
                if depth == 0 {
                    out.push_str(&cpp::substitute(&inside, names, values));
                    inside.clear();
                    out.push(')');
                } else {
                    inside.push(')');
                }
            }
            _ if depth > 0 => inside.push(c),
            _ => out.push(c),
        }
    }
    out.push_str(&inside);
    out
}

impl Importer {
    /// The condition of an `if c`/`elif c` header with the body's locals put in (`None` for
    /// `else`); a condition that cannot be translated is noted (the production is skipped).
    pub(in crate::import::abop) fn python_condition(
        &mut self,
        head: &str,
        names: &[String],
        values: &[String],
        n: usize,
    ) -> Result<Option<String>, ()> {
        if head.trim() == "else" {
            return Ok(None);
        }
        // `if(z == 1)` as well as `if z == 1`.
        let c = head
            .trim_start_matches("elif")
            .trim_start_matches("if")
            .trim();
        let c = cpp::substitute(c, names, values);
        // Checked here, translated with the production (translating it twice would read the
        // `^` that Python's `**` becomes as Python's bitwise or).
        match self.expression(&c, &Env::new()) {
            Ok(_) => Ok(Some(c)),
            Err(why) => {
                self.note(
                    n,
                    format!("the condition {c}: {why}; the production is skipped"),
                );
                Err(())
            }
        }
    }

    /// L-Py: a production with a Python body of `if`/`elif`/`else` and `produce`.
    pub(in crate::import::abop) fn python_production(
        &mut self,
        pattern: &str,
        body: &[Line],
        n: usize,
    ) {
        let mut branches: Vec<(Option<String>, String, usize)> = Vec::new();
        // The `if`/`elif`/`else:` headers the current line is nested in: their indentation and
        // condition (`None` for `else`, which the order of the productions already says).
        let mut open: Vec<(usize, Option<String>)> = Vec::new();
        let marked = self.lpy.flags_written.len();
        let owned = self.body_lines(body);
        let mut lines: Vec<&Line> = owned.iter().collect();
        let (names, values) = python_locals(&mut lines);
        let local = |text: &str| in_parentheses(text, &names, &values);
        for line in lines {
            while open
                .last()
                .is_some_and(|(indent, _)| *indent >= line.indent)
            {
                open.pop();
            }
            let code = &local(&line.code);
            let code = code.as_str();
            let (head, tail) = match code.find(':') {
                Some(i)
                    if ["if ", "if(", "elif ", "elif("]
                        .iter()
                        .any(|k| code.starts_with(k))
                        || code.starts_with("else") =>
                {
                    (&code[..i], code[i + 1..].trim())
                }
                _ => ("", code),
            };
            // The statement that must be a `produce`, the condition of its own header if it
            // has one, and what the note says when it is not.
            let (condition, statement, hint) = if head.is_empty() {
                (
                    None,
                    code,
                    " (Meristem imports bodies made of if, elif, else and produce)",
                )
            } else {
                let Ok(condition) = self.python_condition(head, &names, &values, line.n) else {
                    return;
                };
                if tail.is_empty() {
                    open.push((line.indent, condition));
                    continue;
                }
                (condition, tail, "")
            };
            match produce(statement) {
                Some(s) => branches.push((nested(&open, condition), s.to_string(), line.n)),
                None => {
                    self.note(line.n, format!("the Python code '{statement}' is not translated{hint}; the production is skipped"));
                    return;
                }
            }
        }
        if branches.is_empty() {
            self.note(n, "a Python production that produces nothing; skipped");
            return;
        }
        for (condition, successor, line) in branches {
            let successor = if successor.trim().is_empty() {
                "*".to_string()
            } else {
                successor
            };
            let text = match condition {
                Some(c) => format!("{pattern} : {c} --> {successor}"),
                None => format!("{pattern} --> {successor}"),
            };
            self.production(&text, line);
        }
        // The probe's markers count the steps since they were written.
        for &k in &self.lpy.flags_written[marked..] {
            let m = flags::marker(k);
            self.out.line(format!("{m}(c) -> {m}(c+1)"), n);
        }
    }
}
