//! The line-oriented parser. Each line is a directive, a keyword line (the axiom, a section), or a
//! production; a line that cannot be read yields a diagnostic and parsing resumes at the next line.

use super::ast::{Directive, Section, SourceFile, Span};
use super::comments::blank_comments;
use super::directive::parse_directive;
use super::production::parse_production;
use super::scanner::{check_brackets, ModuleScanner};
use crate::diagnostics::Diagnostic;
use crate::vocabulary::{keyword_named, DirectiveKind, KeywordKind};

/// Parses a grammar. Always returns a (possibly partial) [`SourceFile`] and every diagnostic found.
pub fn parse(source: &str) -> (SourceFile, Vec<Diagnostic>) {
    let (text, diagnostics) = blank_comments(source);
    let lines = split_lines(&text);
    let declared = declared_modules(&lines);
    let mut parser = Parser {
        file: SourceFile {
            line_starts: crate::diagnostics::line_starts(&text),
            ..SourceFile::default()
        },
        diagnostics,
        scanner: ModuleScanner::new(&declared),
        section: Section::Productions,
    };
    for (start, line) in lines {
        // Past `E0145` the rest is not read, as it says: each production after it gave `E0106`
        // (no predecessor: its modules were not scanned), 1.3 million errors for a 24 MB text.
        if parser.scanner.stopped() {
            break;
        }
        parser.line(start, line);
    }
    (parser.file, parser.diagnostics)
}

/// Lines with the byte offset at which each starts. A line ends at `\n`, `\r\n` or a lone `\r`
/// (old Mac files): splitting at both characters makes `\r\n` an empty line more, which is skipped.
fn split_lines(text: &str) -> Vec<(usize, &str)> {
    let mut lines = Vec::new();
    let mut start = 0;
    for line in text.split(is_line_end) {
        lines.push((start, line));
        start += line.len() + 1;
    }
    lines
}

/// `\n` or `\r` (a function rather than `['\n', '\r']`: the first plant's core carries no
/// searcher for a set of characters).
fn is_line_end(c: char) -> bool {
    c == '\n' || c == '\r'
}

/// The names `#module` lines declare, longest first: they change how every line is split into
/// modules, so they are read before anything else.
fn declared_modules(lines: &[(usize, &str)]) -> Vec<String> {
    let module = format!("#{}", DirectiveKind::Module.name());
    let mut declared: Vec<String> = Vec::new();
    for &(_, line) in lines {
        if let Some(rest) = line.trim_start().strip_prefix(module.as_str()) {
            if rest.is_empty() || rest.starts_with(char::is_whitespace) {
                declared.extend(rest.split_whitespace().map(str::to_string));
            }
        }
    }
    crate::sort::sort_by_key(&mut declared, |name| std::cmp::Reverse(name.len()));
    declared
}

/// The keyword of a line (`axiom:`, `homomorphism:`, …) and the byte offset just after its colon.
fn keyword(content: &str) -> Option<(KeywordKind, usize)> {
    let colon = content.find(':')?;
    keyword_named(&content[..colon], true).map(|k| (k.kind, colon + 1))
}

struct Parser<'a> {
    file: SourceFile,
    diagnostics: Vec<Diagnostic>,
    scanner: ModuleScanner<'a>,
    /// The section the productions read now belong to.
    section: Section,
}

