//! The line-oriented parser. Each line is a directive, an axiom, or a production; a line that
//! cannot be read yields a diagnostic and parsing resumes at the next line.

use super::ast::{
    Directive, ModuleSyntax, ProductionSyntax, Section, SourceFile, Span, GROUP_MODULES,
};
use super::comments::blank_comments;
use super::expr::{parse_expression, split_arguments};
use crate::diagnostics::Diagnostic;

/// `@` names of LANGUAGE.md sections 6 and 7, matched longest first so that `@GcF` is `@Gc F`.
const AT_NAMES: &[&str] = &[
    "@Pendulum",
    "@Repeat",
    "@Switch",
    "@Prune",
    "@Gc",
    "@Ge",
    "@Tp",
    "@Ts",
    "@M",
    "@O",
    "@v",
];

/// Parses a grammar. Always returns a (possibly partial) [`SourceFile`] and every diagnostic found.
pub fn parse(source: &str) -> (SourceFile, Vec<Diagnostic>) {
    let (text, mut diagnostics) = blank_comments(source);
    let mut file = SourceFile::default();
    let lines = split_lines(&text);

    // `#module` declarations change how every line is split into modules, so read them first.
    let mut declared: Vec<String> = Vec::new();
    for &(_, line) in &lines {
        if let Some(rest) = line.trim_start().strip_prefix("#module") {
            if rest.is_empty() || rest.starts_with(char::is_whitespace) {
                declared.extend(rest.split_whitespace().map(str::to_string));
            }
        }
    }
    declared.sort_by_key(|name| std::cmp::Reverse(name.len()));
    let scanner = ModuleScanner {
        declared: &declared,
    };

    let mut section = Section::Productions;
    for (start, line) in lines {
        let lead = line.len() - line.trim_start().len();
        let content = line.trim();
        if content.is_empty() {
            continue;
        }
        let at = start + lead;
        let span = at..at + content.len();
        if let Some(after_hash) = content.strip_prefix('#') {
            parse_directive(after_hash, at, &scanner, &mut file, &mut diagnostics);
        } else if let Some((keyword, rest_at)) = keyword(content) {
            let rest = &content[rest_at..];
            let rest_start = at + rest_at;
            match keyword {
                Keyword::Axiom => {
                    let modules = scanner.scan(rest, rest_start, &mut diagnostics);
                    check_brackets(&modules, &mut diagnostics);
                    if let Some((_, previous)) = &file.axiom {
                        diagnostics.push(Diagnostic::warning(
                            "E0104",
                            span.clone(),
                            format!(
                                "a second axiom replaces the one at byte {}; a grammar has one axiom",
                                previous.start
                            ),
                        ));
                    }
                    file.axiom = Some((modules, span));
                }
                Keyword::DerivationLength | Keyword::MaximumDepth => {
                    let name = match (keyword, section) {
                        (Keyword::DerivationLength, _) => "iterations",
                        (_, Section::Decomposition) => "decomposition_depth",
                        (_, Section::Homomorphism) => "homomorphism_depth",
                        (_, Section::Productions) => {
                            diagnostics.push(Diagnostic::error(
                                "E0111",
                                at..rest_start,
                                "'maximum depth:' belongs after 'homomorphism:' or 'decomposition:'",
                            ));
                            continue;
                        }
                    };
                    let trimmed = rest.trim();
                    let args_at = rest_start + (rest.len() - rest.trim_start().len());
                    file.directives.push(Directive {
                        name: name.into(),
                        written: content[..rest_start - at].trim().to_string(),
                        name_span: at..rest_start,
                        args: trimmed.to_string(),
                        args_span: args_at..args_at + trimmed.len(),
                        target: None,
                        expr: None,
                        modules: Vec::new(),
                    });
                }
                Keyword::Section(new_section) => {
                    section = new_section;
                    if !rest.trim().is_empty() {
                        diagnostics.push(Diagnostic::error(
                            "E0112",
                            rest_start..at + content.len(),
                            "a section keyword stands alone on its line",
                        ));
                    }
                }
            }
        } else if content.eq_ignore_ascii_case("endlsystem") {
            section = Section::Productions;
        } else if let Some(p) = parse_production(content, at, section, &scanner, &mut diagnostics) {
            file.productions.push(p);
        }
    }
    (file, diagnostics)
}

