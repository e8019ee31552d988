//! Splitting text into modules: names, parameter lists and control-module groups, and the
//! bracket checks every module string gets.

use super::ast::{ModuleSyntax, Span};
use super::brackets::PARENTHESES;
use super::expr::parse_expression;
use crate::diagnostics::Diagnostic;
use crate::vocabulary::{module_named, Command, GroupKind, Meaning, MODULES};
use std::cell::Cell;

/// Deepest control modules (`@Switch`, `@Pendulum`, `@Repeat`) may be written one inside another
/// (`E0132`): the scanner, and later the derivation, follow a group's members one level at a time.
pub const MAX_GROUP_DEPTH: usize = 64;

/// Most modules one grammar's text may hold, in its axiom, successors and module lists together
/// (`E0145`): the default `#max_modules`, so that any axiom within the default module limit is
/// read. A module costs some 150 bytes in the syntax tree (its name, span and parameter list)
/// before the resolver turns it into 4, so this keeps a text of 40 million `F` from asking for
/// gigabytes before any limit is checked; scanning stops at the module that passes it.
pub const MAX_SCANNED_MODULES: usize = 5_000_000;

/// `E0145`'s words, a constant text (the first plant's core formats no message it can spare; a
/// test checks the number against [`MAX_SCANNED_MODULES`]).
const TOO_MANY_MODULES: &str = "the text holds more than 5000000 modules (axiom, successors and \
     module lists together); the rest is not read. Write a long axiom as a short one and \
     productions that grow it";

/// Reports unbalanced `[` `]` in one module string (axiom or successor).
pub(super) fn check_brackets(modules: &[ModuleSyntax], diagnostics: &mut Vec<Diagnostic>) {
    let mut open: Vec<&Span> = Vec::new();
    for m in modules {
        match branch_bracket(&m.name) {
            Some(Command::Push) => open.push(&m.span),
            Some(_) if open.pop().is_none() => {
                diagnostics.push(Diagnostic::error(
                    "E0108",
                    m.span.clone(),
                    "']' has no matching '['",
                ));
            }
            _ => {}
        }
    }
    for span in open {
        diagnostics.push(Diagnostic::error(
            "E0109",
            span.clone(),
            "'[' is never closed by a ']'",
        ));
    }
}

/// `Push` for the name of `[`, `Pop` for `]`, `None` for any other name.
pub(super) fn branch_bracket(name: &str) -> Option<Command> {
    module_named(name)
        .and_then(|m| m.command())
        .filter(|c| matches!(c, Command::Push | Command::Pop))
}

/// The control module a name stands for, if any.
fn group_kind(name: &str) -> Option<GroupKind> {
    match module_named(name)?.meaning {
        Meaning::Group(kind) => Some(kind),
        _ => None,
    }
}

/// Splits a module string into module names (LANGUAGE.md section 1).
pub(super) struct ModuleScanner<'a> {
    /// `#module` names, longest first.
    declared: &'a [String],
    /// The vocabulary's `@` names, longest first, so that `@GcF` is `@Gc F`.
    at_names: Vec<&'static str>,
    /// How many control modules the text being scanned is inside.
    depth: Cell<usize>,
    /// Modules scanned so far in the whole text ([`MAX_SCANNED_MODULES`]).
    scanned: Cell<usize>,
}

impl<'a> ModuleScanner<'a> {
    pub(super) fn new(declared: &'a [String]) -> Self {
        let mut at_names: Vec<&'static str> = MODULES
            .iter()
            .map(|m| m.name)
            .filter(|n| n.starts_with('@'))
            .collect();
        crate::sort::sort_by_key(&mut at_names, |n| std::cmp::Reverse(n.len()));
        ModuleScanner {
            declared,
            at_names,
            depth: Cell::new(0),
            scanned: Cell::new(0),
        }
    }

    /// True for a name declared with `#module`.
    pub(super) fn is_declared(&self, name: &str) -> bool {
        self.declared.iter().any(|d| d == name)
    }

    /// The modules of `text`, which starts at byte `base` of the file.
    pub(super) fn scan(
        &self,
        text: &str,
        base: usize,
        diagnostics: &mut Vec<Diagnostic>,
    ) -> Vec<ModuleSyntax> {
        let mut modules = Vec::new();
        let mut i = 0;
        while i < text.len() {
            if self.scanned.get().saturating_add(modules.len()) > MAX_SCANNED_MODULES {
                self.too_many(base + i..base + text.len(), diagnostics);
                break;
            }
            let Some(c) = text[i..].chars().next() else {
                break;
            };
            let next = if c.is_whitespace() {
                Some(i + c.len_utf8())
            } else if c == '(' {
                parameter_list(text, i, base, &mut modules, diagnostics)
            } else if c == ')' {
                diagnostics.push(Diagnostic::error(
                    "E0110",
                    base + i..base + i + 1,
                    "')' has no matching '('",
                ));
                Some(i + 1)
            } else {
                self.module(text, i, base, &mut modules, diagnostics)
            };
            match next {
                Some(n) => i = n,
                None => break,
            }
        }
        self.scanned
            .set(self.scanned.get().saturating_add(modules.len()));
        modules
    }

