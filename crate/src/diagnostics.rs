//! Diagnostics: errors are data. Every stage reports problems as [`Diagnostic`]s with a byte span
//! into the source text; nothing in the core panics on user input.

use serde::Serialize;
use std::ops::Range;

/// How bad a diagnostic is. An `Error` stops the pipeline before geometry is produced.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    Error,
    Warning,
}

/// One problem found in a grammar, located by a UTF-8 byte range of the source text.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    pub severity: Severity,
    /// A stable code (`E0101`), listed in docs/LANGUAGE.md, for tests and documentation.
    pub code: &'static str,
    pub message: String,
    pub span: Range<usize>,
}

impl Diagnostic {
    pub fn error(code: &'static str, span: Range<usize>, message: impl Into<String>) -> Self {
        Diagnostic {
            severity: Severity::Error,
            code,
            message: message.into(),
            span,
        }
    }

    pub fn warning(code: &'static str, span: Range<usize>, message: impl Into<String>) -> Self {
        Diagnostic {
            severity: Severity::Warning,
            code,
            message: message.into(),
            span,
        }
    }
}

/// True when any diagnostic is an error.
pub fn has_errors(diagnostics: &[Diagnostic]) -> bool {
    diagnostics.iter().any(|d| d.severity == Severity::Error)
}

/// A diagnostic with its position resolved to 1-based line and column (columns count Unicode
/// scalar values). This is the shape that crosses the wasm boundary and the CLI prints.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LocatedDiagnostic {
    pub severity: Severity,
    pub code: &'static str,
    pub message: String,
    /// UTF-8 byte offsets into the source.
    pub from: usize,
    pub to: usize,
    pub line: usize,
    pub column: usize,
}

/// Maps byte offsets of one text to lines and columns. A line ends at `\n`, `\r\n` or a lone
/// `\r`; a byte order mark at the start is not a column (editors do not show it), though spans
/// still count its bytes (they are offsets into the text as given).
pub struct LineIndex<'a> {
    text: &'a str,
    line_starts: Vec<usize>,
}

/// Where each line of `text` starts (byte offsets): after `\n`, and after a `\r` not followed by
/// `\n`; the first line after a byte order mark.
pub fn line_starts(text: &str) -> Vec<usize> {
    let bytes = text.as_bytes();
    let mut starts = vec![if text.starts_with('\u{feff}') {
        '\u{feff}'.len_utf8()
    } else {
        0
    }];
    starts.extend(bytes.iter().enumerate().filter_map(|(i, &b)| {
        let ends = b == b'\n' || (b == b'\r' && bytes.get(i + 1) != Some(&b'\n'));
        ends.then_some(i + 1)
    }));
    starts
}

/// The 1-based line of byte `offset`, given the [`line_starts`] of its text: what a message
/// says of another place than its own span (its span carries its own place).
pub fn line_of(line_starts: &[usize], offset: usize) -> usize {
    line_starts.partition_point(|&start| start <= offset).max(1)
}

impl<'a> LineIndex<'a> {
    pub fn new(text: &'a str) -> Self {
        LineIndex {
            text,
            line_starts: line_starts(text),
        }
    }

    /// 1-based (line, column) of a byte offset; offsets past the end or inside a character are
    /// clamped to the previous character boundary.
    pub fn line_column(&self, offset: usize) -> (usize, usize) {
        let mut offset = offset.min(self.text.len());
        while !self.text.is_char_boundary(offset) {
            offset -= 1;
        }
        let line = self
            .line_starts
            .partition_point(|&start| start <= offset)
            .saturating_sub(1);
        let from = self.line_starts[line].min(offset);
        let column = self.text[from..offset].chars().count() + 1;
        (line + 1, column)
    }

    pub fn locate(&self, d: &Diagnostic) -> LocatedDiagnostic {
        let (line, column) = self.line_column(d.span.start);
        LocatedDiagnostic {
            severity: d.severity,
            code: d.code,
            message: d.message.clone(),
            from: d.span.start,
            to: d.span.end.max(d.span.start),
            line,
            column,
        }
    }
}

/// Every diagnostic of `source` with its line and column, in source order.
pub fn locate_all(source: &str, diagnostics: &[Diagnostic]) -> Vec<LocatedDiagnostic> {
    let index = LineIndex::new(source);
    let mut located: Vec<_> = diagnostics.iter().map(|d| index.locate(d)).collect();
    crate::sort::sort_by_key(&mut located, |d| (d.from, d.to));
    located
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_and_column_count_characters_not_bytes() {
        let text = "ab\nωx\n";
        let index = LineIndex::new(text);
        assert_eq!(index.line_column(0), (1, 1));
        assert_eq!(index.line_column(3), (2, 1));
        assert_eq!(index.line_column(5), (2, 2)); // after the two-byte ω
        assert_eq!(index.line_column(4), (2, 1)); // inside ω: clamped
        assert_eq!(index.line_column(100), (3, 1));
    }

    #[test]
    fn lone_carriage_returns_end_lines_and_a_byte_order_mark_is_no_column() {
        let index = LineIndex::new("\u{feff}ab\rcd\r\nef");
        assert_eq!(index.line_column(0), (1, 1)); // the mark itself
        assert_eq!(index.line_column(3), (1, 1)); // 'a'
        assert_eq!(index.line_column(4), (1, 2));
        assert_eq!(index.line_column(6), (2, 1)); // 'c'
        assert_eq!(index.line_column(8), (2, 3)); // the '\r' of "\r\n"
        assert_eq!(index.line_column(10), (3, 1)); // 'e'
    }
}