/// Lines with the byte offset at which each starts (`\r\n` endings are handled by `trim`).
fn split_lines(text: &str) -> Vec<(usize, &str)> {
    let mut lines = Vec::new();
    let mut start = 0;
    for line in text.split('\n') {
        lines.push((start, line));
        start += line.len() + 1;
    }
    lines
}

#[derive(Clone, Copy)]
enum Keyword {
    Axiom,
    DerivationLength,
    MaximumDepth,
    Section(Section),
}

/// Recognises `axiom:`, `ω:`, `derivation length:` and the section keywords; returns the keyword
/// and the byte offset just after its colon.
fn keyword(content: &str) -> Option<(Keyword, usize)> {
    let colon = content.find(':')?;
    let word = content[..colon].trim().to_ascii_lowercase();
    let kw = match word.as_str() {
        "axiom" | "ω" => Keyword::Axiom,
        "derivation length" => Keyword::DerivationLength,
        "homomorphism" => Keyword::Section(Section::Homomorphism),
        "decomposition" => Keyword::Section(Section::Decomposition),
        "productions" => Keyword::Section(Section::Productions),
        "maximum depth" => Keyword::MaximumDepth,
        _ => return None,
    };
    Some((kw, colon + 1))
}

fn parse_directive(
    after_hash: &str,
    at: usize,
    scanner: &ModuleScanner,
    file: &mut SourceFile,
    diagnostics: &mut Vec<Diagnostic>,
) {
    let name_len = after_hash
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(after_hash.len());
    if name_len == 0 {
        diagnostics.push(Diagnostic::error(
            "E0103",
            at..at + 1,
            "expected a directive name after '#'",
        ));
        return;
    }
    let name = &after_hash[..name_len];
    let rest = &after_hash[name_len..];
    let args = rest.trim();
    let args_at = at + 1 + name_len + (rest.len() - rest.trim_start().len());
    let mut directive = Directive {
        name: name.to_string(),
        written: format!("#{name}"),
        name_span: at..at + 1 + name_len,
        args: args.to_string(),
        args_span: args_at..args_at + args.len(),
        target: None,
        expr: None,
        modules: Vec::new(),
    };
    match name {
        "define" | "random" => {
            // `#define NAME expr`, `#random NAME = expr` (the '=' is optional for both).
            let ident_len = args
                .find(|c: char| !(c.is_alphanumeric() || c == '_'))
                .unwrap_or(args.len());
            if ident_len == 0 || args.starts_with(|c: char| c.is_ascii_digit()) {
                diagnostics.push(Diagnostic::error(
                    "E0113",
                    directive.name_span.clone(),
                    format!("#{name} needs a name, then an expression"),
                ));
                return;
            }
            directive.target = Some((args[..ident_len].to_string(), args_at..args_at + ident_len));
            let mut expr_text = &args[ident_len..];
            let mut expr_at = args_at + ident_len;
            let trimmed = expr_text.trim_start();
            expr_at += expr_text.len() - trimmed.len();
            expr_text = trimmed;
            if let Some(after_eq) = expr_text.strip_prefix('=') {
                expr_at += 1;
                expr_text = after_eq;
            }
            if expr_text.trim().is_empty() {
                diagnostics.push(Diagnostic::error(
                    "E0113",
                    directive.args_span.clone(),
                    format!("#{name} {} needs an expression", &args[..ident_len]),
                ));
                return;
            }
            match parse_expression(expr_text, expr_at) {
                Ok(e) => directive.expr = Some(e),
                Err(d) => {
                    diagnostics.push(d);
                    return;
                }
            }
        }
        "ignore" | "consider" | "draw" | "module" | "apex" => {
            if args.is_empty() {
                diagnostics.push(Diagnostic::error(
                    "E0133",
                    directive.name_span.clone(),
                    format!("#{name} lists no modules"),
                ));
                return;
            }
            if name == "module" {
                for (offset, word) in args
                    .split_whitespace()
                    .map(|w| (w.as_ptr() as usize - args.as_ptr() as usize, w))
                {
                    if !word.starts_with(|c: char| c.is_alphabetic())
                        || !word.chars().all(|c| c.is_alphanumeric() || c == '_')
                    {
                        let at = args_at + offset;
                        diagnostics.push(Diagnostic::error(
                            "E0134",
                            at..at + word.len(),
                            format!("'{word}' cannot be a module name: names are a letter followed by letters, digits or '_'"),
                        ));
                    }
                }
            } else {
                directive.modules = scanner.scan(args, args_at, diagnostics);
                if let Some(m) = directive
                    .modules
                    .iter()
                    .find(|m| !m.params.is_empty() || m.group.is_some())
                {
                    diagnostics.push(Diagnostic::error(
                        "E0135",
                        m.span.clone(),
                        format!("#{name} lists module names, without parameters"),
                    ));
                }
            }
        }
        _ => {}
    }
    file.directives.push(directive);
}