    /// True once [`MAX_SCANNED_MODULES`] was passed (`E0145`): no more modules are read.
    pub(super) fn stopped(&self) -> bool {
        self.scanned.get() == usize::MAX
    }

    /// `E0145` at `span`, the text not read, once per file (the scanner stops reading modules).
    fn too_many(&self, span: Span, diagnostics: &mut Vec<Diagnostic>) {
        if self.scanned.get() == usize::MAX {
            return;
        }
        self.scanned.set(usize::MAX);
        diagnostics.push(Diagnostic::error(
            "E0145",
            span.start..span.end.min(span.start + 1),
            TOO_MANY_MODULES,
        ));
    }

    /// The module whose name starts at `i` (a control module with its members); returns where
    /// scanning goes on, `None` when the rest cannot be read.
    fn module(
        &self,
        text: &str,
        i: usize,
        base: usize,
        modules: &mut Vec<ModuleSyntax>,
        diagnostics: &mut Vec<Diagnostic>,
    ) -> Option<usize> {
        let rest = &text[i..];
        let len = self.name_length(rest);
        let name = &rest[..len];
        let after = &rest[len..];
        let gap = after.len() - after.trim_start().len();
        if group_kind(name).is_none() || !after[gap..].starts_with('(') {
            modules.push(ModuleSyntax {
                name: name.to_string(),
                span: base + i..base + i + len,
                params: Vec::new(),
                group: None,
            });
            return Some(i + len);
        }
        let open = i + len + gap;
        let Some(close) = PARENTHESES.closing(&text[open..], 0) else {
            diagnostics.push(Diagnostic::error(
                "E0116",
                base + open..base + open + 1,
                "'(' is never closed by a ')'",
            ));
            return None;
        };
        let inner = &text[open + 1..open + close];
        let module = self.group(name, inner, base + open + 1, base + i, diagnostics);
        modules.push(ModuleSyntax {
            span: base + i..base + open + close + 1,
            ..module
        });
        Some(open + close + 1)
    }

    /// The inside of a control module's parentheses: `k, modules` for `@Repeat`, members for the
    /// others (each module is a member; a `[…]` branch is one member).
    fn group(
        &self,
        name: &str,
        inner: &str,
        at: usize,
        start: usize,
        diagnostics: &mut Vec<Diagnostic>,
    ) -> ModuleSyntax {
        let repeat = group_kind(name) == Some(GroupKind::Repeat);
        let mut params = Vec::new();
        let mut body = inner;
        let mut body_at = at;
        if repeat {
            match PARENTHESES.find_char(inner, ',') {
                Some(comma) => {
                    match parse_expression(&inner[..comma], at) {
                        Ok(e) => params.push(e),
                        Err(d) => diagnostics.push(d),
                    }
                    body = &inner[comma + 1..];
                    body_at = at + comma + 1;
                }
                None => diagnostics.push(Diagnostic::error(
                    "E0130",
                    at..at + inner.len(),
                    format!("{name} needs a count and the modules to repeat: {name}(k, A B)"),
                )),
            }
        }
        let span = start..at + inner.len() + 1;
        if self.depth.get() >= MAX_GROUP_DEPTH {
            diagnostics.push(Diagnostic::error(
                "E0132",
                start..start + name.len(),
                format!("control modules nested more than {MAX_GROUP_DEPTH} deep"),
            ));
            return ModuleSyntax {
                name: name.to_string(),
                span,
                params,
                group: Some(vec![Vec::new()]),
            };
        }
        self.depth.set(self.depth.get() + 1);
        let modules = self.scan(body, body_at, diagnostics);
        self.depth.set(self.depth.get() - 1);
        check_brackets(&modules, diagnostics);
        let members = if repeat {
            vec![modules]
        } else {
            let mut members: Vec<Vec<ModuleSyntax>> = Vec::new();
            let mut depth = 0usize;
            for m in modules {
                if depth == 0 {
                    members.push(Vec::new());
                }
                match branch_bracket(&m.name) {
                    Some(Command::Push) => depth += 1,
                    Some(_) => depth = depth.saturating_sub(1),
                    None => {}
                }
                if let Some(last) = members.last_mut() {
                    last.push(m);
                }
            }
            members
        };
        if members.iter().all(Vec::is_empty) || members.is_empty() {
            diagnostics.push(Diagnostic::error(
                "E0131",
                span.clone(),
                format!("{name}(…) needs at least one module"),
            ));
        }
        ModuleSyntax {
            name: name.to_string(),
            span,
            params,
            group: Some(members),
        }
    }