impl Parser<'_> {
    fn line(&mut self, start: usize, line: &str) {
        let lead = line.len() - line.trim_start().len();
        let content = line.trim();
        if content.is_empty() {
            return;
        }
        let at = start + lead;
        if let Some(after_hash) = content.strip_prefix('#') {
            let directive = parse_directive(after_hash, at, &self.scanner, &mut self.diagnostics);
            self.file.directives.extend(directive);
        } else if let Some((keyword, rest_at)) = keyword(content) {
            self.keyword_line(keyword, content, at, rest_at);
        } else if keyword_named(content, false).is_some() {
            // `endlsystem`
            self.section = Section::Productions;
        } else if let Some(p) = parse_production(
            content,
            at,
            self.section,
            &self.scanner,
            &mut self.diagnostics,
        ) {
            self.file.productions.push(p);
        }
    }

    /// A line that starts with a keyword and its colon; `rest_at` is the offset after the colon.
    fn keyword_line(&mut self, keyword: KeywordKind, content: &str, at: usize, rest_at: usize) {
        let rest = &content[rest_at..];
        let rest_start = at + rest_at;
        match keyword {
            KeywordKind::Axiom => self.axiom(rest, rest_start, at..at + content.len()),
            KeywordKind::DerivationLength | KeywordKind::MaximumDepth => {
                self.keyword_directive(keyword, content, at, rest_at)
            }
            KeywordKind::Productions | KeywordKind::EndLSystem => {
                self.section_start(Section::Productions, rest, rest_start, at, content)
            }
            KeywordKind::Homomorphism => {
                self.section_start(Section::Homomorphism, rest, rest_start, at, content)
            }
            KeywordKind::Decomposition => {
                self.section_start(Section::Decomposition, rest, rest_start, at, content)
            }
        }
    }

    fn axiom(&mut self, rest: &str, rest_start: usize, span: Span) {
        let modules = self.scanner.scan(rest, rest_start, &mut self.diagnostics);
        check_brackets(&modules, &mut self.diagnostics);
        if let Some((_, previous)) = &self.file.axiom {
            self.diagnostics.push(Diagnostic::warning(
                "E0104",
                span.clone(),
                format!(
                    "a second axiom replaces the one on line {}; a grammar has one axiom",
                    self.file.line(previous.start)
                ),
            ));
        }
        self.file.axiom = Some((modules, span));
    }

    fn section_start(
        &mut self,
        section: Section,
        rest: &str,
        rest_start: usize,
        at: usize,
        content: &str,
    ) {
        self.section = section;
        if !rest.trim().is_empty() {
            self.diagnostics.push(Diagnostic::error(
                "E0112",
                rest_start..at + content.len(),
                "a section keyword stands alone on its line",
            ));
        }
    }

    /// `derivation length: N` (as `#iterations N`) and `maximum depth: N` (as the depth
    /// directive of the section it stands in).
    fn keyword_directive(
        &mut self,
        keyword: KeywordKind,
        content: &str,
        at: usize,
        rest_at: usize,
    ) {
        let rest = &content[rest_at..];
        let rest_start = at + rest_at;
        let kind = match (keyword, self.section) {
            (KeywordKind::DerivationLength, _) => DirectiveKind::Iterations,
            (_, Section::Decomposition) => DirectiveKind::DecompositionDepth,
            (_, Section::Homomorphism) => DirectiveKind::HomomorphismDepth,
            (_, Section::Productions) => {
                self.diagnostics.push(Diagnostic::error(
                    "E0111",
                    at..rest_start,
                    "'maximum depth:' belongs after 'homomorphism:' or 'decomposition:'",
                ));
                return;
            }
        };
        let trimmed = rest.trim();
        let args_at = rest_start + (rest.len() - rest.trim_start().len());
        self.file.directives.push(Directive {
            name: kind.name().into(),
            kind: Some(kind),
            written: content[..rest_at].trim().to_string(),
            name_span: at..rest_start,
            args: trimmed.to_string(),
            args_span: args_at..args_at + trimmed.len(),
            target: None,
            expr: None,
            modules: Vec::new(),
            points: Vec::new(),
            point_spans: Vec::new(),
        });
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
    fn past_the_module_limit_the_rest_of_the_text_is_not_read() {
        use crate::syntax::scanner::MAX_SCANNED_MODULES;
        // The axiom leaves room for two modules: the production's successor passes the limit.
        let axiom = "F".repeat(MAX_SCANNED_MODULES - 2);
        let rest = "A -> F F F\nB -> C\nC -> D\n#iterations 3\n".repeat(1000);
        let (file, diags) = parse(&format!("axiom: {axiom}\n{rest}"));
        // Each production after it gave E0106 (no predecessor: its modules were not scanned).
        let codes: Vec<_> = diags.iter().map(|d| d.code).collect();
        assert_eq!(codes, ["E0145"]);
        let second_line = 7 + axiom.len() + 1..7 + axiom.len() + 1 + "A -> F F F".len();
        assert!(
            second_line.contains(&diags[0].span.start),
            "{:?}",
            diags[0].span
        );
        assert!(file.productions.len() <= 1, "{}", file.productions.len());
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
    fn a_byte_order_mark_and_every_kind_of_line_end_are_read() {
        for src in [
            "\u{feff}#iterations 2\naxiom: F\nF -> FF",
            "#iterations 2\raxiom: F\rF -> FF\r",
            "\u{feff}#iterations 2 // two\r\naxiom: F\r\nF -> FF",
        ] {
            let (file, diags) = parse(src);
            assert!(diags.is_empty(), "{src:?}: {diags:?}");
            assert_eq!(file.directives.len(), 1, "{src:?}");
            assert_eq!(file.productions.len(), 1, "{src:?}");
            assert!(file.axiom.is_some(), "{src:?}");
        }
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