/// Finds the production arrow: `->`, `-->` or `→`. Returns (start, end) byte offsets in `content`.
fn find_arrow(content: &str) -> Option<(usize, usize)> {
    let ascii = content.find("->");
    let unicode = content.find('→');
    match (ascii, unicode) {
        (Some(a), Some(u)) if u < a => Some((u, u + '→'.len_utf8())),
        (Some(a), _) => {
            // `X --> Y` is one arrow, but in `- -> +` or `-->+` the first '-' is the predecessor.
            if a > 0 && content.as_bytes()[a - 1] == b'-' && !content[..a - 1].trim().is_empty() {
                Some((a - 1, a + 2))
            } else {
                Some((a, a + 2))
            }
        }
        (None, Some(u)) => Some((u, u + '→'.len_utf8())),
        (None, None) => None,
    }
}

/// Finds the first occurrence of `token` outside parentheses.
fn find_top_level(text: &str, token: char) -> Option<usize> {
    let mut depth = 0i32;
    for (i, c) in text.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            c if c == token && depth == 0 => return Some(i),
            _ => {}
        }
    }
    None
}

/// Scans one context (`*` alone means no context).
fn scan_context(
    text: &str,
    at: usize,
    scanner: &ModuleScanner,
    diagnostics: &mut Vec<Diagnostic>,
) -> Vec<ModuleSyntax> {
    if text.trim() == "*" {
        return Vec::new();
    }
    scanner.scan(text, at, diagnostics)
}