    /// Byte length of the module name at the start of `rest` (which is not empty).
    fn name_length(&self, rest: &str) -> usize {
        if let Some(d) = self.declared.iter().find(|d| rest.starts_with(d.as_str())) {
            return d.len();
        }
        let bytes = rest.as_bytes();
        match bytes[0] {
            b'@' => {
                if let Some(known) = self.at_names.iter().find(|n| rest.starts_with(*n)) {
                    return known.len();
                }
                1 + rest[1..]
                    .find(|c: char| !c.is_ascii_alphabetic())
                    .unwrap_or(rest.len() - 1)
            }
            b'?' if bytes.len() > 1 && bytes[1].is_ascii_alphabetic() => 2,
            // cpfg's predefined surfaces: `~l` (leaf), `~p` (petal), one letter each.
            b'~' if bytes.len() > 1 && bytes[1].is_ascii_alphabetic() => 2,
            // A subscript is one letter (`F_a`) or a run of digits (`A_12`).
            c if c.is_ascii_alphabetic()
                && bytes.len() > 2
                && bytes[1] == b'_'
                && bytes[2].is_ascii_alphabetic() =>
            {
                3
            }
            c if c.is_ascii_alphabetic()
                && bytes.len() > 2
                && bytes[1] == b'_'
                && bytes[2].is_ascii_digit() =>
            {
                2 + rest[2..]
                    .find(|c: char| !c.is_ascii_digit())
                    .unwrap_or(rest.len() - 2)
            }
            _ => rest.chars().next().map_or(1, char::len_utf8),
        }
    }
}

/// The parameters of the module just read, in the parentheses at `i` (whitespace before '(' is
/// allowed); returns where scanning goes on, `None` when the parenthesis is never closed.
fn parameter_list(
    text: &str,
    i: usize,
    base: usize,
    modules: &mut [ModuleSyntax],
    diagnostics: &mut Vec<Diagnostic>,
) -> Option<usize> {
    let rest = &text[i..];
    let close = PARENTHESES.closing(rest, 0);
    let Some(last) = modules.last_mut().filter(|m| m.params.is_empty()) else {
        let end = close.map_or(text.len(), |j| i + j + 1);
        diagnostics.push(Diagnostic::error(
            "E0117",
            base + i..base + end,
            "a parameter list '(…)' must follow a module name",
        ));
        return Some(end);
    };
    let Some(close) = close else {
        diagnostics.push(Diagnostic::error(
            "E0116",
            base + i..base + i + 1,
            "'(' is never closed by a ')'",
        ));
        return None;
    };
    let inner = &rest[1..close];
    let pieces = if inner.trim().is_empty() {
        diagnostics.push(Diagnostic::error(
            "E0118",
            base + i..base + i + close + 1,
            "an empty parameter list '()': write the module without parentheses",
        ));
        Vec::new()
    } else {
        PARENTHESES.split(inner, ',')
    };
    for (offset, piece) in pieces {
        let at = base + i + 1 + offset;
        if piece.trim().is_empty() {
            diagnostics.push(Diagnostic::error(
                "E0119",
                at..at + 1,
                "an empty parameter between commas",
            ));
            continue;
        }
        match parse_expression(piece, at) {
            Ok(e) => last.params.push(e),
            Err(d) => diagnostics.push(d),
        }
    }
    last.span.end = base + i + close + 1;
    Some(i + close + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_text_of_more_modules_than_the_limit_stops_at_the_first_over_it() {
        let scanner = ModuleScanner::new(&[]);
        let mut diagnostics = Vec::new();
        let first = scanner.scan(&"F".repeat(MAX_SCANNED_MODULES - 2), 0, &mut diagnostics);
        assert_eq!(first.len(), MAX_SCANNED_MODULES - 2);
        assert!(diagnostics.is_empty());
        // Two more fit; the third module of this line is the first over the limit.
        let text = "A B C D";
        let second = scanner.scan(text, 100, &mut diagnostics);
        assert_eq!(
            second.len(),
            3,
            "scanning stops after the module over the limit"
        );
        assert_eq!(diagnostics.len(), 1);
        assert_eq!(diagnostics[0].code, "E0145");
        let limit = format!("more than {MAX_SCANNED_MODULES} modules");
        assert!(diagnostics[0].message.contains(&limit));
        assert_eq!(diagnostics[0].span, 105..106);
        // Once said, the rest of the text is not read and not reported again.
        assert!(scanner.scan("X Y", 200, &mut diagnostics).is_empty());
        assert_eq!(diagnostics.len(), 1);
    }
}