fn parse_production(
    content: &str,
    at: usize,
    section: Section,
    scanner: &ModuleScanner,
    diagnostics: &mut Vec<Diagnostic>,
) -> Option<ProductionSyntax> {
    let span = at..at + content.len();
    let Some((arrow_start, arrow_end)) = find_arrow(content) else {
        diagnostics.push(Diagnostic::error(
            "E0105",
            span,
            "expected a production 'predecessor -> successor', a directive '#…' or 'axiom: …'",
        ));
        return None;
    };
    let mut lhs = &content[..arrow_start];
    let mut lhs_at = at;
    let mut label = None;

    // A label is an identifier of two or more characters before a ':' (`p1: X -> …`).
    if let Some(colon) = lhs.find(':') {
        let candidate = lhs[..colon].trim();
        let is_ident = candidate.len() >= 2
            && candidate
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '_')
            && candidate.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
            && !scanner.declared.iter().any(|d| d == candidate);
        if is_ident {
            label = Some(candidate.to_string());
            lhs_at += colon + 1;
            lhs = &lhs[colon + 1..];
        }
    }
    let errors_before = diagnostics.len();

    // The condition: after the first ':' outside parentheses.
    let mut condition = None;
    if let Some(colon) = find_top_level(lhs, ':') {
        let text = &lhs[colon + 1..];
        if text.trim().is_empty() {
            diagnostics.push(Diagnostic::error(
                "E0114",
                lhs_at + colon..lhs_at + colon + 1,
                "expected a condition after ':'",
            ));
        } else {
            match parse_expression(text, lhs_at + colon + 1) {
                Ok(e) => condition = Some(e),
                Err(d) => diagnostics.push(d),
            }
        }
        lhs = &lhs[..colon];
    }

    // Contexts: `left < predecessor > right`.
    let mut left = Vec::new();
    let mut right = Vec::new();
    let mut pred_text = lhs;
    let mut pred_at = lhs_at;
    if let Some(lt) = find_top_level(pred_text, '<') {
        left = scan_context(&pred_text[..lt], pred_at, scanner, diagnostics);
        pred_at += lt + 1;
        pred_text = &pred_text[lt + 1..];
    }
    if let Some(gt) = find_top_level(pred_text, '>') {
        right = scan_context(&pred_text[gt + 1..], pred_at + gt + 1, scanner, diagnostics);
        pred_text = &pred_text[..gt];
    }
    for m in &left {
        if m.name == "[" || m.name == "]" {
            diagnostics.push(Diagnostic::error(
                "E0115",
                m.span.clone(),
                "a left context cannot hold brackets",
            ));
        }
    }
    check_brackets(&right, diagnostics);
    let predecessor = scanner.scan(pred_text, pred_at, diagnostics);
    let predecessor = match predecessor.len() {
        1 => predecessor.into_iter().next()?,
        0 => {
            diagnostics.push(Diagnostic::error(
                "E0106",
                span.start..at + arrow_end,
                "a production needs a predecessor module before the arrow",
            ));
            return None;
        }
        n => {
            diagnostics.push(Diagnostic::error(
                "E0107",
                pred_at..pred_at + pred_text.len(),
                format!("the predecessor must be a single module; found {n}"),
            ));
            return None;
        }
    };

    let rhs = &content[arrow_end..];
    let mut rhs_at = at + arrow_end;
    if let Some((second, end)) = find_arrow(rhs) {
        diagnostics.push(Diagnostic::error(
            "E0136",
            rhs_at + second..rhs_at + end,
            "a second arrow: a production has one predecessor and one successor",
        ));
        return None;
    }
    let mut trimmed = rhs.trim();
    rhs_at += rhs.len() - rhs.trim_start().len();
    // A weight: a parenthesised expression right after the arrow.
    let mut weight = None;
    if trimmed.starts_with('(') {
        match matching_paren(trimmed) {
            Some(close) => {
                match parse_expression(&trimmed[1..close], rhs_at + 1) {
                    Ok(e) => weight = Some(e),
                    Err(d) => diagnostics.push(d),
                }
                let after = &trimmed[close + 1..];
                rhs_at += close + 1 + (after.len() - after.trim_start().len());
                trimmed = after.trim();
            }
            None => {
                diagnostics.push(Diagnostic::error(
                    "E0116",
                    rhs_at..rhs_at + 1,
                    "'(' is never closed by a ')'",
                ));
                return None;
            }
        }
    }
    let successor = if trimmed.is_empty() || trimmed == "ε" || trimmed == "*" {
        Vec::new()
    } else {
        let modules = scanner.scan(trimmed, rhs_at, diagnostics);
        check_brackets(&modules, diagnostics);
        modules
    };
    // A line with an error yields no production: half a production would only cause more
    // (misleading) diagnostics later.
    if diagnostics[errors_before..]
        .iter()
        .any(|d| d.severity == crate::diagnostics::Severity::Error)
    {
        return None;
    }
    Some(ProductionSyntax {
        label,
        section,
        left,
        predecessor,
        right,
        condition,
        weight,
        successor,
        span,
    })
}

/// Byte index of the ')' that closes the '(' at the start of `text`.
fn matching_paren(text: &str) -> Option<usize> {
    let mut depth = 0i32;
    for (i, c) in text.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i);
                }
            }
            _ => {}
        }
    }
    None
}

/// Reports unbalanced `[` `]` in one module string (axiom or successor).
fn check_brackets(modules: &[ModuleSyntax], diagnostics: &mut Vec<Diagnostic>) {
    let mut open: Vec<&Span> = Vec::new();
    for m in modules {
        match m.name.as_str() {
            "[" => open.push(&m.span),
            "]" if open.pop().is_none() => {
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

/// Splits a module string into module names (LANGUAGE.md section 1).
struct ModuleScanner<'a> {
    /// `#module` names, longest first.
    declared: &'a [String],
}

impl ModuleScanner<'_> {
    fn scan(
        &self,
        text: &str,
        base: usize,
        diagnostics: &mut Vec<Diagnostic>,
    ) -> Vec<ModuleSyntax> {
        let mut modules = Vec::new();
        let mut i = 0;
        while i < text.len() {
            let rest = &text[i..];
            let Some(c) = rest.chars().next() else { break };
            if c.is_whitespace() {
                i += c.len_utf8();
                continue;
            }
            if c == '(' {
                // Parameters of the module just read (whitespace before '(' is allowed).
                let close = matching_paren(rest);
                let Some(last) = modules
                    .last_mut()
                    .filter(|m: &&mut ModuleSyntax| m.params.is_empty())
                else {
                    let end = close.map_or(text.len(), |j| i + j + 1);
                    diagnostics.push(Diagnostic::error(
                        "E0117",
                        base + i..base + end,
                        "a parameter list '(…)' must follow a module name",
                    ));
                    i = end;
                    continue;
                };
                let Some(close) = close else {
                    diagnostics.push(Diagnostic::error(
                        "E0116",
                        base + i..base + i + 1,
                        "'(' is never closed by a ')'",
                    ));
                    return modules;
                };
                let inner = &rest[1..close];
                if inner.trim().is_empty() {
                    diagnostics.push(Diagnostic::error(
                        "E0118",
                        base + i..base + i + close + 1,
                        "an empty parameter list '()': write the module without parentheses",
                    ));
                } else {
                    for (offset, piece) in split_arguments(inner) {
                        if piece.trim().is_empty() {
                            let at = base + i + 1 + offset;
                            diagnostics.push(Diagnostic::error(
                                "E0119",
                                at..at + 1,
                                "an empty parameter between commas",
                            ));
                            continue;
                        }
                        match parse_expression(piece, base + i + 1 + offset) {
                            Ok(e) => last.params.push(e),
                            Err(d) => diagnostics.push(d),
                        }
                    }
                }
                last.span.end = base + i + close + 1;
                i += close + 1;
                continue;
            }
            if c == ')' {
                diagnostics.push(Diagnostic::error(
                    "E0110",
                    base + i..base + i + 1,
                    "')' has no matching '('",
                ));
                i += 1;
                continue;
            }
            let len = self.name_length(rest);
            let name = &rest[..len];
            let after = &rest[len..];
            let gap = after.len() - after.trim_start().len();
            if GROUP_MODULES.contains(&name) && after[gap..].starts_with('(') {
                let open = i + len + gap;
                let Some(close) = matching_paren(&text[open..]) else {
                    diagnostics.push(Diagnostic::error(
                        "E0116",
                        base + open..base + open + 1,
                        "'(' is never closed by a ')'",
                    ));
                    return modules;
                };
                let module = self.group(
                    name,
                    &text[open + 1..open + close],
                    base + open + 1,
                    base + i,
                    diagnostics,
                );
                modules.push(ModuleSyntax {
                    span: base + i..base + open + close + 1,
                    ..module
                });
                i = open + close + 1;
                continue;
            }
            modules.push(ModuleSyntax {
                name: name.to_string(),
                span: base + i..base + i + len,
                params: Vec::new(),
                group: None,
            });
            i += len;
        }
        modules
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
        let mut params = Vec::new();
        let mut body = inner;
        let mut body_at = at;
        if name == "@Repeat" {
            match find_top_level(inner, ',') {
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
                    "@Repeat needs a count and the modules to repeat: @Repeat(k, A B)",
                )),
            }
        }
        let modules = self.scan(body, body_at, diagnostics);
        check_brackets(&modules, diagnostics);
        let members = if name == "@Repeat" {
            vec![modules]
        } else {
            let mut members: Vec<Vec<ModuleSyntax>> = Vec::new();
            let mut depth = 0usize;
            for m in modules {
                if depth == 0 {
                    members.push(Vec::new());
                }
                match m.name.as_str() {
                    "[" => depth += 1,
                    "]" => depth = depth.saturating_sub(1),
                    _ => {}
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
                start..at + inner.len() + 1,
                format!("{name}(…) needs at least one module"),
            ));
        }
        ModuleSyntax {
            name: name.to_string(),
            span: start..at + inner.len() + 1,
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
                if let Some(known) = AT_NAMES.iter().find(|n| rest.starts_with(*n)) {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn names(src: &str) -> Vec<String> {
        let (file, diags) = parse(&format!("axiom: {src}"));
        assert!(diags.is_empty(), "{diags:?}");
        file.axiom
            .map(|(m, _)| m.into_iter().map(|m| m.name).collect())
            .unwrap_or_default()
    }

    #[test]
    fn module_names_follow_the_lexical_rules() {
        assert_eq!(names("F [ +F ] F"), ["F", "[", "+", "F", "]", "F"]);
        assert_eq!(names("F_aF_lA_1A_12B"), ["F_a", "F_l", "A_1", "A_12", "B"]);
        assert_eq!(
            names("@GcF@Ge?PX01"),
            ["@Gc", "F", "@Ge", "?P", "X", "0", "1"]
        );
        assert_eq!(names("F_ X"), ["F", "_", "X"]);
    }

    #[test]
    fn declared_multi_letter_modules_are_one_module() {
        let (file, diags) = parse("#module Apex Leaf\naxiom: ApexFFLeaf");
        assert!(diags.is_empty());
        let names: Vec<_> = file.axiom.unwrap().0.into_iter().map(|m| m.name).collect();
        assert_eq!(names, ["Apex", "F", "F", "Leaf"]);
    }

    #[test]
    fn productions_accept_labels_every_arrow_and_empty_successors() {
        let (file, diags) = parse("p1: X -> F[+X]\nF --> FF\nA → B\n- -> +\nB -> ε\nC ->\nD -> *");
        assert!(diags.is_empty(), "{diags:?}");
        let p: Vec<_> = file
            .productions
            .iter()
            .map(|p| {
                (
                    p.label.clone(),
                    p.predecessor.name.clone(),
                    p.successor.len(),
                )
            })
            .collect();
        assert_eq!(
            p,
            [
                (Some("p1".into()), "X".into(), 5),
                (None, "F".into(), 2),
                (None, "A".into(), 1),
                (None, "-".into(), 1),
                (None, "B".into(), 0),
                (None, "C".into(), 0),
                (None, "D".into(), 0),
            ]
        );
    }

    #[test]
    fn a_bad_line_does_not_stop_the_parser() {
        let (file, diags) = parse("axiom: X\nX F\nX -> F[\nF -> FF\n");
        assert_eq!(
            file.productions.len(),
            1,
            "the line with an error yields no production"
        );
        assert_eq!(
            diags.iter().map(|d| d.code).collect::<Vec<_>>(),
            ["E0105", "E0109"]
        );
    }
}
